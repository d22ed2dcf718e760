//! `chatter simulate` with general bodies (docs/model.md §11, docs/bodies.md): each body option,
//! JSON, given starts in the paper's coordinates, and exit 2 with a message for bad input.

use crate::common::bin;
use serde_json::Value;
use std::process::{Command, Output};

fn simulate(args: &[&str]) -> Output {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    Command::new(bin()).arg("simulate").args(args).current_dir(root).output().expect("run chatter")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

#[test]
fn every_body_option_simulates() {
    for (args, head) in [
        (
            vec!["--rectangle", "2,1", "--gamma", "1/20", "--exact"],
            "rectangle 2 x 1 (uniform plate), n=4 gamma=1/20",
        ),
        (vec!["--box", "150,75,8"], "box 150 x 75 x 8 (uniform, on its 150 x 75 face), n=4"),
        (
            vec!["--polygon", "0,0 4,0 1,3", "--plate", "--seed", "3"],
            "uniform plate of a polygon with 3 corners, n=3",
        ),
        (
            vec!["--polygon", "2,0 0,1 -1,0 0,-1", "--inertia", "1/2,-1/10,1/3", "--centre", "1/4,0"],
            "polygon with 4 contacts, given inertia, n=4",
        ),
        (
            vec!["--body", "certificates/bodies/lander.ron"],
            "body file certificates/bodies/lander.ron (3 contacts, inertia tensor, J_eff), n=3 gamma=1/20",
        ),
    ] {
        let o = simulate(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", text(&o.stderr));
        let out = text(&o.stdout);
        assert!(out.starts_with(head), "{args:?}: {out}");
        assert!(out.contains("outcome: "), "{out}");
    }
}

#[test]
fn the_phone_comes_to_rest_in_every_random_drop_at_low_gamma() {
    let o = simulate(&["--box", "150,75,8", "--runs", "50", "--gamma", "1/100"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(
        text(&o.stdout).contains("(evidence: f64 simulation proves nothing; --exact proves): CC 50,"),
        "{}",
        text(&o.stdout)
    );
}

#[test]
fn json_reports_describe_the_general_body() {
    let o = simulate(&["--rectangle", "2,1", "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v: Value = serde_json::from_str(text(&o.stdout).trim()).unwrap();
    assert_eq!(v["schema"], "chatter.simulate/1");
    assert_eq!(v["general_body"]["description"], "rectangle 2 x 1 (uniform plate)");
    assert_eq!(v["general_body"]["contacts"][0][0]["exact"], "1");
    assert_eq!(v["general_body"]["contacts"][0][1]["exact"], "-1/2");
    assert_eq!(v["general_body"]["inertia"][0]["exact"], "1/12");
    assert_eq!(v["general_body"]["inertia"][2]["exact"], "1/3");
    let o = simulate(&["--n", "4", "--json"]);
    let v: Value = serde_json::from_str(text(&o.stdout).trim()).unwrap();
    assert!(v["general_body"].is_null());
    let o = simulate(&["--box", "2,1,1", "--runs", "3", "--json"]);
    let v: Value = serde_json::from_str(text(&o.stdout).trim()).unwrap();
    assert_eq!(v["general_body"]["description"], "box 2 x 1 x 1 (uniform, on its 2 x 1 face)");
}

#[test]
fn given_starts_are_in_the_papers_coordinates() {
    // (phi_x, phi_y, h) = (0, 0, 1): flat at height 1; (omega_x, omega_y, v) = (0, 0, -1): every
    // contact lands at t = 1 at once.
    let o = simulate(&["--rectangle", "2,1", "--position", "0,0,1", "--velocity", "0,0,-1", "--exact"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(text(&o.stdout).contains("outcome: simultaneous"), "{}", text(&o.stdout));
    // Tilted: h_k = h + y_k phi_x - x_k phi_y = 1 - y_k/10 - x_k/20, lowest at contact 1 = (1, 1/2).
    let o = simulate(&[
        "--rectangle",
        "2,1",
        "--position",
        "-1/10,1/20,1",
        "--velocity",
        "0,0,-1",
        "--exact",
        "--json",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v: Value = serde_json::from_str(text(&o.stdout).trim()).unwrap();
    assert_eq!(v["sequence"][0], 1, "{v}");
    assert_eq!(v["start"]["position"][0]["exact"], "-1/10");
    let o = simulate(&["--rectangle", "2,1", "--position", "3,0,1", "--velocity", "0,0,-1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("below the floor"), "{}", text(&o.stderr));
    let o = simulate(&["--rectangle", "2,1", "--position", "0,1", "--velocity", "0,0,-1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("phix,phiy,h and wx,wy,v"), "{}", text(&o.stderr));
}

#[test]
fn bad_general_bodies_exit_2_with_a_message() {
    let d = tempfile::tempdir().unwrap();
    let bad_file = d.path().join("bad.ron");
    std::fs::write(&bad_file, "(contacts: [(\"1\", \"0\")], inertia: (\"1\", \"0\"))").unwrap();
    let outside = d.path().join("outside.ron");
    std::fs::write(
        &outside,
        "(contacts: [(\"1\", \"0\"), (\"2\", \"1\"), (\"1\", \"1\")], inertia: (\"1\", \"0\", \"1\"))",
    )
    .unwrap();
    let (bad, out) = (bad_file.to_str().unwrap(), outside.to_str().unwrap());
    for (args, message) in [
        (vec!["--rectangle", "2"], "--rectangle: expected 2 comma-separated numbers"),
        (vec!["--rectangle", "2,-1"], "--rectangle: every side must be > 0"),
        (vec!["--box", "1,1,x"], "--box: "),
        (vec!["--polygon", "0,0 1,1 2,2", "--plate"], "lies on the line through its neighbours"),
        (vec!["--polygon", "0,0 0,3 4,0", "--plate"], "clockwise"),
        (vec!["--polygon", "0,0 2,0 1,1 2,2 0,2", "--plate"], "not convex"),
        (vec!["--polygon", "1,0 0,1 -1,0 0,-1", "--inertia", "1,0,-1"], "positive definite"),
        (
            vec!["--polygon", "1,0 0,1 -1,0 0,-1", "--inertia", "1,0,1", "--centre", "3,0"],
            "outside the contact polygon",
        ),
        (vec!["--polygon", "1,0 0,1 -1,0 0,-1"], "--polygon needs --plate or --inertia"),
        (vec!["--polygon", "1,0 0,1 -1,0", "--plate", "--inertia", "1,0,1"], "drop --inertia"),
        (vec!["--plate"], "go with --polygon"),
        (vec!["--rectangle", "2,1", "--box", "1,1,1"], "describe different bodies"),
        (vec!["--rectangle", "2,1", "--n", "3"], "cannot be used with"),
        (vec!["--rectangle", "2,1", "--gamma", "2"], "gamma must lie in [0, 1]"),
        (vec!["--body", "/nonexistent/body.ron"], "cannot read"),
        (vec!["--body", bad], "not a body file"),
        (vec!["--body", out], "outside the contact polygon"),
    ] {
        let o = simulate(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", text(&o.stdout));
        let err = text(&o.stderr);
        assert!(err.contains(message), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}
