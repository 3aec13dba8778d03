//! The whole force–displacement curve, including its unstable part, traced
//! by pseudo-arclength continuation in (ā, s, δ̄). The solution set of
//! (19)–(20) folds in δ̄ and in ā, so no single variable parametrises it
//! everywhere; the arclength does. Tangent: the null vector of the 2 × 3
//! Jacobian [∂r/∂(ā, s) | ∂r/∂δ̄] (generated), i.e. the cross product of its
//! rows. Corrector: Newton on (19), (20) plus the arclength condition.
//! Folds are detected where a tangent component (dā, dδ̄) or dF̄ changes
//! sign, and located by Newton's method on the fold condition
//! ([`crate::fold`]).
//!
//! Written once for every model. Residual scaling: a model's residuals are
//! of degree d in (ā³, δ̄ā); the corrector's convergence test is on the
//! step, which is scale-free.
//!
//! Owns: [`Curve`], [`Fold`], [`trace`]. May use: `contact`, `model`, `fold`, `error`.

use crate::contact::{Contact, State};
use crate::error::{check_range, short, Error, Result};
use crate::fold::{self, FoldCondition};
use nalgebra::{Matrix3, Vector2, Vector3};
use serde::{Deserialize, Serialize};

/// What folds at a fold point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum FoldKind {
    /// A minimum of F̄: pull-off under load control.
    Load,
    /// A turning point in δ̄.
    Displacement,
    /// A turning point in ā (the contact size).
    ContactSize,
}

/// A fold of the solution curve.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Fold {
    /// Which quantity turns.
    pub kind: FoldKind,
    /// The state at the fold: located by Newton's method on the fold
    /// condition ([`crate::fold::locate`]) from the nearest traced point.
    pub state: State,
}

/// A traced curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Curve {
    /// States in order along the curve, from large approach downwards.
    pub states: Vec<State>,
    /// The folds met on the way.
    pub folds: Vec<Fold>,
}

/// The most points a curve has (`points` above it is an error, not an
/// allocation failure).
pub const MAX_POINTS: usize = 100_000;

/// 1 − ρ below which (but above 0) a curve is refused: its trace lost the
/// sharp turn of the branch by the circle's bifurcation below about 1e-10
/// (`apex45`) and 1e-11 (`energy`).
pub const CURVE_NEAR_CIRCLE: f64 = 1e-9;

/// Trace the curve of `contact` from δ̄ = `delta_start` (on the stable
/// branch) past pull-off and the folds, and return `points` states spaced
/// evenly in arclength.
pub fn trace(contact: &Contact, points: usize, delta_start: f64) -> Result<Curve> {
    check_range(
        "points",
        points as f64,
        (2..=MAX_POINTS).contains(&points),
        "2 ..= 100000",
    )?;
    let rho = contact.rho();
    // (with a margin for the rounding of a typed 0.999999999)
    if rho < 1.0 && 1.0 - rho < 0.999 * CURVE_NEAR_CIRCLE {
        return Err(Error::Unsupported {
            name: "rho",
            value: rho,
            supported: "(0, 1 - 1e-9] or 1 for a curve: closer to 1 the branch turns within √(1 − rho) of the circle's bifurcation (a_bar ≈ 1.5874) more sharply than the trace resolves; solve, pull-off and zero-force answer there, and the curve at rho = 1 is the circle's",
        });
    }
    let start = contact.at_displacement(delta_start)?;
    if rho >= 1.0 {
        // s ≡ 1: the exact axisymmetric curve, parametrised by ā.
        let states: Vec<State> = (0..points)
            .map(|k| {
                let a = start.a_bar * (1.0 - 0.97 * k as f64 / (points - 1) as f64);
                contact.at_contact_size(a).map(|v| v[0])
            })
            .collect::<Result<_>>()?;
        let folds = vec![Fold {
            kind: FoldKind::Load,
            state: contact.pull_off_load()?.state,
        }];
        return Ok(Curve { states, folds });
    }
    let model = contact.model();
    let f = |z: &Vector3<f64>| -> ([f64; 2], [[f64; 3]; 2]) {
        let x = Vector2::new(z[0], z[1]);
        let (r, j) = model.residuals_and_jacobian(x, rho, z[2]);
        let d = model.residuals_d_delta(x, rho, z[2]);
        (
            [r[0], r[1]],
            [[j[(0, 0)], j[(0, 1)], d[0]], [j[(1, 0)], j[(1, 1)], d[1]]],
        )
    };
    // variables scaled so that a unit step means a comparable change
    let scale = Vector3::new(start.a_bar, 0.1, start.delta_bar.abs().max(1.0));
    let tangent = |z: &Vector3<f64>, prev: Option<&Vector3<f64>>| -> Vector3<f64> {
        let (_, j) = f(z);
        let r1 = Vector3::new(j[0][0] * scale[0], j[0][1] * scale[1], j[0][2] * scale[2]);
        let r2 = Vector3::new(j[1][0] * scale[0], j[1][1] * scale[1], j[1][2] * scale[2]);
        let mut t = r1.cross(&r2).normalize();
        match prev {
            Some(p) if t.dot(p) < 0.0 => t = -t,
            None if t[2] > 0.0 => t = -t, // start towards smaller δ̄
            _ => {}
        }
        t
    };
    let to_z = |st: &State| {
        Vector3::new(
            st.a_bar / scale[0],
            st.s / scale[1],
            st.delta_bar / scale[2],
        )
    };
    let from_z = |w: &Vector3<f64>| Vector3::new(w[0] * scale[0], w[1] * scale[1], w[2] * scale[2]);
    let mut w = to_z(&start);
    let mut t = tangent(&from_z(&w), None);
    // the trace is at least four times finer than the output
    let h_max = (0.5 / points as f64).min(0.05);
    let mut h = h_max.min(0.01);
    let mut trail: Vec<(Vector3<f64>, Vector3<f64>)> = vec![(w, t)];
    // the step is at most 0.5/points, so the budget grows with the points
    let max_steps = 20_000.max(50 * points);
    let mut passed_fold = false;
    let mut reached_end = false;
    // the end of the trace, relative to the start: at small ρ the whole
    // branch is elongated (s of order ρ^(1/2)), and a fixed s would end it
    // before the pull-off
    let s_end = 0.05 * start.s;
    for _ in 0..max_steps {
        let mut accepted = None;
        for _ in 0..30 {
            let wp = w + t * h;
            let mut wc = wp;
            let mut ok = false;
            for _ in 0..20 {
                let z = from_z(&wc);
                if !(z[0] > 0.0 && z[1] > 0.0 && z[1] <= 1.0) {
                    break;
                }
                let (r, j) = f(&z);
                let arc = t.dot(&(wc - wp));
                let m = Matrix3::new(
                    j[0][0] * scale[0],
                    j[0][1] * scale[1],
                    j[0][2] * scale[2],
                    j[1][0] * scale[0],
                    j[1][1] * scale[1],
                    j[1][2] * scale[2],
                    t[0],
                    t[1],
                    t[2],
                );
                let Some(dw) = m.lu().solve(&Vector3::new(-r[0], -r[1], -arc)) else {
                    break;
                };
                wc += dw;
                if dw.norm() < 1e-12 {
                    ok = true;
                    break;
                }
            }
            if ok {
                accepted = Some(wc);
                break;
            }
            h *= 0.5;
        }
        let Some(wn) = accepted else {
            return Err(Error::NoConvergence {
                iterations: 20,
                a_bar: from_z(&w)[0],
                s: from_z(&w)[1],
                residual: f64::NAN,
                context: format!(
                    "pseudo-arclength corrector at delta_bar = {} (rho = {})",
                    crate::error::rounded(from_z(&w)[2]),
                    short(rho)
                ),
            });
        };
        let tn = tangent(&from_z(&wn), Some(&t));
        w = wn;
        t = tn;
        h = (h * 1.3).min(h_max);
        trail.push((w, t));
        let z = from_z(&w);
        if t[0] > 0.0 {
            passed_fold = true; // the contact size grows again
        }
        if z[1] < s_end || (passed_fold && z[0] > start.a_bar) {
            reached_end = true;
            break;
        }
    }
    if !reached_end {
        // never a silently shortened curve: say where it stopped
        let z = from_z(&w);
        return Err(Error::NoState(format!(
            "curve at rho = {}: the trace did not reach its end (s < {}, a twentieth of its start, or ā back above its start past the contact-size fold) within {max_steps} steps; it stopped at a_bar = {}, s = {}, delta_bar = {}",
            short(rho),
            crate::error::rounded(s_end),
            short(z[0]),
            short(z[1]),
            short(z[2])
        )));
    }
    // states (flagged beyond the first contact-size fold) and folds
    let size_fold = trail
        .windows(2)
        .position(|p| p[0].1[0].signum() != p[1].1[0].signum());
    let states_all: Vec<State> = trail
        .iter()
        .enumerate()
        .map(|(k, (w, _))| {
            let z = from_z(w);
            let mut st = contact.state_from(z[0], z[1], z[2]);
            st.beyond_size_fold = size_fold.is_some_and(|f| k > f);
            st
        })
        .collect();
    let mut folds = Vec::new();
    for k in 1..trail.len() {
        let (t0, t1) = (trail[k - 1].1, trail[k].1);
        if t0[0].signum() != t1[0].signum() {
            folds.push(refine(contact, FoldKind::ContactSize, &states_all[k])?);
        }
        if t0[2].signum() != t1[2].signum() {
            folds.push(refine(contact, FoldKind::Displacement, &states_all[k])?);
        }
        if k + 1 < trail.len() {
            let (f0, f1, f2) = (
                states_all[k - 1].force_bar,
                states_all[k].force_bar,
                states_all[k + 1].force_bar,
            );
            if f1 < f0 && f1 <= f2 {
                folds.push(refine(contact, FoldKind::Load, &states_all[k])?);
            }
        }
    }
    // a curve reaches the pull-off of its model, or says why not
    if !folds.iter().any(|f| f.kind == FoldKind::Load) {
        if let Ok(p) = contact.pull_off_load() {
            return Err(Error::NoState(format!(
                "curve at rho = {}: the trace ended at s = {} without reaching the pull-off (force {} at s = {})",
                short(rho),
                crate::error::rounded(states_all.last().map(|st| st.s).unwrap_or(f64::NAN)),
                crate::error::rounded(p.state.force_bar),
                crate::error::rounded(p.state.s)
            )));
        }
    }
    // resample evenly in arclength
    let mut arc = vec![0.0];
    for k in 1..trail.len() {
        arc.push(arc[k - 1] + (trail[k].0 - trail[k - 1].0).norm());
    }
    let total = *arc.last().unwrap_or(&0.0);
    let mut states = Vec::with_capacity(points);
    let mut j = 0;
    for i in 0..points {
        let target = total * i as f64 / (points - 1) as f64;
        while j + 1 < arc.len() && arc[j + 1] < target {
            j += 1;
        }
        states.push(states_all[j.min(states_all.len() - 1)]);
    }
    Ok(Curve { states, folds })
}

/// The fold of `kind` near the traced state `near`, by Newton's method on
/// the fold condition; a fold that does not converge is an error that says
/// where (never the traced point in its place).
fn refine(contact: &Contact, kind: FoldKind, near: &State) -> Result<Fold> {
    let which = match kind {
        FoldKind::Load => FoldCondition::Load,
        FoldKind::Displacement => FoldCondition::Displacement,
        FoldKind::ContactSize => FoldCondition::ContactSize,
    };
    let z = fold::locate(
        contact.model(),
        contact.rho(),
        Vector3::new(near.a_bar, near.s, near.delta_bar),
        which,
    )?;
    let mut state = contact.state_from(z[0], z[1], z[2]);
    state.beyond_size_fold = near.beyond_size_fold;
    Ok(Fold { kind, state })
}
