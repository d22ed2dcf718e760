//! The square-case proof: every step checks, the key facts are present, and the committed files
//! in proofs/ are exactly what `chatter prove square` regenerates.

use crate::common::root;
use chatter::symbolic::crosscheck::cross_check;
use chatter::symbolic::report::{markdown, ron, summary};
use chatter::symbolic::square::prove;

#[test]
fn every_step_checks_and_the_key_results_are_there() {
    let p = prove();
    let s = summary(&p);
    assert_eq!(s.failed, 0, "{:?}", p.steps.iter().filter(|x| !x.ok).collect::<Vec<_>>());
    assert!(s.steps >= 150);
    for id in [
        "L0",
        "gD",
        "e1",
        "eig",
        "tuk",
        "e1>e2",
        "e2>1",
        "r1.s30.0",
        "r4.s1.2",
        "KC1",
        "KC2",
        "KC3",
        "lem:square",
        "l:k0",
        "pcc.witness",
        "theorem",
    ] {
        assert!(p.steps.iter().any(|x| x.id == id && x.ok), "step {id}");
    }
    // The K ∩ C_j vertex sets are the paper's.
    let kc3 = p.steps.iter().find(|x| x.id == "KC3").unwrap();
    assert!(kc3.statement.contains("s30, q1, p1, s1"));
}

#[test]
fn the_committed_proof_files_are_current() {
    let p = prove();
    let cross = cross_check(100, 2026);
    assert_eq!((cross.points, cross.inequalities, cross.invariance, cross.pipeline), (100, 100, 100, 100));
    assert!(cross.disagreements.is_empty());
    let md = std::fs::read_to_string(root().join("proofs/square.md")).unwrap();
    let rn = std::fs::read_to_string(root().join("proofs/square.ron")).unwrap();
    assert!(markdown(&p, &cross) == md, "proofs/square.md is stale: run `chatter prove square`");
    assert!(ron(&p, &cross) == rn, "proofs/square.ron is stale: run `chatter prove square`");
    // The RON parses and records every step as checked.
    let v: ron::Value = ron::from_str(&rn).unwrap();
    let text = format!("{v:?}");
    assert!(text.contains("pcc.witness"));
}
