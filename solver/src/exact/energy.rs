//! The potential energy of a contour and its derivatives: what a contact
//! lowers when it moves, so what decides where it goes once a state is
//! lost (the descent of `studies::descent`) and whether a state is stable
//! (`exact::stability`).
//!
//! In the units (17) the potential of the paper's Section 2 is, up to the
//! factor 2ΔγL², Π̄ = ∫ω |∇p̄|² dA − |ω|, where p̄ solves Δp̄ = f,
//! f = φ̄ − δ̄, with p̄ = 0 on ∂ω only (any contour; (3)₂ is not imposed).
//! Its value, by Green's second identity with the gap's particular solution
//! P (ΔP = f) and p̄ = 0 on ∂ω:
//!
//!   ∫ω |∇p̄|² dA = −∫ω p̄ f dA = −∫ω P f dA + ∮ P ∂p̄/∂ν ds,
//!
//! with ∫ω P f dA = ∮ Q dY (∂Q/∂X = P f, `GapAt::energy_potential`) and
//! |ω| = ∮ X dY: boundary integrals on the grid, like F̄'s. Its shape
//! derivative is dΠ̄ = ∮ ((∂p̄/∂ν)² − 1) V ds (Hadamard; V the normal
//! velocity of the contour), and ∂Π̄/∂δ̄ = 2F̄ at a fixed contour.
//!
//! Under a held force F̄₀ the potential is Π̄ − 2F̄₀δ̄, stationary in δ̄
//! where F̄ = F̄₀; since F̄ is affine in δ̄ for a fixed contour, the
//! potential of a contour at F̄₀ ([`AtForce`]) takes that δ̄, and its
//! gradient in the contour coefficients is Π̄'s at that δ̄ (the δ̄ term
//! vanishes there).
//!
//! Owns: [`AtForce`], `Exact::energy`, `Exact::at_force`,
//! `Exact::bordered_hessian`. May use: `exact` (fields, contour, grid),
//! `exact::linear`, `exact::gap`, nalgebra.

// (the potential at a force serves the descent, which the command line asks)
#![cfg_attr(not(feature = "cli"), allow(dead_code))]

use super::{fields, Exact, Fields};
use nalgebra::{Complex, DMatrix, DVector};

/// A contour's potential at a held force.
#[derive(Clone, Debug)]
pub(crate) struct AtForce {
    /// The unknowns with the approach δ̄ at which F̄ is the held force.
    pub u: DVector<f64>,
    /// Π̄ − 2F̄₀δ̄ there.
    pub potential: f64,
    /// Its gradient in the contour coefficients: ∮((∂p̄/∂ν)² − 1)V_k ds.
    pub gradient: DVector<f64>,
    /// The metric of the normal motion: ∮ V_k V_l ds (the L² norm of the
    /// contour's normal velocity), the coefficients' mobility.
    pub metric: DMatrix<f64>,
}

impl Exact {
    /// Π̄ at u = (contour coefficients, δ̄); `None` where the contour's
    /// boundary integral equation is singular (the tests' closed forms
    /// hold the boundary form with it).
    #[cfg(test)]
    pub(crate) fn energy(&self, u: &DVector<f64>) -> Option<f64> {
        let delta = u[self.unknown_count() - 1];
        let c = self.contour_of(u);
        let f = fields(&c, &self.gap, delta, &self.grid)?;
        Some(self.energy_of(u, &f))
    }

    /// Π̄ at u from the fields already solved there.
    fn energy_of(&self, u: &DVector<f64>, f: &Fields) -> f64 {
        let delta = u[self.unknown_count() - 1];
        let s = self.contour_of(u).samples(&self.grid);
        let h = 2.0 * std::f64::consts::PI / self.grid.len() as f64;
        let mut sum = 0.0;
        for i in 0..self.grid.len() {
            let (z, dz) = (s.z[i], s.dz[i]);
            let (x, y) = (z.re, z.im);
            let q = self.gap.energy_potential(x, y, delta);
            let p = self.gap.p(x, y, delta);
            sum += (-q * dz.im + p * f.normal_derivative[i] * dz.norm() - x * dz.im) * h;
        }
        sum
    }

    /// The contour of u (its δ̄ ignored) at the held force `force`: the
    /// approach that gives it, the potential Π̄ − 2F̄₀δ̄, its gradient and
    /// the metric; `None` where the contour's equation is singular or F̄
    /// does not depend on δ̄.
    pub(crate) fn at_force(&self, u: &DVector<f64>, force: f64) -> Option<AtForce> {
        let id = self.unknown_count() - 1;
        let c = self.contour_of(u);
        // F̄ and ∂p̄/∂ν are affine in δ̄ at a fixed contour
        let f0 = fields(&c, &self.gap, 0.0, &self.grid)?;
        let f1 = fields(&c, &self.gap, 1.0, &self.grid)?;
        let slope = f1.force - f0.force;
        if !(slope.abs() > 0.0) {
            return None;
        }
        let delta = (force - f0.force) / slope;
        let f = Fields {
            normal_derivative: f0
                .normal_derivative
                .iter()
                .zip(&f1.normal_derivative)
                .map(|(a, b)| a + delta * (b - a))
                .collect(),
            force,
        };
        let mut at = u.clone();
        at[id] = delta;
        let potential = self.energy_of(&at, &f) - 2.0 * force * delta;
        let s = c.samples(&self.grid);
        let n = self.grid.len();
        let m = id;
        let h = 2.0 * std::f64::consts::PI / n as f64;
        let i_unit = Complex::new(0.0, 1.0);
        // V_k|z′| = Re(e_k · i conj z′) (ν = −i z′/|z′|)
        let v = DMatrix::from_fn(n, m, |i, k| {
            (self.grid.basis[k][i] * i_unit * s.dz[i].conj()).re
        });
        let weights =
            DVector::from_iterator(n, f.normal_derivative.iter().map(|dn| (dn * dn - 1.0) * h));
        let gradient = v.transpose() * weights;
        let scaled = DMatrix::from_fn(n, m, |i, k| v[(i, k)] * h / s.dz[i].norm());
        let metric = v.transpose() * scaled;
        Some(AtForce {
            u: at,
            potential,
            gradient,
            metric,
        })
    }

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::{Contour, Truncation};

    /// At ρ = 1 on a circle of radius ā and any δ̄, p̄ = r⁴/32 − δ̄r²/4 + C
    /// vanishes at ā, and ∫|∇p̄|² dA = 2π(ā⁸/512 − δ̄ā⁶/48 + δ̄²ā⁴/16) by
    /// the radial integral: the boundary form must give that, off the
    /// states as on them.
    #[test]
    fn the_energy_of_a_circle_is_its_closed_form() {
        let ex = Exact::new(1.0, Truncation::with_modes(8)).unwrap();
        let pi = std::f64::consts::PI;
        for (a, d) in [(1.0, 0.3), (2.289, -0.5), (3.0, 2.0), (2.5, 1.2)] {
            let u = ex.unknowns_of(&Contour::ellipse(a, a, 8), d);
            let want =
                2.0 * pi * (a.powi(8) / 512.0 - d * a.powi(6) / 48.0 + d * d * a.powi(4) / 16.0)
                    - pi * a * a;
            let got = ex.energy(&u).unwrap();
            assert!(
                (got - want).abs() < 1e-12 * want.abs().max(1.0),
                "a = {a}, d = {d}: {got} vs {want}"
            );
        }
    }

    /// On an ellipse with a mode-4 dent at ρ = 0.5 (no state), the
    /// potential at a held force changes along a direction as its gradient
    /// (the Hadamard formula) says: central differences of the boundary
    /// form against the shape derivative, two independent routes; and the
    /// approach it takes gives the held force.
    #[test]
    fn the_potential_at_a_force_has_the_hadamard_gradient() {
        let ex = Exact::new(0.5, Truncation::with_modes(12)).unwrap();
        let mut c = Contour::ellipse(2.6, 1.9, 12);
        c.b[1] = 0.05;
        let u = ex.unknowns_of(&c, 1.0);
        let force = -2.0;
        let at = ex.at_force(&u, force).unwrap();
        let m = ex.unknown_count() - 1;
        let check = fields(&ex.contour_of(&at.u), &ex.gap, at.u[m], &ex.grid).unwrap();
        assert!((check.force - force).abs() < 1e-11, "{}", check.force);
        for k in [0, 1, 2, 5] {
            let e = 1e-5;
            let mut up = u.clone();
            up[k] += e;
            let mut down = u.clone();
            down[k] -= e;
            let fd = (ex.at_force(&up, force).unwrap().potential
                - ex.at_force(&down, force).unwrap().potential)
                / (2.0 * e);
            assert!(
                (fd - at.gradient[k]).abs() < 1e-7 * at.gradient.amax(),
                "k = {k}: {fd} vs {}",
                at.gradient[k]
            );
        }
        // the metric is the normal motion's: positive definite
        assert!(at.metric.clone().cholesky().is_some());
    }
}
