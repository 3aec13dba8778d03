//! The grid solver's answer in the plane (issue 71): a state of two
//! coatings at any ρ (its pull-off under load control, or the state at a
//! force), from its ladder of process zones and its JKR limit, with how
//! far to trust it. A state at an approach is refused: the force's limit
//! there missed the reference by more than its bound (at h/L = 0.5).
//!
//! The ladder is [`LADDER`]: process zones ε = 0.2, 0.1, 0.05 and 0.025 of
//! the size scale, four cells across each. Where the force is not held it
//! is the JKR limit (`grid::jkr_limit`) through the three finest rungs;
//! the limit through the three coarsest is its check. Their difference,
//! doubled, is the stated bound on the force's relative error: for the
//! pull-off at ρ = 1, against the axisymmetric reference, it held at
//! h/L = 10, 1, 0.73 and 0.5 (the true errors 5.4e-4, 7.2e-4, 1.2e-3 and
//! 3.9e-3 against bounds of 1.4e-3, 1.7e-3, 3.9e-3 and 7.3e-3;
//! docs/thickness.md). The size and the approach where it is not held are the
//! finest rung's, bounded by their spread over the three finest rungs: at
//! the pull-off F̄ is least in δ̄, so its δ̄ and size move with the law more
//! than its force does, and not monotonically (at h/L = 1, ρ = 1 the finest
//! δ̄ overshoots the reference by 7e-4, three times its change from the
//! rung before; the spread, 3.2e-3, holds it, and at h/L = 10, 0.73 and 0.5
//! too), and the size's at least 0.5 % ([`SIZE_FLOOR`]: at a held force
//! the half width is biased by up to 0.3 % more than its spread shows). An
//! answer whose force bound exceeds `plane::WORST_FORCE_ERROR` is
//! refused (at ρ = 0.0196 with h/L = 0.73 the two limits differ by 3.2 %);
//! coatings outside [`REACH`] are refused before any ladder (at h/L = 0.3,
//! ρ = 1, the rung ε = 0.05 is still 5 % off).
//!
//! Owns: [`state`], [`pull_off`], [`LADDER`], [`REACH`]. May use: its
//! parent `plane` (the state it gives), `grid` (the ladder and its limit),
//! `layer` (the pair), `control` (the hold), `error`, `progress` (the rung
//! a spinner shows), `newton` (the stop request).

use super::{two_digits, Held, Method, PlaneRung, PlaneState, WARN_FORCE_ERROR, WORST_FORCE_ERROR};
use crate::control::Hold;
use crate::error::{rounded, short, Error, Result};
use crate::layer::grid::{jkr_limit, ladder, Rung, Target};
use crate::layer::Layers;

/// The ladder of (process zone ε, cells across it) of [`pull_off`].
pub(crate) const LADDER: [(f64, f64); 4] = [(0.2, 4.0), (0.1, 4.0), (0.05, 4.0), (0.025, 4.0)];

/// The bound on the force's relative error, over the relative difference
/// of the two three-rung limits (see the module).
const BOUND_OVER_DIFFERENCE: f64 = 2.0;

/// The coatings the ladder is measured to resolve, h/L of each: from
/// 0.5 (the bound 7.3e-3 at ρ = 1) to 10. At h/L = 0.3 the finest rung
/// this machine affords, ε = 0.05, is still 5 % short of the reference
/// (78 s); above 10 nothing was measured.
pub(crate) const REACH: (f64, f64) = (0.5, 10.0);

/// The least bound on the size's relative error: the half width, where
/// the gap reaches the law's range, is biased against JKR's edge by more
/// than its spread over the rungs shows at a held force (at ρ = 1, h/L =
/// 0.5: +0.30 % at zero force, the rungs within 0.2 % of each other; the
/// ladder does not close it).
const SIZE_FLOOR: f64 = 0.005;

/// The pull-off under load control of `layers` at `rho` ∈ (0, 1]: [`state`]
/// with no hold.
pub(crate) fn pull_off(layers: &Layers, rho: f64) -> Result<PlaneState> {
    state(layers, rho, None)
}

/// The state of `layers` at `rho` ∈ (0, 1] held at `hold` (a force or an
/// approach; `None`: the pull-off under load control) by the grid solver's
/// [`LADDER`] (see the module); refused where its force bound exceeds
/// [`WORST_FORCE_ERROR`].
pub(crate) fn state(layers: &Layers, rho: f64, hold: Option<Hold>) -> Result<PlaneState> {
    crate::error::check_range("rho", rho, rho > 0.0 && rho <= 1.0, "(0, 1]")?;
    let target = match hold.map(Hold::check_finite).transpose()? {
        None => Target::PullOff,
        // (measured, not yet answered: at h/L = 0.5, ρ = 1 the JKR limit of
        // the force at a held approach missed the reference by 1.1 % with
        // a bound of 0.93 %, and at zero force's approach by 0.025 with
        // 0.014; `explore_states_against_the_reference`)
        Some(Hold::Delta(_)) => {
            return Err(Error::Unavailable {
                model: "layer",
                what: "state at a given approach at rho < 1".into(),
                why: "the grid solver's force at a held approach does not yet stay within a bound it can state: at h/L = 0.5 its limit missed the reference by more than the bound; give a force",
            })
        }
        Some(Hold::Force(f)) => Target::Force(f),
        Some(Hold::Size(_)) => {
            return Err(Error::Unavailable {
                model: "layer",
                what: "state at a given contact size at rho < 1".into(),
                why: "the grid solver holds a force (or finds the pull-off); give force",
            })
        }
    };
    state_of(layers, rho, target)
}

/// An error naming the coating of `layers` outside [`REACH`], if any.
fn within_reach(layers: &Layers) -> Result<()> {
    super::within(
        layers,
        REACH,
        " at rho < 1: the grid solver's ladder is measured to resolve the layer there (docs/thickness.md); at rho = 1 the axisymmetric layer takes 0.001 to 10000",
    )
}

/// [`state`] for the ladder's `target`.
fn state_of(layers: &Layers, rho: f64, target: Target) -> Result<PlaneState> {
    within_reach(layers)?;
    let held = match target {
        Target::PullOff => Held::PullOff,
        Target::Delta(_) => Held::Delta,
        Target::Force(_) => Held::Force,
    };
    let mut done = 0;
    let rungs = ladder(layers, rho, target, &LADDER, &mut |r: &Rung| {
        done += 1;
        crate::progress::stage(format!(
            "the layer in the plane: rung {done} of {} (process zone {}) done, {} cells per side",
            LADDER.len(),
            short(r.eps),
            r.n
        ));
    })?;
    let at = |k: usize, of: fn(&Rung) -> f64| (rungs[k].eps, of(&rungs[k]));
    let force = |r: &Rung| r.state.force_bar;
    let (coarse, fine) = match target {
        Target::Force(f) => (f, f),
        _ => (
            jkr_limit([at(0, force), at(1, force), at(2, force)])?,
            jkr_limit([at(1, force), at(2, force), at(3, force)])?,
        ),
    };
    // (at an approach, relative to the force unit 2R₁Δγ where the force is
    // smaller: it passes through zero)
    let force_error = match target {
        Target::Force(_) => 0.0,
        Target::PullOff => BOUND_OVER_DIFFERENCE * ((fine - coarse) / fine).abs(),
        Target::Delta(_) => BOUND_OVER_DIFFERENCE * ((fine - coarse) / fine.abs().max(1.0)).abs(),
    };
    let plane: Vec<PlaneRung> = rungs
        .iter()
        .map(|r| {
            Ok(PlaneRung {
                eps: Some(r.eps),
                cells: Some(r.n),
                functions: None,
                force_bar: r.state.force_bar,
                delta_bar: r.state.delta_bar,
                a_bar: half_width(r, r.state.half_widths.0, "X")?,
                b_bar: half_width(r, r.state.half_widths.1, "Y")?,
            })
        })
        .collect::<Result<_>>()?;
    let last = &plane[plane.len() - 1];
    let finest = &plane[plane.len() - 3..];
    let spread = |of: fn(&PlaneRung) -> f64| {
        let values = finest.iter().map(of);
        values.clone().fold(f64::MIN, f64::max) - values.fold(f64::MAX, f64::min)
    };
    let size_error = (spread(|r| r.a_bar) / last.a_bar)
        .max(spread(|r| r.b_bar) / last.b_bar)
        .max(SIZE_FLOOR);
    let what = match held {
        Held::PullOff => "pull-off".to_string(),
        Held::Delta => format!("state at delta = {}", short(last.delta_bar)),
        Held::Force => format!("state at force = {}", short(fine)),
        // (the grid holds neither)
        Held::Size | Held::DisplacementPullOff => "state".to_string(),
    };
    if !(force_error <= WORST_FORCE_ERROR) {
        return Err(Error::Unresolved {
            what: format!(
                "the layer's {what} in the plane at rho = {}, h/L = {}: the grid solver's two JKR limits of the force ({} and {}) differ by {} %, so it is within {} % only, not the {} % an answer needs",
                short(rho),
                short(layers.thinnest()),
                rounded(coarse),
                rounded(fine),
                short(100.0 * force_error / BOUND_OVER_DIFFERENCE),
                short(100.0 * force_error),
                short(100.0 * WORST_FORCE_ERROR)
            ),
            residual: force_error,
        });
    }
    let mut warnings = Vec::new();
    if force_error > WARN_FORCE_ERROR {
        warnings.push(format!(
            "the layer's force in the plane is within {} % only (its two JKR limits differ by {} %)",
            two_digits(100.0 * force_error),
            two_digits(100.0 * force_error / BOUND_OVER_DIFFERENCE)
        ));
    }
    Ok(PlaneState {
        rho,
        held,
        method: Method::Grid,
        force_bar: fine,
        force_error,
        force_bar_coarse: coarse,
        a_bar: last.a_bar,
        b_bar: last.b_bar,
        s: last.b_bar / last.a_bar,
        delta_bar: last.delta_bar,
        size_error,
        delta_error: if held == Held::Delta {
            0.0
        } else {
            spread(|r| r.delta_bar)
        },
        griffith_error: None,
        slopes: None,
        verdicts: held.verdicts(None),
        coatings: layers.coatings(),
        coatings_are: super::ON_THE_GRID,
        warnings,
        rungs: plane,
    })
}

/// A rung's half width along `axis`, or an error where its grid holds none.
fn half_width(r: &Rung, w: Option<f64>, axis: &str) -> Result<f64> {
    w.ok_or_else(|| {
        Error::NoState(format!(
            "the layer's pull-off in the plane: on the rung of process zone {} the contact has no edge along {axis} inside the grid",
            short(r.eps)
        ))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::layer::{Coating, Route};

    /// `p`'s half widths and approach each within the bound it states of
    /// the axisymmetric `reference` at ρ = 1.
    fn size_and_approach_within_bounds(p: &PlaneState, reference: &crate::layer::LayerState) {
        for size in [p.a_bar, p.b_bar] {
            assert!(
                ((size - reference.a_bar) / reference.a_bar).abs() <= p.size_error,
                "{size} against {}, bound {}",
                reference.a_bar,
                p.size_error
            );
        }
        assert!(
            (p.delta_bar - reference.delta_bar).abs() <= p.delta_error,
            "{} against {}, bound {}",
            p.delta_bar,
            reference.delta_bar,
            p.delta_error
        );
    }

    // (the slow tier: CI solves the plane through the model layer at 60°
    // and 70°, and the slow tier's tables hold these states' digits too)
    #[test]
    #[ignore = "slow tier (.ci/slow): one ladder, about 35 s"]
    fn the_pull_off_in_the_plane_meets_the_axisymmetric_reference_within_its_bounds() {
        // h/L = 1 at ρ = 1, where the axisymmetric layer (Galerkin in
        // Legendre modes, Griffith's edge) is the independent reference:
        // the force, the size and the approach each within the bound the
        // answer states, and the force's bound below 2e-3
        let layers = Layers::equal(1.0, 0.5).unwrap();
        let reference = layers.pull_off(Route::Griffith).unwrap().load;
        let p = pull_off(&layers, 1.0).unwrap();
        let rel = |x: f64, y: f64| ((x - y) / y).abs();
        assert!(p.force_error < 2e-3, "{}", p.force_error);
        assert!(
            rel(p.force_bar, reference.force_bar) <= p.force_error,
            "{} against {}, bound {}",
            p.force_bar,
            reference.force_bar,
            p.force_error
        );
        size_and_approach_within_bounds(&p, &reference);
        // the ladder's four rungs, coarsest first, each pulling harder than
        // the limit, by less as the process zone shrinks
        assert_eq!(p.rungs.len(), LADDER.len());
        assert!(p.rungs.iter().all(|r| r.force_bar < p.force_bar));
        assert!(p.rungs.windows(2).all(|w| w[0].force_bar < w[1].force_bar));
        assert!(p.warnings.is_empty(), "{:?}", p.warnings);
    }

    #[test]
    #[ignore = "slow tier (.ci/slow): one ladder, about 35 s"]
    fn zero_force_in_the_plane_meets_the_axisymmetric_reference_within_its_bounds() {
        // h/L = 1 at ρ = 1: the state at F̄ = 0 on the branch stable under
        // load control, its approach and size each within the bound it
        // states, against the axisymmetric layer's
        let layers = Layers::equal(1.0, 0.5).unwrap();
        let reference = layers.state(Hold::Force(0.0), Route::Griffith).unwrap();
        let p = state(&layers, 1.0, Some(Hold::Force(0.0))).unwrap();
        assert_eq!(
            (p.held, p.force_bar, p.force_error),
            (Held::Force, 0.0, 0.0)
        );
        size_and_approach_within_bounds(&p, &reference);
        // every rung holds the force asked for
        assert!(
            p.rungs.iter().all(|r| r.force_bar.abs() < 1e-9),
            "{:?}",
            p.rungs
        );
    }

    #[test]
    fn a_held_approach_or_size_in_the_plane_is_refused_with_its_reason() {
        let layers = Layers::equal(1.0, 0.5).unwrap();
        for hold in [Hold::Delta(0.5), Hold::Size(1.0)] {
            match state(&layers, 0.8, Some(hold)) {
                Err(Error::Unavailable {
                    model: "layer",
                    what,
                    ..
                }) => {
                    assert!(what.contains("at rho < 1"), "{what}")
                }
                other => panic!("{hold:?}: {other:?}"),
            }
        }
    }

    #[test]
    fn coatings_beyond_the_ladders_reach_are_refused_at_once() {
        for (thin, thick) in [(0.3, 1.0), (1.0, 20.0)] {
            let c = |h: f64| Coating {
                thinness: h,
                shear_modulus: 1.0,
                nu: 0.5,
            };
            let layers = Layers::new(c(thin), c(thick)).unwrap();
            match pull_off(&layers, 0.8) {
                Err(Error::Unsupported {
                    name: "h/L", value, ..
                }) => {
                    assert!(value == thin || value == thick, "{value}")
                }
                other => panic!("h/L = {thin}, {thick}: {other:?}"),
            }
        }
    }
}

#[cfg(test)]
mod explorations {
    use super::*;
    use crate::layer::Route;

    #[test]
    #[ignore = "exploration: the states at a force and an approach against the axisymmetric reference"]
    fn explore_states_against_the_reference() {
        // THINJKR_PLANE_THIN: h/L (default 1); at ρ = 1 zero force and the
        // state at the approach where the reference's force is minus its
        // pull-off force (a loaded contact)
        let thin: f64 = std::env::var("THINJKR_PLANE_THIN")
            .map(|v| v.parse().unwrap())
            .unwrap_or(1.0);
        let layers = Layers::equal(thin, 0.5).unwrap();
        let pull = layers.pull_off(Route::Griffith).unwrap().load.force_bar;
        // (the test harness's own line ends first)
        println!();
        for hold in [Hold::Force(0.0), Hold::Force(-pull)] {
            let reference = layers.state(hold, Route::Griffith).unwrap();
            let holds = [hold, Hold::Delta(reference.delta_bar)];
            for h in holds {
                let t = std::time::Instant::now();
                let target = match h {
                    Hold::Delta(d) => Target::Delta(d),
                    Hold::Force(f) => Target::Force(f),
                    _ => unreachable!(),
                };
                let p = state_of(&layers, 1.0, target).unwrap();
                println!(
                    "h/L {thin} {h:?}: F {:.7} ({:+.2e} rel, bound {:.2e}) delta {:.6} ({:+.2e}, bound {:.2e}) a {:.5} ({:+.2e} rel, bound {:.2e}); rungs F {:?} delta {:?} a {:?} ({:.0} s)",
                    p.force_bar,
                    p.force_bar / reference.force_bar - 1.0,
                    p.force_error,
                    p.delta_bar,
                    p.delta_bar - reference.delta_bar,
                    p.delta_error,
                    p.a_bar,
                    p.a_bar / reference.a_bar - 1.0,
                    p.size_error,
                    p.rungs.iter().map(|r| r.force_bar).collect::<Vec<_>>(),
                    p.rungs.iter().map(|r| r.delta_bar).collect::<Vec<_>>(),
                    p.rungs.iter().map(|r| r.a_bar).collect::<Vec<_>>(),
                    t.elapsed().as_secs_f64()
                );
            }
        }
    }
}
