//! Issue 73: `thinjkr-derive` behaves as a command-line tool. `--help`, on
//! its own or after a verb, prints help, exits 0 and changes nothing; an
//! unknown verb or argument is a usage error (exit 2); `generate` writes
//! into the checkout that holds the working directory, and outside one
//! says so and names `--root`. None of these reaches symbolica.

use std::path::{Path, PathBuf};
use std::process::Command;

fn run(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_thinjkr-derive"))
        .args(args)
        .current_dir(dir)
        .env("SYMBOLICA_HIDE_BANNER", "1")
        .output()
        .expect("runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// An empty folder outside any checkout.
fn empty(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("thinjkr-derive-cli-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn help_prints_and_changes_nothing() {
    let dir = empty("help");
    for args in [
        &[][..],
        &["--help"][..],
        &["-h"][..],
        &["generate", "--help"][..],
        &["generate", "--root", ".", "--help"][..],
        &["check", "--help"][..],
        &["timings", "-h"][..],
    ] {
        let (code, out, err) = run(&dir, args);
        assert_eq!(code, 0, "{args:?}: {err}");
        assert!(out.contains("Usage: thinjkr-derive"), "{args:?}: {out}");
        assert!(err.is_empty(), "{args:?}: {err}");
    }
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        0,
        "nothing written"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_wrong_verb_or_argument_is_a_usage_error() {
    let dir = empty("usage");
    for (args, says) in [
        (&["frobnicate"][..], "unknown verb \"frobnicate\""),
        (
            &["generate", "--rot", "x"][..],
            "unexpected argument \"--rot\"",
        ),
        (&["generate", "--root"][..], "--root needs a value"),
        (&["check", "--model"][..], "--model needs a value"),
        (&["timings", "now"][..], "unexpected argument \"now\""),
    ] {
        let (code, out, err) = run(&dir, args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(
            out.is_empty() && err.contains(says) && err.contains("usage:"),
            "{args:?}: {err}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Outside a checkout `generate` writes nothing and names `--root`; the
/// checkout is found from the working directory, at its top or below.
#[test]
fn generate_writes_into_the_checkout_it_runs_in() {
    let dir = empty("outside");
    let (code, _, err) = run(&dir, &["generate"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("not inside a thinjkr checkout") && err.contains("--root"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        0,
        "nothing written"
    );
    std::fs::remove_dir_all(&dir).unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
    for inside in [
        root.to_path_buf(),
        root.join("solver/src/generated"),
        root.join("derive"),
    ] {
        assert_eq!(
            thinjkr_derive::generate::repository_of(&inside).as_deref(),
            Some(root),
            "{}",
            inside.display()
        );
    }
    assert_eq!(
        thinjkr_derive::generate::repository_of(&std::env::temp_dir()),
        None
    );
}
