//! criterion benchmarks of the solver at ρ = 0.8: one warm-started
//! displacement-controlled solve (Newton on the generated residuals from a
//! nearby state), one cold solve (bracketing along the branch, then Newton),
//! pull-off, zero force, and a curve of 1 000 points.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use nalgebra::Vector2;
use thinjkr::curve::trace;
use thinjkr::newton::{solve, NewtonConfig};
use thinjkr::{Contact, ModelId};

fn benches(c: &mut Criterion) {
    let contact = Contact::new(0.8).unwrap();
    let model = ModelId::Max.model();
    let prev = contact.at_displacement(2.0).unwrap();
    let cfg = NewtonConfig::default();
    let mut g = c.benchmark_group("rho=0.8");
    g.bench_function("warm displacement solve", |b| {
        b.iter(|| {
            solve(
                |x| model.residuals_and_jacobian(x, 0.8, black_box(1.999)),
                |a| model.residual_scale(a, 1.999),
                Vector2::new(prev.a_bar, prev.s),
                &cfg,
                "bench",
            )
            .unwrap()
        })
    });
    g.bench_function("cold displacement solve", |b| {
        b.iter(|| contact.at_displacement(black_box(2.0)).unwrap())
    });
    g.bench_function("pull-off (load control)", |b| {
        b.iter(|| contact.pull_off_load().unwrap())
    });
    g.bench_function("zero force", |b| b.iter(|| contact.zero_force().unwrap()));
    g.sample_size(10);
    g.bench_function("curve of 1000 points", |b| {
        b.iter(|| trace(&contact, black_box(1000), 20.0).unwrap())
    });
    g.finish();
}

criterion_group!(solver_benches, benches);
criterion_main!(solver_benches);
