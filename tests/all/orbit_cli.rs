//! `chatter certify-orbit` and orbit certificates end to end, through the binary: the file it
//! writes is accepted by `chatter verify` (text and `--json`) and survives `chatter convert`;
//! the `Box(lo, hi)` form of the set is accepted, and rejected when broken; each failure of the
//! producer is reported with its code and exit status 1; bad input is a usage error (exit 2,
//! `chatter.error/1` under `--json`), never a panic.

use crate::common::{bin, root};
use serde_json::Value;
use std::path::Path;
use std::process::{Command, Output};

const VALID: &str = "certificates/valid/orbit-n3-kappa1_8-gamma3_20.ron";

/// The producer's command for the corpus file.
const TRIANGLE: [&str; 9] =
    ["certify-orbit", "--n", "3", "--kappa", "1/8", "--gamma", "3/20", "--pattern", "2,2,1,1"];

fn chatter(args: &[&str], dir: &Path) -> Output {
    Command::new(bin()).args(args).current_dir(dir).output().expect("run chatter")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// Runs a command that must exit with `code` and print one JSON object on stdout, nothing on stderr.
fn json(args: &[&str], dir: &Path, code: i32) -> Value {
    let o = chatter(args, dir);
    assert_eq!(o.status.code(), Some(code), "{args:?}: {}{}", text(&o.stdout), text(&o.stderr));
    assert!(o.stderr.is_empty(), "{args:?}: {}", text(&o.stderr));
    serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|e| panic!("{args:?}: not JSON ({e}): {}", text(&o.stdout)))
}

fn with<'a>(base: &[&'a str], more: &[&'a str]) -> Vec<&'a str> {
    base.iter().chain(more).copied().collect()
}

#[test]
fn certify_orbit_writes_a_file_that_verify_accepts_as_text_and_json_and_convert_keeps() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let v = json(&with(&TRIANGLE, &["-o", "orbit.ron", "--json"]), p, 0);
    assert_eq!(v["schema"], "chatter.certify-orbit/1");
    assert_eq!(v["verdict"], "certified");
    assert_eq!(
        (v["n"].as_u64(), &v["kappa"]["exact"], &v["gamma"]["exact"]),
        (Some(3), &"1/8".into(), &"3/20".into())
    );
    assert_eq!(v["gamma"]["f64"], 0.15);
    assert_eq!(v["requested_pattern"], serde_json::json!([2, 2, 1, 1]));
    assert_eq!(v["certificate"]["claim"], "CompleteChatterFromSet");
    assert_eq!(v["certificate"]["pattern"], serde_json::json!([2, 2, 1, 1]));
    assert_eq!(v["certificate"]["delta"]["exact"], "1/4096");
    assert_eq!(v["certificate"]["rho"]["exact"], "3/5");
    assert_eq!(v["output"], "orbit.ron");
    assert!(v["reason"].is_null() && v["message"].is_null(), "{v}");
    assert!(v.get("timings").is_none(), "timings only with --timings: {v}");
    // The float evidence of docs/orbit-certificates.md §5.
    let diag = &v["diagnostics"];
    for (l, e) in diag["eigenvalues"].as_array().unwrap().iter().zip([0.81970, 0.55431, 0.45437]) {
        assert!((l.as_f64().unwrap() - e).abs() < 1e-4, "{diag}");
    }
    assert!((diag["ratio"].as_f64().unwrap() - 0.55431).abs() < 1e-4, "{diag}");
    let ab = diag["alpha"].as_f64().unwrap() / diag["beta"].as_f64().unwrap();
    assert!((ab - diag["ratio"].as_f64().unwrap()).abs() < 1e-9, "{diag}");
    assert!((diag["period_time"].as_f64().unwrap() - 1.55999).abs() < 1e-4, "{diag}");
    assert!((diag["fixed_point"][0].as_f64().unwrap() - 2.295573).abs() < 1e-5, "{diag}");
    let boxes = v["kernel"]["sub_boxes"].as_u64().unwrap();
    assert!(boxes >= 1, "{v}");
    assert_eq!(v["kernel"]["backends"], serde_json::json!(["malachite", "num-rational"]));
    // The producer is deterministic: the file is the corpus file.
    let written = std::fs::read_to_string(p.join("orbit.ron")).unwrap();
    assert_eq!(written, std::fs::read_to_string(root().join(VALID)).unwrap());

    // chatter verify accepts it, as text and as JSON, with the kernel's sub-box count.
    let o = chatter(&["verify", "orbit.ron"], p);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stdout));
    let line = text(&o.stdout);
    assert!(line.contains("orbit.ron: OK (CompleteChatterFromSet, n = 3"), "{line}");
    assert!(line.contains("1 file: 1 OK") || line.contains("1 OK, 0 rejected"), "{line}");
    let r = json(&["verify", "orbit.ron", "--json"], p, 0);
    assert_eq!(r["verdict"], "accepted");
    assert_eq!(r["files"][0]["verdict"], "accepted");
    assert_eq!(r["files"][0]["orbit_boxes"].as_u64(), Some(boxes));

    // Its JSON twin verifies the same and converts back to the same RON.
    let o = chatter(&["convert", "orbit.ron", "--to", "json", "-o", "orbit.json"], p);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let twin: Value = serde_json::from_str(&std::fs::read_to_string(p.join("orbit.json")).unwrap()).unwrap();
    assert_eq!(
        (&twin["format"], &twin["version"]),
        (&Value::from("chatter-orbit-certificate"), &Value::from(1))
    );
    assert_eq!(twin["set"]["Parallelepiped"]["delta"], "1/4096");
    let rj = json(&["verify", "orbit.json", "--json"], p, 0);
    assert_eq!(rj["files"][0]["orbit_boxes"], r["files"][0]["orbit_boxes"]);
    assert_eq!(rj["files"][0]["claim"], "CompleteChatterFromSet");
    let o = chatter(&["convert", "orbit.json", "--to", "ron"], p);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(text(&o.stdout), written);

    // The text output, without -o: nothing written.
    let o = chatter(&TRIANGLE, p);
    assert_eq!(o.status.code(), Some(0));
    let line = text(&o.stdout);
    assert!(
        line.starts_with(
            "CERTIFIED n=3 kappa=1/8 gamma=3/20 claim=CompleteChatterFromSet: pattern [2, 2, 1, 1]"
        ),
        "{line}"
    );
    assert!(line.contains("(no -o: not written)"), "{line}");
    // --timings adds the times, and only them.
    let t = json(&with(&TRIANGLE, &["--json", "--timings"]), p, 0);
    assert!(t["timings"]["kernel_ms"].as_f64().unwrap() > 0.0, "{t}");
    assert!(t["timings"]["search_ms"].as_f64().unwrap() >= 0.0, "{t}");
    let mut without = t.clone();
    without.as_object_mut().unwrap().remove("timings");
    let mut plain = v.clone();
    plain["output"] = Value::Null;
    assert_eq!(without, plain);
}

/// The corpus file with its parallelepiped replaced by a box `Box(lo, hi)`.
fn boxed(lo: [&str; 3], hi: [&str; 3]) -> String {
    let t = std::fs::read_to_string(root().join(VALID)).unwrap();
    let start = t.find("    set: Parallelepiped(").unwrap();
    let end = t.find("    subdivision:").unwrap();
    let q = |v: [&str; 3]| format!("(\"{}\", \"{}\", \"{}\")", v[0], v[1], v[2]);
    format!(
        "{}    set: Box(\n        lo: {},\n        hi: {},\n    ),\n{}",
        &t[..start],
        q(lo),
        q(hi),
        &t[end..]
    )
}

const BOX_VALID: &str = "certificates/valid/orbit-box-n3-kappa1_8-gamma3_20.ron";
const BOX_INVALID: &str = "certificates/invalid/orbit-box-empty.ron";

#[test]
fn the_box_form_of_the_set_is_accepted_end_to_end_and_rejected_when_broken() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let good = std::fs::read_to_string(root().join(BOX_VALID)).unwrap();
    assert!(good.contains("    set: Box(\n"), "{good}");
    let r = json(&["verify", BOX_VALID, "--json"], &root(), 0);
    assert_eq!(r["files"][0]["verdict"], "accepted", "{r}");
    assert_eq!(r["files"][0]["claim"], "CompleteChatterFromSet");
    assert!(r["files"][0]["orbit_boxes"].as_u64().unwrap() >= 1, "{r}");
    let o = chatter(&["verify", BOX_VALID], &root());
    assert_eq!(o.status.code(), Some(0));
    assert!(text(&o.stdout).contains("OK (CompleteChatterFromSet, n = 3"), "{}", text(&o.stdout));
    // Its JSON twin: the same verdict, and back to the same RON.
    std::fs::write(p.join("box.ron"), &good).unwrap();
    let o = chatter(&["convert", "box.ron", "--to", "json", "-o", "box.json"], p);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let twin: Value = serde_json::from_str(&std::fs::read_to_string(p.join("box.json")).unwrap()).unwrap();
    assert!(twin["set"]["Box"]["lo"].is_array() && twin["set"]["Box"]["hi"].is_array(), "{twin}");
    let rj = json(&["verify", "box.json", "--json"], p, 0);
    assert_eq!(rj["files"][0]["orbit_boxes"], r["files"][0]["orbit_boxes"]);
    assert_eq!(text(&chatter(&["convert", "box.json", "--to", "ron"], p).stdout), good);

    // Broken: the corpus file with lo = hi in one coordinate (a flat box), and mutations of the
    // valid box, each rejected with the code of the rule it breaks.
    let r = json(&["verify", BOX_INVALID, "--json"], &root(), 1);
    assert_eq!(r["files"][0]["code"], "degenerate-set", "{r}");
    let read_box = |t: &str| -> ([String; 3], [String; 3]) {
        let c =
            chatter_kernel::certificate::read_orbit(t, chatter_kernel::certificate::Encoding::Ron).unwrap();
        match c.set {
            chatter_kernel::certificate::OrbitSet::Box { lo, hi } => ([lo.0, lo.1, lo.2], [hi.0, hi.1, hi.2]),
            other => panic!("{other:?}"),
        }
    };
    let (lo, hi) = read_box(&good);
    let l = [lo[0].as_str(), lo[1].as_str(), lo[2].as_str()];
    let h = [hi[0].as_str(), hi[1].as_str(), hi[2].as_str()];
    let cases: Vec<(&str, String, &[&str])> = vec![
        ("lo and hi swapped", boxed(h, l), &["degenerate-set"]),
        (
            "a box far from the cycle",
            boxed(["3", "2", "-1"], ["31/10", "21/10", "-9/10"]),
            &["pattern-not-forced", "set-not-invariant", "no-contraction"],
        ),
        (
            "a box around the cycle, too large",
            boxed(["2", "1", "-5/2"], ["5/2", "3/2", "-3/2"]),
            &["pattern-not-forced", "set-not-invariant", "no-contraction"],
        ),
        ("rho below alpha/beta", good.replace("rho: \"3/5\"", "rho: \"1/2\""), &["no-contraction"]),
        (
            "a step changed",
            good.replace("pattern: [2, 2, 1, 1]", "pattern: [2, 2, 1, 2]"),
            &["pattern-not-forced"],
        ),
    ];
    for (what, t, codes) in cases {
        assert_ne!(t, good, "{what}");
        std::fs::write(p.join("bad.ron"), &t).unwrap();
        let r = json(&["verify", "bad.ron", "--json"], p, 1);
        let code = r["files"][0]["code"].as_str().unwrap_or_else(|| panic!("{what}: {r}"));
        assert!(codes.contains(&code), "{what}: {code}: {r}");
        let o = chatter(&["verify", "bad.ron"], p);
        assert_eq!(o.status.code(), Some(1), "{what}");
        assert!(text(&o.stdout).contains("bad.ron: REJECTED: "), "{what}: {}", text(&o.stdout));
    }
}

/// Each failure of the producer, reached from the command line: exit status 1, the code in the
/// text line and as the JSON report's `reason`, nothing written.
#[test]
fn each_failure_of_certify_orbit_is_reported_with_its_code_and_exit_status_1() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let base = ["certify-orbit", "--n", "3", "--kappa", "1/8"];
    let cases: Vec<(Vec<&str>, &str, &str)> = vec![
        // Every drop at gamma = 1/5 is ICC: no pattern to follow.
        (
            vec!["--gamma", "1/5"],
            "no-pattern",
            "no periodic impact pattern found: 20 drops simulated, outcomes ICC",
        ),
        // The pattern has no attracting cycle there.
        (vec!["--gamma", "1/5", "--pattern", "2,2,1,1"], "no-attracting-cycle", "no attracting cycle found"),
        (vec!["--gamma", "3/20", "--pattern", "1,2"], "pattern-not-stable", "breaks the pattern"),
        // Above the S_1^2 S_2^2 threshold gamma_c (docs/orbit-certificates.md §7.2): no fixed point.
        (
            vec!["--gamma", "763/5000", "--pattern", "2,2,1,1"],
            "no-attracting-cycle",
            "no attracting cycle found",
        ),
    ];
    for (more, code, message) in &cases {
        let args = with(&base, more);
        let o = chatter(&with(&args, &["-o", "x.ron"]), p);
        let line = text(&o.stdout);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {line}{}", text(&o.stderr));
        assert!(o.stderr.is_empty(), "{args:?}: {}", text(&o.stderr));
        assert!(line.starts_with("NOT CERTIFIED n=3 kappa=1/8 gamma="), "{line}");
        assert!(line.contains(&format!("[{code}]")) && line.contains(message), "{args:?}: {line}");
        assert!(!p.join("x.ron").exists(), "{args:?}: a file was written");
        let v = json(&with(&args, &["--json", "-o", "x.ron"]), p, 1);
        assert_eq!(v["schema"], "chatter.certify-orbit/1");
        assert_eq!(v["verdict"], "not-certified");
        assert_eq!(v["reason"], *code, "{v}");
        assert!(v["message"].as_str().unwrap().contains(message), "{v}");
        for key in ["certificate", "diagnostics", "kernel", "output"] {
            assert!(v[key].is_null(), "{key}: {v}");
        }
        assert!(!p.join("x.ron").exists(), "{args:?}: a file was written");
    }
}

/// Bad input: a clear usage error naming the flag, exit status 2, never a panic; under `--json`
/// the same message as `chatter.error/1` on stdout.
#[test]
fn bad_input_to_certify_orbit_is_a_usage_error() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let long = vec!["1"; 65].join(",");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["--n", "65", "--kappa", "1/8", "--gamma", "3/20"],
            "--n: 65 is not supported here: give 3 <= n <= 64 (a regular n-gon)",
        ),
        (vec!["--n", "2", "--kappa", "1/8", "--gamma", "3/20"], "--n: 2"),
        (vec!["--kappa", "1/8", "--gamma", "3/2"], "--gamma: "),
        (vec!["--kappa", "1/8", "--gamma", "-1/2"], "--gamma: "),
        (vec!["--kappa", "0", "--gamma", "3/20"], "--kappa: "),
        (vec!["--kappa", "x", "--gamma", "3/20"], "--kappa: "),
        (
            vec!["--kappa", "1/8", "--gamma", "3/20", "--pattern", "2,x,1"],
            "--pattern: \"2,x,1\": step 2 (\"x\") is not a non-negative integer",
        ),
        (vec!["--kappa", "1/8", "--gamma", "3/20", "--pattern", "2,,1"], "--pattern: \"2,,1\": step 2"),
        (vec!["--kappa", "1/8", "--gamma", "3/20", "--pattern", ""], "--pattern: \"\": step 1"),
        (
            vec!["--kappa", "1/8", "--gamma", "3/20", "--pattern", "2,3,1"],
            "--pattern: \"2,3,1\": step 2 is 3, outside 1..2",
        ),
        (vec!["--kappa", "1/8", "--gamma", "3/20", "--pattern", "0"], "step 1 is 0, outside 1..2"),
        (
            vec!["--kappa", "1/8", "--gamma", "3/20", "--pattern", "-1"],
            "step 1 (\"-1\") is not a non-negative integer",
        ),
        (vec!["--kappa", "1/8", "--gamma", "3/20", "--pattern", &long], "--pattern: 65 steps, more than 64"),
        (
            vec!["--kappa", "1/8", "--gamma", "3/20", "--max-depth", "11"],
            "--max-depth: 11 is more than the kernel's limit 10",
        ),
        (
            vec!["--kappa", "1/8", "--gamma", "3/20", "--pattern", "2,2,1,1", "-o", "/nonexistent/dir/x.ron"],
            "cannot write /nonexistent/dir/x.ron",
        ),
    ];
    for (more, message) in &cases {
        let args = with(&["certify-orbit"], more);
        let o = chatter(&args, p);
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}{err}", text(&o.stdout));
        assert!(o.stdout.is_empty(), "{args:?}: {}", text(&o.stdout));
        assert!(err.starts_with("error: ") && err.contains(message), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        let v = json(&with(&args, &["--json"]), p, 2);
        assert_eq!(v["schema"], "chatter.error/1", "{args:?}: {v}");
        assert_eq!((v["kind"].as_str(), v["exit_code"].as_u64()), (Some("usage"), Some(2)), "{v}");
        assert!(v["message"].as_str().unwrap().contains(message), "{args:?}: {v}");
    }
}
