//! Hostile output and input for the binary (issue 21, first classes): a
//! closed pipe ends every subcommand quietly with status 141, a full disk
//! is an I/O error in words with status 1, a standard output closed before
//! the start is refused instead of losing the output.

use std::process::Command;

fn bash(script: &str) -> (Option<i32>, String, String) {
    let out = Command::new("bash")
        .arg("-c")
        .arg(script)
        .arg(env!("CARGO_BIN_EXE_thinjkr"))
        .output()
        .expect("bash runs");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

const COMMANDS: [&str; 6] = [
    "curve --rho 0.8 --points 100000",
    "curve --rho 0.8 --points 2000 --format json",
    "solve --rho 0.8 --delta 2",
    "pull-off --rho 0.8 --json",
    "models",
    "solve --rho 0.8 --force 1 --model conformal:2",
];

#[test]
fn a_closed_pipe_ends_quietly() {
    for c in COMMANDS {
        let (_, out, err) = bash(&format!(
            "\"$0\" {c} | head -c 1 >/dev/null; echo ${{PIPESTATUS[0]}}"
        ));
        let status: i32 = out.trim().parse().expect("a status");
        // the writer either finished before the reader closed (0) or was
        // told the pipe is closed (141); it never panics
        assert!(status == 0 || status == 141, "{c}: status {status}, {err}");
        assert!(!err.contains("panicked"), "{c}: {err}");
    }
    let (_, out, err) =
        bash("\"$0\" curve --rho 0.8 --points 100000 | head -1 >/dev/null; echo ${PIPESTATUS[0]}");
    assert_eq!(out.trim(), "141", "{err}");
    assert!(err.is_empty(), "quiet: {err}");
}

#[test]
fn a_full_disk_is_an_io_error() {
    for c in COMMANDS {
        let (status, _, err) = bash(&format!("\"$0\" {c} >/dev/full"));
        assert_eq!(status, Some(1), "{c}: {err}");
        assert!(
            err.contains("input/output") && err.contains("No space left"),
            "{c}: {err}"
        );
        assert!(!err.contains("panicked"), "{c}: {err}");
    }
}

#[test]
fn a_closed_standard_output_is_refused() {
    for c in ["solve --rho 0.8 --delta 2", "batch"] {
        let (status, _, err) = bash(&format!("echo 0.8,delta,2 | \"$0\" {c} >&-"));
        assert_eq!(status, Some(1), "{c}: {err}");
        assert!(err.contains("standard output is closed"), "{c}: {err}");
    }
    // /dev/null opened by the shell is a place to write to
    let (status, _, err) = bash("\"$0\" solve --rho 0.8 --delta 2 >/dev/null");
    assert_eq!(status, Some(0), "{err}");
}

/// Every size a user can type is checked before anything is allocated.
#[test]
fn sizes_are_bounded_before_allocation() {
    for args in [
        "exact pull-off --rho 0.9 --modes 8 --points 1000000",
        "exact pull-off --rho 0.9 --modes 8 --points 18446744073709551615",
        "exact solve --rho 0.9 --delta 2 --modes 64 --points 20000",
        "curve --rho 0.8 --points 100001",
    ] {
        let (status, _, err) = bash(&format!("\"$0\" {args}"));
        assert_eq!(status, Some(1), "{args}: {err}");
        assert!(
            err.contains("points") && err.contains("allowed range"),
            "{args}: {err}"
        );
    }
}
