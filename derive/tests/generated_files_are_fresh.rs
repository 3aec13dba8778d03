//! Generated files (docs/ reports, solver/src/generated/) must equal what
//! the derivation produces now. On a mismatch the fresh file is written and
//! the test fails: rerun `cargo run --release -p thinjkr-derive -- generate` (or just
//! this test) and commit. The pattern of rust-analyzer's `ensure_file_contents`.

use thinjkr_derive::generate::{outputs, remove_stale, workspace_root, write_all};

/// One test that does both (each derivation takes about a minute in the
/// test profile): the derivation run twice gives the same files byte for
/// byte, and those files are the committed ones.
#[test]
fn generation_is_deterministic_and_the_generated_files_are_fresh() {
    let first = outputs().expect("derivation and check run");
    let again = outputs().expect("second run");
    assert_eq!(first.len(), again.len());
    for (x, y) in first.iter().zip(&again) {
        assert_eq!(x.path, y.path);
        assert!(
            x.contents == y.contents,
            "{} differs between two runs",
            x.path.display()
        );
    }
    let root = workspace_root();
    let changed = write_all(&root, &first).expect("can write generated files");
    let gone = remove_stale(&root, &first).expect("can remove stale generated files");
    assert!(
        gone.is_empty(),
        "generated files no family or model writes any more were removed: {gone:?}\n\
         commit their removal (cargo run --release -p thinjkr-derive -- generate does the same)"
    );
    assert!(
        changed.is_empty(),
        "generated files were stale and have been rewritten: {changed:?}\n\
         review the diff and commit them (cargo run --release -p thinjkr-derive -- generate does the same)"
    );
}
