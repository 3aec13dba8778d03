#!/usr/bin/env bash
# The conformal:8 load-controlled pull-off at ρ = 0.8, now against the
# baseline commit f2bfdb4 (before the model layer, issue 34), side by side in
# one criterion run: both versions of the `thinjkr` crate are dependencies of
# one throw-away bench crate under target/baseline-bench (its own workspace,
# so the repository's is untouched), the baseline unpacked from git into
# target/baseline-f2bfdb4. Issue 34's goal: now within 10 % of the baseline.
#
# usage: bash solver/benches/baseline/run.sh        (from anywhere; needs git)
set -euo pipefail
root="$(cd "$(dirname "$0")/../../.." && pwd)"
base_commit="${BASELINE:-f2bfdb4}"
base="$root/target/baseline-$base_commit"
bench="$root/target/baseline-bench"
if [ ! -f "$base/solver/Cargo.toml" ]; then
    rm -rf "$base"
    mkdir -p "$base"
    git -C "$root" archive "$base_commit" | tar -x -C "$base"
    # one lockfile cannot hold two path packages of one name and version:
    # the baseline's version is told apart
    sed -i 's/^version.workspace = true$/version = "0.0.0-baseline"/' "$base/solver/Cargo.toml"
fi
mkdir -p "$bench/benches" "$bench/src"
cat > "$bench/Cargo.toml" <<EOF
[package]
name = "baseline-bench"
version = "0.0.0"
edition = "2021"
publish = false

[workspace]

[dependencies]
now = { path = "$root/solver", package = "thinjkr", default-features = false }
base = { path = "$base/solver", package = "thinjkr", default-features = false }
criterion = { version = "0.5", default-features = false, features = ["cargo_bench_support"] }

[[bench]]
name = "pull_off"
harness = false

[profile.release]
debug = false
EOF
echo "" > "$bench/src/lib.rs"
cat > "$bench/benches/pull_off.rs" <<'EOF'
use criterion::{black_box, criterion_group, criterion_main, Criterion};

fn benches(c: &mut Criterion) {
    let mut g = c.benchmark_group("conformal:8 pull-off at rho=0.8");
    g.sample_size(20);
    let now = now::conformal::Conformal::member("conformal", 8).unwrap();
    let base = base::conformal::Conformal::new(8).unwrap();
    // the same state from both, before timing
    let (a, _) = now.pull_off(0.8, now::fold::FoldCondition::Load).unwrap();
    let (b, _) = base.pull_off(0.8, base::conformal::PullOffControl::Load).unwrap();
    assert!((a.force_bar - b.force_bar).abs() < 1e-10, "{} vs {}", a.force_bar, b.force_bar);
    println!("pull-off force: now {:.12}, baseline {:.12}", a.force_bar, b.force_bar);
    // alternate the two, so that a change of the machine's speed hits both
    for round in 0..2 {
        g.bench_function(format!("now (round {round})"), |bch| {
            bch.iter(|| now.pull_off(black_box(0.8), now::fold::FoldCondition::Load).unwrap())
        });
        g.bench_function(format!("baseline (round {round})"), |bch| {
            bch.iter(|| base.pull_off(black_box(0.8), base::conformal::PullOffControl::Load).unwrap())
        });
    }
    g.finish();
}

criterion_group!(baseline_benches, benches);
criterion_main!(baseline_benches);
EOF
cd "$bench"
CARGO_TARGET_DIR="$root/target/baseline-bench/target" cargo bench --bench pull_off -- --noplot 2>&1 |
    grep -E "pull-off force|time:|^conformal|Benchmarking .*: Analyzing" | grep -v Analyzing
