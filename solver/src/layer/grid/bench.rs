//! The grid solver's hooks for the criterion benches (issue 71, item 5),
//! built only with the `bench-internals` feature: the compliance's product
//! and the stiffness's on an n × n grid, and a short pull-off ladder.
//!
//! Owns: `GridProduct`, `GridPullOff`. May use: `layer` (the pair), and the
//! grid's `kernel`, `Compliance` and `pull_off_ladder`.

use super::kernel::Kernel;
use super::{pull_off_ladder, Compliance};
use crate::layer::Layers;

/// One product with the compliance, or with the stiffness, on an n × n
/// grid of two equal incompressible coatings.
pub struct GridProduct {
    kernel: Kernel,
    p: Vec<f64>,
    out: Vec<f64>,
}

impl GridProduct {
    /// The kernel of coatings of thinness `thinness` on n × n cells over a
    /// half width of 1.5 length units, and a smooth pressure field.
    pub fn new(thinness: f64, n: usize) -> GridProduct {
        let layers = Layers::equal(thinness, 0.5).expect("a thinness in range");
        let dx = 3.0 / n as f64;
        let kernel = Kernel::new(&layers, n, dx);
        let p = (0..n * n)
            .map(|c| {
                let (i, j) = ((c / n) as f64, (c % n) as f64);
                (0.37 * i).sin() * (0.23 * j).cos()
            })
            .collect();
        GridProduct {
            kernel,
            p,
            out: vec![0.0; n * n],
        }
    }

    /// The displacement of the pressure field.
    pub fn apply(&mut self) -> f64 {
        Compliance::apply(&self.kernel, &self.p, &mut self.out);
        self.out[0]
    }

    /// The stiffness's product (the preconditioner's).
    pub fn stiffen(&mut self) -> f64 {
        self.kernel.stiffen(&self.p, &mut self.out);
        self.out[0]
    }
}

/// The pull-off under load control at ρ = 1 of two equal incompressible
/// coatings, on a ladder of process zones.
pub struct GridPullOff {
    layers: Layers,
    rungs: Vec<(f64, f64)>,
}

impl GridPullOff {
    /// Coatings of thinness `thinness`, the rungs (ε, cells across the zone).
    pub fn new(thinness: f64, rungs: &[(f64, f64)]) -> GridPullOff {
        GridPullOff {
            layers: Layers::equal(thinness, 0.5).expect("a thinness in range"),
            rungs: rungs.to_vec(),
        }
    }

    /// The last rung's pull-off force.
    pub fn run(&self) -> f64 {
        let ladder = pull_off_ladder(&self.layers, 1.0, &self.rungs, &mut |_| {})
            .expect("the ladder's pull-offs");
        ladder.last().expect("rungs").state.force_bar
    }
}
