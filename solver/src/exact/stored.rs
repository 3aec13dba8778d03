//! The stored pull-offs: the resolved exact pull-offs below ρ = [`TOP`]
//! that `thinjkr exact store-pull-offs` writes to
//! `solver/data/exact_pull_offs.json`, one at every step of the follow in
//! ρ from the pull-off at [`TOP`] ([`resolve`'s arclength
//! follow](super::resolve)), and the route that starts from them.
//!
//! Below ρ = 0.3 the pull-off is the one followed in ρ from the pull-off
//! at ρ = 0.3 (docs/exact.md, "The arclength representation"); following
//! it from 0.3 each time costs one step per 0.01–0.02 in ρ: 7.5 s to
//! ρ = 0.1, a minute and a half to 0.066. Started instead from the stored pull-off nearest above
//! the ρ asked for, the same follow takes one step or two. A stored
//! pull-off is only a start: it is checked on the fine grid before it is
//! used (its boundary error at most [`CONVERGED`](super::CONVERGED)), and
//! the answer is the follow's, resolved like every other. Where the file
//! cannot be read, or a stored state fails its check, the route is not
//! taken and the pull-off is followed from ρ = 0.3 as before.
//!
//! Owns: [`TOP`], [`Stored`], [`StoredPullOff`], [`pull_off`],
//! [`store`]. May use: its parent `exact` (`resolve`'s follow and
//! escalation), `error`.

#[cfg(feature = "cli")]
use super::resolve::{default_tries, pull_off_followed_in_arclength_visiting, pull_off_on};
use super::{Contour, Exact, ExactState, Gap, Route, Truncation};
use crate::error::{Error, Result};

/// The ρ below which the pull-off is followed from the stored ones: the
/// conformal form's escalation resolves the pull-off directly down to
/// here (docs/accuracy.md's row ρ = 0.3: N = 80).
pub(crate) const TOP: f64 = 0.3;

/// How far down in ρ [`store`] follows the pull-off (it stops where the
/// follow stops converging, at ρ = 0.0141 with 320 modes).
#[cfg(feature = "cli")]
const FLOOR: f64 = 0.01;

/// The stored pull-offs, as in `solver/data/exact_pull_offs.json`.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub(crate) struct Stored {
    /// How the file was made.
    pub generated_by: String,
    /// The pull-offs, ρ falling, the first at [`TOP`].
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
}

impl StoredPullOff {
    #[cfg(feature = "cli")]
    fn of(st: &ExactState) -> StoredPullOff {
        StoredPullOff {
            rho: st.rho,
            force_bar: st.force_bar,
            a_bar: st.a_bar,
            s: st.s,
            delta_bar: st.delta_bar,
            bc_error: st.bc_error,
            truncation: st.truncation,
            contour: st.contour.clone(),
        }
    }

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

/// The file compiled in.
const FILE: &str = include_str!("../../data/exact_pull_offs.json");

/// The stored pull-offs, read once; `None` where the file does not parse.
pub(crate) fn stored() -> Option<&'static Stored> {
    static READ: std::sync::OnceLock<Option<Stored>> = std::sync::OnceLock::new();
    READ.get_or_init(|| serde_json::from_str(FILE).ok())
        .as_ref()
}

/// The pull-off at `rho` followed in ρ from the stored pull-off nearest
/// above it; `None` (the route not taken) for another gap than the
/// cylinders', for ρ at or above [`TOP`], or where no stored start passes
/// its check. Below where the stored follow stopped, by more than the
/// follow's smallest step in ρ, and with its last pull-off already at the
/// escalation's last rung, the follow is not tried again: the store's own
/// follow, from that pull-off with the same escalation, failed at every
/// step it tried down to the smallest (a minute's work with 320 modes), so
/// the store's reason is the answer, typed ([`Error::StopsInRho`]).
pub(crate) fn pull_off(gap: Gap, rho: f64) -> Option<Result<ExactState>> {
    if gap != Gap::CYLINDERS || !(rho > 0.0 && rho < TOP) {
        return None;
    }
    let table = stored()?;
    let last_rung = super::resolve::ARCLENGTH_ESCALATION.last().copied();
    let at_last_rung = table
        .pull_offs
        .last()
        .is_some_and(|p| Some(p.truncation.modes) == last_rung);
    if at_last_rung && rho < table.reached - super::resolve::SMALLEST_RHO_STEP {
        return Some(Err(Error::StopsInRho {
            reached: table.reached,
            what: format!(
                "{} (as `thinjkr exact store-pull-offs` followed it, with the most modes the solver accepts; solver/data/exact_pull_offs.json)",
                table.why_stopped
            ),
        }));
    }
    let nearest = table
        .pull_offs
        .iter()
        .filter(|p| p.rho >= rho)
        .min_by(|p, q| p.rho.total_cmp(&q.rho))?;
    let start = nearest.state(gap).ok()?;
    Some(super::resolve::pull_off_followed_in_arclength(&start, rho))
}

/// What `thinjkr exact store-pull-offs` writes: the pull-off at [`TOP`]
/// (the conformal form's escalation), then every pull-off the follow in ρ
/// takes on its way down to where it stops converging (or [`FLOOR`]).
#[cfg(feature = "cli")]
pub(crate) fn store() -> Result<Stored> {
    let gap = Gap::cylinders();
    let (top, _) = pull_off_on(gap, TOP, &default_tries())?;
    let mut pull_offs = vec![StoredPullOff::of(&top)];
    let followed = pull_off_followed_in_arclength_visiting(&top, FLOOR, &mut |st| {
        pull_offs.push(StoredPullOff::of(st))
    });
    let why_stopped = match followed {
        Ok(_) => format!("reached rho = {FLOOR}"),
        Err(Error::StopsInRho { what, .. }) => what,
        Err(e) => return Err(e),
    };
    let reached = pull_offs.last().map_or(TOP, |p| p.rho);
    Ok(Stored {
        generated_by: "thinjkr exact store-pull-offs --out solver/data/exact_pull_offs.json".into(),
        pull_offs,
        reached,
        why_stopped,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let q = table
            .pull_offs
            .iter()
            .min_by(|a, b| (a.rho - 0.045).abs().total_cmp(&(b.rho - 0.045).abs()))
            .unwrap();
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
                assert!(what.starts_with(&table.why_stopped), "{what}");
                assert!(what.contains("solver/data/exact_pull_offs.json"), "{what}");
            }
            other => panic!("{:?}", other.map(|r| r.map(|st| st.rho))),
        }
    }

    /// The file parses, its pull-offs fall in ρ from [`TOP`] down to
    /// `reached`, and three of them (the first, one in the middle, the
    /// last) are rebuilt with a boundary error below 1e-9 and the F̄, ā
    /// and s stored (to 1e-9: the same contour, the same fine grid).
    #[test]
    fn the_stored_pull_offs_are_resolved_states() {
        let table = stored().expect("solver/data/exact_pull_offs.json parses");
        let p = &table.pull_offs;
        assert!(p.len() >= 10, "{} stored pull-offs", p.len());
        assert_eq!(p[0].rho, TOP);
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
    }
}
