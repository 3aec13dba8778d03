//! The whole force–displacement curve of an ellipse model, including its
//! unstable part, traced by the one continuation engine
//! (`crate::continuation`) through the one model interface's family
//! (`crate::equations::Branch`) in (ā, s, δ̄), static 3-vectors. The
//! solution set of (19)–(20) folds in δ̄ and in ā, so no single variable
//! parametrises it everywhere; the arclength does. Jacobian: the generated
//! [∂r/∂(ā, s) | ∂r/∂δ̄], in variables scaled so that a unit step means a
//! comparable change. Folds are the engine's events (a tangent component
//! dā, dδ̄ or dF̄ changes sign), located by Newton's method on the fold
//! condition ([`crate::fold`]).
//!
//! Written once for every model. Residual scaling: a model's residuals are
//! of degree d in (ā³, δ̄ā); the corrector's convergence test is on the
//! step, which is scale-free.
//!
//! Owns: [`Curve`], [`Fold`], [`trace`]. May use: `contact`, `equations`,
//! `fold`, `continuation`, `error`.

use crate::contact::{Contact, State};
use crate::continuation::{self, End, EventKind, On, Settings, Watch};
use crate::equations::Branch;
use crate::error::{check_range, short, Error, Result};
use crate::fold::{self, FoldCondition};
use nalgebra::{Vector2, Vector3};
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
    /// condition (`crate::fold::locate`) from the nearest traced point.
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
pub(crate) const CURVE_NEAR_CIRCLE: f64 = 1e-9;

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
            supported: "(0, 1 - 1e-9] or 1 for a curve: closer to 1 the branch turns within √(1 − rho) of the circle's bifurcation (a_bar ≈ 1.5874) more sharply than the trace resolves; solve, pull-off and zero-force answer there, and the curve at rho = 1 is the circle's".into(),
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
    // variables scaled so that a unit step means a comparable change
    let family = Branch {
        equations: contact.model(),
        rho,
        scale: Vector3::new(start.a_bar, 0.1, start.delta_bar.abs().max(1.0)),
        strict: true,
    };
    let w0 = family.join(&Vector2::new(start.a_bar, start.s), start.delta_bar);
    // the trace is at least four times finer than the output
    let h_max = (0.5 / points as f64).min(0.05);
    let settings = Settings {
        step: h_max.min(0.01),
        min_step: h_max * 1e-9,
        max_step: h_max,
        grow: 1.3,
        fast_iterations: usize::MAX,
        turn: -1.0,
        corrector_iterations: 20,
        step_tolerance: 1e-12,
        // the step is at most 0.5/points, so the budget grows with the points
        max_steps: 20_000.max(50 * points),
    };
    let watch = Watch {
        size_fold: On::Note,
        displacement_fold: On::Note,
        force_minimum: On::Note,
        bifurcation: On::Ignore,
        crossing: None,
    };
    // the end of the trace, relative to the start: at small ρ the whole
    // branch is elongated (s of order ρ^(1/2)), and a fixed s would end it
    // before the pull-off
    let s_end = 0.05 * start.s;
    let mut passed_fold = false;
    let traced = continuation::trace(
        &family,
        w0,
        &Vector3::new(0.0, 0.0, -1.0), // start towards smaller δ̄
        settings,
        watch,
        |p| {
            if p.d_a_bar > 0.0 {
                passed_fold = true; // the contact size grows again
            }
            p.u[1] * family.scale[1] < s_end || (passed_fold && p.a_bar > start.a_bar)
        },
    )?;
    if traced.end != End::Until {
        // never a silently shortened curve: say where it stopped
        let w = traced.points.last().expect("one point").u;
        let (x, d) = family.split(&w);
        let z = Vector3::new(x[0], x[1], d);
        return Err(Error::NoState(format!(
            "curve at rho = {}: the trace did not reach its end (s < {}, a twentieth of its start, or ā back above its start past the contact-size fold) within {} steps; it stopped at a_bar = {}, s = {}, delta_bar = {}",
            short(rho),
            crate::error::rounded(s_end),
            settings.max_steps,
            short(z[0]),
            short(z[1]),
            short(z[2])
        )));
    }
    let trail: Vec<(Vector3<f64>, Vector3<f64>)> =
        traced.points.iter().map(|p| (p.u, p.t)).collect();
    let from_z = |w: &Vector3<f64>| {
        let (x, d) = family.split(w);
        Vector3::new(x[0], x[1], d)
    };
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
    for e in &traced.events {
        let [i, k] = e.between;
        match e.kind {
            EventKind::SizeFold => {
                folds.push(refine(contact, FoldKind::ContactSize, &states_all[k])?)
            }
            EventKind::DisplacementFold => {
                folds.push(refine(contact, FoldKind::Displacement, &states_all[k])?)
            }
            EventKind::ForceMinimum => {
                // from the traced point with the lower force
                let near = if states_all[i].force_bar < states_all[k].force_bar {
                    &states_all[i]
                } else {
                    &states_all[k]
                };
                folds.push(refine(contact, FoldKind::Load, near)?)
            }
            _ => {}
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
    // the size fold itself is where the branch turns, not beyond it
    state.beyond_size_fold = near.beyond_size_fold && kind != FoldKind::ContactSize;
    Ok(Fold { kind, state })
}
