//! The command line's studies of the exact family (issue 32): where the
//! loading path and the unloading trace begin (`start`), the loading path
//! with its jump rule (`loading`, `descent`, the potential it lowers:
//! `potential`), the unloading trace
//! (`unloading`), the reach in ρ of each contact size with the windows
//! it leaves (`reach`), the map of where the search finds no state
//! (`no_state_map`), the stored pull-offs (`stored_pull_offs`) and the
//! band map (`band_map`), the pull-off's second route that checks the first
//! (`model_contour`); and the map of (2)'s pull-off error against the
//! coatings' thinness and the crossing angle (`thickness_map`, issue 71).
//! They answer `thinjkr exact pull-off --unloading` and
//! `--from-model-contour`, `thinjkr exact reach`, `exact bands` and
//! `thinjkr thickness-map`, and compile with the feature `cli` only:
//! the engines they drive (`exact`, `layer`) need none of them.
//!
//! Owns: its submodules. May use: `exact` (the engine), `layer` (the
//! coatings' pull-offs), `report` (the shapes of their outcomes),
//! `conformal` (a gap by its name), `accuracy` (the ρ of its table), `control`, `continuation`, `cutoff`,
//! `error`, `newton`, `progress`.

pub(crate) mod band_map;
pub(crate) mod descent;
pub(crate) mod loading;
pub(crate) mod model_contour;
pub(crate) mod no_state_map;
pub(crate) mod potential;
pub(crate) mod reach;
pub(crate) mod start;
pub(crate) mod stored_pull_offs;
pub(crate) mod thickness_map;
pub(crate) mod unloading;
