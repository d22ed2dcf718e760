//! Polynomials of the proof checker: canonical text, arithmetic, pseudo-remainders, Sturm counts.
#![cfg(feature = "proof")]

use chatter_kernel::exact::{OrderedField, ParseLimits, Ring};
use chatter_kernel::proof::{Failure, Poly, count_roots, derivative, rem};
use malachite::rational::Rational as Q;
use proptest::prelude::*;

fn names() -> Vec<String> {
    ["g", "k", "l"].iter().map(|s| s.to_string()).collect()
}

fn parse(s: &str) -> Result<Poly<Q>, Failure> {
    Poly::parse(s, &names(), ParseLimits::default())
}

#[test]
fn canonical_text_round_trips() {
    for s in [
        "0",
        "1",
        "-1",
        "g",
        "-g",
        "2 g^2 k - 1/3 l + 1",
        "g k l^2 + k l^3 + l^3 + g k - g l + k l - l^2 + g",
    ] {
        assert_eq!(parse(s).unwrap().text(&names()), s);
    }
}

#[test]
fn non_canonical_text_is_rejected() {
    for s in [
        "1 + g",  // order: higher degree first
        "1 g",    // unit coefficient written
        "g^1",    // exponent 1 written
        "0 g",    // zero coefficient
        "g + -1", // sign inside a term
        "k g",    // variables out of order
        "2/4 g",  // coefficient not reduced
        "g + g",  // repeated monomial
        "x",      // unknown variable
        "g^65",   // exponent above the limit
        "g  + 1", // double space
        "g +",    // dangling sign
        "",       // empty
        "- g",    // detached leading sign
    ] {
        assert!(parse(s).is_err(), "{s:?} was accepted");
    }
}

fn small_poly() -> impl Strategy<Value = Poly<Q>> {
    prop::collection::vec((-5i64..=5, 0u32..3, 0u32..3, 0u32..4), 0..6).prop_map(|terms| {
        terms.into_iter().fold(Poly::zero(3), |acc, (c, a, b, d)| {
            let m = Poly::var(3, 0).pow(a).mul(&Poly::var(3, 1).pow(b)).mul(&Poly::var(3, 2).pow(d));
            acc.add(&m.scale(&Q::from_i64(c)))
        })
    })
}

proptest! {
    #[test]
    fn printing_then_parsing_is_the_identity(p in small_poly()) {
        prop_assert_eq!(parse(&p.text(&names())).unwrap(), p);
    }

    #[test]
    fn ring_laws_hold(a in small_poly(), b in small_poly(), c in small_poly()) {
        prop_assert_eq!(a.mul(&b.add(&c)), a.mul(&b).add(&a.mul(&c)));
        prop_assert_eq!(a.mul(&b), b.mul(&a));
        prop_assert!(a.sub(&a).is_zero());
    }

    /// lead(m)^e p - r is a multiple of m, and deg r < deg m: checked by exact division of the
    /// evaluation at random points where m does not vanish... here simply: the remainder of the
    /// remainder is itself, and p - r vanishes at every common point of m = 0.
    #[test]
    fn pseudo_remainder_has_lower_degree_and_agrees_at_roots(p in small_poly(), r0 in -3i64..=3) {
        // m = (l - r0)(k + 1): its roots in l are l = r0 for every g, k.
        let m = Poly::var(3, 2).sub(&Poly::constant(3, Q::from_i64(r0))).mul(&Poly::var(3, 1).add(&Poly::constant(3, Q::from_i64(1))));
        let r = p.pseudo_remainder(&m, 2).unwrap();
        prop_assert!(r.is_zero() || r.degree_in(2) < m.degree_in(2));
        // At l = r0, lead(m)^e p = r (lead(m) = k + 1): both vanish together for k != -1.
        let at = |x: &Poly<Q>| x.subst_constant(2, &Q::from_i64(r0));
        let (pa, ra) = (at(&p), at(&r));
        prop_assert_eq!(pa.is_zero(), ra.is_zero());
    }

    #[test]
    fn sturm_counts_distinct_rational_roots(roots in prop::collection::vec(-6i64..=6, 1..5), lo in -7i64..=6, width in 1i64..=8) {
        // p = prod (x - r) over the roots (repeats allowed), x = l; count distinct roots in (lo, hi].
        let hi = lo + width;
        let p: Vec<Q> = roots.iter().fold(vec![Q::from_i64(1)], |acc, r| {
            let mut out = vec![Q::from_i64(0); acc.len() + 1];
            for (i, c) in acc.iter().enumerate() {
                out[i + 1] = out[i + 1].plus(c);
                out[i] = out[i].minus(&c.times(&Q::from_i64(*r)));
            }
            out
        });
        prop_assume!(!roots.contains(&lo) && !roots.contains(&hi));
        let mut seq = vec![p.clone(), derivative(&p)];
        while !seq.last().unwrap().is_empty() {
            let r: Vec<Q> = rem(&seq[seq.len() - 2], &seq[seq.len() - 1]).iter().map(|c| c.negated()).collect();
            if r.is_empty() { break; }
            seq.push(r);
        }
        let mut distinct = roots.clone();
        distinct.sort();
        distinct.dedup();
        let want = distinct.iter().filter(|r| **r > lo && **r <= hi).count();
        prop_assert_eq!(count_roots(&p, &seq, &Q::from_i64(lo), &Q::from_i64(hi)).unwrap(), want);
    }
}

#[test]
fn a_wrong_sturm_sequence_is_rejected() {
    // p = (x - 1)(x - 2) = x^2 - 3x + 2.
    let p = vec![Q::from_i64(2), Q::from_i64(-3), Q::from_i64(1)];
    let good = vec![p.clone(), derivative(&p), vec![Q::from_ratio(1, 4)]];
    assert_eq!(count_roots(&p, &good, &Q::from_i64(0), &Q::from_i64(3)).unwrap(), 2);
    let mut bad = good.clone();
    bad[2] = vec![Q::from_ratio(1, 2)];
    assert!(count_roots(&p, &bad, &Q::from_i64(0), &Q::from_i64(3)).is_err());
    let mut bad = good.clone();
    bad[1] = vec![Q::from_i64(-3), Q::from_i64(1)];
    assert!(count_roots(&p, &bad, &Q::from_i64(0), &Q::from_i64(3)).is_err());
    assert!(count_roots(&p, &good, &Q::from_i64(1), &Q::from_i64(3)).is_err(), "p(lo) = 0");
    assert!(
        count_roots(&p, &good[..2], &Q::from_i64(0), &Q::from_i64(3)).is_err(),
        "the last remainder must vanish"
    );
}
