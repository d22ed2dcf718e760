//! Tests of `exact::canonical`.

use chatter_kernel::exact::{
    Field, NumberError, OrderedField, ParseLimits, Ring, parse_canonical, parse_canonical_parts, to_canonical,
};
use malachite::Integer;
use malachite::rational::Rational as Q;
use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;

fn parse(s: &str) -> Result<Q, NumberError> {
    parse_canonical::<Q>(s, ParseLimits::default())
}

fn parse_num(s: &str) -> Result<BigRational, NumberError> {
    parse_canonical::<BigRational>(s, ParseLimits::default())
}

/// Parses with both backends, checks they agree on the outcome, and returns the `Q` result.
fn parse_both(s: &str) -> Result<Q, NumberError> {
    let a = parse(s);
    let b = parse_num(s);
    match (&a, &b) {
        (Ok(x), Ok(y)) => assert_eq!(to_canonical(x), to_canonical(y), "backends disagree on {s:?}"),
        (Err(e), Err(f)) => assert_eq!(e, f, "backends give different errors on {s:?}"),
        _ => panic!("backends disagree on {s:?}: {a:?} vs {b:?}"),
    }
    a
}

fn not_reduced(c: &str) -> NumberError {
    NumberError::NotReduced { canonical: c.to_string() }
}

fn unit_den(c: &str) -> NumberError {
    NumberError::UnitDenominator { canonical: c.to_string() }
}

#[test]
fn accepts_small_canonical_numbers() {
    let cases: [(&str, i64, i64); 7] = [
        ("0", 0, 1),
        ("7", 7, 1),
        ("-3", -3, 1),
        ("22/7", 22, 7),
        ("-209/200", -209, 200),
        ("1/2", 1, 2),
        ("-1/9223372036854775807", -1, i64::MAX),
    ];
    for (s, n, d) in cases {
        let x = parse_both(s).unwrap_or_else(|e| panic!("{s:?} rejected: {e:?}"));
        assert_eq!(x, Q::from_ratio(n, d), "{s:?}");
        assert_eq!(to_canonical(&x), s, "round trip of {s:?}");
        assert_eq!(x.to_string(), s);
    }
}

#[test]
fn parts_are_numerator_and_positive_denominator() {
    let (n, d) = parse_canonical_parts::<Integer>("-209/200", ParseLimits::default()).unwrap();
    assert_eq!(n, Integer::from(-209));
    assert_eq!(d, Integer::from(200));
    let (n, d) = parse_canonical_parts::<BigInt>("-209/200", ParseLimits::default()).unwrap();
    assert_eq!(n, BigInt::from(-209));
    assert_eq!(d, BigInt::from(200));
    let (n, d) = parse_canonical_parts::<Integer>("12", ParseLimits::default()).unwrap();
    assert_eq!((n, d), (Integer::from(12), Integer::from(1)));
    let (n, d) = parse_canonical_parts::<BigInt>("0", ParseLimits::default()).unwrap();
    assert_eq!((n, d), (BigInt::from(0), BigInt::from(1)));
}

#[test]
fn accepts_a_500_digit_integer() {
    let s: String = std::iter::once('9').chain("1234567890".chars().cycle().take(499)).collect();
    assert_eq!(s.len(), 500);
    let x = parse_both(&s).unwrap();
    assert_eq!(to_canonical(&x), s);
    assert_eq!(x.denom(), Integer::from(1));
    // 10^499 < x < 10^500
    let ten = Q::from_i64(10);
    let mut p = Q::from_i64(1);
    for _ in 0..499 {
        p = p.times(&ten);
    }
    assert!(x > p);
    assert!(x < p.times(&ten));
    // The negated value and a big fraction with it as denominator also parse.
    let neg = format!("-{s}");
    assert_eq!(parse_both(&neg).unwrap(), x.negated());
    let frac = format!("1/{s}");
    assert_eq!(parse_both(&frac).unwrap(), Q::from_i64(1).over(&x).unwrap());
}

#[test]
fn rejects_non_canonical_text_with_exact_error() {
    use NumberError::*;
    let cases: Vec<(&str, NumberError)> = vec![
        ("", Empty),
        (" 1", Whitespace),
        ("1 ", Whitespace),
        ("1\n", Whitespace),
        ("\t1", Whitespace),
        ("1/ 2", Whitespace),
        ("1\u{a0}", Whitespace),
        ("+1", PlusSign),
        ("+", PlusSign),
        ("01", LeadingZero),
        ("-01", LeadingZero),
        ("-0", NegativeZero),
        ("00", LeadingZero),
        ("2/4", not_reduced("1/2")),
        ("-2/4", not_reduced("-1/2")),
        ("4/2", not_reduced("2")),
        ("-4/2", not_reduced("-2")),
        ("6/4", not_reduced("3/2")),
        ("0/5", not_reduced("0")),
        ("3/1", unit_den("3")),
        ("-3/1", unit_den("-3")),
        ("1/0", ZeroDenominator),
        ("0/0", ZeroDenominator),
        ("1/00", LeadingZero),
        ("1/01", LeadingZero),
        ("1/", MissingDigits),
        ("/2", MissingDigits),
        ("-", MissingDigits),
        ("-/2", MissingDigits),
        ("1//2", InvalidCharacter('/')),
        ("1/2/3", InvalidCharacter('/')),
        ("1.5", InvalidCharacter('.')),
        ("1e3", InvalidCharacter('e')),
        ("--1", InvalidCharacter('-')),
        ("abc", InvalidCharacter('a')),
        ("\u{bd}", InvalidCharacter('\u{bd}')),
        ("1/-2", InvalidCharacter('-')),
        ("0x10", InvalidCharacter('x')),
        ("1_000", InvalidCharacter('_')),
        ("\u{661}", InvalidCharacter('\u{661}')), // ARABIC-INDIC DIGIT ONE is not ASCII
    ];
    for (s, want) in cases {
        let got = parse_both(s);
        assert_eq!(got, Err(want.clone()), "parsing {s:?}");
        // The parts parser gives the same verdict.
        assert_eq!(
            parse_canonical_parts::<Integer>(s, ParseLimits::default()).err(),
            Some(want.clone()),
            "parts of {s:?}"
        );
        // Every error has a non-empty message.
        #[cfg(feature = "explain")]
        assert!(!want.to_string().is_empty());
    }
}

#[test]
fn suggested_canonical_forms_are_themselves_canonical() {
    for s in ["2/4", "-2/4", "4/2", "-12/8", "0/5", "3/1", "-3/1", "100/10", "-1000000/1"] {
        let canonical = match parse_both(s) {
            Err(NumberError::NotReduced { canonical }) => canonical,
            Err(NumberError::UnitDenominator { canonical }) => canonical,
            other => panic!("{s:?}: expected a suggestion, got {other:?}"),
        };
        let x = parse_both(&canonical).unwrap_or_else(|e| panic!("suggestion {canonical:?} of {s:?}: {e:?}"));
        let (p, q) = s.split_once('/').unwrap();
        let v = Q::from_ratio(p.parse().unwrap(), q.parse().unwrap());
        assert_eq!(x, v, "suggestion {canonical:?} for {s:?} has the wrong value");
    }
}

fn digits(n: usize) -> String {
    // No leading zero, no common factor with the denominators used below (ends in 1).
    let mut s = "1".repeat(n);
    if n > 1 {
        s.replace_range(0..1, "9");
    }
    s
}

#[test]
fn default_limit_is_ten_thousand_digits() {
    let d = ParseLimits::default();
    assert_eq!(
        (d.max_digits, d.max_total_digits, d.max_generators, d.deadline),
        (10_000, 2_000_000, 100_000, None),
        "the defaults documented in docs/certificate-format.md §2"
    );
    let at = digits(10_000);
    let x = parse_both(&at).expect("exactly at the limit is accepted");
    assert_eq!(to_canonical(&x), at);
    // The minus sign is not a digit.
    assert!(parse_both(&format!("-{at}")).is_ok());
    let above = digits(10_001);
    assert_eq!(parse_both(&above), Err(NumberError::TooLong { digits: 10_001, max: 10_000 }));
    assert_eq!(parse_both(&format!("-{above}")), Err(NumberError::TooLong { digits: 10_001, max: 10_000 }));
    // Numerator and denominator count together: 9_998 + 2 is fine, 9_999 + 2 is not.
    let ok = format!("{}/10", digits(9_998));
    assert!(parse_both(&ok).is_ok(), "9998+2 digits");
    let bad = format!("{}/10", digits(9_999));
    assert_eq!(parse_both(&bad), Err(NumberError::TooLong { digits: 10_001, max: 10_000 }));
    // The default limits.
    assert!(parse_canonical::<Q>(&at, ParseLimits::default()).is_ok());
    assert!(matches!(parse_canonical::<Q>(&above, ParseLimits::default()), Err(NumberError::TooLong { .. })));
}

#[test]
fn custom_limit_counts_numerator_and_denominator_together() {
    let lim = ParseLimits::digits(5);
    let p = |s: &str| parse_canonical::<Q>(s, lim);
    let pn = |s: &str| parse_canonical::<BigRational>(s, lim).map(|x| to_canonical(&x));
    assert_eq!(p("12345"), Ok(Q::from_i64(12345)));
    assert_eq!(p("-12345"), Ok(Q::from_i64(-12345)));
    assert_eq!(p("123456"), Err(NumberError::TooLong { digits: 6, max: 5 }));
    assert_eq!(p("122/45"), Ok(Q::from_ratio(122, 45)));
    assert_eq!(pn("122/45"), Ok("122/45".to_string()));
    assert_eq!(p("-122/45"), Ok(Q::from_ratio(-122, 45)));
    assert_eq!(p("1/2345"), Ok(Q::from_ratio(1, 2345)));
    assert_eq!(p("123/456"), Err(NumberError::TooLong { digits: 6, max: 5 }));
    assert_eq!(pn("123/456"), Err(NumberError::TooLong { digits: 6, max: 5 }));
    assert_eq!(p("1/23456"), Err(NumberError::TooLong { digits: 6, max: 5 }));
    assert_eq!(
        parse_canonical_parts::<BigInt>("1234/56", lim),
        Err(NumberError::TooLong { digits: 6, max: 5 })
    );
    // A zero limit only rejects; the empty string is still Empty.
    let zero = ParseLimits::digits(0);
    assert_eq!(parse_canonical::<Q>("1", zero), Err(NumberError::TooLong { digits: 1, max: 0 }));
    assert_eq!(parse_canonical::<Q>("", zero), Err(NumberError::Empty));
}

#[test]
fn to_canonical_spells_reduced_forms() {
    assert_eq!(to_canonical(&Q::from_ratio(2, 4)), "1/2");
    assert_eq!(to_canonical(&Q::from_ratio(2, -4)), "-1/2");
    assert_eq!(to_canonical(&Q::from_ratio(-6, -3)), "2");
    assert_eq!(to_canonical(&Q::from_ratio(0, -3)), "0");
    assert_eq!(to_canonical(&Q::zero()), "0");
    assert_eq!(to_canonical(&BigRational::from_ratio(2, -4)), "-1/2");
    assert_eq!(to_canonical(&BigRational::from_ratio(0, -7)), "0");
    assert_eq!(to_canonical(&BigRational::from_ratio(-6, -3)), "2");
    assert_eq!(to_canonical(&Q::from_ratio(i64::MIN, 1)), i64::MIN.to_string());
    assert_eq!(to_canonical(&BigRational::from_ratio(i64::MIN, 1)), i64::MIN.to_string());
    assert_eq!(
        to_canonical(&Q::from_ratio(1, i64::MIN)),
        format!("-1/{}", (i64::MIN as i128).unsigned_abs())
    );
    assert_eq!(
        to_canonical(&BigRational::from_ratio(1, i64::MIN)),
        format!("-1/{}", (i64::MIN as i128).unsigned_abs())
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn canonical_text_round_trips_on_both_backends(p in any::<i64>(), q in 1i64..=i64::MAX) {
        let x = Q::from_ratio(p, q);
        let y = BigRational::from_ratio(p, q);
        let s = to_canonical(&x);
        prop_assert_eq!(&s, &to_canonical(&y));
        prop_assert_eq!(parse(&s), Ok(x.clone()));
        let back = parse_num(&s).expect("num backend accepts canonical text");
        prop_assert_eq!(&back, &y);
        prop_assert_eq!(to_canonical(&back), s.clone());
        // Parsing is injective on canonical text: the unreduced spelling is rejected unless it
        // already is the canonical one.
        let raw = if q == 1 { p.to_string() } else { format!("{p}/{q}") };
        if raw == s {
            prop_assert!(parse(&raw).is_ok());
        } else {
            prop_assert!(parse(&raw).is_err(), "{} accepted but canonical is {}", raw, s);
        }
    }

    #[test]
    fn non_reduced_fractions_suggest_the_reduced_form(p in -1_000_000i64..1_000_000, q in 2i64..1_000_000, k in 2i64..1000) {
        let x = Q::from_ratio(p, q);
        let s = format!("{}/{}", p * k, q * k);
        match parse_both(&s) {
            Err(NumberError::NotReduced { canonical }) => prop_assert_eq!(canonical, to_canonical(&x)),
            Err(NumberError::NegativeZero) => prop_assert!(false, "unexpected NegativeZero"),
            other => prop_assert!(false, "{} gave {:?}", s, other),
        }
    }
}

/// Regression: the length limit was checked before the characters, so garbage under a small
/// limit was reported as "too long" instead of naming the bad character.
#[test]
fn bad_characters_are_named_before_the_length_limit() {
    let lim = ParseLimits::digits(2);
    assert_eq!(parse_canonical::<Q>("abc", lim), Err(NumberError::InvalidCharacter('a')));
    assert_eq!(parse_canonical::<Q>("12/3x", lim), Err(NumberError::InvalidCharacter('x')));
    assert_eq!(parse_canonical::<Q>("123", lim), Err(NumberError::TooLong { digits: 3, max: 2 }));
}
