//! A probe of the unloading path (docs/exact.md, "The short-wave cutoff"):
//! the exact family at ρ traced from its state at F̄ (default 10) towards
//! smaller ā with that state's truncation, its events (folds in ā, force
//! minima, bifurcations with their mode) and, at every traced point up to
//! the first force minimum (every tenth printed), the longest mode unstable
//! under load control and the critical thinness it implies (its wavelength
//! over 2π: the state is stable above the short-wave cutoff for h/L above
//! it), with the largest of them.
//!
//! usage: unloading_probe RHO [FORCE]; NP=points (default 600) bounds the
//! trace.

use thinjkr::control::Hold;
use thinjkr::exact::{self, branch::Event, Exact};

fn main() {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("numbers: RHO [FORCE]"))
        .collect();
    let rho = *args.first().expect("usage: unloading_probe RHO [FORCE]");
    let force = args.get(1).copied().unwrap_or(10.0);
    let points: usize = std::env::var("NP")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(600);
    let st = exact::at_resolved(rho, Hold::Force(force)).expect("a resolved state");
    println!(
        "start: a = {:.5}, F = {:.5}, {} modes, boundary error {:.1e}",
        st.a_bar, st.force_bar, st.truncation.modes, st.bc_error
    );
    let ex = Exact::new(rho, st.truncation).expect("the problem");
    let branch = ex.trace(&st, 0.8, 0.05, points).expect("a trace");
    for e in &branch.events {
        match e {
            Event::ForceMinimum { state } => println!(
                "  force minimum: a = {:.5}, s = {:.4}, F = {:.6}, off the ellipse {:.3e} a, boundary error {:.1e}",
                state.a_bar, state.s, state.force_bar, state.deviation_from_ellipse, state.bc_error
            ),
            other => println!("  {other:?}"),
        }
    }
    // every point up to the first force minimum (F̄ falls along the trace
    // until there), every tenth printed
    let mut critical: (f64, usize, f64) = (0.0, 0, 0.0);
    for (i, p) in branch.points.iter().enumerate() {
        let s = &p.state;
        if i > 0 && s.force_bar > branch.points[i - 1].state.force_bar {
            println!("  the force rises from point {i} on (a = {:.4})", s.a_bar);
            break;
        }
        let stab = ex.stability(s).expect("its stability");
        let (wavelength, n) = stab
            .load
            .iter()
            .filter(|m| m.n > 0)
            .map(|m| (m.wavelength, m.n))
            .fold((0.0, 0), |a, b| if b.0 > a.0 { b } else { a });
        let h_over_l = wavelength / (2.0 * std::f64::consts::PI);
        if h_over_l > critical.0 {
            critical = (h_over_l, n, s.a_bar);
        }
        if i % 10 == 0 {
            println!(
                "  point {i}: a = {:.4}, s = {:.4}, F = {:.4}, off the ellipse {:.3e} a; longest unstable mode n = {n} ({wavelength:.3}), critical h/L {h_over_l:.3}; size unstable: {}",
                s.a_bar,
                s.s,
                s.force_bar,
                s.deviation_from_ellipse,
                stab.load.iter().any(|m| m.n == 0)
            );
        }
    }
    println!(
        "largest critical h/L before the first force minimum: {:.3} (mode n = {} at a = {:.4})",
        critical.0, critical.1, critical.2
    );
}
