//! The sweep of the side-by-side comparison (solver/benches/peer/compare.py):
//! 20 000 warm-started displacement-controlled solves at ρ = 0.8, δ̄ from 6
//! down to 0.5, each continued from the previous solution, with either the
//! generated residuals (`generated`) or the hand-written ones
//! (`handwritten`). Prints the median wall time of `repeats` sweeps and
//! writes the solutions of the last sweep.
//!
//! usage: peer_sweep generated|handwritten OUT_FILE [repeats]

#[path = "../benches/peer/handwritten.rs"]
mod handwritten;

use nalgebra::{Matrix2, Vector2};
use std::io::Write;
use std::time::Instant;
use thinjkr::newton::{solve, NewtonConfig};
use thinjkr::{Contact, ModelId};

const N: usize = 20_000;
const RHO: f64 = 0.8;

fn sweep(
    f: fn(f64, f64, f64, f64) -> ([f64; 2], [[f64; 2]; 2]),
    start: (f64, f64),
    out: &mut Vec<(f64, f64, f64)>,
) {
    out.clear();
    let cfg = NewtonConfig::default();
    let mut x = start;
    for k in 0..N {
        let delta = 6.0 - 5.5 * k as f64 / (N - 1) as f64;
        let sol = solve(
            |v: Vector2<f64>| {
                let (r, j) = f(v[0], v[1], RHO, delta);
                (
                    Vector2::new(r[0], r[1]),
                    Matrix2::new(j[0][0], j[0][1], j[1][0], j[1][1]),
                )
            },
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

/// The generated residuals of the paper's model, through the model interface.
fn generated(a: f64, s: f64, rho: f64, delta: f64) -> ([f64; 2], [[f64; 2]; 2]) {
    let (r, j) = ModelId::Max
        .model()
        .residuals_and_jacobian(Vector2::new(a, s), rho, delta);
    (
        [r[0], r[1]],
        [[j[(0, 0)], j[(0, 1)]], [j[(1, 0)], j[(1, 1)]]],
    )
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let which = args.get(1).map(String::as_str).unwrap_or("generated");
    let path = args.get(2).cloned().unwrap_or_else(|| "/dev/null".into());
    let repeats: usize = args.get(3).and_then(|r| r.parse().ok()).unwrap_or(7);
    let f: fn(f64, f64, f64, f64) -> ([f64; 2], [[f64; 2]; 2]) = match which {
        "generated" => generated,
        "handwritten" => handwritten::residuals_and_jacobian,
        other => panic!("unknown variant {other}"),
    };
    let start = Contact::new(RHO).unwrap().at_displacement(6.0).unwrap();
    let mut out = Vec::with_capacity(N);
    let mut times = Vec::new();
    for _ in 0..repeats {
        let t = Instant::now();
        sweep(f, (start.a, start.s), &mut out);
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
        start.a,
        start.s
    );
}
