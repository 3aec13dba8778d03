//! Near-circular inputs (issue 21, items 8 and 9): every model answers for
//! every ρ up to 1, and the answers are continuous there.
//!
//! - Regular states (δ̄ = 2, F̄ = 10, zero force, pull-off under load) move
//!   linearly in ε = 1 − ρ: each is compared with the circle's state at
//!   ρ = 1 (the model's axisymmetric solution (22)–(25)) at ε from 1e-7 down
//!   to 1 ulp below 1, |Δ| ≤ 10 ε + round-off. Before this, the energy
//!   closure found no state for ε between 2e-12 and 2.3e-8, and ε < 1e-12
//!   counted as ρ = 1 exactly.
//! - The end of displacement control of the models that have one near the
//!   circle moves as √ε towards the circle's loss of stability at ρ = 1
//!   (the cos 2θ mode): the ratio of its distances from the ρ = 1 answer at
//!   ε = 1e-8 and 1e-10 is 10 (a √ε law), so the ρ = 1 answer is the limit.
//! - The energy closure stays stable under displacement control at every
//!   ρ < 1 near 1, and says so at ρ = 1 too.

use thinjkr::{Contact, ModelId, State};

const EPS: [f64; 6] = [1e-7, 1e-9, 1e-11, 1e-12, 1e-14, 1.1e-16];

fn models() -> [ModelId; 4] {
    [
        ModelId::Max,
        ModelId::Apexes,
        ModelId::Energy,
        ModelId::Apex45,
    ]
}

fn close(label: &str, st: &State, circle: &State, eps: f64) {
    let tol = 10.0 * eps + 1e-12;
    for (name, x, y) in [
        ("a_bar", st.a_bar, circle.a_bar),
        ("s", st.s, circle.s),
        ("delta_bar", st.delta_bar, circle.delta_bar),
        ("force_bar", st.force_bar, circle.force_bar),
    ] {
        assert!(
            (x - y).abs() <= tol * (1.0 + y.abs()),
            "{label} at 1 - rho = {eps:e}: {name} = {x} against {y} at rho = 1"
        );
    }
    assert!(
        st.s < 1.0 || eps < 1e-15,
        "{label}: s = 1 at 1 - rho = {eps:e}"
    );
}

#[test]
fn regular_states_are_continuous_up_to_rho_one() {
    for m in models() {
        let circle = Contact::with_model(m, 1.0).unwrap();
        let c_delta = circle.at_displacement(2.0).unwrap();
        let c_force = circle.at_load(10.0).unwrap();
        let c_zero = circle.zero_force().unwrap();
        let c_pull = circle.pull_off_load().unwrap().state;
        for eps in EPS {
            let c = Contact::with_model(m, 1.0 - eps).unwrap();
            let label = |what: &str| format!("{m} {what}");
            close(
                &label("delta 2"),
                &c.at_displacement(2.0).unwrap(),
                &c_delta,
                eps,
            );
            close(&label("force 10"), &c.at_load(10.0).unwrap(), &c_force, eps);
            close(&label("zero force"), &c.zero_force().unwrap(), &c_zero, eps);
            close(
                &label("pull-off"),
                &c.pull_off_load().unwrap().state,
                &c_pull,
                eps,
            );
        }
    }
}

#[test]
fn end_of_displacement_control_tends_to_the_circles_bifurcation() {
    for m in [ModelId::Max, ModelId::Apexes, ModelId::Apex45] {
        let at_one = Contact::with_model(m, 1.0)
            .unwrap()
            .pull_off_displacement()
            .unwrap()
            .state;
        assert_eq!(at_one.s, 1.0);
        let dist = |eps: f64| {
            let st = Contact::with_model(m, 1.0 - eps)
                .unwrap()
                .pull_off_displacement()
                .unwrap()
                .state;
            assert!(st.s < 1.0, "{m} at 1 - rho = {eps:e}");
            (st.force_bar - at_one.force_bar).abs()
        };
        let (d8, d10) = (dist(1e-8), dist(1e-10));
        let ratio = d8 / d10;
        assert!(
            (ratio - 10.0).abs() < 0.3,
            "{m}: distances {d8:e}, {d10:e}, ratio {ratio}"
        );
        // and on below: within round-off of the √ε law (the fold's
        // condition is known to about 1e-13 near the circle)
        for eps in [1e-12, 1e-14, 1.1e-16] {
            let d = dist(eps);
            assert!(
                d <= d10 * (eps / 1e-10).sqrt() * 1.1 + 1e-7,
                "{m} at {eps:e}: {d:e}"
            );
        }
    }
}

#[test]
fn energy_closure_stays_stable_under_displacement_up_to_rho_one() {
    for rho in [1.0 - 1e-9, 1.0] {
        let e = Contact::with_model(ModelId::Energy, rho)
            .unwrap()
            .pull_off_displacement()
            .unwrap_err()
            .to_string();
        assert!(e.contains("stays stable under displacement control"), "{e}");
    }
}

#[test]
fn curve_near_one_is_refused_in_words_not_traced_wrong() {
    let e = thinjkr::curve::trace(&Contact::new(1.0 - 1e-12).unwrap(), 10, 20.0)
        .unwrap_err()
        .to_string();
    assert!(e.contains("rho") && e.contains("1 - 1e-9"), "{e}");
    for rho in [1.0 - 1e-9, 1.0] {
        assert!(thinjkr::curve::trace(&Contact::new(rho).unwrap(), 10, 20.0).is_ok());
    }
}

/// Displacement control below the circle's loss of stability (δ̄ < δ̄_b):
/// at ρ = 1 the answer is the limit of ρ < 1, not the circle (a saddle
/// there): the energy closure's elongated state, the same at 1 − ρ = 1e-13
/// and at ρ = 1; the paper's model below its displacement-controlled
/// pull-off, as at ρ < 1. Above δ̄_b the circle's state.
#[test]
fn displacement_control_below_the_bifurcation_is_the_limit_of_rho_below_one() {
    let at = |m, rho: f64, d| Contact::with_model(m, rho).unwrap().at_displacement(d);
    for d in [-10.0, -0.7] {
        let one = at(ModelId::Energy, 1.0, d).unwrap();
        let near = at(ModelId::Energy, 1.0 - 1e-13, d).unwrap();
        assert!(one.s < 0.9, "energy at delta = {d}: s = {}", one.s);
        assert!((one.a_bar - near.a_bar).abs() < 1e-9 && (one.s - near.s).abs() < 1e-9);
    }
    let e = at(ModelId::Max, 1.0, -10.0).unwrap_err().to_string();
    assert!(
        e.contains("below the displacement-controlled pull-off"),
        "{e}"
    );
    let st = at(ModelId::Max, 1.0, -0.6).unwrap();
    assert_eq!(st.s, 1.0);
}
