//! The straight adhesive edge on the pair of coatings (issue 71, item 3):
//! the line contact of a rigid cylinder, the gap X̄²/2 uniform in Y, with
//! JKR's sharp edges at X̄ = ±ā, and the change of its stress-intensity
//! factor when one edge undulates as A cos(k̄Y), from the real kernel.
//!
//! The pressure is p = Σ cₙ Tₙ(X̄/ā)/√(1 − X̄²/ā²) (Chebyshev's polynomials,
//! the square-root edges built in), whose Fourier transforms are
//! āπ(−i)ⁿJₙ(qā); Galerkin's method with the same functions makes the
//! matrix ā²π iᵐ⁻ⁿ ∫₀^∞ C(q) Jₘ(qā)Jₙ(qā) dq (orders of one parity), C the
//! pair's compliance (1 − Φ)/(βq) at k̄ = 0 and at q̄ = √(q² + k̄²) for the
//! mode k̄. The half-space's 1/(βq) is integrated in closed form,
//! ∫₀^∞ Jₙ²/x dx = 1/2n, the rest by Gauss–Legendre panels. Griffith's
//! condition K = √(2β) (energy release rate K²/4β = Δγ̄) sets δ̄.
//!
//! The undulation: to first order the pressure is the straight solution
//! with its right edge at ā + A cos k̄Y, p₀(X̄; b), plus a correction q(X̄)
//! cos k̄Y with C_k̄ ∗ q = −(C_k̄ − C₀) ∗ ∂p₀/∂b on the contact (the
//! difference of the kernels makes the hypersingular ∂p₀/∂b integrable);
//! then δK/A = ∂K/∂b + K[q]. The edge is stable to the mode when δK/A > 0
//! (advancing the edge raises the tension that pulls it back); the least
//! δK/A over k̄ marks the most unstable undulation. On a half-space it is
//! Rice's δK/A = |k̄|K/2 for k̄ā ≫ 1.
//!
//! The kernel's own stiffness at mode k̄, βk̄/(1 − Φ(k̄)), is least at
//! `stiffness_minimum`: the wavelength at which a uniformly stretched
//! confined film first gives way (Shenoy and Sharma, PRL 86:119, 2001:
//! kh = 2.12 for an incompressible film, about 3h).
//!
//! Owns: `LineContact`, `LineState`, `stiffness_minimum`. May use: `layer`
//! (the pair's Φ and β), `model` (Brent's minimum), `quadrature`, `error`,
//! and the grid's `bessel0`.

use super::bessel0::{j0, orders};
use crate::error::{Error, Result};
use crate::layer::Layers;
use crate::model::brent_minimum;
use crate::quadrature::GaussLegendre;
use nalgebra::{DMatrix, DVector};

/// The wave number k̄ at which the pair's stiffness βk̄/(1 − Φ(k̄)) is
/// least, by Brent's method on ln k̄ between 0.1/h and 20/h (h the
/// thicker coating).
pub(crate) fn stiffness_minimum(layers: &Layers) -> f64 {
    let h = layers.thickest();
    let stiffness = |t: f64| {
        let k = t.exp() / h;
        k / (1.0 - layers.base_share(k))
    };
    brent_minimum(stiffness, (0.1f64).ln(), (20.0f64).ln(), 1e-10).exp() / h
}

/// The line contact of `layers`, with `modes` Chebyshev functions (both
/// parities together).
pub(crate) struct LineContact<'a> {
    layers: &'a Layers,
    modes: usize,
}

/// A straight state: half width ā, approach δ̄, force per unit length F̄,
/// the pressure's coefficients and their derivatives in ā (at fixed δ̄)
/// and in a shift of the contact (odd orders), the stress-intensity
/// factor's change as the right edge moves, and the size of the last
/// even coefficient against the largest.
pub(crate) struct LineState {
    pub(crate) a_bar: f64,
    pub(crate) delta_bar: f64,
    pub(crate) force_bar: f64,
    coef: Vec<f64>,
    coef_a: Vec<f64>,
    coef_shift: Vec<f64>,
    /// ∂K/∂b: the right edge moved alone, at fixed δ̄.
    pub(crate) k_edge: f64,
    pub(crate) tail: f64,
}

/// (−1)^⌊n/2⌋: the sign iⁿ carries for even n and −iⁿ⁺¹ for odd n.
fn sign(n: usize) -> f64 {
    if (n / 2) % 2 == 0 {
        1.0
    } else {
        -1.0
    }
}

impl<'a> LineContact<'a> {
    pub(crate) fn new(layers: &'a Layers, modes: usize) -> LineContact<'a> {
        LineContact { layers, modes }
    }

    /// The pair's compliance at wave number q̄ > 0.
    fn compliance(&self, q: f64) -> f64 {
        (1.0 - self.layers.base_share(q)) / (self.layers.beta() * q)
    }

    /// Gauss–Legendre nodes on [0, top], panel by panel, each no wider than
    /// a quarter period of Jₘ(qā)Jₙ(qā), a quarter of k̄, and a quarter of
    /// its distance from 0 or half of 1/h, whichever is more (the
    /// compliance varies on the scale of h below 1/h and of q above).
    fn nodes(&self, a: f64, top: f64, k: f64) -> Vec<(f64, f64)> {
        let rule = GaussLegendre::new(16);
        let mut cap = std::f64::consts::PI / (2.0 * a);
        if k > 0.0 {
            cap = cap.min(0.25 * k);
        }
        let floor = 0.5 / self.layers.thickest();
        let mut out = Vec::new();
        let mut lo = 0.0;
        while lo < top {
            let width = cap.min((0.25 * lo).max(floor)).min(top - lo);
            out.extend(rule.composite(lo, lo + width, 1));
            lo += width;
        }
        out
    }

    /// Where the integrals stop: Φ is below 1e-17 beyond q̄h = 25, and the
    /// difference of two modes' compliances falls as k̄²/q³; the
    /// undulation's integrals stop at 400k̄ (the least δK/A moves by 8e-4
    /// of itself from 200k̄ to 800k̄, by 1.3e-2 from 50k̄ to 200k̄, at
    /// h/L = 0.1).
    fn top(&self, k: f64) -> f64 {
        (25.0 / self.layers.thinnest() + k).max(400.0 * k)
    }

    /// The Galerkin matrix of mode k̄ at half width ā, and at k̄ = 0 also
    /// its derivative in ā (none at k̄ > 0).
    fn matrix(&self, a: f64, k: f64) -> (DMatrix<f64>, Option<DMatrix<f64>>) {
        let straight = k == 0.0;
        let n = self.modes;
        let beta = self.layers.beta();
        let top = self.top(k);
        let mut integral = DMatrix::<f64>::zeros(n, n);
        let mut slope = DMatrix::<f64>::zeros(n, n);
        let mut j = vec![0.0; n];
        for (q, w) in self.nodes(a, top, k) {
            orders(q * a, &mut j);
            let c = self.compliance(q.hypot(k));
            let rest = c - 1.0 / (beta * q);
            for m in 0..n {
                for l in (m % 2..=m).step_by(2) {
                    let jj = w * j[m] * j[l];
                    integral[(m, l)] += if m == 0 { c * jj } else { rest * jj };
                }
            }
            if straight {
                // dΦ/dq by the five-point difference
                let eta = 1e-3 * q;
                let phi = |x: f64| self.layers.base_share(x);
                let dphi = (8.0 * (phi(q + eta) - phi(q - eta)) - phi(q + 2.0 * eta)
                    + phi(q - 2.0 * eta))
                    / (12.0 * eta);
                for m in 0..n {
                    for l in (m % 2..=m).step_by(2) {
                        slope[(m, l)] += dphi * w * j[m] * j[l];
                    }
                }
            }
        }
        // J₀²'s integral beyond `top`: on to qā = 2000 with J₀ alone, then
        // its asymptotic tail (1/π)(1/X + cos 2X/2X²), to O(X⁻³)
        let far = (2000.0 / a).max(top);
        if far > top {
            let width = std::f64::consts::PI / (2.0 * a);
            let panels = ((far - top) / width).ceil() as usize;
            for (q, w) in GaussLegendre::new(8).composite(top, far, panels) {
                integral[(0, 0)] += w * self.compliance(q.hypot(k)) * j0(q * a).powi(2);
            }
        }
        let x = far * a;
        integral[(0, 0)] +=
            (1.0 / x + (2.0 * x).cos() / (2.0 * x * x)) / (std::f64::consts::PI * beta);
        for m in 1..n {
            integral[(m, m)] += 1.0 / (2.0 * m as f64 * beta);
        }
        let mut matrix = DMatrix::<f64>::zeros(n, n);
        let mut da = DMatrix::<f64>::zeros(n, n);
        for m in 0..n {
            for l in (m % 2..=m).step_by(2) {
                let s = sign(m) * sign(l);
                let v = a * a * std::f64::consts::PI * s * integral[(m, l)];
                let d = 2.0 * v / a + a * std::f64::consts::PI * s * slope[(m, l)] / beta;
                for (i, k) in [(m, l), (l, m)] {
                    matrix[(i, k)] = v;
                    da[(i, k)] = d;
                }
            }
        }
        (matrix, straight.then_some(da))
    }

    /// The straight state at half width ā.
    pub(crate) fn state(&self, a: f64) -> Result<LineState> {
        let n = self.modes;
        let pi = std::f64::consts::PI;
        let beta = self.layers.beta();
        let (matrix, da) = self.matrix(a, 0.0);
        let da = da.expect("the straight state's matrix carries its slope");
        let lu = matrix.lu();
        let solve = |r: DVector<f64>| {
            lu.solve(&r).ok_or_else(|| Error::Unresolved {
                what: format!("the line contact at a_bar = {a}: its Galerkin matrix is singular"),
                residual: f64::NAN,
            })
        };
        let unit = |i: usize, v: f64| DVector::from_fn(n, |m, _| if m == i { v } else { 0.0 });
        // R = δ̄ R₁ − R₂: ∫(δ̄ − X̄²/2) Tₘ(t)/√(1 − t²) dX̄
        let c1 = solve(unit(0, a * pi))?;
        let c2 = solve(unit(0, pi * a.powi(3) / 4.0) + unit(2, pi * a.powi(3) / 8.0))?;
        let root = (pi * a).sqrt();
        // K = −√(πā) Σcₙ = √(2β)
        let delta = (c2.sum() - (2.0 * beta).sqrt() / root) / c1.sum();
        let coef = &c1 * delta - &c2;
        let r_a = unit(0, pi * delta - 0.75 * pi * a * a) - unit(2, 0.375 * pi * a * a);
        let coef_a = solve(r_a - &da * &coef)?;
        let coef_shift = solve(unit(1, -0.5 * pi * a * a))?;
        let k_a = -(pi.sqrt()) * (coef.sum() / (2.0 * a.sqrt()) + a.sqrt() * coef_a.sum());
        let k_shift = -root * coef_shift.sum();
        let largest = coef.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        let last = (0..n).rev().find(|m| m % 2 == 0).expect("modes > 0");
        Ok(LineState {
            a_bar: a,
            delta_bar: delta,
            force_bar: a * pi * coef[0],
            k_edge: 0.5 * (k_a + k_shift),
            tail: coef[last].abs() / largest,
            coef: coef.iter().copied().collect(),
            coef_a: coef_a.iter().copied().collect(),
            coef_shift: coef_shift.iter().copied().collect(),
        })
    }

    /// The most unstable undulation of `state`: the least δK/A/K over k̄h in
    /// [0.05, 8] (h the thicker coating), by Brent's method on ln k̄h, and
    /// that k̄h; the first undulation that fails is the error.
    pub(crate) fn most_unstable(&self, state: &LineState) -> Result<(f64, f64)> {
        let h = self.layers.thickest();
        let failed = std::cell::RefCell::new(None);
        let at = |t: f64| match self.undulation(state, t.exp() / h) {
            Ok(s) => s,
            Err(e) => {
                failed.borrow_mut().get_or_insert(e);
                f64::INFINITY
            }
        };
        let t = brent_minimum(at, (0.05f64).ln(), (8.0f64).ln(), 1e-6);
        if let Some(e) = failed.into_inner() {
            return Err(e);
        }
        Ok((self.undulation(state, t.exp() / h)?, t.exp()))
    }

    /// δK/A over K at mode k̄ > 0: the change of the stress-intensity
    /// factor at the right edge when it undulates as A cos k̄Y.
    pub(crate) fn undulation(&self, state: &LineState, k: f64) -> Result<f64> {
        let n = self.modes;
        let a = state.a_bar;
        let pi = std::f64::consts::PI;
        let (matrix, _) = self.matrix(a, k);
        let mut r = DVector::<f64>::zeros(n);
        let mut j = vec![0.0; n + 1];
        for (q, w) in self.nodes(a, self.top(k), k) {
            orders(q * a, &mut j);
            let diff = self.compliance(q.hypot(k)) - self.compliance(q);
            // the shift's part U and the widening's part V of ∂p₀/∂b
            let (mut u, mut v) = (0.0, 0.0);
            for m in 0..n {
                if m % 2 == 0 {
                    let dj = if m == 0 {
                        -j[1]
                    } else {
                        0.5 * (j[m - 1] - j[m + 1])
                    };
                    u += q * state.coef[m] * sign(m) * j[m];
                    v += sign(m)
                        * (a * state.coef_a[m] * j[m] + state.coef[m] * (j[m] + q * a * dj));
                } else {
                    u += state.coef_shift[m] * sign(m) * j[m];
                }
            }
            for m in 0..n {
                r[m] -= if m % 2 == 0 {
                    0.5 * a * pi * sign(m) * w * diff * v * j[m]
                } else {
                    0.5 * a * a * pi * sign(m) * w * diff * u * j[m]
                };
            }
        }
        let q = matrix.lu().solve(&r).ok_or_else(|| Error::Unresolved {
            what: format!(
                "the line contact's undulation at k = {k}: its Galerkin matrix is singular"
            ),
            residual: f64::NAN,
        })?;
        let k0 = (2.0 * self.layers.beta()).sqrt();
        let k_q = -(pi * a).sqrt() * q.sum();
        Ok((state.k_edge + k_q) / k0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stiffness_is_least_where_confined_films_finger() {
        // Shenoy and Sharma (PRL 86:119, 2001) and the issue: kh = 2.12
        // for ν = ½, 1.84 for ν = 0.45, printed to three figures; one
        // coating or two equal ones, at any thinness (the minimum scales
        // with h)
        for (nu, printed) in [(0.5, 2.12), (0.45, 1.84)] {
            for thin in [0.05, 1.0, 30.0] {
                let kh = stiffness_minimum(&Layers::equal(thin, nu).unwrap()) * thin;
                println!(
                    "nu {nu}, h/L {thin}: kh {kh:.5}, wavelength {:.4} h",
                    2.0 * std::f64::consts::PI / kh
                );
                assert!((kh - printed).abs() < 0.005, "nu {nu}, h/L {thin}: kh {kh}");
            }
        }
    }

    #[test]
    fn the_straight_edge_follows_rice_at_short_waves_and_equation_2_at_long_ones() {
        // short waves (kh ≫ 1): the half-space's crack front, Rice (1985):
        // δK/A = K|k̄|/2 plus a constant, for a contact ten coatings wide
        let layers = Layers::equal(0.1, 0.5).unwrap();
        let line = LineContact::new(&layers, 40);
        let st = line.state(1.0).unwrap();
        let s = |kh: f64| line.undulation(&st, kh / 0.1).unwrap();
        let slope = (s(10.0) - s(6.0)) / 40.0;
        assert!((slope - 0.5).abs() < 2e-3, "{slope}");
        // the straight state itself on coatings 10⁵ times thicker than the
        // contact: the half-space's line contact of JKR, whose force per
        // unit length is πE*ā²/4R − √(2πāE*Δγ) (E* = 2β, Δγ̄ = ½, R̄ = 1)
        let layers = Layers::equal(1000.0, 0.5).unwrap();
        let (a, beta) = (0.002, layers.beta());
        let force = LineContact::new(&layers, 8).state(a).unwrap().force_bar;
        let jkr = 0.5 * std::f64::consts::PI * beta * a * a
            - (2.0 * std::f64::consts::PI * a * beta).sqrt();
        assert!((force / jkr - 1.0).abs() < 1e-9, "{force} against {jkr}");
        // long waves (kh ≪ 1) on thin coatings: (2)'s edge, p = 0 and
        // |∇p| fixed there, whose undulation p₁ = B sinh k(X + ā) gives
        // δK/A/K = p₀″/p₀′ − k coth 2kā, so S(0) − S(k) = k coth 2kā − 1/2ā;
        // the layer's ratio to it falls short by O(kh) (0.96 at kh = 0.05,
        // 0.98 at 0.025) and extrapolates to 1
        let layers = Layers::equal(0.02, 0.5).unwrap();
        let line = LineContact::new(&layers, 200);
        let a = 2.0;
        let st = line.state(a).unwrap();
        let s0 = st.k_edge / (2.0 * layers.beta()).sqrt();
        let ratio = |kh: f64| {
            let k = kh / 0.02;
            let thin_layer = k / (2.0 * k * a).tanh() - 0.5 / a;
            (s0 - line.undulation(&st, k).unwrap()) / thin_layer
        };
        let (coarse, fine) = (ratio(0.05), ratio(0.025));
        assert!(coarse < fine && fine < 1.0, "{coarse} {fine}");
        let limit = 2.0 * fine - coarse;
        assert!((limit - 1.0).abs() < 5e-3, "{coarse} {fine} -> {limit}");
    }

    #[test]
    fn the_straight_edge_is_most_unstable_at_a_longer_wave_than_the_stiffness_minimum() {
        // a contact ten coatings wide (h/L = 0.1): the least δK/A over k̄
        // is negative (the edge is unstable) and lies at k̄h = 1.184 for
        // ν = ½ and 0.877 for ν = 0.45 (docs/thickness.md: the same at
        // a/h = 3 and 30 within 2e-3), 40 and 80 modes within 1e-3 of each
        // other, at 0.56 and 0.48 of the kernel's stiffness minimum (2.12,
        // 1.84)
        for (nu, printed) in [(0.5, 1.184), (0.45, 0.877)] {
            let layers = Layers::equal(0.1, nu).unwrap();
            let stiff = stiffness_minimum(&layers) * 0.1;
            let mut found = Vec::new();
            for modes in [40, 80] {
                let line = LineContact::new(&layers, modes);
                let st = line.state(1.0).unwrap();
                let (s, kh) = line.most_unstable(&st).unwrap();
                assert!(s < 0.0, "nu {nu}, {modes} modes: {s}");
                found.push(kh);
            }
            assert!((found[0] - found[1]).abs() < 1e-3, "nu {nu}: {found:?}");
            assert!((found[1] - printed).abs() < 2e-3, "nu {nu}: {found:?}");
            assert!(
                found[1] / stiff < 0.6,
                "nu {nu}: {} against {stiff}",
                found[1]
            );
        }
    }

    /// The line contact on thin coatings is (2)'s, δ̄ = ā²/6 − 1/ā and
    /// F̄ = 2ā³δ̄/3 − ā⁵/15 per unit length, at the half width ā + b̄: its
    /// edges lie b̄ inside (2)'s, the shift of `layer::thin::edge_shift` from
    /// the kernel's Wiener–Hopf factorisation. Measured at ā = 2 on
    /// h/L = 0.04, 0.02 and 0.01, extrapolated in h/L; a straight edge has
    /// no curvature, so the line tension leaves Griffith's condition alone.
    /// Its second order is the approach shift of `layer::thin::approach_shift`
    /// for this gap (∇̄²φ̄ = 1): δ̄ less (2)'s at ā + b̄, over (h/L)² and
    /// extrapolated linearly through h/L = 0.02 and 0.01, is −a/2 (measured
    /// −0.9046 against −0.9000; from ā = 1.5 to 4 the same extrapolation
    /// through 0.04 and 0.02 spreads from −0.895 to −0.906, so within 1 %;
    /// the interior's count alone would give −a, twice it).
    /// (2)'s approach of the line contact at half width `a`: ā²/6 − 1/ā.
    fn line_delta(a: f64) -> f64 {
        a * a / 6.0 - 1.0 / a
    }

    #[test]
    fn the_straight_edge_lies_the_wiener_hopf_shift_inside_equation_2_s() {
        let a = 2.0f64;
        let delta0 = line_delta(a);
        let delta_slope = a / 3.0 + 1.0 / (a * a);
        let force_slope = 2.0 * (delta_slope * a.powi(3) / 3.0 + delta0 * a * a) - a.powi(4) / 3.0;
        let force0 = 2.0 * a.powi(3) * delta0 / 3.0 - a.powi(5) / 15.0;
        let unit = Layers::equal(1.0, 0.5).unwrap();
        let shift = crate::layer::thin::edge_shift(&unit).unwrap();
        let mut by_delta = Vec::new();
        let mut by_force = Vec::new();
        let mut second = Vec::new();
        for (thin, modes) in [(0.04, 120), (0.02, 200), (0.01, 300)] {
            let layers = Layers::equal(thin, 0.5).unwrap();
            let st = LineContact::new(&layers, modes).state(a).unwrap();
            assert!(st.tail < 1e-11, "h/L {thin}: tail {}", st.tail);
            by_delta.push((st.delta_bar - delta0) / (thin * delta_slope));
            by_force.push((st.force_bar - force0) / (thin * force_slope));
            second.push((st.delta_bar - line_delta(a + shift * thin)) / (thin * thin));
        }
        // the quadratic in h/L through the three, at 0
        let limit = |s: &[f64]| (4.0 * (2.0 * s[2] - s[1]) - (2.0 * s[1] - s[0])) / 3.0;
        for (what, s) in [("delta", &by_delta), ("force", &by_force)] {
            let l = limit(s);
            assert!(
                (l / shift - 1.0).abs() < 5e-5,
                "{what}: {s:?} -> {l} against {shift}"
            );
        }
        let half_a = crate::layer::thin::approach_shift(&unit, f64::INFINITY).unwrap();
        let second_order = 2.0 * second[2] - second[1];
        assert!(
            (second_order / -half_a - 1.0).abs() < 0.01,
            "the second order {second:?} -> {second_order} against -a/2 = {}",
            -half_a
        );
        // as docs/thickness.md prints it ("Why one half")
        let docs = include_str!("../../../../docs/thickness.md");
        let printed = format!("is −{:.4} at ā = 2", -second_order);
        assert!(docs.contains(&printed), "docs/thickness.md: {printed}");
    }

    /// The line contact's second order in h/L at fixed half width: the
    /// layer's δ̄ less (2)'s at ā + b̄ (the first order's edge shift), over
    /// (h/L)², at ā from THINJKR_EDGE_AS (1.5, 2, 3, 4) and h/L 0.04, 0.02,
    /// 0.01, each pair extrapolated linearly to h/L = 0; beside it, the
    /// circle's approach shift's form for this gap (∇²φ̄ = 1):
    /// −`approach_shift` at ρ → ∞ over (h/L)², that is −a/2 (`cargo test
    /// --release -p thinjkr --lib explore_the_line_contact_s_second_order
    /// -- --ignored --nocapture`).
    #[test]
    #[ignore = "exploration: prints the line contact's second order in h/L"]
    fn explore_the_line_contact_s_second_order() {
        let list = std::env::var("THINJKR_EDGE_AS").unwrap_or("1.5,2,3,4".into());
        let unit = Layers::equal(1.0, 0.5).unwrap();
        let b = crate::layer::thin::edge_shift(&unit).unwrap();
        let half_a = crate::layer::thin::approach_shift(&unit, f64::INFINITY).unwrap();
        println!("b/h {b:.7}, the circle's rule for this gap: -{half_a:.6} (h/L)^2");
        for a in list.split(',').map(|x| x.parse::<f64>().unwrap()) {
            let mut r = Vec::new();
            for (thin, modes) in [(0.04, 120), (0.02, 200), (0.01, 300)] {
                let layers = Layers::equal(thin, 0.5).unwrap();
                let st = LineContact::new(&layers, modes).state(a).unwrap();
                r.push((st.delta_bar - line_delta(a + b * thin)) / (thin * thin));
            }
            let lin = |x: f64, y: f64| 2.0 * y - x;
            println!(
                "a {a}: (delta - (2)'s at a + b)/(h/L)^2 = {:.6} {:.6} {:.6}; to 0: {:.6} {:.6}; slope of (2)'s delta {:.6}",
                r[0],
                r[1],
                r[2],
                lin(r[0], r[1]),
                lin(r[1], r[2]),
                a / 3.0 + 1.0 / (a * a)
            );
        }
    }

    /// A number from the environment, or `default`.
    fn var(name: &str, default: f64) -> f64 {
        std::env::var(name)
            .map(|v| v.parse().unwrap())
            .unwrap_or(default)
    }

    /// The explorations' coatings: THINJKR_EDGE_THIN (h/L, 0.1),
    /// THINJKR_EDGE_NU (½) and THINJKR_EDGE_MODES (40).
    fn explored() -> (f64, f64, usize, Layers) {
        let thin = var("THINJKR_EDGE_THIN", 0.1);
        let nu = var("THINJKR_EDGE_NU", 0.5);
        let modes = var("THINJKR_EDGE_MODES", 40.0) as usize;
        (thin, nu, modes, Layers::equal(thin, nu).unwrap())
    }

    #[test]
    #[ignore = "exploration: prints the straight edge's dK/A against kh"]
    fn explore_edge() {
        let (thin, nu, modes, layers) = explored();
        let a = var("THINJKR_EDGE_A", 1.0);
        let line = LineContact::new(&layers, modes);
        let t = std::time::Instant::now();
        let st = line.state(a).unwrap();
        let beta = layers.beta();
        println!(
            "h/L {thin} nu {nu} a {a} (a/h {:.2}) modes {modes}: delta {:.8} F {:.8} (half-space JKR F {:.8}) tail {:.1e} dK/db/K {:.6e} ({:.2} s)",
            a / thin,
            st.delta_bar,
            st.force_bar,
            std::f64::consts::PI * beta * a * a / 2.0 - (2.0 * std::f64::consts::PI * a * beta).sqrt(),
            st.tail,
            st.k_edge / (2.0 * beta).sqrt(),
            t.elapsed().as_secs_f64()
        );
        let list =
            std::env::var("THINJKR_EDGE_KH").unwrap_or("0.25,0.5,1,1.5,2,2.5,3,4,6,10".into());
        for kh in list.split(',').map(|x| x.parse::<f64>().unwrap()) {
            let t = std::time::Instant::now();
            let s = line.undulation(&st, kh / thin).unwrap();
            println!(
                "kh {kh:6.3}: dK/A/K {s:+.8e}  (minus |k|/2: {:+.6e}) ({:.2} s)",
                s - 0.5 * kh / thin,
                t.elapsed().as_secs_f64()
            );
        }
    }

    #[test]
    #[ignore = "exploration: the least dK/A over k for a list of half widths"]
    fn explore_onset() {
        let (thin, nu, modes, layers) = explored();
        let line = LineContact::new(&layers, modes);
        let list = std::env::var("THINJKR_EDGE_AS").unwrap_or("0.5,1,2".into());
        for a in list.split(',').map(|x| x.parse::<f64>().unwrap()) {
            let st = line.state(a).unwrap();
            let (least, kh) = line.most_unstable(&st).unwrap();
            println!(
                "h/L {thin} nu {nu} a/h {:.3}: delta {:.6} F {:.6} dK/db/K {:+.5} tail {:.1e}; least dK/A/K {:+.6} at kh {:.5}",
                a / thin,
                st.delta_bar,
                st.force_bar,
                st.k_edge / (2.0 * layers.beta()).sqrt(),
                st.tail,
                least,
                kh
            );
        }
    }
}
