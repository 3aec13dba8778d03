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
//! The equations are the derived ones: where the paper's printed formulas
//! differ ((18), (25)₁, (26), (27); see `docs/errata.md`), the derived forms
//! are used.

#![deny(missing_docs)]
// `!(x > 0.0)` is how this crate turns a NaN away together with the values
// out of range; the `partial_cmp` form clippy asks for says it less plainly.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod accuracy;
pub mod batch;
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
pub mod registry;
pub mod report;
pub(crate) mod slender;
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
pub use error::{Error, Result};
pub use model::{Model, ModelId};
