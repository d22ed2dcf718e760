//! Tests of `spectral::poly` and `spectral::roots`: arithmetic, square-free parts, Sturm
//! counts against brute force, root isolation, algebraic-number comparisons.

use crate::common::q;
use chatter::exact::{Q, QExt};
use chatter::spectral::poly::{Point, Poly, count_roots};
use chatter::spectral::roots::{RealRoot, isolate};
use proptest::prelude::*;
use std::cmp::Ordering;

fn p(c: &[i64]) -> Poly<Q> {
    Poly::new(c.iter().map(|x| Q::int(*x)).collect())
}

/// prod (t - r_i) for rational roots r_i.
fn from_roots(rs: &[Q]) -> Poly<Q> {
    rs.iter().fold(Poly::constant(Q::int(1)), |acc, r| acc.mul(&Poly::new(vec![-r, Q::int(1)])))
}

#[test]
fn arithmetic_and_division() {
    let a = p(&[1, -3, 0, 2]); // 2t^3 - 3t + 1
    let b = p(&[-1, 1]); // t - 1
    let (qq, r) = a.div_rem(&b);
    assert_eq!(qq.mul(&b).add(&r), a);
    assert!(r.is_zero(), "t = 1 is a root");
    assert_eq!(a.eval(&Q::int(2)), Q::int(11));
    assert_eq!(a.derivative(), p(&[-3, 0, 6]));
    assert_eq!(p(&[0, 1]).pow(3), p(&[0, 0, 0, 1]));
    assert_eq!(p(&[1, 2, 3]).reflect(), p(&[1, -2, 3]));
    assert_eq!(Poly::<Q>::zero().degree(), None);
    assert_eq!(p(&[5, 0, 0]).degree(), Some(0), "trailing zeros are trimmed");
    assert_eq!(a.show("g"), "2 g^3 - 3 g + 1");
    assert_eq!(p(&[0, -1]).show("t"), "-t");
}

#[test]
fn gcd_and_square_free_factorisation() {
    let f = from_roots(&[q("1/2"), q("1/2"), q("1/2"), Q::int(-3), Q::int(-3), Q::int(2)]);
    assert_eq!(f.gcd(&f.derivative()), from_roots(&[q("1/2"), q("1/2"), Q::int(-3)]));
    assert_eq!(f.square_free(), from_roots(&[q("1/2"), Q::int(-3), Q::int(2)]));
    let factors = f.square_free_factors();
    let rebuilt = factors.iter().fold(Poly::constant(Q::int(1)), |acc, (g, m)| acc.mul(&g.pow(*m)));
    assert_eq!(rebuilt, f.monic());
    let mults: Vec<usize> = factors.iter().map(|(_, m)| *m).collect();
    assert_eq!(mults, [1, 2, 3]);
}

#[test]
fn isolation_of_rational_and_irrational_roots() {
    // Roots exactly at bisection midpoints (0, 1/2) and irrational ones (+-sqrt 2).
    let f = from_roots(&[Q::int(0), q("1/2")]).mul(&p(&[-2, 0, 1]));
    let mut roots = isolate(&f);
    assert_eq!(roots.len(), 4);
    // 0 is hit exactly by the first bisection; every root lies in its interval.
    assert!(roots[1].is_exact() && roots[1].lo == Q::int(0));
    for (r, x) in roots.iter().zip([-std::f64::consts::SQRT_2, 0.0, 0.5, std::f64::consts::SQRT_2]) {
        assert!(r.lo.to_f64() <= x + 1e-6 && x - 1e-6 <= r.hi.to_f64(), "{x} in [{}, {}]", r.lo, r.hi);
    }
    let sqrt2 = &mut roots[3];
    let (lo, hi) = sqrt2.decimal_enclosure(12);
    let (l, h): (Q, Q) = (
        lo.replace('.', "").parse::<Q>().unwrap() / Q::pow10(12),
        hi.replace('.', "").parse::<Q>().unwrap() / Q::pow10(12),
    );
    assert!(
        &l * &l <= Q::int(2) && Q::int(2) <= &h * &h,
        "the printed interval [{lo}, {hi}] contains sqrt 2"
    );
    assert!(h - l <= Q::new(2, 1) * Q::pow10(-12));
    assert!(isolate(&p(&[1, 0, 1])).is_empty(), "t^2 + 1 has no real root");
}

#[test]
fn algebraic_comparisons_and_signs() {
    let mut s2 = isolate(&p(&[-2, 0, 1])).pop().unwrap(); // sqrt 2
    // sqrt 2 again, as the middle root of (t^2 - 2)(t - 3).
    let mut s2b = isolate(&p(&[-2, 0, 1]).mul(&p(&[-3, 1]))).swap_remove(1);
    assert_eq!(s2.compare(&mut s2b), Ordering::Equal, "sqrt 2 from two different polynomials");
    let mut s3 = isolate(&p(&[-3, 0, 1])).pop().unwrap();
    assert_eq!(s2.compare(&mut s3), Ordering::Less);
    assert_eq!(s3.compare(&mut s2), Ordering::Greater);
    assert_eq!(s2.sign_of(&p(&[-2, 0, 1])), Ordering::Equal);
    assert_eq!(s2.sign_of(&p(&[-141421, 100000])), Ordering::Greater, "sqrt 2 > 1.41421");
    assert_eq!(s2.sign_of(&p(&[-141422, 100000])), Ordering::Less, "sqrt 2 < 1.41422");
    assert_eq!(s2.negated().sign(), Ordering::Less);
    let mut third = RealRoot::exact(p(&[-1, 3]), q("1/3"));
    assert_eq!(third.compare(&mut s2), Ordering::Less);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Sturm counts against the brute-force count of known rational roots in (a, b].
    #[test]
    fn sturm_counts_match_known_roots(
        roots in prop::collection::vec((-40i64..40, 1i64..8), 1..4),
        quad in prop::option::of((-5i64..5, 1i64..5)),
        a in -60i64..60, w in 1i64..80,
    ) {
        let rs: Vec<Q> = roots.iter().map(|(n, d)| Q::new(*n, *d)).collect();
        let mut f = from_roots(&rs);
        if let Some((s, t)) = quad {
            // (t - s)^2 + t0 with t0 > 0 has no real roots.
            f = f.mul(&Poly::new(vec![Q::int(s * s + t), Q::int(-2 * s), Q::int(1)]));
        }
        let (a, b) = (Q::new(a, 3), Q::new(a + w, 3));
        let mut distinct = rs.clone();
        distinct.sort();
        distinct.dedup();
        let brute = distinct.iter().filter(|r| **r > a && **r <= b).count();
        let seq = f.square_free().sturm();
        prop_assert_eq!(count_roots(&seq, &Point::At(a), &Point::At(b)), brute);
        prop_assert_eq!(count_roots(&seq, &Point::NegInf, &Point::PosInf), distinct.len());
        // Isolation finds each distinct root once, in order.
        let iso = isolate(&f);
        prop_assert_eq!(iso.len(), distinct.len());
        for (r, x) in iso.iter().zip(&distinct) {
            prop_assert!(r.lo <= *x && *x <= r.hi);
        }
    }

    /// Random cubics: Sturm counts agree with sign changes on a fine grid whenever the roots
    /// are well separated from each other and from the grid.
    #[test]
    fn sturm_counts_match_sign_checks_on_random_cubics(c in prop::collection::vec(-20i64..20, 4)) {
        prop_assume!(c[3] != 0);
        let f = p(&c);
        let sf = f.square_free();
        let seq = sf.sturm();
        let total = count_roots(&seq, &Point::NegInf, &Point::PosInf);
        let coef: Vec<f64> = c.iter().map(|x| *x as f64).collect();
        let val = |x: f64| coef[0] + x * (coef[1] + x * (coef[2] + x * coef[3]));
        // Float roots (for the separation check) and grid sign changes over [-30, 30].
        let grid: Vec<f64> = (0..=60_000).map(|i| -30.0 + i as f64 * 1e-3).collect();
        let changes = grid.windows(2).filter(|w| val(w[0]).signum() * val(w[1]).signum() < 0.0).count();
        let min_abs = grid.iter().map(|x| val(*x).abs()).fold(f64::INFINITY, f64::min);
        let disc = { let (a, b, cc, d) = (coef[3], coef[2], coef[1], coef[0]); 18.0*a*b*cc*d - 4.0*b.powi(3)*d + b*b*cc*cc - 4.0*a*cc.powi(3) - 27.0*a*a*d*d };
        prop_assume!(min_abs > 1e-6 && disc.abs() > 1.0);
        prop_assert_eq!(total, changes);
    }
}
