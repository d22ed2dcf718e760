//! The kernel in the number fields Q(cos 2 pi/n) (issue 10 §2): the field path agrees with the
//! rational path wherever both apply (n = 3, 4, 6, every point certificate of the corpus), and
//! certificates for irrational n are accepted, and rejected for the right reasons.

use crate::common::q;
use chatter::certify::{Request, certify};
use chatter::exact::{ParseLimits, Q};
use chatter::write::write;
use chatter_kernel::certificate::{Body, Certificate, Code, Param, read};
use chatter_kernel::check::{check, check_in_field};
use num_rational::BigRational;

/// Every readable point certificate of a regular polygon with rational cos(2 pi/n) in the corpus.
fn rational_point_certificates() -> Vec<(String, Certificate)> {
    let mut out = Vec::new();
    for dir in ["certificates/valid", "certificates/invalid"] {
        for f in crate::corpus::ron_files(dir) {
            let Ok(text) = std::fs::read_to_string(&f) else { continue };
            let Ok(cert) = read(&text) else { continue };
            let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
            let point = matches!((kappa, gamma), (Param::Point(_), Param::Point(_)));
            if [3, 4, 6].contains(n) && point {
                out.push((f.display().to_string(), cert));
            }
        }
    }
    out
}

#[test]
fn the_field_path_agrees_with_the_rational_path_on_the_corpus() {
    let certs = rational_point_certificates();
    let (mut ok, mut rejected) = (0, 0);
    for (name, cert) in &certs {
        let rational = check::<Q>(cert, ParseLimits::default());
        let field = check_in_field::<Q>(cert, ParseLimits::default());
        assert_eq!(rational, field, "{name}");
        assert_eq!(field, check_in_field::<BigRational>(cert, ParseLimits::default()), "{name}");
        if rational.is_ok() { ok += 1 } else { rejected += 1 }
    }
    assert!(ok >= 20 && rejected >= 20, "{ok} accepted, {rejected} rejected");
}

fn certified(n: u64, kappa: &str, gamma: &str) -> Certificate {
    certify(&Request::new(n, q(kappa), q(gamma))).result.unwrap_or_else(|e| panic!("n = {n}: {e}"))
}

fn verdict(
    cert: &Certificate,
) -> Result<chatter_kernel::check::Accepted, chatter_kernel::certificate::Rejection> {
    let a = check::<Q>(cert, ParseLimits::default());
    assert_eq!(a, check::<BigRational>(cert, ParseLimits::default()), "the backends disagree");
    a
}

#[test]
fn certificates_for_irrational_n_verify_and_tampering_is_caught() {
    for (n, kappa, gamma) in
        [(5, "1/40", "1/100"), (7, "1/40", "1/100"), (8, "1/40", "1/100"), (12, "1/100", "1/50")]
    {
        let cert = certified(n, kappa, gamma);
        let a = verdict(&cert).unwrap_or_else(|r| panic!("n = {n}: {r}"));
        assert_eq!(a.pieces.len(), n as usize - 1);
        // Shrinking one generator towards the middle of K breaks invariance or the all-down rule.
        let mut bad = cert.clone();
        let g = &mut bad.cone[0].0;
        g[0] = "0".into();
        g[1] = "0".into();
        let r = verdict(&bad).expect_err("a shrunk cone");
        assert!([Code::ImageOutside, Code::InitialOutside].contains(&r.code), "n = {n}: {r}");
    }
}

#[test]
fn a_field_kappa_needs_version_3_and_its_canonical_text() {
    let mut req = Request::new(5, q("1/40"), q("1/100"));
    req.kappa_field = Some("1/40 + 1/100*c".into());
    let cert = certify(&req).result.expect("certified");
    assert_eq!(cert.version, 3);
    assert!(write(&cert).contains("kappa: \"1/40 + 1/100*c\""));
    verdict(&cert).expect("accepted");
    let mut old = cert.clone();
    old.version = 2;
    assert_eq!(verdict(&old).unwrap_err().code, Code::UnsupportedVersion);
    for bad in ["1/40 + 1/100c", "1/100*c + 1/40", "1/40 + 2/200*c", "1/40 + 1/100*c^2", "1/40 +1/100*c"] {
        let mut c = cert.clone();
        let Body::RegularPolygon { kappa, .. } = &mut c.body;
        *kappa = Param::Point(bad.into());
        let r = verdict(&c).unwrap_err();
        assert_eq!(r.code, Code::BadNumber, "{bad}: {r}");
        assert_eq!(r.locus, chatter_kernel::certificate::Locus::Field { path: "body.kappa".into() }, "{bad}");
    }
}

#[test]
fn boxes_and_out_of_range_n_are_refused_where_cos_is_irrational() {
    let cert = certified(5, "1/40", "1/100");
    let mut boxed = cert.clone();
    boxed.version = 2;
    let Body::RegularPolygon { kappa, .. } = &mut boxed.body;
    *kappa = Param::Interval("1/40".into(), "1/39".into());
    let r = verdict(&boxed).unwrap_err();
    assert_eq!(r.code, Code::UnsupportedBody, "{r}");
    let mut big = cert;
    let Body::RegularPolygon { n, .. } = &mut big.body;
    *n = 65;
    assert_eq!(verdict(&big).unwrap_err().code, Code::UnsupportedBody);
}
