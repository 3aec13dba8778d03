//! The contact of the coatings with a sharp edge on a doubly symmetric,
//! convex domain: the way to JKR's limit at ρ < 1 for coatings whose
//! process zone the grid's cohesive law cannot make small against h
//! (issue 71): the bilateral problem (the pressure on a given domain at a
//! given approach) on the half-space or on the coatings, its force and
//! its stress-intensity factor along the edge, the free edge at an
//! approach or of a size (Griffith's condition), both pull-offs and the
//! walk over sizes of a curve, which the model layer answers with
//! (`plane::by_sharp_edge`).
//!
//! The domain is the level set Φ < 1 of a polynomial,
//! Φ = (1 + e₀)(ξ² + η²) + Σ_{m≥1} e_m Re (ξ + iη)^2m, ξ = X/a, η = Y/b
//! ([`Domain`]; with no modes the ellipse (a, b)). The pressure is
//! p̄ = q/√(1 − Φ), the edge's square root built in, with q a polynomial
//! even in X and in Y: the functions p_n^(m)(2Φ − 1) Re (ξ + iη)^2m,
//! orthogonal in each angular order m, of total degree below 2 `radial`
//! (on an ellipse Φ = s² = X²/a² + Y²/b², and Galin's theorem makes a
//! quadratic gap's pressure exactly q of degree 2). Every function of
//! the solver is smooth on the domain, and its quadratures converge
//! spectrally.
//!
//! The displacement of the half-space pair in the units (17) is
//! w̄ = (1/2πβ) ∫ p̄(x′)/|x − x′| dA′ (β = E*/2 there). About each point it
//! is taken in polar coordinates, where the 1/r cancels against r dr, as
//! lines through the point: along each, the chord of Ω, t = c + h cos ψ
//! takes the edge's square roots at both ends away (the midpoint rule in
//! ψ), and the trapezoidal rule in the line's angle. The contact
//! condition w̄ = δ̄ − φ̄ is collocated at tensor nodes (Gauss–Legendre in
//! Φ, equally spaced elliptic angles in the quarter) and solved in the
//! least squares (more nodes than functions).
//!
//! Near the edge p̄ ≈ −K/√(2πd), d the distance to it, so that
//! K = −q √(2π/|∇Φ|) there; Griffith's condition is K = √(2β) (the
//! energy release rate K²/2β equals Δγ, 1 in these units).
//!
//! Coatings of finite thickness add the base share c(r) of their
//! compliance (`grid::kernel`'s table, smooth on the scale of h), whose
//! integral over the contact is a product rule in (α, θ), Φ = sin² α on
//! the ray of elliptic angle θ ([`Sources`]).
//!
//! Owns: `Domain`, `Bilateral`, `Sources`, `Resolution`, `SharpState`,
//! `Contact` (a state at an approach, the pull-off), `pull_off_ladder`,
//! `pull_off_ladder_from`, `HeldAt` and `held_ladder` (a state at a force,
//! an approach or a size, the least approach), `slopes_in_size`,
//! `size_walk` (a curve's states). May use: `model` (Brent's minimum), `newton` (the stop
//! request), the parent (`layer`: the coatings, `grid::kernel`'s table of
//! the base share, and the Illinois method), `quadrature` (Gauss–Legendre),
//! `error`.

use super::grid::kernel::BaseShare;
use super::Layers;
use crate::error::{Error, Result};
use crate::quadrature::GaussLegendre;
use nalgebra::{DMatrix, DVector};
use rayon::prelude::*;
use rustfft::num_complex::Complex64;
use std::f64::consts::PI;

/// A doubly symmetric convex domain as the level set Φ < 1 of the
/// polynomial Φ = (1 + e₀)(ξ² + η²) + Σ_{m≥1} e_m Re (ξ + iη)^2m in
/// ξ = X/a, η = Y/b: smooth everywhere, so that every function of the
/// solver built on it (the pressure's basis, its square root's argument
/// 1 − Φ along a line) is a polynomial and the quadratures converge
/// spectrally. (A star map x = s z(θ) with a radius f(θ) that is not
/// constant is not smooth at the centre: the lines through it converged
/// only as the square of their points, and the edge's higher modes
/// drove the residual through that error.) Along the ray of elliptic
/// angle θ, X = a r cos θ, Y = b r sin θ, Φ is P(u) = Σ p_m u^m in u = r²
/// ([`Domain::ray`]). With no modes it is the ellipse with semi-axes `a`
/// (along X) and `b`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Domain {
    pub(crate) a: f64,
    pub(crate) b: f64,
    pub(crate) modes: Vec<f64>,
}

/// Φ and its first and second derivatives in (ξ, η) at a point.
struct Level {
    phi: f64,
    d: [f64; 2],
    dd: [f64; 3],
}

impl Domain {
    /// The ellipse with semi-axes `a` and `b`.
    pub(crate) fn ellipse(a: f64, b: f64) -> Domain {
        Domain {
            a,
            b,
            modes: Vec::new(),
        }
    }

    /// Φ at (x, y).
    fn phi(&self, x: f64, y: f64) -> f64 {
        let (xi, eta) = (x / self.a, y / self.b);
        let w2 = Complex64::new(xi * xi - eta * eta, 2.0 * xi * eta);
        let mut phi = (1.0 + self.modes.first().copied().unwrap_or(0.0)) * (xi * xi + eta * eta);
        let mut power = Complex64::new(1.0, 0.0);
        for &e in self.modes.iter().skip(1) {
            power *= w2;
            phi += e * power.re;
        }
        phi
    }

    /// Φ with its derivatives in (ξ, η) at (ξ, η).
    fn level(&self, xi: f64, eta: f64) -> Level {
        let w = Complex64::new(xi, eta);
        let w2 = w * w;
        let e0 = 1.0 + self.modes.first().copied().unwrap_or(0.0);
        let mut l = Level {
            phi: e0 * (xi * xi + eta * eta),
            d: [2.0 * e0 * xi, 2.0 * e0 * eta],
            dd: [2.0 * e0, 0.0, 2.0 * e0],
        };
        // w^(2m−2) and w^(2m−1)
        let mut below = Complex64::new(1.0, 0.0);
        for (m, &e) in self.modes.iter().enumerate().skip(1) {
            let k = 2.0 * m as f64;
            let odd = below * w;
            l.phi += e * (odd * w).re;
            l.d[0] += e * k * odd.re;
            l.d[1] -= e * k * odd.im;
            let second = e * k * (k - 1.0);
            l.dd[0] += second * below.re;
            l.dd[1] -= second * below.im;
            l.dd[2] -= second * below.re;
            below *= w2;
        }
        l
    }

    /// P's coefficients p_1 … p_M along the ray of elliptic angle θ (index
    /// m − 1): p_1 = 1 + e₀ + e₁ cos 2θ, p_m = e_m cos 2mθ.
    fn ray(&self, theta: f64) -> Vec<f64> {
        let mut p: Vec<f64> = (0..self.modes.len().max(2) - 1)
            .map(|k| {
                let m = k + 1;
                self.modes.get(m).copied().unwrap_or(0.0) * (2.0 * m as f64 * theta).cos()
            })
            .collect();
        p[0] += 1.0 + self.modes.first().copied().unwrap_or(0.0);
        p
    }

    /// u = r² where P(u) = `level` along the ray of angle θ (0 < level ≤
    /// 1), and P′(u): Newton's method kept inside a bracket. An error where
    /// P does not rise to the level.
    fn along_ray(&self, theta: f64, level: f64) -> Result<(f64, f64)> {
        let p = self.ray(theta);
        let eval = |u: f64| {
            let (mut v, mut dv) = (0.0, 0.0);
            for (k, &pk) in p.iter().enumerate().rev() {
                dv = dv * u + (k + 1) as f64 * pk;
                v = v * u + pk;
            }
            (v * u, dv)
        };
        let (mut lo, mut hi) = (0.0, level / p[0].max(0.25));
        let mut steps = 0;
        while eval(hi).0 < level {
            (lo, hi) = (hi, 2.0 * hi);
            steps += 1;
            if steps > 8 {
                return Err(Error::NoState(
                    "the sharp edge left the near-elliptic shape (its level set does not close)"
                        .into(),
                ));
            }
        }
        let mut u = 0.5 * (lo + hi);
        for _ in 0..100 {
            let (v, dv) = eval(u);
            if v < level {
                lo = u;
            } else {
                hi = u;
            }
            let next = u - (v - level) / dv;
            let next = if dv > 0.0 && next > lo && next < hi {
                next
            } else {
                0.5 * (lo + hi)
            };
            if (next - u).abs() <= 1e-15 * u || hi - lo <= 1e-15 * hi {
                u = next;
                break;
            }
            u = next;
        }
        Ok((u, eval(u).1))
    }

    /// The point at level `level` on the ray of angle θ, and P′ there.
    fn at_level(&self, theta: f64, level: f64) -> Result<([f64; 2], f64)> {
        let (u, dp) = self.along_ray(theta, level)?;
        let r = u.sqrt();
        let (sn, cs) = theta.sin_cos();
        Ok(([self.a * r * cs, self.b * r * sn], dp))
    }

    /// The edge's point at elliptic angle θ.
    pub(crate) fn edge(&self, theta: f64) -> Result<[f64; 2]> {
        Ok(self.at_level(theta, 1.0)?.0)
    }

    /// |∇Φ| in (X, Y) at the point (x, y): near the edge 1 − Φ is |∇Φ|
    /// times the distance to it.
    fn slope(&self, x: f64, y: f64) -> f64 {
        let l = self.level(x / self.a, y / self.b);
        (l.d[0] / self.a).hypot(l.d[1] / self.b)
    }

    /// How far the ray from (x, y) inside the domain at angle `phi` runs
    /// before it leaves it: where Φ reaches 1 along it (the layer's root
    /// finder; the domain is convex, so the ray leaves it once).
    fn exit(&self, x: f64, y: f64, phi: f64) -> Result<f64> {
        let (e_y, e_x) = phi.sin_cos();
        let level = |r: f64| Ok(self.phi(x + r * e_x, y + r * e_y));
        super::root(level, 0.5 * self.a.min(self.b), 1.0, "edge along a ray")
    }

    /// The same edge in the coordinates of the ellipse (`a`, `b`) with
    /// `count` modes ([`Domain::through`] 64 points of the edge's
    /// quarter). Between rungs the half-widths become the ellipse's, so
    /// that the modes stay small where the contact moves far from its first
    /// guess.
    pub(crate) fn rebased(&self, a: f64, b: f64, count: usize) -> Result<Domain> {
        let points = 64;
        let edge = (0..points)
            .map(|k| self.edge(0.5 * PI * (k as f64 + 0.5) / points as f64))
            .collect::<Result<Vec<_>>>()?;
        Domain::through(&edge, a, b, count)
    }

    /// The domain in the coordinates of the ellipse (`a`, `b`) with `count`
    /// modes whose edge passes nearest `points` (an outline's first
    /// quadrant): the modes fitted in the least squares to Φ = 1 there (Φ
    /// is linear in them).
    pub(crate) fn through(points: &[[f64; 2]], a: f64, b: f64, count: usize) -> Result<Domain> {
        let count = count.max(1);
        let mut m = DMatrix::zeros(points.len(), count);
        let mut rhs = DVector::zeros(points.len());
        for (k, &[x, y]) in points.iter().enumerate() {
            let (xi, eta) = (x / a, y / b);
            let r2 = xi * xi + eta * eta;
            let w2 = Complex64::new(xi * xi - eta * eta, 2.0 * xi * eta);
            m[(k, 0)] = r2;
            let mut power = Complex64::new(1.0, 0.0);
            for j in 1..count {
                power *= w2;
                m[(k, j)] = power.re;
            }
            rhs[k] = 1.0 - r2;
        }
        let modes = m
            .svd(true, true)
            .solve(&rhs, 1e-12)
            .map_err(|_| Error::NoState("the sharp edge could not be rebased".into()))?;
        Ok(Domain {
            a,
            b,
            modes: modes.iter().copied().collect(),
        })
    }

    /// Whether the domain is what the solver assumes, checked at 65 angles
    /// of the quarter: Φ rises along every ray to the edge (P′ > 0 at 16
    /// points), the edge's radius r is between ½ and 2 (near the ellipse
    /// (a, b)), and the edge is convex (Φ's Hessian positive along it). An
    /// error naming what fails; else the largest |x| on the edge.
    fn checked(&self) -> Result<f64> {
        let mut largest: f64 = 0.0;
        for k in 0..=64 {
            let theta = 0.5 * PI * k as f64 / 64.0;
            let (u, _) = self.along_ray(theta, 1.0)?;
            let p = self.ray(theta);
            let rises = (1..=16).all(|j| {
                let v = u * j as f64 / 16.0;
                p.iter()
                    .enumerate()
                    .rev()
                    .fold(0.0, |acc, (i, &pi)| acc * v + (i + 1) as f64 * pi)
                    > 0.0
            });
            let r = u.sqrt();
            let (sn, cs) = theta.sin_cos();
            let l = self.level(r * cs, r * sn);
            let [px, py] = l.d;
            let curvature = l.dd[2] * px * px - 2.0 * l.dd[1] * px * py + l.dd[0] * py * py;
            if !rises || !(0.2..=5.0).contains(&r) || curvature <= 0.0 {
                return Err(Error::NoState(
                    "the sharp edge left the convex near-elliptic shape".into(),
                ));
            }
            largest = largest.max(r * (self.a * cs).hypot(self.b * sn));
        }
        Ok(largest)
    }
}

/// The three-term recurrence of the polynomials orthonormal on [−1, 1]
/// with the weight (1 − t)^α (1 + t)^β (Jacobi's, up to a constant
/// factor): t p_n = b_{n+1} p_{n+1} + a_n p_n + b_n p_{n−1}, p_0 = 1;
/// (a_n, b_{n+1}) for n < `count`.
fn jacobi_recurrence(alpha: f64, beta: f64, count: usize) -> Vec<(f64, f64)> {
    let ab = alpha + beta;
    (0..count)
        .map(|n| {
            let n = n as f64;
            let a = if n == 0.0 {
                (beta - alpha) / (ab + 2.0)
            } else {
                (beta * beta - alpha * alpha) / ((2.0 * n + ab) * (2.0 * n + ab + 2.0))
            };
            let k = n + 1.0;
            let b = 2.0 / (2.0 * k + ab)
                * (k * (k + alpha) * (k + beta) * (k + ab)
                    / ((2.0 * k + ab - 1.0) * (2.0 * k + ab + 1.0)))
                    .sqrt();
            (a, b)
        })
        .collect()
}

/// p_0 … p_{n−1} of the recurrence `rec` at t.
fn orthonormal(rec: &[(f64, f64)], t: f64, out: &mut [f64]) {
    let (mut below, mut here) = (0.0, 1.0);
    let mut b_here = 0.0;
    for (v, &(a, b)) in out.iter_mut().zip(rec) {
        *v = here;
        let next = ((t - a) * here - b_here * below) / b;
        (below, here, b_here) = (here, next, b);
    }
}

/// The bilateral problem on a domain: the basis, its quadrature and the
/// collocation matrix.
pub(crate) struct Bilateral {
    domain: Domain,
    /// Radial functions of the angular order 0 (of order m, `radial` − m:
    /// q is a polynomial of degree below 2 `radial` in (X, Y)), and angular
    /// orders.
    radial: usize,
    angular: usize,
    /// E*/2 of the pair in the units (17).
    beta: f64,
    /// Points along each line through a point, and rays (two a line).
    along: usize,
    rays: usize,
    /// The base share of coatings of finite thickness, where there are
    /// coatings (else the half-space).
    base: Option<Base>,
    /// The collocation nodes (x, y), `radial` × `angular` of them, and the
    /// matrix (the displacement at node i of basis function j) by its QR
    /// factors, Qᵀ and R: fewer functions than nodes, solved in the least
    /// squares.
    nodes: Vec<(f64, f64)>,
    q_t: DMatrix<f64>,
    r: DMatrix<f64>,
    /// The radial functions' recurrence for each angular order m.
    radial_rec: Vec<Vec<(f64, f64)>>,
}

impl Bilateral {
    /// The problem of the half-space pair of modulus `beta` on `domain`
    /// with `radial` radial functions of angular order 0 and `angular`
    /// orders (`radial` × `angular` nodes),
    /// `along` points along each of `rays` / 2 lines (the tests' closed
    /// forms).
    #[cfg(test)]
    pub(crate) fn new(
        domain: Domain,
        beta: f64,
        radial: usize,
        angular: usize,
        along: usize,
        rays: usize,
    ) -> Result<Bilateral> {
        domain.checked()?;
        Bilateral::with_base(domain, beta, None, radial, angular, along, rays)
    }

    /// [`Bilateral::new`] for the coatings `layers` (their β) at the
    /// resolution `res` (its basis, lines and the base share's sources;
    /// the tests' circles).
    #[cfg(test)]
    pub(crate) fn on_layers(
        domain: Domain,
        layers: &Layers,
        res: &Resolution,
    ) -> Result<Bilateral> {
        let largest = domain.checked()?;
        let base = Base::new(&domain, BaseShare::new(layers, 2.05 * largest), res.sources)?;
        Bilateral::with_base(
            domain,
            layers.beta(),
            Some(base),
            res.radial,
            res.angular,
            res.along,
            res.rays,
        )
    }

    #[allow(clippy::too_many_arguments)]
    fn with_base(
        domain: Domain,
        beta: f64,
        base: Option<Base>,
        radial: usize,
        angular: usize,
        along: usize,
        rays: usize,
    ) -> Result<Bilateral> {
        if radial < angular {
            return Err(Error::NoState(format!(
                "the sharp-edge solver needs at least as many radial functions as angular orders ({radial} < {angular})"
            )));
        }
        let s2_nodes = GaussLegendre::new(radial);
        let mut nodes = Vec::with_capacity(radial * angular);
        for l in 0..angular {
            let theta = (l as f64 + 0.5) * 0.5 * PI / angular as f64;
            for &x in &s2_nodes.nodes {
                let ([x, y], _) = domain.at_level(theta, 0.5 * (1.0 + x))?;
                nodes.push((x, y));
            }
        }
        let mut b = Bilateral {
            domain,
            radial,
            angular,
            beta,
            along,
            rays,
            base,
            nodes: Vec::new(),
            q_t: DMatrix::zeros(0, 0),
            r: DMatrix::zeros(0, 0),
            radial_rec: (0..angular)
                .map(|m| jacobi_recurrence(-0.5, 2.0 * m as f64, radial - m))
                .collect(),
        };
        let n = b.unknowns();
        let mut m = DMatrix::zeros(nodes.len(), n);
        let rows: Vec<DVector<f64>> = nodes
            .par_iter()
            .map(|&(x, y)| b.displacement_of_basis(x, y))
            .collect::<Result<_>>()?;
        for (i, row) in rows.iter().enumerate() {
            m.row_mut(i).copy_from(&row.transpose());
        }
        if let Some(base) = &b.base {
            m += base.displacement_of_basis(&b, &nodes);
        }
        let qr = m.qr();
        let r = qr.r();
        let scale = r.diagonal().amax();
        if r.diagonal().iter().any(|d| !(d.abs() > 1e-13 * scale)) {
            return Err(Error::NoState(
                "the collocation matrix of the sharp-edge solver is singular".into(),
            ));
        }
        b.nodes = nodes;
        b.q_t = qr.q().transpose();
        b.r = r;
        Ok(b)
    }

    /// The basis functions' q at (x, y), in blocks of angular order m:
    /// p_n^(m)(2Φ − 1) Re (ξ + iη)^2m, n < `radial` − m (on an ellipse
    /// s^2m p_n^(m)(2s² − 1) cos 2mθ). The p_n^(m) are orthonormal with the
    /// weight (1 − t)^(−½) (1 + t)^2m, so that one order's functions are
    /// orthogonal over the ellipse with the edge's weight 1/√(1 − s²), and
    /// the total degree stays below 2 `radial`. (With Legendre's
    /// polynomials and `radial` functions of every order, combinations hid
    /// near the centre under s^2m, and the collocation's round-off reached
    /// K at 1e-6; now about 1e-12.) Returns Φ.
    fn basis(&self, x: f64, y: f64, out: &mut [f64]) -> f64 {
        let phi = self.domain.phi(x, y);
        let (xi, eta) = (x / self.domain.a, y / self.domain.b);
        let w2 = Complex64::new(xi * xi - eta * eta, 2.0 * xi * eta);
        let mut power = Complex64::new(1.0, 0.0);
        let mut start = 0;
        for rec in &self.radial_rec {
            let block = &mut out[start..start + rec.len()];
            start += rec.len();
            orthonormal(rec, 2.0 * phi - 1.0, block);
            for v in block.iter_mut() {
                *v *= power.re;
            }
            power *= w2;
        }
        phi
    }

    /// w̄ at (x, y) of each basis function's pressure: the polar integral
    /// about (x, y) as lines through it, φ in [0, π), each the chord of Ω
    /// from −ϱ₋ to ϱ₊, on which p̄ has the edge's square root at both ends:
    /// t = c + h cos ψ takes both away (Gauss–Chebyshev, the midpoint rule
    /// in ψ, `along` points), and the trapezoidal rule in φ (`rays` / 2).
    pub(crate) fn displacement_of_basis(&self, x: f64, y: f64) -> Result<DVector<f64>> {
        let n = self.unknowns();
        let mut w = DVector::zeros(n);
        let mut q = vec![0.0; n];
        let lines = self.rays / 2;
        let d_phi = PI / lines as f64;
        let points = self.along;
        let d_psi = PI / points as f64;
        for k in 0..lines {
            let phi = (k as f64 + 0.5) * d_phi;
            let (e_y, e_x) = phi.sin_cos();
            let (ahead, behind) = (
                self.domain.exit(x, y, phi)?,
                self.domain.exit(x, y, phi + PI)?,
            );
            let (mid, half) = (0.5 * (ahead - behind), 0.5 * (ahead + behind));
            for i in 0..points {
                let psi = (i as f64 + 0.5) * d_psi;
                let t = mid + half * psi.cos();
                let phi = self.basis(x + t * e_x, y + t * e_y, &mut q);
                let weight = d_psi * half * psi.sin() / (1.0 - phi).max(f64::MIN_POSITIVE).sqrt();
                for (wj, qj) in w.iter_mut().zip(&q) {
                    *wj += weight * qj;
                }
            }
        }
        Ok(w * (d_phi / (2.0 * PI * self.beta)))
    }

    /// The coefficients of q for the displacement `target` (a function of
    /// (x, y)) at the nodes.
    pub(crate) fn solve(&self, target: impl Fn(f64, f64) -> f64) -> Result<DVector<f64>> {
        let rhs = DVector::from_iterator(
            self.nodes.len(),
            self.nodes.iter().map(|&(x, y)| target(x, y)),
        );
        self.r
            .solve_upper_triangular(&(&self.q_t * rhs))
            .ok_or_else(|| {
                Error::NoState(
                    "the collocation system of the sharp-edge solver has no solution".into(),
                )
            })
    }

    /// The number of basis functions: `radial` − m of each order m.
    fn unknowns(&self) -> usize {
        (0..self.angular).map(|m| self.radial - m).sum()
    }

    /// The stress-intensity factor K at the edge's point of elliptic angle
    /// θ: near the edge 1 − Φ ≈ |∇Φ| d, d the distance to it, so
    /// p̄ ≈ q/√(|∇Φ| d) and K = −q √(2π/|∇Φ|).
    pub(crate) fn intensity(&self, c: &DVector<f64>, theta: f64) -> Result<f64> {
        let [x, y] = self.domain.edge(theta)?;
        let mut q = vec![0.0; c.len()];
        self.basis(x, y, &mut q);
        let q: f64 = q.iter().zip(c.iter()).map(|(a, b)| a * b).sum();
        Ok(-q * (2.0 * PI / self.domain.slope(x, y)).sqrt())
    }

    /// F̄ = ∫ p̄ dA of the coefficients `c`: on the ray of angle θ at
    /// Φ = P(r²) = 1 − v², dA/√(1 − Φ) = ab dv dθ / P′(r²) (on an ellipse
    /// P′ = 1); `points` Gauss–Legendre points in v and the trapezoidal
    /// rule in θ.
    pub(crate) fn force(&self, c: &DVector<f64>, points: usize) -> Result<f64> {
        let rule = GaussLegendre::new(points);
        let mut q = vec![0.0; c.len()];
        let angles = 4 * points;
        let mut total = 0.0;
        for k in 0..angles {
            let theta = (k as f64 + 0.5) * 2.0 * PI / angles as f64;
            for (&t, &wt) in rule.nodes.iter().zip(&rule.weights) {
                let v = 0.5 * (1.0 + t);
                let ([x, y], dp) = self.domain.at_level(theta, 1.0 - v * v)?;
                self.basis(x, y, &mut q);
                total += 0.5 * wt / dp * q.iter().zip(c.iter()).map(|(a, b)| a * b).sum::<f64>();
            }
        }
        Ok(total * self.domain.a * self.domain.b * 2.0 * PI / angles as f64)
    }
}

/// The resolution of a state: the basis (`radial` × `angular`), the lines
/// through each node (`rays`, `along`), the base share's sources, and the
/// edge's modes e_0 … e_{shape − 1} ([`Domain`]), with as many angles of Griffith's
/// condition from θ = 0 to π/2.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Resolution {
    pub(crate) radial: usize,
    pub(crate) angular: usize,
    pub(crate) along: usize,
    pub(crate) rays: usize,
    pub(crate) sources: Sources,
    pub(crate) shape: usize,
}

/// A state with a sharp edge at ρ: its domain, approach δ̄, force F̄ and
/// the largest departure from Griffith's condition over the edge, |K/√(2β)
/// − 1| at 64 points of the quarter.
#[derive(Clone, Debug)]
pub(crate) struct SharpState {
    pub(crate) domain: Domain,
    pub(crate) delta_bar: f64,
    pub(crate) force_bar: f64,
    pub(crate) griffith_error: f64,
    /// The half-widths along X and Y.
    pub(crate) a_bar: f64,
    pub(crate) b_bar: f64,
}

/// A sharp-edge problem: the coatings at ρ with the gap (X² + Y²/ρ)/2 of
/// (1), at one resolution, and the base share's table, built once for
/// domains that reach no farther than `reach` from the centre.
pub(crate) struct Contact<'a> {
    layers: &'a Layers,
    rho: f64,
    res: Resolution,
    share: BaseShare,
    reach: f64,
}

/// How a state's unknowns make its approach and domain
/// ([`Contact::griffith_newton`]).
type Unknowns<'a> = dyn Fn(&DVector<f64>) -> Result<(f64, Domain)> + 'a;

/// What [`size_walk`] hands on at each size: the rungs' states and the
/// finest one's slopes.
type EachSize<'a> = dyn FnMut(&[SharpState], [f64; 2]) -> Result<()> + 'a;

/// How near Griffith's condition, |K/√(2β) − 1| at its angles, a state is
/// taken: the residual's round-off is near 1e-12 on near-circular
/// contacts.
const GRIFFITH_TOLERANCE: f64 = 1e-10;

/// Where no Newton step lowers the residual any more, below this it is
/// taken as the residual's round-off and the state is accepted (on an
/// elongated contact, aspect 0.25 at ρ = 0.07, it stalled at 1e-9 to
/// 2e-8; the force moves by about as much).
const GRIFFITH_FLOOR: f64 = 1e-7;

/// Newton's steps for one state, counting each Jacobian by differences as
/// one.
const NEWTON_STEPS: usize = 40;

impl<'a> Contact<'a> {
    /// The problem of `layers` at `rho` and resolution `res` for domains
    /// about `guess`: its table reaches 1.5 times `guess`'s edge.
    pub(crate) fn new(
        layers: &'a Layers,
        rho: f64,
        res: Resolution,
        guess: &Domain,
    ) -> Result<Contact<'a>> {
        let reach = 1.5 * guess.checked()?;
        Ok(Contact {
            layers,
            rho,
            res,
            share: BaseShare::new(layers, 2.05 * reach),
            reach,
        })
    }

    /// The pressure's coefficients on `domain` at approach `delta`, and
    /// the solver that gave them.
    fn pressure(&self, delta: f64, domain: &Domain) -> Result<(Bilateral, DVector<f64>)> {
        let largest = domain.checked()?;
        if largest > self.reach {
            return Err(Error::NoState(
                "the sharp edge grew beyond the reach of its base share's table".into(),
            ));
        }
        let base = Base::new(domain, self.share.clone(), self.res.sources)?;
        let res = &self.res;
        let solver = Bilateral::with_base(
            domain.clone(),
            self.layers.beta(),
            Some(base),
            res.radial,
            res.angular,
            res.along,
            res.rays,
        )?;
        let rho = self.rho;
        let c = solver.solve(|x, y| delta - 0.5 * (x * x + y * y / rho))?;
        Ok((solver, c))
    }

    /// K/√(2β) − 1 at the Griffith angles on `domain` at `delta`.
    fn griffith(&self, delta: f64, domain: &Domain) -> Result<DVector<f64>> {
        let target = (2.0 * self.layers.beta()).sqrt();
        let (solver, c) = self.pressure(delta, domain)?;
        griffith_angles(self.res.shape)
            .iter()
            .map(|&t| Ok(solver.intensity(&c, t)? / target - 1.0))
            .collect::<Result<Vec<f64>>>()
            .map(DVector::from_vec)
    }

    /// The state at approach `delta`: the edge's modes e_m (about
    /// `guess`'s a and b, from its modes) such that K = √(2β) at the
    /// Griffith angles, by [`Contact::griffith_newton`].
    fn edge_at(
        &self,
        delta: f64,
        guess: &Domain,
        jacobian: &mut Option<DMatrix<f64>>,
    ) -> Result<SharpState> {
        let shape = self.res.shape;
        let domain = |e: &DVector<f64>| {
            Ok((
                delta,
                Domain {
                    a: guess.a,
                    b: guess.b,
                    modes: e.iter().copied().collect(),
                },
            ))
        };
        let e = DVector::from_iterator(
            shape,
            (0..shape).map(|m| guess.modes.get(m).copied().unwrap_or(0.0)),
        );
        let what = format!("at delta = {}", crate::error::rounded(delta));
        self.griffith_newton(e, &domain, jacobian, &what)
    }

    /// The state of half-width `a_bar` along X: the approach δ̄ and the
    /// edge's modes e₁, e₂, … (about `guess`'s a and b, from its modes and
    /// from approach `delta`) such that K = √(2β) at the Griffith angles,
    /// e₀ set by the half-width (Φ = 1 at X = ā on the axis: (1 + e₀) t +
    /// Σ_{m≥1} e_m t^m = 1, t = (ā/a)²), by [`Contact::griffith_newton`].
    /// Regular through the fold of the branch in δ̄ (the pull-off under
    /// displacement control), where a state at a held approach is not.
    fn size_at(
        &self,
        a_bar: f64,
        delta: f64,
        guess: &Domain,
        jacobian: &mut Option<DMatrix<f64>>,
    ) -> Result<SharpState> {
        let shape = self.res.shape;
        let t = (a_bar / guess.a).powi(2);
        // v = (δ̄, e₁, …, e_{shape−1})
        let domain = |v: &DVector<f64>| {
            let higher: f64 = (1..shape).map(|m| v[m] * t.powi(m as i32)).sum();
            let mut modes = vec![(1.0 - higher) / t - 1.0];
            modes.extend(v.iter().skip(1));
            Ok((
                v[0],
                Domain {
                    a: guess.a,
                    b: guess.b,
                    modes,
                },
            ))
        };
        let v = DVector::from_iterator(
            shape,
            std::iter::once(delta)
                .chain((1..shape).map(|m| guess.modes.get(m).copied().unwrap_or(0.0))),
        );
        let what = format!("of size a = {}", crate::error::rounded(a_bar));
        self.griffith_newton(v, &domain, jacobian, &what)
    }

    /// The state whose unknowns `v` make its approach and domain through
    /// `make`, such that K = √(2β) at the Griffith angles, by Newton's
    /// method with Broyden's updates of the Jacobian, which starts from
    /// `jacobian` where given (the last state's) and is taken by forward
    /// differences where not, or where a step does not halve the residual;
    /// with a fresh Jacobian the step is halved until the residual falls.
    /// An error, naming the state by `what`, where it does not converge to
    /// [`GRIFFITH_TOLERANCE`] in [`NEWTON_STEPS`] (or stall below
    /// [`GRIFFITH_FLOOR`]).
    fn griffith_newton(
        &self,
        mut v: DVector<f64>,
        make: &Unknowns<'_>,
        jacobian: &mut Option<DMatrix<f64>>,
        what: &str,
    ) -> Result<SharpState> {
        let n = v.len();
        let residual = |v: &DVector<f64>| -> Result<DVector<f64>> {
            let (delta, domain) = make(v)?;
            self.griffith(delta, &domain)
        };
        let finish = |v: &DVector<f64>| -> Result<SharpState> {
            let (delta, domain) = make(v)?;
            self.state_on(delta, domain)
        };
        let mut r = residual(&v)?;
        for _ in 0..NEWTON_STEPS {
            crate::newton::check_stop()?;
            if r.amax() <= GRIFFITH_TOLERANCE {
                return finish(&v);
            }
            let (jac, fresh) = match jacobian.take() {
                Some(j) => (j, false),
                None => {
                    let mut j = DMatrix::zeros(n, n);
                    for k in 0..n {
                        let h = 1e-7;
                        let mut moved = v.clone();
                        moved[k] += h;
                        j.set_column(k, &((residual(&moved)? - &r) / h));
                    }
                    (j, true)
                }
            };
            let step = jac.clone().lu().solve(&r).ok_or_else(|| {
                Error::NoState("the sharp edge's Griffith system is singular".into())
            })?;
            // the step, halved (with a fresh Jacobian) until the residual
            // falls; an edge that leaves the near-elliptic shape counts as
            // no fall
            let mut lambda = 1.0;
            let (moved, next) = loop {
                let moved = &v - &step * lambda;
                let tried = residual(&moved);
                let next = tried.ok().filter(|n| n.amax() < r.amax());
                match next {
                    Some(next) => break (moved, next),
                    None if fresh && lambda > 1.0 / 64.0 => lambda *= 0.5,
                    None => break (v.clone(), r.clone()),
                }
            };
            if !fresh && next.amax() > 0.5 * r.amax() {
                // a stale Jacobian: take it again by differences, from here
                *jacobian = None;
                (v, r) = (moved, next);
                continue;
            }
            if fresh && lambda <= 1.0 / 64.0 && next.amax() >= r.amax() {
                // no step lowers it: the residual's own round-off, where it
                // is below the floor
                if r.amax() <= GRIFFITH_FLOOR {
                    return finish(&v);
                }
                break;
            }
            // Broyden: J += ((r′ − r) − J s) sᵀ / sᵀs, s = −λ step the move
            let s = -&step * lambda;
            let update = (&next - &r - &jac * &s) * s.transpose() / s.norm_squared();
            *jacobian = Some(jac + update);
            (v, r) = (moved, next);
        }
        Err(Error::NoState(format!(
            "the sharp edge {what} did not meet Griffith's condition in {NEWTON_STEPS} Newton steps (off by {:.1e})",
            r.amax()
        )))
    }

    /// The state at approach `delta` from `guess`'s edge ([`Contact::edge_at`];
    /// the tests' free edge, until states at an approach are answered).
    #[cfg(test)]
    pub(crate) fn at_approach(&self, delta: f64, guess: &Domain) -> Result<SharpState> {
        self.edge_at(delta, guess, &mut None)
    }

    /// The pull-off under load control: the least force along the branch
    /// over the approach. A walk down in δ̄ from `hi` towards `lo` in
    /// `steps` equal steps (and on past `lo`, up to twice the bracket more,
    /// while the force still falls), each state from the last two states'
    /// edges extrapolated (from `guess` first) and the last Jacobian, until
    /// the force rises again (and where the first state is the least, on
    /// up from `hi` as far); then [`Contact::least_near`] about the least
    /// state and its neighbours. An error where a state of the walk is not
    /// found, or the least force lies at an end of the bracket.
    pub(crate) fn pull_off(
        &self,
        guess: &Domain,
        (lo, hi): (f64, f64),
        steps: usize,
    ) -> Result<SharpState> {
        let step = (hi - lo) / steps as f64;
        let mut walk: Vec<SharpState> = Vec::new();
        let mut jacobian = None;
        let mut from = guess.clone();
        // past `lo` while the force still falls, up to twice the bracket
        for k in 0..=3 * steps {
            let st = self.edge_at(hi - k as f64 * step, &from, &mut jacobian)?;
            // the next edge's modes extrapolated from the last two states'
            from = st.domain.clone();
            if let Some(last) = walk.last() {
                for (e, (now, before)) in from
                    .modes
                    .iter_mut()
                    .zip(st.domain.modes.iter().zip(&last.domain.modes))
                {
                    *e = 2.0 * now - before;
                }
            }
            walk.push(st);
            let n = walk.len();
            if n >= 3 && walk[n - 1].force_bar > walk[n - 2].force_bar {
                break;
            }
        }
        let least_of = |walk: &[SharpState]| {
            (0..walk.len())
                .min_by(|&i, &j| walk[i].force_bar.total_cmp(&walk[j].force_bar))
                .unwrap_or(0)
        };
        // the least at the top: on up from `hi` while the force falls
        let mut k = 0;
        while least_of(&walk) == 0 && k < 3 * steps {
            k += 1;
            let from = walk[0].domain.clone();
            let st = self.edge_at(hi + k as f64 * step, &from, &mut jacobian)?;
            walk.insert(0, st);
        }
        let least = least_of(&walk);
        if least == 0 || least + 1 == walk.len() {
            return Err(Error::NoState(format!(
                "the sharp edge's least force over delta in [{}, {}] lies at an end",
                crate::error::rounded(walk[walk.len() - 1].delta_bar),
                crate::error::rounded(hi)
            )));
        }
        let three = walk.drain(least - 1..=least + 1).collect();
        self.least_near(three, &mut jacobian)
    }

    /// The least force near three states, the middle one the least, by
    /// successive parabolic interpolation in δ̄: a state at the vertex of
    /// the parabola through the three (from the least one's edge), then the
    /// least of the four with its neighbours, until the vertex is within
    /// 1e-7 of the least state's δ̄ (there F̄ is within about F̄″ 1e-14 of
    /// its minimum), or the three forces are within 1e-9 of each other
    /// (the states' own round-off: closer, the parabola is noise). An error where the vertex leaves the three's span (the
    /// force not convex there) or 12 steps do not settle it.
    fn least_near(
        &self,
        mut three: Vec<SharpState>,
        jacobian: &mut Option<DMatrix<f64>>,
    ) -> Result<SharpState> {
        for _ in 0..12 {
            three.sort_by(|p, q| p.delta_bar.total_cmp(&q.delta_bar));
            let [(x1, f1), (x2, f2), (x3, f3)] =
                [0, 1, 2].map(|i| (three[i].delta_bar, three[i].force_bar));
            let num = (x2 - x1).powi(2) * (f2 - f3) - (x2 - x3).powi(2) * (f2 - f1);
            let den = (x2 - x1) * (f2 - f3) - (x2 - x3) * (f2 - f1);
            let vertex = x2 - 0.5 * num / den;
            // flat within the states' own round-off (F̄ to about 1e-10 of
            // itself): the least state is the minimum as nearly as the
            // states tell it
            if f1.min(f3) - f2 < 1e-9 * f2.abs() {
                return Ok(three.swap_remove(1));
            }
            if !(vertex > x1 && vertex < x3) || f2 > f1.min(f3) {
                return Err(Error::NoState(format!(
                    "the sharp edge's force is not convex in delta near {}",
                    crate::error::rounded(x2)
                )));
            }
            if (vertex - x2).abs() < 1e-7 {
                return Ok(three.swap_remove(1));
            }
            let st = self.edge_at(vertex, &three[1].domain, jacobian)?;
            three.push(st);
            three.sort_by(|p, q| p.delta_bar.total_cmp(&q.delta_bar));
            let least = (0..4)
                .min_by(|&i, &j| three[i].force_bar.total_cmp(&three[j].force_bar))
                .unwrap_or(1)
                .clamp(1, 2);
            three = three.drain(least - 1..=least + 1).collect();
        }
        Err(Error::NoState(
            "the sharp edge's least force did not settle in 12 parabolic steps".into(),
        ))
    }

    /// The state on `domain` at `delta`: its force and Griffith's error.
    fn state_on(&self, delta: f64, domain: Domain) -> Result<SharpState> {
        let target = (2.0 * self.layers.beta()).sqrt();
        let (solver, c) = self.pressure(delta, &domain)?;
        let mut griffith_error: f64 = 0.0;
        for k in 0..=64 {
            let k = solver.intensity(&c, 0.5 * PI * k as f64 / 64.0)?;
            griffith_error = griffith_error.max((k / target - 1.0).abs());
        }
        Ok(SharpState {
            a_bar: domain.edge(0.0)?[0],
            b_bar: domain.edge(0.5 * PI)?[1],
            force_bar: solver.force(&c, 2 * self.res.radial)?,
            domain,
            delta_bar: delta,
            griffith_error,
        })
    }
}

/// The angles of Griffith's condition: `n` from 0 to π/2.
fn griffith_angles(n: usize) -> Vec<f64> {
    match n {
        1 => vec![0.0],
        _ => (0..n)
            .map(|l| 0.5 * PI * l as f64 / (n - 1) as f64)
            .collect(),
    }
}

impl Resolution {
    /// `radial` × `angular` functions with as many edge modes as angular
    /// orders, 32 points along each of 32 lines through a node, and the
    /// base share over `panels` × `angles` sources.
    pub(crate) fn rung(radial: usize, angular: usize, panels: usize, angles: usize) -> Resolution {
        Resolution {
            radial,
            angular,
            along: 32,
            rays: 64,
            sources: Sources { panels, angles },
            shape: angular,
        }
    }
}

/// The pull-off under load control of `layers` at `rho` on each of
/// `rungs`, coarsest first, `visit` seeing each when found. The first from
/// the ellipse of the axisymmetric pull-off's radius (the same coatings at
/// ρ = 1) stretched to the aspect ρ^0.45 (about (2)'s), walked down over
/// its δ̄ ± (|δ̄|/2 + 0.05 min(ā², 1)) in 16 steps; each next from the last one's edge
/// ([`Domain::rebased`] on its half-widths), over its δ̄ ± 0.01 min(ā², 1) in 4. An
/// error where a rung has none.
pub(crate) fn pull_off_ladder(
    layers: &Layers,
    rho: f64,
    rungs: &[Resolution],
    visit: impl FnMut(&Resolution, &SharpState),
) -> Result<Vec<SharpState>> {
    let (guess, bracket, wide) = circle_start(layers, rho)?;
    pull_off_ladder_from(layers, rho, rungs, guess, (bracket, 16), wide, visit)
}

/// Where the ladders start at `rho`: the axisymmetric layer's pull-off
/// stretched to an ellipse of aspect ρ^0.45, a bracket in δ̄ about its
/// approach, and the walk's scale in δ̄ (the contact's area: at h/L = 10
/// ā = 0.1).
fn circle_start(layers: &Layers, rho: f64) -> Result<(Domain, (f64, f64), f64)> {
    let circle = layers.pull_off(super::Route::Griffith)?.load;
    let stretch = rho.powf(0.45).sqrt();
    let guess = Domain::ellipse(circle.a_bar / stretch, circle.a_bar * stretch);
    let (d, wide) = (circle.delta_bar, 0.05 * circle.a_bar.powi(2).min(1.0));
    let bracket = (d - 0.5 * d.abs() - wide, d + 0.5 * d.abs() + wide);
    Ok((guess, bracket, wide))
}

/// [`pull_off_ladder`] from the edge `guess`, the first rung walking over
/// `first` (its bracket in δ̄ and steps), the finer ones over ±0.2 `wide`
/// about the last one's pull-off in 4 steps.
pub(crate) fn pull_off_ladder_from(
    layers: &Layers,
    rho: f64,
    rungs: &[Resolution],
    mut guess: Domain,
    ((lo, hi), steps): ((f64, f64), usize),
    wide: f64,
    mut visit: impl FnMut(&Resolution, &SharpState),
) -> Result<Vec<SharpState>> {
    let (mut bracket, mut steps) = ((lo, hi), steps);
    let mut found = Vec::with_capacity(rungs.len());
    for res in rungs {
        let st = Contact::new(layers, rho, *res, &guess)?.pull_off(&guess, bracket, steps)?;
        visit(res, &st);
        (bracket, steps) = ((st.delta_bar - 0.2 * wide, st.delta_bar + 0.2 * wide), 4);
        guess = st
            .domain
            .rebased(st.a_bar, st.b_bar, st.domain.modes.len())?;
        found.push(st);
    }
    Ok(found)
}

/// What a state of [`held_ladder`] is held at.
#[derive(Clone, Copy, Debug)]
pub(crate) enum HeldAt {
    /// A force F̄, on the branch stable under load control (above the
    /// pull-off in δ̄).
    Force(f64),
    /// An approach δ̄, on the branch through the pull-off, stable under
    /// displacement control.
    Delta(f64),
    /// A half-width ā along X, anywhere on the branch from large loads
    /// (beyond its pull-offs too).
    Size(f64),
    /// The least approach on the branch: the pull-off under displacement
    /// control.
    LeastApproach,
}

/// A hold the walk in δ̄ reaches: a force or an approach.
#[derive(Clone, Copy)]
enum InDelta {
    Force(f64),
    Delta(f64),
}

impl InDelta {
    /// The state's departure from the hold.
    fn off(self, st: &SharpState) -> f64 {
        match self {
            InDelta::Force(f) => st.force_bar - f,
            InDelta::Delta(d) => st.delta_bar - d,
        }
    }
}

/// The state held at `held` on each of `rungs`. On the first rung: its
/// pull-off under load control (the walk of [`pull_off_ladder`]), then
/// from it
/// - at a force or an approach, a walk in δ̄ towards the hold, from a
///   fifth of the walk's scale, until the hold is passed; at a force the
///   Illinois method in δ̄ to within 1e-10 of it;
/// - at a size, a walk in ā to it ([`Contact::walk_in_size`]);
/// - at the least approach, a walk down in ā until δ̄ rises, then the
///   root of dδ̄/dā ([`Contact::least_approach`]).
///
/// On each finer rung, from the last one's edge rebased: a state at the
/// last one's δ̄ and, at a force, a walk from a fiftieth of that scale; a
/// state at the last one's ā (at a size, the answer; at the least
/// approach, the start of the same walk from a hundredth of ā). The walks'
/// steps grow 1.5 times (halved where Newton's method finds no state). An
/// error where the force is below the first rung's pull-off (no state
/// under load control there) or a state is not found (an approach below
/// the branch's least).
pub(crate) fn held_ladder(
    layers: &Layers,
    rho: f64,
    rungs: &[Resolution],
    held: HeldAt,
    mut visit: impl FnMut(&Resolution, &SharpState),
) -> Result<Vec<SharpState>> {
    let (mut guess, bracket, wide) = circle_start(layers, rho)?;
    let mut found: Vec<SharpState> = Vec::with_capacity(rungs.len());
    for res in rungs {
        // a table that reaches a larger size asked for
        let reach = match held {
            HeldAt::Size(a) if a > guess.a => Domain::ellipse(a, guess.b * a / guess.a),
            _ => guess.clone(),
        };
        let contact = Contact::new(layers, rho, *res, &reach)?;
        let mut jacobian = None;
        let (last, jacobian) = (found.last(), &mut jacobian);
        let st = match held {
            HeldAt::Force(f) => {
                contact.held_in_delta(InDelta::Force(f), last, &guess, bracket, wide, jacobian)?
            }
            HeldAt::Delta(d) => {
                contact.held_in_delta(InDelta::Delta(d), last, &guess, bracket, wide, jacobian)?
            }
            HeldAt::Size(a) => contact.held_in_size(Some(a), last, &guess, bracket, jacobian)?,
            HeldAt::LeastApproach => contact.held_in_size(None, last, &guess, bracket, jacobian)?,
        };
        visit(res, &st);
        guess = st
            .domain
            .rebased(st.a_bar, st.b_bar, st.domain.modes.len())?;
        found.push(st);
    }
    Ok(found)
}

/// `st`'s edge for the next state of a walk in ā: rebased on its
/// half-widths ([`Domain::rebased`], the Jacobian then taken afresh) where
/// they have moved by more than a fifth from its ellipse's, so that its
/// modes stay small.
fn based(st: &SharpState, jacobian: &mut Option<DMatrix<f64>>) -> Result<Domain> {
    let d = &st.domain;
    if (0.8..=1.25).contains(&(st.a_bar / d.a)) && (0.8..=1.25).contains(&(st.b_bar / d.b)) {
        return Ok(d.clone());
    }
    *jacobian = None;
    d.rebased(st.a_bar, st.b_bar, d.modes.len())
}

/// The slopes dF̄/dā and dδ̄/dā along the branch at `st`, a state of
/// size on `res` ([`Contact::slopes_at`]).
pub(crate) fn slopes_in_size(
    layers: &Layers,
    rho: f64,
    res: Resolution,
    st: &SharpState,
) -> Result<[f64; 2]> {
    Contact::new(layers, rho, res, &st.domain)?.slopes_at(st, &mut None)
}

/// The states of each of `sizes` (in order, from the largest down) on
/// each of `rungs`, handed to `each` a size at a time with the slopes on
/// the finest rung ([`Contact::slopes_at`]): the first size as
/// [`held_ladder`]'s state at a size, then on each rung one walk in ā
/// ([`Contact::walk_in_size`]) from its last state, so that nothing of the
/// size of `sizes` is kept. An error where a rung finds no state (where
/// its walk stopped) or `each` fails.
pub(crate) fn size_walk(
    layers: &Layers,
    rho: f64,
    rungs: &[Resolution],
    sizes: &[f64],
    each: &mut EachSize<'_>,
) -> Result<()> {
    let (Some(&first), Some(finest)) = (sizes.first(), rungs.len().checked_sub(1)) else {
        return Ok(());
    };
    let (mut guess, bracket, _) = circle_start(layers, rho)?;
    // one table on each rung that reaches the largest size
    let top = sizes.iter().copied().fold(first, f64::max).max(guess.a);
    let reach = Domain::ellipse(top, guess.b * top / guess.a);
    let contacts = rungs
        .iter()
        .map(|res| Contact::new(layers, rho, *res, &reach))
        .collect::<Result<Vec<_>>>()?;
    let mut jacobians: Vec<Option<DMatrix<f64>>> = vec![None; rungs.len()];
    let mut states: Vec<SharpState> = Vec::with_capacity(rungs.len());
    for (contact, jacobian) in contacts.iter().zip(&mut jacobians) {
        let st = contact.held_in_size(Some(first), states.last(), &guess, bracket, jacobian)?;
        guess = st
            .domain
            .rebased(st.a_bar, st.b_bar, st.domain.modes.len())?;
        states.push(st);
    }
    for (k, &a) in sizes.iter().enumerate() {
        if k > 0 {
            let step = (a - sizes[k - 1]).abs();
            // (one rung after another: side by side on two cores the 30-point
            // curve at rho = 0.8 took 101 s against about 104, the rungs'
            // own quadratures already using both)
            for ((contact, jacobian), st) in contacts.iter().zip(&mut jacobians).zip(&mut states) {
                *st = contact.walk_in_size(st.clone(), a, step, jacobian)?;
            }
        }
        let slopes = contacts[finest].slopes_at(&states[finest], &mut jacobians[finest])?;
        each(&states, slopes)?;
    }
    Ok(())
}

impl Contact<'_> {
    /// One rung of [`held_ladder`] at a force or an approach: from the
    /// last rung's state (`None`: from the pull-off in `bracket`), on
    /// `guess`'s edge, the walk in δ̄.
    fn held_in_delta(
        &self,
        held: InDelta,
        last: Option<&SharpState>,
        guess: &Domain,
        bracket: (f64, f64),
        wide: f64,
        jacobian: &mut Option<DMatrix<f64>>,
    ) -> Result<SharpState> {
        // the table rebuilt wider where the walk nears its reach
        let mut grown: Option<Contact> = None;
        let (mut lo, mut step) = match last {
            None => {
                let p = self.pull_off(guess, bracket, 16)?;
                if let InDelta::Force(f) = held {
                    if f < p.force_bar {
                        return Err(Error::NoState(format!(
                            "no state at force {} under load control: the layer's pull-off in the plane is near {}",
                            crate::error::short(f),
                            crate::error::short(p.force_bar)
                        )));
                    }
                }
                // towards the hold: up in δ̄ at a force (above the pull-off)
                let towards = match held {
                    InDelta::Delta(d) if d < p.delta_bar => -1.0,
                    _ => 1.0,
                };
                (p, towards * 0.2 * wide)
            }
            Some(last) => {
                let at = self.edge_at(last.delta_bar, guess, jacobian)?;
                let towards = if held.off(&at) < 0.0 { 1.0 } else { -1.0 };
                (at, towards * 0.02 * wide)
            }
        };
        // on past the hold (at once where the state is at it); where Newton's
        // method has halved the step below a millionth of the first, the
        // walk is creeping up to the branch's end in δ̄ (a fold), and stops
        let least_step = 1e-6 * step.abs();
        let mut hi = None;
        for _ in 0..60 {
            if held.off(&lo) == 0.0 {
                hi = Some(lo.clone());
                break;
            }
            // a step too long for Newton's method halved (up to 6 times)
            let mut tries = 0;
            let st = loop {
                if 1.2 * lo.a_bar.max(lo.b_bar) > grown.as_ref().unwrap_or(self).reach {
                    let wider = Domain::ellipse(2.0 * lo.a_bar, 2.0 * lo.b_bar);
                    grown = Some(Contact::new(self.layers, self.rho, self.res, &wider)?);
                    *jacobian = None;
                }
                let contact = grown.as_ref().unwrap_or(self);
                let edge = based(&lo, jacobian)?;
                match contact.edge_at(lo.delta_bar + step, &edge, jacobian) {
                    Ok(st) => break st,
                    Err(_)
                        if tries < 6
                            && step.abs() > least_step
                            && !crate::newton::stop_requested() =>
                    {
                        tries += 1;
                        step *= 0.5;
                        *jacobian = None;
                    }
                    Err(e) => return Err(walk_end(held, step, &lo, e)),
                }
            };
            if held.off(&st) * held.off(&lo) <= 0.0 {
                hi = Some(st);
                break;
            }
            lo = st;
            step *= 1.5;
        }
        let hi = hi.ok_or_else(|| {
            let what = match held {
                InDelta::Force(f) => format!("force {}", crate::error::short(f)),
                InDelta::Delta(d) => format!("delta = {}", crate::error::short(d)),
            };
            Error::NoState(format!(
                "the sharp edge did not reach {what} in 60 steps in delta"
            ))
        })?;
        let contact = grown.as_ref().unwrap_or(self);
        Ok(match held {
            InDelta::Force(f) => contact.at_force(lo, hi, f, jacobian)?,
            InDelta::Delta(d) if hi.delta_bar == d => hi,
            InDelta::Delta(d) => {
                let from = if (d - lo.delta_bar).abs() < (d - hi.delta_bar).abs() {
                    &lo
                } else {
                    &hi
                };
                contact.edge_at(d, &from.domain, jacobian)?
            }
        })
    }

    /// One rung of [`held_ladder`] at the size `size` (`None`: the least
    /// approach): from the last rung's state (`None`: from the pull-off in
    /// `bracket`), on `guess`'s edge, the walk in ā.
    fn held_in_size(
        &self,
        size: Option<f64>,
        last: Option<&SharpState>,
        guess: &Domain,
        bracket: (f64, f64),
        jacobian: &mut Option<DMatrix<f64>>,
    ) -> Result<SharpState> {
        let (start, step) = match last {
            None => {
                let p = self.pull_off(guess, bracket, 16)?;
                let step = 0.05 * p.a_bar;
                (p, step)
            }
            Some(last) => (
                self.size_at(last.a_bar, last.delta_bar, guess, jacobian)?,
                0.01 * last.a_bar,
            ),
        };
        match size {
            Some(a) => self.walk_in_size(start, a, step, jacobian),
            None => self.least_approach(start, step, jacobian),
        }
    }

    /// The slopes dF̄/dā and dδ̄/dā along the branch at `st`, a state of
    /// size: central differences over 1e-4 ā, each state from `st`'s
    /// edge. The contact is stable under load control where the first is
    /// positive, under displacement control where the second is (the
    /// branch's own direction; its undulations are the kernel's
    /// stability's).
    fn slopes_at(&self, st: &SharpState, jacobian: &mut Option<DMatrix<f64>>) -> Result<[f64; 2]> {
        let (slopes, _) = self.across(st.a_bar, 1e-4 * st.a_bar, st, &st.domain, jacobian)?;
        Ok(slopes)
    }

    /// The states of size `a` − `h` and `a` + `h` on `edge`, the first from
    /// `near`'s approach and the second from the first's, and the slopes
    /// dF̄/dā and dδ̄/dā between them.
    fn across(
        &self,
        a: f64,
        h: f64,
        near: &SharpState,
        edge: &Domain,
        jacobian: &mut Option<DMatrix<f64>>,
    ) -> Result<([f64; 2], [SharpState; 2])> {
        let below = self.size_at(a - h, near.delta_bar, edge, jacobian)?;
        let above = self.size_at(a + h, below.delta_bar, edge, jacobian)?;
        let da = above.a_bar - below.a_bar;
        let slopes = [
            (above.force_bar - below.force_bar) / da,
            (above.delta_bar - below.delta_bar) / da,
        ];
        Ok((slopes, [below, above]))
    }

    /// The state of size `a` from `start`, walking in ā from a step of
    /// `step`, growing 1.5 times after each step taken and halved (up to 6
    /// times in a row) where Newton's method finds no state, each state
    /// from the last one's edge and the approach extrapolated from the last
    /// two. An error where a step halved 6 times finds none, or 200 steps
    /// do not reach `a`.
    fn walk_in_size(
        &self,
        start: SharpState,
        a: f64,
        step: f64,
        jacobian: &mut Option<DMatrix<f64>>,
    ) -> Result<SharpState> {
        let (mut last, mut before): (SharpState, Option<SharpState>) = (start, None);
        let mut step = step.abs();
        let mut halved = 0;
        for _ in 0..200 {
            let gap = a - last.a_bar;
            // (the edge's half-width is found to its root's round-off)
            if gap.abs() <= 1e-12 * a {
                return Ok(last);
            }
            let to = if gap.abs() <= step {
                a
            } else {
                last.a_bar + step * gap.signum()
            };
            let delta = match &before {
                Some(b) if b.a_bar != last.a_bar => {
                    last.delta_bar
                        + (last.delta_bar - b.delta_bar) / (last.a_bar - b.a_bar)
                            * (to - last.a_bar)
                }
                _ => last.delta_bar,
            };
            match self.size_at(to, delta, &based(&last, jacobian)?, jacobian) {
                Ok(st) => {
                    before = Some(std::mem::replace(&mut last, st));
                    step *= 1.5;
                    halved = 0;
                }
                Err(_) if halved < 6 && !crate::newton::stop_requested() => {
                    halved += 1;
                    step *= 0.5;
                    *jacobian = None;
                }
                Err(e) if crate::newton::stop_requested() => return Err(e),
                Err(e) => {
                    return Err(Error::NoState(format!(
                        "the sharp edge found no state of size a = {} on the walk in a towards {}: the last found is at a = {} ({e})",
                        crate::error::short(to),
                        crate::error::short(a),
                        crate::error::short(last.a_bar)
                    )))
                }
            }
        }
        Err(Error::NoState(format!(
            "the sharp edge did not reach a = {} in 200 steps in a",
            crate::error::short(a)
        )))
    }

    /// The least approach on the branch near `start`: a walk in ā from
    /// it, steps of `step` (down in ā first, the other way where δ̄ rises
    /// at once), until δ̄ rises again; then the root of dδ̄/dā between the
    /// least state's neighbours by the Illinois method, to 1e-9 of ā or of
    /// a slope of 1e-9, the slope a central difference over 1e-4 ā (its
    /// root is located to about δ̄'s round-off over that step, where the
    /// least of δ̄ itself is flat: its square root), and the state there.
    /// Each state from the nearest one's edge. An error where a state is
    /// not found, the slope does not change sign between the neighbours,
    /// or 40 steps find no least.
    fn least_approach(
        &self,
        start: SharpState,
        step: f64,
        jacobian: &mut Option<DMatrix<f64>>,
    ) -> Result<SharpState> {
        let mut walk = vec![start];
        let mut step = -step.abs();
        for _ in 0..40 {
            let n = walk.len();
            let last = &walk[n - 1];
            let delta = match n {
                1 => last.delta_bar,
                _ => 2.0 * last.delta_bar - walk[n - 2].delta_bar,
            };
            let st = self.size_at(last.a_bar + step, delta, &based(last, jacobian)?, jacobian)?;
            walk.push(st);
            let n = walk.len();
            if walk[n - 1].delta_bar <= walk[n - 2].delta_bar {
                continue;
            }
            if n == 2 {
                // rising at once: the least lies the other way
                walk.reverse();
                step = -step;
                continue;
            }
            let (a_lo, a_hi) = {
                let (p, q) = (walk[n - 3].a_bar, walk[n - 1].a_bar);
                (p.min(q), p.max(q))
            };
            let h = 1e-4 * walk[n - 2].a_bar;
            let nearest = |tried: &[SharpState], a: f64| {
                tried
                    .iter()
                    .min_by(|p, q| (p.a_bar - a).abs().total_cmp(&(q.a_bar - a).abs()))
                    .cloned()
                    .ok_or_else(|| {
                        Error::NoState("the sharp edge has no state to start from".into())
                    })
            };
            let mut slope = |a: f64| -> Result<f64> {
                let from = nearest(&walk, a)?;
                let edge = based(&from, jacobian)?;
                let ([_, in_delta], pair) = self.across(a, h, &from, &edge, jacobian)?;
                walk.extend(pair);
                Ok(in_delta)
            };
            let (g_lo, g_hi) = (slope(a_lo)?, slope(a_hi)?);
            if !(g_lo < 0.0 && g_hi > 0.0) {
                return Err(Error::NoState(format!(
                    "the sharp edge's approach is not convex in a between {} and {}",
                    crate::error::rounded(a_lo),
                    crate::error::rounded(a_hi)
                )));
            }
            let root = super::illinois(
                &mut slope,
                (a_lo, g_lo),
                (a_hi, g_hi),
                |lo, hi| (hi - lo).abs() <= 1e-9 * a_hi,
                1e-9,
                60,
            )?
            .map_err(|_| {
                Error::NoState("the sharp edge's least approach was not located in 60 steps".into())
            })?;
            let from = nearest(&walk, root)?;
            let edge = based(&from, jacobian)?;
            return self.size_at(root, from.delta_bar, &edge, jacobian);
        }
        Err(Error::NoState(
            "the sharp edge found no least approach within 40 steps in a".into(),
        ))
    }
}

/// The error where the walk in δ̄ of a hold at `held` finds no state past
/// `lo` (its step `step`): going down at an approach, the branch's least
/// approach; going up, what stopped it; at a force, or where a stop was
/// asked for, `e` itself.
fn walk_end(held: InDelta, step: f64, lo: &SharpState, e: Error) -> Error {
    let (InDelta::Delta(d), false) = (held, crate::newton::stop_requested()) else {
        return e;
    };
    let (d, at) = (crate::error::short(d), crate::error::short(lo.delta_bar));
    Error::NoState(if step < 0.0 {
        // the walk's end going down: the branch turns back in δ̄
        format!(
            "no state at delta = {d}: the branch through the pull-off ends near delta = {at}, its least approach (the sharp edge finds no state past it)"
        )
    } else {
        format!(
            "no state at delta = {d}: the sharp edge's walk up in delta from the pull-off found none past delta = {at} ({e})"
        )
    })
}

impl Contact<'_> {
    /// The state at force `force` between the states `lo` and `hi`, whose
    /// forces lie on either side of it: the Illinois method in δ̄, each
    /// state from the nearer end's edge, to within 1e-10 of the force (of
    /// 1 where it is smaller) or 1e-12 in δ̄.
    fn at_force(
        &self,
        lo: SharpState,
        hi: SharpState,
        force: f64,
        jacobian: &mut Option<DMatrix<f64>>,
    ) -> Result<SharpState> {
        let (ends, mut tried) = (
            [
                (lo.delta_bar, lo.force_bar - force),
                (hi.delta_bar, hi.force_bar - force),
            ],
            vec![lo, hi],
        );
        let found = super::illinois(
            |d| {
                // from the nearest state's edge (`tried` holds the two ends)
                let nearest = tried
                    .iter()
                    .min_by(|p, q| (p.delta_bar - d).abs().total_cmp(&(q.delta_bar - d).abs()))
                    .map(|s| s.domain.clone())
                    .ok_or_else(|| {
                        Error::NoState("the sharp edge has no state to start from".into())
                    })?;
                let st = self.edge_at(d, &nearest, jacobian)?;
                let g = st.force_bar - force;
                tried.push(st);
                Ok(g)
            },
            ends[0],
            ends[1],
            |lo, hi| (hi - lo).abs() <= 1e-12,
            1e-10 * force.abs().max(1.0),
            60,
        )?;
        let d = found.map_err(|_| {
            Error::NoState(format!(
                "the sharp edge's state at force {} was not located in 60 steps",
                crate::error::short(force)
            ))
        })?;
        // (the method answers an approach it tried)
        tried.into_iter().find(|s| s.delta_bar == d).ok_or_else(|| {
            Error::NoState("the sharp edge's state at the force was not kept".into())
        })
    }
}

/// How finely the base share's integral over the contact is taken: in
/// (α, θ) with Φ = sin² α on the ray of angle θ, where dA/√(1 − Φ) =
/// ab sin α dα dθ / P′(r²) and the integrand is smooth; `panels` Gauss–Legendre panels of 8 points in α
/// over [0, π/2], and `angles` points of the trapezoidal rule in θ over
/// the quarter (their mirror images over the rest).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Sources {
    pub(crate) panels: usize,
    pub(crate) angles: usize,
}

/// The base share c(r) of the coatings' compliance (`grid::kernel`'s
/// table; c < 0: the bases take away part of the half-space's) and the
/// source points of its integral with their weights.
struct Base {
    share: BaseShare,
    /// (x, y) of each source point in the quarter and its weight.
    sources: Vec<([f64; 2], f64)>,
}

impl Base {
    /// The base share on `domain` from the table `share`, which reaches
    /// twice the edge's distance from the centre.
    fn new(domain: &Domain, share: BaseShare, sources: Sources) -> Result<Base> {
        let rule = GaussLegendre::new(8).composite(0.0, 0.5 * PI, sources.panels.max(1));
        let d_theta = 2.0 * PI / (4 * sources.angles) as f64;
        let mut points = Vec::with_capacity(rule.len() * sources.angles);
        for l in 0..sources.angles {
            let theta = (l as f64 + 0.5) * d_theta;
            for &(alpha, w) in &rule {
                let s = alpha.sin();
                let (z, dp) = domain.at_level(theta, s * s)?;
                points.push((z, w * s * d_theta * domain.a * domain.b / dp));
            }
        }
        Ok(Base {
            share,
            sources: points,
        })
    }

    /// The base share's displacement at each of `targets` of each basis
    /// function of `problem`: Σ over the sources and their four mirror
    /// images of c(r) times the source's weight and basis value.
    fn displacement_of_basis(&self, problem: &Bilateral, targets: &[(f64, f64)]) -> DMatrix<f64> {
        let n = problem.unknowns();
        let mut values = DMatrix::zeros(self.sources.len(), n);
        let mut q = vec![0.0; n];
        for (k, &([x, y], w)) in self.sources.iter().enumerate() {
            problem.basis(x, y, &mut q);
            for j in 0..n {
                values[(k, j)] = w * q[j];
            }
        }
        let rows: Vec<f64> = targets
            .par_iter()
            .flat_map_iter(|&(x, y)| {
                self.sources.iter().map(move |&([sx, sy], _)| {
                    self.share.at((x - sx).hypot(y - sy))
                        + self.share.at((x + sx).hypot(y - sy))
                        + self.share.at((x - sx).hypot(y + sy))
                        + self.share.at((x + sx).hypot(y + sy))
                })
            })
            .collect();
        DMatrix::from_row_slice(targets.len(), self.sources.len(), &rows) * values
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// K(e) by the arithmetic–geometric mean, k′ = √(1 − e²).
    fn elliptic_k(k_prime: f64) -> f64 {
        let (mut a, mut b) = (1.0, k_prime);
        for _ in 0..40 {
            (a, b) = (0.5 * (a + b), (a * b).sqrt());
        }
        PI / (2.0 * a)
    }

    /// The flat elliptical punch, p̄ = 1/√(1 − X²/a² − Y²/b²), displaces
    /// the half-space uniformly by b K(e)/β (e² = 1 − b²/a², a ≥ b; on a
    /// circle P/(2aE*)): the quadrature of w̄ holds it at points across the
    /// contact, near its edge too, on a circle and an ellipse of aspect 0.5.
    #[test]
    fn the_flat_punch_displaces_the_half_space_uniformly() {
        for (a, b) in [(1.3, 1.3), (2.0, 1.0)] {
            let beta = 0.7;
            let solver = Bilateral::new(Domain::ellipse(a, b), beta, 2, 1, 32, 256).unwrap();
            let exact = b * elliptic_k(b / a) / beta;
            for (x, y) in [
                (0.0, 0.0),
                (0.3 * a, 0.2 * b),
                (0.9 * a, 0.0),
                (0.5 * a, 0.8 * b),
            ] {
                let w = solver.displacement_of_basis(x, y).unwrap()[0];
                assert!(
                    (w / exact - 1.0).abs() < 1e-9,
                    "a = {a}, b = {b} at ({x}, {y}): {w} against {exact}"
                );
            }
        }
    }

    /// Hertz's and the punch's pressures on a circle (ρ = 1, φ̄ = r²/2):
    /// q = p₀(1 − s²) + P₀ with p₀ = 4aβ/π and P₀ = 2β(δ̄ − a²)/(πa);
    /// the collocation returns them and nothing else, its force is
    /// (8/3)βa³ + 2πa²P₀, and with Griffith's condition K = √(2β) the force
    /// is JKR's, whose least value over a is −3π/4 in these units.
    #[test]
    fn hertz_and_jkr_on_a_circle() {
        let (a, beta, delta) = (1.7, 0.9, 2.2);
        let solver = Bilateral::new(Domain::ellipse(a, a), beta, 4, 3, 24, 128).unwrap();
        let c = solver.solve(|x, y| delta - 0.5 * (x * x + y * y)).unwrap();
        let p0 = 4.0 * a * beta / PI;
        let big_p0 = 2.0 * beta * (delta - a * a) / (PI * a);
        // q of degree 1 in s²: the rest of the coefficients zero
        for (j, v) in c.iter().enumerate() {
            assert!(j < 2 || v.abs() < 1e-9 * p0, "c[{j}] = {v:e}");
        }
        let mut basis = vec![0.0; solver.unknowns()];
        for s2 in [0.0, 0.3, 0.7, 1.0] {
            solver.basis(a * f64::sqrt(s2), 0.0, &mut basis);
            let q = basis.iter().zip(c.iter()).map(|(u, v)| u * v).sum::<f64>();
            let hertz = p0 * (1.0 - s2) + big_p0;
            assert!(
                (q - hertz).abs() < 1e-9 * p0,
                "s² = {s2}: {q} against {hertz}"
            );
        }
        let force = solver.force(&c, 16).unwrap();
        let hertz = 8.0 / 3.0 * beta * a.powi(3) + 2.0 * PI * a * a * big_p0;
        assert!(
            (force / hertz - 1.0).abs() < 1e-10,
            "{force} against {hertz}"
        );
        let k = solver.intensity(&c, 0.3).unwrap();
        assert!((k + big_p0 * (PI * a).sqrt()).abs() < 1e-9, "{k}");
        // JKR: the approach that meets Griffith's condition at this a
        let griffith = |a: f64| {
            let s = Bilateral::new(Domain::ellipse(a, a), beta, 3, 1, 24, 96).unwrap();
            let one = s.solve(|_, _| 1.0).unwrap();
            let gap = s.solve(|x, y| 0.5 * (x * x + y * y)).unwrap();
            // K(δ̄) = δ̄ K(1) − K(gap) = √(2β)
            let d = ((2.0 * beta).sqrt() + s.intensity(&gap, 0.0).unwrap())
                / s.intensity(&one, 0.0).unwrap();
            s.force(&(one * d - gap), 16).unwrap()
        };
        let a_pull = (3.0 * (2.0 * PI * beta).sqrt() / (8.0 * beta)).powf(2.0 / 3.0);
        let f = griffith(a_pull);
        assert!((f + 0.75 * PI).abs() < 1e-10, "{f}");
    }

    /// On an ellipse of aspect 0.6 with the gap (X² + Y²/ρ)/2 of (1),
    /// Galin's theorem gives q of degree 2: the collocation with more
    /// functions finds the rest zero, and the displacement its solution
    /// makes off the nodes is the gap's.
    #[test]
    fn a_quadratic_gap_on_an_ellipse_is_galin_s() {
        let (a, b, rho, beta, delta) = (2.0, 1.2, 0.5, 1.1, 3.0);
        let solver = Bilateral::new(Domain::ellipse(a, b), beta, 5, 4, 32, 256).unwrap();
        let target = |x: f64, y: f64| delta - 0.5 * (x * x + y * y / rho);
        let c = solver.solve(target).unwrap();
        let scale = c.amax();
        // the blocks of m hold 5 − m functions
        let mut j = 0;
        for m in 0..4 {
            for n in 0..5 - m {
                // degree 2 in (X, Y): n + m ≤ 1
                if n + m > 1 {
                    let v = c[j];
                    assert!(v.abs() < 1e-8 * scale, "c[{m}][{n}] = {v:e}");
                }
                j += 1;
            }
        }
        for (x, y) in [(0.1, 0.1), (1.5, 0.3), (0.4, 1.0), (1.9, 0.05)] {
            let w = solver.displacement_of_basis(x, y).unwrap().dot(&c);
            assert!(
                (w - target(x, y)).abs() < 1e-8 * delta,
                "({x}, {y}): {w} against {}",
                target(x, y)
            );
        }
    }

    /// At ρ = 1 the sharp edge on a circle of radius ā is the axisymmetric
    /// layer's state at ā (`layer::at_radius`, Griffith's route): the
    /// approach from Griffith's condition K = √(2β) and the force, for two
    /// equal incompressible coatings, against the resolution.
    #[test]
    #[ignore = "exploration: prints the convergence; the held test is below"]
    fn explore_the_circle_against_the_axisymmetric_layer() {
        for (h, a) in [(1.0, 1.1), (0.5, 1.5), (0.2, 2.0)] {
            let layers = Layers::equal(h, 0.5).unwrap();
            let reference = layers.at_radius(a, super::super::Route::Griffith).unwrap();
            println!(
                "h/L = {h}, a = {a}: reference delta {:.10} force {:.10}",
                reference.delta_bar, reference.force_bar
            );
            for (radial, panels, angles) in [
                (8, 4, 16),
                (12, 8, 32),
                (16, 16, 64),
                (24, 24, 96),
                (32, 32, 128),
            ] {
                let t = std::time::Instant::now();
                let (delta, force) = circle_state(&layers, a, radial, Sources { panels, angles });
                println!(
                    "  radial {radial:2} panels {panels:2} angles {angles:3}: delta {delta:.10} ({:+.1e}) force {force:.10} ({:+.1e}) {:.2} s",
                    delta - reference.delta_bar,
                    force / reference.force_bar - 1.0,
                    t.elapsed().as_secs_f64()
                );
            }
        }
    }

    /// The held end of the exploration above: with 32 radial functions and
    /// the base share over 32 panels and 128 angles (0.4 to 0.6 s each), the
    /// circle's approach and force are the axisymmetric layer's within 3e-9
    /// at h/L = 1, 0.5 and 0.2 (measured 1.3e-14, 6.3e-12 and 2.7e-9).
    #[test]
    fn the_sharp_edge_on_a_circle_is_the_axisymmetric_layer() {
        for (h, a) in [(1.0, 1.1), (0.5, 1.5), (0.2, 2.0)] {
            let layers = Layers::equal(h, 0.5).unwrap();
            let reference = layers.at_radius(a, super::super::Route::Griffith).unwrap();
            let (delta, force) = circle_state(
                &layers,
                a,
                32,
                Sources {
                    panels: 32,
                    angles: 128,
                },
            );
            assert!(
                (delta - reference.delta_bar).abs() < 1e-8,
                "h/L = {h}: delta {delta} against {}",
                reference.delta_bar
            );
            assert!(
                (force / reference.force_bar - 1.0).abs() < 1e-8,
                "h/L = {h}: force {force} against {}",
                reference.force_bar
            );
        }
    }

    /// The free edge at ρ = 1: from a circle 5 % too large, at the
    /// axisymmetric layer's approach for ā = 1.1 (h/L = 1), Newton on the
    /// edge's modes (three of them, Griffith's condition at θ = 0, π/4 and
    /// π/2) returns the circle of radius 1.1 (its other modes below 1e-9)
    /// and the reference's force within 1e-9 (measured: 3 steps, 4e-11).
    #[test]
    fn the_free_edge_at_rho_1_finds_the_axisymmetric_layer_s_circle() {
        let layers = Layers::equal(1.0, 0.5).unwrap();
        let reference = layers
            .at_radius(1.1, super::super::Route::Griffith)
            .unwrap();
        let res = Resolution {
            radial: 16,
            angular: 3,
            along: 32,
            rays: 64,
            sources: Sources {
                panels: 16,
                angles: 64,
            },
            shape: 3,
        };
        let guess = Domain::ellipse(1.15, 1.15);
        let st = Contact::new(&layers, 1.0, res, &guess)
            .unwrap()
            .at_approach(reference.delta_bar, &guess)
            .unwrap();
        let (a, b) = (st.a_bar, st.b_bar);
        assert!((a - 1.1).abs() < 1e-9 && (b - 1.1).abs() < 1e-9, "{a}, {b}");
        assert!(
            st.domain.modes[1..].iter().all(|d| d.abs() < 1e-9),
            "{:?}",
            st.domain.modes
        );
        assert!(
            (st.force_bar / reference.force_bar - 1.0).abs() < 1e-9,
            "{} against {}",
            st.force_bar,
            reference.force_bar
        );
        assert!(st.griffith_error < 1e-9, "{:.1e}", st.griffith_error);
    }

    /// The free edge's pull-off at ρ = 1 is the axisymmetric layer's
    /// pull-off under load control at h/L = 0.2, 1 and 10 (issue 71's
    /// done-when asks 1e-3), found in the plane: from an ellipse of aspect
    /// 0.8 with three modes of the edge, which must come back to the circle.
    /// The bracket of the walk in δ̄ is the reference's δ̄ ± ā²/5.
    #[test]
    fn the_free_edge_s_pull_off_at_rho_1_is_the_axisymmetric_layer_s() {
        // the thinner coatings need more radial functions (the base share
        // varies on the scale of h near the edge): at h/L = 0.2, 16 of them
        // leave 5e-5 (24 leave 1e-7, in 23 s)
        for (h, radial, panels, angles, within) in [
            (0.2, 16, 16, 64, 1e-4),
            (1.0, 12, 16, 64, 1e-6),
            (10.0, 12, 8, 32, 1e-6),
        ] {
            let layers = Layers::equal(h, 0.5).unwrap();
            let reference = layers.pull_off(super::super::Route::Griffith).unwrap().load;
            let res = Resolution {
                radial,
                angular: 3,
                along: 32,
                rays: 64,
                sources: Sources { panels, angles },
                shape: 3,
            };
            let (a, d) = (reference.a_bar, reference.delta_bar);
            let guess = Domain::ellipse(1.1 * a, 0.88 * a);
            let t = std::time::Instant::now();
            let st = Contact::new(&layers, 1.0, res, &guess)
                .unwrap()
                .pull_off(&guess, (d - 0.2 * a * a, d + 0.2 * a * a), 16)
                .unwrap();
            let force = st.force_bar / reference.force_bar - 1.0;
            let (ea, eb) = (st.a_bar / a - 1.0, st.b_bar / a - 1.0);
            println!(
                "h/L = {h}: force {:.10} ({force:+.1e}), half-widths ({ea:+.1e}, {eb:+.1e}), delta {:+.1e}, {:.1} s",
                st.force_bar,
                st.delta_bar - d,
                t.elapsed().as_secs_f64()
            );
            assert!(force.abs() < within, "h/L = {h}: force off by {force:.1e}");
            assert!(
                ea.abs() < 1e-4 && eb.abs() < 1e-4,
                "h/L = {h}: {ea:.1e}, {eb:.1e}"
            );
        }
    }

    /// At ρ = 0.8 and h/L = 1 the free edge's pull-off on two rungs (12 × 3
    /// functions with 3 edge modes, then 16 × 4 with 4, from the first's
    /// edge) agrees within 1e-5 (measured 1.7e-6), the edge meets
    /// Griffith's condition between the collocation angles within 1e-5 on
    /// the finer, and the grid solver's pull-off of the same coatings (an
    /// independent route: a cohesive law on a grid of cells, extrapolated
    /// to JKR's limit; docs/thickness.md, "The grid across ρ", held in the slow
    /// tier) is within its stated bound, 0.22 %, of it (measured 0.077 %).
    #[test]
    fn the_free_edge_s_pull_off_at_rho_0_8_converges_and_meets_the_grid_s() {
        two_rungs_meet_the_grid(1.0, 0.8, (1e-5, 1e-5), (-2.536940, 0.0022));
    }

    /// The pull-off of equal coatings of thinness `h` at `rho` on the rungs
    /// 12 × 3 and 16 × 4: the two within `apart`, Griffith's error between
    /// the angles on the finer within `griffith`, and the grid's pull-off
    /// `grid` within its stated relative `bound` of the finer.
    fn two_rungs_meet_the_grid(
        h: f64,
        rho: f64,
        (apart, griffith): (f64, f64),
        (grid, bound): (f64, f64),
    ) {
        let layers = Layers::equal(h, 0.5).unwrap();
        let rungs = [
            Resolution::rung(12, 3, 8, 32),
            Resolution::rung(16, 4, 16, 64),
        ];
        let ladder = pull_off_ladder(&layers, rho, &rungs, |_, _| {}).unwrap();
        let (coarse, fine) = (&ladder[0], &ladder[1]);
        assert!(
            (coarse.force_bar / fine.force_bar - 1.0).abs() < apart,
            "{} against {}",
            coarse.force_bar,
            fine.force_bar
        );
        assert!(
            fine.griffith_error < griffith,
            "{:.1e}",
            fine.griffith_error
        );
        assert!(
            (fine.force_bar / grid - 1.0).abs() < bound,
            "{} against the grid's {grid}",
            fine.force_bar
        );
    }

    /// At θ = 60° with the guide's coatings (equal cylinders, ρ = 1/3,
    /// h/L = 0.5785) the free edge's pull-off on 12 × 3 and 16 × 4
    /// functions agrees within 2e-3 (measured 1.5e-3; 16 × 4 against 32 × 8,
    /// twice the resolution, 1.6e-5 in the exploration), Griffith's
    /// condition holds between the angles within 1e-3 on the finer (1.5e-4),
    /// and the grid solver's pull-off, −1.835787 with its bound 0.24 %
    /// (docs/thickness.md, "At 60°, against twice the resolution"), is
    /// within that bound of it (measured 0.23 %).
    #[test]
    fn at_60_degrees_the_free_edge_s_pull_off_converges_and_meets_the_grid_s() {
        two_rungs_meet_the_grid(0.5785474, 1.0 / 3.0, (2e-3, 1e-3), (-1.835787, 0.0024));
    }

    /// docs/thickness.md's two tables of the sharp edge, every number of
    /// the sharp edge computed again and compared at its printed precision
    /// (they were typed in from the explorations' output): the ladders at
    /// ρ = 0.8 and 60° (the times are not held), and the table against the
    /// grid (the sharp edge's pull-off, its last two rungs' difference, and
    /// the grid's departure from it).
    #[test]
    #[ignore = "slow tier (.ci/slow): the sharp edge's tables of docs/thickness.md, about 5 minutes"]
    fn the_sharp_edge_tables_of_the_docs_are_the_solver_s() {
        use super::super::grid::tables::{doc, table};
        let doc = doc();
        let mut bad = Vec::new();
        let mut check = |what: String, value: f64, printed: &str| {
            if !crate::layer::as_printed(value, printed) {
                bad.push(format!("{what}: computed {value}, printed {printed}"));
            }
        };
        let ladder = [
            Resolution::rung(12, 3, 8, 32),
            Resolution::rung(16, 4, 16, 64),
            Resolution::rung(20, 5, 16, 64),
            Resolution::rung(24, 6, 24, 96),
            Resolution::rung(32, 8, 32, 128),
        ];
        let rows = table(
            &doc,
            "| rung (functions, edge modes) | F̄ at ρ = 0.8, h/L = 1 | time | F̄ at ρ = 1/3, h/L = 0.5785 (60°) | time |",
        );
        assert_eq!(rows.len(), ladder.len());
        for (column, h, rho) in [(1, 1.0, 0.8), (3, 0.5785474, 1.0 / 3.0)] {
            let layers = Layers::equal(h, 0.5).unwrap();
            let found = pull_off_ladder(&layers, rho, &ladder, |_, _| {}).unwrap();
            for (row, st) in rows.iter().zip(&found) {
                check(
                    format!("{} at rho {rho}", row[0]),
                    st.force_bar,
                    &row[column],
                );
            }
        }
        let rows = table(
            &doc,
            "| h/L | ρ | F̄, 20 × 5 | 16 × 4 against 20 × 5 | the grid's F̄ (bound) | grid against sharp |",
        );
        assert!(rows.len() >= 10, "{} rows", rows.len());
        for row in &rows {
            let h = match row[0].as_str() {
                "0.5785" => 0.5785474,
                t => t.parse().unwrap(),
            };
            let rho = match row[1].split_whitespace().next().unwrap() {
                "1/3" => 1.0 / 3.0,
                r => r.parse().unwrap(),
            };
            let layers = Layers::equal(h, 0.5).unwrap();
            let found = pull_off_ladder(&layers, rho, &ladder[..3], |_, _| {}).unwrap();
            let (fine, finest) = (found[1].force_bar, found[2].force_bar);
            let what = format!("h/L {h}, rho {rho}");
            check(what.clone(), finest, &row[2]);
            check(what.clone(), (fine / finest - 1.0).abs(), &row[3]);
            if let Some(grid) = row[4]
                .split_whitespace()
                .next()
                .filter(|g| !g.starts_with('('))
            {
                let grid: f64 = grid.replace('−', "-").parse().unwrap();
                check(what, grid / finest - 1.0, &row[5]);
            }
        }
        assert!(
            bad.is_empty(),
            "docs/thickness.md differs:\n{}",
            bad.join("\n")
        );
    }

    #[test]
    fn a_number_is_read_as_printed() {
        assert!(crate::layer::as_printed(-2.538882851, "−2.53888285"));
        assert!(!crate::layer::as_printed(-2.53888296, "−2.53888285"));
        assert!(crate::layer::as_printed(-0.00147, "**−0.147 %**"));
        assert!(crate::layer::as_printed(3.94e-7, "3.9e-7"));
        assert!(!crate::layer::as_printed(4.0e-7, "3.9e-7"));
        assert!(crate::layer::as_printed(3e-10, "< 1e-9"));
        assert!(!crate::layer::as_printed(2e-9, "< 1e-9"));
    }

    /// The free edge's pull-off across ρ and h/L on three rungs (12 × 3,
    /// 16 × 4 and 20 × 5 functions, as many edge modes as angular orders;
    /// each rung from the last one's pull-off), a markdown row each: run in
    /// release with `--ignored --nocapture`; THINJKR_SHARP_THINS and
    /// THINJKR_SHARP_RHOS (comma-separated) choose the rows.
    #[test]
    #[ignore = "exploration: prints the free edge's pull-offs across rho"]
    fn explore_the_free_edge_across_rho() {
        let list = |k: &str, d: &[f64]| -> Vec<f64> {
            std::env::var(k)
                .ok()
                .map(|v| v.split(',').filter_map(|x| x.trim().parse().ok()).collect())
                .unwrap_or_else(|| d.to_vec())
        };
        let thins = list("THINJKR_SHARP_THINS", &[0.2, 0.3, 0.5, 0.73, 1.0]);
        let rhos = list("THINJKR_SHARP_RHOS", &[0.8, 0.5, 1.0 / 3.0, 0.2, 0.0717968]);
        println!(
            "| h/L | rho | F 12x3 | F 16x4 | F 20x5 | 16 vs 20 | delta | a | b | griffith | s |"
        );
        for &h in &thins {
            let layers = Layers::equal(h, 0.5).unwrap();
            for &rho in &rhos {
                let t = std::time::Instant::now();
                let mut forces = Vec::new();
                let mut values = Vec::new();
                let mut last = None;
                let rungs = [
                    Resolution::rung(12, 3, 8, 32),
                    Resolution::rung(16, 4, 16, 64),
                    Resolution::rung(20, 5, 16, 64),
                ];
                let ladder = pull_off_ladder(&layers, rho, &rungs, |_, st| {
                    forces.push(format!("{:.8}", st.force_bar));
                    values.push(st.force_bar);
                    last = Some(st.clone());
                });
                if let Err(e) = ladder {
                    forces.push(format!("({e})"));
                }
                let apart = match (values.get(1), values.get(2)) {
                    (Some(a), Some(b)) => format!("{:.1e}", (a / b - 1.0).abs()),
                    _ => "-".into(),
                };
                let tail = match last {
                    Some(st) => format!(
                        "{:.6} | {:.6} | {:.6} | {:.1e}",
                        st.delta_bar, st.a_bar, st.b_bar, st.griffith_error
                    ),
                    None => "- | - | - | -".into(),
                };
                println!(
                    "| {h} | {rho:.6} | {} | {apart} | {tail} | {:.1} |",
                    forces.join(" | "),
                    t.elapsed().as_secs_f64()
                );
            }
        }
    }

    /// The state at radius `a` on a circle with Griffith's condition.
    fn circle_state(layers: &Layers, a: f64, radial: usize, sources: Sources) -> (f64, f64) {
        let res = Resolution {
            radial,
            angular: 1,
            along: 32,
            rays: 64,
            sources,
            shape: 1,
        };
        let solver = Bilateral::on_layers(Domain::ellipse(a, a), layers, &res).unwrap();
        let one = solver.solve(|_, _| 1.0).unwrap();
        let gap = solver.solve(|x, y| 0.5 * (x * x + y * y)).unwrap();
        let beta = layers.beta();
        let delta = ((2.0 * beta).sqrt() + solver.intensity(&gap, 0.0).unwrap())
            / solver.intensity(&one, 0.0).unwrap();
        (delta, solver.force(&(one * delta - gap), 24).unwrap())
    }

    /// The free edge's pull-off at ρ = `THINJKR_SHARP_RHO` (0.8) and h/L =
    /// `THINJKR_SHARP_THIN` (1) against the resolution, with
    /// `THINJKR_SHARP_LADDER=1` (`=40`: and 40 × 10 functions; and `THINJKR_SHARP_LINES=2`: twice the
    /// points and lines through each node; `THINJKR_SHARP_SOURCES=2`: twice
    /// the base share's sources; `THINJKR_SHARP_RUNGS=24x4/16/64,…`: these
    /// rungs, radial x angular / panels / angles) (run it in release: `cargo test --release -p
    /// thinjkr --lib explore_the_free_edge_pull_off -- --ignored
    /// --nocapture`); without it the coarsest resolution alone.
    #[test]
    #[ignore = "exploration: prints the free edge's pull-offs"]
    fn explore_the_free_edge_pull_off() {
        let var = |k: &str, d: f64| {
            std::env::var(k)
                .ok()
                .and_then(|v| v.parse().ok())
                .unwrap_or(d)
        };
        let (rho, h) = (
            var("THINJKR_SHARP_RHO", 0.8),
            var("THINJKR_SHARP_THIN", 1.0),
        );
        let layers = Layers::equal(h, 0.5).unwrap();
        // the coarsest alone unless THINJKR_SHARP_LADDER is set (the slow
        // tier runs every exploration)
        let mut ladder = vec![
            Resolution::rung(12, 3, 8, 32),
            Resolution::rung(16, 4, 16, 64),
            Resolution::rung(20, 5, 16, 64),
            Resolution::rung(24, 6, 24, 96),
            Resolution::rung(32, 8, 32, 128),
        ];
        // THINJKR_SHARP_RUNGS = "radialxangular/panels/angles,…": these
        // rungs instead (e.g. 24x4/16/64,32x4/24/96)
        if let Ok(list) = std::env::var("THINJKR_SHARP_RUNGS") {
            ladder = list
                .split(',')
                .map(|r| {
                    let n: Vec<usize> = r
                        .split(['x', '/'])
                        .map(|x| x.trim().parse().expect("radialxangular/panels/angles"))
                        .collect();
                    Resolution::rung(n[0], n[1], n[2], n[3])
                })
                .collect();
        }
        // THINJKR_SHARP_LADDER = 1: those five; = 40: a sixth, 40 × 10
        let rungs = match std::env::var("THINJKR_SHARP_LADDER").as_deref() {
            Ok("40") => {
                ladder.push(Resolution::rung(40, 10, 32, 128));
                ladder.len()
            }
            Ok(_) => ladder.len(),
            Err(_) => 1,
        };
        // the lines through each node: THINJKR_SHARP_LINES = 2, twice the
        // default 32 points along each of 32 lines
        let lines = var("THINJKR_SHARP_LINES", 1.0) as usize;
        // THINJKR_SHARP_WIDER = k: k more angular orders than edge modes
        let wider = var("THINJKR_SHARP_WIDER", 0.0) as usize;
        // THINJKR_SHARP_SOURCES = k: k times the base share's panels and
        // angles
        let more = var("THINJKR_SHARP_SOURCES", 1.0) as usize;
        let rungs: Vec<Resolution> = ladder[..rungs]
            .iter()
            .map(|r| Resolution {
                along: r.along * lines,
                rays: r.rays * lines,
                angular: r.angular + wider,
                radial: r.radial.max(r.angular + wider),
                sources: Sources {
                    panels: r.sources.panels * more,
                    angles: r.sources.angles * more,
                },
                ..*r
            })
            .collect();
        println!("rho {rho} h/L {h}");
        let mut t = std::time::Instant::now();
        let ladder = pull_off_ladder(&layers, rho, &rungs, |res, st| {
            println!(
                "  {}/{}/{}/{}: F {:.8} delta {:.6} half-widths {:.6} {:.6} griffith {:.1e} modes {:?} {:.1} s",
                res.radial,
                res.angular,
                res.sources.panels,
                res.sources.angles,
                st.force_bar,
                st.delta_bar,
                st.a_bar,
                st.b_bar,
                st.griffith_error,
                st.domain.modes,
                t.elapsed().as_secs_f64()
            );
            t = std::time::Instant::now();
        });
        if let Err(e) = ladder {
            println!("  {e}");
        }
    }
}
