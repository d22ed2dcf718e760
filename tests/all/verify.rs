//! Tests of `verify`: file collection, per-file verdicts, backend selection.

use crate::common::root;
use chatter::exact::ParseLimits;
use chatter::verify::{Status, collect_files, verify_file};
use chatter_kernel::verify::{MALACHITE, NUM};

#[test]
fn directories_are_searched_recursively_for_ron_files_in_order() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("sub")).unwrap();
    for f in ["b.ron", "a.ron", "sub/c.ron", "notes.txt"] {
        std::fs::write(dir.path().join(f), "x").unwrap();
    }
    let files = collect_files(&[dir.path().to_path_buf()]).unwrap();
    let names: Vec<String> =
        files.iter().map(|p| p.strip_prefix(dir.path()).unwrap().display().to_string()).collect();
    assert_eq!(names, ["a.ron", "b.ron", "sub/c.ron"]);
}

#[test]
fn verdict_lines() {
    let ok = verify_file(
        &root().join("certificates/valid/doc-example-square.ron"),
        ParseLimits::default(),
        &[MALACHITE, NUM],
    );
    assert_eq!(ok.status, Status::Ok);
    assert!(ok.line().ends_with(
        "doc-example-square.ron: OK (CompleteChatterFromAllDown, n = 4, 4 generators, denominators <= 5 bits)"
    ));
    let bad = verify_file(
        &root().join("certificates/invalid/shrunk-rectangle.ron"),
        ParseLimits::default(),
        &[NUM],
    );
    assert_eq!(bad.status, Status::Rejected);
    assert!(bad.line().contains(": REJECTED: vertex 0 of K∩C_1"));
    let missing =
        verify_file(&root().join("certificates/nope.ron"), ParseLimits::default(), &[MALACHITE, NUM]);
    assert_eq!(missing.status, Status::Error);
    assert!(missing.line().contains("cannot read"));
}

#[test]
fn the_digit_limit_is_configurable() {
    let p = root().join("certificates/valid/doc-example-square.ron");
    // Its longest number, gamma = "1/100", has four digits.
    assert_eq!(verify_file(&p, ParseLimits { max_digits: 4 }, &[MALACHITE, NUM]).status, Status::Ok);
    let v = verify_file(&p, ParseLimits { max_digits: 3 }, &[MALACHITE, NUM]);
    assert_eq!(v.status, Status::Rejected);
    assert!(
        v.reason
            .unwrap()
            .contains("field `body.gamma`: \"1/100\": number has 4 digits, more than the limit of 3")
    );
}
