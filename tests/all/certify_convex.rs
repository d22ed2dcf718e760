//! `certify` for general convex bodies (issue 13 §2-§3; docs/model.md §11.9): the family finder
//! and exactifier certify affine images of the regular plates exactly where the regular pipeline
//! certifies the regular plate, regular polygons given as general bodies give today's verdicts,
//! the length scale does not matter, and the CLI writes family certificates that `verify` accepts.

use crate::common::{bin, q, root};
use crate::transport::{kappa_of, plates};
use chatter::bodies::convex::rectangle_plate;
use chatter::certify::convex::{ConvexRequest, certify_convex, normalised, normaliser};
use chatter::certify::transport::regular_image;
use chatter::certify::{ClaimChoice, Failure, Request, certify};
use chatter::exact::Q;
use chatter::exact::QExt;
use chatter_kernel::certificate::{Claim, ConvexBodyText, ConvexCertificate, Encoding, Param, read_convex};
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
                4 => vec![
                    [[one.clone(), zero.clone()], [zero.clone(), one.clone()]],
                    [[q("2"), q("1")], [q("-1"), q("3")]],
                ],
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
    // The search's normalisation takes a rectangle back to (nearly) the regular square: contacts
    // of radius about 1 at right angles (docs/model.md §11.12).
    for (a, b) in [("150", "75"), ("4", "1"), ("1/3", "7")] {
        let body = rectangle_plate(&q(a), &q(b), q("1/100")).unwrap();
        let (image, _) = normalised(&body, &normaliser(&body)).unwrap();
        let c: Vec<[f64; 2]> = image.contacts().iter().map(|r| [r[0].to_f64(), r[1].to_f64()]).collect();
        for r in &c {
            assert!((r[0].hypot(r[1]) - 1.0).abs() < 1e-5, "{a} x {b}: {c:?}");
        }
        assert!((c[0][0] * c[1][0] + c[0][1] * c[1][1]).abs() < 1e-5, "{a} x {b}: {c:?}");
    }
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
        assert!(std::fs::read_to_string(&out).unwrap().contains("format: \"chatter-family-certificate\","));
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
        (vec!["--rectangle", "2,1", "--gamma", "1/10:0"], "--gamma: the interval 1/10:0 is empty"),
        (vec!["--rectangle", "2,1", "--gamma", "1/10:3/2"], "--gamma: 3/2 is not accepted"),
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

#[test]
fn certified_claims_never_contradict_simulated_drops_on_a_grid() {
    use chatter::sweep::general::{Agreement, finder_vs_simulation};
    let gammas: Vec<Q> = (1..=12).map(|k| Q::new(k, 200)).collect();
    let square = rectangle_plate(&q("1"), &q("1"), q("1/100")).unwrap();
    let rect = rectangle_plate(&q("4"), &q("1"), q("1/100")).unwrap();
    let lander = chatter::bodies::general::general_catalogue(&q("1/100")).unwrap().remove(3).body;
    let (s, r) =
        (finder_vs_simulation(&square, &gammas, 8, 5000), finder_vs_simulation(&rect, &gammas, 8, 5000));
    // An affine image certifies at the same points (§11.7).
    let claims = |g: &[chatter::sweep::general::GridPoint]| g.iter().map(|p| p.certified).collect::<Vec<_>>();
    assert_eq!(claims(&s), claims(&r));
    for grid in [s, r, finder_vs_simulation(&lander, &gammas, 8, 5000)] {
        let a = Agreement::of(&grid);
        assert_eq!(a.contradictions, 0, "{grid:?}");
        assert!(a.certified >= 3 && a.all_cc >= 3, "{a:?}");
    }
}

#[test]
fn bisection_brackets_the_largest_certified_gamma() {
    use chatter::certify::bisect::largest_certified_gamma;
    let third = Q::new(1, 3);
    let below = |g: &Q| if *g <= third { Ok(Claim::CompleteChatterFromAllDown) } else { Err("above".into()) };
    let b = largest_certified_gamma(below, (q("0"), q("1")), 16, &|| {});
    let (lo, hi) = (b.certified.unwrap().0, b.failed.unwrap().0);
    assert!(lo <= third && third < hi && &hi - &lo == Q::new(1, 1 << 16), "{lo} {hi}");
    assert_eq!(b.times.len(), 18);
    let never = largest_certified_gamma(|_| Err("no".into()), (q("1/10"), q("1/2")), 5, &|| {});
    assert!(never.certified.is_none() && never.failed.unwrap().0 == q("1/10") && never.times.len() == 1);
    let always =
        largest_certified_gamma(|_| Ok(Claim::EffectivelyInvariant), (q("1/10"), q("1/2")), 5, &|| {});
    assert!(always.failed.is_none() && always.certified.unwrap().0 == q("1/2"));
}

#[test]
fn largest_gamma_of_a_rectangle_is_the_square_plates() {
    let d = tempfile::tempdir().unwrap();
    let run = |args: &[&str]| {
        let o = chatter(
            &[&["certify", "--largest-gamma", "--steps", "10", "--json"][..], args].concat(),
            d.path(),
        );
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", text(&o.stderr));
        serde_json::from_slice::<serde_json::Value>(&o.stdout).unwrap()
    };
    let (rect, square) = (run(&["--rectangle", "3,1"]), run(&["--n", "4", "--kappa", "1/6"]));
    assert_eq!(rect["certified"], square["certified"]);
    assert_eq!(rect["not_certified"]["gamma"], square["not_certified"]["gamma"]);
    assert_eq!(rect["certified"]["claim"], "CompleteChatterFromAllDown");
    // Just above, the drops do not all end in CC (the square's threshold is where ICC begins).
    assert!(rect["drops_above"]["counts"]["CC"].as_u64().unwrap() < 100, "{rect}");
    let o = chatter(&["certify", "--rectangle", "2,1", "--largest-gamma", "--steps", "0"], d.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("--steps"));
}

#[test]
fn a_full_inertia_tensor_on_the_command_line_is_reduced_to_j_eff() {
    let d = tempfile::tempdir().unwrap();
    let square = "1,0 0,1 -1,0 0,-1";
    // I_xz = 1/10, I_zz = 1/2: J_eff = [[1/2 - 1/50, 0], [0, 1/2]] = [[12/25, 0], [0, 1/2]].
    let full = chatter(&["classify", "--polygon", square, "--inertia", "1/2,0,1/10,1/2,0,1/2"], d.path());
    assert_eq!(full.status.code(), Some(0), "{}", text(&full.stderr));
    let planar = chatter(&["classify", "--polygon", square, "--inertia", "12/25,0,1/2"], d.path());
    let after_body = |o: &Output| text(&o.stdout).lines().skip(1).collect::<Vec<_>>().join("\n");
    assert!(text(&full.stdout).contains("given inertia tensor, J_eff"), "{}", text(&full.stdout));
    assert!(text(&full.stdout).contains("J = [[12/25, 0], [0, 1/2]]"), "{}", text(&full.stdout));
    assert_eq!(after_body(&full), after_body(&planar));
    for (inertia, want) in [
        ("1,0,0,1,0,3", "triangle inequality"),
        ("1,0,2,1,0,1", "not positive definite"),
        ("1,0,0,1", "expected 3 numbers (JXX,JXY,JYY) or 6"),
    ] {
        let o = chatter(&["classify", "--polygon", square, "--inertia", inertia], d.path());
        assert_eq!(o.status.code(), Some(2), "{inertia}");
        assert!(text(&o.stderr).contains(want), "{inertia}: {}", text(&o.stderr));
    }
}

/// The body with contacts and J changed by `f`, the same gamma.
fn changed(body: &ConvexBody<Q>, f: impl Fn(&mut Vec<[Q; 2]>, &mut [[Q; 2]; 2])) -> Option<ConvexBody<Q>> {
    let (mut c, mut j) = (body.contacts().to_vec(), body.inertia().clone());
    f(&mut c, &mut j);
    ConvexBody::new(c, j, body.gamma().clone()).ok()
}

#[test]
fn the_recogniser_accepts_affine_images_and_rejects_perturbed_bodies() {
    use chatter::certify::transport::{RegularPreimage, regular_preimage};
    let g = q("1/50");
    let mut images: Vec<(String, ConvexBody<Q>, usize, Q)> = plates(&g)
        .into_iter()
        .map(|(name, n, b)| (name.to_string(), b, n as usize, q(kappa_of(n))))
        .collect();
    for (n, kappa, r0, r1) in [(3, "3/20", ["2", "0"], ["-1", "3/2"]), (4, "1/10", ["2", "1"], ["-1", "3"])] {
        for (n, kappa) in [(n, kappa), (6, "1/4")] {
            let body = regular_image(n, &[q(r0[0]), q(r0[1])], &[q(r1[0]), q(r1[1])], &q(kappa), &g).unwrap();
            images.push((format!("image n = {n}"), body, n, q(kappa)));
        }
    }
    let tiny = q("1/1000");
    for (name, body, n, kappa) in images {
        let want = Some(RegularPreimage { n, kappa });
        assert_eq!(regular_preimage(&body), want, "{name}");
        // Labels rotated by one: L R is a map of the same kind (§11.7).
        let rotated = changed(&body, |c, _| c.rotate_left(1)).unwrap();
        assert_eq!(regular_preimage(&rotated), want, "{name} rotated");
        let perturbed = [
            ("J_xx", changed(&body, |_, j| j[0][0] = &j[0][0] + &tiny)),
            ("J_xy", changed(&body, |_, j| (j[0][1], j[1][0]) = (&j[0][1] + &tiny, &j[1][0] + &tiny))),
            ("J_yy", changed(&body, |_, j| j[1][1] = &j[1][1] + &tiny)),
            ("contact 2", changed(&body, |c, _| c[2][0] = &c[2][0] + &tiny)),
            ("contact 0", changed(&body, |c, _| c[0][1] = &c[0][1] - &tiny)),
            ("centre", changed(&body, |c, _| c.iter_mut().for_each(|r| r[0] = &r[0] + &tiny))),
        ];
        for (what, b) in perturbed {
            let b = b.unwrap_or_else(|| panic!("{name}: {what} gives an invalid body"));
            assert_eq!(regular_preimage(&b), None, "{name} with {what} moved by 1/1000");
        }
    }
    // Not images: the lander (three feet, J not of the form), a box with a != b and c != 0
    // (§11.7), a pentagon.
    let lander = chatter::bodies::general::general_catalogue(&g).unwrap().remove(3).body;
    let brick = chatter::bodies::convex::uniform_box(&q("3"), &q("2"), &q("1"), g.clone()).unwrap();
    let pentagon = chatter::bodies::convex::polygon_plate(
        &[[q("2"), q("0")], [q("1"), q("2")], [q("-1"), q("2")], [q("-2"), q("0")], [q("0"), q("-2")]],
        g.clone(),
    )
    .unwrap();
    for (name, b) in [("lander", lander), ("box 3 x 2 x 1", brick), ("pentagon", pentagon)] {
        assert_eq!(regular_preimage(&b), None, "{name}");
    }
}

#[test]
fn the_fallback_certifies_the_triangle_between_the_finders_limit_and_the_threshold() {
    use chatter::bodies::convex::polygon_plate;
    use chatter::certify::convex::TRANSPORTED;
    let corners = [[q("0"), q("0")], [q("3"), q("0")], [q("1"), q("2")]];
    // Without the exactifier's retries (as in a cover or a survey) the family finder +
    // exactifier stop below 0.14571 here (with them, since the retries without overshoot, they
    // reach the bracket themselves); the threshold of the equilateral plate (kappa = 1/8) is
    // 0.14589803375 (`classify --n 3 --kappa 1/8`).
    for g in ["14589/100000", "145897/1000000"] {
        let body = polygon_plate(&corners, q(g)).unwrap();
        let mut req = ConvexRequest::new(body.clone());
        req.exactify.retry = false;
        let r = certify_convex(&req);
        assert_eq!(
            r.method,
            Some(TRANSPORTED),
            "gamma = {g}: {:?}",
            r.result.as_ref().err().map(ToString::to_string)
        );
        assert_eq!(general_claim(&body), Some(Claim::CompleteChatterFromAllDown), "gamma = {g}");
        let cert = r.result.unwrap();
        assert!(cert.producer.contains("transported from a regular n = 3 certificate"), "{}", cert.producer);
        assert!(r.notes.iter().any(|n| n.contains("regular n = 3 body with kappa = 1/8")), "{:?}", r.notes);
    }
    // Above the threshold both routes fail, and the notes say so.
    let r = certify_convex(&ConvexRequest::new(polygon_plate(&corners, q("1459/10000")).unwrap()));
    assert!(r.result.is_err() && r.method.is_none());
    assert!(
        r.notes.iter().any(|n| n.starts_with(chatter::certify::convex::TRANSPORT_FAILED)),
        "{:?}",
        r.notes
    );
}

#[test]
fn the_largest_gamma_limit_compares_the_failure_with_the_regular_threshold() {
    use chatter::certify::bisect::Bisection;
    use chatter::report::largest_gamma::{Limit, LimitKind, ThresholdOf};
    let bisection = |ok: &str, bad: &str| Bisection {
        certified: Some((q(ok), Claim::CompleteChatterFromAllDown)),
        failed: Some((q(bad), "why".into())),
        times: vec![],
    };
    let tri = ThresholdOf::regular(3, &q("1/8"));
    // gamma* = 0.14589803375... for n = 3, kappa = 1/8.
    for (ok, bad, kind) in [
        ("1457/10000", "14571/100000", LimitKind::BelowThreshold),
        ("729/5000", "1459/10000", LimitKind::AboveThreshold),
    ] {
        let l = Limit::of(Some(&tri), &bisection(ok, bad));
        assert_eq!(l.kind, kind, "{}", l.text);
        let t = l.threshold.as_ref().unwrap();
        assert!(t.lo.f64 <= 0.145898033751 && 0.14589803374 <= t.hi.f64, "{t:?}");
        assert!(l.text.contains("S_1 of n=3 kappa=1/8"), "{}", l.text);
        let gap = l.relative_gap.unwrap();
        assert!((gap - (0.14589803375 - q(ok).to_f64()) / 0.14589803375).abs() < 1e-9, "{gap}");
    }
    let at = Limit::of(Some(&tri), &bisection("729/5000", "145898033751/1000000000000"));
    assert_eq!(at.kind, LimitKind::InEnclosure, "{}", at.text);
    let none = Limit::of(None, &bisection("1/100", "1/50"));
    assert!(none.kind == LimitKind::NoThreshold && none.threshold.is_none() && none.relative_gap.is_none());
    assert!(none.text.contains("no CC threshold is known"), "{}", none.text);
    // A body that is no affine image: its product criterion's threshold (conjectural, §11.11),
    // the lander's 0.0590763452... (`classify --body lander`).
    let lander = chatter::bodies::general::general_catalogue(&q("1/100")).unwrap().remove(3).body;
    let product = ThresholdOf::product(&lander);
    let l = Limit::of(Some(&product), &bisection("2929/50000", "5859/100000"));
    assert_eq!(l.kind, LimitKind::BelowThreshold, "{}", l.text);
    let t = l.threshold.unwrap();
    assert!(t.lo.f64 <= 0.0590763452725 && 0.059076345271 <= t.hi.f64, "{t:?}");
    assert!(l.text.contains("conjectural"), "{}", l.text);
    let open = Bisection { failed: None, ..bisection("1/100", "1/50") };
    assert_eq!(Limit::of(Some(&tri), &open).kind, LimitKind::NoBracket);
    // The command reports it: the triangle's bracket lies at its regular threshold.
    let d = tempfile::tempdir().unwrap();
    let args =
        ["certify", "--polygon", "0,0 3,0 1,2", "--plate", "--largest-gamma", "--steps", "12", "--json"];
    let o = chatter(&args, d.path());
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["limit"]["criterion"], "S_1 of n=3 kappa=1/8 (docs/model.md §6)", "{v}");
    assert_eq!(v["limit"]["kind"], "above-threshold", "{v}");
    assert!(v["certified"]["gamma"]["f64"].as_f64().unwrap() > 0.1456, "{v}");
}

/// The cones of a family certificate over an interval of gamma, given as a certificate for the
/// single gamma `g` (version 1).
fn at_gamma(cert: &ConvexCertificate, g: &Q) -> ConvexCertificate {
    let mut c = cert.clone();
    let ConvexBodyText::ConvexPolygon { gamma, .. } = &mut c.body;
    *gamma = Param::Point(chatter_kernel::exact::to_canonical(g));
    c.version = 1;
    c
}

/// Brute force against the reduction to the two ends (docs/kernel-soundness.md §6): the cones of
/// an accepted interval certificate are accepted, as single-gamma certificates, at 7 evenly
/// spaced gammas of the interval, ends included, on both backends.
fn holds_inside(cert: &ConvexCertificate, [lo, hi]: [&Q; 2]) {
    for k in 0..=6 {
        let g = lo.clone() + (hi.clone() - lo.clone()) * q(&k.to_string()) / q("6");
        let v = verify_convex_on(&at_gamma(cert, &g), ParseLimits::default(), &[MALACHITE, NUM]);
        assert!(matches!(v, Verdict::Accepted(_)), "gamma = {g}: {v:?}");
    }
}

#[test]
fn an_interval_of_gamma_gives_one_version_2_certificate_that_holds_inside_it() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("c.ron");
    let args =
        ["certify", "--rectangle", "2,1", "--gamma", "1/100:1/50", "--json", "-o", out.to_str().unwrap()];
    let o = chatter(&args, d.path());
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["verdict"], "certified");
    assert_eq!(
        (&v["gamma"]["lo"]["exact"], &v["gamma"]["hi"]["exact"]),
        (&"1/100".into(), &"1/50".into()),
        "{v}"
    );
    let written = std::fs::read_to_string(&out).unwrap();
    assert!(
        written.contains("version: 2,") && written.contains("gamma: [\"1/100\", \"1/50\"],"),
        "{written}"
    );
    let o = chatter(&["verify", "--json", out.to_str().unwrap()], d.path());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["files"][0]["gamma_interval"], serde_json::json!(["1/100", "1/50"]), "{v}");
    let o = chatter(&["verify", out.to_str().unwrap()], d.path());
    assert!(text(&o.stdout).contains("for every gamma in [1/100, 1/50]"), "{}", text(&o.stdout));
    let cert: ConvexCertificate = read_convex(&written, Encoding::Ron).unwrap();
    holds_inside(&cert, [&q("1/100"), &q("1/50")]);
    // The text: the interval in the summary line.
    let o = chatter(&["certify", "--rectangle", "2,1", "--gamma", "1/100:1/50"], d.path());
    assert!(text(&o.stdout).contains("every gamma in [1/100, 1/50] claim="), "{}", text(&o.stdout));
    // PCC is not excluded at the lower end 1/1000: the weaker claim, and the note names the end.
    let o = chatter(&["certify", "--rectangle", "2,1", "--gamma", "1/1000:1/50"], d.path());
    let out = text(&o.stdout);
    assert!(out.contains("claim=CcOrPccFromAllDown"), "{out}");
    assert!(out.contains("does not apply: at the end gamma = 1/1000 of the interval: contacts"), "{out}");
}

#[test]
fn the_search_over_an_interval_serves_both_ends_where_a_point_certificate_serves_one() {
    // The family made for gamma = 1/50 alone fails at 1/100 (its cones are tight at 1/50); the
    // search over [1/100, 1/50] maps every piece at both ends and gives a family for both.
    let body = rectangle_plate(&q("2"), &q("1"), q("1/100")).unwrap();
    let mut point = ConvexRequest::new(rectangle_plate(&q("2"), &q("1"), q("1/50")).unwrap());
    point.claim = ClaimChoice::Exactly(Claim::CompleteChatterFromAllDown);
    let at_hi = certify_convex(&point).result.unwrap();
    let mut widened = at_hi.clone();
    let ConvexBodyText::ConvexPolygon { gamma, .. } = &mut widened.body;
    *gamma = Param::Interval("1/100".into(), "1/50".into());
    widened.version = 2;
    let v = verify_convex_on(&widened, ParseLimits::default(), &[MALACHITE, NUM]);
    let Verdict::Rejected(r) = v else { panic!("the point family holds at 1/100 too: {v:?}") };
    assert_eq!(r.code.as_str(), "image-outside", "{r:?}");
    let mut req = ConvexRequest::new(body);
    (req.gamma_hi, req.claim) = (Some(q("1/50")), point.claim);
    let cert = certify_convex(&req).result.unwrap();
    assert_eq!(cert.version, 2);
    // An upper end outside [0, 1] is gamma's range, not an internal error.
    let mut beyond = req.clone();
    beyond.gamma_hi = Some(q("3/2"));
    assert!(matches!(certify_convex(&beyond).result, Err(Failure::GammaOutOfRange(_))));
    holds_inside(&cert, [&q("1/100"), &q("1/50")]);
}

#[test]
fn a_regular_box_certificate_transports_to_an_interval_family_of_its_affine_images() {
    // n = 3, kappa = 1/8, gamma in [1/10, 7/50]: the regular box certificate carried to the
    // irregular triangle plate holds on the whole interval (docs/model.md §11.7).
    let regular = certify(&Request::boxed(3, [q("1/8"), q("1/8")], [q("1/10"), q("7/50")])).result.unwrap();
    let (_, _, triangle) = plates(&q("1/10")).into_iter().find(|p| p.0 == "irregular triangle").unwrap();
    let family = chatter::certify::transport::transport(&triangle, &regular).unwrap();
    assert_eq!(family.version, 2);
    let ConvexBodyText::ConvexPolygon { gamma, .. } = &family.body;
    assert_eq!(gamma, &Param::Interval("1/10".into(), "7/50".into()));
    holds_inside(&family, [&q("1/10"), &q("7/50")]);
}

/// Issue 25 §4, the lander's target: a gamma within 10^-6 (relative) of its conjectural product
/// threshold 0.0590763452... certifies CC, where the exactifier's overshoot alone made its cones
/// grow until one reached v = 0 (regression: the largest certified gamma was 0.058589834, 8.2e-3
/// short). The claim is checked again on each backend alone.
#[test]
fn the_lander_certifies_within_one_millionth_of_its_threshold() {
    let threshold = 0.05907634527;
    let g = q("590763/10000000");
    assert!((threshold - g.to_f64()) / threshold < 1e-6);
    let lander = chatter::bodies::general::general_catalogue(&g).unwrap().remove(3).body;
    assert_eq!(general_claim(&lander), Some(Claim::CompleteChatterFromAllDown));
}
