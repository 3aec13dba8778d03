//! The one test of "is this the same state?" (issue 69): a state found
//! again (with more modes, from a model's guess, past a fold) is taken
//! for the one it was sought near when its size ā and aspect ratio s lie
//! (and, where the preset asks, its force F̄) within a preset's
//! tolerances of that one's, and, where the preset asks,
//! its fine-grid boundary error is below a bound (a state off the
//! near-elliptic family is no match however close). The presets name why
//! each tolerance is what it is.
//!
//! Owns: [`Same`], [`Within`] and the presets. May use: its parent `exact`
//! (`ExactState`), `seed` (`Guess`).

use super::seed::Guess;
use super::ExactState;

/// How close one number must be to another.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Within {
    /// |x/x₀ − 1| at most this.
    Relative(f64),
    /// |x − x₀| at most this.
    Absolute(f64),
    /// Not compared.
    Any,
}

impl Within {
    fn holds(self, x: f64, x0: f64) -> bool {
        match self {
            Within::Relative(t) => (x / x0 - 1.0).abs() <= t,
            Within::Absolute(t) => (x - x0).abs() <= t,
            Within::Any => true,
        }
    }
}

/// When a state is the one sought near another: ā, s and F̄ within their
/// tolerances, and the boundary error at most `bc_error`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Same {
    pub(crate) a_bar: Within,
    pub(crate) s: Within,
    pub(crate) force_bar: Within,
    /// The largest fine-grid boundary error of a match (∞: not asked).
    pub(crate) bc_error: f64,
}

/// A state's size, aspect ratio and force, what [`Same`] compares.
pub(crate) trait SizeAndShape {
    fn a_bar_s_force(&self) -> (f64, f64, f64);
}

impl SizeAndShape for ExactState {
    fn a_bar_s_force(&self) -> (f64, f64, f64) {
        (self.a_bar, self.s, self.force_bar)
    }
}

impl SizeAndShape for Guess {
    fn a_bar_s_force(&self) -> (f64, f64, f64) {
        (self.a_bar, self.s, self.force_bar)
    }
}

impl Same {
    /// The exact state near a model's (or a coarser truncation's) state it
    /// was started from: near-elliptic (boundary error at most 1e-2, more
    /// modes may resolve it), ā within 2 %, s within 5 %.
    pub(crate) const NEAR_THE_START: Same = Same {
        a_bar: Within::Relative(0.02),
        s: Within::Relative(0.05),
        force_bar: Within::Any,
        bc_error: 1e-2,
    };

    /// On the same side of the circle's bifurcations as the state it was
    /// started from (a contour within a few per cent of its shape): s
    /// within 5 %, near-elliptic.
    pub(crate) const SAME_SIDE: Same = Same {
        a_bar: Within::Any,
        s: Within::Relative(0.05),
        force_bar: Within::Any,
        bc_error: 1e-2,
    };

    /// The state traced from a model's size to the control: near-elliptic,
    /// ā within 2 % of the model's (its s is the trace's).
    pub(crate) const TRACED_NEAR_THE_START: Same = Same {
        a_bar: Within::Relative(0.02),
        s: Within::Any,
        force_bar: Within::Any,
        bc_error: 1e-2,
    };

    /// [`Same::SAME_SIDE`] without the boundary error: the shape alone.
    pub(crate) const SAME_SHAPE: Same = Same {
        a_bar: Within::Any,
        s: Within::Relative(0.05),
        force_bar: Within::Any,
        bc_error: f64::INFINITY,
    };

    /// The same state solved again with more modes at its control: ā
    /// within 1e-3 (not a neighbour on the family).
    pub(crate) const AGAIN: Same = Same {
        a_bar: Within::Relative(1e-3),
        s: Within::Any,
        force_bar: Within::Any,
        bc_error: f64::INFINITY,
    };

    /// A crossing past a band's fold resolved again: where the trace
    /// crossed, ā within 0.01 and s within 1 %.
    pub(crate) const AT_THE_CROSSING: Same = Same {
        a_bar: Within::Absolute(0.01),
        s: Within::Relative(0.01),
        force_bar: Within::Any,
        bc_error: f64::INFINITY,
    };

    /// One state found twice (by two brackets of one screen): ā within
    /// 1e-6.
    pub(crate) const FOUND_TWICE: Same = Same {
        a_bar: Within::Absolute(1e-6),
        s: Within::Any,
        force_bar: Within::Any,
        bc_error: f64::INFINITY,
    };

    /// The minimum of F̄ a loading or unloading path meets is the pull-off
    /// itself: F̄ within 1e-6 and ā within 1e-3 (the path's minimum is
    /// located less finely in ā, where F̄ is flat).
    #[cfg(any(feature = "cli", test))]
    pub(crate) const THE_PULL_OFF: Same = Same {
        a_bar: Within::Relative(1e-3),
        s: Within::Any,
        force_bar: Within::Relative(1e-6),
        bc_error: f64::INFINITY,
    };

    /// The state itself (a descent that stays where it started): ā to
    /// 1e-6 of itself, s to 1e-6.
    #[cfg(any(feature = "cli", test))]
    pub(crate) const ITSELF: Same = Same {
        a_bar: Within::Relative(1e-6),
        s: Within::Absolute(1e-6),
        force_bar: Within::Any,
        bc_error: f64::INFINITY,
    };

    /// Whether `st` (with its boundary error `bc_error`) is the state
    /// sought near `near`.
    pub(crate) fn holds(
        &self,
        st: &impl SizeAndShape,
        bc_error: f64,
        near: &impl SizeAndShape,
    ) -> bool {
        let ((a, s, f), (a0, s0, f0)) = (st.a_bar_s_force(), near.a_bar_s_force());
        bc_error <= self.bc_error
            && self.a_bar.holds(a, a0)
            && self.s.holds(s, s0)
            && self.force_bar.holds(f, f0)
    }

    /// [`Same::holds`] for an exact state, with its own boundary error.
    pub(crate) fn of(&self, st: &ExactState, near: &impl SizeAndShape) -> bool {
        self.holds(st, st.bc_error, near)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn guess(a_bar: f64, s: f64) -> Guess {
        Guess {
            a_bar,
            b_bar: s * a_bar,
            s,
            delta_bar: 0.0,
            force_bar: -2.0,
            bc_defect: 0.0,
        }
    }

    #[test]
    fn each_preset_holds_inside_its_tolerances_and_not_beyond() {
        let g = guess(3.0, 0.8);
        let near = Same::NEAR_THE_START;
        assert!(near.holds(&guess(3.059, 0.839), 1e-2, &g));
        assert!(!near.holds(&guess(3.061, 0.8), 1e-3, &g));
        assert!(!near.holds(&guess(3.0, 0.841), 1e-3, &g));
        assert!(!near.holds(&guess(3.0, 0.8), 1.1e-2, &g));
        assert!(Same::SAME_SIDE.holds(&guess(9.0, 0.8), 1e-3, &g));
        assert!(!Same::SAME_SHAPE.holds(&guess(3.0, 0.76 - 1e-9), 1.0, &g));
        assert!(Same::SAME_SHAPE.holds(&guess(3.0, 0.76 + 1e-9), 1.0, &g));
        assert!(Same::AGAIN.holds(&guess(3.0029, 0.1), 1.0, &g));
        assert!(!Same::AGAIN.holds(&guess(3.0031, 0.8), 0.0, &g));
        assert!(Same::AT_THE_CROSSING.holds(&guess(3.0099, 0.8079), 0.0, &g));
        assert!(!Same::AT_THE_CROSSING.holds(&guess(3.0101, 0.8), 0.0, &g));
        assert!(Same::FOUND_TWICE.holds(&guess(3.0 + 9e-7, 0.5), 0.0, &g));
        assert!(!Same::FOUND_TWICE.holds(&guess(3.0 + 2e-6, 0.8), 0.0, &g));
        let mut off = guess(3.0029, 0.5);
        assert!(Same::THE_PULL_OFF.holds(&off, 1.0, &g));
        off.force_bar = -2.0 * (1.0 + 1.1e-6);
        assert!(!Same::THE_PULL_OFF.holds(&off, 0.0, &g));
        assert!(Same::ITSELF.holds(&guess(3.0 + 2.9e-6, 0.8 + 9e-7), 1.0, &g));
        assert!(!Same::ITSELF.holds(&guess(3.0, 0.8 + 1.1e-6), 0.0, &g));
    }
}
