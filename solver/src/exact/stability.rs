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
//! and the Hessian is bordered by 2∂F̄/∂u and 2∂F̄/∂δ̄. Each negative
//! eigenvalue is reported with the contour mode its eigenvector is made
//! of: n = 0 for A (the size; under load control also δ̄), n = 2j + 2 for
//! b_j (the radius perturbed by cos nθ, wavelength 2πā/n along the
//! contour). The directions are matched to distinct modes by their largest
//! components, largest first: near the series' shortest modes, where the
//! eigenvectors of an elongated contour mix neighbouring modes, the
//! largest component alone can name one mode for two directions.
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
    /// The eigenvalue: negative beyond the neutral band; in
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
        self
    }
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
        let unstable = |a: DMatrix<f64>,
                        with_delta: bool|
         -> (Vec<UnstableMode>, Vec<UnstableMode>) {
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
            let a = match &lift {
                Some(t) => t.transpose() * a * t,
                None => a,
            };
            let mut eig = SymmetricEigen::new(sym(a));
            if let Some(t) = &lift {
                eig.eigenvectors = t * &eig.eigenvectors;
            }
            let scale = eig.eigenvalues.amax().max(1e-300);
            // the unstable directions and the neutral ones, which take
            // their modes first (the neutral band, `crate::cutoff::Eigen`)
            let sign = |i: usize| Eigen::of(eig.eigenvalues[i], scale);
            let negative: Vec<usize> = (0..eig.eigenvalues.len())
                .filter(|&i| sign(i) != Eigen::Stable)
                .collect();
            // the mode of the component k of an eigenvector
            let mode_of = |k: usize| {
                if k == 0 || (with_delta && k == m) {
                    0
                } else {
                    // e^{i m θ} perturbs the radius of the circle by cos (m − 1)θ
                    (mult[k] - 1.0).abs().round() as usize
                }
            };
            // each direction a mode of its own: (direction, component)
            // pairs taken by decreasing |component|, a pair kept when
            // neither its direction nor its mode is taken yet
            let dim = eig.eigenvectors.nrows();
            let mut pairs: Vec<(f64, usize, usize)> = negative
                .iter()
                .flat_map(|&i| {
                    let v = eig.eigenvectors.column(i);
                    (0..dim).map(move |k| (v[k].abs(), i, k))
                })
                .collect();
            pairs.sort_by(|x, y| y.0.total_cmp(&x.0));
            let mut label: Vec<Option<usize>> = vec![None; eig.eigenvalues.len()];
            let mut taken = std::collections::HashSet::new();
            for (_, i, k) in pairs {
                let n = mode_of(k);
                if label[i].is_none() && !taken.contains(&n) {
                    label[i] = Some(n);
                    taken.insert(n);
                }
            }
            let (mut out, mut neutral): (Vec<(usize, UnstableMode)>, Vec<_>) = negative
                .iter()
                .map(|&i| {
                    // (more directions than modes: its largest component)
                    let n = label[i].unwrap_or_else(|| mode_of(eig.eigenvectors.column(i).iamax()));
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
            (strip(out), strip(neutral))
        };
        // the shortest mode the series holds: e^{imθ} is the radius's cos (m − 1)θ
        let n_max = mult
            .iter()
            .map(|&x| (x - 1.0).abs().round())
            .fold(1.0, f64::max);
        // the two controls' eigenproblems, on both cores
        let ((displacement, neutral_displacement), (load, neutral_load)) = super::both(
            n >= super::TWO_CORES_FROM_POINTS,
            || unstable(hess.view((0, 0), (m, m)).into_owned(), false),
            || unstable(hess.clone(), true),
        );
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
