//! The fold in ρ of the family of exact states at a fixed δ̄ or F̄: where
//! the family continued in ρ at that control turns back towards larger ρ,
//! so that no state on it lies below. With ā as the parameter (regular
//! there, where the control is not), the state at the control is a curve
//! ρ*(ā): at each ā, the state at that half-width whose control has the
//! asked value, by the secant method in ρ ([`rho_at`]); the fold is the
//! minimum of ρ*(ā), found by successive parabolas. Both states on either
//! side of it, at ρ a little above, are solved: the evidence that the
//! family turns back there, and not merely that Newton stopped.
//!
//! Owns: [`RhoFold`], [`rho_fold`]. May use: `exact`, `control`, `error`,
//! `newton` (its stop check).

use super::ladder::Ladder;
use super::{Exact, ExactState, Truncation};
use crate::control::Hold;
use crate::error::{Error, Result};
use nalgebra::DVector;
use std::cell::RefCell;

/// A fold in ρ of the family at a fixed control: the smallest ρ the
/// family reaches, at half-width `a_bar`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RhoFold {
    /// The smallest ρ of the family at the control.
    pub rho: f64,
    /// ā at the fold.
    pub a_bar: f64,
    /// ā of the two states at the control at ρ a little above the fold
    /// (0.2 % of the distance the search moved in ρ, at least 1e-4), one on
    /// either side.
    pub beside: [f64; 2],
    /// The ρ of the two states `beside`.
    pub above: f64,
    /// The truncation that resolves the state at the fold.
    pub truncation: Truncation,
}

/// The point of `memo` nearest `a`.
fn memo_at(memo: &[(f64, OnCurve)], a: f64) -> Option<OnCurve> {
    memo.iter()
        .min_by(|x, y| (x.0 - a).abs().total_cmp(&(y.0 - a).abs()))
        .map(|x| x.1.clone())
}

/// One point of ρ*(ā): the unknowns of the state at half-width `a_bar`
/// whose control has its value, and its ρ.
#[derive(Clone)]
struct OnCurve {
    rho: f64,
    u: DVector<f64>,
}

/// The control's quantity at the unknowns `u` of `ex` (δ̄, or F̄ on the
/// grid, as the state equations hold it).
fn quantity(ex: &Exact, u: &DVector<f64>, control: Hold) -> Option<f64> {
    match control {
        Hold::Delta(_) => Some(u[ex.unknown_count() - 1]),
        Hold::Force(_) => ex.modes(u).map(|(_, f)| f),
        Hold::Size(_) => None,
    }
}

/// ρ at which the state at half-width `a_bar` has the control's value: the
/// secant method in ρ, each state by Newton at fixed ā from the one before
/// (from `near` first); steps in ρ at most 0.02; converged where the
/// control's value is met to 1e-10 (relative above 1).
fn rho_at(ex: &RefCell<Exact>, control: Hold, a_bar: f64, near: &OnCurve) -> Result<OnCurve> {
    let target = control.value();
    let solve = |rho: f64, from: &DVector<f64>| -> Result<(DVector<f64>, f64)> {
        let mut ex = ex.borrow_mut();
        ex.move_to_rho(rho)?;
        let id = ex.unknown_count() - 1;
        let u = ex.newton(Hold::Size(a_bar), &ex.contour_of(from), from[id])?;
        let q = quantity(&ex, &u, control)
            .ok_or_else(|| Error::NoState("the exact system is singular there".into()))?;
        Ok((u, q - target))
    };
    let (mut u, mut g) = solve(near.rho, &near.u)?;
    let mut rho = near.rho;
    let mut before: Option<(f64, f64)> = None;
    for _ in 0..30 {
        crate::newton::check_stop()?;
        if g.abs() <= 1e-10 * target.abs().max(1.0) {
            return Ok(OnCurve { rho, u });
        }
        let step = match before {
            Some((r0, g0)) if g != g0 => (-g * (rho - r0) / (g - g0)).clamp(-0.02, 0.02),
            _ => -0.002 * g.signum(),
        };
        let next = rho + step;
        if !(next > 0.0 && next <= 1.0) {
            break;
        }
        let (u1, g1) = solve(next, &u)?;
        before = Some((rho, g));
        (u, g, rho) = (u1, g1, next);
    }
    Err(Error::NoState(format!(
        "no rho where the state at a_bar = {} has {control} (secant in rho from rho = {})",
        crate::error::rounded(a_bar),
        crate::error::rounded(near.rho)
    )))
}

/// The fold in ρ of the family at `control` near `last`, the last state a
/// continuation in ρ downwards at that control converged to: the minimum of
/// ρ*(ā) (ā within 0.5 of `last`'s), searched with the first rung of `ladder`
/// at least as fine as `last`'s truncation, and again with the next where
/// the state at the fold is not resolved (fine-grid boundary error above
/// [`super::CONVERGED`]). `None` where ρ*(ā) has no minimum there (Newton
/// stopped for another reason: a band, a failed step), or where no
/// truncation tried resolves it.
pub(crate) fn rho_fold(last: &ExactState, control: Hold, ladder: &Ladder) -> Option<RhoFold> {
    let from_last = ladder.clone().starting_at(last.truncation.modes);
    from_last.from_rung().iter().find_map(|&t| {
        let (fold, bc_error) = search(last, control, t)?;
        (bc_error <= super::CONVERGED).then_some(fold)
    })
}

/// The two sizes ā either side of the fold (ā = `a`, ρ = `r`, ρ*(ā) ≈
/// r + c (ā − a)² near it) where ρ*(ā) = `above`, by the secant method from
/// the fold outwards (`eval`: ρ*(ā)); `None` where either is not found to
/// 1e-10 on its own side.
fn beside_the_fold(
    eval: &mut dyn FnMut(f64) -> f64,
    a: f64,
    r: f64,
    c: f64,
    above: f64,
) -> Option<[f64; 2]> {
    let mut beside = [f64::NAN; 2];
    for (k, dir) in [-1.0, 1.0].into_iter().enumerate() {
        let (mut x0, mut f0) = (a, r - above);
        let mut x1 = a + dir * ((above - r) / c).sqrt();
        let mut f1 = eval(x1) - above;
        for _ in 0..30 {
            if f1.abs() <= 1e-10 {
                break;
            }
            let x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
            (x0, f0) = (x1, f1);
            x1 = x2;
            f1 = eval(x1) - above;
        }
        if f1.abs() > 1e-10 || (x1 - a) * dir <= 0.0 {
            return None;
        }
        beside[k] = x1;
    }
    Some(beside)
}

/// [`rho_fold`] with the truncation `t`, and the fine-grid boundary error
/// of the state at the fold.
fn search(last: &ExactState, control: Hold, t: Truncation) -> Option<(RhoFold, f64)> {
    let ex = Exact::on(last.gap, last.rho, t).ok()?.deferring_stability();
    let contour = if t.arclength > 0 && last.contour.c.is_empty() {
        last.contour.in_arclength(t.modes)
    } else {
        last.contour.clone()
    };
    let start = OnCurve {
        rho: last.rho,
        u: ex.unknowns_of(&contour, last.delta_bar),
    };
    let ex = RefCell::new(ex);
    let mut memo: Vec<(f64, OnCurve)> = Vec::new();
    // ρ*(ā); +∞ where no state at that ā is found (inside a band, or
    // Newton fails from the nearest point solved): never the minimum
    let mut eval = |a: f64| -> f64 {
        let near = memo_at(&memo, a).unwrap_or_else(|| start.clone());
        let Ok(p) = rho_at(&ex, control, a, &near) else {
            return f64::INFINITY;
        };
        let r = p.rho;
        memo.push((a, p));
        r
    };
    let a0 = last.a_bar;
    let mut h = 0.02;
    let (mut a, mut r) = (a0, eval(a0));
    if !r.is_finite() {
        return None;
    }
    // downhill in ρ in steps of h until a minimum is bracketed
    let (mut rl, mut rr) = (eval(a - h), eval(a + h));
    for _ in 0..25 {
        if r <= rl && r <= rr {
            break;
        }
        let dir = if rl < rr { -1.0 } else { 1.0 };
        a += dir * h;
        if (a - a0).abs() > 0.5 {
            return None;
        }
        (rl, r, rr) = if dir < 0.0 {
            (eval(a - h), rl, r)
        } else {
            (r, rr, eval(a + h))
        };
    }
    if !(r <= rl && r <= rr && rl.is_finite() && rr.is_finite()) {
        return None;
    }
    // successive parabolas through (a − h, a, a + h), h shrinking (at most
    // 12 of them: a widened step keeps h)
    for _ in 0..12 {
        if h <= 1e-3 {
            break;
        }
        let curvature = rl - 2.0 * r + rr;
        let shift = if curvature > 0.0 && curvature.is_finite() {
            (0.5 * h * (rl - rr) / curvature).clamp(-h, h)
        } else {
            0.0
        };
        a += shift;
        h *= 0.25;
        r = eval(a);
        rl = eval(a - h);
        rr = eval(a + h);
        if !(r <= rl && r <= rr) {
            // the parabola's vertex missed by more than h: widen once
            h *= 4.0;
            rl = eval(a - h);
            rr = eval(a + h);
            if !(r <= rl && r <= rr) {
                return None;
            }
        }
        if !(r.is_finite() && rl.is_finite() && rr.is_finite()) {
            return None;
        }
    }
    if h > 1e-3 || r >= last.rho {
        return None;
    }
    // ρ*(ā) ≈ r + c (ā − a)² near the fold, from the last parabola
    let c = ((rl - 2.0 * r + rr) / (2.0 * h * h)).max(1e-6);
    // the two states at the control a little above the fold
    let above = r + (0.002 * (last.rho - r)).max(1e-4);
    let beside = beside_the_fold(&mut eval, a, r, c, above)?;
    // the state at the fold, on the fine grid
    let at_fold = rho_at(
        &ex,
        control,
        a,
        &OnCurve {
            rho: r,
            u: memo_at(&memo, a)?.u,
        },
    )
    .ok()?;
    let mut exact = ex.borrow_mut();
    exact.move_to_rho(at_fold.rho).ok()?;
    let bc_error = exact.state(&at_fold.u).ok()?.bc_error;
    Some((
        RhoFold {
            rho: r,
            a_bar: a,
            beside,
            above,
            truncation: t,
        },
        bc_error,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::ladder::Ladder;
    use crate::exact::resolve::{at_with, continued_in_rho_along};
    use crate::exact::{Gap, Truncation};

    /// The near-elliptic family at F̄ = 0, continued in ρ from its state at
    /// ρ = 0.4 (80 modes) in the arclength representation (48, then 64
    /// modes of each sign) to ρ = 0.36, turns back at ρ ≈ 0.3574 (an independent
    /// exploration put it near 0.356): ρ*(ā) has its minimum there, and at
    /// ρ just above it Newton at fixed F̄ = 0 (not at fixed ā, as the
    /// search) started on either side converges to two distinct resolved
    /// states (boundary error below 1e-9 on the fine grid) that the fold
    /// joins.
    #[test]
    fn the_zero_force_family_turns_back_in_rho() {
        let start = at_with(
            Gap::cylinders(),
            0.4,
            Hold::Force(0.0),
            &Ladder::conformal(),
            &mut |_| {},
        )
        .unwrap();
        let last = continued_in_rho_along(
            &start,
            0.36,
            Hold::Force(0.0),
            &Ladder::of(vec![
                Truncation::in_arclength(48),
                Truncation::in_arclength(64),
            ]),
        )
        .unwrap();
        let ladder = Ladder::of([48, 64, 96].map(Truncation::in_arclength).to_vec());
        let fold = rho_fold(&last, Hold::Force(0.0), &ladder).expect("a fold in rho");
        assert!(
            fold.rho > 0.355 && fold.rho < 0.36,
            "the fold at rho = {}",
            fold.rho
        );
        assert!(fold.beside[0] < fold.a_bar && fold.a_bar < fold.beside[1]);
        let ex = Exact::on(last.gap, fold.above, fold.truncation).unwrap();
        let two: Vec<ExactState> = fold
            .beside
            .iter()
            .map(|&a| {
                let at_a = ex.solve_from(a, &last).unwrap();
                ex.solve_at(Hold::Force(0.0), &at_a.contour, at_a.delta_bar)
                    .unwrap()
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
}
