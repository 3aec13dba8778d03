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
