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
//! Output finer than the trace: past `TRACED_FOR` points each state is
//! corrected onto its own arclength from the traced point before it, and
//! the states are handed out one at a time (`trace_each`), so a curve's
//! memory does not grow with its points.
//!
//! Owns: [`Curve`], [`Fold`], [`trace`], `trace_each`, `TRACED_FOR`,
//! `check_points`, `circle_sizes`. May use: `generated` (`ModelId`), `contact`, `equations`,
//! `fold`, `continuation`, `error`, `model` (its tests: the residuals a state solves).

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

/// The most output points a curve's trace is made fine enough for: it is
/// traced at least four times finer than this many points (or than
/// `points`, where fewer), and each output point is the traced point at or
/// before it; past it each is corrected onto its own arclength from that
/// traced point ([`crate::continuation::at_arclength`]), so the memory a
/// curve takes does not grow with its points.
pub(crate) const TRACED_FOR: usize = 2000;

/// Trace the curve of `contact` from δ̄ = `delta_start` (on the stable
/// branch) past pull-off and the folds, and return `points` states spaced
/// evenly in arclength.
pub fn trace(contact: &Contact, points: usize, delta_start: f64) -> Result<Curve> {
    let mut states = Vec::new();
    let folds = trace_each(contact, points, delta_start, &mut |st| {
        states.push(st);
        Ok(())
    })?;
    Ok(Curve { states, folds })
}

/// [`trace`], handing each state to `each` in order as it is made and
/// returning the folds: the curve is traced and its folds located first,
/// then the states are made one at a time, so nothing of the size of
/// `points` is kept (the command line streams them). An error of `each`
/// ends the curve with it.
pub(crate) fn trace_each(
    contact: &Contact,
    points: usize,
    delta_start: f64,
    each: &mut dyn FnMut(State) -> Result<()>,
) -> Result<Vec<Fold>> {
    check_points(points)?;
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
        return circle_each(contact, start.a_bar, points, each);
    }
    // variables scaled so that a unit step means a comparable change
    let family = Branch {
        equations: contact.model(),
        rho,
        scale: Vector3::new(start.a_bar, 0.1, start.delta_bar.abs().max(1.0)),
        strict: true,
    };
    let w0 = family.join(&Vector2::new(start.a_bar, start.s), start.delta_bar);
    let settings = settings_for(points);
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
    let from_z = |w: &Vector3<f64>| {
        let (x, d) = family.split(w);
        Vector3::new(x[0], x[1], d)
    };
    if traced.end != End::Until {
        // never a silently shortened curve: say where it stopped
        let z = from_z(&traced.points.last().expect("one point").u);
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
    let trail: Vec<Vector3<f64>> = traced.points.iter().map(|p| p.u).collect();
    // the first fold in ā lies between the traced points f and f + 1;
    // the states after it are flagged beyond it
    let size_fold = traced
        .points
        .windows(2)
        .position(|p| p[0].t[0].signum() != p[1].t[0].signum());
    let state_at = |w: &Vector3<f64>, beyond: bool| {
        let z = from_z(w);
        let mut st = contact.state_from(z[0], z[1], z[2]);
        st.beyond_size_fold = beyond;
        st
    };
    let traced_state = |k: usize| state_at(&trail[k], size_fold.is_some_and(|f| k > f));
    let folds = folds_on(contact, &traced.events, &traced_state)?;
    // a curve reaches the pull-off of its model, or says why not
    if !folds.iter().any(|f| f.kind == FoldKind::Load) {
        if let Ok(p) = contact.pull_off_load() {
            return Err(Error::NoState(format!(
                "curve at rho = {}: the trace ended at s = {} without reaching the pull-off (force {} at s = {})",
                short(rho),
                crate::error::rounded(traced_state(trail.len() - 1).s),
                crate::error::rounded(p.state.force_bar),
                crate::error::rounded(p.state.s)
            )));
        }
    }
    let trace = Traced {
        family: &family,
        settings,
        points: &traced.points,
        trail: &trail,
        size_fold,
    };
    spaced_each(&trace, points, &state_at, each)?;
    Ok(folds)
}

/// A traced branch: its family and settings, its points, and the point
/// after which it is past its first fold in ā.
struct Traced<'a> {
    family: &'a Branch<'a, dyn crate::model::Model>,
    settings: Settings,
    points: &'a [continuation::Point<nalgebra::U3>],
    /// The points' scaled unknowns.
    trail: &'a [Vector3<f64>],
    size_fold: Option<usize>,
}

/// `points` states of the trace spaced evenly in arclength, each handed
/// to `each`: a traced point where the trace is finer than the output,
/// else corrected onto its own arclength from the traced point before it
/// (`state_at(w, beyond)`: the state at the scaled point w, flagged beyond
/// the size fold or not).
fn spaced_each(
    trace: &Traced,
    points: usize,
    state_at: &dyn Fn(&Vector3<f64>, bool) -> State,
    each: &mut dyn FnMut(State) -> Result<()>,
) -> Result<()> {
    let trail = trace.trail;
    let past = |j: usize| trace.size_fold.is_some_and(|f| j > f);
    for (j, sigma) in continuation::spaced(trail, points) {
        let st = if points <= TRACED_FOR || sigma == 0.0 {
            state_at(&trail[j], past(j))
        } else {
            let (here, next) = (&trace.points[j], &trace.points[j + 1]);
            let w = continuation::at_arclength(trace.family, trace.settings, here, next, sigma)?;
            let beyond = past(j)
                || (trace.size_fold == Some(j) && continuation::past_size_fold(here, next, sigma));
            state_at(&w, beyond)
        };
        each(st)?;
    }
    Ok(())
}

/// The curve at ρ = 1 (s ≡ 1): the exact axisymmetric curve, `points`
/// states parametrised by ā from its start `a_start` down to 3 % of it,
/// each handed to `each`, and its one fold, the pull-off.
fn circle_each(
    contact: &Contact,
    a_start: f64,
    points: usize,
    each: &mut dyn FnMut(State) -> Result<()>,
) -> Result<Vec<Fold>> {
    let folds = vec![Fold {
        kind: FoldKind::Load,
        state: contact.pull_off_load()?.state,
    }];
    for a in circle_sizes(a_start, points) {
        each(contact.at_contact_size(a)?[0])?;
    }
    Ok(folds)
}

/// The number of a curve's states, checked: 2 ..= [`MAX_POINTS`].
pub(crate) fn check_points(points: usize) -> Result<()> {
    check_range(
        "points",
        points as f64,
        (2..=MAX_POINTS).contains(&points),
        "2 ..= 100000",
    )
    .map(|_| ())
}

/// The sizes of a curve along a branch with one parameter (the circle's,
/// at ρ = 1): `points` of them, evenly spaced from `a_start` down to 3 % of
/// it.
pub(crate) fn circle_sizes(a_start: f64, points: usize) -> impl Iterator<Item = f64> {
    let last = points.saturating_sub(1).max(1) as f64;
    (0..points).map(move |k| a_start * (1.0 - 0.97 * k as f64 / last))
}

/// The trace's settings for a curve of `points` states: the trace is at
/// least four times finer than the output, up to [`TRACED_FOR`] points.
fn settings_for(points: usize) -> Settings {
    let traced_for = points.min(TRACED_FOR);
    let h_max = (0.5 / traced_for as f64).min(0.05);
    Settings {
        step: h_max.min(0.01),
        min_step: h_max * 1e-9,
        max_step: h_max,
        grow: 1.3,
        fast_iterations: usize::MAX,
        turn: -1.0,
        corrector_iterations: 20,
        step_tolerance: 1e-12,
        // the step is at most 0.5/points, so the budget grows with the points
        max_steps: 20_000.max(50 * traced_for),
    }
}

/// The folds the trace passed (`events`), each located by Newton's method
/// from the traced state next to it (`traced_state(k)`: the state at the
/// trace's point k); the force minimum from the one of its two points with
/// the lower force.
fn folds_on(
    contact: &Contact,
    events: &[continuation::Event<nalgebra::U3>],
    traced_state: &dyn Fn(usize) -> State,
) -> Result<Vec<Fold>> {
    let mut folds = Vec::new();
    for e in events {
        let [i, k] = e.between;
        match e.kind {
            EventKind::SizeFold => {
                folds.push(refine(contact, FoldKind::ContactSize, &traced_state(k))?)
            }
            EventKind::DisplacementFold => {
                folds.push(refine(contact, FoldKind::Displacement, &traced_state(k))?)
            }
            EventKind::ForceMinimum => {
                let (si, sk) = (traced_state(i), traced_state(k));
                let near = if si.force_bar < sk.force_bar {
                    &si
                } else {
                    &sk
                };
                folds.push(refine(contact, FoldKind::Load, near)?)
            }
            _ => {}
        }
    }
    Ok(folds)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Past the points its trace is made for ([`TRACED_FOR`]), a curve's
    /// states are corrected onto their own arclength from the traced point
    /// before: each solves (19)–(20), the largest jump in F̄ halves when
    /// the points double (they are spaced, not repeated), and the states
    /// beyond the fold in ā are flagged from the fold on: one switch, with
    /// the located fold between the two states on either side of it.
    #[test]
    fn a_curve_finer_than_its_trace_is_made_of_states() {
        for rho in [0.8, 0.3] {
            let c = Contact::new(rho).unwrap();
            let jump = |cv: &Curve| {
                cv.states
                    .windows(2)
                    .map(|w| (w[1].force_bar - w[0].force_bar).abs())
                    .fold(0.0, f64::max)
            };
            let coarse = trace(&c, 2 * TRACED_FOR, 20.0).unwrap();
            let fine = trace(&c, 4 * TRACED_FOR, 20.0).unwrap();
            assert_eq!(fine.states.len(), 4 * TRACED_FOR);
            let (j1, j2) = (jump(&coarse), jump(&fine));
            assert!(j2 < 0.55 * j1, "rho {rho}: largest jump {j1} → {j2}");
            for st in &fine.states {
                let (r, _) = crate::ModelId::Max.model().residuals_and_jacobian(
                    Vector2::new(st.a_bar, st.s),
                    rho,
                    st.delta_bar,
                );
                assert!(
                    r.norm() < 1e-8 * (1.0 + st.a_bar.powi(3)),
                    "rho {rho}: residual {} at {st:?}",
                    r.norm()
                );
            }
            let switch = fine
                .states
                .iter()
                .position(|st| st.beyond_size_fold)
                .expect("a fold in a");
            assert!(fine.states[switch..].iter().all(|st| st.beyond_size_fold));
            let fold = fine
                .folds
                .iter()
                .find(|f| f.kind == FoldKind::ContactSize)
                .expect("the fold in a located");
            let at = |st: &State| Vector3::new(st.a_bar, st.s, st.delta_bar);
            let (before, after, f) = (
                at(&fine.states[switch - 1]),
                at(&fine.states[switch]),
                at(&fold.state),
            );
            assert!(
                (f - before).norm() + (after - f).norm() < 1.01 * (after - before).norm() + 1e-9,
                "rho {rho}: the fold {f:?} is not between {before:?} and {after:?}"
            );
        }
    }
}
