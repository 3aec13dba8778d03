//! criterion benchmarks of the exact solver (`thinjkr::exact`): one exact
//! state at ā = 2.59 warm-started from the state at ā = 2.6 (chord Newton
//! with the Jacobian of the discrete equations, then the fine-grid check
//! and the stability of the state) at ρ = 0.8 (12 modes) and at ρ = 0.5
//! (24 modes), 8 points per mode, and one exact load-controlled pull-off
//! at ρ = 0.8 (from conformal:8's pull-off, tracing, refinement) with 16
//! modes, the truncation `exact::resolved` picks for it (boundary error
//! 7e-10; doubling changes F̄ by 1e-14 and s by 4e-11, docs/accuracy.md);
//! and, as the command line computes them, the states at F̄ = 10 at ρ = 0.8,
//! 0.6 (past the fold of the mode-10 band's upper arm, where neither
//! `conformal:8`'s start nor the circle's arms reach it) and 0.5 and the
//! pull-offs at ρ = 0.8 and 0.5 with the truncation
//! escalated until the fine-grid boundary error is below 1e-9
//! (`exact::at_resolved`, `exact::pull_off_resolved`, from `conformal:8`'s
//! states), each with its stability. The set-up checks that each
//! benchmarked state is converged to 1e-9: solved again with twice the
//! modes and points, F̄ and s change by less than that. Last, the
//! pull-off at ρ = 0.1, followed in ρ in the arclength representation.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use thinjkr::control::Hold;
use thinjkr::exact::{self, Exact, Truncation};

fn benches(c: &mut Criterion) {
    let mut g = c.benchmark_group("exact");
    g.sample_size(10);
    for (rho, modes) in [(0.8, 12), (0.5, 24)] {
        let ex = Exact::new(rho, Truncation::with_modes(modes)).unwrap();
        let near = ex.from_circle(2.6).unwrap();
        let st = ex.solve_from(2.59, &near).unwrap();
        let fine = Exact::new(rho, Truncation::with_modes(2 * modes))
            .unwrap()
            .solve(2.59, &st.contour, st.delta_bar)
            .unwrap();
        let change = (fine.force_bar / st.force_bar - 1.0)
            .abs()
            .max((fine.s / st.s - 1.0).abs());
        assert!(
            change < 1e-9,
            "the benchmarked state at rho = {rho} is not converged to 1e-9: {change:e}"
        );
        g.bench_function(format!("state at rho = {rho} ({modes} modes), warm"), |b| {
            b.iter(|| ex.solve_from(black_box(2.59), &near).unwrap())
        });
    }
    let ex = Exact::new(0.8, Truncation::with_modes(16)).unwrap();
    g.bench_function("pull-off at rho = 0.8 (16 modes)", |b| {
        b.iter(|| ex.pull_off_load().unwrap())
    });
    // what `thinjkr exact solve --force 10` and `thinjkr exact pull-off`
    // do: the truncation escalated until the fine-grid boundary error is
    // below 1e-9 (12 modes for F = 10 at rho = 0.8; 12, 16 then 40 at
    // rho = 0.5; 12 then 16 for the pull-off at rho = 0.8, 12, 16 then 48
    // at rho = 0.5), each state from conformal:8's; at rho = 0.6 the model's
    // start and the circle's arms fail first, then the arms beside the
    // band are traced past their folds
    for rho in [0.8, 0.6, 0.5] {
        let st = exact::at_resolved(rho, Hold::Force(10.0)).unwrap();
        assert!(st.bc_error <= exact::CONVERGED, "{}", st.bc_error);
        g.bench_function(format!("state at F = 10, rho = {rho}, resolved"), |b| {
            b.iter(|| exact::at_resolved(black_box(rho), Hold::Force(10.0)).unwrap())
        });
    }
    for rho in [0.8, 0.5] {
        g.bench_function(format!("pull-off at rho = {rho}, resolved"), |b| {
            b.iter(|| exact::pull_off_resolved(black_box(rho)).unwrap())
        });
    }
    // below rho = 0.3: followed in rho in the arclength representation
    // from the stored pull-offs (interpolated between those at rho = 0.115,
    // 0.105 and 0.0975, 96 modes of each sign; `exact::stored`); issue 32's goal is 200 ms
    g.measurement_time(std::time::Duration::from_secs(120));
    g.bench_function("pull-off at rho = 0.1, resolved", |b| {
        b.iter(|| exact::pull_off_resolved(black_box(0.1)).unwrap())
    });
}

criterion_group!(exact_benches, benches);
criterion_main!(exact_benches);
