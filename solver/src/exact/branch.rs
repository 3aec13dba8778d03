//! The solution family of the exact problem traced by the one continuation
//! engine (`crate::continuation`) in u = (A, b₀..b_{N−1}, δ̄), with ā
//! free: the family can turn back in ā (a fold of the contact size, where
//! the contour turns strongly non-elliptical near a bifurcation of the
//! circle branch), so ā is not a safe parameter. Folds in ā and in F̄ are
//! reported as data; the load-controlled pull-off is the first minimum of
//! F̄ along the family (at ρ = 1 it sits on a bifurcation point, where the
//! engine locates it by values of F̄). Bifurcation points are flagged where
//! the determinant of the bordered Jacobian [∂r/∂u; tᵀ] changes sign (at a
//! fold it does not). The Jacobian is the derivative of the discrete
//! equations (`exact::linear`); the corrector keeps it while the residual
//! falls fast (the chord method).
//!
//! Owns: [`Branch`], [`BranchPoint`], [`Event`], the family's
//! `Family` implementation. May use: `control`, `fold`, `exact`, `continuation`, `error`,
//! `newton` (its stop check),
//! `exact::seed` (the gap's seed, the richest member's state, as a start).

use super::gap::GapAt;
use super::same::Same;
use super::seed::Guess;
use super::{Exact, ExactState, Gap, Route};
use crate::continuation::{self, EventKind, Family, Linear, On, Settings, Watch};
use crate::control::Hold;
use crate::control::Quantity;
use crate::error::{Error, Result};
use nalgebra::{DMatrix, DVector, Dyn};
use serde::Serialize;

/// How far above the richest model's pull-off, in ā, the exact
/// pull-off's trace starts ([`Exact::pull_off_load`]): `conformal:8`
/// misses the exact pull-off's ā by 1e-5 (ρ = 0.8) to 1e-3 (ρ = 0.5), and
/// the trace must start above it on the same arm.
pub(crate) const ABOVE_MODEL_PULL_OFF: f64 = 0.03;

/// How far above the exact pull-off with fewer modes, in ā, the trace of
/// the next truncation starts: more modes move the pull-off's ā by less
/// than 1e-6 where the coarser one is nearly resolved.
pub(crate) const ABOVE_COARSER_PULL_OFF: f64 = 0.005;

/// How many rays measure a traced contour's departure from its ellipse
/// ([`Exact::first_crossing_through_folds`]).
const DEPARTURE_POINTS: usize = 128;

/// Where a trace past a fold ([`Exact::crossings_past_fold`]) ends: the
/// contour's departure from an ellipse in its coefficients, Σ_{j≥1}|b_j|/ā,
/// above this. The exact pull-off at ρ = 0.8, past the fold of the mode-4
/// band, is 3.3e-2 ā off its ellipse; on the returning stretch of the
/// mode-10 band's lower arm at ρ = 0.6 the boundary error with 40 modes is
/// 5e-2 where the contour is 0.1 ā off its ellipse (a crossing found that
/// far out is not converged by the escalation, and is reported so).
pub(crate) const PAST_FOLD_DEPARTURE: f64 = 0.1;

/// The most steps of a trace past a fold.
pub(crate) const PAST_FOLD_STEPS: usize = 400;

/// How the trace of an arm towards a control ended
/// ([`Exact::first_crossing_through_folds`]).
#[derive(Clone, Debug)]
pub(crate) enum ArmEnd {
    /// The state at the control (of the trace's truncation).
    Reached(Box<ExactState>),
    /// The arm ended before the control: a minimum of F̄ or a departure
    /// from the ellipse beyond [`PAST_FOLD_DEPARTURE`].
    EndsBefore,
    /// [`PAST_FOLD_STEPS`] steps were taken without reaching the control.
    OutOfSteps,
    /// The series stopped following the arm before the control: at this
    /// point its fine-grid boundary error exceeds the bound asked for.
    Unresolved {
        /// ā there.
        a_bar: f64,
        /// F̄ there.
        force_bar: f64,
        /// The boundary error there.
        bc_error: f64,
        /// The trace's modes of each sign.
        modes: usize,
        /// The last state traced within the bound, where there is one, and
        /// the way ā moved into it (±1): where a longer series may take
        /// the trace on.
        resolved_before: Option<(Box<ExactState>, f64)>,
    },
}

/// How a trace to a fold in ā ended ([`Exact::to_size_fold_within`]).
#[derive(Clone, Debug)]
pub(crate) enum SizeFoldEnd {
    /// The located fold, with the contour mode of its null direction.
    Fold(Box<ExactState>, Option<usize>),
    /// ā passed the limit first.
    Beyond,
    /// The series stopped following the family first: at this traced
    /// point its fine-grid boundary error exceeds the bound (read by the
    /// command line's reach study, `studies::reach`).
    #[cfg_attr(not(feature = "cli"), allow(dead_code))]
    Unresolved {
        /// ā there.
        a_bar: f64,
        /// F̄ there.
        force_bar: f64,
        /// The boundary error there.
        bc_error: f64,
    },
}

/// Why a trace past a band's fold stopped ([`Exact::crossings_past_fold`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PastFoldStop {
    /// ā passed the gap's far side before any fold.
    CrossesGap,
    /// The arm folded a second time.
    SecondFold,
    /// Its departure from an ellipse exceeded [`PAST_FOLD_DEPARTURE`].
    Departs,
    /// [`PAST_FOLD_STEPS`] steps were taken.
    Budget,
}

/// How a trace past a band's fold ended: why, whether it had passed its
/// fold, and at which ā; in words by `Display`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PastFoldEnd {
    /// Why it stopped.
    pub stop: PastFoldStop,
    /// Whether the arm had folded before.
    pub folded: bool,
    /// ā of the last traced point.
    pub a_bar: f64,
}

impl std::fmt::Display for PastFoldEnd {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let a = self.a_bar;
        let why = match self.stop {
            PastFoldStop::Budget => {
                return write!(f, "stopped after {PAST_FOLD_STEPS} steps at a = {a:.4}")
            }
            PastFoldStop::CrossesGap => "crosses the gap without folding",
            PastFoldStop::SecondFold => "folds a second time",
            PastFoldStop::Departs => {
                "departs from an ellipse by more than 0.1 a in its coefficients"
            }
        };
        if self.folded {
            write!(f, "followed past its fold until it {why}, at a = {a:.4}")
        } else {
            write!(f, "{why} (at a = {a:.4})")
        }
    }
}

/// The seeding model's (the largest member of the family that seeds the
/// exact solver of `gap`, `conformal:8` for the cylinders') load-controlled
/// pull-off at `rho`, where it has one: the start of the exact pull-off's
/// trace.
pub(crate) fn model_pull_off(gap: Gap, rho: f64) -> Option<Guess> {
    gap.seed?.pull_off(rho)
}

/// What happens between two traced points.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum Event {
    /// ā turns (a fold of the contact size) near this ā.
    SizeFold {
        /// ā at the fold: located, or the traced point after it where the
        /// trace does not locate folds.
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
    /// The exact state the event holds, if any.
    pub(crate) fn state_mut(&mut self) -> Option<&mut ExactState> {
        match self {
            Event::ForceMinimum { state } => Some(state),
            _ => None,
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

/// The half-width of the exact circle (ρ = 1) of the gap `circle` (at
/// ρ = 1) at `control` ((22)–(25) for the cylinders): for F̄ the root of
/// F̄(ā) = F̄ above the circle's pull-off ([`circle_pull_off`]); NaN below
/// that pull-off's force.
pub(crate) fn circle_a_bar(circle: &GapAt, control: Hold) -> f64 {
    match control {
        Hold::Delta(v) => increasing_root(|a| circle.circle_delta(a), v, 1e-12),
        Hold::Size(a) => a,
        Hold::Force(v) => {
            let (a_po, f_po) = circle_pull_off(circle);
            if v.is_nan() || v < f_po {
                f64::NAN
            } else {
                increasing_root(|a| circle.circle_force(a), v, a_po)
            }
        }
    }
}

/// The circle's load-controlled pull-off (ā, F̄) at ρ = 1: the minimum
/// of F̄(ā) (golden section; for the cylinders ā³ = 12, F̄ = −3π/2).
pub(crate) fn circle_pull_off(circle: &GapAt) -> (f64, f64) {
    let f = |a: f64| circle.circle_force(a);
    // bracket: F̄ falls from ā → 0, then rises
    let mut hi = 1.0;
    while hi < 1e6 && f(2.0 * hi) < f(hi) {
        hi *= 2.0;
    }
    let (mut lo, mut hi) = (hi / 2.0_f64.powi(2), 2.0 * hi);
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..200 {
        let (c, d) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if f(c) < f(d) {
            hi = d;
        } else {
            lo = c;
        }
    }
    let a = 0.5 * (lo + hi);
    (a, f(a))
}

/// The root above `lo` of g(ā) = v, g increasing there, by bisection.
fn increasing_root(g: impl Fn(f64) -> f64, v: f64, lo: f64) -> f64 {
    if !v.is_finite() {
        return f64::NAN;
    }
    let (mut lo, mut hi) = (lo, lo.max(1e-12) * 2.0 + 1.0);
    while g(hi) < v && hi < 1e12 {
        hi *= 2.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if g(mid) < v {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Residuals, F̄, Jacobian and ∇F̄ at u, from one linearisation
/// ([`Exact::linear`]).
#[allow(clippy::type_complexity)]
fn linearise(
    ex: &Exact,
    u: &DVector<f64>,
) -> Option<(DVector<f64>, f64, DMatrix<f64>, DVector<f64>)> {
    let lin = ex.linear(u)?;
    let (r, j) = (ex.family_residuals(&lin.dn, u), ex.mode_jacobian(&lin, u));
    Some((r, lin.force, j, lin.d_force))
}

/// The contour mode of the near-null direction of the bordered Jacobian
/// [∂r/∂u; tᵀ] at u: the right singular vector of its smallest singular
/// value, named by the spectrum of its normal motion along the contour
/// (`crate::contour_modes`); 0 when the size (A, or δ̄) dominates. `None`
/// when the SVD gives no singular vectors.
fn null_mode(ex: &Exact, u: &DVector<f64>, bordered: &DMatrix<f64>) -> Option<usize> {
    let v = smallest_right_singular_vector(bordered)?;
    ex.normal_motion(&ex.contour_of(u)).mode_of(&v, false)
}

/// The contour mode of the null direction of the state equations at fixed
/// ā (singular at a fold in ā), held in `held` at u: A and δ̄ move with
/// it, so it is named by the largest amplitude among the shape's modes
/// n ≥ 2 of its normal motion along the contour (`crate::contour_modes`).
/// `None` when the SVD gives no singular vectors.
fn contour_mode(ex: &Exact, u: &DVector<f64>, held: &DMatrix<f64>) -> Option<usize> {
    let v = smallest_right_singular_vector(held)?;
    ex.normal_motion(&ex.contour_of(u)).mode_of(&v, true)
}

/// The right singular vector of the smallest singular value of `a`.
fn smallest_right_singular_vector(a: &DMatrix<f64>) -> Option<DVector<f64>> {
    let svd = a.clone().svd(false, true);
    let v_t = svd.v_t.as_ref()?;
    let k = svd.singular_values.imin();
    Some(v_t.row(k).transpose())
}

/// The exact family's step control: arclength steps in u between 1e-4 and
/// `max_step` (grown by 1.3), the chord corrector, at most `max_steps`.
fn trace_settings(max_step: f64, max_steps: usize) -> Settings {
    Settings {
        step: max_step,
        min_step: 1e-4,
        max_step,
        grow: 1.3,
        fast_iterations: usize::MAX,
        turn: 0.95,
        corrector_iterations: 20,
        step_tolerance: 1e-12,
        max_steps,
    }
}

/// dā/du: ā = A + Σ b_j.
fn a_bar_gradient(n: usize) -> DVector<f64> {
    let mut g = DVector::from_element(n, 1.0);
    g[n - 1] = 0.0;
    g
}

/// The family's n − 1 residuals with a zero row below: the engine's row
/// of the arclength condition.
fn padded(r: &DVector<f64>) -> DVector<f64> {
    r.clone().insert_row(r.len(), 0.0)
}

/// dF̄/dā along the family at a converged state, du/dā, and the factorised
/// Jacobian of the equations at fixed ā there
/// ([`Exact::force_slope_in_size`]).
pub(crate) struct SlopeInSize {
    pub(crate) slope: f64,
    du: DVector<f64>,
    lu: nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>,
}

/// The first step in ā of the secant on dF̄/dā
/// ([`Exact::force_minimum_in_size_stepping`]).
#[derive(Clone, Copy, Debug)]
pub(crate) enum FirstStep {
    /// This long, downhill.
    Downhill(f64),
    /// Newton's step −(dF̄/dā)/κ with a predicted curvature κ = d²F̄/dā²
    /// (at most 0.05 long; downhill by 0.01 where κ is not positive).
    ByCurvature(f64),
}

/// The exact family at one ρ and truncation.
impl Family<Dyn> for Exact {
    fn linearise(&self, u: &DVector<f64>) -> Option<Linear<Dyn>> {
        let (r, force, j, g) = linearise(self, u)?;
        let n = u.len();
        let mut jj = DMatrix::zeros(n, n);
        jj.rows_mut(0, n - 1).copy_from(&j);
        Some(Linear {
            r: padded(&r),
            j: jj,
            force,
            force_grad: g,
        })
    }

    fn residuals(&self, u: &DVector<f64>) -> Option<DVector<f64>> {
        self.residuals_and_force(u).map(|(r, _)| r)
    }

    fn residuals_and_force(&self, u: &DVector<f64>) -> Option<(DVector<f64>, f64)> {
        let (r, force) = self.modes(u)?;
        Some((padded(&r), force))
    }

    fn converged(&self, u: &DVector<f64>, r: &DVector<f64>) -> bool {
        r.rows(0, u.len() - 1).amax() < super::RESIDUAL_TOLERANCE
    }

    fn a_bar_gradient(&self) -> DVector<f64> {
        a_bar_gradient(self.unknown_count())
    }

    fn delta_bar_gradient(&self) -> DVector<f64> {
        let n = self.unknown_count();
        let mut g = DVector::zeros(n);
        g[n - 1] = 1.0;
        g
    }

    fn chord(&self) -> bool {
        true
    }

    fn bifurcation_mode(&self, u: &DVector<f64>, bordered: &DMatrix<f64>) -> Option<usize> {
        null_mode(self, u, bordered)
    }

    fn stuck(&self, u: &DVector<f64>, why: &str) -> Error {
        let contour = self.contour_of(u);
        let (a_bar, b_bar) = (contour.a_bar(), contour.b_bar());
        Error::NoConvergence {
            iterations: 25,
            a_bar,
            s: b_bar / a_bar,
            residual: f64::NAN,
            context: format!(
                "exact branch at rho = {}: {why}",
                crate::error::rounded(self.rho)
            ),
        }
    }
}

impl Exact {
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
        self.trace_from(start, -1.0, a_min, f64::INFINITY, max_step, max_points)
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
    /// family traced towards smaller ā, with the events met on the way,
    /// from the exact state just above the richest model's pull-off
    /// ([`Route::AboveModelPullOff`]) or, where there is none, from the
    /// state at ā = 2.6 continued in ρ from the circle (2.6 lies between
    /// the circle's neutral points ā³ = 12 and ā³ = 20).
    pub fn pull_off_load(&self) -> Result<(ExactState, Vec<Event>)> {
        self.pull_off_load_near(model_pull_off(self.gap(), self.rho).as_ref(), None)
    }

    /// [`Exact::pull_off_load`] with the richest model's pull-off given
    /// (`model`, computed once for every truncation tried), and started
    /// from just above `coarser`, the exact pull-off with fewer contour
    /// modes, where given (its contour padded with zeros): the escalation of
    /// [`super::pull_off_resolved`].
    pub(crate) fn pull_off_load_near(
        &self,
        model: Option<&Guess>,
        coarser: Option<&ExactState>,
    ) -> Result<(ExactState, Vec<Event>)> {
        self.pull_off_found(model, coarser)
            .and_then(|found| self.accept_resolved_pull_off(found))
    }

    /// The pull-off [`Exact::pull_off_load_near`] finds, resolved or not.
    pub(crate) fn pull_off_found(
        &self,
        model: Option<&Guess>,
        coarser: Option<&ExactState>,
    ) -> Result<(ExactState, Vec<Event>)> {
        let from_coarser = coarser.and_then(|c| {
            let st = self.solve_from(c.a_bar + ABOVE_COARSER_PULL_OFF, c).ok()?;
            Same::SAME_SIDE.of(&st, c).then_some((st, c.route))
        });
        // on a gap no circle solves, the walk in the gap from the cylinders'
        // first (issue 73): a seeding member's pull-off may lie on another
        // arm of such a gap (on the bumpy gap at rho = 1, -4.1106 at
        // a = 1.974 against the walk's -4.0799 at 2.049)
        let walked = || -> Result<(ExactState, Route)> {
            let st = self.continued_in_the_gap(self.trace_start())?;
            let route = st.route;
            Ok((st, route))
        };
        let (start, route) = match from_coarser {
            Some(found) => found,
            None if !self.circle.is_radial() => match walked() {
                Ok(found) => found,
                Err(e) => match model.and_then(|m| self.above_model_pull_off(m)) {
                    Some(st) => (st, Route::AboveModelPullOff),
                    None => return Err(e),
                },
            },
            None => match model.and_then(|m| self.above_model_pull_off(m)) {
                Some(st) => (st, Route::AboveModelPullOff),
                None => walked()?,
            },
        };
        // downhill in F̄: from above the minimum (the circle's and the
        // model's starts) towards smaller ā; a start continued in the gap
        // may lie on either side of it
        let direction = match route {
            Route::FromCylinders => self
                .force_slope_in_size(&self.unknowns(&start))
                .map_or(-1.0, |s| -s.slope.signum()),
            _ => -1.0,
        };
        let (branch, _) =
            self.trace_general(&start, direction, 0.5, f64::INFINITY, 0.05, 200, true, None)?;
        let po = branch.events.iter().find_map(|e| match e {
            Event::ForceMinimum { state } => Some(ExactState {
                route,
                ..(**state).clone()
            }),
            _ => None,
        });
        match po {
            Some(st) => Ok((st, branch.events)),
            None => Err(Error::NoState(format!(
                "exact pull-off at rho = {}: no minimum of the force along the traced family (down to a_bar = {})",
                crate::error::rounded(self.rho),
                crate::error::rounded(branch.points.last().map(|p| p.state.a_bar).unwrap_or(f64::NAN))
            ))),
        }
    }

    /// dF̄/dā along the family at the converged unknowns `u`, with du/dā:
    /// the state equations at fixed ā (their Jacobian, the hold's row
    /// first) differentiated in ā. `None` where that Jacobian is singular
    /// (a fold in ā).
    pub(crate) fn force_slope_in_size(&self, u: &DVector<f64>) -> Option<SlopeInSize> {
        let nu = self.unknown_count();
        let lin = self.linear(u)?;
        let mut jac = DMatrix::zeros(nu, nu);
        jac.view_mut((0, 0), (1, nu))
            .copy_from(&a_bar_gradient(nu).transpose());
        jac.view_mut((1, 0), (nu - 1, nu))
            .copy_from(&self.mode_jacobian(&lin, u));
        let mut e = DVector::zeros(nu);
        e[0] = 1.0;
        let lu = jac.lu();
        let du = lu.solve(&e)?;
        let slope = lin.d_force.dot(&du);
        slope.is_finite().then_some(SlopeInSize { slope, du, lu })
    }

    /// The minimum of F̄ over ā on the arm through `start`, the unknowns
    /// of a converged state of this truncation (no fine-grid check of the
    /// start: only the minimum is checked, as [`Exact::state`] checks every
    /// state it returns), with ā as the family's parameter: the
    /// secant method on dF̄/dā = 0 ([`Exact::force_slope_in_size`]), each
    /// state solved at its ā from the tangent's prediction, the first step
    /// 0.01 downhill, steps at most 0.05, ā within 0.3 of `start`'s. A
    /// minimum only: the secant's slope of dF̄/dā is positive where it
    /// stops (|Δā| below 1e-10 ā). An error where that fails (a fold in ā
    /// between, or no minimum near), for the caller's trace to take over
    /// ([`Exact::force_minimum_nearest`]). Far cheaper than the trace: a
    /// handful of states at fixed ā, each one or two Newton steps.
    pub(crate) fn force_minimum_in_size_from(&self, start: DVector<f64>) -> Result<ExactState> {
        self.force_minimum_in_size_stepping(start, FirstStep::Downhill(0.01))
    }

    /// [`Exact::force_minimum_in_size_from`] with the first step `first`
    /// in ā: by a predicted curvature where `start` is already near the
    /// minimum (a prediction), so that the secant's second slope of dF̄/dā
    /// is taken closer to it still.
    pub(crate) fn force_minimum_in_size_stepping(
        &self,
        start: DVector<f64>,
        first: FirstStep,
    ) -> Result<ExactState> {
        let start_a = self.contour_of(&start).a_bar();
        let failed = |why: &str| {
            Error::NoState(format!(
                "the force minimum near a_bar = {} at rho = {} by the secant method in a_bar: {why}",
                crate::error::rounded(start_a),
                crate::error::rounded(self.rho)
            ))
        };
        let id = self.unknown_count() - 1;
        let mut u = start;
        let mut a = start_a;
        let SlopeInSize {
            slope: mut g,
            mut du,
            mut lu,
        } = self
            .force_slope_in_size(&u)
            .ok_or_else(|| failed("the state equations at fixed a_bar are singular"))?;
        let mut step = match first {
            FirstStep::ByCurvature(k) if k > 0.0 => (-g / k).clamp(-0.05, 0.05),
            FirstStep::ByCurvature(_) => -0.01 * g.signum(),
            FirstStep::Downhill(h) => -h.abs() * g.signum(),
        };
        let mut before: Option<(f64, f64)> = None;
        for _ in 0..30 {
            crate::newton::check_stop()?;
            if let Some((a0, g0)) = before {
                let curvature = (g - g0) / (a - a0);
                step = if curvature > 0.0 {
                    (-g / curvature).clamp(-0.05, 0.05)
                } else {
                    // not yet convex: further downhill
                    -0.05 * g.signum()
                };
                if step.abs() <= 1e-10 * a && curvature > 0.0 {
                    return self.state(&u);
                }
            }
            let next = a + step;
            if (next - start_a).abs() > 0.3 {
                return Err(failed("it left a_bar within 0.3 of the start"));
            }
            // from the tangent's prediction, its Jacobian the one of the
            // state stepped from (the same equations at fixed ā: the chord
            // iteration refreshes it where it stops serving), else from the
            // state itself
            let guess = &u + &du * step;
            let solved = self
                .newton_from(Hold::Size(next), guess, Some(lu))
                .or_else(|_| self.newton(Hold::Size(next), &self.contour_of(&u), u[id]))?;
            let slope = self
                .force_slope_in_size(&solved)
                .ok_or_else(|| failed("the state equations at fixed a_bar are singular"))?;
            before = Some((a, g));
            (u, a) = (solved, next);
            SlopeInSize { slope: g, du, lu } = slope;
        }
        Err(failed("no convergence in 30 steps"))
    }

    /// d²F̄/dā² along the family at the converged unknowns `u` of this
    /// truncation: the central difference of dF̄/dā
    /// ([`Exact::force_slope_in_size`]) at ā ± 10⁻³ā, each state solved at
    /// its ā from the tangent's prediction (error 10⁻⁶ā² d⁴F̄/dā⁴ / 6, and
    /// the slopes' round-off over 2·10⁻³ā). `None` where a state or a
    /// slope is not found.
    #[cfg(any(test, feature = "cli"))]
    pub(crate) fn force_curvature_in_size(&self, u: &DVector<f64>) -> Option<f64> {
        let a = self.contour_of(u).a_bar();
        let SlopeInSize { du, lu, .. } = self.force_slope_in_size(u)?;
        let h = 1e-3 * a;
        let slope_at = |step: f64| {
            let guess = u + &du * step;
            let solved = self
                .newton_from(Hold::Size(a + step), guess, Some(lu.clone()))
                .ok()?;
            Some(self.force_slope_in_size(&solved)?.slope)
        };
        let (up, down) = (slope_at(h)?, slope_at(-h)?);
        let curvature = (up - down) / (2.0 * h);
        curvature.is_finite().then_some(curvature)
    }

    /// The minimum of F̄ nearest in ā to `a_bar` on the arm through `start`:
    /// the family traced from `start` (steps of at most 0.02, 40 points, ā
    /// within 0.3–3 times `start`'s) towards `a_bar` to its first force
    /// minimum, and the other way only where that finds none.
    pub(crate) fn force_minimum_nearest(
        &self,
        start: &ExactState,
        a_bar: f64,
    ) -> Result<ExactState> {
        let mut best: Option<ExactState> = None;
        let mut last = None;
        let towards = if a_bar < start.a_bar { -1.0 } else { 1.0 };
        for direction in [towards, -towards] {
            if best.is_some() {
                break;
            }
            match self.trace_general(
                start,
                direction,
                0.3 * start.a_bar,
                3.0 * start.a_bar,
                0.02,
                40,
                true,
                None,
            ) {
                Ok((b, _)) => {
                    for e in b.events {
                        if let Event::ForceMinimum { state } = e {
                            let nearer = best.as_ref().is_none_or(|x| {
                                (x.a_bar - a_bar).abs() > (state.a_bar - a_bar).abs()
                            });
                            if nearer {
                                best = Some(*state);
                            }
                        }
                    }
                }
                Err(e) => last = Some(e),
            }
        }
        best.ok_or_else(|| {
            last.unwrap_or_else(|| {
                Error::NoState(format!(
                    "no minimum of the force on the arm traced both ways from a_bar = {} at rho = {} (40 steps of at most 0.02 each way, a_bar within 0.3 to 3 times the start)",
                    crate::error::rounded(start.a_bar),
                    crate::error::rounded(self.rho)
                ))
            })
        })
    }

    /// The pull-off `found` if it is resolved (boundary error at most
    /// [`super::RESOLVED`]); else an [`Error::Unresolved`] that asks for
    /// more modes.
    pub(crate) fn accept_resolved_pull_off(
        &self,
        found: (ExactState, Vec<Event>),
    ) -> Result<(ExactState, Vec<Event>)> {
        let st = &found.0;
        if st.bc_error <= super::RESOLVED {
            return Ok(found);
        }
        Err(Error::Unresolved {
            what: format!(
                "exact pull-off at rho = {} with {} contour modes (max |dp/dnu - 1| = {:.1e} on the fine grid, above {:.0e}; the contour is {:.1e} a off the ellipse): use more modes",
                crate::error::rounded(self.rho), self.truncation.modes, st.bc_error, super::RESOLVED, st.deviation_from_ellipse
            ),
            residual: st.bc_error,
        })
    }

    /// The start of the pull-off's trace near the richest model's
    /// (`conformal:8`) load-controlled pull-off `po`: the exact state at its ā
    /// plus [`ABOVE_MODEL_PULL_OFF`], on the same near-elliptical arm (its
    /// s within 5 % of the model's, boundary error below 1e-2), by Newton
    /// from the ellipse through the model's ā and b̄ scaled to that size.
    /// `None` where the model has no pull-off or the start does not
    /// converge there; the trace then starts from the circle's route.
    fn above_model_pull_off(&self, po: &Guess) -> Option<ExactState> {
        let (a, scale, delta) = self.just_above(po);
        let ellipse = super::Contour::ellipse(a, po.b_bar * scale, self.truncation.modes);
        let st = self.solve(a, &ellipse, delta).ok()?;
        Same::SAME_SIDE.of(&st, po).then_some(st)
    }

    /// Where a start near a model's pull-off `po` is put, for both routes
    /// from it: ā [`ABOVE_MODEL_PULL_OFF`] above its ā (next to a fold in ā
    /// Newton at fixed ā is ill-conditioned), the factor that scales the
    /// model's contour to that size, and δ̄ ≈ the circle's (ā²/4 − 2/ā for
    /// the cylinders) shifted by the model's offset.
    pub(crate) fn just_above(&self, po: &Guess) -> (f64, f64, f64) {
        let a = po.a_bar + ABOVE_MODEL_PULL_OFF;
        let delta = po.delta_bar + self.circle_delta(a) - self.circle_delta(po.a_bar);
        (a, a / po.a_bar, delta)
    }

    /// ā at which the pull-off's trace starts ([`GapAt::trace_start`],
    /// given the seeding family's `trace_start_a`).
    pub(crate) fn trace_start(&self) -> f64 {
        self.circle
            .trace_start(self.gap().seed.and_then(|m| m.trace_start()))
    }

    /// Trace from `start` with ā first moving in the direction of
    /// `direction` (±1), between `a_min` and `a_max`; stop at the first
    /// force minimum when asked, or at the first crossing of
    /// `control` = target, which is located and returned. A state asked for
    /// by δ̄ or F̄ is looked for on the near-elliptical stretch only: the
    /// trace ends at a size fold, past which the contour turns strongly
    /// non-elliptical (a crossing in the step of the fold is not taken).
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
        control: Option<Hold>,
    ) -> Result<(Branch, Option<ExactState>)> {
        let settings = trace_settings(max_step, max_points.saturating_sub(1));
        let crossing = control.map(|c| (Quantity::of(c), c.value(), On::Stop));
        let watch = Watch {
            // located (a minimum of F̄ just past a fold is then looked for
            // from the fold, where the arclength plane cuts the family once)
            size_fold: if control.is_some() {
                On::Stop
            } else {
                On::Locate
            },
            displacement_fold: On::Ignore,
            force_minimum: if stop_at_force_minimum {
                On::Stop
            } else {
                On::Locate
            },
            bifurcation: On::Note,
            crossing,
        };
        let trace = self.traced(start, direction, settings, watch, |p| {
            p.a_bar < a_min || p.a_bar > a_max
        })?;
        let mut points = Vec::with_capacity(trace.points.len());
        for (k, p) in trace.points.iter().enumerate() {
            let state = if k == 0 {
                start.clone()
            } else {
                self.state(&p.u)?
            };
            points.push(BranchPoint {
                state,
                d_force: p.d_force,
                d_a_bar: p.d_a_bar,
            });
        }
        let mut events = Vec::new();
        let mut found = None;
        for e in &trace.events {
            let [i, j] = e.between;
            match e.kind {
                EventKind::SizeFold => events.push(Event::SizeFold {
                    // located where the trace was asked to (ā = A + Σ b_j)
                    a_bar: e
                        .at
                        .as_ref()
                        .map_or(points[j].state.a_bar, |u| u.rows(0, u.len() - 1).sum()),
                }),
                EventKind::Bifurcation(mode) => events.push(Event::Bifurcation {
                    between: [points[i].state.a_bar, points[j].state.a_bar],
                    mode,
                }),
                EventKind::ForceMinimum => {
                    if let Some(u) = &e.at {
                        events.push(Event::ForceMinimum {
                            state: Box::new(self.state(u)?),
                        });
                    }
                }
                EventKind::Crossing => {
                    let past_fold = trace
                        .events
                        .iter()
                        .any(|f| f.kind == EventKind::SizeFold && f.between == e.between);
                    if let (Some(u), false) = (&e.at, past_fold) {
                        found = Some(self.state(u)?);
                    }
                }
                EventKind::DisplacementFold => {}
            }
        }
        Ok((Branch { points, events }, found))
    }

    /// Trace from `start` with ā first moving in `direction` (±1) to the
    /// first fold of the contact size, located and returned with the
    /// contour mode of its null direction (the dominant b_j of the null
    /// vector of the state equations at fixed ā there); `None` when ā
    /// passes `a_limit` first. Steps of at most `max_step` in u.
    pub(crate) fn to_size_fold(
        &self,
        start: &ExactState,
        direction: f64,
        a_limit: f64,
        max_step: f64,
    ) -> Result<Option<(ExactState, Option<usize>)>> {
        Ok(
            match self.to_size_fold_within(start, direction, a_limit, max_step, f64::INFINITY)? {
                SizeFoldEnd::Fold(st, mode) => Some((*st, mode)),
                // no point's boundary error exceeds an infinite bound
                SizeFoldEnd::Beyond | SizeFoldEnd::Unresolved { .. } => None,
            },
        )
    }

    /// [`Exact::to_size_fold`], ending also where the series stops
    /// following the family: at the first traced point whose fine-grid
    /// boundary error exceeds `within` ([`SizeFoldEnd::Unresolved`]).
    pub(crate) fn to_size_fold_within(
        &self,
        start: &ExactState,
        direction: f64,
        a_limit: f64,
        max_step: f64,
        within: f64,
    ) -> Result<SizeFoldEnd> {
        let n = self.unknown_count();
        let settings = trace_settings(max_step, 2000);
        let watch = Watch {
            size_fold: On::Stop,
            displacement_fold: On::Ignore,
            force_minimum: On::Ignore,
            bifurcation: On::Ignore,
            crossing: None,
        };
        let mut unresolved = None;
        let trace = self.traced(start, direction, settings, watch, |p| {
            if within.is_finite() {
                if let Some(bc) = self.fine_boundary_error(&p.u).filter(|bc| *bc > within) {
                    unresolved = Some(SizeFoldEnd::Unresolved {
                        a_bar: p.a_bar,
                        force_bar: p.force,
                        bc_error: bc,
                    });
                    return true;
                }
            }
            (p.a_bar - a_limit) * direction > 0.0
        })?;
        let Some(u) = trace.located(EventKind::SizeFold) else {
            if let Some(end) = unresolved {
                return Ok(end);
            }
            // past the limit without a fold; a trace that ran out of steps
            // first says where it stopped
            return match trace.end {
                continuation::End::Budget => Err(self.stuck(
                    &trace
                        .points
                        .last()
                        .map_or_else(|| self.unknowns(start), |p| p.u.clone()),
                    "no fold of the contact size within 2000 steps",
                )),
                _ => Ok(SizeFoldEnd::Beyond),
            };
        };
        // the state equations at fixed ā, singular at the fold
        let (_, _, j, _) = linearise(self, u)
            .ok_or_else(|| self.stuck(u, "no linearisation at the located fold"))?;
        let mut held = DMatrix::zeros(n, n);
        held.rows_mut(0, n - 1).copy_from(&j);
        held.set_row(n - 1, &a_bar_gradient(n).transpose());
        Ok(SizeFoldEnd::Fold(
            Box::new(self.state(u)?),
            contour_mode(self, u, &held),
        ))
    }

    /// The states at `control` on the arm through `start`, traced with ā
    /// first moving in `direction` (±1, into a band) through the arm's first
    /// fold in ā and on along its returning stretch, where the contour
    /// undulates more and more with the band's mode (as the load-controlled
    /// pull-off, just past the fold of the mode-4 band, does). Every
    /// crossing of the control from the step of the fold on is located
    /// (one before it is on the arm the other routes start on, and is left
    /// to them). The trace ends where ā passes `a_limit` before any fold
    /// (the arm crosses the gap), at a second fold, where the departure from
    /// an ellipse in the coefficients, Σ_{j≥1}|b_j|/ā, exceeds
    /// [`PAST_FOLD_DEPARTURE`], or after [`PAST_FOLD_STEPS`] steps of at most
    /// `max_step`; how it ended is returned with the crossings ([`PastFoldEnd`]). The
    /// states are of this truncation: whether the series resolves them is
    /// the caller's to decide.
    pub(crate) fn crossings_past_fold(
        &self,
        start: &ExactState,
        direction: f64,
        a_limit: f64,
        control: Hold,
        max_step: f64,
    ) -> Result<(Vec<ExactState>, PastFoldEnd)> {
        let n = self.unknown_count();
        let watch = Watch {
            size_fold: On::Note,
            displacement_fold: On::Ignore,
            force_minimum: On::Ignore,
            bifurcation: On::Ignore,
            crossing: Some((Quantity::of(control), control.value(), On::Locate)),
        };
        let mut past = false;
        let mut why = None;
        let past_fold = trace_settings(max_step, PAST_FOLD_STEPS);
        let trace = self.traced(start, direction, past_fold, watch, |p| {
            let returning = p.d_a_bar * direction < 0.0;
            let second_fold = past && !returning;
            past |= returning;
            let departure: f64 = p.u.rows(2, n - 3).iter().map(|b| b.abs()).sum();
            why = if !past && (p.a_bar - a_limit) * direction > 0.0 {
                Some(PastFoldStop::CrossesGap)
            } else if second_fold {
                Some(PastFoldStop::SecondFold)
            } else if departure > PAST_FOLD_DEPARTURE * p.a_bar {
                Some(PastFoldStop::Departs)
            } else {
                None
            };
            why.is_some()
        })?;
        // the crossings from the step of the first fold on (one before it
        // lies on the arm the other routes start on)
        let fold_step = trace
            .events
            .iter()
            .find(|e| e.kind == EventKind::SizeFold)
            .map(|e| e.between[0]);
        let mut found = Vec::new();
        for e in &trace.events {
            if let (EventKind::Crossing, Some(u), Some(f)) = (e.kind, &e.at, fold_step) {
                if e.between[0] >= f {
                    found.push(self.state(u)?);
                }
            }
        }
        let stop = match (trace.end, why) {
            (continuation::End::Budget, _) | (_, None) => PastFoldStop::Budget,
            (_, Some(why)) => why,
        };
        let end = PastFoldEnd {
            stop,
            folded: fold_step.is_some(),
            a_bar: trace.points.last().map_or(start.a_bar, |p| p.a_bar),
        };
        Ok((found, end))
    }

    /// The continuation from `start` with ā first moving in `direction`
    /// (±1), with `settings`, watching `watch`, until `stop`: every trace
    /// of the family at one ρ.
    fn traced(
        &self,
        start: &ExactState,
        direction: f64,
        settings: Settings,
        watch: Watch,
        stop: impl FnMut(&continuation::Point<Dyn>) -> bool,
    ) -> Result<continuation::Trace<Dyn>> {
        let towards = a_bar_gradient(self.unknown_count()) * direction;
        continuation::trace(self, self.unknowns(start), &towards, settings, watch, stop)
    }

    /// The first state at `control` on the arm through `start`, traced with
    /// ā first moving in `direction` (±1) through the arm's folds in ā
    /// (noted, not stopped at: a fold in ā is no change of stability under
    /// load or displacement control), or how the arm ended first
    /// ([`ArmEnd`]): at a minimum of F̄ (asked by force), where the contour
    /// departs from the ellipse with its half-widths by more than
    /// `departure` ā (along rays, [`DEPARTURE_POINTS`] of them:
    /// in either representation; the arclength representation's
    /// coefficients of an ellipse are not small), after
    /// [`PAST_FOLD_STEPS`] steps of at most `max_step`, or at a point whose
    /// fine-grid boundary error exceeds `resolved_within` (the series no
    /// longer follows the arm). The state found is of this truncation:
    /// whether the series resolves it is the caller's to decide.
    pub(crate) fn first_crossing_through_folds(
        &self,
        start: &ExactState,
        direction: f64,
        control: Hold,
        max_step: f64,
        resolved_within: f64,
        departure: f64,
    ) -> Result<ArmEnd> {
        let watch = Watch {
            size_fold: On::Note,
            displacement_fold: On::Ignore,
            force_minimum: match control {
                Hold::Force(_) => On::Stop,
                _ => On::Ignore,
            },
            bifurcation: On::Ignore,
            crossing: Some((Quantity::of(control), control.value(), On::Stop)),
        };
        let mut unresolved = None;
        // the last point within the bound, and ā at the one before it
        let mut before: Option<(DVector<f64>, f64, f64)> = None;
        let past_fold = trace_settings(max_step, PAST_FOLD_STEPS);
        let trace = self.traced(start, direction, past_fold, watch, |p| {
            if let Some(bc) = self
                .fine_boundary_error(&p.u)
                .filter(|bc| *bc > resolved_within)
            {
                let resolved_before = before.as_ref().and_then(|(u, a_bar, a_before)| {
                    let st = self.state(u).ok()?;
                    Some((Box::new(st), if a_bar >= a_before { 1.0 } else { -1.0 }))
                });
                unresolved = Some(ArmEnd::Unresolved {
                    a_bar: p.a_bar,
                    force_bar: p.force,
                    bc_error: bc,
                    modes: self.truncation.modes,
                    resolved_before,
                });
                return true;
            }
            let a_before = before.as_ref().map_or(start.a_bar, |b| b.1);
            before = Some((p.u.clone(), p.a_bar, a_before));
            self.contour_of(&p.u)
                .deviation_from_ellipse(DEPARTURE_POINTS)
                > departure
        })?;
        for e in &trace.events {
            if let (EventKind::Crossing, Some(u)) = (e.kind, &e.at) {
                return self.state(u).map(|st| ArmEnd::Reached(Box::new(st)));
            }
        }
        Ok(match (unresolved, trace.end) {
            (Some(end), _) => end,
            (None, continuation::End::Budget) => ArmEnd::OutOfSteps,
            (None, _) => ArmEnd::EndsBefore,
        })
    }

    /// The state at `control` started from the richest `conformal:K`'s
    /// (K = 8) state at the same control: Newton at the control from the
    /// ellipse with its ā and b̄ and its δ̄; where that fails, Newton at its
    /// ā, then the family traced to the control (a step or two).
    /// `None` where the model has no state there (ρ below its range), the
    /// start does not converge, or the answer is not near the model's
    /// (within 2 % in ā, 5 % in s) and near-elliptical (boundary error
    /// below 1e-2); the caller decides whether it is resolved.
    fn from_model(&self, control: Hold) -> Option<ExactState> {
        // the seeding model (the seeding family's largest member)
        let guess = self.gap().seed?.state(self.rho, control).ok()?;
        let nm = self.truncation.modes;
        let ellipse = super::Contour::ellipse(guess.a_bar, guess.b_bar, nm);
        // Newton at the control itself from the model's ellipse: the state
        // when it lands near the model's and near-elliptical
        if let Ok(mut st) = self.solve_at(control, &ellipse, guess.delta_bar) {
            if Same::NEAR_THE_START.of(&st, &guess) {
                st.route = Route::FromModel;
                return Some(st);
            }
        }
        // else (near a fold in the control, where that system is singular)
        // at the model's ā, then along the family to the control
        let start = self.solve(guess.a_bar, &ellipse, guess.delta_bar);
        let start = start.ok()?;
        // the exact state near the model's: same side of the circle's
        // bifurcations (a contour within a few per cent of the model's)
        if !Same::SAME_SHAPE.of(&start, &guess) {
            return None;
        }
        let here = control.excess(start.a_bar, start.delta_bar, start.force_bar);
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
        if !Same::TRACED_NEAR_THE_START.of(&st, &guess) {
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
    pub fn at(&self, control: Hold) -> Result<ExactState> {
        self.find(control, None).and_then(|st| {
            let at = format!("{control} ({})", st.route_words());
            self.accept_resolved(at, st)
        })
    }

    /// The state [`Exact::at`] finds, resolved or not; first, where given,
    /// by Newton at the control from `coarser`, the state at the same
    /// control with fewer modes (its contour padded with zeros; accepted
    /// near it, with its route): the escalation of [`super::resolve::at_with`].
    pub(crate) fn find(&self, control: Hold, coarser: Option<&ExactState>) -> Result<ExactState> {
        if let Some(c) = coarser {
            if let Ok(mut st) = self.solve_at(control, &c.contour, c.delta_bar) {
                if Same::NEAR_THE_START.of(&st, c) {
                    st.route = c.route;
                    return Ok(st);
                }
            }
        }
        // on a gap no circle solves (issue 73) the family is traced to the
        // control from the state continued in the gap at the trace's start
        let radial = self.circle.is_radial();
        let a_circle = circle_a_bar(self.circle(), control);
        if let (Hold::Force(v), true) = (control, a_circle.is_nan()) {
            return Err(Error::NoState(format!(
                "exact state at rho = {}: F = {} is below the pull-off force of the circle, {}, and so below that of every rho",
                crate::error::rounded(self.rho),
                crate::error::rounded(v),
                crate::error::rounded(circle_pull_off(self.circle()).1)
            )));
        }
        if !(a_circle.is_finite() && a_circle > 0.0) {
            return Err(Error::NoState(format!(
                "exact state at rho = {}: {control} has no circle to start from",
                crate::error::rounded(self.rho)
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
            return Ok(st);
        }
        // a start whose arm folds before the value is reached is retried
        // once from the far side of the fold (0.3 beyond it in ā)
        let mut a_start = a_circle;
        let (through, how) = if radial {
            ("the circle's", "rho")
        } else {
            ("the cylinders' state at", "the gap")
        };
        let mut ends = Vec::new();
        let st = loop {
            let start = self.continued_in_the_gap(a_start)?;
            let here = control.excess(start.a_bar, start.delta_bar, start.force_bar);
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
                    "the arm through {through} a_bar = {a_start:.6} continued in {how} (contour {:.1e} a off the ellipse there) folds at a_bar = {a_bar:.6} (an imperfect bifurcation: beyond it the contour turns undulated)",
                    start.deviation_from_ellipse
                ),
                (None, Some(force)) => format!(
                    "the arm through {through} a_bar = {a_start:.6} continued in {how} (contour {:.1e} a off the ellipse there) reaches its load-controlled pull-off, F = {force:.6}, first",
                    start.deviation_from_ellipse
                ),
                _ => format!(
                    "the trace from {through} a_bar = {a_start:.6} ended at a_bar = {:.6}",
                    branch.points.last().map(|p| p.state.a_bar).unwrap_or(f64::NAN)
                ),
            };
            ends.push(end);
            match fold {
                Some(a_bar) if ends.len() < 2 => a_start = a_bar + 0.3 * direction,
                _ => {
                    return Err(Error::NoState(format!(
                        "exact state at rho = {}: {} is not reached: {}",
                        crate::error::rounded(self.rho),
                        control,
                        ends.join("; then ")
                    )))
                }
            }
        };
        Ok(st)
    }

    /// `st`, found at `at` (a control and how it was found, or the size it
    /// was solved at), if it is resolved (boundary error at most
    /// [`super::RESOLVED`]); else an [`Error::Unresolved`] that asks for
    /// more modes.
    pub(crate) fn accept_resolved(
        &self,
        at: impl std::fmt::Display,
        st: ExactState,
    ) -> Result<ExactState> {
        if st.bc_error <= super::RESOLVED {
            return Ok(st);
        }
        Err(Error::Unresolved {
            what: format!(
                "exact state at rho = {}, {at}: max |dp/dnu - 1| = {:.1e} with {} modes",
                crate::error::rounded(self.rho),
                st.bc_error,
                self.truncation.modes
            ),
            residual: st.bc_error,
        })
    }
}
