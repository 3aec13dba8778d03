//! The paper's Figures 2–9 and a crossing-angle figure, drawn as SVG with
//! plotters from the derived (corrected) model. Where a figure depends on a
//! printed equation that the checker found to differ ((18), (25)₁, (26),
//! (27)), the printed version is drawn too, dashed and labelled, so that the
//! difference can be seen. Output is deterministic.
//!
//! Owns: figure data and rendering. May use: `contact`, `curve`, `limits`,
//! `generated` (the paper's model `max`, whose figures these are).

use crate::contact::Contact;
use crate::error::{Error, Result};
use crate::generated::max as g;
use crate::limits;
use crate::model::ModelId;
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
    /// x-interval shaded (for the validity range).
    shade: Option<(f64, f64)>,
}

const BLUE: RGBColor = RGBColor(31, 90, 180);
const RED: RGBColor = RGBColor(200, 50, 40);
const GREEN: RGBColor = RGBColor(30, 140, 70);
const GREY: RGBColor = RGBColor(110, 110, 110);

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
    let c = Contact::new(rho)?;
    let fold = c.size_fold()?;
    let s_inf = c.s_infinity()?;
    Ok((1..n)
        .filter_map(|k| {
            // logarithmic in s∞ − s, as in the solver's walk
            let t = k as f64 / n as f64;
            c.state_at_s(s_inf - (s_inf - fold.s) * 10f64.powf(-6.0 * (1.0 - t)))
        })
        .filter(|st| st.force < 40.0)
        .collect())
}

fn figures() -> Result<Vec<Figure>> {
    let mut out = Vec::new();
    // Fig. 2: quantity (14) against s.
    out.push(Figure {
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
        shade: None,
    });
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
        shade: None,
    });
    // Fig. 4: s against ρ at zero force, and the non-adhesive (29).
    let rhos: Vec<f64> = grid(0.05, 1.0, 200).collect();
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
        shade: None,
    });
    // Fig. 5: δ̄ and ā at zero force against ρ; printed (26), (27) lack η.
    let zf: Vec<(f64, f64, f64)> = rhos
        .iter()
        .filter_map(|&r| {
            Contact::new(r)
                .and_then(|c| c.zero_force())
                .ok()
                .map(|st| (r, st.delta, st.a))
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
        shade: None,
    });
    // Figs. 6–8 at ρ = 0.8.
    let b = branch(0.8, 600)?;
    let s_inf = limits::non_adhesive_s(ModelId::Max, 0.8)?;
    let a_max = b.iter().map(|st| st.a).fold(0.0, f64::max);
    out.push(Figure {
        file: "fig6_s_vs_a.svg",
        title: "Fig. 6: aspect ratio against semi-axis, ρ = 0.8".into(),
        x_label: "semi-axis ā",
        y_label: "aspect ratio s",
        series: vec![
            solid("model", b.iter().map(|st| (st.a, st.s)).collect(), BLUE),
            dashed(
                "(29), non-adhesive",
                vec![(1.9, s_inf), (a_max, s_inf)],
                GREY,
            ),
        ],
        shade: None,
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
                    .map(|st| (st.force, st.s))
                    .collect(),
                BLUE,
            ),
            dashed(
                "derived (18), past pull-off",
                b.iter()
                    .filter(|st| st.s < pull.s)
                    .map(|st| (st.force, st.s))
                    .collect(),
                BLUE,
            ),
            dashed(
                "printed (18) (no η): differs",
                b.iter()
                    .map(|st| (printed_force(st.a, st.s, st.delta), st.s))
                    .collect(),
                RED,
            ),
        ],
        shade: None,
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
                    .map(|st| (st.delta, st.force))
                    .collect(),
                BLUE,
            ),
            dashed(
                "derived, past pull-off",
                b.iter()
                    .filter(|st| st.s < pull.s)
                    .map(|st| (st.delta, st.force))
                    .collect(),
                BLUE,
            ),
            dashed("non-adhesive", non_adhesive, GREY),
            dashed(
                "printed (18): differs",
                b.iter()
                    .map(|st| (st.delta, printed_force(st.a, st.s, st.delta)))
                    .collect(),
                RED,
            ),
        ],
        shade: None,
    });
    // Fig. 9: comparison across ρ.
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
            br.iter().map(|st| (st.delta, st.force)).collect(),
            color,
        ));
    }
    out.push(Figure {
        file: "fig9_comparison.svg",
        title: "Fig. 9: force–displacement for several ρ".into(),
        x_label: "approach δ̄",
        y_label: "force F̄",
        series,
        shade: None,
    });
    // Crossing angle of two equal cylinders: ρ = tan²(θ/2).
    let thetas: Vec<f64> = grid(20.0, 90.0, 141).collect();
    let mut s_pts = Vec::new();
    let mut f_pts = Vec::new();
    for &th in &thetas {
        let rho = (th.to_radians() / 2.0).tan().powi(2).min(1.0);
        let po = Contact::new(rho)?.pull_off_load()?.state;
        s_pts.push((th, po.s));
        f_pts.push((th, -po.force / (1.5 * std::f64::consts::PI)));
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
        shade: Some((theta_08, 90.0)),
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
        let ((x0, x1), (y0, y1)) = (pad(x0, x1), pad(y0, y1));
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
        if let Some((a, b)) = fig.shade {
            chart
                .draw_series(std::iter::once(Rectangle::new(
                    [(a, y0), (b, y1)],
                    RGBColor(220, 235, 250).filled(),
                )))
                .map_err(|e| err(&e))?
                .label("paper's range ρ ≥ 0.8")
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
            if s.dashed {
                chart
                    .draw_series(DashedLineSeries::new(pts, 6, 4, color.stroke_width(2)))
                    .map_err(|e| err(&e))?
                    .label(&s.label)
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
                    });
            } else {
                chart
                    .draw_series(LineSeries::new(pts, color.stroke_width(2)))
                    .map_err(|e| err(&e))?
                    .label(&s.label)
                    .legend(move |(x, y)| {
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

/// Every figure as (file name, SVG text).
pub fn all() -> Result<Vec<(&'static str, String)>> {
    figures()?
        .iter()
        .map(|f| Ok((f.file, render(f)?)))
        .collect()
}

/// Write every figure into `dir`.
pub fn write(dir: &std::path::Path) -> Result<Vec<std::path::PathBuf>> {
    std::fs::create_dir_all(dir)
        .map_err(|e| Error::NoState(format!("cannot create {}: {e}", dir.display())))?;
    all()?
        .into_iter()
        .map(|(name, svg)| {
            let p = dir.join(name);
            std::fs::write(&p, svg)
                .map_err(|e| Error::NoState(format!("cannot write {}: {e}", p.display())))?;
            Ok(p)
        })
        .collect()
}
