//! Tests of the `chatter` binary: arguments, outputs, exit statuses.

use crate::common::{bin, root};
use chatter::exact::QExt;
use std::process::{Command, Output};

fn chatter(args: &[&str], dir: &std::path::Path) -> Output {
    Command::new(bin()).args(args).current_dir(dir).output().expect("run chatter")
}

fn text(o: &Output) -> (String, String) {
    (String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned())
}

#[test]
fn help_documents_the_commands() {
    let d = tempfile::tempdir().unwrap();
    let (out, _) = text(&chatter(&["--help"], d.path()));
    assert!(out.contains("certify") && out.contains("verify") && out.contains("Exit status"), "{out}");
    let (out, _) = text(&chatter(&["certify", "--help"], d.path()));
    for flag in [
        "--n",
        "--kappa",
        "--gamma",
        "--claim",
        "--output",
        "--json",
        "complete-chatter-from-all-down",
        "0.01",
    ] {
        assert!(out.contains(flag), "certify --help lacks {flag}");
    }
    let (out, _) = text(&chatter(&["verify", "--help"], d.path()));
    assert!(out.contains("--backend") && out.contains("--max-digits"));
}

#[test]
fn certify_then_verify_with_exit_statuses() {
    let d = tempfile::tempdir().unwrap();
    let o = chatter(&["certify", "-o", "sq.ron"], d.path());
    let (out, _) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{out}");
    assert!(out.starts_with("CERTIFIED n=4 kappa=1/6 gamma=1/100 claim=CompleteChatterFromAllDown"), "{out}");
    assert!(out.contains("-> sq.ron"));
    let o = chatter(&["verify", "sq.ron"], d.path());
    assert_eq!(o.status.code(), Some(0));
    assert!(text(&o).0.starts_with("sq.ron: OK (CompleteChatterFromAllDown, n = 4"));

    // Not certified: exit 1 and no file.
    let o = chatter(&["certify", "--gamma", "1/10", "-o", "no.ron"], d.path());
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o).0.starts_with("NOT CERTIFIED"));
    assert!(!d.path().join("no.ron").exists());
}

#[test]
fn decimal_input_is_read_exactly() {
    let d = tempfile::tempdir().unwrap();
    assert!(chatter(&["certify", "--gamma", "0.01", "-o", "a.ron"], d.path()).status.success());
    assert!(chatter(&["certify", "--gamma", "1/100", "-o", "b.ron"], d.path()).status.success());
    assert!(
        chatter(&["certify", "--gamma", "1e-2", "--kappa", "2/12", "-o", "c.ron"], d.path()).status.success()
    );
    let read = |f: &str| std::fs::read_to_string(d.path().join(f)).unwrap();
    assert_eq!(read("a.ron"), read("b.ron"));
    assert_eq!(read("a.ron"), read("c.ron"));
}

#[test]
fn usage_errors_exit_2_with_a_message() {
    let d = tempfile::tempdir().unwrap();
    for (args, needle) in [
        (vec!["certify", "--n", "65"], "--n: 65 is not supported"),
        (vec!["certify", "--n", "four"], "--n"),
        (vec!["certify", "--kappa", "abc"], "--kappa"),
        (vec!["certify", "--kappa", "-1/6"], "kappa must be > 0"),
        (vec!["certify", "--gamma", "1/0"], "zero denominator"),
        (vec!["certify", "--gamma", "3/2"], "gamma must lie in [0, 1]"),
        (vec!["certify", "--max-vertices", "2"], "--max-vertices"),
        (vec!["verify", "no-such-dir-or-file.ron"], "could not be read"),
        (vec!["frobnicate"], "unrecognized subcommand"),
    ] {
        let o = chatter(&args, d.path());
        let (out, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {out}{err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

#[test]
fn certify_json() {
    let d = tempfile::tempdir().unwrap();
    let o = chatter(&["certify", "--n", "3", "--kappa", "3/20", "--gamma", "0.05", "--json"], d.path());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["schema"], "chatter.certify/1");
    assert_eq!(v["verdict"], "certified");
    assert_eq!(v["claim"], "CompleteChatterFromAllDown");
    assert_eq!(v["gamma"]["lo"]["exact"], "1/20");
    assert_eq!(v["gamma"]["hi"]["f64"], 0.05);
    assert!(v["generators"].as_u64().unwrap() >= 3);
    assert_eq!(v["finder"]["outcome"], "found");
    assert!(v.get("timings").is_none(), "timings only with --timings");
    let o = chatter(&["certify", "--gamma", "1/2", "--json"], d.path());
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["verdict"], "not-certified");
    assert_eq!(v["finder"]["outcome"], "no-cone");
    assert!(v["reason"].as_str().unwrap().contains("no effectively invariant cone"));
}

#[test]
fn verify_a_directory_prints_a_line_per_file_and_rejections_as_json() {
    // The whole corpus through the binary is tests/all/json.rs's test (once: each pass costs
    // seconds); here a directory of three valid and one of three invalid files.
    let d = tempfile::tempdir().unwrap();
    let (good, bad) = (d.path().join("good"), d.path().join("bad"));
    for (dir, files) in [
        (
            &good,
            [
                "doc-example-square.ron",
                "n2-kappa1_4-gamma1_9-complete-chatter-from-all-down.ron",
                "orbit-n3-kappa1_8-gamma3_20.ron",
            ],
        ),
        (&bad, ["shrunk-rectangle.ron", "basin-leaf-missing.ron", "orbit-delta-enlarged.ron"]),
    ] {
        std::fs::create_dir(dir).unwrap();
        let from = root().join(if dir == &good { "certificates/valid" } else { "certificates/invalid" });
        for f in files {
            std::fs::copy(from.join(f), dir.join(f)).unwrap();
        }
    }
    let o = chatter(&["verify", good.to_str().unwrap()], &root());
    let (out, err) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert_eq!(out.lines().count(), 4, "one line per file and the summary: {out}");
    assert!(out.lines().take(3).all(|l| l.contains(": OK (")), "{out}");
    assert_eq!(out.lines().last(), Some("3 files: 3 OK, 0 rejected, 0 errors"));

    let o = chatter(&["verify", bad.to_str().unwrap(), "--json"], &root());
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!((v["summary"]["ok"].as_u64(), v["summary"]["rejected"].as_u64()), (Some(0), Some(3)), "{v}");
    let files = v["files"].as_array().unwrap();
    assert_eq!(files.len(), 3);
    assert!(
        files.iter().all(|f| f["verdict"] == "rejected" && f["code"].is_string() && f["reason"].is_string())
    );
}

#[test]
fn one_bad_file_among_good_ones_fails_the_run() {
    let o = chatter(
        &[
            "verify",
            "certificates/valid/doc-example-square.ron",
            "certificates/invalid/shrunk-rectangle.ron",
            "--backend",
            "malachite",
        ],
        &root(),
    );
    assert_eq!(o.status.code(), Some(1));
    let (out, _) = text(&o);
    assert!(out.lines().next().unwrap().contains(": OK"));
    assert!(out.lines().nth(1).unwrap().contains(": REJECTED: "));
}

/// Regression: `chatter verify DIR | head -1` panicked with "failed printing to stdout".
#[test]
fn a_closed_stdout_ends_the_run_quietly() {
    use std::io::{BufRead, BufReader};
    use std::process::Stdio;
    let mut child = Command::new(bin())
        .args(["verify", "certificates/valid", "certificates/invalid"])
        .current_dir(root())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap()).read_line(&mut first).unwrap(); // then drop the pipe
    let out = child.wait_with_output().unwrap();
    assert!(first.contains(": OK ("));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(out.status.code(), Some(141));
}

#[test]
fn classify_shows_the_evidence() {
    let d = tempfile::tempdir().unwrap();
    let o = chatter(&["classify", "--n", "3", "--kappa", "3/20", "--gamma", "0.05"], d.path());
    let (out, err) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    for needle in [
        "CC criterion (S_1 has a real, positive dominant eigenvalue): HOLDS",
        "det(tI - S_1) = t^3 - 147/460 t^2 - 147/460 t + 1/20",
        "PCC is excluded by the paper's Lemma",
        "CC threshold for this kappa: holds for gamma below a threshold in [0.115197810299, 0.115197810301]",
        "float finder, translation seed: found a cone",
        "certificate: CompleteChatterFromAllDown",
    ] {
        assert!(out.contains(needle), "missing {needle:?} in\n{out}");
    }
    // An irrational body is decided exactly in its number field, and certified there (issue 10
    // §2): the PCC criterion holds (real roots), so the claim is CC or PCC.
    let o = chatter(&["classify", "--n", "5", "--kappa", "1/20", "--gamma", "1/100", "--json"], d.path());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert!(v["field"].as_str().unwrap().contains("cos(2*pi/5)"));
    assert_eq!((v["cc"]["holds"].as_bool(), v["pcc"]["holds"].as_bool()), (Some(true), Some(true)), "{v}");
    assert_eq!(v["certificate"]["verdict"], "certified");
    assert_eq!(v["certificate"]["claim"], "CcOrPccFromAllDown");
}

/// Regression (issue 10 §1): `classify` shows the float finder's verdict and a batch of simulated
/// drops for every n; n = 5 used to print neither.
#[test]
fn classify_shows_finder_and_drops_for_irrational_n() {
    let d = tempfile::tempdir().unwrap();
    let o = chatter(&["classify", "--n", "5", "--kappa", "1/200", "--gamma", "1/100"], d.path());
    let (out, err) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    for needle in [
        "CC criterion (S_1 has a real, positive dominant eigenvalue): HOLDS",
        "float finder, translation seed: found a cone",
        "float finder, all-down seed: found a cone",
        "simulation (evidence: 20 random drops in f64, budget 2000 impacts; `chatter simulate --exact` proves): CC 20,",
        "certificate: CcOrPccFromAllDown",
    ] {
        assert!(out.contains(needle), "missing {needle:?} in\n{out}");
    }
    for n in ["7", "8", "12"] {
        let o = chatter(&["classify", "--n", n, "--kappa", "1/50", "--gamma", "1/100", "--json"], d.path());
        assert_eq!(o.status.code(), Some(0), "n = {n}");
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        // Here the finder, the drops and the exact CC criterion agree (n = 12 fails at this kappa).
        let cc = v["cc"]["holds"].as_bool().unwrap();
        assert_eq!(cc, n != "12", "n = {n}: {v}");
        for seed in ["translation", "all_down"] {
            assert_eq!(v["finder"][seed]["outcome"], if cc { "found" } else { "no-cone" }, "n = {n}: {v}");
        }
        assert_eq!(v["drops"]["counts"][if cc { "CC" } else { "ICC" }], 20, "n = {n}: {v}");
    }
}

#[test]
fn classify_the_rod_from_a_rotating_start() {
    let d = tempfile::tempdir().unwrap();
    let run = |g: &str, vel: &str| {
        let o = chatter(
            &["classify", "--n", "2", "--kappa", "1/3", "--gamma", g, "--velocity", vel, "--json"],
            d.path(),
        );
        assert_eq!(o.status.code(), Some(0));
        serde_json::from_slice::<serde_json::Value>(&o.stdout).unwrap()
    };
    let v = run("1/20", "-1,-1");
    assert_eq!(v["goyal"], true);
    assert_eq!(v["from_velocity"]["cc"], true, "pure translation chatters below 7 - 4 sqrt 3");
    assert_eq!(run("1/20", "0.9,-1")["from_velocity"]["cc"], false, "a fast rotation leaves the cone");
    assert_eq!(run("1/10", "-1,-1")["goyal"], false);
    let o = chatter(&["classify", "--n", "3", "--velocity", "1,2"], d.path());
    assert_eq!(o.status.code(), Some(2), "--velocity is for the rod");
}

#[test]
fn bodies_json_has_the_documented_keys() {
    let d = tempfile::tempdir().unwrap();
    let o = chatter(&["bodies", "--json"], d.path());
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["schema"], "chatter.bodies/1");
    let rows = v["bodies"].as_array().unwrap();
    assert!(rows.len() >= 12);
    for r in rows {
        for k in [
            "name",
            "n",
            "kappa",
            "kappa_f64",
            "cc_gamma_max",
            "pcc_gamma_max",
            "cc_gamma_interval",
            "pcc_gamma_interval",
        ] {
            assert!(r.get(k).is_some(), "{k} missing in {r}");
        }
        if let Some([lo, hi]) =
            r["cc_gamma_interval"].as_array().map(|a| [a[0].as_str().unwrap(), a[1].as_str().unwrap()])
        {
            let (lo, hi): (chatter::exact::Q, chatter::exact::Q) = (lo.parse().unwrap(), hi.parse().unwrap());
            let m = r["cc_gamma_max"].as_f64().unwrap();
            assert!(lo.to_f64() <= m && m <= hi.to_f64());
        }
    }
    let cube = rows.iter().find(|r| r["name"].as_str().unwrap().starts_with("cube")).unwrap();
    assert!(cube["cc_gamma_max"].is_null(), "the cube never meets the CC criterion");
    assert_eq!(cube["kappa"], "1/3");
    // User bodies, alone.
    let o = chatter(
        &[
            "bodies", "--only", "--plate", "5", "--prism", "4", "--height", "1/2", "--n", "3", "--kappa",
            "0.15",
        ],
        d.path(),
    );
    let (out, err) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(
        out.contains("flat pentagon plate")
            && out.contains("square prism, height 1/2")
            && out.contains("n = 3, kappa = 3/20")
    );
    let o = chatter(&["bodies", "--prism", "4"], d.path());
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn prove_square_writes_and_checks_the_proof_files() {
    let o = chatter(&["prove", "square", "--check"], &root());
    let (out, err) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{out}{err}");
    assert!(
        out.contains("kernel check OK (malachite + num-rational)")
            && out.contains("inequalities 100, invariance 100, pipeline 100"),
        "{out}"
    );
    let d = tempfile::tempdir().unwrap();
    let o = chatter(&["prove", "square", "--out", "p", "--points", "5", "--json"], d.path());
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["verdict"], "accepted");
    assert_eq!(v["producer_problems"].as_array().map(Vec::len), Some(0));
    assert_eq!(v["cross_check"]["points"], 5);
    assert!(d.path().join("p/square.md").exists() && d.path().join("p/square.ron").exists());
    // --check against files from another seed reports them stale.
    let o = chatter(&["prove", "square", "--out", "p", "--check"], d.path());
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o).0.contains("stale: p/square.md"));
}

/// Issue 10 §2: `certify --body NAME` takes a catalogue body with its exact kappa, rational or in
/// Q(cos 2 pi/n); a body whose kappa no certificate can name is a usage error.
#[test]
fn certify_a_catalogue_body_by_name() {
    let d = tempfile::tempdir().unwrap();
    let o = chatter(&["certify", "--body", "square plate", "--gamma", "1/100", "--json"], d.path());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!((o.status.code(), &v["verdict"]), (Some(0), &serde_json::json!("certified")), "{v}");
    assert_eq!((v["n"].as_u64(), v["kappa_field"].is_null()), (Some(4), true), "{v}");
    let o = chatter(&["certify", "--body", "dodecahedron", "--gamma", "1/100", "--json"], d.path());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!((v["n"].as_u64(), &v["kappa_field"]), (Some(5), &serde_json::json!("19/30 + 2/3*c")), "{v}");
    assert_eq!(v["verdict"], "not-certified", "the dodecahedron's CC criterion never holds: {v}");
    let o = chatter(&["certify", "--body", "icosahedron", "--gamma", "1/100"], d.path());
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("no certificate can name it"), "{err}");
}
