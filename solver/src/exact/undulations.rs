//! How much of a contour's shape lies in undulations shorter than the
//! short-wave cutoff: the part of the contour the thin-layer model (2)
//! does not resolve (issue 32 (b)).
//!
//! The stability verdicts say which *directions* the model cannot judge;
//! this says the same of a *shape*. The contour's radial departure from
//! its ellipse (the ellipse through its extremes, as
//! `Contour::deviation_from_ellipse`), r − r_ellipse, is expanded in the
//! arclength σ, d(σ) = Σ d_n cos(2πnσ/P) (P the perimeter; the doubly
//! symmetric class holds only even n). Its modes with P/n shorter than the
//! cutoff are the shape's unresolved part, measured by its largest radial
//! excursion along the contour. A
//! state whose unresolved part is a visible fraction of its size (lobes,
//! notches, grooves narrower than 2πh) owes its shape to undulations a
//! real coating, stiffer than (2) at short waves, would not let it take.
//!
//! Owns: [`ShortWaves`], [`short_waves`]. May use: `exact` (the contour),
//! `cutoff`.

use super::Contour;
use crate::cutoff::Cutoff;
use nalgebra::Complex;

/// The share of ā above which a shape's unresolved part is called
/// visible: a state whose undulations shorter than the cutoff reach 1 %
/// of its size owes its shape, not only a direction's verdict, to what
/// (2) does not resolve. A choice, as the cutoff's 2πh is; docs/exact.md
/// ("The shape's unresolved part") gives the amounts it is set against.
pub(crate) const VISIBLE: f64 = 1e-2;

/// Points along the contour the spectrum is read from.
const POINTS: usize = 4096;

/// The unresolved part of a contour's departure from its ellipse.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub(crate) struct ShortWaves {
    /// The largest radial excursion of the unresolved part (the modes
    /// shorter than the cutoff) along the contour, over ā.
    pub amplitude: f64,
    /// The largest of those modes, where any is above round-off.
    pub mode: Option<usize>,
    /// Its wavelength P/n (in units of L).
    pub wavelength: Option<f64>,
    /// The whole departure's largest |d| over ā (every mode).
    pub departure: f64,
    /// Whether the unresolved part is above 1 % of ā (`VISIBLE`): the shape is then
    /// (2)'s, not a coating's of that thickness.
    pub unresolved: bool,
}

impl ShortWaves {
    /// In words, with the cutoff: how much of the contour's shape (2) does
    /// not resolve.
    pub(crate) fn words(&self, cutoff: Cutoff) -> String {
        let part = match self.mode {
            Some(n) if self.amplitude >= 1e-4 => format!(
                "up to {} of a in undulations shorter than the cutoff (the largest n = {n}, wavelength {:.3} < 2π h/L = {:.3})",
                percent(self.amplitude),
                self.wavelength.unwrap_or(f64::INFINITY),
                cutoff.wavelength
            ),
            _ => format!(
                "less than 0.01 % of a in undulations shorter than the cutoff (2π h/L = {:.3})",
                cutoff.wavelength
            ),
        };
        let verdict = if self.unresolved {
            "(2) does not resolve that part of its shape, and a real coating this thick, stiffer at short waves, would not take it"
        } else {
            "below 1 % of a, the share at which a shape is called unresolved"
        };
        format!(
            "its contour departs from its ellipse by up to {} of a; {part}: {verdict}",
            percent(self.departure)
        )
    }
}

/// A share of ā as a percentage with two significant digits (at least
/// 0.01 %).
fn percent(share: f64) -> String {
    let p = 100.0 * share;
    if p < 0.01 {
        "less than 0.01 %".to_string()
    } else if p < 10.0 {
        format!("{p:.2} %")
    } else {
        format!("{p:.0} %")
    }
}

/// The undulations of `contour` shorter than `cutoff`'s wavelength.
pub(crate) fn short_waves(contour: &Contour, cutoff: Cutoff) -> ShortWaves {
    short_waves_at(&|t| contour.point_at(t), cutoff)
}

/// [`short_waves`] of a doubly symmetric contour given by [`POINTS`]
/// points at equal steps of any parameter, counter-clockwise from the X
/// axis (the Y axis at a quarter of them), as a `conformal:K` map gives.
pub(crate) fn short_waves_at(z: &dyn Fn(f64) -> Complex<f64>, cutoff: Cutoff) -> ShortWaves {
    let h = 2.0 * std::f64::consts::PI / POINTS as f64;
    let z: Vec<Complex<f64>> = (0..POINTS).map(|k| z(h * k as f64)).collect();
    short_waves_of(&z, cutoff)
}

fn short_waves_of(z: &[Complex<f64>], cutoff: Cutoff) -> ShortWaves {
    let (a, b) = (z[0].norm(), z[POINTS / 4].norm());
    // the arclength at each point (chords; the spectrum's low modes are
    // what matters, and 4096 points resolve them far below the amounts
    // reported)
    let mut sigma = vec![0.0; POINTS + 1];
    for k in 0..POINTS {
        sigma[k + 1] = sigma[k] + (z[(k + 1) % POINTS] - z[k]).norm();
    }
    let perimeter = sigma[POINTS];
    let d: Vec<f64> = z
        .iter()
        .map(|z| (z.norm() - super::ellipse_radius(a, b, z.im.atan2(z.re))) / a)
        .collect();
    // d_n = (2/P) ∮ d cos(2πnσ/P) dσ, the midpoint rule on each chord
    let coefficient = |n: usize| -> f64 {
        let k = 2.0 * std::f64::consts::PI * n as f64 / perimeter;
        (0..POINTS)
            .map(|i| {
                let ds = sigma[i + 1] - sigma[i];
                let mid = 0.5 * (sigma[i] + sigma[i + 1]);
                0.5 * (d[i] + d[(i + 1) % POINTS]) * (k * mid).cos() * ds
            })
            .sum::<f64>()
            * 2.0
            / perimeter
    };
    // modes up to a sixteenth of the points: beyond, the chords' rule
    // no longer reads them
    let n_max = POINTS / 16;
    let first_short = (perimeter / cutoff.wavelength).floor() as usize + 1;
    let short: Vec<(usize, f64)> = (first_short.max(2)..=n_max)
        .filter(|n| n % 2 == 0)
        .map(|n| (n, coefficient(n)))
        .collect();
    // the unresolved part d_short(σ) = Σ d_n cos(2πnσ/P) over the short
    // modes, its largest excursion along the contour
    let amplitude = (0..POINTS)
        .map(|i| {
            short
                .iter()
                .map(|&(n, dn)| {
                    dn * (2.0 * std::f64::consts::PI * n as f64 * sigma[i] / perimeter).cos()
                })
                .sum::<f64>()
                .abs()
        })
        .fold(0.0, f64::max);
    let largest = short.iter().map(|&(n, dn)| (n, dn.abs())).fold(
        (None, 0.0),
        |best: (Option<usize>, f64), (n, a)| {
            if a > best.1 {
                (Some(n), a)
            } else {
                best
            }
        },
    );
    // (below round-off no mode is named)
    let mode = largest.0.filter(|_| largest.1 > 1e-10);
    ShortWaves {
        amplitude,
        mode,
        wavelength: mode.map(|n| perimeter / n as f64),
        departure: d.iter().fold(0.0, |m: f64, v| m.max(v.abs())),
        unresolved: amplitude > VISIBLE,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// docs/exact.md's table "The shape's unresolved part": every cell is
    /// the exact pull-off's unresolved part at that ρ and h/L, to its
    /// printed digits, with its largest mode, and the first column the
    /// whole departure from the ellipse.
    #[test]
    fn the_unresolved_shape_table_of_the_docs_is_the_solvers() {
        let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/exact.md"))
            .unwrap();
        let from = doc
            .find("**The shape's unresolved part.**")
            .expect("the section");
        let mut lines = doc[from..]
            .lines()
            .skip_while(|l| !l.starts_with("| ρ (departure) |"));
        let header: Vec<f64> = lines
            .next()
            .unwrap()
            .trim_matches(|c| c == '|' || c == ' ')
            .split(" | ")
            .skip(1)
            .map(|c| c.trim_start_matches("h/L = ").parse().unwrap())
            .collect();
        let rows: Vec<Vec<String>> = lines
            .skip(1)
            .take_while(|l| l.starts_with("| "))
            .map(|l| {
                l.trim_matches(|c| c == '|' || c == ' ')
                    .split(" | ")
                    .map(str::to_string)
                    .collect()
            })
            .collect();
        assert_eq!(rows.len(), 7, "the table's rows");
        let share = |p: f64| {
            if p < 10.0 {
                format!("{p:.1}")
            } else {
                format!("{p:.0}")
            }
        };
        for row in &rows {
            let (rho, departure) = row[0].split_once(" (").unwrap();
            let rho: f64 = rho.parse().unwrap();
            let (st, _) = crate::exact::pull_off_resolved(rho).unwrap();
            for (k, &thinness) in header.iter().enumerate() {
                let sw = short_waves(&st.contour, Cutoff::for_thinness(thinness).unwrap());
                assert_eq!(
                    format!("{} %)", share(100.0 * sw.departure)),
                    departure,
                    "rho {rho}"
                );
                let p = 100.0 * sw.amplitude;
                let cell = if p < 0.01 {
                    "< 0.01".to_string()
                } else {
                    let v = if p < 10.0 {
                        format!("{p:.2}")
                    } else {
                        format!("{p:.0}")
                    };
                    format!("{v} (n = {})", sw.mode.unwrap())
                };
                assert_eq!(cell, row[k + 1], "rho {rho}, h/L {thinness}");
            }
        }
    }

    /// An ellipse has no departure; a circle with a cos 10θ ripple of
    /// amplitude ε has ε in mode 10 when the cutoff is longer than its
    /// wavelength and nothing when it is shorter.
    #[test]
    fn a_ripple_is_counted_where_the_cutoff_does_not_resolve_it() {
        let ellipse = Contour::ellipse(3.0, 1.8, 16);
        let all = short_waves(&ellipse, Cutoff::for_thinness(0.01).unwrap());
        assert!(all.amplitude < 1e-12 && all.departure < 1e-12, "{all:?}");
        // z = A e^{iθ} + b_4 e^{−9iθ}... r = A + b cos 10θ to first order:
        // the radial ripple of the series' e^{−9iθ} term on a circle
        let a = 3.0;
        let eps = 1e-3;
        let mut b = vec![0.0; 5];
        b[4] = eps * a;
        let ripple = Contour {
            a: a - eps * a,
            b,
            c: Vec::new(),
        };
        // its wavelength 2π·3/10 = 1.885: a cutoff of 2π·0.5 = 3.14 does
        // not resolve it, one of 2π·0.2 = 1.26 does
        let coarse = short_waves(&ripple, Cutoff::for_thinness(0.5).unwrap());
        assert_eq!(coarse.mode, Some(10), "{coarse:?}");
        // (the arclength of the rippled circle is not quite aθ: a leak
        // of order ε² · 10 into the neighbouring modes)
        assert!((coarse.amplitude - eps).abs() < 2e-2 * eps, "{coarse:?}");
        // (the circle's mean radius is a(1 − ε))
        let wavelength = 2.0 * std::f64::consts::PI * a * (1.0 - eps) / 10.0;
        assert!(
            (coarse.wavelength.unwrap() - wavelength).abs() < 1e-4,
            "{coarse:?}"
        );
        let fine = short_waves(&ripple, Cutoff::for_thinness(0.2).unwrap());
        assert!(fine.amplitude < 2e-2 * eps, "{fine:?}");
    }
}
