//! A family of one's own as data: family files read and checked (a bad file
//! is refused with its path and the key at fault), the built-in family's
//! file, a particular solution written with an extra harmonic term (X² − Y²
//! is harmonic, so the pressure and Π̄ must not change), derived, checked
//! and generated in memory; and a particular solution that does not solve
//! (2), which the derivation refuses. The whole walk through `generate`, the
//! command line and Python is `solver/tests/walk.rs`.

use std::path::Path;
use thinjkr_derive::codegen_conformal;
use thinjkr_derive::conformal::derive;
use thinjkr_derive::family::{self, Family};

/// The built-in family, from its data file.
fn builtin() -> Family {
    let root = thinjkr_derive::generate::workspace_root();
    family::read_all(&root)
        .expect("the repository's family files read")
        .into_iter()
        .find(|f| f.name == "conformal")
        .expect("derive/families/conformal.toml")
}

const MINE: &str = r#"
kind = "conformal"
name = "mine"
title = "the conformal family with a harmonic term added to the particular solution"
gap = "X^2/2 + mu*Y^2/2"
particular = "X^4/24 + mu*Y^4/24 - dbar*(X^2 + Y^2)/4 + 3*(X^2 - Y^2) - 5"
powers = [1, 3, 5]
rho_min = 0.5
trace_start_a = 2.6
"#;

#[test]
fn a_family_of_ones_own_derives_checks_and_generates() {
    let mine = family::parse(MINE, Path::new("derive/families/mine.toml")).unwrap();
    assert_eq!(mine.largest(), 3);
    assert!(!mine.seeds_exact, "seeds_exact defaults to false");
    let d = derive(&mine.member(3)).expect("the walk's family derives and passes its checks");
    let reference = derive(&builtin().member(3)).unwrap();
    assert!(
        (&d.potential - &reference.potential).is_zero(),
        "a harmonic term in P is cancelled by its own correction"
    );
    let members = codegen_conformal::derive_family(&mine).unwrap();
    let files = codegen_conformal::outputs(&members).unwrap();
    let k3 = files
        .iter()
        .find(|o| o.path == Path::new("solver/src/generated/mine/k3.rs"))
        .expect("a module for K = 3 in the family's own folder");
    assert!(k3.contents.contains("Model `mine:3`"));
    // 149 monomials for K = 3, as an independent implementation counted (issue 20)
    assert!(k3
        .contents
        .contains("pub const POTENTIAL_ROWS: usize = 149;"));
    let table = files
        .iter()
        .find(|o| o.path == Path::new("solver/src/generated/mine/table.rs"))
        .expect("the family's table");
    assert!(table.contents.contains("pub static POTENTIAL"));
    let tables = files
        .iter()
        .find(|o| o.path == Path::new("solver/src/generated/mine/tables.json"))
        .expect("the family's tables as data");
    let parsed: serde_json::Value = serde_json::from_str(&tables.contents).unwrap();
    assert_eq!(parsed["members"][2]["potential_rows"], 149);
    let digests = [
        "0123456789abcdef".to_string(),
        codegen_conformal::digest(tables.contents.as_bytes()),
    ];
    let registry =
        codegen_conformal::registry_outputs(&[builtin(), mine], &[true, true], &digests).unwrap();
    assert!(registry[0].contents.contains("name: \"mine\""));
    assert!(registry[0]
        .contents
        .contains("members: &super::mine::MEMBERS"));
    let json: serde_json::Value = serde_json::from_str(&registry[1].contents).unwrap();
    assert_eq!(json["families"][1]["name"], "mine");
    assert_eq!(json["families"][1]["tables"], "mine/tables.json");
    // each entry carries its tables' digest, and the registry its entries'
    // (as the solver's loader checks them)
    assert_eq!(json["families"][1]["tables_digest"], digests[1].as_str());
    assert_eq!(
        json["digest"],
        codegen_conformal::digest(json["families"].to_string().as_bytes()).as_str()
    );
}

#[test]
fn a_particular_solution_that_does_not_solve_2_is_refused() {
    let wrong = MINE.replace("name = \"mine\"", "name = \"wrong\"").replace(
        "X^4/24 + mu*Y^4/24 - dbar*(X^2 + Y^2)/4 + 3*(X^2 - Y^2) - 5",
        "X^4/24 - dbar*(X^2 + Y^2)/4",
    );
    let f = family::parse(&wrong, Path::new("derive/families/wrong.toml")).unwrap();
    let err = codegen_conformal::derive_family(&f).unwrap_err();
    assert!(err.contains("(2)"), "{err}");
    assert!(
        err.contains("wrong:1") && err.contains("wrong.toml"),
        "{err}"
    );
}

#[test]
fn a_bad_family_file_is_refused_naming_the_file_and_the_key() {
    let at = Path::new("derive/families/bad.toml");
    let long_why = format!("rho_min = 0.5\nrho_min_why = \"{}\"", "x".repeat(73));
    let cases: &[(&str, &str, &str)] = &[
        ("kind = \"conformal\"", "kind = \"spline\"", "kind"),
        ("name = \"mine\"", "name = \"Mine\"", "name"),
        ("name = \"mine\"", "name = \"max\"", "taken"),
        ("name = \"mine\"", "name = \"exact\"", "taken"),
        ("powers = [1, 3, 5]", "powers = [1, 2]", "odd"),
        ("powers = [1, 3, 5]", "powers = [3, 5]", "powers[0]"),
        ("powers = [1, 3, 5]", "powers = [1, 3, 3]", "twice"),
        (
            "powers = [1, 3, 5]",
            "powers = [1, 3, 5, 7, 9, 11, 13, 15, 17]",
            "1 to 8",
        ),
        ("rho_min = 0.5", "rho_min = 0", "rho_min"),
        (
            "rho_min = 0.5",
            "rho_min = 0.5\nrho_min_why = \"one line\\nand another\"",
            "rho_min_why",
        ),
        ("rho_min = 0.5", &long_why, "rho_min_why"),
        ("trace_start_a = 2.6", "trace_start_a = -1", "trace_start_a"),
        (
            "gap = \"X^2/2 + mu*Y^2/2\"",
            "gap = \"X^2/2 + (mu*Y^2/2\"",
            "gap does not parse",
        ),
        ("rho_min = 0.5", "rho_min = 0.5\nspeed = 3", "speed"),
        (
            "rho_min = 0.5",
            "rho_min = 0.5\ndoubtful_defects = [0.1]",
            "one per member (3)",
        ),
        (
            "rho_min = 0.5",
            "rho_min = 0.5\ndoubtful_defects = [0.1, 0, 0.2]",
            "doubtful_defects[1]",
        ),
        ("rho_min = 0.5", "", "rho_min"),
    ];
    for (from, to, word) in cases {
        assert!(MINE.contains(from), "{from}");
        let text = MINE.replace(from, to);
        let err = family::parse(&text, at).unwrap_err();
        assert!(
            err.starts_with("derive/families/bad.toml: ") && err.contains(word),
            "{to}: {err}"
        );
    }
}

/// `trace_start_a` is optional (issue 73): omitted, the solver starts the
/// trace between the circle's neutral points of modes 4 and 6 (or, on a
/// gap no circle solves, the cylinders' of modes 2 and 4); given, it is
/// kept.
#[test]
fn trace_start_a_may_be_omitted() {
    let at = Path::new("derive/families/mine.toml");
    let given = family::parse(MINE, at).unwrap();
    assert_eq!(given.trace_start_a, Some(2.6));
    let omitted = family::parse(&MINE.replace("trace_start_a = 2.6\n", ""), at).unwrap();
    assert_eq!(omitted.trace_start_a, None);
    assert_eq!(omitted.powers, given.powers);
}

#[test]
fn two_families_of_one_name_or_two_seeds_of_one_gap_are_refused() {
    let dir = std::env::temp_dir().join(format!("thinjkr-families-{}", std::process::id()));
    let families = dir.join(family::FOLDER);
    std::fs::create_dir_all(&families).unwrap();
    std::fs::write(families.join("a.toml"), MINE).unwrap();
    std::fs::write(families.join("b.toml"), MINE).unwrap();
    let err = family::read_all(&dir).unwrap_err();
    assert!(err.contains("b.toml") && err.contains("a.toml"), "{err}");
    let seeding = MINE.replace("rho_min = 0.5", "rho_min = 0.5\nseeds_exact = true");
    std::fs::write(families.join("a.toml"), &seeding).unwrap();
    std::fs::write(
        families.join("b.toml"),
        seeding.replace("name = \"mine\"", "name = \"other\""),
    )
    .unwrap();
    let err = family::read_all(&dir).unwrap_err();
    assert!(err.contains("seeds_exact"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}
