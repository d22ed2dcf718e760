//! `chatter simulate` on the command line: outputs, files, exit statuses.

use crate::common::bin;
use serde_json::Value;
use std::process::{Command, Output};

fn simulate(args: &[&str], dir: &std::path::Path) -> Output {
    Command::new(bin()).arg("simulate").args(args).current_dir(dir).output().expect("run chatter")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn json(o: &Output) -> Value {
    serde_json::from_str(stdout(o).trim()).unwrap_or_else(|e| panic!("not JSON ({e}): {}", stdout(o)))
}

#[test]
fn default_run_prints_outcome_sequence_and_time() {
    let d = tempfile::tempdir().unwrap();
    let o = simulate(&["--n", "3", "--kappa", "3/20", "--gamma", "1/20", "--seed", "7"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    for part in [
        "n=3 kappa=3/20 gamma=1/20",
        "random drop, seed 7",
        "outcome: CC",
        "decided by: ",
        "impacts: 200",
        "sequence: ",
        "total time: ",
        "accumulation point",
    ] {
        assert!(out.contains(part), "missing {part:?} in\n{out}");
    }
}

#[test]
fn json_has_the_documented_keys() {
    let d = tempfile::tempdir().unwrap();
    let o = simulate(&["--n", "3", "--kappa", "1/8", "--gamma", "1/200", "--json"], d.path());
    assert_eq!(o.status.code(), Some(0));
    let v = json(&o);
    assert_eq!(v["outcome"], "PCC");
    assert_eq!(v["decided_by"], "paper-pcc-criterion");
    assert!(v["impacts"].as_u64().unwrap() > 5);
    assert_eq!(v["schema"], "chatter.simulate/1");
    assert_eq!(v["kappa"]["exact"], "1/8");
    assert_eq!(v["arithmetic"], "f64");
    assert_eq!(v["start"]["seed"], 0);

    let o = simulate(&["--n", "3", "--kappa", "1/8", "--gamma", "1/200", "--json", "--exact"], d.path());
    let v = json(&o);
    assert_eq!(
        (v["outcome"].as_str(), v["decided_by"].as_str()),
        (Some("PCC"), Some("exact-pair-chatter-proof"))
    );
    assert_eq!(v["arithmetic"], "exact");

    let o = simulate(&["--position", "1/2,1/2,1", "--velocity", "-1,-1,-1", "--exact", "--json"], d.path());
    let v = json(&o);
    assert_eq!(v["outcome"], "simultaneous");
    assert_eq!(v["simultaneous"]["contacts"], serde_json::json!([0, 1]));
    let exact: Vec<&str> =
        v["start"]["position"].as_array().unwrap().iter().map(|x| x["exact"].as_str().unwrap()).collect();
    assert_eq!(exact, ["1/2", "1/2", "1"]);
    assert_eq!(v["start"]["velocity"][0]["f64"], -1.0);
}

#[test]
fn runs_print_counts_by_outcome() {
    let d = tempfile::tempdir().unwrap();
    let o = simulate(
        &["--n", "3", "--kappa", "3/20", "--gamma", "1/20", "--runs", "12", "--seed", "5", "--json"],
        d.path(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v = json(&o);
    let counts = v["counts"].as_object().unwrap();
    let keys: Vec<&str> = counts.keys().map(String::as_str).collect();
    for k in ["CC", "PCC", "ICC", "undecided", "simultaneous"] {
        assert!(keys.contains(&k), "{keys:?}");
    }
    assert_eq!(counts.values().map(|c| c.as_u64().unwrap()).sum::<u64>(), 12);
    assert_eq!(v["seeds"], serde_json::json!([5, 16]));
    // Deterministic.
    let again = simulate(
        &["--n", "3", "--kappa", "3/20", "--gamma", "1/20", "--runs", "12", "--seed", "5", "--json"],
        d.path(),
    );
    assert_eq!(stdout(&o), stdout(&again));
    let o = simulate(&["--runs", "4"], d.path());
    assert!(
        stdout(&o).contains(
            "outcomes (evidence: f64 simulation proves nothing; --exact proves): CC 4, PCC 0, ICC 0, undecided 0, simultaneous 0"
        ),
        "{}",
        stdout(&o)
    );
}

#[test]
fn trajectory_csv_has_one_row_per_impact_and_the_plot_is_written() {
    let d = tempfile::tempdir().unwrap();
    let o = simulate(
        &["--n", "4", "--impacts", "60", "--trajectory", "t.csv", "--plot", "p.svg", "--json"],
        d.path(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v = json(&o);
    let csv = std::fs::read_to_string(d.path().join("t.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "impact,contact,time,log2_dt,log2_time_to_accumulation,h0,h1,hc,log2_q_scale,u0,u1,v,log2_p_scale,log2_energy"
    );
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len() as u64, v["impacts"].as_u64().unwrap());
    assert_eq!(rows.len(), 60);
    assert!(rows.iter().all(|r| r.split(',').count() == 14));
    assert!(rows[59].starts_with("60,"));
    let svg = std::fs::read_to_string(d.path().join("p.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("contact 3") && svg.contains("impact number"));
    assert!(svg.contains("impacts 37 to 60"), "panel (a) shows the last 24 impacts");

    // The rod has two coordinates; an ICC run has no accumulation point.
    let o = simulate(
        &[
            "--n",
            "2",
            "--kappa",
            "1/3",
            "--gamma",
            "0.074",
            "--position",
            "0,1/10",
            "--velocity",
            "-1,-1",
            "--trajectory",
            "rod.csv",
            "--plot",
            "rod.svg",
        ],
        d.path(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("outcome: ICC"));
    let csv = std::fs::read_to_string(d.path().join("rod.csv")).unwrap();
    assert!(csv.starts_with(
        "impact,contact,time,log2_dt,log2_time_to_accumulation,h0,h1,log2_q_scale,u0,u1,log2_p_scale"
    ));
    let svg = std::fs::read_to_string(d.path().join("rod.svg")).unwrap();
    assert!(svg.contains("contact 1") && !svg.contains("contact 2") && svg.contains("ICC after"));
}

#[test]
fn the_plot_format_follows_the_extension() {
    let d = tempfile::tempdir().unwrap();
    let o = simulate(&["--n", "3", "--kappa", "1/8", "--gamma", "0.15", "--plot", "band.png"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let png = std::fs::read(d.path().join("band.png")).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n", "a PNG file, not SVG text");
    let o = simulate(&["--plot", "x.pdf"], d.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains(".svg or .png"), "{}", stderr(&o));
    assert!(!d.path().join("x.pdf").exists());
}

/// Regression (issue 10 §1): every n from 2 to 64 simulates in f64; n = 5 used to exit 2.
#[test]
fn every_n_up_to_64_simulates_in_f64() {
    let d = tempfile::tempdir().unwrap();
    let o = simulate(&["--n", "5", "--kappa", "1/200", "--gamma", "1/100", "--seed", "3"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    for part in [
        "n=5 kappa=1/200 gamma=1/100",
        "random drop, seed 3",
        "f64 (renormalised)",
        "outcome: CC",
        "decided by: ",
    ] {
        assert!(out.contains(part), "missing {part:?} in\n{out}");
    }
    for n in ["7", "8", "12", "64"] {
        let o = simulate(&["--n", n, "--runs", "4", "--json"], d.path());
        assert_eq!(o.status.code(), Some(0), "n = {n}: {}", stderr(&o));
        let v = json(&o);
        assert_eq!(v["n"].as_u64(), Some(n.parse().unwrap()));
        let total: u64 = v["counts"].as_object().unwrap().values().map(|c| c.as_u64().unwrap()).sum();
        assert_eq!(total, 4, "n = {n}: {v}");
    }
    // A given start, checked exactly in Q(cos 2 pi/7), and a trajectory file with 7 contacts.
    let o = simulate(
        &[
            "--n",
            "7",
            "--position",
            "1/10,1/5,1",
            "--velocity",
            "-1,-1,-1",
            "--trajectory",
            "t.csv",
            "--json",
        ],
        d.path(),
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(json(&o)["start"]["kind"], "given");
    assert!(std::fs::read_to_string(d.path().join("t.csv")).unwrap().lines().count() > 1);
    let o = simulate(&["--n", "7", "--position", "1,0,0", "--velocity", "-1,-1,-1"], d.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("below the floor"), "{}", stderr(&o));
}

/// `--exact` works for every n (issue 10 §1; it was exit 2 for irrational cos 2 pi/n): the text
/// names the field, the JSON report says `exact`, and the f64 evidence (CC) is proved here by an
/// orbit certificate made on the fly in Q(cos 2 pi/n) (issue 22 §2): the exact run stops when its
/// state enters the certificate's set X, after a prefix of the f64 run's impacts.
#[test]
fn exact_simulation_runs_in_the_number_field_for_every_n() {
    let d = tempfile::tempdir().unwrap();
    // (n = 7 at κ = 1/100: its exact run takes 4.5 s, 12 s at 1/200; CI time, issue 23 §4.)
    for (n, kappa) in [("5", "1/200"), ("7", "1/100"), ("12", "1/200")] {
        let args = ["--n", n, "--kappa", kappa, "--gamma", "1/100", "--impacts", "300"];
        // The text once, where the run is shortest (each exact run makes its orbit certificate
        // again: n = 5's takes 2.5 s).
        if n == "5" {
            let o = simulate(&[&args[..], &["--exact"]].concat(), d.path());
            assert_eq!(o.status.code(), Some(0), "n = {n}: {}", stderr(&o));
            let text = stdout(&o);
            assert!(
                text.contains(&format!("exact, in Q(cos 2pi/{n})"))
                    && text.contains("outcome: CC (proved)")
                    && text.contains("kernel-checked orbit certificate"),
                "{text}"
            );
        }
        let e = json(&simulate(&[&args[..], &["--exact", "--json"]].concat(), d.path()));
        let f = json(&simulate(&[&args[..], &["--json"]].concat(), d.path()));
        assert_eq!((e["arithmetic"].as_str(), f["arithmetic"].as_str()), (Some("exact"), Some("f64")));
        assert_eq!((e["outcome"].as_str(), f["outcome"].as_str()), (Some("CC"), Some("CC")), "n = {n}");
        assert_eq!((e["proved"].as_bool(), f["proved"].as_bool()), (Some(true), Some(false)), "n = {n}");
        assert_eq!(e["entered"]["kind"], "orbit", "n = {n}");
        let (es, fs) = (e["sequence"].as_array().unwrap(), f["sequence"].as_array().unwrap());
        assert!(!es.is_empty() && es.len() < fs.len() && fs[..es.len()] == es[..], "n = {n}");
    }
    for n in ["0", "1", "65", "1000"] {
        let o = simulate(&["--n", n], d.path());
        assert_eq!(o.status.code(), Some(2), "n = {n}");
        assert!(stderr(&o).contains("outside 2..=64"), "n = {n}: {}", stderr(&o));
        assert!(!stderr(&o).contains("panicked"));
    }
}

#[test]
fn bad_input_exits_2_with_a_message() {
    let d = tempfile::tempdir().unwrap();
    let cases: [(&[&str], &str); 14] = [
        (&["--n", "65"], "--n: 65 is outside 2..=64"),
        (&["--n", "x"], "--n"),
        (&["--kappa", "0"], "--kappa"),
        (&["--kappa", "1/0"], "--kappa"),
        (&["--gamma", "3/2"], "--gamma"),
        (&["--impacts", "0"], "--impacts"),
        (&["--impacts", "-3"], "--impacts"),
        (&["--runs", "0"], "--runs"),
        (&["--seed", "-1"], "--seed"),
        (&["--position", "1,1,1"], "together"),
        (&["--position", "1,1", "--velocity", "-1,-1,-1"], "expected 3 coordinates"),
        (&["--position", "1,-1,1", "--velocity", "-1,-1,-1"], "below the floor"),
        (&["--runs", "3", "--plot", "x.svg"], "single run"),
        (&["--pcc-epsilon", "2"], "--pcc-epsilon"),
    ];
    for (args, needle) in cases {
        let o = simulate(args, d.path());
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stdout(&o));
        assert!(stderr(&o).contains(needle), "{args:?}: {}", stderr(&o));
        assert!(!stderr(&o).contains("panicked"));
    }
    let o = simulate(&["--trajectory", "no/such/dir/t.csv"], d.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("cannot write"));
    let o = simulate(&["--position", "0,0,0", "--velocity", "0,0,0"], d.path());
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn help_documents_the_flags() {
    let d = tempfile::tempdir().unwrap();
    let out = stdout(&simulate(&["--help"], d.path()));
    for flag in [
        "--n",
        "--kappa",
        "--gamma",
        "--seed",
        "--impacts",
        "--exact",
        "--trajectory",
        "--plot",
        "--runs",
        "--json",
        "--velocity",
        "--position",
        "SplitMix64",
        "undecided",
        "simultaneous",
    ] {
        assert!(out.contains(flag), "simulate --help lacks {flag}");
    }
}
