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
//! With the stability verdicts' critical thinness it also says for which
//! coatings (2) gives a state as a contact it resolves ([`Coatings`]): thin
//! enough that the shape is resolved, thick enough that every unstable
//! mode is shorter than the cutoff.
//!
//! Owns: [`ShortWaves`], [`short_waves`],
//! [`Coatings`], [`Thinnesses`], [`no_thinness_words`], [`size_unstable`].
//! May use: `exact` (the contour, the stability's modes), `cutoff`.

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
pub(crate) const POINTS: usize = 4096;

/// A range of the thinness h/L, from `from` (0: no lower bound) up to
/// `to` (not included; null: no upper bound).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub(crate) struct Thinnesses {
    /// The smallest h/L of the range: the critical thinness of the
    /// control's stability (0 where no contour mode is unstable).
    pub from: f64,
    /// The h/L from which the shape is unresolved
    /// ([`ShortWaves::critical_thinness`]); null where it never is.
    pub to: Option<f64>,
}

impl Thinnesses {
    /// The range's bounds, each `None` where it has none: the least h/L
    /// (absent where it is 0) and the h/L it stops at.
    pub(crate) fn bounds(self) -> (Option<f64>, Option<f64>) {
        ((self.from > 0.0).then_some(self.from), self.to)
    }
}

/// For which coatings (2) gives a state as a contact it resolves: its shape
/// resolved (h/L below the shape's critical thinness) and, under each
/// control, every unstable contour mode shorter than the cutoff (h/L at
/// least that control's critical thinness). Null under a control where no
/// thinness does both (or the size itself is unstable there).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub(crate) struct Coatings {
    /// Under load control.
    pub load: Option<Thinnesses>,
    /// Under displacement control.
    pub displacement: Option<Thinnesses>,
}

impl Coatings {
    /// The ranges of a state with these stability verdicts and this shape;
    /// `None` where its stability was not computed (no verdict, no range).
    pub(crate) fn of(
        stab: &super::stability::ExactStability,
        shape: &ShortWaves,
    ) -> Option<Coatings> {
        stab.shortest_wavelength?;
        Some(Coatings {
            load: thinnesses(&stab.load, stab.critical_thinness_load, shape),
            displacement: thinnesses(
                &stab.displacement,
                stab.critical_thinness_displacement,
                shape,
            ),
        })
    }
}

/// Why no thinness makes a state a stable contact whose shape (2)
/// resolves under a control where its [`Coatings`] have no range there
/// (`modes` its unstable modes there), in words.
pub(crate) fn no_thinness_words(
    modes: &[super::stability::UnstableMode],
    shape: &ShortWaves,
) -> String {
    if size_unstable(modes) {
        return "its size is unstable".into();
    }
    let u = longest_unstable(modes);
    format!(
        "below h/L = {:.3} it is unstable to n = {}, from {:.3} on its undulations from n = {} on pass 1 % of a",
        u.map_or(0.0, |m| Cutoff::thinness_for(m.wavelength)),
        u.map_or(0, |m| m.n),
        shape.critical_thinness.unwrap_or(f64::INFINITY),
        shape.critical_mode.unwrap_or(0)
    )
}

/// Whether the size (n = 0) is among the unstable `modes`: no thinness
/// stabilises it.
pub(crate) fn size_unstable(modes: &[super::stability::UnstableMode]) -> bool {
    modes.iter().any(|m| m.n == 0)
}

/// The longest unstable contour mode (n ≥ 1) of `modes`.
pub(crate) fn longest_unstable(
    modes: &[super::stability::UnstableMode],
) -> Option<&super::stability::UnstableMode> {
    modes
        .iter()
        .filter(|m| m.n > 0)
        .max_by(|p, q| p.wavelength.total_cmp(&q.wavelength))
}

fn thinnesses(
    modes: &[super::stability::UnstableMode],
    critical: Option<f64>,
    shape: &ShortWaves,
) -> Option<Thinnesses> {
    if size_unstable(modes) {
        return None;
    }
    // both bounds are wavelengths of modes of the same contour over 2π,
    // P/(2πn): the range is open where the shape's critical mode is
    // longer (smaller n) than the longest unstable one (compared by n, not
    // by thinness: the two read the perimeter by different quadratures)
    let open = match (longest_unstable(modes), shape.critical_mode) {
        (Some(u), Some(m)) => m < u.n,
        _ => true,
    };
    open.then(|| Thinnesses {
        from: critical.unwrap_or(0.0),
        to: shape.critical_thinness,
    })
}

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
    /// The thinness h/L from which the shape is unresolved: the smallest
    /// h/L whose cutoff 2π h/L leaves more than 1 % of ā in the shorter
    /// modes, P/(2π m) for the longest such mode m ([`ShortWaves::critical_mode`]).
    /// With thinner coatings (2) resolves the shape. Null where even the
    /// whole departure from the ellipse (every mode n ≥ 2) is below 1 %.
    pub critical_thinness: Option<f64>,
    /// The mode m whose wavelength sets [`ShortWaves::critical_thinness`]:
    /// with it and the shorter modes the unresolved part passes 1 % of ā.
    pub critical_mode: Option<usize>,
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
        let thinner = match (self.critical_thinness, self.critical_mode) {
            (Some(h), Some(m)) => format!(
                "; it is resolved for h/L below {h:.3} (above, the modes from n = {m} on, shorter than the cutoff, pass 1 % of a)"
            ),
            _ => "; it is resolved at every thinness (its whole departure is below 1 % of a)".into(),
        };
        format!(
            "its contour departs from its ellipse by up to {} of a; {part}: {verdict}{thinner}",
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
    // (beyond the modes read, none is short: capped before the cast, so a
    // cutoff far below the contour's scale cannot overflow it)
    let first_short = (perimeter / cutoff.wavelength).floor().min(n_max as f64) as usize + 1;
    let modes: Vec<(usize, f64)> = (2..=n_max)
        .step_by(2)
        .map(|n| (n, coefficient(n)))
        .collect();
    // the part in the modes from m on, d_m(σ) = Σ_{n ≥ m} d_n cos(2πnσ/P),
    // summed from the shortest mode down; its largest excursion along the
    // contour at the cutoff's first short mode is the unresolved part, and
    // the largest m at which it passes 1 % (the first met from the
    // shortest mode down) sets the critical thinness
    let mut partial = vec![0.0; POINTS];
    let mut amplitude = 0.0;
    let mut critical_mode = None;
    for &(n, dn) in modes.iter().rev() {
        let k = 2.0 * std::f64::consts::PI * n as f64 / perimeter;
        for (p, s) in partial.iter_mut().zip(&sigma) {
            *p += dn * (k * s).cos();
        }
        let excursion = partial.iter().fold(0.0, |m: f64, v| m.max(v.abs()));
        if n >= first_short {
            amplitude = excursion;
        }
        if critical_mode.is_none() && excursion > VISIBLE {
            critical_mode = Some(n);
        }
    }
    let short: Vec<(usize, f64)> = modes
        .iter()
        .copied()
        .filter(|&(n, _)| n >= first_short)
        .collect();
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
        critical_thinness: critical_mode.map(|m| Cutoff::thinness_for(perimeter / m as f64)),
        critical_mode,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// docs/exact-record.md's table "The shape's unresolved part": every cell is
    /// the exact pull-off's unresolved part at that ρ and h/L, to its
    /// printed digits, with its largest mode, and the first column the
    /// whole departure from the ellipse; and its table "Coatings for which
    /// a state is resolved and stable": each pull-off's critical thinness
    /// under load with its longest unstable mode, its shape's critical
    /// thinness with its mode, and the range of both (`Coatings`), the same
    /// under displacement control.
    #[test]
    #[ignore = "slow tier (.ci/slow): about 30 s; a docs table regenerated"]
    fn the_unresolved_shape_table_of_the_docs_is_the_solvers() {
        let doc = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../docs/exact-record.md"
        ))
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
        // a table's rows after its header line, as cells
        let cells = |lines: &mut dyn Iterator<Item = &str>| -> Vec<Vec<String>> {
            lines
                .skip(1)
                .take_while(|l| l.starts_with("| "))
                .map(|l| {
                    l.trim_matches(|c| c == '|' || c == ' ')
                        .split(" | ")
                        .map(str::to_string)
                        .collect()
                })
                .collect()
        };
        let rows = cells(&mut lines);
        assert_eq!(rows.len(), 7, "the table's rows");
        // the pull-offs, judged with the default thinness, by ρ's digits
        let mut pull_offs: std::collections::HashMap<String, crate::exact::ExactState> =
            Default::default();
        let mut pull_off = |rho: &str| -> crate::exact::ExactState {
            pull_offs
                .entry(rho.to_string())
                .or_insert_with(|| {
                    crate::exact::pull_off_resolved(rho.parse().unwrap())
                        .unwrap()
                        .0
                        .judged(Cutoff::default())
                })
                .clone()
        };
        let share = |p: f64| {
            if p < 10.0 {
                format!("{p:.1}")
            } else {
                format!("{p:.0}")
            }
        };
        for row in &rows {
            let (rho, departure) = row[0].split_once(" (").unwrap();
            let st = pull_off(rho);
            let rho: f64 = rho.parse().unwrap();
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
        // "Coatings for which a state is resolved and stable": the pull-offs'
        // bounds, each with its mode, and the range of both
        let from = doc
            .find("**Coatings for which a state is resolved and stable.**")
            .expect("the section");
        let rows = cells(
            &mut doc[from..]
                .lines()
                .skip_while(|l| !l.starts_with("| ρ | stable under load"))
                .skip(1),
        );
        assert_eq!(rows.len(), 12, "the coatings table's rows");
        for row in &rows {
            let st = pull_off(&row[0]);
            let (stab, shape) = (&st.stability, st.shape.unwrap());
            let coatings = st.coatings.expect("judged with its stability");
            assert_eq!(coatings.load, coatings.displacement, "rho {}", row[0]);
            let n = longest_unstable(&stab.load).unwrap().n;
            let stable = format!("{:.3} (n = {n})", stab.critical_thinness_load.unwrap());
            let resolved = match (shape.critical_thinness, shape.critical_mode) {
                (Some(h), Some(m)) => format!("{h:.3} (n = {m})"),
                _ => "every h/L".to_string(),
            };
            let both = match coatings.load {
                None => "none".to_string(),
                Some(Thinnesses { from, to: None }) => format!("{from:.3} on"),
                Some(Thinnesses { from, to: Some(to) }) => format!("{from:.3} to {to:.3}"),
            };
            assert_eq!([stable, resolved, both], row[1..4], "rho {}", row[0]);
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
