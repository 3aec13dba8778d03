//! The claims decided by a routine rather than by comparing two formulas:
//! numbers read off figures, inequalities, the axisymmetric and
//! non-adhesive roots, the error statements of Section 6. Each takes its
//! printed form from the catalog (`derive/claims.toml`, field `routine`).
//!
//! Owns: [`Routines`], [`error_against_reference`], [`EXACT_REFERENCE`].
//! May use: `check`, `claims` (the result type and its constructors),
//! `ir`, `model`, `numeric`, `routes`, `sym`.

use crate::check::{approx_printed, combine, compare, Verdict};
use crate::claims::{expr_claim, failed, numeric_claim, ClaimResult, Entry};
use crate::ir::Ir;
use crate::model::{Derivation, Limits};
use crate::numeric::{bisect, Curve};
use crate::sym::{ex, plain, simplify, subs};
use std::collections::BTreeMap;
use symbolica::atom::Atom;

/// Where a routine builds a result, its source and printed form are left
/// to [`Routines::run`], which takes them from the catalog entry.
const FROM_CATALOG: &str = "";

/// The routines for one derivation; the claims read off figures and
/// Section 6 share their computations, which run once.
pub struct Routines<'a> {
    d: &'a Derivation,
    figures: Option<Vec<ClaimResult>>,
}

impl<'a> Routines<'a> {
    /// The routines for `d`.
    pub fn new(d: &'a Derivation) -> Self {
        Routines { d, figures: None }
    }

    /// Run the routine `name` for the catalog entry `e`: the result carries
    /// the entry's ID, source and printed form.
    pub fn run(&mut self, name: &str, e: &Entry) -> ClaimResult {
        let d = self.d;
        let limits = || {
            d.limits
                .as_ref()
                .map_err(|err| format!("the limits of this ansatz failed: {err}"))
        };
        let mut c = match name {
            "collocation" => claim_10(d),
            "non_adhesive_root" => match limits() {
                Ok(l) => claim_29(l, &e.printed),
                Err(why) => failed(&e.id, &e.source, &e.printed, why),
            },
            "zero_force_approximation" => match limits() {
                Ok(l) => claim_30(l, &e.printed),
                Err(why) => failed(&e.id, &e.source, &e.printed, why),
            },
            "bound_at_0_6" | "pull_off_reading" | "heavy_load_reading" | "a_priori_error" => {
                let all = self.figures.get_or_insert_with(|| figure_claims(d));
                all.iter()
                    .find(|c| c.id == e.id)
                    .cloned()
                    .unwrap_or_else(|| {
                        failed(
                            &e.id,
                            &e.source,
                            &e.printed,
                            format!("routine {name} gave no result for {}", e.id),
                        )
                    })
            }
            "error_against_exact" => error_against_reference(d, EXACT_REFERENCE),
            _ => failed(
                &e.id,
                &e.source,
                &e.printed,
                format!("unknown routine {name} in derive/claims.toml"),
            ),
        };
        c.id = e.id.clone();
        c.source = e.source.clone();
        c.printed = e.shown.clone().unwrap_or_else(|| e.printed.clone());
        c
    }
}

/// (10): the printed A, B are those of the derived collocation, and they
/// make the apex values of (9) equal.
fn claim_10(d: &Derivation) -> ClaimResult {
    let printed = "A = 1/a^2*(1 + 1/xi), B = 1/b^2*(1 + b/(a*xi))";
    let coefficient = |name: &str| {
        d.collocation
            .iter()
            .find(|(n, _)| n == name)
            .map(|x| x.1.clone())
    };
    let (Some(a), Some(b)) = (coefficient("A"), coefficient("B")) else {
        return failed(
            "10",
            "Eq. (10)",
            printed,
            "the derivation has no collocated A or B".into(),
        );
    };
    let ca = expr_claim("10", "", "1/a^2*(1 + 1/xi)", &[], &a, None, "");
    let mut cb = expr_claim(
        "10",
        "Eq. (10)",
        "1/b^2*(1 + b/(a*xi))",
        &[("b", ex("s*a"))],
        &b,
        None,
        "",
    );
    let nd = d
        .normal_derivative
        .subs_all(&[("b", ex("s*a"))])
        .subs_all(&[("A", ex("(1 + 1/xi)/a^2")), ("B", ex("(1 + s/xi)/(s*a)^2"))]);
    let equal = crate::check::compare(&nd.at(&Atom::num(0)), &nd.at(&Atom::num(1)), 10);
    cb.printed = printed.into();
    cb.derived = format!("A = {}, B = {}", plain(&a), plain(&b));
    cb.verdict = combine(&[cb.verdict, ca.verdict, equal.verdict]);
    cb.note = format!(
        "A: {}; B: {}; with the printed (10), (9) at t = 0 and t = π/2: {}",
        ca.note,
        cb.note,
        if equal.verdict == Verdict::Holds {
            "equal (exact)"
        } else {
            "not equal"
        }
    );
    cb
}

/// (29): the printed root s² must satisfy the derived non-adhesive relation.
fn claim_29(l: &Limits, printed: &str) -> ClaimResult {
    let derived_rho_of_printed = subs(
        &l.non_adhesive_rho,
        "s",
        &symbolica::atom::AtomCore::pow(&ex(printed), &ex("1/2")),
    );
    let mut c = expr_claim(
        "29",
        "Eq. (29)",
        "rho",
        &[],
        &derived_rho_of_printed,
        None,
        "",
    );
    c.derived = format!("rho = {}", plain(&l.non_adhesive_rho));
    c.note = format!("the printed s² substituted into the derived relation ρ(s) of the limit Δγ → 0 (ā → ∞ at fixed δ̄/ā²): {}", c.note);
    c
}

/// (30): error below 0.01 % on (0.4, 1) against the root of the derived (28);
/// asymptotic exactness at ρ = 1 (equal ds/dρ).
fn claim_30(l: &Limits, printed_full: &str) -> ClaimResult {
    let run = || -> Result<ClaimResult, String> {
        let rho_s = Ir::from_atom(&l.zero_force.rho)?;
        let approx = Ir::from_atom(&ex(printed_full))?;
        let mut worst: (f64, f64) = (0.0, 0.0);
        for k in 0..2000 {
            let rho = 0.4 + 0.6 * (k as f64 + 0.5) / 2000.0;
            let s = bisect(
                |s| rho_s.eval(&BTreeMap::from([("s", s)])).unwrap_or(f64::NAN) - rho,
                1e-6,
                1.0,
            )?;
            let sa = approx.eval(&BTreeMap::from([("rho", rho)]))?;
            let e = ((sa - s) / s).abs();
            if e > worst.0 {
                worst = (e, rho);
            }
        }
        // ds/dρ at ρ = 1, exactly: 1/(dρ/ds) at s = 1 against d(30)/dρ.
        let drho = crate::sym::value_at(&crate::sym::diff(&l.zero_force.rho, "s"), "s", 1)?;
        let dprinted = crate::sym::value_at(&crate::sym::diff(&ex(printed_full), "rho"), "rho", 1)?;
        let slope = compare(&simplify(&(Atom::num(1) / &drho)), &dprinted, 30);
        if slope.verdict == Verdict::Unverified {
            return Err("ds/dρ at ρ = 1 could not be compared (evaluation failed)".into());
        }
        let holds = worst.0 < 1e-4 && slope.verdict == Verdict::Holds;
        Ok(numeric_claim(
            "30",
            "Eq. (30) and the text after it",
            printed_full,
            holds,
            format!("root of (28); ds/dρ(1) = {}", plain(&simplify(&(Atom::num(1) / &drho)))),
            format!(
                "max relative error of (30) on (0.4, 1): {:.4} % at ρ = {:.4} (2000 points; claim: < 0.01 %); ds/dρ at ρ = 1: (28) gives {}, (30) gives {} ({})",
                worst.0 * 100.0,
                worst.1,
                plain(&simplify(&(Atom::num(1) / &drho))),
                plain(&dprinted),
                if slope.verdict == Verdict::Holds { "equal: asymptotically exact" } else { "not equal" }
            ),
        ))
    };
    run().unwrap_or_else(|e| failed("30", "Eq. (30)", printed_full, e))
}

/// Claims read off figures and Section 6's error statement.
fn figure_claims(d: &Derivation) -> Vec<ClaimResult> {
    let mut out = Vec::new();
    out.push(match fig2_bound(d) {
        Ok(c) => crate::routes::decided_by_two_routes(
            c,
            crate::routes::two_evaluations(&d.bc_error, (3, 5)),
        ),
        Err(e) => failed("fig2.bound", FROM_CATALOG, FROM_CATALOG, e),
    });
    match fig7(d) {
        Ok((a, b)) => {
            out.push(a);
            out.push(b);
        }
        Err(e) => {
            out.push(failed("fig7.pulloff", "Fig. 7", FROM_CATALOG, e.clone()));
            out.push(failed("fig7.heavy", FROM_CATALOG, FROM_CATALOG, e));
        }
    }
    out.push(sec6_error(d).unwrap_or_else(|e| failed("sec6.error", FROM_CATALOG, FROM_CATALOG, e)));
    out
}

/// fig2.bound: (14) < 10 % for s ≥ 0.6.
fn fig2_bound(d: &Derivation) -> Result<ClaimResult, String> {
    let e = Ir::from_atom(&d.bc_error)?;
    let at = |s: f64| e.eval(&BTreeMap::from([("s", s)])).unwrap_or(f64::NAN);
    let samples = (0..=4000)
        .map(|k| 0.6 + 0.4 * k as f64 / 4000.0)
        .map(|s| (at(s), s))
        .collect::<Vec<_>>();
    if let Some((_, s)) = samples.iter().find(|(v, _)| !v.is_finite()) {
        return Err(format!("(14) could not be evaluated at s = {s}"));
    }
    let worst = samples
        .into_iter()
        .fold((0.0, 0.0), |m, v| if v.0 > m.0 { v } else { m });
    let at06 = crate::sym::eval_prec(&d.bc_error, &[("s", crate::sym::rat(3, 5))], 30)?;
    // where (14) crosses 10 %, if it does on [0.3, 0.99]
    let threshold = bisect(|s| at(s) - 0.1, 0.3, 0.99).ok();
    let mut values = vec![("worst", worst.0), ("worst_s", worst.1), ("at_0_6", at06)];
    if let Some(t) = threshold {
        values.push(("threshold", t));
    }
    Ok(numeric_claim(
        "fig2.bound",
        FROM_CATALOG,
        FROM_CATALOG,
        worst.0 < 0.1,
        format!("(14) = η(s) − 1 = {}", plain(&d.bc_error)),
        format!(
            "max of (14) on [0.6, 1] is {:.4} % at s = {:.4}; at s = 0.6 exactly (30 digits) {:.5} %; {}",
            worst.0 * 100.0,
            worst.1,
            at06 * 100.0,
            match threshold {
                Some(t) => format!("(14) < 10 % only for s > {t:.5}"),
                None => "(14) does not cross 10 % on [0.3, 0.99]".into(),
            }
        ),
    )
    .with(&values))
}

/// fig7: pull-off and heavy load at ρ = 0.8.
fn fig7(d: &Derivation) -> Result<(ClaimResult, ClaimResult), String> {
    let c = Curve::new(d, 0.8)?;
    let po = c.first_minimum(|st| st.fbar)?;
    // the pull-off the printed (18) would give on the same branch
    let printed_18 = Ir::from_atom(&ex(
        "pi*3^(1/2)*abar^3*(2*s^2*abar*dbar - (s + 1)^3)*s^2*(s + 1)/(16*(s^2 + 1)*(s^2 + s + 1)^(3/2))",
    ))?;
    let f18 = |st: &crate::numeric::State| {
        printed_18
            .eval(&BTreeMap::from([
                ("abar", st.abar),
                ("s", st.s),
                ("dbar", st.dbar),
            ]))
            .unwrap_or(f64::NAN)
    };
    let po_printed = c.first_minimum(f18)?;
    let f_printed = f18(&po_printed);
    if !f_printed.is_finite() {
        return Err("the printed (18) could not be evaluated on the branch".into());
    }
    let (ok_s, tol_s) = approx_printed(po.s, "0.895");
    let (ok_f, tol_f) = approx_printed(po.fbar, "-4.21");
    let pull = numeric_claim(
        "fig7.pulloff",
        FROM_CATALOG,
        FROM_CATALOG,
        ok_s && ok_f,
        format!("s = {:.5}, F̄ = {:.5} (ā = {:.5}, δ̄ = {:.5})", po.s, po.fbar, po.abar, po.dbar),
        format!(
            "minimum of the derived F̄ along the branch from s∞: s {} (±{tol_s}), F̄ {} (±{tol_f}); tolerance: half a unit in the last printed digit",
            if ok_s { "agrees" } else { "differs" },
            if ok_f { "agrees" } else { "differs" }
        ),
    )
    .with(&[
        ("s", po.s),
        ("fbar", po.fbar),
        ("fbar_printed_18", f_printed),
        ("s_ok", ok_s as u8 as f64),
        ("fbar_ok", ok_f as u8 as f64),
    ]);
    let heavy = c.first_crossing(|st| st.fbar, 10.0)?;
    let (ok_h, tol_h) = approx_printed(heavy.s, "0.93");
    let heavy_c = numeric_claim(
        "fig7.heavy",
        FROM_CATALOG,
        FROM_CATALOG,
        ok_h,
        format!("s = {:.5} at F̄ = 10 (ā = {:.5}, δ̄ = {:.5})", heavy.s, heavy.abar, heavy.dbar),
        format!(
            "tolerance ±{tol_h}; s∞ = {:.5} is the non-adhesive limit (29), approached only as F̄ → ∞",
            c.s_inf()?
        ),
    )
    .with(&[("s", heavy.s), ("s_inf", c.s_inf()?), ("s_pull_off", po.s)]);
    let pull = crate::routes::decided_by_two_routes(
        pull,
        crate::routes::on_branch(d, 0.8, &po, "the pull-off"),
    );
    let heavy_c = crate::routes::decided_by_two_routes(
        heavy_c,
        crate::routes::on_branch(d, 0.8, &heavy, "F̄ = 10"),
    );
    Ok((pull, heavy_c))
}

/// sec6.error: (14) < 0.5 % for ρ ≥ 0.8, any loading.
/// Load control visits the branch from F̄ → ∞ down to pull-off (the first
/// minimum of F̄). Displacement control is stable while dδ̄/dā > 0 and
/// continues past the load pull-off down to the fold of the contact size
/// (the first minimum of ā), where dδ̄/dā changes sign through infinity.
fn sec6_error(d: &Derivation) -> Result<ClaimResult, String> {
    let mut worst_load: (f64, f64) = (0.0, 0.0);
    let mut worst_disp: (f64, f64, f64) = (0.0, 0.0, 0.0);
    for k in 0..=20 {
        let rho = 0.8 + 0.19 * k as f64 / 20.0;
        let c = Curve::new(d, rho)?;
        let po = c.first_minimum(|st| st.fbar)?;
        if po.bc_error > worst_load.0 {
            worst_load = (po.bc_error, rho);
        }
        let fold = c.first_minimum(|st| st.abar)?;
        if fold.bc_error > worst_disp.0 {
            worst_disp = (fold.bc_error, rho, fold.s);
        }
    }
    let c = Curve::new(d, 0.8)?;
    let s_half = c.first_crossing(|st| st.bc_error, 0.005)?;
    let values = [
        ("worst_load", worst_load.0),
        ("worst_displacement", worst_disp.0),
        ("s_half", s_half.s),
    ];
    Ok(numeric_claim(
        "sec6.error",
        FROM_CATALOG,
        FROM_CATALOG,
        worst_load.0 < 0.005 && worst_disp.0 < 0.005,
        format!("max (14) = {:.4} % under load control, {:.4} % under displacement control", worst_load.0 * 100.0, worst_disp.0 * 100.0),
        format!(
            "21 values of ρ in [0.8, 0.99]. Load control (F̄ from +∞ to pull-off): max {:.4} % at ρ = {:.3}, at pull-off: {}. Displacement control continues past the load pull-off (dδ̄/dā > 0) to the fold of the contact size (minimum of ā): there (14) = {:.4} % (ρ = {:.3}, s = {:.4}); at ρ = 0.8 it passes 0.5 % at s = {:.4}, F̄ = {:.4}",
            worst_load.0 * 100.0,
            worst_load.1,
            if worst_load.0 < 0.005 { "holds" } else { "does not hold" },
            worst_disp.0 * 100.0,
            worst_disp.1,
            worst_disp.2,
            s_half.s,
            s_half.fbar
        ),
    )
    .with(&values))
    .map(|claim| {
        crate::routes::decided_by_two_routes(
            claim,
            crate::routes::on_branch(d, 0.8, &s_half, "the state where (14) = 0.5 %"),
        )
    })
}

/// The reference the solver writes: `thinjkr accuracy --reference
/// derive/data/exact_reference.json` (derive cannot depend on the solver).
pub const EXACT_REFERENCE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data/exact_reference.json");

/// `sec6.error.exact`: the model's load-controlled pull-off at ρ = 0.8
/// (the first minimum of F̄ on its branch, from this derivation) against
/// the exact pull-off of (2)–(3) read from [`EXACT_REFERENCE`]. Holds when
/// F̄, ā and s are all within 0.5 %; `unverified` when the reference is
/// missing, unresolved (boundary error above 1e-5) or not shown converged
/// under doubling (change above 1e-6, far below the 0.5 % asked about).
/// The claim `sec6.error.exact` with the reference read from `path`.
pub fn error_against_reference(d: &Derivation, path: &str) -> ClaimResult {
    let id = "sec6.error.exact";
    let source = FROM_CATALOG;
    let run = || -> Result<ClaimResult, String> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("no exact reference ({path}: {e}); run `thinjkr accuracy --reference derive/data/exact_reference.json`"))?;
        let v: serde_json::Value =
            serde_json::from_str(&text).map_err(|e| format!("{path} is not valid JSON: {e}"))?;
        let entry = v["pull_off"]
            .as_array()
            .and_then(|a| a.iter().find(|e| e["rho"].as_f64() == Some(0.8)))
            .ok_or_else(|| format!("{path} has no exact pull-off at rho = 0.8"))?;
        let num = |k: &str| {
            entry[k]
                .as_f64()
                .ok_or_else(|| format!("{path}: entry rho = 0.8 has no number {k}"))
        };
        let (f_x, a_x, s_x, bc) = (
            num("force_bar")?,
            num("a_bar")?,
            num("s")?,
            num("bc_error")?,
        );
        if !(bc <= 1e-5) {
            return Err(format!(
                "the exact pull-off at rho = 0.8 is not resolved (boundary error {bc:.1e} > 1e-5)"
            ));
        }
        let (dc_f, dc_s) = (num("doubling_change_force")?, num("doubling_change_s")?);
        if !(dc_f <= 1e-6 && dc_s <= 1e-6) {
            return Err(format!(
                "the exact pull-off at rho = 0.8 is not shown converged: doubling changes F by {dc_f:.1e} and s by {dc_s:.1e}"
            ));
        }
        let c = Curve::new(d, 0.8)?;
        let po = c.first_minimum(|st| st.fbar)?;
        let route = crate::routes::on_branch(d, 0.8, &po, "the model's pull-off");
        let rel = |m: f64, x: f64| m / x - 1.0;
        let (ef, ea, es) = (rel(po.fbar, f_x), rel(po.abar, a_x), rel(po.s, s_x));
        let within = |e: f64| e.abs() < 0.005;
        let verdict = |e: f64| if within(e) { "within" } else { "outside" };
        Ok(numeric_claim(
            id,
            source,
            FROM_CATALOG,
            within(ef) && within(ea) && within(es),
            format!(
                "model pull-off F̄ = {:.6}, ā = {:.6}, s = {:.6}; exact F̄ = {f_x:.6}, ā = {a_x:.6}, s = {s_x:.6}",
                po.fbar, po.abar, po.s
            ),
            format!(
                "relative errors of the model: F̄ {:+.3} % ({}), ā {:+.3} % ({}), s {:+.3} % ({}); the exact pull-off has boundary error {bc:.0e} and changes by {dc_f:.0e} (F̄), {dc_s:.0e} (s) when modes and points are doubled; the bound (14) at the model's pull-off is {:.3} %",
                100.0 * ef,
                verdict(ef),
                100.0 * ea,
                verdict(ea),
                100.0 * es,
                verdict(es),
                100.0 * po.bc_error
            ),
        ))
        .map(|claim| crate::routes::decided_by_two_routes(claim, route))
    };
    run().unwrap_or_else(|e| failed(id, source, FROM_CATALOG, e))
}
