//! The study that writes the stored pull-offs (`thinjkr exact
//! store-pull-offs`, solver/data/exact_pull_offs.json): the pull-off at
//! ρ = 0.3 and every pull-off the follow in ρ takes on its way down. The
//! table, and the route that starts from it, are the engine's
//! (`exact::stored`).
//!
//! Owns: [`store`]. May use: `exact` (its pull-off, its follow in ρ, the
//! table's shape), `error`.

use crate::error::{Error, Result};
use crate::exact::ladder::Ladder;
use crate::exact::stored::{in_plain_gauge, Stored, StoredPullOff, STORED_FROM_RHO};
use crate::exact::{pull_off_followed_in_arclength_visiting, pull_off_on, Exact, ExactState, Gap};

/// How far down in ρ [`store`] follows the pull-off (it stops where the
/// follow stops converging, at ρ = 0.0141 with 320 modes).
const FLOOR: f64 = 0.01;

/// What `thinjkr exact store-pull-offs` writes: the pull-off at [`STORED_FROM_RHO`]
/// (the conformal form's escalation), then every pull-off the follow in ρ
/// takes on its way down to where it stops converging (or [`FLOOR`]).
pub(crate) fn store() -> Result<Stored> {
    let gap = Gap::cylinders();
    let (top, _) = pull_off_on(gap, STORED_FROM_RHO, &Ladder::conformal())?;
    let mut pull_offs = vec![record(&top, None)?];
    let mut recorded = Ok(());
    let followed = pull_off_followed_in_arclength_visiting(&top, FLOOR, &mut |st| {
        if recorded.is_ok() {
            match record(st, pull_offs.last()) {
                Ok(p) => pull_offs.push(p),
                Err(e) => recorded = Err(e),
            }
        }
    });
    recorded?;
    let why_stopped = match followed {
        Ok(_) => format!("reached rho = {FLOOR}"),
        Err(Error::StopsInRho { what, .. }) => what,
        Err(e) => return Err(e),
    };
    let reached = pull_offs.last().map_or(STORED_FROM_RHO, |p| p.rho);
    Ok(Stored {
        generated_by: "thinjkr exact store-pull-offs --out solver/data/exact_pull_offs.json".into(),
        pull_offs,
        reached,
        why_stopped,
    })
}

/// The record of the pull-off `st`, stored after `before` (`None` for
/// the first), with its curvature in ā computed on its own truncation
/// where it is in the plain gauge.
fn record(st: &ExactState, before: Option<&StoredPullOff>) -> Result<StoredPullOff> {
    let narrow_groove = st.contour.narrow_groove().is_some();
    let plain = in_plain_gauge(
        st.truncation,
        narrow_groove,
        before.is_some_and(|b| b.narrow_groove),
    );
    let force_curvature = if plain {
        let ex = Exact::on(st.gap, st.rho, st.truncation)?.deferring_stability();
        ex.force_curvature_in_size(&ex.unknowns(st))
    } else {
        None
    };
    Ok(StoredPullOff {
        rho: st.rho,
        force_bar: st.force_bar,
        a_bar: st.a_bar,
        s: st.s,
        delta_bar: st.delta_bar,
        bc_error: st.bc_error,
        truncation: st.truncation,
        contour: st.contour.clone(),
        force_curvature,
        narrow_groove,
    })
}
