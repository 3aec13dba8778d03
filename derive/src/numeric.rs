//! Numerical evaluation of the derived model, for the claims that the paper
//! reads off its figures (Figs. 2 and 7, Section 6) and for (30).
//!
//! The solution set of (19)–(20) at fixed ρ is explicit in s (see
//! [`crate::nondimensional::Branch`]): ā³ = X(s), δ̄ā = Y(s). The physical
//! branch starts at the non-adhesive aspect ratio s∞(ρ) of (29) (where
//! ā → ∞) and is followed towards smaller s; pull-off is the first local
//! minimum of F̄ met on the way, the displacement-controlled pull-off the
//! first local minimum of δ̄.
//!
//! Owns: the f64 model curve and 1-D root finding / minimisation.
//! May use: `ir`, `model`, `sym`.

use crate::ir::Ir;
use crate::model::Derivation;
use crate::sym::{simplify, subs};
use std::collections::BTreeMap;

/// The model along its solution curve at one ρ, evaluated in f64.
pub struct Curve {
    rho: f64,
    x: Ir,
    y: Ir,
    fbar: Ir,
    bc_error: Ir,
    rho_inf: Ir,
}

/// A state on the curve.
#[derive(Clone, Copy, Debug)]
pub struct State {
    /// Aspect ratio s.
    pub s: f64,
    /// ā.
    pub abar: f64,
    /// δ̄.
    pub dbar: f64,
    /// F̄.
    pub fbar: f64,
    /// Quantity (14) as a fraction.
    pub bc_error: f64,
}

impl Curve {
    /// Build the evaluators for `rho` from a derivation with a branch.
    pub fn new(d: &Derivation, rho: f64) -> Result<Curve, String> {
        let b = d
            .branch
            .as_ref()
            .ok_or("the residuals have no explicit branch in s")?;
        let eta = |e| simplify(&subs(e, "eta", &d.eta));
        let limits = d.limits.as_ref().map_err(|e| e.clone())?;
        Ok(Curve {
            rho,
            x: Ir::from_atom(&eta(&b.abar_cubed))?,
            y: Ir::from_atom(&eta(&b.dbar_abar))?,
            fbar: Ir::from_atom(&eta(&d.fbar_reduced))?,
            bc_error: Ir::from_atom(&d.bc_error)?,
            rho_inf: Ir::from_atom(&limits.non_adhesive_rho)?,
        })
    }

    /// The state at aspect ratio `s`, if ā³ > 0 there.
    pub fn at(&self, s: f64) -> Option<State> {
        let mut v = BTreeMap::new();
        v.insert("s", s);
        v.insert("rho", self.rho);
        let x = self.x.eval(&v).ok()?;
        if !(x.is_finite() && x > 0.0) {
            return None;
        }
        let abar = x.cbrt();
        let dbar = self.y.eval(&v).ok()? / abar;
        v.insert("abar", abar);
        v.insert("dbar", dbar);
        let fbar = self.fbar.eval(&v).ok()?;
        let bc_error = self.bc_error.eval(&v).ok()?;
        Some(State {
            s,
            abar,
            dbar,
            fbar,
            bc_error,
        })
    }

    /// s∞(ρ): the non-adhesive aspect ratio, where ā → ∞ on the branch.
    pub fn s_inf(&self) -> Result<f64, String> {
        let f = |s: f64| {
            let mut v = BTreeMap::new();
            v.insert("s", s);
            self.rho_inf.eval(&v).map(|r| r - self.rho)
        };
        bisect(|s| f(s).unwrap_or(f64::NAN), 1e-6, 1.0)
    }

    /// Walk from s∞ towards smaller s and return the first local minimum of
    /// `key` (refined by golden-section search).
    pub fn first_minimum(&self, key: impl Fn(&State) -> f64) -> Result<State, String> {
        let s_inf = self.s_inf()?;
        let n = 4000;
        let h = s_inf / n as f64;
        let mut prev: Option<(f64, f64)> = None;
        let mut prev2: Option<(f64, f64)> = None;
        for k in 1..n {
            let s = s_inf - k as f64 * h;
            let Some(st) = self.at(s) else { break };
            let val = key(&st);
            if let (Some((s1, v1)), Some((_, v2))) = (prev, prev2) {
                if v1 < v2 && v1 <= val {
                    let sm = golden(
                        |s| self.at(s).map(|st| key(&st)).unwrap_or(f64::INFINITY),
                        s1 - h,
                        s1 + h,
                    );
                    return self.at(sm).ok_or_else(|| "minimum off the branch".into());
                }
            }
            prev2 = prev;
            prev = Some((s, val));
        }
        Err("no local minimum along the branch".into())
    }

    /// The first state (walking from s∞ down) where `key` crosses `target`.
    pub fn first_crossing(
        &self,
        key: impl Fn(&State) -> f64,
        target: f64,
    ) -> Result<State, String> {
        let s_inf = self.s_inf()?;
        let n = 4000;
        let h = s_inf / n as f64;
        let mut prev: Option<(f64, f64)> = None;
        for k in 1..n {
            let s = s_inf - k as f64 * h;
            let Some(st) = self.at(s) else { break };
            let val = key(&st) - target;
            if let Some((sp, vp)) = prev {
                if vp.signum() != val.signum() {
                    let sc = bisect(
                        |s| self.at(s).map(|st| key(&st) - target).unwrap_or(f64::NAN),
                        s,
                        sp,
                    )?;
                    return self.at(sc).ok_or_else(|| "crossing off the branch".into());
                }
            }
            prev = Some((s, val));
        }
        Err(format!("no crossing of {target}"))
    }
}

/// Bisection for a sign change of `f` on [lo, hi].
pub fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> Result<f64, String> {
    let mut flo = f(lo);
    if !(flo.is_finite() && f(hi).is_finite()) || flo.signum() == f(hi).signum() {
        return Err(format!("no sign change on [{lo}, {hi}]"));
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        let fm = f(mid);
        if !fm.is_finite() {
            return Err(format!(
                "the function is not finite at {mid} (bisection on [{lo}, {hi}])"
            ));
        }
        if fm.signum() == flo.signum() {
            lo = mid;
            flo = fm;
        } else {
            hi = mid;
        }
        if hi - lo < 1e-15 * (1.0 + lo.abs()) {
            break;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// Golden-section minimisation on [a, b].
pub fn golden(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let mut c = b - r * (b - a);
    let mut d = a + r * (b - a);
    for _ in 0..200 {
        if f(c) < f(d) {
            b = d;
        } else {
            a = c;
        }
        c = b - r * (b - a);
        d = a + r * (b - a);
        if (b - a).abs() < 1e-14 {
            break;
        }
    }
    0.5 * (a + b)
}
