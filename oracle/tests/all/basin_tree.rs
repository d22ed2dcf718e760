//! Tree leaves of basin certificates, version 2 (issue 27), judged by the oracle alone (the kernel
//! of this branch does not read version 2 yet, so nothing is compared with it): the corpus's
//! linear leaves rewritten as one-path trees, accepted with the originals' shares; a tree in a
//! version-1 file; every failure of rule B1 on trees with its code and path (the oracle's message
//! starts with the path, as the kernel's locus names it); the schema of trees in RON and JSON; a
//! tree whose root lists a contact that does not land first, refused by rule B4 at the sample
//! drops; a tree that really branches at its root.

use crate::common::root;
use chatter_oracle::judge;
use chatter_oracle::read::Encoding;
use chatter_oracle::verdict::{Judgement, Outcome};

/// n = 3, κ = 1/8, γ = 1/2: four `Icc(first: 0, steps: [2,2,2], cuts: [])` leaves, one undecided.
const ICC: &str = "certificates/valid/basin-icc-n3-kappa1_8-gamma1_2.ron";
/// The same in JSON.
const ICC_JSON: &str = "certificates/valid/basin-icc-n3-kappa1_8-gamma1_2.json";
/// The square plate (n = 4, κ = 1/6, γ = 1/100): one leaf `Rest(first: 3, steps: [], node: 0)`.
const REST: &str = "certificates/valid/basin-rest-n4-kappa1_6-gamma1_100.ron";

fn text(file: &str) -> String {
    std::fs::read_to_string(root().join(file)).unwrap()
}

/// The one-path tree of the impacts `contacts` (the first absolute, the others steps) with the
/// end `end` (`Icc`, `Cc` or `Rest(node: r)`), as RON.
fn chain(contacts: &[u64], end: &str) -> String {
    let (first, rest) = contacts.split_first().expect("an impact");
    let then =
        if rest.is_empty() { end.to_string() } else { format!("Impacts(next: [{}])", chain(rest, end)) };
    format!("(contact: {first}, then: {then})")
}

fn tree(contacts: &[u64], end: &str) -> String {
    format!("Tree(next: [{}])", chain(contacts, end))
}

/// The integers of a RON list or field value such as `[2,2,2]` or `3`.
fn integers(s: &str) -> Vec<u64> {
    s.trim_matches(|c| c == '[' || c == ']')
        .split(',')
        .filter(|x| !x.trim().is_empty())
        .map(|x| x.trim().parse().unwrap())
        .collect()
}

/// A field's value in `Icc(first: 0, steps: [2,2,2], cuts: [])`.
fn field<'a>(verdict: &'a str, name: &str) -> &'a str {
    let at = verdict.find(&format!("{name}: ")).unwrap() + name.len() + 2;
    let rest = &verdict[at..];
    let end =
        if rest.starts_with('[') { rest.find(']').unwrap() + 1 } else { rest.find([',', ')']).unwrap() };
    &rest[..end]
}

/// The file with version 2 and every linear leaf `Icc(first, steps, cuts: [])` or `Rest(first,
/// steps, node)` replaced by its one-path tree.
fn as_trees(file: &str) -> String {
    let original = text(file);
    let lines = original.lines().map(|line| {
        let Some(at) = line.find("verdict: Icc(").or_else(|| line.find("verdict: Rest(")) else {
            return line.to_string();
        };
        let verdict = &line[at + "verdict: ".len()..line.rfind(')').unwrap()];
        let mut contacts = integers(field(verdict, "first"));
        contacts.extend(integers(field(verdict, "steps")));
        let end = if verdict.starts_with("Icc") {
            assert_eq!(field(verdict, "cuts"), "[]");
            "Icc".to_string()
        } else {
            format!("Rest(node: {})", field(verdict, "node"))
        };
        format!("{}verdict: {}),", &line[..at], tree(&contacts, &end))
    });
    let out: Vec<String> = lines.collect();
    // Only the basin certificate's own version (the embedded time-to-rest certificate keeps its own).
    out.join("\n").replacen("version: 1,", "version: 2,", 1)
}

/// The file with version 2 and leaf `leaf`'s verdict replaced by `verdict` (the others as trees).
fn with_leaf(file: &str, leaf: usize, verdict: &str) -> String {
    let (mut k, trees) = (0, as_trees(file));
    let lines = trees.lines().map(|line| {
        let Some(at) = line.find("verdict: ") else { return line.to_string() };
        k += 1;
        if k - 1 != leaf {
            return line.to_string();
        }
        format!("{}verdict: {verdict}),", &line[..at])
    });
    lines.collect::<Vec<_>>().join("\n")
}

fn basin_report(j: &Judgement) -> ([String; 3], [usize; 3]) {
    match &j.outcome {
        Outcome::Accept(r) => r.basin.clone().expect("a basin report"),
        other => panic!("rejected: {other:?}"),
    }
}

fn rejected(text: &str) -> (Vec<&'static str>, String) {
    match judge(text, Encoding::Ron).outcome {
        Outcome::Reject { codes, why } => (codes, why),
        Outcome::Accept(r) => panic!("accepted: {r:?}\n{text}"),
    }
}

/// The code and the path the message starts with (after the leaf's B4 prefix, if any).
fn assert_fails(text: &str, code: &str, path: &str) {
    let (codes, why) = rejected(text);
    assert_eq!(codes, [code], "{why}");
    assert!(why.starts_with(&format!("{path}:")), "{code}: expected the path {path}, got {why:?}");
}

#[test]
fn linear_leaves_rewritten_as_one_path_trees_get_the_same_shares_and_bound() {
    for file in [ICC, REST] {
        let (linear, trees) = (judge(&text(file), Encoding::Ron), judge(&as_trees(file), Encoding::Ron));
        assert!(as_trees(file).contains("Tree(next: [(contact: "), "{file}");
        assert_eq!(basin_report(&linear), basin_report(&trees), "{file}");
        assert_eq!(linear.time_to_rest_bound, trees.time_to_rest_bound, "{file}");
    }
    let (icc, rest) =
        (basin_report(&judge(&as_trees(ICC), Encoding::Ron)), judge(&as_trees(REST), Encoding::Ron));
    assert_eq!(icc.1, [0, 4, 1], "four ICC trees and one undecided leaf");
    assert_eq!(basin_report(&rest), (["1".to_string(), "0".to_string(), "0".to_string()], [1, 0, 0]));
    assert!(rest.time_to_rest_bound.is_some(), "a Rest end bounds the time to rest");
    let expected = "Tree(next: [(contact: 0, then: Impacts(next: [(contact: 2, then: Impacts(next: [(contact: 2, \
                    then: Impacts(next: [(contact: 2, then: Icc)]))]))]))])";
    assert!(as_trees(ICC).contains(expected), "{}", as_trees(ICC));
}

#[test]
fn a_tree_in_json_reads_as_in_ron() {
    let mut v: serde_json::Value = serde_json::from_str(&text(ICC_JSON)).unwrap();
    v["version"] = 2.into();
    let end = |then: serde_json::Value, contact: u64| serde_json::json!({"contact": contact, "then": then});
    for leaf in v["leaves"].as_array_mut().unwrap() {
        let Some(icc) = leaf["verdict"].get("Icc").cloned() else { continue };
        let steps: Vec<u64> = icc["steps"].as_array().unwrap().iter().map(|s| s.as_u64().unwrap()).collect();
        let mut then = serde_json::json!("Icc");
        for &s in steps.iter().rev() {
            then = serde_json::json!({"Impacts": {"next": [end(then, s)]}});
        }
        leaf["verdict"] = serde_json::json!({"Tree": {"next": [end(then, icc["first"].as_u64().unwrap())]}});
    }
    let json = serde_json::to_string_pretty(&v).unwrap();
    assert!(json.contains("\"Impacts\""), "{json}");
    let (ron, json) = (judge(&as_trees(ICC), Encoding::Ron), judge(&json, Encoding::Json));
    assert_eq!(basin_report(&ron), basin_report(&json));
    // A `Rest` end in JSON: an object; an unknown end.
    let rest = serde_json::to_string(&serde_json::json!({"Rest": {"node": 0}})).unwrap();
    let bad = serde_json::to_string(&v).unwrap().replacen("\"Icc\"", &rest, 1);
    assert_eq!(judge(&bad, Encoding::Json).codes(), ["basin-out-of-range"], "a Rest end without rest");
    let bad = serde_json::to_string(&v).unwrap().replacen("\"Icc\"", "\"Stop\"", 1);
    assert_eq!(judge(&bad, Encoding::Json).codes(), ["unknown-variant"]);
}

#[test]
fn a_tree_needs_version_2_and_version_3_is_unknown() {
    let v1 = as_trees(ICC).replacen("version: 2,", "version: 1,", 1);
    assert_fails(&v1, "unsupported-version", "version");
    // Linear leaves read in both versions.
    let linear_v2 = text(ICC).replacen("version: 1,", "version: 2,", 1);
    assert_eq!(
        basin_report(&judge(&linear_v2, Encoding::Ron)),
        basin_report(&judge(&text(ICC), Encoding::Ron))
    );
    let v3 = as_trees(ICC).replacen("version: 2,", "version: 3,", 1);
    assert_eq!(rejected(&v3).0, ["unsupported-version"]);
    // The version is checked at the first tree leaf, after its path's length.
    let long = format!("(path: \"{}\", verdict: {}),", "0".repeat(65), tree(&[0], "Icc"));
    let v1_long =
        v1.replacen("(path: \"0\", verdict: ", &format!("{long}\n        (path: \"0\", verdict: "), 1);
    assert_eq!(rejected(&v1_long).0, ["too-large"]);
    // Leaves in file order: a linear leaf's failure before a later tree's version.
    let first_out =
        with_leaf(ICC, 0, "Icc(first: 5, steps: [], cuts: [])").replacen("version: 2,", "version: 1,", 1);
    assert_eq!(rejected(&first_out).0, ["basin-out-of-range"]);
}

#[test]
fn every_failure_of_rule_b1_on_a_tree_has_its_code_and_path() {
    let out = "basin-out-of-range";
    let icc = |verdict: &str| with_leaf(ICC, 0, verdict);
    let rest = |verdict: &str| with_leaf(REST, 0, verdict);
    assert_fails(&icc("Tree(next: [])"), out, "leaves[0].verdict");
    assert_fails(&icc(&tree(&[0], "Impacts(next: [])")), out, "leaves[0].verdict");
    let twice = "Tree(next: [(contact: 1, then: Icc), (contact: 1, then: Icc)])";
    assert_fails(&icc(twice), out, "leaves[0].verdict");
    assert_fails(&icc(&tree(&[3], "Icc")), out, "leaves[0].first");
    assert_fails(&icc(&tree(&[0, 2, 0], "Icc")), out, "leaves[0].steps");
    assert_fails(&icc(&tree(&[0, 3], "Icc")), out, "leaves[0].steps");
    assert_fails(&icc(&tree(&[0, 2], "Cc")), out, "leaves[0]");
    assert_fails(&icc(&tree(&[0], "Rest(node: 0)")), out, "leaves[0]");
    assert_fails(&rest(&tree(&[3], "Rest(node: 1000)")), out, "leaves[0].node");
    let mixed = "Tree(next: [(contact: 3, then: Rest(node: 0)), (contact: 0, then: Icc)])";
    assert_fails(&rest(mixed), out, "leaves[0].verdict");
    // Leaf 3 (the fourth) names its own index.
    assert_fails(&with_leaf(ICC, 3, "Tree(next: [])"), out, "leaves[3].verdict");
}

#[test]
fn rule_b1_on_a_tree_goes_in_the_specs_order() {
    let out = "basin-out-of-range";
    let icc = |verdict: &str| with_leaf(ICC, 0, verdict);
    // (4) before (5): the root's contacts before an empty list below its first impact.
    let below_empty = "Tree(next: [(contact: 0, then: Impacts(next: [])), (contact: 5, then: Icc)])";
    assert_fails(&icc(below_empty), out, "leaves[0].first");
    // Range before repetition, impact by impact.
    let twice_out = "Tree(next: [(contact: 7, then: Icc), (contact: 7, then: Icc)])";
    assert_fails(&icc(twice_out), out, "leaves[0].first");
    let twice_then_out =
        "Tree(next: [(contact: 1, then: Icc), (contact: 1, then: Icc), (contact: 9, then: Icc)])";
    assert_fails(&icc(twice_then_out), out, "leaves[0].verdict");
    // Depth first: a failure below the first impact before the second impact's end.
    let first_below =
        "Tree(next: [(contact: 0, then: Impacts(next: [(contact: 0, then: Icc)])), (contact: 1, then: Cc)])";
    assert_fails(&icc(first_below), out, "leaves[0].steps");
    // Mixed ends only after the walk: a Cc end without an orbit certificate first.
    let mixed = "Tree(next: [(contact: 0, then: Icc), (contact: 1, then: Cc)])";
    assert_fails(&icc(mixed), out, "leaves[0]");
}

/// A root list of `count` impacts `(contact: 0, then: Icc)` (the second of which repeats).
fn wide(count: usize) -> String {
    format!("Tree(next: [{}])", vec!["(contact: 0, then: Icc)"; count].join(", "))
}

#[test]
fn a_tree_has_at_most_4096_impacts_and_paths_of_at_most_4096() {
    let icc = |verdict: &str| with_leaf(ICC, 0, verdict);
    // The count is checked before the contacts: 4096 impacts read on to the repetition.
    assert_fails(&icc(&wide(4_096)), "basin-out-of-range", "leaves[0].verdict");
    let (codes, why) = rejected(&icc(&wide(4_097)));
    assert_eq!(codes, ["too-large"]);
    assert!(why.contains("max-basin-tree"), "{why}");
    // The impacts so far: the root's two and a list of 4095 below the first.
    let below = format!(
        "Tree(next: [(contact: 0, then: Impacts(next: [{}])), (contact: 1, then: Icc)])",
        vec!["(contact: 2, then: Icc)"; 4_095].join(", ")
    );
    assert!(rejected(&icc(&below)).1.contains("max-basin-tree"));
    // Paths: 4096 impacts pass rule B1 (and fail B4: the drops separate long before); 4097 do
    // not (max-basin-prefix and max-basin-tree are both 4096, and the count is checked first).
    // Deep nesting needs a larger stack than a test thread's.
    let deep = |impacts: usize| {
        let contacts: Vec<u64> = std::iter::once(0).chain(std::iter::repeat_n(2, impacts - 1)).collect();
        with_leaf(ICC, 0, &tree(&contacts, "Icc"))
    };
    let run = move || {
        let (ok, long) = (rejected(&deep(4096)), rejected(&deep(4097)));
        assert_eq!(ok.0, ["leaf-not-shown"], "{}", ok.1);
        assert_eq!(long.0, ["too-large"], "{}", long.1);
        // A path of 4097 impacts is a tree of 4097: the count, checked first, stops it.
        assert!(long.1.contains("max-basin-tree"), "{}", long.1);
    };
    std::thread::Builder::new().stack_size(1 << 28).spawn(run).unwrap().join().unwrap();
}

#[test]
fn the_schema_of_a_tree_refuses_unknown_fields_variants_and_forms() {
    let icc = |verdict: &str| with_leaf(ICC, 0, verdict);
    let cases = [
        ("Tree(next: [(contact: 0, then: Stop)])", "unknown-variant"),
        ("Tree(next: [(contact: 0, then: Icc, why: 1)])", "unknown-field"),
        ("Tree(next: [(contact: 0)])", "missing-field"),
        ("Tree(next: [(contact: 0, then: Icc, contact: 1)])", "duplicate-field"),
        ("Tree(nodes: [(contact: 0, then: Icc)])", "unknown-field"),
        ("Tree(next: [(contact: 0, then: Icc(first: 0))])", "syntax"),
        ("Tree(next: [(contact: 0, then: Impacts)])", "syntax"),
        ("Tree(next: [(contact: 0, then: Rest(3))])", "syntax"),
        ("Tree(next: [(contact: -1, then: Icc)])", "syntax"),
        ("Tree", "syntax"),
        ("Tree(next: [(contact: 0, then: Rest(node: 0, extra: 1))])", "unknown-field"),
    ];
    for (verdict, code) in cases {
        assert_eq!(rejected(&icc(verdict)).0, [code], "{verdict}");
    }
}

#[test]
fn a_tree_whose_root_lists_a_contact_that_does_not_land_first_is_refused() {
    // Every sample drop of the triangle's leaf lands at contact 0 first: a root listing only 1.
    let (codes, why) = rejected(&with_leaf(ICC, 0, &tree(&[1, 2, 2, 2], "Icc")));
    assert_eq!(codes, ["leaf-not-shown"], "{why}");
    assert!(why.starts_with("leaf 0 (path \"0\"): in the tree after the impacts []"), "{why}");
    // The square's drops land at contact 3 first: a root listing 0 and 1 only.
    let wrong = "Tree(next: [(contact: 0, then: Rest(node: 0)), (contact: 1, then: Rest(node: 0))])";
    assert_eq!(rejected(&with_leaf(REST, 0, wrong)).0, ["leaf-not-shown"]);
    // A wrong step below the right first contact, and a path that ends too early.
    assert_eq!(rejected(&with_leaf(ICC, 1, &tree(&[0, 1, 2, 2], "Icc"))).0, ["leaf-not-shown"]);
    assert_eq!(rejected(&with_leaf(ICC, 1, &tree(&[0, 2], "Icc"))).0, ["leaf-not-shown"]);
}

#[test]
fn a_tree_that_branches_at_its_root_is_accepted_where_every_branch_holds() {
    // The square's root lists contact 3 (which lands first) and contact 0: every other contact is
    // excluded by 3, and node 0's cone holds the velocity after either impact at the sample drops
    // (after 0 at the formula's state, in which contact 3 is below the floor).
    let branch = |node: u64| {
        format!("Tree(next: [(contact: 3, then: Rest(node: 0)), (contact: 0, then: Rest(node: {node}))])")
    };
    let judged = judge(&with_leaf(REST, 0, &branch(0)), Encoding::Ron);
    let linear = judge(&text(REST), Encoding::Ron);
    assert_eq!(basin_report(&judged), basin_report(&linear));
    // The bound is the drops' own: at the end of the path their real motion follows.
    assert_eq!(judged.time_to_rest_bound, linear.time_to_rest_bound);
    // Every branch is checked over the whole leaf, the ones no drop follows too: node 1's cone
    // misses the velocity after contact 0; after contact 2 (which lands long after 3) the
    // formula's centre is below the floor, so hc > 0 fails at that end.
    let (codes, why) = rejected(&with_leaf(REST, 0, &branch(1)));
    assert_eq!(codes, ["leaf-not-shown"]);
    assert!(why.contains("after the impacts [0]: the velocity"), "{why}");
    let off = "Tree(next: [(contact: 3, then: Rest(node: 0)), (contact: 2, then: Rest(node: 0))])";
    assert!(rejected(&with_leaf(REST, 0, off)).1.contains("after the impacts [2]: hc > 0 and v < 0 fail"));
}

#[test]
fn a_tree_covers_the_square_where_two_contacts_land_together() {
    // The box (0.05, 0.05, 0.05, 0.05, 1.05) ± 1/1000: its three sample drops have ω_x = ω_y and
    // φ_x = φ_y, where the square's contacts 0 and 3 land together. No linear leaf holds there;
    // the tree listing both does (each branch checked at the tie's state), and the drops, which
    // meet a simultaneous impact, give no time (volume zero: docs/basin-certificates.md Lemma 4.1).
    let lo = "[\"49/1000\", \"49/1000\", \"49/1000\", \"49/1000\", \"1049/1000\"]";
    let hi = "[\"51/1000\", \"51/1000\", \"51/1000\", \"51/1000\", \"1051/1000\"]";
    let symmetric = |verdict: &str| {
        let file = with_leaf(REST, 0, verdict);
        let at = file.find("drops: ").unwrap();
        let end = at + file[at..].find('\n').unwrap();
        format!("{}drops: (lo: {lo}, hi: {hi}),{}", &file[..at], &file[end..])
    };
    for first in [0, 3] {
        let (codes, why) = rejected(&symmetric(&tree(&[first], "Rest(node: 0)")));
        assert_eq!(codes, ["leaf-not-shown"], "{why}");
    }
    let both = "Tree(next: [(contact: 3, then: Rest(node: 0)), (contact: 0, then: Rest(node: 0))])";
    let judged = judge(&symmetric(both), Encoding::Ron);
    assert_eq!(basin_report(&judged).0, ["1", "0", "0"]);
    assert_eq!(judged.time_to_rest_bound, None);
}
