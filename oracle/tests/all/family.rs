//! General convex bodies (family certificates, docs/certificate-format.md §13) against the kernel,
//! through the text API: the tool's family certificates for random convex plates and their
//! mutations (a cone shrunk towards one of its generators, a generator lifted to v = 0, γ tripled,
//! the claim raised, the claim lowered); the kernel's code must be one the oracle's first failing
//! rule can give. (Moved from the tool's tests/all/oracle_convex.rs.)
//!
//! Version 2, γ an interval [γ_lo, γ_hi]: the tool's interval certificates for random plates,
//! accepted by both with the same `gamma_interval`; mutations of interval certificates (the upper
//! end widened until the kernel rejects, the ends swapped, version 1, the legacy header, an end at
//! 0 or 1, lo = hi, a non-canonical end, the RON tuple form (a syntax error, as for a box's κ),
//! random structure-aware edits) with the same code, the same field or the same end of the
//! interval from both; and, by brute force, the reduction to the ends: the cones of an accepted
//! interval certificate are accepted as single-γ (version 1) certificates at five values of γ
//! strictly inside the interval, and refused at the widened end where the kernel first refused
//! the interval; the oracle's own interior test (`convex::rules::interior`) refuses an interval
//! the cones do not hold on. Beside them, the reading's arities of contacts, inertia and tensor
//! (`syntax`) against a generator's (`wrong-arity`).

use crate::common::{differential_file, differential_ron, kernel_file, kernel_text_as_file, root};
use chatter::bodies::convex::polygon_plate;
use chatter::certify::convex::{ConvexRequest, certify_convex};
use chatter::exact::Q;
use chatter_oracle::arith::Rat;
use chatter_oracle::arith::rational::{parse_rational, ratio, rational_text};
use chatter_oracle::compare::{KernelView, differential};
use chatter_oracle::read::{Encoding, Value, parse::parse, write::to_ron};
use chatter_oracle::verdict::{Judgement, Outcome};

/// splitmix64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
}

/// The tool's family certificate (RON) for the uniform plate of a random convex polygon: n
/// corners at radius 1/2 to 3/2 and jittered angles, from an integer table of (cos, sin) · 1000
/// at multiples of 2π/48 (no floating point); `None` where the tool finds no family.
fn random_certificate(rng: &mut Rng, n: usize, gamma: Q) -> Option<String> {
    random_interval_certificate(rng, n, gamma, None)
}

/// [`random_certificate`] over [gamma, gamma_hi] when `gamma_hi` is given (version 2).
fn random_interval_certificate(rng: &mut Rng, n: usize, gamma: Q, gamma_hi: Option<Q>) -> Option<String> {
    const COS: [i64; 13] = [1000, 991, 966, 924, 866, 793, 707, 609, 500, 383, 259, 131, 0];
    let trig = |k: usize| -> (i64, i64) {
        let k = k % 48;
        let (q, r) = (k / 12, k % 12);
        let (c, s) = (COS[r], COS[12 - r]);
        match q {
            0 => (c, s),
            1 => (-s, c),
            2 => (-c, -s),
            _ => (s, -c),
        }
    };
    let step = 48 / n;
    let pts: Vec<[Q; 2]> = (0..n)
        .map(|k| {
            let (c, s) = trig(k * step + (rng.next() % 2) as usize);
            let r = 500 + (rng.next() % 1000) as i64;
            [Q::new(c * r, 1_000_000), Q::new(s * r, 1_000_000)]
        })
        .collect();
    let body = polygon_plate(&pts, gamma).ok()?;
    let mut request = ConvexRequest::new(body);
    request.gamma_hi = gamma_hi;
    let cert = certify_convex(&request).result.ok()?;
    Some(chatter::write::write_convex(&cert))
}

fn strings_of(v: &Value) -> Vec<String> {
    match v {
        Value::Tuple(xs) => {
            xs.iter().map(|x| if let Value::Str(s) = x { s.clone() } else { panic!() }).collect()
        }
        _ => panic!("a tuple"),
    }
}

fn field<'a>(v: &'a mut Value, name: &str) -> &'a mut Value {
    let Value::Named { fields: Some(fs), .. } = v else { panic!("a struct") };
    &mut fs.iter_mut().find(|(k, _)| k == name).expect("the field").1
}

/// The mutations of a version-4 text that the test tries.
fn mutations(text: &str) -> Vec<(String, String)> {
    let base = parse(text, Encoding::Ron).expect("the tool's text parses");
    let mut out = vec![];
    let Value::List(cones) = field(&mut base.clone(), "cones").clone() else { panic!("cones") };
    for i in 0..cones.len() {
        let mut m = base.clone();
        let Value::List(cone) = &mut field(&mut m, "cones").clone() else { panic!() };
        let Value::List(gens) = &mut cone[i] else { panic!() };
        let g0: Vec<_> =
            strings_of(&gens[0]).iter().map(|s| parse_rational(s, usize::MAX).unwrap()).collect();
        for g in gens.iter_mut().skip(1) {
            let x: Vec<_> = strings_of(g).iter().map(|s| parse_rational(s, usize::MAX).unwrap()).collect();
            let two = parse_rational("2", 9).unwrap();
            *g = Value::Tuple(
                x.iter().zip(&g0).map(|(a, b)| Value::Str(rational_text(&((a + b) / &two)))).collect(),
            );
        }
        *field(&mut m, "cones") = Value::List(cone.clone());
        out.push((format!("K_{i} shrunk"), to_ron(&m)));
    }
    let mut m = base.clone();
    if let Value::List(cone) = field(&mut m, "cones")
        && let Value::List(gens) = &mut cone[0]
        && let Value::Tuple(x) = &mut gens[0]
    {
        x[2] = Value::Str("0".into());
    }
    out.push(("a generator at v = 0".into(), to_ron(&m)));
    let mut m = base.clone();
    let gamma = field(field(&mut m, "body"), "gamma");
    if let Value::Str(g) = gamma {
        let tripled = parse_rational(g, usize::MAX).unwrap() * parse_rational("3", 9).unwrap();
        *gamma = Value::Str(rational_text(&tripled));
    }
    out.push(("gamma tripled".into(), to_ron(&m)));
    let mut m = base.clone();
    *field(&mut m, "claim") = Value::Named { name: "CompleteChatterFromAllDown".into(), fields: None };
    out.push(("claim raised".into(), to_ron(&m)));
    let mut m = base;
    *field(&mut m, "claim") = Value::Named { name: "EffectivelyInvariant".into(), fields: None };
    out.push(("claim lowered".into(), to_ron(&m)));
    out
}

#[test]
fn kernel_and_oracle_agree_on_random_bodies_and_mutations() {
    let mut rng = Rng(2026);
    let (mut accepted, mut rejected, mut certified) = (0, 0, 0);
    for trial in 0..10 {
        let n = 3 + trial % 4;
        let gamma = Q::new(1 + (rng.next() % 40) as i64, 1000);
        let Some(text) = random_certificate(&mut rng, n, gamma) else { continue };
        let (k, _, cmp) = differential_ron(&text);
        assert!(k.accepted && cmp.is_ok(), "trial {trial}: {cmp:?}\n{text}");
        certified += 1;
        for (what, m) in mutations(&text) {
            let (k, _, cmp) = differential_ron(&m);
            assert!(cmp.is_ok(), "trial {trial}, {what}: {cmp:?}\n{m}");
            assert!(k.accepted || what != "claim lowered", "trial {trial}: a weaker claim is refused\n{m}");
            if k.accepted { accepted += 1 } else { rejected += 1 }
        }
    }
    assert!(
        certified >= 5 && rejected >= 15 && accepted >= 1,
        "{certified} certified, {accepted} accepted, {rejected} rejected"
    );
}

// ---------------------------------------------------------------------------------------------
// Version 2: γ an interval.

/// The corpus's interval certificate of the 2 × 1 plate over [1/100, 1/50].
const RECTANGLE: &str = "certificates/valid/convex-rectangle-2x1-gamma1_100-1_50.ron";
/// The corpus's lander (with its inertia tensor, rule K0) over [1/20, 117/2000].
const LANDER: &str = "certificates/valid/convex-lander-gamma1_20-117_2000-inertia-tensor.ron";

fn read(file: &str) -> String {
    std::fs::read_to_string(root().join(file)).expect("a corpus file")
}

fn q(s: &str) -> Rat {
    parse_rational(s, usize::MAX).expect("a canonical number")
}

/// The text with `body.gamma` replaced by `gamma`.
fn with_gamma(text: &str, gamma: Value) -> String {
    let mut v = parse(text, Encoding::Ron).expect("parses");
    *field(field(&mut v, "body"), "gamma") = gamma;
    to_ron(&v)
}

/// An interval `[lo, hi]` as RON.
fn interval(lo: &Rat, hi: &Rat) -> Value {
    Value::List(vec![Value::Str(rational_text(lo)), Value::Str(rational_text(hi))])
}

/// The text with `version` set.
fn with_version(text: &str, version: u64) -> String {
    let mut v = parse(text, Encoding::Ron).expect("parses");
    *field(&mut v, "version") = Value::Int(version.to_string());
    to_ron(&v)
}

/// The ends [lo, hi] of a file's interval of γ.
fn ends_of(text: &str) -> [Rat; 2] {
    let mut v = parse(text, Encoding::Ron).expect("parses");
    let Value::List(ends) = field(field(&mut v, "body"), "gamma").clone() else { panic!("an interval") };
    let end = |i: usize| match &ends[i] {
        Value::Str(s) => q(s),
        other => panic!("a number, found {other:?}"),
    };
    [end(0), end(1)]
}

/// Both verdicts, which must agree (the comparison includes the end of the interval a failure of
/// K2-K4 names and the accepted `gamma_interval`); for a rejection at a field, the oracle names
/// that field or one enclosing it (`body.contacts[0]` for the kernel's `body.contacts[0].x`).
fn agreeing(what: &str, text: &str) -> (KernelView, Judgement) {
    let (k, o, cmp) = differential_ron(text);
    assert!(cmp.is_ok(), "{what}: {cmp:?}\nkernel {k:?}\noracle {o:?}\n{text}");
    if let (Some(locus), Outcome::Reject { why, .. }) = (&k.locus, &o.outcome)
        && locus["kind"] == "field"
        && let Some((path, _)) = why.strip_prefix("field `").and_then(|w| w.split_once('`'))
    {
        let kernel = locus["path"].as_str().expect("a path");
        assert!(kernel.starts_with(path), "{what}: kernel at {kernel}, oracle {why}");
    }
    (k, o)
}

/// Up to `count` of the tool's interval certificates of random plates (n = 3 to 6, γ_lo in
/// [1/1000, 30/1000], γ_hi 1/1000 to 20/1000 above), from at most 12 tries.
fn random_interval_certificates(seed: u64, count: usize) -> Vec<(String, String)> {
    let mut rng = Rng(seed);
    let mut out = vec![];
    for trial in 0..12 {
        let n = 3 + trial % 4;
        let lo = 1 + (rng.next() % 30) as i64;
        let hi = lo + 1 + (rng.next() % 20) as i64;
        if let Some(t) = random_interval_certificate(&mut rng, n, Q::new(lo, 1000), Some(Q::new(hi, 1000))) {
            out.push((format!("random plate {trial} (n = {n}, [{lo}/1000, {hi}/1000])"), t));
        }
        if out.len() == count {
            break;
        }
    }
    out
}

/// A rejection by both, with `code`; at the field `path` (the kernel's locus and the oracle's
/// message) when given.
fn refused(what: &str, text: &str, code: &str, path: Option<&str>) -> (KernelView, Judgement) {
    let (k, o) = agreeing(what, text);
    assert_eq!(k.code.as_deref(), Some(code), "{what}: kernel {k:?}");
    assert!(o.codes().contains(&code), "{what}: oracle {o:?}");
    if let Some(path) = path {
        assert_eq!(k.locus.as_ref().unwrap()["path"], path, "{what}: kernel {k:?}");
        let Outcome::Reject { why, .. } = &o.outcome else { unreachable!() };
        assert!(why.starts_with(&format!("field `{path}`: ")), "{what}: oracle {why}");
    }
    (k, o)
}

/// An acceptance by both, with the `gamma_interval` of the tool's report of the kernel's verdict
/// (`chatter verify --json`, through a temporary file) and the oracle's, which must be the same.
fn accepted_by_both(what: &str, text: &str) -> Option<[String; 2]> {
    let (k, o) = agreeing(what, text);
    assert!(k.accepted && o.accepted(), "{what}: kernel {k:?}\noracle {o:?}\n{text}");
    let reported = kernel_text_as_file(text);
    let (_, cmp) = differential(text, Encoding::Ron, &reported);
    assert!(cmp.is_ok(), "{what}: {cmp:?}");
    assert_eq!(reported.gamma_interval.as_ref(), Some(&o.gamma_interval), "{what}");
    o.gamma_interval
}

#[test]
fn interval_certificates_of_random_plates_are_accepted_by_kernel_and_oracle() {
    let mut rng = Rng(4711);
    let mut certified = 0;
    for trial in 0..7 {
        let n = 3 + trial % 4;
        let lo = 1 + (rng.next() % 30) as i64;
        let hi = lo + 1 + (rng.next() % 20) as i64;
        let (glo, ghi) = (Q::new(lo, 1000), Q::new(hi, 1000));
        let Some(text) = random_interval_certificate(&mut rng, n, glo, Some(ghi)) else { continue };
        assert!(text.contains("version: 2,"), "trial {trial}: {text}");
        let want = [rational_text(&ratio(lo, 1000)), rational_text(&ratio(hi, 1000))];
        assert_eq!(accepted_by_both(&format!("trial {trial}"), &text), Some(want), "trial {trial}");
        certified += 1;
        if certified > 2 {
            continue;
        }
        // The same text in version 2 with one γ, and the interval's one-point form [lo, lo].
        let [a, _] = ends_of(&text);
        let point = with_gamma(&text, Value::Str(rational_text(&a)));
        assert_eq!(accepted_by_both(&format!("trial {trial}, gamma = lo in version 2"), &point), None);
        let degenerate = with_gamma(&text, interval(&a, &a));
        let at = Some([rational_text(&a), rational_text(&a)]);
        assert_eq!(accepted_by_both(&format!("trial {trial}, [lo, lo]"), &degenerate), at);
    }
    assert!(certified >= 3, "{certified} interval certificates");
    for file in [RECTANGLE, LANDER, "certificates/valid/convex-rectangle-2x1-gamma1_100-1_50.json"] {
        let (k, o, cmp) = differential_file(&root().join(file));
        assert!(k.accepted && o.accepted() && cmp.is_ok(), "{file}: {cmp:?}");
        let reported = kernel_file(&root().join(file)).gamma_interval;
        assert!(o.gamma_interval.is_some() && reported == Some(o.gamma_interval), "{file}");
    }
}

/// The upper end of `text`'s interval widened step by step (hi + (hi - lo), doubling the step)
/// until the kernel rejects, each step compared; the first refused upper end and its code.
fn widened_until_refused(what: &str, text: &str) -> (Rat, String) {
    let [lo, hi] = ends_of(text);
    let one = q("1");
    let mut step = &hi - &lo;
    loop {
        let wider = std::cmp::min(&hi + &step, one.clone());
        let (k, o) =
            agreeing(&format!("{what}: upper end {wider}"), &with_gamma(text, interval(&lo, &wider)));
        if !k.accepted {
            let code = k.code.clone().expect("a code");
            // A failure past the lower end is at the upper one: its field, or the end in the locus.
            let locus = k.locus.expect("a locus");
            let at_upper =
                locus["path"] == "body.gamma[1]" || locus["gamma"] == rational_text(&wider).as_str();
            assert!(at_upper, "{what}: {wider} refused at {locus} ({})", k.message);
            let Outcome::Reject { why, .. } = &o.outcome else { unreachable!() };
            let prefix = format!("at the end gamma = {} of the interval: ", rational_text(&wider));
            assert!(why.starts_with(&prefix) || why.starts_with("field `body.gamma[1]`"), "{what}: {why}");
            return (wider, code);
        }
        assert!(wider < one, "{what}: the whole of [lo, 1] accepted");
        step = &step + &step;
    }
}

#[test]
fn mutated_interval_certificates_get_the_same_code_from_kernel_and_oracle() {
    let mut texts = vec![("rectangle".to_string(), read(RECTANGLE)), ("lander".to_string(), read(LANDER))];
    texts.extend(random_interval_certificates(1234, 2));
    assert!(texts.len() >= 4, "{} interval certificates", texts.len());
    let mut widened_codes = vec![];
    for (what, text) in &texts {
        let what = what.as_str();
        let [lo, hi] = ends_of(text);
        // The upper end widened until the kernel rejects.
        widened_codes.push(widened_until_refused(what, text).1);
        // The ends swapped; the version; the legacy header (an alias of version 1).
        refused(what, &with_gamma(text, interval(&hi, &lo)), "parameter-out-of-range", Some("body.gamma"));
        refused(what, &with_version(text, 1), "unsupported-version", Some("version"));
        let legacy = with_version(text, 4).replacen("chatter-family-certificate", "chatter-certificate", 1);
        refused(what, &legacy, "unsupported-version", Some("version"));
        refused(what, &with_version(text, 3), "unsupported-version", None);
        // An end at 0 or at 1 with a claim about drops; above 1; a non-canonical end.
        refused(
            what,
            &with_gamma(text, interval(&q("0"), &hi)),
            "parameter-out-of-range",
            Some("body.gamma[0]"),
        );
        let at_hi = Some("body.gamma[1]");
        refused(what, &with_gamma(text, interval(&lo, &q("1"))), "parameter-out-of-range", at_hi);
        refused(what, &with_gamma(text, interval(&lo, &q("3/2"))), "parameter-out-of-range", at_hi);
        let spoilt = Value::List(vec![Value::Str(rational_text(&lo)), Value::Str("2/100".into())]);
        refused(what, &with_gamma(text, spoilt), "bad-number", Some("body.gamma[1]"));
        let spoilt = Value::List(vec![Value::Str("+1/100".into()), Value::Str(rational_text(&hi))]);
        refused(what, &with_gamma(text, spoilt), "bad-number", Some("body.gamma[0]"));
        // A negative lower end; not an interval of two numbers.
        refused(
            what,
            &with_gamma(text, interval(&q("-1/100"), &hi)),
            "parameter-out-of-range",
            Some("body.gamma[0]"),
        );
        for wrong in [vec![Value::Str(rational_text(&lo)); 3], vec![Value::Str(rational_text(&lo))], vec![]] {
            refused(what, &with_gamma(text, Value::List(wrong)), "syntax", None);
        }
        let integer = Value::List(vec![Value::Str(rational_text(&lo)), Value::Int("1".into())]);
        refused(what, &with_gamma(text, integer), "syntax", None);
        // An interval is a list: the RON tuple form is a syntax error (docs/certificate-format.md
        // §2, §9).
        let tuple = Value::Tuple(vec![Value::Str(rational_text(&lo)), Value::Str(rational_text(&hi))]);
        refused(what, &with_gamma(text, tuple), "syntax", None);
        // Down to EffectivelyInvariant: γ = 0 and 1 are allowed ends.
        let mut v = parse(text, Encoding::Ron).unwrap();
        *field(&mut v, "claim") = Value::Named { name: "EffectivelyInvariant".into(), fields: None };
        let weaker = to_ron(&v);
        accepted_by_both(&format!("{what}, EffectivelyInvariant"), &weaker);
        agreeing(
            &format!("{what}, EffectivelyInvariant from 0"),
            &with_gamma(&weaker, interval(&q("0"), &hi)),
        );
        agreeing(
            &format!("{what}, EffectivelyInvariant up to 1"),
            &with_gamma(&weaker, interval(&lo, &q("1"))),
        );
    }
    eprintln!("the widened upper ends were refused with {widened_codes:?}");
    // The reading's arities (not interval rules, found beside them): a contact, the inertia or the
    // tensor of the wrong length is `syntax` for both, before any rule; a generator's is
    // `wrong-arity`.
    let lander = read(LANDER);
    for (what, from, to, code) in [
        ("a contact with three numbers", r#"("164/75", "0"),"#, r#"("164/75", "0", "1"),"#, "syntax"),
        (
            "the inertia with two numbers",
            r#"inertia: ("1506401745601/1655594062500", "0","#,
            "inertia: (\"0\",",
            "syntax",
        ),
        (
            "the tensor with five numbers",
            r#"Some(("853103/937500", "0", "#,
            r#"Some(("853103/937500", "#,
            "syntax",
        ),
        (
            "a generator with two numbers",
            r#""-46340550799679341/87925745849991168", "-1")"#,
            r#""-1")"#,
            "wrong-arity",
        ),
    ] {
        assert!(lander.contains(from), "{what}");
        refused(what, &lander.replacen(from, to, 1), code, None);
    }
    // A box certificate's interval of κ written as a tuple: a syntax error too.
    let boxed = read("certificates/valid/n4-kappa1_10_3_25-gamma1_100_1_50-box.ron");
    assert!(boxed.contains(r#"kappa: ["1/10", "3/25"]"#), "{boxed}");
    let tuple = boxed.replacen(r#"kappa: ["1/10", "3/25"]"#, r#"kappa: ("1/10", "3/25")"#, 1);
    let (k, o, cmp) = differential_ron(&tuple);
    assert!(cmp.is_ok() && k.code.as_deref() == Some("syntax") && o.codes() == ["syntax"], "{cmp:?}");
    // The corpus's rejections at an end of an interval: the same end from both.
    for (file, end) in
        [("convex-interval-upper-end-outside.ron", "1/30"), ("convex-interval-pcc-at-lower-end.ron", "1/200")]
    {
        let (k, o, cmp) = differential_file(&root().join("certificates/invalid").join(file));
        assert!(cmp.is_ok(), "{file}: {cmp:?}");
        assert_eq!(k.locus.unwrap()["gamma"], end, "{file}");
        let Outcome::Reject { why, .. } = &o.outcome else { panic!("{file}: accepted") };
        assert_eq!(chatter_oracle::convex::rules::end_named(why), Some(end), "{file}: {why}");
    }
}

/// Random structure-aware edits (`chatter_oracle::mutate`) of the corpus's interval certificate
/// of the rectangle, each compared.
#[test]
fn random_edits_of_an_interval_certificate_get_the_same_verdict() {
    use chatter_oracle::mutate::{decode, mutated};
    let base = parse(&read(RECTANGLE), Encoding::Ron).unwrap();
    let mut rng = Rng(47);
    let (mut accepted, mut rejected) = (0, 0);
    for case in 0..60 {
        let len = 1 + rng.next() % 9;
        let bytes: Vec<u8> = (0..len).map(|_| rng.next() as u8).collect();
        let plan = decode(&bytes);
        let text = mutated(&base, &plan.edits);
        let (k, _) = agreeing(&format!("case {case} {plan:?}"), &text);
        if k.accepted { accepted += 1 } else { rejected += 1 }
    }
    assert!(accepted >= 3 && rejected >= 20, "{accepted} accepted, {rejected} rejected");
}

#[test]
fn an_interval_certificates_cones_hold_at_gammas_strictly_inside_the_interval() {
    let mut texts = vec![("rectangle".to_string(), read(RECTANGLE)), ("lander".to_string(), read(LANDER))];
    texts.extend(random_interval_certificates(99, 2));
    assert!(texts.len() >= 4, "{} interval certificates", texts.len());
    for (what, text) in &texts {
        accepted_by_both(what, text);
        let [lo, hi] = ends_of(text);
        // Five evenly spaced values strictly inside: lo + k (hi - lo)/6, k = 1..5, each as a
        // version-1 certificate with the same cones.
        for k in 1..=5 {
            let gamma = &lo + (&hi - &lo) * ratio(k, 6);
            let single = with_version(&with_gamma(text, Value::Str(rational_text(&gamma))), 1);
            let (kernel, oracle) = agreeing(&format!("{what} at gamma = {gamma}"), &single);
            assert!(oracle.accepted(), "{what}: the oracle refuses gamma = {gamma} inside: {oracle:?}");
            assert!(kernel.accepted, "{what}: the kernel refuses gamma = {gamma} inside: {kernel:?}");
        }
        // A control: where widening the upper end first failed, the same cones at that γ alone are
        // refused by both (at a content rule, or γ = 1 for a claim about drops).
        let (wider, _) = widened_until_refused(what, text);
        let single = with_version(&with_gamma(text, Value::Str(rational_text(&wider))), 1);
        let (kernel, oracle) = agreeing(&format!("{what} at gamma = {wider}"), &single);
        assert!(!kernel.accepted && !oracle.accepted(), "{what}: gamma = {wider} alone is accepted");
    }
}

/// The oracle's own brute-force test of the reduction to the ends (`convex::rules::interior`, K2-K4
/// at two interior values of γ) is not vacuous: called on an interval the rectangle's cones do not
/// hold on, it fails with `corner-argument-violated`; on the certificate's interval it passes.
#[test]
fn the_oracles_interior_test_refuses_an_interval_the_cones_do_not_hold_on() {
    use chatter_oracle::arith::{Field, Num};
    use chatter_oracle::claim::Claim;
    use chatter_oracle::convex::model::Body;
    use chatter_oracle::convex::rules::{Family, interior, polygons};
    let f = Field::rationals();
    let num = |v: &Value| match v {
        Value::Str(s) => Num::rational(&f, q(s)),
        other => panic!("a number, found {other:?}"),
    };
    let mut v = parse(&read(RECTANGLE), Encoding::Ron).unwrap();
    let Value::List(contacts) = field(field(&mut v, "body"), "contacts").clone() else { panic!() };
    let contacts = contacts
        .iter()
        .map(|c| match c {
            Value::Tuple(xy) => (num(&xy[0]), num(&xy[1])),
            _ => panic!("a contact"),
        })
        .collect();
    let Value::Tuple(j) = field(field(&mut v, "body"), "inertia").clone() else { panic!() };
    let Value::List(cones) = field(&mut v, "cones").clone() else { panic!() };
    let cones: Vec<Vec<[Num; 3]>> = cones
        .iter()
        .map(|c| match c {
            Value::List(gens) => gens
                .iter()
                .map(|g| match g {
                    Value::Tuple(x) => [num(&x[0]), num(&x[1]), num(&x[2])],
                    _ => panic!("a generator"),
                })
                .collect(),
            _ => panic!("a cone"),
        })
        .collect();
    let gamma = |s: &str| Num::rational(&f, q(s));
    let body = Body::new(contacts, [num(&j[0]), num(&j[1]), num(&j[2])], gamma("1/100")).expect("the body");
    let family = Family::new(&body, &cones, polygons(&cones).expect("K1"));
    let claim = Claim::CompleteChatterFromAllDown;
    assert!(interior(&body, claim, &family, &gamma("1/100"), &gamma("1/50")).is_ok());
    // [1/100, 1/10]: the samples 4/100 and 17/175 lie beyond 3/100, where K2 already fails.
    let wide = interior(&body, claim, &family, &gamma("1/100"), &gamma("1/10")).expect_err("refused");
    assert_eq!(wide.codes, ["corner-argument-violated"], "{}", wide.why);
    assert!(wide.why.starts_with("the ends pass but gamma = 1/25 fails (image-"), "{}", wide.why);
}
