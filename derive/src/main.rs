//! `thinjkr-derive`: `check [--json] [--model NAME]` holds the paper's
//! printed claims against the derivation; `generate [--root DIR]` writes the
//! generated Rust code and the reports in `docs/`; `timings` times the
//! symbolic stages. `--help` (on its own or after a verb) prints help and
//! does nothing else.

use std::process::ExitCode;
use thinjkr_derive::model::{Derivation, ModelDerivation};
use thinjkr_derive::{ansatz, claims};

const HELP: &str = "thinjkr-derive: the derivation of thinjkr's models with symbolica, its checker and its code generator

Usage: thinjkr-derive <VERB> [OPTIONS]

Verbs:
  check [--json] [--model NAME]  hold the paper's printed claims against the derivation (default model: max)
  generate [--root DIR]          derive every model and every family of derive/families/, check them, and write
                                 solver/src/generated/ and the reports in docs/ (tens of seconds)
  timings                        time each symbolic stage (medians of 5 runs)

Options:
  -h, --help  this help (after a verb: that verb's); nothing else is done

Example (from the repository's top, reusing the workspace's release build):
  cargo run --release -p thinjkr-derive -- generate
";

const GENERATE_HELP: &str = "thinjkr-derive generate: derive every model and every family of derive/families/, check each step, and
write the generated Rust (solver/src/generated/), the registry and the reports in docs/

Usage: thinjkr-derive generate [--root DIR]

Options:
  --root DIR  the repository to read derive/families/ from and write into (default: the thinjkr checkout
              that holds the working directory)
  -h, --help  this help; nothing is generated

Each file is reported as created, updated, unchanged or removed (a generated file no family writes any more).
";

const CHECK_HELP: &str =
    "thinjkr-derive check: hold the paper's printed claims against the derivation

Usage: thinjkr-derive check [--json] [--model NAME]

Options:
  --json        one JSON document
  --model NAME  the closure whose derivation the claims are held against (default: max, the paper's)
  -h, --help    this help; nothing is checked
";

const TIMINGS_HELP: &str =
    "thinjkr-derive timings: time each symbolic stage per ansatz (medians of 5 runs)

Usage: thinjkr-derive timings
";

fn usage(why: &str) -> ExitCode {
    eprintln!("thinjkr-derive: {why}\nusage: thinjkr-derive check [--json] [--model NAME] | generate [--root DIR] | timings (--help for more)");
    ExitCode::from(2)
}

/// Whether `args` (after the verb) ask for help.
fn wants_help(args: &[String]) -> bool {
    args.iter().skip(1).any(|a| a == "--help" || a == "-h")
}

/// Every argument after the verb is one `allowed` (a flag) or the value of
/// one of `with_value`; else the usage error naming it.
fn known(args: &[String], allowed: &[&str], with_value: &[&str]) -> Result<(), ExitCode> {
    let mut rest = args.iter().skip(1);
    while let Some(a) = rest.next() {
        if with_value.contains(&a.as_str()) {
            if rest.next().is_none() {
                return Err(usage(&format!("{a} needs a value")));
            }
        } else if !allowed.contains(&a.as_str()) {
            return Err(usage(&format!("unexpected argument {a:?}")));
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        None | Some("--help" | "-h" | "help") => {
            print!("{HELP}");
            ExitCode::SUCCESS
        }
        Some(verb @ ("check" | "generate" | "timings")) if wants_help(&args) => {
            print!(
                "{}",
                match verb {
                    "check" => CHECK_HELP,
                    "generate" => GENERATE_HELP,
                    _ => TIMINGS_HELP,
                }
            );
            ExitCode::SUCCESS
        }
        Some("check") => check(&args),
        Some("generate") => generate(&args),
        Some("timings") => timings(&args),
        Some(other) => usage(&format!("unknown verb {other:?}")),
    }
}

/// `check [--json] [--model NAME]`: the paper's printed claims held
/// against the derivation, as a table or one JSON document.
fn check(args: &[String]) -> ExitCode {
    if let Err(code) = known(args, &["--json"], &["--model"]) {
        return code;
    }
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

/// `generate [--root DIR]`: every output written into the repository,
/// each reported as created, updated, unchanged or removed.
fn generate(args: &[String]) -> ExitCode {
    if let Err(code) = known(args, &[], &["--root"]) {
        return code;
    }
    let t = std::time::Instant::now();
    // `--root DIR`: the repository to read families from and write
    // into (default: the checkout that holds the working directory)
    let root = match args.iter().position(|a| a == "--root") {
        Some(i) => std::path::PathBuf::from(&args[i + 1]),
        None => {
            let here = std::env::current_dir().unwrap_or_default();
            match thinjkr_derive::generate::repository_of(&here) {
                Some(root) => root,
                None => {
                    return usage(&format!(
                        "{} is not inside a thinjkr checkout (no derive/families/ and solver/ above it): run it in one, or give --root DIR",
                        here.display()
                    ))
                }
            }
        }
    };
    let outputs = match thinjkr_derive::generate::outputs_in(&root) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("generation failed: {e}");
            return ExitCode::FAILURE;
        }
    };
    // which files were there before: a new one is reported as created
    let existed: Vec<bool> = outputs
        .iter()
        .map(|o| root.join(&o.path).exists())
        .collect();
    let written = thinjkr_derive::generate::write_all(&root, &outputs).and_then(|changed| {
        thinjkr_derive::generate::remove_stale(&root, &outputs).map(|gone| (changed, gone))
    });
    match written {
        Ok((changed, gone)) => {
            for p in &gone {
                println!("{:>9} {}", "removed", p.display());
            }
            for (o, existed) in outputs.iter().zip(&existed) {
                let mark = match (changed.contains(&o.path), *existed) {
                    (true, false) => "created",
                    (true, true) => "updated",
                    (false, _) => "unchanged",
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

/// `timings`: the medians of 5 runs of each symbolic stage, per ansatz.
fn timings(args: &[String]) -> ExitCode {
    if let Err(code) = known(args, &[], &[]) {
        return code;
    }
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
