//! The reader accepts exactly the grammar of docs/certificate-format.md §2 (issue 23 §3): one test
//! per deviation found, and the digit limit on a whole number-field element (§12).
#![cfg(all(feature = "boxes", feature = "field", feature = "explain"))]

use chatter_kernel::exact::{CosField, NumberError, ParseLimits};
use chatter_kernel::reject::{Code, Detail, Locus};
use chatter_kernel::syntax::strict::Offence;
use chatter_kernel::verify::{BOTH, Verdict, verify_text};
use malachite::rational::Rational;
use num_rational::BigRational;

const BOX: &str = include_str!("../../../certificates/valid/n4-kappa1_10_3_25-gamma1_100_1_50-box.ron");

fn verdict(text: &str) -> Verdict {
    verify_text(text, ParseLimits::default(), &BOTH)
}

/// The (line, column) of the first occurrence of `needle`.
fn position(text: &str, needle: &str) -> (usize, usize) {
    let at = text.find(needle).expect("present");
    let line = text[..at].matches('\n').count() + 1;
    let column = at - text[..at].rfind('\n').map_or(0, |i| i + 1) + 1;
    (line, column)
}

/// Deviation: a parameter interval written as a tuple was read like the list of §2 and §9.
#[test]
fn a_parameter_interval_written_as_a_tuple_is_a_syntax_error() {
    assert!(matches!(verdict(BOX), Verdict::Accepted(_)), "the list form is accepted");
    for (list, tuple) in [
        (r#"kappa: ["1/10", "3/25"]"#, r#"kappa: ("1/10", "3/25")"#),
        (r#"gamma: ["1/100", "1/50"]"#, r#"gamma: ("1/100", "1/50")"#),
        (r#"kappa: ["1/10", "3/25"]"#, "kappa :\n  (\"1/10\", \"3/25\")"),
    ] {
        let text = BOX.replacen(list, tuple, 1);
        assert_ne!(text, BOX);
        let Verdict::Rejected(r) = verdict(&text) else { panic!("{tuple}: accepted") };
        assert_eq!(r.code, Code::Syntax, "{tuple}");
        assert_eq!(*r.detail, Detail::Lexical(Offence::TupleInterval, false), "{tuple}");
        let open = text.find(tuple).unwrap() + tuple.find('(').unwrap();
        let (line, column) = position(&text, &text[open..]);
        assert_eq!(r.locus, Locus::Text { line, column }, "{tuple}");
        assert!(r.message().contains("is a list"), "{}", r.message());
    }
}

/// The rule looks at the value of `kappa` and `gamma` only: elsewhere tuples are what the grammar
/// says, and the words inside strings are not tokens.
#[test]
fn tuples_elsewhere_and_the_words_kappa_and_gamma_in_strings_are_unaffected() {
    let text = BOX.replacen("producer: \"", "producer: \"kappa: (", 1);
    assert!(text.contains("kappa: ("));
    assert!(matches!(verdict(&text), Verdict::Accepted(_)));
    let point = include_str!("../../../certificates/valid/doc-example-square.ron");
    assert!(matches!(verdict(point), Verdict::Accepted(_)), "generators are tuples");
}

/// The JSON twin has no tuples: an interval is an array there, as before.
#[cfg(feature = "json")]
#[test]
fn the_json_twin_of_a_box_is_unaffected() {
    let json = r#"{"format": "chatter-certificate", "version": 2,
        "body": {"RegularPolygon": {"n": 4, "kappa": ["1/10", "3/25"], "gamma": ["1/100", "1/50"]}},
        "coordinates": "ContactVelocities", "claim": "EffectivelyInvariant",
        "cone": [["0", "1", "-1"]]}"#;
    let v = chatter_kernel::verify::verify_text_in(
        json,
        chatter_kernel::syntax::Encoding::Json,
        ParseLimits::default(),
        &BOTH,
    );
    let Verdict::Rejected(r) = v else { panic!("one generator is no cone") };
    assert_eq!(r.code, Code::DegenerateCone, "read, then judged by the rules: {r:?}");
}

/// A field element of 2 coefficients of 6,000 digits each: each coefficient is under max-digits,
/// the element (12,000 digits) is not. Before, the limit applied per coefficient.
#[test]
fn the_digit_limit_applies_to_a_whole_field_element() {
    let six = format!("1/{}", "3".repeat(5_998));
    let element = format!("{six} + {six}*c");
    let limits = ParseLimits::default();
    let field = CosField::<Rational>::new(5).unwrap();
    assert_eq!(
        field.parse(&element, limits).err(),
        Some(NumberError::TooLong { digits: 11_998, max: 10_000 })
    );
    let field = CosField::<BigRational>::new(5).unwrap();
    assert_eq!(
        field.parse(&element, limits).err(),
        Some(NumberError::TooLong { digits: 11_998, max: 10_000 })
    );
    // Within the limit as a whole: read (and canonical).
    let half = format!("1/{}", "3".repeat(4_000));
    assert!(field.parse(&format!("{half} + {half}*c"), limits).is_ok());
    // The powers of c do not count; a certificate with such an element is `too-large` at its path.
    let cert =
        include_str!("../../../certificates/valid/n5-kappa1_200-gamma1_5-complete-chatter-from-all-down.ron")
            .replacen("version: 1,", "version: 3,", 1)
            .replacen("kappa: \"1/200\"", &format!("kappa: \"{element}\""), 1);
    let Verdict::Rejected(r) = verdict(&cert) else { panic!("accepted") };
    assert_eq!(r.code, Code::TooLarge);
    assert_eq!(r.locus, Locus::Field { path: "body.kappa".into() });
}

/// At the limit exactly: the exponents of c do not count, and the limit is checked before the
/// spelling, so a non-canonical element beyond it is `too-large` (as in chatter-oracle).
#[test]
fn the_digit_limit_of_an_element_counts_its_coefficients_only_and_comes_first() {
    let half = format!("1/{}", "3".repeat(4_999));
    let at_limit = format!("{half} + {half}*c^2");
    let field = CosField::<Rational>::new(7).unwrap();
    assert!(field.parse(&at_limit, ParseLimits::digits(10_000)).is_ok());
    let one_less = ParseLimits::digits(9_999);
    assert_eq!(
        field.parse(&at_limit, one_less).err(),
        Some(NumberError::TooLong { digits: 10_000, max: 9_999 })
    );
    let swapped = format!("{half}*c^2 + {half}");
    let field = CosField::<BigRational>::new(7).unwrap();
    assert_eq!(
        field.parse(&swapped, one_less).err(),
        Some(NumberError::TooLong { digits: 10_000, max: 9_999 })
    );
    assert!(matches!(
        field.parse(&swapped, ParseLimits::digits(10_000)),
        Err(NumberError::NotCanonical { .. })
    ));
}
