//! Orbit certificates in `classify` and `reproduce` (issue 15): where the CC criterion fails but
//! drops end in CC, `classify` tries an orbit certificate, says what it proves and that it
//! refutes Conjecture 1 (i) ⇒ (iii) there, or why none was made; the reproduction report states
//! the refutation with the certificate it wrote, and that file verifies on both backends.

use crate::common::{bin, q, root};
use chatter::orbit::Request;
use chatter::report::Verdict as ReportVerdict;
use chatter::report::classify::{ClassifyRequest, classify};
use chatter::report::classify_orbit::{ORBIT_DEPTH, ORBIT_DROPS, attempt, orbit_attempt};
use chatter_kernel::certificate::Claim;
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify_text};
use serde_json::Value;
use std::path::Path;
use std::process::{Command, Output};

fn chatter(args: &[&str], dir: &Path) -> Output {
    Command::new(bin()).args(args).current_dir(dir).output().unwrap()
}

/// The file is accepted by the kernel on both backends as an orbit certificate; its sub-box count.
fn verifies(path: &Path) -> usize {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    match verify_text(&text, ParseLimits::default(), &[MALACHITE, NUM]) {
        Verdict::Accepted(a) => {
            assert_eq!(a.claim, Claim::CompleteChatterFromSet);
            a.orbit_boxes.expect("an orbit certificate counts its sub-boxes")
        }
        other => panic!("{}: {other:?}", path.display()),
    }
}

/// Validates a classify document against the committed schema.
fn valid_classify(v: &Value) {
    let path = root().join("docs/schema/chatter.classify.v1.schema.json");
    let schema: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let validator = jsonschema::validator_for(&schema).unwrap();
    let errors: Vec<String> =
        validator.iter_errors(v).map(|e| format!("{e} at {}", e.instance_path())).collect();
    assert!(errors.is_empty(), "{errors:#?}");
}

#[test]
fn classify_at_the_band_point_says_refuted_and_writes_a_certificate_the_kernel_accepts() {
    let d = tempfile::tempdir().unwrap();
    let args = ["classify", "--n", "3", "--kappa", "1/8", "--gamma", "3/20"];
    let o = chatter(&[&args[..], &["--json", "--orbit-out", "orbit.ron"]].concat(), d.path());
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!((v["cc"]["holds"].as_bool(), v["cc"]["dominant"].as_str()), (Some(false), Some("negative")));
    assert!(v["drops"]["counts"]["CC"].as_u64().unwrap() > 0);
    let orbit = &v["orbit"];
    valid_classify(&v);
    assert_eq!(orbit["verdict"], "certified", "{orbit}");
    assert_eq!(orbit["claim"], "CompleteChatterFromSet");
    assert_eq!(orbit["conjecture_1_refuted"], true);
    assert_eq!(
        orbit["conjecture_1"],
        "the paper's Conjecture 1 ((i) CC possible ⇒ (iii) S_1 criterion) is false here: CC is possible (proved from X) but S_1's dominant eigenvalue is negative"
    );
    assert!(orbit["proves"].as_str().unwrap().contains("not proved: CC from every drop"), "{orbit}");
    assert_eq!(orbit["backends"], serde_json::json!(["malachite", "num-rational"]));
    assert_eq!(orbit["failure"], Value::Null);
    assert_eq!(orbit["file"], "orbit.ron");
    let pattern: Vec<u64> = serde_json::from_value(orbit["pattern"].clone()).unwrap();
    let mut sorted = pattern.clone();
    sorted.sort_unstable();
    assert_eq!(sorted, [1, 1, 2, 2], "a phase of the cycle S_2 S_2 S_1 S_1");
    assert_eq!(orbit["set"]["kind"], "parallelepiped");
    let delta = q(orbit["set"]["delta"]["exact"].as_str().unwrap());
    assert!(delta > q("0") && delta <= q("1/16"), "{delta}");
    let eig = orbit["cycle"]["eigenvalues"].as_array().unwrap();
    assert!(eig.iter().all(|l| l.as_f64().unwrap().abs() < 1.0), "{eig:?}");
    // The written file is the kernel's to judge, not the producer's.
    let boxes = verifies(&d.path().join("orbit.ron"));
    assert_eq!(orbit["sub_boxes"].as_u64(), Some(boxes as u64));
    let o = chatter(&["verify", "orbit.ron"], d.path());
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stdout));

    // The text output: a labelled section with the claim, its limits and the conjecture.
    let o = chatter(&args, d.path());
    let text = String::from_utf8_lossy(&o.stdout);
    for needle in [
        "orbit certificate (docs/orbit-certificates.md): CC proved from an explicit set X of post-impact states (not from every drop); accepted by the kernel on both backends (malachite + num-rational)",
        "X = x* + A [-delta, delta]^3 with delta = ",
        "bounds rho = ",
        "every motion whose state right after an impact lies in X",
        "not proved: CC from every drop",
        "the paper's Conjecture 1 ((i) CC possible ⇒ (iii) S_1 criterion) is false here: CC is possible (proved from X) but S_1's dominant eigenvalue is negative.",
        "`--orbit-out FILE` writes it",
    ] {
        assert!(text.contains(needle), "missing {needle:?} in\n{text}");
    }
}

#[test]
fn classify_where_the_criterion_holds_does_not_try_an_orbit() {
    // Below the threshold (and for the rod): no orbit field, no orbit section.
    for (n, kappa, gamma) in [(3, "1/8", "1/20"), (4, "1/6", "1/100"), (2, "1/3", "1/20")] {
        let r = classify(&ClassifyRequest::new(n, q(kappa), q(gamma))).unwrap();
        assert!(r.orbit.is_none(), "n = {n}, kappa = {kappa}, gamma = {gamma}");
        assert!(!r.lines().iter().any(|l| l.contains("orbit certificate")));
        let v = chatter::report::to_value(&r);
        assert!(v.get("orbit").is_none(), "{v}");
    }
    // Above the band (κ = 1/8, γ = 0.2) every drop ends in ICC: nothing to certify either.
    let r = classify(&ClassifyRequest::new(3, q("1/8"), q("1/5"))).unwrap();
    assert!(!r.cc.holds);
    assert_eq!(r.drops.as_ref().unwrap().counts.get("CC"), Some(&0));
    assert!(r.orbit.is_none());
    // --orbit-out where there is no orbit certificate writes nothing and says so.
    let d = tempfile::tempdir().unwrap();
    let o = chatter(
        &["classify", "--n", "3", "--kappa", "1/8", "--gamma", "1/20", "--orbit-out", "orbit.ron"],
        d.path(),
    );
    assert_eq!(o.status.code(), Some(0));
    assert!(
        String::from_utf8_lossy(&o.stdout)
            .contains("--orbit-out: no orbit certificate, orbit.ron not written")
    );
    assert!(!d.path().join("orbit.ron").exists());
}

#[test]
fn a_failed_orbit_attempt_reports_its_reason_and_claims_nothing() {
    // Every point of the n = 3 band where drops end in CC gets a certificate (docs/orbit-certificates.md
    // §5), so the failure is made at the band point by a pattern no drop follows: the fixed point
    // of its return map breaks the pattern (condition 1), and the report says so.
    let r = classify(&ClassifyRequest::new(3, q("1/8"), q("3/20"))).unwrap();
    let drops = r.drops.clone().unwrap();
    let req = Request {
        n: 3,
        kappa: q("1/8"),
        gamma: q("3/20"),
        pattern: Some(vec![1, 2]),
        drops: ORBIT_DROPS,
        max_depth: ORBIT_DEPTH,
    };
    let o = attempt(req, &r.cc, &drops);
    assert_eq!(o.verdict, ReportVerdict::NotCertified);
    assert_eq!(o.failure, Some("pattern-not-stable"), "{o:?}");
    assert!(o.reason.as_ref().unwrap().contains("breaks the pattern"), "{o:?}");
    assert_eq!(o.pattern, Some(vec![1, 2]));
    assert!(!o.conjecture_1_refuted);
    assert_eq!(
        o.conjecture_1,
        "not decided by a certificate here: 20 of 20 drops end in CC although the CC criterion fails, evidence against Conjecture 1 (i) ⇒ (iii) but not a proof"
    );
    assert!(o.certificate.is_none() && o.set.is_none() && o.sub_boxes.is_none() && o.backends.is_empty());
    // The report carries it: text, and JSON valid against the committed schema.
    let mut failed = r.clone();
    failed.orbit = Some(o.clone());
    let lines = failed.lines().join("\n");
    assert!(
        lines.contains("orbit certificate (docs/orbit-certificates.md): none (pattern 1,2 from the simulated drops): pattern not stable over the set"),
        "{lines}"
    );
    assert!(lines.contains("  Conjecture 1: not decided by a certificate here"));
    let v = chatter::report::to_value(&failed);
    assert_eq!(v["orbit"]["verdict"], "not-certified");
    assert_eq!(v["orbit"]["failure"], "pattern-not-stable");
    assert_eq!(v["orbit"]["conjecture_1_refuted"], false);
    valid_classify(&v);

    // No CC drop and no cycle in the producer's own drops (every drop ICC at γ = 1/5), or the
    // criterion holds: nothing is tried.
    let r = classify(&ClassifyRequest::new(3, q("1/8"), q("1/5"))).unwrap();
    let mut none = r.drops.clone().unwrap();
    none.counts.insert("CC".into(), 0);
    assert!(orbit_attempt(3, &q("1/8"), &q("1/5"), &r.cc, Some(&none)).is_none());
}

#[test]
fn classify_at_the_pentagon_band_point_certifies_its_cycle_and_says_conjecture_1_fails_for_n_5() {
    // Issue 22: about 2% of drops at n = 5, κ = 961/25600, γ = 61/160 settle into a cycle of 6
    // impacts; classify's 20 evidence drops may all miss it, its pattern search does not.
    let d = tempfile::tempdir().unwrap();
    let args = ["classify", "--n", "5", "--kappa", "961/25600", "--gamma", "61/160"];
    let o = chatter(&[&args[..], &["--json", "--orbit-out", "pentagon.ron"]].concat(), d.path());
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    valid_classify(&v);
    assert_eq!(v["cc"]["holds"].as_bool(), Some(false), "S_1's criterion fails, decided exactly");
    let orbit = &v["orbit"];
    assert_eq!(orbit["verdict"], "certified", "{orbit}");
    assert_eq!(orbit["conjecture_1_refuted"], true);
    assert!(orbit["conjecture_1"].as_str().unwrap().starts_with("the paper's Conjecture 1"), "{orbit}");
    let mut pattern: Vec<u64> =
        orbit["pattern"].as_array().unwrap().iter().map(|x| x.as_u64().unwrap()).collect();
    pattern.sort();
    assert_eq!(pattern, vec![1, 1, 2, 3, 4, 4], "a phase of the 6-impact cycle 1,1,2,4,4,3");
    assert!(verifies(&d.path().join("pentagon.ron")) >= 1);
    let text = chatter(&args, d.path());
    let lines = String::from_utf8_lossy(&text.stdout);
    assert!(lines.contains("Conjecture 1 ((i) CC possible ⇒ (iii) S_1 criterion) is false here"), "{lines}");
}

/// Called by the existing `reproduce --quick` test (tests/all/reproduce.rs) on its output folder:
/// the band item states the refutation with the certificate's file name and S_1's exact evidence,
/// in report.md and report.html, and the file verifies on both backends.
pub fn check_reproduce_output(out: &Path) {
    let rel = "certificates/orbit-n3-kappa1_8-gamma3_20.ron";
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    // The band item's section of report.md: marked "differs", led by the refutation.
    let start =
        md.find("The n = 3 band above the threshold where drops still chatter — **differs**").unwrap();
    let band = &md[start..md[start..].find("\n## ").map_or(md.len(), |e| start + e)];
    let statement = format!(
        "Conjecture 1 (i) ⇒ (iii) is refuted at κ = 1/8, γ = 3/20 by the certificate `{rel}`: CC is possible (proved from X), but S₁'s dominant eigenvalue is negative (the CC criterion (iii) fails)"
    );
    let ours = format!(
        "- Ours: Conjecture 1 (i) ⇒ (iii) is refuted at κ = 1/8, γ = 0.15: the orbit certificate `{rel}`, accepted by the kernel on both backends, proves CC from an explicit set of post-impact states (not from every drop), while S₁'s dominant eigenvalue is real and negative (criterion fails)"
    );
    let verify = format!("- Shown by: `chatter verify {rel}`");
    for needle in [
        ours.as_str(),
        statement.as_str(),
        "det(tI − S₁) = t^3",
        "dominant: real and negative",
        "claim CompleteChatterFromSet",
        "accepted by the kernel on both backends (malachite and num-rational)",
        "not proved: CC from every drop",
        verify.as_str(),
    ] {
        assert!(band.contains(needle), "report.md's band item lacks {needle:?}:\n{band}");
        // report.html: the same text, escaped, with `code` spans as <code>.
        let escaped = needle.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;");
        let mut parts = escaped.split('`');
        let mut html_needle = parts.next().unwrap().to_string();
        for (i, p) in parts.enumerate() {
            html_needle.push_str(if i % 2 == 0 { "<code>" } else { "</code>" });
            html_needle.push_str(p);
        }
        let html_needle = html_needle.trim_start_matches("- Ours: ").trim_start_matches("- Shown by: ");
        assert!(html.contains(html_needle), "report.html lacks {html_needle:?}");
    }
    assert!(html.contains("4. The n = 3 band above the threshold where drops still chatter <span class=\"verdict differs\">differs</span>"));
    assert!(verifies(&out.join(rel)) >= 1);
}
