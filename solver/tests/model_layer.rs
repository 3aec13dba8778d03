//! The model layer (`thinjkr::registry`): one control type and one set of
//! verbs over every kind of model, answering what each kind's own API
//! answers (the same bits), and saying in a typed error what a kind does not
//! have.

use thinjkr::conformal::Conformal;
use thinjkr::control::Hold;
use thinjkr::fold::FoldCondition;
use thinjkr::registry::{parse, Choice};
use thinjkr::report::AnyState;
use thinjkr::{Contact, Error, ModelId};

fn json<T: serde::Serialize>(v: &T) -> String {
    serde_json::to_string(v).unwrap()
}

#[test]
fn each_kind_answers_through_the_layer_as_through_its_own_api() {
    let rho = 0.8;
    let max = parse("max").unwrap();
    let c = Contact::with_model(ModelId::Max, rho).unwrap();
    assert_eq!(
        json(&max.state(rho, Hold::Force(1.0)).unwrap()),
        json(&AnyState::Ellipse(c.at_load(1.0).unwrap()))
    );
    assert_eq!(
        json(&max.zero_force(rho).unwrap()),
        json(&AnyState::Ellipse(c.zero_force().unwrap()))
    );
    // at a given ā: both states, the one before the size fold first
    let both = max.states(rho, Hold::Size(3.0)).unwrap();
    assert_eq!(both.len(), 2);
    assert_eq!(
        json(&both[0]),
        json(&max.state(rho, Hold::Size(3.0)).unwrap())
    );
    let k4 = parse("conformal:4").unwrap();
    let m = Conformal::member("conformal", 4).unwrap();
    assert_eq!(
        json(&k4.state(rho, Hold::Delta(2.0)).unwrap()),
        json(&AnyState::Conformal(
            m.solve(rho, Hold::Delta(2.0)).unwrap()
        ))
    );
    let p = k4.pull_off(rho, FoldCondition::Load).unwrap();
    let (direct, folds) = m.pull_off(rho, FoldCondition::Load).unwrap();
    assert_eq!(json(&p.state), json(&AnyState::Conformal(direct)));
    assert_eq!(p.passed.len(), folds.len());
    let exact = parse("exact").unwrap();
    assert_eq!(
        json(&exact.state(rho, Hold::Force(10.0)).unwrap()),
        json(&AnyState::Exact(Box::new(
            thinjkr::exact::at_resolved(rho, Hold::Force(10.0)).unwrap()
        )))
    );
    let ellipse_pull_off = max.pull_off(rho, FoldCondition::Displacement).unwrap();
    assert_eq!(
        json(&ellipse_pull_off.state),
        json(&AnyState::Ellipse(c.pull_off_displacement().unwrap().state))
    );
    assert!(ellipse_pull_off.basis.is_some());
}

#[test]
fn what_a_kind_does_not_have_is_a_typed_error() {
    let exact = parse("exact").unwrap();
    assert!(matches!(
        exact.state(0.8, Hold::Size(3.0)),
        Err(Error::Unavailable { model: "exact", .. })
    ));
    assert!(matches!(
        exact.pull_off(0.8, FoldCondition::Displacement),
        Err(Error::Unavailable { model: "exact", .. })
    ));
    assert!(matches!(
        parse("max")
            .unwrap()
            .pull_off(0.8, FoldCondition::ContactSize),
        Err(Error::Usage(_))
    ));
    assert!(matches!(Hold::named("speed", 1.0), Err(Error::Usage(_))));
    assert_eq!(Hold::named("a", 2.5).unwrap(), Hold::Size(2.5));
    for (name, kind) in [
        ("max", "max"),
        ("conformal:8", "conformal:8"),
        ("exact", "exact"),
    ] {
        assert_eq!(parse(name).unwrap().name(), kind);
    }
    assert!(matches!(parse("conformal:8"), Ok(Choice::Contour(_))));
    let why = parse("nonesuch:2").unwrap_err();
    assert!(why.contains("conformal:K with K = 1 ..= 8"), "{why}");
}
