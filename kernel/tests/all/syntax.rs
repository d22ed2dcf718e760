//! The syntax layer: the header names the kind of a file, each kind with its own format string,
//! and the legacy headers `("chatter-certificate", 4 | 5)` still read as family and orbit
//! certificates (docs/certificate-format.md §13, §14), with the same verdicts.
#![cfg(all(feature = "family", feature = "orbit"))]

use chatter_kernel::certificate::{Certificate, ConvexCertificate, OrbitCertificate};
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::reject::{Code, Detail, Locus, Needs};
use chatter_kernel::syntax::{Encoding, Kind, kind_of, read};
use chatter_kernel::verify::{BOTH, Verdict, verify_text, verify_text_in};

const CONE: &str = include_str!("../../../certificates/valid/doc-example-square.ron");
const FAMILY: &str = include_str!("../../../certificates/valid/convex-rectangle-2x1-gamma1_50.ron");
const ORBIT: &str = include_str!("../../../certificates/valid/orbit-n3-kappa1_8-gamma3_20.ron");

/// `text` with its header written in the legacy form `("chatter-certificate", version)`.
fn legacy(text: &str, format: &str, version: u64) -> String {
    let new = format!("format: \"{format}\",\n    version: 1,");
    assert!(text.contains(&new), "the corpus file has the current header");
    text.replacen(&new, &format!("format: \"chatter-certificate\",\n    version: {version},"), 1)
}

fn kind(text: &str) -> Kind {
    kind_of(text, Encoding::Ron, Kind::Cone).expect("a readable header").0
}

#[test]
fn each_kind_has_its_own_format_string() {
    assert_eq!(kind(CONE), Kind::Cone);
    assert_eq!(kind(FAMILY), Kind::Family);
    assert_eq!(kind(ORBIT), Kind::Orbit);
    assert_eq!(kind(include_str!("../../../proofs/square.ron")), Kind::Proof);
    let refutation = include_str!("../../../certificates/valid/refutation-n4-kappa1_6-gamma1_20.ron");
    assert_eq!(kind(refutation), Kind::Refutation);
    for k in [Kind::Cone, Kind::Family, Kind::Orbit, Kind::Refutation, Kind::Proof] {
        let others = [Kind::Cone, Kind::Family, Kind::Orbit, Kind::Refutation, Kind::Proof];
        assert_eq!(others.iter().filter(|o| o.format() == k.format()).count(), 1, "{k:?}");
    }
}

#[test]
fn legacy_headers_read_as_family_and_orbit_certificates_with_the_same_verdict() {
    let limits = ParseLimits::default();
    for (text, format, version, want) in [
        (FAMILY, "chatter-family-certificate", 4, Kind::Family),
        (ORBIT, "chatter-orbit-certificate", 5, Kind::Orbit),
    ] {
        let old = legacy(text, format, version);
        assert_eq!(kind(&old), want);
        let (now, then) = (verify_text(text, limits, &BOTH), verify_text(&old, limits, &BOTH));
        assert!(matches!(now, Verdict::Accepted(_)), "{now:?}");
        assert_eq!(now, then, "{format}");
    }
    let c: ConvexCertificate = read(&legacy(FAMILY, "chatter-family-certificate", 4), Encoding::Ron).unwrap();
    assert_eq!((c.format.as_str(), c.version), ("chatter-certificate", 4));
    let o: OrbitCertificate = read(&legacy(ORBIT, "chatter-orbit-certificate", 5), Encoding::Ron).unwrap();
    assert_eq!((o.format.as_str(), o.version), ("chatter-certificate", 5));
}

#[test]
fn a_reader_refuses_the_other_kinds() {
    let r = read::<Certificate>(FAMILY, Encoding::Ron).unwrap_err();
    assert_eq!((r.code, &r.locus), (Code::WrongFormat, &Locus::Field { path: "format".into() }));
    let old = legacy(FAMILY, "chatter-family-certificate", 4);
    let r = read::<Certificate>(&old, Encoding::Ron).unwrap_err();
    assert_eq!(r.code, Code::UnsupportedVersion);
    assert_eq!(*r.detail, Detail::Needs(Needs::Kind("chatter-family-certificate"), 4));
    let r = read::<OrbitCertificate>(CONE, Encoding::Ron).unwrap_err();
    assert_eq!(r.code, Code::WrongFormat);
    let r = read::<ConvexCertificate>(&CONE.replacen("version: 1,", "version: 6,", 1), Encoding::Ron)
        .unwrap_err();
    assert_eq!((r.code, *r.detail), (Code::UnsupportedVersion, Detail::Version(6, [1, 5])));
    let r = read::<ConvexCertificate>(&FAMILY.replacen("version: 1,", "version: 3,", 1), Encoding::Ron);
    assert_eq!((r.unwrap_err().code), Code::UnsupportedVersion);
    // Version 2 (an interval of gamma allowed) reads a single gamma too, with the same verdict.
    let two = FAMILY.replacen("version: 1,", "version: 2,", 1);
    assert_eq!(
        verify_text(&two, ParseLimits::default(), &BOTH),
        verify_text(FAMILY, ParseLimits::default(), &BOTH)
    );
}

#[cfg(feature = "json")]
#[test]
fn the_json_twin_names_its_kind_the_same_way() {
    let json = include_str!("../../../certificates/valid/doc-example-square.json");
    assert_eq!(kind_of(json, Encoding::Json, Kind::Cone).unwrap().0, Kind::Cone);
    let family = json.replacen("\"chatter-certificate\"", "\"chatter-family-certificate\"", 1);
    assert_eq!(kind_of(&family, Encoding::Json, Kind::Cone).unwrap().0, Kind::Family);
    let Verdict::Rejected(r) = verify_text_in(&family, Encoding::Json, ParseLimits::default(), &BOTH) else {
        panic!("a cone certificate under the family format is refused")
    };
    assert_eq!(r.code, Code::UnknownVariant, "the family schema has no body RegularPolygon: {r:?}");
}
