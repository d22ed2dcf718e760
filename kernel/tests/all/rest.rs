//! Time-to-rest certificates (docs/certificate-format.md §16, docs/time-to-rest.md §5): the
//! corpus file of the square plate on both backends, every rule G1-G5 with its corpus file, and
//! the bound as tight as rule G5 allows.
#![cfg(feature = "rest")]

use chatter_kernel::exact::ParseLimits;
use chatter_kernel::syntax::Encoding;
use chatter_kernel::syntax::cone::Claim;
use chatter_kernel::verify::{BOTH, Verdict, verify_rest_text_in};
use std::path::PathBuf;

fn corpus(rel: &str) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../certificates").join(rel);
    std::fs::read_to_string(path).unwrap()
}

const SQUARE: &str = "valid/rest-n4-kappa1_6-gamma1_100.ron";

fn code_of(text: &str) -> String {
    match verify_rest_text_in(text, Encoding::Ron, ParseLimits::default(), &BOTH) {
        Verdict::Rejected(r) => r.code.as_str().to_string(),
        Verdict::Accepted(_) => "accepted".into(),
        Verdict::Disagree(s) => format!("disagree: {s}"),
    }
}

#[test]
fn the_square_plates_virtual_time_graph_is_accepted_on_both_backends_with_its_bound() {
    let Verdict::Accepted(a) =
        verify_rest_text_in(&corpus(SQUARE), Encoding::Ron, ParseLimits::default(), &BOTH)
    else {
        panic!("the square plate's time-to-rest certificate is rejected")
    };
    assert_eq!(
        (a.claim, a.n, a.bound.as_str(), a.nodes),
        (Claim::CompleteChatterFromAllDown, 4, "2896399/32768", 10)
    );
}

#[test]
fn every_rule_of_time_to_rest_certificates_has_a_corpus_file_rejected_with_its_code() {
    let rows = [
        ("rest-claim-not-about-drops.ron", "unknown-variant"),
        ("rest-weight-not-positive.ron", "virtual-time-not-positive"),
        ("rest-scale-below-one.ron", "virtual-time-not-positive"),
        ("rest-missing-successor.ron", "missing-successor"),
        ("rest-image-outside.ron", "image-outside"),
        ("rest-virtual-time-increases.ron", "virtual-time-increases"),
        ("rest-initial-outside.ron", "initial-outside"),
        ("rest-bound-too-small.ron", "bound-too-small"),
        ("rest-v2-flight.ron", "virtual-time-increases"),
        ("rest-v2-numerator-height.ron", "virtual-time-not-positive"),
        ("rest-v2-scale-field.ron", "unknown-field"),
        ("rest-v2-missing-numerator.ron", "missing-field"),
    ];
    for (file, code) in rows {
        assert_eq!(code_of(&corpus(&format!("invalid/{file}"))), code, "{file}");
    }
}

/// Version 2 (numerators a_r): the tool's files for the square plate and the triangle are accepted
/// on both backends; the square's B is under a ninth of version 1's for the same body.
#[test]
fn the_version_2_graphs_are_accepted_on_both_backends() {
    for (file, n, nodes) in [
        ("valid/rest-v2-n4-kappa1_6-gamma1_100.ron", 4, 10),
        ("valid/rest-v2-n3-kappa1_10-gamma1_20.ron", 3, 9),
    ] {
        let Verdict::Accepted(a) =
            verify_rest_text_in(&corpus(file), Encoding::Ron, ParseLimits::default(), &BOTH)
        else {
            panic!("{file} is rejected")
        };
        assert_eq!((a.claim, a.n, a.nodes), (Claim::CompleteChatterFromAllDown, n, nodes), "{file}");
    }
    let b = |file: &str| -> f64 {
        let text = corpus(file);
        let line = text.lines().find(|l| l.trim_start().starts_with("bound:")).unwrap();
        let (p, q) = line.split('"').nth(1).unwrap().split_once('/').unwrap();
        p.parse::<f64>().unwrap() / q.parse::<f64>().unwrap()
    };
    assert!(b("valid/rest-v2-n4-kappa1_6-gamma1_100.ron") * 8.0 < b(SQUARE));
    // A version-1 node read as version 2 lacks its numerator and has a scale.
    let as_v2 = corpus(SQUARE).replace("version: 1", "version: 2");
    assert_eq!(code_of(&as_v2), "unknown-field");
}

#[test]
fn the_bound_less_one_unit_of_its_last_place_breaks_rule_g5_only() {
    let text = corpus(SQUARE);
    assert_eq!(code_of(&text), "accepted");
    let lowered = text.replace("bound: \"2896399/32768\"", "bound: \"5792797/65536\"");
    assert_ne!(lowered, text);
    assert_eq!(code_of(&lowered), "bound-too-small");
    // Raising B keeps the certificate valid: G5 is an inequality.
    assert_eq!(code_of(&text.replace("bound: \"2896399/32768\"", "bound: \"100\"")), "accepted");
}

#[test]
fn a_time_to_rest_certificate_at_an_interval_or_another_n_is_refused() {
    let text = corpus(SQUARE);
    let boxed = text.replace("kappa: \"1/6\"", "kappa: [\"1/7\", \"1/6\"]");
    assert_eq!(code_of(&boxed), "parameter-out-of-range");
    let pentagon = text.replace("RegularPolygon(n: 4", "RegularPolygon(n: 5");
    assert_eq!(code_of(&pentagon), "unsupported-body");
}
