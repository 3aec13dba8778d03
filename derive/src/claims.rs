//! The catalog of the paper's printed claims, transcribed exactly as printed
//! (in symbolica's input syntax; `sint`, `cost` stand for sin t, cos t and
//! `dg` for Δγ), and their evaluation against the derivation.
//!
//! Every printed symbol keeps the paper's meaning. Before comparison the
//! same notational map is applied to every printed form: Δγ is written
//! through g = √(2mΔγ), the right-hand side of (3)₂ (`dg → g²/(2m)`). In
//! Section 4 R is the common radius R₁ = R₂ (`R → R1`, stated per claim).
//! Nothing else is changed.
//!
//! Owns: the catalog and the claim-by-claim evaluation.
//! May use: `check`, `model`, `numeric`, `sym`.

use crate::check::{approx_printed, compare, Comparison, Method, Verdict};
use crate::ir::Ir;
use crate::model::{Derivation, Limits};
use crate::numeric::{bisect, Curve};
use crate::sym::{ex, plain, simplify, solve_linear, subs, subs_all};
use serde::Serialize;
use std::collections::BTreeMap;
use symbolica::atom::Atom;

/// One checked claim.
#[derive(Clone, Debug, Serialize)]
pub struct ClaimResult {
    /// Equation number (`.k` for the k-th line of a display) or text label.
    pub id: String,
    /// Where in the paper.
    pub source: String,
    /// The verdict.
    pub verdict: Verdict,
    /// How it was reached.
    pub method: Method,
    /// The printed form, as transcribed.
    pub printed: String,
    /// The derived form.
    pub derived: String,
    /// Details: the size of a difference, the sample, the second route.
    pub note: String,
    /// Numbers computed by the check, named, for the prose of the reports
    /// (`report::consequence`): no number in a report is typed by hand.
    #[serde(skip)]
    pub values: BTreeMap<String, f64>,
}

impl ClaimResult {
    fn with(mut self, values: &[(&str, f64)]) -> Self {
        for (k, v) in values {
            self.values.insert((*k).to_string(), *v);
        }
        self
    }
}

fn mapped(printed: &str) -> Atom {
    subs(&ex(printed), "dg", &ex("g^2/(2*m)"))
}

fn seed(id: &str) -> u64 {
    id.bytes().fold(1469598103934665603u64, |h, b| {
        (h ^ b as u64).wrapping_mul(1099511628211)
    })
}

fn describe(c: &Comparison) -> String {
    match c.verdict {
        Verdict::Holds if c.method == Method::Exact => "the difference simplifies to 0".into(),
        Verdict::Holds => format!(
            "no exact normal form reached; agrees to {:.1e} relative at {} points with {} digits",
            c.max_rel_diff,
            crate::check::POINTS,
            crate::check::DIGITS
        ),
        Verdict::Differs => {
            let (pt, vp, vd) = c.sample.clone().unwrap_or_default();
            format!(
                "largest relative difference {:.3e} (at {pt}: printed {vp:.10}, derived {vd:.10})",
                c.max_rel_diff
            )
        }
        Verdict::Unverified => "could not be evaluated at the sample points".into(),
    }
}

/// Compare a printed expression (after the notational map and the extra
/// `rules`) with a derived one; when `target` is set, both are equations
/// `= 0` solved for that symbol first.
fn expr_claim(
    id: &str,
    source: &str,
    printed: &str,
    rules: &[(&str, Atom)],
    derived: &Atom,
    target: Option<&str>,
    extra_note: &str,
) -> ClaimResult {
    let p_eq = subs_all(&mapped(printed), rules);
    let (p, d) = match target {
        Some(t) => match (solve_linear(&p_eq, t), solve_linear(derived, t)) {
            (Some(p), Some(d)) => (p, d),
            _ => {
                return ClaimResult {
                    id: id.into(),
                    source: source.into(),
                    verdict: Verdict::Unverified,
                    method: Method::Exact,
                    printed: printed.into(),
                    derived: plain(derived),
                    note: format!("could not solve for {t}"),
                    values: BTreeMap::new(),
                }
            }
        },
        None => (p_eq, derived.clone()),
    };
    let c = compare(&p, &d, seed(id));
    let mut note = match target {
        Some(t) => format!("both solved for {t}; {}", describe(&c)),
        None => describe(&c),
    };
    if !extra_note.is_empty() {
        note = format!("{note}. {extra_note}");
    }
    ClaimResult {
        id: id.into(),
        source: source.into(),
        verdict: c.verdict,
        method: c.method,
        printed: printed.into(),
        derived: plain(&d),
        note,
        values: BTreeMap::new(),
    }
}

fn numeric_claim(
    id: &str,
    source: &str,
    printed: &str,
    holds: bool,
    derived: String,
    note: String,
) -> ClaimResult {
    let note = format!("derived: {derived}; {note}");
    ClaimResult {
        id: id.into(),
        source: source.into(),
        verdict: if holds {
            Verdict::Holds
        } else {
            Verdict::Differs
        },
        method: Method::Solve,
        printed: printed.into(),
        derived,
        note,
        values: BTreeMap::new(),
    }
}

/// The verdict of a claim made of several checks: `unverified` if any
/// check is, else `differs` if any differs, else `holds`.
pub fn combine(parts: &[Verdict]) -> Verdict {
    if parts.contains(&Verdict::Unverified) {
        Verdict::Unverified
    } else if parts.contains(&Verdict::Differs) {
        Verdict::Differs
    } else {
        Verdict::Holds
    }
}

fn failed(id: &str, source: &str, printed: &str, why: String) -> ClaimResult {
    ClaimResult {
        id: id.into(),
        source: source.into(),
        verdict: Verdict::Unverified,
        method: Method::Solve,
        printed: printed.into(),
        derived: String::new(),
        note: why,
        values: BTreeMap::new(),
    }
}

/// The IDs the checker must cover, in the order of the paper.
pub const REQUIRED_IDS: &[&str] = &[
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

/// Check every claim against the derivation of the paper's ansatz.
pub fn check_all(d: &Derivation) -> Result<Vec<ClaimResult>, String> {
    let l = d
        .limits
        .as_ref()
        .map_err(|e| format!("limits of the paper's ansatz failed: {e}"))?;
    let mut out = Vec::new();
    let lap = |k: usize| d.laplace[k].residual.clone();
    let with_eta = |e: &Atom| simplify(&subs(e, "eta", &d.eta));
    let dim = |e: &Atom| subs(e, "L", &ex("(g*R1/m)^(1/3)"));
    let u_rules = [("sint", ex("u^(1/2)")), ("cost", ex("(1-u)^(1/2)"))];

    out.push(expr_claim(
        "6.1",
        "Eq. (6), line 1",
        "1/a^2 + 1/b^2 + A + B - m*delta/(2*p0)",
        &[],
        &lap(0),
        Some("delta"),
        "derived: coefficient of 1 in Δp − m(φ − δ)",
    ));
    out.push(expr_claim(
        "6.2",
        "Eq. (6), line 2",
        "A/b^2 + 6*A/a^2 + B/a^2 - m/(4*p0*R1)",
        &[],
        &lap(1),
        Some("m"),
        "derived: coefficient of x²",
    ));
    out.push(expr_claim(
        "6.3",
        "Eq. (6), line 3",
        "A/b^2 + 6*B/b^2 + B/a^2 - m/(4*p0*R2)",
        &[],
        &lap(2),
        Some("m"),
        "derived: coefficient of y²",
    ));
    out.push(crate::routes::decided_by_two_routes(
        expr_claim(
            "8",
            "Eq. (8)",
            "pi*a*b*p0/12*(6 - A*a^2 - B*b^2)",
            &[],
            &d.force,
            None,
            "",
        ),
        crate::routes::force(d),
    ));
    out.push(expr_claim(
        "9",
        "Eq. (9)",
        "2*p0/(a*b)*(a^2*sint^2 + b^2*cost^2)^(1/2)*(A*a^2*cost^2 + B*b^2*sint^2 - 1)",
        &u_rules,
        &d.normal_derivative.value(),
        None,
        "sin²t written u; derived as −∇p·∇E/|∇E| on x = a cos t, y = b sin t",
    ));
    out.push(claim_10(d));
    out.push(expr_claim(
        "11",
        "Eq. (11)",
        "2*p0/(s*a*xi)*(sint^2 + s^2*cost^2)^(1/2)*(cost^2 + s*sint^2)",
        &u_rules,
        &d.normal_derivative_collocated.value(),
        None,
        "",
    ));
    let crit = d
        .extrema
        .critical_points
        .iter()
        .map(plain)
        .collect::<Vec<_>>()
        .join(", ");
    out.push(expr_claim("13", "Eq. (13)", "4*p0/(3^(3/2)*a*(2*m*dg)^(1/2))*(s^2 + s + 1)^(3/2)/(s*(s + 1))", &[], &d.xi_adhesion, None, &format!("maximum of (11) at sin²t = {} (the only interior root of d(∂p/∂ν)²/du); minimum at sin²t = {}, i.e. at the apexes", crit, plain(&d.extrema.u_min))));
    out.push(expr_claim(
        "15.1",
        "Eq. (15), line 1",
        "1/(2*(s^2 + 1))*(eta*s^2*dbar*abar - s - s^2)",
        &[],
        &d.xi[0],
        None,
        "",
    ));
    out.push(expr_claim(
        "15.2",
        "Eq. (15), line 2",
        "(eta*s^2*abar^3 - 2*(6*s^2 + s + 1))/(4*(3*s^2 + 1))",
        &[],
        &d.xi[1],
        None,
        "",
    ));
    out.push(expr_claim(
        "15.3",
        "Eq. (15), line 3",
        "(eta*s^4*abar^3 - 2*rho*s*(s^2 + s + 6))/(4*rho*(s^2 + 3))",
        &[],
        &d.xi[2],
        None,
        "",
    ));
    out.push(expr_claim(
        "16",
        "Eq. (16)",
        "2*(s^2 + s + 1)^(3/2)/(3^(3/2)*s*(s + 1))",
        &[],
        &d.eta,
        None,
        "derived: η = max ∂p/∂ν / its apex value; (14) = η − 1",
    ));
    out.push(crate::routes::decided_by_two_routes(
        expr_claim(
            "18",
            "Eq. (18)",
            "pi*3^(1/2)*abar^3*(2*s^2*abar*dbar - (s + 1)^3)*s^2*(s + 1)/(16*(s^2 + 1)*(s^2 + s + 1)^(3/2))",
            &[],
            &with_eta(&d.fbar_reduced),
            None,
            &format!(
                "derived F̄ = {}; the printed form lacks the factor η(s) in front of 2s²āδ̄ (equal only at s = 1)",
                plain(&d.fbar_reduced)
            ),
        ),
        crate::routes::force_bar(d),
    ));
    out.push(expr_claim("19", "Eq. (19)", "abar^3 - 2*dbar*(3*s^2 + 1)/(s^2 + 1)*abar - 2*(3*s^4 - 2*s^3 + 6*s^2 + 1)/(s^2*(s^2 + 1)*eta)", &[], &d.residuals[0], Some("dbar"), ""));
    out.push(expr_claim("20", "Eq. (20)", "abar^3 - 2*rho*dbar*(s^2 + 3)/(s^2*(s^2 + 1))*abar - 2*rho*(s^4 + 6*s^2 - 2*s + 3)/(s^3*(s^2 + 1)*eta)", &[], &d.residuals[1], Some("dbar"), ""));
    let ax = &l.axisymmetric;
    out.push(expr_claim("22", "Eq. (22)", "a^2/(4*R) - 2/a*(2*dg/m)^(1/2)", &[("R", ex("R1"))], &dim(&ax.delta), None, "derived from (19) at ρ = s = 1, η(1) = 1, then (17); second route: the exact radial solution of (2)–(3) gives the same δ (see claim 37)"));
    out.push(expr_claim(
        "23",
        "Eq. (23)",
        "pi*m/48*a^4*(a^2/(2*R) - 12/a*(2*dg/m)^(1/2))",
        &[("R", ex("R1"))],
        &dim(&ax.force),
        None,
        "",
    ));
    out.push(crate::routes::decided_by_two_routes(
        expr_claim("25.1", "Eq. (25), first relation", "abar^2/4 - 2^(4/3)/abar", &[], &ax.dbar, None, "derived δ̄ = ā²/4 − 2/ā; substituting (24) into (22) gives 2/ā, not 2^(4/3)/ā (a factor 2^(1/3) on the adhesive term)"),
        crate::routes::axisymmetric(l, 0),
    ));
    out.push(crate::routes::decided_by_two_routes(
        expr_claim(
            "25.2",
            "Eq. (25), second relation",
            "pi/96*abar^4*(abar^2 - 24/abar)",
            &[],
            &ax.fbar,
            None,
            "",
        ),
        crate::routes::axisymmetric(l, 1),
    ));
    out.push(crate::routes::decided_by_two_routes(
        expr_claim(
            "sec4.Fc",
            "Section 4, critical force",
            "-3*pi/2",
            &[],
            &ax.critical.1,
            None,
            "minimum of F̄(ā) from dF̄/dā = 0",
        ),
        crate::routes::axisymmetric_critical(l, 1),
    ));
    out.push(crate::routes::decided_by_two_routes(
        decimal_checked(
            expr_claim(
                "sec4.ac",
                "Section 4, critical radius",
                "2^(2/3)*3^(1/3)",
                &[],
                &ax.critical.0,
                None,
                "",
            ),
            &ax.critical.0,
            "2.2894",
        ),
        crate::routes::axisymmetric_critical(l, 0),
    ));
    out.push(crate::routes::decided_by_two_routes(
        decimal_checked(
            expr_claim(
                "sec4.dc",
                "Section 4, critical approach",
                "2^(-2/3)*3^(2/3) - 2^(2/3)*3^(-1/3)",
                &[],
                &ax.critical.2,
                None,
                &format!(
                    "the printed value follows the printed (25)₁; with the derived δ̄(ā) it is {}",
                    plain(&ax.critical.2)
                ),
            ),
            &ax.critical.2,
            "0.2097",
        ),
        crate::routes::axisymmetric_critical(l, 2),
    ));
    let abar_dbar = simplify(&subs(&ex("abar*dbar"), "dbar", &l.zero_force.dbar));
    let mut c26 = expr_claim(
        "26",
        "Eq. (26)",
        "(s + 1)^3/(2*s^2)",
        &[],
        &with_eta(&abar_dbar),
        None,
        &format!(
            "compared as ā δ̄; derived ā δ̄ = {} (η(s) missing in print, as in (18))",
            plain(&abar_dbar)
        ),
    );
    c26.printed = "abar*dbar = (s + 1)^3/(2*s^2)".into();
    out.push(crate::routes::decided_by_two_routes(
        c26,
        crate::routes::zero_force(d, &abar_dbar, 0),
    ));
    out.push(crate::routes::decided_by_two_routes(
        expr_claim(
            "27",
            "Eq. (27)",
            "3/s^2*(s^3 + 5*s^2 + s + 1)",
            &[],
            &with_eta(&l.zero_force.abar_cubed),
            None,
            &format!(
                "compared as ā³; derived ā³ = {}",
                plain(&l.zero_force.abar_cubed)
            ),
        ),
        crate::routes::zero_force(d, &l.zero_force.abar_cubed, 1),
    ));
    out.push(expr_claim(
        "28",
        "Eq. (28)",
        "s^2*(s^3 + 5*s^2 + s + 1)/(s^3 + s^2 + 5*s + 1)",
        &[],
        &l.zero_force.rho,
        None,
        "η cancels between (19) and (20), so (28) holds although (26), (27) differ",
    ));
    out.push(claim_29(l));
    out.push(claim_30(l));
    let nce = &l.near_circular_exact;
    out.push(expr_claim("36", "Eq. (36)", "a0/3*(1 - 4*R/a0^3*(2*dg/m)^(1/2))^(-1)", &[], &nce.a2, None, "derived by an independent first-order perturbation of the free-boundary problem (2)–(3) with gap (31), contour r = a₀ + μ a₂ cos 2θ"));
    out.push(expr_claim(
        "37",
        "Eq. (37)",
        "a0^2/(4*R) - 2/a0*(2*dg/m)^(1/2)",
        &[],
        &nce.delta,
        None,
        "zeroth order of the same perturbation",
    ));
    let ncm = &l.near_circular_model;
    let a2_rule = (
        "a2",
        ex("a0") * ex("-1/2") * subs(&ncm.s1, "abar0", &ex("a0")),
    );
    out.push(expr_claim(
        "38",
        "Eq. (38)",
        "(9*a2 - 4*a0)/(4*(a0 - 3*a2))",
        &[a2_rule, ("a0", ex("abar0"))],
        &ncm.xi0,
        None,
        "a₂/a₀ taken from the model's own expansion (ds/dμ = −2a₂/a₀ by (35)); derived ξ at μ = 0",
    ));
    out.push(expr_claim("39", "Eq. (39)", "(1/(a0*delta))*(2*dg/m)^(1/2) - s^2*eta*(1 + mu*a2/a0)/(s*(1 + s) + 2*xi*(1 + s^2))", &[("a2", ex("r2*a0")), ("a0", ex("abar*L/(1 + mu*r2)")), ("delta", ex("dbar*L^2/R1")), ("g", ex("m*L^3/R1")), ("xi", d.xi[0].clone())], &Atom::num(0), None, "with a = a₀(1 + μ a₂/a₀) and ξ from (15)₁ the two sides are identical (exactly, not only to first order)"));
    let dbar0 = subs(&ax.dbar, "abar", &ex("abar0"));
    let rho_printed = "s^2*(6*s^2 + s + 1 + 2*xi*(1 + 3*s^2))/(s*(s^2 + s + 6) + 2*xi*(3 + s^2))";
    out.push(match d.rho_from_xi.as_ref() {
        Some(rho) => expr_claim(
            "appendix.rho",
            "Appendix, display before (38)",
            rho_printed,
            &[],
            rho,
            None,
            "derived: ā³ eliminated between (15)₂ and (15)₃ at a common ξ, solved for ρ",
        ),
        None => failed(
            "appendix.rho",
            "Appendix, display before (38)",
            rho_printed,
            "the derivation has no ρ(s, ξ): eliminating ā³ between (15)₂ and (15)₃ failed".into(),
        ),
    });
    out.push(expr_claim(
        "appendix.a2",
        "Appendix, display before the end",
        "(2*q + 1)/(3*q + 3)",
        &[("q", ex("1/abar0") / &dbar0)],
        &(ex("-1/2") * &ncm.s1),
        None,
        "q = √(2Δγ/m)/(a₀δ) = 1/(ā₀δ̄₀); derived a₂/a₀ = −(ds/dμ)/2 from the model",
    ));
    out.push(expr_claim("appendix.36", "Appendix: the model reduces to (36)", "-2/3*(1 - 4*R/a0^3*(2*dg/m)^(1/2))^(-1)", &[("a0", ex("abar0*L")), ("g", ex("m*L^3/R"))], &ncm.s1, None, &format!("ds/dμ at μ = 0 from expanding (19)–(20) (η'(1) = {}) against −2a₂/a₀ with a₂ from (36)", plain(&ncm.eta_prime_1))));
    out.push(expr_claim(
        "sec6.p0",
        "Section 6, p₀",
        "3^(3/2)*xi*a*(2*m*dg)^(1/2)*s*(s + 1)/(4*(s^2 + s + 1)^(3/2))",
        &[],
        &d.p0_explicit,
        None,
        "",
    ));
    out.push(expr_claim(
        "sec6.p",
        "Section 6, p(x, y)",
        "p0*(1 - x^2/a^2 - y^2/b^2)*(1 - x^2/a^2*(1 + 1/xi) - y^2/b^2*(1 + s/xi))",
        &[("b", ex("s*a"))],
        &d.pressure_collocated,
        None,
        "",
    ));
    out.extend(figure_claims(d));
    Ok(out)
}

/// Also test the printed decimal approximation against the derived value.
fn decimal_checked(mut c: ClaimResult, derived: &Atom, printed_decimal: &str) -> ClaimResult {
    let v = match crate::sym::eval_prec(derived, &[], 30) {
        Ok(v) if v.is_finite() => v,
        other => {
            c.verdict = Verdict::Unverified;
            c.note = format!(
                "{}{}printed ≈ {printed_decimal}, but the derived value could not be evaluated ({other:?}), so no verdict",
                c.note,
                if c.note.is_empty() { "" } else { "; " }
            );
            return c;
        }
    };
    let (ok, tol) = approx_printed(v, printed_decimal);
    c.values.insert("derived".into(), v);
    c.note = format!(
        "{}{}printed ≈ {printed_decimal}, derived value {v:.6} ({} within ±{tol})",
        c.note,
        if c.note.is_empty() { "" } else { "; " },
        if ok { "agrees" } else { "not" }
    );
    if !ok && c.verdict == Verdict::Holds {
        c.verdict = Verdict::Differs;
    }
    c
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
fn claim_29(l: &Limits) -> ClaimResult {
    let printed = "1/6*(((1 - rho)^2 + 36*rho)^(1/2) - 1 + rho)";
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
    c.printed = format!("s^2 = {printed}");
    c.derived = format!("rho = {}", plain(&l.non_adhesive_rho));
    c.note = format!("the printed s² substituted into the derived relation ρ(s) of the limit Δγ → 0 (ā → ∞ at fixed δ̄/ā²): {}", c.note);
    c
}

/// (30): error below 0.01 % on (0.4, 1) against the root of the derived (28);
/// asymptotic exactness at ρ = 1 (equal ds/dρ).
fn claim_30(l: &Limits) -> ClaimResult {
    let printed_full = "(((3/10*(1 - rho))^2 + rho)^(1/2) - 3/10*(1 - rho))^(1/2)";
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
    // fig2.bound: (14) < 10 % for s ≥ 0.6.
    let bound = || -> Result<ClaimResult, String> {
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
            "Section 3, text on Fig. 2",
            "(14) < 10 % for s ≥ 0.6",
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
    };
    out.push(match bound() {
        Ok(c) => crate::routes::decided_by_two_routes(
            c,
            crate::routes::two_evaluations(&d.bc_error, (3, 5)),
        ),
        Err(e) => failed("fig2.bound", "Fig. 2", "(14) < 10 % for s ≥ 0.6", e),
    });
    // fig7: pull-off and heavy load at ρ = 0.8.
    let fig7 = || -> Result<(ClaimResult, ClaimResult), String> {
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
            "Section 6, text on Fig. 7",
            "s ≈ 0.895 at pull-off, F̄ ≈ −4.21 (ρ = 0.8)",
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
            "Section 6, text on Fig. 7",
            "s ≈ 0.93 at F̄ = 10 (ρ = 0.8)",
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
    };
    match fig7() {
        Ok((a, b)) => {
            out.push(a);
            out.push(b);
        }
        Err(e) => {
            out.push(failed(
                "fig7.pulloff",
                "Fig. 7",
                "s ≈ 0.895 at F̄ ≈ −4.21",
                e.clone(),
            ));
            out.push(failed("fig7.heavy", "Fig. 7", "s ≈ 0.93 at F̄ = 10", e));
        }
    }
    // sec6.error: (14) < 0.5 % for ρ ≥ 0.8, any loading.
    // Load control visits the branch from F̄ → ∞ down to pull-off (the first
    // minimum of F̄). Displacement control is stable while dδ̄/dā > 0 and
    // continues past the load pull-off down to the fold of the contact size
    // (the first minimum of ā), where dδ̄/dā changes sign through infinity.
    let err = || -> Result<ClaimResult, String> {
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
            "Section 6",
            "(14) < 0.5 % for ρ ≥ 0.8, any loading scenario",
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
    };
    out.push(err().unwrap_or_else(|e| failed("sec6.error", "Section 6", "(14) < 0.5 %", e)));
    out.push(error_against_exact(d));
    out
}

/// The printed form of `sec6.error.exact`.
const SEC6_EXACT_PRINTED: &str =
    "error below 0.5 %, held against the exact solution of (2)–(3) at ρ = 0.8: pull-off F̄, ā, s";

/// The reference the solver writes: `thinjkr accuracy --reference
/// derive/data/exact_reference.json` (derive cannot depend on the solver).
pub const EXACT_REFERENCE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data/exact_reference.json");

/// `sec6.error.exact`: the model's load-controlled pull-off at ρ = 0.8
/// (the first minimum of F̄ on its branch, from this derivation) against
/// the exact pull-off of (2)–(3) read from [`EXACT_REFERENCE`]. Holds when
/// F̄, ā and s are all within 0.5 %; `unverified` when the reference is
/// missing, unresolved (boundary error above 1e-5) or not shown converged
/// under doubling (change above 1e-6, far below the 0.5 % asked about).
fn error_against_exact(d: &Derivation) -> ClaimResult {
    error_against_reference(d, EXACT_REFERENCE)
}

/// [`error_against_exact`] with the reference read from `path`.
pub fn error_against_reference(d: &Derivation, path: &str) -> ClaimResult {
    let id = "sec6.error.exact";
    let source = "Section 6";
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
            SEC6_EXACT_PRINTED,
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
    run().unwrap_or_else(|e| failed(id, source, SEC6_EXACT_PRINTED, e))
}
