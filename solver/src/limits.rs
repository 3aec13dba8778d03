//! Closed-form limits of a model, from its generated code where its
//! derivation produced them: the axisymmetric solution (22)–(25) and its
//! critical point; the non-adhesive aspect ratio (29); the zero-force
//! relation (28) and the paper's approximation (30); the near-circular
//! asymptotics of the Appendix, (35)–(37). A limit the model lacks is an
//! [`Error::Unavailable`] that says why.
//!
//! Owns: these functions. May use: `generated` (`ModelId`), `contact`, `model`, `error`.

use crate::contact::{bisect, Contact};
use crate::error::{check_range, Error, Result};
use crate::generated::ModelId;

fn unavailable(model: ModelId, what: &str) -> Error {
    Error::Unavailable {
        model: model.name(),
        what: what.to_string(),
        why: model.model().info().missing_limits,
    }
}

/// The axisymmetric state (ρ = 1) at contact radius ā: (δ̄, F̄), (25) (for
/// the paper's model the derived forms: the printed (25)₁ has 2^(4/3)/ā where
/// the derivation gives 2/ā; see docs/errata.md).
pub fn axisymmetric(model: ModelId, a: f64) -> Result<(f64, f64)> {
    check_range("a", a, a > 0.0, "(0, ∞)")?;
    model
        .model()
        .axisymmetric(a)
        .ok_or_else(|| unavailable(model, "axisymmetric solution (22)-(25)"))
}

/// The axisymmetric critical point (Section 4), the minimum of F̄(ā) at
/// ρ = 1: (ā_c, F̄_c, δ̄_c); for the paper's model (12^(1/3), −3π/2, 12^(−1/3)).
pub fn axisymmetric_critical(model: ModelId) -> Result<(f64, f64, f64)> {
    let st = Contact::with_model(model, 1.0)?.pull_off_load()?.state;
    Ok((st.a_bar, st.force_bar, st.delta_bar))
}

/// The non-adhesive aspect ratio s∞(ρ): for the paper's model the root of
/// the derived relation ρ = s²(3s² + 1)/(s² + 3), i.e. (29).
#[cfg_attr(not(feature = "figures"), allow(dead_code))]
pub(crate) fn non_adhesive_s(model: ModelId, rho: f64) -> Result<f64> {
    Contact::with_model(model, rho)?.s_infinity()
}

/// The zero-force aspect ratio: the root of (28) for `rho` ∈ (0, 1].
pub fn zero_force_s(model: ModelId, rho: f64) -> Result<f64> {
    check_range("rho", rho, rho > 0.0 && rho <= 1.0, "(0, 1]")?;
    let m = model.model();
    if !m.info().has_zero_force_limit {
        return Err(unavailable(model, "zero-force relation (28)"));
    }
    if rho == 1.0 {
        return Ok(1.0);
    }
    bisect(|s| m.zero_force_rho(s).unwrap_or(f64::NAN) - rho, 1e-9, 1.0)
}

/// The paper's approximation (30) to the root of (28) (a printed formula,
/// not generated).
pub fn zero_force_s_approx(rho: f64) -> f64 {
    let c = 0.3 * (1.0 - rho);
    ((c * c + rho).sqrt() - c).sqrt()
}

/// Near-circular asymptotics (Appendix): for ρ = (1 − μ)/(1 + μ), at the
/// axisymmetric contact radius ā₀, s ≈ 1 + μ ds/dμ with ds/dμ = −2a₂/a₀ and
/// a₂ from (36). Returns ds/dμ.
pub fn near_circular_ds_dmu(model: ModelId, a0: f64) -> Result<f64> {
    model
        .model()
        .near_circular_ds_dmu(a0)
        .ok_or_else(|| unavailable(model, "near-circular expansion (Appendix)"))
}
