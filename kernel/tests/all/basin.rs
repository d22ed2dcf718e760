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
