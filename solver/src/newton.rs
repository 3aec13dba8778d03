//! Damped Newton's method for a model's two residuals in x = (ā, s) (for
//! the paper's model, (19)–(20)), with a backtracking line search on ‖r‖²
//! that also keeps the iterate inside the domain ā > 0, 0 < s ≤ 1. Written
//! once for every model.
//!
//! Owns: [`NewtonConfig`], [`solve`], [`solve_within`]. May use: `error`, nalgebra.

use crate::error::{Error, Result};
use nalgebra::{Matrix2, Vector2};

/// Controls of Newton's method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NewtonConfig {
    /// Converged when the scaled residual norm is below this.
    pub tolerance: f64,
    /// Iteration limit.
    pub max_iterations: usize,
    /// Smallest line-search step before giving up.
    pub min_step: f64,
    /// Also converged when the full Newton step is below this (relative to
    /// 1 + |x|), or a Newton iteration no longer halves the residual, while
    /// the scaled residual is below `stall_residual`: the residual has then
    /// reached the round-off floor of its f64 evaluation (quadratic
    /// convergence would halve it many times over).
    pub step_tolerance: f64,
    /// See `step_tolerance`.
    pub stall_residual: f64,
}

impl Default for NewtonConfig {
    fn default() -> Self {
        NewtonConfig {
            tolerance: 1e-12,
            max_iterations: 60,
            min_step: 1e-10,
            step_tolerance: 1e-13,
            stall_residual: 1e-8,
        }
    }
}

/// A converged solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solution {
    /// ā.
    pub a_bar: f64,
    /// s.
    pub s: f64,
    /// Iterations used.
    pub iterations: usize,
    /// Final residual norm (scaled by 1 + ā³).
    pub residual: f64,
}

/// Solve `f(x) = 0`, x = (ā, s), from `start`, where `f` returns the
/// residuals and the Jacobian ∂r/∂(ā, s), and `scale(ā)` the magnitude of
/// the residuals' terms (the model's `residual_scale`): the converged norm
/// is ‖r‖/scale.
pub fn solve(
    f: impl Fn(Vector2<f64>) -> (Vector2<f64>, Matrix2<f64>),
    scale: impl Fn(f64) -> f64,
    start: Vector2<f64>,
    config: &NewtonConfig,
    context: &str,
) -> Result<Solution> {
    solve_within(f, scale, start, config, context, |_| true)
}

/// [`solve`], with the line search also rejecting iterates where
/// `admissible` is false (a solution set with two nearby sheets, such as
/// the adhesive and compressive-edge roots of a quadratic closure at large
/// loads, is then kept on the start's sheet).
pub fn solve_within(
    f: impl Fn(Vector2<f64>) -> (Vector2<f64>, Matrix2<f64>),
    scale: impl Fn(f64) -> f64,
    start: Vector2<f64>,
    config: &NewtonConfig,
    context: &str,
    admissible: impl Fn(Vector2<f64>) -> bool,
) -> Result<Solution> {
    let (mut a, mut s) = (start[0], start[1]);
    let norm = |r: Vector2<f64>, a: f64| r.norm() / scale(a);
    let (mut r, mut j) = f(Vector2::new(a, s));
    let mut rn = norm(r, a);
    for it in 0..config.max_iterations {
        if rn.is_finite() && rn < config.tolerance {
            return Ok(Solution {
                a_bar: a,
                s,
                iterations: it,
                residual: rn,
            });
        }
        let step = j.lu().solve(&(-r));
        let Some(step) = step.filter(|d| d.iter().all(|x| x.is_finite())) else {
            break;
        };
        if step[0].abs() <= config.step_tolerance * (1.0 + a.abs())
            && step[1].abs() <= config.step_tolerance
            && rn < config.stall_residual
        {
            return Ok(Solution {
                a_bar: a,
                s,
                iterations: it,
                residual: rn,
            });
        }
        let mut lambda = 1.0;
        let mut accepted = false;
        while lambda >= config.min_step {
            let (an, sn) = (a + lambda * step[0], s + lambda * step[1]);
            if an > 0.0
                && sn > 0.0
                && sn <= 1.0 + 1e-12
                && admissible(Vector2::new(an, sn.min(1.0)))
            {
                let (rt, jt) = f(Vector2::new(an, sn.min(1.0)));
                let rtn = norm(rt, an);
                if rtn.is_finite() && rtn < rn * (1.0 - 1e-4 * lambda) {
                    if rn < config.stall_residual && rtn > 0.5 * rn {
                        return Ok(Solution {
                            a_bar: an,
                            s: sn.min(1.0),
                            iterations: it + 1,
                            residual: rtn,
                        });
                    }
                    a = an;
                    s = sn.min(1.0);
                    r = rt;
                    j = jt;
                    rn = rtn;
                    accepted = true;
                    break;
                }
            }
            lambda *= 0.5;
        }
        if !accepted {
            if rn < config.tolerance * 1e3 {
                return Ok(Solution {
                    a_bar: a,
                    s,
                    iterations: it,
                    residual: rn,
                });
            }
            break;
        }
    }
    if rn.is_finite() && rn < config.tolerance {
        return Ok(Solution {
            a_bar: a,
            s,
            iterations: config.max_iterations,
            residual: rn,
        });
    }
    Err(Error::NoConvergence {
        iterations: config.max_iterations,
        a_bar: a,
        s,
        residual: rn,
        context: context.to_string(),
    })
}
