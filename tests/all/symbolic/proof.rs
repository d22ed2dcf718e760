//! The step checker can fail: wrong identities, bad certificates, missing atoms, failed
//! premises are all recorded as failures.

use chatter::exact::Q;
use chatter::symbolic::mpoly::{G, K, L, MPoly};
use chatter::symbolic::proof::Proof;
use chatter::symbolic::ratfn::RatFn;

fn proof() -> Proof {
    // chi = l^2 - g (so l = sqrt g), e1 and e2 unused.
    let chi = MPoly::var(L).pow(2).sub(&MPoly::var(G));
    let mut p = Proof::new(chi, RatFn::int(0), RatFn::int(0));
    p.lemma("test");
    p.assume("H", "g > 0, k > 0, l > 0");
    p.atom("g", RatFn::var(G), "H");
    p.atom("k", RatFn::var(K), "H");
    p.atom("l", RatFn::var(L), "H");
    p
}

#[test]
fn correct_steps_pass() {
    let mut p = proof();
    let (g, k, l) = (RatFn::var(G), RatFn::var(K), RatFn::var(L));
    assert!(p.identity("i", "l^2 = g", &l.mul(&l), &g, true, &["H"]));
    assert!(p.positive(
        "p",
        "g + 2 k l > 0",
        &g.add(&k.mul(&l).mul(&RatFn::int(2))),
        &[(Q::int(1), &["g"]), (Q::int(2), &["k", "l"])],
        &[],
        &[]
    ));
    assert!(p.positive(
        "q",
        "l^3 / k > 0 via l^3 = g l",
        &l.pow(3).div(&k),
        &[(Q::int(1), &["g", "l"])],
        &["k"],
        &[]
    ));
    assert!(p.all_ok());
}

#[test]
fn wrong_steps_fail() {
    let mut p = proof();
    let (g, k, l) = (RatFn::var(G), RatFn::var(K), RatFn::var(L));
    assert!(!p.identity("i1", "l^2 = g + 1", &l.mul(&l), &g.add(&RatFn::int(1)), true, &[]));
    assert!(!p.identity("i2", "l^2 = g without chi", &l.mul(&l), &g, false, &[]));
    assert!(!p.positive(
        "p1",
        "negative coefficient",
        &g.sub(&k),
        &[(Q::int(1), &["g"]), (Q::int(-1), &["k"])],
        &[],
        &[]
    ));
    assert!(!p.positive(
        "p2",
        "certificate differs",
        &g.add(&k),
        &[(Q::int(1), &["g"]), (Q::int(2), &["k"])],
        &[],
        &[]
    ));
    assert!(!p.positive("p3", "unknown atom", &g, &[(Q::int(1), &["x"])], &[], &[]));
    assert!(!p.positive("p4", "empty certificate", &RatFn::int(0), &[], &[], &[]));
    assert!(!p.fact("f", "cites a failed step", "logic", true, String::new(), &["i1"]));
    // An atom whose justifying step failed is not registered.
    p.atom("bad", l.clone(), "i1");
    assert!(!p.positive("p5", "uses an unjustified atom", &l, &[(Q::int(1), &["bad"])], &[], &[]));
    assert_eq!(p.steps.iter().filter(|s| !s.ok).count(), 8);
    assert!(p.steps.iter().all(|s| s.ok || !s.detail.is_empty() || s.id == "f"));
}
