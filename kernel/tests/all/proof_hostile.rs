//! Hostile proofs (from an adversarial review): each is refused quickly with a message, or, where
//! the region may be empty, the checker says so instead of reporting conclusions as meaningful.
#![cfg(all(feature = "proof", feature = "explain"))]

use chatter_kernel::exact::ParseLimits;
use chatter_kernel::proof::{Failure, Hypothesis, ProofFile, Step, check, read};
use chatter_kernel::reject::{Code, Detail, KindDetail, Rejection};
use malachite::rational::Rational as Q;

fn committed() -> ProofFile {
    read(include_str!("../../../proofs/square.ron")).expect("the committed proof reads")
}

/// The square's proof with `steps` put in front of its steps (after its header).
fn with_steps(steps: Vec<Step>) -> ProofFile {
    let mut f = committed();
    f.steps.splice(0..0, steps);
    f
}

fn rejection(f: &ProofFile) -> Rejection {
    check::<Q>(f, ParseLimits::default()).expect_err("refused")
}

/// The proof's failure in a rejection.
fn failure(r: &Rejection) -> &Failure {
    let Detail::Kind(KindDetail::Proof(f)) = r.detail.as_ref() else {
        panic!("not a proof's failure: {r:?}")
    };
    f
}

#[test]
fn chained_definitions_do_not_blow_up() {
    let f = with_steps(vec![
        Step::Define { id: "e1".into(), num: "g + 1".into(), den: "1".into(), positive: None },
        Step::Define { id: "e2".into(), num: "e1^64".into(), den: "1".into(), positive: None },
        Step::Identity { id: "boom".into(), lhs: "e2^8".into(), rhs: "0".into() },
    ]);
    let r = rejection(&f);
    assert_eq!(r.code, Code::TooLarge, "{r}");
    assert!(
        matches!(failure(&r), Failure::Substitution(..) | Failure::Product(..) | Failure::Terms(_)),
        "{r}"
    );
}

#[test]
fn long_products_of_atoms_do_not_blow_up() {
    let terms = vec![("1".to_string(), vec!["l".to_string(); 200])];
    let f = with_steps(vec![Step::Positive { id: "p".into(), expr: "1".into(), terms, over: vec![] }]);
    let r = rejection(&f);
    assert_eq!(r.code, Code::TooLarge, "{r}");
}

#[test]
fn thousands_of_variables_are_refused() {
    let mut f = committed();
    f.variables.extend((0..2000).map(|i| format!("z{i}")));
    let r = check::<Q>(&f, ParseLimits::default()).unwrap_err();
    assert_eq!(r.code, Code::InvalidHeader);
}

#[test]
fn pcc_coefficients_must_not_involve_the_variable() {
    let mut f = committed();
    let i = f.steps.iter().position(|s| matches!(s, Step::Pcc { .. })).unwrap();
    let Step::Pcc { p, .. } = &mut f.steps[i] else { unreachable!() };
    *p = "s".into();
    assert_eq!(failure(&rejection(&f)), &Failure::PqVariables);
}

#[test]
fn a_witness_names_each_parameter_once() {
    let mut f = committed();
    let i = f.steps.iter().position(|s| matches!(s, Step::Witness { .. })).unwrap();
    let Step::Witness { at, .. } = &mut f.steps[i] else { unreachable!() };
    at.insert(0, ("g".into(), "1/2".into()));
    let r = rejection(&f);
    assert_eq!((r.code, failure(&r)), (Code::DuplicateName, &Failure::GivenTwice("g".into())));
}

#[test]
fn an_empty_region_is_refused_or_flagged() {
    // A hypothesis that vanishes wherever chi does: refused.
    let mut f = committed();
    f.hypotheses.push(Hypothesis {
        name: "h".into(),
        expr: "-g k l^2 - k l^3 - l^3 - g k + g l - k l + l^2 - g".into(),
    });
    let r = rejection(&f);
    assert_eq!((r.code, failure(&r)), (Code::InvalidHeader, &Failure::HypothesisVanishes));
    assert!(r.message().contains("the region would be empty"), "{r}");
    // lambda > 1 contradicts the proof's own RootBound: the steps still check, but no witness
    // shows a point of the region, and the checker says so.
    let mut f = committed();
    f.hypotheses.push(Hypothesis { name: "l-1".into(), expr: "l - 1".into() });
    let c = check::<Q>(&f, ParseLimits::default()).expect("the steps still check");
    assert!(!c.nonempty);
    assert!(check::<Q>(&committed(), ParseLimits::default()).unwrap().nonempty, "the square's witness");
}
