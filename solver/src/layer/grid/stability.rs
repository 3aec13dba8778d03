//! The stability of a grid state under displacement control, from the real
//! kernel (issue 71, item 3): no short-wave cutoff is imposed, the layer's
//! own stiffness decides.
//!
//! A state at approach δ̄ is a stationary point of the energy
//! ½(g − g₀)ᵀA⁻¹(g − g₀) + ΣU(g) over the cells' gaps (g₀ = φ̄ − δ̄, A the
//! pair's compliance, U the law's potential, p = −U′). Its second variation,
//! A⁻¹ − diag(p′), is positive definite exactly when every eigenvalue of the
//! Newton matrix J = I − A diag(p′) is positive: J is A times it, and similar
//! to the symmetric I − A^½ diag(p′) A^½, so its eigenvalues are real. The
//! cells in contact (p′ ≪ 0) give eigenvalues far above 1, the cells far out
//! (p′ ≈ 0) eigenvalues near 1; what can go through zero are the modes that
//! move the edge, and those are the eigenvalues of J nearest zero. They are
//! found by Arnoldi's method on J⁻¹ (each product one solve of the Newton
//! step, `jacobian_solve`): its largest Ritz values, with their vectors,
//! each checked by its own residual ‖Jx − λx‖ before it is reported.
//!
//! Under load control a state is stable when it is stable under
//! displacement control and dF̄/dδ̄ > 0 (the Schur complement of the
//! bordered second variation): the pull-off under load control, where
//! dF̄/dδ̄ = 0, is reached by unloading when every state above it on the
//! path has all its eigenvalues positive.
//!
//! Each eigenvector (a change of the cells' gaps) is told by its angular
//! content about the centre, θ = atan2(Y/b, X/a) with the state's half
//! widths: its share in each cos nθ, sin nθ.
//!
//! Owns: `Mode`, `least_modes`. May use: its parent `grid` (the sheet, its
//! state, the Newton step's solve), `error`.

use super::{jacobian_solve, Compliance, Sheet, SheetState};
use crate::error::{rounded, Error, Result};
use nalgebra::{DMatrix, DVector};

/// One eigenvalue of the Newton matrix J of a state, nearest zero.
#[derive(Clone, Debug)]
pub(crate) struct Mode {
    /// The eigenvalue λ of J: positive where the state is stable to this
    /// mode under displacement control.
    pub(crate) eigenvalue: f64,
    /// The angular order n that carries most of the eigenvector.
    pub(crate) n: usize,
    /// That order's share of the eigenvector (0 to 1).
    pub(crate) share: f64,
    /// Whether the mode is odd in Y (sin nθ) rather than even (cos nθ).
    pub(crate) odd: bool,
    /// ‖Jx − λx‖/‖x‖, the eigenpair's residual.
    pub(crate) residual: f64,
}

/// The largest angular order told apart.
const ORDERS: usize = 16;

/// The relative residual a solve with J must reach.
const SOLVE_TOL: f64 = 1e-11;

/// The largest residual ‖Jx − λx‖/‖x‖ of an eigenpair that is reported.
pub(crate) const CONVERGED: f64 = 1e-6;

/// The `count` eigenvalues of the Newton matrix of `state` (solved on
/// `sheet`) nearest zero, smallest first, from `krylov` steps of Arnoldi's
/// method on J⁻¹ (`krylov` at most the number of cells, and more than
/// `count`); an error where a solve fails or fewer than `count` of them
/// converge to [`CONVERGED`].
pub(crate) fn least_modes(
    sheet: &Sheet,
    state: &SheetState,
    count: usize,
    krylov: usize,
) -> Result<Vec<Mode>> {
    let cells = state.gap.len();
    let m = krylov.min(cells);
    if count == 0 || count >= m {
        return Err(Error::Usage(format!(
            "least_modes: {count} modes from {m} Krylov steps"
        )));
    }
    let law = sheet.law;
    let dp: Vec<f64> = state.gap.iter().map(|&g| law.pressure(g).1).collect();
    let mut products = 0;
    let mut solve =
        |b: &[f64]| jacobian_solve(&sheet.kernel, law, &dp, b, SOLVE_TOL, &mut products);
    // a start with a part in every symmetry class (a fixed pseudo-random
    // vector, so that the result is the same run to run)
    let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
    let start = DVector::from_fn(cells, |_, _| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    });
    let mut basis: Vec<DVector<f64>> = vec![start.normalize()];
    let mut h = DMatrix::<f64>::zeros(m + 1, m);
    for k in 0..m {
        let mut w = DVector::from_vec(solve(basis[k].as_slice())?);
        // modified Gram–Schmidt, twice
        for _ in 0..2 {
            for (j, v) in basis.iter().enumerate() {
                let c = v.dot(&w);
                h[(j, k)] += c;
                w.axpy(-c, v, 1.0);
            }
        }
        let norm = w.norm();
        h[(k + 1, k)] = norm;
        if norm < 1e-14 {
            break;
        }
        basis.push(w / norm);
    }
    let steps = basis.len().min(m);
    let hm = h.view((0, 0), (steps, steps)).into_owned();
    // the Ritz values of J⁻¹, largest in size first (J's nearest zero); J's
    // eigenvalues are real, so a complex one among the first `count` is one
    // not yet converged, and none after it may be reported as the least
    let mut all: Vec<nalgebra::Complex<f64>> = hm.complex_eigenvalues().iter().copied().collect();
    all.sort_by(|a, b| b.norm().total_cmp(&a.norm()));
    if let Some(z) = all
        .iter()
        .take(count)
        .find(|z| z.im.abs() > 1e-8 * z.norm())
    {
        return Err(Error::Unresolved {
            what: format!(
                "the grid state's least eigenvalues at delta_bar = {}: a complex Ritz value among them after {steps} Arnoldi steps (1/lambda = {} with imaginary part {}), not converged",
                rounded(state.delta_bar),
                rounded(z.re),
                rounded(z.im)
            ),
            residual: z.im.abs() / z.norm(),
        });
    }
    let ritz: Vec<f64> = all.iter().map(|z| z.re).collect();
    let mut modes: Vec<Mode> = Vec::new();
    for theta in ritz {
        if modes.len() == count {
            break;
        }
        let lambda = 1.0 / theta;
        // a repeated Ritz value (at ρ = 1, cos nθ and sin nθ) is one
        // eigenvalue of two vectors: the second by inverse iteration from
        // a start orthogonal to the first
        let repeats = modes
            .iter()
            .filter(|md| (md.eigenvalue - lambda).abs() <= 1e-7 * lambda.abs().max(1e-3))
            .count();
        let y = ritz_vector(&hm, theta, repeats)?;
        let x = basis[..steps]
            .iter()
            .zip(y.iter())
            .fold(DVector::zeros(cells), |acc, (v, c)| acc + v * *c);
        let residual = {
            let mut ax = vec![0.0; cells];
            let scaled: Vec<f64> = x.iter().zip(&dp).map(|(x, d)| x * d).collect();
            sheet.kernel.apply(&scaled, &mut ax);
            let jx = &x - DVector::from_vec(ax);
            (jx - &x * lambda).norm() / x.norm()
        };
        let (n, share, odd) = angular_order(sheet, state, &x);
        modes.push(Mode {
            eigenvalue: lambda,
            n,
            share,
            odd,
            residual,
        });
    }
    let unconverged: Vec<&Mode> = modes.iter().filter(|md| md.residual > CONVERGED).collect();
    if modes.len() < count || !unconverged.is_empty() {
        return Err(Error::Unresolved {
            what: format!(
                "the grid state's least eigenvalues at delta_bar = {}: {} of {count} converge in {steps} Arnoldi steps (the worst residual {})",
                rounded(state.delta_bar),
                modes.len() - unconverged.len(),
                rounded(unconverged.iter().map(|md| md.residual).fold(0.0, f64::max))
            ),
            residual: unconverged.iter().map(|md| md.residual).fold(0.0, f64::max),
        });
    }
    modes.sort_by(|a, b| a.eigenvalue.total_cmp(&b.eigenvalue));
    Ok(modes)
}

/// The eigenvector of the Hessenberg matrix `hm` for its eigenvalue
/// `theta`, by inverse iteration: the `which`-th of a repeated one (each
/// start made orthogonal to the vectors before it).
fn ritz_vector(hm: &DMatrix<f64>, theta: f64, which: usize) -> Result<DVector<f64>> {
    let k = hm.nrows();
    let shifted = hm - DMatrix::identity(k, k) * (theta * (1.0 + 1e-12));
    let lu = shifted.lu();
    let mut found: Vec<DVector<f64>> = Vec::new();
    for j in 0..=which {
        let mut y = DVector::from_fn(k, |i, _| 1.0 + ((i * 7 + j * 13) % 11) as f64 / 11.0);
        for _ in 0..3 {
            for f in &found {
                let c = f.dot(&y);
                y.axpy(-c, f, 1.0);
            }
            y = lu
                .solve(&y)
                .ok_or_else(|| Error::NoState("the Ritz vector's system is singular".into()))?
                .normalize();
        }
        found.push(y);
    }
    Ok(found.pop().expect("one at least"))
}

/// The angular order n ≤ [`ORDERS`] that carries most of the field `x`,
/// with its share and whether it is odd in Y: the field sampled on the
/// ring through its largest cell, (X, Y) = r(a cos θ, b sin θ) with the
/// state's half widths a, b (where the grid holds them), at [`RING`]
/// angles by bilinear interpolation, and its Fourier coefficients in θ.
fn angular_order(sheet: &Sheet, state: &SheetState, x: &DVector<f64>) -> (usize, f64, bool) {
    let n = sheet.n;
    let (a, b) = match state.half_widths {
        (Some(a), Some(b)) => (a, b),
        _ => (1.0, 1.0),
    };
    let (peak, _) = x.iamax_full();
    let (xp, yp) = (sheet.centre(peak / n), sheet.centre(peak % n));
    let r = ((xp / a).powi(2) + (yp / b).powi(2))
        .sqrt()
        .max(0.5 * sheet.dx / a.min(b));
    // bilinear between the cells' centres
    let at = |px: f64, py: f64| -> f64 {
        let index = |c: f64| {
            let t = (c / sheet.dx + 0.5 * n as f64 - 0.5).clamp(0.0, (n - 1) as f64);
            let i = (t.floor() as usize).min(n - 2);
            (i, t - i as f64)
        };
        let ((i, u), (j, w)) = (index(px), index(py));
        let v = |i: usize, j: usize| x[i * n + j];
        (1.0 - u) * ((1.0 - w) * v(i, j) + w * v(i, j + 1))
            + u * ((1.0 - w) * v(i + 1, j) + w * v(i + 1, j + 1))
    };
    let samples: Vec<(f64, f64)> = (0..RING)
        .map(|k| {
            let theta = 2.0 * std::f64::consts::PI * k as f64 / RING as f64;
            (theta, at(r * a * theta.cos(), r * b * theta.sin()))
        })
        .collect();
    let mut best = (0, 0.0, false);
    let mut total = 0.0;
    for order in 0..=ORDERS {
        let (c, s) = samples.iter().fold((0.0, 0.0), |(c, s), (th, v)| {
            let o = order as f64 * th;
            (c + v * o.cos(), s + v * o.sin())
        });
        let weight = if order == 0 { 0.5 } else { 1.0 };
        for (part, odd) in [(weight * c * c, false), (s * s, true)] {
            total += part;
            if part > best.1 {
                best = (order, part, odd);
            }
        }
    }
    (best.0, best.1 / total.max(1e-300), best.2)
}

/// The angles at which a mode is sampled to tell its order.
const RING: usize = 64;

#[cfg(test)]
mod tests {
    use super::super::tests::{coarse, rungs_of};
    use super::*;
    use crate::layer::Layers;

    /// On a grid small enough to hold J whole, the eigenvalues Arnoldi
    /// finds nearest zero are those of J, computed apart in its symmetric
    /// form I − A^½ diag(p′) A^½ (A whole, a column per product); at ρ = 1
    /// the orders n ≥ 1 come in equal pairs (cos nθ and sin nθ).
    #[test]
    fn the_least_eigenvalues_are_those_of_the_whole_newton_matrix() {
        let n = 20;
        let (sheet, a) = coarse(1.0, 1.0, n);
        let state = sheet.cold_state(0.1 * a * a).unwrap();
        let cells = n * n;
        let dp: Vec<f64> = state.gap.iter().map(|&g| sheet.law.pressure(g).1).collect();
        let mut whole = DMatrix::<f64>::zeros(cells, cells);
        let mut col = vec![0.0; cells];
        for c in 0..cells {
            let mut e = vec![0.0; cells];
            e[c] = 1.0;
            sheet.kernel.apply(&e, &mut col);
            whole.set_column(c, &DVector::from_column_slice(&col));
        }
        // (the FFT's product is symmetric to round-off)
        let whole = (&whole + whole.transpose()) * 0.5;
        let eig = whole.symmetric_eigen();
        assert!(eig.eigenvalues.min() > 0.0);
        let root = &eig.eigenvectors
            * DMatrix::from_diagonal(&eig.eigenvalues.map(f64::sqrt))
            * eig.eigenvectors.transpose();
        let symmetric = DMatrix::identity(cells, cells)
            - &root * DMatrix::from_diagonal(&DVector::from_column_slice(&dp)) * &root;
        let mut all: Vec<f64> = symmetric
            .symmetric_eigen()
            .eigenvalues
            .iter()
            .copied()
            .collect();
        all.sort_by(|x, y| x.abs().total_cmp(&y.abs()));
        let found = least_modes(&sheet, &state, 4, 80).unwrap();
        let mut nearest: Vec<f64> = all[..4].to_vec();
        nearest.sort_by(f64::total_cmp);
        for (f, want) in found.iter().zip(&nearest) {
            assert!(
                (f.eigenvalue - want).abs() < 1e-8 * want.abs(),
                "{} against {want} ({nearest:?})",
                f.eigenvalue
            );
            assert!(f.residual < CONVERGED);
        }
        // (here n = 1 is the pair: 0.33656 twice)
        let pairs: Vec<_> = found
            .windows(2)
            .filter(|pair| pair[0].n == pair[1].n && pair[0].n >= 1)
            .collect();
        assert!(!pairs.is_empty(), "{found:?}");
        for pair in pairs {
            assert!((pair[0].eigenvalue / pair[1].eigenvalue - 1.0).abs() < 1e-7);
        }
    }

    /// At the pull-off under displacement control the branch folds in δ̄:
    /// there the least eigenvalue is the axisymmetric mode's (n = 0, at
    /// ρ = 1), and it vanishes as the square root of the distance to the
    /// fold, so λ² is linear in δ̄ near it, and its root is where Newton's
    /// walk down in δ̄ stops.
    #[test]
    fn the_least_eigenvalue_vanishes_at_the_fold_in_the_approach() {
        use super::super::Sheet as S;
        let (sheet, a) = coarse(1.0, 1.0, 40);
        let mut st = sheet.cold_state(0.0).unwrap();
        // down in δ̄ in steps halved where Newton fails or lands off the
        // branch (the force jumps: below the fold Newton can find the
        // bodies apart), to 1e-6 a²
        let mut h = 0.05 * a * a;
        let mut last = vec![st.clone()];
        while h > 1e-6 * a * a && last.len() < 2000 {
            let d = st.delta_bar - h;
            match sheet.state(d, &S::predict(&st, d)) {
                Ok(s) if (s.force_bar - st.force_bar).abs() < 0.05 * st.force_bar.abs() => {
                    st = s;
                    last.push(st.clone());
                }
                _ => h *= 0.5,
            }
        }
        assert!(last.len() < 2000);
        let fold = st.delta_bar;
        // three states at about 4e-3, 1e-3 and 2.5e-4 a² above the fold
        let near: Vec<&SheetState> = [4e-3, 1e-3, 2.5e-4]
            .iter()
            .map(|off| {
                last.iter()
                    .min_by(|x, y| {
                        let f = |s: &SheetState| (s.delta_bar - fold - off * a * a).abs();
                        f(x).total_cmp(&f(y))
                    })
                    .unwrap()
            })
            .collect();
        let least: Vec<Mode> = near
            .iter()
            .map(|s| least_modes(&sheet, s, 2, 60).unwrap().remove(0))
            .collect();
        for (s, m) in near.iter().zip(&least) {
            assert_eq!((m.n, m.odd), (0, false), "{} {m:?}", s.delta_bar);
            assert!(m.eigenvalue > 0.0);
        }
        // λ² linear in δ̄ near the fold (λ vanishes as a square root: were
        // it linear in δ̄, the slope of λ² would fall with the distance,
        // fivefold between these pairs); its root through the nearer two is the fold,
        // just beyond where the walk stopped (Newton's reach shrinks at a
        // fold: 2.6e-5 a² short of it here), closer than the nearest state
        let l: Vec<f64> = least.iter().map(|m| m.eigenvalue.powi(2)).collect();
        let d: Vec<f64> = near.iter().map(|s| s.delta_bar).collect();
        let (outer, inner) = ((l[0] - l[1]) / (d[0] - d[1]), (l[1] - l[2]) / (d[1] - d[2]));
        assert!(
            outer > 0.0 && (0.5..2.0).contains(&(inner / outer)),
            "slopes of the square {outer}, {inner}"
        );
        let root = d[2] - l[2] / inner;
        assert!(
            root < fold && fold - root < 2.5e-4 * a * a,
            "the root {root} against the walk's end {fold}"
        );
    }

    /// The least eigenvalues along the path of a contact unloaded under
    /// displacement control, on each rung's grid: from a loaded state down
    /// through the pull-off under load control towards the one under
    /// displacement control (THINJKR_STAB_DOWN=0: not below the pull-off
    /// under load control). THINJKR_STAB_THIN (h/L, default 0.73),
    /// THINJKR_STAB_RHO (default 1), THINJKR_STAB_RUNGS (default 0.2:4),
    /// THINJKR_STAB_COUNT and THINJKR_STAB_KRYLOV (the eigenvalues asked
    /// and Arnoldi's steps, default 4 and 100), THINJKR_STAB_UP and
    /// THINJKR_STAB_UPS (the loaded states, default 4 at every 0.1 a²),
    /// THINJKR_STAB_KEEP (below the pull-off, every how many states; 4).
    #[test]
    #[ignore = "exploration: the least eigenvalues along the unloading path (a minute as it stands; the slow tier runs it)"]
    fn explore_path() {
        use super::super::{pull_off_ladder, Sheet as S};
        let var = |k: &str, d: &str| std::env::var(k).unwrap_or(d.into());
        let thin: f64 = var("THINJKR_STAB_THIN", "0.73").parse().unwrap();
        let rho: f64 = var("THINJKR_STAB_RHO", "1").parse().unwrap();
        let rungs = rungs_of(&var("THINJKR_STAB_RUNGS", "0.2:4"));
        let layers = Layers::equal(thin, 0.5).unwrap();
        let a = layers.radius_guess();
        let ladder = pull_off_ladder(&layers, rho, &rungs, &mut |_| {}).unwrap();
        for r in &ladder {
            let sheet = r.sheet(&layers, rho);
            let po = sheet.state(r.state.delta_bar, &r.state.gap).unwrap();
            println!(
                "h/L {thin} rho {rho} eps {} n {}: pull-off F {:.6} at delta {:.6}",
                r.eps, r.n, po.force_bar, po.delta_bar
            );
            let mut path = vec![];
            // up: loaded states, every `up` a²; down: towards the pull-off
            // in δ̄, in steps of `down` a² halved where Newton fails, the
            // last state kept of every `keep`
            let up: f64 = var("THINJKR_STAB_UP", "0.1").parse().unwrap();
            let ups: usize = var("THINJKR_STAB_UPS", "4").parse().unwrap();
            let keep: usize = var("THINJKR_STAB_KEEP", "4").parse().unwrap();
            let mut prev = po.clone();
            for k in 1..=ups {
                let d = po.delta_bar + k as f64 * up * a * a;
                prev = sheet.state(d, &S::predict(&prev, d)).unwrap();
                path.push(prev.clone());
            }
            let (mut prev, mut h, mut k) = (po.clone(), 0.02 * a * a, 0);
            let down = var("THINJKR_STAB_DOWN", "1") != "0";
            while down && h > 1e-5 * a * a && k < 2000 {
                let d = prev.delta_bar - h;
                match sheet.state(d, &S::predict(&prev, d)) {
                    // (not a jump off the branch: below its fold Newton can
                    // find the bodies apart)
                    Ok(s) if (s.force_bar - prev.force_bar).abs() < 0.05 * prev.force_bar.abs() => {
                        k += 1;
                        if k % keep == 0 {
                            path.push(s.clone());
                        }
                        prev = s;
                    }
                    _ => h *= 0.5,
                }
            }
            path.push(prev);
            path.push(po);
            path.sort_by(|x, y| y.delta_bar.total_cmp(&x.delta_bar));
            path.dedup_by(|x, y| x.delta_bar == y.delta_bar);
            let count: usize = var("THINJKR_STAB_COUNT", "4").parse().unwrap();
            let krylov: usize = var("THINJKR_STAB_KRYLOV", "100").parse().unwrap();
            for s in &path {
                let t = std::time::Instant::now();
                match least_modes(&sheet, s, count, krylov) {
                    Ok(modes) => println!(
                        "  delta {:.5} F {:.5} dF/dd {:+.3e}: {} ({:.1} s)",
                        s.delta_bar,
                        s.force_bar,
                        s.force_slope,
                        modes
                            .iter()
                            .map(|m| format!(
                                "{:+.4e} n{}{} {:.2}",
                                m.eigenvalue,
                                m.n,
                                if m.odd { "s" } else { "c" },
                                m.share
                            ))
                            .collect::<Vec<_>>()
                            .join(", "),
                        t.elapsed().as_secs_f64()
                    ),
                    Err(e) => println!("  delta {:.5} F {:.5}: {e}", s.delta_bar, s.force_bar),
                }
            }
        }
    }
}
