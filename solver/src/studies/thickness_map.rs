//! The map of (2)'s pull-off error against the coatings' thinness h/L and
//! the crossing angle θ (issue 71, item 4; `thinjkr thickness-map`,
//! docs/thickness.md and docs/data/thickness_map.jsonl): equal
//! incompressible coatings on equal cylinders (ρ = tan²(θ/2)), the
//! layer's pull-off under load control (at ρ = 1 the axisymmetric layer,
//! below it the layer in the plane: the sharp edge's, else the grid's)
//! against (2)'s exact pull-off at the same ρ, which in the units (17) is
//! the same at every thinness. Every point gets a row: where the layer has
//! no pull-off, the row says why.
//!
//! Owns: [`map`], [`markdown`], [`THETAS`], [`THINS`], [`MAX_POINTS`].
//! May use: `layer` (the pair, its pull-offs), `exact` ((2)'s exact
//! pull-off), `report` (the point's shape), `error`, `newton` (the stop
//! request), `progress`.

use crate::error::{short, Error, Result};
use crate::layer::{Layers, Route};
use crate::report::{ThicknessAnswer, ThicknessPoint};

/// The map's crossing angles, degrees: docs/exact.md's ten-angle table's
/// from 30° up, where either of the layer's methods in the plane may
/// answer.
pub(crate) const THETAS: [f64; 7] = [30.0, 40.0, 50.0, 60.0, 70.0, 80.0, 90.0];

/// The map's thinnesses h/L: from the layer in the plane's thinnest (0.3)
/// to its thickest (10).
pub(crate) const THINS: [f64; 7] = [0.3, 0.5, 0.73, 1.0, 2.0, 5.0, 10.0];

/// The bound on the axisymmetric layer's pull-off, relative: halving its
/// panels and raising its modes by half moves a state by less than 1e-10,
/// and its two routes agree within 4.2e-10 (docs/thickness.md, "Checks").
const AXISYMMETRIC_BOUND: f64 = 1e-9;

/// The most points one map may ask for: each takes seconds to a minute.
pub(crate) const MAX_POINTS: usize = 400;

/// The map at every (θ, h/L) of `thetas` × `thins`, θ outer; `visit` sees
/// each point as it is found. An error only where (2)'s exact pull-off at
/// an angle has none, the input is out of range, or a stop is asked for.
pub(crate) fn map(
    thetas: &[f64],
    thins: &[f64],
    mut visit: impl FnMut(&ThicknessPoint),
) -> Result<Vec<ThicknessPoint>> {
    let count = thetas.len().saturating_mul(thins.len());
    crate::error::check_range(
        "points",
        count as f64,
        (1..=MAX_POINTS).contains(&count),
        "1 to 400 (angles times thinnesses)",
    )?;
    for &t in thetas {
        crate::error::check_range("theta-deg", t, t > 0.0 && t <= 90.0, "(0, 90]")?;
    }
    let mut points = Vec::with_capacity(count);
    for &theta_deg in thetas {
        // equal cylinders: ρ = tan²(θ/2), exactly 1 at 90°
        let rho = if theta_deg == 90.0 {
            1.0
        } else {
            (0.5 * theta_deg.to_radians()).tan().powi(2)
        };
        let force_bar_2 = crate::exact::pull_off_resolved(rho)?.0.force_bar;
        for &thinness in thins {
            let layers = Layers::equal(thinness, 0.5)?;
            let found = if rho == 1.0 {
                layers.pull_off(Route::Griffith).map(|p| {
                    (
                        p.load.force_bar,
                        AXISYMMETRIC_BOUND,
                        "axisymmetric".to_string(),
                    )
                })
            } else {
                crate::layer::plane::pull_off(&layers, rho).map(|p| {
                    let method = match p.method {
                        crate::layer::Method::SharpEdge => "sharp_edge",
                        crate::layer::Method::Grid => "grid",
                    };
                    (p.force_bar, p.force_error, method.to_string())
                })
            };
            let layer = match found {
                Ok((force_bar, force_error, method)) => ThicknessAnswer::Found {
                    force_bar,
                    force_error,
                    method,
                    error_2: force_bar_2 / force_bar - 1.0,
                },
                Err(e) if crate::newton::stop_requested() => return Err(e),
                Err(e) => ThicknessAnswer::None { why: e.to_string() },
            };
            let point = ThicknessPoint {
                theta_deg,
                rho,
                thinness,
                force_bar_2,
                layer,
            };
            visit(&point);
            points.push(point);
        }
    }
    Ok(points)
}

/// The map as docs/thickness.md prints it: one row per angle, (2)'s
/// relative error at each thinness (with its method's mark: s the sharp
/// edge, g the grid, none at ρ = 1), "–" where the layer has none.
pub(crate) fn markdown(points: &[ThicknessPoint]) -> Result<String> {
    let mut thins: Vec<f64> = Vec::new();
    for p in points {
        if !thins.contains(&p.thinness) {
            thins.push(p.thinness);
        }
    }
    let mut s = String::from("| θ | ρ | F̄₍₂₎ |");
    for h in &thins {
        s += &format!(" h/L = {} |", short(*h));
    }
    s += "\n|---|---|---|";
    s += &"---|".repeat(thins.len());
    s += "\n";
    for row in points.chunk_by(|p, q| p.theta_deg == q.theta_deg) {
        if row.len() != thins.len() {
            return Err(Error::NoState(
                "the thickness map's rows do not share their thinnesses".into(),
            ));
        }
        s += &format!(
            "| {}° | {:.4} | {:.4} |",
            short(row[0].theta_deg),
            row[0].rho,
            row[0].force_bar_2
        );
        for p in row {
            s += &match &p.layer {
                ThicknessAnswer::Found {
                    error_2, method, ..
                } => format!(
                    " {:+.1} %{} |",
                    100.0 * error_2,
                    match method.as_str() {
                        "sharp_edge" => " s",
                        "grid" => " g",
                        _ => "",
                    }
                ),
                ThicknessAnswer::None { .. } => " – |".to_string(),
            };
        }
        s += "\n";
    }
    Ok(s)
}

/// docs/data/thickness_map.jsonl's points (`thinjkr thickness-map
/// --json`; the slow tier makes them again and compares every byte).
#[cfg(test)]
pub(crate) fn committed() -> Vec<ThicknessPoint> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../docs/data/thickness_map.jsonl"
    );
    std::fs::read_to_string(path)
        .expect("docs/data/thickness_map.jsonl")
        .lines()
        .map(|l| {
            let v: serde_json::Value = serde_json::from_str(l).unwrap();
            serde_json::from_value(v["thickness"].clone()).unwrap()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_docs_map_table_is_the_committed_points() {
        let points = committed();
        assert_eq!(points.len(), THETAS.len() * THINS.len());
        let doc =
            std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/thickness.md"))
                .unwrap();
        let table = markdown(&points).unwrap();
        assert!(
            doc.contains(&table),
            "docs/thickness.md lacks the map's table:\n{table}"
        );
    }

    /// CI's sample of the map: one point of the sharp edge's (70°, h/L =
    /// 0.73) computed again, within 1e-9 of its committed row.
    #[test]
    fn a_point_of_the_map_is_the_solver_s() {
        let row = committed()
            .into_iter()
            .find(|p| p.theta_deg == 70.0 && p.thinness == 0.73)
            .expect("the row of 70 degrees, h/L = 0.73");
        let fresh = map(&[70.0], &[0.73], |_| {}).unwrap().remove(0);
        let force = |p: &ThicknessPoint| match &p.layer {
            ThicknessAnswer::Found {
                force_bar, method, ..
            } => (*force_bar, method.clone()),
            other => panic!("{other:?}"),
        };
        let ((f, m), (g, n)) = (force(&fresh), force(&row));
        assert_eq!((m.as_str(), n.as_str()), ("sharp_edge", "sharp_edge"));
        assert!((f / g - 1.0).abs() < 1e-9, "{f} against {g}");
        assert!((fresh.force_bar_2 / row.force_bar_2 - 1.0).abs() < 1e-9);
    }

    #[test]
    fn a_map_too_large_or_an_angle_out_of_range_is_refused() {
        let many = vec![0.5; 401];
        for (thetas, thins, name) in [
            (&[60.0][..], &many[..], "points"),
            (&[0.0][..], &[1.0][..], "theta-deg"),
            (&[91.0][..], &[1.0][..], "theta-deg"),
        ] {
            match map(thetas, thins, |_| {}) {
                Err(Error::OutOfRange { name: n, .. }) => assert_eq!(n, name),
                other => panic!("{name}: {other:?}"),
            }
        }
    }
}
