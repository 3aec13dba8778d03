//! The documents read in an editor and a diff (issue 32, item 4): no line
//! of docs/*.md or README.md is longer than 400 characters (a table cell
//! says why in at most 120 and refers to the full text; prose is wrapped;
//! the generator tidies what it writes, `derive/src/markdown.rs`), and
//! every table row has its header's number of cells.

/// README.md and docs/*.md.
fn documents() -> Vec<std::path::PathBuf> {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = vec![root.join("README.md")];
    for e in std::fs::read_dir(root.join("docs")).expect("docs/ exists") {
        let p = e.expect("a docs entry").path();
        if p.extension().is_some_and(|x| x == "md") {
            files.push(p);
        }
    }
    files
}

#[test]
fn no_line_of_the_docs_is_longer_than_400_characters() {
    let files = documents();
    assert!(files.len() >= 8, "{files:?}");
    let mut long = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).expect("a readable document");
        for (i, line) in text.lines().enumerate() {
            let n = line.chars().count();
            if n > 400 {
                long.push(format!("{}:{}: {n} characters", f.display(), i + 1));
            }
        }
    }
    assert!(long.is_empty(), "{}", long.join("\n"));
}

/// Every row of a table in docs/*.md and README.md has as many cells as its
/// header (a cell lost or added shifts every column after it, and the
/// tests that read a table by column then read the wrong one). Escaped
/// pipes (`\|`) are text, not separators.
#[test]
fn every_table_row_has_as_many_cells_as_its_header() {
    let files = documents();
    let separators = |line: &str| line.replace("\\|", "").matches('|').count();
    let is_rule = |line: &str| {
        line.starts_with('|') && line.chars().all(|c| matches!(c, '|' | '-' | ':' | ' '))
    };
    let (mut tables, mut uneven) = (0, Vec::new());
    for f in &files {
        let text = std::fs::read_to_string(f).expect("a readable document");
        let lines: Vec<&str> = text.lines().collect();
        for i in 1..lines.len() {
            if !(is_rule(lines[i]) && lines[i - 1].starts_with('|')) {
                continue;
            }
            tables += 1;
            let header = separators(lines[i - 1]);
            for (k, row) in lines[i + 1..]
                .iter()
                .enumerate()
                .take_while(|(_, l)| l.starts_with('|'))
            {
                if separators(row) != header {
                    uneven.push(format!(
                        "{}:{}: {} cells, the header {}",
                        f.display(),
                        i + k + 2,
                        separators(row) - 1,
                        header - 1
                    ));
                }
            }
        }
    }
    assert!(tables >= 20, "{tables} tables found");
    assert!(uneven.is_empty(), "{}", uneven.join("\n"));
}
