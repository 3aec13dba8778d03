//! thinjkr: the approximate JKR model of adhesive contact between two thin
//! incompressible elastic coatings on rigid cylinders (Argatov, Mishuris &
//! Popov, Tribology Letters 64:12, 2016), solved with Newton's method on
//! residuals, Jacobians and model functions generated from a symbolic
//! derivation (crate `thinjkr-derive`). No symbolic algebra at run time.

#![deny(missing_docs)]

pub mod error;
#[allow(missing_docs)]
pub mod generated;
pub mod model;
pub mod newton;

pub use error::{Error, Result};
pub use model::{Apex45, Model, Paper};
