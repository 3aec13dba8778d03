//! The generator's accuracy check rejects what it should: the `apex45`
//! collocation (∂p/∂ν equal at t = 0 and t = π/4), whose closed-form η(s)
//! cancels catastrophically as s → 1, fails it as derived, and the failure
//! names the function and the point; the paper's η passes. With its
//! cancelling radicals rationalised (`sym::rationalize`, what the generator
//! emits) apex45's η passes too.

use thinjkr_derive::accuracy::{check, TOLERANCE};
use thinjkr_derive::ansatz;
use thinjkr_derive::model::Derivation;
use thinjkr_derive::sym::{normalize_radicals, simplify};

#[test]
fn the_check_rejects_apex45_eta_and_passes_the_papers() {
    let paper = Derivation::new(&ansatz::PAPER).expect("paper derives");
    let worst = check("eta", &["s"], &[paper.eta.clone()], &[], None).expect("paper's eta passes");
    assert!(worst <= TOLERANCE, "worst {worst}");

    let apex45 = Derivation::new(&ansatz::APEX_45).expect("apex45 derives");
    // η as the plain quotient of the maximum by the apex value, before the
    // derivation rationalises it
    let plain_eta = normalize_radicals(&simplify(&(&apex45.extrema.max / &apex45.extrema.apex)));
    let failures = check("eta", &["s"], &[plain_eta.clone()], &[], None)
        .expect_err("apex45's eta must fail the check");
    // it fails near s = 1, not at small s
    assert!(failures.iter().all(|f| f.function == "eta"));
    let s_values: Vec<f64> = failures
        .iter()
        .map(|f| f.point.iter().find(|(n, _)| n == "s").expect("s").1)
        .collect();
    assert!(s_values.iter().all(|&s| s >= 0.7), "{s_values:?}");
    assert!(s_values.contains(&0.99), "{s_values:?}");
    let text = failures[0].to_string();
    assert!(text.contains("eta") && text.contains("s = "), "{text}");
    let probe = [("s", thinjkr_derive::sym::rat(999, 1000))];
    let rationalized = thinjkr_derive::sym::rationalize(&plain_eta, &probe);
    // which is the form the derivation keeps
    assert!(check("eta", &["s"], &[apex45.eta.clone()], &[], None).is_ok());
    let worst =
        check("eta", &["s"], &[rationalized], &[], None).expect("the rationalised eta passes");
    assert!(worst <= TOLERANCE, "worst {worst}");
}
