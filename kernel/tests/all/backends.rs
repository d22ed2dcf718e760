//! Tests of `exact::backends`: the malachite backend (`Q`, `Integer`) and the num backend
//! (`BigRational`, `BigInt`) must agree on everything.

use chatter_kernel::exact::{Field, Int, OrderedField, Ring, lcm_all, scale_to_ints, to_canonical};
use malachite::Integer;
use malachite::rational::Rational as Q;
use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;
use std::cmp::Ordering;

/// A rational as a product of fractions of i128 parts, built on both backends from decimal text
/// (so the two constructions are independent).
fn both_from_parts(parts: &[(i128, i128)]) -> (Q, BigRational) {
    let mut a = Q::one();
    let mut b = BigRational::one();
    for &(n, d) in parts {
        let d = if d == 0 { 1 } else { d };
        let (na, da) = (
            Integer::parse_digits(&n.unsigned_abs().to_string()).unwrap(),
            Integer::parse_digits(&d.unsigned_abs().to_string()).unwrap(),
        );
        let (nb, db) = (
            BigInt::parse_digits(&n.unsigned_abs().to_string()).unwrap(),
            BigInt::parse_digits(&d.unsigned_abs().to_string()).unwrap(),
        );
        let na = if (n < 0) != (d < 0) { na.negated() } else { na };
        let nb = if (n < 0) != (d < 0) { nb.negated() } else { nb };
        a = a.times(&Q::from_fraction(&na, &da));
        b = b.times(&BigRational::from_fraction(&nb, &db));
    }
    (a, b)
}

fn c<F: Field>(x: &F) -> String {
    to_canonical(x)
}

/// Strategy for a rational given by 1 to 4 factors (i64 or i128 parts), possibly zero.
fn rational_parts() -> impl Strategy<Value = Vec<(i128, i128)>> {
    let small = (any::<i64>(), any::<i64>()).prop_map(|(n, d)| (n as i128, d as i128));
    let big = (any::<i128>(), any::<i128>());
    let tiny = (-20i128..20, -20i128..20);
    prop::collection::vec(prop_oneof![small, big, tiny], 1..5)
}

fn assert_agree(a: &Q, b: &BigRational) {
    assert_eq!(c(a), c(b));
    assert_eq!(a.numer().to_string(), Field::numer(b).to_string());
    assert_eq!(a.denom().to_string(), Field::denom(b).to_string());
    assert_eq!(a.sign(), b.sign());
    assert_eq!(a.is_zero(), b.is_zero());
    assert_eq!(a.is_positive(), b.is_positive());
    assert_eq!(a.is_negative(), b.is_negative());
    assert_eq!(a.to_string(), c(a));
    assert_eq!(b.to_string(), c(b));
}

#[test]
fn backend_names() {
    assert_eq!(<Q as Field>::BACKEND, "malachite");
    assert_eq!(<BigRational as Field>::BACKEND, "num-rational");
}

#[test]
fn constants_agree() {
    assert_agree(&Q::zero(), &BigRational::zero());
    assert_agree(&Q::one(), &BigRational::one());
    assert_agree(&Q::from_i64(i64::MIN), &BigRational::from_i64(i64::MIN));
    assert_agree(&Q::from_ratio(-6, 4), &BigRational::from_ratio(-6, 4));
    assert_eq!(c(&Q::from_ratio(-6, 4)), "-3/2");
    assert_eq!(c(&Q::from_ratio(6, -4)), "-3/2");
    assert_eq!(c(&BigRational::from_ratio(6, -4)), "-3/2");
    assert_eq!(c(&BigRational::from_ratio(-6, -4)), "3/2");
    assert_eq!(Integer::zero().sign(), Ordering::Equal);
    assert_eq!(Ring::sign(&BigInt::zero()), Ordering::Equal);
    assert_eq!(Ring::sign(&BigInt::from_i64(-5)), Ordering::Less);
    assert_eq!(Integer::from_i64(-5).sign(), Ordering::Less);
    assert_eq!(Integer::from_i64(5).sign(), Ordering::Greater);
    assert_eq!(Ring::sign(&BigInt::from_i64(5)), Ordering::Greater);
    assert_eq!(Q::from_int(&Integer::from(7)), Q::from_i64(7));
    assert_eq!(c(&BigRational::from_int(&BigInt::from(-7))), "-7");
}

#[test]
fn division_by_zero_is_none_on_both() {
    assert_eq!(Q::one().over(&Q::zero()), None);
    assert_eq!(Q::zero().over(&Q::zero()), None);
    assert_eq!(BigRational::one().over(&BigRational::zero()), None);
    assert_eq!(BigRational::zero().over(&BigRational::zero()), None);
    assert_eq!(Q::from_ratio(-3, 7).over(&Q::from_ratio(0, 5)), None);
    assert_eq!(BigRational::from_ratio(-3, 7).over(&BigRational::from_ratio(0, 5)), None);
    assert_eq!(Q::zero().over(&Q::from_ratio(3, 7)), Some(Q::zero()));
    assert_eq!(c(&BigRational::zero().over(&BigRational::from_ratio(3, 7)).unwrap()), "0");
}

#[test]
fn parse_digits_accepts_only_nonempty_ascii_digits() {
    for s in ["", "-1", "+1", "1a", " 1", "1 ", "1_000", "1.0", "\u{661}", "0x1", "-"] {
        assert_eq!(Integer::parse_digits(s), None, "malachite accepted {s:?}");
        assert_eq!(BigInt::parse_digits(s), None, "num accepted {s:?}");
    }
    let long = "9".repeat(300);
    for (s, want) in [("0", "0"), ("000", "0"), ("007", "7"), ("123", "123"), (long.as_str(), long.as_str())]
    {
        assert_eq!(Integer::parse_digits(s).map(|x| x.to_string()).as_deref(), Some(want), "malachite {s:?}");
        assert_eq!(BigInt::parse_digits(s).map(|x| x.to_string()).as_deref(), Some(want), "num {s:?}");
    }
}

#[test]
fn bit_length_hand_values() {
    let cases: [(i64, u64); 9] =
        [(0, 0), (1, 1), (-1, 1), (2, 2), (3, 2), (4, 3), (-255, 8), (256, 9), (i64::MIN, 64)];
    for (v, bits) in cases {
        assert_eq!(Integer::from_i64(v).bit_length(), bits, "malachite {v}");
        assert_eq!(BigInt::from_i64(v).bit_length(), bits, "num {v}");
    }
}

#[test]
fn gcd_hand_values() {
    let cases: [(i64, i64, i64); 8] = [
        (0, 0, 0),
        (0, 5, 5),
        (-5, 0, 5),
        (12, 18, 6),
        (-12, 18, 6),
        (-12, -18, 6),
        (17, 5, 1),
        (i64::MIN, 6, 2),
    ];
    for (a, b, g) in cases {
        assert_eq!(
            Integer::from_i64(a).gcd(&Integer::from_i64(b)),
            Integer::from_i64(g),
            "malachite gcd({a},{b})"
        );
        assert_eq!(BigInt::from_i64(a).gcd(&BigInt::from_i64(b)), BigInt::from_i64(g), "num gcd({a},{b})");
    }
}

fn s(a: &Integer, b: &BigInt) -> Result<(), TestCaseError> {
    prop_assert_eq!(a.to_string(), b.to_string());
    Ok(())
}

fn ints<Z: Int>(v: &[i64]) -> Vec<Z> {
    v.iter().map(|&x| Z::from_i64(x)).collect()
}

#[test]
fn lcm_all_hand_values() {
    let cases: [(&[i64], i64); 7] = [
        (&[], 1),
        (&[1], 1),
        (&[6], 6),
        (&[4, 6], 12),
        (&[2, 3, 4, 5, 6], 60),
        (&[7, 7, 7], 7),
        (&[8, 12, 18], 72),
    ];
    for (xs, l) in cases {
        assert_eq!(lcm_all(ints::<Integer>(xs).iter()), Integer::from_i64(l), "malachite lcm{xs:?}");
        assert_eq!(lcm_all(ints::<BigInt>(xs).iter()), BigInt::from_i64(l), "num lcm{xs:?}");
    }
}

fn primes_dividing(n: i64) -> Vec<i64> {
    let mut n = n.abs();
    let mut ps = vec![];
    let mut p = 2;
    while p * p <= n {
        if n % p == 0 {
            ps.push(p);
            while n % p == 0 {
                n /= p;
            }
        }
        p += 1;
    }
    if n > 1 {
        ps.push(n);
    }
    ps
}

/// Checks the contract of `scale_to_ints` on one backend: integers, a positive multiple of the
/// input, and minimal (no prime can be divided out while keeping all entries integral).
fn check_scale<F: Field>(xs: &[(i64, i64)]) -> Vec<String> {
    let v: Vec<F> = xs.iter().map(|&(n, d)| F::from_ratio(n, d)).collect();
    let out = scale_to_ints(&v);
    assert_eq!(out.len(), v.len());
    let dens: Vec<F::Int> = v.iter().map(Field::denom).collect();
    let l = lcm_all(dens.iter());
    assert!(l.is_positive());
    // out = l * v, entrywise.
    let lf = F::from_int(&l);
    for (o, x) in out.iter().zip(&v) {
        assert_eq!(F::from_int(o), x.times(&lf), "entry is l * x");
        assert_eq!(o.sign(), x.sign(), "sign preserved");
    }
    // Minimality: for every prime p dividing l (hence dividing some denominator), l/p no longer
    // makes all entries integral.
    let mut primes: Vec<i64> = vec![];
    for d in &dens {
        let d: i64 = d.to_string().parse().expect("small denominators in these tests");
        primes.extend(primes_dividing(d));
    }
    primes.sort_unstable();
    primes.dedup();
    for p in primes {
        let lp = F::from_int(&l.div_exact(&F::Int::from_i64(p)));
        assert!(
            v.iter().any(|x| x.times(&lp).denom() != F::Int::one()),
            "l/{p} still clears all denominators of {xs:?}"
        );
    }
    out.iter().map(|z| z.to_string()).collect()
}

#[test]
fn scale_to_ints_hand_examples() {
    type Case<'a> = (&'a [(i64, i64)], &'a [i64]);
    let cases: [Case; 8] = [
        (&[], &[]),
        (&[(0, 1)], &[0]),
        (&[(1, 2), (1, 3)], &[3, 2]),
        (&[(-1, 2), (3, 4), (5, 6)], &[-6, 9, 10]),
        (&[(2, 3), (-4, 9), (0, 5)], &[6, -4, 0]),
        (&[(3, 1), (6, 1)], &[3, 6]),
        (&[(1, 6), (1, 10), (1, 15)], &[5, 3, 2]),
        (&[(7, 12), (-5, 18), (1, 8)], &[42, -20, 9]),
    ];
    for (xs, want) in cases {
        let want: Vec<String> = want.iter().map(|w| w.to_string()).collect();
        assert_eq!(check_scale::<Q>(xs), want, "malachite {xs:?}");
        assert_eq!(check_scale::<BigRational>(xs), want, "num {xs:?}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn field_operations_agree(pa in rational_parts(), pb in rational_parts(), zero_a in prop::bool::weighted(0.05)) {
        let (mut a1, mut a2) = both_from_parts(&pa);
        if zero_a {
            a1 = Q::zero();
            a2 = BigRational::zero();
        }
        let (b1, b2) = both_from_parts(&pb);
        assert_agree(&a1, &a2);
        assert_agree(&b1, &b2);
        assert_agree(&a1.plus(&b1), &a2.plus(&b2));
        assert_agree(&a1.minus(&b1), &a2.minus(&b2));
        assert_agree(&a1.times(&b1), &a2.times(&b2));
        assert_agree(&a1.negated(), &a2.negated());
        prop_assert_eq!(a1.over(&b1).is_none(), a2.over(&b2).is_none());
        if let (Some(x), Some(y)) = (a1.over(&b1), a2.over(&b2)) {
            assert_agree(&x, &y);
            // (a / b) * b == a
            prop_assert_eq!(x.times(&b1), a1.clone());
        }
        prop_assert_eq!(a1.cmp(&b1), a2.cmp(&b2));
        prop_assert_eq!(a1 == b1, a2 == b2);
        // The reduced form really is reduced, with a positive denominator.
        prop_assert!(a1.denom().is_positive());
        if !a1.is_zero() {
            prop_assert_eq!(a1.numer().gcd(&a1.denom()), Integer::one());
            prop_assert_eq!(Field::numer(&a2).gcd(&Field::denom(&a2)), BigInt::one());
        } else {
            prop_assert_eq!(a1.denom(), Integer::one());
            prop_assert_eq!(Field::denom(&a2), BigInt::one());
        }
        // from_fraction(numer, denom) is the identity.
        prop_assert_eq!(Q::from_fraction(&a1.numer(), &a1.denom()), a1.clone());
        prop_assert_eq!(BigRational::from_fraction(&Field::numer(&a2), &Field::denom(&a2)), a2.clone());
    }

    #[test]
    fn integer_operations_agree(pa in rational_parts(), pb in rational_parts()) {
        let (a1, a2) = both_from_parts(&pa);
        let (b1, b2) = both_from_parts(&pb);
        // Big integers: the numerators of the two products.
        let (x1, x2) = (a1.numer(), Field::numer(&a2));
        let (y1, y2) = (b1.numer(), Field::numer(&b2));
        s(&x1, &x2)?;
        s(&y1, &y2)?;
        s(&x1.plus(&y1), &x2.plus(&y2))?;
        s(&x1.minus(&y1), &x2.minus(&y2))?;
        s(&x1.times(&y1), &x2.times(&y2))?;
        s(&x1.negated(), &x2.negated())?;
        prop_assert_eq!(Ring::sign(&x1), Ring::sign(&x2));
        prop_assert_eq!(x1.bit_length(), x2.bit_length());
        prop_assert_eq!(x1.cmp(&y1), x2.cmp(&y2));
        let g1 = x1.gcd(&y1);
        let g2 = x2.gcd(&y2);
        s(&g1, &g2)?;
        prop_assert!(!g1.is_negative());
        if !g1.is_zero() {
            // The gcd divides both, and the quotients are coprime.
            let (qx1, qy1) = (x1.div_exact(&g1), y1.div_exact(&g1));
            let (qx2, qy2) = (x2.div_exact(&g2), y2.div_exact(&g2));
            s(&qx1, &qx2)?;
            s(&qy1, &qy2)?;
            prop_assert_eq!(qx1.times(&g1), x1.clone());
            prop_assert_eq!(qy2.times(&g2), y2.clone());
            prop_assert_eq!(qx1.gcd(&qy1), Integer::one());
        }
        // div_exact of a product by either factor.
        if !y1.is_zero() {
            let p1 = x1.times(&y1);
            let p2 = x2.times(&y2);
            prop_assert_eq!(p1.div_exact(&y1), x1.clone());
            prop_assert_eq!(p2.div_exact(&y2), x2.clone());
        }
        // bit_length: 2^(n-1) <= |x| < 2^n.
        let n = x1.bit_length();
        let abs = if x1.is_negative() { x1.negated() } else { x1.clone() };
        if n == 0 {
            prop_assert!(x1.is_zero());
        } else {
            let two = Integer::from(2);
            let mut lo = Integer::one();
            for _ in 1..n { lo = lo.times(&two); }
            prop_assert!(lo <= abs);
            prop_assert!(abs < lo.times(&two));
        }
        // parse_digits round-trips the decimal text of |x|, on both backends.
        let text = abs.to_string();
        prop_assert_eq!(Integer::parse_digits(&text), Some(abs.clone()));
        prop_assert_eq!(BigInt::parse_digits(&text).map(|z| z.to_string()), Some(text.clone()));
        let padded = format!("00{text}");
        prop_assert_eq!(Integer::parse_digits(&padded), Some(abs.clone()));
        prop_assert_eq!(BigInt::parse_digits(&padded).map(|z| z.to_string()), Some(text.clone()));
        let neg = format!("-{text}");
        prop_assert_eq!(Integer::parse_digits(&neg), None);
        prop_assert_eq!(BigInt::parse_digits(&neg), None);
    }

    #[test]
    fn scale_to_ints_agrees(xs in prop::collection::vec((-1000i64..1000, 1i64..200), 0..6)) {
        let a = check_scale::<Q>(&xs);
        let b = check_scale::<BigRational>(&xs);
        prop_assert_eq!(a, b);
    }

    #[test]
    fn lcm_all_agrees_and_is_a_common_multiple(xs in prop::collection::vec(1i64..100_000, 0..8)) {
        let l1 = lcm_all(ints::<Integer>(&xs).iter());
        let l2 = lcm_all(ints::<BigInt>(&xs).iter());
        prop_assert_eq!(l1.to_string(), l2.to_string());
        prop_assert!(l1.is_positive());
        for x in &xs {
            let xi = Integer::from_i64(*x);
            prop_assert_eq!(l1.gcd(&xi), xi.clone(), "{} does not divide the lcm", x);
        }
        // Minimal: every prime of l comes from some x, and l/p is not a common multiple.
        let mut primes: Vec<i64> = xs.iter().flat_map(|&x| primes_dividing(x)).collect();
        primes.sort_unstable();
        primes.dedup();
        for p in primes {
            let lp = l1.div_exact(&Integer::from_i64(p));
            prop_assert!(
                xs.iter().any(|&x| lp.gcd(&Integer::from_i64(x)) != Integer::from_i64(x)),
                "l/{} is still a common multiple", p
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The num backend's gcd (Lehmer's, issue 23 §3) is malachite's, on long numbers with a long
    /// common factor, and its fractions stay reduced as malachite's.
    #[test]
    fn the_num_backends_gcd_and_fractions_agree_with_malachite(
        a in "[1-9][0-9]{0,300}", b in "[1-9][0-9]{0,300}", c in "[1-9][0-9]{0,120}",
    ) {
        let (x, y, z) = (BigInt::parse_digits(&a).unwrap(), BigInt::parse_digits(&b).unwrap(), BigInt::parse_digits(&c).unwrap());
        let (u, v, w) = (Integer::parse_digits(&a).unwrap(), Integer::parse_digits(&b).unwrap(), Integer::parse_digits(&c).unwrap());
        let num = x.times(&z).gcd(&y.times(&z).negated());
        prop_assert_eq!(num.to_string(), u.times(&w).gcd(&v.times(&w)).to_string());
        let q = BigRational::from_fraction(&x.times(&z), &y.times(&z).negated());
        let m = Q::from_fraction(&u.times(&w), &v.times(&w).negated());
        prop_assert_eq!(to_canonical(&q), to_canonical(&m));
        let r = q.plus(&BigRational::from_fraction(&z, &y)).times(&q).over(&BigRational::from_fraction(&x, &z)).unwrap();
        let s = m.plus(&Q::from_fraction(&w, &v)).times(&m).over(&Q::from_fraction(&u, &w)).unwrap();
        prop_assert_eq!(to_canonical(&r), to_canonical(&s));
    }

    /// With powers of two in both numbers (the dyadic enclosures of orbit and basin
    /// certificates: the num backend's gcd takes the common power of two out first), gcd, 2^k and
    /// reduced fractions are malachite's.
    #[test]
    fn dyadic_gcds_and_fractions_agree_with_malachite(
        a in "[1-9][0-9]{0,60}", b in "[1-9][0-9]{0,60}", i in 0u64..300, j in 0u64..300,
    ) {
        let big2 = |k: u64| BigInt::from(1u8) << k;
        let mal2 = |k: u64| Integer::from(1u32) << k;
        let (x, y) = (BigInt::parse_digits(&a).unwrap().times(&big2(i)), BigInt::parse_digits(&b).unwrap().times(&big2(j)));
        let (u, v) = (Integer::parse_digits(&a).unwrap().times(&mal2(i)), Integer::parse_digits(&b).unwrap().times(&mal2(j)));
        prop_assert_eq!(x.to_string(), u.to_string());
        prop_assert_eq!(x.gcd(&y).to_string(), u.gcd(&v).to_string());
        prop_assert_eq!(x.gcd(&big2(j)).to_string(), u.gcd(&mal2(j)).to_string());
        let q = BigRational::from_fraction(&x, &big2(j)).plus(&BigRational::from_fraction(&y, &big2(i)));
        let m = Q::from_fraction(&u, &mal2(j)).plus(&Q::from_fraction(&v, &mal2(i)));
        prop_assert_eq!(to_canonical(&q), to_canonical(&m));
    }
}

/// `verify::agree`, which `verify` on both backends applies to their runs (the corpus tests run
/// each backend alone and compare, tests/all/corpus.rs): identical verdicts are that verdict,
/// different ones a disagreement naming both, a time-limit wins, and no run is no verdict.
#[test]
fn agree_combines_the_runs_of_the_backends() {
    use chatter_kernel::reject::Rejection;
    use chatter_kernel::verify::{Verdict, agree};
    let limit = || Rejection::time_limit("checking");
    let over = || Rejection::limit("max-generators", 9, 8, chatter_kernel::reject::Counted::Generators);
    assert_eq!(agree([("a", Ok::<u8, Rejection>(1)), ("b", Ok(1))]), Verdict::Accepted(1));
    assert_eq!(agree([("a", Err::<u8, _>(over())), ("b", Err(over()))]), Verdict::Rejected(over()));
    let Verdict::Disagree(d) = agree([("a", Ok(1)), ("b", Ok(2))]) else { panic!("agreed") };
    assert_eq!(d, "a says Ok(1), b says Ok(2)");
    let Verdict::Disagree(d) = agree([("a", Ok(1)), ("b", Err(over()))]) else { panic!("agreed") };
    assert!(d.starts_with("a says Ok(1), b says Err("), "{d}");
    assert_eq!(agree([("a", Ok(1)), ("b", Err(limit()))]), Verdict::Rejected(limit()));
    assert!(matches!(agree(Vec::<(&str, Result<u8, Rejection>)>::new()), Verdict::Disagree(_)));
}
