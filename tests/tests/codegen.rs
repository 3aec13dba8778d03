//! The generated code against the derivation it came from: residuals agree
//! with symbolica's evaluation of the derived expressions (40 digits) to
//! 1e-12 relative; the generated Jacobian agrees with symbolica's own
//! derivative and with central finite differences; the second ansatz is
//! generated, compiles and is solved.
//!
//! Physical range: 0.05 ≤ ρ ≤ 1, 0.3 ≤ s ≤ 1, 0.5 ≤ ā ≤ 20, −2 ≤ δ̄ ≤ 50.

use nalgebra::Vector2;
use proptest::prelude::*;
use std::sync::OnceLock;
use symbolica::atom::Atom;
use thinjkr::newton::{solve, NewtonConfig};
use thinjkr::ModelId;
use thinjkr_derive::sym::{diff, eval_prec, rat, simplify, subs};
use thinjkr_derive::{ansatz, model::Derivation};

struct Derived {
    residuals: Vec<Atom>,
    jacobian: Vec<[Atom; 2]>,
    fbar: Atom,
}

// symbolica is used from the single test thread only (RUST_TEST_THREADS=1);
// the derived expressions are built once.
fn derived(which: &ansatz::Ansatz) -> Derived {
    let d = Derivation::new(which).expect("derivation");
    let residuals: Vec<Atom> = d
        .residuals
        .iter()
        .map(|r| simplify(&subs(r, "eta", &d.eta)))
        .collect();
    let jacobian = residuals
        .iter()
        .map(|r| [diff(r, "abar"), diff(r, "s")])
        .collect();
    Derived {
        residuals,
        jacobian,
        fbar: simplify(&subs(&d.fbar_reduced, "eta", &d.eta)),
    }
}

fn paper() -> &'static Derived {
    static D: OnceLock<Derived> = OnceLock::new();
    D.get_or_init(|| derived(&ansatz::PAPER))
}

fn point(a: f64, s: f64, rho: f64, dbar: f64) -> Vec<(&'static str, Atom)> {
    // exact rationals close to the f64 inputs; the f64 side uses the same values
    let q = |x: f64| rat((x * 1e9).round() as i64, 1_000_000_000);
    vec![
        ("abar", q(a)),
        ("s", q(s)),
        ("rho", q(rho)),
        ("dbar", q(dbar)),
    ]
}

fn rj(id: ModelId, a: f64, s: f64, rho: f64, dbar: f64) -> ([f64; 2], [[f64; 2]; 2]) {
    let (r, j) = id
        .model()
        .residuals_and_jacobian(Vector2::new(a, s), rho, dbar);
    (
        [r[0], r[1]],
        [[j[(0, 0)], j[(0, 1)]], [j[(1, 0)], j[(1, 1)]]],
    )
}

fn round9(x: f64) -> f64 {
    (x * 1e9).round() / 1e9
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, .. ProptestConfig::default() })]

    #[test]
    fn residuals_match_symbolica(a in 0.5f64..20.0, s in 0.3f64..1.0, rho in 0.05f64..1.0, dbar in -2.0f64..50.0) {
        let (a, s, rho, dbar) = (round9(a), round9(s), round9(rho), round9(dbar));
        let (r, _) = rj(ModelId::Max, a, s, rho, dbar);
        let scale = 1.0 + a.powi(3) + dbar.abs() * a;
        for k in 0..2 {
            let exact = eval_prec(&paper().residuals[k], &point(a, s, rho, dbar), 40).unwrap();
            prop_assert!((r[k] - exact).abs() <= 1e-12 * scale.max(exact.abs()), "r{} generated {} symbolica {}", k + 1, r[k], exact);
        }
        let f = ModelId::Max.model().force_bar(Vector2::new(a, s), rho, dbar);
        let exact = eval_prec(&paper().fbar, &point(a, s, rho, dbar), 40).unwrap();
        let fscale = a.powi(3) * (1.0 + a * dbar.abs());
        prop_assert!((f - exact).abs() <= 1e-12 * fscale.max(exact.abs()), "F̄ generated {} symbolica {}", f, exact);
    }

    #[test]
    fn jacobian_matches_symbolica_and_finite_differences(a in 0.5f64..20.0, s in 0.3f64..0.999, rho in 0.05f64..1.0, dbar in -2.0f64..50.0) {
        let (a, s, rho, dbar) = (round9(a), round9(s), round9(rho), round9(dbar));
        let (_, j) = rj(ModelId::Max, a, s, rho, dbar);
        let scale = 1.0 + a.powi(3) + dbar.abs() * a;
        for k in 0..2 {
            for (c, name) in ["abar", "s"].iter().enumerate() {
                let exact = eval_prec(&paper().jacobian[k][c], &point(a, s, rho, dbar), 40).unwrap();
                prop_assert!((j[k][c] - exact).abs() <= 1e-11 * scale.max(exact.abs()), "∂r{}/∂{} generated {} symbolica {}", k + 1, name, j[k][c], exact);
            }
        }
        // central differences on the generated residuals
        let h_a = 1e-6 * a;
        let h_s = 1e-6;
        let r = |a: f64, s: f64| rj(ModelId::Max, a, s, rho, dbar).0;
        let (rp, rm) = (r(a + h_a, s), r(a - h_a, s));
        let (sp, sm) = (r(a, s + h_s), r(a, s - h_s));
        for k in 0..2 {
            let fd_a = (rp[k] - rm[k]) / (2.0 * h_a);
            let fd_s = (sp[k] - sm[k]) / (2.0 * h_s);
            prop_assert!((j[k][0] - fd_a).abs() <= 1e-6 * scale / a, "∂r{}/∂ā {} vs FD {}", k + 1, j[k][0], fd_a);
            prop_assert!((j[k][1] - fd_s).abs() <= 1e-6 * scale, "∂r{}/∂s {} vs FD {}", k + 1, j[k][1], fd_s);
        }
    }
}

#[test]
fn d_residuals_d_delta_matches_finite_differences() {
    for &(a, s, rho, dbar) in &[
        (3.0, 0.9, 0.8, 2.0),
        (1.2, 0.5, 0.3, -0.5),
        (10.0, 0.99, 0.95, 30.0),
    ] {
        let d = ModelId::Max
            .model()
            .residuals_d_delta(Vector2::new(a, s), rho, dbar);
        let h = 1e-6;
        let rp = rj(ModelId::Max, a, s, rho, dbar + h).0;
        let rm = rj(ModelId::Max, a, s, rho, dbar - h).0;
        for k in 0..2 {
            let fd = (rp[k] - rm[k]) / (2.0 * h);
            approx::assert_relative_eq!(d[k], fd, max_relative = 1e-7);
        }
    }
}

#[test]
fn every_other_model_is_generated_solved_and_matches_its_derivation() {
    // ρ = 0.8, δ̄ = 2: start from the paper's solution, solve each other
    // collocation model's residuals; they agree with their own derivation
    // to 1e-12 of the residual scale.
    let cfg = NewtonConfig::default();
    let scale = |a: f64| 1.0 + a.powi(3) + 2.0 * a;
    let paper = solve(
        |x| ModelId::Max.model().residuals_and_jacobian(x, 0.8, 2.0),
        scale,
        Vector2::new(3.0, 0.9),
        &cfg,
        "paper",
    )
    .unwrap();
    for (id, which) in [
        (ModelId::Apexes, &ansatz::APEXES),
        (ModelId::Apex45, &ansatz::APEX_45),
    ] {
        let other = solve(
            |x| id.model().residuals_and_jacobian(x, 0.8, 2.0),
            scale,
            Vector2::new(paper.a_bar, paper.s),
            &cfg,
            "other",
        )
        .unwrap();
        assert!(
            other.residual < 1e-12,
            "{id}: scaled residual {}",
            other.residual
        );
        assert!(other.s > 0.3 && other.s < 1.0 && other.a_bar > 0.5);
        // a different closure gives a different (nearby) state
        assert!((other.s - paper.s).abs() > 1e-6 || (other.a_bar - paper.a_bar).abs() > 1e-6);
        assert!((other.s - paper.s).abs() < 0.05);
        let d = derived(which);
        let (a, s) = (round9(other.a_bar), round9(other.s));
        let at = point(a, s, 0.8, 2.0);
        let (rg, _) = rj(id, a, s, 0.8, 2.0);
        for k in 0..2 {
            let exact = eval_prec(&d.residuals[k], &at, 40).unwrap();
            assert!(
                (rg[k] - exact).abs() < 1e-12 * scale(a),
                "{id} r{}: {} vs {}",
                k + 1,
                rg[k],
                exact
            );
        }
    }
}

/// The generated kernel of the layer of finite thickness (Φ = 1 − C·Gk/(1 − ν),
/// `solver/src/generated/layer_kernel.rs`) against the numerical layer of
/// thinjkr-derive (the state vector carried across the layer by its matrix
/// exponential, no symbolic step): equal to round-off (absolute, since Φ is
/// 1 − a number near 1 on the numerical route).
#[test]
fn the_generated_layer_kernel_is_the_numerical_layers() {
    for (q, nu) in [
        (0.01, 0.5),
        (0.3, 0.5),
        (1.0, 0.5),
        (2.5, 0.3),
        (6.0, 0.0),
        (0.1, 0.45),
        (4.0, 0.45),
    ] {
        let generated = thinjkr::generated::layer_kernel::base_share_at(q, nu);
        let route = 1.0 - thinjkr_derive::layer::propagated_compliance(q, nu).unwrap() / (1.0 - nu);
        assert!(
            (generated - route).abs() <= 1e-14,
            "q = {q}, ν = {nu}: {generated} vs {route}"
        );
    }
    // the limits: long waves meet the rigid base alone, short waves the half-space
    for nu in [0.0, 0.3, 0.5] {
        assert_eq!(
            thinjkr::generated::layer_kernel::base_share_at(0.0, nu),
            1.0
        );
        assert!(thinjkr::generated::layer_kernel::base_share_at(40.0, nu) < 1e-30);
    }
}
