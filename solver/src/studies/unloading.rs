//! The unloading path to a pull-off (issue 32, milestone (b)): the exact
//! family traced from its state at F̄ = 10 (else the largest stable load
//! on the pull-off's piece, `start`) the way F̄ falls (towards smaller
//! ā, or larger past a fold in ā) up to its first minimum of F̄, and
//! whether that minimum is the given pull-off; on the way, the longest
//! contour mode unstable under load control at every traced point, whose
//! wavelength over 2π is the thinness h/L below which the path is unstable
//! above the short-wave cutoff (a contact that thin changes shape before it
//! reaches the minimum).
//!
//! Owns: [`unloading`]. May use: `exact` (the problem and its
//! states, `branch` (the trace), `stability`), its parent `studies`: `start`
//! (where it begins; the start itself comes from the caller, shared with
//! the loading path), `cutoff`, `error`, `report` (the outcome's
//! shape).

use super::start::{Start, StartAt};
use crate::cutoff::Cutoff;
use crate::error::Result;
use crate::exact::{Exact, ExactState};
use crate::report::Passed;

/// The largest boundary error of a traced point that still counts as a
/// state of the problem (a trace that leaves it leaves the family it can
/// resolve: the path is then not settled).
const TRACED: f64 = 1e-6;

/// The unloading path from its start to the first minimum of F̄ at
/// `pull_off.rho`, judged with `cutoff`'s thinness: an entry of the
/// pull-off's `passed` list. `start` is where it begins
/// ([`super::start::start`], shared with the loading path: the state at
/// F̄ = 10, else the largest stable load on the pull-off's piece), or why
/// there is none.
pub(crate) fn unloading(pull_off: &ExactState, cutoff: Cutoff, start: &Result<Start>) -> Passed {
    let (from_force, start_at) = super::start::reported_from(start);
    match path(pull_off, start) {
        Ok(p) => p.judged(cutoff, from_force, start_at),
        Err(why) => Passed::Unloading {
            from_force,
            start_at,
            reaches: None,
            first_minimum_force: None,
            first_minimum_a_bar: None,
            critical_thinness: None,
            critical_mode: None,
            cutoff_thinness: cutoff.thinness,
            stable_above_cutoff: None,
            bands_crossed: Vec::new(),
            why_not_settled: Some(why),
        },
    }
}

/// What the trace found.
struct Path {
    minimum: ExactState,
    reaches: bool,
    /// (h/L, mode n) of the longest unstable contour mode on the way.
    critical: (f64, usize),
    /// Whether the size itself (n = 0) is unstable under load somewhere on
    /// the way (then the path is unstable at any thinness).
    size_unstable: bool,
    /// The modes of the bifurcation points the trace meets before the
    /// minimum: at ρ < 1 there are none on the family (the circle's are
    /// imperfect), so each is a band the trace steps across, from one
    /// piece onto the next (at ρ = 1 the circle's neutral points).
    bands_crossed: Vec<usize>,
}

impl Path {
    fn judged(self, cutoff: Cutoff, from_force: f64, start_at: Option<StartAt>) -> Passed {
        let (h, n) = self.critical;
        Passed::Unloading {
            from_force,
            start_at,
            reaches: Some(self.reaches),
            first_minimum_force: Some(self.minimum.force_bar),
            first_minimum_a_bar: Some(self.minimum.a_bar),
            critical_thinness: (n > 0).then_some(h),
            critical_mode: (n > 0).then_some(n),
            cutoff_thinness: cutoff.thinness,
            stable_above_cutoff: Some(!self.size_unstable && cutoff.thinness > h),
            bands_crossed: self.bands_crossed,
            why_not_settled: None,
        }
    }
}

/// The trace from the start to the first minimum, or why it is not
/// settled (in words, for the report).
fn path(pull_off: &ExactState, start: &Result<Start>) -> std::result::Result<Path, String> {
    let start = &start
        .as_ref()
        .map_err(|e| format!("no start: {}", e.detail()))?
        .state;
    let from = crate::error::short(start.force_bar);
    let ex = Exact::of_state(start).map_err(|e| e.to_string())?;
    let failed = |e: crate::error::Error| format!("the trace from force = {from} failed: {e}");
    // unloading lowers F̄: towards smaller ā, unless F̄ rises that way (a
    // start on the returning stretch past a fold in ā, as on the arm of a
    // larger contact at ρ = 0.3), then towards larger ā
    let first = ex
        .trace_from(start, -1.0, 0.8, f64::INFINITY, 0.05, 2)
        .map_err(failed)?;
    let rises = first
        .points
        .get(1)
        .is_some_and(|p| p.state.force_bar > start.force_bar);
    let direction = if rises { 1.0 } else { -1.0 };
    let branch = ex
        .trace_from(start, direction, 0.8, f64::INFINITY, 0.05, 600)
        .map_err(failed)?;
    let mut critical = (0.0f64, 0usize);
    let mut size_unstable = false;
    let points = &branch.points;
    for (i, p) in points.iter().enumerate() {
        let st = &p.state;
        if st.bc_error > TRACED {
            return Err(format!(
                "the trace from force = {from} leaves the states its {} modes resolve at a = {:.4} (boundary error {:.1e}) before a minimum of the force",
                start.truncation.modes, st.a_bar, st.bc_error
            ));
        }
        if i > 0 && st.force_bar > points[i - 1].state.force_bar {
            // the force rises: the minimum lies between the last two points
            let minimum = first_minimum(&branch, &points[i - 1].state);
            let reaches = crate::exact::same::Same::THE_PULL_OFF.of(&minimum, pull_off);
            let bands_crossed = branch
                .events
                .iter()
                .take_while(|e| !matches!(e, crate::exact::branch::Event::ForceMinimum { .. }))
                .filter_map(|e| match e {
                    crate::exact::branch::Event::Bifurcation { between, mode } => {
                        // one the trace met before this minimum
                        let before = between
                            .iter()
                            .all(|a| (a - minimum.a_bar) * (start.a_bar - minimum.a_bar) >= 0.0);
                        before.then_some(*mode).flatten()
                    }
                    _ => None,
                })
                .collect();
            return Ok(Path {
                minimum,
                reaches,
                critical,
                size_unstable,
                bands_crossed,
            });
        }
        // a traced point past the minimum (the force rising along the
        // trace there; the trace can step over the minimum before the
        // force it prints rises) is not on the way to it
        if p.d_force >= 0.0 {
            continue;
        }
        let stab = ex.stability(st).map_err(|e| e.to_string())?;
        for m in &stab.load {
            if m.n == 0 {
                size_unstable = true;
            } else if m.wavelength / (2.0 * std::f64::consts::PI) > critical.0 {
                critical = (m.wavelength / (2.0 * std::f64::consts::PI), m.n);
            }
        }
    }
    Err(format!(
        "the trace from force = {from} meets no minimum of the force within its {} points",
        points.len()
    ))
}

/// The trace's first located force minimum, or the traced point before the
/// force rose where none was located.
fn first_minimum(branch: &crate::exact::branch::Branch, before: &ExactState) -> ExactState {
    branch
        .events
        .iter()
        .find_map(|e| match e {
            crate::exact::branch::Event::ForceMinimum { state } if state.bc_error <= TRACED => {
                Some((**state).clone())
            }
            _ => None,
        })
        .unwrap_or_else(|| before.clone())
}
