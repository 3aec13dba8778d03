//! Coatings thin against the contact, at first order in h/L, at any ρ: the
//! layer's pull-off as (2)'s exact pull-off plus the effect of the layer's
//! edge, where the grid solver cannot reach (issue 71).
//!
//! Within a few coating thicknesses of the contact line the thin-layer
//! equation (2) fails; there the layer is a straight edge of the real
//! kernel, and away from it (2) holds. Matching the two at first order in
//! h/L: (2)'s solution holds on a contour offset outward from the true
//! contact line by b̄, the edge's shift, and Griffith's condition on it
//! reads ∂p̄/∂ν = 1 − b̄κ̄/2 (κ̄ the contour's curvature). The energy says
//! why: the adhesion Δγ acts on the true area, the offset contour's area
//! less b̄ times its perimeter, so the edge adds a line tension Δγ·b̄ to
//! (2)'s contact. At fixed approach the force then moves by
//! ΔF̄ = ½b̄ dP̄/dδ̄ (P̄ the perimeter, along (2)'s branch), and so does the
//! pull-off, a minimum of F̄ (docs/thickness.md, "Thin coatings: the first
//! order in h/L").
//!
//! The shift is the straight edge's: with N(k̄) = C̄(k̄)/k̄² the pair's
//! compliance over its thin limit, the Wiener–Hopf factorisation of N
//! gives b̄ = (1/π)∫₀^∞ ln(1/N(k̄)) dk̄/k̄² (1.459081 h for two equal
//! incompressible coatings of thickness h). Only incompressible coatings
//! have (2) as their thin limit; the shift of others is refused.
//!
//! Owns: `edge_shift`, `approach_shift`, `FirstOrder`, `first_order_pull_off`, `first_order_at`. May use:
//! `layer` (the pair's compliance), `exact` (the exact pull-off of (2) and
//! its linearisation), `control`, `quadrature`, `error`.

use super::Layers;
use crate::control::Hold;
use crate::error::{rounded, short, Error, Result};
use crate::exact::{pull_off_resolved, Contour, Exact, ExactState};
use crate::quadrature::GaussLegendre;
use nalgebra::DVector;

/// Where the shift's integral leaves the quadrature for its expansions, in
/// k̄h (h the thicker coating): below, ln(1/N)/k̄² is a + ck̄² from its
/// values at this and twice this; above [`TOP`], N is the half-space's
/// 1/(βk̄³) (the base's share Φ is below 1e-15 beyond k̄h = 22). The shift
/// moves by 2e-8 of itself from here to 0.02 and by 1e-7 to 0.005, where
/// the cancellation in 1 − Φ ≈ (k̄h)³ begins to show (4e-6 at 0.0025).
const BOTTOM: f64 = 0.01;
/// See [`BOTTOM`] (in k̄h, h the thinner coating).
const TOP: f64 = 40.0;
/// How far from 1 the compliance over its thin limit may be at [`BOTTOM`]:
/// a pair whose N does not tend to 1 there has another thin limit than
/// (2).
const THIN_LIMIT: f64 = 1e-3;

/// The pair's compliance over its thin limit at small k̄: ln(1/N(k̄)) =
/// ak̄² + ck̄⁴ + … below `k0` = [`BOTTOM`]/h (h the thicker coating),
/// through its values at `k0` and 2`k0`; with ln(1/N) itself. Only for
/// incompressible coatings (ν = ½ each), whose thin limit is (2).
struct LowWaves<F: Fn(f64) -> f64> {
    log_inverse: F,
    k0: f64,
    a: f64,
    c: f64,
}

fn low_waves(layers: &Layers) -> Result<LowWaves<impl Fn(f64) -> f64 + '_>> {
    for (c, name) in layers.coatings().iter().zip(["nu1", "nu2"]) {
        if c.nu != 0.5 {
            return Err(Error::OutOfRange {
                name,
                value: c.nu,
                range: "{0.5}: the first order in h/L holds for incompressible coatings, whose thin limit is (2)".into(),
            });
        }
    }
    let beta = layers.beta();
    // ln(1/N) at k̄, N = (1 − Φ)/(βk̄³)
    let log_inverse = move |k: f64| -((1.0 - layers.base_share(k)) / (beta * k.powi(3))).ln();
    let k0 = BOTTOM / layers.thickest();
    let n0 = (-log_inverse(k0)).exp();
    if (n0 - 1.0).abs() > THIN_LIMIT {
        return Err(Error::Unresolved {
            what: format!(
                "the edge's shift: the pair's compliance is {} times its thin limit at kh = {BOTTOM}, not near 1",
                rounded(n0)
            ),
            residual: (n0 - 1.0).abs(),
        });
    }
    // f = ln(1/N)/k̄² ≈ a + ck̄² through f(k₀) and f(2k₀)
    let (f1, f2) = (
        log_inverse(k0) / (k0 * k0),
        log_inverse(2.0 * k0) / (4.0 * k0 * k0),
    );
    let c = (f2 - f1) / (3.0 * k0 * k0);
    Ok(LowWaves {
        log_inverse,
        k0,
        a: f1 - c * k0 * k0,
        c,
    })
}

/// The edge's shift b̄ of `layers` in the units (17): the contact line lies
/// b̄ inside the contour on which (2)'s solution holds. Only for
/// incompressible coatings (ν = ½ each).
pub(crate) fn edge_shift(layers: &Layers) -> Result<f64> {
    let LowWaves {
        log_inverse,
        k0,
        a,
        c,
    } = low_waves(layers)?;
    let beta = layers.beta();
    // [0, k₀]: ∫(a + ck̄²)
    let mut sum = a * k0 + c * k0.powi(3) / 3.0;
    // [k₀, K] in ln k̄, panels 0.25 wide
    let top = TOP / layers.thinnest();
    let (lo, hi) = (k0.ln(), top.ln());
    let panels = ((hi - lo) / 0.25).ceil() as usize;
    for (t, w) in GaussLegendre::new(16).composite(lo, hi, panels) {
        let k = t.exp();
        sum += w * log_inverse(k) / k;
    }
    // [K, ∞): ∫ ln(βk̄³)/k̄² dk̄ = (ln(βK³) + 3)/K
    sum += ((beta * top.powi(3)).ln() + 3.0) / top;
    Ok(sum / std::f64::consts::PI)
}

/// The interior's approach shift of `layers` at `rho`, units (17): away
/// from the edge the layer's contact is (2)'s at the approach δ̄ + Δδ̄,
/// Δδ̄ = a(1 + 1/ρ)/2 with N(k̄) = 1 − ak̄² + … (a = 1.800008 (h/L)² for
/// two equal incompressible coatings), of second order in h/L. With that
/// N the layer's surface displacement is (2)'s plus a∇̄² of it, a constant
/// inside the contact, whose gap X²/2 + Y²/(2ρ) gives the form 1 + 1/ρ;
/// the factor ½ is the edge's: the even term −ak̄² of ln N is shared
/// equally by the Wiener–Hopf factors N₊ and N₋, and only 1/N₋ acts on
/// the load (an argument; measured on the circle, at ρ = 0.8 against the
/// sharp edge and on the line contact, `layer::grid::edge`;
/// docs/thickness.md, "Why one half"). It moves no
/// force minimum (F̄ is stationary in δ̄ there) and no state at a given
/// force.
pub(crate) fn approach_shift(layers: &Layers, rho: f64) -> Result<f64> {
    Ok(0.5 * low_waves(layers)?.a * (1.0 + 1.0 / rho))
}

/// The layer's pull-off at first order in the edge's shift at one ρ.
#[derive(Clone, Debug)]
pub(crate) struct FirstOrder {
    /// (2)'s exact pull-off under load control.
    pub(crate) thin_limit: ExactState,
    /// ½ dP̄/dδ̄ along (2)'s branch at it: the pull-off force's change per
    /// unit of the edge's shift.
    pub(crate) force_per_shift: f64,
    /// The edge's shift b̄.
    pub(crate) shift: f64,
}

/// The layer's pull-off under load control at ρ at first order in h/L:
/// (2)'s exact pull-off and the force's change per unit shift, from the
/// linear response of (2)'s state to Griffith's condition
/// ∂p̄/∂ν = 1 − κ̄/2 per unit b̄ at fixed ā (at the pull-off, a minimum of
/// F̄, the same as at fixed δ̄ or along any parameter of the branch).
pub(crate) fn first_order_pull_off(layers: &Layers, rho: f64) -> Result<FirstOrder> {
    let (thin_limit, _) = pull_off_resolved(rho)?;
    first_order_at(layers, thin_limit)
}

/// [`first_order_pull_off`] at (2)'s exact pull-off `thin_limit`, found
/// already.
pub(crate) fn first_order_at(layers: &Layers, thin_limit: ExactState) -> Result<FirstOrder> {
    let shift = edge_shift(layers)?;
    let force_per_shift = force_per_shift(&thin_limit)?;
    Ok(FirstOrder {
        thin_limit,
        force_per_shift,
        shift,
    })
}

impl FirstOrder {
    /// The pull-off force's move at first order, b̄·½dP̄/dδ̄ (for equal
    /// coatings of thinness 1, dF̄/d(h/L)).
    pub(crate) fn force_moved(&self) -> f64 {
        self.shift * self.force_per_shift
    }

    /// [`FirstOrder::force_moved`] as a share of −F̄₍₂₎: (2)'s relative
    /// error at first order.
    pub(crate) fn share(&self) -> f64 {
        -self.force_moved() / self.thin_limit.force_bar
    }

    /// The factor on the coatings' thicknesses at which (2)'s pull-off is
    /// off the layer's by `error` at first order, (2)'s relative error
    /// −F̄₍₂₎/F̄ − 1 (for equal coatings of thinness 1, the h/L).
    pub(crate) fn thickness_factor_for_error(&self, error: f64) -> f64 {
        error / ((1.0 + error) * self.share())
    }
}

/// ∂F̄/∂b̄ at fixed ā of (2)'s state `st` under ∂p̄/∂ν = 1 − b̄κ̄/2: one
/// solve with the Jacobian of its discrete equations.
pub(crate) fn force_per_shift(st: &ExactState) -> Result<f64> {
    let ex = Exact::of_state(st)?;
    let u = ex.unknowns(st);
    let singular = || Error::Unresolved {
        what: format!(
            "the first order in h/L at rho = {}: the exact state's Jacobian is singular",
            rounded(st.rho)
        ),
        residual: f64::NAN,
    };
    let lin = ex.linear(&u).ok_or_else(singular)?;
    let jacobian = ex
        .held_jacobian(&u, Hold::Size(st.a_bar))
        .ok_or_else(singular)?;
    let contour = ex.contour_of(&u);
    // the residual's modes of ∂p̄/∂ν − 1 + b̄κ̄/2: J du = −∂R/∂b̄, the modes of
    // −κ̄/2 (`cos_modes_of` takes 1 off)
    let half_curvature: Vec<f64> = ex
        .grid
        .theta
        .iter()
        .map(|&theta| 1.0 - 0.5 * curvature(&contour, theta))
        .collect();
    let modes = ex.cos_modes_of(&half_curvature);
    let mut rhs = DVector::zeros(u.len());
    rhs.rows_mut(1, modes.len()).copy_from(&modes);
    let du = jacobian.lu().solve(&rhs).ok_or_else(singular)?;
    let slope = lin.d_force.dot(&du);
    if !slope.is_finite() {
        return Err(Error::Unresolved {
            what: format!(
                "the first order in h/L at rho = {}: the force's slope is {}",
                rounded(st.rho),
                short(slope)
            ),
            residual: f64::NAN,
        });
    }
    Ok(slope)
}

/// The curvature of `c` at θ (positive where convex).
pub(crate) fn curvature(c: &Contour, theta: f64) -> f64 {
    let [_, d1, d2] = c.at(theta);
    (d2 * d1.conj()).im / d1.norm().powi(3)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::layer::Route;
    use std::f64::consts::PI;

    /// The perimeter of `c` by the trapezoid rule on 4096 points
    /// (spectrally accurate for the periodic |z′|).
    fn perimeter(c: &Contour) -> f64 {
        let h = std::f64::consts::TAU / 4096.0;
        (0..4096).map(|i| c.at(i as f64 * h)[1].norm()).sum::<f64>() * h
    }

    /// The value at 0 of the quadratic through three (x, y), x halving.
    fn richardson(points: [(f64, f64); 3]) -> f64 {
        let [(_, y0), (_, y1), (_, y2)] = points;
        let (r1, r2) = (2.0 * y1 - y0, 2.0 * y2 - y1);
        (4.0 * r2 - r1) / 3.0
    }

    #[test]
    fn the_edge_shift_scales_with_the_coatings_and_refuses_compressible_ones() {
        // equal incompressible coatings: b̄/h is one number at every
        // thinness (its value is held against the straight line contact in
        // `grid::edge` and against the circle below)
        let per_h = |thin: f64| edge_shift(&Layers::equal(thin, 0.5).unwrap()).unwrap() / thin;
        let first = per_h(0.01);
        for thin in [0.3, 10.0] {
            assert!(
                (per_h(thin) / first - 1.0).abs() < 1e-9,
                "h/L {thin}: {} against {first}",
                per_h(thin)
            );
        }
        // unequal coatings: between the two coatings' own shifts
        let unequal = Layers::new(
            crate::layer::Coating {
                thinness: 0.1,
                shear_modulus: 1.0,
                nu: 0.5,
            },
            crate::layer::Coating {
                thinness: 0.2,
                shear_modulus: 1.0,
                nu: 0.5,
            },
        )
        .unwrap();
        let shift = edge_shift(&unequal).unwrap();
        assert!(shift > 0.1 * first && shift < 0.2 * first, "{shift}");
        let err = edge_shift(&Layers::equal(0.1, 0.45).unwrap()).unwrap_err();
        assert!(
            matches!(err, Error::OutOfRange { name: "nu1", .. }),
            "{err}"
        );
    }

    /// At fixed contact radius ā on the circle (ρ = 1) the layer's δ̄ and F̄
    /// depart from (2)'s, δ̄ = ā²/4 − 2/ā and F̄ = π(ā⁶ − 24ā³)/96, as the
    /// line tension says, with no constant fitted: (2) on the circle of
    /// radius ā + b̄ with ∂p̄/∂ν = 1 − b̄/2(ā + b̄) gives
    /// ∂δ̄/∂b̄ = δ̄′ + 1/ā² and ∂F̄/∂b̄ = F̄′ + πā²/8 (primes in ā). The
    /// layer's slopes are extrapolated from h/L = 0.02, 0.01, 0.005.
    #[test]
    fn the_layer_s_first_order_is_a_line_tension_on_the_circle() {
        let thins = [0.02, 0.01, 0.005];
        let shifts: Vec<f64> = thins
            .iter()
            .map(|&t| edge_shift(&Layers::equal(t, 0.5).unwrap()).unwrap())
            .collect();
        let pairs: Vec<Layers> = thins
            .iter()
            .map(|&t| Layers::equal(t, 0.5).unwrap())
            .collect();
        for a in [1.5f64, 12f64.cbrt(), 3.0, 4.0] {
            let (delta0, force0) = (
                a * a / 4.0 - 2.0 / a,
                PI * (a.powi(6) - 24.0 * a.powi(3)) / 96.0,
            );
            let slopes: Vec<(f64, f64)> = pairs
                .iter()
                .zip(&shifts)
                .map(|(l, b)| {
                    let st = l.at_radius(a, Route::Griffith).unwrap();
                    ((st.delta_bar - delta0) / b, (st.force_bar - force0) / b)
                })
                .collect();
            let at = |f: fn(&(f64, f64)) -> f64| {
                richardson([
                    (thins[0], f(&slopes[0])),
                    (thins[1], f(&slopes[1])),
                    (thins[2], f(&slopes[2])),
                ])
            };
            let (delta_slope, force_slope) = (at(|s| s.0), at(|s| s.1));
            let delta_line = a / 2.0 + 2.0 / (a * a) + 1.0 / (a * a);
            let force_line = PI * (a.powi(5) - 12.0 * a * a) / 16.0 + PI * a * a / 8.0;
            assert!(
                (delta_slope / delta_line - 1.0).abs() < 1e-4,
                "a {a}: d delta/db {delta_slope} against {delta_line}"
            );
            assert!(
                (force_slope - force_line).abs() < 1e-4 * force_line.abs().max(1.0),
                "a {a}: dF/db {force_slope} against {force_line}"
            );
        }
    }

    /// At ρ = 1 the pull-off's first order is (2)'s ½dP̄/dδ̄ = πā²/8 at
    /// ā³ = 12 times the shift, and the axisymmetric layer's pull-offs
    /// approach (2)'s −3π/2 with that slope (extrapolated from h/L = 0.02,
    /// 0.01 and 0.005).
    #[test]
    fn the_circle_s_pull_off_moves_as_the_axisymmetric_layer_s() {
        let layers = Layers::equal(0.01, 0.5).unwrap();
        let first = first_order_pull_off(&layers, 1.0).unwrap();
        let circle = PI * 12f64.powf(2.0 / 3.0) / 8.0;
        // (the exact pull-off's radius is a root found to about 1e-8 of itself)
        assert!(
            (first.force_per_shift / circle - 1.0).abs() < 1e-7,
            "{} against {circle}",
            first.force_per_shift
        );
        let thins = [0.02, 0.01, 0.005];
        let slopes: Vec<(f64, f64)> = thins
            .iter()
            .map(|&t| {
                let l = Layers::equal(t, 0.5).unwrap();
                let pull = l.pull_off_under(Route::Griffith, true).unwrap();
                (t, (pull.force_bar + 1.5 * PI) / edge_shift(&l).unwrap())
            })
            .collect();
        let slope = richardson([slopes[0], slopes[1], slopes[2]]);
        assert!(
            (slope / circle - 1.0).abs() < 1e-4,
            "{slope} against {circle}"
        );
    }

    /// At ρ < 1 the linear response (Griffith's condition perturbed at fixed
    /// ā) and the energy (½dP̄/dδ̄ from two exact states at δ̄ ± 1e-5, by
    /// Newton's method at held δ̄) give the same first order.
    #[test]
    fn the_response_and_the_energy_give_the_same_first_order() {
        for rho in [0.8, 0.5, 0.2174428320539990, 0.07179676972449082] {
            let (st, _) = pull_off_resolved(rho).unwrap();
            let response = force_per_shift(&st).unwrap();
            let ex = Exact::of_state(&st).unwrap();
            let at = |d: f64| {
                let delta = st.delta_bar + d;
                ex.solve_at(Hold::Delta(delta), &st.contour, delta).unwrap()
            };
            let (up, down) = (at(1e-5), at(-1e-5));
            let energy = 0.5 * (perimeter(&up.contour) - perimeter(&down.contour))
                / (up.delta_bar - down.delta_bar);
            assert!(
                (energy / response - 1.0).abs() < 1e-6,
                "rho {rho}: {energy} against {response}"
            );
        }
    }
}
