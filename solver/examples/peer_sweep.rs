//! The sweep of the side-by-side comparison (solver/benches/peer/compare.py):
//! 20 000 warm-started displacement-controlled solves at ρ = 0.8, δ̄ from 6
//! down to 0.5, each continued from the previous solution, with either the
//! generated residuals through `&dyn Model` (`generated`), through the
//! static model type (`static`), or the hand-written ones (`handwritten`). Prints the median wall time of `repeats` sweeps and
//! writes the solutions of the last sweep.
//!
//! With `cold`: 10 000 cold solves at pseudo-random (ρ, δ̄) (ρ in
//! [0.7, 1), δ̄ in [0.5, 6], a fixed linear congruential sequence), each a
//! new `Contact` and `at_displacement` (no warm start); writes
//! `rho delta a s` per line.
//!
//! With `cold-newton`: the same inputs, each solved only by Newton's method
//! on the generated residuals from the closed-form start the SciPy side
//! uses (ā from the axisymmetric (25)₁, s from (30)): the same algorithm as
//! fsolve there, without the bracketing that makes a cold solve safe.
//!
//! With `layer`: the warm sweep through the model layer, each state a
//! checked state continued from the one before (`Choice::state_near`).
//!
//! With `checks-after` / `edge-after`: the generated sweep, then every
//! field and check of a checked state (or the adhesive-edge check alone)
//! computed over its converged states in a second pass, off the Newton
//! chain: the least a checked state can cost (docs/performance.md).
//!
//! usage: peer_sweep generated|static|handwritten|layer|checks-after|edge-after|cold|cold-newton OUT_FILE [repeats]

#[path = "../benches/peer/handwritten.rs"]
mod handwritten;

use nalgebra::{Matrix2, Vector2};
use std::io::Write;
use std::time::Instant;
use thinjkr::generated::max::Max;
use thinjkr::model::Model;
use thinjkr::newton::{solve, NewtonConfig};
use thinjkr::{Contact, ModelId};

const N: usize = 20_000;
const RHO: f64 = 0.8;

fn sweep(
    f: impl Fn(Vector2<f64>, f64) -> (Vector2<f64>, Matrix2<f64>),
    start: (f64, f64),
    out: &mut Vec<(f64, f64, f64)>,
) {
    out.clear();
    let cfg = NewtonConfig::default();
    let mut x = start;
    for k in 0..N {
        let delta = 6.0 - 5.5 * k as f64 / (N - 1) as f64;
        let sol = solve(
            |v: Vector2<f64>| f(v, delta),
            |a| 1.0 + a * a * a,
            Vector2::new(x.0, x.1),
            &cfg,
            "sweep",
        )
        .expect("converges");
        x = (sol.a_bar, sol.s);
        out.push((delta, sol.a_bar, sol.s));
    }
}

/// The sweep through the model layer (`thinjkr::registry`): the same δ̄,
/// each state continued from the one before by `Choice::state_near`, which
/// returns a checked state (force, stability, boundary error) as every
/// front end gets it.
fn layer_sweep(out: &mut Vec<(f64, f64, f64)>) {
    use thinjkr::control::Hold;
    out.clear();
    let m = thinjkr::registry::parse("max").expect("a model");
    let mut near = m.state(RHO, Hold::Delta(6.0)).expect("a state");
    for k in 0..N {
        let delta = 6.0 - 5.5 * k as f64 / (N - 1) as f64;
        near = m
            .state_near(RHO, Hold::Delta(delta), &near)
            .expect("converges");
        let (a, b, _, _) = near.size_and_load();
        out.push((delta, a, b / a));
    }
}

/// What a checked state adds to the Newton iterations, over a sweep's
/// converged states: with `all`, its pressure parameters, F̄ and the error
/// (14) beside the adhesive-edge check; else that check alone. The sum of
/// the fields and whether every state passed (so that none is optimised
/// away).
fn checks_after(out: &[(f64, f64, f64)], all: bool) -> (f64, bool) {
    let mut sum = 0.0;
    let mut adhesive = true;
    for &(d, a, s) in out {
        let x = Vector2::new(a, s);
        let [g0, g1] = Max.edge_slopes(x, RHO, d);
        adhesive &= g0.min(g1) > 0.0 && s <= 1.0;
        if all {
            let p = Max.pressure_parameters(x, RHO, d);
            sum += p.xi + p.p0 + p.shape[0] + p.shape[1];
            sum += Max.force_bar(x, RHO, d) + Max.bc_error(x, RHO, d);
        }
    }
    (sum, adhesive)
}

/// The hand-written residuals in the model interface's types.
fn handwritten_nalgebra(v: Vector2<f64>, delta: f64) -> (Vector2<f64>, Matrix2<f64>) {
    let (r, j) = handwritten::residuals_and_jacobian(v[0], v[1], RHO, delta);
    (
        Vector2::new(r[0], r[1]),
        Matrix2::new(j[0][0], j[0][1], j[1][0], j[1][1]),
    )
}

/// The cold-solve inputs: (ρ, δ̄) from a fixed linear congruential
/// sequence (the Python side draws the same numbers from the file written).
pub fn cold_inputs(n: usize) -> Vec<(f64, f64)> {
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n)
        .map(|_| (0.7 + 0.3 * next(), 0.5 + 5.5 * next()))
        .collect()
}

const N_COLD: usize = 10_000;

/// ā from ā³ − 4δ̄ā − 8 = 0 (the derived (25)₁ at ρ = 1) by Cardano's
/// formula, s from (30).
fn closed_form_start(rho: f64, delta: f64) -> (f64, f64) {
    let (p, q): (f64, f64) = (-4.0 * delta, -8.0);
    let disc = (q / 2.0).powi(2) + (p / 3.0).powi(3);
    let a0 = if disc >= 0.0 {
        let r = disc.sqrt();
        (-q / 2.0 + r).cbrt() + (-q / 2.0 - r).cbrt()
    } else {
        let m = 2.0 * (-p / 3.0).sqrt();
        m * ((3.0 * q / (p * m)).acos() / 3.0).cos()
    };
    (a0, thinjkr::limits::zero_force_s_approx(rho))
}

/// `repeats` timed passes of `solve` over the cold inputs; writes the last.
fn timed_cold(path: &str, repeats: usize, solve_one: impl Fn(f64, f64) -> (f64, f64)) {
    let inputs = cold_inputs(N_COLD);
    let mut times = Vec::new();
    let mut out = Vec::with_capacity(N_COLD);
    for _ in 0..repeats {
        out.clear();
        let t = Instant::now();
        for &(rho, delta) in &inputs {
            let (a, s) = solve_one(rho, delta);
            out.push((rho, delta, a, s));
        }
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    let mut w = std::io::BufWriter::new(std::fs::File::create(path).expect("writable"));
    for (r, d, a, s) in &out {
        writeln!(w, "{r:.17e} {d:.17e} {a:.17e} {s:.17e}").unwrap();
    }
    println!("median_seconds={:.6e}", times[times.len() / 2]);
}

/// Newton's method alone from the closed-form start.
fn cold_newton(path: &str, repeats: usize) {
    let model = ModelId::Max.model();
    let cfg = NewtonConfig::default();
    timed_cold(path, repeats, |rho, delta| {
        let (a0, s0) = closed_form_start(rho, delta);
        let sol = solve(
            |x| model.residuals_and_jacobian(x, rho, delta),
            |a| model.residual_scale(a, delta),
            Vector2::new(a0, s0),
            &cfg,
            "cold newton",
        )
        .expect("converges");
        (sol.a_bar, sol.s)
    });
}

/// thinjkr's cold solve: a new contact and `at_displacement`.
fn cold(path: &str, repeats: usize) {
    timed_cold(path, repeats, |rho, delta| {
        let st = Contact::new(rho)
            .and_then(|c| c.at_displacement(delta))
            .expect("a state");
        (st.a_bar, st.s)
    });
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let which = args.get(1).map(String::as_str).unwrap_or("generated");
    let path = args.get(2).cloned().unwrap_or_else(|| "/dev/null".into());
    let repeats: usize = args.get(3).and_then(|r| r.parse().ok()).unwrap_or(7);
    match which {
        "cold" => return cold(&path, repeats),
        "cold-newton" => return cold_newton(&path, repeats),
        _ => {}
    }
    let start = Contact::new(RHO).unwrap().at_displacement(6.0).unwrap();
    let mut out = Vec::with_capacity(N);
    let mut times = Vec::new();
    let dynamic: &dyn Model = ModelId::Max.model();
    for _ in 0..repeats {
        let t = Instant::now();
        let x0 = (start.a_bar, start.s);
        match which {
            // the model as the solver holds it, `&dyn Model`
            "generated" => sweep(
                |v, d| dynamic.residuals_and_jacobian(v, RHO, d),
                x0,
                &mut out,
            ),
            // the static model type (`thinjkr::generated::max::Max`)
            "static" => sweep(|v, d| Max.residuals_and_jacobian(v, RHO, d), x0, &mut out),
            "handwritten" => sweep(handwritten_nalgebra, x0, &mut out),
            // through the model layer: each state a checked `State`
            // continued from the one before (`Choice::state_near`)
            "layer" => layer_sweep(&mut out),
            // the generated sweep, then what a checked state adds, computed
            // after it over the converged (ā, s), off the Newton chain:
            // every field and check of a state, or the adhesive edge alone
            "checks-after" | "edge-after" => {
                sweep(|v, d| Max.residuals_and_jacobian(v, RHO, d), x0, &mut out);
                let all = which == "checks-after";
                std::hint::black_box(checks_after(&out, all));
            }
            other => panic!("unknown variant {other}"),
        }
        times.push(t.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    let mut w = std::io::BufWriter::new(std::fs::File::create(&path).expect("writable"));
    for (d, a, s) in &out {
        writeln!(w, "{d:.17e} {a:.17e} {s:.17e}").unwrap();
    }
    println!(
        "median_seconds={:.6e} start_a={:.17e} start_s={:.17e}",
        times[times.len() / 2],
        start.a_bar,
        start.s
    );
}
