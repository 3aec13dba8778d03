//! The second route to a state of the layer: the elastic energy.
//!
//! A state of contact radius ā and any approach δ̄ (g = δ̄g₁ − g₂ of
//! `galerkin`, without the edge condition) stores the elastic energy
//! Ū = π∫₀ᵃ p̄ (δ̄ − r²/2) r dr = ½F̄δ̄ − 2∫₀ᵃ g t² dt in units mL⁸/R²
//! (∫p̄ r³ dr = (4/π)∫ g t² dt), a quadratic in δ̄ whose coefficients depend
//! on ā. The contact is in equilibrium where the energy released by its
//! edge at fixed approach equals the work of adhesion: ∂Ū/∂ā = πā at fixed
//! δ̄ (2πaΔγ in the units). The coefficients' derivatives in ā are exact
//! derivatives of the Galerkin solution (`galerkin::solve_with`), not
//! differences: differences of sixth order amplified the solution's
//! round-off, about 1e-9 at h/L = 0.01, to 4e-8 in the force. Of the
//! quadratic's two roots the one whose edge is in tension (g(ā) < 0) is the
//! adhesive state. Nothing here uses the stress-intensity factor.
//!
//! Owns: `by_energy`. May use: the parent (`layer`), `error`.

use super::{LayerState, Layers};
use crate::error::{rounded, Error, Result};
use nalgebra::DVector;

/// The state of contact radius ā found from the energy balance, with the
/// modes that resolve (L1) there.
pub(crate) fn by_energy(layers: &Layers, a_bar: f64) -> Result<LayerState> {
    let s = layers.resolved(a_bar)?;
    let modes = s.g1.len();
    let Some((d1, d2)) = &s.slopes else {
        unreachable!("solve_with was asked for the slopes")
    };
    // ∫₀ᵃ g dt = ā c₀ and ∫₀ᵃ g t² dt = ā³(c₀/3 + 2c₁/15), with their
    // derivatives in ā
    let a = a_bar;
    let moments = |c: &DVector<f64>, d: &DVector<f64>| {
        let q = c[0] / 3.0 + 2.0 * c[1] / 15.0;
        let dq = d[0] / 3.0 + 2.0 * d[1] / 15.0;
        (c[0] + a * d[0], 3.0 * a * a * q + a.powi(3) * dq)
    };
    let (di1, dm1) = moments(&s.g1, d1);
    let (di2, dm2) = moments(&s.g2, d2);
    // Ū = A δ̄² + B δ̄ + C, A = 2∫g₁, B = −2(∫g₂ + ∫g₁t²), C = 2∫g₂t²
    let (qa, qb, qc) = (
        2.0 * di1,
        -2.0 * (di2 + dm1),
        2.0 * dm2 - std::f64::consts::PI * a,
    );
    let (e1, e2) = s.edge();
    let (i1, i2) = s.integral();
    let no_state = || {
        Error::NoState(format!(
            "the layer's energy balance at a_bar = {} has no root with an edge in tension",
            rounded(a_bar)
        ))
    };
    let discriminant = qb * qb - 4.0 * qa * qc;
    if !(discriminant >= 0.0) || qa == 0.0 {
        return Err(no_state());
    }
    let root = discriminant.sqrt();
    // the two roots without cancellation
    let q = -0.5 * (qb + root.copysign(qb));
    let tension: Vec<f64> = [q / qa, qc / q]
        .into_iter()
        .filter(|d| d * e1 - e2 < 0.0)
        .collect();
    let &[delta_bar] = tension.as_slice() else {
        return Err(no_state());
    };
    Ok(LayerState {
        a_bar,
        delta_bar,
        force_bar: 4.0 * (delta_bar * i1 - i2),
        force_slope: f64::NAN,
        delta_slope: f64::NAN,
        modes,
        tail: s.tail(),
        coatings: layers.coatings(),
        coatings_are: super::COATINGS_ARE,
        verdicts: super::Verdicts {
            load: None,
            displacement: None,
        },
    })
}
