//! The short-wave cutoff of a contour state's stability: which of its
//! unstable contour modes the thin-layer model resolves.
//!
//! The leading-order model (2)–(3) is the long-wave limit of the elastic
//! layer: its pressure–displacement relation Δp = m(φ − δ) holds for
//! undulations of wavenumber k with kh ≪ 1 (h the coating thickness), and
//! its first correction is of relative order (kh)². It has no length of
//! its own below which undulations are stabilised: at ρ = 1 the circle of
//! radius ā is unstable to every mode n > ā³/4 + 1, whose wavelengths
//! 2πā/n lie below 2πā/(ā³/4 + 1) (docs/exact.md, "Stability"), and the series
//! of an exact state reports every such mode it holds, down to its
//! shortest. A real coating stabilises short undulations at a few h (the
//! fingering of confined elastic films has a wavelength of about 3h), so
//! the model's verdict on a mode shorter than that is not the coating's.
//!
//! The cutoff counts a mode as resolved when its wavelength along the
//! contour (perimeter / n) is at least 2π h, that is kh ≤ 1, the edge of
//! the long-wave range; shorter modes are reported as not resolved, and a
//! state's stability verdict counts only the resolved ones. In the units
//! (17) the cutoff wavelength is 2π h/L, so it is set by the thinness h/L:
//! `physical` knows it (the thicker coating's h over L); the dimensionless
//! commands take `--thinness` and otherwise h/L = 0.1 ([`Cutoff::default`]).
//!
//! A direction whose eigenvalue is zero up to `NEUTRAL` of the largest is
//! neutral, neither stable nor unstable: the state sits on a fold or a
//! bifurcation of the control (a pull-off under its own control, or the
//! circle at a neutral point ā³ = 4(n − 1)), located only as well as
//! round-off allows. The verdicts count the clearly negative directions;
//! the neutral ones are shown beside them (`Eigen`).
//!
//! Owns: [`Cutoff`], the neutral band (`Eigen`). May use: `error`.

use crate::error::{check_range, Result};
use serde::{Deserialize, Serialize};

/// The shortest wavelength (in units of L) whose stability the thin-layer
/// model is trusted with: 2π h/L.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Cutoff {
    /// The thinness h/L (the coating thickness over the length unit L of
    /// (17); for two coatings the thicker one's).
    pub thinness: f64,
    /// The cutoff wavelength 2π h/L: modes shorter than it are not
    /// resolved by (2).
    pub wavelength: f64,
}

impl Cutoff {
    /// The thinness of the dimensionless commands when none is given:
    /// h/L = 0.1, coatings a few per cent of the contact's size at the
    /// loads of docs/accuracy.md (ā ≈ 1.5–4), well inside the thin-layer
    /// range (`physical` warns from h/a = 0.2).
    pub(crate) const DEFAULT_THINNESS: f64 = 0.1;

    /// The thinnest coatings whose verdicts are computed, h/L: an atom's
    /// size against L of a few tens of micrometres, far below any coating
    /// (2) describes; thinner, the cutoff's wavelength loses its digits
    /// against the contour's.
    pub(crate) const THINNEST: f64 = 1e-6;
    /// The thickest, h/L: (2) is the limit h/L → 0, and coatings far
    /// thicker than the contact have nothing of it left (`layer`).
    pub(crate) const THICKEST: f64 = 1e3;

    /// The cutoff of coatings of thinness h/L (positive, finite, and in
    /// [`Cutoff::THINNEST`, `Cutoff::THICKEST`]).
    pub fn for_thinness(thinness: f64) -> Result<Cutoff> {
        check_range(
            "thinness",
            thinness,
            thinness > 0.0 && thinness.is_finite(),
            "(0, ∞)",
        )?;
        if !(Cutoff::THINNEST..=Cutoff::THICKEST).contains(&thinness) {
            return Err(crate::error::Error::Unsupported {
                name: "thinness",
                value: thinness,
                supported: format!(
                    "[{}, {}] (the stability verdicts are computed there)",
                    Cutoff::THINNEST,
                    Cutoff::THICKEST
                )
                .into(),
            });
        }
        Ok(Cutoff::of(thinness))
    }

    /// The cutoff of a thinness already checked.
    fn of(thinness: f64) -> Cutoff {
        Cutoff {
            thinness,
            wavelength: 2.0 * std::f64::consts::PI * thinness,
        }
    }

    /// Whether a mode of this wavelength (units of L; ∞ for the size) is
    /// resolved by the model.
    pub(crate) fn resolves(&self, wavelength: f64) -> bool {
        wavelength >= self.wavelength
    }

    /// The thinness h/L whose cutoff is `wavelength` (the inverse of
    /// [`Cutoff::for_thinness`]'s 2π h/L): a state unstable to a mode of
    /// that wavelength is stable above the cutoff only from there on.
    pub(crate) fn thinness_for(wavelength: f64) -> f64 {
        wavelength / (2.0 * std::f64::consts::PI)
    }

    /// Why a contour state whose verdict under a control is "unstable"
    /// above this cutoff is doubtful, in the words every front end shows:
    /// which modes (2) resolves, the longest (n, wavelength) among the
    /// contour modes, and the critical thinness (that wavelength over 2π)
    /// above which none would be. A contact that moves through states
    /// stable above the cutoff under that control does not come to such a
    /// state: at the limit of stable states no resolved eigenvalue is
    /// negative. `size_unstable`: the size (n = 0) is unstable, which no
    /// thinness changes; `a_bar` gives the critical thinness as h/a too.
    pub(crate) fn unstable_words(
        &self,
        under_load: bool,
        resolved: usize,
        size_unstable: bool,
        longest: Option<(usize, f64)>,
        a_bar: f64,
    ) -> String {
        let control = if under_load { "load" } else { "displacement" };
        let head = format!(
            "unstable under {control} control above the short-wave cutoff (2π h/L = {:.3}, h/L = {})",
            self.wavelength,
            crate::error::short(self.thinness)
        );
        let end = format!(
            "(2) predicts a change of shape, and no contact moving through stable states under {control} control comes to this state"
        );
        match longest {
            Some((n, wavelength)) if !size_unstable => {
                let h = Cutoff::thinness_for(wavelength);
                format!(
                    "{head} to {resolved} contour mode{}, the longest n = {n} ({wavelength:.3} long): {end}; stable above the cutoff for h/L >= {h:.3} (h/a >= {:.3})",
                    if resolved == 1 { "" } else { "s" },
                    h / a_bar
                )
            }
            _ => format!("{head} in its size (n = 0), whatever the thinness: {end}"),
        }
    }
}

/// The neutral band: an eigenvalue within this fraction of the largest
/// in magnitude is zero as far as the state is located. At the folds
/// where thinjkr ends a control (the pull-offs of `conformal:2` … `8`),
/// the fold's own eigenvalue measures 1e-11 … 3e-9 of the largest; the
/// nearest clearly unstable ones 3e-4 and more.
pub(crate) const NEUTRAL: f64 = 1e-6;

/// What an eigenvalue of a stability Hessian says about its direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Eigen {
    /// Positive beyond the neutral band.
    Stable,
    /// Zero within the neutral band: a fold or bifurcation.
    Neutral,
    /// Negative beyond the neutral band.
    Unstable,
}

impl Eigen {
    /// The direction of eigenvalue `l` of a Hessian whose largest
    /// eigenvalue in magnitude is `scale`.
    pub(crate) fn of(l: f64, scale: f64) -> Eigen {
        let band = NEUTRAL * scale.abs();
        if l < -band {
            Eigen::Unstable
        } else if l <= band {
            Eigen::Neutral
        } else {
            Eigen::Stable
        }
    }
}

impl Default for Cutoff {
    fn default() -> Self {
        Cutoff::of(Cutoff::DEFAULT_THINNESS)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_neutral_band_is_a_millionth_of_the_largest() {
        assert_eq!(Eigen::of(-2e-6, 1.0), Eigen::Unstable);
        assert_eq!(Eigen::of(-5e-7, 1.0), Eigen::Neutral);
        assert_eq!(Eigen::of(0.0, 1.0), Eigen::Neutral);
        assert_eq!(Eigen::of(1.5e-6, 2.0), Eigen::Neutral);
        assert_eq!(Eigen::of(3e-6, 2.0), Eigen::Stable);
        assert_eq!(Eigen::of(-3e-6, -2.0), Eigen::Unstable);
    }

    #[test]
    fn the_cutoff_is_two_pi_h_and_refuses_a_bad_thinness() {
        let c = Cutoff::for_thinness(0.5).unwrap();
        assert!((c.wavelength - std::f64::consts::PI).abs() < 1e-15);
        assert!(c.resolves(f64::INFINITY) && c.resolves(3.2) && !c.resolves(3.1));
        assert_eq!(Cutoff::default(), Cutoff::for_thinness(0.1).unwrap());
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let e = Cutoff::for_thinness(bad).unwrap_err().to_string();
            assert!(e.contains("thinness") && e.contains("(0, ∞)"), "{e}");
        }
    }
}
