//! The solution family of the exact problem traced by pseudo-arclength
//! continuation in u = (A, b₀..b_{N−1}, δ̄), with ā free: the family can
//! turn back in ā (a fold of the contact size, where the contour turns
//! strongly non-elliptical near a bifurcation of the circle branch), so ā
//! is not a safe parameter. Folds in ā and in F̄ are reported as data; the
//! load-controlled pull-off is the first minimum of F̄ along the family,
//! located by golden-section search on F̄ in the
//! arclength (dF̄/dσ changes sign there; at ρ = 1 it sits on a bifurcation
//! point, where the tangent is not defined).
//! Bifurcation points are flagged where the determinant of the bordered
//! Jacobian [∂r/∂u; tᵀ] changes sign (at a fold it does not).
//!
//! Owns: [`Branch`], [`BranchPoint`], [`Event`]. May use: `exact`, `error`,
//! `conformal` (the richest member's state as a start).

use super::{Exact, ExactState, Route};
use crate::error::{Error, Result};
use nalgebra::{DMatrix, DVector};
use serde::Serialize;

/// What happens between two traced points.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum Event {
    /// ā turns (a fold of the contact size) near this ā.
    SizeFold {
        /// ā at the fold (the nearer traced point).
        a_bar: f64,
    },
    /// F̄ has a minimum here (the load-controlled pull-off of the arm
    /// when it is the first met with ā decreasing), refined.
    ForceMinimum {
        /// The refined state.
        state: Box<ExactState>,
    },
    /// The determinant of the bordered Jacobian changes sign: a
    /// bifurcation point of the family lies between these ā.
    Bifurcation {
        /// ā at the two traced points that bracket it.
        between: [f64; 2],
        /// The contour mode n (radius perturbed by cos nθ) that dominates
        /// the null direction there: the right singular vector of the
        /// smallest singular value of the bordered Jacobian at the later
        /// point (0 when the contour's size or δ̄ dominates; `None` when
        /// the singular vectors could not be computed).
        mode: Option<usize>,
    },
}

impl Event {
    /// The event in words, for a person (`None` for the force minimum,
    /// which is reported as the pull-off itself).
    pub fn describe(&self) -> Option<String> {
        match self {
            Event::SizeFold { a_bar } => {
                Some(format!("the family turns back in a near a = {a_bar:.6}"))
            }
            Event::Bifurcation { between, mode } => Some(format!(
                "a bifurcation point between a = {:.6} and {:.6} (contour mode {})",
                between[0],
                between[1],
                mode.map_or("not computed".to_string(), |n| format!("n = {n}"))
            )),
            Event::ForceMinimum { .. } => None,
        }
    }
}

/// What an exact state is asked for by.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum ExactControl {
    /// The approach δ̄.
    Delta(f64),
    /// The force F̄ (F̄ = 0: the zero-force state).
    Force(f64),
}

impl std::fmt::Display for ExactControl {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ExactControl::Delta(d) => write!(f, "delta = {}", crate::error::short(*d)),
            ExactControl::Force(v) => write!(f, "force = {}", crate::error::short(*v)),
        }
    }
}

/// One traced point.
#[derive(Clone, Debug, Serialize)]
pub struct BranchPoint {
    /// The state.
    pub state: ExactState,
    /// dF̄/dσ along the unit tangent in u.
    pub d_force: f64,
    /// dā/dσ.
    pub d_a_bar: f64,
}

/// A traced piece of the family.
#[derive(Clone, Debug, Serialize)]
pub struct Branch {
    /// The traced points in order.
    pub points: Vec<BranchPoint>,
    /// The events met, in order.
    pub events: Vec<Event>,
}

/// The half-width of the exact circle (ρ = 1) with approach δ̄:
/// the root of ā²/4 − 2/ā = δ̄ (increasing in ā), by bisection.
fn circle_a_bar_at_delta(delta_bar: f64) -> f64 {
    if !delta_bar.is_finite() {
        return f64::NAN;
    }
    let f = |a: f64| a * a / 4.0 - 2.0 / a - delta_bar;
    let (mut lo, mut hi) = (1e-12, 1.0);
    while f(hi) < 0.0 {
        hi *= 2.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Residuals, Jacobian (central differences) and ∇F̄ at u.
fn linearise(ex: &Exact, u: &DVector<f64>) -> Option<(DVector<f64>, DMatrix<f64>, DVector<f64>)> {
    let (r, _) = ex.modes(u)?;
    let n = u.len();
    let mut j = DMatrix::zeros(r.len(), n);
    let mut g = DVector::zeros(n);
    for k in 0..n {
        let h = 1e-6 * (1.0 + u[k].abs());
        let mut up = u.clone();
        let mut um = u.clone();
        up[k] += h;
        um[k] -= h;
        let (rp, fp) = ex.modes(&up)?;
        let (rm, fm) = ex.modes(&um)?;
        j.set_column(k, &((rp - rm) / (2.0 * h)));
        g[k] = (fp - fm) / (2.0 * h);
    }
    Some((r, j, g))
}

/// The unit tangent t with ∂r/∂u t = 0 and t·t_prev > 0, and the
/// determinant of the bordered matrix [∂r/∂u; t_prevᵀ].
fn tangent(j: &DMatrix<f64>, t_prev: &DVector<f64>) -> Option<(DVector<f64>, f64)> {
    let n = t_prev.len();
    let mut m = DMatrix::zeros(n, n);
    m.rows_mut(0, n - 1).copy_from(j);
    m.row_mut(n - 1).copy_from(&t_prev.transpose());
    let mut rhs = DVector::zeros(n);
    rhs[n - 1] = 1.0;
    let lu = m.lu();
    let det = lu.determinant();
    let t = lu.solve(&rhs)?;
    let norm = t.norm();
    (norm.is_finite() && norm > 0.0).then(|| (t / norm, det))
}

/// A factored bordered Jacobian.
type Bordered = nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>;

/// The contour mode of the near-null direction of the bordered Jacobian
/// [∂r/∂u; tᵀ]: the largest component, among the b_j, of the right
/// singular vector of its smallest singular value; b_j perturbs the radius
/// by cos (2j + 2)θ. 0 when A or δ̄ dominates; `None` when the SVD gives
/// no singular vectors.
fn null_mode(j: &DMatrix<f64>, t: &DVector<f64>) -> Option<usize> {
    let n = t.len();
    let mut m = DMatrix::zeros(n, n);
    m.rows_mut(0, n - 1).copy_from(j);
    m.row_mut(n - 1).copy_from(&t.transpose());
    let svd = m.svd(false, true);
    let v_t = svd.v_t.as_ref()?;
    let k = svd.singular_values.imin();
    let i = (0..n)
        .max_by(|&a, &b| v_t[(k, a)].abs().total_cmp(&v_t[(k, b)].abs()))
        .unwrap_or(0);
    Some(if i == 0 || i == n - 1 {
        0
    } else {
        2 * (i - 1) + 2
    })
}

/// dā/du: ā = A + Σ b_j.
fn a_bar_gradient(n: usize) -> DVector<f64> {
    let mut g = DVector::from_element(n, 1.0);
    g[n - 1] = 0.0;
    g
}

impl Exact {
    /// Newton's method for r(u) = 0 with t·(u − u_pred) = 0: first keeping
    /// the bordered Jacobian while each step reduces the residual at least
    /// fourfold (the chord method; refreshed otherwise), and where that
    /// fails with the Jacobian renewed at every step. The answer is
    /// accepted only when the residual is below the tolerance.
    fn correct(&self, u_pred: &DVector<f64>, t: &DVector<f64>) -> Option<DVector<f64>> {
        self.correct_with(u_pred, t, true, None)
            .or_else(|| self.correct_with(u_pred, t, false, None))
    }

    /// [`Exact::correct`] starting from the factored bordered Jacobian
    /// `start` of a nearby point (the refinements between two traced
    /// points reuse the one of the first).
    fn correct_near(
        &self,
        u_pred: &DVector<f64>,
        t: &DVector<f64>,
        start: &Bordered,
    ) -> Option<DVector<f64>> {
        self.correct_with(u_pred, t, true, Some(start.clone()))
            .or_else(|| self.correct(u_pred, t))
    }

    /// The factored bordered Jacobian [∂r/∂u; tᵀ] at u.
    fn bordered(&self, u: &DVector<f64>, t: &DVector<f64>) -> Option<Bordered> {
        let n = u.len();
        let (_, j, _) = linearise(self, u)?;
        let mut m = DMatrix::zeros(n, n);
        m.rows_mut(0, n - 1).copy_from(&j);
        m.row_mut(n - 1).copy_from(&t.transpose());
        Some(m.lu())
    }

    fn correct_with(
        &self,
        u_pred: &DVector<f64>,
        t: &DVector<f64>,
        chord: bool,
        start: Option<Bordered>,
    ) -> Option<DVector<f64>> {
        let n = u_pred.len();
        let mut u = u_pred.clone();
        let mut lu = start;
        let mut last = f64::INFINITY;
        for _ in 0..if chord { 40 } else { 25 } {
            let r = self.modes(&u)?.0;
            let res = r.amax();
            if lu.is_none() || !chord || res > 0.25 * last {
                lu = Some(self.bordered(&u, t)?);
            }
            last = res;
            let mut rhs = DVector::zeros(n);
            rhs.rows_mut(0, n - 1).copy_from(&(-&r));
            rhs[n - 1] = -t.dot(&(&u - u_pred));
            let step = lu.as_ref()?.solve(&rhs)?;
            if !step.iter().all(|v| v.is_finite()) {
                return None;
            }
            u += &step;
            if step.amax() < 1e-12 * (1.0 + u.amax()) {
                let (r, _) = self.modes(&u)?;
                return (r.amax() < super::RESIDUAL_TOLERANCE).then_some(u);
            }
        }
        None
    }

    /// Trace the family from `start` (a converged state) towards smaller
    /// ā, for at most `max_points` points or until ā < `a_min`, with
    /// arclength steps (in u) adapted between 1e-4 and `max_step`. Every
    /// fold in ā, minimum of F̄ (refined) and sign change of the bordered
    /// determinant (a bifurcation) is an event. A step that cannot be
    /// corrected even at the smallest size is an error that says where.
    pub fn trace(
        &self,
        start: &ExactState,
        a_min: f64,
        max_step: f64,
        max_points: usize,
    ) -> Result<Branch> {
        self.trace_until(start, a_min, max_step, max_points, false)
    }

    /// Trace from `start` with ā first moving in `direction` (+1: growing,
    /// −1: shrinking) until ā leaves [`a_min`, `a_max`] or `max_points`
    /// points are traced; events as in [`Exact::trace`].
    pub fn trace_from(
        &self,
        start: &ExactState,
        direction: f64,
        a_min: f64,
        a_max: f64,
        max_step: f64,
        max_points: usize,
    ) -> Result<Branch> {
        self.trace_general(
            start, direction, a_min, a_max, max_step, max_points, false, None,
        )
        .map(|(b, _)| b)
    }

    /// The load-controlled pull-off: the first minimum of F̄ along the
    /// family traced from the state at ā = 2.6 (continued in ρ from the
    /// circle; 2.6 lies between the circle's neutral points ā³ = 12 and
    /// ā³ = 20) towards smaller ā, with the events met on the way.
    pub fn pull_off_load(&self) -> Result<(ExactState, Vec<Event>)> {
        let start = self.from_circle(2.6)?;
        let branch = self.trace_until(&start, 0.5, 0.05, 200, true)?;
        let po = branch.events.iter().find_map(|e| match e {
            Event::ForceMinimum { state } => Some((**state).clone()),
            _ => None,
        });
        match po {
            Some(st) if st.bc_error > super::RESOLVED => Err(Error::Unresolved {
                what: format!(
                    "exact pull-off at rho = {} with {} contour modes (max |dp/dnu - 1| = {:.1e} on the fine grid, above {:.0e}; the contour is {:.1e} a off the ellipse): use more modes",
                    self.rho, self.truncation.modes, st.bc_error, super::RESOLVED, st.deviation_from_ellipse
                ),
                residual: st.bc_error,
            }),
            Some(st) => Ok((st, branch.events)),
            None => Err(Error::NoState(format!(
                "exact pull-off at rho = {}: no minimum of the force along the traced family (down to a_bar = {})",
                self.rho,
                branch.points.last().map(|p| p.state.a_bar).unwrap_or(f64::NAN)
            ))),
        }
    }

    fn trace_until(
        &self,
        start: &ExactState,
        a_min: f64,
        max_step: f64,
        max_points: usize,
        stop_at_force_minimum: bool,
    ) -> Result<Branch> {
        self.trace_general(
            start,
            -1.0,
            a_min,
            f64::INFINITY,
            max_step,
            max_points,
            stop_at_force_minimum,
            None,
        )
        .map(|(b, _)| b)
    }

    /// Trace from `start` with ā first moving in the direction of
    /// `direction` (±1), between `a_min` and `a_max`; stop at the first
    /// force minimum when asked, or at the first crossing of
    /// `control` = target, which is refined and returned.
    #[allow(clippy::too_many_arguments)]
    fn trace_general(
        &self,
        start: &ExactState,
        direction: f64,
        a_min: f64,
        a_max: f64,
        max_step: f64,
        max_points: usize,
        stop_at_force_minimum: bool,
        control: Option<ExactControl>,
    ) -> Result<(Branch, Option<ExactState>)> {
        let n = self.truncation.modes + 2;
        let da = a_bar_gradient(n);
        let fail = |st: &ExactState, why: String| Error::NoConvergence {
            iterations: 25,
            a_bar: st.a_bar,
            s: st.s,
            residual: f64::NAN,
            context: format!("exact branch at rho = {}: {why}", self.rho),
        };
        let mut u = self.unknowns(start);
        let (_, j, g) = linearise(self, &u).ok_or_else(|| fail(start, "singular start".into()))?;
        // the initial tangent points to ā moving in `direction`
        let (mut t, mut det) =
            tangent(&j, &(&da * direction)).ok_or_else(|| fail(start, "no tangent".into()))?;
        if t.dot(&da) * direction < 0.0 {
            t = -t;
        }
        let key = |u: &DVector<f64>, force: f64| match control {
            Some(ExactControl::Delta(target)) => u[n - 1] - target,
            Some(ExactControl::Force(target)) => force - target,
            None => f64::NAN,
        };
        let mut points = vec![BranchPoint {
            state: start.clone(),
            d_force: g.dot(&t),
            d_a_bar: da.dot(&t),
        }];
        let mut events = Vec::new();
        let mut h = max_step;
        while points.len() < max_points {
            let last = points.last().expect("one point").state.clone();
            if last.a_bar < a_min || last.a_bar > a_max {
                break;
            }
            let Some(un) = self.correct(&(&u + &t * h), &t) else {
                if h <= 1e-4 {
                    return Err(fail(
                        &last,
                        format!(
                            "no corrected point at step {h:e} after a_bar = {}",
                            last.a_bar
                        ),
                    ));
                }
                h = (h * 0.5).max(1e-4);
                continue;
            };
            let (_, j, g) =
                linearise(self, &un).ok_or_else(|| fail(&last, "singular system".into()))?;
            let Some((tn, detn)) = tangent(&j, &t) else {
                return Err(fail(&last, "no tangent".into()));
            };
            // a step that turns the tangent by more than ~18° may have
            // jumped to another sheet of the family: retry it shorter
            if tn.dot(&t) < 0.95 && h > 1e-4 {
                h = (h * 0.5).max(1e-4);
                continue;
            }
            let st = self.state(&un)?;
            let p = BranchPoint {
                d_force: g.dot(&tn),
                d_a_bar: da.dot(&tn),
                state: st,
            };
            let prev = points.last().expect("one point");
            if prev.d_a_bar.signum() != p.d_a_bar.signum() {
                events.push(Event::SizeFold {
                    a_bar: p.state.a_bar,
                });
                if control.is_some() {
                    // a state asked for by δ̄ or F̄ is looked for on the
                    // near-elliptical stretch only: past a size fold the
                    // contour turns strongly non-elliptical
                    points.push(p);
                    break;
                }
            }
            if detn.signum() != det.signum() {
                events.push(Event::Bifurcation {
                    between: [prev.state.a_bar, p.state.a_bar],
                    mode: null_mode(&j, &t),
                });
            }
            if control.is_some() {
                let (k0, k1) = (key(&u, prev.state.force_bar), key(&un, p.state.force_bar));
                if k0 == 0.0 {
                    let hit = prev.state.clone();
                    return Ok((Branch { points, events }, Some(hit)));
                }
                if k0.signum() != k1.signum() {
                    let value = |v: &DVector<f64>| self.modes(v).map(|(_, force)| key(v, force));
                    let hit = self.refine(&u, &t, k0, &un, k1, &value, "exact state")?;
                    points.push(p);
                    return Ok((Branch { points, events }, Some(hit)));
                }
            }
            if prev.d_force < 0.0 && p.d_force >= 0.0 {
                let refined = self.minimise_force(&u, &t, &un)?;
                events.push(Event::ForceMinimum {
                    state: Box::new(refined),
                });
                if stop_at_force_minimum {
                    points.push(p);
                    break;
                }
            }
            u = un;
            t = tn;
            det = detn;
            points.push(p);
            h = (h * 1.3).min(max_step);
        }
        Ok((Branch { points, events }, None))
    }

    /// The state at `control` started from the richest `conformal:K`'s
    /// (K = 8) state at the
    /// same control: Newton at its ā from the ellipse with its ā and b̄
    /// and its δ̄, then the family traced to the control (a step or two).
    /// `None` where the model has no state there (ρ below its range), the
    /// start does not converge, or the answer is not near the model's
    /// (within 2 % in ā, 5 % in s) and near-elliptical (boundary error
    /// below 1e-2); the caller decides whether it is resolved.
    fn from_model(&self, control: ExactControl) -> Option<ExactState> {
        use crate::conformal::{Conformal, Control};
        // the richest member generated
        let model: Conformal = crate::conformal::members().last()?;
        let guess = model
            .solve(
                self.rho,
                match control {
                    ExactControl::Delta(v) => Control::Delta(v),
                    ExactControl::Force(v) => Control::Force(v),
                },
            )
            .ok()?;
        let nm = self.truncation.modes;
        let start = self.solve(
            guess.a_bar,
            &super::Contour::ellipse(guess.a_bar, guess.b_bar, nm),
            guess.delta_bar,
        );
        let start = start.ok()?;
        // the exact state near the model's: same side of the circle's
        // bifurcations (a contour within a few per cent of the model's)
        if (start.s / guess.s - 1.0).abs() > 0.05 {
            return None;
        }
        let here = match control {
            ExactControl::Delta(v) => start.delta_bar - v,
            ExactControl::Force(v) => start.force_bar - v,
        };
        let direction = if here < 0.0 { 1.0 } else { -1.0 };
        let (_, found) = self
            .trace_general(
                &start,
                direction,
                0.5,
                1e3,
                0.02,
                200,
                direction < 0.0,
                Some(control),
            )
            .ok()?;
        let mut st = found?;
        // near-elliptical and near the model's (an unresolved answer is
        // still returned: more contour modes may resolve it)
        if st.bc_error > 1e-2 || (st.a_bar / guess.a_bar - 1.0).abs() > 0.02 {
            return None;
        }
        st.route = Route::FromModel;
        Some(st)
    }

    /// The exact state at approach δ̄ or force F̄. First from the richest
    /// model's state at the same control ([`Route::FromModel`]: only a
    /// start, the state is the exact family's, accepted near the model's;
    /// found but not resolved with this truncation, an
    /// [`Error::Unresolved`] that asks for more modes). Otherwise
    /// ([`Route::FromCircle`]) the exact circle at
    /// ρ = 1 with the same δ̄ or F̄ (δ̄ = ā²/4 − 2/ā, F̄ = π(ā⁶ − 24ā³)/96,
    /// (22)–(25); for F̄ the root above the pull-off) is continued in ρ at
    /// its ā ([`Exact::from_circle`]), and the family is traced from there
    /// in steps of at most 0.02 to the requested value. The trace stays on
    /// the near-elliptical arm it starts on: it stops at a size fold (where
    /// the arm turns into an undulated contour at an imperfect bifurcation
    /// of a mode n, near the circle's ā³ = 4(n − 1)) and at the
    /// load-controlled pull-off; no approximate model is used on this
    /// route. An unresolved state is [`Error::Unresolved`], a value not reached is
    /// [`Error::NoState`] saying where the arm ended.
    pub fn at(&self, control: ExactControl) -> Result<ExactState> {
        let a_circle = match control {
            ExactControl::Delta(v) => circle_a_bar_at_delta(v),
            ExactControl::Force(v) => {
                let disc = 144.0 + 96.0 * v / std::f64::consts::PI;
                if disc.is_nan() || disc < 0.0 {
                    return Err(Error::NoState(format!(
                        "exact state at rho = {}: F = {v:e} is below the pull-off force of the circle, -3 pi/2, and so below that of every rho",
                        self.rho
                    )));
                }
                (12.0 + disc.sqrt()).cbrt()
            }
        };
        if !(a_circle.is_finite() && a_circle > 0.0) {
            return Err(Error::NoState(format!(
                "exact state at rho = {}: {control} has no circle to start from",
                self.rho
            )));
        }
        // first from the richest model at the same control (the contour
        // family converges to the exact solution); its answer is accepted
        // only resolved (below), so a start that lands elsewhere falls
        // back to the circle's route
        // (found but not resolved with this truncation: the same state by
        // the circle's route would be no better resolved, so more modes
        // are asked for at once)
        if let Some(st) = self.from_model(control) {
            if st.bc_error <= super::RESOLVED {
                return Ok(st);
            }
            return Err(Error::Unresolved {
                what: format!(
                    "exact state at rho = {}, {control}: max |dp/dnu - 1| = {:.1e} with {} modes ({})",
                    self.rho, st.bc_error, self.truncation.modes, st.route
                ),
                residual: st.bc_error,
            });
        }
        // a start whose arm folds before the value is reached is retried
        // once from the far side of the fold (0.3 beyond it in ā)
        let mut a_start = a_circle;
        let mut ends = Vec::new();
        let st = loop {
            let start = self.from_circle(a_start)?;
            let here = match control {
                ExactControl::Delta(v) => start.delta_bar - v,
                ExactControl::Force(v) => start.force_bar - v,
            };
            // on the near-elliptical arms above the pull-off δ̄ and F̄ grow with ā
            let direction = if here < 0.0 { 1.0 } else { -1.0 };
            let (branch, found) = self.trace_general(
                &start,
                direction,
                0.5,
                1e3,
                0.02,
                2000,
                direction < 0.0,
                Some(control),
            )?;
            if let Some(st) = found {
                break st;
            }
            let fold = branch.events.iter().find_map(|e| match e {
                Event::SizeFold { a_bar } => Some(*a_bar),
                _ => None,
            });
            let end = match (fold, branch.events.iter().find_map(|e| match e {
                Event::ForceMinimum { state } => Some(state.force_bar),
                _ => None,
            })) {
                (Some(a_bar), _) => format!(
                    "the arm through the circle's a_bar = {a_start:.6} continued in rho (contour {:.1e} a off the ellipse there) folds at a_bar = {a_bar:.6} (an imperfect bifurcation: beyond it the contour turns undulated)",
                    start.deviation_from_ellipse
                ),
                (None, Some(force)) => format!(
                    "the arm through the circle's a_bar = {a_start:.6} continued in rho (contour {:.1e} a off the ellipse there) reaches its load-controlled pull-off, F = {force:.6}, first",
                    start.deviation_from_ellipse
                ),
                _ => format!(
                    "the trace from the circle's a_bar = {a_start:.6} ended at a_bar = {:.6}",
                    branch.points.last().map(|p| p.state.a_bar).unwrap_or(f64::NAN)
                ),
            };
            ends.push(end);
            match fold {
                Some(a_bar) if ends.len() < 2 => a_start = a_bar + 0.3 * direction,
                _ => {
                    return Err(Error::NoState(format!(
                        "exact state at rho = {}: {} is not reached: {}",
                        self.rho,
                        control,
                        ends.join("; then ")
                    )))
                }
            }
        };
        if st.bc_error > super::RESOLVED {
            return Err(Error::Unresolved {
                what: format!(
                    "exact state at rho = {}, {control}: max |dp/dnu - 1| = {:.1e} with {} modes",
                    self.rho, st.bc_error, self.truncation.modes
                ),
                residual: st.bc_error,
            });
        }
        Ok(st)
    }

    /// The minimum of F̄ between two traced points u0 (tangent t0,
    /// dF̄/dσ < 0) and u1 (dF̄/dσ ≥ 0), by golden-section search on F̄ of
    /// the corrected points along the arclength σ from u0 (F̄ values, not
    /// dF̄/dσ: at ρ = 1 the minimum sits on the bifurcation point of the
    /// mode n = 4, ā³ = 12, where the tangent is not defined). 45 steps
    /// shrink the bracket by 0.618⁴⁵ ≈ 4e-10; F̄ is flat there, so its
    /// error is of the order of the square of that.
    fn minimise_force(
        &self,
        u0: &DVector<f64>,
        t0: &DVector<f64>,
        u1: &DVector<f64>,
    ) -> Result<ExactState> {
        let fail = |sigma: f64| {
            Error::NoState(format!(
                "exact pull-off at rho = {}: no corrected point near sigma = {sigma}",
                self.rho
            ))
        };
        let jac0 = self.bordered(u0, t0).ok_or_else(|| fail(0.0))?;
        let at = |sigma: f64| -> Result<(DVector<f64>, f64)> {
            let u = [
                0.0, 1e-9, -1e-9, 1e-7, -1e-7, 1e-6, -1e-6, 1e-5, -1e-5, 1e-4, -1e-4,
            ]
            .iter()
            .find_map(|off| {
                self.correct_near(&(u0 + t0 * (sigma + off * (1.0 + sigma.abs()))), t0, &jac0)
            })
            .ok_or_else(|| fail(sigma))?;
            let (_, force) = self.modes(&u).ok_or_else(|| fail(sigma))?;
            Ok((u, force))
        };
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let (mut lo, mut hi) = (0.0, t0.dot(&(u1 - u0)));
        let mut x1 = hi - g * (hi - lo);
        let mut x2 = lo + g * (hi - lo);
        let (mut p1, mut f1) = at(x1)?;
        let (mut p2, mut f2) = at(x2)?;
        for _ in 0..45 {
            if f1 < f2 {
                hi = x2;
                (x2, p2, f2) = (x1, p1.clone(), f1);
                x1 = hi - g * (hi - lo);
                (p1, f1) = at(x1)?;
            } else {
                lo = x1;
                (x1, p1, f1) = (x2, p2.clone(), f2);
                x2 = lo + g * (hi - lo);
                (p2, f2) = at(x2)?;
            }
        }
        self.state(if f1 < f2 { &p1 } else { &p2 })
    }

    /// The zero of `value` between two traced points (u0 with tangent t0
    /// and value f0, u1 with value f1 of the other sign), by regula falsi
    /// (Illinois) on the arclength σ from u0: σ stays inside the bracket.
    /// A point where the bordered system is singular (a bifurcation
    /// point) is corrected a little beside it (from 1e-9 in σ up).
    #[allow(clippy::too_many_arguments)]
    fn refine(
        &self,
        u0: &DVector<f64>,
        t0: &DVector<f64>,
        f0: f64,
        u1: &DVector<f64>,
        f1: f64,
        value: &dyn Fn(&DVector<f64>) -> Option<f64>,
        what: &str,
    ) -> Result<ExactState> {
        let (mut sa, mut fa) = (0.0, f0);
        let (mut sb, mut fb) = (t0.dot(&(u1 - u0)), f1);
        let mut best = u1.clone();
        let fail = |why: &str| Error::NoState(format!("{what} at rho = {}: {why}", self.rho));
        let jac0 = self
            .bordered(u0, t0)
            .ok_or_else(|| fail("singular bordered system"))?;
        for _ in 0..60 {
            let sigma = sb - fb * (sb - sa) / (fb - fa);
            let u = [0.0, 1e-9, -1e-9, 1e-7, -1e-7, 1e-6, -1e-6, 1e-4, -1e-4]
                .iter()
                .find_map(|off| {
                    self.correct_near(&(u0 + t0 * (sigma + off * (1.0 + sigma.abs()))), t0, &jac0)
                })
                .ok_or_else(|| fail(&format!("no corrected point near sigma = {sigma}")))?;
            let f = value(&u).ok_or_else(|| fail("singular system"))?;
            best = u;
            if f == 0.0 || (sb - sa).abs() < 1e-12 * (1.0 + sigma.abs()) {
                break;
            }
            if f.signum() == fb.signum() {
                fa *= 0.5;
            } else {
                (sa, fa) = (sb, fb);
            }
            (sb, fb) = (sigma, f);
            if (sigma - sa).abs() < 1e-12 * (1.0 + sigma.abs()) {
                break;
            }
        }
        self.state(&best)
    }
}
