//! The grid solver's hooks for the criterion benches and the peers'
//! comparison (issue 71, item 5), built only with the `bench-internals`
//! feature: the compliance's product and the stiffness's on an n × n grid,
//! a short pull-off ladder, and a sphere on a half-space on a fixed grid
//! (solver/benches/peer/grid_peers.py runs it beside tamaas and
//! ContactMechanics).
//!
//! Owns: `GridProduct`, `GridPullOff`, `SphereOnHalfSpace`, `SphereState`.
//! May use: `layer` (the pair), `error`, and the grid's `kernel`,
//! `Compliance`, `Sheet`, `Target` and `pull_off_ladder`.

use super::kernel::Kernel;
use super::{pull_off_ladder, Compliance, Sheet, SheetState, Target};
use crate::error::Result;
use crate::layer::Layers;
use std::time::Instant;

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

/// A rigid sphere of radius 1 on an elastic half-space of contact modulus
/// E* = 1 (β = ½), work of adhesion ½ (the grid's units with the base
/// taken away), the grid's cohesive law of range `range` on n × n cells
/// over the half width `half_width`: a problem tamaas and ContactMechanics
/// solve too. JKR's pull-off is −(3/2)πRΔγ = −3π/4.
pub struct SphereOnHalfSpace {
    sheet: Sheet,
}

/// One state of [`SphereOnHalfSpace`] and what it cost.
#[derive(Clone, Copy, Debug)]
pub struct SphereState {
    /// The approach.
    pub delta: f64,
    /// The force, compressive positive.
    pub force: f64,
    /// dF/dδ along the branch.
    pub force_slope: f64,
    /// States solved for it (1 for one state; every state of the walk and
    /// the secant for a pull-off).
    pub states: usize,
    /// Newton steps over those states.
    pub steps: usize,
    /// Products with the compliance over those states.
    pub products: usize,
    /// Wall time, seconds.
    pub seconds: f64,
}

impl SphereOnHalfSpace {
    /// The grid (its kernel is built here, outside every timing).
    pub fn new(n: usize, half_width: f64, range: f64) -> SphereOnHalfSpace {
        let dx = 2.0 * half_width / n as f64;
        SphereOnHalfSpace {
            sheet: Sheet::on(Kernel::half_space(0.5, n, dx), 1.0, n, dx, range),
        }
    }

    /// The states at `deltas` in turn, the first from no guess (a loaded
    /// contact is the easy start), each next from the last one's gaps moved
    /// along their slope in δ, as an unloading curve is followed.
    pub fn sweep(&self, deltas: &[f64]) -> Result<Vec<SphereState>> {
        let mut out = Vec::with_capacity(deltas.len());
        let mut last: Option<SheetState> = None;
        for &d in deltas {
            let before = self.sheet.work.get();
            let clock = Instant::now();
            let state = match &last {
                None => self.sheet.cold_state(d)?,
                Some(s) => self.sheet.state(d, &Sheet::predict(s, d))?,
            };
            out.push(self.record(&state, before, clock));
            last = Some(state);
        }
        Ok(out)
    }

    /// The pull-off under load control, from the state at `from` (solved
    /// from no guess, not counted): steps of `step` in δ, then the secant
    /// on dF/dδ to `tol` in δ (the grid's own walk, `Sheet::find`).
    pub fn pull_off(&self, from: f64, step: f64, tol: f64) -> Result<SphereState> {
        let first = self.sheet.cold_state(from)?;
        let before = self.sheet.work.get();
        let clock = Instant::now();
        let state = self.sheet.find(Target::PullOff, first, step, tol)?;
        Ok(self.record(&state, before, clock))
    }

    fn record(&self, state: &SheetState, before: super::Work, clock: Instant) -> SphereState {
        let seconds = clock.elapsed().as_secs_f64();
        let work = self.sheet.work.get();
        SphereState {
            delta: state.delta_bar,
            force: state.force_bar,
            force_slope: state.force_slope,
            states: work.states - before.states,
            steps: work.steps - before.steps,
            products: work.products - before.products,
            seconds,
        }
    }
}
