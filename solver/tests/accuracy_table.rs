//! `docs/accuracy.md` is fresh: the rows ρ = 1 and ρ = 0.9 of its three
//! tables (pull-off, zero force, F̄ = 10), recomputed here, are the lines
//! the file holds (the full table takes minutes: `thinjkr accuracy`).

use thinjkr::exact::table::{render_row, row, Quantity};

#[test]
fn accuracy_table_rows_are_fresh() {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/accuracy.md"))
        .expect("docs/accuracy.md exists");
    let lines: Vec<&str> = doc.lines().collect();
    for rho in [1.0, 0.9] {
        for q in Quantity::ALL {
            let line = render_row(&row(rho, q));
            assert!(
                lines.contains(&line.as_str()),
                "docs/accuracy.md is stale (run `thinjkr accuracy --out docs/accuracy.md`): no line\n{line}"
            );
        }
    }
}
