//! Closed-form limits of the model, from generated code: the exact
//! axisymmetric solution (22)–(25) and its critical point; the non-adhesive
//! aspect ratio (29); the zero-force relation (28) and its approximation
//! (30); the near-circular asymptotics of the Appendix, (35)–(37).
//!
//! Owns: these functions. May use: `generated`, `error`.

use crate::contact::bisect;
use crate::error::{check_range, Result};
use crate::generated::paper as g;

/// The axisymmetric state (ρ = 1) at contact radius ā: (δ̄, F̄), derived
/// forms of (25) (the printed (25)₁ has 2^(4/3)/ā where the derivation gives
/// 2/ā; see docs/errata.md).
pub fn axisymmetric(a: f64) -> (f64, f64) {
    (g::axisymmetric_dbar(a), g::axisymmetric_force_bar(a))
}

/// The axisymmetric critical point (Section 4): (ā_c, F̄_c, δ̄_c) =
/// (12^(1/3), −3π/2, 12^(−1/3)).
pub fn axisymmetric_critical() -> (f64, f64, f64) {
    let a = 12f64.cbrt();
    let (d, f) = axisymmetric(a);
    (a, f, d)
}

/// The non-adhesive aspect ratio s∞(ρ): the root of the derived relation
/// ρ = s²(3s² + 1)/(s² + 3), i.e. (29).
pub fn non_adhesive_s(rho: f64) -> f64 {
    if rho >= 1.0 {
        return 1.0;
    }
    bisect(|s| g::non_adhesive_rho(s) - rho, 1e-9, 1.0).unwrap_or(f64::NAN)
}

/// The zero-force aspect ratio: the root of (28) for `rho` ∈ (0, 1].
pub fn zero_force_s(rho: f64) -> Result<f64> {
    check_range("rho", rho, rho > 0.0 && rho <= 1.0, "(0, 1]")?;
    if rho == 1.0 {
        return Ok(1.0);
    }
    bisect(|s| g::zero_force_rho(s) - rho, 1e-9, 1.0)
}

/// The approximation (30) to the root of (28).
pub fn zero_force_s_approx(rho: f64) -> f64 {
    let c = 0.3 * (1.0 - rho);
    ((c * c + rho).sqrt() - c).sqrt()
}

/// Near-circular asymptotics (Appendix): for ρ = (1 − μ)/(1 + μ), at the
/// axisymmetric contact radius ā₀, s ≈ 1 + μ ds/dμ with ds/dμ = −2a₂/a₀ and
/// a₂ from (36). Returns ds/dμ.
pub fn near_circular_ds_dmu(a0: f64) -> f64 {
    g::near_circular_ds_dmu(a0)
}
