//! The potential at a held force of a contour that need not be a state:
//! what the descent of `studies::descent` lowers, with its gradient and
//! the metric of the normal motion.
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
//! vanishes there). Its Hessian, which the stability needs too, is the
//! engine's (`Exact::bordered_hessian`, `exact::energy`).
//!
//! Owns: [`AtForce`], [`at_force`]. May use: `exact` (the fields, the
//! contour, the grid, the gap), nalgebra.

use crate::exact::{fields, Exact, Fields};
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

/// Π̄ at u = (contour coefficients, δ̄); `None` where the contour's
/// boundary integral equation is singular (the tests' closed forms
/// hold the boundary form with it).
#[cfg(test)]
fn energy(ex: &Exact, u: &DVector<f64>) -> Option<f64> {
    let delta = u[ex.unknown_count() - 1];
    let c = ex.contour_of(u);
    let f = fields(&c, ex.gap_at(), delta, &ex.grid)?;
    Some(energy_of(ex, u, &f))
}

/// Π̄ at u from the fields already solved there.
fn energy_of(ex: &Exact, u: &DVector<f64>, f: &Fields) -> f64 {
    let delta = u[ex.unknown_count() - 1];
    let s = ex.contour_of(u).samples(&ex.grid);
    let h = 2.0 * std::f64::consts::PI / ex.grid.len() as f64;
    let mut sum = 0.0;
    for i in 0..ex.grid.len() {
        let (z, dz) = (s.z[i], s.dz[i]);
        let (x, y) = (z.re, z.im);
        let q = ex.gap_at().energy_potential(x, y, delta);
        let p = ex.gap_at().p(x, y, delta);
        sum += (-q * dz.im + p * f.normal_derivative[i] * dz.norm() - x * dz.im) * h;
    }
    sum
}

/// The contour of u (its δ̄ ignored) at the held force `force`: the
/// approach that gives it, the potential Π̄ − 2F̄₀δ̄, its gradient and
/// the metric; `None` where the contour's equation is singular or F̄
/// does not depend on δ̄.
pub(crate) fn at_force(ex: &Exact, u: &DVector<f64>, force: f64) -> Option<AtForce> {
    let id = ex.unknown_count() - 1;
    let c = ex.contour_of(u);
    // F̄ and ∂p̄/∂ν are affine in δ̄ at a fixed contour
    let f0 = fields(&c, ex.gap_at(), 0.0, &ex.grid)?;
    let f1 = fields(&c, ex.gap_at(), 1.0, &ex.grid)?;
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
    let potential = energy_of(ex, &at, &f) - 2.0 * force * delta;
    let s = c.samples(&ex.grid);
    let n = ex.grid.len();
    let m = id;
    let h = 2.0 * std::f64::consts::PI / n as f64;
    let i_unit = Complex::new(0.0, 1.0);
    // V_k|z′| = Re(e_k · i conj z′) (ν = −i z′/|z′|)
    let v = DMatrix::from_fn(n, m, |i, k| {
        (ex.grid.basis[k][i] * i_unit * s.dz[i].conj()).re
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
            let got = energy(&ex, &u).unwrap();
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
        let at = at_force(&ex, &u, force).unwrap();
        let m = ex.unknown_count() - 1;
        let check = fields(&ex.contour_of(&at.u), ex.gap_at(), at.u[m], &ex.grid).unwrap();
        assert!((check.force - force).abs() < 1e-11, "{}", check.force);
        for k in [0, 1, 2, 5] {
            let e = 1e-5;
            let mut up = u.clone();
            up[k] += e;
            let mut down = u.clone();
            down[k] -= e;
            let fd = (at_force(&ex, &up, force).unwrap().potential
                - at_force(&ex, &down, force).unwrap().potential)
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
