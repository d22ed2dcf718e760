//! One regression test per reported bug (ripgrep style), named after the issue.

use crate::common::{bin, q};
use chatter::certify::{ClaimChoice, Failure, Request, certify};
use chatter::cli::{Cli, Env, Outcome, run};
use chatter::exact::Q;
use chatter::exact::QField;
use chatter_kernel::certificate::{Claim, Code, Locus};
use chatter_kernel::check::check;
use chatter_kernel::exact::{Field, OrderedField, Ring};
use chatter_kernel::model::{Rod, Shape};
use chatter_kernel::verify::{Backend, Kinds, MALACHITE, Verdict, verify};
use clap::Parser;
use num_bigint::BigInt;
use num_rational::BigRational;
use std::cmp::Ordering;
use std::fmt;
use std::process::Command;

/// A deliberately wrong backend: num-rational with every sign reversed.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Debug)]
struct Liar(BigRational);

impl fmt::Display for Liar {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
}

impl Ring for Liar {
    fn zero() -> Self {
        Liar(BigRational::zero())
    }
    fn from_i64(v: i64) -> Self {
        Liar(BigRational::from_i64(v))
    }
    fn plus(&self, o: &Self) -> Self {
        Liar(self.0.plus(&o.0))
    }
    fn minus(&self, o: &Self) -> Self {
        Liar(self.0.minus(&o.0))
    }
    fn times(&self, o: &Self) -> Self {
        Liar(self.0.times(&o.0))
    }
    fn negated(&self) -> Self {
        Liar(self.0.negated())
    }
    fn sign(&self) -> Ordering {
        self.0.sign().reverse()
    }
}

impl OrderedField for Liar {
    fn over(&self, o: &Self) -> Option<Self> {
        self.0.over(&o.0).map(Liar)
    }
    fn from_ratio(n: i64, d: i64) -> Self {
        Liar(BigRational::from_ratio(n, d))
    }
}

impl QField for Liar {
    fn from_q(x: &Q) -> Self {
        Liar(BigRational::from_q(x))
    }
    fn enclose(&self, width: &Q) -> (Q, Q) {
        self.0.enclose(width)
    }
}

impl Field for Liar {
    type Int = BigInt;
    const BACKEND: &'static str = "liar";
    fn from_fraction(n: &BigInt, d: &BigInt) -> Self {
        Liar(BigRational::from_fraction(n, d))
    }
    fn numer(&self) -> BigInt {
        Field::numer(&self.0)
    }
    fn denom(&self) -> BigInt {
        Field::denom(&self.0)
    }
}

const LIAR: Backend = Backend { name: "liar", check: check::<Liar>, kinds: Kinds::of::<Liar>() };

fn outcome(args: &[&str], env: &Env) -> Outcome {
    let mut argv = vec!["chatter"];
    argv.extend_from_slice(args);
    run(Cli::try_parse_from(argv).expect("valid arguments"), env)
}

#[test]
fn issue8_a_wrong_backend_is_an_internal_error_in_verify_and_certify() {
    let liar = Env { backends: [MALACHITE, LIAR] };
    let d = tempfile::tempdir().unwrap();
    let path = d.path().join("sq.ron");
    let path = path.to_str().unwrap();
    assert_eq!(outcome(&["certify", "-o", path], &Env::default()), Outcome::Success);
    let o = outcome(&["verify", path], &liar);
    assert!(matches!(o, Outcome::Internal(_)), "{o:?}");
    assert_eq!(o.exit_code(), 3);
    let o = outcome(&["certify", "-o", &format!("{path}.2")], &liar);
    assert!(matches!(o, Outcome::Internal(_)), "{o:?}");
    assert_eq!(o.exit_code(), 3);
    // Each backend alone gives a verdict; only their disagreement is an internal error.
    assert_eq!(outcome(&["verify", "--backend", "malachite", path], &liar), Outcome::Success);
}

/// `chatter certify ARGS` as a process: (exit status, stdout).
fn certify_cli(args: &[&str]) -> (Option<i32>, String) {
    let o = Command::new(bin()).arg("certify").args(args).output().expect("run chatter");
    (o.status.code(), String::from_utf8_lossy(&o.stdout).into_owned())
}

#[test]
fn issue8_rod_above_the_all_down_limit_is_not_certified_without_a_panic() {
    // kappa (1 + 2 gamma) >= 1: the all-down drop (-1, 0) leaves with v >= 0.
    for (k, g) in [("1", "1/10"), ("1/2", "1/2"), ("3", "1/100"), ("1", "99/100")] {
        let (code, out) = certify_cli(&["--n", "2", "--kappa", k, "--gamma", g]);
        assert_eq!(code, Some(1), "kappa={k} gamma={g}: {out}");
        assert!(out.starts_with("NOT CERTIFIED"), "{out}");
        let r = certify(&Request { claim: ClaimChoice::Exactly(Claim::CcOrPccFromAllDown), ..req(2, k, g) });
        assert!(matches!(r.result, Err(Failure::SeedNotBelow { .. })), "kappa={k} gamma={g}: {:?}", r.result);
    }
    let o = Command::new(bin())
        .args(["classify", "--n", "2", "--kappa", "1", "--gamma", "1/10"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
}

fn req(n: u64, kappa: &str, gamma: &str) -> Request {
    Request::new(n, q(kappa), q(gamma))
}

#[test]
fn issue8_rod_on_goyals_boundary_is_certified_with_the_papers_cone() {
    // sqrt(kappa) = 2/(sqrt(gamma) + 1) - 1 exactly: kappa = 1/4, gamma = 1/9 and
    // kappa = 1/9, gamma = 1/4 (sqrt: 1/3 = 2/(3/2) - 1).
    for (k, g) in [("1/4", "1/9"), ("1/9", "1/4")] {
        let Shape::Rod(rod) = Shape::new(2, q(k), q(g)).unwrap() else { unreachable!() };
        let s = rod.step();
        let (tr, det) = (&s[0][0] + &s[1][1], &(&s[0][0] * &s[1][1]) - &(&s[0][1] * &s[1][0]));
        assert_eq!(&tr * &tr, &Q::int(4) * &det, "a double eigenvalue: Goyal's boundary");
        let r = certify(&req(2, k, g));
        let cert = r.result.unwrap_or_else(|e| panic!("kappa={k} gamma={g}: {e}"));
        assert_eq!(cert.claim, Claim::CompleteChatterFromAllDown);
        assert_eq!(r.method, Some("exact eigenvectors: the paper's two-ray cone {p_min, R p_min}"));
        assert!(matches!(verify(&cert, Default::default()), Verdict::Accepted(_)));
    }
    // Just beyond the boundary there is no cone.
    let r = certify(&req(2, "1/4", "1001/9000"));
    assert!(matches!(r.result, Err(Failure::Finder(_))), "{:?}", r.result);
    let _ = Rod::new(q("1/4"), q("1/9")).unwrap();
}

#[test]
fn issue8_gamma_one_does_not_claim_all_eigenvalues_real() {
    let (code, out) = certify_cli(&["--gamma", "1"]);
    assert_eq!(code, Some(1), "{out}");
    assert!(!out.contains("contradicts the paper"), "{out}");
    assert!(!out.contains("real roots"), "{out}");
    // Since issue 9 the claims about drops are refused at gamma = 1 before the Lemma is tried;
    // the Lemma itself still fails by the modulus there.
    assert!(out.contains("0 < gamma < 1"), "{out}");
    let b = chatter_kernel::model::Polygon::new(4, q("1/6"), q("1")).unwrap();
    let quad = chatter_kernel::model::pcc_quadratic(&b).unwrap();
    assert_eq!(quad.exclusion(), chatter_kernel::model::PccExclusion::ModulusNotBelowOne);
    // Where the roots are real for n >= 4, the contradiction with the paper is reported.
    let (_, out) = certify_cli(&["--gamma", "1/1000"]);
    assert!(out.contains("real roots") && out.contains("contradicts the paper"), "{out}");
}

#[test]
fn issue8_rejections_carry_a_structured_locus() {
    let text =
        std::fs::read_to_string(crate::common::root().join("certificates/invalid/shrunk-rectangle.ron"))
            .unwrap();
    let Verdict::Rejected(r) = chatter_kernel::verify::verify_text(&text, Default::default(), &[MALACHITE])
    else {
        panic!("rejected")
    };
    assert_eq!(r.code, Code::ImageOutside);
    assert!(
        matches!(r.locus, Locus::Piece { piece: 1, vertex: 0, outside: Some(_), corner: None }),
        "{:?}",
        r.locus
    );
}

#[test]
fn issue8_long_numbers_are_abbreviated_in_rejections() {
    // The documented shrunk rectangle, with -4/9 replaced by a 1,200-digit neighbour.
    let text =
        std::fs::read_to_string(crate::common::root().join("certificates/invalid/shrunk-rectangle.ron"))
            .unwrap();
    let big = format!("-4{}1/9{}", "0".repeat(600), "0".repeat(600));
    let text = text.replace("\"-4/9\"", &format!("\"{big}\""));
    let Verdict::Rejected(r) = chatter_kernel::verify::verify_text(&text, Default::default(), &[MALACHITE])
    else {
        panic!("rejected")
    };
    assert_eq!(r.code, Code::ImageOutside);
    assert!(r.message().len() < 300, "{} characters: {}", r.message().len(), r.message());
    assert!(
        r.message().contains("characters)"),
        "the long numbers are marked as abbreviated: {}",
        r.message()
    );
}

#[test]
fn issue11_a_rod_box_checks_r2_at_every_corner_before_r3() {
    // Found by the structure-aware smoke test: at the corner kappa = 1/3 only R3 fails, at
    // kappa = 13/30 R2 fails; the documented order (R2 at every corner, then R3) reports R2. (That
    // both rules fail is decided by the oracle in oracle/tests/all/rules.rs.)
    let text = std::fs::read_to_string(
        crate::common::root().join("certificates/valid/n2-kappa1_3-gamma7_100-effectively-invariant.ron"),
    )
    .unwrap();
    let text = text
        .replace("version: 1", "version: 2")
        .replace("kappa: \"1/3\"", "kappa: [\"1/3\", \"13/30\"]")
        .replace("claim: EffectivelyInvariant", "claim: CcOrPccFromAllDown");
    let cert = chatter_kernel::certificate::read(&text).unwrap();
    let Verdict::Rejected(r) = verify(&cert, Default::default()) else { panic!() };
    assert_eq!(r.code, Code::ImageOutside, "{r}");
    assert!(matches!(r.locus, Locus::Piece { corner: Some(1), .. }), "{:?}", r.locus);
}

/// `chatter` with `args` in `dir`: stdout, and the exit status.
fn chatter_in(dir: &std::path::Path, args: &[&str]) -> (String, i32) {
    let out = Command::new(bin()).args(args).current_dir(dir).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(out.status.code().is_some(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    (text, out.status.code().unwrap())
}

#[test]
fn issue24_a_cone_entry_is_proved_no_icc_no_pcc_and_not_cc() {
    // The reviewer's drop: it enters a kernel-checked cone at its first impact, which proves
    // v <= 0 for ever and no PCC, not that the impacts accumulate at a finite time (CC). The
    // reviewer's point (κ 3/20, γ 1/20) has had a time-to-rest certificate since 2026-11-27, which
    // proves CC there, and (3/20, 3/50) since the merged graphs of the same day; (9/64, 1/8) has
    // none, and its drops settle into no cycle an orbit certificate is made for.
    use chatter::simulate::{Decision, Initial, Model, Options, SetKind, Shape, simulate_with};
    let d = tempfile::tempdir().unwrap();
    let args = ["simulate", "--n", "3", "--kappa", "9/64", "--gamma", "1/8", "--exact"];
    let (text, code) = chatter_in(d.path(), &args);
    assert_eq!(code, 0, "{text}");
    assert!(
        text.contains(
            "outcome: no ICC, no PCC (proved; CC not proved: finite accumulation time not derived, \
             docs/time-to-rest.md; evidence: CC after 1 impact"
        ),
        "{text}"
    );
    assert!(!text.contains("outcome: CC"), "{text}");
    let (json, code) = chatter_in(d.path(), &[&args[..], &["--json"]].concat());
    assert_eq!(code, 0, "{json}");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(v["outcome"], "no-ICC-no-PCC", "{json}");
    assert_eq!((v["proved"].as_bool(), v["basis"].as_str()), (Some(true), Some("proof")));
    assert_eq!(v["evidence"]["outcome"], "CC", "the evidence stays visible as evidence");
    assert_eq!(
        (v["entered"]["kind"].as_str(), v["entered"]["finite_time"].as_bool()),
        (Some("cone"), Some(false))
    );
    assert!(v["entered"]["time_to_rest_bound"].is_null(), "a cone bounds no time: {json}");
    // The library says the same.
    let model = Model::new(Shape::Polygon(3), q("9/64"), q("1/8")).unwrap();
    let sets = chatter::prove::made(&model);
    let initial = Initial::RandomDrop { seed: 0 };
    let run = simulate_with(
        &model,
        &initial,
        chatter::simulate::Arithmetic::Exact,
        &Options::new(200),
        Some(&sets),
    );
    assert_eq!(
        (run.outcome, run.proved, run.evidence),
        (chatter::simulate::Outcome::NoIccNoPcc, true, chatter::simulate::Outcome::Cc)
    );
    assert!(
        matches!(run.decision, Decision::Certified { after: 1, kind: SetKind::Cone, .. }),
        "{:?}",
        run.decision
    );
    // A batch counts it apart from CC: proved no-ICC-no-PCC, evidence CC.
    let (json, code) = chatter_in(d.path(), &[&args[..], &["--runs", "4", "--json"]].concat());
    assert_eq!(code, 0, "{json}");
    let b: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(
        (b["proved"]["CC"].as_u64(), b["proved"]["no-ICC-no-PCC"].as_u64()),
        (Some(0), Some(4)),
        "{json}"
    );
    assert_eq!((b["counts"]["CC"].as_u64(), b["counts"]["no-ICC-no-PCC"].as_u64()), (Some(0), Some(4)));
    assert_eq!(b["evidence"]["CC"], 4);
    assert!(b["evidence"].get("no-ICC-no-PCC").is_none(), "never evidence: {json}");
}

#[test]
fn issue24_an_orbit_entry_is_proved_cc_with_a_finite_time() {
    // n = 5 has no cone excluding PCC here; an orbit certificate is made on the fly and the exact
    // drop enters its set X after 5 impacts: CC, the impacts accumulating at a finite time.
    let d = tempfile::tempdir().unwrap();
    let args =
        ["simulate", "--n", "5", "--kappa", "1/200", "--gamma", "1/100", "--impacts", "300", "--exact"];
    let (text, code) = chatter_in(d.path(), &args);
    assert_eq!(code, 0, "{text}");
    assert!(
        text.contains("outcome: CC (proved)") && text.contains("kernel-checked orbit certificate"),
        "{text}"
    );
    let (json, code) = chatter_in(d.path(), &[&args[..], &["--json"]].concat());
    assert_eq!(code, 0, "{json}");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!((v["outcome"].as_str(), v["proved"].as_bool()), (Some("CC"), Some(true)), "{json}");
    assert_eq!(v["entered"]["kind"], "orbit");
    // The pattern is the shortest repeated word of steps, 4 (the drop's cycle of contacts repeats
    // it five times; certified as 4,4,4,4,4 before issue 24 §2, entered after 6 impacts then).
    assert_eq!(v["entered"]["impact"], 5);
    assert_eq!(v["entered"]["certificate"], "orbit certificate made on the fly (pattern 4)");
    assert_eq!(v["entered"]["finite_time"], true);
}

#[test]
fn issue24_map_columns_count_cone_entries_apart_from_cc() {
    // One point (kappa = 9/64, gamma = 1/8) with a CompleteChatterFromAllDown certificate and no
    // time-to-rest certificate: its three drops enter the cone at their first impact, so they are
    // proved no-ICC-no-PCC, not CC. (Until the merged graphs of 2026-11-27 the point was
    // (3/20, 3/50), which now has a time-to-rest certificate.)
    use chatter::sweep::table::{HEADER, parse_csv};
    let d = tempfile::tempdir().unwrap();
    let args = [
        "map",
        "--n",
        "3",
        "--kappa",
        "0.125:0.15625:1",
        "--gamma",
        "0.1:0.15:1",
        "--certify",
        "--simulate",
        "3",
        "--out",
        "m",
    ];
    let (text, code) = chatter_in(d.path(), &args);
    assert_eq!(code, 0, "{text}");
    let csv = std::fs::read_to_string(d.path().join("m/points.csv")).unwrap();
    let header: Vec<&str> = HEADER.split(',').collect();
    let at =
        |name: &str| header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("no column {name}"));
    assert_eq!(at("sim_no_icc_no_pcc_proved"), at("sim_cc_proved") + 1);
    let line: Vec<&str> = csv.lines().nth(1).unwrap().split(',').collect();
    assert_eq!(line[at("claim")], "CompleteChatterFromAllDown");
    assert_eq!(line[at("sim_cc_evidence")], "3", "the f64 evidence is CC");
    assert_eq!((line[at("sim_cc_proved")], line[at("sim_no_icc_no_pcc_proved")]), ("0", "3"), "{csv}");
    assert_eq!(line[at("sim_contradicted")], "0", "no-ICC-no-PCC does not contradict CC evidence");
    let rows = parse_csv(&csv).unwrap();
    let proved = rows[0].sim.as_ref().unwrap().proved.unwrap();
    assert_eq!(proved[chatter::simulate::Outcome::NoIccNoPcc.index()], 3);
    assert_eq!(rows[0].to_csv(), csv.lines().nth(1).unwrap(), "the row reads back");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.path().join("m/summary.json")).unwrap()).unwrap();
    assert_eq!(
        (s["counts"]["drops_proved"]["CC"].as_u64(), s["counts"]["drops_proved"]["no-ICC-no-PCC"].as_u64()),
        (Some(0), Some(3))
    );
    assert_eq!(s["disagreement_kinds"]["evidence-cc-unproved"]["points"], 1);
    assert!(text.contains("drops_proved: CC 0, ICC 0, PCC 0, no-ICC-no-PCC 3"), "{text}");
}

#[test]
fn issue_25_certify_with_a_body_file_uses_the_gamma_of_the_command_line() {
    // Regression (issue 25): `certify --body FILE --gamma G` used the file's gamma (1/20).
    let lander = concat!(env!("CARGO_MANIFEST_DIR"), "/certificates/bodies/lander.ron");
    let run = |args: &[&str]| {
        let o = Command::new(bin()).args(args).output().expect("run chatter");
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let out = run(&["certify", "--body", lander, "--gamma", "1/100"]);
    assert!(out.contains("gamma=1/100 claim=CcOrPccFromAllDown"), "{out}");
    // Without --gamma the file's gamma (1/20) is used.
    let out = run(&["certify", "--body", lander]);
    assert!(out.contains("gamma=1/20 claim=CompleteChatterFromAllDown"), "{out}");
}

#[test]
fn a_body_files_gamma_yields_to_the_command_lines_in_simulate_and_classify() {
    // Issue 25 §2: `--body FILE --gamma G` uses G in every command that takes a body file.
    let lander = concat!(env!("CARGO_MANIFEST_DIR"), "/certificates/bodies/lander.ron");
    let run = |args: &[&str]| {
        let o = Command::new(bin()).args(args).output().expect("run chatter");
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let out = run(&["simulate", "--body", lander, "--gamma", "1/100", "--runs", "1"]);
    assert!(out.contains("n=3 gamma=1/100,"), "{out}");
    let out = run(&["simulate", "--body", lander, "--runs", "1"]);
    assert!(out.contains("n=3 gamma=1/20,"), "{out}");
    let out = run(&["classify", "--body", lander, "--gamma", "1/100"]);
    assert!(out.contains("3 contacts, gamma = 1/100 "), "{out}");
    let out = run(&["classify", "--body", lander]);
    assert!(out.contains("3 contacts, gamma = 1/20 "), "{out}");
}
