//! Tests of `chatter_kernel::model::Rod` and the rod rules of `chatter_kernel::check`: the planar rod model and its certificate checks (n = 2).

use crate::common::q;
use chatter::certify::{ClaimChoice, Request, certify};
use chatter::exact::{ParseLimits, Q};
use chatter_kernel::certificate::{Body, Certificate, Claim, Code, Coordinates, FORMAT, Generator};
use chatter_kernel::check::check;
use chatter_kernel::model::{Rod, mat2_vec};
use num_rational::BigRational;

fn rod_cert(kappa: &str, gamma: &str, claim: Claim, gens: &[(&str, &str)]) -> Certificate {
    Certificate {
        format: FORMAT.into(),
        version: 1,
        body: Body::RegularPolygon { n: 2, kappa: kappa.into(), gamma: gamma.into() },
        coordinates: Coordinates::ContactVelocities,
        claim,
        cone: gens.iter().map(|(a, b)| Generator(vec![a.to_string(), b.to_string()])).collect(),
        time_to_rest_bound: None,
        producer: "test".into(),
    }
}

fn both(c: &Certificate) -> Result<chatter_kernel::check::Accepted, chatter_kernel::certificate::Rejection> {
    let a = check::<Q>(c, ParseLimits::default());
    assert_eq!(a, check::<BigRational>(c, ParseLimits::default()), "backends agree");
    a
}

#[test]
fn rod_impacts_follow_the_model() {
    let r = Rod::new(q("1/3"), q("1/20")).unwrap();
    assert_eq!(r.coupling(), q("-1/2"), "(kappa - 1)/(kappa + 1)");
    let p = [q("-3"), q("1")];
    let after = mat2_vec(&r.impact(0), &p);
    assert_eq!(after[0], q("3/20"), "u0 -> -gamma u0");
    // u1 -> u1 - (1 + gamma) coupling u0 = 1 - (21/20)(-1/2)(-3) = 1 - 63/40.
    assert_eq!(after[1], q("-23/40"));
    assert_eq!(r.step(), chatter_kernel::model::mat2_mul(&r.impact(0), &r.relabel()));
    assert!(Rod::new(q("0"), q("1/2")).is_err() && Rod::new(q("1"), q("3/2")).is_err());
}

#[test]
fn the_paper_s_rod_cone_is_certified_below_the_threshold_and_not_above() {
    // 7 - 4 sqrt 3 = 0.0717967... for kappa = 1/3.
    for (gamma, ok) in
        [("1/1000", true), ("1/20", true), ("7/100", true), ("359/5000", false), ("1/10", false)]
    {
        let mut r = Request::new(2, q("1/3"), q(gamma));
        r.claim = ClaimChoice::Strongest;
        let rep = certify(&r);
        assert_eq!(rep.result.is_ok(), ok, "gamma = {gamma}: {:?}", rep.result.err().map(|e| e.to_string()));
        if let Ok(c) = rep.result {
            let a = both(&c).unwrap();
            assert_eq!((a.n, a.generators, a.claim), (2, 2, Claim::CompleteChatterFromAllDown));
            assert!(a.pcc.is_none(), "no PCC quadratic for two contacts");
            assert!(a.contains_translation);
        }
    }
}

#[test]
fn rod_rejections_are_located() {
    let ok = rod_cert("1/3", "1/20", Claim::CcOrPccFromAllDown, &[("0", "-2"), ("2/7", "-16/7")]);
    assert!(both(&ok).is_ok(), "{:?}", both(&ok));
    // Shrunk: the upper end 1/10 (in u0 at v = -1) is below the attracting eigenvector.
    let small = rod_cert("1/3", "1/20", Claim::EffectivelyInvariant, &[("0", "-2"), ("1/10", "-21/10")]);
    let r = both(&small).unwrap_err();
    assert_eq!(r.code, Code::ImageOutside);
    assert_eq!(
        r.locus,
        chatter_kernel::certificate::Locus::Piece {
            piece: 1,
            vertex: 0,
            outside: Some(chatter_kernel::certificate::Boundary::End { generator: 1 }),
            corner: None,
        },
        "{r}"
    );
    assert!(r.message().contains("of K∩C_1") && r.message().contains("beyond generator 1"), "{r}");
    let up = rod_cert("1/3", "1/20", Claim::EffectivelyInvariant, &[("0", "-2"), ("1", "1")]);
    assert_eq!(both(&up).unwrap_err().code, Code::GeneratorNotBelow);
    let ray = rod_cert("1/3", "1/20", Claim::EffectivelyInvariant, &[("1", "-3"), ("2", "-6")]);
    assert_eq!(both(&ray).unwrap_err().code, Code::DegenerateCone);
    let three = rod_cert("1/3", "1/20", Claim::EffectivelyInvariant, &[("0", "-2")]);
    let mut three = three;
    three.cone[0].0.push("-1".into());
    let r = both(&three).unwrap_err();
    assert_eq!(r.code, Code::WrongArity);
    assert!(r.message().contains("expected 2 coordinates (u0, u1)"));
    // A cone in u0 < 0 is vacuous: no piece, effectively invariant, but not all-down.
    let vac = rod_cert("1/3", "1/20", Claim::EffectivelyInvariant, &[("-1", "-1"), ("-3/2", "-1/2")]);
    let a = both(&vac).unwrap();
    assert_eq!(a.pieces, [0]);
    assert!(!a.contains_translation);
    let vac = rod_cert("1/3", "1/20", Claim::CcOrPccFromAllDown, &[("-1", "-1"), ("-3/2", "-1/2")]);
    assert_eq!(both(&vac).unwrap_err().code, Code::InitialOutside);
}
