//! Time-to-rest certificates of a general convex body (docs/certificate-format.md §17, format
//! `chatter-family-time-to-rest`): the corpus's files (`rest-family-*`) judged by the oracle with
//! the kernel's verdict, code, n, nodes and B; their JSON twins; one edit per rule, each with the
//! code the kernel gives; targeted random edits of a weight, a numerator, the bound, a generator
//! or a successor (`Edit::Field`), and random structure-aware edits (`mutate::decode`), judged
//! alike by both.

use crate::common::{differential_file, differential_ron, root};
use chatter_oracle::arith::rational::{ratio, rational_text};
use chatter_oracle::compare::Agreement;
use chatter_oracle::mutate::{Edit, FIELDS, decode, mutated};
use chatter_oracle::read::{Encoding, parse::parse};
use chatter_oracle::verdict::Kind;
use std::collections::BTreeMap;

/// The valid general bodies' time-to-rest certificates of the corpus (the last over an interval
/// of γ, version 2).
const VALID: [&str; 3] = [
    "rest-family-lander-gamma1_50.ron",
    "rest-family-rectangle2x1-gamma1_100.ron",
    "rest-family-rectangle2x1-gamma1_100-1_50.ron",
];

/// The valid file over an interval of γ.
const INTERVAL: &str = VALID[2];

fn text(dir: &str, name: &str) -> String {
    std::fs::read_to_string(root().join("certificates").join(dir).join(name)).expect("a corpus file")
}

/// The corpus's `rest-family-*` files, valid and invalid.
fn corpus_files() -> Vec<std::path::PathBuf> {
    let mut out = vec![];
    for dir in ["valid", "invalid"] {
        for e in std::fs::read_dir(root().join("certificates").join(dir)).expect("the corpus") {
            let path = e.expect("entry").path();
            if path.file_name().is_some_and(|n| n.to_string_lossy().starts_with("rest-family-")) {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// Every `rest-family-*` file of the corpus: read as the new kind, the kernel's verdict (both
/// accept with the same claim, n, nodes and B; both reject with the same code), and the valid ones
/// accepted.
#[test]
fn corpus_rest_family_files_get_the_kernels_verdict() {
    let mut failures = vec![];
    let mut accepted = 0;
    for path in corpus_files() {
        let (kernel, oracle, cmp) = differential_file(&path);
        let name = path.display();
        if let Err(f) = cmp {
            failures.push(format!("{name}: {f}"));
        }
        if oracle.kind != Kind::RestFamily && oracle.accepted() {
            failures.push(format!("{name}: read as {:?}", oracle.kind));
        }
        if path.parent().is_some_and(|d| d.ends_with("valid")) {
            assert!(oracle.accepted() && kernel.accepted, "{name}: {oracle:?} {kernel:?}");
            assert!(oracle.time_to_rest_bound.is_some(), "{name}");
            accepted += 1;
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(accepted >= VALID.len(), "{accepted} valid rest-family files");
}

/// The JSON twin (the tool's `convert`) of each valid file gets its RON's verdict from the oracle,
/// and the kernel's on the twin agrees.
#[test]
fn json_twins_of_rest_family_certificates_get_the_verdict_of_their_ron() {
    use chatter::convert::{Target, convert};
    use chatter_kernel::syntax::Encoding as KernelEncoding;
    for name in VALID {
        let ron = text("valid", name);
        let json = convert(&ron, KernelEncoding::Ron, Target::Json).expect("a twin");
        let oracle = chatter_oracle::judge(&json, Encoding::Json);
        assert_eq!(oracle, chatter_oracle::judge(&ron, Encoding::Ron), "{name}");
        assert!(oracle.accepted(), "{name}: {oracle:?}");
        let kernel = crate::common::kernel_rest_family_in(&json, KernelEncoding::Json);
        let cmp = chatter_oracle::compare::compare(&kernel, &oracle);
        assert_eq!(cmp, Ok(Agreement::BothAccept), "{name}: {kernel:?} {oracle:?}");
    }
}

/// The lander's file with `from` replaced by `to` (the first occurrence, which must exist).
fn lander_with(from: &str, to: &str) -> String {
    let base = text("valid", VALID[0]);
    assert!(base.contains(from), "{from:?} is not in the lander's file");
    base.replacen(from, to, 1)
}

/// One edit per rule of §17 (and of the header and schema), each rejected by the oracle with the
/// expected code and by the kernel with the same one.
#[test]
fn each_rule_breaks_alike() {
    // Node 3 (contact 1, no entry) given contact 3 = n.
    let node3 = "contact: 1,\n            cone: [(\"7027177/16777216\"";
    let cases: Vec<(&str, String)> = vec![
        ("unsupported-version", lander_with("version: 1,", "version: 3,")),
        ("syntax", lander_with("FamilyTimeToRest(", "TimeToRest(")),
        ("unknown-field", lander_with("entries:", "extra: 1,\n    entries:")),
        ("missing-field", lander_with("    entries: [0, 1, 2],\n", "")),
        ("unknown-variant", lander_with("CompleteChatterFromAllDown", "EffectivelyInvariant")),
        ("unsupported-version", lander_with("gamma: \"1/50\"", "gamma: [\"1/100\", \"1/50\"]")),
        ("parameter-out-of-range", lander_with("gamma: \"1/50\"", "gamma: \"1\"")),
        ("bad-number", lander_with("gamma: \"1/50\"", "gamma: \"2/100\"")),
        ("unsupported-body", lander_with("(\"164/75\", \"0\")", "(\"-164/75\", \"0\")")),
        ("inertia-not-derived", lander_with("\"1765967/1406250\"", "\"1765969/1406250\"")),
        ("wrong-arity", lander_with("entries: [0, 1, 2]", "entries: [0, 1]")),
        ("missing-successor", lander_with("entries: [0, 1, 2]", "entries: [1, 1, 2]")),
        ("missing-successor", lander_with("entries: [0, 1, 2]", "entries: [0, 1, 99]")),
        ("parameter-out-of-range", lander_with(node3, &node3.replace("contact: 1", "contact: 3"))),
        (
            "generator-not-below",
            lander_with("\"-7689285/16777216\", \"-1\")", "\"-7689285/16777216\", \"1\")"),
        ),
        ("wrong-arity", lander_with("\"-7689285/16777216\", \"-1\")", "\"-7689285/16777216\")")),
        (
            "virtual-time-not-positive",
            lander_with("weight: (\"-10743095/16777216\", \"-1\", \"1\")", "weight: (\"0\", \"0\", \"-1\")"),
        ),
        ("bound-too-small", lander_with("bound: \"12935641583736815/549755813888\"", "bound: \"1\"")),
        ("missing-successor", lander_with("next: [(1, 3), (2, 4)]", "next: [(2, 4)]")),
        // B is read before G3 (the kernel's order since version 2).
        (
            "bad-number",
            lander_with("next: [(1, 3), (2, 4)]", "next: [(2, 4)]").replacen(
                "bound: \"12935641583736815/549755813888\"",
                "bound: \"2/2\"",
                1,
            ),
        ),
        ("missing-successor", lander_with("next: [(1, 3), (2, 4)]", "next: [(1, 4), (2, 4)]")),
    ];
    let mut failures = vec![];
    for (i, (code, text)) in cases.iter().enumerate() {
        let (kernel, oracle, cmp) = differential_ron(text);
        if cmp.is_err() || kernel.code.as_deref() != Some(*code) || !oracle.codes().contains(code) {
            failures.push(format!("case {i} ({code}): kernel {kernel:?}, oracle {oracle:?}, {cmp:?}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// One number of a valid file changed flips the verdict of both: the bound halved
/// (`bound-too-small`), a numerator's height coordinate negated (G2), a weight scaled down (F).
#[test]
fn one_number_changed_flips_the_verdict() {
    let lander = text("valid", VALID[0]);
    let (kernel, oracle, cmp) = differential_ron(&lander);
    assert!(kernel.accepted && oracle.accepted() && cmp.is_ok(), "{kernel:?} {oracle:?}");
    let b = "12935641583736815/549755813888";
    let halved = lander.replacen(b, "12935641583736815/1099511627776", 1);
    let flipped = lander.replacen("\"26827743191587/549755813888\"", "\"-26827743191587/549755813888\"", 1);
    for (code, t) in [("bound-too-small", halved), ("virtual-time-not-positive", flipped)] {
        let (kernel, oracle, cmp) = differential_ron(&t);
        assert_eq!(kernel.code.as_deref(), Some(code), "{kernel:?}");
        assert!(oracle.codes().contains(&code) && cmp.is_ok(), "{oracle:?} {cmp:?}");
    }
}

/// splitmix64, for deterministic inputs.
fn next(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// Single edits of a weight, the bound, a generator, a successor or a numerator of the valid
/// files (`Edit::Field`; `scale` is not a field of this kind), judged alike by the kernel and
/// the oracle; both verdicts occur.
#[test]
fn rest_family_parts_mutated_alike() {
    let bases: Vec<_> =
        VALID.iter().map(|b| parse(&text("valid", b), Encoding::Ron).expect("a base file parses")).collect();
    let names: Vec<u8> = (0..FIELDS.len() as u8).filter(|&i| FIELDS[usize::from(i)] != "scale").collect();
    let (mut tally, mut codes): (BTreeMap<String, usize>, BTreeMap<String, usize>) = Default::default();
    let mut failures = vec![];
    let mut state = 31;
    for case in 0..60 {
        let r = next(&mut state);
        let edit = Edit::Field { name: names[case % names.len()], at: (r >> 8) as u8, how: (r >> 16) as u8 };
        // The lander (small) three times in four.
        let base = if r % 4 == 3 { &bases[1] } else { &bases[0] };
        let text = mutated(base, &[edit]);
        let (kernel, _, cmp) = differential_ron(&text);
        *codes.entry(kernel.code.clone().unwrap_or_else(|| "accepted".into())).or_default() += 1;
        match cmp {
            Ok(a) => *tally.entry(format!("{a:?}")).or_default() += 1,
            Err(f) => failures.push(format!("case {case} {edit:?}: {f}\n{text}")),
        }
    }
    eprintln!("rest-family mutations: {tally:?}\nkernel verdicts: {codes:?}");
    assert!(failures.is_empty(), "{} disagreements:\n{}", failures.len(), failures.join("\n\n"));
    assert!(tally.get("BothAccept").copied().unwrap_or(0) >= 2, "{tally:?}");
    assert!(tally.get("BothReject").copied().unwrap_or(0) >= 10, "{tally:?}");
}

/// Random structure-aware plans of up to three edits (the fuzz target's decoder: numbers nudged,
/// scaled, negated, spoiled; elements dropped, duplicated, swapped; identifiers, integers and
/// fields changed; γ widened) of a valid file, judged alike by the kernel and the oracle (a
/// rejection at an end of an interval of γ at the same end): `cases` plans from `seed`, of which
/// at least `rejected` must be rejected by both.
fn random_edits_judged_alike(name: &str, seed: u64, cases: usize, rejected: usize) {
    let base = parse(&text("valid", name), Encoding::Ron).expect("parses");
    let (mut tally, mut codes): (BTreeMap<String, usize>, BTreeMap<String, usize>) = Default::default();
    let mut failures = vec![];
    let mut state = seed;
    for case in 0..cases {
        let len = 1 + 4 * (1 + next(&mut state) % 3) as usize;
        let bytes: Vec<u8> = (0..len).map(|_| next(&mut state) as u8).collect();
        let plan = decode(&bytes);
        let text = mutated(&base, &plan.edits);
        let (kernel, _, cmp) = differential_ron(&text);
        *codes.entry(kernel.code.clone().unwrap_or_else(|| "accepted".into())).or_default() += 1;
        match cmp {
            Ok(a) => *tally.entry(format!("{a:?}")).or_default() += 1,
            Err(f) => failures.push(format!("case {case} {plan:?}: {f}\n{text}")),
        }
    }
    eprintln!("{name} edits: {tally:?}\nkernel verdicts: {codes:?}");
    assert!(failures.is_empty(), "{} disagreements:\n{}", failures.len(), failures.join("\n\n"));
    assert!(tally.get("BothReject").copied().unwrap_or(0) >= rejected, "{tally:?}");
}

/// 80 random edit plans of the lander's file, judged alike.
#[test]
fn random_edits_of_the_lander_judged_alike() {
    random_edits_judged_alike(VALID[0], 37, 80, 30);
}

/// The file over an interval of γ with `from` replaced by `to` (the first occurrence, which must
/// exist).
fn interval_with(from: &str, to: &str) -> String {
    let base = text("valid", INTERVAL);
    assert!(base.contains(from), "{from:?} is not in the interval file");
    base.replacen(from, to, 1)
}

/// The γ of the interval file as written.
const GAMMA: &str = "gamma: [\"1/100\", \"1/50\"]";

/// The end of an interval of γ a kernel rejection's locus names, if any.
fn kernel_end(k: &chatter_oracle::compare::KernelView) -> Option<String> {
    k.locus.as_ref().and_then(|l| l["gamma"].as_str()).map(str::to_string)
}

/// Both verdicts on `text`, which must agree; the kernel's code (`None`: accepted) and the end of
/// the interval its locus names, which must be `end` (the oracle's reason names the same end:
/// [`chatter_oracle::compare`]'s `wrong-end`).
fn agreed(what: &str, text: &str) -> (Option<String>, Option<String>) {
    let (kernel, oracle, cmp) = differential_ron(text);
    assert!(cmp.is_ok(), "{what}: {cmp:?}\nkernel {kernel:?}\noracle {oracle:?}");
    if let Some(code) = &kernel.code {
        assert!(oracle.codes().contains(&code.as_str()), "{what}: kernel {kernel:?}, oracle {oracle:?}");
    }
    (kernel.code.clone(), kernel_end(&kernel))
}

/// The file over [1/100, 1/50] is accepted by both with the same claim, n, nodes, B and
/// `gamma_interval`; so are its interval written with equal ends and the lander's file marked
/// version 2 (one γ, no `gamma_interval`).
#[test]
fn interval_files_accepted_alike() {
    let (kernel, oracle, cmp) = differential_ron(&text("valid", INTERVAL));
    assert_eq!(cmp, Ok(Agreement::BothAccept), "{kernel:?} {oracle:?}");
    let ends = Some(["1/100".to_string(), "1/50".to_string()]);
    assert_eq!(oracle.gamma_interval, ends);
    assert_eq!(kernel.gamma_interval, Some(ends));
    assert_eq!(oracle.time_to_rest_bound.as_deref(), Some("4635600924347/274877906944"));
    let cases = [
        ("equal ends 1/100", interval_with(GAMMA, "gamma: [\"1/100\", \"1/100\"]"), Some(["1/100", "1/100"])),
        ("equal ends 1/50", interval_with(GAMMA, "gamma: [\"1/50\", \"1/50\"]"), Some(["1/50", "1/50"])),
        ("the lander as version 2", lander_with("version: 1,", "version: 2,"), None),
    ];
    for (what, t, ends) in cases {
        let (kernel, oracle, cmp) = differential_ron(&t);
        assert_eq!(cmp, Ok(Agreement::BothAccept), "{what}: {kernel:?} {oracle:?}");
        let ends = ends.map(|e| e.map(String::from));
        assert_eq!(oracle.gamma_interval, ends, "{what}");
        assert_eq!(kernel.gamma_interval, Some(ends), "{what}");
    }
}

/// Edits of the file over an interval of γ, each rejected by both with the expected code, the
/// kernel's locus naming the expected end of the interval (`None`: no end) and the oracle's
/// reason the same one.
#[test]
fn interval_edits_break_alike() {
    let gamma = |lo: &str, hi: &str| interval_with(GAMMA, &format!("gamma: [\"{lo}\", \"{hi}\"]"));
    let first_weight = "weight: (\"-1180119/8388608\", \"-705725/8388608\", \"1\")";
    let cases: Vec<(&str, Option<&str>, String)> = vec![
        ("unsupported-version", None, interval_with("version: 2,", "version: 1,")),
        ("unsupported-version", None, interval_with("version: 2,", "version: 3,")),
        ("parameter-out-of-range", None, gamma("1/50", "1/100")),
        ("bad-number", None, gamma("1/100", "2/100")),
        ("bad-number", None, gamma("2/200", "1/50")),
        ("parameter-out-of-range", None, gamma("1/100", "1")),
        ("parameter-out-of-range", None, gamma("0", "1/50")),
        ("parameter-out-of-range", None, gamma("-1/100", "1/50")),
        ("parameter-out-of-range", None, gamma("1/100", "3/2")),
        // The upper end widened: G3 fails there (vertex 0 of K_0 ∩ C_01 maps outside K_4).
        ("image-outside", Some("1/40"), gamma("1/100", "1/40")),
        ("image-outside", Some("1/2"), gamma("1/100", "1/2")),
        // The lower end lowered: G3 fails there.
        ("image-outside", Some("1/200"), gamma("1/200", "1/50")),
        // B far too small: G5 at the first end.
        (
            "bound-too-small",
            Some("1/100"),
            interval_with("bound: \"4635600924347/274877906944\"", "bound: \"1\""),
        ),
        ("bad-number", None, interval_with("bound: \"4635600924347/274877906944\"", "bound: \"2/2\"")),
        // G1 does not depend on γ: no end.
        ("virtual-time-not-positive", None, interval_with(first_weight, "weight: (\"0\", \"0\", \"-1\")")),
        ("wrong-arity", None, interval_with("entries: [0, 1, 2, 3]", "entries: [0, 1, 2]")),
        ("unknown-variant", None, interval_with("CompleteChatterFromAllDown", "EffectivelyInvariant")),
    ];
    let mut failures = vec![];
    for (i, (code, end, text)) in cases.iter().enumerate() {
        let (kernel, oracle, cmp) = differential_ron(text);
        let ok = cmp.is_ok()
            && kernel.code.as_deref() == Some(*code)
            && oracle.codes().contains(code)
            && kernel_end(&kernel).as_deref() == *end;
        if !ok {
            failures
                .push(format!("case {i} ({code} at {end:?}): kernel {kernel:?}, oracle {oracle:?}, {cmp:?}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The interval's upper end widened step by step from 1/50 until a rule fails: both reject at
/// the first value of γ that fails, with the same code, naming that upper end; every narrower
/// interval is accepted by both.
#[test]
fn widening_the_upper_end_fails_there_alike() {
    let mut failed = None;
    for k in 1..=50 {
        // γ_hi = 1/50 + k/10000.
        let hi = rational_text(&(ratio(1, 50) + ratio(k, 10000)));
        let t = interval_with(GAMMA, &format!("gamma: [\"1/100\", \"{hi}\"]"));
        let (code, end) = agreed(&format!("upper end {hi}"), &t);
        if let Some(code) = code {
            assert_eq!(end.as_deref(), Some(hi.as_str()), "upper end {hi}: {code}");
            failed = Some((hi, code));
            break;
        }
    }
    let (hi, code) = failed.expect("some upper end up to 1/50 + 1/200 fails");
    eprintln!("the interval [1/100, {hi}] fails first, with {code} at its upper end");
}

/// B lowered to just below the least B (on a grid of 1/64) that the interval file passes: both
/// reject with `bound-too-small` at the same end; at that least B both accept.
#[test]
fn the_least_bound_over_the_interval_agrees() {
    let written = "bound: \"4635600924347/274877906944\"";
    let with = |b: i64| interval_with(written, &format!("bound: \"{}\"", rational_text(&ratio(b, 64))));
    // B = b/64, bisected on [1, 64 B] with both judging each value.
    let (mut lo, mut hi) = (1, 64 * 17);
    assert_eq!(agreed("B = 17", &with(hi)).0, None, "B = 17 passes");
    assert!(agreed("B = 1/64", &with(lo)).0.is_some(), "B = 1/64 fails");
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if agreed(&format!("B = {mid}/64"), &with(mid)).0.is_none() { hi = mid } else { lo = mid }
    }
    let (code, end) = agreed("just below", &with(lo));
    assert_eq!(code.as_deref(), Some("bound-too-small"));
    assert!(end.is_some(), "a failure of G5 over an interval names an end");
    eprintln!("least B on the grid: {hi}/64; below it G5 fails at gamma = {end:?}");
}

/// 40 random edit plans of the file over an interval of γ, judged alike.
#[test]
fn random_edits_of_the_interval_file_judged_alike() {
    random_edits_judged_alike(INTERVAL, 41, 40, 15);
}

/// The reduction to the ends by brute force: the interval file's graph at one γ (version 1) is
/// accepted by both at the ends and at values strictly inside [1/100, 1/50], and refused alike
/// (with the code the interval got) at the first widened upper end; the oracle's own interior
/// test on an interval the graph does not hold on ([1/100, 1/2]: it fails at 1/2) gives
/// `corner-argument-violated`.
#[test]
fn the_graph_holds_inside_the_interval() {
    for g in ["1/100", "3/250", "1/75", "3/200", "7/400", "49/2500", "1/50"] {
        let t = interval_with(GAMMA, &format!("gamma: \"{g}\"")).replacen("version: 2,", "version: 1,", 1);
        let (kernel, oracle, cmp) = differential_ron(&t);
        assert_eq!(cmp, Ok(Agreement::BothAccept), "gamma = {g}: {kernel:?} {oracle:?}");
        assert_eq!(oracle.gamma_interval, None);
    }
    let t = interval_with(GAMMA, "gamma: \"201/10000\"").replacen("version: 2,", "version: 1,", 1);
    assert_eq!(agreed("gamma = 201/10000", &t), (Some("virtual-time-increases".into()), None));

    use chatter_oracle::arith::{Field, Num};
    use chatter_oracle::convex::virtual_time::interior;
    use chatter_oracle::kinds::{limits::Limits, rest_family};
    let value = parse(&text("valid", INTERVAL), Encoding::Ron).expect("parses");
    let file = rest_family::read(&value).expect("the schema");
    let p = rest_family::prepare(&file, &Limits::default()).expect("the rules before G3");
    let q = Field::rationals();
    let num = |a, b| Num::rational(&q, ratio(a, b));
    let bound = num(4635600924347, 274877906944);
    assert!(interior(&p.graph, (&num(1, 100), &num(1, 50)), &bound, true).is_ok());
    let e = interior(&p.graph, (&num(1, 100), &num(1, 2)), &bound, true).expect_err("fails inside");
    assert_eq!(e.codes, ["corner-argument-violated"], "{}", e.why);
}
