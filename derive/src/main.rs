//! `thinjkr-derive`: `check [--json]` holds the paper's printed claims
//! against the derivation; `generate` writes the generated Rust code and the
//! reports in `docs/`.

use std::process::ExitCode;
use thinjkr_derive::model::{Derivation, ModelDerivation};
use thinjkr_derive::{ansatz, claims};

fn usage() -> ExitCode {
    eprintln!("usage: thinjkr-derive check [--json] | generate [--root DIR] | timings");
    ExitCode::from(2)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("check") => {
            let json = args.iter().any(|a| a == "--json");
            // `--model NAME`: hold the paper's claims against another
            // closure's derivation (default: the paper's, `max`)
            let name = args
                .iter()
                .position(|a| a == "--model")
                .and_then(|i| args.get(i + 1))
                .map(String::as_str)
                .unwrap_or(ansatz::PAPER.id);
            let Some(a) = ansatz::ALL.iter().find(|a| a.id == name) else {
                eprintln!(
                    "unknown model {name}: one of {}",
                    ansatz::ALL
                        .iter()
                        .map(|a| a.id)
                        .collect::<Vec<_>>()
                        .join(", ")
                );
                return ExitCode::FAILURE;
            };
            let d = match Derivation::new(a) {
                Ok(d) => d,
                Err(e) => {
                    eprintln!("derivation failed: {e}");
                    return ExitCode::FAILURE;
                }
            };
            let results = match claims::check_all(&d) {
                Ok(r) => r,
                Err(e) => {
                    eprintln!("check failed: {e}");
                    return ExitCode::FAILURE;
                }
            };
            if json {
                println!(
                    "{}",
                    serde_json::to_string_pretty(&results).expect("serialisable")
                );
            } else {
                println!("{:<14} {:<10} {:<8} note", "id", "verdict", "method");
                for r in &results {
                    println!(
                        "{:<14} {:<10} {:<8} {}",
                        r.id,
                        r.verdict.as_str(),
                        format!("{:?}", r.method).to_lowercase(),
                        r.note
                    );
                }
            }
            ExitCode::SUCCESS
        }
        Some("generate") => {
            let t = std::time::Instant::now();
            // `--root DIR`: the workspace to read families from and write
            // into (default: this one)
            let root = match args.iter().position(|a| a == "--root") {
                Some(i) => match args.get(i + 1) {
                    Some(dir) => std::path::PathBuf::from(dir),
                    None => return usage(),
                },
                None => thinjkr_derive::generate::workspace_root(),
            };
            let outputs = match thinjkr_derive::generate::outputs_in(&root) {
                Ok(o) => o,
                Err(e) => {
                    eprintln!("generation failed: {e}");
                    return ExitCode::FAILURE;
                }
            };
            let written =
                thinjkr_derive::generate::write_all(&root, &outputs).and_then(|changed| {
                    thinjkr_derive::generate::remove_stale(&root, &outputs)
                        .map(|gone| (changed, gone))
                });
            match written {
                Ok((changed, gone)) => {
                    for p in &gone {
                        println!("{:>9} {}", "removed", p.display());
                    }
                    for o in &outputs {
                        let mark = if changed.contains(&o.path) {
                            "updated"
                        } else {
                            "unchanged"
                        };
                        println!("{mark:>9} {}", o.path.display());
                    }
                    eprintln!(
                        "generated {} files in {:.3} s",
                        outputs.len(),
                        t.elapsed().as_secs_f64()
                    );
                    ExitCode::SUCCESS
                }
                Err(e) => {
                    eprintln!("could not write: {e}");
                    ExitCode::FAILURE
                }
            }
        }
        Some("timings") => {
            // medians of 5 runs of each symbolic stage, per ansatz
            let median = |f: &dyn Fn() -> bool| {
                let mut v: Vec<f64> = (0..5)
                    .map(|_| {
                        let t = std::time::Instant::now();
                        assert!(f());
                        t.elapsed().as_secs_f64()
                    })
                    .collect();
                v.sort_by(f64::total_cmp);
                v[2]
            };
            for a in ansatz::ALL {
                let derive = median(&|| ModelDerivation::new(a).is_ok());
                let d = ModelDerivation::new(a).expect("derives");
                let codegen = median(&|| thinjkr_derive::codegen::module_source(&d).is_ok());
                println!(
                    "ansatz {:<8} derive {:.3} s, generate code {:.3} s",
                    a.id, derive, codegen
                );
            }
            let d = Derivation::new(&ansatz::PAPER).expect("derives");
            println!(
                "check (paper) {:.3} s",
                median(&|| claims::check_all(&d).is_ok())
            );
            println!(
                "everything (derive both, check, render all files) {:.3} s",
                median(&|| thinjkr_derive::generate::outputs().is_ok())
            );
            ExitCode::SUCCESS
        }
        _ => usage(),
    }
}
