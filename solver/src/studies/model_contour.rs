//! The exact pull-off's second route, which checks the first (issue 73;
//! `thinjkr exact pull-off --from-model-contour`): from the seeding
//! model's own contour at its pull-off, then the least force along that
//! arm, with no walk in the gap or in ρ. The library's routes to a
//! pull-off (`exact::resolve`) never take it; the command line offers it
//! as a check of theirs.
//!
//! Owns: [`pull_off_from_model_contour`]. May use: `exact` (the problem,
//! its seed, the secant and the trace to a force minimum), `conformal`
//! (the gap named by the user), `error`.

use crate::error::{Error, Result};
use crate::exact::ladder::Ladder;
use crate::exact::{Exact, ExactState, Gap, Route, CONVERGED};

/// The exact load-controlled pull-off at `rho` on the gap named `gap` by
/// its second route ([`pull_off_from_contour`]). A usage error where no
/// family seeds the gap.
pub(crate) fn pull_off_from_model_contour(gap: &str, rho: f64) -> Result<ExactState> {
    pull_off_from_contour(crate::conformal::gap_at_rho(gap, rho)?, rho)
}

/// The load-controlled pull-off on `gap` at `rho` by a second route, which
/// checks the first (issue 73): Newton from the seeding model's own
/// contour at its pull-off (`Seed::pull_off_contour`; the arclength
/// representation holds a member's map as it is), scaled to ā
/// `exact::branch::ABOVE_MODEL_PULL_OFF` larger as the route from its ellipse starts,
/// then the minimum of F̄ over ā along that arm by the secant on
/// dF̄/dā = 0 (`Exact::force_minimum_in_size_from`), else (a fold in ā
/// near it) by the trace downhill in F̄ from that start
/// (`Exact::force_minimum_nearest`): no walk in the gap or in ρ. The
/// arclength ladder is climbed until the minimum's boundary error is
/// below [`CONVERGED`]. An ellipse through the model's ā
/// and b̄ is no such start: on the bumpy gap (φ̄ = X²/2 + μY²/2 + X⁴/24)
/// at ρ = 1 Newton from it lands on a neighbouring arm, whose minimum is
/// F̄ = −4.1106 at ā = 1.974 against the walk's −4.0799 at 2.0485, which
/// this route finds (docs/exact-record.md, "Members on gaps no circle
/// solves"). Route `from_model_contour`.
fn pull_off_from_contour(gap: Gap, rho: f64) -> Result<ExactState> {
    let seed = gap.seed.ok_or_else(|| {
        Error::Usage(format!(
            "no family seeds the exact solver of the gap {} (seeds_exact = true in its data file): the pull-off from a model's contour needs one",
            gap.name
        ))
    })?;
    let (po, contour) = seed.pull_off_contour(rho).ok_or_else(|| {
        Error::NoState(format!(
            "{} has no load-controlled pull-off at rho = {} to start the exact one from",
            seed.name(),
            crate::error::rounded(rho)
        ))
    })?;
    let mut ladder = Ladder::arclength();
    let mut why = None;
    while let Some(t) = ladder.rung() {
        let ex = Exact::on(gap, rho, t)?;
        // just above the model's pull-off, as the route from its ellipse
        // starts: the contour scaled to that size
        let (a, scale, delta) = ex.just_above(&po);
        let found = ex
            .solve(a, &contour.scaled(scale).in_arclength(t.modes), delta)
            .and_then(|st| {
                let u = ex.unknowns(&st);
                ex.force_minimum_in_size_from(u.clone()).or_else(|_| {
                    // downhill in F̄ from the start, where the secant fails
                    // (a fold in ā near the minimum)
                    let slope = ex.force_slope_in_size(&u).map_or(1.0, |s| s.slope);
                    ex.force_minimum_nearest(&st, st.a_bar - 0.1 * slope.signum())
                })
            });
        match found {
            Ok(st) if st.bc_error <= CONVERGED => {
                return Ok(ExactState {
                    route: Route::FromModelContour,
                    ..st
                })
            }
            Ok(st) => {
                ladder.saw(t.modes, st.bc_error);
                why = Some(format!(
                    "max |dp/dnu - 1| = {:.1e} with {} modes of each sign",
                    st.bc_error, t.modes
                ));
            }
            Err(e) => why = Some(e.to_string()),
        }
        if !ladder.escalate() {
            break;
        }
    }
    Err(Error::NoState(format!(
        "exact pull-off at rho = {} from {}'s contour at its pull-off (a = {}): no minimum of the force resolved ({})",
        crate::error::rounded(rho),
        seed.name(),
        crate::error::rounded(po.a_bar),
        why.unwrap_or_default()
    )))
}

#[cfg(test)]
mod tests {
    use crate::exact::Gap;

    /// Issue 73: the pull-off's second route (`exact pull-off
    /// --from-model-contour`): Newton from conformal:8's own contour just
    /// above its pull-off, then the least force along that arm (the secant
    /// on dF̄/dā = 0, no walk in ρ), in the arclength representation, finds
    /// the pull-off the default route reaches (traced from just above
    /// conformal:8's pull-off from an ellipse), to 1e-9 in F̄ and 1e-6 in ā
    /// (F̄ is flat at its minimum), at ρ = 1, 0.8 and 0.5.
    #[test]
    fn the_second_route_from_the_seeds_contour_finds_the_same_pull_off() {
        for rho in [1.0, 0.8, 0.5] {
            let second = super::pull_off_from_model_contour("cylinders", rho).unwrap();
            let (first, _) = crate::exact::pull_off_resolved(rho).unwrap();
            assert_eq!(
                serde_json::to_value(second.route).unwrap(),
                "from_model_contour"
            );
            assert!(second.bc_error < 1e-9, "{rho}: {}", second.bc_error);
            assert!(
                (second.force_bar - first.force_bar).abs() < 1e-9 * first.force_bar.abs(),
                "{rho}: {} against {}",
                second.force_bar,
                first.force_bar
            );
            assert!(
                (second.a_bar - first.a_bar).abs() < 1e-6,
                "{rho}: {} against {}",
                second.a_bar,
                first.a_bar
            );
        }
    }

    /// The second route needs a model to start from: on a gap no family
    /// seeds (the bumpy gap of `exact::gap`, `BUMPY`, with no seed) it is a
    /// usage error naming the gap, before any solve.
    #[test]
    fn the_second_route_on_a_gap_no_family_seeds_is_refused() {
        let bumpy = Gap {
            name: "bumpy",
            particular: &crate::exact::gap::BUMPY,
            seed: None,
        };
        let e = super::pull_off_from_contour(bumpy, 0.8).unwrap_err();
        assert!(matches!(e, crate::Error::Usage(_)), "{e:?}");
        assert!(e.to_string().contains("the gap bumpy"), "{e}");
    }
}
