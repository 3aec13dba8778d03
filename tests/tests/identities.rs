//! The paper's identities, as properties of the solver (derived forms used
//! throughout: where the paper's print differs — (18), (25)₁, (26), (27) —
//! the derived expression is the reference, as the comments say).

use approx::assert_relative_eq;
use proptest::prelude::*;
use std::sync::OnceLock;
use thinjkr::units::Cylinders;
use thinjkr::{limits, Contact, Error};
use thinjkr_derive::sym::{eval_prec, rat, simplify, subs};
use thinjkr_derive::{ansatz, model::Derivation};

fn paper() -> &'static Derivation {
    static D: OnceLock<Derivation> = OnceLock::new();
    D.get_or_init(|| Derivation::new(&ansatz::PAPER).expect("derivation"))
}

fn q(x: f64) -> symbolica::atom::Atom {
    rat((x * 1e12).round() as i64, 1_000_000_000_000)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, .. ProptestConfig::default() })]

    /// (14) = η − 1 for the paper's model near s = 1, against a form derived
    /// by hand: multiplying 2Q^(3/2) − 3√3 s(1+s) (Q = 1 + s + s²) by its
    /// conjugate gives 4Q³ − 27s²(1+s)² = (1−s)²(1+2s)²(2+s)², so
    /// η − 1 = (1−s)²(1+2s)²(2+s)² / (3√3 s(1+s)(2Q^(3/2) + 3√3 s(1+s))),
    /// which has no cancellation. The generated function must agree with it
    /// relative to its own value, down to s = 1 − 1e-9 where η − 1 ~ 1e-18.
    #[test]
    fn bc_error_is_relatively_accurate_near_one(log_t in -9.0f64..-0.3) {
        let s = 1.0 - 10f64.powf(log_t);
        let q = 1.0 + s + s * s;
        let r3 = 3f64.sqrt();
        let by_hand = ((1.0 - s) * (1.0 + 2.0 * s) * (2.0 + s)).powi(2)
            / (3.0 * r3 * s * (1.0 + s) * (2.0 * q * q.sqrt() + 3.0 * r3 * s * (1.0 + s)));
        let generated = thinjkr::generated::max::bc_error(s);
        prop_assert!((generated - by_hand).abs() <= 1e-14 * by_hand, "s = {s}: {generated:e} vs {by_hand:e}");
    }

    /// Zero force: the solver's state satisfies the derived relations of
    /// Section 5, evaluated from the derive crate's expressions. The printed
    /// (26), (27) lack η(s); the derived forms are used here. (28) holds as printed.
    #[test]
    fn zero_force_reduction(rho in 0.3f64..0.99) {
        let st = Contact::new(rho).unwrap().zero_force().unwrap();
        let l = paper().limits.as_ref().unwrap();
        let eta = &paper().eta;
        let at = [("s", q(st.s))];
        let ad = eval_prec(&simplify(&subs(&subs(&l.zero_force.dbar, "eta", eta), "abar", &rat(1, 1))), &at, 30).unwrap();
        let a3 = eval_prec(&simplify(&subs(&l.zero_force.abar_cubed, "eta", eta)), &at, 30).unwrap();
        let r = eval_prec(&l.zero_force.rho, &at, 30).unwrap();
        prop_assert!((st.a_bar * st.delta_bar - ad).abs() < 1e-8 * ad.abs(), "a δ {} vs {}", st.a_bar * st.delta_bar, ad);
        prop_assert!((st.a_bar.powi(3) - a3).abs() < 1e-8 * a3, "a³ {} vs {}", st.a_bar.powi(3), a3);
        prop_assert!((r - rho).abs() < 1e-9, "(28): {} vs {}", r, rho);
        prop_assert!(st.force_bar.abs() < 1e-9);
    }

    /// Solving again at a state's own δ̄ returns the same state.
    #[test]
    fn resolving_at_own_delta_is_idempotent(rho in 0.2f64..1.0, delta in -0.2f64..40.0) {
        let c = Contact::new(rho).unwrap();
        if let Ok(st) = c.at_displacement(delta) {
            let again = c.at_displacement(st.delta_bar).unwrap();
            prop_assert!((again.a_bar - st.a_bar).abs() < 1e-9 * st.a_bar && (again.s - st.s).abs() < 1e-9);
            // and at its own force, when it lies on the part that is stable under load control
            if st.s >= c.pull_off_load().unwrap().state.s {
                let by_force = c.at_load(st.force_bar).unwrap();
                prop_assert!((by_force.a_bar - st.a_bar).abs() < 1e-7 * st.a_bar, "{} vs {}", by_force.a_bar, st.a_bar);
            }
        }
    }
}

/// Near-circular contacts: ρ = (1 − μ)/(1 + μ) at fixed physical δ and mean
/// radius R. (35)–(36) predict s ≈ 1 − 2μ a₂/a₀; the error must shrink like
/// μ²: halving μ divides it by ≈ 4. (36) holds as printed (checker).
#[test]
fn near_circular_agreement_rate() {
    let l = paper().limits.as_ref().unwrap();
    for a0 in [2.6, 3.5, 6.0] {
        let delta0 = a0 * a0 / 4.0 - 2.0 / a0; // (22) at the mean radius R, derived form of (25)₁
                                               // a₂/a₀ from the exact perturbation (36), nondimensional: R = m = L = 1, g = 1
        let a2 = eval_prec(
            &l.near_circular_exact.a2,
            &[
                ("a0", q(a0)),
                ("R", rat(1, 1)),
                ("m", rat(1, 1)),
                ("g", rat(1, 1)),
            ],
            30,
        )
        .unwrap();
        let slope = -2.0 * a2 / a0;
        let err = |mu: f64| {
            let rho = (1.0 - mu) / (1.0 + mu);
            // R₁ = R/(1 − μ): δ̄ scales with R₁^(1/3) at fixed δ
            let delta = delta0 * (1.0 - mu).powf(-1.0 / 3.0);
            let st = Contact::new(rho).unwrap().at_displacement(delta).unwrap();
            (st.s - (1.0 + mu * slope)).abs()
        };
        let e: Vec<f64> = [0.02, 0.01, 0.005].iter().map(|&m| err(m)).collect();
        for k in 0..2 {
            let ratio = e[k] / e[k + 1];
            assert!(
                (3.5..4.5).contains(&ratio),
                "a0 = {a0}: error ratio {ratio} (errors {e:?})"
            );
        }
    }
}

/// ρ = 1: s = 1, the derived axisymmetric relations (22)–(23) (in the form
/// δ̄ = ā²/4 − 2/ā; the printed (25)₁ has 2^(4/3)/ā), pull-off −3π/2 at
/// ā = 12^(1/3); and continuity from ρ < 1.
#[test]
fn axisymmetric_limit() {
    let c = Contact::new(1.0).unwrap();
    // below δ̄ = 2^(4/3)/4 − 2^(1/3) (ā = 2^(2/3), where the circle loses
    // stability to an ellipse) the circle is not the answer: as for ρ < 1,
    // the paper's model is below its displacement-controlled pull-off
    let e = c.at_displacement(-1.0).unwrap_err().to_string();
    assert!(
        e.contains("below the displacement-controlled pull-off"),
        "{e}"
    );
    for delta in [-0.6, 0.0, 0.3, 2.0, 10.0] {
        let st = c.at_displacement(delta).unwrap();
        assert_eq!(st.s, 1.0);
        // δ̄ is the one asked for and ā its root; at δ̄ = 0 the two terms
        // cancel, so the comparison is relative to their size
        let terms = st.a_bar * st.a_bar / 4.0 + 2.0 / st.a_bar;
        assert_relative_eq!(
            st.delta_bar,
            st.a_bar * st.a_bar / 4.0 - 2.0 / st.a_bar,
            max_relative = 1e-12,
            epsilon = 1e-14 * terms
        );
        let f = std::f64::consts::PI / 96.0
            * st.a_bar.powi(4)
            * (st.a_bar * st.a_bar - 24.0 / st.a_bar);
        assert_relative_eq!(st.force_bar, f, max_relative = 1e-12, epsilon = 1e-12);
        assert!(st.bc_error.abs() < 1e-15);
    }
    let po = c.pull_off_load().unwrap().state;
    assert_relative_eq!(
        po.force_bar,
        -1.5 * std::f64::consts::PI,
        max_relative = 1e-12
    );
    assert_relative_eq!(po.a_bar, 12f64.cbrt(), max_relative = 1e-12);
    // the model is continuous as ρ → 1
    let near = Contact::new(1.0 - 1e-7)
        .unwrap()
        .at_displacement(2.0)
        .unwrap();
    let exact = c.at_displacement(2.0).unwrap();
    assert!(
        (near.s - 1.0).abs() < 1e-5 && (near.a_bar - exact.a_bar).abs() < 1e-5 * exact.a_bar,
        "{near:?} vs {exact:?}"
    );
    let near_po = Contact::new(1.0 - 1e-6)
        .unwrap()
        .pull_off_load()
        .unwrap()
        .state;
    assert!((near_po.force_bar - po.force_bar).abs() < 1e-4);
}

/// F̄(δ̄) is continuous along a traced curve, and every traced point solves
/// (19)–(20); the folds are found in the expected order.
#[test]
fn curve_is_continuous_and_solves_the_equations() {
    for rho in [0.8, 0.5, 0.2] {
        let c = Contact::new(rho).unwrap();
        let curve = thinjkr::curve::trace(&c, 400, 20.0).unwrap();
        let po = c.pull_off_load().unwrap().state;
        // continuity: doubling the number of points halves the largest jump
        let max_jump = |n: usize| {
            let cv = thinjkr::curve::trace(&c, n, 20.0).unwrap();
            cv.states
                .windows(2)
                .map(|w| (w[1].force_bar - w[0].force_bar).abs())
                .fold(0.0, f64::max)
        };
        let (j1, j2) = (max_jump(500), max_jump(1000));
        assert!(
            j2 < 0.7 * j1,
            "rho {rho}: largest F̄ jump {j1} with 500 points, {j2} with 1000"
        );
        for st in &curve.states {
            let (r, _) = thinjkr::ModelId::Max.model().residuals_and_jacobian(
                nalgebra::Vector2::new(st.a_bar, st.s),
                rho,
                st.delta_bar,
            );
            assert!(r.norm() < 1e-8 * (1.0 + st.a_bar.powi(3)));
            assert!(st.force_bar.is_finite() && st.a_bar > 0.0 && st.s > 0.0 && st.s <= 1.0);
        }
        let min_f = curve
            .states
            .iter()
            .map(|s| s.force_bar)
            .fold(f64::INFINITY, f64::min);
        assert!(
            min_f >= po.force_bar - 1e-6 && min_f < po.force_bar + 0.05,
            "rho {rho}: {min_f} vs pull-off {}",
            po.force_bar
        );
        let kinds: Vec<_> = curve.folds.iter().map(|f| f.kind).collect();
        assert!(kinds.contains(&thinjkr::curve::FoldKind::Load), "{kinds:?}");
        // the curve's load fold is located by the fold Newton: the pull-off
        // state itself, not the nearest of the 400 traced points
        let fold = curve
            .folds
            .iter()
            .find(|f| f.kind == thinjkr::curve::FoldKind::Load)
            .unwrap();
        let (df, da, ds) = (
            (fold.state.force_bar - po.force_bar).abs() / po.force_bar.abs(),
            (fold.state.a_bar - po.a_bar).abs() / po.a_bar,
            (fold.state.s - po.s).abs(),
        );
        assert!(
            df < 1e-12 && da < 1e-9 && ds < 1e-9,
            "rho {rho}: curve fold differs from the pull-off by {df:e} in F, {da:e} in a, {ds:e} in s"
        );
        assert!(
            kinds.contains(&thinjkr::curve::FoldKind::ContactSize),
            "{kinds:?}"
        );
    }
}

/// Contact-size control returns states that solve the equations, and agrees
/// with displacement control.
#[test]
fn contact_size_control() {
    let c = Contact::new(0.8).unwrap();
    let st = c.at_displacement(2.0).unwrap();
    let by_size = c.at_contact_size(st.a_bar).unwrap();
    assert!(
        by_size
            .iter()
            .any(|x| (x.s - st.s).abs() < 1e-9 && (x.delta_bar - 2.0).abs() < 1e-8),
        "{by_size:?}"
    );
    // below the fold of the contact size there is no state
    let fold = c.size_fold().unwrap();
    assert!(c.at_contact_size(0.9 * fold.a_bar).unwrap().is_empty());
}

/// The dimensional and the nondimensional APIs agree.
#[test]
fn physical_units_agree_with_dimensionless() {
    let cyl = Cylinders {
        r1: 0.01,
        r2: 0.02,
        theta_deg: 70.0,
        h1: 1e-4,
        h2: 2e-4,
        g1: 1e6,
        g2: 5e5,
        work_of_adhesion: 0.05,
        nu1: 0.5,
        nu2: 0.5,
    };
    let sc = cyl.scales().unwrap();
    assert!(sc.big_r2 <= sc.big_r1);
    assert_relative_eq!(
        1.0 / sc.big_r1 + 1.0 / sc.big_r2,
        1.0 / 0.01 + 1.0 / 0.02,
        max_relative = 1e-12
    );
    assert_relative_eq!(
        sc.big_r1 * sc.big_r2,
        0.01 * 0.02 / 70f64.to_radians().sin().powi(2),
        max_relative = 1e-12
    );
    let phys = cyl.pull_off().unwrap();
    let dimless = Contact::new(sc.rho).unwrap().pull_off_load().unwrap().state;
    assert_relative_eq!(
        phys.force,
        dimless.force_bar * 2.0 * sc.big_r1 * 0.05,
        max_relative = 1e-9
    );
    assert_relative_eq!(
        phys.a,
        dimless.a_bar * (2.0 * sc.big_r1.powi(2) * 0.05 / sc.m).powf(1.0 / 6.0),
        max_relative = 1e-9
    );
    let at_f = cyl.at_load(0.5 * phys.force).unwrap();
    assert_relative_eq!(at_f.force, 0.5 * phys.force, max_relative = 1e-7);
    assert!(at_f.h_over_a > 0.0);
}

fn names(e: Error) -> &'static str {
    match e {
        Error::OutOfRange { name, .. } => name,
        other => panic!("expected OutOfRange, got {other}"),
    }
}

/// Bad input is a typed error naming the parameter.
#[test]
fn bad_inputs_are_typed_errors() {
    for rho in [0.0, -0.5, 1.5, f64::NAN, f64::INFINITY] {
        assert_eq!(names(Contact::new(rho).unwrap_err()), "rho");
    }
    let good = Cylinders {
        r1: 0.01,
        r2: 0.01,
        theta_deg: 60.0,
        h1: 1e-4,
        h2: 1e-4,
        g1: 1e6,
        g2: 1e6,
        work_of_adhesion: 0.05,
        nu1: 0.5,
        nu2: 0.5,
    };
    let cases: Vec<(&str, Cylinders)> = vec![
        ("r1", Cylinders { r1: -1.0, ..good }),
        (
            "r2",
            Cylinders {
                r2: f64::NAN,
                ..good
            },
        ),
        (
            "theta_deg",
            Cylinders {
                theta_deg: 0.0,
                ..good
            },
        ),
        (
            "theta_deg",
            Cylinders {
                theta_deg: 120.0,
                ..good
            },
        ),
        ("h1", Cylinders { h1: 0.0, ..good }),
        (
            "h2",
            Cylinders {
                h2: f64::INFINITY,
                ..good
            },
        ),
        ("g1", Cylinders { g1: -3.0, ..good }),
        ("g2", Cylinders { g2: 0.0, ..good }),
        (
            "work_of_adhesion",
            Cylinders {
                work_of_adhesion: 0.0,
                ..good
            },
        ),
    ];
    for (name, cyl) in cases {
        assert_eq!(names(cyl.pull_off().unwrap_err()), name);
    }
    let c = Contact::new(0.8).unwrap();
    let po = c.pull_off_load().unwrap().state;
    assert_eq!(names(c.at_load(po.force_bar - 0.1).unwrap_err()), "force");
    assert_eq!(names(c.at_contact_size(-1.0).unwrap_err()), "a");
    assert_eq!(names(c.at_displacement(f64::NAN).unwrap_err()), "delta");
    assert_eq!(names(good.at_load(f64::NAN).unwrap_err()), "force");
}

/// Over a grid of (ρ, δ̄) the solver converges or says that no contact
/// exists; never a NaN.
#[test]
fn sweep_converges_or_reports_no_state() {
    let mut solved = 0;
    for i in 0..=19 {
        let rho = 0.05 + 0.95 * i as f64 / 19.0;
        let c = Contact::new(rho).unwrap();
        for j in 0..=25 {
            let delta = -2.0 + 52.0 * j as f64 / 25.0;
            match c.at_displacement(delta) {
                Ok(st) => {
                    solved += 1;
                    for v in [
                        st.a_bar,
                        st.s,
                        st.delta_bar,
                        st.force_bar,
                        st.xi,
                        st.p0,
                        st.bc_error,
                        st.shape_a,
                        st.shape_b,
                    ] {
                        assert!(v.is_finite(), "rho {rho} delta {delta}: {st:?}");
                    }
                }
                Err(Error::NoState(_)) => {
                    assert!(delta < 1.0, "rho {rho}: no state at delta {delta}")
                }
                Err(e) => panic!("rho {rho} delta {delta}: {e}"),
            }
        }
        // pull-off under both controls and zero force exist everywhere but ρ = 1 (displacement)
        c.pull_off_load().unwrap().state;
        c.zero_force().unwrap();
        if rho < 1.0 {
            c.pull_off_displacement().unwrap().state;
        }
    }
    assert!(solved > 400);
    // (30) approximates the derived root of (28) on (0.4, 1) to 0.01 %
    for k in 0..100 {
        let rho = 0.4 + 0.6 * (k as f64 + 0.5) / 100.0;
        let s = limits::zero_force_s(thinjkr::ModelId::Max, rho).unwrap();
        assert!((limits::zero_force_s_approx(rho) - s).abs() / s < 1e-4);
    }
}
