//! The pair's compliance on the grid: the surface displacement at a cell's
//! centre from a unit pressure on another cell, and its product with a
//! pressure field by zero-padded FFTs (a linear, not periodic,
//! convolution).
//!
//! The compliance of the pair at wave number k̄ is (1 − Φ(k̄))/(βk̄) in the
//! units (17) (Φ the pair's base share, β of `Layers`): the half-space's
//! 1/(βk̄), whose influence on a square cell is Love's closed form, less the
//! base's share, Φ/(βk̄), a function c(r) smooth on the scale of h,
//! integrated over the cell by the 4 × 4-point Gauss rule (exact to order
//! (Δ/h)⁸). c(r) is a Hankel transform, −(1/2πβ)∫₀^∞ Φ J₀(k̄r) dk̄, by
//! Gauss–Legendre panels no wider than a half period of J₀ at the grid's
//! largest distance, tabulated in r at h/100 and read by cubic
//! interpolation.
//!
//! Owns: `Kernel`, `BaseShare`. May use: `layer` (the pair's Φ and β), `quadrature`,
//! `layer::grid::bessel0`.

use super::super::Layers;
use super::bessel0::j0;
use super::Compliance;
use crate::quadrature::GaussLegendre;
use rayon::prelude::*;
use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// The compliance of the pair on an n × n grid of square cells of side Δ.
pub(crate) struct Kernel {
    /// Cells per side.
    n: usize,
    /// The padded side, 2n.
    m: usize,
    /// The spectrum of the cell influences, wrapped on the padded grid
    /// (real: the influences are even in x and y), divided by m².
    spectrum: Vec<f64>,
    /// Its reciprocal, divided by m² (the stiffness of the padded grid,
    /// capped where the spectrum is below 1e-4 of its largest).
    stiffness: Vec<f64>,
    forward: Arc<dyn Fft<f64>>,
    inverse: Arc<dyn Fft<f64>>,
}

/// The displacement at (x, y) from a unit pressure on the square
/// [−d, d]², times 2πβ: Love's ∫∫ dA′/|x − x′| (Johnson, Contact
/// Mechanics, 3.25), as the four corners of G(u, v) with ∂²G/∂u∂v = 1/r.
pub(crate) fn love(x: f64, y: f64, d: f64) -> f64 {
    fn g(u: f64, v: f64) -> f64 {
        let a = if u == 0.0 {
            0.0
        } else {
            u * (v / u.abs()).asinh()
        };
        let b = if v == 0.0 {
            0.0
        } else {
            v * (u / v.abs()).asinh()
        };
        a + b
    }
    g(x + d, y + d) - g(x + d, y - d) - g(x - d, y + d) + g(x - d, y - d)
}

/// c(r), the base's share of the compliance in the plane, on
/// r = 0, dr, 2dr, … up to `r_max` (the grid's, and `layer::sharp`'s).
#[derive(Clone)]
pub(crate) struct BaseShare {
    dr: f64,
    c: Vec<f64>,
}

impl BaseShare {
    pub(crate) fn new(layers: &Layers, r_max: f64) -> BaseShare {
        let [a, b] = layers.coatings();
        let (h_min, h_max) = (a.thinness.min(b.thinness), a.thinness.max(b.thinness));
        // Φ < 1e-17 beyond k̄h = 25
        let k_top = 25.0 / h_min;
        let width = (std::f64::consts::PI / r_max).min(0.5 / h_max);
        let panels = (k_top / width).ceil() as usize;
        let rule = GaussLegendre::new(16).composite(0.0, k_top, panels);
        let nodes: Vec<(f64, f64)> = rule
            .iter()
            .map(|&(k, w)| (k, w * layers.base_share(k)))
            .collect();
        let dr = (h_min / 100.0).min(r_max / 2000.0);
        let count = (r_max / dr).ceil() as usize + 3;
        let scale = 1.0 / (2.0 * std::f64::consts::PI * layers.beta());
        let c = (0..count)
            .into_par_iter()
            .map(|i| {
                let r = i as f64 * dr;
                -scale * nodes.iter().map(|&(k, wphi)| wphi * j0(k * r)).sum::<f64>()
            })
            .collect();
        BaseShare { dr, c }
    }

    /// Cubic interpolation in the table (c is even in r: the points below
    /// zero mirror those above).
    pub(crate) fn at(&self, r: f64) -> f64 {
        let t = r / self.dr;
        let i = (t.floor() as usize).min(self.c.len() - 3);
        let u = t - i as f64;
        let pick = |v: &[f64], j: isize| v[j.unsigned_abs()];
        let w = [
            -u * (u - 1.0) * (u - 2.0) / 6.0,
            (u + 1.0) * (u - 1.0) * (u - 2.0) / 2.0,
            -(u + 1.0) * u * (u - 2.0) / 2.0,
            (u + 1.0) * u * (u - 1.0) / 6.0,
        ];
        w.iter()
            .enumerate()
            .map(|(k, wk)| wk * pick(&self.c, i as isize + k as isize - 1))
            .sum()
    }

    /// ∫∫ c over the square of side `dx` centred at (x, y), by the
    /// 4 × 4-point Gauss rule.
    fn over_cell(&self, x: f64, y: f64, dx: f64, rule: &GaussLegendre) -> f64 {
        let mut sum = 0.0;
        for (u, wu) in rule.nodes.iter().zip(&rule.weights) {
            for (v, wv) in rule.nodes.iter().zip(&rule.weights) {
                sum += wu * wv * self.at((x + 0.5 * dx * u).hypot(y + 0.5 * dx * v));
            }
        }
        0.25 * dx * dx * sum
    }
}

impl Kernel {
    /// The kernel of `layers` on n × n cells of side `dx`.
    pub(crate) fn new(layers: &Layers, n: usize, dx: f64) -> Kernel {
        let r_max = dx * n as f64 * std::f64::consts::SQRT_2 + dx;
        let base = BaseShare::new(layers, r_max);
        Kernel::with_base(n, dx, layers.beta(), Some(&base))
    }

    /// The half-space of modulus β alone (E* = 2β), no base: the peers'
    /// problem of solver/benches/peer/grid_peers.py.
    #[cfg(feature = "bench-internals")]
    pub(crate) fn half_space(beta: f64, n: usize, dx: f64) -> Kernel {
        Kernel::with_base(n, dx, beta, None)
    }

    /// The half-space of modulus β less the base's share `base`, if any.
    fn with_base(n: usize, dx: f64, beta: f64, base: Option<&BaseShare>) -> Kernel {
        let m = 2 * n;
        let half_space = 1.0 / (2.0 * std::f64::consts::PI * beta);
        let d = 0.5 * dx;
        let rule = GaussLegendre::new(4);
        let mut buf = vec![Complex64::new(0.0, 0.0); m * m];
        for i in 0..n {
            for j in 0..=i {
                let (x, y) = (i as f64 * dx, j as f64 * dx);
                let v =
                    half_space * love(x, y, d) + base.map_or(0.0, |b| b.over_cell(x, y, dx, &rule));
                for (a, b) in [(i, j), (j, i)] {
                    for (ia, jb) in [
                        (a, b),
                        ((m - a) % m, b),
                        (a, (m - b) % m),
                        ((m - a) % m, (m - b) % m),
                    ] {
                        buf[ia * m + jb] = Complex64::new(v, 0.0);
                    }
                }
            }
        }
        let mut planner = FftPlanner::new();
        let forward = planner.plan_fft_forward(m);
        let inverse = planner.plan_fft_inverse(m);
        fft2(&mut buf, m, m, &forward);
        let norm = 1.0 / (m * m) as f64;
        let spectrum: Vec<f64> = buf.iter().map(|z| z.re * norm).collect();
        let floor = 1e-4 * spectrum.iter().fold(0.0f64, |a, b| a.max(*b));
        let stiffness = spectrum
            .iter()
            .map(|s| norm * norm / s.max(floor))
            .collect();
        Kernel {
            n,
            m,
            spectrum,
            stiffness,
            forward,
            inverse,
        }
    }

    /// The product of `p` with the padded grid's operator of spectrum
    /// `multiplier` (divided by m²), two real rows per complex FFT.
    fn product(&self, p: &[f64], out: &mut [f64], multiplier: &[f64]) {
        let (n, m) = (self.n, self.m);
        let half = m / 2 + 1;
        let pairs = n.div_ceil(2);
        let zero = Complex64::new(0.0, 0.0);
        // rows 2q and 2q + 1 as one complex row
        let mut rows = vec![zero; pairs * m];
        rows.par_chunks_mut(m).enumerate().for_each(|(q, row)| {
            for j in 0..n {
                let im = if 2 * q + 1 < n {
                    p[(2 * q + 1) * n + j]
                } else {
                    0.0
                };
                row[j] = Complex64::new(p[2 * q * n + j], im);
            }
        });
        fft_rows(&mut rows, m, &self.forward);
        // the columns of frequency 0 … m/2, each the length m of the padded
        // rows: X = (Z_k + conj Z_{m−k})/2, Y = (Z_k − conj Z_{m−k})/2i
        let mut cols = vec![zero; half * m];
        cols.par_chunks_mut(m).enumerate().for_each(|(k, col)| {
            let k2 = (m - k) % m;
            for q in 0..pairs {
                let (z, w) = (rows[q * m + k], rows[q * m + k2].conj());
                col[2 * q] = 0.5 * (z + w);
                if 2 * q + 1 < n {
                    let d = z - w;
                    col[2 * q + 1] = Complex64::new(0.5 * d.im, -0.5 * d.re);
                }
            }
        });
        fft_rows(&mut cols, m, &self.forward);
        // the spectrum is symmetric in its two indices
        cols.par_chunks_mut(m).enumerate().for_each(|(k, col)| {
            for (r, z) in col.iter_mut().enumerate() {
                *z *= multiplier[k * m + r];
            }
        });
        fft_rows(&mut cols, m, &self.inverse);
        // rows 2q and 2q + 1 of the product, each Hermitian in its
        // frequency, as one complex row whose inverse FFT holds the first
        // in its real part and the second in its imaginary part
        rows.par_chunks_mut(m).enumerate().for_each(|(q, row)| {
            for (k, slot) in row.iter_mut().enumerate() {
                let (kk, conj) = if k < half { (k, false) } else { (m - k, true) };
                let a = cols[kk * m + 2 * q];
                let b = if 2 * q + 1 < n {
                    cols[kk * m + 2 * q + 1]
                } else {
                    zero
                };
                let (a, b) = if conj { (a.conj(), b.conj()) } else { (a, b) };
                *slot = a + Complex64::new(-b.im, b.re);
            }
        });
        fft_rows(&mut rows, m, &self.inverse);
        for q in 0..pairs {
            for j in 0..n {
                out[2 * q * n + j] = rows[q * m + j].re;
                if 2 * q + 1 < n {
                    out[(2 * q + 1) * n + j] = rows[q * m + j].im;
                }
            }
        }
    }
}

impl Compliance for Kernel {
    /// The displacement A·p at every cell from the pressures p (n × n, row
    /// by row). The pressures are real, and so is the product: two rows
    /// of pressure go through one complex FFT (the real and imaginary
    /// parts, told apart by the symmetry of a real row's transform), only
    /// the columns of non-negative frequency are transformed (the others
    /// are their conjugates), and two rows of the product come back from
    /// one inverse FFT, half the transforms of a complex product.
    fn apply(&self, p: &[f64], out: &mut [f64]) {
        self.product(p, out, &self.spectrum)
    }

    fn stiffen(&self, w: &[f64], out: &mut [f64]) {
        self.product(w, out, &self.stiffness)
    }
}

fn fft_rows(buf: &mut [Complex64], m: usize, fft: &Arc<dyn Fft<f64>>) {
    buf.par_chunks_mut(m * 16).for_each(|rows| {
        let mut scratch = vec![Complex64::new(0.0, 0.0); fft.get_inplace_scratch_len()];
        for row in rows.chunks_mut(m) {
            fft.process_with_scratch(row, &mut scratch);
        }
    });
}

fn transpose(buf: &mut [Complex64], m: usize) {
    const B: usize = 32;
    for ib in (0..m).step_by(B) {
        for jb in (ib..m).step_by(B) {
            for i in ib..(ib + B).min(m) {
                let start = if ib == jb { i + 1 } else { jb };
                for j in start..(jb + B).min(m) {
                    buf.swap(i * m + j, j * m + i);
                }
            }
        }
    }
}

/// The 2D FFT of an rows × m array in place (rows = m).
fn fft2(buf: &mut [Complex64], rows: usize, m: usize, fft: &Arc<dyn Fft<f64>>) {
    debug_assert_eq!(rows, m);
    fft_rows(buf, m, fft);
    transpose(buf, m);
    fft_rows(buf, m, fft);
    transpose(buf, m);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::layer::Layers;

    #[test]
    fn love_s_square_is_the_quadrature_of_one_over_r() {
        // centre of the square: 8d·asinh(1); far away: area/r
        let d = 0.5;
        assert!((love(0.0, 0.0, d) - 8.0 * d * 1f64.asinh()).abs() < 1e-14);
        let (x, y) = (1.3, 0.4);
        let rule = GaussLegendre::new(40).composite(-d, d, 1);
        let mut q = 0.0;
        for &(u, wu) in &rule {
            for &(v, wv) in &rule {
                q += wu * wv / (x - u).hypot(y - v);
            }
        }
        assert!(
            (love(x, y, d) - q).abs() < 1e-12,
            "{} against {q}",
            love(x, y, d)
        );
    }

    #[test]
    fn the_convolution_is_the_direct_sum() {
        let layers = Layers::equal(0.5, 0.5).unwrap();
        for (n, dx) in [(12, 0.1), (9, 0.13)] {
            let k = Kernel::new(&layers, n, dx);
            let p: Vec<f64> = (0..n * n).map(|i| ((i * 7919) % 13) as f64 - 6.0).collect();
            let mut w = vec![0.0; n * n];
            k.apply(&p, &mut w);
            // the direct sum with the same cell influences
            let base = BaseShare::new(&layers, dx * n as f64 * std::f64::consts::SQRT_2 + dx);
            let hs = 1.0 / (2.0 * std::f64::consts::PI * layers.beta());
            let rule = GaussLegendre::new(4);
            let infl = |di: isize, dj: isize| {
                let (x, y) = (di as f64 * dx, dj as f64 * dx);
                hs * love(x, y, 0.5 * dx) + base.over_cell(x, y, dx, &rule)
            };
            for (a, wa) in w.iter().enumerate() {
                let (ai, aj) = ((a / n) as isize, (a % n) as isize);
                let mut direct = 0.0;
                for (b, pb) in p.iter().enumerate() {
                    let (bi, bj) = ((b / n) as isize, (b % n) as isize);
                    direct += infl(ai - bi, aj - bj) * pb;
                }
                assert!(
                    (wa - direct).abs() < 1e-12 * direct.abs().max(1.0),
                    "{a}: {wa} against {direct}"
                );
            }
        }
    }
}

#[cfg(test)]
mod gaussian {
    use super::*;
    use crate::layer::{Coating, Layers};

    /// The displacement at distance r from the centre of the pressure
    /// e^(−r²/s²) on the pair, by the Hankel transform of the compliance
    /// (1 − Φ)/(βk̄) (a route that shares only Φ with the grid's):
    /// w(r) = (s²/2β)∫₀^∞ (1 − Φ) e^(−k̄²s²/4) J₀(k̄r) dk̄.
    fn exact(layers: &Layers, s: f64, r: f64) -> f64 {
        let rule = GaussLegendre::new(32).composite(0.0, 14.0 / s, 200);
        let sum: f64 = rule
            .iter()
            .map(|&(k, w)| {
                w * (1.0 - layers.base_share(k)) * (-(k * s).powi(2) / 4.0).exp() * j0(k * r)
            })
            .sum();
        s * s / (2.0 * layers.beta()) * sum
    }

    /// (grid − exact)/(largest displacement) at the centres of the cells
    /// (i, n/2) of a grid of `cells` = n·`refine` cells per side (each cell of
    /// the n-grid split into refine × refine, refine odd, so that the
    /// centres are shared), for i at about 0, s, 2s and 4s from the centre.
    fn errors(layers: &Layers, s: f64, n: usize, refine: usize) -> Vec<f64> {
        let w_half = 4.5 * s;
        let cells = n * refine;
        let dx = 2.0 * w_half / cells as f64;
        let k = Kernel::new(layers, cells, dx);
        let centre = |i: usize| (i as f64 + 0.5 - 0.5 * cells as f64) * dx;
        let mut p = vec![0.0; cells * cells];
        for i in 0..cells {
            for j in 0..cells {
                p[i * cells + j] = (-(centre(i).powi(2) + centre(j).powi(2)) / (s * s)).exp();
            }
        }
        let mut w = vec![0.0; cells * cells];
        k.apply(&p, &mut w);
        let top = exact(layers, s, 0.0);
        let fine = |i: usize| i * refine + refine / 2;
        [n / 2, n / 2 + n / 9, n / 2 + 2 * n / 9, n / 2 + 4 * n / 9]
            .iter()
            .map(|&i| {
                let (a, b) = (fine(i), fine(n / 2));
                (w[a * cells + b] - exact(layers, s, centre(a).hypot(centre(b)))) / top
            })
            .collect()
    }

    #[test]
    fn a_gaussian_pressure_displaces_the_surface_as_the_hankel_transform_says() {
        // The grid samples the pressure at the cells' centres, an error of
        // order Δ² once the cells are finer than the coatings (Δ ≤ h/8): a
        // third of the cell size cuts it about ninefold, and the two grids
        // extrapolated leave 15 % of it or less, 12 % at the centre for
        // h/L = 0.3 (the kernel itself,
        // Love's cells and the base's share, is exact to a higher order;
        // 3e-6 where the error changes sign between the two grids).
        // Here s = 0.3 and Δ = 0.0375, then 0.0125: a thick pair (nearly
        // JKR's half-spaces), one about as thick as the load is wide, and
        // two unequal compressible coatings (h/L 0.2 and 0.6).
        let s = 0.3;
        let unequal = Layers::new(
            Coating {
                thinness: 0.2,
                shear_modulus: 1.0,
                nu: 0.3,
            },
            Coating {
                thinness: 0.6,
                shear_modulus: 3.0,
                nu: 0.45,
            },
        )
        .unwrap();
        for layers in [
            Layers::equal(10.0, 0.5).unwrap(),
            Layers::equal(0.3, 0.5).unwrap(),
            unequal,
        ] {
            let (coarse, fine) = (errors(&layers, s, 72, 1), errors(&layers, s, 72, 3));
            for (c, f) in coarse.iter().zip(&fine) {
                let extrapolated = (9.0 * f - c) / 8.0;
                assert!(f.abs() < 3e-4, "{f}");
                assert!(
                    extrapolated.abs() < 0.15 * f.abs() + 3e-6,
                    "{extrapolated} against {f}"
                );
            }
        }
        // a thin pair, h/L = 0.05: the coarse cells (Δ = 0.75h) sample the
        // kernel's width poorly (8e-3 at the centre), the fine (Δ = h/4)
        // leave less than 1e-4 everywhere
        let thin = Layers::equal(0.05, 0.5).unwrap();
        let fine = errors(&thin, s, 72, 3);
        assert!(fine.iter().all(|f| f.abs() < 1e-4), "{fine:?}");
    }
}
