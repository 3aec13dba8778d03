//! The layer's kernel (derive/src/layer.rs): derived from three-dimensional
//! elasticity, it passes every check, and kernels that are wrong in the
//! ways the issue names fail them.
//!
//! The expected series coefficients were worked by hand from the
//! literature's form, independently of this code: at ν = ½ the numerator
//! sinh 2x − 2x = (4/3)x³(1 + x²/5 + 2x⁴/105 + …) and the denominator
//! cosh 2x + 2x² + 1 = 2(1 + 2x² + x⁴/3 + …) give C·3G/(h³k²) =
//! 1 − (9/5)x² + (23/7)x⁴ + … with x = kh. Without the 2(kh)² term the
//! denominator is 2(1 + x² + x⁴/6 + …), and c₂ = 1/5 − 1 = −4/5.

use thinjkr_derive::check::Verdict;
use thinjkr_derive::layer::{
    check_kernel, derive_kernel, incompressible_series, literature_kernel, propagated_compliance,
    propagated_m, thin_layer_m, KernelCheck,
};
use thinjkr_derive::sym::{ex, is_zero, subs};

fn verdict(checks: &[KernelCheck], name: &str) -> Verdict {
    checks
        .iter()
        .find(|c| c.name == name)
        .unwrap_or_else(|| panic!("no check {name}"))
        .verdict
}

#[test]
fn the_derived_kernel_passes_every_check_and_has_the_hand_worked_series() {
    let k = derive_kernel().expect("the kernel derives");
    let checks = check_kernel(&k.compliance);
    assert_eq!(checks.len(), 5);
    for c in &checks {
        assert_eq!(c.verdict, Verdict::Holds, "{}: {}", c.name, c.note);
    }
    let s = incompressible_series(&k.compliance).unwrap();
    for (i, want) in [(3, "1"), (5, "-9/5"), (7, "23/7")] {
        assert!(
            is_zero(&(&s[i] - &ex(want))),
            "coefficient of (kh)^{i}: {}",
            s[i]
        );
    }
    // the steps the derivation checked of itself
    assert_eq!(k.steps.len(), 4, "{:?}", k.steps);
}

#[test]
fn a_kernel_without_the_2_kh_squared_term_fails() {
    let wrong = ex("(1-nu)/(G*k) * ((3-4*nu)*(ekh^2-ekh^-2)/2 - 2*k*h) \
                    / ((3-4*nu)*(ekh^2+ekh^-2)/2 + 4*nu*(2*nu-3) + 5)");
    let checks = check_kernel(&wrong);
    assert_eq!(verdict(&checks, "literature"), Verdict::Differs);
    assert_eq!(verdict(&checks, "propagator"), Verdict::Differs);
    // its thin limit keeps the leading term but not the next one
    let s = incompressible_series(&wrong).unwrap();
    assert!(is_zero(&(&s[5] - &ex("-4/5"))), "{}", s[5]);
}

#[test]
fn a_kernel_at_nu_0_3_where_one_half_is_claimed_fails() {
    let wrong = subs(&literature_kernel(), "nu", &ex("3/10"));
    let checks = check_kernel(&wrong);
    for name in [
        "literature",
        "thin incompressible",
        "thick",
        "winkler",
        "propagator",
    ] {
        assert_eq!(verdict(&checks, name), Verdict::Differs, "{name}");
    }
}

#[test]
fn the_kernel_gives_the_m_of_4() {
    let k = derive_kernel().unwrap();
    let m = thin_layer_m(&k.compliance).unwrap();
    assert!(is_zero(&(m - ex("(h1^3/(3*G1) + h2^3/(3*G2))^(-1)"))));
    // the numerical route alone, against (4) evaluated by hand:
    // h₁³/3G₁ + h₂³/3G₂ = 0.343/3.9 + 1.331/1.8
    let printed = 1.0 / (0.343 / 3.9 + 1.331 / 1.8);
    let route = propagated_m(0.7, 1.3, 1.1, 0.6).unwrap();
    assert!(
        (route / printed - 1.0).abs() < 1e-12,
        "{route} vs {printed}"
    );
}

#[test]
fn the_propagator_is_good_to_round_off_at_small_kh() {
    // against the literature's form at 30 digits
    let lit = literature_kernel();
    for kh in [0.0025, 0.01, 0.04, 0.16] {
        let route = propagated_compliance(kh, 0.5).unwrap();
        let exact = thinjkr_derive::layer::kernel_value(&lit, kh, 0.5).unwrap();
        assert!(
            (route / exact - 1.0).abs() < 1e-14,
            "kh = {kh}: {route} vs {exact}"
        );
    }
}

#[test]
fn the_propagator_reaches_the_limits_by_itself() {
    // the half-space: C·Gk → 1 − ν; the Winkler layer: C·Gk/kh → (1 − 2ν)/(2(1 − ν))
    // (at kh = 20 the half-space is reached to (2kh² + 2kh + 1)·2e^{−2kh}
    // ≈ 7e-15; the propagator's round-off grows with e^{kh})
    for nu in [0.0, 0.3, 0.5] {
        let thick = propagated_compliance(20.0, nu).unwrap();
        assert!(
            (thick / (1.0 - nu) - 1.0).abs() < 1e-12,
            "ν = {nu}: {thick}"
        );
    }
    for nu in [0.0, 0.3] {
        let kh = 1e-4;
        let thin = propagated_compliance(kh, nu).unwrap() / kh;
        let winkler = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
        assert!(
            (thin / winkler - 1.0).abs() < 1e-6,
            "ν = {nu}: {thin} vs {winkler}"
        );
    }
}

#[test]
fn the_base_share_is_the_hand_worked_form_without_cancellation() {
    // 1 − Ψ with sinh, cosh multiplied through by e^{−2q} = t, worked by hand:
    // Ψ = (f(1 − t²)/2 − 2qt)/(f(1 + t²)/2 + (2q² + o)t), f = 3 − 4ν,
    // o = 8ν² − 12ν + 5, so 1 − Ψ = (f t² + (2q² + 2q + o)t)/(f(1 + t²)/2 + (2q² + o)t)
    let k = derive_kernel().unwrap();
    let phi = thinjkr_derive::layer::base_share(&k.compliance);
    let hand = ex("((3-4*nu)*t^2 + (2*q^2+2*q+8*nu^2-12*nu+5)*t) \
                   / ((3-4*nu)*(1+t^2)/2 + (2*q^2+8*nu^2-12*nu+5)*t)");
    assert!(is_zero(&(phi - hand)));
}
