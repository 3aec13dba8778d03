//! criterion benchmarks of the family `conformal:K` at ρ = 0.8, per K: one
//! evaluation of Π̄ with its gradient and Hessian (the residuals and their
//! Jacobian; for K ≤ 4 by the unrolled evaluator and, side by side, by the
//! table evaluator it unrolls), one cold state at F̄ = 1 (from the circle at ρ = 1, continued
//! in ρ), and the load-controlled pull-off (pseudo-arclength trace from
//! ā = 2.6). The goals: conformal:4 state ≤ 50 µs, conformal:8
//! state ≤ 5 ms, conformal:8 pull-off ≤ 100 ms.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use nalgebra::DVector;
use thinjkr::conformal::Conformal;
use thinjkr::control::Hold;
use thinjkr::fold::FoldCondition;

fn benches(c: &mut Criterion) {
    let mut g = c.benchmark_group("conformal rho=0.8");
    for k in [1, 2, 4, 6, 8] {
        let m = Conformal::member("conformal", k).unwrap();
        let st = m.solve(0.8, Hold::Force(1.0)).unwrap();
        let x =
            DVector::from_iterator(k + 1, st.coefficients.iter().copied().chain([st.delta_bar]));
        g.bench_function(format!("K={k} residuals and Jacobian"), |b| {
            b.iter(|| m.potential(black_box(&x), 0.8))
        });
        if k <= 4 {
            g.bench_function(
                format!("K={k} residuals and Jacobian, table evaluator"),
                |b| b.iter(|| m.potential_by_table(black_box(&x), 0.8)),
            );
        }
        g.bench_function(format!("K={k} cold state at F=1"), |b| {
            b.iter(|| m.solve(0.8, Hold::Force(black_box(1.0))).unwrap())
        });
    }
    g.sample_size(10);
    for k in [4, 8] {
        let m = Conformal::member("conformal", k).unwrap();
        g.bench_function(format!("K={k} pull-off"), |b| {
            b.iter(|| m.pull_off(black_box(0.8), FoldCondition::Load).unwrap())
        });
    }
    g.finish();
}

criterion_group!(conformal_benches, benches);
criterion_main!(conformal_benches);
