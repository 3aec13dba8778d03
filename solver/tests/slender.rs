//! The slender model through the model layer (issue 32, milestone (c)),
//! held against a second route written here from the strip alone: the
//! width relation solved by Cardano's formula, the line force integrated
//! over X by composite Simpson in ξ = t/(1 − t), and the pull-off found by
//! golden section. Nothing here reuses the generated code.

use thinjkr::control::Hold;
use thinjkr::fold::FoldCondition;
use thinjkr::registry::{parse, Choice};
use thinjkr::report::AnyState;
use thinjkr::Error;

fn slender() -> Choice {
    parse("slender").expect("the slender model is registered")
}

fn state(a: AnyState) -> thinjkr::report::SlenderState {
    match a {
        AnyState::Slender(s) => s,
        other => panic!("not a slender state: {other:?}"),
    }
}

/// The strip's half-width β at local approach D (slender units): the one
/// positive root of β³ − 6Dβ − 6 = 0 (p'' = μY²/2 − d, p(±b) = 0,
/// p'(b) = 1, scaled), by Cardano where the discriminant allows and by
/// the trigonometric form where it does not.
fn width(d: f64) -> f64 {
    let (p, q) = (-6.0 * d, -6.0);
    let disc = (q / 2.0) * (q / 2.0) + (p / 3.0).powi(3);
    if disc >= 0.0 {
        let u = (-q / 2.0 + disc.sqrt()).cbrt();
        let v = (-q / 2.0 - disc.sqrt()).cbrt();
        u + v
    } else {
        let r = (-p / 3.0).sqrt();
        let phi = ((-q / 2.0) / r.powi(3)).acos();
        2.0 * r * (phi / 3.0).cos()
    }
}

/// G(Δ) = 2 ∫₀^∞ g(β(Δ − ξ²/2)) dξ with g = 2β⁵/45 − 2β²/3, by composite
/// Simpson in t (ξ = t/(1 − t)) with `n` intervals.
fn g_of_delta(delta: f64, n: usize) -> f64 {
    let f = |t: f64| {
        if t >= 1.0 {
            return 0.0;
        }
        let xi = t / (1.0 - t);
        let b = width(delta - 0.5 * xi * xi);
        (2.0 * b.powi(5) / 45.0 - 2.0 * b * b / 3.0) / ((1.0 - t) * (1.0 - t))
    };
    let h = 1.0 / n as f64;
    let mut s = f(0.0) + f(1.0);
    for k in 1..n {
        s += f(k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 };
    }
    2.0 * s * h / 3.0
}

#[test]
fn the_pull_off_agrees_with_a_second_route_from_the_strip() {
    // second route: the minimum of G over Δ by golden section
    let (mut a, mut b) = (-1.0, 2.0);
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let g = |d: f64| g_of_delta(d, 20_000);
    for _ in 0..80 {
        let (c, d) = (b - r * (b - a), a + r * (b - a));
        if g(c) < g(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let delta_c = 0.5 * (a + b);
    let g_c = g(delta_c);
    for rho in [1.0, 0.2, 0.02] {
        let p = slender().pull_off(rho, FoldCondition::Load).unwrap();
        let st = state(p.state);
        let scaled_force = st.force_bar / rho.sqrt();
        let scaled_delta = st.delta_bar * rho.cbrt();
        eprintln!("rho {rho}: G = {scaled_force:.12} (route {g_c:.12}), Delta = {scaled_delta:.9} (route {delta_c:.9})");
        // the force at a minimum is second-order in the location's error
        assert!((scaled_force - g_c).abs() < 1e-9, "{scaled_force} vs {g_c}");
        assert!(
            (scaled_delta - delta_c).abs() < 1e-5,
            "{scaled_delta} vs {delta_c}"
        );
        // the width relation at the centre: Δ = β₀²/6 − 1/β₀
        let beta0 = st.b_bar / rho.cbrt();
        assert!((scaled_delta - (beta0 * beta0 / 6.0 - 1.0 / beta0)).abs() < 1e-12);
        assert!(!st.stable_load && st.stable_displacement);
    }
}

#[test]
fn states_at_a_control_agree_with_the_second_route() {
    for (rho, hold) in [
        (0.1, Hold::Delta(1.0)),
        (0.05, Hold::Delta(-2.0)),
        (0.3, Hold::Force(0.0)),
        (0.02, Hold::Force(10.0)),
    ] {
        let st = state(slender().state(rho, hold).unwrap());
        let route = rho.sqrt() * g_of_delta(st.delta_bar * rho.cbrt(), 20_000);
        assert!(
            (st.force_bar - route).abs() < 1e-9 * route.abs().max(1.0),
            "{hold} at rho {rho}: {} vs {route}",
            st.force_bar
        );
        if let Hold::Force(f) = hold {
            assert!((st.force_bar - f).abs() < 1e-9 * f.abs().max(1.0));
            assert!(st.stable_load, "the state at a force is the stable one");
        }
    }
    // at a tensile force above the minimum: the stable state and one more
    let all = slender().states(0.05, Hold::Force(-0.5)).unwrap();
    assert_eq!(all.len(), 2);
}

/// What a slender contact has not is refused, typed, with the reason.
#[test]
fn what_a_slender_contact_lacks_is_refused_with_the_reason() {
    let m = slender();
    let unavailable = |e: Error| {
        matches!(
            e,
            Error::Unavailable {
                model: "slender",
                ..
            }
        )
    };
    assert!(unavailable(m.state(0.1, Hold::Size(2.0)).unwrap_err()));
    assert!(unavailable(
        m.pull_off(0.1, FoldCondition::Displacement).unwrap_err()
    ));
    assert!(unavailable(m.curve(0.1, 50, 3.0).unwrap_err()));
    let below = m.state(0.1, Hold::Force(-2.0)).unwrap_err();
    assert!(
        matches!(below, Error::OutOfRange { name: "force", .. }),
        "{below}"
    );
    let rho = m.state(1.5, Hold::Delta(1.0)).unwrap_err();
    assert!(
        matches!(rho, Error::OutOfRange { name: "rho", .. }),
        "{rho}"
    );
    let huge = m.state(0.1, Hold::Delta(1e6)).unwrap_err();
    assert!(
        matches!(huge, Error::Unsupported { name: "delta", .. }),
        "{huge}"
    );
    let nan = m.state(0.1, Hold::Force(f64::NAN)).unwrap_err();
    assert!(
        matches!(nan, Error::OutOfRange { name: "force", .. }),
        "{nan}"
    );
    assert!(thinjkr::registry::entries()
        .iter()
        .any(|e| e.name == "slender"));
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]

    /// The scaling laws and the round trip, for random ρ and approach:
    /// the state at δ̄ and the state at ρ' with δ̄' = δ̄ (ρ/ρ')^(1/3) have
    /// the same β₀, their forces in the ratio (ρ'/ρ)^(1/2); and the stable
    /// state at that force (the one on the approach's side of the force
    /// minimum) has the approach back.
    #[test]
    fn the_scaling_laws_and_the_round_trip_hold(
        rho in 0.02f64..1.0,
        rho2 in 0.02f64..1.0,
        scaled in -2.0f64..40.0,
    ) {
        let m = slender();
        let delta = scaled / rho.cbrt();
        let a = state(m.state(rho, Hold::Delta(delta)).unwrap());
        let b = state(m.state(rho2, Hold::Delta(scaled / rho2.cbrt())).unwrap());
        proptest::prop_assert!((a.beta0 - b.beta0).abs() <= 1e-12 * a.beta0);
        let ratio = (b.force_bar / a.force_bar) / (rho2 / rho).sqrt();
        proptest::prop_assert!(
            (ratio - 1.0).abs() <= 1e-9 || a.force_bar.abs() < 1e-9,
            "force ratio {ratio}"
        );
        let back = m
            .states(rho, Hold::Force(a.force_bar))
            .unwrap()
            .into_iter()
            .map(state)
            .find(|s| s.stable_load == a.stable_load)
            .unwrap();
        proptest::prop_assert!(
            (back.delta_bar - delta).abs() <= 1e-8 * delta.abs().max(1.0),
            "delta {delta} -> force {} -> delta {}",
            a.force_bar,
            back.delta_bar
        );
    }
}
