//! The gap φ̄ of the problem (2)–(3) as data: the exact solver solves
//! Δp̄ = φ̄ − δ̄ for whatever gap it is given, so that a contour family on
//! another gap (a data file of its own, `derive/families/*.toml`) is
//! measured against the exact solution of that gap, not of the cylinders'.
//!
//! A gap is given by a particular solution P(X, Y; μ, δ̄) of ΔP = φ̄ − δ̄
//! (μ = 1/ρ), a sum of monomials c·X^i·Y^j·μ^k·δ̄^l with rational c, even in
//! X and Y (the problem's two symmetries) and at most linear in δ̄: the
//! generator writes these terms into the registry beside the family's
//! formulas, after checking ΔP = φ̄ − δ̄ symbolically. At a given ρ the
//! solver needs P = P₀ + δ̄P₁ and its gradient and second derivatives, the
//! gap φ̄ = ΔP₀ (ΔP₁ = −1 is checked here), and for the force's boundary
//! form F̄ = −∮ w ∂p̄/∂ν ds + ∮ W dY (w = (X² + Y²)/4, Δw = 1) the
//! antiderivative W = ∫ w(φ̄ − δ̄) dX. All are polynomials, computed once
//! from the terms ([`GapAt`]).
//!
//! At ρ = 1 a gap that depends on X² + Y² alone has the exact circular
//! states: on the circle of radius ā, ∮∂p̄/∂ν ds = ∫(φ̄ − δ̄)dA gives
//! δ̄ = ⟨φ̄⟩ − 2/ā (⟨·⟩ the mean over the disk), and Green's identity
//! F̄ = −πā³/2 + ∫ w(φ̄ − δ̄) dA; a contour mode cos nθ is neutral where
//! ā(φ̄(ā) − ⟨φ̄⟩) = n − 1 (the perturbed (3)₂: p̄₀″(ā) = n/ā). For the
//! cylinders' gap these are (22)–(25): δ̄ = ā²/4 − 2/ā,
//! F̄ = π(ā⁶ − 24ā³)/96 and ā³ = 4(n − 1).
//!
//! Owns: [`Gap`], [`Term`], [`GapAt`], [`Hessian`]. May use: `error`, `exact` (the
//! test's solve on the circle), `model` (the test's Brent minimum), `control`
//! (the tests' controls).

use crate::error::{Error, Result};

/// One monomial c·X^x·Y^y·μ^mu·δ̄^dbar of a particular solution, c = num/den.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Term {
    /// Power of X.
    pub x: u8,
    /// Power of Y.
    pub y: u8,
    /// Power of μ = 1/ρ.
    pub mu: u8,
    /// Power of δ̄ (0 or 1).
    pub dbar: u8,
    /// Numerator of the coefficient.
    pub num: i64,
    /// Denominator of the coefficient (positive).
    pub den: i64,
}

/// A gap, given by a particular solution of ΔP = φ̄ − δ̄ (2) and the name
/// of the family file it comes from, with the model that gives the exact
/// solver its starting guesses, handed in by the layer above
/// ([`super::seed`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Gap {
    /// Where it comes from: `cylinders` for the paper's (1), else the
    /// family whose data file gives it.
    pub name: &'static str,
    /// P's monomials.
    pub particular: &'static [Term],
    /// The model that seeds the exact solver of this gap, if any.
    pub seed: Option<&'static dyn super::seed::Seed>,
}

impl PartialEq for Gap {
    /// The same particular solution, term for term in any order (whatever
    /// the seed).
    fn eq(&self, other: &Gap) -> bool {
        let sorted = |g: &Gap| {
            let mut t: Vec<Term> = g.particular.to_vec();
            t.sort_by_key(|t| (t.x, t.y, t.mu, t.dbar, t.num, t.den));
            t
        };
        sorted(self) == sorted(other)
    }
}

const fn term(x: u8, y: u8, mu: u8, dbar: u8, num: i64, den: i64) -> Term {
    Term {
        x,
        y,
        mu,
        dbar,
        num,
        den,
    }
}

impl Gap {
    /// The gap (1) of two crossed cylinders in the units (17),
    /// φ̄ = X²/2 + μY²/2, with P = X⁴/24 + μY⁴/24 − δ̄(X² + Y²)/4: the
    /// problem of the paper.
    /// (Unseeded: `Gap::cylinders()`, given by the layer that knows the
    /// registry, adds the seed.)
    pub(crate) const CYLINDERS: Gap = Gap {
        name: "cylinders",
        seed: None,
        particular: &[
            term(4, 0, 0, 0, 1, 24),
            term(0, 4, 1, 0, 1, 24),
            term(2, 0, 0, 1, -1, 4),
            term(0, 2, 0, 1, -1, 4),
        ],
    };

    /// The polynomials at `rho`, after checking the terms: even powers of
    /// X and Y, δ̄ at most linearly, nonzero denominators and ΔP₁ = −1.
    pub(crate) fn at(&self, rho: f64) -> Result<GapAt> {
        let bad = |why: String| Error::Usage(format!("the gap {}: {why}", self.name));
        let mu = 1.0 / rho;
        let (mut p0, mut p1) = (Poly::default(), Poly::default());
        let mut lap_p1: Vec<(u8, u8, u8, i128, i128)> = Vec::new();
        for t in self.particular {
            if t.den <= 0 || t.x % 2 == 1 || t.y % 2 == 1 || t.dbar > 1 || t.x > 24 || t.y > 24 {
                return Err(bad(format!(
                    "the term X^{} Y^{} mu^{} dbar^{} ({}/{}) is not even in X and Y with degree at most 24, linear in dbar, with a positive denominator",
                    t.x, t.y, t.mu, t.dbar, t.num, t.den
                )));
            }
            let c = t.num as f64 * mu.powi(t.mu as i32) / t.den as f64;
            if t.dbar == 0 {
                p0.push(t.x as i32, t.y as i32, c);
            } else {
                p1.push(t.x as i32, t.y as i32, c);
                // ΔP₁ in exact arithmetic, term by term
                for (k, dx, dy) in [(t.x, 2u8, 0u8), (t.y, 0, 2)] {
                    if k >= 2 {
                        let f = k as i128 * (k as i128 - 1);
                        lap_p1.push((t.x - dx, t.y - dy, t.mu, f * t.num as i128, t.den as i128));
                    }
                }
            }
        }
        // ΔP₁ = −1: every monomial's coefficients sum to 0 but the constant's, −1
        let mut keys: Vec<(u8, u8, u8)> = lap_p1.iter().map(|t| (t.0, t.1, t.2)).collect();
        // the constant term is always checked (a P without δ̄ fails there)
        keys.push((0, 0, 0));
        keys.sort();
        keys.dedup();
        for k in keys {
            let (mut num, mut den) = (0i128, 1i128);
            // exact where it fits in i128; a sum that overflows is refused
            // (no family's coefficients come near: a hostile file's may)
            let mut fits = true;
            for t in lap_p1.iter().filter(|t| (t.0, t.1, t.2) == k) {
                let next = num
                    .checked_mul(t.4)
                    .zip(t.3.checked_mul(den))
                    .and_then(|(a, b)| a.checked_add(b))
                    .zip(den.checked_mul(t.4));
                let Some((n, d)) = next else {
                    fits = false;
                    break;
                };
                let g = gcd(n, d);
                (num, den) = (n / g, d / g);
            }
            let want = if k == (0, 0, 0) { -1 } else { 0 };
            if !fits || num != want * den {
                return Err(bad(
                    "its dbar part P1 does not satisfy ΔP1 = −1 (P must solve ΔP = φ − dbar)"
                        .into(),
                ));
            }
        }
        Ok(GapAt::new(p0, p1))
    }
}

fn gcd(a: i128, b: i128) -> i128 {
    let (mut a, mut b) = (a.abs(), b.abs());
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.max(1)
}

/// A polynomial Σ c X^i Y^j with real coefficients.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Poly {
    terms: Vec<(i32, i32, f64)>,
}

impl Poly {
    fn push(&mut self, i: i32, j: i32, c: f64) {
        if c == 0.0 {
            return;
        }
        match self.terms.iter_mut().find(|t| t.0 == i && t.1 == j) {
            Some(t) => t.2 += c,
            None => self.terms.push((i, j, c)),
        }
    }

    pub(crate) fn eval(&self, x: f64, y: f64) -> f64 {
        self.terms
            .iter()
            .map(|&(i, j, c)| c * x.powi(i) * y.powi(j))
            .sum()
    }

    fn dx(&self) -> Poly {
        let mut out = Poly::default();
        for &(i, j, c) in self.terms.iter().filter(|t| t.0 > 0) {
            out.push(i - 1, j, c * i as f64);
        }
        out
    }

    fn dy(&self) -> Poly {
        let mut out = Poly::default();
        for &(i, j, c) in self.terms.iter().filter(|t| t.1 > 0) {
            out.push(i, j - 1, c * j as f64);
        }
        out
    }

    fn laplacian(&self) -> Poly {
        let (xx, yy) = (self.dx().dx(), self.dy().dy());
        let mut out = xx;
        for &(i, j, c) in &yy.terms {
            out.push(i, j, c);
        }
        out
    }

    /// The product with w = (X² + Y²)/4.
    fn times_w(&self) -> Poly {
        let mut out = Poly::default();
        for &(i, j, c) in &self.terms {
            out.push(i + 2, j, c / 4.0);
            out.push(i, j + 2, c / 4.0);
        }
        out
    }

    /// The product with another polynomial.
    fn times(&self, other: &Poly) -> Poly {
        let mut out = Poly::default();
        for &(i, j, c) in &self.terms {
            for &(k, l, d) in &other.terms {
                out.push(i + k, j + l, c * d);
            }
        }
        out
    }

    /// The polynomial times a constant.
    fn scaled(&self, factor: f64) -> Poly {
        let mut out = Poly::default();
        for &(i, j, c) in &self.terms {
            out.push(i, j, c * factor);
        }
        out
    }

    /// ∫ · dX from X = 0.
    fn integral_x(&self) -> Poly {
        let mut out = Poly::default();
        for &(i, j, c) in &self.terms {
            out.push(i + 1, j, c / (i + 1) as f64);
        }
        out
    }

    /// The mean over the disk of radius `a` about the origin (even powers:
    /// ⟨X^i Y^j⟩ = a^(i+j) · 2/(i+j+2) · (i−1)!!(j−1)!!/(i+j)!!).
    fn disk_mean(&self, a: f64) -> f64 {
        self.terms
            .iter()
            .map(|&(i, j, c)| c * a.powi(i + j) * 2.0 / (i + j + 2) as f64 * angular_mean(i, j))
            .sum()
    }
}

/// (1/2π)∫cos^i θ sin^j θ dθ for even i, j: (i−1)!!(j−1)!!/(i+j)!!.
fn angular_mean(i: i32, j: i32) -> f64 {
    let dfact = |n: i32| (1..=n).rev().step_by(2).map(|k| k as f64).product::<f64>();
    dfact(i - 1) * dfact(j - 1) / dfact(i + j)
}

/// The gap's polynomials at one ρ: P = P₀ + δ̄P₁, their derivatives, the
/// gap φ̄ = ΔP₀, the force's antiderivative W = W₀ + δ̄W₁ and the energy's
/// Q = Q₀ + δ̄Q₁ + δ̄²Q₂ = ∫ P(φ̄ − δ̄) dX.
#[derive(Clone, Debug)]
pub(crate) struct GapAt {
    p0: Poly,
    p1: Poly,
    p0x: Poly,
    p0y: Poly,
    p1x: Poly,
    p1y: Poly,
    p0xx: Poly,
    p0xy: Poly,
    p0yy: Poly,
    p1xx: Poly,
    p1xy: Poly,
    p1yy: Poly,
    phi: Poly,
    w0: Poly,
    w1: Poly,
    w0y: Poly,
    w1y: Poly,
    #[cfg_attr(not(feature = "cli"), allow(dead_code))]
    q: [Poly; 3],
}

/// P's second derivatives at one point.
pub(crate) struct Hessian {
    pub p_xx: f64,
    pub p_xy: f64,
    pub p_yy: f64,
}

impl GapAt {
    fn new(p0: Poly, p1: Poly) -> GapAt {
        let phi = p0.laplacian();
        let w0 = phi.times_w().integral_x();
        let mut minus_one = Poly::default();
        minus_one.push(0, 0, -1.0);
        let w1 = minus_one.times_w().integral_x();
        // P(φ̄ − δ̄) = P₀φ̄ + δ̄(P₁φ̄ − P₀) − δ̄²P₁
        let mut p1_phi_minus_p0 = p1.times(&phi);
        for &(i, j, c) in &p0.terms {
            p1_phi_minus_p0.push(i, j, -c);
        }
        let q = [
            p0.times(&phi).integral_x(),
            p1_phi_minus_p0.integral_x(),
            p1.scaled(-1.0).integral_x(),
        ];
        GapAt {
            q,
            p0x: p0.dx(),
            p0y: p0.dy(),
            p1x: p1.dx(),
            p1y: p1.dy(),
            p0xx: p0.dx().dx(),
            p0xy: p0.dx().dy(),
            p0yy: p0.dy().dy(),
            p1xx: p1.dx().dx(),
            p1xy: p1.dx().dy(),
            p1yy: p1.dy().dy(),
            w0y: w0.dy(),
            w1y: w1.dy(),
            phi,
            w0,
            w1,
            p0,
            p1,
        }
    }

    /// The gap (1 − t)·`self` + t·`other` (issue 73: the walk in the gap
    /// from a gap whose states are known to another): P blends as φ̄ does,
    /// and its δ̄ part still satisfies ΔP₁ = −1.
    pub(crate) fn blend(&self, other: &GapAt, t: f64) -> GapAt {
        let mix = |a: &Poly, b: &Poly| {
            let mut out = a.scaled(1.0 - t);
            for &(i, j, c) in &b.terms {
                out.push(i, j, t * c);
            }
            out
        };
        GapAt::new(mix(&self.p0, &other.p0), mix(&self.p1, &other.p1))
    }

    /// P at (X, Y) with approach δ̄.
    pub(crate) fn p(&self, x: f64, y: f64, delta_bar: f64) -> f64 {
        self.p0.eval(x, y) + delta_bar * self.p1.eval(x, y)
    }

    /// ∂P/∂δ̄ = P₁ at (X, Y).
    /// ∇P = P_X + i P_Y at the point z, as a complex number.
    pub(crate) fn grad_complex(
        &self,
        z: nalgebra::Complex<f64>,
        delta_bar: f64,
    ) -> nalgebra::Complex<f64> {
        let (px, py) = self.grad(z.re, z.im, delta_bar);
        nalgebra::Complex::new(px, py)
    }

    pub(crate) fn p_delta(&self, x: f64, y: f64) -> f64 {
        self.p1.eval(x, y)
    }

    /// ∇P at (X, Y) as P_X + i P_Y.
    pub(crate) fn grad(&self, x: f64, y: f64, delta_bar: f64) -> (f64, f64) {
        (
            self.p0x.eval(x, y) + delta_bar * self.p1x.eval(x, y),
            self.p0y.eval(x, y) + delta_bar * self.p1y.eval(x, y),
        )
    }

    /// ∇P₁ = ∂∇P/∂δ̄ at (X, Y).
    pub(crate) fn grad_delta(&self, x: f64, y: f64) -> (f64, f64) {
        (self.p1x.eval(x, y), self.p1y.eval(x, y))
    }

    /// P's second derivatives at (X, Y).
    pub(crate) fn hessian(&self, x: f64, y: f64, delta_bar: f64) -> Hessian {
        let d = delta_bar;
        Hessian {
            p_xx: self.p0xx.eval(x, y) + d * self.p1xx.eval(x, y),
            p_xy: self.p0xy.eval(x, y) + d * self.p1xy.eval(x, y),
            p_yy: self.p0yy.eval(x, y) + d * self.p1yy.eval(x, y),
        }
    }

    /// W = ∫ w(φ̄ − δ̄) dX, ∂W/∂X = w(φ̄ − δ̄), ∂W/∂Y and ∂W/∂δ̄ at (X, Y).
    pub(crate) fn force_potential(&self, x: f64, y: f64, delta_bar: f64) -> [f64; 4] {
        let w = (x * x + y * y) / 4.0;
        [
            self.w0.eval(x, y) + delta_bar * self.w1.eval(x, y),
            w * (self.phi.eval(x, y) - delta_bar),
            self.w0y.eval(x, y) + delta_bar * self.w1y.eval(x, y),
            self.w1.eval(x, y),
        ]
    }

    /// Q = ∫ P(φ̄ − δ̄) dX at (X, Y): ∫ω P(φ̄ − δ̄) dA = ∮ Q dY, for the
    /// energy's boundary form (`studies::potential`, the command line's).
    #[cfg_attr(not(feature = "cli"), allow(dead_code))]
    pub(crate) fn energy_potential(&self, x: f64, y: f64, delta_bar: f64) -> f64 {
        let [q0, q1, q2] = &self.q;
        q0.eval(x, y) + delta_bar * (q1.eval(x, y) + delta_bar * q2.eval(x, y))
    }

    /// The gap φ̄ at (X, Y).
    pub(crate) fn phi(&self, x: f64, y: f64) -> f64 {
        self.phi.eval(x, y)
    }

    /// Whether φ̄ depends on X² + Y² alone (then circles solve the problem),
    /// tried at radii 0.5 … 4 and 16 angles to 1e-12.
    pub(crate) fn is_radial(&self) -> bool {
        (1..=8).all(|k| {
            let r = 0.5 * k as f64;
            let on_axis = self.phi(r, 0.0);
            (1..16).all(|m| {
                let t = std::f64::consts::PI * m as f64 / 16.0;
                let v = self.phi(r * t.cos(), r * t.sin());
                (v - on_axis).abs() <= 1e-12 * on_axis.abs().max(1.0)
            })
        })
    }

    /// The circle's approach at radius ā: δ̄ = ⟨φ̄⟩ − 2/ā.
    pub(crate) fn circle_delta(&self, a_bar: f64) -> f64 {
        self.phi.disk_mean(a_bar) - 2.0 / a_bar
    }

    /// The circle's force at radius ā (with the circle's δ̄):
    /// F̄ = −πā³/2 + πā²⟨w(φ̄ − δ̄)⟩.
    pub(crate) fn circle_force(&self, a_bar: f64) -> f64 {
        let pi = std::f64::consts::PI;
        let wf = self.phi.times_w();
        let mut w = Poly::default();
        w.push(0, 0, 1.0);
        let w = w.times_w();
        let d = self.circle_delta(a_bar);
        -pi * a_bar.powi(3) / 2.0
            + pi * a_bar * a_bar * (wf.disk_mean(a_bar) - d * w.disk_mean(a_bar))
    }

    /// ā(φ̄(ā, 0) − ⟨φ̄⟩): mode n of the circle is neutral where it is n − 1.
    pub(crate) fn neutral_measure(&self, a_bar: f64) -> f64 {
        a_bar * (self.phi(a_bar, 0.0) - self.phi.disk_mean(a_bar))
    }

    /// ā at which a pull-off's trace on this gap starts (this at ρ = 1),
    /// the one rule of the exact solver and of a family's members (issue
    /// 73). On a gap the circle solves: `given` (a family's
    /// `trace_start_a`: 2.6 for the cylinders), else halfway between the
    /// circle's neutral points of modes 4 and 6, where the near-elliptic
    /// arm that carries the pull-off lies. On a gap no circle solves:
    /// halfway between the cylinders' neutral points of modes 2 and 4
    /// (ā³ = 4 and 12), whatever `given` says (it names a place between a
    /// circle's neutral points, which such a gap has not), and the trace
    /// goes downhill in F̄ from there (the pull-off may lie on either side).
    /// There the cylinders' states continue from the circle in ρ (next to
    /// a neutral point they fold at once), and a state on such a gap is
    /// continued from them in the gap (the exact solver) or from its
    /// circle's guess at ρ = 1 (a member); at 2.6, next to the neutral
    /// point of mode 4, the bumpy gap's states fold in ρ at once.
    pub(crate) fn trace_start(&self, given: Option<f64>) -> f64 {
        let neutral =
            |c: &GapAt, m: usize, n: usize| 0.5 * (c.neutral_point(m) + c.neutral_point(n));
        if !self.is_radial() {
            return Gap::CYLINDERS
                .at(1.0)
                .map_or(f64::NAN, |c| neutral(&c, 2, 4));
        }
        given.unwrap_or_else(|| neutral(self, 4, 6))
    }

    /// The circle's neutral point of mode n: the root of
    /// ā(φ̄(ā, 0) − ⟨φ̄⟩) = n − 1 (ā³ = 4(n − 1) for the cylinders), by
    /// bisection; NaN where there is none below ā = 1e6.
    pub(crate) fn neutral_point(&self, n: usize) -> f64 {
        let target = n as f64 - 1.0;
        let (mut lo, mut hi) = (0.0, 1.0);
        while self.neutral_measure(hi) < target {
            hi *= 2.0;
            if hi > 1e6 {
                return f64::NAN;
            }
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if self.neutral_measure(mid) < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }
}

/// The quartic gap φ̄ = (X² + μY²)²/8 (docs/exact.md, "The gap as data"):
/// P = (3 − μ)X⁶/720 + μX⁴Y²/48 + μ²Y⁶/240 − δ̄(X² + Y²)/4; for tests.
#[cfg(test)]
pub(crate) static QUARTIC: [Term; 6] = [
    term(6, 0, 0, 0, 3, 720),
    term(6, 0, 1, 0, -1, 720),
    term(4, 2, 1, 0, 1, 48),
    term(0, 6, 2, 0, 1, 240),
    term(2, 0, 0, 1, -1, 4),
    term(0, 2, 0, 1, -1, 4),
];

/// The gap of issue 73's `bumpy` family, φ̄ = X²/2 + μY²/2 + X⁴/24: the
/// cylinders' and the first term beyond the parabola of one cylinder's own
/// gap (r − √(r² − x²) = x²/2r + x⁴/8r³ + …, here x⁴/24), not radial at
/// ρ = 1. P = the cylinders' + X⁶/720; for tests.
#[cfg(test)]
pub(crate) static BUMPY: [Term; 5] = [
    term(4, 0, 0, 0, 1, 24),
    term(0, 4, 1, 0, 1, 24),
    term(6, 0, 0, 0, 1, 720),
    term(2, 0, 0, 1, -1, 4),
    term(0, 2, 0, 1, -1, 4),
];

#[cfg(test)]
mod tests {
    use super::*;

    /// The one rule of where a pull-off's trace starts: a family's
    /// `trace_start_a` on a gap the circle solves, else halfway between its
    /// circle's neutral points of modes 4 and 6 (ā³ = 12 and 20 for the
    /// cylinders); on a gap no circle solves, halfway between the
    /// cylinders' neutral points of modes 2 and 4 (ā³ = 4 and 12) whatever
    /// the family says.
    #[test]
    fn a_trace_starts_between_neutral_points_of_the_circle_the_gap_has() {
        let cube_root = |v: f64| v.powf(1.0 / 3.0);
        let cylinders = Gap::CYLINDERS.at(1.0).unwrap();
        assert_eq!(cylinders.trace_start(Some(2.6)), 2.6);
        let between_4_and_6 = 0.5 * (cube_root(12.0) + cube_root(20.0));
        assert!((cylinders.trace_start(None) - between_4_and_6).abs() < 1e-12);
        let bumpy = Gap {
            name: "bumpy",
            particular: &BUMPY,
            seed: None,
        }
        .at(1.0)
        .unwrap();
        let between_2_and_4 = 0.5 * (cube_root(4.0) + cube_root(12.0));
        for given in [Some(2.6), None] {
            assert!(
                (bumpy.trace_start(given) - between_2_and_4).abs() < 1e-12,
                "{given:?}"
            );
        }
    }

    fn bumpy() -> Gap {
        Gap {
            name: "bumpy",
            particular: &BUMPY,
            seed: None,
        }
    }

    /// Issue 73: the exact zero-force state on a gap no circle solves,
    /// with no model to start from (the test's gap has no seed): at ρ = 1
    /// the cylinders' state at the circle's ā for that force continued in
    /// the gap and traced to it (route `from_cylinders`), at 0.8 continued
    /// in ρ from there; held to the states the command line finds from the
    /// loaded bumpy:4 at the same force (route `from_model`, a second route:
    /// `thinjkr exact zero-force --rho R --gap bumpy`), to 1e-9. At F̄ = −2
    /// and −3 the walk in the gap at the circle's ā folds in t (t = 0.19 and
    /// 0.36 at ρ = 1) and the route ends with that error, which the other
    /// routes follow.
    #[test]
    fn the_exact_zero_force_on_a_gap_no_circle_solves_by_two_routes() {
        for (rho, a_bar, delta_bar, route) in [
            (
                1.0,
                2.5437099245,
                1.3616289228,
                crate::exact::Route::FromCylinders,
            ),
            (
                0.8,
                2.5375140763,
                1.4126230628,
                crate::exact::Route::ContinuedInRho,
            ),
        ] {
            let st = crate::exact::resolve::at_resolved_on(
                bumpy(),
                rho,
                crate::control::Hold::Force(0.0),
            )
            .unwrap();
            assert_eq!(st.route, route, "{rho}");
            assert!((st.a_bar - a_bar).abs() < 1e-9, "{rho}: {}", st.a_bar);
            assert!(
                (st.delta_bar - delta_bar).abs() < 1e-9,
                "{rho}: {}",
                st.delta_bar
            );
        }
    }

    /// Issue 73: the exact pull-off on a gap no circle solves (the bumpy
    /// gap, φ̄ = X²/2 + μY²/2 + X⁴/24) at ρ = 1 and 0.8, reached from the
    /// cylinders' state continued in the gap itself and traced downhill in
    /// F̄ to its minimum, against a second route that uses neither the walk's
    /// trace nor its events: Brent's minimum of F̄(ā), each ā a state by
    /// Newton at that ā from the last, over ā ± 0.03 around it. The two
    /// agree to 1e-9 in F̄ and 1e-5 in ā (F̄ is flat there: ā's error
    /// enters F̄ squared). The pull-offs are written in docs/exact.md
    /// ("A gap no circle solves").
    #[test]
    fn the_exact_pull_off_on_a_gap_no_circle_solves_is_the_least_force() {
        for (rho, force, a_bar) in [
            (1.0, -4.0799495862, 2.048533),
            (0.8, -3.6247387220, 2.090889),
        ] {
            let (st, _) = crate::exact::pull_off_resolved_on(bumpy(), rho).unwrap();
            assert_eq!(st.route, crate::exact::Route::FromCylinders, "{rho}");
            assert!(st.bc_error < 1e-9, "{rho}: bc {}", st.bc_error);
            let ex = crate::exact::Exact::on(bumpy(), rho, st.truncation).unwrap();
            let near = std::cell::RefCell::new(st.clone());
            let f = |a: f64| {
                let s = ex.solve_from(a, &near.borrow()).unwrap();
                let f = s.force_bar;
                *near.borrow_mut() = s;
                f
            };
            let a_min = crate::model::brent_minimum(f, st.a_bar - 0.03, st.a_bar + 0.03, 1e-7);
            let f_min = f(a_min);
            assert!(
                (f_min - st.force_bar).abs() < 1e-9 * st.force_bar.abs(),
                "{rho}: {f_min} against {}",
                st.force_bar
            );
            assert!(
                (a_min - st.a_bar).abs() < 1e-5,
                "{rho}: {a_min} against {}",
                st.a_bar
            );
            // the numbers docs/exact.md quotes
            assert!(
                (st.force_bar - force).abs() < 1e-9,
                "{rho}: {}",
                st.force_bar
            );
            assert!((st.a_bar - a_bar).abs() < 1e-6, "{rho}: {}", st.a_bar);
        }
    }

    /// Issue 73, item 4: a route started from a model names the model
    /// that seeded it; on the cylinders' gap conformal:8, as the route's
    /// own words always did.
    #[test]
    fn a_route_from_a_model_names_the_seeding_model() {
        use crate::exact::Route;
        for route in [
            Route::FromModel,
            Route::AboveModelPullOff,
            Route::FromScreen,
        ] {
            assert_eq!(route.to_string(), route.words("conformal:8"));
            let w = route.words("bumpy:3");
            assert!(w.contains("bumpy:3") && !w.contains("conformal:8"), "{w}");
        }
        assert_eq!(
            Route::FromCylinders.words("bumpy:3"),
            Route::FromCylinders.to_string()
        );
    }

    /// Issue 73: the exact pull-off on the bumpy gap at ρ = 1, 0.8 and
    /// 0.5, and with THINJKR_BUMPY_SCAN=ρ the states at fixed ā on either
    /// side of the start continued in the gap from ā = THINJKR_BUMPY_A
    /// (default: the trace's start).
    #[test]
    #[ignore = "exploration: prints the exact pull-off on the bumpy gap"]
    fn explore_the_pull_off_on_the_bumpy_gap() {
        if let Ok(r) = std::env::var("THINJKR_BUMPY_SCAN") {
            let rho: f64 = r.parse().unwrap();
            let ex =
                crate::exact::Exact::on(bumpy(), rho, crate::exact::Truncation::with_modes(48))
                    .unwrap();
            let a0: f64 =
                std::env::var("THINJKR_BUMPY_A").map_or(ex.trace_start(), |v| v.parse().unwrap());
            let start = ex.continued_in_the_gap(a0).unwrap();
            for dir in [1.0, -1.0] {
                let mut near = start.clone();
                for k in 1..40 {
                    let a = start.a_bar + dir * 0.02 * k as f64;
                    match ex.solve_from(a, &near) {
                        Ok(st) => {
                            println!(
                                "\na {:.3} F {:.8} s {:.5} delta {:.5} bc {:.1e} dev {:.1e}",
                                st.a_bar,
                                st.force_bar,
                                st.s,
                                st.delta_bar,
                                st.bc_error,
                                st.deviation_from_ellipse
                            );
                            near = st;
                        }
                        Err(e) => {
                            println!("\na {a:.3}: {e}");
                            break;
                        }
                    }
                }
            }
            return;
        }
        for rho in [1.0, 0.8, 0.5] {
            let clock = std::time::Instant::now();
            match crate::exact::pull_off_resolved_on(bumpy(), rho) {
                Ok((st, _)) => println!(
                    "\nrho {rho}: F {:.10} a {:.6} s {:.6} delta {:.8} bc {:.1e} modes {} route {} ({:.1} s)",
                    st.force_bar,
                    st.a_bar,
                    st.s,
                    st.delta_bar,
                    st.bc_error,
                    st.truncation.modes,
                    st.route,
                    clock.elapsed().as_secs_f64()
                ),
                Err(e) => println!("\nrho {rho}: {e}"),
            }
        }
    }

    /// Issue 72: coefficients near i64::MAX, whose exact sum of ΔP₁'s terms
    /// overflows i128, are refused (they panicked in a debug build and
    /// wrapped in a release one).
    #[test]
    fn coefficients_whose_exact_sum_overflows_are_refused() {
        const M: i64 = i64::MAX;
        const TERMS: &[Term] = &[term(2, 0, 0, 1, M - 1, M), term(0, 2, 0, 1, M - 3, M - 2)];
        let terms = TERMS;
        let gap = Gap {
            name: "huge",
            particular: terms,
            seed: None,
        };
        let e = gap.at(1.0).expect_err("refused");
        assert!(e.to_string().contains("ΔP1 = −1"), "{e}");
    }

    /// The cylinders' gap gives (22)–(25) and the neutral points
    /// ā³ = 4(n − 1), and its polynomials are those of the paper's gap.
    #[test]
    fn the_cylinders_gap_gives_the_closed_forms_of_the_circle() {
        let g = Gap::CYLINDERS.at(1.0).unwrap();
        assert!(g.is_radial());
        for a in [0.7, 1.5, 2.3, 3.1] {
            let d = a * a / 4.0 - 2.0 / a;
            assert!((g.circle_delta(a) - d).abs() < 1e-13 * (1.0 + d.abs()));
            let f = std::f64::consts::PI * (a.powi(6) - 24.0 * a.powi(3)) / 96.0;
            assert!(
                (g.circle_force(a) - f).abs() < 1e-12 * (1.0 + f.abs()),
                "{a}"
            );
            assert!((g.neutral_measure(a) - a.powi(3) / 4.0).abs() < 1e-13 * a.powi(3));
        }
        for n in [2usize, 4, 6, 10] {
            let a_n = (4.0 * (n as f64 - 1.0)).cbrt();
            assert!((g.neutral_point(n) - a_n).abs() < 1e-14 * a_n, "{n}");
        }
        let g = Gap::CYLINDERS.at(0.5).unwrap();
        assert!(!g.is_radial());
        let (x, y, d) = (0.9, -1.3, 0.7);
        let phi = x * x / 2.0 + y * y / (2.0 * 0.5);
        assert!((g.phi(x, y) - phi).abs() < 1e-14);
        let p = x.powi(4) / 24.0 + y.powi(4) / 12.0 - d * (x * x + y * y) / 4.0;
        assert!((g.p(x, y, d) - p).abs() < 1e-14);
        // W: ∂W/∂X = w(φ̄ − δ̄) against a central difference of W
        let h = 1e-5;
        let [_, wx, wy, wd] = g.force_potential(x, y, d);
        let w = |x: f64, y: f64, d: f64| g.force_potential(x, y, d)[0];
        assert!((wx - (w(x + h, y, d) - w(x - h, y, d)) / (2.0 * h)).abs() < 1e-8);
        assert!((wy - (w(x, y + h, d) - w(x, y - h, d)) / (2.0 * h)).abs() < 1e-8);
        assert!((wd - (w(x, y, d + h) - w(x, y, d - h)) / (2.0 * h)).abs() < 1e-8);
        assert!((wx - (x * x + y * y) / 4.0 * (phi - d)).abs() < 1e-14);
    }

    use super::QUARTIC;

    /// At ρ = 1 the quartic gap is r⁴/8, and the axisymmetric problem
    /// (1/r)(r p′)′ = r⁴/8 − δ̄, p(ā) = 0, p′(ā) = 1 has
    /// p = r⁶/288 − δ̄r²/4 + C, so δ̄ = ā⁴/24 − 2/ā and
    /// F̄ = 2π∫p r dr = π(ā⁸ − 96ā³)/384, with its minimum (the
    /// load-controlled pull-off) at ā⁵ = 36. Three routes agree: this
    /// closed form, the gap's disk means ([`GapAt::circle_delta`],
    /// [`GapAt::circle_force`]) and the exact solver's boundary integral
    /// solution on the circle (Newton from the circle at ρ = 1), to 1e-10.
    /// Its neutral points are ā⁵ = 12(n − 1), and the gap is the one
    /// given: ΔP = (X² + μY²)²/8 − δ̄ at a ρ below 1.
    #[test]
    fn the_quartic_gap_at_rho_1_has_the_circles_of_its_closed_form() {
        let quartic = Gap {
            name: "quartic",
            particular: &QUARTIC,
            seed: None,
        };
        assert!(quartic != Gap::CYLINDERS);
        let at = quartic.at(0.6).unwrap();
        let (x, y, mu): (f64, f64, f64) = (1.1, -0.7, 1.0 / 0.6);
        let want = (x * x + mu * y * y).powi(2) / 8.0;
        assert!(
            (at.phi(x, y) - want).abs() < 1e-14,
            "{} vs {want}",
            at.phi(x, y)
        );
        assert!(!at.is_radial());
        let g = quartic.at(1.0).unwrap();
        assert!(g.is_radial());
        let closed_delta = |a: f64| a.powi(4) / 24.0 - 2.0 / a;
        let closed_force = |a: f64| std::f64::consts::PI * (a.powi(8) - 96.0 * a.powi(3)) / 384.0;
        let ex =
            super::super::Exact::on(quartic, 1.0, super::super::Truncation::with_modes(8)).unwrap();
        for a in [1.6, 2.0, 2.5] {
            assert!((g.circle_delta(a) - closed_delta(a)).abs() < 1e-13 * (1.0 + a.powi(4)));
            assert!((g.circle_force(a) - closed_force(a)).abs() < 1e-12 * (1.0 + a.powi(8)));
            let st = ex.from_circle(a).unwrap();
            assert!(st.bc_error < 1e-10, "{a}: bc {}", st.bc_error);
            assert!((st.s - 1.0).abs() < 1e-12);
            assert!(
                (st.delta_bar - closed_delta(a)).abs() < 1e-10,
                "{a}: {}",
                st.delta_bar
            );
            let f = closed_force(a);
            assert!(
                (st.force_bar - f).abs() < 1e-10 * f.abs().max(1.0),
                "{a}: {} vs {f}",
                st.force_bar
            );
        }
        let (a_po, f_po) = crate::exact::branch::circle_pull_off(&g);
        let a5 = 36f64.powf(0.2);
        assert!((a_po - a5).abs() < 1e-7, "{a_po} vs {a5}");
        assert!((f_po - closed_force(a5)).abs() < 1e-12);
        for n in [2usize, 4, 6] {
            let a_n = (12.0 * (n as f64 - 1.0)).powf(0.2);
            assert!((g.neutral_point(n) - a_n).abs() < 1e-13 * a_n, "{n}");
        }
    }

    /// A particular solution whose δ̄ part does not solve ΔP₁ = −1, or with
    /// an odd power, is refused with the gap's name.
    #[test]
    fn a_wrong_particular_solution_is_refused() {
        static WRONG: [Term; 2] = [term(4, 0, 0, 0, 1, 24), term(2, 0, 0, 1, -1, 4)];
        let e = Gap {
            name: "wrong",
            particular: &WRONG,
            seed: None,
        }
        .at(1.0)
        .unwrap_err();
        assert!(e.to_string().contains("the gap wrong"), "{e}");
        static ODD: [Term; 1] = [term(3, 0, 0, 0, 1, 6)];
        assert!(Gap {
            name: "odd",
            particular: &ODD,
            seed: None,
        }
        .at(1.0)
        .is_err());
        static NO_DBAR: [Term; 1] = [term(4, 0, 0, 0, 1, 24)];
        assert!(Gap {
            name: "no_dbar",
            particular: &NO_DBAR,
            seed: None,
        }
        .at(1.0)
        .is_err());
        assert!(Gap {
            name: "empty",
            particular: &[],
            seed: None,
        }
        .at(1.0)
        .is_err());
    }
}
