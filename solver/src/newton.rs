//! Damped Newton's method, written once for every model and any number of
//! unknowns (`damped`: static nalgebra vectors where the size is known,
//! dynamic otherwise), with a backtracking line search on the scaled
//! residual norm that also keeps the iterate inside the model's domain.
//! [`solve`] and `solve_within` are its form for the ellipse models'
//! two residuals in x = (ā, s) (for the paper's model, (19)–(20)) on the
//! domain ā > 0, 0 < s ≤ 1; `conformal:K` uses it in x = (c, δ̄).
//! `chord` is Newton's method with the Jacobian kept while it serves,
//! for a system whose Jacobian costs far more than its residuals (the
//! exact solver's).
//!
//! A caller may ask a long computation to stop (the Python package's
//! Ctrl-C): run it [`stoppable`] with a flag, and once the flag is raised
//! every iteration of `chord` (the exact solver's Newton) on that
//! computation's threads fails at once, and so do the escalations and
//! continuations above it (`check_stop`), so the computation unwinds in
//! moments; the caller discards what it returns. `damped` does not look:
//! its solves take microseconds, and a check in its loop measurably slowed
//! the energy model's cold solve (about 20 %).
//!
//! Owns: [`NewtonConfig`], `Problem`, `Iterate`, `damped`, `chord`
//! (`ChordSystem`, `ChordConfig`, `ChordStop`), [`solve`],
//! `solve_within`, the stop flag ([`stoppable`]). May use: `error`,
//! nalgebra.

use crate::error::{Error, Result};
use nalgebra::allocator::Allocator;
use nalgebra::{
    DVector, DefaultAllocator, Dim, DimMin, Dyn, Matrix2, OMatrix, OVector, Vector2, LU,
};

thread_local! {
    /// The stop flag of the computation running on this thread.
    static STOP: std::cell::RefCell<Option<std::sync::Arc<std::sync::atomic::AtomicBool>>> =
        const { std::cell::RefCell::new(None) };
}

/// Run `f` so that raising `stop` (from another thread) makes every
/// iteration of the exact solver's Newton inside it fail at once: `f` then returns soon, with an
/// error the caller discards. Work `f` hands to other threads carries the
/// flag with it (`carried`).
pub fn stoppable<T>(
    stop: &std::sync::Arc<std::sync::atomic::AtomicBool>,
    f: impl FnOnce() -> T,
) -> T {
    carried(Some(stop.clone()), f)
}

/// The stop flag of the computation on this thread, to hand to work on
/// other threads ([`carried`]).
pub(crate) fn stop_flag() -> Option<std::sync::Arc<std::sync::atomic::AtomicBool>> {
    STOP.with(|s| s.borrow().clone())
}

/// Run `f` under the stop flag `stop` (from [`stop_flag`]), restoring the
/// thread's own flag afterwards.
pub(crate) fn carried<T>(
    stop: Option<std::sync::Arc<std::sync::atomic::AtomicBool>>,
    f: impl FnOnce() -> T,
) -> T {
    struct Restore(Option<std::sync::Arc<std::sync::atomic::AtomicBool>>);
    impl Drop for Restore {
        fn drop(&mut self) {
            let old = self.0.take();
            STOP.with(|s| *s.borrow_mut() = old);
        }
    }
    let _restore = Restore(STOP.with(|s| s.replace(stop)));
    f()
}

/// Whether the computation on this thread has been asked to stop.
pub(crate) fn stop_requested() -> bool {
    STOP.with(|s| {
        s.borrow()
            .as_ref()
            .is_some_and(|f| f.load(std::sync::atomic::Ordering::Relaxed))
    })
}

/// `Err` once the computation on this thread has been asked to stop: for
/// the loops above Newton's (escalations, continuations), so that they end
/// at their next step rather than try every fallback.
pub(crate) fn check_stop() -> Result<()> {
    if stop_requested() {
        return Err(Error::NoState("stopped at the caller's request".into()));
    }
    Ok(())
}

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
pub(crate) fn solve_within(
    f: impl Fn(Vector2<f64>) -> (Vector2<f64>, Matrix2<f64>),
    scale: impl Fn(f64) -> f64,
    start: Vector2<f64>,
    config: &NewtonConfig,
    context: &str,
    admissible: impl Fn(Vector2<f64>) -> bool,
) -> Result<Solution> {
    let problem = Problem {
        equations: |x: &Vector2<f64>| f(*x),
        norm: |r: &Vector2<f64>, x: &Vector2<f64>| r.norm() / scale(x[0]),
        // ā > 0, 0 < s ≤ 1 (s a hair above 1 is taken as 1)
        domain: |x: &Vector2<f64>| {
            (x[0] > 0.0 && x[1] > 0.0 && x[1] <= 1.0 + 1e-12)
                .then(|| Vector2::new(x[0], x[1].min(1.0)))
                .filter(|y| admissible(*y))
        },
        // ā relative, s absolute
        small_step: |d: &Vector2<f64>, x: &Vector2<f64>| {
            d[0].abs() <= config.step_tolerance * (1.0 + x[0].abs())
                && d[1].abs() <= config.step_tolerance
        },
    };
    match damped(&problem, start, config) {
        Ok(c) => Ok(Solution {
            a_bar: c.x[0],
            s: c.x[1],
            iterations: c.iterations,
            residual: c.residual,
        }),
        Err(c) => Err(Error::NoConvergence {
            iterations: config.max_iterations,
            a_bar: c.x[0],
            s: c.x[1],
            residual: c.residual,
            context: context.to_string(),
        }),
    }
}

/// A system for [`damped`]: its equations with their Jacobian, the norm
/// that decides convergence, its domain and what a negligible step is.
pub(crate) struct Problem<F, N, P, S> {
    /// The residuals r(x) and ∂r/∂x, side by side.
    pub equations: F,
    /// The scaled residual norm at x.
    pub norm: N,
    /// x itself (or x moved onto the domain's edge) where it lies in the
    /// domain; `None` outside (the line search then shortens the step).
    pub domain: P,
    /// Whether a Newton step d at x is negligible.
    pub small_step: S,
}

/// Where [`damped`] ended: the last iterate, its scaled residual norm, the
/// Jacobian there and the iterations used.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Iterate<D: Dim>
where
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
{
    /// The iterate.
    pub x: OVector<f64, D>,
    /// ∂r/∂x at the iterate (as the equations gave it), for a caller that
    /// goes on from there (a tangent, a stability test).
    pub jacobian: OMatrix<f64, D, D>,
    /// Its scaled residual norm.
    pub residual: f64,
    /// Iterations used.
    pub iterations: usize,
}

/// Damped Newton's method for r(x) = 0 in any number of unknowns (static
/// or dynamic nalgebra vectors), written once for every model: a full
/// step, halved until the scaled norm falls (Armijo, 1e-4) and the iterate
/// stays in the domain. Converged when the norm is below the tolerance, or
/// below `stall_residual` with a negligible step or an iteration that no
/// longer halves it (the round-off floor of its evaluation). `Err` with the
/// last iterate otherwise.
pub(crate) fn damped<D, F, N, P, S>(
    problem: &Problem<F, N, P, S>,
    start: OVector<f64, D>,
    config: &NewtonConfig,
) -> std::result::Result<Iterate<D>, Iterate<D>>
where
    D: Dim + DimMin<D, Output = D>,
    DefaultAllocator: Allocator<D> + Allocator<D, D>,
    F: Fn(&OVector<f64, D>) -> (OVector<f64, D>, OMatrix<f64, D, D>),
    N: Fn(&OVector<f64, D>, &OVector<f64, D>) -> f64,
    P: Fn(&OVector<f64, D>) -> Option<OVector<f64, D>>,
    S: Fn(&OVector<f64, D>, &OVector<f64, D>) -> bool,
{
    let mut x = start;
    let (mut r, mut j) = (problem.equations)(&x);
    let mut rn = (problem.norm)(&r, &x);
    let done = |x: OVector<f64, D>,
                jacobian: OMatrix<f64, D, D>,
                residual: f64,
                iterations: usize| Iterate {
        x,
        jacobian,
        residual,
        iterations,
    };
    for it in 0..config.max_iterations {
        if rn.is_finite() && rn < config.tolerance {
            return Ok(done(x, j, rn, it));
        }

        let step = j.clone().lu().solve(&(-&r));
        let Some(step) = step.filter(|d| d.iter().all(|v| v.is_finite())) else {
            break;
        };
        if (problem.small_step)(&step, &x) && rn < config.stall_residual {
            return Ok(done(x, j, rn, it));
        }
        let mut lambda = 1.0;
        let mut accepted = false;
        while lambda >= config.min_step {
            if let Some(xn) = (problem.domain)(&(&x + &step * lambda)) {
                let (rt, jt) = (problem.equations)(&xn);
                let rtn = (problem.norm)(&rt, &xn);
                if rtn.is_finite() && rtn < rn * (1.0 - 1e-4 * lambda) {
                    if rn < config.stall_residual && rtn > 0.5 * rn {
                        return Ok(done(xn, jt, rtn, it + 1));
                    }
                    (x, r, j, rn) = (xn, rt, jt, rtn);
                    accepted = true;
                    break;
                }
            }
            lambda *= 0.5;
        }
        if !accepted {
            if rn < config.tolerance * 1e3 {
                return Ok(done(x, j, rn, it));
            }
            break;
        }
    }
    if rn.is_finite() && rn < config.tolerance {
        return Ok(done(x, j, rn, config.max_iterations));
    }
    Err(done(x, j, rn, config.max_iterations))
}

/// A system for [`chord`]: its residuals alone (cheap) and its factorised
/// Jacobian (dear), each `None` where the system is not defined at u.
pub(crate) trait ChordSystem {
    /// r(u).
    fn residuals(&self, u: &DVector<f64>) -> Option<DVector<f64>>;
    /// The LU factors of ∂r/∂u at u.
    fn jacobian(&self, u: &DVector<f64>) -> Option<LU<f64, Dyn, Dyn>>;
}

/// The bounds of [`chord`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ChordConfig {
    /// The residuals' round-off floor (max norm): below it the iterate is
    /// taken as it is (further steps only move along a near-singular
    /// direction, as at a bifurcation point).
    pub floor: f64,
    /// Converged when the steps stall with the max norm below this.
    pub tolerance: f64,
    /// Iteration limit.
    pub max_iterations: usize,
}

/// Why [`chord`] stopped without converging.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ChordFailure {
    /// The residuals are not defined at the start.
    NoResiduals,
    /// The Jacobian is not defined (singular) at an iterate.
    NoJacobian,
    /// The Newton step is not finite.
    SingularStep,
    /// No damping of a fresh step reduced the residual.
    LineSearch,
    /// The steps stalled above the tolerance.
    Stalled,
    /// The iteration limit (this many iterations).
    Iterations(usize),
    /// The caller asked the computation to stop ([`stoppable`]).
    Stopped,
}

impl std::fmt::Display for ChordFailure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ChordFailure::NoResiduals => f.write_str("singular boundary integral equation"),
            ChordFailure::NoJacobian => f.write_str("singular system in the Jacobian"),
            ChordFailure::SingularStep => f.write_str("singular Newton matrix"),
            ChordFailure::LineSearch => f.write_str("line search failed"),
            ChordFailure::Stalled => f.write_str("Newton stalled above the residual tolerance"),
            ChordFailure::Iterations(n) => write!(f, "no convergence in {n} Newton iterations"),
            ChordFailure::Stopped => f.write_str("stopped at the caller's request"),
        }
    }
}

/// Where [`chord`] stopped without converging: the last iterate, its
/// residual (max norm; NaN where none), the iterations used and why.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ChordStop {
    /// The last iterate.
    pub u: DVector<f64>,
    /// Its residual.
    pub residual: f64,
    /// Iterations used.
    pub iterations: usize,
    /// Why it stopped.
    pub why: ChordFailure,
}

/// Newton's method with the Jacobian kept while it serves (the chord
/// method), for a system whose Jacobian costs far more than its residuals
/// (the exact solver's boundary integral equations): the Jacobian is
/// refreshed after a step that reduced the residual (max norm) less than
/// fourfold or needed damping, and before a damped step is taken with an
/// old one; a fresh step is halved (down to 1e-4) until the residual
/// falls. Converged at the round-off floor, or when the steps stall
/// (below 1e-13 relative, or below 1e-9 and no longer halving) with the
/// residual below the tolerance, or when no damping of a fresh step
/// reduces a residual already below the tolerance (the system's own
/// round-off floor lies above `floor`). It begins with the factorised Jacobian
/// `first` where one is given (made at a nearby point, such as the
/// converged state a continuation steps from), kept while it serves and
/// refreshed as any old one is; `None` factorises at `start`.
pub(crate) fn chord(
    system: &impl ChordSystem,
    start: DVector<f64>,
    first: Option<LU<f64, Dyn, Dyn>>,
    config: &ChordConfig,
) -> std::result::Result<DVector<f64>, ChordStop> {
    let mut u = start;
    let stop = |u: &DVector<f64>, residual: f64, iterations: usize, why: ChordFailure| ChordStop {
        u: u.clone(),
        residual,
        iterations,
        why,
    };
    let Some(mut r) = system.residuals(&u) else {
        return Err(stop(&u, f64::NAN, 0, ChordFailure::NoResiduals));
    };
    let mut lu = first;
    let mut last_step = f64::INFINITY;
    for it in 0..config.max_iterations {
        if r.amax() <= config.floor {
            return Ok(u);
        }
        if stop_requested() {
            return Err(stop(&u, r.amax(), it, ChordFailure::Stopped));
        }
        let fresh = lu.is_none();
        let step = {
            let factors = match &lu {
                Some(f) => f,
                None => match system.jacobian(&u) {
                    Some(f) => lu.insert(f),
                    None => return Err(stop(&u, r.amax(), it, ChordFailure::NoJacobian)),
                },
            };
            match factors
                .solve(&(-&r))
                .filter(|v| v.iter().all(|x| x.is_finite()))
            {
                Some(step) => step,
                None => return Err(stop(&u, r.amax(), it, ChordFailure::SingularStep)),
            }
        };
        // damp until the residual decreases
        let mut lambda = 1.0;
        let r0 = r.amax();
        let accepted = loop {
            let un = &u + &step * lambda;
            match system.residuals(&un) {
                Some(rn) if rn.amax() < r0 || r0 < config.floor => break Some((un, rn)),
                _ if !fresh => break None,
                _ if lambda > 1e-4 => lambda *= 0.5,
                // no damping of a fresh step reduces a residual already
                // within the tolerance: this system's round-off floor lies
                // above `floor` (more modes, crowded points); converged
                _ if r0 < config.tolerance => return Ok(u),
                _ => return Err(stop(&u, r0, it, ChordFailure::LineSearch)),
            }
        };
        let Some((un, rn)) = accepted else {
            // an old Jacobian that does not give descent: refresh it
            lu = None;
            continue;
        };
        if lambda < 1.0 || rn.amax() > 0.25 * r0 {
            lu = None;
        }
        u = un;
        r = rn;
        let size = step.amax() * lambda;
        if size < 1e-13 * (1.0 + u.amax()) || (size < 1e-9 && size > 0.5 * last_step) {
            // converged only if the residual holds to the tolerance, not
            // merely because the steps stalled
            let res = r.amax();
            if res < config.tolerance {
                return Ok(u);
            }
            return Err(stop(&u, res, it, ChordFailure::Stalled));
        }
        last_step = size;
    }
    Err(stop(
        &u,
        r.amax(),
        config.max_iterations,
        ChordFailure::Iterations(config.max_iterations),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// r(u) = u − 1 held at least `noise` in size (its round-off floor: no
    /// step reduces a residual of that size), with the exact Jacobian 1.
    struct Noisy {
        noise: f64,
    }

    impl ChordSystem for Noisy {
        fn residuals(&self, u: &DVector<f64>) -> Option<DVector<f64>> {
            let e = u[0] - 1.0;
            Some(DVector::from_element(
                1,
                e.signum() * e.abs().max(self.noise),
            ))
        }
        fn jacobian(&self, _: &DVector<f64>) -> Option<LU<f64, Dyn, Dyn>> {
            Some(nalgebra::DMatrix::from_element(1, 1, 1.0).lu())
        }
    }

    const CONFIG: ChordConfig = ChordConfig {
        floor: 1e-13,
        tolerance: 1e-11,
        max_iterations: 60,
    };

    #[test]
    fn a_round_off_floor_within_the_tolerance_is_converged() {
        // the floor 1e-12 lies above `floor` and below the tolerance
        let u = chord(
            &Noisy { noise: 1e-12 },
            DVector::from_element(1, 3.0),
            None,
            &CONFIG,
        )
        .unwrap_or_else(|stop| panic!("{} at residual {:e}", stop.why, stop.residual));
        assert!((u[0] - 1.0).abs() <= 2e-12, "{}", u[0]);
    }

    #[test]
    fn a_round_off_floor_above_the_tolerance_is_a_failure() {
        let stop = chord(
            &Noisy { noise: 1e-9 },
            DVector::from_element(1, 3.0),
            None,
            &CONFIG,
        )
        .expect_err("a residual of 1e-9 is above the tolerance 1e-11");
        assert!(stop.residual >= 1e-11, "{:e}", stop.residual);
        assert!(
            matches!(stop.why, ChordFailure::LineSearch | ChordFailure::Stalled),
            "{}",
            stop.why
        );
    }
}
