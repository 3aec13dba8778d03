//! The band map of the near-elliptic exact family at one ρ: the intervals
//! of the contact size ā where no near-elliptic exact state exists, each
//! with the contour mode responsible and F̄, δ̄ at both edges.
//!
//! At ρ = 1 the circle branch meets, at each neutral point ā³ = 4(n − 1),
//! the branch of contours undulated with cos nθ; for ρ < 1 the crossing is
//! imperfect and the near-elliptic family can split there: the arm from
//! smaller ā folds back at ā₁, the arm from larger ā at ā₂, and when
//! ā₁ < ā₂ no near-elliptic state has a size in between (docs/exact.md,
//! "Which family"). Pieces of the family can also lie in such a gap
//! without joining either arm, so the gaps are not read off two traces:
//! - a screen: the richest `conformal:K`'s states at fixed ā (each
//!   continued in ρ from the circle at its ā) on a grid of step 0.01; a
//!   grid point is near-elliptic when that state exists with a defect of
//!   (3)₂ below 1e-2. Runs of points that are not bound candidate gaps.
//! - each candidate is settled by the exact family itself: from the exact
//!   state at the last near-elliptic grid point on either side (started
//!   from the model's ellipse, with the first truncation of the default
//!   escalation that resolves it) the family is traced into the gap
//!   (steps of at most 0.01 in its unknowns) to its first fold in ā,
//!   located. Both arms folding, the lower fold below the upper, make a
//!   band; an arm that crosses the gap without folding, or folds that
//!   overlap, mean near-elliptic states exist across it (the model's gap
//!   is its own), and the candidate is reported as such.
//! - a band narrower than the screen's step can pass between two grid
//!   points; bands sit at the circle's neutral points, so each neutral
//!   point the screen passed without a gap is probed by the exact family
//!   in the same way, in steps of `PROBE_STEP` (`report::Probe`).
//!
//! The map also carries F̄(ā) of the model and of the exact family over
//! the screen (`report::CurvePoint`), for the figure.
//!
//! [`states_at`] uses the same screen to find every near-elliptic exact
//! state at a given δ̄ or F̄. A band is an interval of ā, not of F̄ or δ̄:
//! past its fold an arm goes on along a returning stretch whose contour
//! undulates more and more with the band's mode, and its load and approach
//! go on changing there (the load-controlled pull-off lies on such a
//! stretch just past the mode-4 band). So a state at given F̄ or δ̄ is also
//! looked for on the arms beside a gap traced past their folds
//! (`past_folds_or_band`, [`states_at`]).
//!
//! The map itself is drawn by the study `studies::band_map` (`thinjkr
//! exact bands`) from the screen and the settling here; its record
//! (`report::BandMap`) is the command line's output.
//!
//! Owns: [`BandEdge`], [`Band`], `screen`, `settle`, [`states_at`],
//! `past_folds_or_band`. May use: `control`, `exact`
//! (its family and traces; the screen by the gap's seed, `exact::seed`),
//! `error`, `newton` (the caller's stop flag, carried to rayon's threads),
//! `progress` (the gap being settled), rayon.

use super::ladder::Ladder;
use super::same::Same;
use super::seed::Guess;
use super::{Contour, Exact};
use crate::control::Hold;
use crate::error::{Error, Result};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// The most grid points of a screen.
pub(crate) const MAX_GRID: usize = 1000;

/// One edge of a band: the located fold in ā of an arm of the exact
/// family.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct BandEdge {
    /// ā at the fold.
    pub a_bar: f64,
    /// s there.
    pub s: f64,
    /// F̄ there.
    pub force_bar: f64,
    /// δ̄ there.
    pub delta_bar: f64,
    /// The contour mode n (cos nθ) of the fold's null direction (0 where
    /// the size or δ̄ dominates; `None` when it could not be computed).
    pub mode: Option<usize>,
    /// max |∂p̄/∂ν − 1| of the fold state on the fine grid.
    pub bc_error: f64,
    /// Contour modes N of the truncation used.
    pub modes: usize,
}

/// An interval of ā with no near-elliptic exact state.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Band {
    /// The fold of the arm from smaller ā (the band's lower edge).
    pub lower: BandEdge,
    /// The fold of the arm from larger ā (the band's upper edge).
    pub upper: BandEdge,
}

/// The model's near-elliptic states at fixed ā on the grid from `from` to
/// `to` in steps of [`STEP`] (`None` where there is none), with the grid
/// and the model.
#[allow(clippy::type_complexity)]
pub(crate) fn screen(
    gap: super::Gap,
    rho: f64,
    from: f64,
    to: f64,
) -> Result<(&'static dyn super::seed::Seed, Vec<f64>, Vec<Option<Guess>>)> {
    // the grid's size is bounded before it is computed (a `to` of 1e300
    // must not overflow the count, nor wrap to an empty screen)
    let steps = ((to - from) / STEP).round();
    crate::error::check_range(
        "to",
        to,
        steps.is_finite() && steps >= 0.0 && steps < MAX_GRID as f64,
        "at most from + 9.99 (a screen of at most 1000 grid points)",
    )?;
    let count = steps as usize + 1;
    let model = gap.seed.ok_or_else(|| {
        Error::NoState(format!(
            "no contour family in the registry seeds the exact solver of the gap {}",
            gap.name
        ))
    })?;
    let grid: Vec<f64> = (0..count).map(|j| from + STEP * j as f64).collect();
    let stop = crate::newton::stop_flag();
    let answers: Vec<Result<Guess>> = grid
        .par_iter()
        .map(|&a| {
            crate::newton::carried(stop.clone(), || {
                crate::newton::check_stop()?;
                model.state(rho, Hold::Size(a))
            })
        })
        .collect();
    // a seed that answers nowhere (ρ below its range) says why
    if let Some(Err(why)) = answers
        .iter()
        .find(|a| a.is_err())
        .filter(|_| answers.iter().all(|a| a.is_err()))
    {
        return Err(Error::NoState(format!(
            "the screen of {} has no state in it: {}",
            model.name(),
            why.detail()
        )));
    }
    let states = answers
        .into_iter()
        .map(|a| a.ok().filter(|st| st.bc_defect < 1e-2))
        .collect();
    Ok((model, grid, states))
}

/// A run of grid points without a near-elliptic state.
pub(crate) enum Gap {
    /// Bracketed by the near-elliptic points lo and hi.
    Inside(usize, usize),
    /// At an end of the grid: its first and last points (the band map's
    /// open ends).
    #[cfg_attr(not(feature = "cli"), allow(dead_code))]
    AtEnd(usize, usize),
}

/// The runs of grid points without a near-elliptic state.
pub(crate) fn gaps(states: &[Option<Guess>]) -> Vec<Gap> {
    let (count, mut out, mut j) = (states.len(), Vec::new(), 0);
    while j < count {
        if states[j].is_some() {
            j += 1;
            continue;
        }
        let start = j;
        while j < count && states[j].is_none() {
            j += 1;
        }
        out.push(match (start.checked_sub(1), (j < count).then_some(j)) {
            (Some(lo), Some(hi)) => Gap::Inside(lo, hi),
            (lo, hi) => Gap::AtEnd(lo.unwrap_or(start), hi.unwrap_or(count - 1)),
        });
    }
    out
}

/// The model's near-elliptic states beside the gap between lo and hi,
/// nearest first, up to five grid points away on either side (an exact
/// start that fails next to the gap may succeed a little further out).
#[allow(clippy::type_complexity)]
pub(crate) fn beside(states: &[Option<Guess>], lo: usize, hi: usize) -> (Vec<&Guess>, Vec<&Guess>) {
    (
        states[..=lo]
            .iter()
            .rev()
            .take(5)
            .map_while(|s| s.as_ref())
            .collect(),
        states[hi..]
            .iter()
            .take(5)
            .map_while(|s| s.as_ref())
            .collect(),
    )
}

/// The grid step of the screen in ā.
pub(crate) const STEP: f64 = 0.01;

/// How far beyond a gap's far side, in ā, an arm traced into the gap may go
/// before it is said to cross the gap without folding.
const BEYOND_GAP: f64 = 0.05;

/// The step (in the family's unknowns) of the traces that probe the
/// neutral points: at ρ = 0.9 the mode-8 band is 0.003 wide in ā
/// (3.0435 < ā < 3.0464), and a trace in steps of 0.01 can step across it.
pub(crate) const PROBE_STEP: f64 = 0.002;

/// The circle's neutral points ā_n = (4(n − 1))^(1/3), n even, 0.1 or
/// more inside `range` and 0.1 or more from every interval of `found` (the
/// gaps the screen found), each with the model's near-elliptic states on
/// the grid 0.05 or more below it and above it (up to five each, nearest
/// first, consecutive).
#[allow(clippy::type_complexity)]
pub(crate) fn unscreened_neutral_points<'a>(
    circle: &super::gap::GapAt,
    range: [f64; 2],
    grid: &[f64],
    states: &'a [Option<Guess>],
    found: &[[f64; 2]],
) -> Vec<(usize, f64, Vec<&'a Guess>, Vec<&'a Guess>)> {
    let [from, to] = range;
    (2..=200)
        .step_by(2)
        .map(|n| (n, circle.neutral_point(n)))
        .take_while(|&(_, a_n)| a_n <= to - 0.1)
        .filter(|&(_, a_n)| {
            a_n >= from + 0.1 && !found.iter().any(|w| a_n > w[0] - 0.1 && a_n < w[1] + 0.1)
        })
        .map(|(n, a_n)| {
            let left = grid
                .iter()
                .zip(states)
                .rev()
                .filter(|(a, _)| **a <= a_n - 0.05)
                .take(5)
                .map_while(|(_, s)| s.as_ref())
                .collect();
            let right = grid
                .iter()
                .zip(states)
                .filter(|(a, _)| **a >= a_n + 0.05)
                .take(5)
                .map_while(|(_, s)| s.as_ref())
                .collect();
            (n, a_n, left, right)
        })
        .collect()
}

/// Every near-elliptic exact state at `control` with ā in [`from`, `to`]:
/// where the screening model's (`conformal:8`'s) value of the control
/// crosses the target between two neighbouring grid points of the screen
/// (step 0.01), the exact state by Newton with the control held, from the
/// ellipse of the model's state nearer the target, with the truncations
/// `tries` escalated as for every exact state (`super::resolved`); kept
/// when resolved and within one grid step of the bracket. Sorted by ā, one
/// per state (answers within 1e-6 in ā are one). The states on the arms
/// beside each gap of the screen, traced through their folds and on along
/// their returning stretches (`past_folds`), are added. Brackets where
/// Newton fails, and crossings past a fold that do not converge, are
/// reported in `missed` (ā and why).
pub fn states_at(
    rho: f64,
    control: crate::control::Hold,
    from: f64,
    to: f64,
    tries: &[super::Truncation],
) -> Result<AllStates> {
    states_at_on(
        super::Gap::cylinders(),
        rho,
        control,
        from,
        to,
        &Ladder::of(tries.to_vec()),
    )
}

/// [`states_at`] on `gap`.
pub(crate) fn states_at_on(
    gap: super::Gap,
    rho: f64,
    control: crate::control::Hold,
    from: f64,
    to: f64,
    ladder: &Ladder,
) -> Result<AllStates> {
    crate::error::check_range("rho", rho, rho > 0.0 && rho <= 1.0, "(0, 1]")?;
    crate::error::check_range("from", from, from.is_finite() && from > 0.5, "(0.5, to)")?;
    crate::error::check_range("to", to, to.is_finite() && to > from, "(from, from + 10]")?;
    let (_, grid, states) = screen(gap, rho, from, to)?;
    let value = |m: &Guess| control.excess(m.a_bar, m.delta_bar, m.force_bar);
    let brackets: Vec<(&Guess, &Guess)> = states
        .windows(2)
        .filter_map(|w| match (&w[0], &w[1]) {
            (Some(l), Some(r)) if value(l) * value(r) <= 0.0 && value(l) != value(r) => {
                Some((l, r))
            }
            _ => None,
        })
        .collect();
    let stop = crate::newton::stop_flag();
    let answers: Vec<(f64, Result<super::ExactState>)> = brackets
        .par_iter()
        .map(|&(l, r)| crate::newton::carried(stop.clone(), || {
            let start = if value(l).abs() <= value(r).abs() { l } else { r };
            let found = super::resolved(gap, rho, ladder, |ex| {
                ex.solve_at(
                    control,
                    &Contour::ellipse(start.a_bar, start.b_bar, ex.truncation().modes),
                    start.delta_bar,
                )
            })
            .and_then(|mut st| {
                if st.a_bar >= l.a_bar - STEP && st.a_bar <= r.a_bar + STEP {
                    st.route = super::Route::FromScreen;
                    Ok(st)
                } else {
                    Err(Error::NoState(format!(
                        "Newton from the model's state at a = {:.2} landed at a = {:.4}, outside the bracket",
                        start.a_bar, st.a_bar
                    )))
                }
            });
            (0.5 * (l.a_bar + r.a_bar), found)
        }))
        .collect();
    // the arms beside each gap of the screen, traced past their folds
    let past: Vec<PastFolds> = gaps(&states)
        .into_iter()
        .filter_map(|gap| match gap {
            Gap::Inside(lo, hi) => Some(beside(&states, lo, hi)),
            Gap::AtEnd(..) => None,
        })
        .collect::<Vec<_>>()
        .par_iter()
        .map(|(left, right)| {
            crate::newton::carried(stop.clone(), || {
                past_folds(gap, rho, control, left, right, STEP, ladder)
            })
        })
        .collect();
    let mut out = AllStates {
        range: [from, to],
        screen: grid.len(),
        states: Vec::new(),
        missed: Vec::new(),
    };
    let answers = answers
        .into_iter()
        .map(|(a, found)| (a, found.map_err(|e| e.to_string())))
        .chain(past.into_iter().flat_map(|p| {
            let missed = p.missed.into_iter().map(|(a, why)| (a, Err(why)));
            p.states
                .into_iter()
                .map(|st| (st.a_bar, Ok(st)))
                .chain(missed)
                .collect::<Vec<_>>()
        }));
    for (a, found) in answers {
        match found {
            Ok(st) => {
                if !out
                    .states
                    .iter()
                    .any(|o: &super::ExactState| Same::FOUND_TWICE.of(o, &st))
                {
                    out.states.push(st);
                }
            }
            Err(why) => out.missed.push((a, why)),
        }
    }
    out.states.sort_by(|x, y| x.a_bar.total_cmp(&y.a_bar));
    Ok(out)
}

/// What [`states_at`] found.
#[derive(Clone, Debug)]
pub struct AllStates {
    /// The ā range screened.
    pub range: [f64; 2],
    /// Grid points screened.
    pub screen: usize,
    /// The exact states, by increasing ā.
    pub states: Vec<super::ExactState>,
    /// Brackets of the screen where no state was accepted: their ā and why.
    pub missed: Vec<(f64, String)>,
}

/// The exact state at `control` where no route found one (`err`, from
/// [`super::resolve::at_with`] climbing the ladder): on the arms beside
/// each gap of the model's screen (ā within 15 % of the circle's ā at that
/// control, `a_circle`) whose neighbours' values of the control lie on
/// either side of it, traced through their folds and on along their
/// returning stretches ([`past_folds`]); of several, the one nearest an
/// ellipse. Where there is none and a band's edges bracket the control,
/// an error that says so in words (the band, its mode, the values at its
/// edges, and how far its arms were followed past their folds); otherwise
/// `err` itself.
pub(crate) fn past_folds_or_band(
    gap: super::Gap,
    rho: f64,
    control: crate::control::Hold,
    a_circle: f64,
    ladder: &Ladder,
    err: Error,
) -> Result<super::ExactState> {
    use crate::control::Hold;
    if !(matches!(err, Error::NoState(_)) && rho > 0.0 && rho < 1.0 && a_circle > 1.0) {
        return Err(err);
    }
    type Of<T> = fn(&T) -> f64;
    let (target, of_state, of_edge, name): (f64, Of<Guess>, Of<BandEdge>, &str) = match control {
        Hold::Force(f) => (f, |s| s.force_bar, |e| e.force_bar, "force"),
        Hold::Delta(d) => (d, |s| s.delta_bar, |e| e.delta_bar, "delta"),
        Hold::Size(a) => (a, |s| s.a_bar, |e| e.a_bar, "a"),
    };
    let range = [0.85 * a_circle, 1.15 * a_circle];
    let Ok((_, grid, states)) = screen(gap, rho, range[0], range[1]) else {
        return Err(err);
    };
    // the screen's gaps, then the neutral points it passed (narrow bands)
    let mut brackets = Vec::new();
    let mut found = Vec::new();
    for hole in gaps(&states) {
        let Gap::Inside(lo, hi) = hole else { continue };
        found.push([grid[lo], grid[hi]]);
        let (left, right) = beside(&states, lo, hi);
        brackets.push((left, right, STEP));
    }
    for (_, _, left, right) in
        unscreened_neutral_points(&gap.at(1.0)?, range, &grid, &states, &found)
    {
        if !left.is_empty() && !right.is_empty() {
            brackets.push((left, right, PROBE_STEP));
        }
    }
    brackets.retain(|(left, right, _)| {
        (of_state(left[0]) - target) * (of_state(right[0]) - target) <= 0.0
    });
    // the states past the arms' folds first
    let mut past = Vec::new();
    let mut followed = Vec::new();
    for (left, right, step) in &brackets {
        let found = past_folds(gap, rho, control, left, right, *step, ladder);
        past.extend(found.states);
        followed.extend(found.followed);
        followed.extend(found.missed.into_iter().map(|(_, why)| why));
    }
    if let Some(st) = past.into_iter().min_by(|x, y| {
        x.deviation_from_ellipse
            .total_cmp(&y.deviation_from_ellipse)
    }) {
        return Ok(st);
    }
    // none: a band whose edges bracket the value is the reason
    for (left, right, step) in brackets {
        if let Ok(Ok(band)) = settle(gap, rho, &left, &right, step) {
            let (v0, v1) = (of_edge(&band.lower), of_edge(&band.upper));
            if (v0 - target) * (v1 - target) <= 0.0 {
                let mode = band
                    .lower
                    .mode
                    .map(|n| format!(", mode cos {n}θ"))
                    .unwrap_or_default();
                return Err(Error::InBand(format!(
                    "no near-elliptic exact state at {control} for rho = {}: that {name} lies in the band {:.4} < a < {:.4}{mode} (its edges, where the family folds back, have {name} = {:.4} and {:.4}), and no arm beside it, followed past its fold, reaches it converged ({})",
                    crate::error::short(rho),
                    band.lower.a_bar,
                    band.upper.a_bar,
                    v0,
                    v1,
                    followed.join("; ")
                )));
            }
        }
    }
    Err(err)
}

/// The exact states at `control` on the two arms beside the gap between
/// the model's near-elliptic states `left` and `right` (nearest first),
/// each traced into the gap through its first fold and on past it
/// ([`Exact::crossings_past_fold`], steps of at most `step`), from the
/// exact state at the first of them where Newton converges, with the first
/// rung of `ladder` that converges it (boundary error ≤
/// [`super::CONVERGED`]; a single truncation: ≤ [`super::RESOLVED`]),
/// until ā passes [`BEYOND_GAP`] beyond the gap's far side. Each crossing
/// is solved again by Newton at the control with the rungs of `ladder`
/// from its own on ([`super::resolved`]), and kept when that state lies
/// where the trace crossed ([`Same::AT_THE_CROSSING`]); route
/// [`super::Route::PastFold`]. Where `ladder` is an escalation (more than
/// one rung), the arclength representation's rungs above its last follow it,
/// for the start and the crossings alike: an escalation's answer is
/// converged, and a single rung left of it would be answered as a user's
/// choice of modes, resolved only (at F̄ = 0 for ρ = 0.36 the conformal
/// form's 96 modes leave 3e-7, at ρ = 0.35 the lower arm's start 7.5e-8).
fn past_folds(
    gap: super::Gap,
    rho: f64,
    control: crate::control::Hold,
    left: &[&Guess],
    right: &[&Guess],
    step: f64,
    ladder: &Ladder,
) -> PastFolds {
    let mut out = PastFolds::default();
    let escalation = ladder.rungs().len() > 1;
    let ladder = match escalation {
        true => {
            let above = ladder.top_modes() + 1;
            ladder.clone().then(Ladder::arclength().from_modes(above))
        }
        false => ladder.clone(),
    };
    for (beside, other, direction, which) in
        [(left, right, 1.0, "lower"), (right, left, -1.0, "upper")]
    {
        let start = super::resolved(gap, rho, &ladder, |ex| {
            beside
                .iter()
                .find_map(|m| {
                    let ellipse = Contour::ellipse(m.a_bar, m.b_bar, ex.truncation().modes);
                    ex.solve(m.a_bar, &ellipse, m.delta_bar)
                        .ok()
                        .map(|st| (m.a_bar, st))
                })
                .ok_or_else(|| Error::NoState("no exact state beside the gap".into()))
                .and_then(|(a, st)| ex.accept_resolved(format_args!("a = {a:.2}"), st))
        });
        let crossings = start.and_then(|start| {
            let ex = Exact::on(gap, rho, start.truncation)?.deferring_stability();
            let limit = other[0].a_bar + direction * BEYOND_GAP;
            let (found, how) = ex.crossings_past_fold(&start, direction, limit, control, step)?;
            Ok((start.truncation, found, how))
        });
        let (truncation, found, how) = match crossings {
            Ok(c) => c,
            Err(e) => {
                out.followed
                    .push(format!("the {which} arm not followed: {e}"));
                continue;
            }
        };
        out.followed.push(format!(
            "the {which} arm, traced with {} modes, {how}",
            truncation.modes
        ));
        // the rungs from the trace's on
        let from_trace = ladder.clone().at_rung(truncation);
        for crossing in found {
            let again = super::resolved(gap, rho, &from_trace, |ex| {
                let mut contour = crossing.contour.clone();
                if ex.truncation().arclength == 0 {
                    contour.b.resize(ex.truncation().modes, 0.0);
                }
                ex.solve_at(control, &contour, crossing.delta_bar)
                    .and_then(|st| ex.accept_resolved(control, st))
            });
            match again {
                // (a trace on the escalation's last rung leaves the
                // re-solve one rung, answered as resolved only)
                Ok(st) if escalation && st.bc_error > super::CONVERGED => out.missed.push((
                    crossing.a_bar,
                    format!(
                        "past the fold of the {which} arm: the crossing's boundary error is {:.1e} with {} modes, the most tried",
                        st.bc_error,
                        st.truncation.modes
                    ),
                )),
                Ok(mut st) if Same::AT_THE_CROSSING.of(&st, &crossing) => {
                    st.route = super::Route::PastFold;
                    out.states.push(st);
                }
                Ok(st) => out.missed.push((
                    crossing.a_bar,
                    format!(
                        "past the fold of the {which} arm: the crossing moved to a = {:.4} with more modes",
                        st.a_bar
                    ),
                )),
                Err(e) => out.missed.push((
                    crossing.a_bar,
                    format!("past the fold of the {which} arm: {e}"),
                )),
            }
        }
    }
    out
}

/// What [`past_folds`] found beside one gap.
#[derive(Default)]
struct PastFolds {
    /// The converged states at the control.
    states: Vec<super::ExactState>,
    /// How far each arm was followed, or why not, in words.
    followed: Vec<String>,
    /// Crossings of the control that gave no converged state: ā, why.
    missed: Vec<(f64, String)>,
}

/// Why a gap between the model's near-elliptic states holds no band
/// ([`settle`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum NoBand {
    /// The arms' folds overlap (the lower arm folds at ā = `lower`, the
    /// upper at ā = `upper`): near-elliptic states exist at every ā between.
    Overlap { lower: f64, upper: f64 },
    /// The exact family traced from ā = `from` passes the gap's far side
    /// without folding.
    NoFold { from: f64 },
}

/// Settle one candidate gap between the model's near-elliptic states
/// `left` and `right`, tracing in steps of at most `step`: the band, or why
/// there is none.
pub(crate) fn settle(
    gap: super::Gap,
    rho: f64,
    left: &[&Guess],
    right: &[&Guess],
    step: f64,
) -> Result<std::result::Result<Band, NoBand>> {
    let lower = fold_from(gap, rho, left, 1.0, right[0].a_bar + BEYOND_GAP, step)?;
    let upper = fold_from(gap, rho, right, -1.0, left[0].a_bar - BEYOND_GAP, step)?;
    Ok(match (lower, upper) {
        (Some(lower), Some(upper)) if lower.a_bar < upper.a_bar => Ok(Band { lower, upper }),
        (Some(lower), Some(upper)) => Err(NoBand::Overlap {
            lower: lower.a_bar,
            upper: upper.a_bar,
        }),
        (None, _) => Err(NoBand::NoFold {
            from: left[0].a_bar,
        }),
        (_, None) => Err(NoBand::NoFold {
            from: right[0].a_bar,
        }),
    })
}

/// The located fold of the exact family traced in `direction` from the
/// exact state near the first of the model's states `beside` the gap (in
/// order) that gives one; `None` when ā passes `limit` first.
/// The rungs of [`Ladder::conformal`] are tried in turn (those
/// predicted not to converge skipped, [`Ladder::escalate`]), from the
/// first that resolves the start, until the fold state's boundary error is
/// below [`super::CONVERGED`] (else the best below [`super::RESOLVED`],
/// which the band table prints with its boundary error, else an
/// [`Error::Unresolved`]).
fn fold_from(
    gap: super::Gap,
    rho: f64,
    beside: &[&Guess],
    direction: f64,
    limit: f64,
    step: f64,
) -> Result<Option<BandEdge>> {
    let mut best: Option<BandEdge> = None;
    let mut last_error = None;
    let near = beside[0];
    let mut ladder = Ladder::conformal();
    while let Some(t) = ladder.rung() {
        crate::newton::check_stop()?;
        let ex = Exact::on(gap, rho, t)?;
        // the first of the model's states beside the gap whose exact
        // neighbour this truncation resolves
        let start = beside.iter().find_map(|m| {
            ex.solve(
                m.a_bar,
                &Contour::ellipse(m.a_bar, m.b_bar, t.modes),
                m.delta_bar,
            )
            .map_err(|e| last_error = Some(e.to_string()))
            .ok()
        });
        match start {
            Some(st) if st.bc_error <= super::RESOLVED => {
                let Some((fold, mode)) = ex.to_size_fold(&st, direction, limit, step)? else {
                    return Ok(None);
                };
                let edge = BandEdge {
                    a_bar: fold.a_bar,
                    s: fold.s,
                    force_bar: fold.force_bar,
                    delta_bar: fold.delta_bar,
                    mode,
                    bc_error: fold.bc_error,
                    modes: t.modes,
                };
                if edge.bc_error <= super::CONVERGED {
                    return Ok(Some(edge));
                }
                ladder.saw(t.modes, edge.bc_error);
                if edge.bc_error <= super::RESOLVED
                    && best.as_ref().is_none_or(|b| edge.bc_error < b.bc_error)
                {
                    best = Some(edge);
                }
            }
            Some(st) => {
                last_error = Some(format!(
                    "boundary error {:.0e} with {} modes",
                    st.bc_error, t.modes
                ));
            }
            None => {}
        }
        if !ladder.escalate() {
            break;
        }
    }
    match best {
        Some(edge) => Ok(Some(edge)),
        None => Err(Error::Unresolved {
            what: format!(
                "the band edge of the exact family traced from a = {:.2} at rho = {} ({})",
                near.a_bar,
                crate::error::short(rho),
                last_error.unwrap_or_else(|| "no truncation resolves the fold".into())
            ),
            residual: f64::NAN,
        }),
    }
}
