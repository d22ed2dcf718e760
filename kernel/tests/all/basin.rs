//! Basin certificates (issue 27, docs/basin-certificates.md): the corpus's `basin-*.ron` files
//! in `certificates/valid` and `certificates/invalid` on both backends: the valid files are
//! accepted with shares that are exact rationals summing to 1, and every invalid file is rejected
//! with the code recorded in `certificates/invalid/expected.json` (each breaks one rule of B1-B4).
#![cfg(feature = "basin")]

use chatter_kernel::exact::{ParseLimits, Ring, parse_canonical};
use chatter_kernel::syntax::Encoding;
use chatter_kernel::verify::{BOTH, Verdict, verify_basin_text_in};
use std::path::PathBuf;

type Q = malachite::rational::Rational;

fn dir(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../certificates").join(rel)
}

fn ron_files(rel: &str) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir(rel))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "ron"))
        .filter(|p| p.file_name().is_some_and(|n| n.to_string_lossy().starts_with("basin-")))
        .collect();
    v.sort();
    v
}

#[test]
fn every_valid_basin_certificate_is_accepted_with_shares_summing_to_one() {
    let files = ron_files("valid");
    assert!(!files.is_empty());
    let mut twins = 0;
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        let verdict = verify_basin_text_in(&text, Encoding::Ron, ParseLimits::default(), &BOTH);
        // The JSON twin (docs/certificate-format.md §11, §15), where the corpus has one: the
        // kernel's JSON reader gives the same report.
        if let Ok(json) = std::fs::read_to_string(f.with_extension("json")) {
            assert_eq!(verify_basin_text_in(&json, Encoding::Json, ParseLimits::default(), &BOTH), verdict);
            twins += 1;
        }
        let Verdict::Accepted(r) = verdict else {
            panic!("{}: not accepted", f.display());
        };
        let share = |s: &str| parse_canonical::<Q>(s, ParseLimits::default()).unwrap();
        let sum = share(&r.cc_share).plus(&share(&r.icc_share)).plus(&share(&r.undecided_share));
        assert_eq!(sum, Q::one(), "{}", f.display());
        assert_eq!(r.leaves.iter().sum::<usize>(), text.matches("(path: ").count(), "{}", f.display());
        // A CC share needs CC leaves, each with a time bound: the largest is reported.
        assert_eq!(r.leaves[0] > 0, r.time_to_rest_bound.is_some(), "{}", f.display());
        if let Some(b) = &r.time_to_rest_bound {
            assert!(share(b).is_positive(), "{}", f.display());
        }
    }
    assert!(twins >= 1, "a basin certificate's JSON twin in the corpus");
}

#[test]
fn every_invalid_basin_certificate_is_rejected_with_its_recorded_code() {
    let manifest = std::fs::read_to_string(dir("invalid/expected.json")).unwrap();
    let entries: Vec<serde_json::Value> = serde_json::from_str(&manifest).unwrap();
    let entries: Vec<serde_json::Value> =
        entries.into_iter().filter(|e| e["file"].as_str().unwrap().starts_with("basin-")).collect();
    assert!(entries.len() >= 15, "{} basin files", entries.len());
    let listed: Vec<String> = entries.iter().map(|e| e["file"].as_str().unwrap().to_string()).collect();
    let mut on_disk: Vec<String> =
        ron_files("invalid").iter().map(|p| p.file_name().unwrap().to_string_lossy().to_string()).collect();
    on_disk.sort();
    let mut sorted = listed.clone();
    sorted.sort();
    assert_eq!(sorted, on_disk, "every invalid file is listed, and vice versa");
    for e in &entries {
        let file = e["file"].as_str().unwrap();
        let text = std::fs::read_to_string(dir("invalid").join(file)).unwrap();
        match verify_basin_text_in(&text, Encoding::Ron, ParseLimits::default(), &BOTH) {
            Verdict::Rejected(r) => assert_eq!(r.code.as_str(), e["code"].as_str().unwrap(), "{file}: {r:?}"),
            other => panic!("{file}: expected a rejection, got {other:?}"),
        }
    }
}

#[test]
fn a_ratio_of_one_over_a_power_of_two_per_leaf_is_what_the_shares_add() {
    // Two leaves "0" and "1" (each half of the box): shares are 1/2 each, whatever the verdicts.
    let files = ron_files("valid");
    let text = std::fs::read_to_string(&files[0]).unwrap();
    let start = text.find("    leaves: [").unwrap();
    let end = text[start..].find("    ],\n").unwrap() + start + "    ],\n".len();
    let halves = "    leaves: [\n        (path: \"0\", verdict: Undecided),\n        (path: \"1\", verdict: Undecided),\n    ],\n";
    let two = format!("{}{halves}{}", &text[..start], &text[end..]);
    let Verdict::Accepted(r) = verify_basin_text_in(&two, Encoding::Ron, ParseLimits::default(), &BOTH)
    else {
        panic!("two undecided halves are a partition");
    };
    assert_eq!((r.cc_share.as_str(), r.icc_share.as_str(), r.undecided_share.as_str()), ("0", "0", "1"));
    assert_eq!(r.leaves, [0, 0, 2]);
    assert_eq!(r.time_to_rest_bound, None);
}

/// A linear leaf written as its one-path tree (version 2, docs/certificate-format.md §15):
/// `Icc(first: a, steps: [b, c], cuts: [])` is `Tree(next: [(contact: a, then: Impacts(next:
/// [(contact: b, then: Impacts(next: [(contact: c, then: Icc)]))]))])`.
fn as_tree(verdict: &str) -> String {
    let Some((head, rest)) = verdict.split_once("(first: ") else { return verdict.to_string() };
    let (first, rest) = rest.split_once(", steps: [").unwrap();
    let (steps, rest) = rest.split_once(']').unwrap();
    let end = match head {
        "Icc" => "Icc".to_string(),
        "Rest" => format!("Rest(node: {})", rest.trim_start_matches(", node: ").trim_end_matches(')')),
        other => panic!("no cuts-free tree for {other}"),
    };
    let contacts: Vec<&str> =
        std::iter::once(first).chain(steps.split(',').map(str::trim).filter(|s| !s.is_empty())).collect();
    let mut then = end;
    for (k, c) in contacts.iter().enumerate().rev() {
        let list = format!("[(contact: {c}, then: {then})]");
        then = if k == 0 { format!("Tree(next: {list})") } else { format!("Impacts(next: {list})") };
    }
    then
}

#[test]
fn a_one_path_tree_is_accepted_with_the_report_of_the_prefix_it_writes() {
    for file in ["basin-icc-n3-kappa1_8-gamma1_2.ron", "basin-rest-n4-kappa1_6-gamma1_100.ron"] {
        let text = std::fs::read_to_string(dir("valid").join(file)).unwrap();
        let trees: String = text
            .lines()
            .map(|l| match l.split_once("verdict: ") {
                Some((a, v)) if !v.starts_with("Undecided") => {
                    format!("{a}verdict: {}),\n", as_tree(v.trim_end().trim_end_matches("),")))
                }
                _ => format!("{l}\n"),
            })
            .collect::<String>()
            .replacen("version: 1,", "version: 2,", 1);
        assert!(trees.contains("Tree(next: [(contact: "), "{trees}");
        let run = |t: &str| verify_basin_text_in(t, Encoding::Ron, ParseLimits::default(), &BOTH);
        let (Verdict::Accepted(linear), Verdict::Accepted(tree)) = (run(&text), run(&trees)) else {
            panic!("{file}: {:?}", run(&trees));
        };
        assert_eq!((tree.trees, linear.trees), (linear.leaves.iter().sum::<usize>() - linear.leaves[2], 0));
        assert_eq!(tree, chatter_kernel::basin::BasinReport { trees: tree.trees, ..linear }, "{file}");
        // The same tree in a version-1 file is refused.
        let v1 = trees.replacen("version: 2,", "version: 1,", 1);
        let Verdict::Rejected(r) = run(&v1) else { panic!("{file}: version 1 accepted") };
        assert_eq!(r.code.as_str(), "unsupported-version", "{file}");
    }
}
