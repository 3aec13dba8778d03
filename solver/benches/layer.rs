//! criterion benchmarks of the layer of finite thickness at ρ = 1
//! (`thinjkr::layer`): the pull-offs (under load and displacement control,
//! Griffith's route) of equal incompressible coatings, side by side in one
//! group at h/L = 0.73 (the docs' coatings: h = 0.1 mm, G = 1 MPa,
//! R = 10 mm, Δγ = 0.05 J/m²), 0.3, 0.1 and 0.01; one state at a contact
//! radius; and the energy route's state beside it.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use thinjkr::control::Hold;
use thinjkr::layer::{Layers, Route};

fn benches(c: &mut Criterion) {
    let mut g = c.benchmark_group("layer pull-off");
    g.sample_size(10);
    for h in [0.73, 0.3, 0.1, 0.01] {
        let layers = Layers::equal(h, 0.5).unwrap();
        g.bench_function(format!("h/L = {h}"), |b| {
            b.iter(|| layers.pull_off(black_box(Route::Griffith)).unwrap())
        });
    }
    g.finish();
    let layers = Layers::equal(0.3, 0.5).unwrap();
    let mut g = c.benchmark_group("layer state at h/L = 0.3, a = 1.8");
    for route in [Route::Griffith, Route::Energy] {
        g.bench_function(format!("{route:?}"), |b| {
            b.iter(|| layers.state(Hold::Size(black_box(1.8)), route).unwrap())
        });
    }
    g.finish();
}

criterion_group!(layer, benches);
criterion_main!(layer);
