//! The checker: complete, and able to tell agreement from disagreement.
//!
//! The expected verdicts below were established by hand, independently of
//! this code (see docs/errata.md for the derived forms):
//! - (18) lacks η(s): printed F̄ ≠ derived at s ≠ 1;
//! - (25)₁ has 2^(4/3)/ā where (22) with (24) gives 2/ā, hence δ̄_c too;
//! - (26), (27) lack η(s) (consequence of (18)); (28) holds since η cancels;
//! - (19), (20), (13), (36) hold.

use thinjkr_derive::check::{compare, Verdict};
use thinjkr_derive::claims::check_all;
use thinjkr_derive::{ansatz, model::Derivation, sym::ex};

/// The IDs the checker must cover, in the order of the paper (the claims
/// the paper prints, listed here independently of the catalog
/// derive/claims.toml, which must cover them).
const REQUIRED_IDS: &[&str] = &[
    "2",
    "4",
    "6.1",
    "6.2",
    "6.3",
    "8",
    "9",
    "10",
    "11",
    "13",
    "15.1",
    "15.2",
    "15.3",
    "18",
    "19",
    "20",
    "22",
    "23",
    "25.1",
    "25.2",
    "26",
    "27",
    "28",
    "29",
    "30",
    "36",
    "37",
    "38",
    "39",
    "sec4.Fc",
    "sec4.ac",
    "sec4.dc",
    "sec6.p0",
    "sec6.p",
    "sec6.error",
    "sec6.error.exact",
    "fig2.bound",
    "fig7.pulloff",
    "fig7.heavy",
    "appendix.36",
];

fn results() -> Vec<thinjkr_derive::claims::ClaimResult> {
    check_all(&Derivation::new(&ansatz::PAPER).expect("derivation")).expect("check")
}

#[test]
fn every_required_id_has_a_verdict_and_a_method() {
    let r = results();
    for id in REQUIRED_IDS {
        let c = r
            .iter()
            .find(|c| c.id == *id)
            .unwrap_or_else(|| panic!("claim {id} missing"));
        assert_ne!(
            c.verdict,
            Verdict::Unverified,
            "claim {id} unverified: {}",
            c.note
        );
    }
    let json = serde_json::to_value(&r).expect("serialises");
    for obj in json.as_array().expect("array") {
        for key in ["id", "verdict", "method", "printed", "derived"] {
            assert!(obj.get(key).is_some(), "key {key} missing in {obj}");
        }
    }
}

#[test]
fn verdicts_match_the_hand_derivation() {
    let r = results();
    let verdict = |id: &str| r.iter().find(|c| c.id == id).expect("present").verdict;
    for id in ["18", "25.1", "26", "27", "sec4.dc"] {
        assert_eq!(verdict(id), Verdict::Differs, "{id}");
    }
    for id in [
        "6.1",
        "6.2",
        "6.3",
        "8",
        "9",
        "10",
        "11",
        "13",
        "15.1",
        "19",
        "20",
        "22",
        "23",
        "25.2",
        "28",
        "29",
        "36",
        "37",
        "appendix.36",
        "sec4.Fc",
        "sec4.ac",
    ] {
        assert_eq!(verdict(id), Verdict::Holds, "{id}");
    }
}

#[test]
fn the_comparison_tells_a_changed_coefficient_from_an_identity() {
    // (19) solved for δ̄, and the same with one coefficient changed.
    let d = ex("(abar^3 - 2*(3*s^4 - 2*s^3 + 6*s^2 + 1)/(s^2*(s^2 + 1)*eta))*(s^2 + 1)/(2*(3*s^2 + 1)*abar)");
    let same = ex(
        "(abar^2/2)*(s^2 + 1)/(3*s^2 + 1) - (3*s^4 - 2*s^3 + 6*s^2 + 1)/(s^2*eta*(3*s^2 + 1)*abar)",
    );
    let changed = ex("(abar^3 - 2*(3*s^4 - 2*s^3 + 6*s^2 + 2)/(s^2*(s^2 + 1)*eta))*(s^2 + 1)/(2*(3*s^2 + 1)*abar)");
    assert_eq!(compare(&same, &d, 1).verdict, Verdict::Holds);
    assert_eq!(compare(&changed, &d, 1).verdict, Verdict::Differs);
    // a radical identity that needs the numeric tier or radical normalisation
    assert_eq!(
        compare(&ex("3^(3/2)/3^(1/2)"), &ex("3"), 2).verdict,
        Verdict::Holds
    );
    assert_eq!(
        compare(&ex("2^(4/3)"), &ex("2"), 3).verdict,
        Verdict::Differs
    );
}

/// `sec6.error.exact` is `unverified`, never a verdict, when its exact
/// reference is missing, not JSON, unresolved or not shown converged; with
/// the committed reference it is decided (the verdict itself depends on
/// the exact solution: see docs/errata.md).
#[test]
fn the_exact_error_claim_needs_a_resolved_converged_reference() {
    use thinjkr_derive::special::{error_against_reference, EXACT_REFERENCE};
    let d = Derivation::new(&ansatz::PAPER).expect("derivation");
    let dir = std::env::temp_dir().join(format!("thinjkr-ref-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = std::fs::read_to_string(EXACT_REFERENCE).expect("reference exists");
    let v: serde_json::Value = serde_json::from_str(&good).unwrap();
    let with = |key: &str, value: f64| {
        let mut w = v.clone();
        for e in w["pull_off"].as_array_mut().unwrap() {
            e[key] = serde_json::json!(value);
        }
        w.to_string()
    };
    let cases = [
        ("missing", None),
        ("garbage", Some("not json".to_string())),
        ("unresolved", Some(with("bc_error", 1e-3))),
        ("unconverged", Some(with("doubling_change_force", 1e-4))),
    ];
    for (name, content) in cases {
        let p = dir.join(format!("{name}.json"));
        if let Some(c) = content {
            std::fs::write(&p, c).unwrap();
        }
        let r = error_against_reference(&d, p.to_str().unwrap());
        assert_eq!(r.verdict, Verdict::Unverified, "{name}: {}", r.note);
    }
    let r = error_against_reference(&d, EXACT_REFERENCE);
    assert_ne!(r.verdict, Verdict::Unverified, "{}", r.note);
    std::fs::remove_dir_all(&dir).ok();
}

/// A derivation step that fails, or a derived side that cannot be
/// evaluated, gives `unverified` with the reason, never `holds` or
/// `differs`: here the elimination behind the Appendix's ρ(s, ξ) is
/// removed, the collocation lost, and (14) replaced by an expression with
/// a symbol nothing assigns (so no number can be computed from it).
#[test]
fn a_failing_derivation_step_is_unverified() {
    let good = Derivation::new(&ansatz::PAPER).expect("derivation");
    let verdict_of = |d: &Derivation, id: &str| {
        let r = check_all(d).expect("check runs");
        let c = r.into_iter().find(|c| c.id == id).expect("present");
        (c.verdict, c.note)
    };
    let mut d = good.clone();
    d.rho_from_xi = None;
    let (v, note) = verdict_of(&d, "appendix.rho");
    assert_eq!(v, Verdict::Unverified, "{note}");
    assert!(note.contains("eliminating"), "{note}");

    let mut d = good.clone();
    d.collocation.clear();
    let (v, note) = verdict_of(&d, "10");
    assert_eq!(v, Verdict::Unverified, "{note}");

    let mut d = good.clone();
    d.bc_error = ex("s*unknown_symbol");
    let (v, note) = verdict_of(&d, "fig2.bound");
    assert_eq!(v, Verdict::Unverified, "{note}");
}

/// The second routes decide: a second route that disagrees with the
/// derived side makes the claim `unverified`, whatever the comparison
/// with the printed form said.
#[test]
fn disagreeing_second_routes_leave_no_verdict() {
    use thinjkr_derive::routes::{decided_by_two_routes, SecondRoute};
    let r = results();
    let c18 = r.iter().find(|c| c.id == "18").expect("present").clone();
    assert_eq!(c18.verdict, Verdict::Differs, "{}", c18.note);
    assert!(c18.note.contains("Second route agrees"), "{}", c18.note);
    let broken = decided_by_two_routes(
        c18.clone(),
        Ok(SecondRoute {
            text: "quadrature 1.0 vs derived 2.0".into(),
            agrees: false,
        }),
    );
    assert_eq!(broken.verdict, Verdict::Unverified);
    let failed = decided_by_two_routes(c18, Err("quadrature failed".into()));
    assert_eq!(failed.verdict, Verdict::Unverified);
    let c8 = r.iter().find(|c| c.id == "8").expect("present");
    assert_eq!(c8.verdict, Verdict::Holds, "{}", c8.note);
    assert!(c8.note.contains("Second route agrees"), "{}", c8.note);
}

/// The numbers in the reports' prose are computed by the check from the
/// model being checked: the same sentences, for the ansatz `apexes` (∂p/∂ν fixed at the apex), carry
/// other numbers (and every one of them is computed, none missing).
#[test]
fn report_numbers_come_from_the_model_checked() {
    use thinjkr_derive::report::consequence;
    let paper = results();
    let other = check_all(&Derivation::new(&ansatz::APEXES).expect("the apexes model derives"))
        .expect("check runs");
    for (id, differs) in [
        // (14) depends on the collocation only, which apexes shares
        ("fig2.bound", false),
        ("fig7.pulloff", true),
        ("fig7.heavy", true),
        ("sec6.error", true),
    ] {
        let find = |r: &[thinjkr_derive::claims::ClaimResult]| {
            r.iter().find(|c| c.id == id).expect("present").clone()
        };
        let (a, b) = (consequence(&find(&paper)), consequence(&find(&other)));
        assert!(!a.contains("computed no values"), "{id}: {a}");
        assert!(
            !b.contains("computed no values"),
            "{id}: {b} ({})",
            find(&other).note
        );
        if differs {
            assert_ne!(a, b, "{id}: the same text for two models");
        } else {
            assert_eq!(a, b, "{id}");
        }
    }
    // the paper's pull-off, as the check computed it, is the number printed
    let c = paper.iter().find(|c| c.id == "fig7.pulloff").unwrap();
    let f = c.values["fbar"];
    assert!(
        consequence(c).contains(&format!("{f:.3}")),
        "{}",
        consequence(c)
    );
}

/// Which closure reproduces the printed forms that differ for the paper's:
/// with `apexes` (∂p/∂ν = √(2mΔγ) at both apexes, so η ≡ 1) the derived
/// zero-force forms lose η and become the printed (26) and (27) exactly;
/// the printed (18) still differs, because it keeps the paper's prefactor
/// 1/η(s) = 3√3 s(s+1)/(2(s²+s+1)^(3/2)) while dropping η in front of
/// 2s²āδ̄ (worked by hand from the derived forms in docs/derivation.md).
/// docs/errata.md reports this per claim ("Other closures").
#[test]
fn the_apexes_closure_gives_the_printed_zero_force_forms() {
    let d = Derivation::new(&ansatz::APEXES).expect("apexes derives");
    let r = check_all(&d).expect("check runs");
    let verdict = |id: &str| r.iter().find(|c| c.id == id).expect("present").verdict;
    assert_eq!(verdict("26"), Verdict::Holds);
    assert_eq!(verdict("27"), Verdict::Holds);
    assert_eq!(verdict("18"), Verdict::Differs);
    let errata = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/errata.md"))
        .expect("errata exists");
    let differs = results()
        .into_iter()
        .filter(|c| c.verdict == Verdict::Differs)
        .count();
    assert_eq!(errata.matches("- Other closures:").count(), differs);
}

/// Every `differs` verdict, and every critical value of Section 4, is
/// confirmed by a second, independent route that agrees with the derived
/// side (quadrature of the pressure, the radial ODE at ρ = 1, the
/// numerically found zero-force state, the residuals at a branch state,
/// a 30-digit evaluation): each erratum rests on two routes.
#[test]
fn every_differing_claim_is_confirmed_by_a_second_route() {
    let r = results();
    let mut checked = 0;
    for c in &r {
        if c.verdict == Verdict::Differs || c.id.starts_with("sec4.") {
            assert!(
                c.note.contains("Second route agrees"),
                "{} ({:?}) has no agreeing second route: {}",
                c.id,
                c.verdict,
                c.note
            );
            checked += 1;
        }
    }
    assert!(checked >= 12, "{checked}");
}

/// The radial ODE route is converged: halving its step changes δ̄ and F̄
/// by less than 1e-11 relative, far below the 1e-9 the claims ask.
#[test]
fn the_radial_route_is_converged_in_its_step() {
    use thinjkr_derive::routes::{radial, RADIAL_STEPS};
    let (d1, f1) = radial(2.5, RADIAL_STEPS);
    let (d2, f2) = radial(2.5, 2 * RADIAL_STEPS);
    assert!(((d1 - d2) / d2).abs() < 1e-11, "{d1} {d2}");
    assert!(((f1 - f2) / f2).abs() < 1e-11, "{f1} {f2}");
}

/// The catalog is data (derive/claims.toml): IDs are unique, every entry
/// is a formula with a derived form the paper's derivation resolves or a
/// routine, and it covers every claim the paper prints.
#[test]
fn the_catalog_is_data_and_every_key_resolves() {
    use thinjkr_derive::claims::{catalog, derived_form};
    let cat = catalog().expect("derive/claims.toml parses");
    let d = Derivation::new(&ansatz::PAPER).expect("derivation");
    let mut ids = std::collections::BTreeSet::new();
    for e in &cat {
        assert!(ids.insert(e.id.clone()), "duplicate id {}", e.id);
        match (&e.derived, &e.routine) {
            (Some(k), None) => {
                let _ = derived_form(&d, k).unwrap_or_else(|why| panic!("{}: {k}: {why}", e.id));
            }
            (None, Some(_)) => {}
            _ => panic!("{}: needs exactly one of `derived` and `routine`", e.id),
        }
    }
    for id in REQUIRED_IDS {
        assert!(ids.contains(*id), "the catalog lacks {id}");
    }
}

/// The derived forms are shown compactly (sym::compact: factored, powers
/// merged, numeric radicals gathered): η(s), (15), (18)–(20) and the
/// zero-force forms are at most 1.5 times as long as the printed forms
/// (both without spaces), and (14) is shown as η − 1. The lengths are
/// printed (`--nocapture`) for the record.
#[test]
fn derived_forms_are_printed_compactly() {
    use thinjkr_derive::claims::{catalog, derived_form};
    use thinjkr_derive::sym::{compact, is_zero, plain, simplify};
    let d = Derivation::new(&ansatz::PAPER).expect("derivation");
    let cat = catalog().expect("catalog");
    let printed = |id: &str| {
        cat.iter()
            .find(|e| e.id == id)
            .expect("in the catalog")
            .printed
            .replace(' ', "")
    };
    let eta_symbolic = |k: &str| derived_form(&d, k).expect("derived");
    let cases = [
        ("16", eta_symbolic("eta")),
        ("15.1", eta_symbolic("xi.0")),
        ("15.2", eta_symbolic("xi.1")),
        ("15.3", eta_symbolic("xi.2")),
        ("18", eta_symbolic("fbar_reduced")),
        ("19", eta_symbolic("residual.0")),
        ("20", eta_symbolic("residual.1")),
        ("26", eta_symbolic("zero_force.abar_dbar")),
        ("27", eta_symbolic("zero_force.abar_cubed")),
        ("28", eta_symbolic("zero_force.rho")),
    ];
    for (id, form) in cases {
        let shown = plain(&compact(&form));
        let (n, p) = (shown.chars().count(), printed(id).chars().count());
        println!(
            "({id}): derived {n} characters, printed {p}, ratio {:.2}: {shown}",
            n as f64 / p as f64
        );
        assert!(n as f64 <= 1.5 * p as f64, "({id}) {n} vs {p}: {shown}");
    }
    assert!(is_zero(&simplify(&(&d.bc_error - &(&d.eta - &ex("1"))))));
}
