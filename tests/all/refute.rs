//! Refutations (issue 11 §2): the producer (`chatter::refute`) and the kernel's checker
//! (`chatter_kernel::refute`) on both backends, hostile edits, and the rule that a refutation can
//! never verify where a certificate exists.

use crate::common::q;
use chatter::certify::{Request, certify};
use chatter::exact::Q;
use chatter::refute::{NoRefutation, RefuteConfig, refute};
use chatter::write::write_refutation as write;
use chatter_kernel::certificate::{Body, Claim, Code, KindLocus, Locus};
use chatter_kernel::refute::{Refutation, Step};
use chatter_kernel::syntax::{Encoding, read as read_in};

/// Reads a refutation (RON).
fn read(text: &str) -> Result<Refutation, chatter_kernel::reject::Rejection> {
    read_in(text, Encoding::Ron)
}
use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify_refutation};

fn made(n: u64, k: &str, g: &str, claim: Claim) -> Refutation {
    refute(n, &q(k), &q(g), claim, &RefuteConfig::default())
        .unwrap_or_else(|e| panic!("n={n} kappa={k} gamma={g}: {e}"))
}

fn verdict(r: &Refutation) -> Verdict<chatter_kernel::refute::Refuted> {
    verify_refutation(r, Default::default(), &[MALACHITE, NUM])
}

fn rejected(r: &Refutation) -> chatter_kernel::certificate::Rejection {
    match verdict(r) {
        Verdict::Rejected(x) => x,
        other => panic!("expected a rejection: {other:?}"),
    }
}

#[test]
fn refutations_verify_on_both_backends_and_round_trip() {
    for (n, k, g, claim) in [
        (4, "1/6", "1/10", Claim::EffectivelyInvariant),
        (4, "1/6", "3/100", Claim::EffectivelyInvariant),
        (3, "1/8", "3/20", Claim::EffectivelyInvariant),
        (3, "1/8", "1/5", Claim::CcOrPccFromAllDown),
        (6, "1/20", "1/10", Claim::EffectivelyInvariant),
        (2, "1/3", "1/10", Claim::EffectivelyInvariant),
        (2, "1", "1/10", Claim::CcOrPccFromAllDown),
    ] {
        let r = made(n, k, g, claim);
        let Verdict::Accepted(a) = verdict(&r) else {
            panic!("n={n} kappa={k} gamma={g}: {:?}", verdict(&r))
        };
        assert_eq!((a.claim, a.n, a.points), (claim, n, r.points.len()));
        assert_eq!(read(&write(&r)).unwrap(), r, "the writer's text reads back");
        // Pruned: every point but the last is used by a later one.
        let mut used = vec![false; r.points.len()];
        for s in &r.points {
            match s {
                Step::Combination { terms } => terms.iter().for_each(|(i, _)| used[*i] = true),
                Step::Image { of, .. } => used[*of] = true,
                Step::Seed { .. } => {}
            }
        }
        assert!(used[..used.len() - 1].iter().all(|u| *u), "n={n}: unused points");
    }
}

/// The index of the first step of a kind.
fn first(r: &Refutation, kind: fn(&Step) -> bool) -> usize {
    r.points.iter().position(kind).expect("a step of that kind")
}

#[test]
fn hostile_edits_are_rejected_at_the_step() {
    let base = made(4, "1/6", "3/100", Claim::EffectivelyInvariant);
    let at = |x: &chatter_kernel::certificate::Rejection| match &x.locus {
        Locus::Kind(KindLocus::Step { index, .. }) => *index,
        other => panic!("{other:?}"),
    };
    // A negative coefficient.
    let mut r = base.clone();
    let i = first(&r, |s| matches!(s, Step::Combination { .. }));
    if let Step::Combination { terms } = &mut r.points[i] {
        terms[0].1 = format!("-{}", terms[0].1);
    }
    let x = rejected(&r);
    assert_eq!((x.code, at(&x)), (Code::StepFailed, i), "{x}");
    assert!(x.message().contains("negative"), "{x}");
    // A reference to a later point.
    let mut r = base.clone();
    let i = first(&r, |s| matches!(s, Step::Image { .. }));
    r.points[i] = Step::Image { step: 1, of: i };
    assert_eq!(at(&rejected(&r)), i);
    // An image of a point outside C_j (an imaged point under another map).
    let images: Vec<(usize, usize, usize)> = base
        .points
        .iter()
        .enumerate()
        .filter_map(|(i, s)| match s {
            Step::Image { step, of } => Some((i, *step, *of)),
            _ => None,
        })
        .collect();
    let mut outside = None;
    'search: for &(i, j, of) in &images {
        for other in (1..4).filter(|o| *o != j) {
            let mut r = base.clone();
            r.points[i] = Step::Image { step: other, of };
            if let Verdict::Rejected(x) = verdict(&r)
                && x.message().contains("is not in C_")
                && at(&x) == i
            {
                outside = Some(x);
                break 'search;
            }
        }
    }
    assert!(outside.is_some(), "some image step's point lies outside another C_j");
    let (i, _, of) = images[0];
    // No such map, no such seed.
    let mut r = base.clone();
    r.points[i] = Step::Image { step: 4, of };
    assert!(rejected(&r).message().contains("S_4 does not exist"));
    let mut r = base.clone();
    r.points[0] = Step::Seed { index: 7 };
    assert_eq!(at(&rejected(&r)), 0);
    // Dropping the last point: the new last one has v < 0.
    let mut r = base.clone();
    r.points.pop();
    let x = rejected(&r);
    assert!(x.message().contains("nothing is refuted"), "{x}");
}

#[test]
fn a_refutation_never_verifies_where_a_certificate_exists() {
    // Refutations made above the threshold, moved to points where a certificate exists.
    for (n, k, g_refuted, g_certified) in [
        (4, "1/6", "3/100", "1/100"),
        (3, "1/8", "3/20", "1/10"),
        (6, "1/20", "1/10", "1/100"),
        (2, "1/3", "1/10", "1/20"),
    ] {
        let cert = certify(&Request::new(n, q(k), q(g_certified))).result;
        assert!(cert.is_ok(), "n={n} gamma={g_certified} certifies");
        let mut r = made(n, k, g_refuted, Claim::EffectivelyInvariant);
        let Body::RegularPolygon { gamma, .. } = &mut r.body;
        *gamma = g_certified.into();
        assert!(
            matches!(verdict(&r), Verdict::Rejected(_)),
            "n={n}: refutation moved to gamma={g_certified}"
        );
        // And the producer finds none there.
        let none = refute(
            n,
            &q(k),
            &q(g_certified),
            Claim::EffectivelyInvariant,
            &RefuteConfig { max_iterations: 300, ..Default::default() },
        );
        assert!(none.is_err(), "n={n} gamma={g_certified}");
    }
}

#[test]
fn certify_and_refute_never_both_succeed_on_a_grid() {
    let cfg = RefuteConfig { max_iterations: 400, ..Default::default() };
    for n in [3u64, 4, 6] {
        for k in [1, 3, 6] {
            for g in [1, 2, 3, 5, 8, 13, 21, 34] {
                let (kappa, gamma) = (Q::new(k, 30), Q::new(g, 200));
                let certified = certify(&Request::new(n, kappa.clone(), gamma.clone())).result.is_ok();
                let refuted = refute(n, &kappa, &gamma, Claim::EffectivelyInvariant, &cfg).is_ok();
                assert!(!(certified && refuted), "n={n} kappa={kappa} gamma={gamma}");
            }
        }
    }
}

#[test]
fn the_producer_says_why_it_cannot_refute() {
    let e =
        refute(4, &q("1/6"), &q("1/100"), Claim::EffectivelyInvariant, &RefuteConfig::default()).unwrap_err();
    assert_eq!(e, NoRefutation::FloatCone);
    assert!(e.to_string().contains("chatter certify"));
    // The rod: the default 4000 iterations take 9 s (CI time, issue 23 §4); 200 say the same.
    let config = RefuteConfig { max_iterations: 200, ..RefuteConfig::default() };
    let e = refute(2, &q("1/3"), &q("1/20"), Claim::EffectivelyInvariant, &config).unwrap_err();
    assert!(matches!(e, NoRefutation::Converged { .. } | NoRefutation::Budget { iterations: 200 }), "{e}");
}
