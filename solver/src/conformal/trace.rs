//! A `conformal:K` branch at fixed ρ, traced by the one continuation
//! engine ([`crate::continuation`]) through the one model interface's
//! family ([`crate::equations::Branch`]): the K equations ∇_c Π̄ = 0 in the
//! K + 1 unknowns x = (c, δ̄). Steps grow while the corrector converges in
//! few iterations and the tangent turns little, and halve otherwise, so the
//! trace passes the folds in ā that each mode's imperfect bifurcation
//! makes; a state whose map is not one-to-one ends the trace with that
//! reason.
//!
//! The pull-off is the first extremum of F̄ (load control: located by
//! golden-section search on F̄) or of δ̄ (displacement control: Illinois on
//! dδ̄/dσ). Folds in ā passed on the way are reported.
//!
//! Owns: [`Extremum`], [`to_extremum`], [`to_nearby_extremum`],
//! [`to_force_on_the_pull_off_arm`], [`crossings`], [`Curve`], [`CurveFold`], [`curve`], [`curve_each`].
//! May use: `fold`, `control` (the quantity a crossing watches),
//! the parent module,
//! `equations` (the family of the one model interface), `continuation`,
//! `curve` (fold kinds, the bound on points), `error`, nalgebra.

use super::Conformal;
use crate::continuation::{self, End, EventKind, Family, On, Settings, Watch};
use crate::equations::{unit_scale, Branch};
use crate::error::{short, Error, Result};
use crate::fold::FoldCondition;
use nalgebra::{DVector, Dyn};
use serde::Serialize;

/// A fold in ā passed by the trace, before the pull-off.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Extremum {
    /// ā at the fold (to the trace's step).
    pub a_bar: f64,
    /// F̄ there.
    pub force_bar: f64,
}

/// The branch of one member at one ρ: the solver's one model interface's
/// family ([`crate::equations::Branch`]) in u = (c, δ̄), unscaled; with
/// `strict`, a state whose map is not one-to-one ends the trace with that
/// error.
fn branch(m: &Conformal, rho: f64, strict: bool) -> Branch<'_, Conformal> {
    Branch {
        equations: m,
        rho,
        scale: unit_scale(m),
        strict,
    }
}

/// Trace from `x0` towards smaller ā to the first extremum of F̄ or δ̄.
/// Returns the extremum's x and the folds in ā passed before it.
pub(crate) fn to_extremum(
    m: &Conformal,
    x0: &DVector<f64>,
    rho: f64,
    control: FoldCondition,
) -> Result<(DVector<f64>, Vec<Extremum>)> {
    // towards smaller ā = Σ c_k
    let towards = -branch(m, rho, true).a_bar_gradient();
    extremum_along(m, x0, rho, control, &towards, f64::INFINITY)
}

/// Trace from `x0` near an extremum of F̄ (load) or δ̄ (displacement) to
/// it: towards falling F̄ or δ̄, no farther than `reach` in ā.
pub(crate) fn to_nearby_extremum(
    m: &Conformal,
    x0: &DVector<f64>,
    rho: f64,
    control: FoldCondition,
    reach: f64,
) -> Result<(DVector<f64>, Vec<Extremum>)> {
    let family = branch(m, rho, true);
    let towards = match control {
        FoldCondition::Load => -family
            .linearise(x0)
            .map(|l| l.force_grad)
            .ok_or_else(|| stuck(m, x0, rho, "the equations are not defined at the start"))?,
        FoldCondition::Displacement => -family.delta_bar_gradient(),
        FoldCondition::ContactSize => -family.a_bar_gradient(),
    };
    extremum_along(m, x0, rho, control, &towards, reach)
}

/// The step control of a trace along an arm to an event (an extremum, a
/// crossing): steps from 0.02 up to 0.1 in the family's scaled unknowns.
const ARM: Settings = Settings {
    step: 0.02,
    min_step: 1e-10,
    max_step: 0.1,
    grow: 1.3,
    fast_iterations: 3,
    turn: 0.995,
    corrector_iterations: 12,
    step_tolerance: 1e-12,
    max_steps: 20_000,
};

fn extremum_along(
    m: &Conformal,
    x0: &DVector<f64>,
    rho: f64,
    control: FoldCondition,
    towards: &DVector<f64>,
    reach: f64,
) -> Result<(DVector<f64>, Vec<Extremum>)> {
    let n = x0.len();
    let family = branch(m, rho, true);
    let a0: f64 = x0.rows(0, n - 1).sum();
    let (force_minimum, displacement_fold, size_fold) = match control {
        FoldCondition::Load => (On::Stop, On::Ignore, On::Note),
        FoldCondition::Displacement => (On::Ignore, On::Stop, On::Note),
        FoldCondition::ContactSize => (On::Ignore, On::Ignore, On::Stop),
    };
    let watch = Watch {
        size_fold,
        displacement_fold,
        force_minimum,
        bifurcation: On::Ignore,
        crossing: None,
    };
    let trace = continuation::trace(&family, x0.clone(), towards, ARM, watch, |p| {
        p.a_bar < 0.3 || (p.a_bar - a0).abs() > reach
    })?;
    let folds = trace
        .events
        .iter()
        .filter(|e| e.kind == EventKind::SizeFold)
        .map(|e| {
            let q = &trace.points[e.between[1]];
            Extremum {
                a_bar: q.a_bar,
                force_bar: q.force,
            }
        })
        .collect();
    let wanted = match control {
        FoldCondition::Load => EventKind::ForceMinimum,
        FoldCondition::Displacement => EventKind::DisplacementFold,
        FoldCondition::ContactSize => EventKind::SizeFold,
    };
    match (trace.end, trace.located(wanted)) {
        (End::Event(_), Some(x)) => Ok((x.clone(), folds)),
        _ => {
            let last = &trace.points.last().expect("one point").u;
            Err(stuck(
                m,
                last,
                rho,
                "no extremum before the contact vanished or the step budget ended",
            ))
        }
    }
}

/// Trace from `x0` along the arm its pull-off trace follows
/// ([`to_extremum`] under load control) to where F̄ crosses `force`:
/// towards smaller ā (`smaller`) up to the arm's first minimum of F̄ (the
/// pull-off), or towards larger ā up to twice the start's ā. The crossing,
/// located, or `None` where the trace ends there before it crosses; an
/// error where the step budget ends it.
pub(crate) fn to_force_on_the_pull_off_arm(
    m: &Conformal,
    x0: &DVector<f64>,
    rho: f64,
    force: f64,
    smaller: bool,
) -> Result<Option<DVector<f64>>> {
    let family = branch(m, rho, true);
    let sign = if smaller { -1.0 } else { 1.0 };
    let towards = family.a_bar_gradient() * sign;
    let a0: f64 = x0.rows(0, x0.len() - 1).sum();
    let watch = Watch {
        size_fold: On::Note,
        displacement_fold: On::Ignore,
        force_minimum: if smaller { On::Stop } else { On::Ignore },
        bifurcation: On::Ignore,
        crossing: Some((crate::control::Quantity::Force, force, On::Stop)),
    };
    let trace = continuation::trace(&family, x0.clone(), &towards, ARM, watch, |p| {
        p.a_bar < 0.3 || p.a_bar > 2.0 * a0
    })?;
    let trace = within_budget(m, rho, trace, "the force")?;
    Ok(trace.located(EventKind::Crossing).cloned())
}

/// `trace`, or, where the step budget ended it, the error that says where
/// it stopped before `what` was crossed.
fn within_budget(
    m: &Conformal,
    rho: f64,
    trace: continuation::Trace<Dyn>,
    what: &str,
) -> Result<continuation::Trace<Dyn>> {
    if trace.end != End::Budget {
        return Ok(trace);
    }
    let last = &trace.points.last().expect("one point").u;
    Err(stuck(
        m,
        last,
        rho,
        &format!("the step budget ran out before {what} was crossed"),
    ))
}

/// Every crossing of `quantity` = `value`, located, along the branch
/// traced from `x0` towards larger ā up to ā = `a_limit` (`larger`), or
/// towards smaller ā until the contact vanishes (ā < 0.3), in the order
/// met; the trace ends where the map stops being one-to-one (a crossing
/// past that is no contact). An error where the step budget ends it.
pub(crate) fn crossings(
    m: &Conformal,
    x0: &DVector<f64>,
    rho: f64,
    (quantity, value): (crate::control::Quantity, f64),
    larger: bool,
    a_limit: f64,
) -> Result<Vec<DVector<f64>>> {
    let family = branch(m, rho, false);
    let towards = family.a_bar_gradient() * if larger { 1.0 } else { -1.0 };
    let watch = Watch {
        size_fold: On::Ignore,
        displacement_fold: On::Ignore,
        force_minimum: On::Ignore,
        bifurcation: On::Ignore,
        crossing: Some((quantity, value, On::Locate)),
    };
    let k = x0.len() - 1;
    let contact = |u: &DVector<f64>| m.univalence(&u.as_slice()[..k]).is_ok();
    let trace = continuation::trace(&family, x0.clone(), &towards, ARM, watch, |p| {
        p.a_bar < 0.3 || p.a_bar > a_limit || !contact(&p.u)
    })?;
    Ok(within_budget(m, rho, trace, "the value")?
        .events
        .iter()
        .filter(|e| e.kind == EventKind::Crossing)
        .filter_map(|e| e.at.clone())
        .filter(|u| contact(u))
        .collect())
}

fn stuck(m: &Conformal, x: &DVector<f64>, rho: f64, why: &str) -> Error {
    let k = x.len() - 1;
    let (a, b) = m.semi_axes(&x.as_slice()[..k]);
    Error::NoState(format!(
        "the {} branch at rho = {} stopped at a_bar = {:.4}, s = {:.4}: {why}",
        m.name(),
        short(rho),
        a,
        b / a
    ))
}

/// A fold of a `conformal:K` curve.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct CurveFold {
    /// Which quantity turns.
    pub kind: crate::curve::FoldKind,
    /// The state there (located by the engine; a fold in ā at the traced
    /// point after it).
    pub state: super::ConformalState,
}

/// A traced `conformal:K` curve.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Curve {
    /// States in order along each arm, the arm of large contacts first.
    pub states: Vec<super::ConformalState>,
    /// The index of the arm of each state (0: from large contacts; 1: the
    /// arm that carries the load-controlled pull-off, where that is
    /// another arm).
    pub arm: Vec<usize>,
    /// Whether each state lies beyond the first fold in ā met from where
    /// its arm was started (the contour grows undulated there).
    pub beyond_size_fold: Vec<bool>,
    /// The folds met on the way.
    pub folds: Vec<CurveFold>,
    /// How each arm ends, in words.
    pub end: String,
}

/// The smallest ā a curve is traced to.
const CURVE_A_MIN: f64 = 0.5;

/// One arm: its points, whether each lies beyond the first fold in ā, the
/// folds on it (as (kind, x)), and how it ends.
struct Arm {
    points: Vec<continuation::Point<Dyn>>,
    beyond: Vec<bool>,
    folds: Vec<(crate::curve::FoldKind, DVector<f64>)>,
    end: String,
}

/// Trace one arm from `x0` along `towards` past its folds until ā <
/// [`CURVE_A_MIN`] or above `a_max` or the first state whose map is not
/// one-to-one (not returned: past its folds in ā the contour grows
/// undulated until it is no contact), or whose contour is wider across
/// than along where its gap makes the states longer along
/// ([`super::Family::wider_than_its_gap_allows`]; not returned either).
fn arm(
    m: &Conformal,
    rho: f64,
    x0: DVector<f64>,
    towards: &DVector<f64>,
    settings: Settings,
    a_max: f64,
) -> Result<Arm> {
    let n = x0.len();
    let family = branch(m, rho, false);
    let watch = Watch {
        size_fold: On::Note,
        displacement_fold: On::Locate,
        force_minimum: On::Locate,
        bifurcation: On::Ignore,
        crossing: None,
    };
    let mut broke = None;
    let mut wider = None;
    let traced = continuation::trace(&family, x0, towards, settings, watch, |p| {
        let c = &p.u.as_slice()[..n - 1];
        if let Err(e) = m.univalence(c) {
            broke = Some(e);
            return true;
        }
        // b̄ > ā where the gap makes the near-elliptic states longer
        // along: not the state the family approximates (the rule every
        // state's warnings apply)
        let (a, b) = m.semi_axes(c);
        if let Some(s) = m.family().wider_than_its_gap_allows(rho, a, b) {
            wider = Some(s);
            return true;
        }
        p.a_bar < CURVE_A_MIN || p.a_bar > a_max
    })?;
    let mut pts = traced.points;
    let end = match (&broke, wider, traced.end) {
        (Some(e), _, _) => {
            pts.pop();
            format!("the map stops being one-to-one ({e})")
        }
        (None, Some(s), _) => {
            pts.pop();
            format!(
                "the contour turns wider across than along (s = {}), not the near-elliptic state the family approximates",
                crate::error::rounded(s)
            )
        }
        (None, None, End::Until) => {
            let q = pts.last().expect("one point");
            format!("it reaches a = {:.4}, the end of the traced range", q.a_bar)
        }
        (None, None, _) => {
            let last = &pts.last().expect("one point").u;
            return Err(stuck(m, last, rho, "the curve's step budget ended"));
        }
    };
    let kept = pts.len();
    let mut folds = Vec::new();
    for e in &traced.events {
        if e.between[1] >= kept {
            continue;
        }
        let kind = match e.kind {
            EventKind::SizeFold => crate::curve::FoldKind::ContactSize,
            EventKind::DisplacementFold => crate::curve::FoldKind::Displacement,
            EventKind::ForceMinimum => crate::curve::FoldKind::Load,
            _ => continue,
        };
        let x = e.at.clone().unwrap_or_else(|| pts[e.between[1]].u.clone());
        folds.push((kind, x));
    }
    let first_fold = traced
        .events
        .iter()
        .find(|e| e.kind == EventKind::SizeFold)
        .map(|e| e.between[1]);
    let beyond = (0..kept)
        .map(|k| first_fold.is_some_and(|f| k >= f))
        .collect();
    Ok(Arm {
        points: pts,
        beyond,
        folds,
        end,
    })
}

/// The curve of one member at ρ: the arm from δ̄ = `delta_start` downwards
/// and, where the load-controlled pull-off lies on another arm (each
/// mode's imperfect bifurcation splits the family for ρ < 1), that arm,
/// traced both ways from its state at ā = [`Conformal::trace_start`]
/// (continued in ρ from the circle); each arm past its folds until its
/// contour is no longer one-to-one, or back above the contact it started
/// from. `points` states in all, spaced evenly
/// in arclength and shared among the arms by length.
pub(crate) fn curve(m: &Conformal, rho: f64, points: usize, delta_start: f64) -> Result<Curve> {
    let (mut states, mut arm, mut beyond_size_fold) = (Vec::new(), Vec::new(), Vec::new());
    let (folds, end) = curve_each(m, rho, points, delta_start, &mut |st, a, beyond| {
        states.push(st);
        arm.push(a);
        beyond_size_fold.push(beyond);
        Ok(())
    })?;
    Ok(Curve {
        states,
        arm,
        beyond_size_fold,
        folds,
        end,
    })
}

/// [`curve`], handing each state to `each` in order as it is made, with
/// its arm and whether it lies beyond its arm's first fold in ā; returns
/// the folds and how the arms end. The arms are traced and their folds
/// located first, then the states are made one at a time, so nothing of
/// the size of `points` is kept (the command line streams them). Where
/// more points are asked for than the trace was made for (its step is at
/// least 1e-3), each is corrected onto its own arclength from the traced
/// point before it ([`continuation::at_arclength`]). An error of `each`
/// ends the curve with it.
pub(crate) fn curve_each(
    m: &Conformal,
    rho: f64,
    points: usize,
    delta_start: f64,
    each: &mut dyn FnMut(super::ConformalState, usize, bool) -> Result<()>,
) -> Result<(Vec<CurveFold>, String)> {
    let start = m.solve(rho, super::Hold::Delta(delta_start))?;
    let mut x0 = DVector::from_vec(start.coefficients.clone());
    x0 = x0.push(start.delta_bar);
    let n = x0.len();
    let family = branch(m, rho, false);
    let mut down = DVector::zeros(n);
    down[n - 1] = -1.0;
    // at least four traced points per output point
    let max_step = (0.25 * (start.a_bar + delta_start.abs()) / points as f64).clamp(1e-3, 0.1);
    // the most points the trace is made fine enough for
    let traced_for = (0.25 * (start.a_bar + delta_start.abs()) / 1e-3).floor() as usize;
    let settings = Settings {
        step: max_step.min(0.02),
        min_step: 1e-10,
        max_step,
        grow: 1.3,
        fast_iterations: 3,
        turn: 0.995,
        corrector_iterations: 12,
        step_tolerance: 1e-12,
        max_steps: 20_000.max(50 * points),
    };
    // no arm is followed back above the contact it starts from
    let a_max = start.a_bar;
    let first = arm(m, rho, x0, &down, settings, a_max)?;
    let mut folds = first.folds.clone();
    let mut ends = vec![format!("the arm from large contacts: {}", first.end)];
    let has_pull_off = folds
        .iter()
        .any(|(k, _)| *k == crate::curve::FoldKind::Load);
    // the arm from large contacts passes ā = 2.6 on its near-elliptic
    // stretch (before its first fold): it is the pull-off arm
    let passes_seed = first
        .points
        .iter()
        .zip(&first.beyond)
        .any(|(p, &b)| !b && p.a_bar <= m.trace_start());
    let mut arms = vec![(first.points, first.beyond)];
    if !(has_pull_off && passes_seed) {
        match m.solve(rho, super::Hold::Size(m.trace_start())) {
            Ok(seed) => {
                let mut x = DVector::from_vec(seed.coefficients.clone());
                x = x.push(seed.delta_bar);
                let up = family.a_bar_gradient();
                let upper = arm(m, rho, x.clone(), &up, settings, a_max)?;
                let lower = arm(m, rho, x, &-up, settings, a_max)?;
                let mut pts: Vec<_> = upper.points.into_iter().rev().collect();
                let mut beyond: Vec<bool> = upper.beyond.into_iter().rev().collect();
                // the seed is the first of the lower part
                pts.pop();
                beyond.pop();
                pts.extend(lower.points);
                beyond.extend(lower.beyond);
                arms.push((pts, beyond));
                folds.extend(upper.folds);
                folds.extend(lower.folds);
                ends.push(format!(
                    "the pull-off arm through a = {}: upwards {}; downwards {}",
                    crate::error::short(m.trace_start()),
                    upper.end,
                    lower.end
                ));
            }
            Err(e) => ends.push(format!(
                "no pull-off arm through a = {}: {e}",
                crate::error::short(m.trace_start())
            )),
        }
    }
    let folds = folds
        .into_iter()
        .map(|(kind, x)| {
            Ok(CurveFold {
                kind,
                state: m.state(&x, rho)?,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    // each arm spaced evenly in arclength, the points shared by length
    let trails: Vec<Vec<DVector<f64>>> = arms
        .iter()
        .map(|(pts, _)| pts.iter().map(|p| p.u.clone()).collect())
        .collect();
    let length = |t: &[DVector<f64>]| t.windows(2).map(|w| (&w[1] - &w[0]).norm()).sum::<f64>();
    let total: f64 = trails.iter().map(|t| length(t)).sum();
    let family = branch(m, rho, false);
    let mut left = points;
    for (i, ((pts, beyond), trail)) in arms.iter().zip(&trails).enumerate() {
        let share = if i + 1 == arms.len() {
            left
        } else {
            (((points as f64) * length(trail) / total.max(f64::MIN_POSITIVE)).round() as usize)
                .clamp(2.min(left), left)
        };
        left -= share;
        for (j, sigma) in continuation::spaced(trail, share) {
            if points <= traced_for || sigma == 0.0 {
                each(m.state(&pts[j].u, rho)?, i, beyond[j])?;
            } else {
                let (p, q) = (&pts[j], &pts[j + 1]);
                let x = continuation::at_arclength(&family, settings, p, q, sigma)?;
                let past =
                    beyond[j] || (beyond[j + 1] && continuation::past_size_fold(p, q, sigma));
                each(m.state(&x, rho)?, i, past)?;
            }
        }
    }
    Ok((folds, ends.join("; ")))
}
