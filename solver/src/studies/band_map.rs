//! The study that draws the band map (`thinjkr exact bands`, issue 26):
//! at one ρ, every interval of the contact size ā where no near-elliptic
//! exact state exists, found by the seed's screen and settled by the exact
//! family's folds, with the circle's neutral points the screen passed
//! probed, and F̄(ā) of the model and of the exact family over the screen
//! for the figure. The screen and the settling of one gap are the
//! engine's (`exact::bands`), which its routes to a state use too; the
//! map's shape is the command line's output (`report::BandMap`).
//!
//! Owns: [`bands`]. May use: `exact` (the screen, the settling, the
//! escalation), `report` (the map's shape), `control` (its tests), `error`, `newton` (the stop flag carried to
//! rayon's threads), `progress`, rayon.

use crate::error::Result;
use crate::exact::bands::{
    beside, gaps, screen, settle, unscreened_neutral_points, Gap, NoBand, PROBE_STEP, STEP,
};
use crate::exact::ladder::Ladder;
use crate::exact::same::Same;
use crate::exact::seed::Guess;
use crate::exact::Contour;
use crate::report::{BandMap, Crossed, CurvePoint, Probe};
use rayon::prelude::*;

/// The exact family's F̄(ā) is sampled at every this many grid points of
/// the screen (0.05 in ā).
const CURVE_EVERY: usize = 5;

/// The band map at `rho` for ā in [`from`, `to`] (see the module; the
/// screen's step [`STEP`], the probes' [`PROBE_STEP`]).
pub(crate) fn bands(rho: f64, from: f64, to: f64) -> Result<BandMap> {
    let gap = crate::exact::Gap::cylinders();
    crate::error::check_range("rho", rho, rho > 0.0 && rho <= 1.0, "(0, 1]")?;
    crate::error::check_range("from", from, from.is_finite() && from > 0.5, "(0.5, to)")?;
    crate::error::check_range("to", to, to.is_finite() && to > from, "(from, from + 10]")?;
    crate::progress::stage(format!(
        "the screen by the seed's family, a from {from} to {to}"
    ));
    let (model, grid, states) = screen(gap, rho, from, to)?;
    let holes = gaps(&states);
    let mut map = BandMap {
        rho,
        range: [from, to],
        step: STEP,
        screen: model.name(),
        bands: Vec::new(),
        crossed: Vec::new(),
        unsettled: Vec::new(),
        open_ends: Vec::new(),
        probed: Vec::new(),
        curve: curve(gap, rho, &grid, &states),
    };
    let count = holes.len();
    for (k, hole) in holes.into_iter().enumerate() {
        crate::progress::stage(format!(
            "gap {} of {count} the screen found, settled by the exact family's folds",
            k + 1
        ));
        match hole {
            Gap::Inside(lo, hi) => {
                let (left, right) = beside(&states, lo, hi);
                let screened = [grid[lo], grid[hi]];
                match settle(gap, rho, &left, &right, STEP) {
                    Ok(Ok(band)) => map.bands.push(band),
                    Ok(Err(why)) => map.crossed.push(Crossed {
                        screened,
                        why: no_band_words(why, "crosses the gap"),
                    }),
                    Err(e) => map.unsettled.push(Crossed {
                        screened,
                        why: e.to_string(),
                    }),
                }
            }
            Gap::AtEnd(first, last) => map.open_ends.push([grid[first], grid[last]]),
        }
    }
    probe_neutral_points(gap, &mut map, &grid, &states)?;
    Ok(map)
}

/// Probe each neutral point of the circle ā³ = 4(n − 1) that the screen
/// passed without a gap ([`unscreened_neutral_points`]): the exact family
/// is traced towards it from the model's states 0.05 or more below and
/// above, in steps of [`PROBE_STEP`], as a gap is settled; two folds that
/// leave an interval between them are a band.
fn probe_neutral_points(
    gap: crate::exact::Gap,
    map: &mut BandMap,
    grid: &[f64],
    states: &[Option<Guess>],
) -> Result<()> {
    let found: Vec<[f64; 2]> = map
        .bands
        .iter()
        .map(|b| [b.lower.a_bar, b.upper.a_bar])
        .chain(map.crossed.iter().map(|c| c.screened))
        .chain(map.unsettled.iter().map(|c| c.screened))
        .chain(map.open_ends.iter().copied())
        .collect();
    let mut probes = Vec::new();
    for (n, a_n, left, right) in
        unscreened_neutral_points(&gap.at(1.0)?, map.range, grid, states, &found)
    {
        let outcome = if left.is_empty() || right.is_empty() {
            "the model has no near-elliptic state beside it".to_string()
        } else {
            match settle(gap, map.rho, &left, &right, PROBE_STEP) {
                Ok(Ok(band)) => {
                    map.bands.push(band);
                    "band".to_string()
                }
                Ok(Err(why)) => no_band_words(why, "passes the neutral point"),
                Err(e) => format!("not settled: {e}"),
            }
        };
        probes.push(Probe {
            n,
            a_bar: a_n,
            outcome,
        });
    }
    map.bands
        .sort_by(|x, y| x.lower.a_bar.total_cmp(&y.lower.a_bar));
    map.probed = probes;
    Ok(())
}

/// F̄(ā) over the screen: the model's at every grid point, the exact
/// family's at every [`CURVE_EVERY`]th, each exact state by Newton at that ā
/// from the model's ellipse there (truncations escalated as for every
/// exact state, `exact::resolved`), kept when resolved and near the
/// model's state (s within 5 %).
fn curve(
    gap: crate::exact::Gap,
    rho: f64,
    grid: &[f64],
    states: &[Option<Guess>],
) -> Vec<CurvePoint> {
    let stop = crate::newton::stop_flag();
    grid.par_iter()
        .zip(states)
        .enumerate()
        .map(|(j, (&a_bar, st))| {
            crate::newton::carried(stop.clone(), || {
                let exact = st.as_ref().filter(|_| j % CURVE_EVERY == 0).and_then(|m| {
                    crate::exact::resolved(gap, rho, &Ladder::conformal(), |ex| {
                        ex.solve(
                            m.a_bar,
                            &Contour::ellipse(m.a_bar, m.b_bar, ex.truncation().modes),
                            m.delta_bar,
                        )
                    })
                    .ok()
                    .filter(|e| e.bc_error <= crate::exact::RESOLVED && Same::SAME_SHAPE.of(e, m))
                    .map(|e| e.force_bar)
                });
                CurvePoint {
                    a_bar,
                    model: st.as_ref().map(|m| m.force_bar),
                    exact,
                }
            })
        })
        .collect()
}

/// Why a gap holds no band, in words, `passes` saying what the family
/// passed without folding ("crosses the gap", "passes the neutral point").
fn no_band_words(why: NoBand, passes: &str) -> String {
    match why {
        NoBand::Overlap { lower, upper } => format!(
            "the arms' folds overlap (the lower arm folds at a = {lower:.4}, the upper at a = {upper:.4}): near-elliptic states exist at every a between"
        ),
        NoBand::NoFold { from } => {
            format!("the exact family from a = {from:.2} {passes} without folding")
        }
    }
}

#[cfg(test)]
mod tests {
    //! The band map (moved from solver/tests/bands.rs with the builder): at
    //! ρ = 0.8 one band at each of the circle's neutral points
    //! ā³ = 4(n − 1), n = 4, 6, 8 (the screen's gaps) and 10 (a narrow one,
    //! found by the probe of the neutral point), in that mode, with
    //! resolved edges, against the committed map and the arms' folds traced
    //! without a model; at ρ = 0.9 the mode-8 band 0.003 wide that the
    //! screen steps over; none at ρ = 1; bad input a typed error.
    use super::*;
    use crate::control::Hold;
    use crate::error::Error;
    use crate::exact::branch::Event;
    use crate::exact::{Exact, Truncation};

    #[test]
    fn bands_at_rho_0_8_sit_at_the_circle_modes_and_match_the_arms_folds() {
        let map = bands(0.8, 2.0, 4.0).unwrap();
        let modes: Vec<Option<usize>> = map.bands.iter().map(|b| b.lower.mode).collect();
        assert_eq!(modes, vec![Some(4), Some(6), Some(8), Some(10)], "{map:#?}");
        let probed: Vec<(usize, &str)> = map
            .probed
            .iter()
            .map(|p| (p.n, p.outcome.as_str()))
            .collect();
        assert_eq!(probed.first(), Some(&(10, "band")), "{probed:?}");
        for b in &map.bands {
            let n = b.lower.mode.unwrap() as f64;
            let neutral = (4.0 * (n - 1.0)).cbrt();
            assert_eq!(b.lower.mode, b.upper.mode, "{b:#?}");
            assert!(b.lower.a_bar < b.upper.a_bar, "{b:#?}");
            assert!(
                (b.lower.a_bar - neutral).abs() < 0.12 && (b.upper.a_bar - neutral).abs() < 0.12,
                "band {} .. {} far from the neutral point {neutral}",
                b.lower.a_bar,
                b.upper.a_bar
            );
            assert!(
                b.lower.bc_error <= 1e-9 && b.upper.bc_error <= 1e-9,
                "{b:#?}"
            );
        }
        assert!(
            map.crossed.is_empty() && map.unsettled.is_empty() && map.open_ends.is_empty(),
            "{map:#?}"
        );
        // the committed band maps (docs/data/exact_bands.jsonl, drawn in
        // docs/figures/exact_bands.svg) hold this one
        let text = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/data/exact_bands.jsonl"),
        )
        .expect("the committed band maps exist");
        let committed = crate::report::band_maps_from_json_lines(&text).expect("band map lines");
        let at = committed
            .iter()
            .find(|m| m.rho == 0.8)
            .expect("the committed maps have rho = 0.8");
        assert_eq!(at.bands.len(), map.bands.len());
        for (c, b) in at.bands.iter().zip(&map.bands) {
            for (ce, be) in [(&c.lower, &b.lower), (&c.upper, &b.upper)] {
                assert!(
                    (ce.a_bar - be.a_bar).abs() < 1e-8
                        && (ce.force_bar - be.force_bar).abs() < 1e-8
                        && ce.mode == be.mode,
                    "committed {ce:?}, now {be:?}: regenerate docs/data/exact_bands.jsonl (docs/exact.md, \"Bands\")"
                );
            }
        }
        // and its F̄(ā): the model's at every grid point, the exact family's at
        // every fifth, as now
        assert_eq!(at.curve.len(), map.curve.len());
        for (c, p) in at.curve.iter().zip(&map.curve) {
            for (was, now) in [(c.model, p.model), (c.exact, p.exact)] {
                assert!(
                    match (was, now) {
                        (Some(w), Some(n)) => (w - n).abs() < 1e-8 * (1.0 + n.abs()),
                        (None, None) => true,
                        _ => false,
                    },
                    "the committed F(a) at a = {} is {was:?}, now {now:?}: regenerate docs/data/exact_bands.jsonl",
                    p.a_bar
                );
            }
        }
        assert!(
            map.curve.iter().filter(|p| p.exact.is_some()).count() >= 30,
            "the exact F(a) is sampled at most grid points outside the bands"
        );
        // the mode-8 band against the arms traced without any model, in steps
        // of at most 0.01 (the fold's ā as the nearer traced point)
        let ex = Exact::new(
            0.8,
            Truncation {
                modes: 16,
                points: 256,
                arclength: 0,
            },
        )
        .unwrap();
        let traced_fold = |from: Hold, direction: f64| {
            let start = ex.at(from).unwrap();
            let br = ex
                .trace_from(&start, direction, 2.5, 3.6, 0.01, 80)
                .unwrap();
            br.events
                .iter()
                .find_map(|e| match e {
                    Event::SizeFold { a_bar } => Some(*a_bar),
                    _ => None,
                })
                .unwrap()
        };
        let band = &map.bands[2];
        let lower = traced_fold(Hold::Force(0.0), 1.0);
        let upper = traced_fold(Hold::Force(10.0), -1.0);
        assert!(
            (band.lower.a_bar - lower).abs() < 0.01 && (band.upper.a_bar - upper).abs() < 0.01,
            "band {} .. {}, traced folds {lower} .. {upper}",
            band.lower.a_bar,
            band.upper.a_bar
        );
    }

    #[test]
    fn no_band_at_rho_one() {
        let map = bands(1.0, 2.0, 3.5).unwrap();
        assert!(
            map.bands.is_empty()
                && map.crossed.is_empty()
                && map.unsettled.is_empty()
                && map.open_ends.is_empty(),
            "{map:#?}"
        );
    }

    #[test]
    fn band_map_input_is_a_typed_error() {
        let name = |r: crate::Result<_>| match r {
            Err(Error::OutOfRange { name, .. }) => name,
            other => panic!("{other:?}"),
        };
        assert_eq!(name(bands(0.0, 2.0, 4.0)), "rho");
        assert_eq!(name(bands(1.5, 2.0, 4.0)), "rho");
        assert_eq!(name(bands(f64::NAN, 2.0, 4.0)), "rho");
        assert_eq!(name(bands(0.8, f64::NAN, 4.0)), "from");
        assert_eq!(name(bands(0.8, 2.0, 1.0)), "to");
        assert_eq!(name(bands(0.8, 2.0, 40.0)), "to");
    }

    /// At ρ = 0.9 the mode-8 band is narrower than the screen's step (the
    /// model has a state at every grid point): the probe of the neutral point
    /// ā³ = 28 finds it. Its edges are folds of the family: Newton at fixed ā
    /// from the ellipse with the edge's s and δ̄ converges to a resolved
    /// near-elliptic state 1e-4 outside each edge, and from either edge's in
    /// the band's middle to none (a second route: no trace, no fold location).
    #[test]
    fn a_band_narrower_than_the_screen_is_found_at_its_neutral_point() {
        let map = bands(0.9, 2.9, 3.2).unwrap();
        assert!(
            map.crossed.is_empty() && map.unsettled.is_empty() && map.open_ends.is_empty(),
            "the screen finds no gap here: {map:#?}"
        );
        let [band] = map.bands.as_slice() else {
            panic!("one band expected: {map:#?}");
        };
        assert_eq!(map.probed.len(), 1);
        assert_eq!(
            (map.probed[0].n, map.probed[0].outcome.as_str()),
            (8, "band")
        );
        let (lo, hi) = (band.lower.a_bar, band.upper.a_bar);
        assert!(hi - lo > 1e-3 && hi - lo < map.step, "{lo} .. {hi}");
        assert!(band.lower.bc_error <= 1e-9 && band.upper.bc_error <= 1e-9);
        let ex = Exact::new(0.9, Truncation::with_modes(16)).unwrap();
        // Newton at fixed ā from the ellipse with an edge's s and δ̄: a resolved
        // state within 1 % of that s, if it finds one
        let near_elliptic = |a: f64, edge: &crate::exact::bands::BandEdge| {
            let ellipse = crate::exact::Contour::ellipse(a, edge.s * a, 16);
            ex.solve(a, &ellipse, edge.delta_bar)
                .ok()
                .filter(|st| st.bc_error <= 1e-9 && (st.s / edge.s - 1.0).abs() < 0.01)
        };
        assert!(
            near_elliptic(lo - 1e-4, &band.lower).is_some(),
            "no state below {lo}"
        );
        assert!(
            near_elliptic(hi + 1e-4, &band.upper).is_some(),
            "no state above {hi}"
        );
        let mid = 0.5 * (lo + hi);
        assert!(
            near_elliptic(mid, &band.lower).is_none() && near_elliptic(mid, &band.upper).is_none(),
            "a near-elliptic state inside the band {lo} .. {hi}"
        );
    }
}
