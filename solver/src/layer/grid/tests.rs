//! The grid solver's tests: the force's slope, the symmetry at ρ = 1, and
//! the pull-off at ρ = 1 against the axisymmetric reference of `layer` as
//! the process zone shrinks; an exploration (ignored) prints pull-offs on a
//! ladder of grids and process zones for docs/thickness.md.
//!
//! Owns: nothing. May use: `layer` (the pair and its axisymmetric reference).

use super::*;
use crate::layer::{Layers, Route};

/// The half width of the tests' coarse grids, in size scales.
const WIDTH: f64 = 1.4;

/// The rungs of a ladder as the explorations read them, `ε:cells,…`.
pub(super) fn rungs_of(text: &str) -> Vec<(f64, f64)> {
    text.split(',')
        .map(|x| {
            let (e, n) = x.split_once(':').expect("eps:cells");
            (e.parse().expect("eps"), n.parse().expect("cells"))
        })
        .collect()
}

/// A coarse grid of the tests: equal incompressible coatings of thinness
/// `thin` at `rho` on n × n cells over [`WIDTH`] size scales each side, a
/// process zone of 0.3 size scales; with the size scale a.
pub(super) fn coarse(thin: f64, rho: f64, n: usize) -> (Sheet, f64) {
    let layers = Layers::equal(thin, 0.5).unwrap();
    let a = layers.radius_guess();
    let dx = 2.0 * WIDTH * a / n as f64;
    let range = (0.3 * a / (4.0 * layers.beta() * std::f64::consts::E.powi(2))).sqrt();
    (Sheet::new(&layers, rho, n, dx, range), a)
}

#[test]
#[ignore = "exploration: prints the grid solver's pull-offs on a ladder of grids"]
fn explore_ladder() {
    let thin: f64 = std::env::var("THINJKR_GRID_THIN")
        .map(|v| v.parse().unwrap())
        .unwrap_or(1.0);
    let rho: f64 = std::env::var("THINJKR_GRID_RHO")
        .map(|v| v.parse().unwrap())
        .unwrap_or(1.0);
    let rungs = rungs_of(&std::env::var("THINJKR_GRID_RUNGS").unwrap_or("0.2:4,0.2:8".into()));
    let layers = Layers::equal(thin, 0.5).unwrap();
    let reference = layers.pull_off(Route::Griffith).unwrap().load.force_bar;
    pull_off_ladder(&layers, rho, &rungs, &mut |r| {
        println!(
            "h/L {thin} rho {rho} eps {} cells/zone {} n {} W {:.4}: F {:.8} rel {:+.3e} delta {:.6} a {:.4} b {:.4} edge gap {:.0} ranges; {} states, {} Newton steps, {} products ({:.1} s)",
            r.eps,
            r.cells_per_zone,
            r.n,
            r.width,
            r.state.force_bar,
            r.state.force_bar / reference - 1.0,
            r.state.delta_bar,
            r.state.half_widths.0.unwrap_or(f64::NAN),
            r.state.half_widths.1.unwrap_or(f64::NAN),
            r.state.edge_gap,
            r.work.states,
            r.work.steps,
            r.work.products,
            r.seconds
        );
    })
    .unwrap();
}

#[test]
fn the_force_slope_is_the_derivative_of_the_force() {
    // dF̄/dδ̄ from the linear solve against central differences of F̄ over
    // δ̄ ± η (error of order η², about 1e-9 here); two coatings as thick
    // as the contact is wide and thinner ones at ρ = 0.6
    for (thin, rho) in [(1.0, 1.0), (0.4, 0.6)] {
        let n = 40;
        let (s, a) = coarse(thin, rho, n);
        let range = s.law.range;
        let delta = 0.25 * a * a;
        let mid = s.cold_state(delta).unwrap();
        let eta = 1e-4 * a * a;
        let side = |d: f64| s.state(d, &mid.gap).unwrap().force_bar;
        let fd = (side(delta + eta) - side(delta - eta)) / (2.0 * eta);
        assert!(
            (fd - mid.force_slope).abs() < 1e-6 * mid.force_slope.abs(),
            "h/L {thin}, rho {rho}: {fd} against {}",
            mid.force_slope
        );
        // at ρ = 1 the state is symmetric in X and Y, as the grid is
        if rho == 1.0 {
            for i in 0..n {
                for j in 0..i {
                    let (g, t) = (mid.gap[i * n + j], mid.gap[j * n + i]);
                    assert!((g - t).abs() < 1e-9 * range, "{i} {j}: {g} against {t}");
                }
            }
        } else {
            // longer along X, the larger radius
            assert!(mid.half_widths.0.unwrap() > mid.half_widths.1.unwrap());
        }
    }
}

#[test]
fn the_pull_off_tends_to_the_reference_as_the_process_zone_shrinks() {
    // h/L = 1 at ρ = 1, against the axisymmetric reference of `layer`:
    // the pull-off at process zones ε = 0.2, 0.1, 0.05 of the contact
    // radius, four cells across the zone (a ladder, each from the last),
    // and at ε = 0.2 with eight
    let layers = Layers::equal(1.0, 0.5).unwrap();
    let reference = layers.pull_off(Route::Griffith).unwrap().load.force_bar;
    let ladder = pull_off_ladder(
        &layers,
        1.0,
        &[(0.2, 4.0), (0.2, 8.0), (0.1, 4.0), (0.05, 4.0)],
        &mut |_| {},
    )
    .unwrap();
    let f: Vec<f64> = ladder.iter().map(|r| r.state.force_bar).collect();
    let err: Vec<f64> = f.iter().map(|f| f / reference - 1.0).collect();
    // the cells: eight across the zone move the pull-off by 2.2e-4
    assert!((f[1] / f[0] - 1.0).abs() < 3e-4, "{f:?}");
    // the process zone: less adhesive than JKR's sharp edge, by 4.0 %,
    // 2.5 % and 1.4 %, each halving of ε taking off a little less than half
    for (wide, narrow) in [(err[0], err[2]), (err[2], err[3])] {
        assert!(
            narrow > 0.0 && (1.5..2.0).contains(&(wide / narrow)),
            "{err:?}"
        );
    }
    // every grid wide enough: the gap at its edge is 20 ranges or more
    assert!(ladder.iter().all(|r| r.state.edge_gap >= EDGE_GAP));
    // the JKR limit through the three: within 2e-3 of the reference (the
    // finer ε = 0.05, 0.025, 0.0125 of docs/thickness.md come within 3e-4)
    let limit = jkr_limit([(0.2, f[0]), (0.1, f[2]), (0.05, f[3])]).unwrap();
    assert!(
        (limit / reference - 1.0).abs() < 2e-3,
        "{limit} against {reference}"
    );
}
