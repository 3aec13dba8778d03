//! What the command-line tests share: running the built `thinjkr` inside a
//! bash script, so that a test can close, fill or cap what the shell gives
//! it (`>&-`, `2>/dev/full`, `ulimit -v`).

use std::process::Command;

/// Run `script` in bash with `$0` the built binary: (exit status, stdout,
/// stderr).
pub fn bash(script: &str) -> (Option<i32>, String, String) {
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
