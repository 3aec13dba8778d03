//! What the tests that hold docs/exact-record.md's tables to the solver share:
//! the cells of one row of a table, found after an anchor.

/// The cells after the first of the first line starting with `prefix`
/// after `anchor` in docs/exact-record.md.
pub fn row(anchor: &str, prefix: &str) -> Vec<String> {
    let doc = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../docs/exact-record.md"
    ))
    .unwrap();
    let from = doc
        .find(anchor)
        .unwrap_or_else(|| panic!("no {anchor} in docs/exact-record.md"));
    let line = doc[from..]
        .lines()
        .find(|l| l.starts_with(prefix))
        .unwrap_or_else(|| panic!("no row {prefix} after {anchor}"));
    line.trim_matches(|c| c == '|' || c == ' ')
        .split(" | ")
        .skip(1)
        .map(str::to_string)
        .collect()
}
