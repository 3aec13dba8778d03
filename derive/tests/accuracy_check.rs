//! The generator's accuracy check rejects what it should: the `apex45`
//! collocation (∂p/∂ν equal at t = 0 and t = π/4), whose closed-form η(s)
//! cancels catastrophically as s → 1, fails it, and the failure names the
//! function and the point; the paper's η passes. (This is why `apex45` is
//! not in `ansatz::ALL` until its radicals are rationalised.)

use thinjkr_derive::accuracy::{check, TOLERANCE};
use thinjkr_derive::ansatz;
use thinjkr_derive::model::Derivation;

#[test]
fn the_check_rejects_apex45_eta_and_passes_the_papers() {
    let paper = Derivation::new(&ansatz::PAPER).expect("paper derives");
    let worst = check("eta", &["s"], &[paper.eta.clone()], &[], None).expect("paper's eta passes");
    assert!(worst <= TOLERANCE, "worst {worst}");

    let apex45 = Derivation::new(&ansatz::APEX_45).expect("apex45 derives");
    let failures = check("eta", &["s"], &[apex45.eta.clone()], &[], None)
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
}
