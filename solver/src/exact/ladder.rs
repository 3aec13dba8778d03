//! The one ladder of truncations (issue 69): the rungs a state's contour
//! modes are raised through where a truncation does not resolve it, with
//! the rung being climbed and the one rule for the next
//! ([`Ladder::escalate`]). Which rungs a route climbs is a preset
//! ([`Ladder::conformal`], [`Ladder::arclength`], [`Ladder::notched_arm`],
//! [`Ladder::raised`]) or the user's truncations; what a rung is tried
//! for is the caller's.
//!
//! Owns: [`Ladder`] and its presets. May use: its parent `exact`
//! (`Truncation`, `CONVERGED`).

use super::{Truncation, CONVERGED};

/// The conformal-map form's contour modes ([`Ladder::conformal`]), whose
/// top is the most a user may ask for ([`super::MAX_USER_MODES`]).
pub(crate) const CONFORMAL_MODES: [usize; 12] = [12, 16, 20, 24, 28, 32, 40, 48, 56, 64, 80, 96];

/// The arclength representation's modes of each sign
/// ([`Ladder::arclength`]): in the pull-off followed in ρ
/// (`resolve::pull_off_followed_in_arclength`) 96 carries the pull-off
/// down to ρ ≈ 0.089, 128 to ρ ≈ 0.074, 160 (with the points crowded into
/// the grooves below ρ ≈ 0.068,
/// [`Contour::crowded_at_groove`](super::Contour::crowded_at_groove)) to
/// 0.0415, 192 to 0.0270, 224 to 0.0243, 256 to 0.0188, 288 to 0.0169 and
/// 320 ([`MAX_ESCALATED_MODES`]), to
/// ρ = 0.0141 (θ = 13.5°), where the grooves have narrowed to a half-width
/// of 0.013.
const ARCLENGTH_MODES: [usize; 10] = [48, 64, 96, 128, 160, 192, 224, 256, 288, 320];

/// The most modes of each sign the default escalations try: the
/// arclength ladder's top (320, the pull-off followed down to
/// ρ = 0.0141), more than twice [`super::MAX_USER_MODES`] (the doubling checks of
/// `thinjkr accuracy` stop here).
pub(crate) const MAX_ESCALATED_MODES: usize = ARCLENGTH_MODES[ARCLENGTH_MODES.len() - 1];

/// The modes of each sign beyond [`ARCLENGTH_MODES`] with which a state
/// on the arm of a larger contact is resolved where the arm's trace
/// needed that ladder's top ([`Ladder::notched_arm`]): the notched
/// zero-force state at ρ = 0.3 is left at 4.9e-7 by 320, 3.6e-8 by 384,
/// 2.6e-9 by 448 and 1.9e-10 by 512 ([`super::MAX_MODES`]; docs/exact.md,
/// "Zero force at ρ = 0.3").
const NOTCHED_ARM_MODES: [usize; 3] = [384, 448, 512];

/// The longer series a trace down an arm of a larger contact takes on
/// with, in turn, where its path's modes no longer resolve it
/// ([`Ladder::raised`], `larger_contacts::traced_with_raised_modes`): the
/// notched arm of ā = 3.435 at ρ = 0.3 needs 160 modes below F̄ ≈ 3.5, 256
/// below F̄ ≈ 2.2 and 320 below F̄ ≈ 0.66, down to F̄ = 0 (boundary error
/// 4.9e-7 there).
const RAISED_MODES: [usize; 3] = [160, 256, 320];

/// Truncations in the order they are tried, and the one being tried.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Ladder {
    rungs: Vec<Truncation>,
    /// The rung being tried.
    at: usize,
    /// The modes and boundary errors met on the rungs climbed, from which
    /// [`Ladder::escalate`] extrapolates.
    seen: Vec<(usize, f64)>,
}

impl Ladder {
    /// A ladder of `rungs`, at the first.
    pub(crate) fn of(rungs: Vec<Truncation>) -> Ladder {
        Ladder {
            rungs,
            at: 0,
            seen: Vec::new(),
        }
    }

    /// The default escalation: the conformal-map form with 12, 16, 20, 24,
    /// 28, 32, 40, 48, 56, 64, 80 and 96 contour modes, each with
    /// `POINTS_PER_MODE` quadrature points per mode.
    pub(crate) fn conformal() -> Ladder {
        Ladder::of(CONFORMAL_MODES.map(Truncation::with_modes).to_vec())
    }

    /// The arclength representation's escalation, 48 to 320 modes of each
    /// sign ([`ARCLENGTH_MODES`]).
    pub(crate) fn arclength() -> Ladder {
        Ladder::of(ARCLENGTH_MODES.map(Truncation::in_arclength).to_vec())
    }

    /// The arclength escalation, then 384, 448 and 512 modes
    /// ([`NOTCHED_ARM_MODES`]): a state on the notched arm of a larger
    /// contact.
    pub(crate) fn notched_arm() -> Ladder {
        let mut ladder = Ladder::arclength();
        ladder
            .rungs
            .extend(NOTCHED_ARM_MODES.map(Truncation::in_arclength));
        ladder
    }

    /// 160, 256 and 320 modes of each sign ([`RAISED_MODES`]): a trace
    /// down an arm taken on where its path's modes no longer resolve it.
    pub(crate) fn raised() -> Ladder {
        Ladder::of(RAISED_MODES.map(Truncation::in_arclength).to_vec())
    }

    /// This ladder, then `next`'s rungs.
    pub(crate) fn then(mut self, next: Ladder) -> Ladder {
        self.rungs.extend(next.rungs);
        self
    }

    /// The rungs with at least `modes` modes (of their kind).
    pub(crate) fn from_modes(mut self, modes: usize) -> Ladder {
        self.rungs.retain(|t| t.modes >= modes);
        self
    }

    /// The rungs finer than `t`: the arclength representation's above the
    /// conformal form's, and within a kind more modes above fewer.
    #[cfg(any(feature = "cli", test))]
    pub(crate) fn above(mut self, t: Truncation) -> Ladder {
        let order = |t: &Truncation| (t.arclength > 0, t.modes);
        self.rungs.retain(|r| order(r) > order(&t));
        self
    }

    /// At the first rung with at least `modes` modes, else at the top: a
    /// climb taken on from a state of that many modes.
    pub(crate) fn starting_at(mut self, modes: usize) -> Ladder {
        self.at = self
            .rungs
            .iter()
            .position(|t| t.modes >= modes)
            .unwrap_or(self.rungs.len().saturating_sub(1));
        self
    }

    /// At the rung `t`, else at the top: a climb taken on from a state
    /// found on that rung.
    pub(crate) fn at_rung(mut self, t: Truncation) -> Ladder {
        self.at = self
            .rungs
            .iter()
            .position(|r| *r == t)
            .unwrap_or(self.rungs.len().saturating_sub(1));
        self
    }

    /// The rungs from the one being tried up.
    pub(crate) fn from_rung(&self) -> &[Truncation] {
        &self.rungs[self.at.min(self.rungs.len())..]
    }

    /// Every rung, in order.
    pub(crate) fn rungs(&self) -> &[Truncation] {
        &self.rungs
    }

    /// The rung being tried; `None` on a ladder with no rungs.
    pub(crate) fn rung(&self) -> Option<Truncation> {
        self.rungs.get(self.at).copied()
    }

    /// The top rung's modes (0 on a ladder with no rungs).
    pub(crate) fn top_modes(&self) -> usize {
        self.rungs.last().map_or(0, |t| t.modes)
    }

    /// Notes the boundary error a rung's answer reached, for
    /// [`Ladder::escalate`]'s extrapolation.
    pub(crate) fn saw(&mut self, modes: usize, bc_error: f64) {
        self.seen.push((modes, bc_error));
    }

    /// Climbs to the next rung worth trying; false at the top. With two
    /// boundary errors seen, the error is extrapolated geometrically in the
    /// number of modes from the last two, e₂·r^(N₂ − N) (r from
    /// e₁ = e₂·r^(N₂ − N₁); it falls spectrally), and the climb goes to the
    /// first rung predicted below [`CONVERGED`]/4, else to the top; simply
    /// one rung up where fewer than two are seen or the error did not
    /// fall. An extrapolation that is too hopeful costs one more rung, from
    /// which it is made again.
    pub(crate) fn escalate(&mut self) -> bool {
        let next = self.next_rung();
        if next < self.rungs.len() {
            self.at = next;
            true
        } else {
            false
        }
    }

    fn next_rung(&self) -> usize {
        let i = self.at;
        let [.., (n1, e1), (n2, e2)] = self.seen[..] else {
            return i + 1;
        };
        if !(e2 < e1 && n2 > n1 && e2 > 0.0) {
            return i + 1;
        }
        let log_rate = (e1 / e2).ln() / (n2 - n1) as f64;
        let predicted = |t: &Truncation| e2 * (-log_rate * (t.modes as f64 - n2 as f64)).exp();
        (i + 1..self.rungs.len())
            .find(|&k| predicted(&self.rungs[k]) <= CONVERGED / 4.0)
            .unwrap_or(self.rungs.len().saturating_sub(1))
            .max(i + 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn modes(l: &Ladder) -> Vec<usize> {
        l.rungs().iter().map(|t| t.modes).collect()
    }

    #[test]
    fn the_presets_keep_their_rungs() {
        assert_eq!(modes(&Ladder::conformal()), CONFORMAL_MODES);
        assert!(Ladder::conformal().rungs().iter().all(|t| t.arclength == 0));
        assert_eq!(modes(&Ladder::arclength()), ARCLENGTH_MODES);
        assert_eq!(
            modes(&Ladder::notched_arm())[ARCLENGTH_MODES.len()..],
            NOTCHED_ARM_MODES
        );
        assert_eq!(
            modes(&Ladder::arclength().from_modes(150)),
            [160, 192, 224, 256, 288, 320]
        );
        assert_eq!(super::super::MAX_USER_MODES, 96);
    }

    #[test]
    fn above_orders_the_arclength_form_over_the_conformal() {
        let all = Ladder::conformal().then(Ladder::arclength());
        let from_conformal = all.clone().above(Truncation::with_modes(80));
        assert_eq!(modes(&from_conformal)[..2], [96, 48]);
        let from_arclength = all.above(Truncation::in_arclength(288));
        assert_eq!(modes(&from_arclength), [320]);
    }

    #[test]
    fn escalate_climbs_one_rung_without_a_rate_and_skips_with_one() {
        let mut l = Ladder::conformal();
        assert!(l.escalate());
        assert_eq!(l.rung().unwrap().modes, 16);
        // an error that rose: one rung
        l.saw(12, 1e-5);
        l.saw(16, 2e-5);
        assert!(l.escalate());
        assert_eq!(l.rung().unwrap().modes, 20);
        // 1e-4 at 20 and 1e-6 at 24 modes: a factor 10 in two modes, so
        // 1e-9/4 is predicted from 24 + 2·log10(4000) ≈ 31.2 modes on
        l.saw(20, 1e-4);
        l.saw(24, 1e-6);
        l.at = 3;
        assert!(l.escalate());
        assert_eq!(l.rung().unwrap().modes, 32);
        // from the top, no climb
        l.at = l.rungs().len() - 1;
        assert!(!l.escalate());
        assert_eq!(Ladder::of(Vec::new()).rung(), None);
    }

    #[test]
    fn starting_at_takes_the_first_rung_as_fine_as_the_start() {
        assert_eq!(
            Ladder::arclength().starting_at(100).rung().unwrap().modes,
            128
        );
        assert_eq!(
            Ladder::arclength().starting_at(400).rung().unwrap().modes,
            320
        );
    }
}
