//! Rule T1 (docs/time-to-rest.md §2): the oracle's test 1/B ≤ λ_1 against an integer square root
//! at a point where λ_1 is irrational, at the threshold Δ = 0, and on the failing hypotheses; the
//! theorem itself on exact simulated rod drops (T|v|/h never exceeds 1/λ_1 and comes within any
//! margin of it, so a smaller B is false); and the kernel's verdict on bounds 10^-30 either side
//! of 1/λ_1.

use chatter_oracle::arith::Num;
use chatter_oracle::arith::rational::{Rat, parse_rational, ratio, rational_text};
use chatter_oracle::claim::Claim;
use chatter_oracle::cone3::dot;
use chatter_oracle::kinds::limits::Limits;
use chatter_oracle::kinds::rest::Graph;
use chatter_oracle::plane::{inside, project};
use chatter_oracle::read::Encoding;
use chatter_oracle::regular::model::{Polygon, V3};
use chatter_oracle::regular::rest::{below_largest_root, time_to_rest};
use chatter_oracle::regular::rod::Rod;
use chatter_oracle::regular::virtual_time::Node;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

fn r(s: &str) -> Rat {
    parse_rational(s, 10_000).expect("canonical")
}

fn rod(kappa: &str, gamma: &str) -> Rod {
    Rod { kappa: r(kappa), gamma: r(gamma) }
}

fn ten(e: u32) -> BigInt {
    BigInt::from(10).pow(e)
}

/// At κ = 1/3, γ = 7/100: σ = 107/200, Δ = 249/40000, λ_1 = (107 + √249)/400 and
/// 1/λ_1 = (107 - √249)/28 (rationalised), irrational. With s = ⌊√249 · 10^30⌋ / 10^30 the
/// rationals (107 - s - 10^-30)/28 < 1/λ_1 < (107 - s)/28 bracket it 10^-30/28 apart.
fn bracket() -> (Rat, Rat) {
    let s = (BigInt::from(249) * ten(60)).sqrt();
    let lo = Rat::new(BigInt::from(107) * ten(30) - &s - BigInt::one(), BigInt::from(28) * ten(30));
    let hi = Rat::new(BigInt::from(107) * ten(30) - &s, BigInt::from(28) * ten(30));
    (lo, hi)
}

#[test]
fn an_irrational_lambda_is_bracketed_by_bounds_ten_to_the_minus_thirty_apart() {
    let body = rod("1/3", "7/100");
    let (lo, hi) = bracket();
    assert!(&hi - &lo < ratio(1, 1) / Rat::from_integer(ten(30)));
    assert!(!below_largest_root(&body, &lo), "B just below 1/λ_1 is not shown");
    assert!(below_largest_root(&body, &hi), "B just above 1/λ_1 is shown");
    let limits = Limits::default();
    let claim = Claim::CompleteChatterFromAllDown;
    assert_eq!(time_to_rest(&body, claim, &rational_text(&hi), &limits), Ok(rational_text(&hi)));
    let refused = time_to_rest(&body, claim, &rational_text(&lo), &limits).unwrap_err();
    assert_eq!(refused.codes, ["time-to-rest-not-shown"]);
    // The tool's bound in the corpus file (within 2^-40 of 1/λ_1, above it) is shown; B = 2/σ too.
    assert!(below_largest_root(&body, &r("439804651110400/134997745010057")));
    assert!(below_largest_root(&body, &r("400/107")));
}

#[test]
fn at_the_threshold_delta_zero_the_bound_is_exactly_one_over_lambda() {
    // κ = 1/4, γ = 1/9: σ = 2/3, Δ = 0, λ_1 = λ_2 = 1/3.
    let body = rod("1/4", "1/9");
    let eps = Rat::new(BigInt::one(), ten(40));
    assert!(below_largest_root(&body, &r("3")));
    assert!(!below_largest_root(&body, &(r("3") - &eps)));
    assert!(below_largest_root(&body, &(r("3") + &eps)));
}

#[test]
fn every_hypothesis_of_the_theorem_is_required() {
    let limits = Limits::default();
    let code = |b: &Rod, claim: Claim, text: &str| time_to_rest(b, claim, text, &limits).map_err(|f| f.codes);
    let drops = Claim::CcOrPccFromAllDown;
    let ok = rod("1/3", "1/20");
    assert_eq!(code(&ok, drops, "5/2"), Ok("5/2".into()), "λ_1 = 2/5");
    assert_eq!(code(&ok, drops, "12/5"), Err(vec!["time-to-rest-not-shown"]));
    assert_eq!(code(&ok, Claim::EffectivelyInvariant, "5/2"), Err(vec!["time-to-rest-not-shown"]));
    for b in ["0", "-5/2"] {
        assert_eq!(code(&ok, drops, b), Err(vec!["time-to-rest-not-shown"]), "B = {b}");
    }
    // κ ≥ 1: σ ≤ 0. κ = 1/3, γ = 1/5: σ = 3/5, Δ = 9/25 - 4/5 < 0 (complex roots).
    for (k, g) in [("1", "1/20"), ("2", "1/20"), ("1/3", "1/5")] {
        assert_eq!(code(&rod(k, g), drops, "1000"), Err(vec!["time-to-rest-not-shown"]), "{k}, {g}");
    }
    // The number is read first.
    assert_eq!(code(&ok, Claim::EffectivelyInvariant, "10/4"), Err(vec!["bad-number"]));
    assert_eq!(code(&ok, drops, "c"), Err(vec!["bad-number"]));
}

/// The rod's drop of docs/time-to-rest.md §2, simulated exactly with the oracle's impact map:
/// end 0 lands at time 0 with speed w0, end 1 is at height 1 moving down at u. Returns T_M |v|/h
/// for the flights after the first `impacts` impacts (a partial sum of the time to rest T).
fn drop_ratio(body: &Rod, w0: &Rat, u: &Rat, impacts: usize) -> Rat {
    let (mut h, mut p) = ([Rat::zero(), Rat::one()], body.impact(0, &[-w0.clone(), -u.clone()]));
    let mut t = Rat::zero();
    for _ in 0..impacts {
        // The end that lands next: moving down, soonest.
        let next = (0..2)
            .filter(|&k| p[k].is_negative())
            .map(|k| (&h[k] / -&p[k], k))
            .min()
            .expect("an all-down drop never separates (Theorem, step (b))");
        let (f, k) = next;
        assert!(f.is_positive(), "no simultaneous impacts");
        h = [&h[0] + &f * &p[0], &h[1] + &f * &p[1]];
        assert!(h[k].is_zero());
        t += f;
        p = body.impact(k, &p);
    }
    // h = H/2 = 1/2 and |v| = (w0 + u)/2 just before the first impact.
    t * (w0 + u)
}

#[test]
fn simulated_drops_stay_within_one_over_lambda_and_approach_it() {
    for (k, g, inv_lambda) in [("1/3", "1/20", r("5/2")), ("1/6", "1/6", r("2")), ("1/4", "1/9", r("3"))] {
        let body = rod(k, g);
        assert!(below_largest_root(&body, &inv_lambda), "{k}, {g}");
        let mut largest = Rat::zero();
        for (w0, u) in [("1", "1"), ("1", "1/3"), ("3", "1/100"), ("1", "0"), ("1/2", "7")] {
            let x = drop_ratio(&body, &r(w0), &r(u), 60);
            assert!(x <= inv_lambda, "κ = {k}, γ = {g}, w0 = {w0}, u = {u}: T|v|/h ≥ {x}");
            largest = largest.max(x);
        }
        // u = 0 attains 1/λ_1 in the limit, so B = 1/λ_1 - 1/100 is false.
        let below = &inv_lambda - ratio(1, 100);
        assert!(!below_largest_root(&body, &below));
        // At Δ = 0 the flights decay like 1/m² and the tail after M impacts is 1/(M + 1) of T.
        let slow = if g == "1/9" { 400 } else { 60 };
        assert!(drop_ratio(&body, &r("1"), &r("0"), slow) > below, "κ = {k}, γ = {g}: sharp");
        assert!(largest > ratio(1, 1), "{largest}");
    }
}

fn with_bound(file: &str, bound: Option<&str>) -> String {
    let text = std::fs::read_to_string(crate::common::root().join("certificates/valid").join(file)).unwrap();
    let start = text.find("    time_to_rest_bound:").expect("the field");
    let end = start + text[start..].find('\n').unwrap() + 1;
    let line = bound.map(|b| format!("    time_to_rest_bound: Some(\"{b}\"),\n")).unwrap_or_default();
    format!("{}{line}{}", &text[..start], &text[end..])
}

#[test]
fn the_kernel_agrees_ten_to_the_minus_thirty_either_side_of_an_irrational_bound() {
    let (lo, hi) = bracket();
    let file = "n2-kappa1_3-gamma7_100-complete-chatter-from-all-down.ron";
    let (k, o, cmp) = crate::common::differential_ron(&with_bound(file, Some(&rational_text(&hi))));
    assert!(cmp.is_ok() && k.accepted && o.accepted(), "{cmp:?} {k:?} {o:?}");
    assert_eq!(o.time_to_rest_bound, Some(rational_text(&hi)));
    let (k, o, cmp) = crate::common::differential_ron(&with_bound(file, Some(&rational_text(&lo))));
    assert!(cmp.is_ok(), "{cmp:?}");
    assert_eq!(
        (k.code.as_deref(), o.codes()),
        (Some("time-to-rest-not-shown"), &["time-to-rest-not-shown"][..])
    );
    // Without the field, and with `None`, the certificate is accepted without a bound.
    let (k, o, cmp) = crate::common::differential_ron(&with_bound(file, None));
    assert!(cmp.is_ok() && k.accepted && o.time_to_rest_bound.is_none(), "{cmp:?}");
    let none =
        with_bound(file, None).replace("    producer:", "    time_to_rest_bound: None,\n    producer:");
    let (k, o, cmp) = crate::common::differential_ron(&none);
    assert!(cmp.is_ok() && k.accepted && o.accepted(), "{cmp:?}");
}

#[test]
fn the_bound_is_refused_on_every_body_but_the_rod_at_a_point() {
    let square =
        std::fs::read_to_string(crate::common::root().join("certificates/valid/doc-example-square.ron"))
            .unwrap();
    let rod_box = std::fs::read_to_string(
        crate::common::root().join("certificates/valid/n2-kappa1_4_1_3-gamma1_100_1_20-box.ron"),
    )
    .unwrap();
    for (what, text) in [("square", square), ("rod box", rod_box)] {
        let at = text.find("    producer:").expect("a producer");
        let with = format!("{}    time_to_rest_bound: Some(\"1000\"),\n{}", &text[..at], &text[at..]);
        let (k, o, cmp) = crate::common::differential_ron(&with);
        assert!(cmp.is_ok(), "{what}: {cmp:?}");
        assert_eq!(k.code.as_deref(), Some("time-to-rest-not-shown"), "{what}");
        assert_eq!(o.codes(), ["time-to-rest-not-shown"], "{what}");
        // Refused before the numbers are read: even a malformed B.
        let bad = with.replace("Some(\"1000\")", "Some(\"10/4\")");
        assert_eq!(chatter_oracle::judge(&bad, Encoding::Ron).codes(), ["time-to-rest-not-shown"], "{what}");
        assert!(crate::common::differential_ron(&bad).2.is_ok(), "{what}");
    }
}

/// The optional field's syntax (docs/certificate-format.md §2: RON `Some("p/q")` or `None`, JSON
/// the string itself; §11: no `null`), and `Some(...)` where another value belongs: the kernel
/// (ron and serde_json) and the oracle's parser give the same verdicts and codes.
#[test]
fn the_optional_field_and_the_header_get_the_kernels_codes() {
    let file = "n2-kappa1_3-gamma1_20-complete-chatter-from-all-down.ron";
    let base = std::fs::read_to_string(crate::common::root().join("certificates/valid").join(file)).unwrap();
    let bound = "Some(\"5/2\")";
    let edits: Vec<(&str, &str, &str)> = vec![
        (bound, "None", "accepted"),
        (bound, "Some(\"5/2\",)", "accepted"),
        (bound, "Some ( \"5/2\" )", "accepted"),
        (bound, "\"5/2\"", "syntax"),
        (bound, "Some(\"5/2\", \"1\")", "syntax"),
        (bound, "Some()", "syntax"),
        (bound, "Some(5)", "syntax"),
        (bound, "Some(None)", "syntax"),
        (bound, "Some(x: \"5/2\")", "syntax"),
        (bound, "ContactVelocities", "syntax"),
        (bound, "(\"5/2\")", "syntax"),
        (bound, "Some([\"5/2\"])", "syntax"),
        (bound, "Some(\"10/4\")", "bad-number"),
        (bound, "Some(\"5/2\"),\n    time_to_rest_bound: None", "duplicate-field"),
        ("claim: CompleteChatterFromAllDown", "claim: Some(\"1\")", "unknown-variant"),
        ("claim: CompleteChatterFromAllDown", "claim: None", "unknown-variant"),
        ("coordinates: ContactVelocities", "coordinates: Some(ContactVelocities)", "unknown-variant"),
        ("kappa: \"1/3\"", "kappa: Some(\"1/3\")", "syntax"),
        ("version: 1", "version: Some(1)", "syntax"),
        ("(\"-10/3\", \"4/3\")", "Some(\"-10/3\", \"4/3\")", "syntax"),
        // The kernel reads the header leniently (`Some` implicit), then the schema strictly.
        ("format: \"chatter-certificate\"", "format: Some(\"3\")", "wrong-format"),
        ("format: \"chatter-certificate\"", "format: Some(\"chatter-certificate\")", "syntax"),
        ("format: \"chatter-certificate\"", "format: None", "missing-field"),
        ("version: 1", "version: None", "missing-field"),
        ("version: 1", "version: Some(7)", "unsupported-version"),
        ("version: 1", "version: None,\n    version: 1", "duplicate-field"),
        // Its struct names: the header is read under any struct name (or none), then the schema,
        // which wants the kind's own name (kernel/tests/all/point_kernel.rs).
        ("Certificate(", "Refutation(", "syntax"),
        ("Certificate(", "Foo(", "syntax"),
        (
            "Certificate(\n    format: \"chatter-certificate\"",
            "Refutation(\n    format: \"x\"",
            "wrong-format",
        ),
        ("Certificate(\n    format: \"chatter-certificate\"", "Proof(\n    format: \"x\"", "wrong-format"),
        ("Certificate(\n    format: \"chatter-certificate\"", "Foo(\n    format: \"x\"", "wrong-format"),
        (
            "Certificate(\n    format: \"chatter-certificate\"",
            "Refutation(\n    format: None",
            "missing-field",
        ),
    ];
    for (from, to, want) in edits {
        assert!(base.contains(from), "{from}");
        let text = base.replacen(from, to, 1);
        let (k, o, cmp) = crate::common::differential_ron(&text);
        assert!(cmp.is_ok(), "{to}: {cmp:?}");
        let got = if k.accepted { "accepted" } else { k.code.as_deref().unwrap_or("") };
        assert_eq!(got, want, "{to}: kernel {k:?}");
        assert_eq!(o.accepted(), want == "accepted", "{to}: oracle {o:?}");
    }
    // JSON: the value itself; `null` is outside the strict syntax.
    let json = r#"{"format": "chatter-certificate", "version": 1, "body": {"RegularPolygon": {"n": 2, "kappa": "1/3", "gamma": "1/20"}}, "coordinates": "ContactVelocities", "claim": "CompleteChatterFromAllDown", "cone": [["-10/3", "4/3"], ["4/3", "-10/3"]], "time_to_rest_bound": B, "producer": ""}"#;
    let dir = std::env::temp_dir().join(format!("chatter-oracle-ttr-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (b, want) in [
        ("\"5/2\"", "accepted"),
        ("\"12/5\"", "time-to-rest-not-shown"),
        ("null", "syntax"),
        ("[\"5/2\"]", "syntax"),
        ("{\"Some\": \"5/2\"}", "syntax"),
    ] {
        let path = dir.join("bound.json");
        std::fs::write(&path, json.replace("B", b)).unwrap();
        let (k, o, cmp) = crate::common::differential_file(&path);
        assert!(cmp.is_ok(), "{b}: {cmp:?}");
        let got = if k.accepted { "accepted" } else { k.code.as_deref().unwrap_or("") };
        assert_eq!(got, want, "{b}: kernel {k:?}");
        assert_eq!(o.accepted(), want == "accepted", "{b}: oracle {o:?}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// The graph and B of a time-to-rest certificate of the corpus, after the oracle's file rules.
fn rest_graph(file: &str) -> (Graph, Rat) {
    use chatter_oracle::kinds::rest::{bound, prepare, read};
    let text = std::fs::read_to_string(crate::common::root().join("certificates/valid").join(file)).unwrap();
    let value = chatter_oracle::read::parse::parse(&text, Encoding::Ron).expect("parses");
    let f = read(&value).expect("the schema");
    (prepare(&f, &Limits::default()).expect("the file's rules"), bound(&f, &Limits::default()).expect("B"))
}

/// Φ_r(q, p) = (a_r·q)/(-b_r·p) (a_r = c_r b_r in version 1), docs/time-to-rest.md §5.
fn virtual_time(node: &Node, q: &V3, p: &V3) -> Num {
    &dot(&node.numerator, q) / &dot(&node.weight, p).neg()
}

/// The next impact of a flight from (q, p) in the frame of the last impact: its contact j and the
/// flight's length, `None` at a simultaneous impact (outside the model).
fn next_impact(b: &Polygon, q: &V3, p: &V3) -> Option<(i64, Num)> {
    let mut best: Option<(i64, Num)> = None;
    let mut tie = false;
    for k in 1..b.n as i64 {
        let u = b.speed(k, p);
        if !u.is_negative() {
            continue;
        }
        let t = &b.speed(k, q) / &u.neg();
        let earlier = best.as_ref().is_none_or(|(_, t0)| t < *t0);
        if earlier {
            (best, tie) = (Some((k, t)), false);
        } else if best.as_ref().is_some_and(|(_, t0)| t == *t0) {
            tie = true;
        }
    }
    assert!(best.is_some(), "a velocity with v < 0 moves some contact down");
    (!tie).then_some(best).flatten()
}

/// Follows the all-down drop with velocity Σ λ_k (-m_{k,k+1}) before its first impact at contact 0,
/// in the configuration α m_{0,1} + α' m_{n-1,0}, exactly for `impacts` impacts, checking the steps
/// of the proof of Theorem 5.1 at every impact: the velocity in its node's cone, Φ ≥ 0, Φ falling
/// by at least each flight. Returns T (the flights' sum) + Φ at the end, B h/|v| and the number of
/// impacts followed (fewer than `impacts` at a simultaneous impact).
fn follow_drop(
    (g, b_bound): &(Graph, Rat),
    lambda: &[i64],
    alpha: [i64; 2],
    impacts: usize,
) -> (Num, Num, usize) {
    let b = &g.body;
    let f = &b.kappa.field;
    let int = |k: i64| Num::int(f, k);
    let ks = &g.polygons;
    let d = b.all_down();
    let p0: V3 =
        std::array::from_fn(|i| (0..b.n).fold(int(0), |acc, k| &acc + &(&int(lambda[k]) * &d[k][i])));
    let (m01, m0) = (b.rest_point(0, 1), b.rest_point(b.n as i64 - 1, 0));
    let mut q: V3 = std::array::from_fn(|i| &(&int(alpha[0]) * &m01[i]) + &(&int(alpha[1]) * &m0[i]));
    let bound = &(&Num::rational(f, b_bound.clone()) * &q[2]) / &p0[2].neg();
    let (mut p, mut r, mut time) = (b.impact(0, &p0), 0, int(0));
    let mut phi = virtual_time(&g.nodes[0], &q, &p);
    assert!(phi <= bound, "Φ after the first impact exceeds B h/|v|");
    let mut followed = 1;
    for _ in 0..impacts {
        let inside_node = project(&p).is_some_and(|x| inside(&ks[r].sides, &x));
        assert!(inside_node && !phi.is_negative(), "node {r}: the velocity leaves K_r or Φ < 0");
        let Some((j, flight)) = next_impact(b, &q, &p) else { break };
        let landed: V3 = std::array::from_fn(|i| &q[i] + &(&flight * &p[i]));
        let s = g.nodes[r].next.iter().find(|(step, _)| *step == j as u64).expect("a successor").1 as usize;
        q = [b.speed(j, &landed), b.speed(j + 1, &landed), landed[2].clone()];
        p = b.step(j, &p);
        let after = virtual_time(&g.nodes[s], &q, &p);
        assert!(after <= &phi - &flight, "node {r} -> {s}: Φ falls by less than the flight");
        (phi, r, time, followed) = (after, s, &time + &flight, followed + 1);
    }
    (&time + &phi, bound, followed)
}

/// Theorem 5.1 (docs/time-to-rest.md §5) on exact drops of the square plate at the corpus's two
/// accepted graphs: along 40 impacts of drops from several all-down velocities and first-impact
/// configurations, every post-impact velocity lies in the cone of the node `next` assigns, Φ ≥ 0,
/// Φ falls by at least each flight, and T + Φ never exceeds B h/|v| (evidence for the proof's
/// steps (a)-(f) on these drops; the proof itself is the document's).
#[test]
fn exact_drops_follow_the_virtual_time_of_the_corpus_graphs() {
    let lambdas: [&[i64]; 4] = [&[1, 2, 3, 4], &[5, 1, 1, 2], &[1, 3, 1, 7], &[2, 1, 4, 1]];
    for file in [
        "rest-n4-kappa1_6-gamma1_100.ron",
        "rest-n4-kappa1_6-gamma1_50.ron",
        "rest-v2-n4-kappa1_6-gamma1_100.ron",
        "rest-v2-n3-kappa1_10-gamma1_20.ron",
    ] {
        let g = rest_graph(file);
        let (mut worst, mut impacts) = (Rat::zero(), vec![]);
        for (i, lambda) in lambdas.iter().enumerate() {
            let alpha = [[1, 1], [2, 5], [7, 1], [1, 3]][i];
            let (spent, bound, followed) = follow_drop(&g, lambda, alpha, 40);
            assert!(spent <= bound && spent.is_positive(), "{file}: T + Φ = {spent:?} > B h/|v|");
            worst = worst.max((&spent / &bound).as_rational().expect("rational").clone());
            impacts.push(followed);
        }
        assert!(impacts.iter().all(|&m| m > 40), "{file}: impacts followed {impacts:?}");
        let per_mille = (worst * Rat::from_integer(1000.into())).floor();
        eprintln!("{file}: impacts {impacts:?}, largest (T + Φ)/(B h/|v|) about {per_mille}/1000");
    }
}

/// A time-to-rest certificate's JSON twin (written by the tool's `convert`, docs/certificate-format.md
/// §16 and §11) gets the RON file's verdict from the oracle, and the kernel's verdict on the twin
/// agrees with it (code, claim, nodes and B).
#[test]
fn json_twins_of_rest_certificates_get_the_verdict_of_their_ron() {
    use chatter::convert::{Target, convert};
    use chatter_kernel::syntax::Encoding as KernelEncoding;
    let files = [
        "valid/rest-n4-kappa1_6-gamma1_50.ron",
        "valid/rest-v2-n3-kappa1_10-gamma1_20.ron",
        "invalid/rest-image-outside.ron",
        "invalid/rest-bound-too-small.ron",
        "invalid/rest-v2-flight.ron",
        "invalid/rest-v2-scale-field.ron",
    ];
    for file in files {
        let ron = std::fs::read_to_string(crate::common::root().join("certificates").join(file)).unwrap();
        let json = convert(&ron, KernelEncoding::Ron, Target::Json).expect("a twin");
        let oracle = chatter_oracle::judge(&json, Encoding::Json);
        assert_eq!(oracle, chatter_oracle::judge(&ron, Encoding::Ron), "{file}");
        let kernel = crate::common::kernel_rest_in(&json, KernelEncoding::Json);
        assert!(chatter_oracle::compare::compare(&kernel, &oracle).is_ok(), "{file}: {kernel:?} {oracle:?}");
        assert_eq!(oracle.accepted(), file.starts_with("valid/"), "{file}");
    }
}
