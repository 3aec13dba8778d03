//! The jump rule of the loading path (issue 32 (b)): where a contact goes
//! at a held force F̄₀ from a contour that is no state there (a state of a
//! nearby force, or one past a fold of its arm).
//!
//! Statics does not say where a jump lands; the rule used here is the
//! descent of the potential at the held force, V = Π̄ − 2F̄₀δ̄
//! (`studies::potential`), the quasi-static limit of a contact line whose
//! normal speed is proportional to the local excess of the energy release
//! rate over the work of adhesion: V_n ∝ 1 − (∂p̄/∂ν)² (the steepest
//! descent of V in the L² norm of the normal motion). The contact ends in
//! the first local minimum of V down the gradient from where it starts, or
//! it shrinks without end (δ̄ → −∞, V → −∞ at a tensile force): it
//! detaches.
//!
//! The short-wave cutoff ([`Cutoff`]) enters as which contour modes move
//! by the descent: the modes whose wavelength along the contour (its
//! perimeter over n) is at least the cutoff's are the descent's; the
//! shorter ones, whose stability the thin-layer equation (2) cannot judge,
//! are held at equilibrium (their gradient zero, by Newton's method, stable
//! or not in (2)), as a real coating, stiffer at short waves, holds them.
//! So the descent minimises the reduced potential V(a, s*(a)) over the
//! resolved coefficients a, s*(a) the equilibrium of the others.
//!
//! Steps are pseudo-transient: d = −(H + M/τ)⁻¹ g in the resolved
//! coefficients, with H the reduced Hessian (the bordered Hessian's Schur
//! complements on δ̄ and on the held modes), M the metric of the normal
//! motion and g the gradient: a short gradient-flow step for small τ,
//! Newton's step of the minimisation for large τ. A step is taken when
//! H + M/τ is positive definite and V falls by at least 1e-4 of the
//! predicted decrease; τ grows fourfold after a step and shrinks fourfold
//! otherwise. In the arclength representation the shape coordinates are
//! A and the b_j; the c_j follow from the gauge (θ proportional to
//! arclength), to first order along its tangent and exactly after each
//! step (the reparametrisations move no contour and would leave M
//! singular).
//!
//! Where the held modes' equilibrium keeps cutting the steps short (a
//! longer trial finds none, [`STALL_STEPS`] steps in a row), the descent
//! stalls: it is not settled there, rather than creeping on.
//!
//! Owns: [`Landing`], [`descend`]. May use: `exact` (the problem, its
//! energy's Hessian and Newton), `studies::potential` (the potential), `control`, `cutoff`, `newton` (the stop request),
//! nalgebra.

use super::potential::{at_force, AtForce};
use crate::control::Hold;
use crate::cutoff::Cutoff;
use crate::exact::{Exact, ExactState};
use nalgebra::{DMatrix, DVector};

/// Where a descent ends.
#[derive(Clone, Debug)]
pub(crate) enum Landing {
    /// A state at the held force: a local minimum of the potential in the
    /// resolved modes, solved again by Newton's method at the force.
    Landed(Box<ExactState>),
    /// The contact shrank below a tenth of its starting area with the
    /// potential still falling: it comes off.
    Detached,
    /// The descent stopped before either (in words, for a report).
    NotSettled(String),
}

/// The largest number of descent steps.
const MAX_STEPS: usize = 600;

/// The gradient's norm in the metric (the normal speed's L² norm) below
/// which the descent has reached a stationary point.
const STATIONARY: f64 = 1e-9;

/// How many steps in a row the descent may take whose length the held
/// modes' equilibrium cut (a longer trial step found none) before it is
/// said to stall there: a descent pinned to such steps creeps (at ρ = 0.5
/// with h/L = 0.28, from the state at F̄ = 8.21 unstable to n = 10, before
/// the Hessian had the gauge's curvature term it moved ā by 3e-6 a step,
/// one step a second, so 600 steps took 12 min and the loading path's
/// bracketing repeated them for hours).
const STALL_STEPS: usize = 20;

/// How far a saddle is left along its unstable direction, relative to ā
/// (in the metric's unit norm).
const KICK: f64 = 1e-3;

/// How many saddles one descent may leave.
const MAX_KICKS: usize = 8;

/// The most unstable direction of the reduced Hessian in the metric (unit
/// norm in M), or `None` where the Hessian is positive definite there.
fn unstable_direction(
    p: &Point,
    mc: &nalgebra::Cholesky<f64, nalgebra::Dyn>,
) -> Option<DVector<f64>> {
    // L⁻¹ H L⁻ᵀ with M = L Lᵀ: its eigenvectors w give v = L⁻ᵀ w
    let l = mc.l();
    let l_inv = l.clone().try_inverse()?;
    let sym = &l_inv * &p.hessian * l_inv.transpose();
    let eig = nalgebra::SymmetricEigen::new((&sym + sym.transpose()) * 0.5);
    let i = eig.eigenvalues.imin();
    // (round-off at a nearly neutral direction is no instability)
    if eig.eigenvalues[i] >= -1e-8 * eig.eigenvalues.amax() {
        return None;
    }
    Some(l_inv.transpose() * eig.eigenvectors.column(i))
}

/// Which coefficients the descent moves: A (the size: the multiplier 1,
/// mode n = 0) and the contour modes at least the cutoff's wavelength long
/// on a contour of `perimeter`; each told by its multiplier m, the mode
/// n = |m − 1|, not by its place among the coefficients.
fn resolved_coefficients(ex: &Exact, perimeter: f64, cutoff: Cutoff) -> Vec<bool> {
    ex.grid
        .multipliers
        .iter()
        .map(|&m| {
            let n = (m - 1.0).abs().round();
            n == 0.0 || cutoff.resolves(perimeter / n)
        })
        .collect()
}

/// The rows/columns `idx` of a square matrix.
fn block(a: &DMatrix<f64>, rows: &[usize], cols: &[usize]) -> DMatrix<f64> {
    DMatrix::from_fn(rows.len(), cols.len(), |i, j| a[(rows[i], cols[j])])
}

/// One point of the descent: the held modes at equilibrium, the potential,
/// its gradient, Hessian and metric in the resolved coefficients.
struct Point {
    u: DVector<f64>,
    potential: f64,
    gradient: DVector<f64>,
    hessian: DMatrix<f64>,
    metric: DMatrix<f64>,
    /// dS/dA of the held modes' equilibrium (for the next predictor).
    held_response: DMatrix<f64>,
    /// ∂u/∂(shape coordinates) on the arclength representation's gauge
    /// (the identity for the conformal-map form).
    lift: DMatrix<f64>,
}

/// The descent's problem.
struct Descent<'a> {
    ex: &'a Exact,
    force: f64,
    /// Indices among the shape coordinates (A, b₀..b_{N−1}).
    free: Vec<usize>,
    held: Vec<usize>,
    /// The number of shape coordinates, 1 + N.
    shape: usize,
    /// The number of gauge coefficients c_j (0 in the conformal-map form).
    gauge: usize,
}

impl Descent<'_> {
    /// The Hessian of V at the held force in the coefficients (the
    /// bordered Hessian's Schur complement on δ̄), symmetrised, with the
    /// gauge's curvature term where the coefficients move on the arclength
    /// representation's gauge ([`Descent::gauge_term`]).
    fn hessian(&self, at: &AtForce) -> Option<DMatrix<f64>> {
        let b = self.ex.bordered_hessian(&at.u)?;
        let m = b.nrows() - 1;
        let h = b.view((0, 0), (m, m)).into_owned();
        let border = b.view((0, m), (m, 1)).into_owned();
        let corner = b[(m, m)];
        if !(corner.abs() > 0.0) {
            return None;
        }
        let h = h - &border * border.transpose() / corner + self.gauge_term(at)?;
        Some((&h + h.transpose()) * 0.5)
    }

    /// What the gauge's curvature adds to the Hessian of V along the gauge:
    /// the shape coordinates s move the c_j as c(s) with G(s, c(s)) = 0
    /// (the gauge rows), so d²V/ds² = Lᵀ∇²V L + Σ_c ∂V/∂c_c ∂²c_c/∂s²,
    /// and differentiating G = 0 twice gives the second term as
    /// Lᵀ(Σ_j λ_j ∇²G_j)L with G_cᵀλ = −∂V/∂c. It vanishes at a state
    /// (there ∂V/∂c = 0), not on the way: without it the held modes'
    /// Newton's method converged only linearly in the arclength
    /// representation, and the lifted Hessian missed central differences
    /// of the lifted gradient by up to 31 % (ρ = 0.8, 32 modes, a contour
    /// 3 % of ā off a state). Zero in the conformal-map form.
    fn gauge_term(&self, at: &AtForce) -> Option<DMatrix<f64>> {
        let m = self.shape + self.gauge;
        if self.gauge == 0 {
            return Some(DMatrix::zeros(m, m));
        }
        let g = self.ex.gauge_jacobian(&at.u);
        let gc = g
            .view((0, self.shape), (self.gauge, self.gauge))
            .transpose();
        let lambda = gc
            .lu()
            .solve(&(-at.gradient.rows(self.shape, self.gauge)))?;
        Some(gauge_curvature(&self.ex, &lambda))
    }

    /// u moved onto the arclength representation's gauge (θ proportional
    /// to arclength) by Newton's method in the c_j alone.
    fn on_gauge(&self, mut u: DVector<f64>) -> Option<DVector<f64>> {
        if self.gauge == 0 {
            return Some(u);
        }
        for _ in 0..30 {
            let dz = self.ex.contour_of(&u).samples(&self.ex.grid).dz;
            let rows = DVector::from_vec(self.ex.gauge_rows(&dz));
            let scale = u[0] * u[0];
            if rows.amax() <= 1e-13 * scale.max(1.0) {
                return Some(u);
            }
            let g = self.ex.gauge_jacobian(&u);
            let gc = g
                .view((0, self.shape), (self.gauge, self.gauge))
                .into_owned();
            let step = gc.lu().solve(&(-rows))?;
            for i in 0..self.gauge {
                u[self.shape + i] += step[i];
            }
        }
        None
    }

    /// ∂u/∂(shape coordinates) along the gauge at u: the identity on
    /// (A, b_j) and −G_c⁻¹G_o for the c_j (G the gauge rows' Jacobian).
    fn lift(&self, u: &DVector<f64>) -> Option<DMatrix<f64>> {
        let m = self.shape + self.gauge;
        let mut z = DMatrix::zeros(m, self.shape);
        z.view_mut((0, 0), (self.shape, self.shape))
            .fill_with_identity();
        if self.gauge > 0 {
            let g = self.ex.gauge_jacobian(u);
            let go = g.view((0, 0), (self.gauge, self.shape)).into_owned();
            let gc = g
                .view((0, self.shape), (self.gauge, self.gauge))
                .into_owned();
            let dc = gc.lu().solve(&(-go))?;
            z.view_mut((self.shape, 0), (self.gauge, self.shape))
                .copy_from(&dc);
        }
        Some(z)
    }

    /// u moved by `d` in the shape coordinates, along the gauge's tangent.
    fn moved(&self, u: &DVector<f64>, lift: &DMatrix<f64>, d: &DVector<f64>) -> DVector<f64> {
        let mut out = u.clone();
        let du = lift * d;
        for k in 0..du.len() {
            out[k] += du[k];
        }
        out
    }

    /// The point at the coefficients of u: on the gauge, the held modes
    /// put at equilibrium first (Newton's method on their gradient).
    fn point(&self, u: DVector<f64>) -> Option<Point> {
        let mut u = u;
        for _ in 0..30 {
            u = self.on_gauge(u)?;
            let at = at_force(self.ex, &u, self.force)?;
            let lift = self.lift(&at.u)?;
            let hess = {
                let h = self.hessian(&at)?;
                let h = lift.transpose() * h * &lift;
                (&h + h.transpose()) * 0.5
            };
            let gradient = lift.transpose() * &at.gradient;
            let metric = lift.transpose() * &at.metric * &lift;
            let g_held =
                DVector::from_iterator(self.held.len(), self.held.iter().map(|&k| gradient[k]));
            let scale = gradient.amax().max(1.0);
            let h_hh = block(&hess, &self.held, &self.held);
            if g_held.amax() <= 1e-11 * scale {
                let free = &self.free;
                let h_ff = block(&hess, free, free);
                let h_fh = block(&hess, free, &self.held);
                let (hessian, held_response) = if self.held.is_empty() {
                    (h_ff, DMatrix::zeros(0, free.len()))
                } else {
                    let lu = h_hh.lu();
                    let response = -lu.solve(&h_fh.transpose())?;
                    (&h_ff + &h_fh * &response, response)
                };
                return Some(Point {
                    gradient: DVector::from_iterator(free.len(), free.iter().map(|&k| gradient[k])),
                    metric: block(&metric, free, free),
                    potential: at.potential,
                    u: at.u,
                    hessian,
                    held_response,
                    lift,
                });
            }
            let step = h_hh.lu().solve(&(-g_held))?;
            let mut d = DVector::zeros(self.shape);
            for (i, &k) in self.held.iter().enumerate() {
                d[k] = step[i];
            }
            u = self.moved(&at.u, &lift, &d);
        }
        None
    }

    /// One step of the descent from `p`: Newton's step regularised by the
    /// metric over `tau` (shortened, tau / 4, until the potential falls
    /// enough; lengthened, tau × 4, after a step taken).
    fn trial(&self, p: &Point, tau: &mut f64) -> Trial {
        let mut out = Trial {
            next: None,
            stationary: false,
            unreachable_equilibrium: false,
        };
        while *tau > 1e-12 {
            let Some(ch) = (&p.hessian + &p.metric / *tau).cholesky() else {
                *tau /= 4.0;
                continue;
            };
            let step = ch.solve(&(-&p.gradient));
            let predicted = p.gradient.dot(&step);
            // a decrease below the potential's round-off cannot be seen:
            // the point is stationary to working precision
            if *tau >= 1.0 && -predicted < 1e-13 * p.potential.abs().max(1.0) {
                out.stationary = true;
                break;
            }
            let u = self.moved(&p.u, &p.lift, &self.with_held(p, &step));
            match self.point(u) {
                Some(next) if next.potential <= p.potential + 1e-4 * predicted => {
                    out.next = Some(next);
                    *tau = (*tau * 4.0).min(1e12);
                    break;
                }
                other => {
                    out.unreachable_equilibrium |= other.is_none();
                    *tau /= 4.0
                }
            }
        }
        out
    }

    /// The point a kick of KICK ā along the unstable direction `v` leads
    /// to from the saddle `p`, on the side the descent came from (from
    /// `start_u`: the path's imperfection picks it); `None` where the short
    /// modes have no equilibrium there.
    fn kicked(
        &self,
        p: &Point,
        v: DVector<f64>,
        start_u: &DVector<f64>,
        a_bar: f64,
    ) -> Option<Point> {
        let came = DVector::from_iterator(
            self.free.len(),
            self.free.iter().map(|&k| p.u[k] - start_u[k]),
        );
        let sign = if came.dot(&v) < 0.0 { -1.0 } else { 1.0 };
        let kick = v * (sign * KICK * a_bar);
        self.point(self.moved(&p.u, &p.lift, &self.with_held(p, &kick)))
    }

    /// The shape coordinates' step of a step `d` in the free ones, the held
    /// ones following their equilibrium to first order.
    fn with_held(&self, p: &Point, d: &DVector<f64>) -> DVector<f64> {
        let mut full = DVector::zeros(self.shape);
        for (i, &k) in self.free.iter().enumerate() {
            full[k] = d[i];
        }
        let held = &p.held_response * d;
        for (i, &k) in self.held.iter().enumerate() {
            full[k] = held[i];
        }
        full
    }
}

/// What one step of the descent found: the next point (none where no
/// step lowered the potential), whether the point is stationary to
/// working precision, and whether a trial step failed for want of the
/// held modes' equilibrium (rather than for the potential).
struct Trial {
    next: Option<Point>,
    stationary: bool,
    unreachable_equilibrium: bool,
}

/// The descent of the potential at the held `force` from the contour and
/// approach of `start` (a state of `ex`'s truncation), moving the modes
/// that `cutoff` resolves.
pub(crate) fn descend(ex: &Exact, start: &ExactState, force: f64, cutoff: Cutoff) -> Landing {
    let samples = start.contour.samples(&ex.grid);
    let h = 2.0 * std::f64::consts::PI / ex.grid.len() as f64;
    let perimeter: f64 = samples.dz.iter().map(|d| d.norm()).sum::<f64>() * h;
    let shape = 1 + ex.truncation().modes;
    let resolved = resolved_coefficients(ex, perimeter, cutoff);
    let (free, held): (Vec<usize>, Vec<usize>) = (0..shape).partition(|&k| resolved[k]);
    let d = Descent {
        ex,
        force,
        free,
        held,
        shape,
        gauge: ex.truncation().arclength,
    };
    let Some(mut p) = d.point(ex.unknowns(start)) else {
        return Landing::NotSettled(format!(
            "the modes shorter than the cutoff have no equilibrium near the start (a = {:.4})",
            start.a_bar
        ));
    };
    let start_u = p.u.clone();
    let start_area = area(ex, &start_u);
    let mut kicks = 0;
    // Newton's step first (a start near a minimum, the path's common
    // case); shortened where the Hessian is not positive definite
    let mut tau: f64 = 1e6;
    // whether the last pass found no step above round-off
    let mut at_rest = false;
    // the steps in a row whose length the held modes' equilibrium cut
    let mut cut_by_held = 0;
    for _ in 0..MAX_STEPS {
        if crate::newton::check_stop().is_err() {
            return Landing::NotSettled("stopped at the caller's request".into());
        }
        let a_bar = ex.contour_of(&p.u).a_bar();
        if area(ex, &p.u) < start_area / 10.0 {
            return Landing::Detached;
        }
        // the normal speed's norm: gᵀM⁻¹g
        let Some(mc) = p.metric.clone().cholesky() else {
            return Landing::NotSettled(format!("the contour degenerates at a = {a_bar:.4}"));
        };
        let speed = p.gradient.dot(&mc.solve(&p.gradient)).max(0.0).sqrt();
        if at_rest || speed < STATIONARY * p.gradient.amax().max(1.0) {
            at_rest = false;
            // a minimum lands; a saddle (a resolved mode unstable) is left
            // along its most unstable direction, on the side the descent
            // came from (the path's imperfection picks it)
            match unstable_direction(&p, &mc) {
                None => return land(ex, &p, force),
                Some(_) if kicks == MAX_KICKS => {
                    return Landing::NotSettled(format!(
                        "the descent stays on a saddle at a = {a_bar:.4}"
                    ))
                }
                Some(v) => {
                    kicks += 1;
                    match d.kicked(&p, v, &start_u, a_bar) {
                        Some(next) => {
                            p = next;
                            tau = 1e-2;
                            continue;
                        }
                        None => {
                            return Landing::NotSettled(format!(
                                "the contour off the saddle at a = {a_bar:.4} has no equilibrium of its short modes"
                            ))
                        }
                    }
                }
            }
        }
        let trial = d.trial(&p, &mut tau);
        if trial.stationary {
            at_rest = true;
            continue;
        }
        let (moved, unreachable_equilibrium) =
            (trial.next.is_some(), trial.unreachable_equilibrium);
        if let Some(next) = trial.next {
            p = next;
        }
        cut_by_held = if moved && unreachable_equilibrium {
            cut_by_held + 1
        } else {
            0
        };
        if cut_by_held == STALL_STEPS {
            let at = ex.contour_of(&p.u);
            return Landing::NotSettled(format!(
                "the descent stalls at a = {:.4}, s = {:.4}: for {STALL_STEPS} steps in a row a longer step found no equilibrium of the contour modes shorter than the cutoff",
                at.a_bar(),
                at.b_bar() / at.a_bar()
            ));
        }
        if !moved {
            let at = ex.contour_of(&p.u);
            let why = if d.held.is_empty() || !unreachable_equilibrium {
                "no step lowers the potential"
            } else {
                "the contour modes shorter than the cutoff lose their equilibrium (what the contact does then is below the thin-layer model's resolution)"
            };
            let after = if kicks > 0 {
                " (after leaving an unstable state along a resolved mode: the contact changes shape towards contours the series does not follow)"
            } else {
                ""
            };
            return Landing::NotSettled(format!(
                "{why} at a = {:.4}, s = {:.4}{after}",
                at.a_bar(),
                at.b_bar() / at.a_bar()
            ));
        }
    }
    Landing::NotSettled(format!("no minimum within {MAX_STEPS} steps"))
}

/// The contact's area |ω| = ∮ X dY at u.
fn area(ex: &Exact, u: &DVector<f64>) -> f64 {
    let s = ex.contour_of(u).samples(&ex.grid);
    let h = 2.0 * std::f64::consts::PI / ex.grid.len() as f64;
    s.z.iter()
        .zip(&s.dz)
        .map(|(z, dz)| z.re * dz.im)
        .sum::<f64>()
        * h
}

/// The stationary point `p`, solved again at the force by Newton's method
/// (all modes, the truncation's equations).
fn land(ex: &Exact, p: &Point, force: f64) -> Landing {
    let id = ex.unknown_count() - 1;
    match ex.solve_at(Hold::Force(force), &ex.contour_of(&p.u), p.u[id]) {
        Ok(st) => Landing::Landed(Box::new(st)),
        Err(e) => Landing::NotSettled(format!("Newton at the descent's end failed: {e}")),
    }
}

/// Σ_j λ_j ∂²G_j/∂u_k∂u_l for the arclength representation's rows
/// G_j (`Exact::gauge_rows`) in the coefficients (coefficients ×
/// coefficients): the rows are quadratic in them, |z′|² with
/// z′ = Σ_l u_l i m_l e_l, so ∂²|z′(θ_i)|²/∂u_k∂u_l =
/// 2 m_k m_l Re(ē_k e_l)(θ_i), summed with the weights
/// Σ_j λ_j cos 2jθ_i (the rows' modes) and the gauge weight. With λ the
/// gauge's multipliers it is what the curvature of the gauge adds to a
/// Hessian in the coefficients that move on it (here).
fn gauge_curvature(ex: &Exact, lambda: &DVector<f64>) -> DMatrix<f64> {
    let np = ex.truncation().arclength;
    let m = ex.truncation().coefficients();
    let n = ex.grid.len();
    if np == 0 {
        return DMatrix::zeros(m, m);
    }
    let mut weights = ex.cos_modes.rows(1, np).transpose() * lambda;
    if let Some(w) = &ex.gauge_weight {
        weights.component_mul_assign(w);
    }
    let mult = &ex.grid.multipliers;
    let basis = &ex.grid.basis;
    let re = DMatrix::from_fn(n, m, |i, k| mult[k] * basis[k][i].re);
    let im = DMatrix::from_fn(n, m, |i, k| mult[k] * basis[k][i].im);
    let weighted = |e: &DMatrix<f64>| DMatrix::from_fn(n, m, |i, k| weights[i] * e[(i, k)]);
    (weighted(&re).transpose() * &re + weighted(&im).transpose() * &im) * 2.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::{Contour, Truncation};

    /// At ρ = 1 the circles are the states, F̄ = π(ā⁶ − 24ā³)/96, with the
    /// load-controlled pull-off at ā³ = 12: at a force just above it, a
    /// contact started just above the smaller (unstable) circle descends
    /// to the larger (stable) one, one started just below it comes off; at
    /// a force below the pull-off the stable circle of the pull-off comes
    /// off.
    #[test]
    fn at_rho_1_the_descent_finds_the_stable_circle_or_comes_off() {
        // both representations: the conformal-map form and the arclength
        // one, whose c_j follow the gauge
        for t in [Truncation::with_modes(8), Truncation::in_arclength(8)] {
            let ex = Exact::new(1.0, t).unwrap();
            let force_of = |a: f64| std::f64::consts::PI * (a.powi(6) - 24.0 * a.powi(3)) / 96.0;
            let pull_off_a = 12f64.cbrt();
            let force = force_of(pull_off_a) + 0.5;
            // the two circles at that force, by bisection on either side
            let root = |mut lo: f64, mut hi: f64| {
                for _ in 0..100 {
                    let mid = 0.5 * (lo + hi);
                    if (force_of(mid) > force) == (force_of(lo) > force) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                0.5 * (lo + hi)
            };
            let small = root(0.5, pull_off_a);
            let large = root(pull_off_a, 4.0);
            let circle = |a: f64| {
                ex.solve(a, &Contour::ellipse(a, a, 8), a * a / 4.0 - 2.0 / a)
                    .unwrap()
            };
            let cutoff = Cutoff::for_thinness(0.5).unwrap();
            match descend(&ex, &circle(small + 0.05), force, cutoff) {
                Landing::Landed(st) => {
                    assert!(
                        (st.a_bar - large).abs() < 1e-9,
                        "{t:?}: {} vs {large}",
                        st.a_bar
                    );
                    assert!((st.force_bar - force).abs() < 1e-10);
                }
                other => panic!("{t:?}: {other:?}"),
            }
            assert!(matches!(
                descend(&ex, &circle(small - 0.05), force, cutoff),
                Landing::Detached
            ));
            assert!(matches!(
                descend(
                    &ex,
                    &circle(pull_off_a),
                    force_of(pull_off_a) - 1e-3,
                    cutoff
                ),
                Landing::Detached
            ));
        }
    }

    /// The reduced Hessian the descent steps with is the derivative of the
    /// gradient it descends: off a state (the zero-force state at ρ = 0.8
    /// moved along two shape coordinates by up to 3 % of ā), every column
    /// of the Hessian in the shape coordinates agrees with central
    /// differences of the gradient along the gauge, in the conformal-map
    /// form and in the arclength representation (where the gauge's
    /// curvature term carries up to a third of it).
    #[test]
    fn the_hessian_is_the_derivative_of_the_gradient_along_the_gauge() {
        let zero = crate::exact::at_resolved(0.8, Hold::Force(0.0)).unwrap();
        for t in [Truncation::with_modes(32), Truncation::in_arclength(32)] {
            let ex = Exact::new(0.8, t).unwrap();
            let st = ex
                .solve_at(Hold::Force(0.0), &zero.contour, zero.delta_bar)
                .unwrap();
            let shape = 1 + ex.truncation().modes;
            let d = Descent {
                ex: &ex,
                force: 0.0,
                free: (0..shape).collect(),
                held: vec![],
                shape,
                gauge: ex.truncation().arclength,
            };
            // the gradient in the shape coordinates at u, put on the gauge
            let gradient = |u: DVector<f64>| {
                let at = at_force(&ex, &d.on_gauge(u).unwrap(), 0.0).unwrap();
                d.lift(&at.u).unwrap().transpose() * &at.gradient
            };
            for off in [1e-3, 1e-2, 3e-2] {
                let u0 = ex.unknowns(&st);
                let mut dir = DVector::zeros(shape);
                dir[3] = off * st.a_bar;
                dir[5] = 0.5 * off * st.a_bar;
                let u = d
                    .on_gauge(d.moved(&u0, &d.lift(&u0).unwrap(), &dir))
                    .unwrap();
                let at = at_force(&ex, &u, 0.0).unwrap();
                let lift = d.lift(&at.u).unwrap();
                let h = lift.transpose() * d.hessian(&at).unwrap() * &lift;
                assert!(gradient(at.u.clone()).amax() > 10.0 * off, "off a state");
                let eps = 1e-6;
                for k in [0, 1, 2, 3, 4, 6, 9] {
                    let mut e = DVector::zeros(shape);
                    e[k] = eps;
                    let central = (gradient(d.moved(&at.u, &lift, &e))
                        - gradient(d.moved(&at.u, &lift, &(-&e))))
                        / (2.0 * eps);
                    let column = (&h.column(k) + h.row(k).transpose()) * 0.5;
                    let err = (&central - &column).amax() / column.amax();
                    assert!(err < 1e-6, "{t:?}, {off:e} off, column {k}: {err:.1e}");
                }
            }
        }
    }
}
