//! Where the loading path and the unloading trace begin (issue 32, item
//! 2): the resolved exact state at the large load F̄ = 10 where one is
//! found, otherwise the largest load on the piece of the family that
//! carries the pull-off (which the pull-off's continuation in ρ connects
//! to the circle; below ρ ≈ 0.165 no state at F̄ = 10 is found:
//! docs/exact.md, "Below ρ = 0.3") at which its state is resolved and
//! stable under load above the short-wave cutoff.
//!
//! That piece is traced from the pull-off on both sides; its stable side
//! is the one whose first state has fewer directions unstable under load
//! (the fold of the load at the pull-off turns one eigenvalue's sign).
//! Along it, up to its first maximum of F̄ and as far as the pull-off's
//! truncation resolves its states to [`CONVERGED`], the start is the
//! state of largest F̄ with no resolved mode unstable under load; where
//! there is none, no path begins and the error says why.
//!
//! Owns: [`Start`], [`start`], [`reported_from`], [`at_large_load`],
//! [`largest_on_pull_off_piece`]. May use: `exact` (the
//! problem, its states and `resolve`, the large load, `branch` (the
//! trace), `stability` (the verdicts)), `control`, `cutoff`,
//! `error`, `newton` (the stop request), `report` ([`StartAt`], the
//! start's shape in the output).

use crate::control::Hold;
use crate::cutoff::Cutoff;
use crate::error::{Error, Result};
use crate::exact::stability::UnstableMode;
use crate::exact::START_FORCE;
use crate::exact::{Exact, ExactState, CONVERGED};
pub(crate) use crate::report::StartAt;

/// How far the piece is traced from the pull-off at most (points of the
/// trace, arclength steps up to [`STEP`]): at ρ = 0.1 the 96-mode states
/// pass 1e-9 after 9 to 17.
const POINTS: usize = 30;

/// The largest arclength step of that trace (in the unknowns).
const STEP: f64 = 0.05;

/// The state a path begins from, and which it is.
#[derive(Clone, Debug)]
pub(crate) struct Start {
    /// The state (resolved to [`CONVERGED`]).
    pub state: ExactState,
    /// Which state it is.
    pub at: StartAt,
}

/// Where the paths to `pull_off` begin: the resolved state at F̄ =
/// [`START_FORCE`] at its ρ, else the largest stable load on the
/// pull-off's piece ([`largest_on_pull_off_piece`]). An error only where the user asked to stop, or where
/// neither is found (both reasons said).
pub(crate) fn start(pull_off: &ExactState, cutoff: Cutoff) -> Result<Start> {
    let large = at_large_load(pull_off.rho);
    crate::newton::check_stop()?;
    match large {
        Ok(state) => Ok(Start {
            state,
            at: StartAt::LargeLoad,
        }),
        Err(e) => largest_on_pull_off_piece(pull_off, cutoff, e.detail()),
    }
}

/// The load a path reports it started from, and which start that was:
/// `start`'s, else (no start) the large load it was asked from.
pub(crate) fn reported_from(start: &Result<Start>) -> (f64, Option<StartAt>) {
    match start {
        Ok(s) => (s.state.force_bar, Some(s.at.clone())),
        Err(_) => (START_FORCE, None),
    }
}

/// The resolved exact state at F̄ = [`START_FORCE`] at `rho`.
pub(crate) fn at_large_load(rho: f64) -> Result<ExactState> {
    // searched, not refused by the map (the path's start says why none)
    crate::exact::at_resolved_searching(
        crate::exact::Gap::cylinders(),
        rho,
        Hold::Force(START_FORCE),
    )
}

/// The largest F̄ on the piece through `pull_off` at which its state is
/// resolved and stable under load above `cutoff`: the piece traced from
/// the pull-off on its stable side (the side whose first traced state has
/// fewer directions unstable under load: a fold of the load turns one
/// eigenvalue's sign there); `why` says why F̄ = 10 is not the start. An
/// error that says so where no state on that side is.
pub(crate) fn largest_on_pull_off_piece(
    pull_off: &ExactState,
    cutoff: Cutoff,
    why: String,
) -> Result<Start> {
    let ex = Exact::of_state(pull_off)?;
    let none = |what: String| {
        Error::NoState(format!(
            "no state at F = {START_FORCE} ({}); {what}",
            crate::report::first_clause(&why)
        ))
    };
    let side = |direction: f64| -> Result<Vec<(ExactState, Vec<UnstableMode>)>> {
        let branch = ex.trace_from(pull_off, direction, 0.5, f64::INFINITY, STEP, POINTS)?;
        let mut out = Vec::new();
        for p in branch.points.into_iter().skip(1) {
            crate::newton::check_stop()?;
            if p.state.bc_error > CONVERGED {
                break;
            }
            let load = ex.stability(&p.state)?.under(cutoff).load;
            out.push((p.state, load));
        }
        Ok(out)
    };
    let traced = |e: Error| {
        none(format!(
            "the trace up the pull-off's piece failed: {}",
            e.detail()
        ))
    };
    let grows = side(1.0).map_err(traced)?;
    let shrinks = side(-1.0).map_err(traced)?;
    let unstable =
        |s: &[(ExactState, Vec<UnstableMode>)]| s.first().map_or(usize::MAX, |f| f.1.len());
    let stable_side = if unstable(&shrinks) < unstable(&grows) {
        shrinks
    } else {
        grows
    };
    // up to the first maximum of F̄, the states of no resolved mode
    // unstable under load, the largest load first
    let rising: Vec<&(ExactState, Vec<UnstableMode>)> = stable_side
        .iter()
        .scan(pull_off.force_bar, |last, s| {
            (s.0.force_bar > *last).then(|| {
                *last = s.0.force_bar;
                s
            })
        })
        .collect();
    let top = rising.last().ok_or_else(|| {
        none("the pull-off's piece is not resolved to 1e-9 above it by its modes".into())
    })?;
    let maximum = rising.len() < stable_side.len();
    match rising
        .iter()
        .rev()
        .find(|s| s.1.iter().all(|m| !m.resolved))
    {
        Some(s) => Ok(Start {
            state: s.0.clone(),
            at: StartAt::PullOffPiece {
                why_not_large_load: why,
                maximum: maximum && std::ptr::eq(*s, *top),
                top_force: top.0.force_bar,
                start_force: s.0.force_bar,
            },
        }),
        None => {
            let m = top.1.iter().find(|m| m.resolved).map_or(0, |m| m.n);
            Err(none(format!(
                "on the piece that carries the pull-off, every state its modes resolve above it (up to F = {} at a = {}) is unstable under load to a mode the cutoff resolves (at the largest load n = {m}): no stable start",
                crate::error::short(top.0.force_bar),
                crate::error::short(top.0.a_bar)
            )))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Where no state at F̄ = 10 is the start (the reason given here), the
    /// pull-off's piece is traced: at ρ = 0.3 with h/L = 0.6 (n = 6 and
    /// shorter not resolved) its last state resolved to 1e-9 above the
    /// pull-off, on its stable side, is the start; at
    /// ρ = 0.1 with h/L = 0.1 every resolved state above the pull-off on
    /// its stable side is unstable under load, and no path begins (an
    /// error, not a start). The stable side is checked by a second route:
    /// the first state on the other side has one direction more unstable
    /// under load (the fold's). The ρ = 0.3 start is the one docs/exact.md
    /// prints.
    #[test]
    fn where_force_10_has_no_state_the_start_is_the_largest_stable_load_on_the_pull_offs_piece() {
        let (po, _) = crate::exact::pull_off_resolved(0.3).unwrap();
        let cutoff = Cutoff::for_thinness(0.6).unwrap();
        let start = largest_on_pull_off_piece(&po, cutoff, "not asked".into()).unwrap();
        let StartAt::PullOffPiece {
            maximum,
            top_force,
            start_force,
            ..
        } = start.at.clone()
        else {
            panic!("not a start on the pull-off's piece: {:?}", start.at)
        };
        assert!(!maximum);
        assert_eq!(top_force, start_force);
        assert!(start.state.bc_error <= CONVERGED);
        assert!(start.state.force_bar > po.force_bar + 0.01);
        let ex = Exact::new(0.3, po.truncation).unwrap();
        let held = ex.stability(&start.state).unwrap().under(cutoff);
        assert!(held.load.iter().all(|m| !m.resolved), "{:?}", held.load);
        let unstable_at = |direction: f64| {
            let b = ex
                .trace_from(&po, direction, 0.5, f64::INFINITY, STEP, 2)
                .unwrap();
            ex.stability(&b.points[1].state).unwrap().load.len()
        };
        let (grows, shrinks) = (unstable_at(1.0), unstable_at(-1.0));
        assert_eq!(grows.abs_diff(shrinks), 1);
        let stable_side = if shrinks < grows { -1.0 } else { 1.0 };
        assert_eq!((start.state.a_bar - po.a_bar).signum(), stable_side);
        assert!(start.at.words(false).contains("not resolved by them"));
        // docs/exact.md, "Where the path starts", prints this start
        let doc = include_str!("../../../docs/exact-record.md");
        let printed = format!(
            "F̄ = −{:.4} (ā = {:.4})",
            -start.state.force_bar, start.state.a_bar
        );
        assert!(
            doc.contains(&printed),
            "docs/exact-record.md lacks {printed}"
        );

        let (po, _) = crate::exact::pull_off_resolved(0.1).unwrap();
        let none = largest_on_pull_off_piece(&po, Cutoff::for_thinness(0.1).unwrap(), "x".into());
        let Err(Error::NoState(why)) = none else {
            panic!("a start at rho = 0.1: {none:?}")
        };
        assert!(why.contains("no stable start"), "{why}");
    }

    /// Below ρ ≈ 0.068 the pull-off's points are crowded into its grooves;
    /// the piece above it is traced in that gauge (`Exact::of_state`): at
    /// ρ = 0.05 both sides' first states are resolved to 1e-9 (in the plain
    /// gauge the corrector failed at the first step at ρ = 0.0311 and
    /// 0.0198, so that no start was found at 20° and 16°).
    #[test]
    fn the_piece_above_a_grooved_pull_off_is_traced_in_its_own_gauge() {
        let (po, _) = crate::exact::pull_off_resolved(0.05).unwrap();
        assert!(po.contour.narrow_groove().is_some());
        let ex = Exact::of_state(&po).unwrap();
        for direction in [1.0, -1.0] {
            let b = ex
                .trace_from(&po, direction, 0.5, f64::INFINITY, STEP, 2)
                .unwrap_or_else(|e| panic!("side {direction}: {e}"));
            let first = &b.points[1].state;
            assert!(first.bc_error <= CONVERGED, "{:e}", first.bc_error);
            assert_eq!((first.a_bar - po.a_bar).signum(), direction);
        }
    }
}
