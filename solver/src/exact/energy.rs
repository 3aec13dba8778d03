//! The Hessian of the potential energy at a held force, bordered by δ̄:
//! what decides whether a state is stable (`exact::stability`).
//!
//! In the units (17) the potential of the paper's Section 2 is, up to the
//! factor 2ΔγL², Π̄ = ∫ω |∇p̄|² dA − |ω|, p̄ = 0 on ∂ω only (any contour);
//! its shape derivative is dΠ̄ = ∮ ((∂p̄/∂ν)² − 1) V ds (Hadamard; V the
//! normal velocity of the contour), and ∂Π̄/∂δ̄ = 2F̄ at a fixed contour.
//! Its second derivatives follow from the linearisation of ∂p̄/∂ν
//! (`exact::linear`). The potential's value and gradient at a held force,
//! which the descent of the loading path lowers, are that study's
//! (`studies::potential`).
//!
//! Owns: `Exact::bordered_hessian`. May use: `exact` (the contour, the
//! grid), `exact::linear`, nalgebra.

use super::Exact;
use nalgebra::{Complex, DMatrix, DVector};

impl Exact {
    /// The Hessian of Π̄ − 2F̄δ̄ in u = (coefficients, δ̄) at u, bordered by
    /// δ̄ (∂²/∂u∂δ̄ = 2∂F̄/∂u, ∂²/∂δ̄² = 2∂F̄/∂δ̄), from the linearisation
    /// of ∂p̄/∂ν; not symmetrised. `None` where the system is singular.
    pub(crate) fn bordered_hessian(&self, u: &DVector<f64>) -> Option<DMatrix<f64>> {
        let m = self.truncation.coefficients();
        let mult = &self.grid.multipliers;
        let lin = self.linear(u)?;
        let samples = self.contour_of(u).samples(&self.grid);
        let n = self.grid.len();
        let h = 2.0 * std::f64::consts::PI / n as f64;
        // ∂Π̄/∂u_k = Σ_i ((∂p̄/∂ν)² − 1) Re(e_k(θ_i) · i conj z′_i) h at fixed δ̄
        // (V_k|z′| = Re(∂z/∂u_k ν̄)|z′| with ν = −i z′/|z′|), and its
        // derivative in u_l with δz′ = i m_l e_l,
        // summed as products over the points i: Σ_i a_ik ∂(∂p̄/∂ν)_i/∂u_l with
        // a_ik = 2 ∂p̄/∂ν_i V_k h, and Σ_i b_i Re(e_k conj e_l) m_l with
        // b_i = ((∂p̄/∂ν)² − 1) h (Re(e_k conj e_l) = Re e_k Re e_l + Im e_k Im e_l)
        let basis = &self.grid.basis;
        let rot: Vec<Complex<f64>> = samples
            .dz
            .iter()
            .map(|d| Complex::new(0.0, 1.0) * d.conj())
            .collect();
        let weights: Vec<f64> = lin.dn.iter().map(|dn| (dn * dn - 1.0) * h).collect();
        let a = DMatrix::from_fn(n, m, |i, k| 2.0 * lin.dn[i] * (basis[k][i] * rot[i]).re * h);
        let re = DMatrix::from_fn(n, m, |i, k| basis[k][i].re);
        let im = DMatrix::from_fn(n, m, |i, k| basis[k][i].im);
        let weighted = |e: &DMatrix<f64>| DMatrix::from_fn(n, m, |i, k| weights[i] * e[(i, k)]);
        let moving = a.transpose() * lin.d_dn.columns(0, m);
        let turning = weighted(&re).transpose() * &re + weighted(&im).transpose() * &im;
        let mut hess = DMatrix::zeros(m + 1, m + 1);
        for l in 0..m {
            for k in 0..m {
                hess[(k, l)] = moving[(k, l)] + turning[(k, l)] * mult[l];
            }
        }
        // the border: ∂²(Π̄ − 2F̄δ̄)/∂u∂δ̄ = 2∂F̄/∂u at fixed applied F̄, and
        // ∂²/∂δ̄² = 2∂F̄/∂δ̄
        for k in 0..=m {
            hess[(m, k)] = 2.0 * lin.d_force[k];
            hess[(k, m)] = 2.0 * lin.d_force[k];
        }
        Some(hess)
    }
}
