//! The linearisation of the exact problem: ∂p̄/∂ν on the contour and F̄,
//! with their derivatives in the unknowns u = (A, b₀..b_{N−1}, δ̄), by
//! differentiating the discrete boundary integral solution of [`super::bie`]
//! (the same trapezoid rule, kernel and differentiation matrix) once for
//! every unknown. It serves Newton's Jacobian, the trace's bordered
//! Jacobian and the stability's Hessian, which had each taken central
//! differences (two solves per unknown); here the second-kind system is
//! factored once, and each unknown costs products of the tabulated
//! kernels with the contour basis.
//!
//! The derivation, for a contour coefficient c_l with multiplier m_l
//! (z = Σ c_l e^{i m_l θ}): δz_j = e_l(θ_j), δz'_j = i m_l δz_j,
//! δz''_j = −m_l² δz_j; with ι_ij = 1/(z_j − z_i) and w_ij = z'_j ι_ij,
//! δw_ij = i m_l ι_ij δz_j − w_ij ι_ij (δz_j − δz_i). The reduced system
//! μ_i + Σ_j Im(w_ij)(μ_j − μ_i)/n = g_i gives
//! A δμ = δg − Σ_j Im(δw_ij)(μ_j − μ_i)/n, with g = −P on the contour;
//! the normal derivative Re(F′ν) of [`super::bie`] is differentiated term
//! by term (ψ = μ′/z′, the Cauchy sum, ν = −i z′/|z′|), and ∇P·ν and the
//! force's boundary integrals as in [`super::fields`]. For δ̄ only g, ∇P
//! and the force's integrands change. The sums over the points of a
//! quantity the reflections map to itself are taken over the orbits'
//! representatives (the symmetric copies folded into the weights). A test
//! holds every entry against central differences of [`super::fields`].
//! The last linearisation is kept with its unknowns (asked for again at
//! the same unknowns, it is not computed again), and on large grids
//! independent products run on two cores ([`super::both`]).
//!
//! Owns: [`Linear`], [`Exact::linear`]. May use: `exact`, `exact::bie`,
//! nalgebra, rayon (through `exact::both`).

use super::bie::{orbits, ContourSamples, Grid};
use super::Exact;
use super::GapAt;
use nalgebra::{Complex, DMatrix, DVector};

/// ∂p̄/∂ν at the grid points and F̄, with their derivatives in u.
#[derive(Clone, Debug)]
pub(crate) struct Linear {
    /// ∂p̄/∂ν at the grid points.
    pub dn: Vec<f64>,
    /// F̄.
    pub force: f64,
    /// ∂(∂p̄/∂ν)(θ_i)/∂u_l: n × (N + 2).
    pub d_dn: DMatrix<f64>,
    /// ∂F̄/∂u_l.
    pub d_force: DVector<f64>,
}

type C = Complex<f64>;

impl Exact {
    /// The linearisation at u = (A, b₀..b_{N−1}, δ̄); `None` where the
    /// discrete system is singular (a self-intersecting contour).
    pub(crate) fn linear(&self, u: &DVector<f64>) -> Option<Linear> {
        if let Ok(last) = self.last_linear.lock() {
            if let Some((at, lin)) = last.as_ref() {
                if at == u {
                    return Some(lin.clone());
                }
            }
        }
        let lin = self.linearise(u)?;
        if let Ok(mut last) = self.last_linear.lock() {
            *last = Some((u.clone(), lin.clone()));
        }
        Some(lin)
    }

    /// [`Exact::linear`], computed.
    fn linearise(&self, u: &DVector<f64>) -> Option<Linear> {
        let nc = self.truncation.coefficients();
        let nu = nc + 1;
        let grid = &self.grid;
        let n = grid.len();
        let nf = n as f64;
        let i_unit = C::new(0.0, 1.0);
        let contour = self.contour_of(u);
        let delta = u[nc];
        let s = contour.samples(grid);
        let (reps, orbit) = orbits(n);
        let m = reps.len();
        let mult: Vec<f64> = grid.multipliers.clone();
        // the contour basis: e_l(θ_j) = grid.basis[l][j]
        let e = &grid.basis;

        // the forward solve, as bie::solve_dirichlet_symmetric
        let (inv, w, a) = forward_system(&s, &reps, &orbit);
        // the gap's particular solution P and its gradient P_X + i P_Y
        let gap = &self.gap;
        let grad_p: Vec<C> = s.z.iter().map(|z| gap.grad_complex(*z, delta)).collect();
        let g =
            DVector::from_iterator(m, reps.iter().map(|&i| -gap.p(s.z[i].re, s.z[i].im, delta)));
        let lu = a.lu();
        let mu_red = lu.solve(&g)?;
        if mu_red.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let mu = DVector::from_iterator(n, orbit.iter().map(|&k| mu_red[k]));
        let d_mu = grid.derivative(&mu);
        let dd_mu = grid.derivative(&d_mu);
        let psi: Vec<C> = (0..n).map(|j| d_mu[j] / s.dz[j]).collect();
        let speed: Vec<f64> = s.dz.iter().map(|d| d.norm()).collect();
        let nu_of = |i: usize| -i_unit * s.dz[i] / speed[i];
        let (d_psi, f_prime, dn_rep) =
            at_representatives(&s, &reps, &w, &psi, &d_mu, &dd_mu, &grad_p);
        let dn: Vec<f64> = orbit.iter().map(|&k| dn_rep[k]).collect();

        // δz, δz′, δz″ of each unknown at each point (δ̄ moves none)
        let moves = Moves { e, mult: &mult, nc };
        let (dz_of, ddz_of) = (|j, l| moves.dz(j, l), |j, l| moves.ddz(j, l));

        // δg at the representatives, minus Σ_j Im(δw_ij)(μ_j − μ_i)/n
        let mu_c: Vec<C> = mu.iter().map(|&v| C::new(v, 0.0)).collect();
        let q = moving_kernel_sums(grid, &reps, &inv, &w, &mult, &mu_c);
        let rhs = DMatrix::<f64>::from_fn(m, nu, |r, l| {
            let i = reps[r];
            if l < nc {
                -(grad_p[i].conj() * e[l][i]).re - q[(r, l)].im / nf
            } else {
                -gap.p_delta(s.z[i].re, s.z[i].im)
            }
        });
        let d_mu_red = lu.solve(&rhs)?;
        // δμ′ and δμ″ at the representatives (the sums below need δψ there
        // only)
        let (d1p, d2r) = grid.orbit_derivatives();
        let d1r = DMatrix::from_fn(m, m, |r, k| d1p[(reps[r], k)]);
        // (independent products, on both cores)
        let two_cores = n >= super::TWO_CORES_FROM_POINTS;
        let (dd_mu_rep, ddd_mu_rep) =
            super::both(two_cores, || d1r * &d_mu_red, || d2r * &d_mu_red);
        // δψ_j = (δμ′_j − ψ_j δz′_j)/z′_j
        let d_psi_rep = DMatrix::<C>::from_fn(m, nu, |r, l| {
            let j = reps[r];
            (dd_mu_rep[(r, l)] - psi[j] * ddz_of(j, l)) / s.dz[j]
        });
        // Σ_j δψ_j w_ij, and Σ_j (ψ_j − ψ_i) δw_ij
        let (t, u) = super::both(
            two_cores,
            || orbit_product(&w, &d_psi_rep, &reps),
            || moving_kernel_sums(grid, &reps, &inv, &w, &mult, &psi),
        );
        let w_sum: Vec<C> = (0..m).map(|r| w.row(r).iter().sum()).collect();
        let mut d_dn_rep = DMatrix::<f64>::zeros(m, nu);
        // P's second derivatives at the representatives
        let hess: Vec<_> = reps
            .iter()
            .map(|&i| gap.hessian(s.z[i].re, s.z[i].im, delta))
            .collect();
        for (r, &i) in reps.iter().enumerate() {
            let dz = s.dz[i];
            let (x, y) = (s.z[i].re, s.z[i].im);
            let nu_i = nu_of(i);
            for l in 0..nu {
                let (dz1, dz2, dz3) = (dz_of(i, l), ddz_of(i, l), moves.dddz(i, l));
                let d_d_psi = (dz2 * dd_mu[i] + dz * ddd_mu_rep[(r, l)]
                    - dz3 * d_mu[i]
                    - s.ddz[i] * dd_mu_rep[(r, l)])
                    / (dz * dz)
                    - 2.0 * d_psi[r] * dz2 / dz;
                let mut d_sum = d_d_psi + t[(r, l)] - d_psi_rep[(r, l)] * w_sum[r];
                if l < nc {
                    d_sum += u[(r, l)];
                }
                let d_f_prime = d_psi_rep[(r, l)] + d_sum / (i_unit * nf);
                let d_nu =
                    -i_unit * (dz2 / speed[i] - dz * ((dz.conj() * dz2).re / speed[i].powi(3)));
                let d_grad_p = moved_gradient(gap, &hess[r], (x, y), dz1, l < nc);
                d_dn_rep[(r, l)] = (d_f_prime * nu_i + f_prime[r] * d_nu).re
                    + (d_grad_p.conj() * nu_i + grad_p[i].conj() * d_nu).re;
            }
        }
        let d_dn = DMatrix::<f64>::from_fn(n, nu, |j, l| d_dn_rep[(orbit[j], l)]);

        let (force, d_force) = force_and_slope(gap, &s, delta, &dn, &d_dn, nc, &|i, l| {
            (dz_of(i, l), ddz_of(i, l))
        });
        Some(Linear {
            dn,
            force,
            d_dn,
            d_force,
        })
    }
}

/// δz, δz′ and δz″ at point j of unknown l: the contour basis e_l(θ_j)
/// and its multiplier m_l for the `nc` contour coefficients (δz′ = i m_l
/// δz, δz″ = −m_l² δz); δ̄ moves no point.
struct Moves<'a> {
    e: &'a [Vec<C>],
    mult: &'a [f64],
    nc: usize,
}

impl Moves<'_> {
    fn dz(&self, j: usize, l: usize) -> C {
        if l < self.nc {
            self.e[l][j]
        } else {
            C::new(0.0, 0.0)
        }
    }

    fn ddz(&self, j: usize, l: usize) -> C {
        C::new(0.0, 1.0) * self.mult.get(l).copied().unwrap_or(0.0) * self.dz(j, l)
    }

    fn dddz(&self, j: usize, l: usize) -> C {
        -(self.mult.get(l).copied().unwrap_or(0.0).powi(2)) * self.dz(j, l)
    }
}

/// δ(∇P) at the point (x, y) = (P_XX δx + P_XY δy) + i (P_XY δx + P_YY δy)
/// for a contour coefficient that moves the point by δz (`by_contour`),
/// else ∂∇P/∂δ̄.
fn moved_gradient(
    gap: &GapAt,
    h: &super::gap::Hessian,
    (x, y): (f64, f64),
    dz: C,
    by_contour: bool,
) -> C {
    if by_contour {
        C::new(
            h.p_xx * dz.re + h.p_xy * dz.im,
            h.p_xy * dz.re + h.p_yy * dz.im,
        )
    } else {
        let (gx, gy) = gap.grad_delta(x, y);
        C::new(gx, gy)
    }
}

/// The forward solve's tables, as [`super::bie`]'s symmetric Dirichlet
/// solve builds them, at the orbits' representatives `reps` (row r) and
/// every point j: ι_ij = 1/(z_j − z_i), the kernel w_ij = z′_j ι_ij (bie's
/// w = z′_j/(z_j − z_i) rounds differently, and moved the ρ = 1 pull-off,
/// located by values of F̄ where F̄ is flat, by 4e-8 in ā), and the reduced
/// system A of μ_i + Σ_j Im(w_ij)(μ_j − μ_i)/n (columns by `orbit`).
fn forward_system(
    s: &ContourSamples,
    reps: &[usize],
    orbit: &[usize],
) -> (DMatrix<C>, DMatrix<C>, DMatrix<f64>) {
    let (m, n) = (reps.len(), s.z.len());
    let nf = n as f64;
    let mut inv = DMatrix::<C>::zeros(m, n);
    let mut w = DMatrix::<C>::zeros(m, n);
    let mut a = DMatrix::<f64>::zeros(m, m);
    for (r, &i) in reps.iter().enumerate() {
        let mut row = 0.0;
        for j in 0..n {
            if j != i {
                let v = C::new(1.0, 0.0) / (s.z[j] - s.z[i]);
                inv[(r, j)] = v;
                let wij = s.dz[j] * v;
                w[(r, j)] = wij;
                let k = wij.im / nf;
                a[(r, orbit[j])] += k;
                row += k;
            }
        }
        a[(r, r)] += 1.0 - row;
    }
    (inv, w, a)
}

/// At the orbits' representatives (row r, point i = `reps[r]`): ψ′, F′
/// and ∂p̄/∂ν = Re(F′ν) + Re(conj(∇P) ν), ν = −i z′/|z′|, as
/// [`super::bie`]'s normal derivative, from ψ = μ′/z′, μ′, μ″, the kernel
/// `w` and ∇P = P_X + i P_Y at every point.
fn at_representatives(
    s: &ContourSamples,
    reps: &[usize],
    w: &DMatrix<C>,
    psi: &[C],
    d_mu: &DVector<f64>,
    dd_mu: &DVector<f64>,
    grad_p: &[C],
) -> (Vec<C>, Vec<C>, Vec<f64>) {
    let (m, n) = (reps.len(), s.z.len());
    let nf = n as f64;
    let i_unit = C::new(0.0, 1.0);
    let mut d_psi = vec![C::new(0.0, 0.0); m];
    let mut f_prime = vec![C::new(0.0, 0.0); m];
    let mut dn_rep = vec![0.0; m];
    for (r, &i) in reps.iter().enumerate() {
        let dz = s.dz[i];
        d_psi[r] = (dz * dd_mu[i] - s.ddz[i] * d_mu[i]) / (dz * dz);
        let mut sum = d_psi[r];
        for j in 0..n {
            if j != i {
                sum += (psi[j] - psi[i]) * w[(r, j)];
            }
        }
        f_prime[r] = psi[i] + sum / (i_unit * nf);
        let nu_i = -i_unit * dz / dz.norm();
        dn_rep[r] = (f_prime[r] * nu_i).re + (grad_p[i].conj() * nu_i).re;
    }
    (d_psi, f_prime, dn_rep)
}

/// F̄ = Σ_i (−w ∂p̄/∂ν |z′| + W Im z′) h (as [`super::fields`]) and its
/// derivatives in the unknowns, from ∂p̄/∂ν `dn` and its derivatives
/// `d_dn` (columns: the `nc` contour coefficients, then δ̄); `moved(i, l)`:
/// δz and δz′ at point i for unknown l.
fn force_and_slope(
    gap: &GapAt,
    s: &ContourSamples,
    delta: f64,
    dn: &[f64],
    d_dn: &DMatrix<f64>,
    nc: usize,
    moved: &dyn Fn(usize, usize) -> (C, C),
) -> (f64, DVector<f64>) {
    let n = s.z.len();
    let nu = d_dn.ncols();
    let h = 2.0 * std::f64::consts::PI / n as f64;
    let mut force = 0.0;
    let mut d_force = DVector::<f64>::zeros(nu);
    for i in 0..n {
        let (z, dz) = (s.z[i], s.dz[i]);
        let (x, y) = (z.re, z.im);
        let speed = dz.norm();
        let ww = (x * x + y * y) / 4.0;
        // W = ∫ w(φ̄ − δ̄) dX, ∂W/∂X, ∂W/∂Y, ∂W/∂δ̄
        let [big_w, w_x, w_y, w_delta] = gap.force_potential(x, y, delta);
        force += (-ww * dn[i] * speed + big_w * dz.im) * h;
        for l in 0..nu {
            let (dz1, dz2) = moved(i, l);
            let d_ww = (x * dz1.re + y * dz1.im) / 2.0;
            let d_speed = (dz.conj() * dz2).re / speed;
            let d_big_w = w_x * dz1.re + w_y * dz1.im + if l < nc { 0.0 } else { w_delta };
            d_force[l] +=
                (-d_ww * dn[i] * speed - ww * d_dn[(i, l)] * speed - ww * dn[i] * d_speed
                    + d_big_w * dz.im
                    + big_w * dz2.im)
                    * h;
        }
    }
    (force, d_force)
}

/// Σ_j δw_ij (x_j − x_i) for every representative i (row r) and contour
/// coefficient l (column), with w_ij = z′_j ι_ij, ι_ij = 1/(z_j − z_i) and
/// δw_ij = i m_l ι_ij δz_j − w_ij ι_ij (δz_j − δz_i), δz_j = e_l(θ_j):
/// i m_l ((ι∘Δx)E)_rl − ((ι∘w∘Δx)E)_rl + e_l(θ_i) Σ_j ι_ij w_ij Δx_ij, the
/// sums over j for all l at once: products with the basis E, which are
/// discrete Fourier sums ([`Grid::basis_sums`]).
fn moving_kernel_sums(
    grid: &Grid,
    reps: &[usize],
    inv: &DMatrix<C>,
    w: &DMatrix<C>,
    mult: &[f64],
    x: &[C],
) -> DMatrix<C> {
    let (m, n) = inv.shape();
    let zero = C::new(0.0, 0.0);
    let mut b_sum = vec![zero; m];
    // the rows of (ι∘Δx) and (ι∘w∘Δx), made as each row's FFT takes them
    let (pa, pb) = super::both(
        n >= super::TWO_CORES_FROM_POINTS,
        || {
            grid.basis_sums(m, |r, row| {
                moving_row(row, reps[r], x, |j| inv[(r, j)]);
            })
        },
        || {
            grid.basis_sums(m, |r, row| {
                b_sum[r] = moving_row(row, reps[r], x, |j| inv[(r, j)] * w[(r, j)]);
            })
        },
    );
    let i_unit = C::new(0.0, 1.0);
    DMatrix::from_fn(m, mult.len(), |r, l| {
        i_unit * mult[l] * pa[(r, l)] - pb[(r, l)] + grid.basis[l][reps[r]] * b_sum[r]
    })
}

/// `row` ← k_j (x_j − x_i) for j ≠ i and 0 at j = i, with the factor k_j
/// = `factor(j)`; returns the row's sum.
fn moving_row(row: &mut [C], i: usize, x: &[C], factor: impl Fn(usize) -> C) -> C {
    let zero = C::new(0.0, 0.0);
    let mut sum = zero;
    for (j, v) in row.iter_mut().enumerate() {
        *v = if j == i {
            zero
        } else {
            factor(j) * (x[j] - x[i])
        };
        sum += *v;
    }
    sum
}

/// Σ_j w_rj δψ_jl over the n points, from δψ at the orbits'
/// representatives (`d_psi_rep`, one row per representative). The contour
/// and every perturbation of its coefficients keep both reflections, so δψ
/// (like ψ = μ′/z′, μ even) at the images of a representative q under
/// θ → −θ, π − θ and π + θ is conj δψ_q, −conj δψ_q and −δψ_q. The sum is
/// then Σ_q (A_rq δψ_q + B_rq conj δψ_q), with A the signed weights w of the
/// images where δψ is ±δψ_q and B of those where it is ±conj δψ_q (each
/// distinct point once: at θ = 0, π/2, … images coincide), that is
/// Σ_q ((A + B)_rq Re δψ_q + i(A − B)_rq Im δψ_q): four real products of
/// (rows × representatives) by (representatives × unknowns), a quarter of
/// the work of the product over all points (nalgebra multiplies real
/// matrices with a blocked kernel, complex ones entry by entry).
fn orbit_product(w: &DMatrix<C>, d_psi_rep: &DMatrix<C>, reps: &[usize]) -> DMatrix<C> {
    let (rows, n) = w.shape();
    let half = n / 2;
    let m = reps.len();
    let mut plain = DMatrix::<C>::zeros(rows, m);
    let mut conjugated = DMatrix::<C>::zeros(rows, m);
    for (k, &q) in reps.iter().enumerate() {
        // (point, sign, conjugated)
        let images = [
            (q, 1.0, false),
            ((n - q) % n, 1.0, true),
            ((half + n - q) % n, -1.0, true),
            ((half + q) % n, -1.0, false),
        ];
        for (idx, &(j, sign, conj)) in images.iter().enumerate() {
            if images[..idx].iter().any(|im| im.0 == j) {
                continue;
            }
            let target = if conj { &mut conjugated } else { &mut plain };
            for r in 0..rows {
                target[(r, k)] += w[(r, j)] * sign;
            }
        }
    }
    let i_unit = C::new(0.0, 1.0);
    let p = &plain + &conjugated;
    let q = (&plain - &conjugated) * i_unit;
    let (x, y) = (d_psi_rep.map(|v| v.re), d_psi_rep.map(|v| v.im));
    let re = p.map(|v| v.re) * &x + q.map(|v| v.re) * &y;
    let im = p.map(|v| v.im) * &x + q.map(|v| v.im) * &y;
    re.zip_map(&im, C::new)
}

#[cfg(test)]
mod tests {
    use super::super::{fields, Truncation};
    use super::*;

    /// Every entry of the linearisation against central differences of
    /// [`fields`] (step 1e-6), on an undulated, non-elliptical contour
    /// at ρ = 0.7: ∂p̄/∂ν at every point and F̄ in every unknown agree to
    /// 1e-7 of the column's largest entry (measured: at most 2.6e-9, the
    /// central differences' own error); ∂p̄/∂ν and F̄ themselves agree with
    /// `fields` to 1e-12.
    #[test]
    fn the_linearisation_is_the_derivative_of_the_fields() {
        let conformal = Truncation {
            modes: 6,
            points: 64,
            arclength: 0,
        };
        let u = vec![2.1, 0.35, -0.04, 0.02, 0.01, -0.006, 0.003, 1.3];
        holds_against_central_differences(conformal, u);
        // the arclength representation: c_j of e^{3iθ}, e^{5iθ} too
        let arclength = Truncation {
            arclength: 2,
            ..conformal
        };
        let u = vec![
            2.1, 0.35, -0.04, 0.02, 0.01, -0.006, 0.003, 0.05, -0.012, 1.3,
        ];
        holds_against_central_differences(arclength, u);
    }

    fn holds_against_central_differences(t: Truncation, u: Vec<f64>) {
        let ex = Exact::new(0.7, t).unwrap();
        let nu = u.len();
        let u = DVector::from_vec(u);
        let lin = ex.linear(&u).unwrap();
        let at =
            |u: &DVector<f64>| fields(&ex.contour_of(u), &ex.gap, u[nu - 1], &ex.grid).unwrap();
        let f0 = at(&u);
        assert!((f0.force - lin.force).abs() < 1e-12 * f0.force.abs().max(1.0));
        for (a, b) in f0.normal_derivative.iter().zip(&lin.dn) {
            assert!((a - b).abs() < 1e-12, "{a} vs {b}");
        }
        for l in 0..nu {
            let h = 1e-6 * (1.0 + u[l].abs());
            let (mut up, mut um) = (u.clone(), u.clone());
            up[l] += h;
            um[l] -= h;
            let (fp, fm) = (at(&up), at(&um));
            let fd: Vec<f64> = (0..64)
                .map(|i| (fp.normal_derivative[i] - fm.normal_derivative[i]) / (2.0 * h))
                .collect();
            let scale = fd.iter().fold(1e-300_f64, |s, v| s.max(v.abs()));
            for (i, v) in fd.iter().enumerate() {
                let an = lin.d_dn[(i, l)];
                assert!(
                    (an - v).abs() <= 1e-7 * scale,
                    "d(dp/dnu)_{i}/du_{l}: {an} vs {v} (scale {scale:e})"
                );
            }
            let fd_force = (fp.force - fm.force) / (2.0 * h);
            assert!(
                (lin.d_force[l] - fd_force).abs() <= 1e-7 * fd_force.abs().max(1.0),
                "dF/du_{l}: {} vs {fd_force}",
                lin.d_force[l]
            );
        }
    }
}
