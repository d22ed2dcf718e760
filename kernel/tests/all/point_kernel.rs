//! What the point-certificate kernel (`--no-default-features`) reads and refuses, in every build:
//! the header under any struct name with every position where it is, a parameter of one number or
//! two, and the JSON twin only with the feature `json` (docs/kernel-soundness.md §4).

use chatter_kernel::exact::ParseLimits;
use chatter_kernel::reject::{Code, Locus};
use chatter_kernel::syntax::cone::Certificate;
use chatter_kernel::syntax::{Encoding, Kind, kind_of, schema};
use chatter_kernel::verify::{BOTH, Verdict, verify_text, verify_text_in};

const SQUARE: &str = include_str!("../../../certificates/valid/doc-example-square.ron");
const SQUARE_JSON: &str = include_str!("../../../certificates/valid/doc-example-square.json");

fn rejection(text: &str) -> (Code, Locus) {
    match verify_text(text, ParseLimits::default(), &BOTH) {
        Verdict::Rejected(r) => (r.code, r.locus),
        other => panic!("expected a rejection, got {other:?}"),
    }
}

#[test]
fn the_header_is_read_under_any_struct_name_or_none() {
    assert!(matches!(verify_text(SQUARE, ParseLimits::default(), &BOTH), Verdict::Accepted(_)));
    let unnamed = SQUARE.replacen("Certificate(", "(", 1);
    assert!(matches!(verify_text(&unnamed, ParseLimits::default(), &BOTH), Verdict::Accepted(_)));
    for name in ["Refutation", "Proof", "Anything"] {
        let named = SQUARE.replacen("Certificate(", &format!("{name}("), 1);
        assert_eq!(kind_of(&named, Encoding::Ron, Kind::Cone).unwrap().0, Kind::Cone, "{name}");
        // The full schema still wants its own struct name.
        assert_eq!(rejection(&named).0, Code::Syntax, "{name}");
    }
}

#[test]
fn an_error_in_the_header_is_reported_where_it_is_written() {
    // The header is read with the struct name blanked: the columns of the first line stay, and the
    // error is where the full schema of the text as written puts it.
    let text =
        SQUARE.replacen("Certificate(\n    format: \"chatter-certificate\",", "Certificate(format: 5,", 1);
    let written = schema::<Certificate>(&text, Encoding::Ron).unwrap_err();
    let Locus::Text { line: 1, column } = written.locus else { panic!("{written:?}") };
    assert!(column > "Certificate(format:".len() - 1, "after the struct name: column {column}");
    assert_eq!(rejection(&text), (Code::Syntax, written.locus));
}

#[test]
fn a_parameter_is_one_number_or_a_list_of_two() {
    for bad in [r#"["1/10", "1/9", "1/8"]"#, r#"["1/10"]"#, "[]", "[1, 2]"] {
        let text = SQUARE.replacen(r#"kappa: "1/6""#, &format!("kappa: {bad}"), 1);
        assert_eq!(rejection(&text).0, Code::Syntax, "kappa: {bad}");
    }
}

#[cfg(not(feature = "json"))]
#[test]
fn without_the_feature_json_the_json_twin_is_refused_naming_it() {
    use chatter_kernel::reject::{Detail, Needs};
    match verify_text_in(SQUARE_JSON, Encoding::Json, ParseLimits::default(), &BOTH) {
        Verdict::Rejected(r) => {
            assert_eq!(r.code, Code::Syntax);
            assert_eq!(*r.detail, Detail::Needs(Needs::Feature("json"), 0));
        }
        other => panic!("the JSON twin without the feature json: {other:?}"),
    }
}

#[cfg(feature = "json")]
#[test]
fn with_the_feature_json_the_json_twin_has_the_verdict_of_its_ron() {
    let json = verify_text_in(SQUARE_JSON, Encoding::Json, ParseLimits::default(), &BOTH);
    assert_eq!(json, verify_text(SQUARE, ParseLimits::default(), &BOTH));
    assert!(matches!(json, Verdict::Accepted(_)));
}
