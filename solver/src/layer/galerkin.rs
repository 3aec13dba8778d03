//! The layer's integral equation at one contact radius, solved by
//! Galerkin's method in the even Legendre polynomials.
//!
//! In the units (17) at ρ = 1, the pressure p̄(r) of a contact of radius ā
//! is carried by g(t) = ∫ₜᵃ r p̄(r)/√(r² − t²) dr, and the contact
//! condition (the approach δ̄ less the gap r²/2 inside the contact) reads
//! (Hankel transform, then Abel's)
//!
//!   g(s) − (1/π) ∫₋ₐᵃ F(s − t) g(t) dt = β (δ̄ − s²),  0 ≤ s ≤ ā,   (L1)
//!
//! with g even, F(u) = ∫₀^∞ Φ(k) cos(ku) dk, Φ the pair's share of the
//! half-space compliance that the rigid bases take away (the generated
//! `base_share`, weighted by each coating's (1 − ν)/G), and β = E*/(2mL³)
//! the half-space modulus of the pair in the units (17). On a half-space
//! (Φ = 0) g is β(δ̄ − s²): Sneddon's solution. By linearity g = δ̄ g₁ − g₂,
//! with g₁ for the right side β and g₂ for βs²; this module solves for both.
//!
//! In the basis P₂ₙ(t/ā), n < N, the cosine transforms are
//! ĝₙ(k) = 2ā(−1)ⁿ j₂ₙ(kā), and the Galerkin matrix is
//! ā/(4m + 1) δₘₙ − (1/2π) ∫₀^∞ Φ(k) ĝₘ ĝₙ dk, the integral taken by
//! composite Gauss–Legendre panels of 24 points no longer than 4π/ā (four
//! periods of the oscillation of ĝₘĝₙ) and than 2h⁻¹ (Φ is analytic within
//! about 1 of the real axis in kh) up to k = 22/h, beyond which Φ
//! is below 1e-15. The solution is analytic on [−ā, ā] except near the
//! edges, at a distance of about 2h (where F is singular), so its Legendre
//! coefficients fall geometrically, as (1 + √(2h/ā))^(−2n); the last ones
//! measure the truncation.
//!
//! Owns: `Solution`, `solve_with`, `modes_for`. May use: the parent (`layer`: the
//! coatings), `generated` (the layer's kernel), `error`, `quadrature` (Gauss–Legendre).

use super::bessel::orders;
use super::Layers;
use crate::error::{rounded, short, Error, Result};
use crate::quadrature::GaussLegendre;
use nalgebra::{DMatrix, DVector};
use rayon::prelude::*;

/// Φ below 1e-15 beyond q = kh = 22 (Φ ≈ 4q²e^{−2q}/(3 − 4ν)).
const Q_MAX: f64 = 22.0;
/// Gauss–Legendre points per panel.
const PANEL_POINTS: usize = 24;
/// Periods of the oscillation (π/ā in k) per panel: 6 points a period, where
/// the rule's error for a pure oscillation is below 1e-20.
const PERIODS: f64 = 4.0;
/// Nodes per block of the matrix product.
const BLOCK: usize = 128;
/// Nodes per part of the assembly that one thread takes; the parts are
/// summed in order, so the result does not depend on the number of threads.
const PART: usize = 16 * BLOCK;
/// The most Legendre modes a state may use.
pub(crate) const MODES_MAX: usize = 700;
/// The most work a state may take, quadrature nodes × modes² (the matrix
/// products' size): 2e11 is about 20 s on two cores. The table's thinnest
/// row, h/L = 0.001 at its pull-off, takes 3.5e10.
const WORK_MAX: f64 = 2e11;
/// The most quadrature nodes a state may allocate (64 MB).
const NODES_MAX: f64 = 4e6;
/// Parts of the assembly summed at a time: the memory held is this many
/// pairs of matrices, whatever the number of nodes.
const GROUP: usize = 8;

/// g₁ and g₂ of (L1) at one contact radius, as Legendre coefficients:
/// g(t) = Σ cₙ P₂ₙ(t/ā).
#[derive(Clone, Debug)]
pub(crate) struct Solution {
    pub(crate) a_bar: f64,
    pub(crate) g1: DVector<f64>,
    pub(crate) g2: DVector<f64>,
    /// dg₁/dā and dg₂/dā, where asked for.
    pub(crate) slopes: Option<(DVector<f64>, DVector<f64>)>,
}

impl Solution {
    /// g(ā) of g = δ̄g₁ − g₂ at the edge: Σ cₙ (P₂ₙ(1) = 1), for g₁ and g₂.
    pub(crate) fn edge(&self) -> (f64, f64) {
        (self.g1.sum(), self.g2.sum())
    }

    /// ∫₀ᵃ g dt for g₁ and g₂ (only P₀ has a mean).
    pub(crate) fn integral(&self) -> (f64, f64) {
        (self.a_bar * self.g1[0], self.a_bar * self.g2[0])
    }

    /// The truncation: the largest of the last two coefficients of g₁ and
    /// g₂, each over its largest coefficient.
    pub(crate) fn tail(&self) -> f64 {
        let tail = |c: &DVector<f64>| {
            let n = c.len();
            let top = c.amax().max(f64::MIN_POSITIVE);
            c.rows(n.saturating_sub(2), n.min(2)).amax() / top
        };
        tail(&self.g1).max(tail(&self.g2))
    }
}

/// The number of modes for a relative truncation of about 1e-15 at contact
/// radius ā: the geometric rate (1 + √(2h/ā))^(−2n) of the module's doc,
/// h the thinner coating's thickness.
pub(crate) fn modes_for(layers: &Layers, a_bar: f64) -> usize {
    let rate = (1.0 + (2.0 * layers.thinnest() / a_bar).sqrt()).ln();
    let degree = 15.0 * std::f64::consts::LN_10 / rate;
    ((degree / 2.0).ceil() as usize + 4).clamp(8, MODES_MAX)
}

/// G and G′ (zero unless `slopes`) over the quadrature nodes `part`.
fn assemble(
    layers: &Layers,
    a_bar: f64,
    n: usize,
    part: &[(f64, f64)],
    slopes: bool,
) -> (DMatrix<f64>, DMatrix<f64>) {
    let mut g = DMatrix::<f64>::zeros(n, n);
    let mut g_slope = DMatrix::<f64>::zeros(if slopes { n } else { 0 }, if slopes { n } else { 0 });
    let mut weighted = DMatrix::<f64>::zeros(n, BLOCK);
    let mut plain = DMatrix::<f64>::zeros(n, BLOCK);
    let mut moved = DMatrix::<f64>::zeros(n, BLOCK);
    let mut j = vec![0.0; 2 * n];
    for block in part.chunks(BLOCK) {
        for (col, &(k, w)) in block.iter().enumerate() {
            let x = k * a_bar;
            orders(x, &mut j);
            let scale = w * layers.base_share(k) / (2.0 * std::f64::consts::PI);
            for i in 0..n {
                let sign = if i % 2 == 0 { 2.0 } else { -2.0 };
                let g_hat = sign * a_bar * j[2 * i];
                plain[(i, col)] = g_hat;
                weighted[(i, col)] = scale * g_hat;
                if slopes {
                    // ∂/∂ā [2ā j₂ₙ(kā)] = 2(j₂ₙ + x j₂ₙ′), x j_l′ = x j_{l−1} − (l + 1) j_l
                    let x_slope = if i == 0 {
                        -x * j[1]
                    } else {
                        x * j[2 * i - 1] - (2 * i + 1) as f64 * j[2 * i]
                    };
                    moved[(i, col)] = scale * sign * (j[2 * i] + x_slope);
                }
            }
        }
        let used = block.len();
        let p = plain.columns(0, used).transpose();
        g.gemm(1.0, &weighted.columns(0, used), &p, 1.0);
        if slopes {
            g_slope.gemm(1.0, &moved.columns(0, used), &p, 1.0);
        }
    }
    (g, g_slope)
}

/// Solves (L1) for g₁ and g₂ at contact radius `a_bar` with `modes`
/// Legendre modes and quadrature panels `refine` times finer than the
/// module's rule; with `slopes` also the derivatives of g₁'s and g₂'s
/// coefficients in ā (the basis P₂ₙ(t/ā) moving with the edge).
pub(crate) fn solve_with(
    layers: &Layers,
    a_bar: f64,
    modes: usize,
    refine: f64,
    slopes: bool,
) -> Result<Solution> {
    let n = modes.clamp(2, MODES_MAX);
    let k_max = Q_MAX / layers.thinnest();
    let width = (PERIODS * std::f64::consts::PI / a_bar).min(2.0 / layers.thickest()) / refine;
    let panels = (k_max / width).ceil();
    let work = panels * PANEL_POINTS as f64 * (n * n) as f64;
    if !(work <= WORK_MAX && panels * PANEL_POINTS as f64 <= NODES_MAX) {
        return Err(Error::Unsupported {
            name: "a_bar",
            value: a_bar,
            supported: format!(
                "a contact radius whose quadrature takes at most {} nodes and nodes times Legendre \
                 modes squared stay below {} (this one needs {} nodes and {} at h/L = {}; the work grows \
                 as a_bar² h⁻³)",
                short(NODES_MAX),
                short(WORK_MAX),
                short(panels * PANEL_POINTS as f64),
                short(work),
                short(layers.thinnest())
            )
            .into(),
        });
    }
    let nodes = GaussLegendre::new(PANEL_POINTS).composite(0.0, k_max, panels as usize);
    // G = (1/2π)∫Φ ĝ ĝᵀ dk, and with slopes G′ = (1/2π)∫Φ ∂ĝ/∂ā ĝᵀ dk: parts
    // on rayon's threads, summed in order a group at a time
    let (mut g, mut g_slope) = (DMatrix::<f64>::zeros(n, n), DMatrix::<f64>::zeros(n, n));
    let parts: Vec<&[(f64, f64)]> = nodes.chunks(PART).collect();
    for group in parts.chunks(GROUP) {
        let sums: Vec<(DMatrix<f64>, DMatrix<f64>)> = group
            .par_iter()
            .map(|part| assemble(layers, a_bar, n, part, slopes))
            .collect();
        for (p, p_slope) in sums {
            g += p;
            if slopes {
                g_slope += p_slope;
            }
        }
    }
    let mut a = -g;
    for i in 0..n {
        a[(i, i)] += a_bar / (4 * i + 1) as f64;
    }
    let beta = layers.beta();
    let mut rhs = DMatrix::<f64>::zeros(n, 2);
    rhs[(0, 0)] = beta * a_bar;
    rhs[(0, 1)] = beta * a_bar.powi(3) / 3.0;
    rhs[(1, 1)] = beta * a_bar.powi(3) * 2.0 / 15.0;
    let unsolved = || Error::Unresolved {
        what: format!(
            "the layer's Galerkin system at a_bar = {} with {n} modes is singular",
            rounded(a_bar)
        ),
        residual: f64::INFINITY,
    };
    // scaled to the orthonormal basis (the mass matrix becomes 1), where
    // the matrix is symmetric positive definite: Cholesky
    let d = DVector::from_fn(n, |i, _| ((4 * i + 1) as f64 / a_bar).sqrt());
    let scaled = DMatrix::from_fn(n, n, |i, k| d[i] * a[(i, k)] * d[k]);
    let chol = scaled.cholesky().ok_or_else(unsolved)?;
    let solve_scaled = |b: &DMatrix<f64>| {
        let mut y = DMatrix::from_fn(n, b.ncols(), |i, c| d[i] * b[(i, c)]);
        chol.solve_mut(&mut y);
        DMatrix::from_fn(n, b.ncols(), |i, c| d[i] * y[(i, c)])
    };
    let x = solve_scaled(&rhs);
    // the normwise backward error: the solve is backward stable, and x is
    // as large against b as A is close to singular (in the thin limit)
    let residual = (&a * &x - &rhs).amax() / (a.amax() * x.amax() * n as f64 + rhs.amax());
    if !(residual < 1e-13) {
        return Err(Error::Unresolved {
            what: format!(
                "the layer's Galerkin system at a_bar = {} with {n} modes solves only to {}",
                rounded(a_bar),
                short(residual)
            ),
            residual,
        });
    }
    let slopes = if slopes {
        // S c = b, so S dc/dā = db/dā − (dS/dā) c with
        // dS/dā = diag(1/(4m + 1)) − G′ − G′ᵀ
        let mut ds = -(&g_slope + g_slope.transpose());
        for i in 0..n {
            ds[(i, i)] += 1.0 / (4 * i + 1) as f64;
        }
        let mut db = DMatrix::<f64>::zeros(n, 2);
        db[(0, 0)] = beta;
        db[(0, 1)] = beta * a_bar * a_bar;
        db[(1, 1)] = beta * a_bar * a_bar * 2.0 / 5.0;
        let dx = solve_scaled(&(db - ds * &x));
        Some((dx.column(0).into_owned(), dx.column(1).into_owned()))
    } else {
        None
    };
    Ok(Solution {
        a_bar,
        g1: x.column(0).into_owned(),
        g2: x.column(1).into_owned(),
        slopes,
    })
}
