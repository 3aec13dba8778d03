//! Hooks for the criterion benches of crate-internal machinery, built only
//! with the `bench-internals` feature (solver/benches/grid.rs); not an API.
//!
//! Owns: nothing of its own; it re-exports `layer::grid`'s and
//! `layer::sharp`'s bench hooks.
//! May use: `layer`.

pub use crate::layer::grid::bench::{GridProduct, GridPullOff, SphereOnHalfSpace, SphereState};
pub use crate::layer::sharp_bench::SharpPullOff;
