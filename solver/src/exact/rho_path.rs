//! The family of exact states at a fixed δ̄ or F̄ followed in ρ by
//! pseudo-arclength continuation in (u, ρ) together: where the plain
//! continuation in ρ (Newton at each ρ from the state before) stops because
//! the family folds in ā close by (a band's edge), the path in (u, ρ) is
//! regular and steps around it; a fold in ρ itself shows as ρ turning back,
//! and is located there.
//! The equations are the state equations at the control
//! ([`Exact::equations`]); their derivative in u is the discrete one
//! ([`Exact::held_jacobian`]), in ρ a central difference (the gap is the
//! only thing that depends on ρ).
//!
//! Owns: [`follow`], [`Followed`]. May use: `exact`, `control`, `error`,
//! `newton` (its stop check).

use super::{Exact, ExactState, RESIDUAL_TOLERANCE};
use crate::control::Hold;
use crate::error::{Error, Result};
use nalgebra::{DMatrix, DVector};

/// How a path in (u, ρ) ended.
pub(crate) enum Followed {
    /// It reached the ρ asked for: the state there.
    Reached(Box<ExactState>),
    /// ρ turned back (a fold in ρ) above the ρ asked for: `fold`, the
    /// smallest ρ of the path between its last two points, where dρ/dσ
    /// (linear in the arclength σ between them) vanishes; ā at the path's
    /// lowest point, and its fine-grid boundary error (`None` where that
    /// system is singular).
    TurnedBack {
        a_bar: f64,
        fold: f64,
        // read by `studies::reach`, which the command line runs
        #[cfg_attr(not(feature = "cli"), allow(dead_code))]
        bc_error: Option<f64>,
    },
}

/// The path's unknowns v = (u, ρ) and its equations R(u; ρ) at `control`.
struct Path {
    ex: std::cell::RefCell<Exact>,
    control: Hold,
}

impl Path {
    fn residuals(&self, v: &DVector<f64>) -> Option<DVector<f64>> {
        let n = v.len() - 1;
        let mut ex = self.ex.borrow_mut();
        ex.move_to_rho(v[n]).ok()?;
        ex.equations(&v.rows(0, n).into_owned(), self.control)
            .map(|(r, _)| r)
    }

    /// [∂R/∂u | ∂R/∂ρ], n × (n + 1).
    fn jacobian(&self, v: &DVector<f64>) -> Option<DMatrix<f64>> {
        let n = v.len() - 1;
        let rho = v[n];
        let u = v.rows(0, n).into_owned();
        let ju = {
            let mut ex = self.ex.borrow_mut();
            ex.move_to_rho(rho).ok()?;
            ex.held_jacobian(&u, self.control)?
        };
        let h = 1e-6;
        let mut vp = v.clone();
        vp[n] = rho + h;
        let rp = self.residuals(&vp)?;
        vp[n] = rho - h;
        let rm = self.residuals(&vp)?;
        let mut j = DMatrix::zeros(n, n + 1);
        j.columns_mut(0, n).copy_from(&ju);
        j.column_mut(n).copy_from(&((rp - rm) / (2.0 * h)));
        Some(j)
    }

    /// The unit tangent of the path at v, oriented along `before`.
    fn tangent(&self, j: &DMatrix<f64>, before: &DVector<f64>) -> Option<DVector<f64>> {
        let n = j.nrows();
        let mut m = DMatrix::zeros(n + 1, n + 1);
        m.rows_mut(0, n).copy_from(j);
        m.row_mut(n).copy_from(&before.transpose());
        let mut e = DVector::zeros(n + 1);
        e[n] = 1.0;
        let t = m.lu().solve(&e)?;
        let t = t.normalize();
        Some(if t.dot(before) < 0.0 { -t } else { t })
    }

    /// Newton on [R(v); tᵀ(v − v_p)] = 0 from the prediction v_p.
    fn correct(&self, vp: &DVector<f64>, t: &DVector<f64>) -> Option<DVector<f64>> {
        let n = vp.len() - 1;
        let mut v = vp.clone();
        for _ in 0..8 {
            let r = self.residuals(&v)?;
            if r.amax() < RESIDUAL_TOLERANCE {
                return Some(v);
            }
            let j = self.jacobian(&v)?;
            let mut m = DMatrix::zeros(n + 1, n + 1);
            m.rows_mut(0, n).copy_from(&j);
            m.row_mut(n).copy_from(&t.transpose());
            let mut g = DVector::zeros(n + 1);
            g.rows_mut(0, n).copy_from(&r);
            g[n] = t.dot(&(&v - vp));
            let dv = m.lu().solve(&g)?;
            v -= dv;
            if !(v.iter().all(|x| x.is_finite()) && v[n] > 0.0 && v[n] <= 1.0) {
                return None;
            }
        }
        let r = self.residuals(&v)?;
        (r.amax() < RESIDUAL_TOLERANCE).then_some(v)
    }
}

/// The path's step in (shape, ρ) at which [`follow`] stops refining a
/// fold it locates: the fold's ρ is then the path's smallest between its
/// last two points, off by about this squared times dρ/dσ's slope.
const FOLD_STEP: f64 = 1e-3;

/// The farthest the corrector of a step of [`follow`] locating a fold
/// may move from the prediction, relative to the step: at ā = 4.18 (128
/// modes) the correctors of the path from the circle moved at most 0.14
/// times the step, except one that moved 7.3 times and left the path
/// near its fold at ρ ≈ 0.324 for another branch (which turned back at
/// 0.1423, with a boundary error of 4e-5 there; the sizes 4.179 and 4.181
/// turn back at 0.3218 and 0.3267).
const FARTHEST_CORRECTION: f64 = 0.25;

/// The family at `control` followed in ρ from `start` (a converged state of
/// its truncation at a larger ρ) down to `rho`: pseudo-arclength steps in
/// (u, ρ) of at most 0.05 (halved where the corrector fails, down to
/// 1e-5; at most 400). [`Followed::TurnedBack`] where ρ turns back above
/// `rho`: the path then steps again from its point before the turn with an
/// eighth of the step, until the step is below [`FOLD_STEP`], so that its
/// `fold` is located; a step whose corrector moves farther than
/// [`FARTHEST_CORRECTION`] times the step is halved (below a step of 1e-5
/// the path stops with an error rather than take it).
/// [`Followed::Reached`] with the state at `rho` (Newton at the control
/// there from the path's last point beyond it). An error where a step
/// fails. At ρ = 0.5 and 0.4 the sizes of the band edges that
/// [`super::bands`] located by traces in ā turn back at ρ within 1e-6 of
/// it (`studies::reach`'s tests); at F̄ = 0 from ρ = 0.3 the fold is the
/// minimum of ρ over ā along the family to 6 digits, 0.178691 (which a
/// search of that minimum by successive parabolas, `exact::rho_fold`
/// until 2026-12-05, gave too).
pub(crate) fn follow(start: &ExactState, rho: f64, control: Hold) -> Result<Followed> {
    let ex = Exact::on(start.gap, start.rho, start.truncation)?.deferring_stability();
    let u0 = ex.unknowns(start);
    let n = u0.len();
    let mut v = DVector::zeros(n + 1);
    v.rows_mut(0, n).copy_from(&u0);
    v[n] = start.rho;
    let path = Path {
        ex: std::cell::RefCell::new(ex),
        control,
    };
    let failed = |at: &DVector<f64>, why: &str| {
        Error::NoState(format!(
            "the path in (shape, rho) at {control} from rho = {} stopped at rho = {}: {why}",
            crate::error::rounded(start.rho),
            crate::error::rounded(at[n])
        ))
    };
    // the first tangent: towards smaller ρ
    let mut down = DVector::zeros(n + 1);
    down[n] = -1.0;
    let j = path
        .jacobian(&v)
        .ok_or_else(|| failed(&v, "singular system"))?;
    let mut t = path
        .tangent(&j, &down)
        .ok_or_else(|| failed(&v, "no tangent"))?;
    let mut ds: f64 = 0.01;
    let mut refining = false;
    let mut lowest = (v[n], start.a_bar);
    let mut lowest_point = v.clone();
    for _ in 0..400 {
        crate::newton::check_stop()?;
        let vp = &v + &t * ds;
        let Some(next) = path.correct(&vp, &t) else {
            if ds < 1e-5 {
                return Err(failed(&v, "the corrector fails with steps down to 1e-5"));
            }
            ds *= 0.5;
            continue;
        };
        let j = path
            .jacobian(&next)
            .ok_or_else(|| failed(&next, "singular system"))?;
        let t_next = path
            .tangent(&j, &t)
            .ok_or_else(|| failed(&next, "no tangent"))?;
        // a corrector that moved far from the prediction may have jumped to
        // another branch: the step is halved, and below 1e-5 the path
        // stops rather than take the jump
        if (&next - &vp).norm() > FARTHEST_CORRECTION * ds {
            if ds < 1e-5 {
                return Err(failed(
                    &v,
                    "the corrector leaves the path (it moves farther than a quarter of the step) with steps down to 1e-5",
                ));
            }
            ds *= 0.5;
            continue;
        }
        if next[n] < lowest.0 {
            let a = {
                let ex = path.ex.borrow();
                ex.contour_of(&next.rows(0, n).into_owned()).a_bar()
            };
            lowest = (next[n], a);
            lowest_point = next.clone();
        }
        if next[n] <= rho {
            // the state at `rho` itself, from the point beyond it
            let mut ex = path.ex.borrow_mut();
            ex.move_to_rho(rho)?;
            let u = next.rows(0, n).into_owned();
            let id = n - 1;
            let solved = ex.newton(control, &ex.contour_of(&u), u[id])?;
            return Ok(Followed::Reached(Box::new(ex.state(&solved)?)));
        }
        // ρ going up again after it went down: a fold in ρ
        if t[n] < 0.0 && t_next[n] > 0.0 {
            let h = (&next - &v).norm();
            if h > FOLD_STEP {
                // again from v, in finer steps that do not grow
                refining = true;
                ds = h / 8.0;
                continue;
            }
            let bc_error = {
                let mut ex = path.ex.borrow_mut();
                ex.move_to_rho(lowest.0)?;
                ex.fine_boundary_error(&lowest_point.rows(0, n).into_owned())
            };
            // dρ/dσ = t[n] at v and t_next[n] at next, σ = h apart
            let (d0, d1) = (t[n], t_next[n]);
            let at = -d0 * h / (d1 - d0);
            let fold = (v[n] + d0 * at + (d1 - d0) * at * at / (2.0 * h)).min(lowest.0);
            return Ok(Followed::TurnedBack {
                a_bar: lowest.1,
                fold,
                bc_error,
            });
        }
        v = next;
        t = t_next;
        if !refining {
            ds = (ds * 1.3).min(0.05);
        }
    }
    Err(failed(&v, "400 steps without reaching it"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::ladder::Ladder;
    use crate::exact::resolve::{at_with, continued_in_rho_along};
    use crate::exact::{Gap, Truncation};

    /// The state at `control` at ρ = 0.4 (the conformal ladder), continued
    /// in ρ to `to` in the arclength representation with `modes` of each
    /// sign.
    fn continued_from_0_4(control: Hold, to: f64, modes: &[usize]) -> ExactState {
        let start = at_with(
            Gap::cylinders(),
            0.4,
            control,
            &Ladder::conformal(),
            &mut |_| {},
        )
        .unwrap();
        let ladder = Ladder::of(modes.iter().map(|&m| Truncation::in_arclength(m)).collect());
        continued_in_rho_along(&start, to, control, &ladder).unwrap()
    }

    /// The near-elliptic family at F̄ = 0, continued in ρ from its state at
    /// ρ = 0.4 (80 modes) in the arclength representation (48, then 64
    /// modes of each sign) to ρ = 0.36, turns back at ρ ≈ 0.3574 (an
    /// independent exploration put it near 0.356; the minimum of ρ over ā
    /// by successive parabolas, `exact::rho_fold` until 2026-12-05, at
    /// 0.357419): the path locates the fold there, and at ρ just above it
    /// Newton at fixed F̄ = 0 started from the path's states on either
    /// side (at fixed ā) converges to two distinct resolved states
    /// (boundary error below 1e-9 on the fine grid) that the fold joins.
    #[test]
    fn the_zero_force_family_turns_back_in_rho() {
        let zero = Hold::Force(0.0);
        let last = continued_from_0_4(zero, 0.36, &[48, 64]);
        let Followed::TurnedBack { fold, a_bar, .. } = follow(&last, 0.3, zero).unwrap() else {
            panic!("the family at zero force reaches rho = 0.3");
        };
        assert!((fold - 0.357419).abs() < 1e-6, "the fold at rho = {fold}");
        let above = fold + 1e-4;
        // (96 modes of each sign resolve the states there; 64 leave 1e-8)
        let ex = Exact::on(last.gap, above, Truncation::in_arclength(96)).unwrap();
        let two: Vec<ExactState> = [a_bar - 0.005, a_bar + 0.005]
            .iter()
            .map(|&a| {
                let at_a = ex.solve_from(a, &last).unwrap();
                ex.solve_at(zero, &at_a.contour, at_a.delta_bar).unwrap()
            })
            .collect();
        for st in &two {
            assert!(st.bc_error <= crate::exact::CONVERGED, "{}", st.bc_error);
            // F̄ on the fine grid; Newton holds it on the coarse one
            // (measured: 1e-8, the series' resolution at bc 1e-9)
            assert!(st.force_bar.abs() <= 1e-7, "{}", st.force_bar);
        }
        assert!(
            two[1].a_bar - two[0].a_bar > 1e-3,
            "{} and {}",
            two[0].a_bar,
            two[1].a_bar
        );
    }

    /// At F̄ = 10 the near-elliptic family continued from ρ = 0.4 (56
    /// modes, then 48 to 96 of each sign in the arclength representation)
    /// to ρ = 0.3235 is followed on in (shape, ρ) and turns back between
    /// ρ = 0.3222 and 0.3228 (measured: the located fold 0.322343; the
    /// path's lowest step, which this test read until 2026-12-05, 0.322471;
    /// from the state at ρ = 0.4 itself, 0.322687, and the plain
    /// continuation's last state is at
    /// 0.322422: folds of neighbouring arms of an imperfect bifurcation,
    /// docs/exact.md); a second route, Newton at F̄ = 10 and ρ = 0.3215 from
    /// that state (the plain continuation's step), finds no state.
    #[test]
    fn the_force_10_family_turns_back_in_rho() {
        let control = Hold::Force(10.0);
        let last = continued_from_0_4(control, 0.3235, &[48, 64, 96]);
        match follow(&last, 0.3, control).unwrap() {
            Followed::TurnedBack { fold: rho, .. } => {
                assert!(rho > 0.3222 && rho < 0.3228, "turned back at rho = {rho}")
            }
            Followed::Reached(st) => panic!("reached rho = 0.3 at a = {}", st.a_bar),
        }
        let below = Exact::on(last.gap, 0.3215, last.truncation).unwrap();
        assert!(below
            .solve_at(control, &last.contour, last.delta_bar)
            .is_err());
    }
}
