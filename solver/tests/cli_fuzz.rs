//! The CLI on random argument values (finite, huge, tiny, negative, NaN,
//! ±inf): it never panics or aborts, exits with 0 or with a typed error
//! ("thinjkr: error: …", exit code 1), and a successful run prints no NaN
//! or inf. The exact model is left out (seconds per call).

use proptest::prelude::*;
use std::process::Command;

fn value() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
        Just(-0.0),
        Just(1e-300),
        Just(1e300),
        Just(-1e300),
        Just(f64::MIN_POSITIVE),
        -10.0..10.0f64,
        0.0..1.0f64,
        prop::num::f64::NORMAL,
    ]
}

fn run(args: &[String]) -> Result<(), TestCaseError> {
    let out = Command::new(env!("CARGO_BIN_EXE_thinjkr"))
        .args(args)
        .output()
        .expect("the binary runs");
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    prop_assert!(!stderr.contains("panicked"), "{args:?} panicked: {stderr}");
    match out.status.code() {
        Some(0) => {
            for bad in ["NaN", "inf"] {
                prop_assert!(!stdout.contains(bad), "{args:?} printed {bad}: {stdout}");
            }
        }
        // usage errors (clap's and thinjkr's) exit with 2
        Some(1) => prop_assert!(stderr.contains("thinjkr: error:"), "{args:?}: {stderr}"),
        Some(2) => prop_assert!(stderr.contains("error:"), "{args:?}: {stderr}"),
        other => prop_assert!(false, "{args:?} ended with {other:?}: {stderr}"),
    }
    Ok(())
}

fn num(x: f64) -> String {
    format!("{x:e}")
}

const MODELS: [&str; 4] = ["max", "apexes", "energy", "apex45"];

proptest! {
    #![proptest_config(ProptestConfig { cases: 40, ..ProptestConfig::default() })]

    #[test]
    fn solve_never_panics(rho in value(), v in value(), control in 0..3usize, m in 0..4usize, json in any::<bool>()) {
        let flag = ["--delta", "--force", "--a"][control];
        let mut args = vec!["solve".into(), "--rho".into(), num(rho), flag.into(), num(v), "--model".into(), MODELS[m].into()];
        if json { args.push("--json".into()); }
        run(&args)?;
    }

    #[test]
    fn pull_off_and_zero_force_never_panic(rho in value(), m in 0..4usize, displacement in any::<bool>()) {
        let control = if displacement { "displacement" } else { "load" };
        run(&["pull-off".into(), "--rho".into(), num(rho), "--model".into(), MODELS[m].into(), "--control".into(), control.into()])?;
        run(&["zero-force".into(), "--rho".into(), num(rho), "--model".into(), MODELS[m].into()])?;
    }

    #[test]
    fn curve_never_panics(rho in value(), points in prop_oneof![Just(0usize), Just(1), 2..60usize, Just(usize::MAX)]) {
        run(&["curve".into(), "--rho".into(), num(rho), "--points".into(), points.to_string()])?;
    }

    #[test]
    fn physical_never_panics(v in prop::collection::vec(value(), 8), force in value()) {
        let names = ["--r1", "--r2", "--theta-deg", "--h1", "--h2", "--g1", "--g2", "--work-of-adhesion"];
        let mut args: Vec<String> = vec!["physical".into()];
        for (n, x) in names.iter().zip(&v) {
            args.push((*n).into());
            args.push(num(*x));
        }
        args.push("--force".into());
        args.push(num(force));
        run(&args)?;
    }
}
