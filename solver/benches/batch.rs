//! criterion benchmarks of cold solves and of the batch API (issue 12):
//! making a contact, one cold solve under each control (δ̄, F̄, ā) and the
//! pull-off and zero-force states, for the paper's model `max` and the
//! energy model, each by the cold search (the default) and, for
//! comparison in the same run, by the walk it replaced; and the issue's
//! 1000 × 1000 grid of (ρ, δ̄) through `batch::solve_all` on all cores;
//! and the same 10⁶ lines as text through the binary, `thinjkr batch`
//! (issue 21: reading, parsing, solving and writing every row).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use thinjkr::batch::{solve_all, Item};
use thinjkr::control::Hold;
use thinjkr::{Contact, ModelId, Search};

fn benches(c: &mut Criterion) {
    for model in [ModelId::Max, ModelId::Energy] {
        let contact = Contact::with_model(model, 0.8).unwrap();
        let mut g = c.benchmark_group(format!("cold, {model}, rho = 0.8"));
        g.sample_size(20);
        g.bench_function("make the contact", |b| {
            b.iter(|| Contact::with_model(model, black_box(0.8)).unwrap())
        });
        for (name, search) in [("cold", Search::Cold), ("walk", Search::Walk)] {
            let contact = contact.search(search);
            g.bench_function(format!("{name}: displacement (delta = 2)"), |b| {
                b.iter(|| contact.at_displacement(black_box(2.0)).unwrap())
            });
            g.bench_function(format!("{name}: load (F = 1)"), |b| {
                b.iter(|| contact.at_load(black_box(1.0)).unwrap())
            });
            g.bench_function(format!("{name}: contact size (a = 3)"), |b| {
                b.iter(|| contact.at_contact_size(black_box(3.0)).unwrap())
            });
            g.bench_function(format!("{name}: pull-off"), |b| {
                b.iter(|| contact.pull_off_load().unwrap())
            });
            g.bench_function(format!("{name}: zero force"), |b| {
                b.iter(|| contact.zero_force().unwrap())
            });
        }
        g.finish();
        let grid: Vec<Item> = (0..1000)
            .flat_map(|i| {
                (0..1000).map(move |k| Item {
                    rho: 0.3 + 0.7 * i as f64 / 999.0,
                    given: Hold::Delta(-0.2 + 10.0 * k as f64 / 999.0),
                })
            })
            .collect();
        let mut g = c.benchmark_group(format!("batch, {model}"));
        g.sample_size(10);
        g.bench_function("1000 x 1000 (rho, delta) grid, all cores", |b| {
            b.iter(|| solve_all(&model, black_box(&grid)))
        });
        g.finish();
    }
}

/// 10⁶ lines `rho,delta,value` (the grid above, six decimals) through the
/// release binary, stdin from a file, stdout to /dev/null.
fn cli(c: &mut Criterion) {
    use std::io::Write;
    let path = std::env::temp_dir().join(format!("thinjkr-bench-batch-{}.csv", std::process::id()));
    {
        let mut f = std::io::BufWriter::new(std::fs::File::create(&path).unwrap());
        writeln!(f, "rho,control,value").unwrap();
        for i in 0..1000 {
            for k in 0..1000 {
                let rho = 0.3 + 0.7 * i as f64 / 999.0;
                let delta = -0.2 + 10.0 * k as f64 / 999.0;
                writeln!(f, "{rho:.6},delta,{delta:.6}").unwrap();
            }
        }
    }
    let mut g = c.benchmark_group("batch, max, command line");
    g.sample_size(10);
    g.bench_function("10^6 lines through `thinjkr batch`", |b| {
        b.iter(|| {
            let status = std::process::Command::new(env!("CARGO_BIN_EXE_thinjkr"))
                .arg("batch")
                .stdin(std::fs::File::open(&path).unwrap())
                .stdout(std::process::Stdio::null())
                .stderr(std::process::Stdio::null())
                .status()
                .unwrap();
            // some grid points lie below the displacement-controlled
            // pull-off: their rows carry an error (status 3)
            assert!(matches!(status.code(), Some(0) | Some(3)), "{status}");
        })
    });
    g.finish();
    let _ = std::fs::remove_file(&path);
}

criterion_group!(batch_benches, benches, cli);
criterion_main!(batch_benches);
