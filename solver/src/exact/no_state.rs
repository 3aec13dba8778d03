//! The map of where the exact search finds no state (issue 72): at each
//! force and approach of a grid, the search of `resolve` (every route)
//! run once at each ρ of a ladder below ρ = 0.3, and its outcome stored by
//! `thinjkr exact store-no-state` in `solver/data/exact_no_state.json`.
//! Below the fold in ρ of the family at a control the search tries arms of
//! larger contacts, rung after rung, and takes minutes to say it found
//! none (zero force at ρ = 0.15: 94 s; F̄ = 10 at ρ = 0.1: more than 25 min).
//! A request inside a cell of the map (between two of its controls and
//! two of its ρ, or on one of them) whose every corner found none is
//! refused at once, citing the map; one whose every corner found none or
//! ran out of the store's time limit without an answer (F̄ = 10 at ρ = 0.1
//! did, at 25 min) is refused at once as not resolved, saying so; `--search`
//! (the command line) searches anyway, without a limit. A cell with a
//! corner where a state was found, or where the search failed otherwise,
//! is searched as before.
//!
//! The map holds the cylinders' gap only; where the file cannot be read,
//! nothing is refused.
//!
//! The map is written by the study `studies::no_state_map`.
//!
//! Owns: [`NoStateMap`], [`Cell`], [`Line`], [`refusal`], [`SEARCH_ANYWAY`].
//! May use: its parent `exact` (the gap), `control`, `error`.

use super::Gap;
use crate::control::Hold;
use crate::error::{short, Error};
use serde::{Deserialize, Serialize};
use std::sync::atomic::{AtomicBool, Ordering};

/// Set by the command line's `--search`: search even where the map says
/// the search finds nothing.
pub(crate) static SEARCH_ANYWAY: AtomicBool = AtomicBool::new(false);

/// Where the map is stored (relative to the solver's crate).
pub(crate) const PATH: &str = "solver/data/exact_no_state.json";

/// The ρ at which the search is run, from just below where the conformal
/// seed's states end (0.3) down to where the stored pull-offs have only a
/// few rungs left.
#[cfg_attr(not(any(feature = "cli", test)), allow(dead_code))]
pub(crate) const LADDER: [f64; 8] = [0.25, 0.2, 0.175, 0.15, 0.125, 0.1, 0.075, 0.05];

/// What the search found at one control and ρ.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub(crate) enum Cell {
    /// A state, of this half-width.
    Found {
        /// ρ.
        rho: f64,
        /// Its ā.
        a_bar: f64,
    },
    /// No state: the search's reason, in brief.
    None {
        /// ρ.
        rho: f64,
        /// What it said.
        why: String,
    },
    /// The search ran the store's whole time limit without an answer:
    /// near it a request is refused as not resolved, unless a corner found
    /// a state.
    Stopped {
        /// ρ.
        rho: f64,
        /// The time limit, in minutes.
        minutes: f64,
    },
    /// The search failed otherwise than by finding no state: nothing is
    /// refused near it.
    Unsettled {
        /// ρ.
        rho: f64,
        /// Why.
        why: String,
    },
}

impl Cell {
    pub(crate) fn rho(&self) -> f64 {
        match self {
            Cell::Found { rho, .. }
            | Cell::None { rho, .. }
            | Cell::Stopped { rho, .. }
            | Cell::Unsettled { rho, .. } => *rho,
        }
    }
}

/// The search's outcomes at one control value, one per ρ of the ladder.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct Line {
    /// `force` or `delta`.
    pub(crate) control: String,
    /// F̄ or δ̄.
    pub(crate) value: f64,
    /// Its cells, by decreasing ρ.
    pub(crate) cells: Vec<Cell>,
}

/// The map as stored.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct NoStateMap {
    /// The command that wrote it.
    pub(crate) generated_by: String,
    /// The time limit of one search, in minutes.
    pub(crate) minutes: f64,
    /// Its lines.
    pub(crate) lines: Vec<Line>,
}

const FILE: &str = include_str!("../../data/exact_no_state.json");

/// The stored map, read once; `None` where the file does not parse.
pub(crate) fn map() -> Option<&'static NoStateMap> {
    static READ: std::sync::OnceLock<Option<NoStateMap>> = std::sync::OnceLock::new();
    READ.get_or_init(|| serde_json::from_str(FILE).ok())
        .as_ref()
}

/// The control's name in the map and its value; `None` for ā.
pub(crate) fn key(control: Hold) -> Option<(&'static str, f64)> {
    match control {
        Hold::Force(v) => Some(("force", v)),
        Hold::Delta(v) => Some(("delta", v)),
        _ => None,
    }
}

/// The refusal of a state at `control` at `rho` on `gap` where the map's
/// cell around it found none at every corner; `None` where it must be
/// searched (or [`SEARCH_ANYWAY`] is set).
pub(crate) fn refusal(gap: Gap, rho: f64, control: Hold) -> Option<Error> {
    if gap != Gap::CYLINDERS || SEARCH_ANYWAY.load(Ordering::Relaxed) {
        return None;
    }
    refusal_in(map()?, rho, control)
}

/// [`refusal`] in `map`.
pub(crate) fn refusal_in(map: &NoStateMap, rho: f64, control: Hold) -> Option<Error> {
    let (name, value) = key(control)?;
    let mut lines: Vec<&Line> = map.lines.iter().filter(|l| l.control == name).collect();
    lines.sort_by(|a, b| a.value.total_cmp(&b.value));
    // the lines at or either side of the value
    let below = lines.iter().rev().find(|l| l.value <= value)?;
    let above = lines.iter().find(|l| l.value >= value)?;
    let (mut corners, mut stopped) = (Vec::new(), Vec::new());
    // the cell of the line at or below the value at or below ρ: what the
    // search said there
    let mut nearest: Option<(f64, &str)> = None;
    for line in [below, above] {
        // the cells at or either side of ρ on this line
        let upper = line
            .cells
            .iter()
            .filter(|c| c.rho() >= rho)
            .min_by(|a, b| a.rho().total_cmp(&b.rho()))?;
        let lower = line
            .cells
            .iter()
            .filter(|c| c.rho() <= rho)
            .max_by(|a, b| a.rho().total_cmp(&b.rho()))?;
        for cell in [upper, lower] {
            match cell {
                Cell::None { .. } => corners.push((line.value, cell.rho())),
                Cell::Stopped { .. } => stopped.push((line.value, cell.rho())),
                Cell::Found { .. } | Cell::Unsettled { .. } => return None,
            }
        }
        if let (None, Cell::None { rho, why }) = (nearest, lower) {
            nearest = Some((*rho, why.as_str()));
        }
    }
    let span = |a: f64, b: f64| {
        if a == b {
            short(a)
        } else {
            format!("{} … {}", short(a), short(b))
        }
    };
    // each corner once (on a line or a ρ of the ladder, the cell's sides
    // coincide), and the cell's range in ρ
    for c in [&mut corners, &mut stopped] {
        c.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        c.dedup();
    }
    let rhos = stopped.iter().chain(&corners).map(|c| c.1);
    let (hi, lo) = (
        rhos.clone().fold(f64::NEG_INFINITY, f64::max),
        rhos.fold(f64::INFINITY, f64::min),
    );
    if !stopped.is_empty() {
        // every corner found none or ran out of time: not resolved
        let at = if stopped.len() + corners.len() == 1 {
            String::new()
        } else if corners.is_empty() {
            format!(" at each of the cell's {} corners", stopped.len())
        } else {
            format!(
                " at {} of the cell's corners, and found none at the other {}",
                stopped.len(),
                corners.len()
            )
        };
        return Some(Error::Unresolved {
            what: format!(
                "the exact search at {name} = {}, rho = {} ran {} min without finding a state{at} (the map {PATH}; --search searches anyway, without a limit); the map was written by `{}`",
                span(below.value, above.value),
                span(hi, lo),
                short(map.minutes),
                map.generated_by,
            ),
            residual: f64::INFINITY,
        });
    }
    let (nearest_rho, first) = nearest?;
    Some(Error::NoState(format!(
        "the exact search finds no state at {name} = {}, rho = {}{} (the map {PATH}; --search searches anyway, for minutes); the map was written by `{}`; at {name} = {}, rho = {} the search said: {first}",
        span(below.value, above.value),
        span(hi, lo),
        if corners.len() == 1 {
            String::new()
        } else {
            format!(", the corners of the cell around {control}, rho = {}", short(rho))
        },
        map.generated_by,
        short(below.value),
        short(nearest_rho),
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn none(rho: f64) -> Cell {
        Cell::None {
            rho,
            why: "nothing".into(),
        }
    }

    fn found(rho: f64) -> Cell {
        Cell::Found { rho, a_bar: 3.0 }
    }

    /// A map of one minute's searches with lines of force (value, cells).
    fn map_of(lines: Vec<(f64, Vec<Cell>)>) -> NoStateMap {
        NoStateMap {
            generated_by: "a test".into(),
            minutes: 1.0,
            lines: lines
                .into_iter()
                .map(|(value, cells)| Line {
                    control: "force".into(),
                    value,
                    cells,
                })
                .collect(),
        }
    }

    fn a_map() -> NoStateMap {
        map_of(vec![
            (0.0, vec![found(0.2), none(0.15), none(0.1)]),
            (2.0, vec![found(0.2), found(0.15), none(0.1)]),
        ])
    }

    /// A request is refused only inside a cell whose every corner found
    /// none; on a line, between two of its cells that found none.
    #[test]
    fn only_a_cell_that_found_none_at_every_corner_refuses() {
        let m = a_map();
        let refused = |rho: f64, f: f64| refusal_in(&m, rho, Hold::Force(f)).is_some();
        assert!(refused(0.15, 0.0));
        assert!(refused(0.12, 0.0));
        assert!(refused(0.1, 0.0));
        assert!(refused(0.1, 1.0));
        // a corner found a state
        assert!(!refused(0.17, 0.0));
        assert!(!refused(0.12, 1.0));
        // outside the map
        assert!(!refused(0.05, 0.0));
        assert!(!refused(0.12, -1.0));
        assert!(!refused(0.12, 3.0));
        assert!(refusal_in(&m, 0.12, Hold::Delta(0.0)).is_none());
        let e = refusal_in(&m, 0.12, Hold::Force(0.0)).unwrap();
        let words = e.to_string();
        assert!(words.contains("--search"), "{words}");
        assert!(words.contains("rho = 0.15 … 0.1"), "{words}");
    }

    /// A cell whose corners found none or ran out of the store's time
    /// limit (F̄ = 10 at ρ = 0.1 did, at 25 min) is refused as not resolved,
    /// saying so; a corner that found a state, or failed otherwise, leaves
    /// it to the search.
    #[test]
    fn a_cell_that_ran_out_of_time_is_refused_as_not_resolved() {
        let stopped = |rho: f64| Cell::Stopped { rho, minutes: 1.0 };
        let failed = Cell::Unsettled {
            rho: 0.1,
            why: "a failure".into(),
        };
        let m = map_of(vec![
            (0.0, vec![found(0.2), none(0.15), none(0.1)]),
            (10.0, vec![found(0.2), stopped(0.15), failed]),
        ]);
        let e = refusal_in(&m, 0.15, Hold::Force(10.0)).expect("refused");
        assert_eq!(e.kind(), "unresolved");
        let words = e.to_string();
        assert!(
            words.contains("ran 1 min without finding a state (") && words.contains("--search"),
            "{words}"
        );
        let e = refusal_in(&m, 0.15, Hold::Force(5.0)).expect("refused");
        assert!(
            e.to_string()
                .contains("at 1 of the cell's corners, and found none at the other 1"),
            "{e}"
        );
        // on a line between two ρ: its two corners, each counted once
        let m2 = map_of(vec![(10.0, vec![found(0.2), stopped(0.15), stopped(0.1)])]);
        let e = refusal_in(&m2, 0.12, Hold::Force(10.0)).expect("refused");
        assert!(
            e.to_string().contains("at each of the cell's 2 corners"),
            "{e}"
        );
        // a corner that failed otherwise, or found a state
        assert!(refusal_in(&m, 0.12, Hold::Force(10.0)).is_none());
        assert!(refusal_in(&m, 0.17, Hold::Force(10.0)).is_none());
    }

    /// The committed map parses, its cells follow the ladder, and every
    /// cell that found none says why.
    #[test]
    fn the_committed_map_reads() {
        let m = map().expect("solver/data/exact_no_state.json parses");
        for l in &m.lines {
            let rhos: Vec<f64> = l.cells.iter().map(Cell::rho).collect();
            assert_eq!(rhos, LADDER.to_vec(), "{} = {}", l.control, l.value);
        }
    }
}
