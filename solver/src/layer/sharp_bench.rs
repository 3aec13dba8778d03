//! The sharp edge's hook for the criterion benches (issue 71, item 5),
//! built only with the `bench-internals` feature: the pull-off the model
//! layer answers with in the plane, the sharp edge's ladder and its bound
//! (`layer::plane::by_sharp_edge`).
//!
//! Owns: `SharpPullOff`. May use: `layer` (the pair) and its `plane`,
//! `error`.

use super::plane::by_sharp_edge::pull_off;
use super::Layers;
use crate::error::Result;

/// The sharp edge's pull-off for the criterion benches (built only with
/// the `bench-internals` feature): two equal incompressible coatings of
/// thinness `thinness` at `rho`, on the rungs 12 × 3, 16 × 4 and 20 × 5.
pub struct SharpPullOff {
    layers: Layers,
    rho: f64,
}

impl SharpPullOff {
    /// The coatings of thinness `thinness` at `rho`.
    pub fn new(thinness: f64, rho: f64) -> Result<SharpPullOff> {
        Ok(SharpPullOff {
            layers: Layers::equal(thinness, 0.5)?,
            rho,
        })
    }

    /// The pull-off's force, the finest rung's.
    pub fn run(&self) -> Result<f64> {
        Ok(pull_off(&self.layers, self.rho)?.force_bar)
    }
}
