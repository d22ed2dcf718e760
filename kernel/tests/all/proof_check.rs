//! The proof checker on the committed proof of the square-case lemmas: it checks on both
//! backends, and a change to any coefficient, claim or reference makes it fail at that step.
#![cfg(all(feature = "proof", feature = "explain"))]

use chatter_kernel::exact::{ParseLimits, Ring};
use chatter_kernel::proof::{Failure, ProofFile, Step, check, read};
use chatter_kernel::reject::{Code, Detail, KindDetail, KindLocus, Locus};
use chatter_kernel::verify::{Verdict, verify_proof};
use malachite::rational::Rational as Q;

fn committed() -> ProofFile {
    read(include_str!("../../../proofs/square.ron")).expect("the committed proof reads")
}

/// The index of the step at which the checker (malachite) rejects `f`.
fn fails_at(f: &ProofFile) -> Option<usize> {
    match check::<Q>(f, ParseLimits::default()) {
        Ok(_) => None,
        Err(r) => match &r.locus {
            Locus::Kind(KindLocus::Step { index, .. }) => {
                let Detail::Kind(KindDetail::Proof(f)) = r.detail.as_ref() else {
                    panic!("not a proof's failure: {r}")
                };
                assert_eq!(r.code, f.code(), "{r}");
                Some(*index)
            }
            other => panic!("a step mutation is reported at {other:?}: {r}"),
        },
    }
}

#[test]
fn the_committed_proof_checks_on_both_backends() {
    let Verdict::Accepted(c) = verify_proof(&committed(), ParseLimits::default()) else { panic!("rejected") };
    assert!(c.steps >= 150);
    let all = c.conclusions.join("\n");
    for j in 1..=3 {
        assert!(all.contains(&format!("S_{j}(K ∩ C_{j}) ⊆ K")), "{all}");
    }
    for fact in
        ["I_0(D) ⊆ K", "conditions 1 and 2", "every real root of chi is below 1", "336365601/1000000000000"]
    {
        assert!(all.contains(fact), "{fact} missing from {all}");
    }
    assert!(c.hypotheses.iter().any(|h| h.contains("root of chi")));
}

fn bump(c: &str) -> String {
    let q: Q = chatter_kernel::exact::parse_canonical(c, ParseLimits::default()).expect("canonical");
    chatter_kernel::exact::to_canonical(&q.plus(&Q::from(1)))
}

#[test]
fn changing_any_coefficient_fails_at_that_step() {
    let base = committed();
    let mut tried = 0;
    for (i, s) in base.steps.iter().enumerate() {
        let Step::Positive { terms, .. } = s else { continue };
        for t in 0..terms.len() {
            let mut f = base.clone();
            let Step::Positive { terms, .. } = &mut f.steps[i] else { unreachable!() };
            terms[t].0 = bump(&terms[t].0);
            assert_eq!(fails_at(&f), Some(i), "coefficient {t} of step {i} ({})", s.id());
            tried += 1;
        }
    }
    assert!(tried >= 150, "{tried} coefficients");
}

#[test]
fn changing_any_atom_reference_fails_at_that_step() {
    let base = committed();
    let mut tried = 0;
    for (i, s) in base.steps.iter().enumerate() {
        let Step::Positive { terms, over, .. } = s else { continue };
        for (t, (_, atoms)) in terms.iter().enumerate() {
            for a in 0..atoms.len() {
                let mut f = base.clone();
                let Step::Positive { terms, .. } = &mut f.steps[i] else { unreachable!() };
                let other = if terms[t].1[a] == "k" { "g" } else { "k" };
                terms[t].1[a] = other.into();
                assert_eq!(fails_at(&f), Some(i), "atom {a} of term {t} of step {i} ({})", s.id());
                tried += 1;
            }
        }
        if !over.is_empty() {
            let mut f = base.clone();
            let Step::Positive { over, .. } = &mut f.steps[i] else { unreachable!() };
            over[0] = if over[0] == "k" { "l".into() } else { "k".into() };
            assert_eq!(fails_at(&f), Some(i), "denominator of step {i} ({})", s.id());
        }
    }
    assert!(tried >= 150, "{tried} references");
}

#[test]
fn changing_any_claim_fails_at_that_step() {
    let base = committed();
    let mut kinds = std::collections::BTreeSet::new();
    for (i, s) in base.steps.iter().enumerate() {
        let mut f = base.clone();
        let kind = match &mut f.steps[i] {
            Step::Positive { expr, .. } => {
                *expr = if expr == "e1" { "e2".into() } else { "e1".into() };
                "claim"
            }
            Step::Identity { lhs, rhs, .. } => {
                *rhs = if lhs == "e1" { "e2".into() } else { "e1".into() };
                "identity"
            }
            Step::Image { equals, .. } => {
                equals[0].1 = if equals[0].1 == "s01" { "s30".into() } else { "s01".into() };
                "image"
            }
            Step::Define { positive: Some(p), .. } => {
                *p = "1+k".into();
                "define"
            }
            Step::RootBound { below, .. } => {
                *below = "1/2".into();
                "root bound"
            }
            Step::Invariant { crossings, .. } => {
                crossings.reverse();
                crossings.push("s01".into());
                "crossings"
            }
            Step::Cone { vertices, .. } => {
                vertices.swap(0, 1);
                "cone"
            }
            Step::Pcc { q, .. } => {
                *q = "g^2 + 1".into();
                "pcc"
            }
            Step::AllDown { cone, .. } => {
                *cone = "L".into();
                "all-down"
            }
            Step::Witness { roots, .. } => {
                *roots += 1;
                "witness"
            }
            _ => continue,
        };
        assert_eq!(fails_at(&f), Some(i), "{kind} of step {i} ({})", s.id());
        kinds.insert(kind);
    }
    assert_eq!(kinds.len(), 10, "every kind of step was mutated: {kinds:?}");
}

#[test]
fn moving_a_named_point_fails_where_it_is_used() {
    let base = committed();
    let i = base.steps.iter().position(|s| s.id() == "k1").unwrap();
    let mut f = base.clone();
    let Step::Point { x, .. } = &mut f.steps[i] else { panic!("k1 is a point") };
    *x = "e1".into();
    let at = fails_at(&f).expect("k1 moved to s1 breaks a later step");
    assert!(at > i, "{at}");
}

#[test]
fn a_missing_obligation_fails_the_rule_that_needs_it() {
    let base = committed();
    let removed = base.steps.iter().position(|s| s.id() == "K.S3.q1.left").expect("an image obligation");
    let mut f = base.clone();
    f.steps.remove(removed);
    let rule = f.steps.iter().position(|s| s.id() == "inv.S3").unwrap();
    assert_eq!(fails_at(&f), Some(rule));
    let r = check::<Q>(&f, ParseLimits::default()).unwrap_err();
    assert_eq!(r.code, Code::SignNotProved, "{r}");
    assert!(
        matches!(r.detail.as_ref(), Detail::Kind(KindDetail::Proof(Failure::NoStep(key, _))) if key == "K.S3.q1.left"),
        "{r}"
    );
    assert!(r.message().contains("no step `K.S3.q1.left`"), "{r}");
}

#[test]
fn the_header_is_checked_against_the_model() {
    let mut f = committed();
    f.eigenvalue.chi = f.eigenvalue.chi.replacen("+ g", "+ 2 g", 1);
    let r = check::<Q>(&f, ParseLimits::default()).unwrap_err();
    assert!(matches!(r.locus, Locus::Field { .. }), "{r}");
    let mut f = committed();
    f.coordinates[2] = ["0".into(), "1".into(), "1".into()];
    assert!(check::<Q>(&f, ParseLimits::default()).is_err(), "v must stay the third coordinate");
    let mut f = committed();
    f.eigenvalue.map = 2;
    assert!(check::<Q>(&f, ParseLimits::default()).is_err(), "chi belongs to S_3, not S_2");
    let mut f = committed();
    f.steps.insert(0, f.steps[0].clone());
    assert_eq!(fails_at(&f), Some(1), "a repeated id");
}

#[test]
fn hypotheses_are_about_the_parameters_and_include_kappa_positive() {
    use chatter_kernel::proof::Hypothesis;
    let mut f = committed();
    f.hypotheses.push(Hypothesis { name: "e1".into(), expr: "e1".into() });
    let r = check::<Q>(&f, ParseLimits::default()).unwrap_err();
    assert!(matches!(&r.locus, Locus::Field { path } if path == "hypotheses[4]"), "{r}");
    let mut f = committed();
    f.hypotheses.retain(|h| h.expr != "k");
    let r = check::<Q>(&f, ParseLimits::default()).unwrap_err();
    assert!(matches!(r.detail.as_ref(), Detail::Kind(KindDetail::Proof(Failure::KappaHypothesis))), "{r}");
}

#[test]
fn definitions_are_explicit_in_the_parameters_and_earlier_definitions() {
    let base = committed();
    let i = base.steps.iter().position(|s| matches!(s, Step::Define { id, .. } if id == "e1")).unwrap();
    let mut f = base.clone();
    let Step::Define { num, .. } = &mut f.steps[i] else { unreachable!() };
    *num = "e2".into(); // e1 := e2 / den, e2 not yet defined
    assert_eq!(fails_at(&f), Some(i));
    let mut f = base.clone();
    let Step::Define { id, .. } = &mut f.steps[i] else { unreachable!() };
    *id = "k".into(); // redefining a parameter
    assert_eq!(fails_at(&f), Some(i));
}

#[test]
fn map_names_bodies_and_headers_are_read_strictly() {
    let base = committed();
    let i = base.steps.iter().position(|s| matches!(s, Step::Image { map, .. } if map == "S1")).unwrap();
    for bad in ["S01", "S+1", "S4", "I1"] {
        let mut f = base.clone();
        let Step::Image { map, .. } = &mut f.steps[i] else { unreachable!() };
        *map = bad.into();
        assert_eq!(fails_at(&f), Some(i), "{bad}");
    }
    for n in [2, 5] {
        let mut f = base.clone();
        f.body = chatter_kernel::proof::ProofBody::RegularPolygon { n };
        let r = check::<Q>(&f, ParseLimits::default()).unwrap_err();
        assert_eq!(r.code, Code::InvalidHeader, "n = {n}: {r}");
    }
    let text = include_str!("../../../proofs/square.ron");
    let r = read(&text.replacen("version: 1,", "version: 2,\n    extra: 0,", 1)).unwrap_err();
    assert_eq!(r.code, Code::UnsupportedVersion, "{r}");
    let r = read(&text.replacen("version: 1,", "version: 1,\n    extra: 0,", 1)).unwrap_err();
    assert_eq!(r.code, Code::UnknownField, "{r}");
}
