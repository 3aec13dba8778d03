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
//! posed in the metric of the contour's normal motion, and each negative
//! eigenvalue is reported with the contour mode its direction is made of,
//! read from the spectrum of its normal displacement along the contour
//! (`crate::contour_modes`): n = 0 the size (under load control also δ̄),
//! n the radius perturbed by cos nθ, wavelength P/n along the contour (P
//! the perimeter). The names are bounded by the second route, the
//! variation of each control restricted to the long-wave motions (the
//! modes 0, 2, …, n; under load with δ̄), `NormalMotion::long_wave`: no
//! unstable direction is named by a mode, the size n = 0 among them, on
//! whose long-wave motions the variation is positive, and one is named by
//! the first mode whose motions added make it negative. Where the
//! directions of a peanut-shaped contour mix neighbouring modes (ρ ≤ 0.07)
//! the least unstable one had been called n = 4; on the pieces at ρ = 0.3
//! a short direction had been called the size under load, and the
//! longest unstable mode had been one rung shorter than the ladder's.
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
//! Owns: [`ExactStability`], [`UnstableMode`]. May use: `exact`, `error`, `cutoff`, `contour_modes` (the
//! eigenproblem in the metric of the normal motion and the modes' names),
//! nalgebra; in its tests `control` (a size held).

use super::{Exact, ExactState};
use crate::contour_modes::{NamedDirection, NormalMotion};
use crate::cutoff::Cutoff;
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
    /// How the coefficients of this problem's series move `contour`: the
    /// normal displacement of each at the grid's points, and the shortest
    /// mode the series holds (e^{imθ} moves the radius by cos (m − 1)θ).
    pub(crate) fn normal_motion(&self, contour: &super::Contour) -> NormalMotion {
        let samples = contour.samples(&self.grid);
        let m = self.truncation.coefficients();
        let i_unit = nalgebra::Complex::new(0.0, 1.0);
        let normal_speed = DMatrix::from_fn(self.grid.len(), m, |i, k| {
            (self.grid.basis[k][i] * i_unit * samples.dz[i].conj()).re
        });
        let speed: Vec<f64> = samples.dz.iter().map(|d| d.norm()).collect();
        NormalMotion::new(normal_speed, &speed, self.shortest_mode())
    }

    /// In the arclength representation, the directions that keep θ
    /// proportional to arclength (the null space Z of the gauge rows'
    /// Jacobian at u, m × (m − P); a reparametrisation does not move the
    /// contour): the Hessian is restricted to them. None in the conformal
    /// form.
    fn gauge_restriction(&self, u: &nalgebra::DVector<f64>) -> Option<DMatrix<f64>> {
        if self.truncation.arclength == 0 {
            return None;
        }
        let m = self.truncation.coefficients();
        // the eigenvectors of GᵀG (m × m) with its m − P smallest
        // eigenvalues (zero where the P gauge rows are independent)
        let g = self.gauge_jacobian(u).columns(0, m).into_owned();
        let gg = SymmetricEigen::new(g.transpose() * &g);
        let mut order: Vec<usize> = (0..m).collect();
        order.sort_by(|&a, &b| gg.eigenvalues[a].total_cmp(&gg.eigenvalues[b]));
        let keep = m - g.nrows();
        Some(DMatrix::from_fn(m, keep, |r, c| {
            gg.eigenvectors[(r, order[c])]
        }))
    }

    /// The shortest contour mode the series holds.
    fn shortest_mode(&self) -> usize {
        self.grid
            .multipliers
            .iter()
            .map(|&x| (x - 1.0).abs().round() as usize)
            .max()
            .unwrap_or(0)
    }

    /// The long-wave ladders of `st` (a state of this problem's
    /// truncation) under displacement and under load control
    /// ([`NormalMotion::long_wave_ladder`]; under load δ̄ is kept in every
    /// rung), and the contour's perimeter: the second route, by the
    /// motions' modes rather than the directions' names.
    #[cfg(test)]
    pub(crate) fn long_wave_ladders(
        &self,
        st: &ExactState,
    ) -> Result<(
        Vec<crate::contour_modes::Rung>,
        Vec<crate::contour_modes::Rung>,
        f64,
    )> {
        let m = self.truncation.coefficients();
        let u = self.unknowns(st);
        let hess = self.bordered_hessian(&u).ok_or_else(|| {
            Error::NoState("exact stability: singular boundary integral equation".into())
        })?;
        let restriction = self.gauge_restriction(&u);
        let motion = self.normal_motion(&st.contour);
        let h_cc = hess.view((0, 0), (m, m)).into_owned();
        Ok((
            motion.long_wave_ladder(&h_cc, restriction.as_ref()),
            motion.long_wave_ladder(&hess, restriction.as_ref()),
            motion.perimeter(),
        ))
    }

    /// The linear stability of `st` (a state of this problem's truncation).
    pub fn stability(&self, st: &ExactState) -> Result<ExactStability> {
        let m = self.truncation.coefficients();
        let err = || Error::NoState("exact stability: singular boundary integral equation".into());
        let u = self.unknowns(st);
        let hess = self.bordered_hessian(&u).ok_or_else(err)?;
        let n = self.grid.len();
        let restriction = self.gauge_restriction(&u);
        // Each direction is named by the contour mode its normal motion is
        // made of, measured along the contour itself (`crate::contour_modes`).
        let motion = self.normal_motion(&st.contour);
        let perimeter = motion.perimeter();
        // the long-wave motions on which the state is stable: no unstable
        // direction is named by their modes
        let h_cc = hess.view((0, 0), (m, m)).into_owned();
        let by_displacement = motion.long_wave(&h_cc, restriction.as_ref());
        let by_load = by_displacement.under_load(motion.long_wave(&hess, restriction.as_ref()));
        let unstable =
            |a: DMatrix<f64>, long_wave| -> Option<(Vec<UnstableMode>, Vec<UnstableMode>)> {
                let (out, neutral) = motion.directions(&a, restriction.as_ref(), long_wave)?;
                let named = |v: Vec<NamedDirection>| {
                    v.into_iter()
                        .map(|d| UnstableMode {
                            n: d.n,
                            wavelength: d.wavelength,
                            eigenvalue: d.eigenvalue,
                            resolved: true,
                        })
                        .collect()
                };
                Some((named(out), named(neutral)))
            };
        // the shortest mode the series holds: e^{imθ} is the radius's cos (m − 1)θ
        let n_max = self.shortest_mode().max(1) as f64;
        // the two controls' eigenproblems, on both cores
        let (by_displacement, by_load) = super::both(
            n >= super::TWO_CORES_FROM_POINTS,
            || unstable(h_cc.clone(), by_displacement),
            || unstable(hess.clone(), by_load),
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

#[cfg(test)]
mod tests {
    use super::*;

    /// docs/exact-record.md's table "A second route: the long-wave motions alone"
    /// is the solver's: at each pull-off the variation under displacement
    /// control restricted to the motions of modes up to 4 has the least
    /// eigenvalue printed and is positive, with modes up to 6 the printed
    /// negative one (the first unstable rung), each fit missing by less
    /// than 1e-9; so no unstable direction there is named n = 4 (or 2).
    #[test]
    #[ignore = "slow tier (.ci/slow): about 30 s; a docs table regenerated"]
    fn the_long_wave_table_of_the_docs_is_the_solvers() {
        let doc = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/exact-record.md"),
        )
        .unwrap();
        let at = doc
            .find("**A second route: the long-wave motions alone.**")
            .expect("the section");
        let row = |head: &str| -> Vec<String> {
            let line = doc[at..]
                .lines()
                .find(|l| l.starts_with(head))
                .unwrap_or_else(|| panic!("row {head}"));
            line.split('|')
                .map(|c| c.trim().replace('−', "-"))
                .filter(|c| !c.is_empty())
                .skip(1)
                .collect()
        };
        let (rhos, upto4, upto6) = (row("| ρ |"), row("| modes ≤ 4 |"), row("| modes ≤ 6 |"));
        assert_eq!((rhos.len(), upto4.len(), upto6.len()), (5, 5, 5));
        for i in 0..5 {
            let rho: f64 = rhos[i].parse().unwrap();
            let (st, _) = crate::exact::pull_off_resolved(rho).unwrap();
            let ex = Exact::new(rho, st.truncation).unwrap();
            let u = ex.unknowns(&st);
            let m = ex.truncation.coefficients();
            let h_cc = ex
                .bordered_hessian(&u)
                .unwrap()
                .view((0, 0), (m, m))
                .into_owned();
            let restriction = ex.gauge_restriction(&u);
            let motion = ex.normal_motion(&st.contour);
            let ladder = motion.long_wave_ladder(&h_cc, restriction.as_ref());
            let ns: Vec<usize> = ladder.iter().map(|r| r.n).collect();
            assert_eq!(ns, [0, 2, 4, 6], "rho = {rho}: {ladder:?}");
            assert!(ladder.iter().all(|r| r.miss < 1e-9), "{ladder:?}");
            for (rung, printed) in [(&ladder[2], &upto4[i]), (&ladder[3], &upto6[i])] {
                let printed: f64 = printed.parse().unwrap();
                assert!(
                    (rung.least - printed).abs() <= 5e-4,
                    "rho = {rho}, modes up to {}: printed {printed}, solved {}",
                    rung.n,
                    rung.least
                );
            }
            assert_eq!(
                motion.long_wave(&h_cc, restriction.as_ref()).stable_upto,
                Some(4)
            );
        }
    }

    /// The ladder names the longest unstable direction. At ρ = 0.3 on the
    /// piece between the folds ā = 3.6004 and 3.6731 (docs/exact.md, "The
    /// windows settled"), under load control the size with δ̄ alone is
    /// stable (the rung n = 0 positive) and the first unstable rung is
    /// n = 12. Named by its largest relative amplitude alone, one unstable
    /// direction there is called the size, n = 0, at some of the three
    /// states and the longest unstable mode is 16 or 12 by turns; named
    /// within the ladder's bounds every state's longest is 12, none is
    /// called 0, and the critical thinness is mode 12's, P/(2π·12).
    #[test]
    fn on_a_window_at_rho_0_3_the_ladder_names_the_longest_unstable_mode() {
        use crate::control::Hold;
        // the state of the reach map (`thinjkr exact reach`: 128 modes of
        // each sign, from the circle continued to rho = 0.98 at its size)
        let t = super::super::Truncation::in_arclength(128);
        let st = Exact::new(0.98, t)
            .unwrap()
            .deferring_stability()
            .from_circle(3.62)
            .unwrap();
        let Ok(super::super::rho_path::Followed::Reached(st)) =
            super::super::rho_path::follow(&st, 0.3, Hold::Size(3.62))
        else {
            panic!("the size 3.62 reaches rho = 0.3");
        };
        let ex = Exact::new(0.3, st.truncation).unwrap();
        let mut by_amplitude_alone = Vec::new();
        for a in [3.6185, 3.6367, 3.6549] {
            let here = ex
                .solve_at(Hold::Size(a), &st.contour, st.delta_bar)
                .unwrap();
            assert!(here.bc_error <= super::super::CONVERGED);
            let (_, load_ladder, perimeter) = ex.long_wave_ladders(&here).unwrap();
            let rung = |n: usize| load_ladder.iter().find(|r| r.n == n).unwrap().least;
            assert!(
                rung(0) > 1.0 && rung(10) > 0.5 && rung(12) < -0.2,
                "{load_ladder:?}"
            );
            let load = &here.stability.load;
            assert!(load.iter().all(|m| m.n >= 12), "a = {a}: {load:?}");
            assert_eq!(load.iter().map(|m| m.n).min(), Some(12), "a = {a}");
            let h = here.stability.critical_thinness_load.unwrap();
            let mode_12 = perimeter / 12.0 / (2.0 * std::f64::consts::PI);
            assert!(
                (h - mode_12).abs() < 1e-12,
                "a = {a}: {h} against {mode_12}"
            );
            // the same Hessian's directions named without the ladder
            let u = ex.unknowns(&here);
            let hess = ex.bordered_hessian(&u).unwrap();
            let restriction = ex.gauge_restriction(&u);
            let motion = ex.normal_motion(&here.contour);
            let unbounded = crate::contour_modes::LongWave {
                size_stable: false,
                stable_upto: None,
                unstable_at: None,
            };
            let (named, _) = motion
                .directions(&hess, restriction.as_ref(), unbounded)
                .unwrap();
            by_amplitude_alone.push(named.iter().map(|d| d.n).min().unwrap());
        }
        assert!(by_amplitude_alone.contains(&0), "{by_amplitude_alone:?}");
    }
}
