//! The paper's Figures 2–9 and a crossing-angle figure, drawn as SVG with
//! plotters from the derived (corrected) model. Where a figure depends on a
//! printed equation that the checker found to differ ((18), (25)₁, (26),
//! (27)), the printed version is drawn too, dashed and labelled, so that the
//! difference can be seen. Output is deterministic.
//!
//! The figures of the exact solution ([`exact_all`]) are drawn from the
//! exact pull-offs of the accuracy run (`derive/data/exact_reference.json`,
//! [`crate::accuracy::Reference`]), with the stored pull-offs between them
//! below ρ = 0.3 (`exact::stored`), beside every model's.
//!
//! Owns: figure data and rendering. May use: `accuracy`, `fold`, `contact`, `curve`, `limits`,
//! `exact`, `generated` (the paper's model `max`, whose figures these are),
//! `model` (every ellipse model beside it), `conformal` (its arms and
//! convergence), `slender` (its pull-off beside the models'), `layer` (the
//! pull-off against the coatings' thickness), `studies` (the reach map's
//! lines, with the feature `cli`), `report` (the thickness map's points,
//! with the feature `cli`), `error`.

use crate::contact::Contact;
use crate::error::{Error, Result};
use crate::generated::max as g;
use crate::generated::ModelId;
use crate::limits;
use plotters::prelude::*;

/// One curve of a figure.
struct Series {
    label: String,
    points: Vec<(f64, f64)>,
    color: RGBColor,
    dashed: bool,
}

/// One figure.
struct Figure {
    file: &'static str,
    title: String,
    x_label: &'static str,
    y_label: &'static str,
    series: Vec<Series>,
    /// x-intervals shaded (a validity range, bands), with the legend's
    /// label for them.
    shade: Vec<(f64, f64)>,
    shade_label: &'static str,
    /// Same scale on both axes (contours).
    equal: bool,
}

const BLUE: RGBColor = RGBColor(31, 90, 180);
const RED: RGBColor = RGBColor(200, 50, 40);
const GREEN: RGBColor = RGBColor(30, 140, 70);
const GREY: RGBColor = RGBColor(110, 110, 110);
const ORANGE: RGBColor = RGBColor(230, 140, 20);

fn solid(label: &str, points: Vec<(f64, f64)>, color: RGBColor) -> Series {
    Series {
        label: label.into(),
        points,
        color,
        dashed: false,
    }
}

fn dashed(label: &str, points: Vec<(f64, f64)>, color: RGBColor) -> Series {
    Series {
        label: label.into(),
        points,
        color,
        dashed: true,
    }
}

fn grid(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f64> {
    (0..n).map(move |k| lo + (hi - lo) * k as f64 / (n - 1) as f64)
}

/// The printed (18) (lacks η(s); see docs/errata.md), for comparison only.
fn printed_force(a: f64, s: f64, d: f64) -> f64 {
    std::f64::consts::PI
        * 3f64.sqrt()
        * a.powi(3)
        * (2.0 * s * s * a * d - (s + 1.0).powi(3))
        * s
        * s
        * (s + 1.0)
        / (16.0 * (s * s + 1.0) * (s * s + s + 1.0).powf(1.5))
}

/// The states of the ρ-curve sampled along the explicit branch, from large
/// approach to the fold of the contact size.
fn branch(rho: f64, n: usize) -> Result<Vec<crate::contact::State>> {
    branch_of(ModelId::Max, rho, n)
}

/// [`branch`] of the model `model`.
fn branch_of(model: ModelId, rho: f64, n: usize) -> Result<Vec<crate::contact::State>> {
    let c = Contact::with_model(model, rho)?;
    let fold = c.size_fold()?;
    let s_inf = c.s_infinity()?;
    Ok((1..n)
        .filter_map(|k| {
            // logarithmic in s∞ − s, as in the solver's walk
            let t = k as f64 / n as f64;
            c.state_at_s(s_inf - (s_inf - fold.s) * 10f64.powf(-6.0 * (1.0 - t)))
        })
        .filter(|st| st.force_bar < 40.0)
        .collect())
}

fn figures() -> Result<Vec<Figure>> {
    let rhos: Vec<f64> = grid(0.05, 1.0, 200).collect();
    let mut out = Vec::new();
    out.extend(fig2_bc_error()?);
    out.extend(fig3_axisymmetric()?);
    out.extend(fig4_zero_force_s(&rhos)?);
    out.extend(fig5_zero_force(&rhos)?);
    out.extend(figs6_to_8()?);
    out.extend(fig9_comparison()?);
    out.extend(crossing_angle()?);
    out.extend(conformal_arms()?);
    out.extend(thickness()?);
    Ok(out)
}

/// The pull-off of two equal incompressible coatings of finite thickness
/// at ρ = 1 against their thinness h/L (`layer`, docs/thickness.md), with
/// its two limits: (2)'s −3πRΔγ and JKR's −1.5πRΔγ.
fn thickness() -> Result<Vec<Figure>> {
    let (lo, hi) = (-2.3f64, 2.0f64); // h/L from 0.005 to 100
    let mut layer = Vec::new();
    for x in grid(lo, hi, 27) {
        let pull = crate::layer::Layers::equal(10f64.powf(x), 0.5)?
            .pull_off(crate::layer::Route::Griffith)?
            .load;
        layer.push((x, pull.force_bar * 2.0 / std::f64::consts::PI));
    }
    let level = |y: f64| vec![(lo, y), (hi, y)];
    Ok(vec![Figure {
        file: "thickness_pull_off.svg",
        title: "Pull-off of coatings of finite thickness at ρ = 1 (ν = ½)".into(),
        x_label: "log₁₀ h/L",
        y_label: "pull-off force F / (πRΔγ)",
        series: vec![
            solid("the layer of finite thickness", layer, BLUE),
            dashed("the thin-layer equation (2): −3", level(-3.0), RED),
            dashed("JKR's half-space: −1.5", level(-1.5), GREEN),
        ],
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    }])
}

/// `conformal:K` at ρ = 0.8: F̄ against ā on each arm of its curve (the
/// arm from large contacts and the arm that carries the pull-off), solid
/// up to an arm's first fold in ā and dashed beyond (the contour grows
/// undulated there), beside the paper's model.
fn conformal_arms() -> Result<Vec<Figure>> {
    let (lo, hi) = (2.2, 3.6);
    let inside = |a: f64, f: f64| (lo..=hi).contains(&a) && (-5.0..=25.0).contains(&f);
    let b = branch(0.8, 600)?;
    let mut series = vec![dashed(
        "max (the paper's model)",
        b.iter()
            .filter(|st| inside(st.a_bar, st.force_bar))
            .map(|st| (st.a_bar, st.force_bar))
            .collect(),
        GREY,
    )];
    for (k, color) in [(2, GREEN), (4, ORANGE), (8, BLUE)] {
        let m = crate::conformal::seeding_family(&crate::exact::Gap::CYLINDERS)
            .ok_or_else(|| crate::Error::NoState("no contour family seeds the exact solver".into()))
            .and_then(|f| crate::conformal::Conformal::member(f.name, k))?;
        let cv = m.curve(0.8, 800, 20.0)?;
        // contiguous pieces of one arm on one side of its first fold
        let mut label = m.name();
        let mut piece: Vec<(f64, f64)> = Vec::new();
        let mut key = (usize::MAX, false);
        let flush = |piece: &mut Vec<(f64, f64)>,
                     beyond: bool,
                     label: &mut String,
                     series: &mut Vec<Series>| {
            if piece.len() > 1 {
                let pts = std::mem::take(piece);
                let l = std::mem::take(label);
                series.push(if beyond {
                    dashed(&l, pts, color)
                } else {
                    solid(&l, pts, color)
                });
            }
            piece.clear();
        };
        for (i, st) in cv.states.iter().enumerate() {
            let here = (cv.arm[i], cv.beyond_size_fold[i]);
            if here != key {
                flush(&mut piece, key.1, &mut label, &mut series);
                key = here;
            }
            if inside(st.a_bar, st.force_bar) {
                piece.push((st.a_bar, st.force_bar));
            } else {
                flush(&mut piece, key.1, &mut label, &mut series);
            }
        }
        flush(&mut piece, key.1, &mut label, &mut series);
    }
    Ok(vec![Figure {
        file: "conformal_arms.svg",
        title: "conformal:K at ρ = 0.8: force against contact size on each arm".into(),
        x_label: "semi-axis ā",
        y_label: "force F̄",
        series,
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    }])
}

/// Fig. 2: quantity (14) against s.
fn fig2_bc_error() -> Result<Vec<Figure>> {
    Ok(vec![Figure {
        file: "fig2_bc_error.svg",
        title: "Fig. 2: error (14) of the boundary condition (3)₂".into(),
        x_label: "aspect ratio s",
        y_label: "(max − min)/min of ∂p/∂ν  [%]",
        series: vec![solid(
            "(14) = η(s) − 1",
            grid(0.3, 1.0, 200)
                .map(|s| (s, 100.0 * g::bc_error(s)))
                .collect(),
            BLUE,
        )],
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    }])
}

/// Fig. 3: the axisymmetric force–displacement curve.
fn fig3_axisymmetric() -> Result<Vec<Figure>> {
    let mut out = Vec::new();
    // Fig. 3: axisymmetric force–displacement.
    let (a_c, _, _) = limits::axisymmetric_critical(ModelId::Max)?;
    let stable: Vec<(f64, f64)> = grid(a_c, 3.4, 200)
        .map(|a| (g::axisymmetric_dbar(a), g::axisymmetric_force_bar(a)))
        .collect();
    let unstable: Vec<(f64, f64)> = grid(0.6, a_c, 200)
        .map(|a| (g::axisymmetric_dbar(a), g::axisymmetric_force_bar(a)))
        .filter(|p| p.0 > -3.0)
        .collect();
    let printed: Vec<(f64, f64)> = grid(0.6, 3.4, 300)
        .map(|a| {
            (
                a * a / 4.0 - 2f64.powf(4.0 / 3.0) / a,
                g::axisymmetric_force_bar(a),
            )
        })
        .filter(|p| p.0 > -3.0)
        .collect();
    out.push(Figure {
        file: "fig3_axisymmetric.svg",
        title: "Fig. 3: force–displacement, axisymmetric case ρ = 1".into(),
        x_label: "approach δ̄",
        y_label: "force F̄",
        series: vec![
            solid("derived (25), stable", stable, BLUE),
            dashed("derived (25), unstable", unstable, BLUE),
            dashed("printed (25)₁ (2^(4/3)/ā): differs", printed, RED),
        ],
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    });
    Ok(out)
}

/// Fig. 4: s against ρ at zero force, and the non-adhesive (29).
fn fig4_zero_force_s(rhos: &[f64]) -> Result<Vec<Figure>> {
    let mut out = Vec::new();
    // Fig. 4: s against ρ at zero force, and the non-adhesive (29).
    out.push(Figure {
        file: "fig4_zero_force_s.svg",
        title: "Fig. 4: aspect ratio at zero force".into(),
        x_label: "radii ratio ρ",
        y_label: "aspect ratio s",
        series: vec![
            solid(
                "(28), zero force",
                rhos.iter()
                    .map(|&r| (r, limits::zero_force_s(ModelId::Max, r).unwrap_or(f64::NAN)))
                    .collect(),
                BLUE,
            ),
            dashed(
                "(29), non-adhesive",
                rhos.iter()
                    .map(|&r| {
                        (
                            r,
                            limits::non_adhesive_s(ModelId::Max, r).unwrap_or(f64::NAN),
                        )
                    })
                    .collect(),
                GREY,
            ),
        ],
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    });
    Ok(out)
}

/// Fig. 5: δ̄ and ā at zero force against ρ.
fn fig5_zero_force(rhos: &[f64]) -> Result<Vec<Figure>> {
    let mut out = Vec::new();
    // Fig. 5: δ̄ and ā at zero force against ρ; printed (26), (27) lack η.
    let zf: Vec<(f64, f64, f64)> = rhos
        .iter()
        .filter_map(|&r| {
            Contact::new(r)
                .and_then(|c| c.zero_force())
                .ok()
                .map(|st| (r, st.delta_bar, st.a_bar))
        })
        .collect();
    let printed_zf: Vec<(f64, f64, f64)> = rhos
        .iter()
        .filter_map(|&r| limits::zero_force_s(ModelId::Max, r).ok().map(|s| (r, s)))
        .map(|(r, s)| {
            let a = (3.0 / (s * s) * (s.powi(3) + 5.0 * s * s + s + 1.0)).cbrt();
            (r, (s + 1.0).powi(3) / (2.0 * s * s) / a, a)
        })
        .collect();
    out.push(Figure {
        file: "fig5_zero_force.svg",
        title: "Fig. 5: approach and semi-axis at zero force".into(),
        x_label: "radii ratio ρ",
        y_label: "δ̄ and ā",
        series: vec![
            solid(
                "δ̄, derived (26)",
                zf.iter().map(|p| (p.0, p.1)).collect(),
                BLUE,
            ),
            solid(
                "ā, derived (27)",
                zf.iter().map(|p| (p.0, p.2)).collect(),
                GREEN,
            ),
            dashed(
                "δ̄, printed (26): differs",
                printed_zf.iter().map(|p| (p.0, p.1)).collect(),
                RED,
            ),
            dashed(
                "ā, printed (27): differs",
                printed_zf.iter().map(|p| (p.0, p.2)).collect(),
                RED,
            ),
        ],
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    });
    Ok(out)
}

/// Figs. 6–8 at ρ = 0.8.
fn figs6_to_8() -> Result<Vec<Figure>> {
    let mut out = Vec::new();
    // Figs. 6–8 at ρ = 0.8.
    let b = branch(0.8, 600)?;
    let s_inf = limits::non_adhesive_s(ModelId::Max, 0.8)?;
    let a_max = b.iter().map(|st| st.a_bar).fold(0.0, f64::max);
    out.push(Figure {
        file: "fig6_s_vs_a.svg",
        title: "Fig. 6: aspect ratio against semi-axis, ρ = 0.8".into(),
        x_label: "semi-axis ā",
        y_label: "aspect ratio s",
        series: vec![
            solid("model", b.iter().map(|st| (st.a_bar, st.s)).collect(), BLUE),
            dashed(
                "(29), non-adhesive",
                vec![(1.9, s_inf), (a_max, s_inf)],
                GREY,
            ),
        ],
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    });
    let pull = Contact::new(0.8)?.pull_off_load()?.state;
    out.push(Figure {
        file: "fig7_s_vs_force.svg",
        title: "Fig. 7: aspect ratio against force, ρ = 0.8".into(),
        x_label: "force F̄",
        y_label: "aspect ratio s",
        series: vec![
            solid(
                "derived (18)",
                b.iter()
                    .filter(|st| st.s >= pull.s)
                    .map(|st| (st.force_bar, st.s))
                    .collect(),
                BLUE,
            ),
            dashed(
                "derived (18), past pull-off",
                b.iter()
                    .filter(|st| st.s < pull.s)
                    .map(|st| (st.force_bar, st.s))
                    .collect(),
                BLUE,
            ),
            dashed(
                "printed (18) (no η): differs",
                b.iter()
                    .map(|st| (printed_force(st.a_bar, st.s, st.delta_bar), st.s))
                    .collect(),
                RED,
            ),
        ],
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    });
    let non_adhesive: Vec<(f64, f64)> = grid(0.0, 3.0, 100)
        .map(|d| {
            // Δγ → 0 at fixed δ̄/ā² (the limit of the derivation): F̄ ∝ δ̄³
            let s = s_inf;
            let a = (2.0 * d * (3.0 * s * s + 1.0) / (s * s + 1.0)).sqrt();
            (
                d,
                std::f64::consts::PI * a.powi(3) * s * (2.0 * g::eta(s) * s * s * d * a)
                    / (24.0 * g::eta(s) * (s * s + 1.0)),
            )
        })
        .collect();
    out.push(Figure {
        file: "fig8_force_displacement.svg",
        title: "Fig. 8: force–displacement, ρ = 0.8".into(),
        x_label: "approach δ̄",
        y_label: "force F̄",
        series: vec![
            solid(
                "derived (18)",
                b.iter()
                    .filter(|st| st.s >= pull.s)
                    .map(|st| (st.delta_bar, st.force_bar))
                    .collect(),
                BLUE,
            ),
            dashed(
                "derived, past pull-off",
                b.iter()
                    .filter(|st| st.s < pull.s)
                    .map(|st| (st.delta_bar, st.force_bar))
                    .collect(),
                BLUE,
            ),
            dashed("non-adhesive", non_adhesive, GREY),
            dashed(
                "printed (18): differs",
                b.iter()
                    .map(|st| (st.delta_bar, printed_force(st.a_bar, st.s, st.delta_bar)))
                    .collect(),
                RED,
            ),
        ],
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    });
    Ok(out)
}

/// Fig. 9: comparison across ρ.
fn fig9_comparison() -> Result<Vec<Figure>> {
    let mut out = Vec::new();
    // Fig. 9: comparison across ρ.
    let (a_c, _, _) = limits::axisymmetric_critical(ModelId::Max)?;
    let mut series = vec![solid(
        "ρ = 1 (exact)",
        grid(a_c * 0.7, 3.4, 200)
            .map(|a| (g::axisymmetric_dbar(a), g::axisymmetric_force_bar(a)))
            .collect(),
        BLUE,
    )];
    for (rho, color) in [(0.8, GREEN), (0.6, RED)] {
        let br = branch(rho, 600)?;
        series.push(solid(
            &format!("ρ = {rho}"),
            br.iter().map(|st| (st.delta_bar, st.force_bar)).collect(),
            color,
        ));
    }
    out.push(Figure {
        file: "fig9_comparison.svg",
        title: "Fig. 9: force–displacement for several ρ".into(),
        x_label: "approach δ̄",
        y_label: "force F̄",
        series,
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    });
    Ok(out)
}

/// Pull-off of equal cylinders against their crossing angle.
fn crossing_angle() -> Result<Vec<Figure>> {
    let mut out = Vec::new();
    // Crossing angle of two equal cylinders: ρ = tan²(θ/2).
    let thetas: Vec<f64> = grid(20.0, 90.0, 141).collect();
    let mut s_pts = Vec::new();
    let mut f_pts = Vec::new();
    for &th in &thetas {
        let rho = (th.to_radians() / 2.0).tan().powi(2).min(1.0);
        let po = Contact::new(rho)?.pull_off_load()?.state;
        s_pts.push((th, po.s));
        f_pts.push((th, -po.force_bar / (1.5 * std::f64::consts::PI)));
    }
    let theta_08 = 2.0 * 0.8f64.sqrt().atan().to_degrees();
    out.push(Figure {
        file: "crossing_angle.svg",
        title: "Equal cylinders crossed at θ: pull-off (ρ = tan²(θ/2))".into(),
        x_label: "crossing angle θ [degrees]",
        y_label: "s, and |F̄| / (3π/2) at pull-off",
        series: vec![
            solid("aspect ratio s at pull-off", s_pts, BLUE),
            solid("pull-off force |F̄|/(3π/2)", f_pts, RED),
        ],
        shade: vec![(theta_08, 90.0)],
        shade_label: "paper's range ρ ≥ 0.8",
        equal: false,
    });
    Ok(out)
}

fn render(fig: &Figure) -> Result<String> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (720, 480)).into_drawing_area();
        let err = |e: &dyn std::fmt::Display| Error::NoState(format!("drawing {}: {e}", fig.file));
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let finite = |p: &&(f64, f64)| p.0.is_finite() && p.1.is_finite();
        let pts: Vec<(f64, f64)> = fig
            .series
            .iter()
            .flat_map(|s| s.points.iter().filter(finite).copied())
            .collect();
        let (mut x0, mut x1, mut y0, mut y1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for (x, y) in &pts {
            x0 = x0.min(*x);
            x1 = x1.max(*x);
            y0 = y0.min(*y);
            y1 = y1.max(*y);
        }
        let pad = |lo: f64, hi: f64| {
            let d = (hi - lo).max(1e-9) * 0.05;
            (lo - d, hi + d)
        };
        let ((mut x0, mut x1), (mut y0, mut y1)) = (pad(x0, x1), pad(y0, y1));
        if fig.equal {
            // the plotting area is about 620 × 400 pixels: widen the
            // shorter range about its middle so one unit is as long on
            // both axes
            let ratio = 620.0 / 400.0;
            let (w, h) = (x1 - x0, y1 - y0);
            if w / h < ratio {
                let (m, half) = (0.5 * (x0 + x1), 0.5 * h * ratio);
                (x0, x1) = (m - half, m + half);
            } else {
                let (m, half) = (0.5 * (y0 + y1), 0.5 * w / ratio);
                (y0, y1) = (m - half, m + half);
            }
        }
        let mut chart = ChartBuilder::on(&root)
            .caption(&fig.title, ("sans-serif", 20))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|e| err(&e))?;
        chart
            .configure_mesh()
            .x_desc(fig.x_label)
            .y_desc(fig.y_label)
            .draw()
            .map_err(|e| err(&e))?;
        if !fig.shade.is_empty() {
            chart
                .draw_series(fig.shade.iter().map(|&(a, b)| {
                    Rectangle::new([(a, y0), (b, y1)], RGBColor(220, 235, 250).filled())
                }))
                .map_err(|e| err(&e))?
                .label(fig.shade_label)
                .legend(|(x, y)| {
                    Rectangle::new(
                        [(x, y - 5), (x + 18, y + 5)],
                        RGBColor(220, 235, 250).filled(),
                    )
                });
        }
        for s in &fig.series {
            let color = s.color;
            let pts: Vec<(f64, f64)> = s.points.iter().filter(finite).copied().collect();
            let drawn = if s.dashed {
                chart
                    .draw_series(DashedLineSeries::new(pts, 6, 4, color.stroke_width(2)))
                    .map_err(|e| err(&e))?
            } else {
                chart
                    .draw_series(LineSeries::new(pts, color.stroke_width(2)))
                    .map_err(|e| err(&e))?
            };
            // a series without a label (a further piece of a labelled one)
            // stays out of the legend
            if !s.label.is_empty() {
                drawn.label(&s.label).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
                });
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))?;
    }
    Ok(svg)
}

/// The band map of the exact family (docs/figures/exact_bands.svg) from
/// the maps `bands` (one per ρ, as `thinjkr exact bands --json` writes
/// them): each band a bar over its ā-interval at its ρ, coloured by its
/// contour mode; the circle's neutral points ā³ = 4(n − 1) dashed; the
/// reach of each size from `reach`, the lines `thinjkr exact reach --json`
/// writes (ā and the smallest ρ its state continued from the circle at
/// fixed ā reaches, in order of ā; a size without one left out, the line
/// broken there): the same map by a second route at every ρ; the exact
/// pull-off's ā from `reference`. With the feature `cli`, whose study
/// (`thinjkr exact reach`) the reach map is.
#[cfg(feature = "cli")]
pub fn exact_bands(
    bands: &[crate::report::BandMap],
    reach: &str,
    reference: &crate::accuracy::Reference,
) -> Result<(&'static str, String)> {
    let reach: Vec<(f64, Option<f64>)> = crate::studies::reach::from_json_lines(reach)?
        .iter()
        .map(|p| (p.a_bar, crate::studies::reach::reach_of(p)))
        .collect();
    // one colour per mode n = 2, 4, …, 16
    let colors = [
        RGBColor(120, 120, 120),
        BLUE,
        RED,
        GREEN,
        ORANGE,
        RGBColor(130, 60, 160),
        RGBColor(140, 90, 40),
        RGBColor(0, 150, 150),
    ];
    let color = |n: usize| colors[(n / 2).saturating_sub(1) % colors.len()];
    let (lo, hi) = bands
        .iter()
        .map(|m| m.rho)
        .chain(reach.iter().filter_map(|p| p.1))
        .chain(reference.pull_off.iter().map(|e| e.rho))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), r| {
            (a.min(r), b.max(r))
        });
    let mut series = Vec::new();
    // the reach, one line per run of sizes that have one
    for (k, run) in reach
        .split(|p| p.1.is_none())
        .filter(|run| !run.is_empty())
        .enumerate()
    {
        let label = if k == 0 {
            "the reach of each size ā (fold in ρ at fixed ā, from the circle)"
        } else {
            ""
        };
        let pts = run.iter().filter_map(|&(a, r)| r.map(|r| (a, r))).collect();
        series.push(solid(label, pts, GREY));
    }
    let mut labelled = Vec::new();
    for m in bands {
        for b in &m.bands {
            let n = b.lower.mode.unwrap_or(0);
            let label = if labelled.contains(&n) {
                String::new()
            } else {
                labelled.push(n);
                format!("band, mode cos {n}θ")
            };
            series.push(solid(
                &label,
                vec![(b.lower.a_bar, m.rho), (b.upper.a_bar, m.rho)],
                color(n),
            ));
        }
    }
    labelled.sort_unstable();
    // the circle's neutral points within the range screened, dashed in
    // their mode's colour, one legend entry for all
    let range = bands
        .iter()
        .map(|m| (m.range[0], m.range[1]))
        .chain(reach.iter().map(|p| (p.0, p.0)))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), (c, d)| {
            (a.min(c), b.max(d))
        });
    let mut first = true;
    for &n in &labelled {
        let a = (4.0 * (n as f64 - 1.0)).cbrt();
        if a < range.0 || a > range.1 {
            continue;
        }
        let label = if std::mem::take(&mut first) {
            "the circle's neutral points ā³ = 4(n − 1)"
        } else {
            ""
        };
        series.push(dashed(
            label,
            vec![(a, lo - 0.05), (a, hi + 0.05)],
            color(n),
        ));
    }
    let po: Vec<(f64, f64)> = reference
        .pull_off
        .iter()
        .filter(|e| e.rho >= lo - 1e-12 && e.rho <= hi + 1e-12)
        .map(|e| (e.a_bar, e.rho))
        .collect();
    series.push(solid("exact pull-off", po, BLACK));
    let fig = Figure {
        file: "exact_bands.svg",
        title: "No near-elliptic exact state: the bands in ā, and the reach of each size".into(),
        x_label: "ā",
        y_label: "ρ = R₁/R₂",
        series,
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    };
    Ok((fig.file, render(&fig)?))
}

/// The band maps with the F̄(ā) curves they carry, one figure per ρ of
/// `BANDS_FORCE_FILES` (others are not drawn), for ā in [2, 3.2] (the
/// bands of modes 4, 6 and 8 and the pull-off): the bands shaded, the exact
/// family's F̄ at its sampled sizes (a line through them, broken where a
/// sample is missing), `conformal:8`'s at every grid point, and each
/// ellipse model's along its explicit branch.
pub fn exact_bands_force(bands: &[crate::report::BandMap]) -> Result<Vec<(&'static str, String)>> {
    let (lo, hi) = (2.0, 3.2);
    let mut out = Vec::new();
    for m in bands {
        let Some(&(_, file)) = BANDS_FORCE_FILES.iter().find(|(r, _)| *r == m.rho) else {
            continue;
        };
        let inside = |a: f64| (lo..=hi).contains(&a);
        let mut series = Vec::new();
        // pieces of a sampled curve between missing samples
        let pieces = |of: &dyn Fn(&crate::report::CurvePoint) -> Option<f64>| {
            let mut all: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
            for p in m.curve.iter().filter(|p| inside(p.a_bar)) {
                match of(p) {
                    Some(f) => all.last_mut().expect("one").push((p.a_bar, f)),
                    None if p.model.is_none() => all.push(Vec::new()),
                    None => {}
                }
            }
            all.retain(|v| v.len() > 1);
            all
        };
        for (k, piece) in pieces(&|p| p.model).into_iter().enumerate() {
            let label = if k == 0 { m.screen.as_str() } else { "" };
            series.push(dashed(label, piece, BLUE));
        }
        for (model, color) in ModelId::ALL.iter().zip([GREY, RED, GREEN, ORANGE]) {
            let pts: Vec<(f64, f64)> = branch_of(*model, m.rho, 400)?
                .iter()
                .filter(|st| inside(st.a_bar) && st.force_bar < 12.0)
                .map(|st| (st.a_bar, st.force_bar))
                .collect();
            series.push(dashed(&format!("model {model}"), pts, color));
        }
        for (k, piece) in pieces(&|p| p.exact).into_iter().enumerate() {
            let label = if k == 0 { "exact (2)–(3)" } else { "" };
            series.push(solid(label, piece, BLACK));
        }
        out.push(
            (Figure {
                file,
                title: format!(
                    "F̄ against ā at ρ = {}: bands of the exact family shaded",
                    m.rho
                ),
                x_label: "ā",
                y_label: "F̄",
                series,
                shade: m
                    .bands
                    .iter()
                    .filter(|b| b.upper.a_bar > lo && b.lower.a_bar < hi)
                    .map(|b| (b.lower.a_bar.max(lo), b.upper.a_bar.min(hi)))
                    .collect(),
                shade_label: "no near-elliptic exact state",
                equal: false,
            })
            .rendered()?,
        );
    }
    Ok(out)
}

/// The files of [`exact_bands_force`], by ρ.
pub(crate) const BANDS_FORCE_FILES: [(f64, &str); 6] = [
    (0.9, "exact_bands_force_0.9.svg"),
    (0.8, "exact_bands_force_0.8.svg"),
    (0.7, "exact_bands_force_0.7.svg"),
    (0.6, "exact_bands_force_0.6.svg"),
    (0.5, "exact_bands_force_0.5.svg"),
    (0.4, "exact_bands_force_0.4.svg"),
];

impl Figure {
    fn rendered(&self) -> Result<(&'static str, String)> {
        Ok((self.file, render(self)?))
    }
}

/// The exact solution's figures from `reference`: the pull-off F̄ against
/// ρ and against the crossing angle θ (exact and every model), the exact contours at pull-off beside the
/// paper's ellipse at ρ = 0.8, 0.5 and the lowest resolved ρ, and
/// |∂p̄/∂ν − 1| along the contour at ρ = 0.8 and 0.5 for the paper's model and
/// the exact solution.
pub fn exact_all(reference: &crate::accuracy::Reference) -> Result<Vec<(&'static str, String)>> {
    exact_figures(reference)?
        .iter()
        .map(|f| Ok((f.file, render(f)?)))
        .collect()
}

/// Model `m`'s load-controlled pull-off F̄ at the points (x, ρ) of `xs`, as
/// a series against x. A model without a pull-off at some ρ (apexes and
/// apex45 below about 0.2) is drawn where it has one, and its label says at
/// how many of the points (`x_name`) it has none.
fn model_pull_offs(m: ModelId, xs: &[(f64, f64)], x_name: &str, color: RGBColor) -> Series {
    let pts: Vec<(f64, f64)> = xs
        .iter()
        .filter_map(|&(x, rho)| {
            Contact::with_model(m, rho)
                .and_then(|c| c.pull_off_load())
                .map(|p| (x, p.state.force_bar))
                .ok()
        })
        .collect();
    let gaps = xs.len() - pts.len();
    let label = if gaps == 0 {
        format!("model {m}")
    } else {
        format!("model {m} (no pull-off at {gaps} of {} {x_name})", xs.len())
    };
    solid(&label, pts, color)
}

/// Each slender model's load-controlled pull-off F̄ = G_min ρ^(1/2) at the
/// points (x, ρ) of `xs`, dashed (the limit ρ → 0, not an ellipse model).
fn slender_pull_offs(xs: &[(f64, f64)]) -> Vec<Series> {
    crate::slender::Slender::all()
        .map(|m| {
            let pts = xs
                .iter()
                .filter_map(|&(x, rho)| m.pull_off_load(rho).map(|p| (x, p.force_bar)).ok())
                .collect();
            dashed(&format!("{} (the limit ρ → 0)", m.name()), pts, MAGENTA)
        })
        .collect()
}

fn exact_figures(reference: &crate::accuracy::Reference) -> Result<Vec<Figure>> {
    let po = &reference.pull_off;
    let entry = |rho: f64| {
        po.iter().find(|e| e.rho == rho).ok_or_else(|| {
            Error::NoState(format!(
                "the exact reference has no pull-off at rho = {rho}"
            ))
        })
    };
    let lowest = po.iter().map(|e| e.rho).fold(f64::INFINITY, f64::min);
    // the exact curve: the reference's pull-offs and, between them, the
    // stored ones (resolved states of the same follow, `exact::stored`)
    // down to the reference's lowest ρ
    let mut exact_curve: Vec<(f64, f64)> = po.iter().map(|e| (e.rho, e.force_bar)).collect();
    if let Some(table) = crate::exact::stored::stored() {
        exact_curve.extend(
            table
                .pull_offs
                .iter()
                .filter(|q| q.rho >= lowest && po.iter().all(|e| (e.rho - q.rho).abs() > 1e-9))
                .map(|q| (q.rho, q.force_bar)),
        );
    }
    exact_curve.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut out = pull_off_figures(&exact_curve, lowest);
    out.push(contours_figure(&entry, lowest)?);
    out.push(bc_error_figure(&entry)?);
    out.push(conformal_convergence_figure(po));
    Ok(out)
}

/// An entry of the exact reference at ρ, or why there is none.
type Entry<'a> = &'a dyn Fn(f64) -> Result<&'a crate::accuracy::ReferenceState>;

/// The load-controlled pull-off against ρ and against the crossing
/// angle θ: the exact curve and every model's.
fn pull_off_figures(exact_curve: &[(f64, f64)], lowest: f64) -> Vec<Figure> {
    let mut out = Vec::new();
    // 1. pull-off force against ρ
    let colors = [BLUE, RED, GREEN, ORANGE];
    let mut series = vec![solid("exact (2)–(3)", exact_curve.to_vec(), BLACK)];
    let xs: Vec<(f64, f64)> = grid(lowest, 1.0, 31).map(|rho| (rho, rho)).collect();
    for (m, &c) in ModelId::ALL.iter().zip(&colors) {
        series.push(model_pull_offs(*m, &xs, "ρ", c));
    }
    series.extend(slender_pull_offs(&xs));
    out.push(Figure {
        file: "exact_pull_off.svg",
        title: "Load-controlled pull-off: the exact solution and the models".into(),
        x_label: "ρ = R₁/R₂",
        y_label: "F̄ at pull-off",
        series,
        shade: vec![(0.8, 1.0)],
        shade_label: "paper's range ρ ≥ 0.8",
        equal: false,
    });
    // 1b. the same against the crossing angle θ of two equal cylinders
    // (ρ = tan²(θ/2)), from θ = 16° (ρ = 0.02) to 90°
    let theta_of = |rho: f64| 2.0 * rho.sqrt().atan().to_degrees();
    let mut series = vec![solid(
        "exact (2)–(3)",
        exact_curve
            .iter()
            .map(|&(rho, f)| (theta_of(rho), f))
            .collect(),
        BLACK,
    )];
    let xs: Vec<(f64, f64)> = grid(16.0, 90.0, 75)
        .map(|th| (th, (th.to_radians() / 2.0).tan().powi(2).min(1.0)))
        .collect();
    for (m, &c) in ModelId::ALL.iter().zip(&colors) {
        series.push(model_pull_offs(*m, &xs, "θ", c));
    }
    series.extend(slender_pull_offs(&xs));
    out.push(Figure {
        file: "exact_crossing_angle.svg",
        title: format!(
            "Equal cylinders crossed at θ: pull-off, exact (resolved for θ ≥ {:.0}°) and the models",
            theta_of(lowest)
        ),
        x_label: "crossing angle θ [degrees] (ρ = tan²(θ/2))",
        y_label: "F̄ at pull-off",
        series,
        shade: vec![(theta_of(0.8), 90.0)],
        shade_label: "paper's range ρ ≥ 0.8",
        equal: false,
    });
    out
}

/// The exact contours at pull-off beside the paper's ellipses.
fn contours_figure(entry: Entry, lowest: f64) -> Result<Figure> {
    let colors = [BLUE, RED, GREEN, ORANGE];
    // 2. contours at pull-off
    let mut series = Vec::new();
    let mut rhos = vec![0.8, 0.5];
    if lowest < 0.5 {
        rhos.push(lowest);
    }
    for (&rho, &c) in rhos.iter().zip(&colors) {
        let e = entry(rho)?;
        let z: Vec<(f64, f64)> = grid(0.0, 2.0 * std::f64::consts::PI, 241)
            .map(|t| {
                let [z, _, _] = e.contour.at(t);
                (z.re, z.im)
            })
            .collect();
        series.push(solid(&format!("exact, ρ = {rho}"), z, c));
        let m = Contact::new(rho)?.pull_off_load()?.state;
        let ell = grid(0.0, 2.0 * std::f64::consts::PI, 241)
            .map(|t| (m.a_bar * t.cos(), m.b_bar * t.sin()))
            .collect();
        series.push(dashed(&format!("paper's ellipse, ρ = {rho}"), ell, c));
    }
    Ok(Figure {
        file: "exact_contours.svg",
        title: format!(
            "Contact at pull-off: exact contour and the paper's ellipse (ρ < {lowest}: not resolved)"
        ),
        x_label: "X",
        y_label: "Y",
        series,
        shade: Vec::new(),
        shade_label: "",
        equal: true,
    })
}

/// The boundary condition (3)₂ along the contour at pull-off: the
/// exact solution's and the paper's model's.
fn bc_error_figure(entry: Entry) -> Result<Figure> {
    use crate::exact::{Exact, ExactState, Truncation};
    let colors = [BLUE, RED, GREEN, ORANGE];
    // 3. |∂p̄/∂ν − 1| along the contour; the exact solution's is at the
    // round-off level of its boundary integral (below 1e-9 at every point,
    // docs/accuracy.md), whose digits differ between builds: both curves
    // are floored at 1e-9 so that the drawing is reproducible
    let floor = 1e-9;
    let mut series = Vec::new();
    for (&rho, &c) in [0.8, 0.5].iter().zip(&colors) {
        let e = entry(rho)?;
        let ex = Exact::new(
            rho,
            Truncation {
                modes: e.modes,
                points: e.points,
                arclength: e.contour.c.len(),
            },
        )?;
        let st = ExactState {
            rho,
            a_bar: e.a_bar,
            b_bar: e.a_bar * e.s,
            s: e.s,
            delta_bar: e.delta_bar,
            force_bar: e.force_bar,
            contour: e.contour.clone(),
            bc_error: e.bc_error,
            deviation_from_ellipse: 0.0,
            truncation: ex.truncation(),
            stability: Default::default(),
            route: Default::default(),
            shape: None,
            coatings: None,
            warnings: Vec::new(),
            gap: crate::exact::Gap::CYLINDERS,
        };
        let exact: Vec<(f64, f64)> = ex
            .boundary_profile(&st)?
            .into_iter()
            .map(|(phi, dn)| (phi.to_degrees(), (dn - 1.0).abs().max(floor).log10()))
            .collect();
        let contact = Contact::new(rho)?;
        let m = contact.pull_off_load()?.state;
        let model: Vec<(f64, f64)> = grid(0.0, std::f64::consts::FRAC_PI_2, 181)
            .map(|t| {
                let u = t.sin().powi(2);
                let phi = (m.b_bar * t.sin()).atan2(m.a_bar * t.cos());
                let dn = contact.normal_derivative(&m, u);
                (phi.to_degrees(), (dn - 1.0).abs().max(floor).log10())
            })
            .collect();
        series.push(solid(&format!("exact, ρ = {rho}"), exact, c));
        series.push(dashed(&format!("paper's model, ρ = {rho}"), model, c));
    }
    Ok(Figure {
        file: "exact_bc_error.svg",
        title: "Boundary condition (3)₂ along the contour at pull-off".into(),
        x_label: "polar angle of the contour point [degrees]",
        y_label: "log₁₀ |∂p̄/∂ν − 1| (floored at 1e-9)",
        series,
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    })
}

/// The conformal family's pull-off error against K, per ρ of the
/// reference.
fn conformal_convergence_figure(po: &[crate::accuracy::ReferenceState]) -> Figure {
    // 4. the conformal family's pull-off error against K, per ρ
    let mut series = Vec::new();
    let colors = [BLUE, RED, GREEN, ORANGE, GREY, BLACK];
    for (e, &c) in po.iter().filter(|e| e.rho < 1.0).zip(colors.iter().cycle()) {
        // a member whose pull-off is not reached is left out of the line
        // and named in its label (docs/accuracy.md says why)
        let (mut pts, mut missing) = (Vec::new(), Vec::new());
        let seed_family =
            crate::conformal::seeding_family(&crate::exact::Gap::CYLINDERS).map(|f| f.name);
        for m in crate::conformal::members().filter(|m| Some(m.family().name) == seed_family) {
            match m.pull_off(e.rho, crate::fold::FoldCondition::Load) {
                Ok((st, _)) => {
                    let err = (st.force_bar / e.force_bar - 1.0).abs().max(1e-12);
                    pts.push((m.terms() as f64, err.log10()));
                }
                Err(_) => missing.push(m.terms().to_string()),
            }
        }
        if pts.is_empty() {
            // no member reaches a pull-off (below ρ = 0.3 the family refuses)
            continue;
        }
        let label = if missing.is_empty() {
            format!("ρ = {}", e.rho)
        } else {
            format!("ρ = {} (not reached: K = {})", e.rho, missing.join(", "))
        };
        series.push(solid(&label, pts, c));
    }
    Figure {
        file: "conformal_convergence.svg",
        title: "conformal:K against the exact pull-off".into(),
        x_label: "K (terms of the map)",
        y_label: "log₁₀ |F̄_K / F̄_exact − 1| (floored at 1e-12)",
        series,
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    }
}

/// The map of (2)'s pull-off error against the coatings' thinness, one
/// line per crossing angle (`thinjkr thickness-map --figure`,
/// docs/figures/thickness_map.svg), from the map's `points`: the layer's
/// pull-offs that were found, and a dashed zero.
#[cfg(feature = "cli")]
pub(crate) fn thickness_map(points: &[crate::report::ThicknessPoint]) -> Result<String> {
    use crate::report::ThicknessAnswer;
    const COLORS: [RGBColor; 7] = [
        RED,
        ORANGE,
        GREEN,
        RGBColor(20, 160, 170),
        BLUE,
        RGBColor(120, 60, 170),
        GREY,
    ];
    let mut series = Vec::new();
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (k, row) in points
        .chunk_by(|p, q| p.theta_deg == q.theta_deg)
        .enumerate()
    {
        let line: Vec<(f64, f64)> = row
            .iter()
            .filter_map(|p| match p.layer {
                ThicknessAnswer::Found { error_2, .. } => {
                    Some((p.thinness.log10(), 100.0 * error_2))
                }
                ThicknessAnswer::None { .. } => None,
            })
            .collect();
        for p in row {
            lo = lo.min(p.thinness.log10());
            hi = hi.max(p.thinness.log10());
        }
        if !line.is_empty() {
            series.push(solid(
                &format!("θ = {}°", crate::error::short(row[0].theta_deg)),
                line,
                COLORS[k % COLORS.len()],
            ));
        }
    }
    series.push(dashed("(2) exact", vec![(lo, 0.0), (hi, 0.0)], GREY));
    render(&Figure {
        file: "thickness_map.svg",
        title: "(2)'s pull-off error against the layer of finite thickness (ν = ½)".into(),
        x_label: "log₁₀ h/L",
        y_label: "(2)'s error −F₍₂₎/F − 1 [%]",
        series,
        shade: Vec::new(),
        shade_label: "",
        equal: false,
    })
}

/// Every figure as (file name, SVG text).
pub fn all() -> Result<Vec<(&'static str, String)>> {
    figures()?
        .iter()
        .map(|f| Ok((f.file, render(f)?)))
        .collect()
}

#[cfg(all(test, feature = "cli"))]
mod tests {
    /// docs/figures/thickness_map.svg is the map drawn from the committed
    /// points (the slow tier computes both again).
    #[test]
    fn the_thickness_map_s_figure_is_the_committed_points() {
        let points = crate::studies::thickness_map::committed();
        let figure = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../docs/figures/thickness_map.svg"
        ))
        .unwrap();
        assert!(
            figure == super::thickness_map(&points).unwrap(),
            "docs/figures/thickness_map.svg is stale: `thinjkr thickness-map --json --figure docs/figures/thickness_map.svg > docs/data/thickness_map.jsonl`"
        );
    }
}
