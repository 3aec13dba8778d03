//! The Dirichlet problem for the Laplacian inside a smooth closed contour,
//! solved by a second-kind boundary integral equation with the trapezoid
//! rule (spectrally convergent for analytic contours and data), and the
//! normal derivative of the solution on the contour.
//!
//! The harmonic function is q = Re F, F(z) = (1/2πi)∮ μ(τ)/(τ − z) dτ, a
//! Cauchy integral with a real density μ (the double-layer potential).
//! Its interior boundary value is F(t) = μ(t) + (1/2πi)∮ (μ(τ) − μ(t))/(τ − t) dτ,
//! so q = g on the contour is the second-kind equation
//! μ(t) + Re (1/2πi)∮ (μ(τ) − μ(t))/(τ − t) dτ = g(t), whose kernel
//! Im(τ'/(τ − t))/(2π) is smooth. F' is the Cauchy integral of ψ = dμ/dτ,
//! with the same boundary formula; ∂q/∂ν = Re(F' ν) with ν the outward
//! normal as a complex number. Derivatives in the parameter are spectral:
//! the trigonometric interpolant differentiated, by FFT (the Fourier
//! differentiation matrix's entries serve the orbits' derivative
//! matrices).
//!
//! Owns: [`Grid`], [`solve_dirichlet`], [`solve_dirichlet_symmetric`].
//! May use: nalgebra.

use nalgebra::{Complex, DMatrix, DVector};

/// The equispaced parameter grid θ_i = 2πi/n and its spectral derivative.
#[derive(Clone, Debug)]
pub(crate) struct Grid {
    /// The parameter values.
    pub theta: Vec<f64>,
    /// The Fourier differentiation matrix by offset: D_ij =
    /// `by_offset[j − i]` for i < j ([`Grid::d1_entry`]).
    by_offset: Vec<f64>,
    /// The contour basis at the points: `basis[k][i]` = e^{i m_k θ_i} with
    /// the multipliers m_k of [`Grid::multipliers`].
    pub basis: Vec<Vec<Complex<f64>>>,
    /// The multipliers m_k of the basis: m_0 = 1 (A), m_{j+1} = −(2j + 1)
    /// (b_j, j < N), then m_{N+1+j} = 2j + 3 (c_j, the arclength
    /// representation's positive modes, j < P).
    pub multipliers: Vec<f64>,
    /// N, the number of negative modes b_j in the basis.
    pub negative: usize,
    /// [`Grid::orbit_derivatives`], made on first use.
    orbit_derivatives: std::sync::OnceLock<(DMatrix<f64>, DMatrix<f64>)>,
    /// The forward FFT of the grid's length, planned on first use
    /// ([`Grid::basis_sums`]).
    fft: std::sync::OnceLock<Planned>,
}

/// A planned FFT (no `Debug` of its own).
#[derive(Clone)]
struct Planned(std::sync::Arc<dyn rustfft::Fft<f64>>);

impl std::fmt::Debug for Planned {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "FFT of length {}", self.0.len())
    }
}

impl Grid {
    /// A grid of `n` points with the contour basis tabulated: e^{iθ},
    /// `negative` modes e^{−(2j+1)iθ} (b_j) and `positive` modes e^{(2j+3)iθ}
    /// (c_j), [`Grid::multipliers`] (the contour series is evaluated on the
    /// grid at every residual; the table saves its exponentials).
    pub(crate) fn with_basis(n: usize, negative: usize, positive: usize) -> Grid {
        let mut g = Grid::new(n);
        g.multipliers = (0..=negative)
            .map(multiplier)
            .chain((0..positive).map(|j| 2.0 * j as f64 + 3.0))
            .collect();
        g.negative = negative;
        // e^{i m θ_j} = ω^{(m j) mod n}, ω = e^{2πi/n}: every multiplier is
        // an integer, so the table is read from the n roots of unity (n
        // exponentials instead of n per mode, and each entry from its
        // reduced argument)
        let n = g.len();
        let h = 2.0 * std::f64::consts::PI / n as f64;
        let roots: Vec<Complex<f64>> = (0..n)
            .map(|k| Complex::new(0.0, k as f64 * h).exp())
            .collect();
        g.basis = g
            .multipliers
            .iter()
            .map(|&m| {
                let m = m as i64;
                (0..n as i64)
                    .map(|j| roots[(m * j).rem_euclid(n as i64) as usize])
                    .collect()
            })
            .collect();
        g
    }

    /// P, the number of positive modes c_j in the basis.
    pub(crate) fn positive(&self) -> usize {
        self.multipliers.len().saturating_sub(self.negative + 1)
    }

    /// A grid of `n` points (`n` even, ≥ 8), without a basis table.
    pub(crate) fn new(n: usize) -> Grid {
        let n = n.max(8) & !1;
        let h = 2.0 * std::f64::consts::PI / n as f64;
        let theta = (0..n).map(|i| i as f64 * h).collect();
        // d/dθ of the trigonometric interpolant (n even):
        // D_ij = ½ (−1)^(i−j) cot((i − j) h/2), i ≠ j; antisymmetric, and
        // made so exactly (the lower triangle is the upper one negated)
        // the entry depends on j − i only: one cotangent per offset
        let by_offset: Vec<f64> = (0..n)
            .map(|k| {
                let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
                -0.5 * sign / (0.5 * k as f64 * h).tan()
            })
            .collect();
        Grid {
            theta,
            by_offset,
            basis: Vec::new(),
            multipliers: Vec::new(),
            negative: 0,
            orbit_derivatives: std::sync::OnceLock::new(),
            fft: std::sync::OnceLock::new(),
        }
    }

    /// Σ_j a_rj e^{i m_l θ_j} for every row r of a matrix `a` of `rows`
    /// rows and n columns (one per grid point) and every multiplier m_l of
    /// the basis: the product of `a` with the basis table, as one FFT per
    /// row (X_k = Σ_j a_j e^{−2πi jk/n}, read at k = −m_l mod n). n log n
    /// per row instead of n times the basis' length. `fill(r, row)` writes
    /// row r of `a` (it is not kept: one row's buffer serves all).
    pub(crate) fn basis_sums(
        &self,
        rows: usize,
        mut fill: impl FnMut(usize, &mut [Complex<f64>]),
    ) -> DMatrix<Complex<f64>> {
        let n = self.len();
        let fft = self.planned();
        let zero = Complex::new(0.0, 0.0);
        let mut row = vec![zero; n];
        let mut scratch = vec![zero; fft.get_inplace_scratch_len()];
        let at: Vec<usize> = self
            .multipliers
            .iter()
            .map(|&m| (-(m.round() as i64)).rem_euclid(n as i64) as usize)
            .collect();
        let mut out = DMatrix::zeros(rows, at.len());
        for r in 0..rows {
            fill(r, &mut row);
            fft.process_with_scratch(&mut row, &mut scratch);
            for (l, &k) in at.iter().enumerate() {
                out[(r, l)] = row[k];
            }
        }
        out
    }

    /// The first derivative of samples symmetric under the reflections
    /// θ → −θ and θ → π − θ, from their values at the orbits'
    /// representatives ([`orbits`]): D₁P (n × m, P the n × m expansion of
    /// representatives to all points), and the second derivative at the
    /// representatives, R D₁ D₁ P (m × m). The same products as D₁
    /// applied to the expanded samples, a quarter of the work.
    pub(crate) fn orbit_derivatives(&self) -> &(DMatrix<f64>, DMatrix<f64>) {
        self.orbit_derivatives.get_or_init(|| {
            let n = self.len();
            let (reps, orbit) = orbits(n);
            let mut d1p = DMatrix::zeros(n, reps.len());
            for j in 0..n {
                for (k, &o) in orbit.iter().enumerate() {
                    d1p[(j, o)] += self.d1_entry(j, k);
                }
            }
            let rows = DMatrix::from_fn(reps.len(), n, |r, k| self.d1_entry(reps[r], k));
            let d2r = rows * &d1p;
            (d1p, d2r)
        })
    }

    /// The number of points.
    pub(crate) fn len(&self) -> usize {
        self.theta.len()
    }

    /// The entry D_ij of the Fourier differentiation matrix (n even):
    /// ½ (−1)^(i−j) cot((i − j) h/2), i ≠ j, and 0 on the diagonal; exactly
    /// antisymmetric (the lower triangle is the upper one negated).
    pub(crate) fn d1_entry(&self, i: usize, j: usize) -> f64 {
        match i.cmp(&j) {
            std::cmp::Ordering::Equal => 0.0,
            std::cmp::Ordering::Less => self.by_offset[j - i],
            std::cmp::Ordering::Greater => -self.by_offset[i - j],
        }
    }

    /// The forward FFT of the grid's length, planned on first use.
    fn planned(&self) -> &std::sync::Arc<dyn rustfft::Fft<f64>> {
        let n = self.len();
        &self
            .fft
            .get_or_init(|| Planned(rustfft::FftPlanner::new().plan_fft_forward(n)))
            .0
    }

    /// The spectral derivative of periodic samples: their trigonometric
    /// interpolant differentiated, its Nyquist mode dropped (n even), by
    /// FFT. The differentiation matrix ([`Grid::d1_entry`]) applied to `f`
    /// is the same sum (n log n instead of n² operations, and no n × n
    /// table).
    pub(crate) fn derivative(&self, f: &DVector<f64>) -> DVector<f64> {
        let n = self.len();
        let fft = self.planned();
        let mut x: Vec<Complex<f64>> = f.iter().map(|&v| Complex::new(v, 0.0)).collect();
        let mut scratch = vec![Complex::new(0.0, 0.0); fft.get_inplace_scratch_len()];
        fft.process_with_scratch(&mut x, &mut scratch);
        // the inverse transform as the forward one of the conjugate:
        // y = conj(FFT(conj Y))/n, with Y_k = i k X_k (k taken in
        // (−n/2, n/2), the Nyquist mode zero); y is real
        for (k, v) in x.iter_mut().enumerate() {
            let wave = match (2 * k).cmp(&n) {
                std::cmp::Ordering::Less => k as f64,
                std::cmp::Ordering::Equal => 0.0,
                std::cmp::Ordering::Greater => k as f64 - n as f64,
            };
            *v = Complex::new(0.0, -wave) * v.conj();
        }
        fft.process_with_scratch(&mut x, &mut scratch);
        let scale = 1.0 / n as f64;
        DVector::from_iterator(n, x.iter().map(|v| v.re * scale))
    }
}

/// The multiplier m_k of θ in the k-th term of the contour series,
/// e^{i m_k θ}: m_0 = 1 (the coefficient A), m_{j+1} = −(2j + 1) (b_j).
pub(crate) fn multiplier(k: usize) -> f64 {
    if k == 0 {
        1.0
    } else {
        -(2.0 * (k - 1) as f64 + 1.0)
    }
}

/// The contour at the grid: points τ, dτ/dθ and d²τ/dθ², counter-clockwise.
pub(crate) struct ContourSamples {
    /// τ(θ_i).
    pub z: Vec<Complex<f64>>,
    /// τ'(θ_i).
    pub dz: Vec<Complex<f64>>,
    /// τ''(θ_i).
    pub ddz: Vec<Complex<f64>>,
}

/// The solution of the Dirichlet problem on the contour.
pub(crate) struct Dirichlet {
    /// The outward normal derivative ∂q/∂ν at the grid points.
    pub normal_derivative: Vec<f64>,
    /// The density μ.
    pub density: DVector<f64>,
}

/// Solve Δq = 0 inside the contour with q = `g` on it; `None` when the
/// discrete system is singular (a self-intersecting contour).
pub(crate) fn solve_dirichlet(grid: &Grid, c: &ContourSamples, g: &[f64]) -> Option<Dirichlet> {
    let n = grid.len();
    let mu = kernel_matrix(c, n)
        .lu()
        .solve(&DVector::from_column_slice(g))?;
    finish(grid, c, mu)
}

/// [`solve_dirichlet`] for a contour and data symmetric about both axes
/// (z(−θ) = z̄(θ), z(π − θ) = −z̄(θ), g(−θ) = g(π − θ) = g(θ)), the class of
/// every exact state. The discrete operator commutes with the two
/// reflections, which map the grid to itself (n even), so it maps
/// symmetric densities to symmetric ones; being invertible on the whole
/// space it is invertible on them, and the unique solution is symmetric.
/// The system is therefore solved for one value per orbit {j, −j, n/2 − j,
/// n/2 + j} (about n/4 + 1 unknowns, the columns of each orbit summed):
/// the same μ as [`solve_dirichlet`] (checked in a test) with about 1/64
/// of the LU work.
pub(crate) fn solve_dirichlet_symmetric(
    grid: &Grid,
    c: &ContourSamples,
    g: &[f64],
) -> Option<Dirichlet> {
    let n = grid.len();
    let (reps, orbit) = orbits(n);
    let m = reps.len();
    // τ'_j/(τ_j − τ_i) for the representatives i, row by row: the kernel
    // here and the Cauchy integral of ψ in `finish_at`
    let mut w = vec![Complex::new(0.0, 0.0); m * n];
    let mut a = DMatrix::<f64>::zeros(m, m);
    for (r, &i) in reps.iter().enumerate() {
        let mut row = 0.0;
        for j in 0..n {
            if j != i {
                let wij = c.dz[j] / (c.z[j] - c.z[i]);
                w[r * n + j] = wij;
                let k = wij.im / n as f64;
                a[(r, orbit[j])] += k;
                row += k;
            }
        }
        a[(r, r)] += 1.0 - row;
    }
    let rhs = DVector::from_iterator(m, reps.iter().map(|&i| g[i]));
    let reduced = a.lu().solve(&rhs)?;
    let mu = DVector::from_iterator(n, orbit.iter().map(|&k| reduced[k]));
    finish_at(grid, c, mu, &reps, &orbit, Some(&w))
}

/// The orbits of the grid's n points (n even) under the reflections
/// θ → −θ and θ → π − θ: the representative of each orbit (its smallest
/// index), in increasing order, and each point's orbit as the index of its
/// representative in that list.
pub(crate) fn orbits(n: usize) -> (Vec<usize>, Vec<usize>) {
    let half = n / 2;
    let rep = |j: usize| {
        [j, (n - j) % n, (half + n - j) % n, (half + j) % n]
            .into_iter()
            .min()
            .expect("four")
    };
    let of: Vec<usize> = (0..n).map(rep).collect();
    let mut reps = of.clone();
    reps.sort_unstable();
    reps.dedup();
    let orbit = of
        .iter()
        .map(|r| reps.binary_search(r).expect("a representative"))
        .collect();
    (reps, orbit)
}

/// The matrix of the second-kind equation: K_ij = Im(τ'_j/(τ_j − τ_i))/n
/// for j ≠ i, and 1 − Σ_j K_ij on the diagonal.
fn kernel_matrix(c: &ContourSamples, n: usize) -> DMatrix<f64> {
    let mut a = DMatrix::<f64>::zeros(n, n);
    for i in 0..n {
        let mut row = 0.0;
        for j in 0..n {
            if j != i {
                let k = (c.dz[j] / (c.z[j] - c.z[i])).im / n as f64;
                a[(i, j)] = k;
                row += k;
            }
        }
        a[(i, i)] = 1.0 - row;
    }
    a
}

/// ∂q/∂ν on the contour from the density μ, at every point.
fn finish(grid: &Grid, c: &ContourSamples, mu: DVector<f64>) -> Option<Dirichlet> {
    let n = grid.len();
    let all: Vec<usize> = (0..n).collect();
    finish_at(grid, c, mu, &all, &all, None)
}

/// ∂q/∂ν on the contour from the density μ, computed at the points
/// `targets` and copied to every point j from `targets[of[j]]` (for a
/// symmetric solution, one point per orbit: ∂q/∂ν is symmetric too).
/// `w`, where given, holds τ'_j/(τ_j − τ_i) for the r-th target i at
/// r·n + j.
fn finish_at(
    grid: &Grid,
    c: &ContourSamples,
    mu: DVector<f64>,
    targets: &[usize],
    of: &[usize],
    w: Option<&[Complex<f64>]>,
) -> Option<Dirichlet> {
    let n = grid.len();
    let i_unit = Complex::new(0.0, 1.0);
    if mu.iter().any(|v| !v.is_finite()) {
        return None;
    }
    let d_mu = grid.derivative(&mu);
    // μ″, read at the target points below
    let dd_mu_all = grid.derivative(&d_mu);
    // ψ = dμ/dτ = μ'/τ'
    let psi: Vec<Complex<f64>> = (0..n).map(|i| d_mu[i] / c.dz[i]).collect();
    let at: Vec<f64> = targets
        .iter()
        .enumerate()
        .map(|(r, &i)| {
            // dψ/dθ at i
            let dd_mu = dd_mu_all[i];
            let d_psi = (c.dz[i] * dd_mu - c.ddz[i] * d_mu[i]) / (c.dz[i] * c.dz[i]);
            let mut sum = d_psi;
            match w {
                Some(w) => {
                    let w = &w[r * n..(r + 1) * n];
                    for j in 0..n {
                        if j != i {
                            sum += (psi[j] - psi[i]) * w[j];
                        }
                    }
                }
                None => {
                    for j in 0..n {
                        if j != i {
                            sum += (psi[j] - psi[i]) * c.dz[j] / (c.z[j] - c.z[i]);
                        }
                    }
                }
            }
            let f_prime = psi[i] + sum / (i_unit * n as f64);
            let nu = -i_unit * c.dz[i] / c.dz[i].norm();
            (f_prime * nu).re
        })
        .collect();
    Some(Dirichlet {
        normal_derivative: of.iter().map(|&k| at[k]).collect(),
        density: mu,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The differentiation matrix is exactly antisymmetric; the derivative
    /// by FFT differentiates sin 3θ spectrally, and on samples of
    /// exp(2 cos θ) plus a Nyquist component (which the matrix and the FFT
    /// both drop) the FFT and the matrix applied to the samples both give
    /// the exact derivative to round-off: the FFT within 4 ε n max|f| (the
    /// wavenumbers up to n/2 multiply the coefficients' rounding; measured
    /// 1.0e-12 at n = 768) and no worse than the matrix (5.2e-11 there:
    /// sums of n terms up to n/2π).
    #[test]
    fn the_derivative_matrix_is_antisymmetric_and_spectral() {
        let g = Grid::new(64);
        for i in 0..64 {
            for j in 0..64 {
                assert_eq!(g.d1_entry(i, j), -g.d1_entry(j, i));
            }
        }
        let f = DVector::from_iterator(64, g.theta.iter().map(|t| (3.0 * t).sin()));
        let d = g.derivative(&f);
        for (i, t) in g.theta.iter().enumerate() {
            assert!((d[i] - 3.0 * (3.0 * t).cos()).abs() < 1e-12, "{i}");
        }
        for n in [64, 768] {
            let g = Grid::new(n);
            let f = DVector::from_iterator(
                n,
                g.theta
                    .iter()
                    .enumerate()
                    .map(|(i, t)| (2.0 * t.cos()).exp() + if i % 2 == 0 { 0.3 } else { -0.3 }),
            );
            let exact = DVector::from_iterator(
                n,
                g.theta
                    .iter()
                    .map(|t| -2.0 * t.sin() * (2.0 * t.cos()).exp()),
            );
            let matrix = DMatrix::from_fn(n, n, |i, j| g.d1_entry(i, j)) * &f;
            let by_fft = g.derivative(&f);
            let round_off = 4.0 * f64::EPSILON * n as f64 * f.amax();
            let (e_matrix, e_fft) = ((&matrix - &exact).amax(), (&by_fft - &exact).amax());
            assert!(
                e_fft <= round_off && e_fft <= e_matrix.max(round_off / n as f64),
                "n = {n}: FFT {e_fft:e}, matrix {e_matrix:e}, round-off {round_off:e}"
            );
        }
    }

    /// An ellipse-like contour z = Ae^{iθ} + b0 e^{−iθ} + b1 e^{−3iθ}.
    fn samples(grid: &Grid, a: f64, b0: f64, b1: f64) -> ContourSamples {
        let e = |k: f64, t: f64| Complex::new(0.0, k * t).exp();
        let i = Complex::new(0.0, 1.0);
        ContourSamples {
            z: grid
                .theta
                .iter()
                .map(|&t| a * e(1.0, t) + b0 * e(-1.0, t) + b1 * e(-3.0, t))
                .collect(),
            dz: grid
                .theta
                .iter()
                .map(|&t| i * (a * e(1.0, t) - b0 * e(-1.0, t) - 3.0 * b1 * e(-3.0, t)))
                .collect(),
            ddz: grid
                .theta
                .iter()
                .map(|&t| -(a * e(1.0, t) + b0 * e(-1.0, t) + 9.0 * b1 * e(-3.0, t)))
                .collect(),
        }
    }

    /// q = Re z⁴ and q = Re e^{z}: the boundary values give back the
    /// normal derivative Re(F'(z) ν) to near machine precision.
    #[test]
    fn harmonic_functions_are_reproduced() {
        let grid = Grid::new(160);
        let c = samples(&grid, 1.5, 0.5, 0.05);
        for (f, df) in [
            (
                Box::new(|z: Complex<f64>| z.powi(4)) as Box<dyn Fn(Complex<f64>) -> Complex<f64>>,
                Box::new(|z: Complex<f64>| 4.0 * z.powi(3))
                    as Box<dyn Fn(Complex<f64>) -> Complex<f64>>,
            ),
            (
                Box::new(|z: Complex<f64>| z.exp()),
                Box::new(|z: Complex<f64>| z.exp()),
            ),
        ] {
            let g: Vec<f64> = c.z.iter().map(|&z| f(z).re).collect();
            let d = solve_dirichlet(&grid, &c, &g).unwrap();
            let mut worst: f64 = 0.0;
            for i in 0..grid.len() {
                let nu = Complex::new(0.0, -1.0) * c.dz[i] / c.dz[i].norm();
                let exact = (df(c.z[i]) * nu).re;
                worst = worst.max((d.normal_derivative[i] - exact).abs());
            }
            assert!(worst < 1e-11, "worst {worst:e}");
        }
    }

    /// On a doubly symmetric contour with symmetric data the reduced
    /// solve gives the full solve's density and normal derivative.
    #[test]
    fn symmetric_solve_equals_the_full_solve() {
        for n in [64, 66, 160] {
            let grid = Grid::new(n);
            let c = samples(&grid, 1.5, 0.4, -0.06);
            let g: Vec<f64> =
                c.z.iter()
                    .map(|z| z.re.powi(4) / 24.0 + z.im.powi(4) / 12.0 - 0.7 * z.norm_sqr())
                    .collect();
            let full = solve_dirichlet(&grid, &c, &g).unwrap();
            let sym = solve_dirichlet_symmetric(&grid, &c, &g).unwrap();
            let dmu = (&full.density - &sym.density).amax();
            let dn = full
                .normal_derivative
                .iter()
                .zip(&sym.normal_derivative)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            assert!(dmu < 1e-12 && dn < 1e-11, "n = {n}: {dmu:e} {dn:e}");
        }
    }
}
