//! The one walk down in ρ (issue 69), and in the gap's parameter (issue
//! 73, `IN_THE_GAP`): a state followed from its ρ to a
//! smaller one in steps that grow by half after each step taken (up to the
//! preset's largest) and are halved after each step missed, until a step
//! no larger than the preset's smallest misses. What a step is (Newton at
//! a held control, a traced pull-off, a path at fixed ā) is the caller's;
//! the step sizes are [`RhoSteps`], one preset per walk.
//!
//! Owns: [`RhoSteps`] and its presets, [`Attempt`], [`Stopped`],
//! [`walk_down`]. May use: `error`, `newton` (the stop request).

use crate::error::Result;

/// The exact state continued from the circle at fixed ā
/// (`Exact::from_circle`): no fine-grid check on the way, long steps.
pub(crate) const FROM_THE_CIRCLE: RhoSteps = RhoSteps {
    first: 0.05,
    largest: 0.1,
    smallest: 1e-4,
};

/// A state at fixed ā and ρ continued in the gap itself, from the
/// cylinders' gap to another, on s = 1 − t from 1 to 0
/// (`Exact::continued_in_the_gap`, issue 73): the same walk, its parameter the
/// share of the known gap.
pub(crate) const IN_THE_GAP: RhoSteps = RhoSteps {
    first: 0.1,
    largest: 0.25,
    smallest: 1e-3,
};

/// A state continued in ρ at its control (`resolve::continued_in_rho`).
pub(crate) const AT_A_CONTROL: RhoSteps = RhoSteps {
    first: 0.01,
    largest: 0.01,
    smallest: 1e-3,
};

/// The pull-off followed in ρ in the arclength representation
/// (`resolve::pull_off_followed_in_arclength`), whose smallest step the
/// stored pull-offs also read.
pub(crate) const PULL_OFF_IN_ARCLENGTH: RhoSteps = RhoSteps {
    first: 0.01,
    largest: 0.02,
    smallest: 0.00125,
};

/// A larger contact's state continued in ρ at its ā
/// (`larger_contacts`).
pub(crate) const AT_FIXED_SIZE: RhoSteps = RhoSteps {
    first: 0.01,
    largest: 0.01,
    smallest: 1e-4,
};

/// The step sizes of a walk in ρ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct RhoSteps {
    /// The first step.
    pub first: f64,
    /// The largest step: a step taken grows by half up to it.
    pub largest: f64,
    /// A missed step is halved while it is larger than this; a step this
    /// small that misses ends the walk.
    pub smallest: f64,
}

/// What one step of a walk gave.
pub(crate) enum Attempt<S, M> {
    /// The state at the step's ρ.
    Took(S),
    /// Try the same step again (the caller raised its modes).
    Again,
    /// The step missed, and why.
    Missed(M),
}

/// Where a walk stopped: the ρ of its last step, which missed with a step
/// no larger than the preset's smallest, and why it missed.
pub(crate) struct Stopped<M> {
    /// The ρ that step aimed at.
    pub next: f64,
    /// Why it missed.
    pub why: M,
}

/// Follows `at` (a state at `rho_of(at)`) down to `rho` with the steps
/// `steps`: `attempt(at, next)` tries the step to `next`. The state at
/// `rho` where every step is taken; else where the walk stopped (`at` holds
/// the last state taken). An error only where the user asked to stop.
pub(crate) fn walk_down<S, M>(
    at: &mut S,
    rho: f64,
    steps: RhoSteps,
    rho_of: impl Fn(&S) -> f64,
    mut attempt: impl FnMut(&S, f64) -> Result<Attempt<S, M>>,
) -> Result<std::result::Result<(), Stopped<M>>> {
    let mut step = steps.first;
    while rho_of(at) > rho {
        crate::newton::check_stop()?;
        let next = (rho_of(at) - step).max(rho);
        match attempt(at, next)? {
            Attempt::Took(s) => {
                *at = s;
                step = (step * 1.5).min(steps.largest);
            }
            Attempt::Again => {}
            Attempt::Missed(_) if step > steps.smallest => step *= 0.5,
            Attempt::Missed(why) => return Ok(Err(Stopped { next, why })),
        }
    }
    Ok(Ok(()))
}

#[cfg(test)]
mod tests {
    use super::*;

    // steps in powers of two: every ρ of these walks is exact in binary
    const STEPS: RhoSteps = RhoSteps {
        first: 0.0625,
        largest: 0.125,
        smallest: 0.03125,
    };

    /// A walk whose steps all succeed grows its step by half to the
    /// preset's largest and ends at the asked ρ.
    #[test]
    fn a_walk_grows_its_steps_to_the_largest() {
        let mut at = 1.0f64;
        let mut tried = Vec::new();
        let end = walk_down(
            &mut at,
            0.5,
            STEPS,
            |r| *r,
            |_, next| {
                tried.push(next);
                Ok(Attempt::<f64, ()>::Took(next))
            },
        )
        .unwrap();
        assert!(end.is_ok() && at == 0.5);
        // 0.0625, then 0.09375, then 0.125 (capped) each time
        assert_eq!(tried, vec![0.9375, 0.84375, 0.71875, 0.59375, 0.5]);
    }

    /// A walk whose steps past a wall all miss halves its step down to the
    /// smallest and stops there, naming the step and keeping the last
    /// state taken.
    #[test]
    fn a_walk_halves_its_missed_steps_and_stops_at_the_smallest() {
        let mut at = 1.0f64;
        let mut tried = Vec::new();
        let end = walk_down(
            &mut at,
            0.5,
            STEPS,
            |r| *r,
            |_, next| {
                tried.push(next);
                Ok(if next >= 0.84375 {
                    Attempt::Took(next)
                } else {
                    Attempt::Missed(next)
                })
            },
        )
        .unwrap();
        let stopped = end.err().expect("stopped at the wall");
        assert_eq!(at, 0.84375);
        // missed with 0.125, 0.0625, then 0.03125: no smaller step
        assert_eq!(tried, vec![0.9375, 0.84375, 0.71875, 0.78125, 0.8125]);
        assert_eq!((stopped.next, stopped.why), (0.8125, 0.8125));
    }

    /// A step tried again (the caller's modes raised) keeps its size.
    #[test]
    fn a_step_tried_again_keeps_its_size() {
        let mut at = 1.0f64;
        let mut tried = Vec::new();
        let mut again = true;
        let end = walk_down(
            &mut at,
            0.9375,
            STEPS,
            |r| *r,
            |_, next| {
                tried.push(next);
                Ok(if std::mem::take(&mut again) {
                    Attempt::<f64, ()>::Again
                } else {
                    Attempt::Took(next)
                })
            },
        )
        .unwrap();
        assert!(end.is_ok());
        assert_eq!(tried, vec![0.9375, 0.9375]);
    }
}
