//! Folds of a model's solution curve, located by Newton's method on the
//! fold condition, for any model (written once against [`Model`]).
//!
//! The curve is r(ā, s; δ̄) = 0 (for the paper, (19)–(20)). Unknowns
//! z = (ā, s, δ̄); the extended system is r(z) = 0 and c(z) = 0 with
//! - displacement control (a turning point in δ̄): c = det ∂r/∂(ā, s);
//! - load control (a turning point in F̄, pull-off): c = det of the bordered
//!   matrix [∂r/∂(ā, s) ∂r/∂δ̄; ∂F̄/∂(ā, s) ∂F̄/∂δ̄], which vanishes where
//!   dF̄ = 0 along the curve;
//! - contact-size control (a turning point in ā): c = det of the bordered
//!   matrix with last row (1, 0, 0), which vanishes where dā = 0. For an energy model r is a row scaling of
//!   ∇Π̄ and F̄ = ∂Π̄/∂δ̄, so this is the Hessian of Π̄ in (ā, s, δ̄) up to
//!   positive factors: the load-controlled stability limit.
//!
//! The rows of r in the Jacobian of the extended system are analytic
//! (generated); the row of c is a central difference of the analytic
//! Jacobian (so second derivatives are not needed from the generator).
//!
//! Owns: [`FoldCondition`], `locate`. May use: `model`, `error`.

use crate::error::{Error, Result};
use crate::model::Model;
use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};
use serde::{Deserialize, Serialize};

/// Which quantity turns.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "cli", derive(clap::ValueEnum))]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum FoldCondition {
    /// A turning point in δ̄: the end of displacement control.
    Displacement,
    /// A turning point in F̄: the end of load control (pull-off).
    Load,
    /// A turning point in ā: the fold of the contact size.
    #[cfg_attr(feature = "cli", value(skip))]
    ContactSize,
}

/// [∂r/∂(ā, s) ∂r/∂δ̄; last row].
pub(crate) fn bordered(j: &Matrix2<f64>, d: &Vector2<f64>, last: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(
        j[(0, 0)],
        j[(0, 1)],
        d[0],
        j[(1, 0)],
        j[(1, 1)],
        d[1],
        last[0],
        last[1],
        last[2],
    )
}

fn condition(model: &dyn Model, rho: f64, z: Vector3<f64>, which: FoldCondition) -> f64 {
    let x = Vector2::new(z[0], z[1]);
    let (_, j) = model.residuals_and_jacobian(x, rho, z[2]);
    match which {
        FoldCondition::Displacement => j.determinant(),
        FoldCondition::Load => bordered(
            &j,
            &model.residuals_d_delta(x, rho, z[2]),
            &model.force_bar_gradient(x, rho, z[2]),
        )
        .determinant(),
        FoldCondition::ContactSize => bordered(
            &j,
            &model.residuals_d_delta(x, rho, z[2]),
            &Vector3::new(1.0, 0.0, 0.0),
        )
        .determinant(),
    }
}

/// Locate the fold of `which` near `guess` = (ā, s, δ̄) by Newton's method
/// on the extended system. Fails with [`Error::NoConvergence`] (saying
/// where) when it does not converge in 40 iterations.
pub(crate) fn locate(
    model: &dyn Model,
    rho: f64,
    guess: Vector3<f64>,
    which: FoldCondition,
) -> Result<Vector3<f64>> {
    locate_within(model, rho, guess, which, 1e-10)
}

/// [`locate`], accepting a Newton step that stagnates below `stagnation`
/// (relative) with the residuals at round-off: where the fold condition
/// itself is only known to round-off that large (near ρ = 1 the fold of a
/// nearly circular contact, whose condition is a difference of nearly
/// equal terms), the fold is located to that precision.
pub(crate) fn locate_within(
    model: &dyn Model,
    rho: f64,
    guess: Vector3<f64>,
    which: FoldCondition,
    stagnation: f64,
) -> Result<Vector3<f64>> {
    let mut z = guess;
    let mut last = f64::INFINITY;
    for _ in 0..40 {
        let x = Vector2::new(z[0], z[1]);
        let (r, j) = model.residuals_and_jacobian(x, rho, z[2]);
        let d = model.residuals_d_delta(x, rho, z[2]);
        let c = condition(model, rho, z, which);
        let mut grad = Vector3::zeros();
        for k in 0..3 {
            // the s-step stays below s = 1 (beyond it some models'
            // functions are not defined), except at s = 1 itself
            let mut h = 1e-6 * (1.0 + z[k].abs());
            if k == 1 && z[1] < 1.0 {
                h = h.min(0.5 * (1.0 - z[1]));
            }
            let mut zp = z;
            let mut zm = z;
            zp[k] += h;
            zm[k] -= h;
            grad[k] =
                (condition(model, rho, zp, which) - condition(model, rho, zm, which)) / (2.0 * h);
        }
        let m = bordered(&j, &d, &grad);
        let rhs = -Vector3::new(r[0], r[1], c);
        let Some(step) = m
            .lu()
            .solve(&rhs)
            .filter(|v| v.iter().all(|x| x.is_finite()))
        else {
            break;
        };
        // damp steps that would leave the domain
        let mut lambda = 1.0;
        while lambda > 1e-6 {
            let zn = z + step * lambda;
            if zn[0] > 0.0 && zn[1] > 0.0 && zn[1] <= 1.0 {
                break;
            }
            lambda *= 0.5;
        }
        z += step * lambda;
        let size = step.component_div(&z.map(|v| 1.0 + v.abs())).amax();
        let rn = r.norm() / model.residual_scale(z[0], z[2]);
        let converged = size < 1e-13 || (size < stagnation && size >= 0.5 * last && rn < 1e-12);
        if converged && condition(model, rho, z, which).is_finite() {
            return Ok(z);
        }
        last = size;
    }
    Err(Error::NoConvergence {
        iterations: 40,
        a_bar: z[0],
        s: z[1],
        residual: f64::NAN,
        context: format!(
            "the {} fold at rho = {rho}, delta = {}",
            match which {
                FoldCondition::Displacement => "displacement-control",
                FoldCondition::Load => "load-control",
                FoldCondition::ContactSize => "contact-size",
            },
            crate::error::rounded(z[2])
        ),
    })
}
