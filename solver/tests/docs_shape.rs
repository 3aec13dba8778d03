//! The documents read in an editor and a diff (issue 32, item 4): no line
//! of docs/*.md or README.md is longer than 400 characters (a table cell
//! says why in at most 120 and refers to the full text; prose is wrapped;
//! the generator tidies what it writes, `derive/src/markdown.rs`).

#[test]
fn no_line_of_the_docs_is_longer_than_400_characters() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = vec![root.join("README.md")];
    for e in std::fs::read_dir(root.join("docs")).expect("docs/ exists") {
        let p = e.expect("a docs entry").path();
        if p.extension().is_some_and(|x| x == "md") {
            files.push(p);
        }
    }
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
