//! Sweeps in ρ (issue 31, "property tests sweep ρ from 0.02 to 1 in fine
//! steps for every model and control"): along each control the answers of
//! the model layer are continuous in ρ, or the change is an event the
//! answers themselves report.
//!
//! The steps, named: 240 values of ρ from 0.02 to 1, equally spaced in
//! ln ρ (each 1.65 % above the one before), at the controls δ̄ = 0.5 and 2,
//! F̄ = −1, 0 and 10, and ā = 3. Between two answered neighbours ā may move
//! by at most 3 % and s by at most 0.03, set before measuring as a slope of
//! at most 1.8 in ln ρ (measured, the largest steps are 1.03 % in ā, the
//! `apexes` closure at δ̄ = 0.5, and 0.023 in s, `apex45` at δ̄ = 0.5 near
//! the end of its range; the run prints them all); a larger change must come
//! with a reported event: a typed error between them (no state at that ρ,
//! or the control beyond the branch's range, as a force below the
//! pull-off force), or a change of a flag the state carries (beyond the
//! contact-size fold).
//! Every answer is finite, with ā > 0 and 0 < s ≤ 1.
//!
//! The models of the ellipse, the slender limit, the contour family
//! (conformal:4 and 8, where a change of arm is the event the state reports:
//! `folds_crossed`, the folds of its arm in ρ that the continuation from
//! the circle crossed) and the exact solution (on a coarser grid from
//! ρ = 0.4, where a change of route is the event: its states say their
//! route, not yet their arm; issue 32, milestone (b), maps those arms).

use thinjkr::control::Hold;
use thinjkr::registry::parse;
use thinjkr::report::AnyState;
use thinjkr::Error;

/// The sweep's controls: δ̄ = 0.5 and 2, F̄ = −1, 0 and 10, ā = 3.
const CONTROLS: [Hold; 6] = [
    Hold::Delta(0.5),
    Hold::Delta(2.0),
    Hold::Force(-1.0),
    Hold::Force(0.0),
    Hold::Force(10.0),
    Hold::Size(3.0),
];

/// The sweep's ρ: `n` values from 0.02 to 1, equally spaced in ln ρ.
fn rho_grid(n: usize) -> Vec<f64> {
    let (lo, hi) = (0.02f64.ln(), 0.0f64);
    (0..n)
        .map(|i| (lo + (hi - lo) * i as f64 / (n - 1) as f64).exp().min(1.0))
        .collect()
}

/// Along one sweep, the answers (ā, s, what the state says of its arm) at
/// each ρ, or `None` where the model reported no state: between answered
/// neighbours on the same arm (`same`), ā may move by at most 3 % and s by
/// at most 0.03, else the test fails naming the two ρ; a larger step
/// between neighbours the states put on different arms is a reported
/// event. Returns the largest step on an arm (|Δā|/ā, |Δs|) and the number
/// of jumps reported by the arm.
fn steps_along<K: Copy + std::fmt::Debug>(
    what: &str,
    rho: &[f64],
    answers: &[Option<(f64, f64, K)>],
    same: impl Fn(K, K) -> bool,
) -> ((f64, f64), usize) {
    let (mut largest, mut events) = ((0.0f64, 0.0f64), 0);
    for (i, w) in answers.windows(2).enumerate() {
        let (Some((a0, s0, k0)), Some((a1, s1, k1))) = (w[0], w[1]) else {
            continue;
        };
        let (da, ds) = ((a1 - a0).abs() / a1, (s1 - s0).abs());
        if !same(k0, k1) {
            events += usize::from(da > 0.03 || ds > 0.03);
            continue; // reported: another arm
        }
        largest = (largest.0.max(da), largest.1.max(ds));
        assert!(
            da <= 0.03 && ds <= 0.03,
            "{what}: between rho = {:.5} and {:.5} the state jumps (a_bar {a0:.6} -> {a1:.6}, s {s0:.6} -> {s1:.6}) on one arm ({k0:?})",
            rho[i],
            rho[i + 1]
        );
    }
    (largest, events)
}

#[test]
fn the_models_of_the_ellipse_answer_continuously_in_rho_or_report_why() {
    let rho = rho_grid(240);
    let controls = CONTROLS;
    let mut report = Vec::new();
    for name in ["max", "apexes", "energy", "apex45"] {
        let model = parse(name).unwrap();
        for hold in controls {
            // (ā, s, beyond the size fold) at each ρ, or None where the
            // model reports no state
            let mut answers: Vec<Option<(f64, f64, bool)>> = Vec::new();
            for &r in &rho {
                match model.state(r, hold) {
                    Ok(AnyState::Ellipse(st)) => {
                        assert!(
                            st.a_bar.is_finite()
                                && st.a_bar > 0.0
                                && st.s > 0.0
                                && st.s <= 1.0
                                && st.delta_bar.is_finite()
                                && st.force_bar.is_finite(),
                            "{name} {hold} at rho = {r}: {st:?}"
                        );
                        answers.push(Some((st.a_bar, st.s, st.beyond_size_fold)));
                    }
                    Ok(other) => panic!("{name}: not a state of the ellipse: {other:?}"),
                    // a reported event: no state there, or a control beyond
                    // the branch's range (a force below the pull-off force),
                    // each typed, its message saying why
                    Err(
                        Error::NoState(_)
                        | Error::Unsupported { .. }
                        | Error::OutOfRange {
                            name: "force" | "a",
                            ..
                        },
                    ) => answers.push(None),
                    Err(e) => panic!(
                        "{name} {hold} at rho = {r}: an error of kind {}: {e}",
                        e.kind()
                    ),
                }
            }
            let answered = answers.iter().filter(|a| a.is_some()).count();
            // a change of the flag (beyond the size fold) is the event
            let (largest, _) =
                steps_along(&format!("{name} {hold}"), &rho, &answers, |x, y| x == y);
            report.push(format!(
                "{name} {hold}: {answered} of {} answered, largest step |da|/a = {:.4}, |ds| = {:.4}",
                rho.len(),
                largest.0,
                largest.1
            ));
        }
    }
    // the paper's model answers everywhere at large loads (every ρ has a
    // state at F̄ = 10 and at δ̄ = 2): the sweep is not vacuous
    assert!(
        report
            .iter()
            .filter(|l| l.starts_with("max ")
                && (l.contains("force = 10:") || l.contains("delta = 2:")))
            .all(|l| l.contains(&format!("{} of {} answered", rho.len(), rho.len()))),
        "{}",
        report.join("\n")
    );
    println!("{}", report.join("\n"));
}

/// The slender limit over the same sweep: at every ρ of the grid and every
/// control it answers or says why, typed (the contact size ā: no finite
/// length; a force below its pull-off: out of range), and along ρ its
/// state, the half-width at the centre b̄₀ (its one unknown β₀ times
/// ρ^(1/3); F̄ and δ̄ are continuous functions of it), moves by at most 3 %
/// between neighbours (measured: at most 1.9 %, at F̄ = −1 near the force
/// minimum, where β₀ moves as the square root of the distance to it; a jump
/// would be a defect).
#[test]
fn the_slender_model_answers_continuously_in_rho_or_report_why() {
    let rho = rho_grid(240);
    let model = parse("slender").unwrap();
    let mut report = Vec::new();
    for hold in CONTROLS {
        let mut answers: Vec<Option<f64>> = Vec::new();
        for &r in &rho {
            match model.state(r, hold) {
                Ok(AnyState::Slender(st)) => {
                    assert!(
                        st.b_bar > 0.0 && st.delta_bar.is_finite() && st.force_bar.is_finite(),
                        "slender {hold} at rho = {r}: {st:?}"
                    );
                    answers.push(Some(st.b_bar));
                }
                Ok(other) => panic!("slender: not a slender state: {other:?}"),
                Err(Error::OutOfRange { name: "force", .. } | Error::Unavailable { .. }) => {
                    answers.push(None)
                }
                Err(e) => panic!(
                    "slender {hold} at rho = {r}: an error of kind {}: {e}",
                    e.kind()
                ),
            }
        }
        let answered = answers.iter().flatten().count();
        let mut largest: f64 = 0.0;
        for (i, w) in answers.windows(2).enumerate() {
            let (Some(b0), Some(b1)) = (w[0], w[1]) else {
                continue;
            };
            // the state is its one unknown β₀ = b̄₀ ρ^(−1/3) (F̄ and δ̄ are
            // continuous functions of it): its half-width b̄₀
            let step = ((b1 - b0) / b1).abs();
            largest = largest.max(step);
            assert!(
                step <= 0.03,
                "slender {hold}: between rho = {:.5} and {:.5} the state jumps (b {b0:.6} -> {b1:.6})",
                rho[i],
                rho[i + 1]
            );
        }
        report.push(format!(
            "slender {hold}: {answered} of {} answered, largest relative step {largest:.4}",
            rho.len()
        ));
    }
    println!("{}", report.join("\n"));
    // at large loads and approaches it answers everywhere; the size never
    assert!(report[1].contains("240 of 240") && report[4].contains("240 of 240"));
    assert!(report[5].contains(" 0 of 240"), "{}", report.join("\n"));
}

/// The contour family over the same sweep (conformal:4 and 8; ρ from
/// 0.3, its `rho_min`, below which each answer is the typed refusal):
/// every answer is finite with ā > 0, and between answered neighbours ā
/// moves by at most 3 % and s by at most 0.03, unless the answers report
/// an event: a typed error between them, or another arm (`folds_crossed`:
/// the continuation from the circle crossed another number of folds of its
/// arm in ρ, or the state came by another route than that continuation).
/// The jump at F̄ = 10 between ρ = 0.59 and 0.585 (s 0.849 → 0.808) is such
/// an event: the Jacobian at the control changes sign at ρ = 0.585.
#[test]
#[ignore = "slow tier (.ci/slow): about 280 s; CI runs the window near rho = 0.59 below"]
fn the_contour_family_answers_continuously_in_rho_or_reports_its_arm() {
    let rho = rho_grid(240);
    let (report, arm_events) = contour_sweep(&["conformal:4", "conformal:8"], &rho);
    // ρ ≥ 0.3 is 74 of the grid's 240: at F̄ = 10 conformal:8 answers at
    // each (the sweep is not vacuous), and its jump near ρ = 0.59 is
    // reported by the arm
    assert!(
        report
            .iter()
            .any(|l| l.starts_with("conformal:8 force = 10:") && l.contains("74 of 240")),
        "{}",
        report.join("\n")
    );
    assert!(arm_events >= 1);
}

/// CI's sample of the sweep above: conformal:8 on the grid's 22 values of ρ
/// from 0.50 to 0.70 (indices 196 to 217 of the 240), which hold the
/// reported jump at F̄ = 10 near ρ = 0.59; every control but the size
/// answers at each.
#[test]
fn the_contour_family_answers_continuously_near_its_arm_jump() {
    let rho = rho_grid(240)[196..218].to_vec();
    assert!(rho[0] < 0.5 + 1e-2 && rho[21] > 0.69, "{rho:?}");
    let (report, arm_events) = contour_sweep(&["conformal:8"], &rho);
    // the five controls other than the size (its line says "a = 3:")
    let others: Vec<&String> = report
        .iter()
        .filter(|l| l.contains(" of 22 answered") && !l.contains("a = 3:"))
        .collect();
    assert_eq!(others.len(), CONTROLS.len() - 1, "{}", report.join("\n"));
    assert!(
        others.iter().all(|l| l.contains("22 of 22 answered")),
        "{}",
        report.join("\n")
    );
    assert!(arm_events >= 1, "{}", report.join("\n"));
}

/// The contour family's sweep over `rho` for each model of `names`: the
/// report's lines (one per model and control, then the model's time) and
/// the jumps reported by the arm.
fn contour_sweep(names: &[&str], rho: &[f64]) -> (Vec<String>, usize) {
    let mut report = Vec::new();
    let mut arm_events = 0;
    for &name in names {
        let model = parse(name).unwrap();
        let began = std::time::Instant::now();
        for hold in CONTROLS {
            // (ā, s, the folds crossed) at each ρ, or None where the model
            // reports no state
            // (on both cores: each ρ is solved on its own)
            use rayon::prelude::*;
            let solved: Vec<_> = rho.par_iter().map(|&r| model.state(r, hold)).collect();
            let mut answers: Vec<Option<(f64, f64, Option<usize>)>> = Vec::new();
            for (&r, answer) in rho.iter().zip(solved) {
                match answer {
                    Ok(AnyState::Conformal(st)) => {
                        assert!(
                            st.a_bar.is_finite()
                                && st.a_bar > 0.0
                                && st.s > 0.0
                                && st.delta_bar.is_finite()
                                && st.force_bar.is_finite()
                                && st.bc_defect.is_finite(),
                            "{name} {hold} at rho = {r}: {st:?}"
                        );
                        let arm = st.folds_crossed.as_ref().map(Vec::len);
                        answers.push(Some((st.a_bar, st.s, arm)));
                    }
                    Ok(other) => panic!("{name}: not a contour state: {other:?}"),
                    Err(Error::NoState(_) | Error::Unsupported { .. }) => answers.push(None),
                    Err(e) => panic!(
                        "{name} {hold} at rho = {r}: an error of kind {}: {e}",
                        e.kind()
                    ),
                }
            }
            let answered = answers.iter().flatten().count();
            // the same arm: the same count of folds crossed from the circle
            // (a state by another route has no count: always an event)
            let (largest, events) =
                steps_along(&format!("{name} {hold}"), rho, &answers, |x, y| {
                    x.is_some() && x == y
                });
            arm_events += events;
            report.push(format!(
                "{name} {hold}: {answered} of {} answered, largest step on an arm |da|/a = {:.4}, |ds| = {:.4}",
                rho.len(),
                largest.0,
                largest.1
            ));
        }
        report.push(format!("{name}: {:.1} s", began.elapsed().as_secs_f64()));
    }
    println!(
        "{}\njumps reported by the arm: {arm_events}",
        report.join("\n")
    );
    (report, arm_events)
}

/// The exact solution over a coarser sweep where it resolves every control
/// (25 values of ρ from 0.4 to 1, equally spaced in ln ρ, 3.9 % apart; below
/// ρ ≈ 0.36 the states at zero force and F̄ = 10 end at folds in ρ, each
/// refusal costing half a minute): every answer is resolved (boundary error
/// at most 1e-9) with ā > 0, and between answered neighbours ā moves by at
/// most 3 % and s by at most 0.03, unless the answers report an event: a
/// typed error between them, or another route (`route`: from the seeding
/// model's state, past a fold of a band, continued in ρ, …). The exact
/// states do not yet name their arm, so two states on different arms
/// reached by the same route would pass unnoticed where no state between
/// them shows the change; at F̄ = 10 the state at ρ = 0.609 between the
/// two arms comes past a fold (s 0.812 → 0.811 → 0.843).
#[test]
#[ignore = "slow tier (.ci/slow): about 80 s; CI runs the window near rho = 0.609 below"]
fn the_exact_solution_answers_continuously_in_rho_or_reports_its_route() {
    exact_sweep(&exact_grid());
}

/// The exact sweep's 25 values of ρ from 0.4 to 1, equally spaced in ln ρ.
fn exact_grid() -> Vec<f64> {
    let n = 25;
    (0..n)
        .map(|i| (0.4f64.ln() * (1.0 - i as f64 / (n - 1) as f64)).exp())
        .collect()
}

/// CI's sample of the sweep above: its six values of ρ from 0.564 to 0.683
/// (indices 9 to 14), which hold the route event at F̄ = 10 (ρ = 0.609,
/// between its neighbours 0.586 and 0.632).
#[test]
fn the_exact_solution_answers_continuously_near_its_route_event() {
    let rho = exact_grid()[9..15].to_vec();
    assert!(rho[0] < 0.586 && rho[5] > 0.632, "{rho:?}");
    exact_sweep(&rho);
}

/// The exact sweep over `rho` at every control.
fn exact_sweep(rho: &[f64]) {
    use rayon::prelude::*;
    let n = rho.len();
    let model = parse("exact").unwrap();
    let mut report = Vec::new();
    let mut route_events = 0;
    for hold in CONTROLS {
        let solved: Vec<_> = rho.par_iter().map(|&r| model.state(r, hold)).collect();
        let mut answers = Vec::new();
        for (&r, answer) in rho.iter().zip(solved) {
            match answer {
                Ok(AnyState::Exact(st)) => {
                    assert!(
                        st.a_bar > 0.0 && st.s > 0.0 && st.bc_error <= 1e-9,
                        "exact {hold} at rho = {r}: a {}, s {}, bc {:e}",
                        st.a_bar,
                        st.s,
                        st.bc_error
                    );
                    answers.push(Some((st.a_bar, st.s, st.route)));
                }
                Ok(other) => panic!("exact: not an exact state: {other:?}"),
                Err(e) if e.kind() == "no_state" || e.kind() == "unavailable" => answers.push(None),
                Err(e) => panic!(
                    "exact {hold} at rho = {r}: an error of kind {}: {e}",
                    e.kind()
                ),
            }
        }
        let answered = answers.iter().flatten().count();
        let (largest, events) = steps_along(&format!("exact {hold}"), rho, &answers, |x, y| x == y);
        route_events += events;
        report.push(format!(
            "exact {hold}: {answered} of {n} answered, largest step by one route |da|/a = {:.4}, |ds| = {:.4}",
            largest.0, largest.1
        ));
    }
    println!(
        "{}\njumps reported by the route: {route_events}",
        report.join("\n")
    );
    // every control but the size answers at every ρ of this range
    for line in &report[..5] {
        assert!(line.contains(&format!("{n} of {n} answered")), "{line}");
    }
    assert!(route_events >= 1);
}

/// The contour family against the exact solution over the exact sweep's
/// grid (25 values of ρ from 0.4 to 1, the controls but the size): where
/// both answer and a member's ā is more than 1 % off the exact state's, the
/// member's state carries the boundary-defect warning (issue 72, item 5:
/// its line, measured on docs/accuracy.md's rows, holds over the sweep),
/// or it lies within 0.5 % of another exact state at its control (it is
/// that state, on another arm than the exact solver's answer).
#[test]
#[ignore = "slow tier (.ci/slow): the exact sweep's solves, about 80 s"]
fn every_member_state_of_the_sweep_more_than_one_per_cent_off_the_exact_one_is_warned() {
    use rayon::prelude::*;
    let rho = exact_grid();
    let exact = parse("exact").unwrap();
    let mut compared = 0;
    // (what, |error in a|, defect, warned) of every member state compared
    let mut seen = Vec::new();
    for hold in CONTROLS.into_iter().filter(|h| !matches!(h, Hold::Size(_))) {
        let solved: Vec<_> = rho.par_iter().map(|&r| exact.state(r, hold)).collect();
        for (&r, answer) in rho.iter().zip(solved) {
            let Ok(AnyState::Exact(ex)) = answer else {
                continue;
            };
            for name in ["conformal:4", "conformal:8"] {
                let Ok(AnyState::Conformal(st)) = parse(name).unwrap().state(r, hold) else {
                    continue;
                };
                compared += 1;
                let warned = st
                    .warnings
                    .iter()
                    .any(|w| w.contains("misses the boundary condition (3)2"));
                seen.push((
                    (
                        format!(
                            "{name} {hold} rho {r:.4}: a = {} against the exact {}",
                            st.a_bar, ex.a_bar
                        ),
                        r,
                        hold,
                        st.a_bar,
                    ),
                    (st.a_bar / ex.a_bar - 1.0).abs(),
                    st.bc_defect,
                    warned,
                ));
            }
        }
    }
    for (what, error, defect, warned) in seen.iter().filter(|x| x.1 > 5e-3) {
        println!(
            "{}: {error:.2e} off, defect {defect:.2e}, warned {warned}",
            what.0
        );
    }
    // a state more than 1 % off the exact solver's answer and not warned
    // must lie near another exact state at its control (the family has
    // several at some controls: the exact answer at F̄ = 10, ρ = 0.609 lies
    // on another arm, its route "past a fold", the sweep above); every
    // near-elliptic exact state there, screened for ā from 1 to 4
    // (`exact solve --all`), is asked for one within 0.5 % in ā
    let silent: Vec<_> = seen.iter().filter(|x| x.1 > 1e-2 && !x.3).collect();
    for (what, error, defect, _) in silent {
        let (r, hold, a_bar) = (what.1, what.2, what.3);
        let all =
            thinjkr::exact::bands::states_at(r, hold, 1.0, 4.0, &thinjkr::exact::default_tries())
                .unwrap_or_else(|e| panic!("{}: the exact states at its control: {e}", what.0));
        let nearest = all
            .states
            .iter()
            .map(|ex| (ex.a_bar / a_bar - 1.0).abs())
            .fold(f64::INFINITY, f64::min);
        println!(
            "{}: {error:.2e} off the exact answer, defect {defect:.2e}, not warned; the nearest of the {} exact states at its control is {nearest:.2e} off",
            what.0,
            all.states.len()
        );
        assert!(
            nearest <= 5e-3,
            "{}: more than 1 % off the exact answer without a warning, and {nearest:.2e} off the nearest exact state at its control",
            what.0
        );
    }
    assert!(compared >= 200, "{compared} states compared");
}
