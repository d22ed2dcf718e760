//! Basin certificates with an embedded time-to-rest certificate and `Rest` leaves
//! (docs/certificate-format.md §15 and §16, docs/time-to-rest.md Theorem 5.1), judged by the oracle
//! alone (the kernel of this branch does not know them yet, so nothing is compared with it): files
//! built here as RON text around the corpus's square plate (n = 4, κ = 1/6, γ = 1/100, version 2)
//! and a small box of drops. The test's own arithmetic (the first contact, the state after it, the
//! membership of a velocity in a node's cone by Carathéodory's triangles, Φ) is written here from
//! the documents, apart from the oracle's model of the square (`Polygon`: contact speeds and
//! impacts) and its drops (`drop_state`, `leaf_points`).

use crate::common::root;
use chatter_oracle::arith::rational::{parse_rational, rational_text};
use chatter_oracle::arith::{Field, Num, Rat};
use chatter_oracle::basin::{DIMS, drop_state, leaf_points};
use chatter_oracle::isolate::every_failure;
use chatter_oracle::kinds::basin::time_text;
use chatter_oracle::read::Encoding;
use chatter_oracle::regular::model::{Polygon, V3};
use chatter_oracle::verdict::{Judgement, Kind, Outcome};
use num_bigint::BigInt;
use serde::Deserialize;

/// The corpus's version-2 certificate of the square plate at γ = 1/100.
const REST: &str = "certificates/valid/rest-v2-n4-kappa1_6-gamma1_100.ron";
/// The same plate at γ = 1/50 (version 1).
const REST_GAMMA_1_50: &str = "certificates/valid/rest-n4-kappa1_6-gamma1_50.ron";

/// The box's centre (ω_x, ω_y, φ_x, φ_y, h) in thousandths; half-width 1/1000. Not symmetric:
/// at (50, 50, 50, 50, 1050) contacts 0 and 3 of the square land at the same time (see
/// `the_symmetric_box_meets_a_simultaneous_impact`).
const CENTRE: [i64; DIMS] = [50, 20, 30, 10, 1050];

fn r(p: i64, q: i64) -> Rat {
    Rat::new(BigInt::from(p), BigInt::from(q))
}

fn rat(s: &str) -> Rat {
    parse_rational(s, usize::MAX).expect("a canonical rational")
}

fn corners(centre: [i64; DIMS]) -> ([Rat; DIMS], [Rat; DIMS]) {
    (std::array::from_fn(|k| r(centre[k] - 1, 1000)), std::array::from_fn(|k| r(centre[k] + 1, 1000)))
}

fn text(file: &str) -> String {
    std::fs::read_to_string(root().join(file)).unwrap().trim_end().to_string()
}

/// A node of a time-to-rest certificate, read with `ron` for the test's own arithmetic.
#[derive(Deserialize)]
struct NodeText {
    cone: Vec<(String, String, String)>,
    weight: (String, String, String),
    numerator: (String, String, String),
    next: Vec<(u64, usize)>,
}

#[derive(Deserialize)]
#[serde(rename = "TimeToRest")]
struct RestText {
    bound: String,
    nodes: Vec<NodeText>,
}

/// A node's numbers: the projected generators (u0/−v, u1/−v), b_r, a_r, the successors.
struct NodeNumbers {
    points: Vec<(Rat, Rat)>,
    weight: [Rat; 3],
    numerator: [Rat; 3],
    next: Vec<(u64, usize)>,
}

fn rest_numbers() -> (Rat, Vec<NodeNumbers>) {
    let t: RestText = ron::from_str(&text(REST)).expect("the corpus file");
    let triple = |g: &(String, String, String)| [rat(&g.0), rat(&g.1), rat(&g.2)];
    let nodes = t
        .nodes
        .iter()
        .map(|n| NodeNumbers {
            points: n
                .cone
                .iter()
                .map(|g| {
                    let [a, b, v] = triple(g);
                    (&a / &-v.clone(), &b / &-v)
                })
                .collect(),
            weight: triple(&n.weight),
            numerator: triple(&n.numerator),
            next: n.next.clone(),
        })
        .collect();
    (rat(&t.bound), nodes)
}

fn square(gamma: Rat) -> Polygon {
    let f = Field::cos(4);
    Polygon::new(4, Num::rational(&f, r(1, 6)), Num::rational(&f, gamma))
}

fn q_of(x: &Num) -> Rat {
    x.as_rational().expect("n = 4: rational").clone()
}

fn v3(x: &V3) -> [Rat; 3] {
    std::array::from_fn(|i| q_of(&x[i]))
}

fn dot(a: &[Rat; 3], b: &[Rat; 3]) -> Rat {
    &(&(&a[0] * &b[0]) + &(&a[1] * &b[1])) + &(&a[2] * &b[2])
}

/// The contact that lands next from (q, p) (the smallest h_k/(−u_k) over u_k < 0, k in `among`),
/// and the time; `None` when two contacts land together.
fn next_contact(body: &Polygon, q: &V3, p: &V3, among: &[i64]) -> Option<(i64, Rat)> {
    let mut times: Vec<(Rat, i64)> = among
        .iter()
        .filter(|&&k| q_of(&body.speed(k, p)) < Rat::from_integer(0.into()))
        .map(|&k| (q_of(&body.speed(k, q)) / -q_of(&body.speed(k, p)), k))
        .collect();
    times.sort();
    (times.len() < 2 || times[0].0 < times[1].0).then(|| (times[0].1, times[0].0.clone()))
}

/// The flight of length t from (q, p) and the impact at contact k, in the frame renamed so that k
/// is contact 0: (h_k, h_{k+1}, hc) and (u_k, u_{k+1}, v) after the impact.
fn impact(body: &Polygon, q: &V3, p: &V3, k: i64, t: &Rat) -> (V3, V3) {
    let f = &body.kappa.field;
    let moved: V3 = std::array::from_fn(|i| &q[i] + &(&Num::rational(f, t.clone()) * &p[i]));
    let after = body.impact(k, p);
    let q1 = [body.speed(k, &moved), body.speed(k + 1, &moved), moved[2].clone()];
    let p1 = [body.speed(k, &after), body.speed(k + 1, &after), after[2].clone()];
    (q1, p1)
}

fn orient(a: &(Rat, Rat), b: &(Rat, Rat), c: &(Rat, Rat)) -> Rat {
    &(&(&b.0 - &a.0) * &(&c.1 - &a.1)) - &(&(&b.1 - &a.1) * &(&c.0 - &a.0))
}

/// Whether the velocity p (v < 0) lies in the node's cone: its point on v = −1 in a triangle of
/// three generators' points (Carathéodory), by the signs of three orientations.
fn in_cone(node: &NodeNumbers, p: &[Rat; 3]) -> bool {
    let x = (&p[0] / &-p[2].clone(), &p[1] / &-p[2].clone());
    let g = &node.points;
    let zero = Rat::from_integer(0.into());
    for a in 0..g.len() {
        for b in a + 1..g.len() {
            for c in b + 1..g.len() {
                let o = orient(&g[a], &g[b], &g[c]);
                if o == zero {
                    continue;
                }
                let signs = [orient(&g[a], &g[b], &x), orient(&g[b], &g[c], &x), orient(&g[c], &g[a], &x)];
                if signs.iter().all(|s| s * &o >= zero) {
                    return true;
                }
            }
        }
    }
    false
}

/// A drop of the box: the sample point m as the state (q, p).
fn drop_at(body: &Polygon, m: &[Rat; DIMS], centre: [i64; DIMS]) -> (V3, V3) {
    let (lo, hi) = corners(centre);
    drop_state(body, m, &lo, &hi).expect("a drop of the box")
}

fn sample_points(centre: [i64; DIMS]) -> Vec<[Rat; DIMS]> {
    let (lo, hi) = corners(centre);
    leaf_points(&lo, &hi)
}

/// The basin certificate of the square at γ = `gamma` over the box around `centre`, with the
/// embedded `rest` text (RON, `None`: no field) and the leaves.
fn basin(gamma: &str, centre: [i64; DIMS], rest: Option<&str>, leaves: &str) -> String {
    let (lo, hi) = corners(centre);
    let list = |x: &[Rat; DIMS]| {
        x.iter().map(|v| format!("\"{}\"", rational_text(v))).collect::<Vec<_>>().join(", ")
    };
    let rest = rest.map(|t| format!("rest: Some({t}),\n    ")).unwrap_or_default();
    format!(
        "Certificate(\n    format: \"chatter-basin-certificate\",\n    version: 1,\n    body: RegularPolygon(n: 4, \
         kappa: \"1/6\", gamma: \"{gamma}\"),\n    drops: (lo: [{}], hi: [{}]),\n    {rest}leaves: [{leaves}],\n    \
         producer: \"oracle/tests/all/basin_rest.rs\",\n)\n",
        list(&lo),
        list(&hi)
    )
}

fn rest_leaf(first: i64, steps: &[i64], node: usize) -> String {
    let steps = steps.iter().map(i64::to_string).collect::<Vec<_>>().join(", ");
    format!("(path: \"\", verdict: Rest(first: {first}, steps: [{steps}], node: {node}))")
}

/// The contact of the square that lands first for every sample drop of the box (the same for
/// the three, no simultaneous impact), and each drop's state after that impact.
fn first_contact(centre: [i64; DIMS]) -> (i64, Vec<(V3, V3, Rat, Rat)>) {
    let body = square(r(1, 100));
    let mut first = None;
    let mut after = vec![];
    for m in sample_points(centre) {
        let (q, p) = drop_at(&body, &m, centre);
        let zero = Rat::from_integer(0.into());
        assert!((0..4).all(|k| q_of(&body.speed(k, &p)) < zero), "every contact moves down");
        let (k, t) = next_contact(&body, &q, &p, &[0, 1, 2, 3]).expect("one contact lands first");
        assert!(first.is_none_or(|f| f == k), "the same first contact at every sample drop");
        first = Some(k);
        let (q1, p1) = impact(&body, &q, &p, k, &t);
        after.push((q1, p1, t, q_of(&q[2])));
    }
    (first.expect("three drops"), after)
}

fn judge(text: &str) -> Judgement {
    chatter_oracle::judge(text, Encoding::Ron)
}

fn accepted_cc(j: &Judgement) -> bool {
    match &j.outcome {
        Outcome::Accept(report) => {
            report.basin == Some((["1".to_string(), "0".to_string(), "0".to_string()], [1, 0, 0]))
        }
        Outcome::Reject { .. } => false,
    }
}

#[test]
fn a_rest_leaf_entering_node_0_after_the_first_impact_is_accepted_with_its_time() {
    let (first, after) = first_contact(CENTRE);
    let (bound, nodes) = rest_numbers();
    let rest = text(REST);
    let file = basin("1/100", CENTRE, Some(&rest), &rest_leaf(first, &[], 0));
    let j = judge(&file);
    assert_eq!(j.kind, Kind::Basin);
    assert!(accepted_cc(&j), "{j:?}");
    // The time to rest over h of each sample drop, (t_1 + Φ_0(q, p))/h, computed here.
    let zero = Rat::from_integer(0.into());
    let mut worst: Option<Rat> = None;
    for (q1, p1, t, h) in &after {
        let (q, p) = (v3(q1), v3(p1));
        assert!(in_cone(&nodes[0], &p), "rule G4: the velocity after the first impact is in K_0");
        let speed = -dot(&nodes[0].weight, &p);
        assert!(speed > zero && q[2] > zero && p[2] < zero);
        let time = (t + &(dot(&nodes[0].numerator, &q) / &speed)) / h;
        // Theorem 5.1 (f) with G5: Φ_0 <= B h_1/|v| (|v| = 1, h_1 = h − t_1), so the time over h
        // is at most (t_1 + B h_1)/h <= max(1, B).
        assert!(time > zero && time <= &(t + &(&bound * &(h - t))) / h, "{time}");
        worst = Some(worst.map_or(time.clone(), |w| w.max(time)));
    }
    let worst = worst.unwrap();
    eprintln!("first contact {first}; largest time to rest over h {worst} (B = {bound})");
    let f = Field::rationals();
    assert_eq!(j.time_to_rest_bound, Some(time_text(&Num::rational(&f, worst.clone()))));
    assert!(worst > Rat::from_integer(0.into()) && worst <= bound.max(Rat::from_integer(1.into())));
}

#[test]
fn a_rest_leaf_after_two_impacts_enters_node_0s_successor() {
    let (first, after) = first_contact(CENTRE);
    let (_, nodes) = rest_numbers();
    let body = square(r(1, 100));
    // The second impact of the centre drop, j places on from the first (the renamed frame).
    let (q1, p1, _, _) = &after[0];
    let (j, t) = next_contact(&body, q1, p1, &[1, 2, 3]).expect("one contact lands next");
    let s = nodes[0].next.iter().find(|(step, _)| *step == j as u64).expect("a successor").1;
    let (_, p2) = impact(&body, q1, p1, j, &t);
    assert!(in_cone(&nodes[s], &v3(&p2)), "rule G3: S_j p in K_s");
    let rest = text(REST);
    let file = basin("1/100", CENTRE, Some(&rest), &rest_leaf(first, &[j], s));
    assert!(accepted_cc(&judge(&file)), "{:?}", judge(&file));
    // The same prefix ending in a node whose cone misses the velocity.
    let p2 = v3(&p2);
    let other = (0..nodes.len()).find(|&r| !in_cone(&nodes[r], &p2)).expect("a node missing S_j p");
    let file = basin("1/100", CENTRE, Some(&rest), &rest_leaf(first, &[j], other));
    assert_eq!(judge(&file).codes(), ["leaf-not-shown"]);
}

#[test]
fn rest_leaves_and_certificates_that_break_b1_b2_or_b4_are_rejected_with_their_codes() {
    let (first, after) = first_contact(CENTRE);
    let (_, nodes) = rest_numbers();
    let rest = text(REST);
    let leaf = rest_leaf(first, &[], 0);
    let code = |file: &str| judge(file).codes().to_vec();
    // B1: a node the certificate does not have; no `rest` field, or `None`.
    assert_eq!(
        code(&basin("1/100", CENTRE, Some(&rest), &rest_leaf(first, &[], nodes.len()))),
        ["basin-out-of-range"]
    );
    assert_eq!(code(&basin("1/100", CENTRE, None, &leaf)), ["basin-out-of-range"]);
    assert_eq!(
        code(&basin("1/100", CENTRE, None, &leaf).replace("leaves:", "rest: None,\n    leaves:")),
        ["basin-out-of-range"]
    );
    // B1: contacts and steps as for Cc and Icc.
    assert_eq!(code(&basin("1/100", CENTRE, Some(&rest), &rest_leaf(4, &[], 0))), ["basin-out-of-range"]);
    assert_eq!(
        code(&basin("1/100", CENTRE, Some(&rest), &rest_leaf(first, &[0], 0))),
        ["basin-out-of-range"]
    );
    assert_eq!(
        code(&basin("1/100", CENTRE, Some(&rest), &rest_leaf(first, &[4], 0))),
        ["basin-out-of-range"]
    );
    // B2: a certificate of another γ (in a basin of γ = 1/100, and the converse), another claim.
    let other = text(REST_GAMMA_1_50);
    assert_eq!(code(&basin("1/100", CENTRE, Some(&other), &leaf)), ["basin-out-of-range"]);
    assert_eq!(code(&basin("1/50", CENTRE, Some(&rest), &leaf)), ["basin-out-of-range"]);
    let weaker = rest.replace("claim: CompleteChatterFromAllDown", "claim: CcOrPccFromAllDown");
    assert_eq!(code(&basin("1/100", CENTRE, Some(&weaker), &leaf)), ["basin-out-of-range"]);
    let interval = rest.replace("gamma: \"1/100\"", "gamma: [\"1/100\", \"1/100\"]");
    assert_eq!(code(&basin("1/100", CENTRE, Some(&interval), &leaf)), ["basin-out-of-range"]);
    // B4: a node whose cone misses the velocity after the first impact (at a sample drop), and a
    // wrong first contact (not forced).
    let p1 = v3(&after[0].1);
    let missing = (0..nodes.len()).find(|&r| !in_cone(&nodes[r], &p1)).expect("a node missing it");
    assert_eq!(
        code(&basin("1/100", CENTRE, Some(&rest), &rest_leaf(first, &[], missing))),
        ["leaf-not-shown"]
    );
    for wrong in (0..4).filter(|&k| k != first) {
        assert_eq!(code(&basin("1/100", CENTRE, Some(&rest), &rest_leaf(wrong, &[], 0))), ["leaf-not-shown"]);
    }
    // The schema: exactly the fields first, steps and node.
    let leaf_cuts = leaf.replace("node: 0", "node: 0, cuts: []");
    assert_eq!(code(&basin("1/100", CENTRE, Some(&rest), &leaf_cuts)), ["unknown-field"]);
    let leaf_no_node = leaf.replace(", node: 0", "");
    assert_eq!(code(&basin("1/100", CENTRE, Some(&rest), &leaf_no_node)), ["missing-field"]);
    let cc_node = leaf.replace("Rest(", "Icc(").replace("node: 0", "cuts: [], node: 0");
    assert_eq!(code(&basin("1/100", CENTRE, Some(&rest), &cc_node)), ["unknown-field"]);
    assert_eq!(code(&basin("1/100", CENTRE, Some(&rest), "(path: \"\", verdict: Rest)")), ["syntax"]);
    let named = rest.replacen("TimeToRest(", "Certificate(", 1);
    assert_eq!(code(&basin("1/100", CENTRE, Some(&named), &leaf)), ["syntax"]);
}

#[test]
fn the_embedded_certificate_passes_its_own_rules_after_b3() {
    let (first, _) = first_contact(CENTRE);
    let rest = text(REST);
    let leaf = rest_leaf(first, &[], 0);
    let code = |file: &str| judge(file).codes().to_vec();
    let small = {
        let at = rest.find("bound: \"").unwrap() + "bound: \"".len();
        let end = at + rest[at..].find('"').unwrap();
        format!("{}1/1000{}", &rest[..at], &rest[end..])
    };
    let file = basin("1/100", CENTRE, Some(&small), &leaf);
    assert_eq!(code(&file), ["bound-too-small"]);
    assert_eq!(every_failure(&file, Encoding::Ron), ["bound-too-small"]);
    // Its header: another kind's format (a cone certificate of version 2), an unknown format,
    // an unsupported version.
    for other in ["chatter-certificate", "chatter-nothing"] {
        let format = rest.replacen("chatter-time-to-rest", other, 1);
        assert_eq!(code(&basin("1/100", CENTRE, Some(&format), &leaf)), ["wrong-format"], "{other}");
    }
    let version = rest.replacen("version: 2", "version: 4", 1);
    assert_eq!(code(&basin("1/100", CENTRE, Some(&version), &leaf)), ["unsupported-version"]);
    // B3 comes first; every failing rule is found when each is evaluated on its own.
    let halves = "(path: \"0\", verdict: Undecided)";
    let file = basin("1/100", CENTRE, Some(&small), halves);
    assert_eq!(code(&file), ["not-a-partition"]);
    assert_eq!(every_failure(&file, Encoding::Ron), ["not-a-partition", "bound-too-small"]);
    // A node whose cone misses the velocity, with the bound broken too: B4 is still evaluated.
    let (_, nodes) = rest_numbers();
    let (_, after) = first_contact(CENTRE);
    let p1 = v3(&after[0].1);
    let missing = (0..nodes.len()).find(|&r| !in_cone(&nodes[r], &p1)).unwrap();
    let file = basin("1/100", CENTRE, Some(&small), &rest_leaf(first, &[], missing));
    assert_eq!(every_failure(&file, Encoding::Ron), ["bound-too-small", "leaf-not-shown"]);
    let valid = basin("1/100", CENTRE, Some(&rest), &leaf);
    assert!(every_failure(&valid, Encoding::Ron).is_empty());
}

#[test]
fn rest_leaves_share_the_box_with_the_other_kinds() {
    // The box halved in h: the lower half a Rest leaf, the upper half undecided; then both Rest.
    let (first, _) = first_contact(CENTRE);
    let rest = text(REST);
    let two = format!(
        "{}, (path: \"9\", verdict: Undecided)",
        rest_leaf(first, &[], 0).replace("path: \"\"", "path: \"8\"")
    );
    let j = judge(&basin("1/100", CENTRE, Some(&rest), &two));
    let Outcome::Accept(report) = &j.outcome else { panic!("{j:?}") };
    assert_eq!(report.basin, Some((["1/2".to_string(), "0".to_string(), "1/2".to_string()], [1, 0, 1])));
    assert!(j.time_to_rest_bound.is_some());
    let both = format!(
        "{}, {}",
        two.split(", (path: \"9\"").next().unwrap(),
        rest_leaf(first, &[], 0).replace("path: \"\"", "path: \"9\"")
    );
    let j = judge(&basin("1/100", CENTRE, Some(&rest), &both));
    let Outcome::Accept(report) = &j.outcome else { panic!("{j:?}") };
    assert_eq!(report.basin, Some((["1".to_string(), "0".to_string(), "0".to_string()], [2, 0, 0])));
}

#[test]
fn the_symmetric_box_meets_a_simultaneous_impact() {
    // At ω_x = ω_y and φ_x = φ_y the square's contacts 0 and 3 have the same height and speed
    // (u_3 = 2v − u_1, h_3 = 2hc − h_1): they land together, and no prefix is forced.
    let centre = [50, 50, 50, 50, 1050];
    let body = square(r(1, 100));
    let mid = sample_points(centre).remove(0);
    let (q, p) = drop_at(&body, &mid, centre);
    assert!(next_contact(&body, &q, &p, &[0, 1, 2, 3]).is_none());
    let rest = text(REST);
    for first in 0..4 {
        let j = judge(&basin("1/100", centre, Some(&rest), &rest_leaf(first, &[], 0)));
        assert_eq!(j.codes(), ["leaf-not-shown"], "first {first}");
    }
}

#[test]
fn the_json_twin_of_a_basin_with_a_rest_leaf_gets_the_verdict_of_its_ron() {
    use chatter::convert::{Target, convert};
    use chatter_kernel::syntax::Encoding as KernelEncoding;
    let (first, _) = first_contact(CENTRE);
    let rest = text(REST);
    let ron = basin("1/100", CENTRE, Some(&rest), &rest_leaf(first, &[], 0));
    let rest_json = convert(&rest, KernelEncoding::Ron, Target::Json).expect("a twin");
    let (lo, hi) = corners(CENTRE);
    let texts = |x: &[Rat; DIMS]| {
        x.iter().map(|v| format!("\"{}\"", rational_text(v))).collect::<Vec<_>>().join(", ")
    };
    let json = format!(
        "{{\"format\": \"chatter-basin-certificate\", \"version\": 1, \"body\": {{\"RegularPolygon\": {{\"n\": 4, \
         \"kappa\": \"1/6\", \"gamma\": \"1/100\"}}}}, \"drops\": {{\"lo\": [{}], \"hi\": [{}]}}, \"rest\": {}, \
         \"leaves\": [{{\"path\": \"\", \"verdict\": {{\"Rest\": {{\"first\": {first}, \"steps\": [], \"node\": 0}}}}}}], \
         \"producer\": \"oracle/tests/all/basin_rest.rs\"}}\n",
        texts(&lo),
        texts(&hi),
        rest_json.trim_end()
    );
    assert!(serde_json::from_str::<serde_json::Value>(&json).is_ok(), "{json}");
    let twin = chatter_oracle::judge(&json, Encoding::Json);
    assert!(accepted_cc(&twin), "{twin:?}");
    assert_eq!(twin, judge(&ron));
}
