//! Linear stability of an exact state from the second variation of the
//! potential energy, mode by mode in the doubly symmetric class.
//!
//! In the units (17) the potential Π = U − Δγ|ω| of the paper's Section 2
//! (U = ½∫ p(δ − φ) dA, the energy stored in the layer) is, up to the
//! factor 2ΔγL², Π̄ = ∫ω |∇p̄|² dA − |ω|, where p̄ solves Δp̄ = f,
//! f = X²/2 + Y²/(2ρ) − δ̄, with p̄ = 0 on ∂ω only. Its shape derivative is
//! dΠ̄ = ∮ ((∂p̄/∂ν)² − 1) V ds (Hadamard), V the normal velocity of the
//! contour: it vanishes at the exact states, where ∂p̄/∂ν = 1. And
//! ∂Π̄/∂δ̄ = 2F̄ at fixed ω.
//!
//! The gradient of Π̄ in the contour coefficients (A, b₀..b_{N−1}) is this
//! shape derivative with V_k = Re(∂z/∂u_k · ν̄); the Hessian is its
//! derivative, from the linearisation of ∂p̄/∂ν (`exact::linear`). Under displacement control (δ̄ fixed) a
//! state is stable when the Hessian in the coefficients is positive
//! definite; under load control the potential is Π̄ − 2F̄δ̄ with δ̄ free,
//! and the Hessian is bordered by 2∂F̄/∂u and 2∂F̄/∂δ̄. The eigenproblem is
//! posed in the metric of the contour's normal motion, H v = λ M v with
//! M = ∮ V_k V_l ds (δ̄ weighted as a uniform motion): a congruence, so the
//! signs are the Hessian's, and the directions are orthogonal in how they
//! move the contour, each one undulation. Each negative eigenvalue is
//! reported with the contour mode its direction is made of, read from the
//! spectrum of its normal displacement in the arclength σ (e^{−2πinσ/P}, P
//! the perimeter): n = 0 the size (under load control also δ̄), n the
//! radius perturbed by cos nθ, wavelength P/n along the contour. The
//! directions are matched to distinct modes by their largest relative
//! amplitudes, largest first. Named by its largest coefficient instead, a
//! short undulation of an elongated contour in the conformal parameter had
//! been called n = 2 (ρ = 0.3), and in the coefficients' own metric the
//! directions mix neighbouring modes.
//!
//! At ρ = 1 the Hessian is diagonal in the modes with signs those of
//! ā²/4 + 1/ā − n/ā (see `tests/exact.rs`): modes with n > ā³/4 + 1 are
//! unstable. Short undulations of the contact line are unstable in this
//! thin-layer model, as in the fingering instability of thin confined
//! elastic films; the model holds only for wavelengths much longer than
//! the coating thickness h, so such modes are reported with their
//! wavelength, for comparison with h, not hidden.
//!
//! Each mode is marked resolved or not by a short-wave [`Cutoff`] (its
//! wavelength against 2π h/L, `crate::cutoff`), and the two verdicts count
//! only the resolved modes: [`Cutoff::default`] when the state is solved,
//! the user's thinness through [`ExactStability::under`].
//!
//! Owns: [`ExactStability`], [`UnstableMode`]. May use: `exact`, `error`, `cutoff`, nalgebra.

use super::{Exact, ExactState};
use crate::cutoff::{Cutoff, Eigen};
use crate::error::{Error, Result};
use nalgebra::{DMatrix, SymmetricEigen};
use serde::Serialize;

/// One unstable direction of the second variation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct UnstableMode {
    /// The contour mode the eigenvector is made of: the radius perturbed
    /// by cos nθ (n = 0: the size; under load control also δ̄).
    pub n: usize,
    /// The wavelength along the contour, its perimeter over n, in units
    /// of L (∞ for n = 0, null in JSON; 2πā/n on a circle).
    #[cfg_attr(feature = "schema", schemars(with = "Option<f64>"))]
    pub wavelength: f64,
    /// The eigenvalue of the second variation in the metric of the normal
    /// motion ∮ V² ds (per unit normal displacement; on the circle of
    /// radius ā, 2(ā³/4 + 1 − n)/ā): negative beyond the neutral band; in
    /// [`ExactStability::neutral_load`] and `neutral_displacement`, zero
    /// within it (either sign).
    pub eigenvalue: f64,
    /// Whether the wavelength is at least the cutoff's (the model resolves
    /// the mode and predicts a change of shape), or shorter (the
    /// thin-layer equation (2) does not hold there).
    pub resolved: bool,
}

/// Which modes of an exact state are unstable.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct ExactStability {
    /// Under displacement control (δ̄ fixed).
    pub displacement: Vec<UnstableMode>,
    /// Under load control (F̄ fixed, δ̄ free).
    pub load: Vec<UnstableMode>,
    /// The neutral directions under displacement control: eigenvalue zero
    /// within the neutral band (`crate::cutoff::Eigen`), a fold or
    /// bifurcation of the control (at ρ = 1 the circle's mode n where
    /// ā³ = 4(n − 1)). The verdicts do not count them.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub neutral_displacement: Vec<UnstableMode>,
    /// The same under load control (at the pull-off, the size).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub neutral_load: Vec<UnstableMode>,
    /// The wavelength of the shortest contour mode the state's series
    /// represents (its perimeter over that mode's n); none where the
    /// stability was not computed.
    pub shortest_wavelength: Option<f64>,
    /// The short-wave cutoff the verdicts count modes above.
    pub cutoff: Cutoff,
    /// No resolved mode is unstable under displacement control: `false`
    /// when one is; `true` when none is and the series reaches the cutoff
    /// (its shortest mode is not longer than the cutoff's wavelength);
    /// null (not settled) when none is but the series stops short of the
    /// cutoff, or the stability was not computed.
    pub stable_displacement: Option<bool>,
    /// The same under load control.
    pub stable_load: Option<bool>,
    /// The critical thinness under displacement control: the smallest h/L
    /// at which every contour mode (n ≥ 1) unstable under this control is
    /// shorter than the cutoff 2π h/L, so that (2) resolves none of them
    /// (its longest unstable mode's wavelength over 2π). Below it the model
    /// predicts a change of shape. Null where no contour mode is unstable;
    /// the size (n = 0) is in `displacement`, and no thinness stabilises it.
    pub critical_thinness_displacement: Option<f64>,
    /// The same under load control: with thinner coatings the state is
    /// unstable under load above the cutoff, so a contact unloaded through
    /// states stable above the cutoff does not come to it (docs/exact.md,
    /// "The short-wave cutoff").
    pub critical_thinness_load: Option<f64>,
}

impl Default for ExactStability {
    /// Not computed: no mode, no verdict.
    fn default() -> Self {
        ExactStability {
            displacement: Vec::new(),
            load: Vec::new(),
            neutral_displacement: Vec::new(),
            neutral_load: Vec::new(),
            shortest_wavelength: None,
            cutoff: Cutoff::default(),
            stable_displacement: None,
            stable_load: None,
            critical_thinness_displacement: None,
            critical_thinness_load: None,
        }
    }
}

impl ExactStability {
    /// The same modes judged under another cutoff (another thinness h/L).
    pub fn under(mut self, cutoff: Cutoff) -> ExactStability {
        for m in self
            .displacement
            .iter_mut()
            .chain(self.load.iter_mut())
            .chain(self.neutral_displacement.iter_mut())
            .chain(self.neutral_load.iter_mut())
        {
            m.resolved = cutoff.resolves(m.wavelength);
        }
        let reaches = self
            .shortest_wavelength
            .is_some_and(|w| w <= cutoff.wavelength);
        let verdict = |v: &[UnstableMode]| {
            if v.iter().any(|m| m.resolved) {
                Some(false)
            } else if reaches {
                Some(true)
            } else {
                None
            }
        };
        self.stable_displacement = verdict(&self.displacement);
        self.stable_load = verdict(&self.load);
        self.cutoff = cutoff;
        let critical = |v: &[UnstableMode]| {
            longest_contour_mode(v).map(|m| Cutoff::thinness_for(m.wavelength))
        };
        self.critical_thinness_displacement = critical(&self.displacement);
        self.critical_thinness_load = critical(&self.load);
        self
    }

    /// Why the state is doubtful under a control (load or displacement):
    /// the words of [`Cutoff::unstable_words`] where its verdict there is
    /// unstable above the cutoff; none where it is stable or not settled.
    pub(crate) fn doubt(&self, under_load: bool, a_bar: f64) -> Option<String> {
        let (modes, verdict) = if under_load {
            (&self.load, self.stable_load)
        } else {
            (&self.displacement, self.stable_displacement)
        };
        (verdict == Some(false)).then(|| {
            self.cutoff.unstable_words(
                under_load,
                modes.iter().filter(|m| m.resolved && m.n > 0).count(),
                modes.iter().any(|m| m.n == 0),
                longest_contour_mode(modes).map(|m| (m.n, m.wavelength)),
                a_bar,
            )
        })
    }
}

/// The longest contour mode (n ≥ 1) among `modes`: the first a thicker
/// coating leaves resolved.
fn longest_contour_mode(modes: &[UnstableMode]) -> Option<&UnstableMode> {
    modes
        .iter()
        .filter(|m| m.n > 0)
        .max_by(|a, b| a.wavelength.total_cmp(&b.wavelength))
}

impl Exact {
    /// The linear stability of `st` (a state of this problem's truncation).
    pub fn stability(&self, st: &ExactState) -> Result<ExactStability> {
        let m = self.truncation.coefficients();
        let mult = &self.grid.multipliers;
        let err = || Error::NoState("exact stability: singular boundary integral equation".into());
        let u = self.unknowns(st);
        let hess = self.bordered_hessian(&u).ok_or_else(err)?;
        let samples = st.contour.samples(&self.grid);
        let n = self.grid.len();
        let h = 2.0 * std::f64::consts::PI / n as f64;
        let perimeter: f64 = samples.dz.iter().map(|d| d.norm()).sum::<f64>() * h;
        let sym = |a: DMatrix<f64>| (&a + a.transpose()) * 0.5;
        // the arclength representation: the Hessian on the directions that
        // keep θ proportional to arclength (the null space Z of the gauge
        // rows' Jacobian; a reparametrisation does not move the contour)
        let restriction = if self.truncation.arclength == 0 {
            None
        } else {
            // the eigenvectors of GᵀG (m × m) with its m − P smallest
            // eigenvalues (zero where the P gauge rows are independent)
            let g = self.gauge_jacobian(&u).columns(0, m).into_owned();
            let gg = SymmetricEigen::new(g.transpose() * &g);
            let mut order: Vec<usize> = (0..m).collect();
            order.sort_by(|&a, &b| gg.eigenvalues[a].total_cmp(&gg.eigenvalues[b]));
            let keep = m - g.nrows();
            Some(DMatrix::from_fn(m, keep, |r, c| {
                gg.eigenvectors[(r, order[c])]
            }))
        };
        // Each direction is named by the contour mode its normal motion is
        // made of, measured along the contour itself: the normal
        // displacement V = Re(∂z/∂u · ν̄) of a direction, times the arc
        // element, expanded in e^{−2πi n σ/P} of the arclength σ (P the
        // perimeter). A coefficient's index names a wavelength only on a
        // near-circular contour: on an elongated one the conformal
        // parameter crowds its points onto the ends, and the largest
        // coefficient of a short undulation can be a long one's (at ρ = 0.3
        // a direction of eigenvalue −873 had been named n = 2).
        let i_unit = nalgebra::Complex::new(0.0, 1.0);
        let normal = DMatrix::from_fn(n, m, |i, k| {
            (self.grid.basis[k][i] * i_unit * samples.dz[i].conj()).re * h
        });
        let speed: Vec<f64> = samples.dz.iter().map(|d| d.norm()).collect();
        let metric = {
            let scaled = DMatrix::from_fn(n, m, |i, k| normal[(i, k)] / (speed[i] * h));
            normal.transpose() * scaled
        };
        let mut sigma = vec![0.0; n];
        for i in 1..n {
            sigma[i] = sigma[i - 1] + 0.5 * (speed[i - 1] + speed[i]) * h;
        }
        let n_max = mult
            .iter()
            .map(|&x| (x - 1.0).abs().round() as usize)
            .max()
            .unwrap_or(0);
        // the even modes of the doubly symmetric class, up to the shortest
        // the series holds and at most half the points
        let modes: Vec<usize> = (0..=n_max.min(n / 2)).step_by(2).collect();
        let fourier = DMatrix::from_fn(2 * modes.len(), n, |r, i| {
            let phase = 2.0 * std::f64::consts::PI * modes[r / 2] as f64 * sigma[i] / perimeter;
            if r % 2 == 0 {
                phase.cos()
            } else {
                phase.sin()
            }
        });
        // the amplitude of each mode in each direction (columns of `dirs`,
        // coefficients first; a δ̄ entry beyond them counts as the size)
        let spectrum = |dirs: &DMatrix<f64>| -> DMatrix<f64> {
            let v = &normal * dirs.rows(0, m);
            let f = &fourier * v;
            DMatrix::from_fn(modes.len(), dirs.ncols(), |r, c| {
                let amp = f[(2 * r, c)].hypot(f[(2 * r + 1, c)]);
                if modes[r] == 0 {
                    // a constant's cosine sum is twice a mode's; δ̄ moves the
                    // whole contact as the size does
                    let delta = if dirs.nrows() > m {
                        dirs[(m, c)].abs() * perimeter
                    } else {
                        0.0
                    };
                    0.5 * amp.max(delta)
                } else {
                    amp
                }
            })
        };
        // (none where the metric or its triangular solves are singular)
        let unstable = |a: DMatrix<f64>| -> Option<(Vec<UnstableMode>, Vec<UnstableMode>)> {
            // in the reduced coordinates [Z 0; 0 1], and back
            let lift = restriction.as_ref().map(|z| {
                let k = z.ncols();
                let extra = a.nrows() - m;
                let mut t = DMatrix::zeros(m + extra, k + extra);
                t.view_mut((0, 0), (m, k)).copy_from(z);
                for e in 0..extra {
                    t[(m + e, k + e)] = 1.0;
                }
                t
            });
            let dim = a.nrows();
            let t = lift.unwrap_or_else(|| DMatrix::identity(dim, dim));
            let a = t.transpose() * a * &t;
            // the eigenproblem in the metric of the normal motion, a v = λ M v
            // (M = ∮ V_k V_l ds, δ̄ weighted as a uniform motion, ∮ 1 ds):
            // the same signs (a congruence), and directions orthogonal in
            // their motion of the contour, so that each is one undulation
            // whose mode the spectrum below can name
            let mut metric_full = DMatrix::zeros(dim, dim);
            metric_full.view_mut((0, 0), (m, m)).copy_from(&metric);
            for e in m..dim {
                metric_full[(e, e)] = perimeter;
            }
            let chol = nalgebra::Cholesky::new(sym(t.transpose() * metric_full * &t));
            let in_metric = || -> Option<SymmetricEigen<f64, nalgebra::Dyn>> {
                let l = chol.as_ref()?.l();
                let x = l.solve_lower_triangular(&a)?;
                let b = l.solve_lower_triangular(&x.transpose())?;
                let mut e = SymmetricEigen::new(sym(b));
                e.eigenvectors = l.transpose().solve_upper_triangular(&e.eigenvectors)?;
                Some(e)
            };
            let mut eig = in_metric()?;
            eig.eigenvectors = &t * &eig.eigenvectors;
            let scale = eig.eigenvalues.amax().max(1e-300);
            // the unstable directions and the neutral ones, which take
            // their modes first (the neutral band, `crate::cutoff::Eigen`)
            let sign = |i: usize| Eigen::of(eig.eigenvalues[i], scale);
            let negative: Vec<usize> = (0..eig.eigenvalues.len())
                .filter(|&i| sign(i) != Eigen::Stable)
                .collect();
            // the modes' amplitudes in each direction, relative to the
            // direction's largest
            let dirs = DMatrix::from_fn(eig.eigenvectors.nrows(), negative.len(), |r, c| {
                eig.eigenvectors[(r, negative[c])]
            });
            let mut amp = spectrum(&dirs);
            for mut col in amp.column_iter_mut() {
                let top = col.max().max(1e-300);
                col /= top;
            }
            // each direction a mode of its own: (direction, mode) pairs
            // taken by decreasing relative amplitude, a pair kept when
            // neither its direction nor its mode is taken yet
            let mut pairs: Vec<(f64, usize, usize)> = (0..negative.len())
                .flat_map(|c| (0..modes.len()).map(move |r| (c, r)))
                .map(|(c, r)| (amp[(r, c)], c, r))
                .collect();
            pairs.sort_by(|x, y| y.0.total_cmp(&x.0));
            let mut label: Vec<Option<usize>> = vec![None; negative.len()];
            let mut taken = std::collections::HashSet::new();
            for (_, c, r) in pairs {
                if label[c].is_none() && !taken.contains(&r) {
                    label[c] = Some(modes[r]);
                    taken.insert(r);
                }
            }
            let (mut out, mut neutral): (Vec<(usize, UnstableMode)>, Vec<_>) = negative
                .iter()
                .enumerate()
                .map(|(c, &i)| {
                    // (more directions than modes: its largest amplitude)
                    let n = label[c].unwrap_or_else(|| modes[amp.column(c).imax()]);
                    (
                        i,
                        UnstableMode {
                            n,
                            wavelength: if n == 0 {
                                f64::INFINITY
                            } else {
                                perimeter / n as f64
                            },
                            eigenvalue: eig.eigenvalues[i],
                            resolved: true,
                        },
                    )
                })
                .partition(|&(i, _)| sign(i) == Eigen::Unstable);
            out.sort_by_key(|u| u.1.n);
            neutral.sort_by_key(|u| u.1.n);
            let strip = |v: Vec<(usize, UnstableMode)>| v.into_iter().map(|u| u.1).collect();
            Some((strip(out), strip(neutral)))
        };
        // the shortest mode the series holds: e^{imθ} is the radius's cos (m − 1)θ
        let n_max = n_max.max(1) as f64;
        // the two controls' eigenproblems, on both cores
        let (by_displacement, by_load) = super::both(
            n >= super::TWO_CORES_FROM_POINTS,
            || unstable(hess.view((0, 0), (m, m)).into_owned()),
            || unstable(hess.clone()),
        );
        let singular = || {
            Error::NoState(
                "exact stability: the metric of the contour's normal motion is singular".into(),
            )
        };
        let (displacement, neutral_displacement) = by_displacement.ok_or_else(singular)?;
        let (load, neutral_load) = by_load.ok_or_else(singular)?;
        Ok(ExactStability {
            displacement,
            load,
            neutral_displacement,
            neutral_load,
            shortest_wavelength: Some(perimeter / n_max),
            ..ExactStability::default()
        }
        .under(Cutoff::default()))
    }
}
