//! The layer of finite thickness at ρ = 1 (`thinjkr::layer`, issue 70):
//! its two limits, its two routes, its states under every control, and its
//! refusals.
//!
//! Units (17) at ρ = 1: lengths in L, the approach in L²/R, the force in
//! 2RΔγ. The thin limit is the thin-layer equation (2), whose axisymmetric
//! solution is (25): δ̄ = ā²/4 − 2/ā, F̄ = πā³(ā³ − 24)/96, pull-off −3π/2
//! (−3πRΔγ). The thick limit is JKR's half-space contact (Johnson, Kendall
//! & Roberts 1971): with E* the pair's plane-strain modulus, F =
//! 4E*a³/3R − √(8πE*a³Δγ) and δ = a²/R − √(2πaΔγ/E*); in the units (17),
//! with β = E*/(2mL³), F̄ = 8βā³/3 − √(8πβā³) and δ̄ = ā² − √(πā/2β),
//! pull-off −3π/4 (−1.5πRΔγ) under load control and −5π/12 (−(5/6)πRΔγ)
//! under displacement control. For two equal coatings of thinness H and
//! Poisson's ratio ν, m = 3G/2h³ and E* = G/(1 − ν), so β = H³/3(1 − ν).

use std::f64::consts::PI;
use thinjkr::control::Hold;
use thinjkr::layer::{Coating, Layers, Route};
use thinjkr::Error;

fn equal(h: f64, nu: f64) -> Layers {
    Layers::equal(h, nu).unwrap()
}

fn pull_off_force(h: f64) -> f64 {
    equal(h, 0.5)
        .pull_off(Route::Griffith)
        .unwrap()
        .load
        .force_bar
}

/// The force at a given radius, and the pull-off under load control, are
/// JKR's to round-off. The approach carries the base's first correction, a
/// rigid shift ∝ F̄·a/h (the kernel is constant over the contact to first
/// order, which moves δ̄ and leaves g, hence F̄, as they are). JKR's radius
/// is ā ∝ β^(−1/3) ∝ L/h, so a/h ∝ (h/L)⁻²: the shift falls tenfold from
/// h/L = 10³ to 10^3.5. So does the pull-off under displacement
/// control, which the shift moves: 9.5e-7 of −5π/12 at h/L = 10³.
#[test]
fn thick_coatings_are_jkr_contact_at_every_radius_and_at_both_pull_offs() {
    let (mut shifts, mut grips_gaps) = (Vec::new(), Vec::new());
    for (h, nu) in [(1e3, 0.5), (1e3, 0.3), (10f64.powf(3.5), 0.5), (1e4, 0.0)] {
        let layers = equal(h, nu);
        let beta = h.powi(3) / (3.0 * (1.0 - nu));
        // JKR's pull-off radius under load control, (9π/32β)^(1/3)
        let a_jkr = (9.0 * PI / (32.0 * beta)).cbrt();
        for a in [0.2 * a_jkr, a_jkr, 3.0 * a_jkr] {
            let s = layers.state(Hold::Size(a), Route::Griffith).unwrap();
            let force = 8.0 * beta * a.powi(3) / 3.0 - (8.0 * PI * beta * a.powi(3)).sqrt();
            let delta = a * a - (PI * a / (2.0 * beta)).sqrt();
            assert!(
                (s.force_bar - force).abs() < 1e-10 * force.abs().max(1.0),
                "h {h} ν {nu} ā {a}: F̄ {} against JKR's {force}",
                s.force_bar
            );
            // over the size of JKR's adhesive term (δ̄ itself passes through 0)
            let shift = (s.delta_bar - delta) / (PI * a / (2.0 * beta)).sqrt();
            // 4.2e-6 at worst (h/L = 10³, ā = 3 × JKR's pull-off radius)
            assert!(
                shift.abs() < 1e-5,
                "h {h} ν {nu} ā {a}: δ̄ {} against JKR's {delta}",
                s.delta_bar
            );
            if nu == 0.5 && a == a_jkr {
                shifts.push(shift);
            }
        }
        let pull = layers.pull_off(Route::Griffith).unwrap();
        assert!(
            (pull.load.force_bar + 0.75 * PI).abs() < 1e-10,
            "h {h}: pull-off {} against −3π/4",
            pull.load.force_bar
        );
        assert!(
            (pull.load.a_bar / a_jkr - 1.0).abs() < 1e-9,
            "h {h}: pull-off radius {} against {a_jkr}",
            pull.load.a_bar
        );
        // the rigid shift of δ̄ moves the minimum of δ̄: first order in a/h
        let grips = (pull.displacement.force_bar + 5.0 * PI / 12.0) / (5.0 * PI / 12.0);
        assert!(
            grips > 0.0 && grips < 1e-6 * (1e3 / h).powi(2),
            "h {h}: fixed-grips pull-off {} against −5π/12",
            pull.displacement.force_bar
        );
        if nu == 0.5 {
            grips_gaps.push(grips);
        }
    }
    for gaps in [&shifts, &grips_gaps] {
        let ratio = gaps[0] / gaps[1];
        assert!(
            (ratio / 10.0 - 1.0).abs() < 0.01,
            "{gaps:?} fall by {ratio}"
        );
    }
}

/// The excess of the pull-off over JKR's falls as (h/L)⁻⁶ (the base's first
/// correction, (a/h)³ with a ∝ L²/h), and is below 1e-8 from h/L = 32.
#[test]
fn the_thick_limit_is_approached_at_sixth_order() {
    let excess: Vec<f64> = [4.0, 8.0, 16.0, 32.0]
        .iter()
        .map(|&h| -(pull_off_force(h) + 0.75 * PI) / (0.75 * PI))
        .collect();
    for w in excess.windows(2) {
        let order = (w[0] / w[1]).log2();
        assert!((order - 6.0).abs() < 0.03, "order {order} from {excess:?}");
    }
    assert!(excess[3] > 0.0 && excess[3] < 1.1e-9, "{excess:?}");
    // extrapolated at sixth order from 16 and 32: JKR's to 1e-12
    let extrapolated = (64.0 * pull_off_force(32.0) - pull_off_force(16.0)) / 63.0;
    assert!((extrapolated + 0.75 * PI).abs() < 1e-12, "{extrapolated}");
}

/// At every radius the layer tends to (25) as h/L → 0, at first order.
#[test]
fn thin_coatings_tend_to_the_thin_layer_equation_at_first_order() {
    let a: f64 = 2.0;
    let (delta_25, force_25) = (
        a * a / 4.0 - 2.0 / a,
        PI * a.powi(3) * (a.powi(3) - 24.0) / 96.0,
    );
    let gap = |h: f64| {
        let s = equal(h, 0.5).state(Hold::Size(a), Route::Griffith).unwrap();
        (s.delta_bar - delta_25, s.force_bar - force_25)
    };
    let (coarse, fine) = (gap(0.02), gap(0.01));
    for (what, c, f) in [("δ̄", coarse.0, fine.0), ("F̄", coarse.1, fine.1)] {
        let order = (c / f).log2();
        assert!(
            (order - 1.0).abs() < 0.1,
            "{what}: order {order} ({c} at h/L = 0.02, {f} at 0.01)"
        );
        assert!(f.abs() < 0.05 * force_25.abs(), "{what}: {f}");
    }
}

/// The pull-off reaches (2)'s −3π/2 at first order: deficit ≈ 1.912 h/L.
/// The stated extrapolation is the cubic through h/L = 0.05, 0.025, 0.0125
/// and 0.00625 (F̄ = F̄₀ + c₁h + c₂h² + c₃h³), whose F̄₀ is −3π/2 to 1e-6.
#[test]
fn the_thin_limit_of_the_pull_off_is_the_thin_layer_equation_s() {
    let hs = [0.05, 0.025, 0.0125, 0.00625];
    let forces: Vec<f64> = hs.iter().map(|&h| pull_off_force(h)).collect();
    let limit = -1.5 * PI;
    let deficits: Vec<f64> = forces.iter().map(|f| f - limit).collect();
    for w in deficits.windows(2) {
        let order = (w[0] / w[1]).log2();
        assert!(
            (order - 1.0).abs() < 0.02,
            "order {order} from {deficits:?}"
        );
    }
    // Neville's scheme at h = 0 for the cubic through the four points
    let mut p = forces.clone();
    for k in 1..4 {
        for i in 0..4 - k {
            p[i] = (hs[i + k] * p[i] - hs[i] * p[i + 1]) / (hs[i + k] - hs[i]);
        }
    }
    eprintln!(
        "pull-offs {forces:?} at h/L {hs:?}: extrapolated {:.10}, −3π/2 = {limit:.10}, relative {:.1e}",
        p[0],
        (p[0] - limit) / limit.abs()
    );
    assert!(
        (p[0] - limit).abs() < 1e-6 * limit.abs(),
        "extrapolated {} against −3π/2 {limit}",
        p[0]
    );
    // the first-order coefficient, in units πRΔγ per h/L
    let slope = deficits[3] / hs[3] * 2.0 / PI;
    assert!((slope - 1.9129).abs() < 1e-3, "{slope}");
}

/// Griffith's condition (the stress-intensity factor) and the energy
/// balance (∂Ū/∂ā at fixed δ̄) give the same states and the same pull-off.
#[test]
fn the_two_routes_agree_on_the_pull_off_to_1e_8() {
    for h in [0.01, 0.1, 1.0, 10.0] {
        let layers = equal(h, 0.5);
        let griffith = layers.pull_off(Route::Griffith).unwrap().load;
        let energy = layers.pull_off(Route::Energy).unwrap().load;
        let gap = (griffith.force_bar - energy.force_bar).abs() / griffith.force_bar.abs();
        eprintln!(
            "h/L {h}: pull-off {:.12} by Griffith, {:.12} by the energy, relative gap {gap:.1e}",
            griffith.force_bar, energy.force_bar
        );
        assert!(
            gap < 1e-8,
            "h/L {h}: pull-off {} by Griffith, {} by the energy ({gap:.1e})",
            griffith.force_bar,
            energy.force_bar
        );
        assert!(
            (griffith.a_bar / energy.a_bar - 1.0).abs() < 1e-5,
            "h/L {h}: radii {} and {}",
            griffith.a_bar,
            energy.a_bar
        );
        let same = layers
            .state(Hold::Size(griffith.a_bar), Route::Energy)
            .unwrap();
        assert!(
            (same.delta_bar - griffith.delta_bar).abs() < 1e-8 * griffith.delta_bar.abs().max(1.0),
            "h/L {h}: δ̄ {} and {}",
            same.delta_bar,
            griffith.delta_bar
        );
    }
}

#[test]
fn states_held_at_a_force_or_an_approach_lie_on_the_stable_branch() {
    let layers = equal(0.3, 0.5);
    let pull = layers.pull_off(Route::Griffith).unwrap();
    assert!(
        pull.load.force_slope.abs() < 1e-9 && pull.displacement.delta_slope.abs() < 1e-9,
        "{pull:?}"
    );
    assert!(
        pull.displacement.a_bar < pull.load.a_bar
            && pull.displacement.force_bar > pull.load.force_bar
    );
    for force in [pull.load.force_bar * 0.5, 0.0, 3.0] {
        let s = layers.state(Hold::Force(force), Route::Griffith).unwrap();
        assert!((s.force_bar - force).abs() < 1e-10, "F̄ {force}: {s:?}");
        assert!(
            s.force_slope > 0.0 && s.a_bar > pull.load.a_bar,
            "F̄ {force}: {s:?}"
        );
    }
    for delta in [pull.displacement.delta_bar * 0.5, 0.0, 1.0] {
        let s = layers.state(Hold::Delta(delta), Route::Griffith).unwrap();
        assert!((s.delta_bar - delta).abs() < 1e-10, "δ̄ {delta}: {s:?}");
        assert!(
            s.delta_slope > 0.0 && s.a_bar > pull.displacement.a_bar,
            "δ̄ {delta}: {s:?}"
        );
    }
    // below either pull-off there is no state
    let below = layers
        .state(Hold::Force(pull.load.force_bar - 0.01), Route::Griffith)
        .unwrap_err();
    assert_eq!(below.kind(), "no_state", "{below}");
    let below = layers
        .state(
            Hold::Delta(pull.displacement.delta_bar - 0.01),
            Route::Griffith,
        )
        .unwrap_err();
    assert_eq!(below.kind(), "no_state", "{below}");
}

/// Two coatings enter symmetrically; unequal ones lie between the equal
/// pairs they are made of.
#[test]
fn the_pair_is_symmetric_and_unequal_coatings_work() {
    let thin = Coating {
        thinness: 0.2,
        shear_modulus: 1.0,
        nu: 0.5,
    };
    let thick = Coating {
        thinness: 0.6,
        shear_modulus: 3.0,
        nu: 0.4,
    };
    let one = Layers::new(thin, thick)
        .unwrap()
        .pull_off(Route::Griffith)
        .unwrap()
        .load;
    let other = Layers::new(thick, thin)
        .unwrap()
        .pull_off(Route::Griffith)
        .unwrap()
        .load;
    assert!(
        (one.force_bar - other.force_bar).abs() < 1e-12,
        "{one:?} against {other:?}"
    );
    assert!(
        one.force_bar < -0.75 * PI && one.force_bar > -1.5 * PI,
        "{one:?}"
    );
}

#[test]
fn bad_coatings_and_controls_are_refused_by_name() {
    let cases: [(Result<Layers, Error>, &str, &str); 5] = [
        (Layers::equal(1e-4, 0.5), "h1/L", "unsupported"),
        (Layers::equal(-1.0, 0.5), "h1/L", "out_of_range"),
        (Layers::equal(f64::NAN, 0.5), "h1/L", "out_of_range"),
        (Layers::equal(0.1, 0.6), "nu1", "out_of_range"),
        (
            Layers::new(
                Coating {
                    thinness: 0.1,
                    shear_modulus: 1.0,
                    nu: 0.5,
                },
                Coating {
                    thinness: 0.1,
                    shear_modulus: 0.0,
                    nu: 0.5,
                },
            ),
            "g2",
            "out_of_range",
        ),
    ];
    for (result, name, kind) in cases {
        let e = result.unwrap_err();
        assert_eq!(e.kind(), kind, "{e}");
        assert!(e.to_string().contains(name), "{e}");
    }
    let layers = equal(1.0, 0.5);
    for hold in [
        Hold::Size(0.0),
        Hold::Size(f64::NAN),
        Hold::Force(f64::INFINITY),
    ] {
        let e = layers.state(hold, Route::Griffith).unwrap_err();
        assert_eq!(e.kind(), "out_of_range", "{e}");
    }
}

/// The pull-off F/(πRΔγ) of equal incompressible coatings against h/L, its
/// radius over h, its approach δ̄, and how far (2)'s pull-off −3πRΔγ is
/// from it: the table of docs/thickness.md, held here row by row.
fn table_row(h: f64) -> String {
    let pull = equal(h, 0.5).pull_off(Route::Griffith).unwrap().load;
    let force = pull.force_bar * 2.0 / PI;
    format!(
        "| {h} | {force:.7} | {} | {} | {:+.2} % |",
        significant(pull.a_bar / h, 4),
        significant(pull.delta_bar, 4),
        100.0 * (-3.0 / force - 1.0)
    )
}

/// `x` to `digits` significant digits, without an exponent.
fn significant(x: f64, digits: i32) -> String {
    let decimals = (digits - 1 - x.abs().log10().floor() as i32).max(0) as usize;
    format!("{x:.decimals$}")
}

/// The h/L at which (2)'s pull-off is `error` (a fraction) off the layer's:
/// the secant method in ln(h/L) on −3/F − 1 − error.
fn thinness_at_error(error: f64) -> f64 {
    let miss = |ln_h: f64| -1.5 * PI / pull_off_force(ln_h.exp()) - 1.0 - error;
    let (mut x0, mut x1) = ((0.5 * error).ln(), (error).ln());
    let (mut f0, mut f1) = (miss(x0), miss(x1));
    for _ in 0..30 {
        let x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
        (x0, f0) = (x1, f1);
        x1 = x2;
        f1 = miss(x1);
        if (x1 - x0).abs() < 1e-10 {
            break;
        }
    }
    assert!(f1.abs() < 1e-9, "no convergence: {f1}");
    x1.exp()
}

/// docs/thickness.md.
fn thickness_doc() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/thickness.md")).unwrap()
}

/// The table's two thinnest rows, h/L = 0.001 and 0.003: their cost grows
/// as (L/h)².
#[test]
#[ignore = "slow tier (.ci/slow): about 3 minutes; CI holds the rows from h/L = 0.01 on"]
fn the_thinnest_rows_of_the_thickness_table_are_the_solver_s() {
    let doc = thickness_doc();
    let missing: Vec<String> = [0.001, 0.003]
        .iter()
        .map(|&h| table_row(h))
        .filter(|row| !doc.lines().any(|l| l == row))
        .collect();
    assert!(
        missing.is_empty(),
        "docs/thickness.md lacks these rows:\n{}",
        missing.join("\n")
    );
}

#[test]
fn the_thickness_table_of_the_docs_is_the_solver_s() {
    let doc = thickness_doc();
    let mut missing = Vec::new();
    for h in [0.01, 0.03, 0.1, 0.3, 0.73, 1.0, 3.0, 10.0, 100.0] {
        let row = table_row(h);
        if !doc.lines().any(|l| l == row) {
            missing.push(row);
        }
    }
    for (error, words) in [(0.01, "1 %"), (0.05, "5 %"), (0.2, "20 %")] {
        let row = format!("| {words} | {:.4} |", thinness_at_error(error));
        if !doc.lines().any(|l| l == row) {
            missing.push(row);
        }
    }
    assert!(
        missing.is_empty(),
        "docs/thickness.md lacks these rows:\n{}",
        missing.join("\n")
    );
}

/// `physical` at 90° without a model: the layer answers wherever (2) is
/// more than 0.5 % off, with (2)'s answer beside it, for coatings of 10 µm,
/// 0.1 mm and 1 mm and with ν = 0.45; (2)'s pull-off is −3πRΔγ.
#[test]
fn physical_at_ninety_degrees_answers_with_the_layer_and_2_beside_it() {
    use thinjkr::units::Cylinders;
    let contact = |h: f64, nu: f64| Cylinders {
        r1: 0.01,
        r2: 0.01,
        theta_deg: 90.0,
        h1: h,
        h2: h,
        g1: 1e6,
        g2: 1e6,
        work_of_adhesion: 0.05,
        nu1: nu,
        nu2: nu,
    };
    let thin = -3.0 * PI * 0.01 * 0.05;
    for (h, nu) in [(1e-5, 0.5), (1e-4, 0.5), (1e-3, 0.5), (1e-4, 0.45)] {
        let answer = thinjkr::registry::physical(None, &contact(h, nu), None, None).unwrap();
        assert_eq!(
            answer.model, "layer",
            "h {h} ν {nu}: {:?}",
            answer.chosen_because
        );
        let t = answer.thin_layer.as_ref().expect("(2) beside the layer");
        assert!(
            (t.si.force / thin - 1.0).abs() < 1e-6,
            "h {h}: (2)'s pull-off {}",
            t.si.force
        );
        let error = (t.si.force - answer.si.force).abs() / answer.si.force.abs();
        assert!(
            (t.relative_error - error).abs() < 1e-12 && error > 0.005,
            "h {h}: {error}"
        );
        assert!(
            answer.si.force < 0.0 && answer.si.force > thin,
            "h {h}: {}",
            answer.si.force
        );
    }
    // the layer's own pull-off through the model layer, at the coatings' h/L
    let named = thinjkr::registry::physical(
        Some(thinjkr::registry::parse("layer").unwrap()),
        &contact(1e-4, 0.5),
        None,
        None,
    )
    .unwrap();
    assert!(named.thin_layer.is_none() && named.model == "layer");
    let default = thinjkr::registry::physical(None, &contact(1e-4, 0.5), None, None).unwrap();
    assert_eq!(named.si.force, default.si.force);
    // a Poisson's ratio outside [0, 0.5] is refused by name
    let e = thinjkr::registry::physical(None, &contact(1e-4, 0.6), None, None).unwrap_err();
    assert!(
        e.kind() == "out_of_range" && e.to_string().contains("nu1"),
        "{e}"
    );
}
