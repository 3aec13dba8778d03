//! criterion benchmarks of the exact solver (`thinjkr::exact`): one exact
//! state warm-started from a neighbour on the family (Newton with the
//! central-difference Jacobian) at ρ = 0.8 (12 modes, 192 points: pull-off
//! converged to 4e-9, see docs/exact.md) and at ρ = 0.5 (24 modes, 384
//! points), and one exact load-controlled pull-off at ρ = 0.8 (continuation
//! from the circle, tracing, refinement).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use thinjkr::exact::{Exact, Truncation};

fn benches(c: &mut Criterion) {
    let mut g = c.benchmark_group("exact");
    g.sample_size(10);
    for (rho, modes) in [(0.8, 12), (0.5, 24)] {
        let ex = Exact::new(
            rho,
            Truncation {
                modes,
                points: 16 * modes,
            },
        )
        .unwrap();
        let near = ex.from_circle(2.6).unwrap();
        g.bench_function(format!("state at rho = {rho} ({modes} modes), warm"), |b| {
            b.iter(|| ex.solve_from(black_box(2.59), &near).unwrap())
        });
    }
    let ex = Exact::new(
        0.8,
        Truncation {
            modes: 12,
            points: 192,
        },
    )
    .unwrap();
    g.bench_function("pull-off at rho = 0.8 (12 modes)", |b| {
        b.iter(|| ex.pull_off_load().unwrap())
    });
}

criterion_group!(exact_benches, benches);
criterion_main!(exact_benches);
