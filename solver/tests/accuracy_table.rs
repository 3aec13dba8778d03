//! The checker's reference is fresh (the rows of `docs/accuracy.md` are
//! held fresh by the unit test `accuracy::tests::accuracy_table_rows_are_fresh`).

/// The checker's reference (derive/data/exact_reference.json, written by
/// the same run) holds the exact pull-off at ρ = 0.8 that the solver
/// computes now, with its truncation: F̄ to 1e-9 relative, ā and s to
/// 1e-7 (the golden-section search locates the minimum of the flat F̄ to
/// about 1e-7 in the arclength; F̄ is stationary there).
#[test]
fn exact_reference_for_the_checker_is_fresh() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../derive/data/exact_reference.json"
    ))
    .expect("derive/data/exact_reference.json exists");
    let r: thinjkr::accuracy::Reference = serde_json::from_str(&text).expect("parses");
    let e = r
        .pull_off
        .iter()
        .find(|e| e.rho == 0.8)
        .expect("an entry at rho = 0.8");
    let (now, _) = thinjkr::exact::pull_off_resolved(0.8).expect("pull-off at 0.8");
    assert_eq!(now.truncation.modes, e.modes);
    for (name, a, b, tol) in [
        ("F", now.force_bar, e.force_bar, 1e-9),
        ("a", now.a_bar, e.a_bar, 1e-7),
        ("s", now.s, e.s, 1e-7),
    ] {
        assert!(
            (a / b - 1.0).abs() < tol,
            "{name}: now {a}, reference {b}: stale, run `{}`",
            r.generated_by
        );
    }
}
