//! Issue 31's closing count: random inputs through the model layer, per
//! model, tallied by what came back: a state (and whether it carries a
//! warning), or a typed error by its kind. Every answered state is held to
//! what it claims here, independently of the library's own checks: finite
//! numbers, ā > 0 and 0 < s ≤ 1 for the ellipse models, and the control it
//! was asked at (δ̄ or F̄ to 1e-8, ā to 1e-8). A panic is caught and counted.
//!
//! `cargo run --release -p thinjkr --example random_audit -- MODEL N [SEED]`
//! (MODEL `all` runs every model but `exact` with N inputs each). The
//! inputs: ρ log-uniform in [0.02, 1]; the control δ̄, F̄ or ā with equal
//! chance, δ̄ uniform in [−3, 20], F̄ in [−6, 60], ā in [0.3, 8].

use std::collections::BTreeMap;
use thinjkr::control::Hold;
use thinjkr::registry::{entries, parse, Choice};
use thinjkr::report::AnyState;

/// xorshift64*: a reproducible stream without a dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The state's broken claims, in words (empty when it holds them).
fn broken(st: &AnyState, hold: Hold) -> Vec<String> {
    let (a, b, d, f) = st.size_and_load();
    let mut out = Vec::new();
    let finite = [b, d, f].iter().all(|v| v.is_finite());
    if !finite {
        out.push("a number is not finite".into());
    }
    if let AnyState::Ellipse(e) = st {
        if !(e.a_bar > 0.0 && e.s > 0.0 && e.s <= 1.0) {
            out.push(format!("a = {}, s = {}", e.a_bar, e.s));
        }
    }
    let off = |x: f64, want: f64| (x - want).abs() > 1e-8 * want.abs().max(1.0);
    match hold {
        Hold::Delta(want) if off(d, want) => out.push(format!("delta {d} asked {want}")),
        Hold::Force(want) if off(f, want) => out.push(format!("force {f} asked {want}")),
        Hold::Size(want) if a.is_finite() && off(a, want) => {
            out.push(format!("a {a} asked {want}"))
        }
        _ => {}
    }
    out
}

fn warned(st: &AnyState) -> bool {
    match st {
        AnyState::Ellipse(e) => e.outside_stated_range || e.beyond_size_fold,
        AnyState::Conformal(c) => !c.warnings.is_empty(),
        _ => false,
    }
}

fn audit(name: &str, model: Choice, n: usize, seed: u64) {
    let mut rng = Rng(seed | 1);
    let mut tally: BTreeMap<String, usize> = BTreeMap::new();
    let mut broken_claims = Vec::new();
    let start = std::time::Instant::now();
    for _ in 0..n {
        let rho = (0.02f64.ln() * (1.0 - rng.next())).exp();
        let pick = rng.next();
        let u = rng.next();
        let hold = if pick < 1.0 / 3.0 {
            Hold::Delta(-3.0 + 23.0 * u)
        } else if pick < 2.0 / 3.0 {
            Hold::Force(-6.0 + 66.0 * u)
        } else {
            Hold::Size(0.3 + 7.7 * u)
        };
        let got = std::panic::catch_unwind(|| model.state(rho, hold));
        let key = match got {
            Err(_) => "panic".to_string(),
            Ok(Ok(st)) => {
                let b = broken(&st, hold);
                if !b.is_empty() {
                    broken_claims.push(format!("rho = {rho}, {hold}: {}", b.join("; ")));
                }
                if warned(&st) {
                    "state, with a warning".into()
                } else {
                    "state".into()
                }
            }
            Ok(Err(e)) => format!("refused: {}", e.kind()),
        };
        *tally.entry(key).or_default() += 1;
    }
    let parts: Vec<String> = tally.iter().map(|(k, v)| format!("{k} {v}")).collect();
    println!(
        "{name}: {n} inputs in {:.1} s: {}; states breaking their claims: {}",
        start.elapsed().as_secs_f64(),
        parts.join(", "),
        broken_claims.len()
    );
    for b in broken_claims.iter().take(5) {
        println!("  {b}");
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let which = args.get(1).map(String::as_str).unwrap_or("all");
    let n: usize = args
        .get(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(10_000)
        .min(1_000_000);
    let seed: u64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(31);
    std::panic::set_hook(Box::new(|_| {}));
    if which == "all" {
        for e in entries().iter().filter(|e| e.name != "exact") {
            audit(&e.name, parse(&e.name).unwrap(), n, seed);
        }
    } else {
        match parse(which) {
            Ok(m) => audit(which, m, n, seed),
            Err(why) => eprintln!("{why}"),
        }
    }
}
