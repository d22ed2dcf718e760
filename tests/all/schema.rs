//! The JSON interface (docs/json.md): the committed schemas in docs/schema/ are those the report
//! types generate, every command's `--json` output (and the summary.json files of map and cover)
//! validates against the schema it names, the default output is byte-stable, and errors under
//! `--json` are JSON on stdout with the documented exit statuses.

use crate::common::{bin, root};
use chatter::report::{schema_file_name, schema_text, schemas};
use serde_json::Value;
use std::path::Path;
use std::process::{Command, Output};

fn chatter(args: &[&str], dir: &Path) -> Output {
    Command::new(bin()).args(args).current_dir(dir).output().expect("run chatter")
}

/// The committed schema of a name.
fn committed(name: &str) -> Value {
    let path = root().join("docs/schema").join(schema_file_name(name));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap()
}

/// Validates a document against the committed schema it names; returns the schema name.
pub(crate) fn validate(doc: &Value) -> String {
    let name = doc["schema"].as_str().unwrap_or_else(|| panic!("no schema name in {doc}")).to_string();
    let validator = jsonschema::validator_for(&committed(&name)).expect("a valid JSON Schema");
    let errors: Vec<String> =
        validator.iter_errors(doc).map(|e| format!("{e} at {}", e.instance_path())).collect();
    assert!(errors.is_empty(), "{name}: {errors:#?}\nin {doc}");
    name
}

/// Runs a command, checks its exit status, parses its stdout as one JSON document and validates it.
fn run_valid(args: &[&str], dir: &Path, code: i32) -> (String, Value) {
    let o = chatter(args, dir);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(code), "{args:?}: {out}{}", String::from_utf8_lossy(&o.stderr));
    let doc: Value =
        serde_json::from_str(out.trim()).unwrap_or_else(|e| panic!("{args:?}: not JSON ({e}): {out}"));
    (validate(&doc), doc)
}

#[test]
fn committed_schemas_are_the_generated_ones() {
    let mut names = Vec::new();
    for (name, schema) in schemas() {
        let path = root().join("docs/schema").join(schema_file_name(name));
        let text = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            text == schema_text(&schema),
            "{} is stale or missing: regenerate with `cargo run --release -- schema --out docs/schema`",
            path.display()
        );
        assert!(jsonschema::validator_for(&schema).is_ok(), "{name}: not a valid JSON Schema");
        names.push(name);
    }
    // The validator does reject: a wrong type, a wrong schema name, a missing field.
    let v = jsonschema::validator_for(&committed("chatter.error/1")).unwrap();
    let good =
        serde_json::json!({"schema": "chatter.error/1", "kind": "usage", "exit_code": 2, "message": "m"});
    assert!(v.is_valid(&good));
    for (key, bad) in [
        ("exit_code", Value::from("two")),
        ("schema", Value::from("chatter.error/2")),
        ("kind", Value::from("oops")),
    ] {
        let mut doc = good.clone();
        doc[key] = bad;
        assert!(!v.is_valid(&doc), "{doc}");
    }
    assert!(!v.is_valid(&serde_json::json!({"schema": "chatter.error/1", "kind": "usage"})));
    let files = std::fs::read_dir(root().join("docs/schema")).unwrap().count();
    assert_eq!(files, names.len(), "docs/schema holds a file that no report type generates");
}

#[test]
fn every_command_output_validates_against_its_schema() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let cases: Vec<(Vec<&str>, i32, &str)> = vec![
        (
            vec!["classify", "--n", "3", "--kappa", "3/20", "--gamma", "1/20", "--json"],
            0,
            "chatter.classify/1",
        ),
        (
            vec!["classify", "--n", "3", "--kappa", "1/8", "--gamma", "3/20", "--json"],
            0,
            "chatter.classify/1",
        ),
        (
            vec!["classify", "--n", "5", "--kappa", "1/20", "--gamma", "1/100", "--json"],
            0,
            "chatter.classify/1",
        ),
        (
            vec![
                "classify",
                "--n",
                "2",
                "--kappa",
                "1/3",
                "--gamma",
                "1/20",
                "--velocity",
                "-1,-1",
                "--json",
            ],
            0,
            "chatter.classify/1",
        ),
        (vec!["bodies", "--json"], 0, "chatter.bodies/1"),
        (
            vec!["simulate", "--n", "3", "--kappa", "1/8", "--gamma", "1/200", "--json"],
            0,
            "chatter.simulate/1",
        ),
        (
            vec!["simulate", "--position", "1/2,1/2,1", "--velocity", "-1,-1,-1", "--exact", "--json"],
            0,
            "chatter.simulate/1",
        ),
        (vec!["simulate", "--n", "5", "--runs", "4", "--json"], 0, "chatter.simulate-batch/1"),
        (
            vec!["certify", "--n", "3", "--kappa", "3/20", "--gamma", "1/20", "-o", "c.ron", "--json"],
            0,
            "chatter.certify/1",
        ),
        (vec!["certify", "--gamma", "1/2", "--json", "--timings"], 1, "chatter.certify/1"),
        (
            vec!["certify", "--rectangle", "2,1", "--gamma", "1/100", "-o", "r.ron", "--json"],
            0,
            "chatter.certify/1",
        ),
        (vec!["certify", "--body", "phone", "--gamma", "1/5", "--json"], 1, "chatter.certify/1"),
        (vec!["verify", "r.ron", "--json"], 0, "chatter.verify/1"),
        (
            vec!["certify", "--rectangle", "2,1", "--largest-gamma", "--steps", "4", "--json"],
            0,
            "chatter.largest-gamma/1",
        ),
        (
            vec!["certify", "--body", "table", "--largest-gamma", "--steps", "2", "--json"],
            0,
            "chatter.largest-gamma/1",
        ),
        (
            vec!["certify", "--n", "3", "--kappa", "1/8:3/20", "--gamma", "1/100:1/50", "--json"],
            0,
            "chatter.certify/1",
        ),
        (
            vec!["refute", "--n", "4", "--kappa", "1/6", "--gamma", "1/10", "--json", "--timings"],
            0,
            "chatter.refute/1",
        ),
        (vec!["refute", "--n", "4", "--kappa", "1/6", "--gamma", "1/100", "--json"], 1, "chatter.refute/1"),
        (vec!["verify", "c.ron", "--json"], 0, "chatter.verify/1"),
        (vec!["prove", "square", "--out", "p", "--points", "5", "--json"], 0, "chatter.prove/1"),
        (vec!["check-proof", "p/square.ron", "c.ron", "--json"], 1, "chatter.check-proof/1"),
        (vec!["certify", "--gamma", "3/2", "--json"], 2, "chatter.error/1"),
        (vec!["simulate", "--n", "5", "--exact", "--json"], 0, "chatter.simulate/1"),
        (vec!["simulate", "--n", "65", "--json"], 2, "chatter.error/1"),
        (vec!["verify", "no-such-file.ron", "--json"], 2, "chatter.verify/1"),
        (
            vec![
                "certify-orbit",
                "--n",
                "3",
                "--kappa",
                "1/8",
                "--gamma",
                "3/20",
                "--pattern",
                "2,2,1,1",
                "-o",
                "orbit.ron",
                "--json",
                "--timings",
            ],
            0,
            "chatter.certify-orbit/1",
        ),
        (vec!["verify", "orbit.ron", "--json"], 0, "chatter.verify/1"),
        (
            vec!["certify-orbit", "--n", "3", "--kappa", "1/8", "--gamma", "1/5", "--json"],
            1,
            "chatter.certify-orbit/1",
        ),
        (
            vec![
                "certify-orbit",
                "--n",
                "3",
                "--kappa",
                "1/8",
                "--gamma",
                "1/5",
                "--pattern",
                "2,2,1,1",
                "--json",
            ],
            1,
            "chatter.certify-orbit/1",
        ),
        (
            vec!["certify-orbit", "--n", "5", "--kappa", "1/8", "--gamma", "1/5", "--json"],
            1,
            "chatter.certify-orbit/1",
        ),
        (
            vec!["certify-orbit", "--n", "1", "--kappa", "1/8", "--gamma", "1/5", "--json"],
            2,
            "chatter.error/1",
        ),
    ];
    for (args, code, want) in cases {
        let (name, _) = run_valid(&args, p, code);
        assert_eq!(name, want, "{args:?}");
    }
    let (_, v) = run_valid(&["verify", "certificates/invalid", "--json"], &root(), 1);
    assert!(v["files"].as_array().unwrap().iter().all(|f| f["verdict"] == "rejected"));
}

#[test]
fn map_and_cover_summaries_validate_against_their_schemas() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let o = chatter(&["map", "--n", "3", "--rho", "0:1:3", "--gamma", "0:1:3", "--certify", "--out", "m"], p);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let cover = ["cover", "--n", "4", "--kappa", "1/10:1/4", "--gamma", "0:1/2", "--kappa-depth", "2"];
    let o =
        chatter(&[&cover[..], &["--gamma-depth", "3", "--area-intervals", "16", "--out", "c"]].concat(), p);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for (dir, want) in [("m", "chatter.map/1"), ("c", "chatter.cover/1")] {
        let text = std::fs::read_to_string(p.join(dir).join("summary.json")).unwrap();
        assert_eq!(validate(&serde_json::from_str(&text).unwrap()), want);
    }
}

#[test]
fn default_json_is_byte_stable_and_timings_are_opt_in() {
    let d = tempfile::tempdir().unwrap();
    for args in [
        &["certify", "--n", "3", "--kappa", "3/20", "--gamma", "1/20", "--json"][..],
        &["refute", "--n", "4", "--kappa", "1/6", "--gamma", "1/10", "--json"],
        &["classify", "--n", "4", "--kappa", "1/6", "--gamma", "1/100", "--json"],
        &["simulate", "--n", "4", "--runs", "8", "--json"],
        &["certify-orbit", "--n", "3", "--kappa", "1/8", "--gamma", "1/5", "--pattern", "2,2,1,1", "--json"],
    ] {
        let (a, b) = (chatter(args, d.path()), chatter(args, d.path()));
        assert_eq!(a.stdout, b.stdout, "{args:?} differs between runs");
        assert!(!String::from_utf8_lossy(&a.stdout).contains("timings"), "{args:?}");
    }
    let (_, v) = run_valid(
        &["certify", "--n", "3", "--kappa", "3/20", "--gamma", "1/20", "--json", "--timings"],
        d.path(),
        0,
    );
    assert!(v["timings"]["kernel_ms"].as_f64().unwrap() > 0.0);
}

#[test]
fn errors_under_json_are_json_on_stdout_with_the_same_exit_status() {
    let d = tempfile::tempdir().unwrap();
    for (args, code) in [
        (&["certify", "--n", "65", "--json"][..], 2),
        (&["classify", "--n", "3", "--velocity", "1,2", "--json"], 2),
        (&["bodies", "--prism", "4", "--json"], 2),
        (&["check-proof", "missing.ron", "--json"], 2),
        (&["certify-orbit", "--n", "65", "--kappa", "1/8", "--gamma", "3/20", "--json"], 2),
        (&["certify-orbit", "--kappa", "1/8", "--gamma", "3/20", "--pattern", "2,x", "--json"], 2),
    ] {
        let o = chatter(args, d.path());
        assert_eq!(o.status.code(), Some(code), "{args:?}");
        assert!(o.stderr.is_empty(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
        let v: Value = serde_json::from_slice(&o.stdout).unwrap();
        assert_eq!(validate(&v), "chatter.error/1");
        assert_eq!(v["exit_code"], code);
        assert_eq!(v["kind"], "usage");
        // Without --json the same error is text on stderr.
        let plain: Vec<&str> = args.iter().copied().filter(|a| *a != "--json").collect();
        let o = chatter(&plain, d.path());
        assert_eq!(o.status.code(), Some(code));
        assert!(o.stdout.is_empty() && String::from_utf8_lossy(&o.stderr).starts_with("error: "));
    }
}

/// One vocabulary: every report's top-level verdict (where it has one) is a word of docs/json.md.
#[test]
fn verdicts_use_one_vocabulary() {
    let words = ["certified", "not-certified", "refuted", "not-refuted", "accepted", "rejected", "error"];
    let d = tempfile::tempdir().unwrap();
    for args in [
        &["certify", "--gamma", "1/2", "--json"][..],
        &["refute", "--n", "4", "--kappa", "1/6", "--gamma", "1/100", "--json"],
        // (One backend: the words, not the backends' agreement, which json.rs checks.)
        &["verify", "--backend", "malachite", "certificates/valid", "--json"],
        &["check-proof", "proofs/square.ron", "--json"],
        &["certify-orbit", "--n", "3", "--kappa", "1/8", "--gamma", "1/5", "--json"],
    ] {
        let dir = if args[0] == "certify" || args[0] == "refute" || args[0] == "certify-orbit" {
            d.path().to_path_buf()
        } else {
            root()
        };
        let o = chatter(args, &dir);
        let v: Value = serde_json::from_slice(&o.stdout).unwrap();
        assert!(words.contains(&v["verdict"].as_str().unwrap()), "{args:?}: {}", v["verdict"]);
    }
}
