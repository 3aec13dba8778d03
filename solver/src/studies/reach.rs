//! The reach in ρ of the near-elliptic family at each contact size (issue
//! 32): the exact state of half-width ā is followed in ρ at that fixed ā
//! from the circle (at ρ = [`PATHS_START_RHO`]) by the path in (shape, ρ)
//! ([`crate::exact::rho_path::follow`], which steps around the folds in ā
//! close by) until ρ turns back; that fold's ρ, located, is the size's
//! reach. Below it no state of that size is connected to the circle at
//! fixed ā. At any ρ the sizes whose reach lies above it are the bands of
//! [`crate::exact::bands`], found here by a second route that needs no model, and
//! that holds below ρ = 0.4, where the screen of `bands` (`conformal:8`)
//! fails: a band edge that `bands` located at ρ = 0.5 by a trace in ā is a
//! size whose reach is 0.5 to 1e-6 (the tests).
//!
//! Owns: [`of_size`], [`reach`], [`reach_of`], [`from_json_lines`],
//! [`windows`], [`valleys`], [`markdown`], [`settle`], [`windows_markdown`], [`windows_from_json_lines`]. May use: its parent `studies` (the loading path, in the windows), `exact` (the family,
//! `rho_path`, `stability`, `undulations`), `control`, `cutoff`, `error`, `report` (the map's and the windows' shapes, [`SizeReach`], [`Window`],
//! re-exported here), `accuracy` (the ρ of its table),
//! `newton` (the stop flag, carried to rayon's threads), `progress` (the sizes followed), rayon.

use crate::control::Hold;
use crate::error::{rounded, Result};
use crate::exact::branch::SizeFoldEnd;
use crate::exact::rho_path::{follow, Followed};
use crate::exact::{Exact, ExactState, Truncation, CONVERGED};
pub(crate) use crate::report::{Reached, SizeReach, Window, WindowEnd, WindowPath};
use rayon::prelude::*;

/// The ρ the paths start from: the circle continued to it at its ā
/// ([`Exact::from_circle`]); at ρ = 1 itself the path's derivative in ρ
/// (a central difference) would need ρ > 1.
pub(crate) const PATHS_START_RHO: f64 = 0.98;

/// The smallest ρ a path is followed to: the smallest of docs/accuracy.md.
pub(crate) const FLOOR: f64 = 0.02;

/// The arclength representation's modes of each sign: at ā = 3.8, where
/// the reach is 0.2109, 96 modes leave a boundary error of 7e-8 at the
/// fold and 128 of 6e-10, and both put the fold at the same ρ to 1e-9.
pub(crate) const MODES: usize = 128;

/// The most sizes of a map.
pub(crate) const MAX_SIZES: usize = 1000;

/// The smallest ρ with a state of the size `p` connected to the circle
/// at fixed ā; `None` where its path stopped.
pub(crate) fn reach_of(p: &SizeReach) -> Option<f64> {
    match p.reached {
        Reached::TurnsBack { rho, .. } => Some(rho),
        Reached::Floor { .. } => Some(FLOOR),
        Reached::Stopped { .. } => None,
    }
}

/// The state of size `a_bar` at ρ = [`PATHS_START_RHO`] continued from the circle
/// with truncation `t`, or why there is none, in words; an error only
/// where the caller asked to stop (not a size's outcome).
pub(crate) fn from_the_circle(
    a_bar: f64,
    t: Truncation,
) -> Result<std::result::Result<ExactState, String>> {
    match Exact::new(PATHS_START_RHO, t)?
        .deferring_stability()
        .from_circle(a_bar)
    {
        Ok(st) => Ok(Ok(st)),
        Err(e) => {
            crate::newton::check_stop()?;
            Ok(Err(e.detail()))
        }
    }
}

/// The reach of the size `a_bar` with `modes` modes of each sign.
pub(crate) fn of_size(a_bar: f64, modes: usize) -> Result<SizeReach> {
    let t = Truncation::in_arclength(modes);
    let stopped = |why: String| SizeReach {
        a_bar,
        modes,
        reached: Reached::Stopped { why },
    };
    let start = match from_the_circle(a_bar, t)? {
        Ok(st) => st,
        Err(why) => return Ok(stopped(why)),
    };
    Ok(match follow(&start, FLOOR, Hold::Size(a_bar)) {
        Ok(Followed::TurnedBack { fold, bc_error, .. }) => SizeReach {
            a_bar,
            modes,
            reached: Reached::TurnsBack {
                rho: fold,
                bc_error,
            },
        },
        Ok(Followed::Reached(st)) => SizeReach {
            a_bar,
            modes,
            reached: Reached::Floor {
                bc_error: st.bc_error,
            },
        },
        Err(e) => {
            crate::newton::check_stop()?;
            stopped(e.detail())
        }
    })
}

/// The reach of every size from `from` to `to` in steps of `step`
/// ([`MODES`] modes), in parallel.
pub(crate) fn reach(from: f64, to: f64, step: f64) -> Result<Vec<SizeReach>> {
    crate::error::check_range("from", from, from.is_finite() && from >= 0.5, "[0.5, to)")?;
    crate::error::check_range(
        "step",
        step,
        step.is_finite() && (1e-3..=1.0).contains(&step),
        "[0.001, 1]",
    )?;
    // the count is bounded before anything is allocated
    let steps = ((to - from) / step).round();
    crate::error::check_range(
        "to",
        to,
        to.is_finite() && to > from && to <= 10.0 && steps < MAX_SIZES as f64,
        "(from, 10], at most 1000 sizes from `from` in steps of `step`",
    )?;
    let sizes: Vec<f64> = (0..=steps as usize)
        .map(|k| from + step * k as f64)
        .collect();
    let stop = crate::newton::stop_flag();
    // the count done, for a person waiting (a size takes seconds)
    let done = std::sync::atomic::AtomicUsize::new(0);
    crate::progress::stage(format!("0 of {} sizes followed in rho", sizes.len()));
    sizes
        .par_iter()
        .map(|&a| {
            let reached = crate::newton::carried(stop.clone(), || of_size(a, MODES));
            let k = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            crate::progress::stage(format!("{k} of {} sizes followed in rho", sizes.len()));
            reached
        })
        .collect()
}

/// The runs of consecutive sizes of `map` (in order of ā) whose reach lies
/// below `rho`: the windows of ā with a state at `rho` connected to the
/// circle at fixed ā, each as its first and last size.
pub(crate) fn windows(map: &[SizeReach], rho: f64) -> Vec<[f64; 2]> {
    let mut out: Vec<[f64; 2]> = Vec::new();
    let mut open = false;
    for p in map {
        let inside = reach_of(&p).is_some_and(|r| r < rho);
        match (inside, open) {
            (true, true) => out.last_mut().expect("an open window")[1] = p.a_bar,
            (true, false) => out.push([p.a_bar, p.a_bar]),
            _ => {}
        }
        open = inside;
    }
    out
}

/// The table of docs/exact.md ("The reach of each size"): at each ρ of
/// docs/accuracy.md ([`crate::accuracy::RHOS`]) below [`PATHS_START_RHO`], the windows
/// of [`windows`]; under it the smallest reach, the valleys of the reach
/// ([`valleys`]), the sizes whose path stopped, and those whose fold is
/// not resolved to [`CONVERGED`].
pub(crate) fn markdown(map: &[SizeReach]) -> String {
    let (Some(first), Some(last)) = (map.first(), map.last()) else {
        return String::new();
    };
    let step = map.get(1).map_or(0.0, |p| p.a_bar - first.a_bar);
    let mut s = format!(
        "| ρ | windows of ā with a state connected to the circle at fixed ā ({} ≤ ā ≤ {}, step {}) |\n|---|---|\n",
        rounded(first.a_bar),
        rounded(last.a_bar),
        rounded(step)
    );
    for rho in crate::accuracy::RHOS
        .into_iter()
        .filter(|&r| r < PATHS_START_RHO)
    {
        let w = windows(map, rho);
        let cell = if w.is_empty() {
            "none".to_string()
        } else {
            w.iter()
                .map(|[a, b]| {
                    if a == b {
                        format!("{a:.2}")
                    } else {
                        format!("{a:.2} – {b:.2}")
                    }
                })
                .collect::<Vec<_>>()
                .join(", ")
        };
        s += &format!("| {rho} | {cell} |\n");
    }
    let lowest = map
        .iter()
        .filter_map(|p| reach_of(&p).map(|r| (r, p.a_bar)))
        .min_by(|x, y| x.0.total_cmp(&y.0));
    if let Some((r, a)) = lowest {
        s += &format!("\nThe smallest reach: ρ = {} (ā = {:.2}).\n", rounded(r), a);
    }
    let v: Vec<String> = valleys(map)
        .iter()
        .map(|(a, r)| format!("{a:.2} ({r:.3})"))
        .collect();
    if !v.is_empty() {
        s += &format!(
            "The valleys of the reach (its local minima over neighbouring sizes), ā (ρ): {}.\n",
            v.join(", ")
        );
    }
    let stopped: Vec<String> = map
        .iter()
        .filter(|p| matches!(p.reached, Reached::Stopped { .. }))
        .map(|p| format!("{:.2}", p.a_bar))
        .collect();
    if !stopped.is_empty() {
        s += &format!(
            "Paths that stopped without turning back (no reach): ā = {}.\n",
            stopped.join(", ")
        );
    }
    let loose: Vec<String> = map
        .iter()
        .filter_map(|p| match p.reached {
            Reached::TurnsBack { bc_error, .. } if bc_error.is_none_or(|e| e > CONVERGED) => {
                Some(format!(
                    "{:.2} ({})",
                    p.a_bar,
                    bc_error.map_or("singular".to_string(), |e| format!("{e:.0e}"))
                ))
            }
            _ => None,
        })
        .collect();
    if !loose.is_empty() {
        s += &format!(
            "Folds whose boundary error is above 1e-9: ā = {}.\n",
            loose.join(", ")
        );
    }
    s
}

/// The sizes of `map` (in order of ā) whose reach lies below that of both
/// neighbours, each with its reach: the bottoms of the sawtooth between
/// the bands' tongues, where the windows close last as ρ falls.
pub(crate) fn valleys(map: &[SizeReach]) -> Vec<(f64, f64)> {
    map.windows(3)
        .filter_map(
            |w| match (reach_of(&w[0]), reach_of(&w[1]), reach_of(&w[2])) {
                (Some(l), Some(r), Some(h)) if r < l && r < h => Some((w[1].a_bar, r)),
                _ => None,
            },
        )
        .collect()
}

/// The boundary error past which a window's trace in ā ends
/// ([`WindowEnd::Unresolved`]): the bound of the traces of
/// `exact::larger_contacts` on the way.
pub(crate) const WINDOW_RESOLVED: f64 = 1e-6;

/// How far from its start a window's trace in ā looks for a fold.
pub(crate) const WINDOW_SPAN: f64 = 1.0;

/// The windows of `map` at `rho`, each settled by the family at `rho`
/// ([`Window`]; [`MODES`] modes of each sign), in parallel.
pub(crate) fn settle(
    map: &[SizeReach],
    rho: f64,
    unloading: Option<crate::cutoff::Cutoff>,
) -> Result<Vec<Window>> {
    crate::error::check_range(
        "rho",
        rho,
        rho.is_finite() && rho > FLOOR && rho < PATHS_START_RHO,
        "(0.02, 0.98)",
    )?;
    let stop = crate::newton::stop_flag();
    windows(map, rho)
        .par_iter()
        .map(|&grid| crate::newton::carried(stop.clone(), || settle_one(map, rho, grid, unloading)))
        .collect()
}

fn settle_one(
    map: &[SizeReach],
    rho: f64,
    grid: [f64; 2],
    unloading: Option<crate::cutoff::Cutoff>,
) -> Result<Window> {
    // the window's size with the smallest reach: the farthest from a band
    let a_bar = map
        .iter()
        .filter(|p| p.a_bar >= grid[0] && p.a_bar <= grid[1])
        .filter_map(|p| reach_of(&p).map(|r| (r, p.a_bar)))
        .min_by(|x, y| x.0.total_cmp(&y.0))
        .map_or(grid[0], |(_, a)| a);
    let failed = |why: String| Window {
        rho,
        grid,
        a_bar,
        force_bar: None,
        bc_error: None,
        coatings: None,
        unloading: None,
        lower: WindowEnd::Failed { why: why.clone() },
        upper: WindowEnd::Failed { why },
    };
    let start = match from_the_circle(a_bar, Truncation::in_arclength(MODES))? {
        Ok(st) => st,
        Err(why) => return Ok(failed(why)),
    };
    let state = match follow(&start, rho, Hold::Size(a_bar)) {
        Ok(Followed::Reached(st)) => st,
        Ok(Followed::TurnedBack { fold, .. }) => {
            return Ok(failed(format!(
                "the path from the circle turned back at rho = {}",
                rounded(fold)
            )))
        }
        Err(e) => {
            crate::newton::check_stop()?;
            return Ok(failed(e.detail()));
        }
    };
    let ex = Exact::on(state.gap, rho, state.truncation)?.deferring_stability();
    let end = |direction: f64, step: f64| window_end(&ex, &state, a_bar, direction, step);
    // an end past the next window of the grid crossed the band between
    let others = windows(map, rho);
    let checked = |e: WindowEnd, direction: f64| {
        let Some(at) = e.a_bar() else { return e };
        // the nearest such window
        let passed = if direction < 0.0 {
            others.iter().rev().find(|w| w[1] < grid[0] && at <= w[1])
        } else {
            others.iter().find(|w| w[0] > grid[1] && at >= w[0])
        };
        match passed {
            Some(&window) => WindowEnd::Crossed { a_bar: at, window },
            None => e,
        }
    };
    // in steps of 0.01, and again in the band maps' fine steps where that
    // crossed a band
    let settled = |direction: f64| -> Result<WindowEnd> {
        match checked(end(direction, 0.01)?, direction) {
            WindowEnd::Crossed { .. } => Ok(checked(
                end(direction, crate::exact::bands::PROBE_STEP)?,
                direction,
            )),
            e => Ok(e),
        }
    };
    // the start's stability and shape (ranges of h/L, so any cutoff)
    let judged = Exact::on(state.gap, rho, state.truncation)?
        .stability(&state)
        .ok()
        .map(|stability| {
            ExactState {
                stability,
                ..(*state).clone()
            }
            .judged(crate::cutoff::Cutoff::default())
        });
    let coatings = judged.as_ref().and_then(|st| st.coatings);
    // unloaded from there where it is a stable contact (2) resolves
    let unloading = match (unloading, &judged, coatings.and_then(|c| c.load)) {
        (Some(cutoff), Some(start), Some(range))
            if cutoff.thinness >= range.from && range.to.is_none_or(|to| cutoff.thinness < to) =>
        {
            Some(unloaded(start, cutoff)?)
        }
        _ => None,
    };
    Ok(Window {
        rho,
        grid,
        a_bar,
        force_bar: Some(state.force_bar),
        bc_error: Some(state.bc_error),
        coatings,
        unloading,
        lower: settled(-1.0)?,
        upper: settled(1.0)?,
    })
}

/// Where the family at fixed ρ traced from `state`, the window's state of
/// size `a_bar`, in ā (`direction` ±1, steps of `step`, at most
/// [`WINDOW_SPAN`]) ends: at a fold in ā, where it stops being resolved,
/// beyond the span, or failed (a stop asked for is an error).
fn window_end(
    ex: &Exact,
    state: &ExactState,
    a_bar: f64,
    direction: f64,
    step: f64,
) -> Result<WindowEnd> {
    let limit = a_bar + direction * WINDOW_SPAN;
    Ok(
        match ex.to_size_fold_within(state, direction, limit, step, WINDOW_RESOLVED) {
            Ok(SizeFoldEnd::Fold(st, mode)) => WindowEnd::Fold {
                a_bar: st.a_bar,
                s: st.s,
                force_bar: st.force_bar,
                mode,
                bc_error: st.bc_error,
            },
            Ok(SizeFoldEnd::Unresolved {
                a_bar,
                force_bar,
                bc_error,
            }) => WindowEnd::Unresolved {
                a_bar,
                force_bar,
                bc_error,
            },
            Ok(SizeFoldEnd::Beyond) => WindowEnd::Beyond { a_bar: limit },
            Err(e) => {
                crate::newton::check_stop()?;
                WindowEnd::Failed { why: e.detail() }
            }
        },
    )
}

/// The loading path from `start` (its stability computed) with `cutoff`.
fn unloaded(start: &ExactState, cutoff: crate::cutoff::Cutoff) -> Result<WindowPath> {
    use super::loading::{loading_path_to_first_band, PathEnd};
    let path = loading_path_to_first_band(start, cutoff)?;
    let shape = |st: &ExactState| st.clone().judged(cutoff).shape;
    // the path on its own piece: up to the state whose shape turned
    // unresolved, where it passed its band (then the state beyond is
    // `passed_to`), else its last state
    let pass = path.passes.first();
    let on_piece = &path.states[..path.states.len() - usize::from(pass.is_some())];
    let last = pass.map_or(on_piece.last().unwrap_or(start), |b| &b.at);
    let unresolved = shape(last)
        .filter(|w| w.unresolved)
        .and_then(|w| w.mode.map(|n| (n, w.amplitude)));
    let resolved_force_bar = on_piece
        .iter()
        .rev()
        .find(|st| shape(st).is_some_and(|w| !w.unresolved))
        .map_or(start.force_bar, |st| st.force_bar);
    let end = match &path.end {
        PathEnd::PullOff { state } => format!(
            "comes off at F = {:.6}, a = {:.6}",
            state.force_bar, state.a_bar
        ),
        PathEnd::Lost { state, why } => format!(
            "loses its state at F = {:.6}, a = {:.6}; {why}",
            state.force_bar, state.a_bar
        ),
        PathEnd::NotSettled(why) => format!("not settled: {why}"),
        PathEnd::PassedBand => pass.map_or(String::new(), |b| {
            format!(
                "passes the band of n = {} onto the piece below, at F = {:.6}, a = {:.6}",
                b.mode, b.to.force_bar, b.to.a_bar
            )
        }),
    };
    Ok(WindowPath {
        thinness: cutoff.thinness,
        states: on_piece.len(),
        jumps: path.jumps.len(),
        unresolved_turned_unstable: path
            .unresolved_turned_unstable(cutoff)
            .into_iter()
            .map(|(_, n)| n)
            .collect(),
        passed_to: pass.map(|b| [b.to.force_bar, b.to.a_bar]),
        resolved_force_bar,
        last_force_bar: last.force_bar,
        last_a_bar: last.a_bar,
        unresolved,
        end,
    })
}

/// The table of docs/exact.md of the settled windows at each ρ of
/// `windows` (in their order).
pub(crate) fn windows_markdown(windows: &[Window]) -> String {
    // the loading path from the start, where any was followed (at a ρ
    // where none was, none was asked for)
    let thinness = windows
        .iter()
        .find_map(|w| w.unloading.as_ref().map(|p| p.thinness));
    let asked = |rho: f64| {
        windows
            .iter()
            .any(|w| w.rho == rho && w.unloading.is_some())
    };
    let mut s = match thinness {
        None => String::from(
            "| ρ | grid window | start: ā, F̄ (boundary error) | towards smaller ā | towards larger ā | start a resolved stable contact for h/L |\n|---|---|---|---|---|---|\n",
        ),
        Some(h) => format!(
            "| ρ | grid window | start: ā, F̄ (boundary error) | towards smaller ā | towards larger ā | start a resolved stable contact for h/L | unloaded from the start, h/L = {h} |\n|---|---|---|---|---|---|---|\n"
        ),
    };
    for w in windows {
        s += &format!(
            "| {} | {:.2} – {:.2} | {:.2}, {} | {} | {} | {}{} |\n",
            w.rho,
            w.grid[0],
            w.grid[1],
            w.a_bar,
            match (w.force_bar, w.bc_error) {
                (Some(f), Some(e)) => format!("{} ({e:.0e})", signed_force(f)),
                _ => "no state".to_string(),
            },
            end_words(&w.lower),
            end_words(&w.upper),
            coatings_words(w),
            if thinness.is_some() {
                format!(" | {}", path_words(w, asked(w.rho)))
            } else {
                String::new()
            }
        );
    }
    s
}

/// A force with a minus sign, not a hyphen, to two decimals.
fn signed_force(f: f64) -> String {
    format!("{f:.2}").replace('-', "−")
}

/// How a window ends on one side, in the table's words.
fn end_words(e: &WindowEnd) -> String {
    match e {
        WindowEnd::Fold {
            a_bar,
            force_bar,
            mode,
            bc_error,
            ..
        } => format!(
            "fold at {a_bar:.4} (F̄ = {}{}; {bc_error:.0e})",
            signed_force(*force_bar),
            mode.map_or(String::new(), |n| format!(", n = {n}"))
        ),
        WindowEnd::Unresolved {
            a_bar,
            force_bar,
            bc_error,
        } => format!(
            "unresolved from {a_bar:.3} (F̄ = {}; {bc_error:.0e})",
            signed_force(*force_bar)
        ),
        WindowEnd::Beyond { a_bar } => format!("no fold up to {a_bar:.2}"),
        WindowEnd::Failed { .. } => "failed".to_string(),
        WindowEnd::Crossed { a_bar, window } => format!(
            "not settled: ended at {a_bar:.4}, past the window {:.2} – {:.2}",
            window[0], window[1]
        ),
    }
}

/// The coatings for which a window's start is a resolved stable contact:
/// under both controls, or each ("0.250 on", "0.248 to 0.744", "none").
fn coatings_words(w: &Window) -> String {
    let range = |t: &Option<crate::exact::undulations::Thinnesses>| match t {
        None => "none".to_string(),
        Some(t) => match t.to {
            None => format!("{:.3} on", t.from),
            Some(to) => format!("{:.3} to {to:.3}", t.from),
        },
    };
    match w.coatings {
        None => "not computed".to_string(),
        Some(c) if c.load == c.displacement => range(&c.load),
        Some(c) => format!(
            "{} (load); {} (displacement)",
            range(&c.load),
            range(&c.displacement)
        ),
    }
}

/// The loading path unloaded from a window's start, in the table's words
/// (`asked`: a path was asked for at the window's ρ).
fn path_words(w: &Window, asked: bool) -> String {
    match &w.unloading {
        None if !asked => "not computed".to_string(),
        None => "not started (not a resolved stable contact at this h/L)".to_string(),
        Some(p) => {
            let turned = if p.unresolved_turned_unstable.is_empty() {
                String::new()
            } else {
                let list: Vec<String> = p
                    .unresolved_turned_unstable
                    .iter()
                    .map(|n| n.to_string())
                    .collect();
                format!("turns unstable to n = {} (unresolved); ", list.join(", "))
            };
            turned
                + &match p.unresolved {
                    Some((n, share)) => format!(
                        "holds to F̄ = {}; at F̄ = {} (ā = {:.4}) n = {n} reaches {:.2} % of ā{}",
                        signed_force(p.resolved_force_bar),
                        signed_force(p.last_force_bar),
                        p.last_a_bar,
                        100.0 * share,
                        match p.passed_to {
                            Some([f, a]) => format!(
                                "; passes the band onto the piece below at F̄ = {} (ā = {a:.4})",
                                signed_force(f)
                            ),
                            None => "; no piece beyond found: not settled".to_string(),
                        }
                    ),
                    None => format!("to F̄ = {}: {}", signed_force(p.last_force_bar), p.end),
                }
        }
    }
}

/// The sizes of the lines `thinjkr exact reach --json` writes (one
/// `{"reach": …}` document per line, as docs/data/exact_reach.jsonl).
pub(crate) fn from_json_lines(text: &str) -> Result<Vec<SizeReach>> {
    crate::report::documents_of(text, "reach", "reach")
}

/// The windows of the lines `thinjkr exact reach --windows-at --json`
/// writes (one `{"window": …}` document per line, as
/// docs/data/exact_windows.jsonl; the docs' table is checked against it).
#[cfg(test)]
pub(crate) fn windows_from_json_lines(text: &str) -> Result<Vec<Window>> {
    crate::report::documents_of(text, "window", "window")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn committed(file: &str) -> String {
        std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../docs/data")
                .join(file),
        )
        .expect("the committed file exists")
    }

    /// A second route to the band maps: the edges `bands` located at
    /// ρ = 0.5 and 0.4 (folds in ā of the family traced in ā at that ρ from
    /// `conformal:8`'s states beside the gap, docs/data/exact_bands.jsonl)
    /// are sizes whose path in ρ at fixed ā from the circle, which uses no
    /// model, turns back at that ρ; and the committed reach of ā = 3.8
    /// (the lowest of the ten sizes 2.0, 2.2, …, 3.8: 0.2109) is what the
    /// path finds now.
    #[test]
    #[ignore = "slow tier (.ci/slow): about 45 s; the reach at rho = 0.2 stays in CI"]
    fn the_band_edges_at_rho_0_5_and_0_4_are_sizes_that_reach_just_that_rho() {
        let maps = crate::report::band_maps_from_json_lines(&committed("exact_bands.jsonl"))
            .expect("band map lines");
        for (rho, lower_of, upper_of) in [(0.5, 6, 8), (0.4, 4, 8)] {
            let map = maps.iter().find(|m| m.rho == rho).expect("the map");
            let edge = |n: usize, lower: bool| {
                let b = map
                    .bands
                    .iter()
                    .find(|b| b.lower.mode == Some(n))
                    .expect("the band");
                if lower {
                    b.lower.a_bar
                } else {
                    b.upper.a_bar
                }
            };
            for a in [edge(lower_of, true), edge(upper_of, false)] {
                let r = of_size(a, 96).unwrap();
                let reach = reach_of(&r).unwrap_or_else(|| panic!("{r:?}"));
                assert!(
                    (reach - rho).abs() < 1e-6,
                    "the edge a = {a} at rho = {rho} reaches {reach}"
                );
            }
        }
        let map = from_json_lines(&committed("exact_reach.jsonl")).expect("reach lines");
        let at = map
            .iter()
            .find(|p| (p.a_bar - 3.8).abs() < 1e-9)
            .expect("a = 3.8 in the map");
        let now = of_size(3.8, MODES).unwrap();
        let (Some(was), Some(is)) = (reach_of(&at), reach_of(&now)) else {
            panic!("{at:?} / {now:?}")
        };
        assert!(
            (was - is).abs() < 1e-8 && (is - 0.2109).abs() < 1e-4,
            "committed {was}, now {is}: regenerate docs/data/exact_reach.jsonl (docs/exact.md)"
        );
    }

    /// The committed reach (docs/data/exact_reach.jsonl) against the
    /// committed band maps at ρ = 0.9 … 0.4 (docs/data/exact_bands.jsonl),
    /// two routes that share no step: every size of the grid inside a band
    /// has no state at that ρ connected to the circle at fixed ā (its reach
    /// lies above ρ, or its path stopped); every size that does have one
    /// lies outside every band. Sizes whose path turns back above ρ although
    /// no band holds them (13 of the 6 × 201) lie within 0.02 of a neutral
    /// point of the circle (n = 8 … 16): the path met the top of a band's
    /// tongue in (ā, ρ), which then moved on in ā (docs/exact.md).
    #[test]
    fn the_reach_and_the_band_maps_agree_at_rho_0_9_to_0_4() {
        let maps = crate::report::band_maps_from_json_lines(&committed("exact_bands.jsonl"))
            .expect("band map lines");
        let map = from_json_lines(&committed("exact_reach.jsonl")).expect("reach lines");
        let circle = crate::exact::Gap::cylinders().at(1.0).unwrap();
        let neutral = |n: usize| circle.neutral_point(n);
        let mut tongue_tops = 0;
        for m in &maps {
            let inside = |a: f64| {
                m.bands
                    .iter()
                    .any(|b| a >= b.lower.a_bar - 1e-9 && a <= b.upper.a_bar + 1e-9)
            };
            let unsettled = |a: f64| {
                m.open_ends
                    .iter()
                    .chain(m.crossed.iter().map(|c| &c.screened))
                    .chain(m.unsettled.iter().map(|c| &c.screened))
                    .any(|w| a >= w[0] && a <= w[1])
            };
            for p in map
                .iter()
                .filter(|p| p.a_bar >= m.range[0] && p.a_bar <= m.range[1])
            {
                let reaches = reach_of(&p).is_some_and(|r| r < m.rho);
                if inside(p.a_bar) {
                    assert!(!reaches, "rho = {}: {p:?} inside a band", m.rho);
                } else if !reaches && !unsettled(p.a_bar) {
                    assert!(
                        (8..=40)
                            .step_by(2)
                            .any(|n| (p.a_bar - neutral(n)).abs() < 0.02),
                        "rho = {}: {p:?} outside every band",
                        m.rho
                    );
                    tongue_tops += 1;
                }
            }
        }
        assert!(tongue_tops < 15, "{tongue_tops} sizes at tongue tops");
    }

    /// The windows table in docs/exact.md is what [`markdown`] renders from
    /// the committed map (docs/data/exact_reach.jsonl).
    #[test]
    fn the_reach_table_in_the_docs_is_the_committed_map() {
        let map = from_json_lines(&committed("exact_reach.jsonl")).expect("reach lines");
        assert!(map.len() > 300, "{} sizes", map.len());
        let table = markdown(&map);
        let doc = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/exact-record.md"),
        )
        .unwrap();
        assert!(
            doc.contains(&table),
            "docs/exact-record.md's reach table is stale; it should read:\n{table}"
        );
    }

    /// A window at ρ = 0.3 settled again: the size 3.62, followed from the
    /// circle at fixed ā, has a state at ρ = 0.3, and the family at
    /// ρ = 0.3 traced in ā from it folds on both sides, resolved below
    /// 1e-9, as committed (docs/data/exact_windows.jsonl). Two second
    /// routes: the lower fold is the one that the arm carrying the state at
    /// F̄ = 10 passes (ā = 3.600373, F̄ = 10.951: that state, reached from a
    /// larger contact at ρ = 0.4, traced down in ā to its fold;
    /// docs/exact.md, "Below the fold"), and the size of the upper fold,
    /// followed from the circle at fixed ā, turns back at ρ = 0.3.
    #[test]
    #[ignore = "slow tier (.ci/slow): about 65 s; the reach at rho = 0.2 stays in CI"]
    fn a_window_at_rho_0_3_is_settled_by_two_folds_that_other_routes_find() {
        let map = from_json_lines(&committed("exact_reach.jsonl")).expect("reach lines");
        let committed =
            windows_from_json_lines(&committed("exact_windows.jsonl")).expect("window lines");
        let was = committed
            .iter()
            .find(|w| w.rho == 0.3 && (w.grid[0] - 3.61).abs() < 1e-9)
            .expect("the committed window");
        let thin = crate::cutoff::Cutoff::for_thinness(0.3).unwrap();
        let is = settle_one(&map, 0.3, was.grid, Some(thin)).unwrap();
        assert_eq!(is.a_bar, was.a_bar);
        // the start's coatings and its loading path at h/L = 0.3, as committed
        let (c, c0) = (
            is.coatings.unwrap().load.unwrap(),
            was.coatings.unwrap().load.unwrap(),
        );
        assert!((c.from - c0.from).abs() < 1e-9, "{c:?} against {c0:?}");
        let (p, p0) = (is.unloading.unwrap(), was.unloading.clone().unwrap());
        assert!((p.last_force_bar - p0.last_force_bar).abs() < 1e-6, "{p:?}");
        assert!((p.resolved_force_bar - p0.resolved_force_bar).abs() < 1e-6);
        assert_eq!(p.unresolved.map(|u| u.0), Some(14));
        assert_eq!(p0.unresolved.map(|u| u.0), Some(14));
        // where it passes that band onto the piece below, as committed
        match (p.passed_to, p0.passed_to) {
            (Some(x), Some(x0)) => assert!(
                (x[0] - x0[0]).abs() < 1e-6 && (x[1] - x0[1]).abs() < 1e-6,
                "{x:?} against {x0:?}"
            ),
            (x, x0) => assert_eq!(x.is_some(), x0.is_some(), "{x:?} against {x0:?}"),
        }
        let fold = |e: &WindowEnd| match e {
            WindowEnd::Fold {
                a_bar,
                force_bar,
                bc_error,
                ..
            } => {
                assert!(*bc_error < CONVERGED, "{e:?}");
                (*a_bar, *force_bar)
            }
            other => panic!("{other:?}"),
        };
        for (now, then) in [(&is.lower, &was.lower), (&is.upper, &was.upper)] {
            let (a, f) = fold(now);
            let (a0, f0) = fold(then);
            assert!(
                (a - a0).abs() < 1e-8 && (f - f0).abs() < 1e-6,
                "{now:?} against {then:?}"
            );
        }
        let (lower, force) = fold(&is.lower);
        assert!((lower - 3.600373).abs() < 2e-6 && (force - 10.951).abs() < 1e-3);
        let (upper, _) = fold(&is.upper);
        let reach = reach_of(&of_size(upper, MODES).unwrap()).expect("a reach");
        assert!(
            (reach - 0.3).abs() < 1e-6,
            "the upper fold's size reaches {reach}"
        );
    }

    /// The lower side of the window 3.78 – 3.79 at ρ = 0.2, which 128
    /// modes stop resolving at ā = 3.775 (F̄ = 10.38), taken on with more
    /// modes (the trace of `larger_contacts` with raised modes) reaches
    /// F̄ = 10 at the state that `exact solve --rho 0.2 --force 10` finds
    /// by another route, on a larger contact's arm from ρ = 0.22 with 256
    /// modes (ā = 3.7732982559, δ̄ = 3.3227651249; docs/exact.md, "Below
    /// ρ = 0.3"): that state lies on a piece connected to the circle.
    #[test]
    fn the_state_at_force_10_and_rho_0_2_lies_on_the_piece_of_the_window_3_78() {
        let (a_bar, rho) = (3.78, 0.2);
        let start = from_the_circle(a_bar, Truncation::in_arclength(MODES))
            .unwrap()
            .unwrap();
        let Followed::Reached(st) = follow(&start, rho, Hold::Size(a_bar)).unwrap() else {
            panic!("the size 3.78 reaches rho = 0.2");
        };
        let ex = Exact::on(st.gap, rho, st.truncation)
            .unwrap()
            .deferring_stability();
        let end =
            crate::exact::larger_contacts::traced_with_raised_modes(&ex, &st, Hold::Force(10.0))
                .unwrap();
        let crate::exact::branch::ArmEnd::Reached(at) = end else {
            panic!("the piece does not reach F = 10");
        };
        assert!(at.bc_error < 1e-6, "boundary error {:e}", at.bc_error);
        assert!(
            (at.a_bar - 3.7732982559).abs() < 1e-8 && (at.delta_bar - 3.3227651249).abs() < 1e-8,
            "a = {}, delta = {}",
            at.a_bar,
            at.delta_bar
        );
    }

    /// A second route to the band maps at the level of their edges: every
    /// edge that `bands` located at ρ = 0.5 and 0.4 (traces in ā from
    /// `conformal:8`'s states, docs/data/exact_bands.jsonl) is a fold of a
    /// window settled from the circle at that ρ
    /// (docs/data/exact_windows.jsonl), to 1e-9 in ā, with the same mode.
    #[test]
    fn every_band_edge_at_rho_0_5_and_0_4_is_a_fold_of_a_settled_window() {
        let maps = crate::report::band_maps_from_json_lines(&committed("exact_bands.jsonl"))
            .expect("band map lines");
        let windows =
            windows_from_json_lines(&committed("exact_windows.jsonl")).expect("window lines");
        for rho in [0.5, 0.4] {
            let folds: Vec<(f64, Option<usize>)> = windows
                .iter()
                .filter(|w| w.rho == rho)
                .flat_map(|w| [&w.lower, &w.upper])
                .filter_map(|e| match e {
                    WindowEnd::Fold { a_bar, mode, .. } => Some((*a_bar, *mode)),
                    _ => None,
                })
                .collect();
            let map = maps.iter().find(|m| m.rho == rho).expect("the map");
            assert!(map.bands.len() >= 5, "{} bands at {rho}", map.bands.len());
            for edge in map.bands.iter().flat_map(|b| [&b.lower, &b.upper]) {
                assert!(
                    folds
                        .iter()
                        .any(|&(a, n)| (a - edge.a_bar).abs() < 1e-9 && n == edge.mode),
                    "the edge a = {} (n = {:?}) at rho = {rho} is no settled fold",
                    edge.a_bar,
                    edge.mode
                );
            }
        }
    }

    /// A second route to where a window's path passes its band: the state
    /// beyond (found by Newton's method at fixed ā from the contour with
    /// the short undulations taken off, `studies::loading`) lies on the
    /// piece of another window at the same ρ, between that window's two
    /// folds in ā and in F̄ (located by traces of the family, `settle`),
    /// below the window it left (docs/data/exact_windows.jsonl), at
    /// ρ = 0.5, 0.4 and 0.3, from every window settled by two folds. (At
    /// ρ = 0.2 the one path's landing, ā = 4.103, lies between two windows
    /// whose traces end unresolved, on no settled piece; the window of
    /// ā = 4.5, open above, passes a band inside its own range.)
    #[test]
    fn every_band_a_window_path_passes_lands_on_the_piece_of_a_settled_window_below() {
        let windows =
            windows_from_json_lines(&committed("exact_windows.jsonl")).expect("window lines");
        let fold = |e: &WindowEnd| match e {
            WindowEnd::Fold {
                a_bar, force_bar, ..
            } => Some((*a_bar, *force_bar)),
            _ => None,
        };
        let mut passes = 0;
        for w in windows
            .iter()
            .filter(|w| w.rho >= 0.3 && fold(&w.lower).is_some() && fold(&w.upper).is_some())
        {
            let Some([force, a_bar]) = w.unloading.as_ref().and_then(|p| p.passed_to) else {
                continue;
            };
            passes += 1;
            let below = windows.iter().find(|v| {
                v.rho == w.rho
                    && v.a_bar < w.a_bar
                    && match (fold(&v.lower), fold(&v.upper)) {
                        (Some(lo), Some(up)) => {
                            lo.0 <= a_bar && a_bar <= up.0 && lo.1 <= force && force <= up.1
                        }
                        _ => false,
                    }
            });
            assert!(
                below.is_some(),
                "the path from a = {} at rho = {} lands at a = {a_bar}, F = {force}, on no settled piece below",
                w.a_bar,
                w.rho
            );
        }
        assert_eq!(passes, 23);
    }

    /// The settled windows' table in docs/exact.md is what
    /// [`windows_markdown`] renders from docs/data/exact_windows.jsonl.
    #[test]
    fn the_windows_table_in_the_docs_is_the_committed_windows() {
        let w = windows_from_json_lines(&committed("exact_windows.jsonl")).expect("window lines");
        assert!([0.5, 0.4, 0.3, 0.2]
            .iter()
            .all(|&rho| w.iter().any(|w| w.rho == rho)));
        let table = windows_markdown(&w);
        let doc = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/exact-record.md"),
        )
        .unwrap();
        assert!(
            doc.contains(&table),
            "docs/exact-record.md's windows table is stale; it should read:\n{table}"
        );
    }

    /// Bad ranges are typed errors that name the parameter, before anything
    /// is computed or allocated.
    #[test]
    fn a_reach_map_checks_its_range_first() {
        let name = |r: Result<Vec<SizeReach>>| match r {
            Err(crate::error::Error::OutOfRange { name, .. }) => name,
            other => panic!("{other:?}"),
        };
        assert_eq!(name(reach(f64::NAN, 4.0, 0.01)), "from");
        assert_eq!(name(reach(0.1, 4.0, 0.01)), "from");
        assert_eq!(name(reach(2.0, 4.0, 0.0)), "step");
        assert_eq!(name(reach(2.0, 4.0, f64::INFINITY)), "step");
        assert_eq!(name(reach(2.0, 1.0, 0.01)), "to");
        assert_eq!(name(reach(2.0, 1e300, 0.01)), "to");
        assert_eq!(name(reach(2.0, 9.0, 0.001)), "to");
    }

    /// [`windows`] groups consecutive sizes below ρ; a stopped size breaks
    /// a window.
    #[test]
    fn windows_are_runs_of_sizes_that_reach_below_rho() {
        let size = |a_bar: f64, reached: Reached| SizeReach {
            a_bar,
            modes: 8,
            reached,
        };
        let turns = |rho: f64| Reached::TurnsBack {
            rho,
            bc_error: Some(1e-12),
        };
        let map = vec![
            size(2.0, turns(0.5)),
            size(2.1, turns(0.2)),
            size(2.2, Reached::Floor { bc_error: 1e-12 }),
            size(2.3, Reached::Stopped { why: "x".into() }),
            size(2.4, turns(0.25)),
            size(2.5, turns(0.35)),
        ];
        assert_eq!(windows(&map, 0.3), vec![[2.1, 2.2], [2.4, 2.4]]);
        assert_eq!(windows(&map, 0.1), vec![[2.2, 2.2]]);
        assert_eq!(windows(&map, 0.01), Vec::<[f64; 2]>::new());
    }
}
