//! criterion benchmarks of the grid solver of issue 71 (crate-internal,
//! reached through the `bench-internals` feature): one product with the
//! pair's compliance on n × n cells (zero-padded FFTs on 2n × 2n), and one
//! with the stiffness (the preconditioner's), side by side for n = 64 to
//! 1024, h/L = 1; and the pull-off at ρ = 1, h/L = 1 on the first rungs of
//! the docs' ladder (ε = 0.2 and 0.1, four cells across the zone); and
//! the sharp edge's pull-off (`layer::sharp`) at θ = 60° with the guide's
//! coatings (ρ = 1/3, h/L = 0.5785), on the rungs 12 × 3, 16 × 4 and
//! 20 × 5, as the model layer answers it.
//!
//! `cargo bench -p thinjkr --bench grid --features bench-internals`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use thinjkr::bench_internals::{GridProduct, GridPullOff, SharpPullOff};

fn benches(c: &mut Criterion) {
    let mut g = c.benchmark_group("grid product");
    g.sample_size(10);
    for n in [64, 128, 256, 512, 1024] {
        let mut grid = GridProduct::new(1.0, n);
        g.bench_function(format!("compliance, n = {n}"), |b| {
            b.iter(|| black_box(grid.apply()))
        });
        g.bench_function(format!("stiffness, n = {n}"), |b| {
            b.iter(|| black_box(grid.stiffen()))
        });
    }
    g.finish();
    let mut g = c.benchmark_group("grid pull-off");
    g.sample_size(10);
    let ladder = GridPullOff::new(1.0, &[(0.2, 4.0), (0.1, 4.0)]);
    g.bench_function("rho = 1, h/L = 1, eps = 0.2 then 0.1", |b| {
        b.iter(|| black_box(ladder.run()))
    });
    g.finish();
    let mut g = c.benchmark_group("sharp pull-off");
    g.sample_size(10);
    let sharp = SharpPullOff::new(0.5785474, 1.0 / 3.0).expect("coatings in range");
    g.bench_function("rho = 1/3, h/L = 0.5785, 12 x 3 to 20 x 5", |b| {
        b.iter(|| black_box(sharp.run().expect("a pull-off")))
    });
    g.finish();
}

criterion_group!(grid, benches);
criterion_main!(grid);
