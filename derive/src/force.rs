//! Step 2 of the derivation: the contact force (8), the integral of the
//! pressure over the elliptical domain ω₀ bounded by (7).
//!
//! A general rule integrates each monomial, so that any polynomial ansatz
//! integrates: over x²/a² + y²/b² ≤ 1,
//! ∫∫ x^(2i) y^(2j) dx dy = π a^(2i+1) b^(2j+1) (2i)! (2j)! / (4^(i+j) i! j! (i+j+1)!),
//! and monomials with an odd exponent integrate to zero.
//!
//! Owns: the monomial rule. May use: `sym`.

use crate::sym::{degree_in, ex, is_zero, poly_coeff, simplify};
use symbolica::atom::Atom;

fn factorial(n: u32) -> i64 {
    (1..=n as i64).product()
}

/// ∫∫ over the ellipse (7) of xⁱ yʲ.
pub fn ellipse_moment(i: u32, j: u32) -> Atom {
    if i % 2 == 1 || j % 2 == 1 {
        return Atom::num(0);
    }
    let (k, l) = (i / 2, j / 2);
    let num = factorial(2 * k) * factorial(2 * l);
    let den = 4_i64.pow(k + l) * factorial(k) * factorial(l) * factorial(k + l + 1);
    ex(&format!("pi*a^{}*b^{}*{num}/{den}", i + 1, j + 1))
}

/// The integral of a polynomial in `x`, `y` over the ellipse (7): for the
/// ansatz (5) this is the force (8).
pub fn integrate_over_ellipse(p: &Atom) -> Result<Atom, String> {
    let dx = degree_in(p, "x", 24).ok_or("degree in x too high")? as u32;
    let dy = degree_in(p, "y", 24).ok_or("degree in y too high")? as u32;
    let mut total = Atom::num(0);
    for i in 0..=dx {
        for j in 0..=dy {
            let c = poly_coeff(p, "x", i, "y", j);
            if !is_zero(&c) {
                total = total + c * ellipse_moment(i, j);
            }
        }
    }
    Ok(simplify(&total))
}
