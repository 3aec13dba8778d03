//! Which contour mode a direction of a contour state's second variation
//! is: the eigenproblem in the metric of the contour's normal motion and
//! the naming of its directions by their spectrum along the contour,
//! written once for every contour representation (the exact solver's
//! series and the `conformal:K` maps).
//!
//! A representation gives, for each of its contour unknowns u_k, the
//! normal displacement V_k = Re(∂z/∂u_k · ν̄) it causes at n equally spaced
//! values of its parameter, and the speed |z′| there. The eigenproblem of
//! a Hessian H (the contour unknowns first, then any others, such as δ̄
//! under load control) is posed as H v = λ M v with M = ∮ V_k V_l ds, each
//! further unknown weighted as a uniform motion of the contour (∮ 1 ds):
//! a congruence, so the signs and every verdict's count are H's, and the
//! directions are orthogonal in how they move the contour, each one
//! undulation. Each is named by the spectrum of its normal displacement in
//! the arclength σ (e^{−2πinσ/P}, P the perimeter): n = 0 the size (or a
//! further unknown), n the radius perturbed by cos nθ, wavelength P/n.
//! The directions are matched to distinct modes by their largest relative
//! amplitudes, largest first.
//!
//! A coefficient's index names a wavelength only on a near-circular
//! contour: on an elongated one a parameter that crowds its points onto
//! the ends (the conformal map's) gives a short undulation a large
//! coefficient of a long mode. Named by its largest coefficient, a
//! direction of eigenvalue −873 at the exact pull-off at ρ = 0.3 had been
//! called n = 2, and `conformal:8` there had reported cos 4θ and no cos 8θ.
//!
//! Owns: [`NormalMotion`], [`NamedDirection`], the long-wave second route
//! ([`NormalMotion::long_wave`]). May use: `cutoff` (the
//! neutral band), nalgebra.

use crate::cutoff::Eigen;
use nalgebra::{Cholesky, DMatrix, DVector, Dyn, SymmetricEigen};

/// How closely the long-wave motions of [`NormalMotion::long_wave`] must
/// be represented (relative misfit in ∮ · ds) to be tried.
const LONG_WAVE_FIT: f64 = 1e-3;

/// One rung of [`NormalMotion::long_wave_ladder`].
#[derive(Clone, Copy, Debug)]
pub(crate) struct Rung {
    /// The shortest mode of the motions the variation is restricted to.
    pub(crate) n: usize,
    /// Its least eigenvalue (per unit normal displacement).
    pub(crate) least: f64,
    /// Its largest eigenvalue in magnitude (the neutral band's scale).
    pub(crate) scale: f64,
    /// The relative misfit of mode n's fit in ∮ · ds.
    #[cfg_attr(not(test), allow(dead_code))]
    pub(crate) miss: f64,
}

/// What the long-wave ladders say of the names of a Hessian's unstable
/// directions ([`NormalMotion::long_wave`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct LongWave {
    /// The size alone (with δ̄ under load control, the ladder's rung n = 0)
    /// is stable: no unstable direction is named n = 0.
    pub(crate) size_stable: bool,
    /// The largest mode n on whose motions (modes 0, 2, …, n) the variation
    /// under displacement control has no clearly negative direction: no
    /// unstable direction is named by a mode 2 … n (none where the size
    /// alone has one).
    pub(crate) stable_upto: Option<usize>,
    /// The first mode n ≥ 2 whose motions added give the variation under
    /// displacement control one: some unstable direction is named by a
    /// mode up to it (none where the ladder reaches no such rung).
    pub(crate) unstable_at: Option<usize>,
}

impl LongWave {
    /// The bounds under load control: the size's verdict from `load`, the
    /// ladder of the bordered Hessian, and the contour modes' from this,
    /// the ladder under displacement control. With δ̄ fixed the bordered
    /// Hessian is the other, so a negative direction on the long waves
    /// under displacement control is one under load too; but at a fold of
    /// the load (a pull-off) the size's zero, restricted to the long waves,
    /// takes a sign from the shorter unstable modes it mixes in (−0.055 at
    /// the pull-off at ρ = 0.1, −1.5e-3 with modes up to 4 at ρ = 0.5), so
    /// the load's own ladder names no contour mode.
    pub(crate) fn under_load(self, load: LongWave) -> LongWave {
        LongWave {
            size_stable: load.size_stable,
            ..self
        }
    }
}

/// One direction of negative or zero eigenvalue, with its contour mode.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct NamedDirection {
    /// The contour mode: the radius perturbed by cos nθ (0: the size).
    pub(crate) n: usize,
    /// The perimeter over n (∞ for n = 0).
    pub(crate) wavelength: f64,
    /// The eigenvalue per unit normal displacement (H v = λ M v).
    pub(crate) eigenvalue: f64,
}

/// The unstable and the neutral directions of one Hessian, each list in
/// increasing n (`crate::cutoff::Eigen`).
pub(crate) type Directions = (Vec<NamedDirection>, Vec<NamedDirection>);

/// How a representation's contour unknowns move its contour.
pub(crate) struct NormalMotion {
    /// V_k |z′| h at the n parameter points (n × m): each column the
    /// normal displacement of one unknown times the arc element.
    normal: DMatrix<f64>,
    /// M = ∮ V_k V_l ds (m × m).
    metric: DMatrix<f64>,
    /// The arc element |z′| h at the points.
    ds: Vec<f64>,
    perimeter: f64,
    /// The even modes of the doubly symmetric class the spectrum reads.
    modes: Vec<usize>,
    /// cos and sin of 2π n σ/P at the points, two rows per mode.
    fourier: DMatrix<f64>,
}

impl NormalMotion {
    /// From `normal_speed[(i, k)]` = V_k(t_i) |z′(t_i)| = Re(∂z/∂u_k ·
    /// conj(−i z′)) (z′ = dz/dt, the contour counter-clockwise) of the m
    /// contour unknowns and the speed |z′(t_i)| at n points t_i = 2πi/n,
    /// reading the modes up to `n_max` (the shortest the representation
    /// holds) and at most n/2.
    pub(crate) fn new(normal_speed: DMatrix<f64>, speed: &[f64], n_max: usize) -> NormalMotion {
        let n = speed.len();
        let h = 2.0 * std::f64::consts::PI / n as f64;
        let normal = normal_speed * h;
        // ∮ V_k V_l ds = Σ (V_k ds)(V_l ds) / ds
        let v = DMatrix::from_fn(n, normal.ncols(), |i, k| normal[(i, k)] / (speed[i] * h));
        let metric = normal.transpose() * v;
        let perimeter: f64 = speed.iter().sum::<f64>() * h;
        let mut sigma = vec![0.0; n];
        for i in 1..n {
            sigma[i] = sigma[i - 1] + 0.5 * (speed[i - 1] + speed[i]) * h;
        }
        let modes: Vec<usize> = (0..=n_max.min(n / 2)).step_by(2).collect();
        let fourier = DMatrix::from_fn(2 * modes.len(), n, |r, i| {
            let phase = 2.0 * std::f64::consts::PI * modes[r / 2] as f64 * sigma[i] / perimeter;
            if r % 2 == 0 {
                phase.cos()
            } else {
                phase.sin()
            }
        });
        NormalMotion {
            normal,
            metric,
            ds: speed.iter().map(|v| v * h).collect(),
            perimeter,
            modes,
            fourier,
        }
    }

    /// The contour's perimeter ∮ ds.
    pub(crate) fn perimeter(&self) -> f64 {
        self.perimeter
    }

    /// The unstable and neutral directions of `hessian` (the m contour
    /// unknowns first, then any further ones), restricted where given to
    /// the directions `restriction` spans (m × k, columns in the contour
    /// unknowns; the further unknowns are kept as they are). No unstable
    /// direction is named by the size where `long_wave` finds it stable
    /// alone, nor by a mode 2 … `long_wave.stable_upto`, and where no
    /// direction is named by a mode up to `long_wave.unstable_at` the one
    /// with the largest amplitude in those modes is named by it
    /// ([`NormalMotion::long_wave`]: on the motions of those modes the
    /// variation has a negative direction, on the shorter list none). So
    /// the longest mode named is the ladder's. None where the metric is
    /// singular.
    pub(crate) fn directions(
        &self,
        hessian: &DMatrix<f64>,
        restriction: Option<&DMatrix<f64>>,
        long_wave: LongWave,
    ) -> Option<Directions> {
        let LongWave {
            size_stable,
            stable_upto,
            unstable_at,
        } = long_wave;
        let m = self.metric.nrows();
        let dim = hessian.nrows();
        // in the reduced coordinates [Z 0; 0 1], and back
        let t = embedding(restriction, m, dim);
        let mut metric = DMatrix::zeros(dim, dim);
        metric.view_mut((0, 0), (m, m)).copy_from(&self.metric);
        for e in m..dim {
            metric[(e, e)] = self.perimeter;
        }
        let mut eig = eigen_in_metric(
            &(t.transpose() * hessian * &t),
            &(t.transpose() * metric * &t),
        )?;
        eig.eigenvectors = &t * &eig.eigenvectors;
        let scale = eig.eigenvalues.amax().max(1e-300);
        let sign = |i: usize| Eigen::of(eig.eigenvalues[i], scale);
        let negative: Vec<usize> = (0..eig.eigenvalues.len())
            .filter(|&i| sign(i) != Eigen::Stable)
            .collect();
        let dirs = DMatrix::from_fn(eig.eigenvectors.nrows(), negative.len(), |r, c| {
            eig.eigenvectors[(r, negative[c])]
        });
        let mut amp = self.spectrum(&dirs);
        for mut col in amp.column_iter_mut() {
            let top = col.max().max(1e-300);
            col /= top;
        }
        // each direction a mode of its own: (direction, mode) pairs taken
        // by decreasing relative amplitude, a pair kept when neither its
        // direction nor its mode is taken yet
        let allowed = |c: usize, r: usize| {
            let n = self.modes[r];
            let free = if n == 0 {
                !size_stable
            } else {
                stable_upto.is_none_or(|k| n > k)
            };
            free || sign(negative[c]) != Eigen::Unstable
        };
        let mut pairs: Vec<(f64, usize, usize)> = (0..negative.len())
            .flat_map(|c| (0..self.modes.len()).map(move |r| (c, r)))
            .filter(|&(c, r)| allowed(c, r))
            .map(|(c, r)| (amp[(r, c)], c, r))
            .collect();
        pairs.sort_by(|x, y| y.0.total_cmp(&x.0));
        let mut label: Vec<Option<usize>> = vec![None; negative.len()];
        let mut taken = vec![false; self.modes.len()];
        for (_, c, r) in pairs {
            if label[c].is_none() && !taken[r] {
                label[c] = Some(self.modes[r]);
                taken[r] = true;
            }
        }
        // the ladder's first unstable rung names a direction
        if let Some(k) = unstable_at {
            let unstable: Vec<usize> = (0..negative.len())
                .filter(|&c| sign(negative[c]) == Eigen::Unstable)
                .collect();
            let within = |c: usize| {
                (0..self.modes.len())
                    .filter(|&r| self.modes[r] <= k && allowed(c, r))
                    .map(|r| amp[(r, c)])
                    .fold(0.0, f64::max)
            };
            let named_within = unstable.iter().any(|&c| label[c].is_some_and(|n| n <= k));
            let widest = unstable
                .iter()
                .max_by(|&&a, &&b| within(a).total_cmp(&within(b)));
            if let (false, Some(&c)) = (named_within, widest) {
                label[c] = Some(k);
            }
        }
        let (mut unstable, mut neutral): (Vec<(usize, NamedDirection)>, Vec<_>) = negative
            .iter()
            .enumerate()
            .map(|(c, &i)| {
                // (more directions than modes: its largest amplitude)
                let n = label[c].unwrap_or_else(|| {
                    let best = (0..self.modes.len())
                        .filter(|&r| allowed(c, r))
                        .max_by(|&a, &b| amp[(a, c)].total_cmp(&amp[(b, c)]));
                    self.modes[best.unwrap_or(0)]
                });
                let wavelength = if n == 0 {
                    f64::INFINITY
                } else {
                    self.perimeter / n as f64
                };
                (
                    i,
                    NamedDirection {
                        n,
                        wavelength,
                        eigenvalue: eig.eigenvalues[i],
                    },
                )
            })
            .partition(|&(i, _)| sign(i) == Eigen::Unstable);
        unstable.sort_by_key(|u| u.1.n);
        neutral.sort_by_key(|u| u.1.n);
        let strip = |v: Vec<(usize, NamedDirection)>| v.into_iter().map(|u| u.1).collect();
        Some((strip(unstable), strip(neutral)))
    }

    /// The ladder's verdict on the names of `hessian`'s unstable
    /// directions (the contour unknowns first, then any further ones, such
    /// as δ̄ under load control, kept in every rung): its last stable rung,
    /// the largest even mode n such that the variation restricted to the
    /// motions made of the modes 0, 2, …, n has no clearly negative
    /// direction (none where already the size alone has one, or none is
    /// tried), its first unstable rung from n = 2 on, and whether its
    /// first rung, the size alone, is stable. Those motions
    /// are the coefficient directions that fit cos 2πjσ/P in ∮ · ds (least
    /// squares in the metric M, within `restriction`), tried while the fit
    /// misses by less than [`LONG_WAVE_FIT`]. This is the limit of a
    /// coating that makes every shorter undulation infinitely stiff: a
    /// second route to which modes a state is unstable to, independent of
    /// how its directions mix.
    pub(crate) fn long_wave(
        &self,
        hessian: &DMatrix<f64>,
        restriction: Option<&DMatrix<f64>>,
    ) -> LongWave {
        let ladder = self.long_wave_ladder(hessian, restriction);
        let unstable = |r: &Rung| Eigen::of(r.least, r.scale) == Eigen::Unstable;
        LongWave {
            size_stable: ladder
                .first()
                .is_some_and(|r| Eigen::of(r.least, r.scale) == Eigen::Stable),
            stable_upto: ladder
                .iter()
                .take_while(|r| !unstable(r))
                .last()
                .map(|r| r.n),
            unstable_at: ladder
                .last()
                .filter(|r| r.n >= 2 && unstable(r))
                .map(|r| r.n),
        }
    }

    /// The rungs of [`NormalMotion::long_wave`]: for n = 0, 2, 4, … the
    /// restricted variation's least eigenvalue and how far the fit of
    /// mode n misses, up to the first rung with a clearly negative
    /// eigenvalue or the last the fit and the metric allow.
    pub(crate) fn long_wave_ladder(
        &self,
        h_cc: &DMatrix<f64>,
        restriction: Option<&DMatrix<f64>>,
    ) -> Vec<Rung> {
        let m = self.metric.nrows();
        // the further unknowns (δ̄ under load control), kept in every rung
        // and weighted as a uniform motion of the contour (∮ 1 ds)
        let extra = h_cc.nrows() - m;
        let mut metric = DMatrix::zeros(m + extra, m + extra);
        metric.view_mut((0, 0), (m, m)).copy_from(&self.metric);
        for e in m..m + extra {
            metric[(e, e)] = self.perimeter;
        }
        let further: Vec<DVector<f64>> = (m..m + extra)
            .map(|e| DVector::from_fn(m + extra, |r, _| if r == e { 1.0 } else { 0.0 }))
            .collect();
        let z = restriction
            .cloned()
            .unwrap_or_else(|| DMatrix::identity(m, m));
        let mut rungs = Vec::new();
        let Some(mz) = Cholesky::new(symmetric(&(z.transpose() * &self.metric * &z))) else {
            return rungs;
        };
        let mut cols: Vec<DVector<f64>> = Vec::new();
        for (r, &n) in self.modes.iter().enumerate() {
            // cos 2πnσ/P at the points, its fit and how far it misses
            let f = DVector::from_fn(self.ds.len(), |i, _| self.fourier[(2 * r, i)]);
            let norm2: f64 = f.iter().zip(&self.ds).map(|(v, d)| v * v * d).sum();
            // (matrix–vector products only: Zᵀ (V ds)ᵀ f, and V ds (Z y))
            let b = z.tr_mul(&self.normal.tr_mul(&f));
            let y = mz.solve(&b);
            let zy = &z * y;
            // V of the fit at the points: (V ds) Z y / ds
            let fit = &self.normal * &zy;
            let miss = (0..f.len())
                .map(|i| (fit[i] / self.ds[i] - f[i]).powi(2) * self.ds[i])
                .sum::<f64>()
                .sqrt()
                / norm2.sqrt();
            if miss > LONG_WAVE_FIT {
                break;
            }
            cols.push(zy);
            let padded: Vec<DVector<f64>> = cols
                .iter()
                .map(|c| DVector::from_fn(m + extra, |r, _| if r < m { c[r] } else { 0.0 }))
                .chain(further.iter().cloned())
                .collect();
            let u = DMatrix::from_columns(&padded);
            let Some(eig) = eigen_in_metric(
                &(u.transpose() * h_cc * &u),
                &(u.transpose() * &metric * &u),
            ) else {
                break;
            };
            let e = eig.eigenvalues;
            let rung = Rung {
                n,
                least: e.min(),
                scale: e.amax().max(1e-300),
                miss,
            };
            let unstable = Eigen::of(rung.least, rung.scale) == Eigen::Unstable;
            rungs.push(rung);
            if unstable {
                break;
            }
        }
        rungs
    }

    /// The contour mode one direction (contour unknowns first, then any
    /// further ones) is made of: the largest amplitude of its normal
    /// motion's spectrum; among n ≥ 2 only with `shape_only` (the size and
    /// any further unknown moving with the shape are not its name). None
    /// where the representation reads no such mode.
    pub(crate) fn mode_of(&self, direction: &DVector<f64>, shape_only: bool) -> Option<usize> {
        let amp = self.spectrum(&DMatrix::from_column_slice(
            direction.len(),
            1,
            direction.as_slice(),
        ));
        (0..self.modes.len())
            .filter(|&r| !shape_only || self.modes[r] > 0)
            .max_by(|&a, &b| amp[(a, 0)].total_cmp(&amp[(b, 0)]))
            .map(|r| self.modes[r])
    }

    /// The amplitude of each mode in each direction (columns of `dirs`,
    /// contour unknowns first; an entry beyond them counts as the size).
    fn spectrum(&self, dirs: &DMatrix<f64>) -> DMatrix<f64> {
        let m = self.metric.nrows();
        let v = &self.normal * dirs.rows(0, m);
        let f = &self.fourier * v;
        DMatrix::from_fn(self.modes.len(), dirs.ncols(), |r, c| {
            let amp = f[(2 * r, c)].hypot(f[(2 * r + 1, c)]);
            if self.modes[r] == 0 {
                // a constant's cosine sum is twice a mode's; a further
                // unknown (δ̄) moves the whole contact as the size does
                let extra = (m..dirs.nrows())
                    .map(|e| dirs[(e, c)].abs() * self.perimeter)
                    .fold(0.0, f64::max);
                0.5 * amp.max(extra)
            } else {
                amp
            }
        })
    }
}

/// (a + aᵀ)/2.
fn symmetric(a: &DMatrix<f64>) -> DMatrix<f64> {
    (a + a.transpose()) * 0.5
}

/// The eigenproblem a v = λ m v (m positive definite): by the Cholesky
/// factor L of m, the eigenvalues of L⁻¹ a L⁻ᵀ and the vectors L⁻ᵀ w. None
/// where m is not positive definite or a triangular solve fails.
fn eigen_in_metric(a: &DMatrix<f64>, m: &DMatrix<f64>) -> Option<SymmetricEigen<f64, Dyn>> {
    let l = Cholesky::new(symmetric(m))?.l();
    let x = l.solve_lower_triangular(&symmetric(a))?;
    let b = l.solve_lower_triangular(&x.transpose())?;
    let mut e = SymmetricEigen::new(symmetric(&b));
    e.eigenvectors = l.transpose().solve_upper_triangular(&e.eigenvectors)?;
    Some(e)
}

/// The embedding T = [Z 0; 0 1] of the reduced coordinates (the columns
/// of `restriction` Z over the first `m` unknowns, the further ones kept)
/// into all `dim`; the identity without a restriction.
fn embedding(restriction: Option<&DMatrix<f64>>, m: usize, dim: usize) -> DMatrix<f64> {
    match restriction {
        Some(z) => {
            let k = z.ncols();
            let extra = dim - m;
            let mut t = DMatrix::zeros(m + extra, k + extra);
            t.view_mut((0, 0), (m, k)).copy_from(z);
            for e in 0..extra {
                t[(m + e, k + e)] = 1.0;
            }
            t
        }
        None => DMatrix::identity(dim, dim),
    }
}
