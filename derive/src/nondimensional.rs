//! Step 4 of the derivation: the adhesion condition (13) gives p₀; the
//! scales (17) make the matched system (6) dimensionless; each of its
//! equations is solved for ξ (Eq. (15)), and eliminating ξ leaves the two
//! residuals (19), (20) in (ā, s) with parameters (ρ, δ̄). The force (8)
//! becomes (18).
//!
//! The scales (17) are applied through one length L = (2R₁²Δγ/m)^(1/6):
//! a = ā L, δ = δ̄ L²/R₁, Δγ = m L⁶/(2R₁²) (so √(2mΔγ) = m L³/R₁ and
//! F = F̄ m L⁶/R₁), R₂ = ρ R₁ (21), b = s a (12). The reduction checks that
//! L, m and R₁ then drop out, which is the content of (17).
//!
//! The paper's η(s) of (16) is, for any ansatz, the ratio of the maximum of
//! ∂p/∂ν on Γ₀ to its apex value; it stays a symbol `eta` in the reduced
//! equations and its closed form is kept beside them.
//!
//! Owns: p₀, ξ-forms, residuals, dimensionless force, branch parametrisation.
//! May use: `contour`, `thin_layer`, `force`, `sym`.

use crate::sym::{degree_in, diff, ex, is_zero, simplify, solve_linear, subs, subs_all};
use symbolica::atom::{Atom, AtomCore};

/// The substitutions of (12), (17), (21), in the order they must be applied.
pub fn scale_rules() -> Vec<(&'static str, Atom)> {
    vec![
        ("b", ex("s*a")),
        ("a", ex("abar*L")),
        ("delta", ex("dbar*L^2/R1")),
        ("R2", ex("rho*R1")),
        ("g", ex("m*L^3/R1")),
    ]
}

/// Fail when a dimensional symbol survived the scaling.
pub fn check_dimensionless(e: &Atom, what: &str) -> Result<(), String> {
    for s in ["L", "m", "R1", "a", "b", "delta", "p0", "g"] {
        if e.contains_symbol(symbolica::symbol!(s)) {
            return Err(format!("{what} still contains {s} after scaling by (17)"));
        }
    }
    Ok(())
}

/// Solve each matched equation for ξ: the dimensionless system (15).
pub fn xi_forms(equations: &[Atom], rules: &[(&str, Atom)]) -> Result<Vec<Atom>, String> {
    equations
        .iter()
        .enumerate()
        .map(|(k, eq)| {
            let e = subs_all(&subs_all(eq, rules), &scale_rules());
            let xi = solve_linear(&e, "xi")
                .ok_or_else(|| format!("equation {} is not linear in xi", k + 1))?;
            check_dimensionless(&xi, &format!("xi from equation {}", k + 1))?;
            Ok(xi)
        })
        .collect()
}

/// Coefficient of the highest power of `abar` (by repeated differentiation).
fn leading_coefficient(e: &Atom, name: &str) -> Result<Atom, String> {
    let n = degree_in(e, name, 12).ok_or("degree too high")?;
    let mut d = e.expand();
    for _ in 0..n {
        d = diff(&d, name);
    }
    let fact: i64 = (1..=n as i64).product();
    Ok(simplify(&(subs(&d, name, &Atom::num(0)) / Atom::num(fact))))
}

/// Eliminate ξ between the first form and each other: the residuals (19),
/// (20), normalised to be monic in ā.
pub fn residuals(xi: &[Atom]) -> Result<Vec<Atom>, String> {
    xi[1..]
        .iter()
        .map(|other| {
            let r = crate::sym::numerator(&(&xi[0] - other)).expand();
            let lc = leading_coefficient(&r, "abar")?;
            Ok(simplify(&(r / lc)))
        })
        .collect()
}

/// The solution set of two residuals that are linear in X = ā³ and
/// Y = δ̄ ā, for fixed (s, ρ): X(s) and Y(s). Then the whole curve of the
/// model is explicit in s.
#[derive(Clone, Debug)]
pub struct Branch {
    /// ā³ as a function of s (and ρ, η).
    pub abar_cubed: Atom,
    /// δ̄ ā as a function of s (and ρ, η).
    pub dbar_abar: Atom,
}

/// Try the parametrisation of [`Branch`]; `None` when a residual is not
/// linear in (ā³, δ̄ā).
pub fn branch(res: &[Atom]) -> Option<Branch> {
    if res.len() != 2 {
        return None;
    }
    let lin: Vec<Atom> = res
        .iter()
        .map(|r| {
            let e = subs(&subs(r, "dbar", &ex("YY/abar")), "abar", &ex("XX^(1/3)"));
            simplify(&e)
        })
        .collect();
    if lin
        .iter()
        .any(|e| e.contains_symbol(symbolica::symbol!("abar")))
    {
        return None;
    }
    let x_of_y = solve_linear(&lin[0], "XX")?;
    let y = solve_linear(&subs(&lin[1], "XX", &x_of_y), "YY")?;
    let x = simplify(&subs(&x_of_y, "YY", &y));
    if !is_zero(&simplify(&subs_all(
        &lin[0],
        &[("XX", x.clone()), ("YY", y.clone())],
    ))) {
        return None;
    }
    Some(Branch {
        abar_cubed: x,
        dbar_abar: y,
    })
}

/// The solution set at fixed (s, ρ) of two residuals that depend on ā and
/// δ̄ only through X = ā³ and Y = δ̄ā, each of the form c_k + X^d h_k(Y/X)
/// with the same d (for a linear closure d = 1, for the energy closure the
/// residuals are quadratic forms in (X, Y) plus a constant, d = 2). With
/// t = Y/X, eliminating X gives the polynomial P(t) = c₂h₁(t) − c₁h₂(t);
/// each root t gives X^d = −c₁/h₁(t) and Y = tX.
#[derive(Clone, Debug)]
pub struct RatioBranch {
    /// d.
    pub degree: u32,
    /// Coefficients of P(t), constant first, in (s, ρ).
    pub poly_t: Vec<Atom>,
    /// X^d as a function of (t, s, ρ).
    pub x_pow: Atom,
}

/// Try the parametrisation of [`RatioBranch`].
pub fn ratio_branch(res: &[Atom]) -> Result<RatioBranch, String> {
    if res.len() != 2 {
        return Err("not two residuals".into());
    }
    let mut parts = Vec::new();
    let mut degree = None;
    for r in res {
        let e = simplify(&subs(
            &subs(r, "dbar", &ex("YY/abar")),
            "abar",
            &ex("XX^(1/3)"),
        ));
        if e.contains_symbol(symbolica::symbol!("abar")) {
            return Err(
                "a residual depends on abar other than through abar^3 and dbar*abar".into(),
            );
        }
        let (num, den) = crate::sym::num_den(&e);
        if den.contains_symbol(symbolica::symbol!("XX"))
            || den.contains_symbol(symbolica::symbol!("YY"))
        {
            return Err("a residual is not polynomial in (abar^3, dbar*abar)".into());
        }
        let n = subs(&num, "YY", &ex("tt*XX")).expand();
        let deg = degree_in(&n, "XX", 8).ok_or("degree in abar^3 too high")?;
        let coeff = |k: usize| crate::sym::poly_coeff(&n, "XX", k as u32, "zz", 0);
        for k in 1..deg {
            if !is_zero(&coeff(k)) {
                return Err(format!("a residual has a term (abar^3)^{k} between the constant and the top degree {deg}"));
            }
        }
        if *degree.get_or_insert(deg) != deg {
            return Err("the residuals have different degrees in (abar^3, dbar*abar)".into());
        }
        parts.push((simplify(&(coeff(0) / &den)), simplify(&(coeff(deg) / &den))));
    }
    let degree = degree.expect("two residuals") as u32;
    let ((c1, h1), (c2, h2)) = (&parts[0], &parts[1]);
    let p = crate::sym::numerator(&simplify(&(c2 * h1 - c1 * h2))).expand();
    let dt = degree_in(&p, "tt", 8).ok_or("degree in t too high")?;
    let poly_t = (0..=dt as u32)
        .map(|k| crate::sym::poly_coeff(&p, "tt", k, "zz", 0))
        .collect();
    let x_pow = simplify(&subs(&(-c1 / h1), "tt", &ex("t")));
    let poly_t = poly_t;
    Ok(RatioBranch {
        degree,
        poly_t,
        x_pow,
    })
}
