//! Pseudo-arclength continuation of a `conformal:K` branch in x = (c, δ̄)
//! at fixed ρ: the K equations ∇_c Π̄ = 0 in K + 1 unknowns, predictor along
//! the tangent (the null vector of the K × (K + 1) Jacobian), corrector by
//! Newton on the equations bordered by the arclength condition. Steps grow
//! while the corrector converges in few iterations and the tangent turns
//! little, and halve otherwise, so the trace passes the folds in ā that
//! each mode's imperfect bifurcation makes.
//!
//! The trace stops at the first extremum of the monitored quantity (F̄ for
//! the load-controlled pull-off, δ̄ for the displacement-controlled one):
//! its component along the tangent changes sign there, and Illinois on the
//! arclength locates the point. Folds in ā passed on the way are reported.
//!
//! Owns: [`to_extremum`]. May use: the parent module, nalgebra.

use super::{Conformal, Equations};
use crate::error::{short, Error, Result};
use nalgebra::{DMatrix, DVector};
use serde::Serialize;

/// Which extremum ends the trace.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PullOffControl {
    /// The minimum of F̄ (pull-off under load control).
    Load,
    /// The extremum of δ̄ (pull-off under displacement control).
    Displacement,
}

/// A fold in ā passed by the trace, before the pull-off.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Extremum {
    /// ā at the fold (to the trace's step).
    pub a_bar: f64,
    /// F̄ there.
    pub force_bar: f64,
}

/// The most steps of one trace.
const MAX_STEPS: usize = 20_000;

struct Point {
    x: DVector<f64>,
    t: DVector<f64>,
    /// The equations at x (one evaluation serves the tangent, the
    /// monitored rate and the fold record).
    e: Equations,
}

/// The unit tangent where the equations are `e`, oriented like `prev`.
fn tangent(e: &Equations, prev: &DVector<f64>) -> Option<DVector<f64>> {
    let n = prev.len();
    let mut a = DMatrix::zeros(n, n);
    a.rows_mut(0, n - 1).copy_from(&e.j);
    a.row_mut(n - 1).copy_from(&prev.transpose());
    let mut rhs = DVector::zeros(n);
    rhs[n - 1] = 1.0;
    let t = a.lu().solve(&rhs)?;
    let norm = t.norm();
    (norm.is_finite() && norm > 0.0).then(|| t / norm)
}

/// Corrector: x with ∇_c Π̄ = 0 and t·(x − base) = sigma, from base + sigma t;
/// with the iterations used and the equations at x.
fn correct(
    m: &Conformal,
    base: &Point,
    sigma: f64,
    rho: f64,
) -> Option<(DVector<f64>, usize, Equations)> {
    let n = base.x.len();
    let mut x = &base.x + &base.t * sigma;
    for it in 0..12 {
        let e = m.equations(&x, rho);
        let mut r = DVector::zeros(n);
        r.rows_mut(0, n - 1).copy_from(&e.r);
        r[n - 1] = base.t.dot(&(&x - &base.x)) - sigma;
        let mut a = DMatrix::zeros(n, n);
        a.rows_mut(0, n - 1).copy_from(&e.j);
        a.row_mut(n - 1).copy_from(&base.t.transpose());
        let dx = a.lu().solve(&r)?;
        x -= &dx;
        if !x.iter().all(|v| v.is_finite()) {
            return None;
        }
        if dx.norm() < 1e-12 * (1.0 + x.norm()) {
            let e = m.equations(&x, rho);
            return (e.r.norm() / e.scale < 1e-10).then_some((x, it + 1, e));
        }
    }
    None
}

/// The monitored quantity's rate along the tangent `t` where the equations
/// are `e`.
fn rate(e: &Equations, t: &DVector<f64>, control: PullOffControl) -> f64 {
    match control {
        PullOffControl::Load => e.force_grad.dot(t),
        PullOffControl::Displacement => t[t.len() - 1],
    }
}

/// Trace from `x0` towards smaller ā to the first extremum of F̄ or δ̄.
/// Returns the extremum's x and the folds in ā passed before it.
pub fn to_extremum(
    m: &Conformal,
    x0: &DVector<f64>,
    rho: f64,
    control: PullOffControl,
) -> Result<(DVector<f64>, Vec<Extremum>)> {
    let n = x0.len();
    let k = n - 1;
    // start towards smaller ā = Σ c_k
    let mut towards = DVector::zeros(n);
    towards.rows_mut(0, k).fill(-1.0);
    let e0 = m.equations(x0, rho);
    let t0 = tangent(&e0, &towards).ok_or_else(|| stuck(m, x0, rho, "at its start"))?;
    let mut p = Point {
        x: x0.clone(),
        t: t0,
        e: e0,
    };
    let mut h = 0.02;
    let mut folds = Vec::new();
    let mut g = rate(&p.e, &p.t, control);
    // the branch starts on the side where the load falls as the contact shrinks
    for _ in 0..MAX_STEPS {
        let Some((y, iterations, ey)) = correct(m, &p, h, rho) else {
            h *= 0.5;
            if h < 1e-10 {
                return Err(stuck(m, &p.x, rho, "the corrector fails for every step"));
            }
            continue;
        };
        let Some(ty) = tangent(&ey, &p.t) else {
            return Err(stuck(m, &y, rho, "the tangent is undefined"));
        };
        if ty.dot(&p.t) < 0.995 {
            // the tangent turned too much: a sharp bend, refine
            h *= 0.5;
            if h < 1e-10 {
                return Err(stuck(m, &p.x, rho, "the branch bends too sharply"));
            }
            continue;
        }
        m.univalence(&y.as_slice()[..k])?;
        let q = Point { x: y, t: ty, e: ey };
        let gq = rate(&q.e, &q.t, control);
        let a_rate = |pt: &Point| pt.t.rows(0, k).sum();
        if a_rate(&p) * a_rate(&q) < 0.0 {
            folds.push(Extremum {
                a_bar: q.x.rows(0, k).sum(),
                force_bar: q.e.force,
            });
        }
        // F̄ (or δ̄) falls along the trace until the extremum: its rate
        // changes sign from negative to positive there
        if g < 0.0 && gq >= 0.0 {
            return Ok((refine(m, &p, h, g, gq, rho, control)?, folds));
        }
        p = q;
        g = gq;
        if iterations <= 3 {
            h = (h * 1.3).min(0.1);
        }
        if p.x.rows(0, k).sum() < 0.3 {
            break;
        }
    }
    Err(stuck(
        m,
        &p.x,
        rho,
        "no extremum before the contact vanished or the step budget ended",
    ))
}

/// Illinois on σ ∈ (0, h) for the zero of the monitored rate.
fn refine(
    m: &Conformal,
    p: &Point,
    h: f64,
    g0: f64,
    g1: f64,
    rho: f64,
    control: PullOffControl,
) -> Result<DVector<f64>> {
    let (mut a, mut b, mut fa, mut fb) = (0.0, h, g0, g1);
    for _ in 0..100 {
        let s = (a * fb - b * fa) / (fb - fa);
        let (x, _, e) =
            correct(m, p, s, rho).ok_or_else(|| stuck(m, &p.x, rho, "refining the extremum"))?;
        let t = tangent(&e, &p.t).ok_or_else(|| stuck(m, &x, rho, "refining the extremum"))?;
        let fs = rate(&e, &t, control);
        if fs * fb < 0.0 {
            (a, fa) = (b, fb);
        } else {
            fa *= 0.5; // Illinois: the retained end's value is halved
        }
        (b, fb) = (s, fs);
        if fs == 0.0 || (b - a).abs() < 1e-13 * (1.0 + h) {
            return Ok(x);
        }
    }
    // never the last iterate in place of a located extremum
    Err(stuck(
        m,
        &p.x,
        rho,
        "the extremum's location did not converge in 100 Illinois steps",
    ))
}

fn stuck(m: &Conformal, x: &DVector<f64>, rho: f64, why: &str) -> Error {
    let k = x.len() - 1;
    let (a, b) = m.semi_axes(&x.as_slice()[..k]);
    Error::NoState(format!(
        "the {} branch at rho = {} stopped at a_bar = {:.4}, s = {:.4}: {why}",
        m.name(),
        short(rho),
        a,
        b / a
    ))
}
