//! A change of the code that is not meant to change an answer changes
//! none (issue 69, "Same failures"): every command of
//! `tests/data/same_answers.jsonl` (every verb and every model, successes
//! and failures) exits with the status it had, fails with the error kind
//! it had, and gives the numbers it had (a state's a_bar, b_bar, s,
//! delta_bar, force_bar, its checks; a batch's and a curve's columns)
//! to 1e-9 of their size, with the same route and control. Its text may
//! change, and its JSON may grow.
//!
//! This is a regression record, not a proof of any number: the numbers
//! are what the program answered when the record was written, and the
//! tests beside it hold them to the paper, the exact solution and second
//! routes. Rewrite it where an answer is meant to change (and say why in
//! the commit): `THINJKR_BLESS=1 cargo nextest run -p thinjkr --test
//! same_answers` writes each command's outcome anew, in the file's order.

use std::collections::BTreeMap;
use std::io::Write;
use std::process::{Command, Stdio};

const FILE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/same_answers.jsonl");

/// The keys whose values are compared, wherever they stand in the JSON.
const NUMBERS: [&str; 11] = [
    "a_bar",
    "b_bar",
    "s",
    "delta_bar",
    "force_bar",
    "bc_error",
    "bc_defect",
    "xi",
    "p0",
    "a",
    "force",
];
const WORDS: [&str; 5] = ["route", "control", "model", "basis", "method"];

/// What a command gave: its exit status, its error's kind, and the
/// compared values by their path in the JSON (or the CSV's row and
/// column).
#[derive(Debug, PartialEq, serde::Serialize, serde::Deserialize)]
struct Outcome {
    status: i32,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    kind: Option<String>,
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    numbers: BTreeMap<String, f64>,
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    words: BTreeMap<String, String>,
}

#[derive(serde::Serialize, serde::Deserialize)]
struct Case {
    args: Vec<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    stdin: Option<String>,
    #[serde(flatten)]
    outcome: Outcome,
}

fn collect(v: &serde_json::Value, path: &str, out: &mut Outcome) {
    match v {
        serde_json::Value::Object(m) => {
            for (k, x) in m {
                let here = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                match x {
                    serde_json::Value::Number(n) if NUMBERS.contains(&k.as_str()) => {
                        out.numbers.insert(here, n.as_f64().expect("a number"));
                    }
                    serde_json::Value::String(s) if WORDS.contains(&k.as_str()) => {
                        out.words.insert(here, s.clone());
                    }
                    serde_json::Value::String(s) if k == "kind" && path.ends_with("error") => {
                        out.kind = Some(s.clone());
                    }
                    _ => collect(x, &here, out),
                }
            }
        }
        serde_json::Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                collect(x, &format!("{path}[{i}]"), out);
            }
        }
        _ => {}
    }
}

/// The outcome of one command: JSON read by [`collect`], CSV by its
/// header's columns (every number of every row).
fn run(case: &Case) -> Outcome {
    let mut child = Command::new(env!("CARGO_BIN_EXE_thinjkr"))
        .args(&case.args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("runs");
    let input = case.stdin.clone().unwrap_or_default();
    let mut pipe = child.stdin.take().expect("stdin");
    // a command that reads no input may close it first
    let _ = pipe.write_all(input.as_bytes());
    drop(pipe);
    let out = child.wait_with_output().expect("ends");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let mut outcome = Outcome {
        status: out.status.code().unwrap_or(-1),
        kind: None,
        numbers: BTreeMap::new(),
        words: BTreeMap::new(),
    };
    let mut lines = stdout.lines();
    match lines.next() {
        Some(first) if first.starts_with('{') => {
            for (i, line) in std::iter::once(first).chain(lines).enumerate() {
                let v: serde_json::Value = serde_json::from_str(line).expect("JSON lines");
                let path = if i == 0 {
                    String::new()
                } else {
                    format!("line{i}")
                };
                collect(&v, &path, &mut outcome);
            }
        }
        Some(header) if header.contains(',') => {
            let columns: Vec<&str> = header.split(',').collect();
            for (r, row) in lines.enumerate() {
                for (c, cell) in row.split(',').enumerate() {
                    if let (Some(name), Ok(x)) = (columns.get(c), cell.parse::<f64>()) {
                        outcome.numbers.insert(format!("row{r}.{name}"), x);
                    }
                }
            }
        }
        _ => {}
    }
    outcome
}

fn close(got: f64, want: f64) -> bool {
    got == want || (got - want).abs() <= 1e-9 * want.abs().max(1.0)
}

#[test]
fn every_recorded_command_gives_the_answer_it_gave() {
    let text = std::fs::read_to_string(FILE).expect("the record");
    let cases: Vec<Case> = text
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{l}: {e}")))
        .collect();
    assert!(cases.len() >= 40, "{} commands in the record", cases.len());
    if std::env::var_os("THINJKR_BLESS").is_some() {
        let mut out = String::new();
        for mut case in cases {
            case.outcome = run(&case);
            out += &serde_json::to_string(&case).expect("serialises");
            out.push('\n');
        }
        std::fs::write(FILE, out).expect("written");
        return;
    }
    let mut differ = Vec::new();
    for case in &cases {
        let got = run(case);
        let want = &case.outcome;
        let command = case.args.join(" ");
        if (got.status, &got.kind) != (want.status, &want.kind) {
            differ.push(format!(
                "{command}: status {} kind {:?}, was {} {:?}",
                got.status, got.kind, want.status, want.kind
            ));
        }
        for (path, &w) in &want.numbers {
            match got.numbers.get(path) {
                Some(&g) if close(g, w) => {}
                other => differ.push(format!("{command}: {path} = {other:?}, was {w}")),
            }
        }
        for (path, w) in &want.words {
            if got.words.get(path) != Some(w) {
                differ.push(format!(
                    "{command}: {path} = {:?}, was {w:?}",
                    got.words.get(path)
                ));
            }
        }
    }
    assert!(differ.is_empty(), "answers changed:\n{}", differ.join("\n"));
}
