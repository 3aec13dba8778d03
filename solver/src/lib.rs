//! thinjkr: the approximate JKR model of adhesive contact between two thin
//! incompressible elastic coatings on rigid cylinders (Argatov, Mishuris &
//! Popov, Tribology Letters 64:12, 2016), solved with Newton's method on
//! residuals, Jacobians and model functions generated from a symbolic
//! derivation (crate `thinjkr-derive`). No symbolic algebra at run time.
//!
//! Several closures of the same ellipse are generated, each one value
//! behind [`Model`], chosen at run time by [`ModelId`]: `max` (the paper's,
//! the default), `apexes`, `energy` (Ritz, with stability) and `apex45`
//! (∂p/∂ν equal at t = 0 and t = π/4, a second collocation).
//!
//! [`layer`] measures the thin-layer equation (2) itself: the contact of
//! coatings of finite thickness at ρ = 1, from three-dimensional elasticity,
//! whose limits are (2) (thin) and JKR's half-space contact (thick).
//!
//! The way in is two functions: [`solve`] (a state of any model at a given
//! δ̄, F̄ or ā) and [`pull_off`] (where a branch ends), each taking the
//! model by the name `thinjkr models` lists.
//!
//! The equations are the derived ones: where the paper's printed formulas
//! differ ((18), (25)₁, (26), (27); see `docs/errata.md`), the derived forms
//! are used.

#![deny(missing_docs)]
// `!(x > 0.0)` is how this crate turns a NaN away together with the values
// out of range; the `partial_cmp` form clippy asks for says it less plainly.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod accuracy;
pub(crate) mod ansatz;
pub mod batch;
/// Hooks into crate-internal machinery for the criterion benches, built
/// only with the `bench-internals` feature; not an API.
#[cfg(feature = "bench-internals")]
#[doc(hidden)]
pub mod bench_internals;
#[cfg(feature = "cli")]
#[doc(hidden)]
pub mod cli;
pub mod conformal;
pub mod contact;
pub(crate) mod continuation;
pub(crate) mod contour_modes;
pub mod control;
pub mod curve;
pub mod cutoff;
pub(crate) mod equations;
pub mod error;
pub mod exact;
#[cfg(feature = "figures")]
pub mod figures;
pub mod fold;
#[allow(missing_docs)]
#[rustfmt::skip]
pub mod generated;
pub mod layer;
pub mod limits;
pub mod model;
pub mod newton;
pub(crate) mod progress;
pub(crate) mod quadrature;
pub mod registry;
pub mod report;
pub(crate) mod slender;
#[cfg(feature = "cli")]
pub(crate) mod studies;
pub mod units;

/// The user's guide.
///
/// In the source repository (where `.cargo/config.toml` sets
/// `--cfg thinjkr_guide` for rustdoc) this module holds `docs/guide.md`
/// itself, whose Rust examples run as doctests; in the packaged crate,
/// which has no `docs/`, it points there.
#[cfg_attr(thinjkr_guide, doc = include_str!("../../docs/guide.md"))]
#[cfg_attr(
    not(thinjkr_guide),
    doc = "The guide is `docs/guide.md` in thinjkr's source repository: the model in a page, units, the library, the command line, limits and exit statuses."
)]
pub mod guide {}

pub use contact::{Contact, FoldBasis, PullOff, Search, Stability, State};
pub use control::Hold;
pub use error::{Error, Result};
pub use fold::FoldCondition;
pub use registry::PullOffAnswer;
pub use report::AnyState;
pub use {generated::ModelId, model::Model};

/// The state of the model named `model` at the ratio of principal relative
/// curvatures `rho` (ρ = 1 for cylinders crossed at 90°), held at `hold`:
/// the one way to any model's state, the one the command line's `solve`
/// and the Python package's `solve` take (`registry::Choice::state`).
///
/// `model` is any name `thinjkr models` lists: `max` (the paper's), `energy`,
/// `conformal:8`, `slender`, `exact`, `layer`, …. Every quantity is in the
/// dimensionless units (17) of the paper; `units` converts physical inputs.
/// At a given F̄ the state is the stable one on the branch from large loads;
/// at a given ā the one before the contact-size fold.
///
/// ```
/// use thinjkr::Hold;
/// // the paper's model at ρ = 0.8 under zero load (Section 5): its ā is
/// // within 0.2 % of the exact solution's, 2.909088 (docs/accuracy.md)
/// let state = thinjkr::solve("max", 0.8, Hold::Force(0.0))?;
/// let (a_bar, b_bar, _delta_bar, force_bar) = state.size_and_load();
/// assert!(b_bar < a_bar && force_bar.abs() < 1e-12);
/// assert!((a_bar / 2.909088 - 1.0).abs() < 2e-3);
/// # Ok::<(), thinjkr::Error>(())
/// ```
///
/// A name no model has, or a value out of its range, is a typed error that
/// names it:
///
/// ```
/// use thinjkr::{Hold, Error};
/// assert_eq!(thinjkr::solve("maxx", 0.8, Hold::Delta(2.0)).unwrap_err().kind(), "usage");
/// let e = thinjkr::solve("max", 1.5, Hold::Delta(2.0)).unwrap_err();
/// assert!(matches!(e, Error::OutOfRange { name: "rho", .. }));
/// ```
pub fn solve(model: &str, rho: f64, hold: Hold) -> Result<AnyState> {
    registry::parse(model)
        .map_err(Error::Usage)?
        .state(rho, hold)
}

/// The pull-off of the model named `model` at `rho`: where the branch from
/// large loads ends under load control (`FoldCondition::Load`, the first
/// minimum of F̄) or displacement control (`FoldCondition::Displacement`, the
/// first extremum of δ̄; not located for `exact`), with what ends it there
/// and what its trace passed (`registry::Choice::pull_off`).
///
/// ```
/// use thinjkr::FoldCondition;
/// // the paper's model and a richer contour at ρ = 0.8 against the exact
/// // pull-off, F̄ = −4.1976054 (docs/accuracy.md): 0.21 % and 1.5e-7 off
/// let paper = thinjkr::pull_off("max", 0.8, FoldCondition::Load)?;
/// let contour = thinjkr::pull_off("conformal:8", 0.8, FoldCondition::Load)?;
/// let off = |p: &thinjkr::PullOffAnswer| (p.state.size_and_load().3 / -4.1976054 - 1.0).abs();
/// assert!(off(&paper) < 2.5e-3 && off(&contour) < 1e-6);
/// # Ok::<(), thinjkr::Error>(())
/// ```
pub fn pull_off(model: &str, rho: f64, control: FoldCondition) -> Result<PullOffAnswer> {
    registry::parse(model)
        .map_err(Error::Usage)?
        .pull_off(rho, control)
}
