//! The guide's walk "Adding a family of your own", with a family that is
//! not in the product: the particular solution written with an extra
//! harmonic term (X² − Y² is harmonic, so the pressure and Π̄ must not
//! change), derived, checked and generated in memory; and a particular
//! solution that does not solve (2), which the derivation refuses.

use thinjkr_derive::codegen_conformal;
use thinjkr_derive::conformal::{conformal, derive, ConformalAnsatz};

#[test]
fn a_family_of_ones_own_derives_checks_and_generates() {
    let mine = ConformalAnsatz {
        family: "mine",
        terms: 3,
        title: "the conformal family with a harmonic term added to the particular solution",
        particular: "X^4/24 + mu*Y^4/24 - dbar*(X^2 + Y^2)/4 + 3*(X^2 - Y^2) - 5",
        gap: "X^2/2 + mu*Y^2/2",
    };
    let d = derive(&mine).expect("the walk's family derives and passes its checks");
    let reference = derive(&conformal(3)).unwrap();
    assert!(
        (&d.potential - &reference.potential).is_zero(),
        "a harmonic term in P is cancelled by its own correction"
    );
    let files = codegen_conformal::outputs(std::slice::from_ref(&d)).unwrap();
    let k3 = files
        .iter()
        .find(|o| o.path.ends_with("k3.rs"))
        .expect("a module for K = 3");
    assert!(k3.contents.contains("Model `mine:3`"));
    // 149 monomials for K = 3, as an independent implementation counted (issue 20)
    assert!(k3
        .contents
        .contains("pub const POTENTIAL_ROWS: usize = 149;"));
    let table = files
        .iter()
        .find(|o| o.path.ends_with("table.rs"))
        .expect("the family's table");
    assert!(table.contents.contains("pub static POTENTIAL"));
}

#[test]
fn a_particular_solution_that_does_not_solve_2_is_refused() {
    let wrong = ConformalAnsatz {
        family: "wrong",
        terms: 2,
        title: "P missing its Y⁴ term",
        particular: "X^4/24 - dbar*(X^2 + Y^2)/4",
        gap: "X^2/2 + mu*Y^2/2",
    };
    let err = derive(&wrong).unwrap_err();
    assert!(err.contains("(2)"), "{err}");
}
