//! thinjkr's side of the peers' comparison (solver/benches/peer/grid_peers.py):
//! a rigid sphere (R = 1) on an elastic half-space (E* = 1), work of
//! adhesion ½, the grid solver's cohesive law of range RANGE, on N × N cells
//! over the half width W. Prints one JSON object per line: the states of an
//! unloading sweep at the approaches given (the first from no guess, each
//! next warm from the last), then the pull-off under load control found by
//! the grid's own walk from the first approach (steps of 0.1, the secant to
//! 1e-6 in δ).
//!
//! usage (built with `--features bench-internals`):
//! grid_peer N W RANGE DELTA [DELTA ...]

use thinjkr::bench_internals::{SphereOnHalfSpace, SphereState};

fn line(kind: &str, n: usize, s: &SphereState) {
    println!(
        "{{\"tool\": \"thinjkr\", \"kind\": \"{kind}\", \"n\": {n}, \"delta\": {:.10}, \"force\": {:.10}, \"force_slope\": {:.6}, \"states\": {}, \"steps\": {}, \"products\": {}, \"seconds\": {:.6}}}",
        s.delta, s.force, s.force_slope, s.states, s.steps, s.products, s.seconds
    );
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: grid_peer N W RANGE DELTA [DELTA ...]";
    if args.len() < 4 {
        eprintln!("{usage}");
        std::process::exit(2);
    }
    let n: usize = args[0].parse().unwrap_or(0);
    let numbers: Vec<f64> = args[1..].iter().filter_map(|a| a.parse().ok()).collect();
    if !(16..=2048).contains(&n) || numbers.len() != args.len() - 1 {
        eprintln!("{usage} (N from 16 to 2048, the rest numbers)");
        std::process::exit(2);
    }
    let (half_width, range, deltas) = (numbers[0], numbers[1], &numbers[2..]);
    let sphere = SphereOnHalfSpace::new(n, half_width, range);
    match sphere.sweep(deltas) {
        Ok(states) => states.iter().for_each(|s| line("state", n, s)),
        Err(e) => {
            eprintln!("the sweep failed: {e}");
            std::process::exit(1);
        }
    }
    match sphere.pull_off(deltas[0], 0.1, 1e-6) {
        Ok(s) => line("pull-off", n, &s),
        Err(e) => {
            eprintln!("the pull-off failed: {e}");
            std::process::exit(1);
        }
    }
}
