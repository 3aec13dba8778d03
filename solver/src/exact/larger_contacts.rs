//! A state at a given δ̄ or F̄ below the fold in ρ of its family (issue 32):
//! from the arms of larger contacts. Continued in ρ at the control, the
//! near-elliptic family turns back (at F̄ = 10 near ρ = 0.3224, at F̄ = 0
//! near 0.357: [`super::rho_path`]), but the contact sizes above the
//! control's state are not bound to that fold: continued in ρ at fixed ā
//! (regular where the control is not), they reach smaller ρ, on the pieces
//! of the family between the bands of its contour modes. At the ρ asked
//! for, the arm through the first such size where the control's value is
//! exceeded is traced down in ā, through its folds in ā, to the control.
//! That state is a state of the problem, not the one a contact holds: it
//! can be unstable (at ρ = 0.3 and F̄ = 10, to n = 2); which state a
//! contact takes is the loading path's question (`studies::loading`).
//!
//! Owns: [`from_larger_contacts`]. May use: `exact` (the
//! problem, `branch`'s trace through folds), `control`, `error`, `newton`
//! (the stop request), `progress` (the stage a spinner shows).

use super::branch::{ArmEnd, PAST_FOLD_STEPS};
use super::ladder::Ladder;
use super::{Exact, ExactState, Truncation};
use crate::control::Hold;
use crate::error::{rounded, Error, Result};

/// The spacing in ā of the contact sizes continued in ρ, above the
/// control's state at the larger ρ: narrower than the pieces between the
/// bands of neighbouring even modes near ā ≈ 3.5 (about 0.15 at ρ = 0.3).
const SIZE_STEP: f64 = 0.04;

/// How many contact sizes are tried, the first [`SIZE_STEP`] above the
/// control's state at the larger ρ.
const SIZES: usize = 15;

/// The arclength representation's modes of each sign on the way (the
/// state at the control is then resolved by the caller's escalation):
/// at ρ = 0.22 and ā = 3.8 they leave a boundary error of 5e-9.
pub(crate) const PATH_MODES: usize = 96;

/// Where a trace down an arm ends: its contour off the ellipse with its
/// half-widths by more than this times ā. At ρ = 0.3 the arm of ā = 3.24
/// reaches F̄ = 0 0.116 ā off its ellipse (a state 128 modes resolve to
/// 1e-11), the notched arm of ā = 3.435 0.198 ā off (320 modes on the way):
/// the 10 % at which a trace past a band's fold stops
/// ([`super::branch::PAST_FOLD_DEPARTURE`]) would miss both. Whether the
/// series still resolves a contour that far out is checked on the way
/// ([`ON_THE_WAY`]), not presumed.
const ARM_DEPARTURE: f64 = 0.3;

/// The largest fine-grid boundary error of a state on the way.
const ON_THE_WAY: f64 = 1e-6;

/// The state at `control` at `rho` on the arm of the first contact size
/// above `start` (the state at the control at a larger ρ) that, continued in
/// ρ at fixed ā, arrives at `rho` beyond the control's value, traced from
/// there down in ā through its folds to the control
/// ([`Exact::first_crossing_through_folds`]), with [`PATH_MODES`] modes
/// (the caller resolves it). Sizes that stop on the way
/// (a band's edge), or arrive below the control's value, are passed over;
/// an error says so where none reaches the control.
pub(crate) fn from_larger_contacts(
    start: &ExactState,
    rho: f64,
    control: Hold,
) -> Result<ExactState> {
    let t = Truncation::in_arclength(PATH_MODES);
    let at_start = Exact::on(start.gap, start.rho, t)?.deferring_stability();
    let at_rho = Exact::on(start.gap, rho, t)?.deferring_stability();
    let mut guess = start.clone();
    let mut tried = Vec::new();
    for k in 1..=SIZES {
        crate::newton::check_stop()?;
        let a_bar = start.a_bar + SIZE_STEP * k as f64;
        crate::progress::stage(format!(
            "the arm of the larger contact a = {a_bar:.2} from rho = {} ({k} of {SIZES})",
            rounded(start.rho)
        ));
        let Ok(here) = at_start.solve_at(Hold::Size(a_bar), &guess.contour, guess.delta_bar) else {
            tried.push(format!(
                "a = {a_bar:.2}: none at rho = {}",
                rounded(start.rho)
            ));
            continue;
        };
        guess = here.clone();
        let arrived = match at_fixed_size(here, rho) {
            Ok(st) => st,
            Err(stopped) => {
                tried.push(format!(
                    "a = {a_bar:.2}: stops at rho = {}",
                    rounded(stopped)
                ));
                continue;
            }
        };
        let excess = control.excess(arrived.a_bar, arrived.delta_bar, arrived.force_bar);
        if excess <= 0.0 {
            tried.push(format!("a = {a_bar:.2}: arrives below the control"));
            continue;
        }
        match traced_with_raised_modes(&at_rho, &arrived, control) {
            Ok(ArmEnd::Reached(state)) => return Ok(*state),
            Ok(ArmEnd::EndsBefore) => tried.push(format!(
                "a = {a_bar:.2}: its arm ends before the control (a minimum of F, or {} % of a off the ellipse)",
                100.0 * ARM_DEPARTURE
            )),
            Ok(ArmEnd::OutOfSteps) => tried.push(format!(
                "a = {a_bar:.2}: its arm is traced for {PAST_FOLD_STEPS} steps without reaching the control"
            )),
            Ok(ArmEnd::Unresolved {
                a_bar: at,
                force_bar,
                bc_error,
                modes,
                ..
            }) => tried.push(format!(
                "a = {a_bar:.2}: {modes} modes no longer resolve its arm at a = {}, F = {} (boundary error {bc_error:.1e})",
                rounded(at),
                rounded(force_bar)
            )),
            Err(e) => tried.push(format!(
                "a = {a_bar:.2}: the trace down its arm fails ({})",
                e.detail()
            )),
        }
    }
    Err(Error::NoState(format!(
        "no arm of a larger contact continued in rho at fixed a from rho = {} reaches {control} at rho = {} ({})",
        rounded(start.rho),
        rounded(rho),
        tried.join("; ")
    )))
}

/// The arm through `arrived` (at ρ of `at_rho`, with [`PATH_MODES`] modes)
/// traced down in ā through its folds to `control`
/// ([`Exact::first_crossing_through_folds`]); where the series no longer
/// resolves the arm (a notch grows on it: docs/exact.md, "Zero force at
/// ρ = 0.3"), taken on from the last state it resolved with the next of
/// [`Ladder::raised`], solved again at that state's ā (and accepted within
/// 1e-6 in F̄ of it: the same arm), the way ā was moving.
pub(crate) fn traced_with_raised_modes(
    at_rho: &Exact,
    arrived: &ExactState,
    control: Hold,
) -> Result<ArmEnd> {
    let mut end = at_rho.first_crossing_through_folds(
        arrived,
        -1.0,
        control,
        0.02,
        ON_THE_WAY,
        ARM_DEPARTURE,
    )?;
    for &t in Ladder::raised().rungs() {
        crate::newton::check_stop()?;
        let ArmEnd::Unresolved {
            resolved_before: Some((last, direction)),
            ..
        } = &end
        else {
            return Ok(end);
        };
        let finer = Exact::on(arrived.gap, arrived.rho, t)?.deferring_stability();
        let from = finer.solve_at(Hold::Size(last.a_bar), &last.contour, last.delta_bar)?;
        if (from.force_bar - last.force_bar).abs() > 1e-6 * last.force_bar.abs().max(1.0) {
            return Err(Error::NoState(format!(
                "with {} modes the arm's state at a = {} has F = {}, not its F = {}",
                t.modes,
                rounded(last.a_bar),
                rounded(from.force_bar),
                rounded(last.force_bar)
            )));
        }
        end = finer.first_crossing_through_folds(
            &from,
            *direction,
            control,
            0.02,
            ON_THE_WAY,
            ARM_DEPARTURE,
        )?;
    }
    Ok(end)
}

/// `st` continued in ρ at its ā down to `rho` (Newton at fixed ā from the
/// state before, the steps [`AT_FIXED_SIZE`](super::rho_walk::AT_FIXED_SIZE));
/// where it stops, the smallest ρ reached.
fn at_fixed_size(mut st: ExactState, rho: f64) -> std::result::Result<ExactState, f64> {
    let held = Hold::Size(st.a_bar);
    let walked = super::rho_walk::walk_down(
        &mut st,
        rho,
        super::rho_walk::AT_FIXED_SIZE,
        |st| st.rho,
        |st, next| {
            let next_state = Exact::on(st.gap, next, st.truncation).and_then(|ex| {
                ex.deferring_stability()
                    .solve_at(held, &st.contour, st.delta_bar)
            });
            Ok(match next_state {
                Ok(n) if n.bc_error <= ON_THE_WAY => super::rho_walk::Attempt::Took(n),
                _ => super::rho_walk::Attempt::Missed(()),
            })
        },
    );
    match walked {
        Ok(Ok(())) => Ok(st),
        // stopped, or asked to stop
        Ok(Err(_)) | Err(_) => Err(st.rho),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::{Route, CONVERGED};

    /// The state of contact size `a_bar` on `start`'s piece at its ρ, with
    /// [`PATH_MODES`] modes: up the sizes [`SIZE_STEP`] apart from `start`
    /// (past a band, where a size has none, from the size before), as the
    /// route climbs them.
    fn size_above(start: &ExactState, a_bar: f64) -> ExactState {
        let ex = Exact::new(start.rho, Truncation::in_arclength(PATH_MODES))
            .unwrap()
            .deferring_stability();
        let mut here = start.clone();
        for k in 1.. {
            let next = (start.a_bar + SIZE_STEP * k as f64).min(a_bar);
            if let Ok(st) = ex.solve_at(Hold::Size(next), &here.contour, here.delta_bar) {
                here = st;
            }
            if next >= a_bar {
                break;
            }
        }
        assert!((here.a_bar - a_bar).abs() < 1e-9, "a = {}", here.a_bar);
        here
    }

    /// Below the fold in ρ of the family at F̄ = 10 (ρ ≈ 0.3224,
    /// `the_force_10_family_turns_back_in_rho`), a state at F̄ = 10 at
    /// ρ = 0.3 lies on the arm of a larger contact: resolved (and unchanged
    /// with more modes), and reached again by a second route that uses no
    /// continuation in ρ: the arm through the state at F̄ = 14 that
    /// `conformal:8` starts, traced down in ā through its fold.
    #[test]
    fn at_rho_0_3_the_state_at_force_10_lies_on_the_arm_of_a_larger_contact() {
        let ten = Hold::Force(10.0);
        let at_0_4 = super::super::resolve::at_resolved(0.4, ten).unwrap();
        let st = super::super::resolve::from_larger_contact(&at_0_4, 0.3, ten).unwrap();
        assert_eq!(st.route, Route::FromLargerContact);
        assert!((st.force_bar - 10.0).abs() < 1e-9, "F = {}", st.force_bar);
        assert!(
            st.bc_error <= CONVERGED,
            "boundary error {:.1e}",
            st.bc_error
        );
        // docs/exact.md ("F̄ = 10 at ρ = 0.3"): the long-wave route finds
        // the variation positive on the modes up to 10 and negative with
        // 12 added, so the longest unstable mode is 12, critical 0.248
        let longest = st.stability.load.iter().map(|m| m.n).min();
        assert_eq!(longest, Some(12), "{:?}", st.stability.load);
        let h = st.stability.critical_thinness_load.unwrap();
        assert!((h - 0.248).abs() <= 5e-4, "critical thinness {h}");
        // ā and s of `x` within `tol` of the state's
        let same = |x: &ExactState, tol: f64, what: &str| {
            for (name, got, want) in [("a", x.a_bar, st.a_bar), ("s", x.s, st.s)] {
                assert!(
                    (got - want).abs() < tol,
                    "{what}: {name} {got} against {want}"
                );
            }
        };
        // more modes: the same state
        let finer = Exact::new(0.3, Truncation::in_arclength(st.truncation.modes + 32)).unwrap();
        let again = finer.solve_at(ten, &st.contour, st.delta_bar).unwrap();
        assert!(again.bc_error <= CONVERGED);
        same(&again, 1e-9, "32 modes more");
        // the second route: from conformal:8's start at F = 14
        let fourteen = super::super::resolve::at_resolved(0.3, Hold::Force(14.0)).unwrap();
        assert_eq!(fourteen.route, Route::FromModel);
        let ex = Exact::new(0.3, Truncation::in_arclength(PATH_MODES)).unwrap();
        let above = ex
            .solve_at(Hold::Force(14.0), &fourteen.contour, fourteen.delta_bar)
            .unwrap();
        let down = ex
            .first_crossing_through_folds(&above, -1.0, ten, 0.02, ON_THE_WAY, ARM_DEPARTURE)
            .unwrap();
        let ArmEnd::Reached(down) = down else {
            panic!("the arm from F = 14 ends before F = 10: {down:?}");
        };
        same(&down, 1e-6, "traced down from F = 14");
    }

    /// Zero force at ρ = 0.3, below the fold in ρ of its family (0.357):
    /// the route of `thinjkr exact zero-force --rho 0.3` finds it on the arm
    /// of a larger contact, its contour more than 10 % of ā off its ellipse
    /// (where a trace past a band's fold would have stopped,
    /// [`super::super::branch::PAST_FOLD_DEPARTURE`]) and yet resolved below
    /// 1e-9: solved again with 64 and 192 modes more, ā, s and δ̄ stay within
    /// 1e-9 and the boundary error at most 1e-9.
    ///
    /// Below it, the first route below the fold continues that state in ρ
    /// at F̄ = 0 to the zero-force state at ρ = 0.2 (route
    /// `ContinuedInRho`, `resolve::below_the_fold`). It converges (192 and
    /// 256 modes, as above), and it lies on the ρ = 0.3 state's arm: stepped
    /// back up in ρ at F̄ = 0 (Newton in steps of 0.01), it lands on that
    /// state to 1e-8. Continued further down, the family turns back between
    /// ρ = 0.17 and 0.19 (docs/exact.md, "Below ρ = 0.3"), so zero force at
    /// ρ = 0.1 is not on it.
    #[test]
    #[ignore = "slow tier (.ci/slow): about 130 s; the larger contact's arm at F = 10, rho = 0.3, stays in CI"]
    fn zero_force_at_rho_0_3_lies_on_a_larger_contacts_arm_and_continues_in_rho_to_0_2() {
        let zero = Hold::Force(0.0);
        let st = super::super::resolve::at_resolved(0.3, zero).unwrap();
        assert_eq!(st.route, Route::FromLargerContact);
        assert!(st.force_bar.abs() < 1e-9, "F = {}", st.force_bar);
        assert!(
            st.bc_error <= CONVERGED,
            "boundary error {:.1e}",
            st.bc_error
        );
        let off = st.deviation_from_ellipse;
        assert!(
            off > super::super::branch::PAST_FOLD_DEPARTURE && off < ARM_DEPARTURE,
            "{off} a off the ellipse"
        );
        let modes = [64, 192].map(|more| st.truncation.modes + more);
        super::super::resolve::assert_same_with_modes(&st, zero, &modes);

        let below = super::super::resolve::at_resolved(0.2, zero).unwrap();
        assert_eq!(below.route, Route::ContinuedInRho);
        assert!(below.force_bar.abs() < 1e-9 && below.bc_error <= CONVERGED);
        super::super::resolve::assert_same_with_modes(&below, zero, &[192, 256]);
        let mut back = below.clone();
        for k in 1..=10 {
            let rho = 0.2 + 0.01 * k as f64;
            back = Exact::on(below.gap, rho, below.truncation)
                .unwrap()
                .deferring_stability()
                .solve_at(zero, &back.contour, back.delta_bar)
                .unwrap();
        }
        assert!(
            (back.a_bar - st.a_bar).abs() < 1e-8,
            "back at rho = 0.3: a = {} against {}",
            back.a_bar,
            st.a_bar
        );
        let ladder = super::super::ladder::Ladder::arclength();
        match super::super::resolve::continued_in_rho_along(&below, 0.1, zero, &ladder) {
            Err(Error::PastRhoFold { fold, from, .. }) => {
                assert!(fold > 0.17 && fold < 0.19, "fold at {fold}");
                assert_eq!(from, 0.2);
            }
            other => panic!("continued to 0.1: {:?}", other.map(|s| s.a_bar)),
        }
    }

    /// At ρ = 0.2 the arm of the contact size ā = 4.0843 (arrived from
    /// ρ = 0.4 at fixed ā, F̄ = 27.16 there) develops a notch at the middle
    /// of each long flank as F̄ falls (docs/exact.md, "Below the fold"): the
    /// trace towards F̄ = 10 with [`PATH_MODES`] modes ends where they no
    /// longer resolve it, typed, not by a failing corrector further down.
    /// That it is the series and not the arm that ends there is checked by
    /// more modes at the same ā: the same F̄, the boundary error a hundredth.
    #[test]
    fn at_rho_0_2_the_trace_ends_where_its_modes_no_longer_resolve_the_arm() {
        let a_bar = 4.0843;
        let at_0_4 = super::super::resolve::at_resolved(0.4, Hold::Force(10.0)).unwrap();
        let t = Truncation::in_arclength(PATH_MODES);
        let arrived = at_fixed_size(size_above(&at_0_4, a_bar), 0.2).unwrap();
        assert!(
            (arrived.force_bar - 27.16).abs() < 0.01,
            "F = {}",
            arrived.force_bar
        );
        let at_rho = Exact::new(0.2, t).unwrap().deferring_stability();
        let end = at_rho
            .first_crossing_through_folds(
                &arrived,
                -1.0,
                Hold::Force(10.0),
                0.02,
                ON_THE_WAY,
                ARM_DEPARTURE,
            )
            .unwrap();
        let ArmEnd::Unresolved {
            a_bar: at,
            force_bar,
            bc_error,
            ..
        } = end
        else {
            panic!("the trace ends otherwise: {end:?}");
        };
        assert!(bc_error > ON_THE_WAY);
        assert!(
            force_bar > 22.0 && force_bar < 27.0,
            "unresolved from F = {force_bar}"
        );
        // the same arm at that ā with 64 modes more
        let finer = Exact::new(0.2, Truncation::in_arclength(PATH_MODES + 64))
            .unwrap()
            .deferring_stability()
            .solve_at(Hold::Size(at), &arrived.contour, arrived.delta_bar)
            .unwrap();
        assert!(
            (finer.force_bar - force_bar).abs() < 1e-4,
            "F = {} with more modes, {force_bar} with {PATH_MODES}",
            finer.force_bar
        );
        assert!(
            finer.bc_error < 1e-2 * bc_error,
            "boundary error {:.1e} with more modes, {bc_error:.1e} with {PATH_MODES}",
            finer.bc_error
        );
    }

    /// The row `which` of docs/exact-record.md's table of the notched zero-force
    /// states' stability holds `computed` (n, wavelength, eigenvalue under
    /// load, under displacement, critical thinness under load, the shape's
    /// critical thinness and its mode) to its digits: each number within
    /// one unit of its last printed digit.
    fn the_docs_stability_row_is(which: &str, computed: &[f64; 7]) {
        let doc = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../docs/exact-record.md"
        ))
        .unwrap();
        let row = doc
            .lines()
            .find(|l| l.starts_with(&format!("| {which} | n = ")))
            .unwrap_or_else(|| panic!("no row {which}"));
        // every number of the row, with the unit of its last digit
        let mut numbers = Vec::new();
        let text = row.replace('\u{2212}', "-");
        let mut chars = text.char_indices().peekable();
        while let Some((i, c)) = chars.next() {
            let starts = c.is_ascii_digit()
                || (c == '-' && chars.peek().is_some_and(|(_, d)| d.is_ascii_digit()));
            if !starts {
                continue;
            }
            let mut end = i + c.len_utf8();
            while let Some(&(j, d)) = chars.peek() {
                if d.is_ascii_digit()
                    || d == '.'
                    || d == 'e'
                    || (d == '-' && text[..j].ends_with('e'))
                {
                    end = j + d.len_utf8();
                    chars.next();
                } else {
                    break;
                }
            }
            let s = text[i..end].trim_end_matches('.');
            let decimals = s.split('.').nth(1).map_or(0, |f| f.len()) as i32;
            // (a tolerance such as 4e-13 is no value of the state; an
            // integer, a mode, is held exactly)
            if !s.contains('e') {
                let unit = if decimals == 0 {
                    0.0
                } else {
                    10f64.powi(-decimals)
                };
                numbers.push((s.parse::<f64>().unwrap(), unit));
            }
        }
        // n, wavelength, under load, under displacement, the two
        // thinnesses, the shape's mode: the row's first seven numbers
        let wanted = &numbers[..7];
        for (k, ((printed, unit), got)) in wanted.iter().zip(computed).enumerate() {
            assert!(
                (printed - got).abs() <= *unit,
                "{which}, column {k}: docs {printed}, computed {got}"
            );
        }
    }

    /// Zero force at ρ = 0.3, below the fold in ρ of its family (0.357): on
    /// the arm of the contact size 0.44 above the zero-force state at
    /// ρ = 0.4, traced down with 256 modes, F̄ passes 0 twice, on either side
    /// of the arm's minimum of F̄ (docs/exact.md, "Zero force at ρ = 0.3").
    /// Both states, solved again at F̄ = 0 with 256 to 512 modes of each
    /// sign, converge geometrically; the table is printed. From 384 modes on
    /// their stability is computed too: both are unstable from n = 12 on
    /// under either control, the eigenvalue of n = 12 the same to 1e-6
    /// with 448 and 512 modes, and no thinness makes either a stable
    /// contact whose shape (2) resolves; docs/exact-record.md's table of their
    /// stability holds the 512 modes' numbers to its digits. The route's
    /// trace, its modes raised on the way ([`traced_with_raised_modes`]),
    /// reaches the first of them. About 8 min (release); run with
    /// `--ignored`.
    #[test]
    #[ignore = "slow tier (.ci/slow)"]
    fn zero_force_at_rho_0_3_on_a_notched_arm_converges_with_modes() {
        let zero = Hold::Force(0.0);
        let at_0_4 = super::super::resolve::at_resolved(0.4, zero).unwrap();
        let size = at_0_4.a_bar + 11.0 * SIZE_STEP;
        let arrived = at_fixed_size(size_above(&at_0_4, size), 0.3).unwrap();
        let ex = Exact::new(0.3, Truncation::in_arclength(256))
            .unwrap()
            .deferring_stability();
        let start = ex
            .solve_at(Hold::Size(size), &arrived.contour, arrived.delta_bar)
            .unwrap();
        let arm = ex.trace_from(&start, -1.0, 3.1, 3.5, 0.01, 200).unwrap();
        let force = |i: usize| arm.points[i].state.force_bar;
        let lowest = (0..arm.points.len())
            .min_by(|&i, &j| force(i).total_cmp(&force(j)))
            .unwrap();
        println!(
            "arrived at rho = 0.3 with F = {:.4}; the arm's least F on the trace {:.5} at a = {:.5}",
            arrived.force_bar,
            force(lowest),
            arm.points[lowest].state.a_bar
        );
        assert!(force(lowest) < -1.0 && force(lowest) > -1.2);
        let nearest_zero = |from: usize, to: usize| {
            (from..to)
                .min_by(|&i, &j| force(i).abs().total_cmp(&force(j).abs()))
                .map(|i| arm.points[i].state.clone())
                .unwrap()
        };
        // the route's trace, its modes raised on the way (96, then 160, 256
        // and 320), reaches the first of them
        let raised = traced_with_raised_modes(
            &Exact::new(0.3, Truncation::in_arclength(PATH_MODES))
                .unwrap()
                .deferring_stability(),
            &arrived,
            zero,
        )
        .unwrap();
        let ArmEnd::Reached(raised) = raised else {
            panic!("the trace with its modes raised ends otherwise: {raised:?}");
        };
        println!(
            "the trace with its modes raised reaches F = 0 with {} modes at a = {:.10}",
            raised.truncation.modes, raised.a_bar
        );
        for (which, near) in [
            ("before the minimum", nearest_zero(0, lowest)),
            ("after it", nearest_zero(lowest, arm.points.len())),
        ] {
            let mut finest: Option<ExactState> = None;
            // the least eigenvalue of the longest unstable mode under load
            // control, at each truncation from 384 modes on
            let mut longest_eigenvalues = Vec::new();
            // what docs/exact-record.md's table of their stability prints, from
            // the 512 modes: the longest unstable mode under load (n,
            // wavelength, eigenvalue), its eigenvalue under displacement,
            // the critical thinness under load, the shape's and its mode
            let mut printed = None;
            for modes in [256, 320, 384, 448, 512] {
                let ex = || Exact::new(0.3, Truncation::in_arclength(modes)).unwrap();
                let mut st = ex()
                    .deferring_stability()
                    .solve_at(zero, &near.contour, near.delta_bar)
                    .unwrap();
                println!(
                    "| {which} | {modes} | {:.10} | {:.10} | {:.10} | {:.1e} |",
                    st.a_bar, st.s, st.delta_bar, st.bc_error
                );
                if modes >= 384 {
                    st.stability = ex().stability(&st).unwrap();
                    // the default cutoff, the one `stability` judged under
                    let cutoff = st.stability.cutoff;
                    st = st.judged(cutoff);
                    let longest = |m: &[super::super::stability::UnstableMode]| {
                        super::super::undulations::longest_unstable(m).map(|m| (m.n, m.eigenvalue))
                    };
                    let (load, displacement) = (
                        longest(&st.stability.load),
                        longest(&st.stability.displacement),
                    );
                    let shape = st.short_waves();
                    println!(
                        "stability | {which} | {modes} | n = {:?} | {:?} | {:.4} | {:?} | {:?} |",
                        load,
                        displacement,
                        st.stability.critical_thinness_load.unwrap_or(f64::NAN),
                        shape.critical_thinness,
                        shape.critical_mode
                    );
                    // the longest unstable mode is n = 12 under either
                    // control, and no thinness makes the state a stable
                    // contact whose shape (2) resolves: its shape stops
                    // being resolved (h/L from the shape's critical
                    // thinness on) below the thinness that puts n = 12 under
                    // the cutoff
                    assert_eq!(load.map(|l| l.0), Some(12), "{which}, {modes} modes");
                    assert_eq!(
                        displacement.map(|d| d.0),
                        Some(12),
                        "{which}, {modes} modes"
                    );
                    let coatings = st.coatings.unwrap();
                    assert_eq!((coatings.load, coatings.displacement), (None, None));
                    assert!(
                        shape.critical_thinness.unwrap()
                            < st.stability.critical_thinness_load.unwrap()
                    );
                    longest_eigenvalues.push(load.unwrap().1);
                    let wavelength =
                        super::super::undulations::longest_unstable(&st.stability.load)
                            .unwrap()
                            .wavelength;
                    printed = Some([
                        12.0,
                        wavelength,
                        load.unwrap().1,
                        displacement.unwrap().1,
                        st.stability.critical_thinness_load.unwrap(),
                        shape.critical_thinness.unwrap(),
                        shape.critical_mode.unwrap() as f64,
                    ]);
                }
                finest = Some(st);
            }
            // the longest unstable mode's eigenvalue has converged
            let (at_448, at_512) = (longest_eigenvalues[1], longest_eigenvalues[2]);
            assert!(
                (at_448 - at_512).abs() <= 1e-6 * at_512.abs(),
                "{which}: {at_448} with 448 modes, {at_512} with 512"
            );
            the_docs_stability_row_is(which, &printed.unwrap());
            let finest = finest.unwrap();
            if which == "before the minimum" {
                assert!(
                    (raised.a_bar - finest.a_bar).abs() < 1e-8,
                    "the raised trace's a = {}",
                    raised.a_bar
                );
            }
            assert!(finest.force_bar.abs() < 1e-9);
            assert!(
                finest.bc_error <= CONVERGED,
                "{which}: boundary error {:.1e} with 512 modes",
                finest.bc_error
            );
        }
    }
}
