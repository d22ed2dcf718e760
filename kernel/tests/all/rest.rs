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
        ("rest-v3-version-2.ron", "unsupported-version"),
        ("rest-v3-bound-not-rational.ron", "bad-number"),
        ("rest-v3-virtual-time-increases.ron", "virtual-time-increases"),
        ("rest-v3-box-version-2.ron", "unsupported-version"),
        ("rest-v3-box-upper-corner.ron", "image-outside"),
        ("rest-v3-box-pcc-on-box.ron", "pcc-not-excluded"),
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
    // A box of parameters needs version 3; the square's version-1 file is refused as such.
    let boxed = text.replace("kappa: \"1/6\"", "kappa: [\"1/7\", \"1/6\"]");
    assert_eq!(code_of(&boxed), "unsupported-version");
    let empty = corpus(V2_SQUARE)
        .replace("version: 2", "version: 3")
        .replace("kappa: \"1/6\"", "kappa: [\"1/6\", \"1/7\"]");
    assert_eq!(code_of(&empty), "parameter-out-of-range");
    // n = 5 needs version 3 (its numbers are read in Q(cos 2π/5)); then the square's graph is
    // not the pentagon's.
    let pentagon = text.replace("RegularPolygon(n: 4", "RegularPolygon(n: 5");
    assert_eq!(code_of(&pentagon), "unsupported-version");
    let v3 = corpus(V2_SQUARE).replace("version: 2", "version: 3");
    assert_eq!(code_of(&v3), "accepted", "version 3 reads a square's file as version 2 does");
    assert_ne!(code_of(&v3.replace("RegularPolygon(n: 4", "RegularPolygon(n: 5")), "accepted");
    for n in [2, 65] {
        let other = v3.replace("RegularPolygon(n: 4", &format!("RegularPolygon(n: {n}"));
        assert_eq!(code_of(&other), "unsupported-body", "n = {n}");
    }
}

const V2_SQUARE: &str = "valid/rest-v2-n4-kappa1_6-gamma1_100.ron";

/// Version 3: the tool's graphs of the pentagon (n = 5, CC) and the octagon (n = 8, CC or PCC),
/// whose covectors and numerators are elements of Q(cos 2π/n), are accepted on both backends.
#[cfg(feature = "field")]
#[test]
fn the_number_field_graphs_are_accepted_on_both_backends() {
    for (file, n, claim, nodes) in [
        ("valid/rest-v3-n5-kappa1_20-gamma1_10.ron", 5, Claim::CompleteChatterFromAllDown, 35),
        ("valid/rest-v3-n8-kappa1_100-gamma1_50.ron", 8, Claim::CcOrPccFromAllDown, 18),
    ] {
        let text = corpus(file);
        assert!(text.contains("*c"), "{file} has field elements");
        let Verdict::Accepted(a) = verify_rest_text_in(&text, Encoding::Ron, ParseLimits::default(), &BOTH)
        else {
            panic!("{file} is rejected")
        };
        assert_eq!((a.claim, a.n, a.nodes), (claim, n, nodes), "{file}");
    }
}

/// The rules over Q(cos 2π/n) give the rational path's verdict (acceptance, code, locus and
/// values) on every time-to-rest file of the corpus about n = 3, 4, 6, valid or not, on both
/// backends: the field path run in a field of degree 1.
#[cfg(feature = "field")]
#[test]
fn the_field_path_gives_the_rational_paths_verdict_on_the_rational_corpus() {
    use chatter_kernel::rest::check_in_field;
    use chatter_kernel::syntax::read;
    use malachite::rational::Rational;
    use num_rational::BigRational;
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../certificates");
    let mut seen = 0;
    for sub in ["valid", "invalid"] {
        for e in std::fs::read_dir(dir.join(sub)).unwrap() {
            let path = e.unwrap().path();
            let name = path.file_name().unwrap().to_string_lossy().to_string();
            if !(name.starts_with("rest-") && name.ends_with(".ron")) || name.starts_with("rest-v3-") {
                continue;
            }
            let Ok(cert) = read::<chatter_kernel::rest::TimeToRest>(
                &std::fs::read_to_string(&path).unwrap(),
                Encoding::Ron,
            ) else {
                continue;
            };
            let limits = ParseLimits::default();
            assert_eq!(
                check_in_field::<Rational>(&cert, limits),
                chatter_kernel::rest::check::<Rational>(&cert, limits),
                "{name}"
            );
            assert_eq!(
                check_in_field::<BigRational>(&cert, limits),
                chatter_kernel::rest::check::<BigRational>(&cert, limits),
                "{name}"
            );
            seen += 1;
        }
    }
    assert!(seen >= 15, "{seen} files");
}

#[cfg(feature = "boxes")]
const BOX: &str = "valid/rest-v3-box-n4-kappa1_6-gamma1_100-1_50.ron";

/// Version 3 over a box: the square's graph for every γ in [1/100, 1/50] is accepted on both
/// backends with its region; a failure names its corner; without version 3 it is refused.
#[cfg(feature = "boxes")]
#[test]
fn a_box_graph_is_accepted_with_its_region_and_a_failure_names_its_corner() {
    let Verdict::Accepted(a) =
        verify_rest_text_in(&corpus(BOX), Encoding::Ron, ParseLimits::default(), &BOTH)
    else {
        panic!("the box file is rejected")
    };
    let region = [["1/6".to_string(), "1/6".to_string()], ["1/100".to_string(), "1/50".to_string()]];
    assert_eq!((a.claim, a.n, a.region), (Claim::CompleteChatterFromAllDown, 4, Some(region)));
    let Verdict::Rejected(r) = verify_rest_text_in(
        &corpus("invalid/rest-v3-box-upper-corner.ron"),
        Encoding::Ron,
        ParseLimits::default(),
        &BOTH,
    ) else {
        panic!("the raised box is not rejected")
    };
    let locus = serde_json::to_value(&r.locus).unwrap();
    assert_eq!(locus["corner"], 2, "{locus}");
}

/// The corner argument, by brute force: the graph and B of every accepted box file hold as a
/// point certificate at 9 evenly spaced γ of the interval and at the corners (both backends).
#[cfg(feature = "boxes")]
#[test]
fn a_box_graph_holds_at_every_sampled_point_of_its_box() {
    let text = corpus(BOX);
    for k in 0..=8 {
        let gamma = format!("{}/{}", 800 + 100 * k, 80_000);
        let point = text.replace("gamma: [\"1/100\", \"1/50\"]", &format!("gamma: \"{gamma}\""));
        assert_ne!(point, text);
        let canonical =
            chatter_kernel::exact::to_canonical(&gamma.parse::<malachite::rational::Rational>().unwrap());
        let point = point.replace(&gamma, &canonical);
        assert_eq!(code_of(&point), "accepted", "gamma = {canonical}");
    }
}
