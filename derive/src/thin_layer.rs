//! Step 1 of the derivation: the thin-layer equation (2) with the gap (1).
//! The ansatz is substituted into Δp = m(φ − δ) and the coefficients of the
//! monomials xⁱ yʲ are matched, which gives system (6) for the ansatz (5).
//!
//! Owns: the gap (1) and the coefficient matching. May use: `sym`.

use crate::sym::{degree_in, diff, ex, is_zero, poly_coeff};
use symbolica::atom::Atom;

/// The gap (1): φ(x, y) = x²/(2R₁) + y²/(2R₂).
pub fn gap() -> Atom {
    ex("x^2/(2*R1) + y^2/(2*R2)")
}

/// One equation of the matched system: the coefficient of xⁱ yʲ in
/// Δp − m(φ − δ), which must vanish.
#[derive(Clone, Debug)]
pub struct LaplaceEquation {
    /// The exponents (i, j) of the monomial xⁱ yʲ.
    pub monomial: (u32, u32),
    /// The coefficient, an expression that must equal zero.
    pub residual: Atom,
}

/// Δp − m(φ − δ) for a pressure `p` in the symbols `x`, `y`: Eq. (2) moved to
/// one side.
pub fn thin_layer_residual(p: &Atom) -> Atom {
    let lap = diff(&diff(p, "x"), "x") + diff(&diff(p, "y"), "y");
    lap - ex("m") * (gap() - ex("delta"))
}

/// Match the coefficients of every monomial of the thin-layer residual:
/// system (6) for the ansatz (5). Monomials whose coefficient vanishes
/// identically are dropped.
pub fn laplace_equations(p: &Atom) -> Result<Vec<LaplaceEquation>, String> {
    let r = thin_layer_residual(p);
    let dx = degree_in(&r, "x", 24).ok_or("pressure degree in x too high")? as u32;
    let dy = degree_in(&r, "y", 24).ok_or("pressure degree in y too high")? as u32;
    let mut out = Vec::new();
    for total in 0..=(dx + dy) {
        for i in (0..=total.min(dx)).rev() {
            let j = total - i;
            if j > dy {
                continue;
            }
            let c = poly_coeff(&r, "x", i, "y", j);
            if !is_zero(&c) {
                out.push(LaplaceEquation {
                    monomial: (i, j),
                    residual: c,
                });
            }
        }
    }
    Ok(out)
}
