//! The one interface through which the solver uses every model: residuals
//! of the model's closure and their Jacobian side by side (for the paper's
//! model, (19)–(20)), ∂/∂δ̄, F̄ (for the paper, the derived form of (18))
//! with its gradient, the explicit branch at fixed (s, ρ), ∂p/∂ν on Γ₀,
//! the pressure (5) and its parameters, and, as data, which closed-form
//! limits and which energy the model has. The implementations are generated
//! (`crate::generated::*`, one value per model); nothing here names a
//! model's formulas.
//!
//! Owns: [`Model`], [`ModelInfo`], [`ClosureKind`], [`PressureParameters`],
//! and numeric helpers the generated implementations share
//! (`real_roots`, `contour_spread`, Brent's minimisation). May use:
//! nalgebra; not `generated`, which implements [`Model`] and lists the
//! models (`ModelId`).

use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};
use serde::{Deserialize, Serialize};

/// How a model imposes the second boundary condition (3)₂.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum ClosureKind {
    /// The maximum of ∂p/∂ν along Γ₀ equals √(2mΔγ) (the paper's (13)).
    Max,
    /// ∂p/∂ν = √(2mΔγ) at given contour points.
    AtPoint,
    /// Stationary total potential energy Π = U − Δγ·πab (Ritz).
    Energy,
}

/// What a model is and what it has, as data (generated).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModelInfo {
    /// Its name, as `thinjkr models` lists it (its `ModelId`'s).
    pub name: &'static str,
    /// One line.
    pub title: &'static str,
    /// The closure of (3)₂.
    pub closure: ClosureKind,
    /// The closure in words.
    pub closure_note: &'static str,
    /// The degree d of the residuals in (ā³, δ̄ā): 1 for collocation
    /// closures, 2 for the energy closure.
    pub residual_degree: u32,
    /// Whether the non-adhesive relation ρ(s) (for the paper, behind (29)) was derived.
    pub has_non_adhesive_limit: bool,
    /// Whether the axisymmetric solution (22)–(25) was derived.
    pub has_axisymmetric_limit: bool,
    /// Whether the zero-force relation ρ(s) (for the paper, (28)) was derived.
    pub has_zero_force_limit: bool,
    /// Whether the near-circular expansion (Appendix) was derived.
    pub has_near_circular_limit: bool,
    /// Why a limit is missing, if one is.
    pub missing_limits: &'static str,
}

/// The pressure (5) of a state: p̄₀ = p₀/(√(2mΔγ) L), the shape parameters
/// times L² (for (5): A L², B L²) and ξ of (10).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PressureParameters {
    /// p̄₀.
    pub p0: f64,
    /// The shape parameters times L².
    pub shape: [f64; 2],
    /// ξ.
    pub xi: f64,
}

/// Up to two points (ā, δ̄) of the model's solution set at one (s, ρ).
pub(crate) type BranchPoints = [Option<(f64, f64)>; 2];

/// One generated model, in the dimensionless variables of (17). The
/// unknowns are x = (ā, s) at given (ρ, δ̄).
pub trait Model: Send + Sync + 'static {
    /// What the model is and has.
    fn info(&self) -> &'static ModelInfo;
    /// Residuals of the closure and their Jacobian ∂r/∂(ā, s), side by side.
    fn residuals_and_jacobian(
        &self,
        x: Vector2<f64>,
        rho: f64,
        delta_bar: f64,
    ) -> (Vector2<f64>, Matrix2<f64>);
    /// ∂r/∂δ̄.
    fn residuals_d_delta(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> Vector2<f64>;
    /// F̄ = F/(2R₁Δγ).
    fn force_bar(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> f64;
    /// ∂F̄/∂(ā, s, δ̄).
    fn force_bar_gradient(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> Vector3<f64>;
    /// The solution set at fixed (s, ρ), explicit: up to two (ā, δ̄).
    fn branch(&self, s: f64, rho: f64) -> BranchPoints;
    /// ∂p̄/∂ν on Γ₀ at u = sin²t, in units of √(2mΔγ) (1 where (3)₂ holds).
    fn normal_derivative(&self, x: Vector2<f64>, rho: f64, delta_bar: f64, u: f64) -> f64;
    /// ∂p̄/∂ν at the two apexes, u = 0 and u = 1 (one evaluation of what
    /// they share where the model has it).
    fn edge_slopes(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> [f64; 2] {
        [
            self.normal_derivative(x, rho, delta_bar, 0.0),
            self.normal_derivative(x, rho, delta_bar, 1.0),
        ]
    }
    /// p̄₀, the shape parameters and ξ.
    fn pressure_parameters(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> PressureParameters;
    /// p̄ at (x̄, ȳ) inside the ellipse (7).
    fn pressure(&self, px: f64, py: f64, x: Vector2<f64>, rho: f64, delta_bar: f64) -> f64;
    /// (max − min)/min of ∂p/∂ν along Γ₀: quantity (14).
    fn bc_error(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> f64;
    /// Π̄, for models with an energy.
    fn potential(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> Option<f64>;
    /// The Hessian of Π̄ in (ā, s, δ̄), for models with an energy.
    fn potential_hessian(&self, x: Vector2<f64>, rho: f64, delta_bar: f64) -> Option<Matrix3<f64>>;
    /// ρ(s) in the non-adhesive limit, if derived.
    fn non_adhesive_rho(&self, s: f64) -> Option<f64>;
    /// (δ̄, F̄) at ρ = 1 for contact radius ā, if derived: (22)–(25).
    fn axisymmetric(&self, a_bar: f64) -> Option<(f64, f64)>;
    /// ρ(s) at zero force, if derived: (28).
    fn zero_force_rho(&self, s: f64) -> Option<f64>;
    /// ds/dμ at μ = 0 (Appendix, (35)–(36)), if derived.
    fn near_circular_ds_dmu(&self, a0: f64) -> Option<f64>;
    /// ā at the minimum of F̄ on the axisymmetric solution (Section 4), if
    /// derived in closed form.
    fn axisymmetric_critical_a(&self) -> Option<f64>;

    /// The scale of the residuals at (ā, δ̄): (1 + ā³ + |δ̄ā|)^d.
    fn residual_scale(&self, a_bar: f64, delta_bar: f64) -> f64 {
        let m = 1.0 + a_bar.powi(3) + (delta_bar * a_bar).abs();
        m.powi(self.info().residual_degree as i32)
    }
}

/// The real roots of c₀ + c₁t + c₂t² (c₂ may vanish), smallest first, by
/// the cancellation-free form of the quadratic formula.
pub(crate) fn real_roots(c: &[f64]) -> [Option<f64>; 2] {
    let (c0, c1, c2) = (
        c[0],
        c.get(1).copied().unwrap_or(0.0),
        c.get(2).copied().unwrap_or(0.0),
    );
    let scale = c0.abs().max(c1.abs()).max(c2.abs());
    if !(scale.is_finite()) || scale == 0.0 {
        return [None, None];
    }
    if c2.abs() <= 1e-300 * scale || c2 == 0.0 {
        return if c1 != 0.0 {
            [Some(-c0 / c1), None]
        } else {
            [None, None]
        };
    }
    let disc = c1 * c1 - 4.0 * c2 * c0;
    if disc < 0.0 {
        return [None, None];
    }
    let q = -0.5 * (c1 + c1.signum() * disc.sqrt());
    let (r1, r2) = if q != 0.0 {
        (q / c2, c0 / q)
    } else {
        (0.0, 0.0)
    };
    let (lo, hi) = if r1 <= r2 { (r1, r2) } else { (r2, r1) };
    [Some(lo), Some(hi)]
}

/// (max − min)/min of `g` on u ∈ [0, 1]: sampled at 65 points, each
/// extremum refined by Brent's method on its neighbouring interval (an
/// extremum of ∂p/∂ν narrower than 1/32 in u would need more samples; the
/// contour values of the ansätze generated so far have at most one
/// interior extremum).
pub(crate) fn contour_spread(g: impl Fn(f64) -> f64) -> f64 {
    let n = 64;
    let v: Vec<f64> = (0..=n).map(|k| g(k as f64 / n as f64)).collect();
    let refine = |k: usize, sign: f64| -> f64 {
        let (lo, hi) = (
            (k.max(1) - 1) as f64 / n as f64,
            ((k + 1).min(n)) as f64 / n as f64,
        );
        // Brent's method for the minimum of −sign·g
        let best = g(brent_minimum(|u| -sign * g(u), lo, hi, 1e-12));
        if sign > 0.0 {
            best.max(v[k])
        } else {
            best.min(v[k])
        }
    };
    let kmax = (0..=n).max_by(|&i, &j| v[i].total_cmp(&v[j])).unwrap_or(0);
    let kmin = (0..=n).min_by(|&i, &j| v[i].total_cmp(&v[j])).unwrap_or(0);
    let (max, min) = (refine(kmax, 1.0), refine(kmin, -1.0));
    (max - min) / min
}

/// Brent's method for the minimum of `f` on [a, b] (parabolic steps
/// safeguarded by golden sections), to `tol` absolute in x.
pub(crate) fn brent_minimum(f: impl Fn(f64) -> f64, a: f64, b: f64, tol: f64) -> f64 {
    const CGOLD: f64 = 0.381_966_011_250_105_1;
    let (mut a, mut b) = (a.min(b), a.max(b));
    let mut x = a + CGOLD * (b - a);
    let (mut w, mut v) = (x, x);
    let mut fx = f(x);
    let (mut fw, mut fv) = (fx, fx);
    let (mut d, mut e) = (0.0f64, 0.0f64);
    for _ in 0..100 {
        let xm = 0.5 * (a + b);
        let tol2 = 2.0 * tol;
        if (x - xm).abs() <= tol2 - 0.5 * (b - a) {
            break;
        }
        let mut parabolic = false;
        if e.abs() > tol {
            let r = (x - w) * (fx - fv);
            let mut q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            } else {
                q = -q;
            }
            if p.abs() < (0.5 * q * e).abs() && p > q * (a - x) && p < q * (b - x) {
                e = d;
                d = p / q;
                let u = x + d;
                if u - a < tol2 || b - u < tol2 {
                    d = tol.copysign(xm - x);
                }
                parabolic = true;
            }
        }
        if !parabolic {
            e = if x >= xm { a - x } else { b - x };
            d = CGOLD * e;
        }
        let u = if d.abs() >= tol {
            x + d
        } else {
            x + tol.copysign(d)
        };
        let fu = f(u);
        if fu <= fx {
            if u >= x {
                a = x;
            } else {
                b = x;
            }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x {
                a = u;
            } else {
                b = u;
            }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    x
}

#[cfg(test)]
mod tests {
    use super::contour_spread;

    /// The spread of a contour-like value (linear times the square root of
    /// linear in u, as ∂p/∂ν of the ansatz (5) on the ellipse), with an
    /// interior maximum, against 10⁶ + 1 samples.
    #[test]
    fn contour_spread_finds_an_interior_extremum() {
        let g = |u: f64| (1.0 + 0.9 * u) * (2.0 - 1.7 * u).sqrt();
        let n = 1_000_000;
        let (mut max, mut min) = (f64::NEG_INFINITY, f64::INFINITY);
        for k in 0..=n {
            let v = g(k as f64 / n as f64);
            max = max.max(v);
            min = min.min(v);
        }
        let dense = (max - min) / min;
        let spread = contour_spread(g);
        // the dense samples miss the maximum by at most g''·(0.5e-6)²
        assert!(
            spread >= dense && spread - dense < 1e-11,
            "{spread} vs {dense}"
        );
    }
}
