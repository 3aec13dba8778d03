//! Generated files (docs/ reports, solver/src/generated/) must equal what
//! the derivation produces now. On a mismatch the fresh file is written and
//! the test fails: rerun `cargo run -p thinjkr-derive -- generate` (or just
//! this test) and commit. The pattern of rust-analyzer's `ensure_file_contents`.

use thinjkr_derive::generate::{outputs, remove_stale, workspace_root, write_all};

#[test]
fn generated_files_are_fresh() {
    let outputs = outputs().expect("derivation and check run");
    let root = workspace_root();
    let changed = write_all(&root, &outputs).expect("can write generated files");
    let gone = remove_stale(&root, &outputs).expect("can remove stale generated files");
    assert!(
        gone.is_empty(),
        "generated files no family or model writes any more were removed: {gone:?}\n\
         commit their removal (cargo run -p thinjkr-derive -- generate does the same)"
    );
    assert!(
        changed.is_empty(),
        "generated files were stale and have been rewritten: {changed:?}\n\
         review the diff and commit them (cargo run -p thinjkr-derive -- generate does the same)"
    );
}

#[test]
fn generation_is_deterministic() {
    let a = outputs().expect("first run");
    let b = outputs().expect("second run");
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.path, y.path);
        assert!(
            x.contents == y.contents,
            "{} differs between two runs",
            x.path.display()
        );
    }
}
