//! Pseudo-arclength continuation, written once for every family of states:
//! the paper's ellipse models (u = (ā, s, δ̄), static 3-vectors), the
//! contour family `conformal:K` (u = (c₁ … c_K, δ̄)) and the exact solution
//! (u = (A, b₀ … b_{N−1}, δ̄)). A family is n − 1 equations in n unknowns
//! whose last is δ̄ (or a multiple of it); the engine follows its solution
//! curve by arclength, so folds in ā, δ̄ or F̄ are passed, not stopped at.
//!
//! - Predictor: a step σ along the unit tangent t, the null vector of the
//!   (n − 1) × n Jacobian, found from the bordered system [∂r/∂u; t_prevᵀ]
//!   t = eₙ and oriented like the previous tangent.
//! - Corrector: Newton's method on the equations bordered by the arclength
//!   condition t·(u − u_pred) = 0; for families whose Jacobian is costly
//!   ([`Family::chord`]) the factored bordered Jacobian is kept while each
//!   step reduces the residual at least fourfold.
//! - Step control: halved when the corrector fails or the tangent turns by
//!   more than [`Settings::turn`] (a turn at the smallest step is taken:
//!   a corner of the branch), grown by [`Settings::grow`] after a fast
//!   correction.
//! - Events between two traced points: a fold in ā (dā/dσ changes sign), in
//!   δ̄ (dδ̄/dσ), a minimum of F̄ (dF̄/dσ from < 0 to ≥ 0), a bifurcation point
//!   (the determinant of the bordered Jacobian changes sign; at a fold it
//!   does not) and the crossing of a target value of ā, δ̄ or F̄. Each is
//!   ignored, noted at the bracketing points, located, or located and made
//!   the end of the trace ([`On`]). A fold in δ̄, a crossing and a force
//!   minimum are located by the Illinois method on σ (on dδ̄/dσ, the value,
//!   dF̄/dσ); a force minimum in a step that also holds a bifurcation point
//!   by golden-section search on F̄ along σ (the tangent is undefined there:
//!   at ρ = 1 the minimum sits on the bifurcation point of mode 4).
//!
//! Owns: [`Family`], [`Linear`], [`Settings`], [`Watch`], [`On`],
//! [`Quantity`], [`Point`], [`EventKind`], [`Event`], [`Trace`], [`trace`],
//! [`at_arclength`], [`past_size_fold`], [`spaced`].
//! May use: `error`, `control`, `newton` (the caller's stop flag), nalgebra.

use crate::control::Quantity;
use crate::error::{Error, Result};
use nalgebra::allocator::Allocator;
use nalgebra::{DefaultAllocator, Dim, DimMin, OMatrix, OVector, LU};

/// The equations of a family and their Jacobian at one point.
#[derive(Clone, Debug)]
pub(crate) struct Linear<D: Dim>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// The n − 1 residuals in the first n − 1 entries (the last is unused).
    pub r: OVector<f64, D>,
    /// Their Jacobian ∂r/∂u in the first n − 1 rows (the last row is the
    /// engine's).
    pub j: OMatrix<f64, D, D>,
    /// F̄ at u.
    pub force: f64,
    /// ∂F̄/∂u.
    pub force_grad: OVector<f64, D>,
}

/// A family of states: n − 1 equations in the n unknowns u.
pub(crate) trait Family<D: Dim>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// The equations, their Jacobian and F̄ at u (`None` where they are not
    /// defined).
    fn linearise(&self, u: &OVector<f64, D>) -> Option<Linear<D>>;
    /// The residuals alone (the chord method's cheap evaluation).
    fn residuals(&self, u: &OVector<f64, D>) -> Option<OVector<f64, D>> {
        self.linearise(u).map(|l| l.r)
    }
    /// The residuals and F̄ at u, without the Jacobian (the search for a
    /// minimum of F̄ along the family needs no more).
    fn residuals_and_force(&self, u: &OVector<f64, D>) -> Option<(OVector<f64, D>, f64)> {
        self.linearise(u).map(|l| (l.r, l.force))
    }
    /// Whether the residuals at u are small enough for a state.
    fn converged(&self, u: &OVector<f64, D>, r: &OVector<f64, D>) -> bool;
    /// Whether u lies in the domain of the equations (a corrector iterate
    /// outside it fails the step).
    fn in_domain(&self, _u: &OVector<f64, D>) -> bool {
        true
    }
    /// Whether an accepted point is a state; an error ends the trace with
    /// its reason (for `conformal:K`: the map is not one-to-one).
    fn admissible(&self, _u: &OVector<f64, D>) -> Result<()> {
        Ok(())
    }
    /// ā = g·u: the constant gradient g.
    fn a_bar_gradient(&self) -> OVector<f64, D>;
    /// δ̄ = g·u: the constant gradient g.
    fn delta_bar_gradient(&self) -> OVector<f64, D>;
    /// Keep the factored bordered Jacobian while the residual falls fast
    /// (for families whose Jacobian costs many residual evaluations).
    fn chord(&self) -> bool {
        false
    }
    /// The contour mode of the near-null direction of the bordered
    /// Jacobian at a bifurcation point near u, where the family knows it.
    fn bifurcation_mode(
        &self,
        _u: &OVector<f64, D>,
        _bordered: &OMatrix<f64, D, D>,
    ) -> Option<usize> {
        None
    }
    /// The trace stopped at u for the reason `why`: the error, in the
    /// family's words (where it stopped, rounded).
    fn stuck(&self, u: &OVector<f64, D>, why: &str) -> Error;
}

/// Step control and budgets of a trace.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Settings {
    /// The first step.
    pub step: f64,
    /// The smallest step: a step that fails at this size ends the trace
    /// with an error.
    pub min_step: f64,
    /// The largest step.
    pub max_step: f64,
    /// The factor a step grows by after a correction within
    /// `fast_iterations`.
    pub grow: f64,
    /// See `grow`.
    pub fast_iterations: usize,
    /// The least cosine between consecutive tangents; a step that turns
    /// more is retried shorter (−1: any turn).
    pub turn: f64,
    /// Corrector iterations.
    pub corrector_iterations: usize,
    /// The corrector has converged when its step is below this times
    /// 1 + max |u|.
    pub step_tolerance: f64,
    /// The most accepted steps.
    pub max_steps: usize,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            step: 0.02,
            min_step: 1e-10,
            max_step: 0.1,
            grow: 1.3,
            fast_iterations: usize::MAX,
            turn: -1.0,
            corrector_iterations: 20,
            step_tolerance: 1e-12,
            max_steps: 20_000,
        }
    }
}

/// What the engine does with an event.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum On {
    /// Nothing.
    Ignore,
    /// Record it between the two traced points that bracket it.
    Note,
    /// Record it, located.
    Locate,
    /// Record it located (a fold in ā: at the later traced point) and end
    /// the trace there.
    Stop,
}

/// The events a trace watches for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Watch {
    /// Folds in ā.
    pub size_fold: On,
    /// Folds in δ̄ (extrema of δ̄: pull-off under displacement control).
    pub displacement_fold: On,
    /// Minima of F̄ (pull-off under load control).
    pub force_minimum: On,
    /// Sign changes of the bordered determinant.
    pub bifurcation: On,
    /// The crossing of a value.
    pub crossing: Option<(Quantity, f64, On)>,
}

impl Default for Watch {
    fn default() -> Self {
        Watch {
            size_fold: On::Note,
            displacement_fold: On::Note,
            force_minimum: On::Note,
            bifurcation: On::Ignore,
            crossing: None,
        }
    }
}

/// One traced point.
#[derive(Clone, Debug)]
pub(crate) struct Point<D: Dim>
where
    DefaultAllocator: Allocator<D>,
{
    /// The unknowns.
    pub u: OVector<f64, D>,
    /// The unit tangent (oriented along the trace).
    pub t: OVector<f64, D>,
    /// ā.
    pub a_bar: f64,
    /// δ̄.
    pub delta_bar: f64,
    /// F̄.
    pub force: f64,
    /// dā/dσ.
    pub d_a_bar: f64,
    /// dδ̄/dσ.
    pub d_delta_bar: f64,
    /// dF̄/dσ.
    pub d_force: f64,
    /// The sign of the bordered determinant.
    det_sign: f64,
}

impl<D: Dim> Point<D>
where
    DefaultAllocator: Allocator<D>,
{
    /// The watched quantity here.
    pub(crate) fn value(&self, q: Quantity) -> f64 {
        match q {
            Quantity::ABar => self.a_bar,
            Quantity::Delta => self.delta_bar,
            Quantity::Force => self.force,
        }
    }
}

/// What happened.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum EventKind {
    /// ā turns.
    SizeFold,
    /// δ̄ turns.
    DisplacementFold,
    /// F̄ has a minimum.
    ForceMinimum,
    /// A bifurcation point, with the contour mode of the null direction
    /// where the family knows it.
    Bifurcation(Option<usize>),
    /// The watched value is reached.
    Crossing,
}

/// An event of a trace.
#[derive(Clone, Debug)]
pub(crate) struct Event<D: Dim>
where
    DefaultAllocator: Allocator<D>,
{
    /// What happened.
    pub kind: EventKind,
    /// The indices of the traced points that bracket it.
    pub between: [usize; 2],
    /// Where, when located.
    pub at: Option<OVector<f64, D>>,
}

/// How a trace ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum End {
    /// At an event watched with [`On::Stop`].
    Event(EventKind),
    /// Where the caller's `until` said so.
    Until,
    /// The step budget ran out.
    Budget,
}

/// A trace: its points, events and end.
#[derive(Clone, Debug)]
pub(crate) struct Trace<D: Dim>
where
    DefaultAllocator: Allocator<D>,
{
    /// The traced points, in order.
    pub points: Vec<Point<D>>,
    /// The events, in order.
    pub events: Vec<Event<D>>,
    /// How it ended.
    pub end: End,
}

impl<D: Dim> Trace<D>
where
    DefaultAllocator: Allocator<D>,
{
    /// The located point of the first event of `kind`.
    pub(crate) fn located(&self, kind: EventKind) -> Option<&OVector<f64, D>> {
        self.events
            .iter()
            .find(|e| e.kind == kind)
            .and_then(|e| e.at.as_ref())
    }
}

/// The engine's bounds on the dimension.
pub(crate) trait Size: Dim + DimMin<Self, Output = Self> {}
impl<D: Dim + DimMin<D, Output = D>> Size for D {}

struct Engine<'a, D: Size, F: Family<D>>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    family: &'a F,
    settings: Settings,
    ga: OVector<f64, D>,
    gd: OVector<f64, D>,
}

impl<'a, D: Size, F: Family<D>> Engine<'a, D, F>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    fn new(family: &'a F, settings: Settings) -> Self {
        Engine {
            family,
            settings,
            ga: family.a_bar_gradient(),
            gd: family.delta_bar_gradient(),
        }
    }

    fn bordered(&self, j: &OMatrix<f64, D, D>, t: &OVector<f64, D>) -> OMatrix<f64, D, D> {
        let mut m = j.clone();
        let n = t.len();
        for k in 0..n {
            m[(n - 1, k)] = t[k];
        }
        m
    }

    /// The unit tangent where the Jacobian is `j`, oriented like `prev`,
    /// and the sign of the bordered determinant.
    fn tangent(
        &self,
        j: &OMatrix<f64, D, D>,
        prev: &OVector<f64, D>,
    ) -> Option<(OVector<f64, D>, f64)> {
        let n = prev.len();
        let lu = self.bordered(j, prev).lu();
        let det = lu.determinant();
        let mut rhs = prev.clone();
        rhs.fill(0.0);
        rhs[n - 1] = 1.0;
        let t = lu.solve(&rhs)?;
        let norm = t.norm();
        (norm.is_finite() && norm > 0.0).then(|| (t / norm, det.signum()))
    }

    /// The corrector from `base + t σ`; with the iterations used and the
    /// linearisation at the answer.
    fn correct(
        &self,
        base: &OVector<f64, D>,
        t: &OVector<f64, D>,
        sigma: f64,
        start: Option<&LU<f64, D, D>>,
    ) -> Option<(OVector<f64, D>, usize, Linear<D>)> {
        let linear = |u: &OVector<f64, D>| self.family.linearise(u).map(|l| (l.r.clone(), l));
        self.correct_then(base, t, sigma, start, &linear)
    }

    /// [`Engine::correct`] with `finish` in place of the linearisation at
    /// the answer: it gives the residuals there (for the convergence test)
    /// and what the caller wants.
    fn correct_then<T>(
        &self,
        base: &OVector<f64, D>,
        t: &OVector<f64, D>,
        sigma: f64,
        start: Option<&LU<f64, D, D>>,
        finish: &dyn Fn(&OVector<f64, D>) -> Option<(OVector<f64, D>, T)>,
    ) -> Option<(OVector<f64, D>, usize, T)> {
        let pred = base + t * sigma;
        if self.family.chord() {
            self.correct_with(&pred, t, true, start.cloned(), finish)
                .or_else(|| self.correct_with(&pred, t, false, None, finish))
        } else {
            self.correct_with(&pred, t, false, None, finish)
        }
    }

    fn correct_with<T>(
        &self,
        pred: &OVector<f64, D>,
        t: &OVector<f64, D>,
        chord: bool,
        start: Option<LU<f64, D, D>>,
        finish: &dyn Fn(&OVector<f64, D>) -> Option<(OVector<f64, D>, T)>,
    ) -> Option<(OVector<f64, D>, usize, T)> {
        let n = pred.len();
        let mut u = pred.clone();
        let mut lu = start;
        let mut last = f64::INFINITY;
        let iterations = self.settings.corrector_iterations * if chord { 2 } else { 1 };
        for it in 0..iterations {
            if !self.family.in_domain(&u) {
                return None;
            }
            let mut r = None;
            if chord && lu.is_some() {
                let cheap = self.family.residuals(&u)?;
                let res = cheap.rows(0, n - 1).amax();
                if res <= 0.25 * last {
                    last = res;
                    r = Some(cheap);
                }
            }
            let r = match r {
                Some(r) => r,
                None => {
                    // a fresh Jacobian: at the start, without the chord
                    // method, or where the residual fell too slowly
                    let l = self.family.linearise(&u)?;
                    last = l.r.rows(0, n - 1).amax();
                    lu = Some(self.bordered(&l.j, t).lu());
                    l.r
                }
            };
            let mut rhs = -r;
            rhs[n - 1] = -t.dot(&(&u - pred));
            let step = lu.as_ref()?.solve(&rhs)?;
            if !step.iter().all(|v| v.is_finite()) {
                return None;
            }
            u += &step;
            if step.amax() < self.settings.step_tolerance * (1.0 + u.amax()) {
                if !self.family.in_domain(&u) {
                    return None;
                }
                let (r, v) = finish(&u)?;
                return self.family.converged(&u, &r).then_some((u, it + 1, v));
            }
        }
        None
    }

    fn point(
        &self,
        u: OVector<f64, D>,
        t: OVector<f64, D>,
        l: &Linear<D>,
        det_sign: f64,
    ) -> Point<D> {
        Point {
            a_bar: self.ga.dot(&u),
            delta_bar: self.gd.dot(&u),
            force: l.force,
            d_a_bar: self.ga.dot(&t),
            d_delta_bar: self.gd.dot(&t),
            d_force: l.force_grad.dot(&t),
            det_sign,
            u,
            t,
        }
    }

    /// A corrected point at σ from `p`, or a little beside it (a bifurcation
    /// point makes the bordered system singular on the point itself).
    fn beside(
        &self,
        p: &Point<D>,
        sigma: f64,
        lu: &LU<f64, D, D>,
    ) -> Result<(OVector<f64, D>, Linear<D>)> {
        let linear = |u: &OVector<f64, D>| self.family.linearise(u).map(|l| (l.r.clone(), l));
        self.beside_then(p, sigma, lu, &linear)
    }

    /// F̄ at the corrected point at σ from `p`, or a little beside it, as
    /// [`Engine::beside`] but without the Jacobian there.
    fn force_beside(
        &self,
        p: &Point<D>,
        sigma: f64,
        lu: &LU<f64, D, D>,
    ) -> Result<(OVector<f64, D>, f64)> {
        let force = |u: &OVector<f64, D>| self.family.residuals_and_force(u);
        self.beside_then(p, sigma, lu, &force)
    }

    /// [`Engine::beside`] with `finish` at the answer (as in
    /// [`Engine::correct_then`]).
    fn beside_then<T>(
        &self,
        p: &Point<D>,
        sigma: f64,
        lu: &LU<f64, D, D>,
        finish: &dyn Fn(&OVector<f64, D>) -> Option<(OVector<f64, D>, T)>,
    ) -> Result<(OVector<f64, D>, T)> {
        [
            0.0, 1e-9, -1e-9, 1e-7, -1e-7, 1e-6, -1e-6, 1e-5, -1e-5, 1e-4, -1e-4,
        ]
        .iter()
        .find_map(|off| {
            self.correct_then(
                &p.u,
                &p.t,
                sigma + off * (1.0 + sigma.abs()),
                Some(lu),
                finish,
            )
            .map(|(u, _, v)| (u, v))
        })
        .ok_or_else(|| {
            self.family.stuck(
                &p.u,
                &format!("no corrected point near arclength {sigma:.3e} while locating an event"),
            )
        })
    }

    fn factored(&self, p: &Point<D>) -> Result<LU<f64, D, D>> {
        let l = self
            .family
            .linearise(&p.u)
            .ok_or_else(|| self.family.stuck(&p.u, "the equations are not defined"))?;
        Ok(self.bordered(&l.j, &p.t).lu())
    }

    /// The minimum of F̄ between `p` (dF̄/dσ < 0) and `q`, by golden-section
    /// search on F̄ along σ: 45 steps shrink the bracket by 0.618⁴⁵ ≈ 4e-10.
    fn force_minimum(&self, p: &Point<D>, q: &Point<D>) -> Result<OVector<f64, D>> {
        let lu = self.factored(p)?;
        let at = |sigma: f64| self.force_beside(p, sigma, &lu);
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let (mut lo, mut hi) = (0.0, p.t.dot(&(&q.u - &p.u)));
        let mut x1 = hi - g * (hi - lo);
        let mut x2 = lo + g * (hi - lo);
        let (mut u1, mut f1) = at(x1)?;
        let (mut u2, mut f2) = at(x2)?;
        for _ in 0..45 {
            if f1 < f2 {
                hi = x2;
                (x2, u2, f2) = (x1, u1.clone(), f1);
                x1 = hi - g * (hi - lo);
                (u1, f1) = at(x1)?;
            } else {
                lo = x1;
                (x1, u1, f1) = (x2, u2.clone(), f2);
                x2 = lo + g * (hi - lo);
                (u2, f2) = at(x2)?;
            }
        }
        Ok(if f1 < f2 { u1 } else { u2 })
    }

    /// The zero of `value` (of the corrected point, its tangent and
    /// linearisation) between `p` (value f0) and `q` (value f1, the other
    /// sign), by the Illinois method on σ.
    fn zero(
        &self,
        p: &Point<D>,
        q: &Point<D>,
        f0: f64,
        f1: f64,
        value: &dyn Fn(&Point<D>) -> f64,
    ) -> Result<OVector<f64, D>> {
        self.zero_point(p, q, f0, f1, value).map(|z| z.u)
    }

    /// [`Engine::zero`] as a point (with its tangent and rates).
    fn zero_point(
        &self,
        p: &Point<D>,
        q: &Point<D>,
        f0: f64,
        f1: f64,
        value: &dyn Fn(&Point<D>) -> f64,
    ) -> Result<Point<D>> {
        let lu = self.factored(p)?;
        let (mut sa, mut fa) = (0.0, f0);
        let (mut sb, mut fb) = (p.t.dot(&(&q.u - &p.u)), f1);
        let mut best = q.clone();
        for _ in 0..100 {
            let sigma = sb - fb * (sb - sa) / (fb - fa);
            let (u, l) = self.beside(p, sigma, &lu)?;
            let (t, det) = self
                .tangent(&l.j, &p.t)
                .ok_or_else(|| self.family.stuck(&u, "no tangent while locating an event"))?;
            let here = self.point(u, t, &l, det);
            let f = value(&here);
            best = here;
            if f == 0.0 || (sb - sa).abs() < 1e-13 * (1.0 + sigma.abs()) {
                return Ok(best);
            }
            if f.signum() == fb.signum() {
                fa *= 0.5; // Illinois: the retained end's value is halved
            } else {
                (sa, fa) = (sb, fb);
            }
            // an Illinois step below 1e-10 of σ: converged (the value's
            // own rounding, from difference Jacobians, makes smaller steps
            // wander without shrinking the bracket)
            let moved = (sigma - sb).abs();
            (sb, fb) = (sigma, f);
            if (sigma - sa).abs() < 1e-13 * (1.0 + sigma.abs())
                || moved < 1e-10 * (1.0 + sigma.abs())
            {
                return Ok(best);
            }
        }
        // never the last iterate in place of a located event
        Err(self.family.stuck(
            &best.u,
            "the event's location did not converge in 100 Illinois steps",
        ))
    }
}

/// The state of `family` at arclength `sigma` past the traced point `p`
/// towards the traced point `next`: the corrector from `p.u + σ t` on the
/// plane normal to p's tangent t (oriented towards `next`; a trace read
/// backwards has it the other way), or a little beside it, as an event is
/// located, with the budgets of `settings`. A curve's output finer than
/// its trace (`crate::curve`, `crate::conformal`) is made of these, so its
/// memory does not grow with the points asked for.
pub(crate) fn at_arclength<D: Size, F: Family<D>>(
    family: &F,
    settings: Settings,
    p: &Point<D>,
    next: &Point<D>,
    sigma: f64,
) -> Result<OVector<f64, D>>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    let engine = Engine::new(family, settings);
    let mut p = p.clone();
    if p.t.dot(&(&next.u - &p.u)) < 0.0 {
        p.t = -p.t;
    }
    let lu = engine.factored(&p)?;
    engine.beside(&p, sigma, &lu).map(|(u, _)| u)
}

/// Whether the point at arclength `sigma` past the traced point `p`
/// towards the next traced point `q` lies past the fold in ā between
/// them: dā/dσ (along p → q) taken as linear in σ over the chord, the fold
/// where it vanishes. False where dā/dσ keeps its sign from `p` to `q`.
pub(crate) fn past_size_fold<D: Dim>(p: &Point<D>, q: &Point<D>, sigma: f64) -> bool
where
    DefaultAllocator: Allocator<D>,
{
    let chord = &q.u - &p.u;
    let along = |x: &Point<D>| x.d_a_bar * x.t.dot(&chord).signum();
    let (dp, dq) = (along(p), along(q));
    if dp.signum() == dq.signum() {
        return false;
    }
    sigma > chord.norm() * dp / (dp - dq)
}

/// Where `count` points spaced evenly in arclength lie on a trace of
/// `trail` (its points' unknowns, in order; the arclength is the sum of
/// the chords): for each, the index of the traced point at or before it
/// and the arclength from that point to it (0 for the first and the last
/// traced point; below the chord to the next one). Lazily, so
/// nothing of the size of `count` is allocated.
pub(crate) fn spaced<'a, D: Dim>(
    trail: &'a [OVector<f64, D>],
    count: usize,
) -> impl Iterator<Item = (usize, f64)> + 'a
where
    DefaultAllocator: Allocator<D>,
{
    let mut arc = Vec::with_capacity(trail.len());
    arc.push(0.0);
    for k in 1..trail.len() {
        arc.push(arc[k - 1] + (&trail[k] - &trail[k - 1]).norm());
    }
    let total = arc.last().copied().unwrap_or(0.0);
    let mut j = 0;
    (0..count).map(move |i| {
        let target = if count > 1 {
            total * i as f64 / (count - 1) as f64
        } else {
            0.0
        };
        while j + 1 < arc.len() && arc[j + 1] < target {
            j += 1;
        }
        // the last traced point is taken as it is
        let sigma = if j + 1 < arc.len() {
            (target - arc[j]).max(0.0)
        } else {
            0.0
        };
        (j, sigma)
    })
}

/// Trace the family from the state `start` with the first tangent oriented
/// along `towards`, watching `watch`, until an event watched with
/// [`On::Stop`], `until` (called on each new point) or the budget.
pub(crate) fn trace<D: Size, F: Family<D>>(
    family: &F,
    start: OVector<f64, D>,
    towards: &OVector<f64, D>,
    settings: Settings,
    watch: Watch,
    mut until: impl FnMut(&Point<D>) -> bool,
) -> Result<Trace<D>>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    let engine = Engine::new(family, settings);
    let l0 = family
        .linearise(&start)
        .ok_or_else(|| family.stuck(&start, "the equations are not defined at its start"))?;
    let (mut t0, det0) = engine
        .tangent(&l0.j, towards)
        .ok_or_else(|| family.stuck(&start, "no tangent at its start"))?;
    if t0.dot(towards) < 0.0 {
        t0 = -t0;
    }
    let mut points = vec![engine.point(start, t0, &l0, det0)];
    let mut events: Vec<Event<D>> = Vec::new();
    let mut h = settings.step;
    let mut accepted = 0;
    let shorter = |h: f64, p: &Point<D>, why: &str| -> Result<f64> {
        if h <= settings.min_step {
            return Err(family.stuck(&p.u, why));
        }
        Ok((h * 0.5).max(settings.min_step))
    };
    while accepted < settings.max_steps {
        crate::newton::check_stop()?;
        let p = points.last().expect("one point");
        let Some((u, iterations, l)) = engine.correct(&p.u, &p.t, h, None) else {
            h = shorter(h, p, "the corrector fails at every step size")?;
            continue;
        };
        let Some((t, det)) = engine.tangent(&l.j, &p.t) else {
            return Err(family.stuck(&u, "the tangent is undefined"));
        };
        if t.dot(&p.t) < settings.turn && h > settings.min_step {
            // the tangent turned too much: a sharp bend, or a jump to
            // another sheet of the family (taken at the smallest step)
            h = (h * 0.5).max(settings.min_step);
            continue;
        }
        family.admissible(&u)?;
        accepted += 1;
        let q = engine.point(u, t, &l, det);
        let i = points.len();
        // the events of the step p → q; where one cannot be located (the
        // family bends too sharply inside the step for the corrector's
        // planes, as at an imperfect bifurcation on a force minimum), the
        // step is taken again shorter
        let found = step_events(&engine, family, &watch, p, &q, &l, [i - 1, i]);
        let (step_events, stop) = match found {
            Ok(found) => found,
            Err(_) if h > settings.min_step => {
                accepted -= 1;
                h = shorter(h, p, "an event of the step cannot be located")?;
                continue;
            }
            Err(e) => return Err(e),
        };
        events.extend(step_events);
        let done = until(&q);
        points.push(q);
        if let Some(kind) = stop {
            return Ok(Trace {
                points,
                events,
                end: End::Event(kind),
            });
        }
        if done {
            return Ok(Trace {
                points,
                events,
                end: End::Until,
            });
        }
        if iterations <= settings.fast_iterations {
            h = (h * settings.grow).min(settings.max_step);
        }
    }
    Ok(Trace {
        points,
        events,
        end: End::Budget,
    })
}

/// The events of one step from `p` to `q` (`l` the linearisation at `q`,
/// `between` their indices): each one `watch` asks for, located where it
/// asks, and the kind of the first that stops the trace. An event that
/// cannot be located is an error (the caller shortens the step).
fn step_events<D: Size, F: Family<D>>(
    engine: &Engine<'_, D, F>,
    family: &F,
    watch: &Watch,
    p: &Point<D>,
    q: &Point<D>,
    l: &Linear<D>,
    between: [usize; 2],
) -> Result<(Vec<Event<D>>, Option<EventKind>)>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    let mut events: Vec<Event<D>> = Vec::new();
    let mut stop = None;
    let mut note = |kind: EventKind, on: On, at: Option<OVector<f64, D>>| {
        events.push(Event { kind, between, at });
        if on == On::Stop && stop.is_none() {
            stop = Some(kind);
        }
    };
    let located = |on: On| matches!(on, On::Locate | On::Stop);
    // the located fold of ā in this step, if any: a minimum of F̄ just
    // before it, in the same step, is looked for up to it
    let mut size_fold = None;
    if watch.size_fold != On::Ignore && p.d_a_bar.signum() != q.d_a_bar.signum() {
        let at = if located(watch.size_fold) {
            let f = engine.zero_point(p, q, p.d_a_bar, q.d_a_bar, &|x: &Point<D>| x.d_a_bar)?;
            let u = f.u.clone();
            size_fold = Some(f);
            Some(u)
        } else {
            None
        };
        note(EventKind::SizeFold, watch.size_fold, at);
    }
    if watch.bifurcation != On::Ignore && p.det_sign != q.det_sign {
        let mode = family.bifurcation_mode(&p.u, &engine.bordered(&l.j, &p.t));
        note(EventKind::Bifurcation(mode), watch.bifurcation, None);
    }
    if let Some((quantity, target, on)) = watch.crossing {
        let (k0, k1) = (p.value(quantity) - target, q.value(quantity) - target);
        // a point exactly at the value is the crossing (the start, or a
        // point the last step landed on)
        let crossed = (k0 == 0.0 && between[1] == 1)
            || k1 == 0.0
            || (k0 != 0.0 && k0.signum() != k1.signum());
        if on != On::Ignore && crossed {
            let at = if !located(on) {
                None
            } else if k0 == 0.0 {
                Some(p.u.clone())
            } else if k1 == 0.0 {
                Some(q.u.clone())
            } else {
                Some(engine.zero(p, q, k0, k1, &|x: &Point<D>| x.value(quantity) - target)?)
            };
            note(EventKind::Crossing, on, at);
        }
    }
    if watch.displacement_fold != On::Ignore && p.d_delta_bar.signum() != q.d_delta_bar.signum() {
        let at = if located(watch.displacement_fold) {
            Some(
                engine.zero(p, q, p.d_delta_bar, q.d_delta_bar, &|x: &Point<D>| {
                    x.d_delta_bar
                })?,
            )
        } else {
            None
        };
        note(EventKind::DisplacementFold, watch.displacement_fold, at);
    }
    // a minimum of F̄ in the step: looked for on either side of a
    // located fold of ā (F̄ can turn twice in a step that passes one)
    // (the flag: the piece ends at the fold)
    let pieces: Vec<(&Point<D>, &Point<D>, bool)> = match &size_fold {
        Some(f) => vec![(p, f, true), (f, q, false)],
        None => vec![(p, q, false)],
    };
    let minimum = pieces
        .into_iter()
        .find(|(a, b, _)| a.d_force < 0.0 && b.d_force >= 0.0);
    if let (true, Some((a, b, to_fold))) = (watch.force_minimum != On::Ignore, minimum) {
        let at = if located(watch.force_minimum) {
            // on the rate where the tangent is defined throughout the
            // step; by values where a bifurcation point lies in it. A
            // piece that ends at the located fold is parametrised from
            // the fold: from its other end the arclength plane can cut
            // the family twice, on either side of the fold
            let rate = &|x: &Point<D>| x.d_force;
            Some(if a.det_sign == b.det_sign && to_fold {
                engine.zero(b, a, b.d_force, a.d_force, rate)?
            } else if a.det_sign == b.det_sign {
                engine.zero(a, b, a.d_force, b.d_force, rate)?
            } else {
                engine.force_minimum(a, b)?
            })
        } else {
            None
        };
        note(EventKind::ForceMinimum, watch.force_minimum, at);
    }
    Ok((events, stop))
}

#[cfg(test)]
mod tests {
    //! The engine on a family whose answers are known in closed form: the
    //! unit circle x² + δ² = 1 (one equation, u = (x, δ)) with ā = x and
    //! F̄ = x. Traced from (1, 0) towards smaller δ it passes the fold in δ
    //! at (0, −1) and the minimum of F̄ at (−1, 0), where x also turns.

    use super::*;
    use nalgebra::{Matrix2, Vector2, U2};

    struct Circle;

    impl Family<U2> for Circle {
        fn linearise(&self, u: &Vector2<f64>) -> Option<Linear<U2>> {
            Some(Linear {
                r: Vector2::new(u[0] * u[0] + u[1] * u[1] - 1.0, 0.0),
                j: Matrix2::new(2.0 * u[0], 2.0 * u[1], 0.0, 0.0),
                force: u[0],
                force_grad: Vector2::new(1.0, 0.0),
            })
        }
        fn converged(&self, _u: &Vector2<f64>, r: &Vector2<f64>) -> bool {
            r[0].abs() < 1e-12
        }
        fn a_bar_gradient(&self) -> Vector2<f64> {
            Vector2::new(1.0, 0.0)
        }
        fn delta_bar_gradient(&self) -> Vector2<f64> {
            Vector2::new(0.0, 1.0)
        }
        fn stuck(&self, u: &Vector2<f64>, why: &str) -> Error {
            Error::NoState(format!(
                "circle at ({}, {}): {why}",
                crate::error::rounded(u[0]),
                crate::error::rounded(u[1])
            ))
        }
    }

    #[test]
    fn the_circle_folds_where_its_closed_form_says() {
        let watch = Watch {
            size_fold: On::Note,
            displacement_fold: On::Locate,
            force_minimum: On::Stop,
            bifurcation: On::Ignore,
            crossing: Some((Quantity::Delta, -0.5, On::Locate)),
        };
        let settings = Settings {
            step: 0.05,
            max_step: 0.2,
            ..Settings::default()
        };
        let t = trace(
            &Circle,
            Vector2::new(1.0, 0.0),
            &Vector2::new(0.0, -1.0),
            settings,
            watch,
            |_| false,
        )
        .expect("traced");
        assert_eq!(t.end, End::Event(EventKind::ForceMinimum));
        // δ = −1/2 first, at x = √3/2
        let c = t.located(EventKind::Crossing).expect("crossing located");
        assert!(
            (c[0] - 0.75f64.sqrt()).abs() < 1e-12 && (c[1] + 0.5).abs() < 1e-12,
            "{c}"
        );
        // δ turns at (0, −1)
        let d = t
            .located(EventKind::DisplacementFold)
            .expect("fold located");
        assert!(d[0].abs() < 1e-9 && (d[1] + 1.0).abs() < 1e-12, "{d}");
        // F̄ = x is least at (−1, 0), where x turns too
        let f = t.located(EventKind::ForceMinimum).expect("minimum located");
        assert!((f[0] + 1.0).abs() < 1e-12 && f[1].abs() < 1e-9, "{f}");
        assert!(t.events.iter().any(|e| e.kind == EventKind::SizeFold));
        let order: Vec<EventKind> = t.events.iter().map(|e| e.kind).collect();
        let pos = |k| order.iter().position(|&e| e == k).expect("present");
        assert!(pos(EventKind::Crossing) < pos(EventKind::DisplacementFold));
        assert!(pos(EventKind::DisplacementFold) < pos(EventKind::ForceMinimum));
        // every traced point is on the circle
        for p in &t.points {
            assert!((p.u.norm() - 1.0).abs() < 1e-12);
        }
    }

    /// A fold of ā watched with `Locate` is located where dā/dσ = 0 (on the
    /// circle traced from (cos 0.3, sin 0.3) towards smaller δ, x turns at
    /// (1, 0)), not at the first point past it.
    #[test]
    fn a_size_fold_is_located_where_the_size_turns() {
        let watch = Watch {
            size_fold: On::Stop,
            ..Watch::default()
        };
        let settings = Settings {
            step: 0.05,
            max_step: 0.2,
            ..Settings::default()
        };
        let t = trace(
            &Circle,
            Vector2::new(0.3f64.cos(), 0.3f64.sin()),
            &Vector2::new(0.0, -1.0),
            settings,
            watch,
            |_| false,
        )
        .expect("traced");
        assert_eq!(t.end, End::Event(EventKind::SizeFold));
        let f = t.located(EventKind::SizeFold).expect("fold located");
        assert!((f[0] - 1.0).abs() < 1e-12 && f[1].abs() < 1e-6, "{f}");
        // the last traced point is past it, a step away
        let last = &t.points.last().expect("points").u;
        assert!(last[1] < -1e-3, "{last}");
    }

    /// A start exactly at the watched value is the crossing (it has no
    /// bracket to refine).
    #[test]
    fn a_start_on_the_value_is_the_crossing() {
        let watch = Watch {
            crossing: Some((Quantity::Delta, 0.0, On::Stop)),
            ..Watch::default()
        };
        let t = trace(
            &Circle,
            Vector2::new(1.0, 0.0),
            &Vector2::new(0.0, -1.0),
            Settings::default(),
            watch,
            |_| false,
        )
        .expect("traced");
        assert_eq!(t.end, End::Event(EventKind::Crossing));
        assert_eq!(
            t.located(EventKind::Crossing),
            Some(&Vector2::new(1.0, 0.0))
        );
    }

    #[test]
    fn a_corrector_that_always_fails_is_an_error_that_says_where() {
        struct Nowhere;
        impl Family<U2> for Nowhere {
            fn linearise(&self, u: &Vector2<f64>) -> Option<Linear<U2>> {
                Circle.linearise(u)
            }
            fn converged(&self, _u: &Vector2<f64>, _r: &Vector2<f64>) -> bool {
                false
            }
            fn a_bar_gradient(&self) -> Vector2<f64> {
                Circle.a_bar_gradient()
            }
            fn delta_bar_gradient(&self) -> Vector2<f64> {
                Circle.delta_bar_gradient()
            }
            fn stuck(&self, u: &Vector2<f64>, why: &str) -> Error {
                Circle.stuck(u, why)
            }
        }
        let e = trace(
            &Nowhere,
            Vector2::new(1.0, 0.0),
            &Vector2::new(0.0, -1.0),
            Settings::default(),
            Watch::default(),
            |_| false,
        )
        .expect_err("no step is accepted");
        assert!(e.to_string().contains("circle at (1, 0)"), "{e}");
    }
}
