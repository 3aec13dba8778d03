//! Hostile input and output, second audit (issue 31, items 8–13): standard
//! error gets the care standard output gets, a thread count the system
//! cannot start falls back, output paths are checked before the work and
//! leave nothing behind, input files are bounded and quoted briefly, and
//! every number in a message has at most six significant digits, with a
//! limit in the units the user typed.

mod common;
use common::bash;

fn scratch(tag: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("thinjkr-hostile-io-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const CONTACT: &str =
    "r1=0.01\nr2=0.015\ntheta_deg=60\nh1=1e-4\nh2=1e-4\ng1=1e6\ng2=1e6\nwork_of_adhesion=0.05\n";

/// The longest run of significant digits in a number written in `text`.
fn longest_mantissa(text: &str) -> usize {
    let mut worst = 0;
    for word in text.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == 'e' || c == '-')) {
        let mantissa = word.split('e').next().unwrap_or("");
        let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
        let significant = digits.trim_start_matches('0').len();
        worst = worst.max(significant);
    }
    worst
}

/// Item 8: a full disk on standard error loses no output and does not
/// panic; the run then ends with a nonzero status.
#[test]
fn standard_error_gets_the_care_standard_output_gets() {
    let dir = scratch("stderr");
    let contact = dir.join("good.toml");
    std::fs::write(&contact, CONTACT).unwrap();
    // ρ = 0.31 is outside the paper's range: the answer comes with a warning
    let (status, out, err) = bash(&format!(
        "\"$0\" physical --file {} --force 0 --model energy --explain 2>/dev/full",
        contact.display()
    ));
    assert_eq!(status, Some(1), "{out}{err}");
    assert!(
        out.starts_with("physical: model energy") && out.contains("dimensionless"),
        "{out}"
    );
    // a batch of 2001 lines, one without a state: every row is written
    let input = dir.join("in.csv");
    let mut lines = String::from("rho,control,value\n");
    for _ in 0..2000 {
        lines.push_str("0.8,delta,2\n");
    }
    lines.push_str("0.8,force,-1000\n");
    std::fs::write(&input, lines).unwrap();
    let (status, out, err) = bash(&format!("\"$0\" batch < {} 2>/dev/full", input.display()));
    assert_eq!(status, Some(3), "some lines failed: {err}");
    assert_eq!(out.lines().count(), 2002, "a header and a row per line");
    assert!(
        out.lines().last().unwrap().contains("pull-off force"),
        "the failed line's row says why"
    );
    // an error whose words cannot be written is still an error (status 1,
    // not a panic's 101); a run with nothing for standard error succeeds
    for (c, want) in [("solve --rho 0.8 --force -1000", 1), ("models", 0)] {
        let (status, out, _) = bash(&format!("\"$0\" {c} 2>/dev/full"));
        assert_eq!(status, Some(want), "{c}: {out}");
    }
    // a closed pipe on standard error is the reader's choice: the output
    // is whole and the status is the command's
    let (_, out, _) = bash(&format!(
        "\"$0\" batch < {} 2> >(head -c 0); echo status $?",
        input.display()
    ));
    assert!(
        out.ends_with("status 3\n") && out.lines().count() == 2003,
        "{}",
        &out[out.len() - 40..]
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// Item 9: more threads than the system can start fall back to fewer,
/// with a warning, instead of panicking at the first parallel step.
#[test]
fn a_thread_count_the_system_cannot_start_falls_back() {
    let dir = scratch("threads");
    let input = dir.join("in.csv");
    std::fs::write(
        &input,
        "rho,control,value\n0.8,delta,2\n0.5,force,-1\n0.9,force,3\n",
    )
    .unwrap();
    for (cap_kb, threads) in [(4_000_000, 2000), (1_000_000, 1000)] {
        let (status, out, err) = bash(&format!(
            "ulimit -v {cap_kb}; RAYON_NUM_THREADS={threads} \"$0\" batch < {}",
            input.display()
        ));
        assert_eq!(
            status,
            Some(0),
            "{threads} threads under {cap_kb} kB: {err}"
        );
        assert_eq!(out.lines().count(), 4, "{out}");
        assert!(err.contains("warning") && err.contains("threads"), "{err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Item 10 (and 13's folder rule): every output path is checked before
/// the work; a refused run leaves no file behind; an output folder is
/// created only where its parent exists, for `figures` and `accuracy` alike.
#[test]
fn output_paths_are_checked_first_and_a_refused_run_leaves_nothing() {
    let dir = scratch("paths");
    let (md, json) = (dir.join("new.md"), dir.join("ref.json"));
    let (status, _, err) = bash(&format!(
        "\"$0\" accuracy --out {} --reference {} --figures /nonexistent_dir/sub",
        md.display(),
        json.display()
    ));
    assert_eq!(status, Some(1), "{err}");
    assert!(
        err.contains("/nonexistent_dir") && err.contains("does not exist"),
        "{err}"
    );
    assert!(!md.exists() && !json.exists(), "nothing left behind");
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        0,
        "no probe left behind"
    );
    let (status, _, err) = bash(&format!("\"$0\" figures --out {}/a/b", dir.display()));
    assert_eq!(status, Some(1), "a missing parent is not created: {err}");
    assert!(err.contains("does not exist"), "{err}");
    assert!(!dir.join("a").exists());
    let (status, _, err) = bash(&format!("\"$0\" accuracy --out {}", dir.display()));
    assert_eq!(status, Some(1));
    assert!(err.contains("is a folder"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Item 11: an input file is bounded before it is read whole, and a parse
/// error quotes at most a few dozen characters of it.
#[test]
fn an_input_file_is_bounded_and_quoted_briefly() {
    let (status, _, err) = bash("timeout 10 \"$0\" physical --file /dev/zero --force 0");
    assert_eq!(status, Some(1), "refused, not read for ever: {err}");
    assert!(err.contains("larger than"), "{err}");
    let dir = scratch("file");
    let long_key = "k".repeat(50_000);
    let file = dir.join("c.toml");
    std::fs::write(&file, format!("{CONTACT}{long_key}=1\n")).unwrap();
    for json in ["", " --json"] {
        let (status, out, err) = bash(&format!(
            "\"$0\" physical --file {} --force 0{json}",
            file.display()
        ));
        // a file that is not a contact is a usage error (status 2)
        assert_eq!(status, Some(2));
        assert!(
            err.contains("not a valid contact file") && err.contains("line 9"),
            "{}",
            &err[..err.len().min(300)]
        );
        assert!(
            err.len() < 600 && out.len() < 800,
            "quoted briefly: {} and {} bytes",
            err.len(),
            out.len()
        );
    }
    std::fs::write(&file, format!("{CONTACT}# {}\n", "x".repeat(100_000))).unwrap();
    let (status, _, err) = bash(&format!(
        "\"$0\" physical --file {} --force 0",
        file.display()
    ));
    assert_eq!(status, Some(1));
    assert!(err.contains("larger than 65536 bytes"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Item 13: at most six significant digits in every message, limits in the
/// units typed, what was typed echoed (not `inf`), and a closed standard
/// input is not an empty batch.
#[test]
fn numbers_in_messages_have_at_most_six_significant_digits() {
    let dir = scratch("numbers");
    let contact = dir.join("good.toml");
    std::fs::write(&contact, CONTACT).unwrap();
    let c = contact.display();
    for cmd in [
        "solve --rho 0.8 --delta -1e308".to_string(),
        "solve --rho 0.8 --force -1e308".to_string(),
        "solve --rho 0.123456789 --force -1000".to_string(),
        "exact bands --rho 0.8 --to 1e300".to_string(),
        "exact bands --rho 0.8 --from 2 --to 1e18".to_string(),
        "pull-off --rho 1e-300".to_string(),
        // issue 32 item 4: a rho of many digits in the refusals of every
        // model and the exact solver
        "pull-off --rho 0.1234567891234 --model apexes".to_string(),
        "solve --rho 0.1234567891234 --force 0 --model conformal:8".to_string(),
        // (with the default escalation the pull-off there is found, in
        // the arclength representation: a fixed truncation refuses)
        "exact pull-off --rho 0.1234567891234 --modes 12".to_string(),
        // (the exact solver's "no state" at zero force there takes minutes:
        // the slow tier's test below)
        format!("physical --file {c} --force -1.0"),
        format!("physical --file {c} --force 1e308"),
        format!("physical --file {c} --delta -1e308"),
    ] {
        let (status, _, err) = bash(&format!("\"$0\" {cmd}"));
        assert_ne!(status, Some(0), "{cmd}");
        assert!(!err.contains("panicked"), "{cmd}: {err}");
        assert!(longest_mantissa(&err) <= 6, "{cmd}: {err}");
    }
    let (_, _, err) = bash(&format!("\"$0\" physical --file {c} --force -1.0"));
    assert!(
        err.contains("force = -1 ") && err.contains(" N, ∞)"),
        "in newtons: {err}"
    );
    let (_, _, err) = bash(&format!("\"$0\" physical --file {c} --force 1e308"));
    assert!(
        err.contains("force = 1e308") && !err.contains("inf "),
        "{err}"
    );
    let (_, _, err) = bash("\"$0\" exact bands --rho 0.8 --from 2 --to 1e18");
    assert!(
        err.contains("parameter to = 1e18"),
        "not an empty screen: {err}"
    );
    let (status, out, err) = bash("\"$0\" batch <&-");
    assert_eq!(status, Some(1), "{out}");
    assert!(err.contains("standard input is closed"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

/// The exact solver's "no state" at zero force for a ρ of many digits, in
/// at most six significant digits (the slow tier: the search takes minutes
/// before it says so; issue 72 asks for seconds).
#[test]
#[ignore = "slow tier (.ci/slow): about 150 s"]
fn the_exact_solvers_no_state_has_at_most_six_significant_digits() {
    let cmd = "exact solve --rho 0.1234567891234 --force 0";
    let (status, _, err) = bash(&format!("\"$0\" {cmd}"));
    assert_ne!(status, Some(0), "{cmd}");
    assert!(!err.contains("panicked"), "{cmd}: {err}");
    assert!(longest_mantissa(&err) <= 6, "{cmd}: {err}");
}

/// A `registry.json` that is a FIFO (or any file that is not regular) is
/// refused with its reason, not read: reading it would block forever.
#[test]
fn a_families_registry_that_is_a_fifo_is_refused_not_read() {
    let (code, out, err) = bash(
        r#"d=$(mktemp -d) && mkfifo "$d/registry.json" && THINJKR_FAMILIES="$d" timeout 20 "$0" models; c=$?; rm -rf "$d"; exit $c"#,
    );
    assert_eq!(code, Some(0), "{out}\n{err}");
    assert!(out.lines().any(|l| l.starts_with("max")), "{out}");
    assert!(err.contains("not a regular file"), "{err}");
}
