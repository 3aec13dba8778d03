//! The sharp edge's hook for the criterion benches (issue 71, item 5),
//! built only with the `bench-internals` feature: the pull-off of
//! `layer::sharp` on its first two rungs.
//!
//! Owns: `SharpPullOff`. May use: `layer` (the pair) and its `sharp`,
//! `error`.

use super::sharp::{pull_off_ladder, Resolution};
use super::Layers;
use crate::error::Result;

/// The sharp edge's pull-off for the criterion benches (built only with
/// the `bench-internals` feature): two equal incompressible coatings of
/// thinness `thinness` at `rho`, on the rungs 12 × 3 and then 16 × 4.
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

    /// The pull-off's force on the finer rung.
    pub fn run(&self) -> Result<f64> {
        let rungs = [
            Resolution::rung(12, 3, 8, 32),
            Resolution::rung(16, 4, 16, 64),
        ];
        let ladder = pull_off_ladder(&self.layers, self.rho, &rungs, |_, _| {})?;
        Ok(ladder[1].force_bar)
    }
}
