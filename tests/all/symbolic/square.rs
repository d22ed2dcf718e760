//! The square-case proof: the producer writes it without problems, the kernel re-checks it on
//! both backends, the committed files are what `chatter prove square` regenerates, and
//! `chatter check-proof` re-checks the committed file (and rejects a changed one, naming the step).

use crate::common::{bin, root};
use chatter::symbolic::crosscheck::cross_check;
use chatter::symbolic::report::{markdown, ron};
use chatter::symbolic::square::prove;
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::{Verdict, verify_proof};
use std::process::Command;

#[test]
fn the_producer_writes_a_proof_the_kernel_accepts() {
    let b = prove();
    assert!(b.problems.is_empty(), "{:?}", b.problems);
    let file = b.finish();
    let Verdict::Accepted(c) = verify_proof(&file, ParseLimits::default()) else { panic!("rejected") };
    assert_eq!(c.steps, file.steps.len());
    let all = c.conclusions.join("\n");
    // The paper's pieces K ∩ C_j, computed by the checker's clipping.
    assert!(all.contains("K ∩ C_3 is the polygon q1, p1, s1, s30"), "{all}");
    assert!(all.contains("K ∩ C_1 is the polygon s3, p3, q3, s01"), "{all}");
    assert!(all.contains("K ∩ C_2 is the polygon r-, r+, s01, s30"), "{all}");
}

#[test]
fn the_committed_proof_files_are_current() {
    let b = prove();
    let file = b.finish();
    let Verdict::Accepted(c) = verify_proof(&file, ParseLimits::default()) else { panic!("rejected") };
    let cross = cross_check(100, 2026);
    assert_eq!((cross.points, cross.inequalities, cross.invariance, cross.pipeline), (100, 100, 100, 100));
    assert!(cross.disagreements.is_empty());
    let md = std::fs::read_to_string(root().join("proofs/square.md")).unwrap();
    let rn = std::fs::read_to_string(root().join("proofs/square.ron")).unwrap();
    assert!(markdown(&b, &Ok(c), &cross) == md, "proofs/square.md is stale: run `chatter prove square`");
    assert!(ron(&file) == rn, "proofs/square.ron is stale: run `chatter prove square`");
    assert!(!rn.contains("ok:"), "no verdict in the proof object");
}

#[test]
fn check_proof_rechecks_the_committed_file_and_names_a_failing_step() {
    let o =
        Command::new(bin()).args(["check-proof", "proofs/square.ron"]).current_dir(root()).output().unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(out.starts_with("proofs/square.ron: OK (square:"), "{out}");
    assert!(out.contains("K satisfies conditions 1 and 2"), "{out}");
    let d = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(root().join("proofs/square.ron")).unwrap();
    let bad = text.replacen("(\"4\", [\"k\"])", "(\"5\", [\"k\"])", 1);
    assert_ne!(bad, text);
    std::fs::write(d.path().join("bad.ron"), bad).unwrap();
    let o = Command::new(bin()).args(["check-proof", "bad.ron"]).current_dir(d.path()).output().unwrap();
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}");
    assert!(out.contains("REJECTED: step 2 `1-l.1`"), "{out}");
    let o = Command::new(bin()).args(["check-proof", "missing.ron"]).current_dir(d.path()).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
}
