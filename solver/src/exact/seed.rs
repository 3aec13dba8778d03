//! The exact solver's starting guesses, handed in with the gap by the layer
//! above: an approximate model of the same gap (the registry gives the
//! largest member of the contour family that seeds it, `conformal:8` for the
//! cylinders) as a [`Seed`], which the solver asks for near-elliptic states
//! ([`Guess`]) and never names. Without a seed the solver starts from the
//! circle (continued in ρ), where the gap allows it.
//!
//! Owns: [`Seed`], [`Guess`]. May use: `control`, `error`, its parent
//! `exact` (`Contour`).

use crate::control::Hold;

/// An approximate state the exact solver starts from: its half-widths,
/// approach, force and how far it misses (3)₂ (the model's boundary
/// defect).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Guess {
    pub a_bar: f64,
    pub b_bar: f64,
    pub s: f64,
    pub delta_bar: f64,
    pub force_bar: f64,
    pub bc_defect: f64,
}

/// What gives the exact solver of a gap its starting guesses.
pub(crate) trait Seed: Send + Sync + std::fmt::Debug {
    /// The model's name, for messages and the band map.
    fn name(&self) -> String;
    /// ā at which the pull-off's trace from the circle starts, where the
    /// model's family says (between the circle's neutral points of modes 4
    /// and 6 of the gap; `crate::exact::gap::GapAt::trace_start`).
    fn trace_start(&self) -> Option<f64>;
    /// The model's state at `rho` under `hold`, or why it has none.
    fn state(&self, rho: f64, hold: Hold) -> crate::Result<Guess>;
    /// The model's load-controlled pull-off at `rho`, where it has one.
    fn pull_off(&self, rho: f64) -> Option<Guess>;
    /// The same pull-off with the model's own contour, the boundary of its
    /// map of the disk z = Σ c_p e^{ipθ} (odd p) as a [`super::Contour`]: A the
    /// coefficient of p = 1, the c_j those of p = 2j + 3 (the arclength
    /// representation's positive powers, which hold the map as it is). The
    /// start of the pull-off's second route (`studies::model_contour`).
    #[cfg(feature = "cli")]
    fn pull_off_contour(&self, rho: f64) -> Option<(Guess, super::Contour)>;
}
