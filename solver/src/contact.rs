//! Contact states of the reduced model (19)–(20) at a fixed radii ratio ρ,
//! in the dimensionless variables of (17): control by displacement δ̄, by
//! contact size ā, by load F̄; pull-off under load and displacement control;
//! the zero-force state.
//!
//! At fixed ρ < 1 the solution set of (19)–(20) is explicit in s (both
//! residuals are linear in ā³ and δ̄ā; generated `branch`). The physical
//! branch starts at the non-adhesive aspect ratio s∞(ρ) of (29), where
//! ā → ∞, and is followed towards smaller s: F̄ and δ̄ decrease, F̄ reaches
//! its minimum (pull-off under load control), and the contact size reaches
//! a minimum (a fold in ā) beyond which s collapses towards 0 and ā grows
//! again. States beyond that fold are flagged. Brackets come from this
//! walk; each state is then polished by Newton's method on the generated
//! residuals and Jacobian. At ρ = 1 the exact axisymmetric solution (22)–(25)
//! is used (s = 1).
//!
//! Owns: [`Contact`], [`State`]. May use: `model`, `newton`, `error`.

use crate::error::{check_range, Error, Result};
use crate::model::{Model, Paper};
use crate::newton::{self, NewtonConfig};
use serde::{Deserialize, Serialize};
use std::marker::PhantomData;

/// One state of the model, dimensionless as in (17) (lengths in
/// L = (2R₁²Δγ/m)^(1/6), pressures in √(2mΔγ) L).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct State {
    /// Radii ratio ρ = R₂/R₁ (21).
    pub rho: f64,
    /// Major semi-axis ā (17).
    pub a: f64,
    /// Minor semi-axis b̄ = s ā.
    pub b: f64,
    /// Aspect ratio s = b/a (12).
    pub s: f64,
    /// Collocation parameter ξ (15)₁.
    pub xi: f64,
    /// Shape parameter A L² of (5), from (10).
    pub shape_a: f64,
    /// Shape parameter B L² of (5), from (10).
    pub shape_b: f64,
    /// Maximum pressure p₀ / (√(2mΔγ) L) (Section 6).
    pub p0: f64,
    /// Force F̄ = F/(2R₁Δγ), derived form of (18).
    pub force: f64,
    /// Approach δ̄ (17).
    pub delta: f64,
    /// A-posteriori error (14) of the boundary condition (3)₂, as a fraction.
    pub bc_error: f64,
    /// ρ below the paper's stated range 0.8 ≤ ρ ≤ 1: read `bc_error`.
    pub outside_stated_range: bool,
    /// The state lies beyond the fold of the contact size, where s
    /// collapses towards 0: far from the physical branch.
    pub beyond_size_fold: bool,
}

/// The reduced model at one radii ratio ρ, for the ansatz `M`.
#[derive(Clone, Debug)]
pub struct Contact<M: Model = Paper> {
    rho: f64,
    newton: NewtonConfig,
    walk_points: usize,
    _model: PhantomData<M>,
}

/// Tolerance within which ρ counts as 1 (the axisymmetric case).
const AXISYMMETRIC: f64 = 1e-12;

impl Contact<Paper> {
    /// The paper's ansatz at radii ratio `rho` ∈ (0, 1].
    pub fn new(rho: f64) -> Result<Self> {
        Contact::<Paper>::with_model(rho)
    }
}

impl<M: Model> Contact<M> {
    /// Any generated ansatz at radii ratio `rho` ∈ (0, 1].
    pub fn with_model(rho: f64) -> Result<Self> {
        check_range("rho", rho, rho > 0.0 && rho <= 1.0, "(0, 1]")?;
        Ok(Contact {
            rho,
            newton: NewtonConfig::default(),
            walk_points: 4000,
            _model: PhantomData,
        })
    }

    /// Replace the Newton controls.
    pub fn newton(mut self, config: NewtonConfig) -> Self {
        self.newton = config;
        self
    }

    /// The radii ratio.
    pub fn rho(&self) -> f64 {
        self.rho
    }

    fn axisymmetric(&self) -> bool {
        self.rho >= 1.0 - AXISYMMETRIC
    }

    /// The pressure p/(√(2mΔγ) L) of `state` at (x̄, ȳ) = (x, y)/L: the
    /// ansatz with its collocation (for the paper, (5) with (10)); zero
    /// outside the ellipse (7).
    pub fn pressure(&self, state: &State, x: f64, y: f64) -> f64 {
        if (x / state.a).powi(2) + (y / state.b).powi(2) > 1.0 {
            return 0.0;
        }
        M::pressure(x, y, state.p0, state.a, state.s, state.xi)
    }

    /// s∞(ρ): the non-adhesive aspect ratio (29), where ā → ∞ on the branch.
    pub fn s_infinity(&self) -> f64 {
        crate::limits::non_adhesive_s(self.rho)
    }

    /// The state on the branch at aspect ratio `s` (explicit; no Newton).
    pub fn state_at_s(&self, s: f64) -> Option<State> {
        let [x, y] = M::branch(s, self.rho);
        if !(x.is_finite() && x > 0.0 && y.is_finite()) {
            return None;
        }
        let a = x.cbrt();
        Some(self.state_from(a, s, y / a))
    }

    /// The full state at (ā, s, δ̄), which must satisfy (19)–(20).
    pub fn state_from(&self, a: f64, s: f64, delta: f64) -> State {
        let xi = M::xi(a, s, delta);
        let [shape_a, shape_b] = M::shape(a, s, xi);
        State {
            rho: self.rho,
            a,
            b: s * a,
            s,
            xi,
            shape_a,
            shape_b,
            p0: M::p0_bar(a, xi, s),
            force: M::force_bar(a, s, delta),
            delta,
            bc_error: M::bc_error(s),
            outside_stated_range: self.rho < 0.8,
            beyond_size_fold: false,
        }
    }

    fn axisymmetric_state(&self, a: f64) -> State {
        let delta = crate::generated::paper::axisymmetric_dbar(a);
        let mut st = self.state_from(a, 1.0, delta);
        st.force = crate::generated::paper::axisymmetric_force_bar(a);
        st.bc_error = 0.0;
        st
    }

    /// Walk the branch from s∞ towards s → 0: the samples (s, state).
    fn walk(&self) -> Vec<State> {
        let s_inf = self.s_infinity();
        let n = self.walk_points;
        let mut out: Vec<State> = Vec::with_capacity(n);
        let mut fold_seen = false;
        for k in 1..n {
            // logarithmic in s∞ − s, from 1e-13 s∞ to s∞: near ρ = 1 the
            // whole physical branch lies within O(1 − ρ) of s∞
            let s = s_inf - s_inf * 10f64.powf(-13.0 * (1.0 - k as f64 / n as f64));
            let Some(mut st) = self.state_at_s(s) else {
                continue;
            };
            if let Some(prev) = out.last() {
                if st.a > prev.a {
                    fold_seen = true;
                }
            }
            st.beyond_size_fold = fold_seen;
            out.push(st);
        }
        out
    }

    /// Polish a state by Newton's method on (19)–(20) at its δ̄.
    fn polish(&self, guess: &State, context: &str) -> Result<State> {
        let delta = guess.delta;
        let sol = newton::solve(
            |a, s| M::residuals_and_jacobian(a, s, self.rho, delta),
            (guess.a, guess.s),
            &self.newton,
            context,
        )?;
        let mut st = self.state_from(sol.a_bar, sol.s, delta);
        st.beyond_size_fold = guess.beyond_size_fold;
        Ok(st)
    }

    /// The explicit branch state at `s`, flagged, polished by Newton.
    fn polish_at_s(&self, s: f64, beyond_size_fold: bool, what: &str) -> Result<State> {
        let mut guess = self
            .state_at_s(s)
            .ok_or_else(|| Error::NoState(format!("{what}: off the branch at s = {s}")))?;
        guess.beyond_size_fold = beyond_size_fold;
        self.polish(&guess, what)
    }

    /// Along the walk, all crossings of `key(state) = target`, each refined
    /// by bisection in s on the explicit branch and polished by Newton.
    fn crossings(
        &self,
        key: impl Fn(&State) -> f64,
        target: f64,
        what: &str,
    ) -> Result<Vec<State>> {
        let walk = self.walk();
        let mut out = Vec::new();
        for w in walk.windows(2) {
            let (f0, f1) = (key(&w[0]) - target, key(&w[1]) - target);
            if f0.signum() != f1.signum() && f0.is_finite() && f1.is_finite() {
                let s = bisect(
                    |s| {
                        self.state_at_s(s)
                            .map(|st| key(&st) - target)
                            .unwrap_or(f64::NAN)
                    },
                    w[1].s,
                    w[0].s,
                )?;
                out.push(self.polish_at_s(s, w[1].beyond_size_fold, what)?);
            }
        }
        Ok(out)
    }

    /// The first local minimum of `key` along the walk, refined by golden
    /// section in s and polished.
    fn first_minimum(&self, key: impl Fn(&State) -> f64, what: &str) -> Result<State> {
        let walk = self.walk();
        for k in 1..walk.len().saturating_sub(1) {
            let (a, b, c) = (key(&walk[k - 1]), key(&walk[k]), key(&walk[k + 1]));
            if b < a && b <= c {
                let (mut lo, mut hi) = (walk[k + 1].s, walk[k - 1].s);
                let f = |s: f64| {
                    self.state_at_s(s)
                        .map(|st| key(&st))
                        .unwrap_or(f64::INFINITY)
                };
                let r = 0.5 * (5f64.sqrt() - 1.0);
                for _ in 0..120 {
                    let (x1, x2) = (hi - r * (hi - lo), lo + r * (hi - lo));
                    if f(x1) < f(x2) {
                        hi = x2;
                    } else {
                        lo = x1;
                    }
                }
                return self.polish_at_s(0.5 * (lo + hi), walk[k].beyond_size_fold, what);
            }
        }
        Err(Error::NoState(format!(
            "{what}: no minimum along the branch at rho = {}",
            self.rho
        )))
    }

    /// Displacement control: the stable state at approach `delta` (the first
    /// one met from the non-adhesive end of the branch).
    pub fn at_displacement(&self, delta: f64) -> Result<State> {
        check_range("delta", delta, true, "finite")?;
        if self.axisymmetric() {
            // δ̄(ā) = ā²/4 − 2/ā is increasing: one state for every δ̄.
            let a = bisect(
                |a| crate::generated::paper::axisymmetric_dbar(a) - delta,
                1e-9,
                1e9,
            )?;
            return Ok(self.axisymmetric_state(a));
        }
        self.crossings(|st| st.delta, delta, "displacement control")?
            .into_iter()
            .next()
            .ok_or_else(|| Error::NoState(format!("no contact at delta = {delta} for rho = {} (below the displacement-controlled pull-off)", self.rho)))
    }

    /// Contact-size control: every state with major semi-axis `a` (none, one
    /// or two). δ̄ enters (19)–(20) linearly: (19) gives δ̄(s), and (20)
    /// becomes one equation in s, whose roots are found by scanning s.
    pub fn at_contact_size(&self, a: f64) -> Result<Vec<State>> {
        check_range("a", a, a > 0.0, "(0, ∞)")?;
        if self.axisymmetric() {
            return Ok(vec![self.axisymmetric_state(a)]);
        }
        let delta_of = |s: f64| {
            let (r, _) = M::residuals_and_jacobian(a, s, self.rho, 0.0);
            let d = M::residuals_d_delta(a, s, self.rho, 0.0);
            -r[0] / d[0]
        };
        let g = |s: f64| {
            let dl = delta_of(s);
            M::residuals_and_jacobian(a, s, self.rho, dl).0[1]
        };
        let n = 2000;
        let mut out = Vec::new();
        for k in 1..n {
            let (s0, s1) = (k as f64 / n as f64, (k + 1) as f64 / n as f64);
            let (g0, g1) = (g(s0), g(s1.min(1.0 - 1e-12)));
            if g0.is_finite() && g1.is_finite() && g0.signum() != g1.signum() {
                let s = bisect(g, s0, s1.min(1.0 - 1e-12))?;
                let mut st = self.state_from(a, s, delta_of(s));
                // the fold flag: compare with the branch's minimum size
                st.beyond_size_fold = s < self.size_fold()?.s;
                out.push(st);
            }
        }
        out.sort_by(|x, y| y.s.total_cmp(&x.s));
        Ok(out)
    }

    /// The fold of the contact size: the minimum of ā along the branch.
    pub fn size_fold(&self) -> Result<State> {
        if self.axisymmetric() {
            return Err(Error::NoState(
                "no fold in a_bar at rho = 1: a_bar decreases to 0".into(),
            ));
        }
        self.first_minimum(|st| st.a, "fold of the contact size")
    }

    /// Load control: the stable state at force `force` (on the branch from
    /// the non-adhesive end down to pull-off).
    pub fn at_load(&self, force: f64) -> Result<State> {
        let pull = self.pull_off_load()?;
        check_range(
            "force",
            force,
            force >= pull.force,
            "[pull-off force, ∞) for this rho",
        )?;
        self.at_load_all(force)?
            .into_iter()
            .next()
            .ok_or_else(|| Error::NoState(format!("no state at force {force}")))
    }

    /// Load control: every state at force `force`, the stable one first.
    pub fn at_load_all(&self, force: f64) -> Result<Vec<State>> {
        check_range("force", force, true, "finite")?;
        if self.axisymmetric() {
            let f = crate::generated::paper::axisymmetric_force_bar;
            let a_c = 12f64.cbrt();
            let mut out = Vec::new();
            if force >= f(a_c) {
                out.push(self.axisymmetric_state(bisect(|a| f(a) - force, a_c, 1e6)?));
                if force < 0.0 {
                    out.push(self.axisymmetric_state(bisect(|a| f(a) - force, 1e-9, a_c)?));
                }
            }
            return Ok(out);
        }
        self.crossings(|st| st.force, force, "load control")
    }

    /// Pull-off under load control: the minimum of F̄ along the branch.
    pub fn pull_off_load(&self) -> Result<State> {
        if self.axisymmetric() {
            return Ok(self.axisymmetric_state(12f64.cbrt()));
        }
        self.first_minimum(|st| st.force, "pull-off under load control")
    }

    /// Pull-off under displacement control: the end of the part of the
    /// branch that continues the stable one with dδ̄/dā > 0 — the first
    /// minimum of δ̄ or the fold of the contact size, whichever comes first.
    pub fn pull_off_displacement(&self) -> Result<State> {
        if self.axisymmetric() {
            return Err(Error::NoState("at rho = 1, delta_bar(a_bar) = a_bar^2/4 - 2/a_bar increases for all a_bar: no displacement-controlled pull-off at finite size".into()));
        }
        let fold = self.size_fold()?;
        match self.first_minimum(|st| st.delta, "pull-off under displacement control") {
            Ok(m) if m.s > fold.s => Ok(m),
            _ => Ok(fold),
        }
    }

    /// The zero-force state (Section 5).
    pub fn zero_force(&self) -> Result<State> {
        self.at_load(0.0)
    }
}

/// Bisection for a sign change of `f` on [lo, hi].
pub(crate) fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> Result<f64> {
    let (mut flo, fhi) = (f(lo), f(hi));
    if !(flo.is_finite() && fhi.is_finite()) || flo.signum() == fhi.signum() {
        return Err(Error::NoState(format!("no sign change on [{lo}, {hi}]")));
    }
    for _ in 0..300 {
        let mid = 0.5 * (lo + hi);
        let fm = f(mid);
        if fm.signum() == flo.signum() {
            lo = mid;
            flo = fm;
        } else {
            hi = mid;
        }
        if (hi - lo).abs() <= 1e-15 * (lo.abs() + hi.abs()) {
            break;
        }
    }
    Ok(0.5 * (lo + hi))
}
