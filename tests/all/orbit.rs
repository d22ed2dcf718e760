//! Orbit certificates (issue 15, docs/orbit-certificates.md): the producer's certificate for the
//! triangle above its CC threshold is accepted on both backends; tampered files are rejected with
//! the code of the condition they break; the kernel's exact return map agrees with the simulator.

use crate::common::root;
use chatter::exact::{ParseLimits, Q};
use chatter::orbit::{Request, certify_orbit};
use chatter::simulate::{Engine, ExactEngine, Model, Shape, Step};
use chatter::write::write_orbit;
use chatter_kernel::certificate::{
    Claim, Code, Encoding, KindLocus, Locus, OrbitCertificate, OrbitSet, read_orbit,
};
use chatter_kernel::exact::{OrderedField, Ring, parse_canonical};
use chatter_kernel::model::Polygon;
use chatter_kernel::orbit::return_map;
use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify_orbit, verify_orbit_on, verify_text};

const VALID: &str = "certificates/valid/orbit-n3-kappa1_8-gamma3_20.ron";

fn valid() -> OrbitCertificate {
    read_orbit(&std::fs::read_to_string(root().join(VALID)).unwrap(), Encoding::Ron).unwrap()
}

fn rejected(cert: &OrbitCertificate) -> chatter_kernel::certificate::Rejection {
    match verify_orbit(cert, ParseLimits::default()) {
        Verdict::Rejected(r) => r,
        other => panic!("expected a rejection on both backends, got {other:?}"),
    }
}

fn q(s: &str) -> Q {
    parse_canonical(s, ParseLimits::default()).unwrap()
}

#[test]
fn the_triangle_band_point_gets_an_orbit_certificate_accepted_on_both_backends() {
    let req = Request {
        n: 3,
        kappa: Q::new(1, 8),
        gamma: Q::new(3, 20),
        pattern: Some(vec![2, 2, 1, 1]),
        drops: 0,
        max_depth: 1,
    };
    let found = certify_orbit(&req, &[MALACHITE, NUM]).expect("certified");
    let cert = &found.certificate;
    assert_eq!(cert.claim, Claim::CompleteChatterFromSet);
    assert_eq!(cert.pattern, vec![2, 2, 1, 1]);
    // The floating-point evidence of docs/orbit-certificates.md §5.
    let expected = [0.81970, 0.55431, 0.45437];
    for (l, e) in found.eigenvalues.iter().zip(expected) {
        assert!((l - e).abs() < 1e-4, "eigenvalues {:?}", found.eigenvalues);
    }
    assert!((found.scales[2] - 0.55431).abs() < 1e-4, "alpha/beta = {}", found.scales[2]);
    // Each backend alone and both together accept, with the same report; the text round-trips.
    let both = verify_orbit(cert, ParseLimits::default());
    let Verdict::Accepted(a) = &both else { panic!("{both:?}") };
    assert_eq!(a.orbit_boxes, Some(found.boxes));
    assert!(found.boxes >= 1);
    for b in [MALACHITE, NUM] {
        assert_eq!(verify_orbit_on(cert, ParseLimits::default(), &[b]), both);
    }
    let text = write_orbit(cert);
    assert_eq!(read_orbit(&text, Encoding::Ron).unwrap(), *cert);
    assert_eq!(verify_text(&text, ParseLimits::default(), &[MALACHITE, NUM]), both);
}

#[test]
fn the_valid_corpus_file_is_accepted_and_tampering_is_rejected_with_the_condition_code() {
    assert!(matches!(verify_orbit(&valid(), ParseLimits::default()), Verdict::Accepted(_)));
    // A pattern step changed: condition 1.
    let mut c = valid();
    c.pattern[3] = 2;
    assert_eq!(rejected(&c).code, Code::PatternNotForced);
    // A step outside 1..n-1.
    let mut c = valid();
    c.pattern[0] = 3;
    assert_eq!(rejected(&c).code, Code::OrbitOutOfRange);
    // rho and lambda >= 1 are not contraction bounds; too small, condition 3 fails.
    for (field, value, code) in [
        ("rho", "1", Code::OrbitOutOfRange),
        ("lambda", "3/2", Code::OrbitOutOfRange),
        ("period", "0", Code::OrbitOutOfRange),
        ("rho", "1/2", Code::NoContraction),
        ("lambda", "1/10", Code::NoContraction),
        ("period", "3/2", Code::NoContraction),
    ] {
        let mut c = valid();
        match field {
            "rho" => c.rho = value.into(),
            "lambda" => c.lambda = value.into(),
            _ => c.period = value.into(),
        }
        assert_eq!(rejected(&c).code, code, "{field} = {value}");
    }
    // x* moved off the orbit: R_P(x*) leaves X (condition 2), at the centre of X.
    let mut c = valid();
    let OrbitSet::Parallelepiped { centre, .. } = &mut c.set else { panic!("a parallelepiped") };
    centre.0 = "2301/1000".into();
    let r = rejected(&c);
    assert_eq!(r.code, Code::SetNotInvariant, "{r}");
    assert!(matches!(r.locus, Locus::Kind(KindLocus::OrbitBox { depth: 0, .. })), "{:?}", r.locus);
    // delta enlarged until a condition fails on a sub-box.
    let mut c = valid();
    let OrbitSet::Parallelepiped { delta, .. } = &mut c.set else { panic!("a parallelepiped") };
    *delta = "1/8".into();
    let r = rejected(&c);
    assert!(matches!(r.code, Code::PatternNotForced | Code::SetNotInvariant | Code::NoContraction), "{r}");
    assert!(matches!(r.locus, Locus::Kind(KindLocus::OrbitBox { .. })), "{:?}", r.locus);
    // The enlarged set is accepted neither with more subdivision allowed: the failure is real.
    c.subdivision = 3;
    assert!(matches!(verify_orbit(&c, ParseLimits::default()), Verdict::Rejected(_)));
}

#[test]
fn the_kernels_exact_return_map_agrees_with_the_exact_and_float_simulators() {
    let (kappa, gamma) = (Q::new(1, 8), Q::new(3, 20));
    let body = Polygon::new(3, kappa.clone(), gamma.clone()).unwrap();
    let OrbitSet::Parallelepiped { centre, .. } = valid().set else { panic!("a parallelepiped") };
    let x = [q(&centre.0), q(&centre.1), q(&centre.2)];
    let pattern = [2usize, 2, 1, 1];
    let per = return_map(&body, &pattern, &x).expect("conditions 1-2 hold at x*");
    // The simulator from q = (0, a, 1), p = (b, c, -1), in the original labels.
    let model = Model::new(Shape::Polygon(3), kappa, gamma).unwrap();
    let one = Q::int(1);
    let start = model
        .given_start(&[Q::int(0), x[0].clone(), one.clone()], &[x[1].clone(), x[2].clone(), one.negated()])
        .unwrap();
    let sys = model.exact.as_ref().expect("exact model for n = 3");
    let mut eng = ExactEngine::new(sys, &start);
    let mut label = 0usize;
    for (s, &j) in pattern.iter().enumerate() {
        label = (label + j) % 3;
        match eng.step() {
            Step::Impact { contact, .. } => assert_eq!(contact, label, "impact {s}"),
            other => panic!("impact {s}: {other:?}"),
        }
        // The kernel's state after step s is the simulator's relabelled: contact `label` is 0.
        let (sq, sp) = eng.state();
        let (kq, kp) = &per.states[s + 1];
        let f = |k: usize| body.contact(k as i64);
        let dot =
            |a: &[Q; 3], b: &[Q; 3]| a[0].times(&b[0]).plus(&a[1].times(&b[1])).plus(&a[2].times(&b[2]));
        assert_eq!(dot(f(label), sq), kq[0], "h0 after impact {s}");
        assert_eq!(dot(f(label + 1), sq), kq[1], "h1 after impact {s}");
        assert_eq!(sq[2], kq[2], "hc after impact {s}");
        assert_eq!(dot(f(label), sp), kp[0], "u0 after impact {s}");
        assert_eq!(dot(f(label + 1), sp), kp[1], "u1 after impact {s}");
        assert_eq!(sp[2], kp[2], "v after impact {s}");
    }
    // One period turns the labels by 2 + 2 + 1 + 1 = 6 = 0 mod 3: R_P(x) is the simulator's state
    // normalised by the two scales.
    let (sq, sp) = eng.state();
    assert_eq!(per.alpha, sq[2]);
    assert_eq!(per.beta, sp[2].negated());
    assert_eq!(per.next[0], sq[1].over(&per.alpha).unwrap());
    assert_eq!(per.next[1], sp[0].over(&per.beta).unwrap());
    // The float simulator follows the pattern periodically from x* (the theorem's conclusion).
    let run = chatter::simulate::simulate_float(
        &model.float,
        &start.to_f64(),
        &chatter::simulate::Options::new(200),
    );
    let expected: Vec<u8> = (0..run.sequence.len().min(200)).map(|i| [2u8, 1, 2, 0][i % 4]).collect();
    assert!(run.sequence.len() >= 100, "{} impacts", run.sequence.len());
    assert_eq!(run.sequence[..expected.len()], expected[..]);
    assert_eq!(run.outcome, chatter::simulate::Outcome::Cc);
}

#[test]
fn a_cone_certificate_cannot_carry_the_orbit_claim() {
    let path = root().join("certificates/valid/n3-kappa1_10-gamma3_20-complete-chatter-from-all-down.ron");
    let text = std::fs::read_to_string(path)
        .unwrap()
        .replace("claim: CompleteChatterFromAllDown", "claim: CompleteChatterFromSet");
    assert!(text.contains("CompleteChatterFromSet"));
    match verify_text(&text, ParseLimits::default(), &[MALACHITE, NUM]) {
        Verdict::Rejected(r) => assert_eq!(r.code, Code::UnknownVariant),
        other => panic!("{other:?}"),
    }
}

#[test]
fn verify_reports_an_orbit_certificate_by_its_sub_boxes() {
    let o = std::process::Command::new(crate::common::bin())
        .args(["verify", "certificates/valid/orbit-n3-kappa1_8-gamma3_20.ron", "--json"])
        .current_dir(root())
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let f = &v["files"][0];
    assert_eq!(f["claim"], "CompleteChatterFromSet");
    assert!(f["orbit_boxes"].as_u64().unwrap() >= 1, "{f}");
    assert!(f.get("generators").is_none(), "an orbit certificate has no generators: {f}");
    // Issue 24: B = T̄/(1 − ρ) of the orbit theorem, derived by the kernel from rho and period.
    let cert =
        std::fs::read_to_string(root().join("certificates/valid/orbit-n3-kappa1_8-gamma3_20.ron")).unwrap();
    let field = |name: &str| {
        let at = cert.find(&format!("{name}: \"")).unwrap() + name.len() + 3;
        crate::common::q(&cert[at..at + cert[at..].find('"').unwrap()])
    };
    let b = field("period") / (chatter::exact::Q::int(1) - field("rho"));
    assert_eq!(f["time_to_rest_bound"], b.to_string(), "{f}");
    let o = std::process::Command::new(crate::common::bin())
        .args(["verify", "certificates/valid/orbit-n3-kappa1_8-gamma3_20.ron"])
        .current_dir(root())
        .output()
        .unwrap();
    let line = String::from_utf8_lossy(&o.stdout);
    assert!(
        line.contains(
            "every state of the set X ends in complete chatter; its impacts accumulate within T <= "
        ) && line.contains(" h/|v| of that impact (time_to_rest_bound); conditions shown on"),
        "{line}"
    );
}
