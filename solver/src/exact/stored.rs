//! The stored pull-offs: the resolved exact pull-offs below ρ = [`STORED_FROM_RHO`]
//! that `thinjkr exact store-pull-offs` writes to
//! `solver/data/exact_pull_offs.json`, one at every step of the follow in
//! ρ from the pull-off at [`STORED_FROM_RHO`] ([`resolve`'s arclength
//! follow](super::resolve)), and the route that starts from them.
//!
//! Below ρ = 0.3 the pull-off is the one followed in ρ from the pull-off
//! at ρ = 0.3 (docs/exact.md, "The arclength representation"); following
//! it from 0.3 each time costs one step per 0.01–0.02 in ρ: 7.5 s to
//! ρ = 0.1, a minute and a half to 0.066. Started instead from the stored pull-off nearest above
//! the ρ asked for, the same follow takes one step or two. Between three
//! stored pull-offs of one truncation in the plain gauge, their
//! interpolation in ρ ([`Prediction`]: contour, δ̄ and the curvature
//! d²F̄/dā² stored with each) is nearer still: the minimum is found from
//! it directly, at the ρ asked for, by a Newton step with the predicted
//! curvature and then the secant; where that fails, or lands farther than [`PREDICTION_REACH`]
//! from the prediction, the follow from the one nearest above is taken. A
//! stored pull-off is only a start: it is checked on the fine grid before it is
//! used (its boundary error at most [`CONVERGED`](super::CONVERGED)), and
//! the answer is the follow's, resolved like every other. Where the file
//! cannot be read, or a stored state fails its check, the route is not
//! taken and the pull-off is followed from ρ = 0.3 as before.
//!
//! Owns: [`STORED_FROM_RHO`], [`Stored`], [`StoredPullOff`], [`Prediction`],
//! [`pull_off`], [`below_the_floor`]. May use: its parent `exact` (`resolve`'s follow and
//! escalation), `error`. The study `studies::stored_pull_offs` writes them.

use super::ladder::Ladder;
use super::{Contour, Exact, ExactState, Gap, Route, Truncation};
use crate::error::{Error, Result};

/// The ρ below which the pull-off is followed from the stored ones: the
/// conformal form's escalation resolves the pull-off directly down to
/// here (docs/accuracy.md's row ρ = 0.3: N = 80).
pub(crate) const STORED_FROM_RHO: f64 = 0.3;

/// The stored pull-offs, as in `solver/data/exact_pull_offs.json`.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub(crate) struct Stored {
    /// How the file was made.
    pub generated_by: String,
    /// The pull-offs, ρ falling, the first at [`STORED_FROM_RHO`].
    pub pull_offs: Vec<StoredPullOff>,
    /// The smallest ρ the follow converged at (the last entry's).
    pub reached: f64,
    /// Why the follow stopped there, in words.
    pub why_stopped: String,
}

/// One stored pull-off: enough to rebuild the state.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub(crate) struct StoredPullOff {
    /// ρ.
    pub rho: f64,
    /// F̄ (for the reader; the state is rebuilt from the contour).
    pub force_bar: f64,
    /// ā.
    pub a_bar: f64,
    /// s = b̄/ā.
    pub s: f64,
    /// δ̄.
    pub delta_bar: f64,
    /// The boundary error when it was stored.
    pub bc_error: f64,
    /// Its discretisation.
    pub truncation: Truncation,
    /// Its contour.
    pub contour: Contour,
    /// d²F̄/dā² along its family at fixed ρ
    /// ([`Exact::force_curvature_in_size`]), for the [`Prediction`]'s
    /// first secant step; `None` where it is not in the plain gauge
    /// ([`in_plain_gauge`]: the equations at fixed ā on its truncation
    /// are not the ones it solves) or where it was not found (near a fold
    /// in ā, as at ρ = 0.29, where the equations at fixed ā are nearly
    /// singular).
    pub force_curvature: Option<f64>,
    /// Whether its contour has a narrow groove
    /// ([`Contour::narrow_groove`]): where it or the pull-off before it
    /// has one, its coefficients are in another gauge than plain
    /// arclength, and it is not interpolated.
    pub narrow_groove: bool,
}

impl StoredPullOff {
    /// The state again, from the contour and δ̄ (no Newton iteration): its
    /// force and boundary error computed on the fine grid, refused when
    /// the boundary error is above [`CONVERGED`](super::CONVERGED).
    pub(crate) fn state(&self, gap: Gap) -> Result<ExactState> {
        let ex = Exact::on(gap, self.rho, self.truncation)?.deferring_stability();
        let mut st = ex.state(&ex.unknowns_of(&self.contour, self.delta_bar))?;
        if st.bc_error > super::CONVERGED {
            return Err(Error::NoState(format!(
                "the stored pull-off at rho = {} has boundary error {:.1e} (the file is stale: `thinjkr exact store-pull-offs`)",
                crate::error::rounded(self.rho),
                st.bc_error
            )));
        }
        st.route = Route::ContinuedInRho;
        Ok(st)
    }
}

/// Whether a stored pull-off of truncation `t` is in the plain gauge of the
/// arclength representation (θ proportional to arclength), so that its
/// coefficients describe its curve as those of its neighbours do: it has
/// no narrow groove, and neither has the pull-off it was followed from
/// (the follow crowds the points of the next one where the last had one).
pub(crate) fn in_plain_gauge(t: Truncation, grooved: bool, before_grooved: bool) -> bool {
    t.arclength > 0 && !grooved && !before_grooved
}

/// The file compiled in.
const FILE: &str = include_str!("../../data/exact_pull_offs.json");

/// The stored pull-offs, read once; `None` where the file does not parse.
pub(crate) fn stored() -> Option<&'static Stored> {
    static READ: std::sync::OnceLock<Option<Stored>> = std::sync::OnceLock::new();
    READ.get_or_init(|| serde_json::from_str(FILE).ok())
        .as_ref()
}

/// The pull-off at `rho` from the [`Prediction`] between stored pull-offs
/// where there is one and it serves, else followed in ρ from the stored
/// pull-off nearest above it; `None` (the route not taken) for another gap than the
/// cylinders', for ρ at or above [`STORED_FROM_RHO`], or where no stored start passes
/// its check. Below where the stored follow stopped, by more than the
/// follow's smallest step in ρ, and with its last pull-off already at the
/// escalation's last rung, the follow is not tried again: the store's own
/// follow, from that pull-off with the same escalation, failed at every
/// step it tried down to the smallest (a minute's work with 320 modes), so
/// the store's reason is the answer, typed ([`Error::StopsInRho`]).
pub(crate) fn pull_off(gap: Gap, rho: f64) -> Option<Result<ExactState>> {
    if gap != Gap::CYLINDERS || !(rho > 0.0 && rho < STORED_FROM_RHO) {
        return None;
    }
    if let Some(below) = below_the_floor(gap, rho, "pull-off") {
        return Some(Err(below));
    }
    let table = stored()?;
    if let Some(found) = predicted(table, rho).and_then(|p| p.pull_off(gap, rho).ok()) {
        return Some(Ok(found));
    }
    let nearest = table
        .pull_offs
        .iter()
        .filter(|p| p.rho >= rho)
        .min_by(|p, q| p.rho.total_cmp(&q.rho))?;
    let start = nearest.state(gap).ok()?;
    Some(super::resolve::pull_off_followed_in_arclength(&start, rho))
}

/// Where `rho` lies below the floor of the cylinders' exact solver: below
/// where the stored follow of the pull-off stopped converging (by more
/// than the follow's smallest step in ρ), with its last pull-off already
/// at the escalation's last rung, the follow is not tried again: the
/// store's own follow, from that pull-off with the same escalation, failed
/// at every step it tried down to the smallest (a minute's work with 320
/// modes). No state at any control is sought there either: below
/// ρ = 0.18 the states the routes find lie on the pull-off's own piece
/// (docs/exact.md, "Where it stops"), and the routes took minutes to say
/// they found none (`exact solve --rho 1e-300 --delta 2`: 121 s; `exact
/// zero-force --rho 5e-324`: 78 s).
/// The store's reason is the answer, typed ([`Error::StopsInRho`]), for
/// `asked` (the pull-off, or a state at a control); `None` above the
/// floor, for another gap, or where the file cannot be read.
pub(crate) fn below_the_floor(gap: Gap, rho: f64, asked: &str) -> Option<Error> {
    if gap != Gap::CYLINDERS {
        return None;
    }
    let table = stored()?;
    let last_rung = Some(Ladder::arclength().top_modes());
    let at_last_rung = table
        .pull_offs
        .last()
        .is_some_and(|p| Some(p.truncation.modes) == last_rung);
    (at_last_rung && rho < table.reached - super::rho_walk::PULL_OFF_IN_ARCLENGTH.smallest).then(|| {
        Error::StopsInRho {
            reached: table.reached,
            what: format!(
                "no exact {asked} is sought at rho = {}: below rho = {} the exact solver seeks none (its pull-off, followed down in rho with the most modes the solver accepts by `thinjkr exact store-pull-offs`, stops there: {}; solver/data/exact_pull_offs.json); the slender limit (--model slender) is the model for rho → 0",
                crate::error::short(rho),
                crate::error::short(table.reached),
                table.why_stopped
            ),
        }
    })
}

/// How far in ā from a [`Prediction`] the minimum found from it may lie
/// and still be taken for the one the follow reaches (more than a hundred
/// times the prediction's error at ρ = 0.1); farther, the follow is taken.
const PREDICTION_REACH: f64 = 0.02;

/// The first step in ā of the secant from a [`Prediction`] without a
/// curvature: about eight times the prediction's error in ā at ρ = 0.1
/// (1.2e-4), so that the secant's first slope is taken near the minimum.
const PREDICTED_FIRST_STEP: f64 = 1e-3;

/// A pull-off at a ρ between stored ones, interpolated from the three
/// stored pull-offs nearest in ρ: their contour coefficients, δ̄ and
/// (where all three have one) the curvature d²F̄/dā², quadratic in ρ
/// (Lagrange).
struct Prediction {
    truncation: Truncation,
    contour: Contour,
    delta_bar: f64,
    force_curvature: Option<f64>,
}

/// The [`Prediction`] at `rho`, where the three stored pull-offs nearest
/// in ρ bracket it, share one truncation, and are in the plain gauge (θ
/// proportional to arclength: neither they nor the pull-offs each was
/// followed from have a narrow groove, so their coefficients describe
/// their curves in the same way); `None` otherwise.
fn predicted(table: &Stored, rho: f64) -> Option<Prediction> {
    let all = &table.pull_offs;
    let mut order: Vec<usize> = (0..all.len()).collect();
    order.sort_by(|&i, &j| {
        (all[i].rho - rho)
            .abs()
            .total_cmp(&(all[j].rho - rho).abs())
    });
    let near: Vec<usize> = order.into_iter().take(3).collect();
    let first = &all[*near.first()?];
    let brackets =
        near.iter().any(|&i| all[i].rho >= rho) && near.iter().any(|&i| all[i].rho <= rho);
    // the grooves as stored (`the_stored_flags_are_fresh` holds them)
    let plain = |i: usize| {
        in_plain_gauge(
            all[i].truncation,
            all[i].narrow_groove,
            i > 0 && all[i - 1].narrow_groove,
        )
    };
    if near.len() < 3
        || !brackets
        || !near
            .iter()
            .all(|&i| all[i].truncation == first.truncation && plain(i))
    {
        return None;
    }
    let weight = |i: usize| {
        near.iter()
            .filter(|&&j| j != i)
            .map(|&j| (rho - all[j].rho) / (all[i].rho - all[j].rho))
            .product::<f64>()
    };
    let weights: Vec<(f64, &StoredPullOff)> = near.iter().map(|&i| (weight(i), &all[i])).collect();
    let mix =
        |f: &dyn Fn(&StoredPullOff) -> f64| weights.iter().map(|(w, p)| w * f(p)).sum::<f64>();
    let modes = first.contour.b.len();
    let positive = first.contour.c.len();
    Some(Prediction {
        truncation: first.truncation,
        contour: Contour {
            a: mix(&|p| p.contour.a),
            b: (0..modes).map(|j| mix(&|p| p.contour.b[j])).collect(),
            c: (0..positive).map(|j| mix(&|p| p.contour.c[j])).collect(),
        },
        delta_bar: mix(&|p| p.delta_bar),
        force_curvature: weights
            .iter()
            .map(|(w, p)| p.force_curvature.map(|k| w * k))
            .sum::<Option<f64>>(),
    })
}

impl Prediction {
    /// The pull-off from the prediction: Newton at its ā, then the secant
    /// on dF̄/dā from there, its first step Newton's with the predicted
    /// curvature (else [`PREDICTED_FIRST_STEP`] downhill);
    /// resolved (boundary error at most [`CONVERGED`](super::CONVERGED)),
    /// within [`PREDICTION_REACH`] of the prediction's ā, and with its
    /// stability, or an error (the caller then follows from the stored
    /// pull-off nearest above).
    fn pull_off(&self, gap: Gap, rho: f64) -> Result<ExactState> {
        let ex = Exact::on(gap, rho, self.truncation)?.deferring_stability();
        let a_bar = self.contour.a_bar();
        let u0 = ex.newton(super::Hold::Size(a_bar), &self.contour, self.delta_bar)?;
        let mut po = ex.force_minimum_in_size_stepping(
            u0,
            match self.force_curvature {
                Some(k) => super::branch::FirstStep::ByCurvature(k),
                None => super::branch::FirstStep::Downhill(PREDICTED_FIRST_STEP),
            },
        )?;
        if po.bc_error > super::CONVERGED || (po.a_bar - a_bar).abs() > PREDICTION_REACH {
            return Err(Error::NoState(format!(
                "the pull-off predicted from the stored ones at rho = {} is not resolved or not near the prediction",
                crate::error::rounded(rho)
            )));
        }
        po.stability = ex.stability(&po)?;
        po.route = Route::BetweenStored;
        ex.accept_resolved_pull_off((po, Vec::new()))
            .map(|(st, _)| st)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The stored pull-off nearest `rho`.
    fn nearest(table: &Stored, rho: f64) -> &StoredPullOff {
        table
            .pull_offs
            .iter()
            .min_by(|a, b| (a.rho - rho).abs().total_cmp(&(b.rho - rho).abs()))
            .expect("stored pull-offs")
    }

    /// The points crowded into the grooves (docs/exact.md, "Points crowded
    /// into the grooves"): the stored pull-off nearest ρ = 0.045 solved
    /// again at its ā with 160 modes of each sign has a boundary error
    /// below 1e-9 with its points crowded, and more than a hundred times
    /// that at equal arclength (1.0e-11 against 1.5e-5 at ρ = 0.0442), with
    /// F̄ the same to 1e-8; the contour at ρ = 0.3 has no groove and is
    /// not crowded.
    #[test]
    fn crowding_the_points_into_a_narrow_groove_resolves_it_with_fewer_modes() {
        let table = stored().unwrap();
        assert!(table.pull_offs[0].contour.groove().is_none());
        assert!(table.pull_offs[0].contour.crowded_at_groove(48).is_none());
        let q = nearest(table, 0.045);
        let po = q.state(Gap::cylinders()).unwrap();
        let n = 160;
        let solve = |c: &Contour| {
            Exact::on(po.gap, po.rho, Truncation::in_arclength(n))
                .unwrap()
                .deferring_stability()
                .keeping_the_speed_of(c)
                .solve(po.a_bar, c, po.delta_bar)
                .unwrap()
        };
        let crowded = solve(&po.contour.crowded_at_groove(n).expect("a narrow groove"));
        let even = solve(&po.contour.in_arclength(n));
        assert!(
            crowded.bc_error < 1e-9,
            "rho {}: {:e}",
            po.rho,
            crowded.bc_error
        );
        assert!(
            even.bc_error > 100.0 * crowded.bc_error,
            "rho {}: {:e}",
            po.rho,
            even.bc_error
        );
        assert!((crowded.force_bar - even.force_bar).abs() < 1e-8);
    }

    /// Well below where the stored follow stopped, the answer is the
    /// store's reason, typed, without a follow (which would take a minute):
    /// a follow's own error would name the ρ it reached from its start, not
    /// the file.
    #[test]
    fn below_the_stored_pull_offs_the_answer_is_the_stores_reason() {
        let table = stored().unwrap();
        match pull_off(Gap::cylinders(), 0.01) {
            Some(Err(Error::StopsInRho { reached, what })) => {
                assert_eq!(reached, table.reached);
                assert!(what.contains(&table.why_stopped), "{what}");
                assert!(what.contains("solver/data/exact_pull_offs.json"), "{what}");
            }
            other => panic!("{:?}", other.map(|r| r.map(|st| st.rho))),
        }
    }

    /// The file parses, its pull-offs fall in ρ from [`STORED_FROM_RHO`] down to
    /// `reached`, and three of them (the first, one in the middle, the
    /// last) are rebuilt with a boundary error below 1e-9 and the F̄, ā
    /// and s stored (to 1e-9: the same contour, the same fine grid).
    #[test]
    fn the_stored_pull_offs_are_resolved_states() {
        let table = stored().expect("solver/data/exact_pull_offs.json parses");
        let p = &table.pull_offs;
        assert!(p.len() >= 10, "{} stored pull-offs", p.len());
        assert_eq!(p[0].rho, STORED_FROM_RHO);
        assert!(p.windows(2).all(|w| w[1].rho < w[0].rho));
        assert_eq!(p[p.len() - 1].rho, table.reached);
        for q in [&p[0], &p[p.len() / 2], &p[p.len() - 1]] {
            let st = q.state(Gap::cylinders()).unwrap();
            assert!(st.bc_error <= 1e-9, "rho {}: bc {:e}", q.rho, st.bc_error);
            for (got, stored) in [
                (st.force_bar, q.force_bar),
                (st.a_bar, q.a_bar),
                (st.s, q.s),
            ] {
                assert!(
                    (got - stored).abs() <= 1e-9 * stored.abs().max(1.0),
                    "rho {}",
                    q.rho
                );
            }
        }
    }

    /// The flags and curvatures stored are those of the stored contours:
    /// every pull-off's narrow groove looked for again, a curvature only in
    /// the plain gauge, and the curvature d²F̄/dā² of the one nearest
    /// ρ = 0.105 computed again, to 1e-6.
    #[test]
    fn the_stored_flags_are_fresh() {
        let table = stored().unwrap();
        for (i, p) in table.pull_offs.iter().enumerate() {
            assert_eq!(
                p.narrow_groove,
                p.contour.narrow_groove().is_some(),
                "rho {}",
                p.rho
            );
            let before = i > 0 && table.pull_offs[i - 1].narrow_groove;
            if !in_plain_gauge(p.truncation, p.narrow_groove, before) {
                assert!(p.force_curvature.is_none(), "rho {}", p.rho);
            }
        }
        let q = nearest(table, 0.105);
        let st = q.state(Gap::cylinders()).unwrap();
        let ex = Exact::on(st.gap, st.rho, st.truncation).unwrap();
        let curvature = ex.force_curvature_in_size(&ex.unknowns(&st)).unwrap();
        let stored_curvature = q.force_curvature.expect("a stored curvature");
        assert!(
            (curvature / stored_curvature - 1.0).abs() < 1e-6,
            "rho {}: {curvature} against {} stored",
            q.rho,
            stored_curvature
        );
    }

    /// From a stored pull-off, the follow in ρ lands on the next one (the
    /// file is the follow's own path): the step from the top, which leaves
    /// the conformal form, to 1e-9 in F̄ and s, 1e-7 in ā (F̄ is stationary
    /// in ā there). A pull-off at ρ between two stored ones is the same from
    /// either route: from the stored start just above, and followed from ρ =
    /// 0.3 (the route without the file), to 1e-9 in F̄.
    #[test]
    fn the_follow_from_a_stored_pull_off_lands_on_the_next() {
        let table = stored().unwrap();
        let (first, second) = (&table.pull_offs[0], &table.pull_offs[1]);
        let start = first.state(Gap::cylinders()).unwrap();
        let next =
            super::super::resolve::pull_off_followed_in_arclength(&start, second.rho).unwrap();
        assert!((next.force_bar - second.force_bar).abs() < 1e-9);
        assert!((next.s - second.s).abs() < 1e-9);
        assert!((next.a_bar - second.a_bar).abs() < 1e-7);
        let between = 0.5 * (second.rho + table.pull_offs[2].rho);
        let stored_route = pull_off(Gap::cylinders(), between).unwrap().unwrap();
        let from_top =
            super::super::resolve::pull_off_followed_in_arclength(&start, between).unwrap();
        assert!(
            (stored_route.force_bar - from_top.force_bar).abs() < 1e-9,
            "{} against {}",
            stored_route.force_bar,
            from_top.force_bar
        );
        // the three nearest include the top (the conformal-map form)
        assert!(predicted(table, between).is_none());
    }

    /// [`Contour::point_at`] (the exponentials by recurrence) is
    /// [`Contour::at`]'s point to 1e-13 of ā on the stored contour with the
    /// most modes (320 of each sign), at 1000 angles round it (measured:
    /// 8.7e-16).
    #[test]
    fn the_point_by_recurrence_is_the_point_of_the_series() {
        let table = stored().unwrap();
        let c = &table.pull_offs.last().unwrap().contour;
        assert_eq!(c.b.len(), 320);
        let worst = (0..1000)
            .map(|k| {
                let theta = 2.0 * std::f64::consts::PI * k as f64 / 1000.0;
                (c.point_at(theta) - c.at(theta)[0]).norm()
            })
            .fold(0.0, f64::max);
        eprintln!("point_at against at: {worst:.1e}, a = {}", c.a_bar());
        assert!(worst < 1e-13 * c.a_bar(), "{worst:e}");
    }

    /// Between stored pull-offs of one truncation in the plain gauge (ρ =
    /// 0.1, between 0.105 and 0.0975) the pull-off is found from the
    /// prediction interpolated from the three nearest, and it is the one the
    /// follow from the stored pull-off just above reaches: F̄ to 1e-11, s to
    /// 1e-9, ā to 1e-8 (F̄ is stationary in ā there). The prediction's ā is
    /// within 1e-3 of it, and its curvature d²F̄/dā² within 1 % of the
    /// curvature there (so that the secant's first step, Newton's, lands
    /// near the minimum); both have the same unstable modes and verdicts,
    /// and the route of the one from the prediction says so.
    /// Measured: F̄ 5e-14, s 5e-11, ā 1e-10 apart, the prediction 1.2e-4
    /// off in ā and its curvature 2.4e-5 (relative) off.
    #[test]
    fn the_pull_off_from_the_prediction_is_the_followed_one() {
        let table = stored().unwrap();
        let rho = 0.1;
        let prediction = predicted(table, rho).unwrap();
        let from_prediction = prediction.pull_off(Gap::cylinders(), rho).unwrap();
        let above = table
            .pull_offs
            .iter()
            .filter(|p| p.rho >= rho)
            .min_by(|p, q| p.rho.total_cmp(&q.rho))
            .unwrap();
        let followed = super::super::resolve::pull_off_followed_in_arclength(
            &above.state(Gap::cylinders()).unwrap(),
            rho,
        )
        .unwrap();
        let (df, ds, da) = (
            (from_prediction.force_bar - followed.force_bar).abs(),
            (from_prediction.s - followed.s).abs(),
            (from_prediction.a_bar - followed.a_bar).abs(),
        );
        eprintln!(
            "rho = 0.1, predicted against followed: F {df:.1e}, s {ds:.1e}, a {da:.1e}; prediction off by {:.1e} in a",
            (prediction.contour.a_bar() - followed.a_bar).abs()
        );
        assert!(df < 1e-11 && ds < 1e-9 && da < 1e-8);
        assert!((prediction.contour.a_bar() - followed.a_bar).abs() < 1e-3);
        let ex = Exact::on(followed.gap, rho, followed.truncation).unwrap();
        let curvature = ex.force_curvature_in_size(&ex.unknowns(&followed)).unwrap();
        eprintln!(
            "curvature: predicted {:?}, at the pull-off {curvature}",
            prediction.force_curvature
        );
        let predicted_curvature = prediction.force_curvature.expect("a predicted curvature");
        assert!((predicted_curvature / curvature - 1.0).abs() < 0.01);
        assert!(from_prediction.bc_error <= crate::exact::CONVERGED);
        // the route says where it came from
        assert_eq!(from_prediction.route, Route::BetweenStored);
        // the same unstable modes and verdicts
        let modes =
            |v: &[super::super::stability::UnstableMode]| v.iter().map(|m| m.n).collect::<Vec<_>>();
        let (p, f) = (&from_prediction.stability, &followed.stability);
        assert_eq!(modes(&p.displacement), modes(&f.displacement));
        assert_eq!(modes(&p.load), modes(&f.load));
        assert_eq!(
            (p.stable_displacement, p.stable_load),
            (f.stable_displacement, f.stable_load)
        );
    }
}
