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
//! normal as a complex number. Derivatives in the parameter are spectral
//! (Fourier differentiation matrix).
//!
//! Owns: [`Grid`], [`solve_dirichlet`]. May use: nalgebra.

use nalgebra::{Complex, DMatrix, DVector};

/// The equispaced parameter grid θ_i = 2πi/n and its Fourier
/// differentiation matrix.
#[derive(Clone, Debug)]
pub struct Grid {
    /// The parameter values.
    pub theta: Vec<f64>,
    d1: DMatrix<f64>,
}

impl Grid {
    /// A grid of `n` points (`n` even, ≥ 8).
    pub fn new(n: usize) -> Grid {
        let n = n.max(8) & !1;
        let h = 2.0 * std::f64::consts::PI / n as f64;
        let theta = (0..n).map(|i| i as f64 * h).collect();
        // d/dθ of the trigonometric interpolant (n even):
        // D_ij = ½ (−1)^(i−j) cot((i − j) h/2), i ≠ j
        let d1 = DMatrix::from_fn(n, n, |i, j| {
            if i == j {
                0.0
            } else {
                let k = i as f64 - j as f64;
                let sign = if (i + j) % 2 == 0 { 1.0 } else { -1.0 };
                0.5 * sign / (0.5 * k * h).tan()
            }
        });
        Grid { theta, d1 }
    }

    /// The number of points.
    pub fn len(&self) -> usize {
        self.theta.len()
    }

    /// Whether the grid is empty (never: at least 8 points).
    pub fn is_empty(&self) -> bool {
        self.theta.is_empty()
    }

    /// Spectral derivative of periodic samples.
    pub fn derivative(&self, f: &DVector<f64>) -> DVector<f64> {
        &self.d1 * f
    }
}

/// The contour at the grid: points τ, dτ/dθ and d²τ/dθ², counter-clockwise.
pub struct ContourSamples {
    /// τ(θ_i).
    pub z: Vec<Complex<f64>>,
    /// τ'(θ_i).
    pub dz: Vec<Complex<f64>>,
    /// τ''(θ_i).
    pub ddz: Vec<Complex<f64>>,
}

/// The solution of the Dirichlet problem on the contour.
pub struct Dirichlet {
    /// The outward normal derivative ∂q/∂ν at the grid points.
    pub normal_derivative: Vec<f64>,
    /// The density μ.
    pub density: DVector<f64>,
}

/// Solve Δq = 0 inside the contour with q = `g` on it; `None` when the
/// discrete system is singular (a self-intersecting contour).
pub fn solve_dirichlet(grid: &Grid, c: &ContourSamples, g: &[f64]) -> Option<Dirichlet> {
    let n = grid.len();
    let i_unit = Complex::new(0.0, 1.0);
    // K_ij = Im(τ'_j/(τ_j − τ_i))/n, j ≠ i
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
    let mu = a.lu().solve(&DVector::from_column_slice(g))?;
    if mu.iter().any(|v| !v.is_finite()) {
        return None;
    }
    let d_mu = grid.derivative(&mu);
    let dd_mu = grid.derivative(&d_mu);
    // ψ = dμ/dτ = μ'/τ', and dψ/dθ
    let psi: Vec<Complex<f64>> = (0..n).map(|i| d_mu[i] / c.dz[i]).collect();
    let d_psi: Vec<Complex<f64>> = (0..n)
        .map(|i| (c.dz[i] * dd_mu[i] - c.ddz[i] * d_mu[i]) / (c.dz[i] * c.dz[i]))
        .collect();
    let normal_derivative = (0..n)
        .map(|i| {
            let mut sum = d_psi[i];
            for j in 0..n {
                if j != i {
                    sum += (psi[j] - psi[i]) * c.dz[j] / (c.z[j] - c.z[i]);
                }
            }
            let f_prime = psi[i] + sum / (i_unit * n as f64);
            let nu = -i_unit * c.dz[i] / c.dz[i].norm();
            (f_prime * nu).re
        })
        .collect();
    Some(Dirichlet {
        normal_derivative,
        density: mu,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
