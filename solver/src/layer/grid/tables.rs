//! The slow tier's hold on docs/thickness.md's grid, edge and stability tables: every
//! row computed again and compared digit for digit as printed (issue 71's
//! tables were typed in from the explorations' output; these tests keep
//! them the code's). About 33 minutes; `.ci/slow` runs them. CI holds the
//! first-order table the same way (about 25 s).
//!
//! Owns: nothing. May use: `layer` (the pair and its axisymmetric
//! reference, `thin`'s first order in h/L), `exact` ((2)'s exact pull-off), the grid's
//! `pull_off_ladder`, `jkr_limit`, `edge`, `plane::by_grid` (the grid's
//! answer in the plane) and `stability` (the least eigenvalues on the
//! unloading path), `control` (the hold of a state at a force), `error`.

use super::edge::{stiffness_minimum, LineContact};
use super::{jkr_limit, pull_off_ladder};
use crate::exact::pull_off_resolved;
use crate::layer::{Layers, Route};

/// docs/thickness.md.
pub(crate) fn doc() -> String {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/thickness.md");
    std::fs::read_to_string(path).expect("docs/thickness.md")
}

/// The rows (cells trimmed) of the table whose header line is `header`.
pub(crate) fn table(doc: &str, header: &str) -> Vec<Vec<String>> {
    let mut lines = doc.lines().skip_while(|l| l.trim() != header);
    assert!(lines.next().is_some(), "no table headed {header}");
    lines
        .skip(1)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            l.trim_matches('|')
                .split('|')
                .map(|c| c.trim().to_string())
                .collect()
        })
        .collect()
}

/// `value` printed as `printed` is: the same count of decimals, or of
/// significant digits in e-notation, or of decimals before a % sign.
fn same(value: f64, printed: &str) -> bool {
    let p = printed.trim_end_matches(" %").trim_end_matches('%');
    let percent = p.len() != printed.len();
    let value = if percent { 100.0 * value } else { value };
    let text = if let Some((mantissa, _)) = p.split_once('e') {
        let digits = mantissa.split_once('.').map_or(0, |(_, d)| d.len());
        let s = format!("{value:+.digits$e}");
        // Rust writes e-2 where the docs write e-02
        let (m, e) = s.split_once('e').expect("e");
        let e: i32 = e.parse().expect("exponent");
        format!("{m}e{}{:02}", if e < 0 { '-' } else { '+' }, e.abs())
    } else {
        let digits = p.split_once('.').map_or(0, |(_, d)| d.len());
        if p.starts_with('+') {
            format!("{value:+.digits$}")
        } else {
            format!("{value:.digits$}")
        }
    };
    text == p
}

fn check(what: &str, value: f64, printed: &str, bad: &mut Vec<String>) {
    if !same(value, printed) {
        bad.push(format!("{what}: computed {value}, printed {printed}"));
    }
}

#[test]
#[ignore = "slow tier (.ci/slow): the grid's ladders behind docs/thickness.md, about 9 minutes"]
fn the_grid_tables_of_the_docs_are_the_solver_s() {
    let doc = doc();
    let mut bad = Vec::new();
    let eps = [0.2, 0.1, 0.05, 0.025, 0.0125];
    let rungs: Vec<(f64, f64)> = eps.iter().map(|&e| (e, 4.0)).collect();
    let ladder_rows = table(&doc, "| h/L | ε | n | W | F̄ | error |");
    let limit_rows = table(&doc, "| h/L | rungs ε | limit F̄₀ | error |");
    let mut forces = std::collections::BTreeMap::new();
    for thin in [1.0, 10.0] {
        let layers = Layers::equal(thin, 0.5).unwrap();
        let reference = layers.pull_off(Route::Griffith).unwrap().load.force_bar;
        let ladder = pull_off_ladder(&layers, 1.0, &rungs, &mut |_| {}).unwrap();
        let rows: Vec<&Vec<String>> = ladder_rows
            .iter()
            .filter(|r| r[0].parse::<f64>().unwrap() == thin)
            .collect();
        assert_eq!(rows.len(), ladder.len(), "h/L {thin}");
        for (r, row) in ladder.iter().zip(rows) {
            let f = r.state.force_bar;
            let at = format!("h/L {thin}, eps {}", r.eps);
            check(&format!("{at}: eps"), r.eps, &row[1], &mut bad);
            check(&format!("{at}: n"), r.n as f64, &row[2], &mut bad);
            check(&format!("{at}: W"), r.width, &row[3], &mut bad);
            check(&format!("{at}: F"), f, &row[4], &mut bad);
            check(
                &format!("{at}: error"),
                f / reference - 1.0,
                &row[5],
                &mut bad,
            );
        }
        let f: Vec<f64> = ladder.iter().map(|r| r.state.force_bar).collect();
        forces.insert((thin as i64, 1000), f.clone());
        let rows: Vec<&Vec<String>> = limit_rows
            .iter()
            .filter(|r| r[0].parse::<f64>().unwrap() == thin)
            .collect();
        assert_eq!(rows.len(), 3, "h/L {thin}: three limits");
        for (k, row) in rows.iter().enumerate() {
            let limit = jkr_limit([
                (eps[k], f[k]),
                (eps[k + 1], f[k + 1]),
                (eps[k + 2], f[k + 2]),
            ])
            .unwrap();
            let at = format!("h/L {thin}, limit from eps {}", eps[k]);
            check(&format!("{at}: F0"), limit, &row[2], &mut bad);
            check(
                &format!("{at}: error"),
                limit / reference - 1.0,
                &row[3],
                &mut bad,
            );
        }
    }
    // ρ < 1 (and ρ = 1 at h/L = 0.5): four rungs each, against (2)'s exact
    // pull-off
    let exact_2 = |rho: f64| pull_off_resolved(rho).unwrap().0.force_bar;
    for row in table(
        &doc,
        "| h/L | ρ | F̄ at ε = 0.2, 0.1, 0.05, 0.025 | F̄₀ (0.2 … 0.05) | F̄₀ (0.1 … 0.025) | (2)'s error | F̄₀/F̄₍₂₎ |",
    ) {
        let (thin, rho): (f64, f64) = (row[0].parse().unwrap(), row[1].parse().unwrap());
        let layers = Layers::equal(thin, 0.5).unwrap();
        let f = match forces.get(&(thin as i64, (rho * 1000.0) as i64)) {
            Some(f) if thin == 1.0 => f[..4].to_vec(),
            _ => pull_off_ladder(&layers, rho, &rungs[..4], &mut |_| {})
                .unwrap()
                .iter()
                .map(|r| r.state.force_bar)
                .collect(),
        };
        let at = format!("h/L {thin}, rho {rho}");
        for (k, printed) in row[2].split(", ").enumerate() {
            check(&format!("{at}: F at eps {}", eps[k]), f[k], printed, &mut bad);
        }
        let coarse = jkr_limit([(eps[0], f[0]), (eps[1], f[1]), (eps[2], f[2])]).unwrap();
        let fine = jkr_limit([(eps[1], f[1]), (eps[2], f[2]), (eps[3], f[3])]).unwrap();
        check(&format!("{at}: coarse limit"), coarse, &row[3], &mut bad);
        check(&format!("{at}: fine limit"), fine, &row[4], &mut bad);
        check(&format!("{at}: (2)'s error"), exact_2(rho) / fine - 1.0, &row[5], &mut bad);
        check(&format!("{at}: ratio"), fine / exact_2(rho), &row[6], &mut bad);
    }
    assert!(
        bad.is_empty(),
        "docs/thickness.md differs:\n{}",
        bad.join("\n")
    );
}

/// A ρ as the docs print it: a number or a fraction `p/q`.
fn rho_of(printed: &str) -> f64 {
    match printed.split_once('/') {
        Some((p, q)) => p.parse::<f64>().unwrap() / q.parse::<f64>().unwrap(),
        None => printed.parse().unwrap(),
    }
}

#[test]
#[ignore = "slow tier (.ci/slow): the layer in the plane behind docs/thickness.md, about 18 minutes"]
fn the_plane_tables_of_the_docs_are_the_model_layer_s() {
    // the grid's answer at ρ < 1 (`plane::by_grid::pull_off`), its
    // bounds measured against the axisymmetric reference at ρ = 1, and
    // across ρ against (2)'s exact pull-off
    let doc = doc();
    let mut bad = Vec::new();
    for row in table(
        &doc,
        "| h/L | F̄ | its error | its bound | δ̄'s error | its bound | ā's error | its bound |",
    ) {
        let thin: f64 = row[0].parse().unwrap();
        let layers = Layers::equal(thin, 0.5).unwrap();
        let reference = layers.pull_off(Route::Griffith).unwrap().load;
        let p = crate::layer::plane::by_grid::pull_off(&layers, 1.0).unwrap();
        let at = format!("h/L {thin} at rho = 1");
        // (the row as the docs print it: `--nocapture` shows it)
        println!(
            "| {thin} | {:.7} | {:+.3} % | {:.3} % | {:+.5} | {:.5} | {:+.3} % | {:.2} % |",
            p.force_bar,
            100.0 * (p.force_bar / reference.force_bar - 1.0),
            100.0 * p.force_error,
            p.delta_bar - reference.delta_bar,
            p.delta_error,
            100.0 * (p.a_bar / reference.a_bar - 1.0),
            100.0 * p.size_error
        );
        check(&format!("{at}: F"), p.force_bar, &row[1], &mut bad);
        check(
            &format!("{at}: F's error"),
            p.force_bar / reference.force_bar - 1.0,
            &row[2],
            &mut bad,
        );
        check(
            &format!("{at}: F's bound"),
            p.force_error,
            &row[3],
            &mut bad,
        );
        check(
            &format!("{at}: delta's error"),
            p.delta_bar - reference.delta_bar,
            &row[4],
            &mut bad,
        );
        check(
            &format!("{at}: delta's bound"),
            p.delta_error,
            &row[5],
            &mut bad,
        );
        check(
            &format!("{at}: a's error"),
            p.a_bar / reference.a_bar - 1.0,
            &row[6],
            &mut bad,
        );
        check(&format!("{at}: a's bound"), p.size_error, &row[7], &mut bad);
    }
    for row in table(
        &doc,
        "| h/L | F̄ | δ̄ | δ̄'s error | its bound | ā's error | its bound |",
    ) {
        let thin: f64 = row[0].parse().unwrap();
        let layers = Layers::equal(thin, 0.5).unwrap();
        let pull = layers.pull_off(Route::Griffith).unwrap().load.force_bar;
        // the row's force: 0, or −F̄₀ (printed as a number)
        let force = if row[1] == "0" { 0.0 } else { -pull };
        let hold = crate::control::Hold::Force(force);
        let reference = layers.state(hold, Route::Griffith).unwrap();
        let p = crate::layer::plane::by_grid::state(&layers, 1.0, Some(hold)).unwrap();
        let at = format!("h/L {thin} at rho = 1, force {}", row[1]);
        println!(
            "| {thin} | {} | {:.4} | {:+.5} | {:.5} | {:+.3} % | {:.2} % |",
            row[1],
            p.delta_bar,
            p.delta_bar - reference.delta_bar,
            p.delta_error,
            100.0 * (p.a_bar / reference.a_bar - 1.0),
            100.0 * p.size_error
        );
        check(&format!("{at}: F"), force, &row[1], &mut bad);
        check(&format!("{at}: delta"), p.delta_bar, &row[2], &mut bad);
        check(
            &format!("{at}: delta's error"),
            p.delta_bar - reference.delta_bar,
            &row[3],
            &mut bad,
        );
        check(
            &format!("{at}: delta's bound"),
            p.delta_error,
            &row[4],
            &mut bad,
        );
        check(
            &format!("{at}: a's error"),
            p.a_bar / reference.a_bar - 1.0,
            &row[5],
            &mut bad,
        );
        check(&format!("{at}: a's bound"), p.size_error, &row[6], &mut bad);
    }
    let circle = -1.5 * std::f64::consts::PI;
    for row in table(
        &doc,
        "| h/L | ρ | F̄ | bound | ā | s | δ̄ | (2)'s F̄ | (2)'s error | F̄/F̄₍₂₎ | against ρ = 1 |",
    ) {
        let (thin, rho) = (row[0].parse::<f64>().unwrap(), rho_of(&row[1]));
        let layers = Layers::equal(thin, 0.5).unwrap();
        let at_circle = layers.pull_off(Route::Griffith).unwrap().load.force_bar / circle;
        let at = format!("h/L {thin}, rho {}", row[1]);
        let p = match crate::layer::plane::by_grid::pull_off(&layers, rho) {
            Ok(p) => p,
            Err(e) => {
                bad.push(format!("{at}: {e}"));
                continue;
            }
        };
        let exact_2 = pull_off_resolved(rho).unwrap().0.force_bar;
        let ratio = p.force_bar / exact_2;
        println!(
            "| {thin} | {} | {:.6} | {:.2} % | {:.4} | {:.3} | {:.4} | {:.6} | {:+.1} % | {:.4} | {:+.2} % |",
            row[1],
            p.force_bar,
            100.0 * p.force_error,
            p.a_bar,
            p.s,
            p.delta_bar,
            exact_2,
            100.0 * (exact_2 / p.force_bar - 1.0),
            ratio,
            100.0 * (ratio / at_circle - 1.0)
        );
        check(&format!("{at}: F"), p.force_bar, &row[2], &mut bad);
        check(&format!("{at}: bound"), p.force_error, &row[3], &mut bad);
        check(&format!("{at}: a"), p.a_bar, &row[4], &mut bad);
        check(&format!("{at}: s"), p.s, &row[5], &mut bad);
        check(&format!("{at}: delta"), p.delta_bar, &row[6], &mut bad);
        check(&format!("{at}: (2)'s F"), exact_2, &row[7], &mut bad);
        check(
            &format!("{at}: (2)'s error"),
            exact_2 / p.force_bar - 1.0,
            &row[8],
            &mut bad,
        );
        check(&format!("{at}: ratio"), ratio, &row[9], &mut bad);
        check(
            &format!("{at}: against rho = 1"),
            ratio / at_circle - 1.0,
            &row[10],
            &mut bad,
        );
    }
    assert!(
        bad.is_empty(),
        "docs/thickness.md differs:\n{}",
        bad.join("\n")
    );
}

#[test]
#[ignore = "slow tier (.ci/slow): the straight edge's table of docs/thickness.md, about 45 s"]
fn the_edge_table_of_the_docs_is_the_solver_s() {
    let doc = doc();
    let mut bad = Vec::new();
    let rows = table(
        &doc,
        "| ν | ā/h | δ̄ | F̄ per unit length | ∂K/∂b / K | least δK/A / K | at kh | its wavelength | stiffness minimum |",
    );
    assert_eq!(rows.len(), 10);
    for row in rows {
        let nu = if row[0] == "½" {
            0.5
        } else {
            row[0].parse().unwrap()
        };
        let a_over_h: f64 = row[1].parse().unwrap();
        let layers = Layers::equal(0.1, nu).unwrap();
        let line = LineContact::new(&layers, 80);
        let st = line.state(a_over_h * 0.1).unwrap();
        let (least, kh) = line.most_unstable(&st).unwrap();
        let at = format!("nu {nu}, a/h {a_over_h}");
        check(&format!("{at}: delta"), st.delta_bar, &row[2], &mut bad);
        check(&format!("{at}: F"), st.force_bar, &row[3], &mut bad);
        let k0 = (2.0 * layers.beta()).sqrt();
        check(&format!("{at}: dK/db"), st.k_edge / k0, &row[4], &mut bad);
        check(&format!("{at}: least"), least, &row[5], &mut bad);
        check(&format!("{at}: kh"), kh, &row[6], &mut bad);
        let wave = row[7].trim_end_matches('h');
        check(
            &format!("{at}: wavelength"),
            2.0 * std::f64::consts::PI / kh,
            wave,
            &mut bad,
        );
        if let Some(rest) = row[8].strip_prefix("kh = ") {
            let (k, lambda) = rest.split_once(" (").expect("kh = x (yh)");
            let stiff = stiffness_minimum(&layers) * 0.1;
            check(&format!("{at}: stiffness minimum"), stiff, k, &mut bad);
            let lambda = lambda.trim_end_matches("h)");
            check(
                &format!("{at}: its wavelength"),
                2.0 * std::f64::consts::PI / stiff,
                lambda,
                &mut bad,
            );
        }
    }
    assert!(
        bad.is_empty(),
        "docs/thickness.md differs:\n{}",
        bad.join("\n")
    );
}

/// The header of docs/thickness.md's table of the least eigenvalues on
/// the unloading path.
const STABILITY_HEADER: &str =
    "| θ | ρ | h/L | ε | cells | loaded F̄ | its least λ | n | pull-off F̄ | its least λ | n |";

#[test]
#[ignore = "slow tier (.ci/slow): the least eigenvalues on the unloading path of docs/thickness.md, about 15 minutes"]
fn the_stability_table_of_the_docs_is_the_solver_s() {
    use super::stability::least_modes;
    let doc = doc();
    let mut bad = Vec::new();
    let rows = table(&doc, STABILITY_HEADER);
    assert!(!rows.is_empty());
    // one ladder ε = 0.2, 0.1 for each pair of coatings and ρ
    let mut done: Vec<(String, String)> = Vec::new();
    for row in &rows {
        let key = (row[1].clone(), row[2].clone());
        if done.contains(&key) {
            continue;
        }
        done.push(key);
        let rho = rho_of(&row[1]);
        let thin: f64 = row[2].parse().expect("h/L");
        let layers = Layers::equal(thin, 0.5).unwrap();
        let a = layers.radius_guess();
        let ladder = pull_off_ladder(&layers, rho, &[(0.2, 4.0), (0.1, 4.0)], &mut |_| {}).unwrap();
        for rung in &ladder {
            let Some(row) = rows
                .iter()
                .find(|r| r[1] == row[1] && r[2] == row[2] && r[3].parse::<f64>() == Ok(rung.eps))
            else {
                continue;
            };
            let at = format!("{} at eps {}", row[0], rung.eps);
            let sheet = rung.sheet(&layers, rho);
            let po = sheet.state(rung.state.delta_bar, &rung.state.gap).unwrap();
            // the path: the pull-off and four loaded states above it
            let mut path = vec![po.clone()];
            for k in 1..=4 {
                let d = po.delta_bar + 0.1 * k as f64 * a * a;
                let next = sheet
                    .state(d, &super::Sheet::predict(path.last().unwrap(), d))
                    .unwrap();
                path.push(next);
            }
            let pairs: Vec<_> = path
                .iter()
                .map(|s| least_modes(&sheet, s, 2, 120).unwrap())
                .collect();
            let least: Vec<_> = pairs.iter().map(|p| p[0].clone()).collect();
            if least.iter().any(|m| m.eigenvalue <= 0.0) {
                bad.push(format!("{at}: a state on the path is unstable: {least:?}"));
            }
            if row[4] != rung.n.to_string() {
                bad.push(format!("{at}: cells {} against {}", rung.n, row[4]));
            }
            for (state, k, cells) in [(&path[4], 4, 5), (&path[0], 0, 8)] {
                let mode = &least[k];
                check(&format!("{at}: F"), state.force_bar, &row[cells], &mut bad);
                check(
                    &format!("{at}: lambda"),
                    mode.eigenvalue,
                    &row[cells + 1],
                    &mut bad,
                );
                // "pair": the two least are one eigenvalue to 1e-4 (the two
                // ends of an elongated contact), whose order is not one
                if row[cells + 2] == "pair" {
                    let other = pairs[k][1].eigenvalue;
                    if (other / mode.eigenvalue - 1.0).abs() >= 1e-4 {
                        bad.push(format!("{at}: not a pair: {} and {other}", mode.eigenvalue));
                    }
                } else if row[cells + 2] != mode.n.to_string() {
                    bad.push(format!("{at}: n {} against {}", mode.n, row[cells + 2]));
                }
            }
        }
    }
    assert!(
        bad.is_empty(),
        "docs/thickness.md differs:\n{}",
        bad.join("\n")
    );
}

#[test]
fn a_printed_number_is_read_at_its_own_precision() {
    assert!(same(1.18379, "1.1838") && !same(1.18379, "1.1837"));
    assert!(same(0.040530, "+4.05e-02") && !same(0.0406, "+4.05e-02"));
    assert!(same(-0.00160, "-1.6e-03"));
    assert!(same(0.638384, "+63.84 %") && !same(0.6385, "+63.84 %"));
    assert!(same(92.0, "92") && same(-0.662110, "-0.6621") && same(1.186, "+1.186"));
}

/// The header of docs/thickness.md's table of the first order in h/L.
pub(crate) const FIRST_ORDER_HEADER: &str =
    "| θ | ρ | F̄₍₂₎ | ½dP̄/dδ̄ | dF̄/d(h/L) | its share of −F̄₍₂₎ | (2) 1 % off at h/L | 5 % off at h/L |";

/// One row of [`FIRST_ORDER_HEADER`]'s table at ρ for equal
/// incompressible coatings, as printed (θ = 2 arctan √ρ).
pub(crate) fn first_order_row(rho: f64) -> crate::error::Result<Vec<String>> {
    let layers = Layers::equal(1.0, 0.5)?;
    let first = crate::layer::thin::first_order_pull_off(&layers, rho)?;
    let (f2, half) = (first.thin_limit.force_bar, first.force_per_shift);
    let off = |e: f64| first.thickness_factor_for_error(e);
    let theta = 2.0 * rho.sqrt().atan().to_degrees();
    Ok(vec![
        if (theta - theta.round()).abs() < 1e-9 {
            format!("{}°", theta.round())
        } else {
            format!("{theta:.1}°")
        },
        format!("{rho:.6}"),
        format!("{f2:.7}"),
        format!("{half:.7}"),
        format!("{:.6}", first.force_moved()),
        format!("{:.4}", first.share()),
        format!("{:.5}", off(0.01)),
        format!("{:.4}", off(0.05)),
    ])
}

/// docs/thickness.md's first-order table, every row computed again: ρ
/// from θ where θ is a whole number of degrees (the ten-angle table's
/// angles, equal cylinders), else as printed; and the shift b/h its prose
/// gives.
#[test]
fn the_first_order_table_of_the_docs_is_the_solver_s() {
    let doc = doc();
    let rows = table(&doc, FIRST_ORDER_HEADER);
    assert_eq!(rows.len(), 12, "{rows:?}");
    let mut bad = Vec::new();
    // the prose's shift, b/h of equal incompressible coatings
    let shift = crate::layer::thin::edge_shift(&Layers::equal(1.0, 0.5).unwrap()).unwrap();
    let printed = format!("b/h = {shift:.7}");
    if !doc.contains(&printed) {
        bad.push(format!("no {printed} in the prose"));
    }
    for row in rows {
        let theta = row[0].trim_end_matches('°');
        let rho = if theta.contains('.') {
            rho_of(&row[1])
        } else {
            (0.5 * theta.parse::<f64>().unwrap().to_radians())
                .tan()
                .powi(2)
        };
        let computed = first_order_row(rho).unwrap();
        if computed != row {
            bad.push(format!("printed {row:?}\ncomputed {computed:?}"));
        }
    }
    assert!(
        bad.is_empty(),
        "docs/thickness.md differs:\n{}",
        bad.join("\n")
    );
}

#[test]
#[ignore = "exploration: the first-order table's rows (THINJKR_THIN_RHOS, or the table's own)"]
fn explore_first_order_rows() {
    let rhos = std::env::var("THINJKR_THIN_RHOS").unwrap_or("1,0.8,0.5".into());
    for rho in rhos.split(',').map(|x| x.parse::<f64>().unwrap()) {
        println!("| {} |", first_order_row(rho).unwrap().join(" | "));
    }
}
