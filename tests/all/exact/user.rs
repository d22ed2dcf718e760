//! Tests of `exact::user`.

use crate::common::q;
use chatter::exact::{Q, Ring, parse_user_number, to_canonical};
use chatter_kernel::exact::OrderedField as _;
use proptest::prelude::*;

fn pow10(e: u32) -> Q {
    let mut p = Q::int(1);
    for _ in 0..e {
        p = p.times(&Q::int(10));
    }
    p
}

#[test]
fn accepts_exact_user_numbers() {
    let cases = [
        ("0.01", "1/100"),
        ("1e-2", "1/100"),
        (".5", "1/2"),
        ("5.", "5"),
        ("-1.25e1", "-25/2"),
        ("2/4", "1/2"),
        ("-2/4", "-1/2"),
        ("+3", "3"),
        ("+3/6", "1/2"),
        (" 1/6 ", "1/6"),
        ("\t1/6\n", "1/6"),
        ("1E3", "1000"),
        ("1e+3", "1000"),
        ("2.5E3", "2500"),
        ("-.5", "-1/2"),
        ("+.5e1", "5"),
        ("1.5e-3", "3/2000"),
        ("0", "0"),
        ("-0", "0"),
        ("-0.0", "0"),
        ("0e5", "0"),
        ("00012", "12"),
        ("007/014", "1/2"),
        ("0.1", "1/10"),
        ("0.3", "3/10"),
        ("22/7", "22/7"),
        ("-209/200", "-209/200"),
        ("0/5", "0"),
        ("3/1", "3"),
        ("123456789012345678901234567890", "123456789012345678901234567890"),
        ("1e30", "1000000000000000000000000000000"),
    ];
    for (s, want) in cases {
        let got = parse_user_number(s).unwrap_or_else(|e| panic!("{s:?} rejected: {e}"));
        assert_eq!(got, q(want), "{s:?}");
    }
}

#[test]
fn rejects_malformed_user_numbers() {
    let long_digits = "1".repeat(2000);
    let long_decimal = format!("0.{}", "3".repeat(1998));
    let cases: Vec<&str> = vec![
        "",
        "   ",
        "abc",
        "1/0",
        "-1/0",
        "0/0",
        "1/00",
        "1..2",
        "1.2.3",
        "1e",
        "1e+",
        "1e-",
        "e5",
        "-e5",
        ".e5",
        "1/2/3",
        "--1",
        "+-1",
        "-+1",
        "++1",
        "1e100000",
        "1e-100000",
        "1e10001",
        "1e-10001",
        "1e99999999999999999999",
        "1e1.5",
        "1e5e5",
        ".",
        "-",
        "+",
        "-.",
        "1/",
        "/2",
        "-/2",
        "1/-2",
        "1/+2",
        "1/2.0",
        "0.5/2",
        "1/2e3",
        "1 /2",
        "1/ 2",
        "1 000",
        "1,5",
        "0x10",
        "1_000",
        "inf",
        "NaN",
        "-inf",
        "\u{bd}",
        "\u{661}",
        "1e\u{661}",
        &long_digits,
        &long_decimal,
    ];
    for s in cases {
        let r = parse_user_number(s);
        assert!(r.is_err(), "{s:?} accepted as {:?}", r.unwrap());
        assert!(!r.unwrap_err().is_empty());
    }
}

#[test]
fn exponent_bound_is_ten_thousand() {
    assert_eq!(parse_user_number("1e10000").unwrap(), pow10(10_000));
    assert_eq!(parse_user_number("-1e-10000").unwrap(), Q::int(-1).over(&pow10(10_000)).unwrap());
    assert_eq!(parse_user_number("2.5E-10000").unwrap(), Q::new(5, 2).over(&pow10(10_000)).unwrap());
    assert!(parse_user_number("1e10001").is_err());
    assert!(parse_user_number("1e-10001").is_err());
    let e = parse_user_number("1e100000").unwrap_err();
    assert!(e.contains("exponent"), "{e}");
}

#[test]
fn length_bound_is_one_thousand_characters() {
    let at = "7".repeat(1000);
    assert_eq!(to_canonical(&parse_user_number(&at).unwrap()), at);
    // Surrounding whitespace is trimmed before the length check.
    assert!(parse_user_number(&format!("  {at}\n")).is_ok());
    let e = parse_user_number(&"7".repeat(1001)).unwrap_err();
    assert!(e.contains("1000"), "{e}");
    assert!(parse_user_number(&"7".repeat(2000)).is_err());
    // A 999-digit fraction part with the leading "." is exactly 1000 characters.
    let frac = format!(".{}", "5".repeat(999));
    let v = parse_user_number(&frac).unwrap();
    assert_eq!(v.times(&pow10(999)), q(&"5".repeat(999)));
}

/// Exponents are bounded, so none of these may panic or hang: the most negative i64 exponent
/// must be rejected like any other exponent beyond the bound.
///
/// BUG (src/exact/user.rs): `e.abs()` overflows for `i64::MIN`. With overflow checks (debug and
/// test builds) `parse_user_number("1e-9223372036854775808")` panics with "attempt to negate with
/// overflow". In release builds `abs` wraps to `i64::MIN`, which passes the `> MAX_EXP` check:
/// "1e-9223372036854775808" then returns the wrong value Ok(1), and "1.5e-9223372036854775808"
/// (where `exp - fp.len()` wraps to `i64::MAX`) aborts the process on a failed allocation in
/// malachite's `pow`.
#[test]
fn most_negative_exponent_is_rejected_without_panicking() {
    let r = std::panic::catch_unwind(|| parse_user_number("1e-9223372036854775808"));
    match r {
        Ok(Err(_)) => {}
        Ok(Ok(v)) => panic!("accepted as {v:?}"),
        Err(_) => panic!("parse_user_number panicked on exponent i64::MIN"),
    }
    // Its neighbour is handled correctly.
    assert!(parse_user_number("1e-9223372036854775807").is_err());
    assert!(parse_user_number("1e9223372036854775807").is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn fractions_are_exact(a in any::<i64>(), b in 1i64..=i64::MAX) {
        prop_assert_eq!(parse_user_number(&format!("{a}/{b}")), Ok(Q::new(a, b)));
        prop_assert_eq!(parse_user_number(&format!(" {a}/{b}\t")), Ok(Q::new(a, b)));
        if a >= 0 {
            prop_assert_eq!(parse_user_number(&format!("+{a}/{b}")), Ok(Q::new(a, b)));
        }
    }

    #[test]
    fn decimals_are_exact(neg in any::<bool>(), ip in 0u64..1_000_000_000_000, fp in "[0-9]{0,6}", exp in -30i32..30, with_exp in any::<bool>()) {
        let sign = if neg { "-" } else { "" };
        let mut s = format!("{sign}{ip}.{fp}");
        // exact = ip + fp / 10^len(fp)
        let k = fp.len() as u32;
        let f: i64 = if fp.is_empty() { 0 } else { fp.parse().unwrap() };
        let mut want = Q::int(ip as i64).plus(&Q::int(f).over(&pow10(k)).unwrap());
        if neg {
            want = want.negated();
        }
        if with_exp {
            s.push_str(&format!("e{exp}"));
            let p = pow10(exp.unsigned_abs());
            want = if exp >= 0 { want.times(&p) } else { want.over(&p).unwrap() };
        }
        prop_assert_eq!(parse_user_number(&s), Ok(want.clone()), "{}", s);
        // Without the integer part when it is zero (".5").
        if ip == 0 && !fp.is_empty() {
            let short = s.replacen("0.", ".", 1);
            prop_assert_eq!(parse_user_number(&short), Ok(want), "{}", short);
        }
    }

    #[test]
    fn canonical_text_is_accepted_with_the_same_value(n in any::<i64>(), d in 1i64..=i64::MAX) {
        let x = Q::new(n, d);
        prop_assert_eq!(parse_user_number(&to_canonical(&x)), Ok(x));
    }

    #[test]
    fn never_panics(s in "[-+ 0-9./eE]{0,40}") {
        let _ = parse_user_number(&s);
    }
}
