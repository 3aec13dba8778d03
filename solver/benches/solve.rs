//! criterion benchmarks of the solver at ρ = 0.8: one warm-started
//! displacement-controlled solve (Newton on the generated residuals from a
//! nearby state), one cold solve (bracketing along the branch, then Newton),
//! pull-off, zero force, and a curve of 1 000 points; and, side by side in
//! one group, the warm sweep of the peer comparison (20 000 solves, δ̄ from
//! 6 to 0.5, each from the previous) with the generated residuals through
//! `&dyn Model` and with the hand-written ones; the slender model's states
//! through the model layer.

#[path = "peer/handwritten.rs"]
mod handwritten;

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use nalgebra::{Matrix2, Vector2};
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

/// 20 000 warm-started solves at ρ = 0.8, δ̄ from 6 down to 0.5.
fn sweep(
    f: impl Fn(Vector2<f64>, f64) -> (Vector2<f64>, Matrix2<f64>),
    start: Vector2<f64>,
) -> Vector2<f64> {
    let cfg = NewtonConfig::default();
    let mut x = start;
    for k in 0..20_000 {
        let delta = 6.0 - 5.5 * k as f64 / 19_999.0;
        let sol = solve(|v| f(v, delta), |a| 1.0 + a * a * a, x, &cfg, "sweep").unwrap();
        x = Vector2::new(sol.a_bar, sol.s);
    }
    x
}

fn warm_sweep(c: &mut Criterion) {
    let start = Contact::new(0.8).unwrap().at_displacement(6.0).unwrap();
    let x0 = Vector2::new(start.a_bar, start.s);
    let model = ModelId::Max.model();
    let mut g = c.benchmark_group("warm sweep, 20000 solves");
    g.sample_size(30);
    g.bench_function("generated, &dyn Model", |b| {
        b.iter(|| {
            sweep(
                |v, d| model.residuals_and_jacobian(v, 0.8, d),
                black_box(x0),
            )
        })
    });
    g.bench_function("hand-written", |b| {
        b.iter(|| {
            sweep(
                |v, d| {
                    let (r, j) = handwritten::residuals_and_jacobian(v[0], v[1], 0.8, d);
                    (
                        Vector2::new(r[0], r[1]),
                        Matrix2::new(j[0][0], j[0][1], j[1][0], j[1][1]),
                    )
                },
                black_box(x0),
            )
        })
    });
    g.finish();
}

/// The slender model (issue 32: a state within 2 µs) through the model
/// layer: a state at δ̄, at F̄, and the pull-off.
fn slender(c: &mut Criterion) {
    use thinjkr::control::Hold;
    let m = thinjkr::registry::parse("slender").unwrap();
    let mut g = c.benchmark_group("slender, rho=0.1");
    g.bench_function("state at delta", |b| {
        b.iter(|| m.state(0.1, Hold::Delta(black_box(1.0))).unwrap())
    });
    g.bench_function("state at force", |b| {
        b.iter(|| m.state(0.1, Hold::Force(black_box(1.0))).unwrap())
    });
    g.bench_function("pull-off (load control)", |b| {
        b.iter(|| {
            m.pull_off(black_box(0.1), thinjkr::fold::FoldCondition::Load)
                .unwrap()
        })
    });
    g.finish();
}

criterion_group!(solver_benches, benches, warm_sweep, slender);
criterion_main!(solver_benches);
