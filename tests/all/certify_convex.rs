//! `certify` for general convex bodies (issue 13 §2-§3; docs/model.md §11.9): the family finder
//! and exactifier certify affine images of the regular plates exactly where the regular pipeline
//! certifies the regular plate, regular polygons given as general bodies give today's verdicts,
//! the length scale does not matter, and the CLI writes version-4 files that `verify` accepts.

use crate::common::{bin, q, root};
use crate::transport::{kappa_of, plates};
use chatter::bodies::convex::rectangle_plate;
use chatter::certify::convex::{ConvexRequest, certify_convex, length_scale, scaled};
use chatter::certify::transport::regular_image;
use chatter::certify::{Failure, Request, certify};
use chatter::exact::Q;
use chatter_kernel::certificate::Claim;
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::model::ConvexBody;
use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify_convex_on};
use std::process::{Command, Output};

/// The claim certified for a general body (checked again here on each backend alone), or `None`.
fn general_claim(body: &ConvexBody<Q>) -> Option<Claim> {
    let cert = certify_convex(&ConvexRequest::new(body.clone())).result.ok()?;
    for b in [MALACHITE, NUM] {
        match verify_convex_on(&cert, ParseLimits::default(), &[b]) {
            Verdict::Accepted(a) => assert_eq!(a.claim, cert.claim, "backend {}", b.name),
            other => panic!("backend {} rejects the pipeline's certificate: {other:?}", b.name),
        }
    }
    Some(cert.claim)
}

/// The claim the regular pipeline certifies for the regular n-gon, or `None`.
fn regular_claim(n: u64, kappa: &str, gamma: &str) -> Option<Claim> {
    certify(&Request::new(n, q(kappa), q(gamma))).result.ok().map(|c| c.claim)
}

const GRID: [&str; 8] = ["1/1000", "1/200", "1/100", "1/50", "3/100", "1/20", "1/10", "1/5"];

#[test]
fn uniform_plates_certify_exactly_where_the_regular_plates_do() {
    // docs/model.md §11.7: a uniform rectangle or parallelogram plate is an affine image of the
    // uniform square plate (kappa = 1/6), a uniform triangle of the equilateral one (1/8).
    let mut certified = 0;
    for g in GRID {
        for (name, n, body) in plates(&q(g)) {
            let want = regular_claim(n, kappa_of(n), g);
            assert_eq!(general_claim(&body), want, "{name} at gamma = {g}");
            certified += usize::from(want.is_some());
        }
    }
    assert!(certified >= 8, "the grid must contain certified points ({certified})");
}

#[test]
fn regular_polygons_and_their_images_as_general_bodies_give_todays_verdicts() {
    let (zero, one) = (q("0"), q("1"));
    for (n, kappa) in [(3, "3/20"), (4, "1/6"), (4, "1/10"), (6, "1/4")] {
        for g in ["1/100", "1/50", "1/20", "1/10"] {
            let want = regular_claim(n, kappa, g);
            // n = 4: r0 = (1, 0), r1 = (0, 1) is the regular square itself.
            let images: Vec<[[Q; 2]; 2]> = match n {
                4 => vec![[[one.clone(), zero.clone()], [zero.clone(), one.clone()]], [[q("2"), q("1")], [q("-1"), q("3")]]],
                _ => vec![[[q("2"), q("0")], [q("-1"), q("3/2")]], [[q("1"), q("1")], [q("-2"), q("1")]]],
            };
            for [r0, r1] in images {
                let body = regular_image(n as usize, &r0, &r1, &q(kappa), &q(g)).unwrap();
                assert_eq!(general_claim(&body), want, "n = {n}, kappa = {kappa}, gamma = {g}, r0 = {r0:?}");
            }
        }
    }
}

#[test]
fn the_length_scale_does_not_change_the_verdict() {
    for g in ["1/100", "1/20"] {
        let base = general_claim(&rectangle_plate(&q("2"), &q("1"), q(g)).unwrap());
        for (a, b) in [("2000", "1000"), ("1/500", "1/1000"), ("150", "75")] {
            let body = rectangle_plate(&q(a), &q(b), q(g)).unwrap();
            assert_eq!(general_claim(&body), base, "{a} x {b} at gamma = {g}");
        }
    }
    // The scale is a power of two near the size, and scaling by it is exact.
    let phone = rectangle_plate(&q("150"), &q("75"), q("1/100")).unwrap();
    let r = length_scale(&phone);
    assert_eq!(r, q("64"));
    let s = scaled(&phone, &r);
    assert_eq!(s.contacts()[0], [q("75/64"), q("-75/128")]);
}

#[test]
fn pcc_decides_the_strongest_claim_and_a_requested_claim_is_honoured() {
    // The lander's adjacent pairs have real PCC roots: at most CcOrPccFromAllDown.
    let lander = chatter::bodies::general::general_catalogue(&q("1/100")).unwrap().remove(3).body;
    assert_eq!(general_claim(&lander), Some(Claim::CcOrPccFromAllDown));
    let mut req = ConvexRequest::new(lander);
    req.claim = chatter::certify::ClaimChoice::Exactly(Claim::CompleteChatterFromAllDown);
    assert!(matches!(certify_convex(&req).result, Err(Failure::PccNotExcluded(_))));
    // gamma = 0: only the invariance itself.
    let flat = rectangle_plate(&q("2"), &q("1"), q("0")).unwrap();
    let r = certify_convex(&ConvexRequest::new(flat));
    assert_eq!(r.result.map(|c| c.claim).ok(), Some(Claim::EffectivelyInvariant));
    assert!(r.notes.iter().any(|n| n.contains("0 < gamma < 1")), "{:?}", r.notes);
}

fn chatter(args: &[&str], dir: &std::path::Path) -> Output {
    Command::new(bin()).args(args).current_dir(dir).output().expect("run chatter")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

#[test]
fn certify_writes_version_4_files_that_verify_accepts() {
    let d = tempfile::tempdir().unwrap();
    let lander = root().join("certificates/bodies/lander.ron");
    for (args, claim) in [
        (vec!["--rectangle", "2,1", "--gamma", "1/100"], "CompleteChatterFromAllDown"),
        (vec!["--box", "150,75,8", "--gamma", "1/100"], "CompleteChatterFromAllDown"),
        (vec!["--body", "phone", "--gamma", "1/100"], "CompleteChatterFromAllDown"),
        (vec!["--body", lander.to_str().unwrap()], "CompleteChatterFromAllDown"),
        (vec!["--body", "lander", "--gamma", "1/100"], "CcOrPccFromAllDown"),
        (vec!["--polygon", "0,0 4,0 0,3", "--plate", "--gamma", "1/50"], "CcOrPccFromAllDown"),
    ] {
        let out = d.path().join("c.ron");
        let o = chatter(&[&["certify"][..], &args, &["-o", out.to_str().unwrap()]].concat(), d.path());
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", text(&o.stderr));
        assert!(text(&o.stdout).starts_with("CERTIFIED"), "{args:?}: {}", text(&o.stdout));
        assert!(text(&o.stdout).contains(&format!("claim={claim}")), "{args:?}: {}", text(&o.stdout));
        assert!(std::fs::read_to_string(&out).unwrap().contains("version: 4"));
        let v = chatter(&["verify", out.to_str().unwrap()], d.path());
        assert_eq!(v.status.code(), Some(0), "{args:?}: {}", text(&v.stdout));
        assert!(text(&v.stdout).contains(claim), "{}", text(&v.stdout));
    }
}

#[test]
fn certify_of_a_general_body_reports_json_and_negative_verdicts() {
    let d = tempfile::tempdir().unwrap();
    let o = chatter(&["certify", "--rectangle", "4,1", "--gamma", "1/100", "--json"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["verdict"], "certified");
    assert_eq!(v["n"], 4);
    assert_eq!(v["general_body"]["description"], "rectangle 4 x 1 (uniform plate)");
    assert!(v["generators"].as_u64().unwrap() >= 12, "at least 3 generators per cone: {v}");
    // Far above the square's threshold no family exists: exit 1 and the transition named.
    let o = chatter(&["certify", "--rectangle", "2,1", "--gamma", "1/5"], d.path());
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o.stdout).contains("no family of effectively invariant cones"), "{}", text(&o.stdout));
}

#[test]
fn bad_general_bodies_in_certify_exit_2_naming_the_flag() {
    let d = tempfile::tempdir().unwrap();
    for (args, needle) in [
        (vec!["--rectangle", "2,1", "--gamma", "0:1/10"], "--gamma: intervals"),
        (vec!["--rectangle", "2,-1"], "--rectangle"),
        (vec!["--polygon", "0,0 4,0 0,3"], "--polygon needs --plate"),
        (vec!["--body", "no-such-body"], "--body"),
        (vec!["--rectangle", "2,1", "--n", "3"], "--n"),
        (vec!["--rectangle", "2,1", "--gamma", "3/2"], "gamma"),
    ] {
        let o = chatter(&[&["certify"][..], &args].concat(), d.path());
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", text(&o.stdout));
        assert!(text(&o.stderr).contains(needle), "{args:?}: {}", text(&o.stderr));
    }
    // --body still takes the regular catalogue.
    let o = chatter(&["certify", "--body", "square plate", "--gamma", "1/100"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(text(&o.stdout).contains("n=4 kappa=1/6"), "{}", text(&o.stdout));
}
