//! The exact solution of the free-boundary problem (2)–(3): the reference
//! against which every approximate model (every closure of the ellipse) is
//! measured.
//!
//! In the units (17) (a = āL, δ = δ̄L²/R₁, F = F̄·2R₁Δγ, p = p̄·√(2mΔγ)·L,
//! L = (2R₁²Δγ/m)^(1/6)) the problem (1)–(3) has no parameter but ρ and δ̄:
//! find a domain ω, symmetric about both axes, and p̄ with
//!
//!   Δp̄ = X²/2 + Y²/(2ρ) − δ̄ in ω,   p̄ = 0 and ∂p̄/∂ν = 1 on ∂ω,   F̄ = ∫ω p̄ dA.
//!
//! (Eq. (2) is Δp = m(φ − δ) with the gap (1)₁ φ = x²/(2R₁) + y²/(2R₂);
//! with x = LX, δ = δ̄L²/R₁ and p = P₀p̄ it becomes (P₀/L²)Δp̄ =
//! (mL²/R₁)(X²/2 + Y²/(2ρ) − δ̄), so P₀ = mL⁴/R₁ = √(2mΔγ)·L (as L³ =
//! R₁√(2Δγ/m)), and (3)₂ becomes ∂p̄/∂ν = √(2mΔγ)L/P₀ = 1; F = P₀L²F̄ =
//! 2R₁Δγ F̄. At ρ = 1 the circle of radius ā with δ̄ = ā²/4 − 2/ā,
//! F̄ = π(ā⁶ − 24ā³)/96 solves it exactly:
//! the derived (22)–(25).)
//!
//! Method: the contour is the curve z(θ) = A e^{iθ} + Σ_{j<N} b_j e^{−(2j+1)iθ}
//! (the form of the exterior conformal map of a doubly symmetric domain;
//! the ellipse with semi-axes a, b is A = (a+b)/2, b₀ = (a−b)/2); or, in the
//! arclength representation ([`Truncation::arclength`] > 0), with modes
//! c_j e^{(2j+3)iθ} too and θ made proportional to arclength by as many
//! more equations (docs/exact.md, "The arclength representation"). p̄ = q + P
//! with the particular solution P = X⁴/24 + Y⁴/(24ρ) − δ̄(X² + Y²)/4 and q
//! harmonic with q = −P on the contour (`bie`: second-kind boundary
//! integral equation, trapezoid rule on n points). The condition
//! ∂p̄/∂ν = 1 is imposed on the cosine modes cos 2kθ, k = 0..N, of
//! ∂p̄/∂ν − 1 (the doubly symmetric part; the rest vanishes by symmetry),
//! and ā = z(0) fixes the member of the family: N + 2 equations for
//! (A, b₀..b_{N−1}, δ̄), solved by Newton's method with the Jacobian of the
//! discrete equations (`exact::linear`: the boundary integral solution
//! differentiated in every unknown).
//! F̄ = ∫ p̄ dA by Green's identity with w = (X² + Y²)/4:
//! F̄ = −∮ w ∂p̄/∂ν ds + ∮ W dY, ∂W/∂X = w·(X²/2 + Y²/(2ρ) − δ̄).
//!
//! The resolution policy (which truncations, when a state is resolved, the
//! routes to a state and the continuation in ρ) is `resolve`.
//!
//! Owns: [`ExactState`], [`Exact`], [`Truncation`], [`Contour`]. May use: `control`, `error`, `newton` (the shared chord iteration),
//! `cutoff` (the verdicts' and the shape's, [`ExactState::judged`]),
//! nalgebra; no model (it is the reference for them): starting guesses come
//! with the gap from the layer above (`seed`), which also defines
//! `Gap::cylinders()`, the cylinders' gap with its seed.

pub mod bands;
pub(crate) mod bie;
pub mod branch;
pub(crate) mod energy;
pub(crate) mod gap;
pub(crate) mod ladder;
pub(crate) mod larger_contacts;
pub(crate) mod linear;
pub(crate) mod no_state;
mod resolve;
pub(crate) mod rho_path;
pub(crate) mod rho_walk;
pub(crate) mod same;
pub(crate) mod seed;
pub mod stability;
pub(crate) mod stored;
pub(crate) mod undulations;

use crate::control::Hold;
use crate::error::{Error, Result};
use bie::{solve_dirichlet, solve_dirichlet_symmetric, ContourSamples, Grid};
pub(crate) use gap::Gap;
use gap::GapAt;
pub(crate) use ladder::MAX_ESCALATED_MODES;
use nalgebra::{Complex, DMatrix, DVector};
#[cfg(feature = "cli")]
pub(crate) use resolve::pull_off_followed_in_arclength_visiting;
pub use resolve::{at_resolved, at_searched, default_tries, pull_off_resolved, CONVERGED};
pub(crate) use resolve::{
    at_resolved_on, at_resolved_searching, pull_off_on, pull_off_resolved_on, resolved,
    searched_on, RESOLVED,
};
use serde::Serialize;

/// The most contour modes a user may ask for (the command line's
/// `--modes`, the Python package's `modes`): the top of the default
/// escalation ([`default_tries`]).
pub const MAX_USER_MODES: usize = ladder::CONFORMAL_MODES[ladder::CONFORMAL_MODES.len() - 1];

/// The large load F̄ = 10 from which the command line's studies of the
/// loading path and the unloading trace begin, where a state is found
/// there (its words in `report`).
pub(crate) const START_FORCE: f64 = 10.0;

/// The largest cosine mode of ∂p̄/∂ν − 1 accepted at convergence (the
/// round-off floor of the boundary integral solution is about 1e-13).
pub(crate) const RESIDUAL_TOLERANCE: f64 = 1e-11;

/// ρ = 0.9, 0.8, 0.6, 0.5 and 0.4 with 12 … 48 modes: F̄, δ̄, ā and s agree to
/// all 12 printed digits, the same truncations are chosen, and the
/// fine-grid boundary errors agree or are smaller; 6 points per mode still
/// agreed (`tests/exact.rs` holds this at ρ = 0.5).
pub const POINTS_PER_MODE: usize = 8;

/// The discretisation: contour modes and quadrature points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Truncation {
    /// Number of contour coefficients b_j (and of imposed modes minus one).
    pub modes: usize,
    /// Quadrature points on the contour.
    pub points: usize,
    /// The arclength representation's positive modes c_j (0: the
    /// conformal-map form, z = A e^{iθ} + Σ b_j e^{−(2j+1)iθ}). With P > 0
    /// the contour also has c_j e^{(2j+3)iθ}, j < P, and its parameter is
    /// made proportional to arclength in the modes cos 2kθ, k = 1..P, of
    /// |z′(θ)|² (`Contour::in_arclength`).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub arclength: usize,
}

fn is_zero(v: &usize) -> bool {
    *v == 0
}

impl Truncation {
    /// `modes` contour modes with [`POINTS_PER_MODE`] points each.
    pub fn with_modes(modes: usize) -> Truncation {
        Truncation {
            modes,
            points: POINTS_PER_MODE * modes,
            arclength: 0,
        }
    }

    /// The arclength representation with `modes` modes of each sign
    /// (b_j, j < `modes`, and c_j, j < `modes` − 1: the multipliers
    /// ±1, ±3, …, ±(2·modes − 1)) and [`POINTS_PER_MODE`] points a mode.
    pub(crate) fn in_arclength(modes: usize) -> Truncation {
        Truncation {
            modes,
            points: POINTS_PER_MODE * modes,
            arclength: modes.saturating_sub(1),
        }
    }

    /// The number of contour coefficients, A, b_j and c_j.
    pub(crate) fn coefficients(&self) -> usize {
        1 + self.modes + self.arclength
    }
}

impl Default for Truncation {
    fn default() -> Self {
        Truncation::with_modes(12)
    }
}

/// The contour z(θ) = A e^{iθ} + Σ b_j e^{−(2j+1)iθ} + Σ c_j e^{(2j+3)iθ}.
#[derive(Clone, Debug, PartialEq, Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Contour {
    /// The leading coefficient A.
    pub a: f64,
    /// The coefficients b_j of e^{−(2j+1)iθ}.
    pub b: Vec<f64>,
    /// The coefficients c_j of e^{(2j+3)iθ} (the arclength
    /// representation; empty in the conformal-map form).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub c: Vec<f64>,
}

impl Contour {
    /// The ellipse with semi-axes `a` (along X) and `b` (along Y).
    pub fn ellipse(a: f64, b: f64, modes: usize) -> Contour {
        let mut c = vec![0.0; modes.max(1)];
        c[0] = 0.5 * (a - b);
        Contour {
            a: 0.5 * (a + b),
            b: c,
            c: Vec::new(),
        }
    }

    /// The contour scaled by `factor` (every coefficient times it).
    pub(crate) fn scaled(&self, factor: f64) -> Contour {
        let times = |v: &Vec<f64>| v.iter().map(|x| x * factor).collect();
        Contour {
            a: self.a * factor,
            b: times(&self.b),
            c: times(&self.c),
        }
    }

    /// The same curve with θ proportional to arclength, as a series of
    /// `modes` modes of each sign (b_j, j < `modes`; c_j, j < `modes` − 1):
    /// the curve is sampled at 32 points a mode, its arclength found by the
    /// spectral integral of |z′|, θ(t) inverted by Newton at equally spaced
    /// t and the series fitted to z(θ(t)) by the discrete Fourier
    /// projection (the point θ = 0 stays on the X axis).
    pub(crate) fn in_arclength(&self, modes: usize) -> Contour {
        self.reparametrised(modes, &|_| 1.0)
    }

    /// [`Contour::in_arclength`] with θ proportional to the weighted
    /// arclength ∫ density ds instead, `density` a positive function of
    /// this contour's θ (even, of period π): the points crowd where it is
    /// large.
    pub(crate) fn reparametrised(&self, modes: usize, density: &dyn Fn(f64) -> f64) -> Contour {
        use std::f64::consts::PI;
        let modes = modes.max(1);
        let n = self.sampling(modes);
        let (mean, arc) = self.weighted_arclength(n, density);
        let speed_at = |theta: f64| density(theta) * self.at(theta)[1].norm();
        // z at equal arclength: t = 2π s/length, θ(t) by Newton from θ = t
        let m = n;
        let points: Vec<Complex<f64>> = (0..m)
            .map(|i| {
                let t = 2.0 * PI * i as f64 / m as f64;
                let mut theta = t;
                for _ in 0..50 {
                    let step = (arc(theta) - mean * t) / speed_at(theta);
                    theta -= step;
                    if step.abs() < 1e-15 {
                        break;
                    }
                }
                self.at(theta)[0]
            })
            .collect();
        let coef = |mult: f64| {
            points
                .iter()
                .enumerate()
                .map(|(i, z)| z * Complex::new(0.0, -mult * 2.0 * PI * i as f64 / m as f64).exp())
                .sum::<Complex<f64>>()
                .re
                / m as f64
        };
        Contour {
            a: coef(1.0),
            b: (0..modes).map(|j| coef(bie::multiplier(j + 1))).collect(),
            c: (0..modes - 1).map(|j| coef(2.0 * j as f64 + 3.0)).collect(),
        }
    }

    /// The points a reparametrisation to `modes` modes samples this
    /// contour at: 32 a mode of the larger of the two series.
    fn sampling(&self, modes: usize) -> usize {
        32 * modes.max(self.b.len() + self.c.len() + 1)
    }

    /// The weighted arclength θ ↦ ∫₀^θ density·|z′| dθ of this contour,
    /// as its mean slope and the function: the integrand sampled at `n`
    /// points (it is even, of period π) and its Fourier series integrated
    /// term by term, the sines summed by the recurrence of e^{2iθ}.
    fn weighted_arclength<'a>(
        &'a self,
        n: usize,
        density: &'a dyn Fn(f64) -> f64,
    ) -> (f64, impl Fn(f64) -> f64 + 'a) {
        use std::f64::consts::PI;
        let speed: Vec<f64> = (0..n)
            .map(|i| {
                let theta = 2.0 * PI * i as f64 / n as f64;
                density(theta) * self.at(theta)[1].norm()
            })
            .collect();
        let mean = speed.iter().sum::<f64>() / n as f64;
        let harmonics = n / 4;
        // the k-th cosine coefficient divided by 2k, the factor of its
        // integral sin(2kθ)/(2k)
        let sine_k: Vec<f64> = (1..harmonics)
            .map(|k| {
                2.0 / n as f64
                    * speed
                        .iter()
                        .enumerate()
                        .map(|(i, v)| v * (2.0 * k as f64 * 2.0 * PI * i as f64 / n as f64).cos())
                        .sum::<f64>()
                    / (2.0 * k as f64)
            })
            .collect();
        let arc = move |theta: f64| {
            let step = Complex::new(0.0, 2.0 * theta).exp();
            let mut e = step;
            let mut sum = 0.0;
            for a in &sine_k {
                sum += a * e.im;
                e *= step;
            }
            mean * theta + sum
        };
        (mean, arc)
    }

    /// The groove of a peanut-shaped contour: the parameter θ of the
    /// bottom of the deepest local minimum of Y(X) on the upper flank
    /// (0 < θ < π/2, X > 0) and its half-width Y there; `None` where the
    /// flank has none (a convex or merely dented contour).
    pub(crate) fn groove(&self) -> Option<(f64, f64)> {
        let m = 4000;
        let quarter = std::f64::consts::FRAC_PI_2;
        let z: Vec<Complex<f64>> = (0..=m)
            .map(|i| self.point_at(quarter * i as f64 / m as f64))
            .collect();
        (1..m)
            .filter(|&i| z[i].im < z[i - 1].im && z[i].im <= z[i + 1].im)
            .filter(|&i| z[i].re > 0.0 && z[i].im > 0.0)
            .min_by(|&i, &j| z[i].im.total_cmp(&z[j].im))
            .map(|i| (quarter * i as f64 / m as f64, z[i].im))
    }

    /// The groove to crowd points into ([`Contour::crowded_at_groove`]):
    /// [`Contour::groove`] where its half-width is below
    /// [`CROWD_BELOW_HALF_WIDTH`].
    pub(crate) fn narrow_groove(&self) -> Option<(f64, f64)> {
        self.groove().filter(|&(_, w)| w < CROWD_BELOW_HALF_WIDTH)
    }

    /// The same curve as a series of `modes` modes of each sign with its
    /// points crowded into its narrow grooves ([`Contour::narrow_groove`]):
    /// θ proportional to the weighted arclength ∫ d ds, the density d = 1 +
    /// h · e^(−(t − t_g)²/σ²) summed over the four grooves, with t = 2π
    /// s/perimeter, σ = [`GROOVE_WIDTH`] (so the map is smooth) and h the
    /// larger of [`GROOVE_CROWDING`] and [`CROWDING_TIMES_HALF_WIDTH`] over
    /// the groove's half-width (narrower grooves, more points); `None`
    /// where the contour has no narrow groove. t is this contour's own
    /// arclength fraction, so that the result depends on the curve only
    /// (up to the truncation) and not on how this contour's points lie.
    pub(crate) fn crowded_at_groove(&self, modes: usize) -> Option<Contour> {
        let (theta_g, half_width) = self.narrow_groove()?;
        let crowding = GROOVE_CROWDING.max(CROWDING_TIMES_HALF_WIDTH / half_width);
        Some(self.crowded_with(theta_g, modes, crowding, GROOVE_WIDTH))
    }

    /// The same curve as a series of `modes` modes of each sign with its
    /// points crowded into the groove whose bottom is at this contour's
    /// parameter `theta_g` (0 < θ_g < π/2) and its three mirror images, by
    /// a bump of height `crowding` and width `width` in t
    /// ([`Contour::crowded_at_groove`]).
    pub(crate) fn crowded_with(
        &self,
        theta_g: f64,
        modes: usize,
        crowding: f64,
        width: f64,
    ) -> Contour {
        let n = self.sampling(modes.max(1));
        let (mean, arc) = self.weighted_arclength(n, &|_| 1.0);
        let t_of = |theta: f64| arc(theta) / mean;
        let t_g = t_of(theta_g);
        let pi = std::f64::consts::PI;
        let density = |theta: f64| {
            let t = t_of(theta);
            1.0 + [t_g, -t_g, pi - t_g, pi + t_g]
                .iter()
                .map(|c| {
                    let d = (t - c).rem_euclid(2.0 * pi);
                    let d = d.min(2.0 * pi - d);
                    crowding * (-(d / width).powi(2)).exp()
                })
                .sum::<f64>()
        };
        self.reparametrised(modes, &density)
    }

    /// z, z', z'' at θ.
    pub fn at(&self, theta: f64) -> [Complex<f64>; 3] {
        let i = Complex::new(0.0, 1.0);
        let e = Complex::new(0.0, theta).exp();
        let mut z = self.a * e;
        let mut dz = i * self.a * e;
        let mut ddz = -self.a * e;
        for (j, &b) in self.b.iter().enumerate() {
            let k = bie::multiplier(j + 1);
            let ek = Complex::new(0.0, k * theta).exp();
            z += b * ek;
            dz += i * k * b * ek;
            ddz += -k * k * b * ek;
        }
        for (j, &c) in self.c.iter().enumerate() {
            let k = 2.0 * j as f64 + 3.0;
            let ek = Complex::new(0.0, k * theta).exp();
            z += c * ek;
            dz += i * k * c * ek;
            ddz += -k * k * c * ek;
        }
        [z, dz, ddz]
    }

    /// The point z(θ) alone, the series' exponentials by the recurrence
    /// of e^{2iθ} (one sine and cosine per point instead of one per term;
    /// rounding grows with the mode number, to about 1e-14 of the
    /// contour's size at 200 modes): for locating a groove and measuring
    /// the departure from the ellipse, where [`Contour::at`] would spend
    /// most of the time in sines and cosines.
    pub(crate) fn point_at(&self, theta: f64) -> Complex<f64> {
        let e = Complex::from_polar(1.0, theta);
        let e2 = e * e;
        let mut z = self.a * e;
        // b_j: e^{−(2j+1)iθ}
        let (mut p, back) = (e.conj(), e2.conj());
        for &b in &self.b {
            z += b * p;
            p *= back;
        }
        // c_j: e^{(2j+3)iθ}
        let mut q = e * e2;
        for &c in &self.c {
            z += c * q;
            q *= e2;
        }
        z
    }

    /// The half-width on the X axis, z(0).
    pub(crate) fn a_bar(&self) -> f64 {
        self.a + self.b.iter().sum::<f64>() + self.c.iter().sum::<f64>()
    }

    /// The half-width on the Y axis, Im z(π/2).
    pub(crate) fn b_bar(&self) -> f64 {
        self.at(std::f64::consts::FRAC_PI_2)[0].im
    }

    pub(crate) fn samples(&self, grid: &Grid) -> ContourSamples {
        let mut c = ContourSamples {
            z: Vec::with_capacity(grid.len()),
            dz: Vec::with_capacity(grid.len()),
            ddz: Vec::with_capacity(grid.len()),
        };
        let tabulated = if self.c.is_empty() {
            grid.basis.len() > self.b.len()
        } else {
            grid.negative == self.b.len() && grid.positive() == self.c.len()
        };
        if tabulated {
            // the same sums as `at`, from the tabulated exponentials, mode
            // by mode: z = Σ c_m e_m, dz = i Σ m c_m e_m, ddz = −Σ m² c_m e_m
            let n = grid.len();
            let zero = Complex::new(0.0, 0.0);
            let (mut s0, mut s1, mut s2) = (vec![zero; n], vec![zero; n], vec![zero; n]);
            let terms = std::iter::once((1.0, self.a))
                .chain(
                    self.b
                        .iter()
                        .enumerate()
                        .map(|(j, &b)| (bie::multiplier(j + 1), b)),
                )
                .chain(
                    self.c
                        .iter()
                        .enumerate()
                        .map(|(j, &c)| (2.0 * j as f64 + 3.0, c)),
                );
            for (row, (m, coef)) in grid.basis.iter().zip(terms) {
                for i in 0..n {
                    let t = row[i] * coef;
                    s0[i] += t;
                    s1[i] += t * m;
                    s2[i] += t * (m * m);
                }
            }
            let i_unit = Complex::new(0.0, 1.0);
            c.z = s0;
            c.dz = s1.into_iter().map(|v| i_unit * v).collect();
            c.ddz = s2.into_iter().map(|v| -v).collect();
            return c;
        }
        for &t in &grid.theta {
            let [z, dz, ddz] = self.at(t);
            c.z.push(z);
            c.dz.push(dz);
            c.ddz.push(ddz);
        }
        c
    }

    /// The largest distance, along rays from the centre and relative to
    /// ā, between this contour and the ellipse with the same half-widths,
    /// over `n` points.
    pub(crate) fn deviation_from_ellipse(&self, n: usize) -> f64 {
        let (a, b) = (self.a_bar(), self.b_bar());
        (0..n)
            .map(|k| {
                let z = self.point_at(2.0 * std::f64::consts::PI * k as f64 / n as f64);
                (z.norm() - ellipse_radius(a, b, z.im.atan2(z.re))).abs() / a
            })
            .fold(0.0, f64::max)
    }
}

/// The radius at polar angle φ of the ellipse with semi-axes a (along X)
/// and b.
pub(crate) fn ellipse_radius(a: f64, b: f64, phi: f64) -> f64 {
    a * b / ((b * phi.cos()).powi(2) + (a * phi.sin()).powi(2)).sqrt()
}

/// ∂p̄/∂ν on the contour and F̄ for a given contour, ρ and δ̄.
pub(crate) struct Fields {
    /// ∂p̄/∂ν at the grid points.
    pub normal_derivative: Vec<f64>,
    /// F̄ = ∫ p̄ dA.
    pub force: f64,
}

/// ∂p̄/∂ν and F̄ for the contour `c` (any contour: the boundary condition
/// (3)₂ is not imposed here).
pub(crate) fn fields(c: &Contour, gap: &GapAt, delta_bar: f64, grid: &Grid) -> Option<Fields> {
    fields_of(&c.samples(grid), gap, delta_bar, grid)
}

/// [`fields`] from the contour's samples on `grid`.
fn fields_of(s: &ContourSamples, gap: &GapAt, delta_bar: f64, grid: &Grid) -> Option<Fields> {
    let n = grid.len();
    let g: Vec<f64> = s.z.iter().map(|&z| -gap.p(z.re, z.im, delta_bar)).collect();
    let d = solve_dirichlet_symmetric(grid, s, &g)?;
    let h = 2.0 * std::f64::consts::PI / n as f64;
    let mut force = 0.0;
    let mut dn = Vec::with_capacity(n);
    for i in 0..n {
        let (z, dz) = (s.z[i], s.dz[i]);
        let (x, y) = (z.re, z.im);
        let speed = dz.norm();
        let (nx, ny) = (dz.im / speed, -dz.re / speed);
        let grad_p = gap.grad(x, y, delta_bar);
        let dp = d.normal_derivative[i] + grad_p.0 * nx + grad_p.1 * ny;
        dn.push(dp);
        // F̄ = −∮ w ∂p̄/∂ν ds + ∮ W dY, w = (X² + Y²)/4, W = ∫ w(φ̄ − δ̄) dX
        let w = (x * x + y * y) / 4.0;
        let big_w = gap.force_potential(x, y, delta_bar)[0];
        force += (-w * dp * speed + big_w * dz.im) * h;
    }
    Some(Fields {
        normal_derivative: dn,
        force,
    })
}

/// The pressure p̄ of a solved contour, evaluated anywhere inside it.
pub struct Field {
    gap: GapAt,
    delta_bar: f64,
    samples: ContourSamples,
    /// F at the contour points (its real part is −P there).
    boundary: Vec<Complex<f64>>,
}

impl Field {
    /// p̄ at (X, Y) inside the contour: P plus the harmonic part q = Re F,
    /// with F evaluated by the barycentric Cauchy formula
    /// F(z) = Σ F_j τ'_j/(τ_j − z) / Σ τ'_j/(τ_j − z) from its boundary
    /// values F_j (Helsing–Ioakimidis: the quadrature errors of numerator
    /// and denominator cancel, which keeps points near the contour accurate).
    pub fn pressure(&self, x: f64, y: f64) -> f64 {
        let z = Complex::new(x, y);
        let mut num = Complex::new(0.0, 0.0);
        let mut den = Complex::new(0.0, 0.0);
        for j in 0..self.samples.z.len() {
            let d = self.samples.z[j] - z;
            if d.norm() == 0.0 {
                return 0.0;
            }
            let w = self.samples.dz[j] / d;
            num += w * self.boundary[j];
            den += w;
        }
        let q = (num / den).re;
        q + self.gap.p(x, y, self.delta_bar)
    }
}

/// One exact state: a member of the solution family of (2)–(3).
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct ExactState {
    /// Radii ratio ρ.
    pub rho: f64,
    /// Half-width of ω on the X axis.
    pub a_bar: f64,
    /// Half-width of ω on the Y axis.
    pub b_bar: f64,
    /// Aspect ratio b̄/ā.
    pub s: f64,
    /// Approach δ̄.
    pub delta_bar: f64,
    /// Force F̄.
    pub force_bar: f64,
    /// The contour.
    pub contour: Contour,
    /// max |∂p̄/∂ν − 1| on an independent grid of twice the points.
    pub bc_error: f64,
    /// Largest radial distance from the ellipse with the same
    /// half-widths, relative to ā.
    pub deviation_from_ellipse: f64,
    /// The discretisation used.
    pub truncation: Truncation,
    /// Which contour modes are unstable under displacement and load
    /// control (the second variation of Π, [`stability`]).
    pub stability: stability::ExactStability,
    /// How the state was found (its start).
    pub route: Route,
    /// How much of its shape lies in undulations shorter than the cutoff
    /// of its verdicts ([`undulations`]); set with the verdicts by
    /// [`ExactState::judged`], absent before.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) shape: Option<undulations::ShortWaves>,
    /// For which coatings (2) gives it as a contact it resolves, its shape
    /// and its stability under each control ([`undulations`]); set with the
    /// verdicts by [`ExactState::judged`], absent before and where its
    /// stability was not computed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) coatings: Option<undulations::Coatings>,
    /// Why the state is doubtful, in the words every front end shows
    /// (empty when it is not, and absent from JSON then): its shape owes a
    /// visible part (above 1 % of ā) to undulations shorter than the
    /// cutoff of its verdicts. Set with the verdicts by
    /// [`ExactState::judged`].
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
    /// The gap of the problem it solves: `cylinders`, the paper's (1), or
    /// the name of the contour family whose own gap it is ([`Gap`];
    /// `exact … --gap`).
    #[serde(serialize_with = "gap_name")]
    #[cfg_attr(feature = "schema", schemars(with = "String"))]
    pub(crate) gap: Gap,
}

/// A gap in JSON: its name.
fn gap_name<S: serde::Serializer>(gap: &Gap, s: S) -> std::result::Result<S::Ok, S::Error> {
    s.serialize_str(gap.name)
}

impl ExactState {
    /// How it was found, in words: its route, naming the model that
    /// seeded it (the largest member of the family that seeds its gap).
    pub(crate) fn route_words(&self) -> String {
        match self.gap.seed {
            Some(seed) => self.route.words(&seed.name()),
            None => self.route.to_string(),
        }
    }

    /// The state with its stability judged under `cutoff` (the verdicts
    /// count the modes at least its wavelength long) and its shape's
    /// unresolved part measured against it.
    pub fn judged(mut self, cutoff: crate::cutoff::Cutoff) -> ExactState {
        self.stability = std::mem::take(&mut self.stability).under(cutoff);
        let shape = undulations::short_waves(&self.contour, cutoff);
        self.warnings = if shape.unresolved {
            vec![format!("the contact's shape: {}", shape.words(cutoff))]
        } else {
            Vec::new()
        };
        self.coatings = undulations::Coatings::of(&self.stability, &shape);
        self.shape = Some(shape);
        self
    }

    /// Its shape's unresolved part under the cutoff of its verdicts: the
    /// one [`ExactState::judged`] measured, else measured now.
    pub(crate) fn short_waves(&self) -> undulations::ShortWaves {
        self.shape
            .unwrap_or_else(|| undulations::short_waves(&self.contour, self.stability.cutoff))
    }

    /// Its [`undulations::Coatings`] (the ones [`ExactState::judged`]
    /// set, else measured now; `None` where its stability was not
    /// computed) with the shape they were measured from.
    pub(crate) fn coatings_measured(
        &self,
    ) -> (Option<undulations::Coatings>, undulations::ShortWaves) {
        let shape = self.short_waves();
        let coatings = self
            .coatings
            .or_else(|| undulations::Coatings::of(&self.stability, &shape));
        (coatings, shape)
    }
}

/// How an exact state was found: the start of its Newton iterations.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum Route {
    /// From the richest approximate model at the same control
    /// (`conformal:8`): its ā, b̄ and δ̄ as an ellipse, Newton at the
    /// control (or at its ā, then the family traced to the control).
    FromModel,
    /// The pull-off traced from the exact state just above the richest
    /// model's pull-off (`conformal:8`'s ā + 0.03).
    AboveModelPullOff,
    /// Where the richest model's states at fixed ā cross the control
    /// (`exact solve --all`): Newton at the control from the model's
    /// ellipse there.
    FromScreen,
    /// From the exact circle at ρ = 1, continued in ρ at fixed ā, then the
    /// family traced to the control (no approximate model used).
    #[default]
    FromCircle,
    /// On a gap no circle solves: from the cylinders' exact state at the
    /// same ρ and ā (continued in ρ from their circle), continued in the
    /// gap itself at fixed ā to this one, then the family traced to the
    /// control (`Exact::continued_in_the_gap`; no approximate model used).
    FromCylinders,
    /// Continued in ρ at the control from the exact state at a larger ρ
    /// (found there by another route), where no route finds it directly.
    ContinuedInRho,
    /// The pull-off found at its ρ from the interpolation of the stored
    /// pull-offs on both sides of it (solver/data/exact_pull_offs.json,
    /// `exact::stored`): the minimum the continuation in ρ reaches, found
    /// without it.
    BetweenStored,
    /// On an arm beside a band of the family, traced through the arm's
    /// fold in ā and on along its returning stretch to the control
    /// (`bands::past_folds_or_band`), where the other routes find nothing.
    PastFold,
    /// Below the fold in ρ of the family at the control: on the arm of a
    /// larger contact, continued in ρ at fixed ā from the state at a larger
    /// ρ and traced down in ā, through its folds, to the control
    /// (`exact::larger_contacts`).
    FromLargerContact,
    /// Newton at the control from a nearby exact state the caller gave
    /// (a sweep's previous point, `registry::Choice::state_near`).
    FromNeighbour,
    /// The pull-off's second route (issue 73): Newton from the seeding
    /// model's own contour at its pull-off, then the minimum of F̄ over ā
    /// along that arm (`studies::model_contour`; `exact pull-off
    /// --from-model-contour`).
    FromModelContour,
}

impl Route {
    /// The route in words, naming `seed`, the model whose states started
    /// it where one did (the largest member of the family that seeds the
    /// gap: conformal:8 on the cylinders').
    pub(crate) fn words(self, seed: &str) -> String {
        match self {
            Route::FromModel => format!("started from {seed} at the same control"),
            Route::AboveModelPullOff => format!("traced from just above {seed}'s pull-off"),
            Route::FromScreen => format!(
                "Newton at the control from {seed}'s state where its states at fixed a cross it"
            ),
            Route::FromModelContour => format!(
                "Newton from {seed}'s own contour at its pull-off, then the least force along that arm (no walk in the gap or in rho)"
            ),
            other => other.to_string(),
        }
    }
}

impl std::fmt::Display for Route {
    /// The route in words, on the cylinders' gap (`Route::words` names
    /// the seeding model of another).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Route::FromModel
            | Route::AboveModelPullOff
            | Route::FromScreen
            | Route::FromModelContour => return f.write_str(&self.words("conformal:8")),
            Route::FromCircle => "continued in rho from the circle at rho = 1",
            Route::FromCylinders => {
                "continued in the gap from the cylinders' state at the same rho and a (continued in rho from their circle)"
            }
            Route::ContinuedInRho => {
                "continued in rho at the same control from the state at a larger rho"
            }
            Route::BetweenStored => {
                "the minimum of F found at this rho from the stored pull-offs on both sides, interpolated in rho"
            }
            Route::PastFold => {
                "traced from beside a band through the fold of its arm, on the returning stretch"
            }
            Route::FromLargerContact => {
                "below the fold in rho of its family: on the arm of a larger contact continued in rho at fixed a, traced down in a to the control"
            }
            Route::FromNeighbour => "Newton at the control from a nearby state given by the caller",
        })
    }
}

/// The grid size from which the exact solver does two independent pieces
/// of work on two cores ([`both`]); on smaller grids waking a second thread
/// costs more than it saves (the warm state at ρ = 0.8 on 96 points took
/// twice as long with every such pair on two cores).
pub(crate) const TWO_CORES_FROM_POINTS: usize = 512;

/// `a` and `b`: on two cores (`rayon::join`) where `two_cores`, else one
/// after the other. Either way each is computed as it would be alone, so
/// the results do not depend on it.
pub(crate) fn both<A: Send, B: Send>(
    two_cores: bool,
    a: impl FnOnce() -> A + Send,
    b: impl FnOnce() -> B + Send,
) -> (A, B) {
    if two_cores {
        rayon::join(a, b)
    } else {
        (a(), b())
    }
}

/// The exact problem at one ρ and truncation.
pub struct Exact {
    rho: f64,
    /// The gap (data), and its polynomials at ρ and at ρ = 1 (the circle's).
    gap_source: Gap,
    gap: GapAt,
    circle: GapAt,
    truncation: Truncation,
    pub(crate) grid: Grid,
    fine: Grid,
    /// cos 2kθ_i on the grid (row k = 0..N, column i), divided by the
    /// number of points: the imposed modes of ∂p̄/∂ν − 1 as the mean of
    /// their product with it.
    pub(crate) cos_modes: DMatrix<f64>,
    /// The arclength representation's gauge weight w at the grid points:
    /// the gauge rows are the modes of w|z′|², so |z′| ∝ w^(−1/2). None
    /// for w = 1, θ proportional to arclength ([`Exact::keeping_the_speed_of`]).
    pub(crate) gauge_weight: Option<DVector<f64>>,
    /// Whether [`Exact::state`] computes the stability of the states it
    /// returns (not while [`resolved`] escalates the truncation).
    with_stability: bool,
    /// The last linearisation and the unknowns it was made at
    /// ([`Exact::linear`]): the secant's last slope and the stability of
    /// the state it returns are taken at the same unknowns.
    last_linear: std::sync::Mutex<Option<(DVector<f64>, linear::Linear)>>,
}

/// The groove's half-width below which the follow of the pull-off in ρ
/// crowds the points into it ([`Contour::crowded_at_groove`]): at
/// ρ = 0.0631 (half-width 0.170) the crowded series is better at every
/// truncation (128 modes: boundary error 3.3e-11 against 8.7e-8 at equal
/// arclength), at ρ = 0.0813 (0.266) no better (96 modes: 1.4e-8 against
/// 8.2e-9), at ρ = 0.215 (0.957) worse (64 modes: 1.6e-6 against 6.2e-12).
pub(crate) const CROWD_BELOW_HALF_WIDTH: f64 = 0.2;
/// The least density of points added at a groove's bottom, relative to 1
/// elsewhere ([`Contour::crowded_at_groove`]); narrower grooves get
/// [`CROWDING_TIMES_HALF_WIDTH`] divided by their half-width where that is
/// more. The best height grows as the groove narrows (boundary error with
/// σ = 0.1, heights 2 / 3 / 4 / 6 / 8): at ρ = 0.0442 (half-width 0.086,
/// 160 modes) 2.3e-11 / 1.0e-11 / 1.8e-10 / 4.5e-9 / 7.9e-8; at ρ = 0.0366
/// (0.061, 192 modes) 5.5e-10 / 5.2e-11 / 5.5e-11 / 2.7e-10 / 4.7e-9; at
/// ρ = 0.0270 (0.036, 256 modes) 1.4e-8 / 4.3e-10 / 3.0e-11 / 2.6e-11 /
/// 2.8e-11.
pub(crate) const GROOVE_CROWDING: f64 = 2.0;
/// The height of the crowding times the groove's half-width, where that
/// is more than [`GROOVE_CROWDING`]: 2.3 at ρ = 0.0442, 3.3 at 0.0366 and
/// 5.6 at 0.0270, inside the best range of each.
pub(crate) const CROWDING_TIMES_HALF_WIDTH: f64 = 0.2;
/// The width σ of the crowding, in the parameter of equal arclength (2π
/// for the whole perimeter). Against 0.05 and 0.07 (heights 2 to 8), 0.1
/// is best or within a factor 1.5 of the best at the three ρ above.
pub(crate) const GROOVE_WIDTH: f64 = 0.1;

/// The longest contour series accepted ([`Truncation::modes`]): beyond
/// [`MAX_ESCALATED_MODES`], for the notched arms below the fold in ρ
/// (docs/exact.md, "Zero force at ρ = 0.3": 448 to 512 modes of each sign
/// resolve them below 1e-9).
pub(crate) const MAX_MODES: usize = 512;
/// The most quadrature points accepted ([`Truncation::points`]): the
/// boundary integral equation's matrices grow as points², the fine check
/// uses twice as many. 320 modes of each sign on 2560 points (`thinjkr
/// exact store-pull-offs`, its last steps) peak at 0.62 GB, a solve with
/// 512 modes on 4096 points at 0.83 GB; an early version took 0.52 GB and
/// 2 min for 64 modes on 2048 points.
pub(crate) const MAX_POINTS: usize = 4096;

/// max |v − 1| over `values` (∂p̄/∂ν on a grid: the boundary condition
/// (3)₂ asks for 1 everywhere).
fn largest_departure_from_one(values: &[f64]) -> f64 {
    values.iter().map(|v| (v - 1.0).abs()).fold(0.0, f64::max)
}

impl Exact {
    /// The exact problem at `rho` ∈ (0, 1] on the cylinders' gap (1),
    /// seeded by the registry's family on it (`Gap::cylinders`).
    pub fn new(rho: f64, truncation: Truncation) -> Result<Exact> {
        Exact::on(Gap::cylinders(), rho, truncation)
    }

    /// The exact problem at `rho` ∈ (0, 1] on `gap`.
    pub(crate) fn on(gap: Gap, rho: f64, truncation: Truncation) -> Result<Exact> {
        if !(rho > 0.0 && rho <= 1.0) {
            return Err(Error::OutOfRange {
                name: "rho",
                value: rho,
                range: "(0, 1]".into(),
            });
        }
        if truncation.modes > MAX_MODES {
            return Err(Error::OutOfRange {
                name: "modes",
                value: truncation.modes as f64,
                range: format!("1 ..= {MAX_MODES} (the contour series' length)").into(),
            });
        }
        if truncation.points > MAX_POINTS {
            return Err(Error::OutOfRange {
                name: "points",
                value: truncation.points as f64,
                range: format!("at most {MAX_POINTS} (memory and time grow as points²: {MAX_POINTS} points with {MAX_MODES} modes take about 0.8 GB)").into(),
            });
        }
        if truncation.modes < 1 || truncation.points < 4 * truncation.modes + 8 {
            return Err(Error::OutOfRange {
                name: "truncation.points",
                value: truncation.points as f64,
                range: "at least 4 · modes + 8 (and modes ≥ 1)".into(),
            });
        }
        if truncation.arclength > truncation.modes {
            return Err(Error::OutOfRange {
                name: "truncation.arclength",
                value: truncation.arclength as f64,
                range: "0 ..= modes (the positive modes of the arclength representation)".into(),
            });
        }
        // the grid and the fine grid (twice the points, for the checks),
        // made on both cores
        let (grid, fine) = both(
            truncation.points >= TWO_CORES_FROM_POINTS,
            || Grid::with_basis(truncation.points, truncation.modes, truncation.arclength),
            || {
                Grid::with_basis(
                    2 * truncation.points,
                    truncation.modes,
                    truncation.arclength,
                )
            },
        );
        let cos_modes = DMatrix::from_fn(truncation.modes + 1, grid.len(), |k, i| {
            (2.0 * k as f64 * grid.theta[i]).cos() / grid.len() as f64
        });
        Ok(Exact {
            rho,
            gap_source: gap,
            gap: gap.at(rho)?,
            circle: gap.at(1.0)?,
            truncation,
            grid,
            fine,
            cos_modes,
            gauge_weight: None,
            with_stability: true,
            last_linear: std::sync::Mutex::new(None),
        })
    }

    /// The same problem at another ρ, its grids kept (they do not depend
    /// on ρ; building them is most of [`Exact::on`]'s work).
    pub(crate) fn move_to_rho(&mut self, rho: f64) -> Result<()> {
        if !(rho > 0.0 && rho <= 1.0) {
            return Err(Error::OutOfRange {
                name: "rho",
                value: rho,
                range: "(0, 1]".into(),
            });
        }
        self.gap = self.gap_source.at(rho)?;
        self.rho = rho;
        if let Ok(mut last) = self.last_linear.lock() {
            *last = None;
        }
        Ok(())
    }

    /// The gap it solves.
    pub(crate) fn gap(&self) -> Gap {
        self.gap_source
    }

    /// Its gap's polynomials at its ρ (for the descent's potential).
    #[cfg(feature = "cli")]
    pub(crate) fn gap_at(&self) -> &GapAt {
        &self.gap
    }

    /// The approach of the exact circle of radius ā at ρ = 1 on this gap
    /// (ā²/4 − 2/ā for the cylinders): the starting guesses' offset.
    pub(crate) fn circle_delta(&self, a_bar: f64) -> f64 {
        self.circle.circle_delta(a_bar)
    }

    /// The circle's polynomials (the gap at ρ = 1).
    pub(crate) fn circle(&self) -> &GapAt {
        &self.circle
    }

    /// The same problem with the states' stability left empty (computed
    /// by [`resolved`] for the answer it chooses).
    pub(crate) fn deferring_stability(mut self) -> Exact {
        self.with_stability = false;
        self
    }

    /// The same problem with the arclength representation's gauge set to
    /// keep the speed profile of `c`: the weight w(θ) = mean|z_c′|²/|z_c′(θ)|²,
    /// so that `c` itself satisfies the gauge, and a state found from it
    /// keeps its points where `c` has them. With a contour whose θ is
    /// proportional to arclength, w = 1.
    pub(crate) fn keeping_the_speed_of(mut self, c: &Contour) -> Exact {
        if self.truncation.arclength == 0 {
            return self;
        }
        let speed2: Vec<f64> = self
            .grid
            .theta
            .iter()
            .map(|&t| c.at(t)[1].norm_sqr())
            .collect();
        let mean = speed2.iter().sum::<f64>() / speed2.len() as f64;
        self.gauge_weight = Some(DVector::from_iterator(
            speed2.len(),
            speed2.iter().map(|v| mean / v),
        ));
        self
    }

    /// The problem `st` is a state of, to go on from it: its gap, ρ and
    /// truncation, with the points crowded into its grooves where it has
    /// narrow ones (the pull-offs below ρ ≈ 0.068 and the states traced
    /// from them: [`Exact::keeping_the_speed_of_grooved`]), else θ
    /// proportional to arclength. (A trace from a grooved pull-off in the
    /// plain gauge fails at its first step.)
    pub(crate) fn of_state(st: &ExactState) -> Result<Exact> {
        Ok(Exact::on(st.gap, st.rho, st.truncation)?.keeping_the_speed_of_grooved(&st.contour))
    }

    /// [`Exact::keeping_the_speed_of`] `c` where `c` has a narrow groove
    /// (its points then crowded into it by the follow,
    /// [`Contour::crowded_at_groove`]); else the same problem (θ
    /// proportional to arclength).
    pub(crate) fn keeping_the_speed_of_grooved(self, c: &Contour) -> Exact {
        if c.narrow_groove().is_some() {
            self.keeping_the_speed_of(c)
        } else {
            self
        }
    }

    /// The cosine modes k = 0..N of ∂p̄/∂ν − 1 at u = (A, b₀..b_{N−1}, δ̄)
    /// (the family's equations, ā free), and F̄.
    pub(crate) fn modes(&self, u: &DVector<f64>) -> Option<(DVector<f64>, f64)> {
        let (r, force) = self.equations(u, Hold::Size(0.0))?;
        Some((r.rows(1, r.len() - 1).into_owned(), force))
    }

    /// The number of unknowns: the contour's coefficients and δ̄.
    pub(crate) fn unknown_count(&self) -> usize {
        self.truncation.coefficients() + 1
    }

    /// The contour of the unknowns u = (A, b₀..b_{N−1}, c₀..c_{P−1}, δ̄).
    pub(crate) fn contour_of(&self, u: &DVector<f64>) -> Contour {
        let nm = self.truncation.modes;
        let np = self.truncation.arclength;
        Contour {
            a: u[0],
            b: u.rows(1, nm).iter().copied().collect(),
            c: u.rows(1 + nm, np).iter().copied().collect(),
        }
    }

    /// The arclength representation's rows: the modes cos 2kθ, k = 1..P,
    /// of |z′(θ)|² (mean over the grid), zero when θ is proportional to
    /// arclength; empty for the conformal-map form.
    pub(crate) fn gauge_rows(&self, dz: &[Complex<f64>]) -> Vec<f64> {
        let mut speed2 = DVector::from_iterator(dz.len(), dz.iter().map(|d| d.norm_sqr()));
        if let Some(w) = &self.gauge_weight {
            speed2.component_mul_assign(w);
        }
        (self.cos_modes.rows(1, self.truncation.arclength) * speed2)
            .iter()
            .copied()
            .collect()
    }

    /// ∂/∂(coefficients) of [`Exact::gauge_rows`]: P × (unknowns), δ̄'s
    /// column zero (∂|z′|²/∂c_l = 2 Re(z̄′ i m_l e_l)).
    pub(crate) fn gauge_jacobian(&self, u: &DVector<f64>) -> DMatrix<f64> {
        let np = self.truncation.arclength;
        let nu = self.unknown_count();
        let mut jac = DMatrix::zeros(np, nu);
        if np == 0 {
            return jac;
        }
        let s = self.contour_of(u).samples(&self.grid);
        let i_unit = Complex::new(0.0, 1.0);
        let w = |i: usize| self.gauge_weight.as_ref().map_or(1.0, |w| w[i]);
        let d = DMatrix::from_fn(self.grid.len(), nu - 1, |i, l| {
            let m = self.grid.multipliers[l];
            2.0 * w(i) * (s.dz[i].conj() * i_unit * m * self.grid.basis[l][i]).re
        });
        jac.columns_mut(0, nu - 1)
            .copy_from(&(self.cos_modes.rows(1, np) * d));
        jac
    }

    /// The cosine modes k = 0..N of ∂p̄/∂ν − 1 from ∂p̄/∂ν at the grid
    /// points `dn`: the equations' residuals besides the held quantity.
    pub(crate) fn cos_modes_of(&self, dn: &[f64]) -> DVector<f64> {
        &self.cos_modes * DVector::from_iterator(dn.len(), dn.iter().map(|v| v - 1.0))
    }

    /// The family's equations (ā free) from ∂p̄/∂ν at the grid points `dn`
    /// of the unknowns u: the cosine modes of [`Exact::cos_modes_of`], then
    /// the arclength representation's rows ([`Exact::gauge_rows`]).
    pub(crate) fn family_residuals(&self, dn: &[f64], u: &DVector<f64>) -> DVector<f64> {
        let bc = self.cos_modes_of(dn);
        if self.truncation.arclength == 0 {
            return bc;
        }
        let gauge = self.gauge_rows(&self.contour_of(u).samples(&self.grid).dz);
        DVector::from_iterator(bc.len() + gauge.len(), bc.iter().copied().chain(gauge))
    }

    /// ∂/∂u of the cosine modes k = 0..N of ∂p̄/∂ν − 1 (as [`Exact::modes`]
    /// computes them) from the linearisation: (N + 1) × (N + 2).
    pub(crate) fn mode_jacobian(&self, lin: &linear::Linear, u: &DVector<f64>) -> DMatrix<f64> {
        let nu = lin.d_dn.ncols();
        let bc = &self.cos_modes * &lin.d_dn;
        if self.truncation.arclength == 0 {
            return bc;
        }
        let gauge = self.gauge_jacobian(u);
        let mut out = DMatrix::zeros(bc.nrows() + gauge.nrows(), nu);
        out.rows_mut(0, bc.nrows()).copy_from(&bc);
        out.rows_mut(bc.nrows(), gauge.nrows()).copy_from(&gauge);
        out
    }

    /// The truncation.
    pub(crate) fn truncation(&self) -> Truncation {
        self.truncation
    }

    /// The unknowns u = (A, b₀..b_{N−1}, δ̄) of a state.
    pub(crate) fn unknowns(&self, st: &ExactState) -> DVector<f64> {
        self.unknowns_of(&st.contour, st.delta_bar)
    }

    /// The unknowns u = (A, b₀..b_{N−1}, c₀..c_{P−1}, δ̄) of a contour and
    /// approach (coefficients beyond the truncation dropped, missing ones 0).
    pub(crate) fn unknowns_of(&self, contour: &Contour, delta_bar: f64) -> DVector<f64> {
        let nm = self.truncation.modes;
        let np = self.truncation.arclength;
        let mut u = DVector::zeros(self.unknown_count());
        u[0] = contour.a;
        for j in 0..nm {
            u[j + 1] = contour.b.get(j).copied().unwrap_or(0.0);
        }
        for j in 0..np {
            u[j + 1 + nm] = contour.c.get(j).copied().unwrap_or(0.0);
        }
        u[nm + np + 1] = delta_bar;
        u
    }

    /// ∂p̄/∂ν along the contour of `st` on the fine grid (twice the points
    /// the state was solved on), as (polar angle atan2(Y, X), ∂p̄/∂ν) for the
    /// first quadrant: the boundary condition (3)₂ asks for 1 everywhere.
    #[cfg(feature = "figures")]
    pub(crate) fn boundary_profile(&self, st: &ExactState) -> Result<Vec<(f64, f64)>> {
        let f = fields(&st.contour, &self.gap, st.delta_bar, &self.fine).ok_or_else(|| {
            Error::NoState("exact boundary profile: the fine-grid system is singular".into())
        })?;
        let quarter = std::f64::consts::FRAC_PI_2;
        Ok(self
            .fine
            .theta
            .iter()
            .zip(&f.normal_derivative)
            .filter(|(t, _)| **t <= quarter + 1e-12)
            .map(|(&t, &dn)| {
                let [z, _, _] = st.contour.at(t);
                (z.im.atan2(z.re), dn)
            })
            .collect())
    }

    /// The pressure field of a state (its boundary integral solved again on
    /// twice the points, with the full system rather than the symmetric
    /// reduction the Newton iteration uses: the second route of the tests
    /// shares neither).
    pub fn field(&self, st: &ExactState) -> Result<Field> {
        let samples = st.contour.samples(&self.fine);
        let g: Vec<f64> = samples
            .z
            .iter()
            .map(|&z| -self.gap.p(z.re, z.im, st.delta_bar))
            .collect();
        let d = solve_dirichlet(&self.fine, &samples, &g).ok_or_else(|| {
            Error::NoState("exact field: singular boundary integral equation".into())
        })?;
        // F_j = μ_j + (1/(i n)) [Σ_{k≠j} (μ_k − μ_j) τ'_k/(τ_k − τ_j) + μ'_j]
        let mu = &d.density;
        let d_mu = self.fine.derivative(mu);
        let n = samples.z.len();
        let i_n = Complex::new(0.0, n as f64);
        let boundary = (0..n)
            .map(|j| {
                let mut sum = Complex::new(d_mu[j], 0.0);
                for k in 0..n {
                    if k != j {
                        sum += (mu[k] - mu[j]) * samples.dz[k] / (samples.z[k] - samples.z[j]);
                    }
                }
                mu[j] + sum / i_n
            })
            .collect();
        Ok(Field {
            gap: self.gap.clone(),
            delta_bar: st.delta_bar,
            samples,
            boundary,
        })
    }

    /// The equations at u = (A, b₀..b_{N−1}, δ̄): the held quantity minus
    /// its value (z(0) − ā, δ̄ − δ̄₀ or F̄ − F̄₀) and the cosine modes
    /// k = 0..N of ∂p̄/∂ν − 1; and F̄.
    fn equations(&self, u: &DVector<f64>, held: Hold) -> Option<(DVector<f64>, f64)> {
        let n_modes = self.truncation.modes;
        let id = self.unknown_count() - 1;
        let c = self.contour_of(u);
        let samples = c.samples(&self.grid);
        let f = fields_of(&samples, &self.gap, u[id], &self.grid)?;
        let mut r = DVector::zeros(self.unknown_count());
        r[0] = match held {
            Hold::Size(a_bar) => c.a_bar() - a_bar,
            Hold::Delta(d) => u[id] - d,
            Hold::Force(v) => f.force - v,
        };
        r.rows_mut(1, n_modes + 1)
            .copy_from(&self.cos_modes_of(&f.normal_derivative));
        if self.truncation.arclength > 0 {
            for (k, g) in self.gauge_rows(&samples.dz).into_iter().enumerate() {
                r[n_modes + 2 + k] = g;
            }
        }
        Some((r, f.force))
    }

    /// The exact state with half-width `a_bar` on the X axis, by Newton's
    /// method from the contour `guess` and approach `delta_guess` (an
    /// approximate model's state, or a neighbour on the family).
    pub fn solve(&self, a_bar: f64, guess: &Contour, delta_guess: f64) -> Result<ExactState> {
        self.state(&self.newton(Hold::Size(a_bar), guess, delta_guess)?)
    }

    /// The exact state at `control` by Newton's method from the contour
    /// `guess` and approach `delta_guess` (an approximate model's state at
    /// the same control): the equations with δ̄ or F̄ held instead of ā.
    /// Near a fold of the family in that control the system is singular,
    /// and Newton fails.
    pub(crate) fn solve_at(
        &self,
        control: Hold,
        guess: &Contour,
        delta_guess: f64,
    ) -> Result<ExactState> {
        self.state(&self.newton(control, guess, delta_guess)?)
    }

    /// The unknowns u = (A, b₀..b_{N−1}, δ̄) of the state [`Exact::solve`]
    /// returns, without the state's fine-grid check and stability: the
    /// shared chord iteration ([`crate::newton::chord`]) on the equations
    /// at `held`.
    fn newton(&self, held: Hold, guess: &Contour, delta_guess: f64) -> Result<DVector<f64>> {
        let u = match (self.truncation.arclength, guess.c.is_empty()) {
            // a contour of the conformal-map form, re-parametrised
            (p, true) if p > 0 => {
                self.unknowns_of(&guess.in_arclength(self.truncation.modes), delta_guess)
            }
            (0, false) => {
                return Err(Error::Usage(
                    "a contour in the arclength representation cannot start the conformal-map form (its conformal map is not computed)".into(),
                ))
            }
            _ => self.unknowns_of(guess, delta_guess),
        };
        self.newton_from(held, u, None)
    }

    /// [`Exact::newton`] from the unknowns `u`, beginning with the
    /// factorised Jacobian `first` where one is given (made at a nearby
    /// state of this problem at the same kind of hold, as a continuation's
    /// last step left it; refreshed where it stops serving).
    pub(crate) fn newton_from(
        &self,
        held: Hold,
        u: DVector<f64>,
        first: Option<nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>>,
    ) -> Result<DVector<f64>> {
        let rho = crate::error::rounded(self.rho);
        self.chord_on(&Held { exact: self, held }, u, first, |delta| {
            format!("exact solution at rho = {rho}, {held} (delta_bar = {delta})")
        })
    }

    /// The shared chord iteration ([`crate::newton::chord`]) on `system`,
    /// equations in this problem's unknowns, from `u` and `first` (as
    /// [`Exact::newton_from`]), to the exact solver's residual; where it
    /// stops, the error at the last iterate's contour, `what` naming the
    /// equations at its approach (rounded).
    pub(crate) fn chord_on(
        &self,
        system: &impl crate::newton::ChordSystem,
        u: DVector<f64>,
        first: Option<nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>>,
        what: impl Fn(String) -> String,
    ) -> Result<DVector<f64>> {
        let id = self.unknown_count() - 1;
        let config = crate::newton::ChordConfig {
            floor: 1e-13,
            tolerance: RESIDUAL_TOLERANCE,
            max_iterations: 60,
        };
        crate::newton::chord(system, u, first, &config).map_err(|stop| {
            // where it stopped: the contour of the last iterate
            let c = self.contour_of(&stop.u);
            Error::NoConvergence {
                iterations: stop.iterations,
                a_bar: c.a_bar(),
                s: c.b_bar() / c.a_bar(),
                residual: stop.residual,
                context: format!("{}: {}", what(crate::error::rounded(stop.u[id])), stop.why),
            }
        })
    }

    /// The exact state at half-width `a_bar` from `near`, a converged state
    /// of the same truncation (at this or a nearby ρ or ā), by Newton's method.
    pub fn solve_from(&self, a_bar: f64, near: &ExactState) -> Result<ExactState> {
        let guess = near.contour.scaled(a_bar / near.a_bar);
        // δ̄ ≈ the circle's (ā²/4 − 2/ā for the cylinders) shifted by the
        // neighbour's offset
        let delta = near.delta_bar + self.circle_delta(a_bar) - self.circle_delta(near.a_bar);
        self.solve(a_bar, &guess, delta)
    }

    /// The exact state at half-width `a_bar`, continued in ρ from the
    /// exact circle at ρ = 1 (steps in ρ halved where Newton fails): no
    /// approximate model is used.
    pub fn from_circle(&self, a_bar: f64) -> Result<ExactState> {
        let u = self.circle_unknowns(a_bar)?;
        self.state(&u)
    }

    /// The exact state at half-width `a_bar` on any gap: on a gap the
    /// circle solves, [`Exact::from_circle`]; on another (issue 73), the
    /// cylinders' state at ā at this ρ (continued in ρ from their circle),
    /// continued in the gap itself at fixed ā and ρ,
    /// φ̄ₜ = (1 − t)·φ̄_cylinders + t·φ̄ from t = 0 to 1 (the one walk, on
    /// s = 1 − t, with the steps [`rho_walk::IN_THE_GAP`]). No approximate
    /// model is used.
    pub(crate) fn continued_in_the_gap(&self, a_bar: f64) -> Result<ExactState> {
        if self.circle.is_radial() {
            return self.from_circle(a_bar);
        }
        let known = Exact::on(Gap::cylinders(), self.rho, self.truncation)?;
        let u = known.circle_unknowns(a_bar)?;
        let mut ex = Exact::on(self.gap_source, self.rho, self.truncation)?;
        let id = self.unknown_count() - 1;
        let mut at = (1.0, u);
        let walked = rho_walk::walk_down(
            &mut at,
            0.0,
            rho_walk::IN_THE_GAP,
            |at| at.0,
            |(_, u), s| {
                // s = 1 − t: s of the cylinders' gap, 1 − s of this one
                ex.gap = self.gap.blend(&known.gap, s);
                Ok(
                    match ex.newton(Hold::Size(a_bar), &ex.contour_of(u), u[id]) {
                        Ok(n) => rho_walk::Attempt::Took((s, n)),
                        Err(e) => rho_walk::Attempt::Missed(e),
                    },
                )
            },
        )?;
        let (s, u) = at;
        if let Err(rho_walk::Stopped { why, .. }) = walked {
            return Err(match why {
                Error::NoConvergence { .. } | Error::Unresolved { .. } | Error::NoState(_) => Error::NoState(format!(
                    "exact state at rho = {} on the gap {}: the continuation in the gap from the cylinders' at a_bar = {} stopped at t = {} of the way (Newton failed there with steps in t down to {:.0e})",
                    crate::error::short(self.rho),
                    self.gap_source.name,
                    crate::error::rounded(a_bar),
                    crate::error::rounded(1.0 - s),
                    rho_walk::IN_THE_GAP.smallest
                )),
                other => other,
            });
        }
        let mut st = self.state(&u)?;
        st.route = Route::FromCylinders;
        Ok(st)
    }

    /// The unknowns of the exact state at half-width `a_bar` continued in ρ
    /// from the exact circle at ρ = 1 ([`Exact::from_circle`]).
    fn circle_unknowns(&self, a_bar: f64) -> Result<DVector<f64>> {
        let nm = self.truncation.modes;
        if !self.circle.is_radial() {
            return Err(Error::Unavailable {
                model: "exact",
                what: format!("route from the circle on the gap {}", self.gap_source.name),
                why: "the gap at rho = 1 is not a function of X^2 + Y^2, so no circle solves it",
            });
        }
        let circle = Exact::on(self.gap_source, 1.0, self.truncation)?;
        // the intermediate states need no fine-grid check or stability
        let u = circle.newton(
            Hold::Size(a_bar),
            &Contour::ellipse(a_bar, a_bar, nm),
            self.circle_delta(a_bar),
        )?;
        let id = self.unknown_count() - 1;
        let contour = |u: &DVector<f64>| circle.contour_of(u);
        let mut at = (1.0, u);
        let walked = rho_walk::walk_down(
            &mut at,
            self.rho,
            rho_walk::FROM_THE_CIRCLE,
            |at| at.0,
            |(_, u), next| {
                let ex = Exact::on(self.gap_source, next, self.truncation)?;
                Ok(match ex.newton(Hold::Size(a_bar), &contour(u), u[id]) {
                    Ok(n) => rho_walk::Attempt::Took((next, n)),
                    Err(e) => rho_walk::Attempt::Missed(e),
                })
            },
        )?;
        let (rho, u) = at;
        if let Err(rho_walk::Stopped { why, .. }) = walked {
            // in the user's words: where the continuation stopped, rounded
            // (not the intermediate ρ to 17 digits)
            return Err(match why {
                Error::NoConvergence { .. } | Error::Unresolved { .. } | Error::NoState(_) => Error::NoState(format!(
                    "exact state at rho = {}: the continuation in rho from the circle at a_bar = {} stopped at rho = {} (Newton failed there with steps in rho down to {:.0e})",
                    crate::error::short(self.rho),
                    crate::error::rounded(a_bar),
                    crate::error::rounded(rho),
                    rho_walk::FROM_THE_CIRCLE.smallest
                )),
                other => other,
            });
        }
        Ok(u)
    }

    /// The contour of `u` and its fields on the fine grid (the check of
    /// every state); `None` where that system is singular.
    fn fine_fields(&self, u: &DVector<f64>) -> Option<(Contour, f64, Fields)> {
        let contour = self.contour_of(u);
        let delta_bar = u[self.unknown_count() - 1];
        let fine = fields(&contour, &self.gap, delta_bar, &self.fine)?;
        Some((contour, delta_bar, fine))
    }

    /// The boundary error of [`Exact::state`] at `u` alone: the largest
    /// |∂p̄/∂ν − 1| on the fine grid; `None` where that system is singular.
    pub(crate) fn fine_boundary_error(&self, u: &DVector<f64>) -> Option<f64> {
        self.fine_fields(u)
            .map(|(_, _, fine)| largest_departure_from_one(&fine.normal_derivative))
    }

    pub(crate) fn state(&self, u: &DVector<f64>) -> Result<ExactState> {
        let (contour, delta_bar, fine) = self.fine_fields(u).ok_or_else(|| {
            Error::NoState("exact state: the fine-grid check system is singular".into())
        })?;
        let bc_error = largest_departure_from_one(&fine.normal_derivative);
        let (a_bar, b_bar) = (contour.a_bar(), contour.b_bar());
        let mut st = ExactState {
            rho: self.rho,
            a_bar,
            b_bar,
            s: b_bar / a_bar,
            delta_bar,
            force_bar: fine.force,
            deviation_from_ellipse: contour.deviation_from_ellipse(4 * self.truncation.points),
            contour,
            bc_error,
            truncation: self.truncation,
            stability: stability::ExactStability::default(),
            // the route of the family traced from the start this gap has
            // (the callers name another where they took one)
            route: if self.circle.is_radial() {
                Route::FromCircle
            } else {
                Route::FromCylinders
            },
            shape: None,
            coatings: None,
            warnings: Vec::new(),
            gap: self.gap_source,
        };
        if self.with_stability {
            st.stability = self.stability(&st)?;
        }
        Ok(st)
    }
}
/// The exact equations at a hold as a system of the shared chord
/// iteration ([`crate::newton::chord`]): the residuals of
/// [`Exact::equations`], the Jacobian of the discrete equations
/// ([`Exact::linear`]) with the hold's row.
struct Held<'a> {
    exact: &'a Exact,
    held: Hold,
}

impl crate::newton::ChordSystem for Held<'_> {
    fn residuals(&self, u: &DVector<f64>) -> Option<DVector<f64>> {
        self.exact.equations(u, self.held).map(|(r, _)| r)
    }

    fn jacobian(
        &self,
        u: &DVector<f64>,
    ) -> Option<nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>> {
        self.exact.held_jacobian(u, self.held).map(|j| j.lu())
    }
}

impl Exact {
    /// The Jacobian of [`Exact::equations`] at `held` in u: the hold's row,
    /// then the derivatives of the discrete equations ([`Exact::linear`]).
    pub(crate) fn held_jacobian(&self, u: &DVector<f64>, held: Hold) -> Option<DMatrix<f64>> {
        let nu = self.unknown_count();
        let lin = self.linear(u)?;
        let mut jac = DMatrix::zeros(nu, nu);
        match held {
            Hold::Size(_) => jac.view_mut((0, 0), (1, nu - 1)).fill(1.0),
            Hold::Delta(_) => jac[(0, nu - 1)] = 1.0,
            Hold::Force(_) => jac.row_mut(0).copy_from(&lin.d_force.transpose()),
        }
        jac.view_mut((1, 0), (nu - 1, nu))
            .copy_from(&self.mode_jacobian(&lin, u));
        Some(jac)
    }
}
