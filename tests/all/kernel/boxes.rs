//! Box certificates (issue 11): one cone for every (kappa, gamma) of a closed box. The kernel
//! checks the box's corners (docs/kernel-soundness.md §2, "Boxes"); these tests check the
//! reduction against brute force, by verifying the same cone as a point certificate at many
//! points inside accepted boxes.

use crate::common::q;
use chatter::certify::{ClaimChoice, Request, certify};
use chatter::exact::Q;
use chatter::write::write;
use chatter_kernel::certificate::{Body, Certificate, Claim, Code, KindLocus, Locus, Param, read};
use chatter_kernel::verify::{Verdict, verify};

fn boxed(n: u64, k: [&str; 2], g: [&str; 2]) -> Certificate {
    let r = certify(&Request::boxed(n, [q(k[0]), q(k[1])], [q(g[0]), q(g[1])]));
    r.result.unwrap_or_else(|e| panic!("n={n} kappa={k:?} gamma={g:?}: {e}"))
}

/// The same cone and claim at the point (kappa, gamma), as a version-1 certificate.
fn at_point(c: &Certificate, kappa: &Q, gamma: &Q) -> Certificate {
    let Body::RegularPolygon { n, .. } = c.body;
    Certificate {
        version: 1,
        body: Body::RegularPolygon { n, kappa: kappa.to_string().into(), gamma: gamma.to_string().into() },
        ..c.clone()
    }
}

fn accepted(c: &Certificate) -> bool {
    matches!(verify(c, Default::default()), Verdict::Accepted(_))
}

/// lo + (hi - lo) i / m.
fn between(lo: &Q, hi: &Q, i: i64, m: i64) -> Q {
    lo + &((hi - lo) * Q::new(i, m))
}

#[test]
fn a_cone_accepted_on_a_box_verifies_at_every_sampled_point_of_the_box() {
    let cases: [(u64, [&str; 2], [&str; 2]); 5] = [
        (4, ["1/10", "3/25"], ["1/100", "1/50"]),
        (3, ["1/10", "1/8"], ["1/100", "1/20"]),
        (3, ["3/20", "1/6"], ["1/20", "3/40"]),
        (6, ["1/40", "1/30"], ["1/100", "1/50"]),
        (2, ["1/4", "1/3"], ["1/100", "1/20"]),
    ];
    for (n, k, g) in cases {
        let c = boxed(n, k, g);
        assert_eq!(c.version, 2);
        assert!(matches!(
            c.body,
            Body::RegularPolygon { kappa: Param::Interval(..), gamma: Param::Interval(..), .. }
        ));
        assert!(accepted(&read(&write(&c)).unwrap()), "the written box certificate reads back and verifies");
        let (k0, k1, g0, g1) = (q(k[0]), q(k[1]), q(g[0]), q(g[1]));
        // A 7 x 7 grid including the corners, and the points (i/7 + 1/13, ...) off the grid.
        for i in 0..=6 {
            for j in 0..=6 {
                for (a, b) in [(i * 13, j * 13), (i * 13 + 1, j * 13 + 2)] {
                    if a > 78 || b > 78 {
                        continue;
                    }
                    let (x, y) = (between(&k0, &k1, a, 78), between(&g0, &g1, b, 78));
                    assert!(accepted(&at_point(&c, &x, &y)), "n={n}: the box's cone at kappa={x}, gamma={y}");
                }
            }
        }
    }
}

#[test]
fn a_box_is_rejected_at_the_corner_where_the_cone_fails() {
    let c = boxed(4, ["1/10", "3/25"], ["1/100", "1/50"]);
    // Raise gamma's upper end until the cone fails there: the rejection names the corner.
    let mut wide = c.clone();
    let Body::RegularPolygon { gamma, .. } = &mut wide.body;
    *gamma = Param::Interval("1/100".into(), "1/2".into());
    let Verdict::Rejected(r) = verify(&wide, Default::default()) else { panic!("gamma = 1/2 is far beyond") };
    match &r.locus {
        Locus::Piece { corner, .. } | Locus::AllDown { corner, .. } => {
            assert!(matches!(corner, Some(2) | Some(3)), "a corner with gamma = 1/2: {r}");
        }
        other => panic!("{other:?}: {r}"),
    }
    assert!(r.message().starts_with("at the corner kappa = "), "{r}");
    // The box itself is fine, and so is the cone at gamma = 1/50.
    assert!(accepted(&c));
    assert!(accepted(&at_point(&c, &q("3/25"), &q("1/50"))));
}

#[test]
fn a_degenerate_interval_is_the_point() {
    let c = boxed(3, ["1/10", "1/8"], ["1/100", "1/20"]);
    let point = at_point(&c, &q("1/8"), &q("1/20"));
    let mut degenerate = point.clone();
    degenerate.version = 2;
    let Body::RegularPolygon { kappa, gamma, .. } = &mut degenerate.body;
    *kappa = Param::Interval("1/8".into(), "1/8".into());
    *gamma = Param::Interval("1/20".into(), "1/20".into());
    let (Verdict::Accepted(a), Verdict::Accepted(b)) =
        (verify(&point, Default::default()), verify(&degenerate, Default::default()))
    else {
        panic!("both accepted")
    };
    assert_eq!((a.claim, a.pieces, a.redundant), (b.claim, b.pieces, b.redundant));
    assert_eq!(
        b.region,
        Some([["1/8".to_string(), "1/8".to_string()], ["1/20".to_string(), "1/20".to_string()]])
    );
}

#[test]
fn intervals_need_version_2_and_lo_at_most_hi() {
    let mut c = boxed(4, ["1/10", "3/25"], ["1/100", "1/50"]);
    c.version = 1;
    let Verdict::Rejected(r) = verify(&c, Default::default()) else { panic!() };
    assert_eq!((r.code, r.locus), (Code::UnsupportedVersion, Locus::Field { path: "version".into() }));
    c.version = 2;
    let Body::RegularPolygon { kappa, .. } = &mut c.body;
    *kappa = Param::Interval("3/25".into(), "1/10".into());
    let Verdict::Rejected(r) = verify(&c, Default::default()) else { panic!() };
    assert_eq!((r.code, r.locus), (Code::ParameterOutOfRange, Locus::Field { path: "body.kappa".into() }));
}

#[test]
fn drop_claims_on_a_box_need_gamma_inside_zero_one() {
    let mut c = boxed(4, ["1/10", "3/25"], ["1/100", "1/50"]);
    let Body::RegularPolygon { gamma, .. } = &mut c.body;
    *gamma = Param::Interval("0".into(), "1/50".into());
    let Verdict::Rejected(r) = verify(&c, Default::default()) else { panic!() };
    assert_eq!((r.code, r.locus), (Code::ParameterOutOfRange, Locus::Field { path: "body.gamma[0]".into() }));
}

#[test]
fn pcc_exclusion_on_a_box_is_refused_where_the_discriminant_is_not_negative() {
    // The square plate's PCC criterion holds for gamma < 0.0051548 at kappa = 1/6: a box
    // reaching down to gamma = 1/1000 cannot carry the complete-chatter claim, whatever the cone.
    let req = Request {
        claim: ClaimChoice::Exactly(Claim::CompleteChatterFromAllDown),
        ..Request::boxed(4, [q("1/6"), q("1/6")], [q("1/1000"), q("1/100")])
    };
    assert!(certify(&req).result.is_err());
    let weaker = certify(&Request::boxed(4, [q("1/6"), q("1/6")], [q("1/1000"), q("1/100")]));
    let mut c = weaker.result.expect("CcOrPccFromAllDown certifies on the box");
    assert_eq!(c.claim, Claim::CcOrPccFromAllDown);
    c.claim = Claim::CompleteChatterFromAllDown;
    let Verdict::Rejected(r) = verify(&c, Default::default()) else { panic!() };
    assert_eq!(r.code, Code::PccNotExcluded);
    let Locus::Kind(KindLocus::PccRegion { kappa, gamma }) = &r.locus else { panic!("{r}") };
    // The point named is one where the discriminant is >= 0, checked with the point model.
    assert_eq!(kappa[0], kappa[1]);
    // The square's PCC discriminant in closed form (docs/model.md §11.6, c_1 = 0): μ = κ/(1 + κ),
    // p² - 4q = (1 + γ)² μ² ((1 + γ)² μ² - 4γ); R4 fails there when it is ≥ 0.
    let (k, g) = (q(&kappa[0]), q(&gamma[0]));
    let mu = &k / &(Q::int(1) + &k);
    let e = &(&(Q::int(1) + &g) * &(Q::int(1) + &g)) * &(&mu * &mu);
    assert!(&e * &(&e - &(Q::int(4) * &g)) >= Q::int(0), "{r}");
}
