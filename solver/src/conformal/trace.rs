//! A `conformal:K` branch at fixed ρ as a family of the one continuation
//! engine ([`crate::continuation`]): the K equations ∇_c Π̄ = 0 in the
//! K + 1 unknowns x = (c, δ̄). Steps grow while the corrector converges in
//! few iterations and the tangent turns little, and halve otherwise, so the
//! trace passes the folds in ā that each mode's imperfect bifurcation
//! makes; a state whose map is not one-to-one ends the trace with that
//! reason.
//!
//! The pull-off is the first extremum of F̄ (load control: located by
//! golden-section search on F̄) or of δ̄ (displacement control: Illinois on
//! dδ̄/dσ). Folds in ā passed on the way are reported.
//!
//! Owns: [`to_extremum`], the family's [`Family`] implementation. May use:
//! the parent module, `continuation`, nalgebra.

use super::Conformal;
use crate::continuation::{self, End, EventKind, Family, Linear, On, Settings, Watch};
use crate::error::{short, Error, Result};
use nalgebra::{DMatrix, DVector, Dyn};
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

/// The branch of one member at one ρ.
struct Branch<'a> {
    m: &'a Conformal,
    rho: f64,
}

impl Family<Dyn> for Branch<'_> {
    fn linearise(&self, x: &DVector<f64>) -> Option<Linear<Dyn>> {
        let e = self.m.equations(x, self.rho);
        let n = x.len();
        let mut r = DVector::zeros(n);
        r.rows_mut(0, n - 1).copy_from(&e.r);
        let mut j = DMatrix::zeros(n, n);
        j.rows_mut(0, n - 1).copy_from(&e.j);
        let ok = r.iter().chain(j.iter()).all(|v| v.is_finite());
        ok.then_some(Linear {
            r,
            j,
            force: e.force,
            force_grad: e.force_grad,
        })
    }

    fn converged(&self, x: &DVector<f64>, r: &DVector<f64>) -> bool {
        let k = x.len() - 1;
        r.rows(0, k).norm() / (1.0 + x.rows(0, k).amax().powi(7)) < 1e-10
    }

    fn admissible(&self, x: &DVector<f64>) -> Result<()> {
        self.m.univalence(&x.as_slice()[..x.len() - 1])
    }

    fn a_bar_gradient(&self) -> DVector<f64> {
        // ā = w(1) = Σ c_k
        let n = self.m.terms() + 1;
        let mut g = DVector::from_element(n, 1.0);
        g[n - 1] = 0.0;
        g
    }

    fn delta_bar_gradient(&self) -> DVector<f64> {
        let n = self.m.terms() + 1;
        let mut g = DVector::zeros(n);
        g[n - 1] = 1.0;
        g
    }

    fn stuck(&self, x: &DVector<f64>, why: &str) -> Error {
        stuck(self.m, x, self.rho, why)
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
    let family = Branch { m, rho };
    // start towards smaller ā = Σ c_k
    let towards = -family.a_bar_gradient();
    let settings = Settings {
        step: 0.02,
        min_step: 1e-10,
        max_step: 0.1,
        grow: 1.3,
        fast_iterations: 3,
        turn: 0.995,
        corrector_iterations: 12,
        step_tolerance: 1e-12,
        max_steps: 20_000,
    };
    let (force_minimum, displacement_fold) = match control {
        PullOffControl::Load => (On::Stop, On::Ignore),
        PullOffControl::Displacement => (On::Ignore, On::Stop),
    };
    let watch = Watch {
        size_fold: On::Note,
        displacement_fold,
        force_minimum,
        bifurcation: On::Ignore,
        crossing: None,
    };
    let trace = continuation::trace(&family, x0.clone(), &towards, settings, watch, |p| {
        p.a_bar < 0.3
    })?;
    let folds = trace
        .events
        .iter()
        .filter(|e| e.kind == EventKind::SizeFold)
        .map(|e| {
            let q = &trace.points[e.between[1]];
            Extremum {
                a_bar: q.a_bar,
                force_bar: q.force,
            }
        })
        .collect();
    let wanted = match control {
        PullOffControl::Load => EventKind::ForceMinimum,
        PullOffControl::Displacement => EventKind::DisplacementFold,
    };
    match (trace.end, trace.located(wanted)) {
        (End::Event(_), Some(x)) => Ok((x.clone(), folds)),
        _ => {
            let last = &trace.points.last().expect("one point").u;
            debug_assert_eq!(last.len(), n);
            Err(stuck(
                m,
                last,
                rho,
                "no extremum before the contact vanished or the step budget ended",
            ))
        }
    }
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
