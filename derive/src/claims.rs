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
//! The catalog itself is data: `derive/claims.toml` (one entry per claim:
//! ID, where, the printed form exactly as printed, substitutions, the
//! derived form it is held against, a printed decimal, the second route),
//! read here with serde. This file is the engine: it evaluates each entry,
//! or hands it to a routine of [`crate::special`] for the claims that are
//! numbers, inequalities or statements.
//!
//! Owns: [`ClaimResult`], the engine ([`check_all`]), the keys of the
//! derived forms ([`derived_form`]). May use: `check`, `layer`, `model`,
//! `numeric`, `routes`, `special`, `sym`.

use crate::check::{approx_printed, compare, describe, seed, Method, Verdict};
use crate::model::Derivation;
use crate::sym::{ex, plain, simplify, solve_linear, subs, subs_all};
use serde::{Deserialize, Serialize};
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
    pub(crate) fn with(mut self, values: &[(&str, f64)]) -> Self {
        for (k, v) in values {
            self.values.insert((*k).to_string(), *v);
        }
        self
    }
}

fn mapped(printed: &str) -> Atom {
    subs(&ex(printed), "dg", &ex("g^2/(2*m)"))
}

/// Compare a printed expression (after the notational map and the extra
/// `rules`) with a derived one; when `target` is set, both are equations
/// `= 0` solved for that symbol first.
pub(crate) fn expr_claim(
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
                    derived: plain(&crate::sym::compact(derived)),
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
        derived: plain(&crate::sym::compact(&d)),
        note,
        values: BTreeMap::new(),
    }
}

pub(crate) fn numeric_claim(
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

pub(crate) fn failed(id: &str, source: &str, printed: &str, why: String) -> ClaimResult {
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

/// One entry of the catalog (`derive/claims.toml`; see its header).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    /// Equation number or label.
    pub id: String,
    /// Where in the paper.
    pub source: String,
    /// The printed form, exactly as printed.
    pub printed: String,
    /// The derived form it is held against (a key of [`derived_form`]).
    pub derived: Option<String>,
    /// Both sides are equations = 0, solved for this symbol first.
    pub solve_for: Option<String>,
    /// Substitutions into the printed form; `@key` is a derived form.
    #[serde(default)]
    pub rules: Vec<(String, String)>,
    /// A printed decimal approximation, also checked.
    pub decimal: Option<String>,
    /// The second route that must agree ([`crate::routes`]).
    pub route: Option<String>,
    /// The printed form as shown in the reports, when compared rearranged.
    pub shown: Option<String>,
    /// How it was derived; `{key}` is replaced by the derived form `key`.
    #[serde(default)]
    pub note: String,
    /// A routine of [`crate::special`] that decides the claim.
    pub routine: Option<String>,
}

#[derive(Deserialize)]
struct Catalog {
    claim: Vec<Entry>,
}

/// The catalog, parsed from `derive/claims.toml` (compiled in).
pub fn catalog() -> Result<Vec<Entry>, String> {
    toml::from_str::<Catalog>(include_str!("../claims.toml"))
        .map(|c| c.claim)
        .map_err(|e| format!("derive/claims.toml: {e}"))
}

/// The derived form named `key` (the catalog's `derived`, `rules` `@key`
/// and `{key}` in notes). A form the derivation did not produce is an
/// error, which makes the claim `unverified`.
pub fn derived_form(d: &Derivation, key: &str) -> Result<Atom, String> {
    let l = || {
        d.limits
            .as_ref()
            .map_err(|e| format!("the limits of this ansatz failed: {e}"))
    };
    let with_eta = |e: &Atom| simplify(&subs(e, "eta", &d.eta));
    let dim = |e: &Atom| subs(e, "L", &ex("(g*R1/m)^(1/3)"));
    let index = |prefix: &str| -> Option<usize> { key.strip_prefix(prefix)?.parse().ok() };
    let pick = |v: &[Atom], k: usize| {
        v.get(k)
            .cloned()
            .ok_or_else(|| format!("the derivation has no {key}"))
    };
    if let Some(k) = index("laplace.") {
        return d
            .laplace
            .get(k)
            .map(|e| e.residual.clone())
            .ok_or_else(|| format!("the derivation has no {key}"));
    }
    if let Some(k) = index("xi.") {
        return pick(&d.xi, k);
    }
    if let Some(k) = index("residual.") {
        return pick(&d.residuals, k);
    }
    let abar_dbar = || -> Result<Atom, String> {
        Ok(simplify(&subs(
            &ex("abar*dbar"),
            "dbar",
            &l()?.zero_force.dbar,
        )))
    };
    let layer_m = || -> Result<Atom, String> {
        crate::layer::thin_layer_m(&crate::layer::kernel()?.compliance)
    };
    Ok(match key {
        "zero" => Atom::num(0),
        // the layer's kernel (three-dimensional elasticity): (4) and (2)
        "layer.m" => layer_m()?,
        "layer.laplacian" => simplify(&(ex("phi - delta") * layer_m()?)),
        "force" => d.force.clone(),
        "normal_derivative" => d.normal_derivative.value(),
        "normal_derivative_collocated" => d.normal_derivative_collocated.value(),
        "xi_adhesion" => d.xi_adhesion.clone(),
        "eta" => d.eta.clone(),
        "fbar_reduced" => d.fbar_reduced.clone(),
        "fbar_reduced.eta" => with_eta(&d.fbar_reduced),
        "p0_explicit" => d.p0_explicit.clone(),
        "pressure_collocated" => d.pressure_collocated.clone(),
        "rho_from_xi" => d.rho_from_xi.clone().ok_or(
            "the derivation has no ρ(s, ξ): eliminating ā³ between (15)₂ and (15)₃ failed",
        )?,
        "extrema.u_min" => d.extrema.u_min.clone(),
        "axisymmetric.delta.dimensional" => dim(&l()?.axisymmetric.delta),
        "axisymmetric.force.dimensional" => dim(&l()?.axisymmetric.force),
        "axisymmetric.eta_at_1" => l()?.axisymmetric.eta_at_1.clone(),
        "axisymmetric.dbar" => l()?.axisymmetric.dbar.clone(),
        "axisymmetric.fbar" => l()?.axisymmetric.fbar.clone(),
        "critical.a_bar" => l()?.axisymmetric.critical.0.clone(),
        "critical.force" => l()?.axisymmetric.critical.1.clone(),
        "critical.delta_bar" => l()?.axisymmetric.critical.2.clone(),
        "zero_force.abar_dbar" => abar_dbar()?,
        "zero_force.abar_dbar.eta" => with_eta(&abar_dbar()?),
        "zero_force.abar_cubed" => l()?.zero_force.abar_cubed.clone(),
        "zero_force.abar_cubed.eta" => with_eta(&l()?.zero_force.abar_cubed),
        "zero_force.rho" => l()?.zero_force.rho.clone(),
        "near_circular_exact.a2" => l()?.near_circular_exact.a2.clone(),
        "near_circular_exact.delta" => l()?.near_circular_exact.delta.clone(),
        "near_circular_model.xi0" => l()?.near_circular_model.xi0.clone(),
        "near_circular_model.s1" => l()?.near_circular_model.s1.clone(),
        "near_circular_model.eta_prime_1" => l()?.near_circular_model.eta_prime_1.clone(),
        // a₂ = −(a₀/2) ds/dμ from the model's expansion, in a₀
        "a2_from_model" => {
            ex("a0") * ex("-1/2") * subs(&l()?.near_circular_model.s1, "abar0", &ex("a0"))
        }
        "a2_over_a0_from_model" => ex("-1/2") * &l()?.near_circular_model.s1,
        // q = 1/(ā₀ δ̄₀) with δ̄₀ the axisymmetric (25)₁ at ā₀
        "q_from_axisymmetric" => {
            ex("1/abar0") / &subs(&l()?.axisymmetric.dbar, "abar", &ex("abar0"))
        }
        _ => return Err(format!("unknown derived form {key} in derive/claims.toml")),
    })
}

/// The catalog's note with every `{key}` replaced by the derived form.
fn fill_note(d: &Derivation, note: &str) -> Result<String, String> {
    let mut out = String::new();
    let mut rest = note;
    while let Some(i) = rest.find('{') {
        let j = rest[i..]
            .find('}')
            .ok_or_else(|| format!("unclosed {{ in note: {note}"))?;
        out.push_str(&rest[..i]);
        let key = &rest[i + 1..i + j];
        out.push_str(&if key == "extrema.critical_points" {
            // a list: every interior critical point of (11) in u
            d.extrema
                .critical_points
                .iter()
                .map(plain)
                .collect::<Vec<_>>()
                .join(", ")
        } else {
            plain(&crate::sym::compact(&derived_form(d, key)?))
        });
        rest = &rest[i + j + 1..];
    }
    out.push_str(rest);
    Ok(out)
}

/// Evaluate one formula entry.
fn formula_claim(d: &Derivation, e: &Entry) -> Result<ClaimResult, String> {
    let key = e
        .derived
        .as_deref()
        .ok_or("neither `derived` nor `routine`")?;
    let derived = derived_form(d, key)?;
    let rules = e
        .rules
        .iter()
        .map(|(sym, val)| {
            let v = match val.strip_prefix('@') {
                Some(k) => derived_form(d, k)?,
                None => ex(val),
            };
            Ok((sym.as_str(), v))
        })
        .collect::<Result<Vec<_>, String>>()?;
    let note = fill_note(d, &e.note)?;
    let mut c = expr_claim(
        &e.id,
        &e.source,
        &e.printed,
        &rules,
        &derived,
        e.solve_for.as_deref(),
        &note,
    );
    if let Some(shown) = &e.shown {
        c.printed = shown.clone();
    }
    if let Some(dec) = &e.decimal {
        c = decimal_checked(c, &derived, dec);
    }
    Ok(c)
}

/// Check every claim of the catalog against the derivation `d` (the
/// paper's ansatz, or another closure's: the printed forms are the paper's).
pub fn check_all(d: &Derivation) -> Result<Vec<ClaimResult>, String> {
    let catalog = catalog()?;
    let mut routines = crate::special::Routines::new(d);
    let mut out = Vec::new();
    for e in &catalog {
        let mut c = match &e.routine {
            Some(name) => routines.run(name, e),
            None => {
                formula_claim(d, e).unwrap_or_else(|why| failed(&e.id, &e.source, &e.printed, why))
            }
        };
        if let Some(route) = &e.route {
            c = crate::routes::decided_by_two_routes(c, crate::routes::by_name(d, route));
        }
        out.push(c);
    }
    Ok(out)
}

/// Also test the printed decimal approximation against the derived value.
pub(crate) fn decimal_checked(
    mut c: ClaimResult,
    derived: &Atom,
    printed_decimal: &str,
) -> ClaimResult {
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
