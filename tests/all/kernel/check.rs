//! Tests of `chatter_kernel::check` on both backends, against the independent oracle
//! (`chatter-oracle`, seen through `kernel::brute`).

use super::brute::{self, Pt, Verdict, orient2, project};
use crate::common::{GAMMAS, KAPPAS, NS, body, q};
use chatter::certify::{Request, certify};
use chatter::exact::{ParseLimits, Q};
use chatter::write::write;
use chatter_kernel::certificate::{Body, Boundary, Certificate, Claim, Code, Generator, Locus, Rejection};
use chatter_kernel::check::{Accepted, check};
use num_rational::BigRational;
use proptest::prelude::*;
use proptest::sample::Index;
use proptest::test_runner::{Config, TestRunner};
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, OnceLock};
use std::time::Instant;

// ---------------------------------------------------------------------------------------------
// Helpers.

/// Bodies that `certify` handles, with the claim it reaches.
const BODIES: [(u64, &str, &str); 4] =
    [(4, "1/6", "1/100"), (3, "3/20", "1/20"), (6, "1/20", "1/1000"), (3, "1/8", "1/100")];

/// The certificates of [`BODIES`], computed once for all tests.
fn certified() -> &'static [Certificate] {
    static CERTS: OnceLock<Vec<Certificate>> = OnceLock::new();
    CERTS.get_or_init(|| {
        BODIES
            .iter()
            .map(|&(n, k, g)| {
                let r = certify(&Request::new(n, q(k), q(g)));
                r.result.unwrap_or_else(|e| panic!("certify n={n} kappa={k} gamma={g}: {e}"))
            })
            .collect()
    })
}

fn certified_for(n: u64, kappa: &str, gamma: &str) -> Certificate {
    let i = BODIES.iter().position(|b| *b == (n, kappa, gamma)).expect("a certified body");
    certified()[i].clone()
}

/// The kernel on both backends, which must agree exactly.
fn run(cert: &Certificate) -> Result<Accepted, Rejection> {
    let a = check::<Q>(cert, ParseLimits::default());
    let b = check::<BigRational>(cert, ParseLimits::default());
    assert_eq!(a, b, "the backends disagree on\n{}", write(cert));
    a
}

/// The kernel (both backends) and the brute force must agree; returns both verdicts.
fn agree(cert: &Certificate) -> (Result<Accepted, Rejection>, Verdict) {
    let r = run(cert);
    let v = brute::evaluate(cert);
    match &r {
        Ok(a) => {
            let o = v.report.clone().unwrap_or_else(|| {
                panic!("kernel accepts, the oracle finds {:?} in\n{}", v.failing, write(cert))
            });
            let Body::RegularPolygon { n, .. } = &cert.body;
            assert_eq!((a.claim, a.n, a.generators), (cert.claim, *n, cert.cone.len()));
            assert_eq!(Some(a.redundant.clone()), o.redundant, "redundant generators of\n{}", write(cert));
            assert_eq!(Some(a.max_denominator_bits), o.max_denominator_bits);
            let pieces = o.pieces.expect("pieces");
            assert_eq!(a.pieces.len(), pieces.len());
            for (k, b) in a.pieces.iter().zip(&pieces) {
                // Degenerate pieces may repeat a point in the kernel's clipped list.
                if *b >= 3 {
                    assert_eq!(k, b, "pieces {:?} vs {:?}", a.pieces, pieces)
                } else {
                    assert!(k >= b)
                }
            }
            assert_eq!(a.pcc, o.pcc);
            assert_eq!(Some(a.contains_translation), o.contains_translation);
        }
        Err(rej) => {
            assert!(!v.accepted(), "kernel rejects ({rej}), brute force accepts\n{}", write(cert));
            assert!(
                v.first_stage.contains(&rej.code),
                "kernel code {:?} ({rej}) is not among the brute force's first failures {:?} (all: {:?}) of\n{}",
                rej.code,
                v.first_stage,
                v.failing,
                write(cert)
            );
        }
    }
    (r, v)
}

/// The projected generators of a certificate (all with v < 0).
fn points(cert: &Certificate) -> Vec<Pt> {
    cert.cone.iter().map(|g| project(&[q(&g.0[0]), q(&g.0[1]), q(&g.0[2])]).expect("v < 0")).collect()
}

/// The generator w (x, y, -1) (w > 0) as canonical text.
fn generator(p: &Pt, w: &Q) -> Generator {
    Generator(vec![(&p.0 * w).to_string(), (&p.1 * w).to_string(), (-w.clone()).to_string()])
}

/// `base` with its cone replaced by weighted projected points.
fn with_points(base: &Certificate, pts: &[(Pt, Q)]) -> Certificate {
    let mut c = base.clone();
    c.cone = pts.iter().map(|(p, w)| generator(p, w)).collect();
    c
}

fn centroid(pts: &[Pt]) -> Pt {
    let m = Q::int(pts.len() as i64);
    let (sx, sy) = pts.iter().fold((Q::int(0), Q::int(0)), |(x, y), p| (x + &p.0, y + &p.1));
    (sx / &m, sy / &m)
}

/// c + f (p - c).
fn scaled_about(c: &Pt, f: &Q, p: &Pt) -> Pt {
    (c.0.clone() + f * &(&p.0 - &c.0), c.1.clone() + f * &(&p.1 - &c.1))
}

fn set_body(c: &mut Certificate, n: u64, kappa: &str, gamma: &str) {
    c.body = Body::RegularPolygon { n, kappa: kappa.into(), gamma: gamma.into() };
}

fn field(path: &str) -> Locus {
    Locus::Field { path: path.to_string() }
}

fn rejected(cert: &Certificate) -> Rejection {
    run(cert).expect_err("the kernel must reject this certificate")
}

fn after<'a>(s: &'a str, pat: &str) -> &'a str {
    &s[s.find(pat).unwrap_or_else(|| panic!("{pat:?} not in {s:?}")) + pat.len()..]
}

fn upto<'a>(s: &'a str, pat: &str) -> &'a str {
    &s[..s.find(pat).unwrap_or_else(|| panic!("{pat:?} not in {s:?}"))]
}

fn pair(s: &str, sep: &str) -> (String, String) {
    let (a, b) = s.split_once(sep).unwrap_or_else(|| panic!("{sep:?} not in {s:?}"));
    (a.to_string(), b.to_string())
}

// ---------------------------------------------------------------------------------------------
// Certificates from the pipeline.

#[test]
fn certified_cones_are_accepted_by_both_backends_and_the_brute_force() {
    for (cert, &(n, kappa, gamma)) in certified().iter().zip(&BODIES) {
        let (r, v) = agree(cert);
        let a = r.unwrap_or_else(|e| panic!("n={n} kappa={kappa} gamma={gamma}: {e}"));
        assert!(v.accepted());
        assert_eq!(a.n, n);
        assert_eq!(a.pieces.len(), n as usize - 1);
        assert!(a.pieces.iter().all(|&p| p >= 3), "{a:?}");
        // Every weaker claim is accepted too, with the same geometry.
        for claim in Claim::ALL.into_iter().filter(|c| *c <= cert.claim) {
            let mut weaker = cert.clone();
            weaker.claim = claim;
            let (w, _) = agree(&weaker);
            let w = w.expect("a weaker claim");
            assert_eq!((w.pieces, w.redundant), (a.pieces.clone(), a.redundant.clone()));
            assert_eq!(w.pcc.is_some(), claim == Claim::CompleteChatterFromAllDown);
        }
    }
    // The square plate reaches complete chatter; the triangle at kappa = 1/8 cannot (PCC).
    assert_eq!(certified_for(4, "1/6", "1/100").claim, Claim::CompleteChatterFromAllDown);
    assert_eq!(certified_for(3, "3/20", "1/20").claim, Claim::CompleteChatterFromAllDown);
    assert_eq!(certified_for(3, "1/8", "1/100").claim, Claim::CcOrPccFromAllDown);
}

#[test]
fn certified_cones_survive_writing_and_reading() {
    for cert in certified() {
        let back = chatter_kernel::certificate::read(&write(cert)).expect("readable");
        assert_eq!(&back, cert);
        assert_eq!(run(&back), run(cert));
    }
}

#[test]
fn rescaled_generators_give_the_same_verdict() {
    // Cones are homogeneous: multiplying a generator by a positive number changes nothing
    // (except the denominators).
    let cert = certified_for(3, "3/20", "1/20");
    let pts = points(&cert);
    let ws = ["1", "3", "2/7", "1000", "1/9"];
    let scaled: Vec<(Pt, Q)> =
        pts.iter().enumerate().map(|(i, p)| (p.clone(), q(ws[i % ws.len()]))).collect();
    let (a, _) = agree(&with_points(&cert, &scaled));
    let b = run(&cert).expect("accepted");
    let a = a.expect("accepted");
    assert_eq!((a.pieces, a.redundant, a.pcc, a.claim), (b.pieces, b.redundant, b.pcc, b.claim));
}

// ---------------------------------------------------------------------------------------------
// Property test: kernel vs brute force on perturbed and random cones.

const WEIGHTS: [&str; 6] = ["1", "1", "2", "1/3", "5/7", "12"];

#[derive(Clone, Debug)]
enum Case {
    /// A certified cone, scaled about its centroid by k/20, shifted by (a/1000, b/100), with a
    /// vertex dropped and a point c + t/10 (vertex - c) added, and a (maybe different) claim.
    Perturb {
        cert: usize,
        claim: Claim,
        scale: Option<i64>,
        shift: Option<(i64, i64)>,
        drop: Option<Index>,
        add: Option<(Index, i64)>,
        weights: Vec<usize>,
    },
    /// Points (x / 2d, y / d) on a random body; optionally one generator with v = 0 or v = 1.
    Random {
        body: (u64, &'static str, &'static str),
        claim: Claim,
        pts: Vec<(i64, i64, i64)>,
        above: Option<(Index, bool)>,
        weights: Vec<usize>,
    },
    /// Points (t/2, c + s t/2) on one line.
    Flat { body: (u64, &'static str, &'static str), claim: Claim, line: (i64, i64), ts: Vec<i64> },
}

fn any_body() -> impl Strategy<Value = (u64, &'static str, &'static str)> {
    (
        prop::sample::select(NS.to_vec()),
        prop::sample::select(KAPPAS.to_vec()),
        prop::sample::select(GAMMAS.to_vec()),
    )
}

fn any_claim() -> impl Strategy<Value = Claim> {
    prop::sample::select(Claim::ALL.to_vec())
}

fn weights() -> impl Strategy<Value = Vec<usize>> {
    prop::collection::vec(0..WEIGHTS.len(), 8)
}

fn case() -> impl Strategy<Value = Case> {
    let perturb = (
        0..BODIES.len(),
        any_claim(),
        prop::option::weighted(0.4, 16i64..=30),
        prop::option::weighted(0.25, (-10i64..=10, -10i64..=10)),
        prop::option::weighted(0.25, any::<Index>()),
        prop::option::weighted(0.3, (any::<Index>(), 0i64..=14)),
        weights(),
    )
        .prop_map(|(cert, claim, scale, shift, drop, add, weights)| Case::Perturb {
            cert,
            claim,
            scale,
            shift,
            drop,
            add,
            weights,
        });
    let random = (
        any_body(),
        any_claim(),
        prop::collection::vec((-2i64..=4, -6i64..=2, 1i64..=2), 3..=7),
        prop::option::weighted(0.1, (any::<Index>(), any::<bool>())),
        weights(),
    )
        .prop_map(|(body, claim, pts, above, weights)| Case::Random { body, claim, pts, above, weights });
    let flat = (any_body(), any_claim(), (-3i64..=3, -2i64..=2), prop::collection::vec(-4i64..=4, 1..=5))
        .prop_map(|(body, claim, line, ts)| Case::Flat { body, claim, line, ts });
    prop_oneof![8 => perturb, 3 => random, 1 => flat]
}

fn build(case: &Case) -> Certificate {
    let w = |ws: &[usize], i: usize| q(WEIGHTS[ws[i % ws.len()]]);
    match case {
        Case::Perturb { cert, claim, scale, shift, drop, add, weights } => {
            let base = &certified()[*cert];
            let mut pts = points(base);
            let c = centroid(&pts);
            if let Some(k) = scale {
                let f = Q::new(*k, 20);
                pts = pts.iter().map(|p| scaled_about(&c, &f, p)).collect();
            }
            if let Some((a, b)) = shift {
                let (dx, dy) = (Q::new(*a, 1000), Q::new(*b, 100));
                pts = pts.iter().map(|p| (&p.0 + &dx, &p.1 + &dy)).collect();
            }
            if let Some(i) = drop {
                pts.remove(i.index(pts.len()));
            }
            if let Some((i, t)) = add {
                let v = pts[i.index(pts.len())].clone();
                let at = i.index(pts.len() + 1);
                pts.insert(at, scaled_about(&c, &Q::new(*t, 10), &v));
            }
            let mut cert = with_points(
                base,
                &pts.iter().enumerate().map(|(i, p)| (p.clone(), w(weights, i))).collect::<Vec<_>>(),
            );
            cert.claim = *claim;
            cert
        }
        Case::Random { body: (n, kappa, gamma), claim, pts, above, weights } => {
            let mut cert = certified()[0].clone();
            set_body(&mut cert, *n, kappa, gamma);
            cert.claim = *claim;
            let pts: Vec<(Pt, Q)> = pts
                .iter()
                .enumerate()
                .map(|(i, &(x, y, d))| ((Q::new(x, 2 * d), Q::new(y, d)), w(weights, i)))
                .collect();
            cert = with_points(&cert, &pts);
            if let Some((i, positive)) = above {
                let k = i.index(cert.cone.len());
                cert.cone[k].0[2] = if *positive { "1".into() } else { "0".into() };
            }
            cert
        }
        Case::Flat { body: (n, kappa, gamma), claim, line: (c, s), ts } => {
            let mut cert = certified()[0].clone();
            set_body(&mut cert, *n, kappa, gamma);
            cert.claim = *claim;
            let pts: Vec<(Pt, Q)> =
                ts.iter().map(|&t| ((Q::new(t, 2), Q::int(*c) + Q::new(s * t, 2)), Q::int(1))).collect();
            with_points(&cert, &pts)
        }
    }
}

#[test]
fn kernel_agrees_with_brute_force_on_random_cones() {
    let cases = 96;
    let mut runner = TestRunner::new(Config { cases, failure_persistence: None, ..Config::default() });
    let (accepted, rejected) = (AtomicUsize::new(0), AtomicUsize::new(0));
    let codes: Mutex<BTreeMap<&'static str, usize>> = Mutex::new(BTreeMap::new());
    let start = Instant::now();
    let result = runner.run(&case(), |c| {
        let cert = build(&c);
        match agree(&cert).0 {
            Ok(_) => accepted.fetch_add(1, Ordering::Relaxed),
            Err(r) => {
                *codes.lock().unwrap().entry(r.code.as_str()).or_default() += 1;
                rejected.fetch_add(1, Ordering::Relaxed)
            }
        };
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    let (a, r) = (accepted.into_inner(), rejected.into_inner());
    eprintln!(
        "kernel vs brute force: {a} accepted, {r} rejected {:?} in {:.1} s",
        codes.lock().unwrap(),
        start.elapsed().as_secs_f64()
    );
    assert_eq!(a + r, cases as usize);
    assert!(a >= 5 && r >= 5, "too one-sided: {a} accepted, {r} rejected");
}

// ---------------------------------------------------------------------------------------------
// Located rejections.

#[test]
fn generator_with_v_zero_is_named() {
    let base = certified_for(4, "1/6", "1/100");
    for (i, v) in [(2, "0"), (5, "1/3"), (0, "0")] {
        let mut c = base.clone();
        c.cone[i].0[2] = v.into();
        let r = rejected(&c);
        assert_eq!(r.code, Code::GeneratorNotBelow);
        assert_eq!(r.locus, Locus::Generator { index: i }, "{r}");
        assert!(r.message().contains("v >= 0"), "{r}");
        let (_, b) = agree(&c);
        assert_eq!(b.failing, vec![Code::GeneratorNotBelow]);
    }
    // The first offending generator is reported.
    let mut c = base.clone();
    c.cone[6].0[2] = "0".into();
    c.cone[3].0[2] = "2".into();
    assert_eq!(rejected(&c).locus, Locus::Generator { index: 3 });
}

#[test]
fn collinear_generators_are_a_degenerate_cone() {
    let base = certified_for(4, "1/6", "1/100");
    let flat = |pts: &[(&str, &str, &str)]| {
        let mut c = base.clone();
        c.cone = pts
            .iter()
            .map(|(a, b, v)| Generator(vec![a.to_string(), b.to_string(), v.to_string()]))
            .collect();
        c
    };
    let cases = [
        // On the projected line u1 = -1 - u0, with a rescaled point.
        vec![("0", "-1", "-1"), ("1/10", "-11/10", "-1"), ("1/5", "-6/5", "-1"), ("2/5", "-12/5", "-2")],
        vec![("1", "2", "-1"), ("2", "4", "-2"), ("3", "6", "-3")],
        vec![("0", "0", "-1"), ("0", "1", "-1")],
        vec![("0", "0", "-1")],
        vec![],
    ];
    for pts in cases {
        let c = flat(&pts);
        let r = rejected(&c);
        assert_eq!(r.code, Code::DegenerateCone, "{r}");
        assert_eq!(r.locus, Locus::Cone, "{r}");
        assert!(r.message().contains("3-D cone"), "{r}");
        if pts.is_empty() {
            assert!(r.message().contains("`cone` is empty"), "{r}");
        } else {
            assert!(r.message().contains(&format!("the {} generators", pts.len())), "{r}");
        }
        assert_eq!(agree(&c).1.failing, vec![Code::DegenerateCone]);
    }
}

/// The locus of an `ImageOutside` rejection.
#[derive(Debug)]
struct Outside {
    vertex: usize,
    j: i64,
    edge: usize,
    from: usize,
    to: usize,
}

/// Checks an `ImageOutside` rejection through its locus, against the oracle: edge `edge`
/// of K runs from generator `from` to `to` (counter-clockwise from the lexicographically
/// smallest vertex), and some vertex of K ∩ C_j maps outside it and inside every earlier edge.
fn verify_outside(cert: &Certificate, r: &Rejection) -> Outside {
    assert_eq!(r.code, Code::ImageOutside, "{r}");
    let Locus::Piece { piece, vertex, outside: Some(Boundary::Edge { index, from, to }), corner: None } =
        r.locus
    else {
        panic!("an image outside K is located at a piece's vertex and an edge: {:?}", r.locus);
    };
    let o = Outside { vertex, j: piece as i64, edge: index, from, to };
    let Body::RegularPolygon { n, .. } = &cert.body;
    assert!((1..*n as i64).contains(&o.j));
    let pts = points(cert);
    let ccw = brute::k_ccw(cert);
    let m = ccw.len();
    let (a, bb) = (&pts[o.from], &pts[o.to]);
    assert_eq!((&ccw[o.edge], &ccw[(o.edge + 1) % m]), (a, bb), "edge {} of {ccw:?}", o.edge);
    let piece = brute::piece(cert, o.j);
    assert!(vertex < piece.len().max(3), "vertex {vertex} of a piece with {} vertices", piece.len());
    let first_violated = |img: &Pt| (0..m).find(|&e| orient2(&ccw[e], &ccw[(e + 1) % m], img) < Q::int(0));
    let witness =
        piece.iter().any(|(_, img)| img.as_ref().is_some_and(|img| first_violated(img) == Some(o.edge)));
    assert!(witness, "no vertex of K∩C_{} maps outside edge {} first: {r}", o.j, o.edge);
    o
}

#[test]
fn shrunken_cone_reports_the_vertex_the_edge_and_the_amount() {
    let mut seen = 0;
    for base in certified() {
        let pts = points(base);
        let c = centroid(&pts);
        for f in ["9/10", "1/2", "99/100"] {
            let f = q(f);
            let shrunk: Vec<(Pt, Q)> = pts.iter().map(|p| (scaled_about(&c, &f, p), Q::int(1))).collect();
            let cert = with_points(base, &shrunk);
            let (r, v) = agree(&cert);
            let r = r.expect_err("a shrunken cone is no longer invariant");
            // The kernel reports the first failing check: images come before I_0(D).
            assert_eq!(r.code, Code::ImageOutside, "{r}");
            assert!(v.failing.contains(&Code::ImageOutside));
            let o = verify_outside(&cert, &r);
            let piece = brute::piece(&cert, o.j).len();
            assert!(piece < 3 || o.vertex < piece, "vertex {} of a piece with {piece} vertices", o.vertex);
            seen += 1;
        }
    }
    assert_eq!(seen, 12);
}

#[test]
fn documented_shrunk_rectangle_message() {
    // docs/certificate-format.md §1 and §5: the rectangle with -11/4 replaced by -4/9.
    let rect = |low: &str| {
        let mut c = certified_for(4, "1/6", "1/100");
        c.cone = [("0", low), ("1/20", low), ("1/20", "3/4"), ("0", "3/4")]
            .iter()
            .map(|(a, b)| Generator(vec![a.to_string(), b.to_string(), "-1".into()]))
            .collect();
        c
    };
    let (a, _) = agree(&rect("-11/4"));
    let a = a.expect("the documented example is valid");
    assert_eq!(a.pcc.expect("complete chatter")[0], "-401/490000");
    let cert = rect("-4/9");
    let (r, _) = agree(&cert);
    let r = r.expect_err("shrunk");
    assert_eq!(
        r.message(),
        "vertex 0 of K∩C_1, at (0, -4/9), maps under S_1 to (7/1474, -3049/1474) outside edge 0 of K (generators 0 -> 1) by -4309/53064"
    );
    let o = verify_outside(&cert, &r);
    assert_eq!((o.j, o.vertex, o.edge, o.from, o.to), (1, 0, 0, 0, 1));
}

#[test]
fn bad_numbers_are_named_by_field() {
    let base = certified_for(4, "1/6", "1/100");
    let mut c = base.clone();
    c.cone[1].0[1] = "2/4".into();
    let r = rejected(&c);
    assert_eq!(r.code, Code::BadNumber);
    assert_eq!(r.locus, field("cone[1].u1"), "{r}");
    assert!(r.message().contains("\"2/4\"") && r.message().contains("\"1/2\""), "{r}");
    for (i, k, bad) in
        [(0, 0, "1.5"), (7, 2, "-0"), (3, 2, " -1"), (2, 0, "+1"), (4, 1, "3/1"), (5, 0, "1/0")]
    {
        let mut c = base.clone();
        c.cone[i].0[k] = bad.into();
        let r = rejected(&c);
        assert_eq!(r.code, Code::BadNumber, "{bad:?}: {r}");
        let name = ["u0", "u1", "v"][k];
        assert_eq!(r.locus, field(&format!("cone[{i}].{name}")), "{r}");
    }
    let mut c = base.clone();
    set_body(&mut c, 4, "2/12", "1/100");
    let r = rejected(&c);
    assert_eq!(r.code, Code::BadNumber);
    assert_eq!(r.locus, field("body.kappa"), "{r}");
    let mut c = base;
    set_body(&mut c, 4, "1/6", "0.01");
    assert_eq!(rejected(&c).locus, field("body.gamma"));
}

#[test]
fn bodies_out_of_range_are_named_by_field() {
    let base = certified_for(4, "1/6", "1/100");
    let mut c = base.clone();
    set_body(&mut c, 65, "1/6", "1/100");
    let r = rejected(&c);
    assert_eq!(r.code, Code::UnsupportedBody);
    assert_eq!(r.locus, field("body.n"), "{r}");
    assert!(r.message().contains("n = 65"), "{r}");
    for n in [0, 1, 65, 1000] {
        set_body(&mut c, n, "1/6", "1/100");
        assert_eq!(rejected(&c).code, Code::UnsupportedBody, "n = {n}");
    }
    // n = 2 is the rod: its generators have two coordinates (u0, u1).
    set_body(&mut c, 2, "1/6", "1/100");
    let r = rejected(&c);
    assert_eq!(r.code, Code::WrongArity, "{r}");
    assert!(r.message().contains("expected 2 coordinates (u0, u1)"), "{r}");
    for (kappa, gamma, field) in [
        ("0", "1/100", "body.kappa"),
        ("-1/6", "1/100", "body.kappa"),
        ("1/6", "3/2", "body.gamma"),
        ("1/6", "-1/100", "body.gamma"),
    ] {
        set_body(&mut c, 4, kappa, gamma);
        let r = rejected(&c);
        assert_eq!(r.code, Code::ParameterOutOfRange, "{kappa} {gamma}: {r}");
        assert_eq!(r.locus, Locus::Field { path: field.to_string() }, "{r}");
    }
    // gamma = 0 and gamma = 1 are legal for the cone property, not for the claims about drops.
    for gamma in ["0", "1"] {
        set_body(&mut c, 4, "1/6", gamma);
        c.claim = Claim::EffectivelyInvariant;
        let r = run(&c);
        assert!(!matches!(&r, Err(e) if e.code == Code::ParameterOutOfRange), "{r:?}");
        for claim in [Claim::CcOrPccFromAllDown, Claim::CompleteChatterFromAllDown] {
            c.claim = claim;
            let r = rejected(&c);
            assert_eq!((r.code, r.locus.clone()), (Code::ParameterOutOfRange, field("body.gamma")), "{r}");
        }
    }
}

#[test]
fn generator_with_two_coordinates_is_wrong_arity() {
    let base = certified_for(3, "3/20", "1/20");
    for (i, len) in [(4, 2), (0, 4), (10, 0)] {
        let mut c = base.clone();
        c.cone[i].0.resize(len, "-1".into());
        let r = rejected(&c);
        assert_eq!(r.code, Code::WrongArity);
        assert_eq!(r.locus, field(&format!("cone[{i}]")), "{r}");
        assert!(r.message().contains(&format!("found {len}")), "{r}");
    }
}

#[test]
fn complete_chatter_is_refused_where_pcc_is_possible() {
    let mut c = certified_for(3, "1/8", "1/100");
    assert!(run(&c).is_ok());
    c.claim = Claim::CompleteChatterFromAllDown;
    let (r, v) = agree(&c);
    let r = r.expect_err("PCC is possible for this body");
    assert_eq!(r.code, Code::PccNotExcluded);
    assert_eq!(v.failing, vec![Code::PccNotExcluded], "the geometry is fine, only PCC fails");
    let (p, qq, discriminant) = brute::pcc(&c);
    assert!(discriminant > Q::int(0));
    for part in [p.to_string(), qq.to_string(), discriminant.to_string()] {
        assert!(r.message().contains(&part), "{part} missing in {r}");
    }
    assert!(r.message().contains("67336801/8100000000"), "{r}");
    // The same happens for n = 6 at kappa = 1/20, gamma = 1/1000 (real roots again).
    let mut c = certified_for(6, "1/20", "1/1000");
    c.claim = Claim::CompleteChatterFromAllDown;
    assert_eq!(agree(&c).0.expect_err("PCC").code, Code::PccNotExcluded);
}

#[test]
fn redundant_generators_are_accepted_and_reported() {
    for base in certified() {
        let clean = run(base).expect("certified");
        let pts = points(base);
        let m = pts.len();
        let c = centroid(&pts);
        // [centroid] + generators + [2 * generator 2] + [midpoint of generators 4, 5].
        let mut cone: Vec<(Pt, Q)> = vec![(c.clone(), Q::int(3))];
        cone.extend(pts.iter().map(|p| (p.clone(), Q::int(1))));
        cone.push((pts[2].clone(), Q::int(2)));
        let mid = ((&pts[4].0 + &pts[5].0) / Q::int(2), (&pts[4].1 + &pts[5].1) / Q::int(2));
        cone.push((mid, q("1/7")));
        let cert = with_points(base, &cone);
        let (a, v) = agree(&cert);
        let a = a.expect("redundant generators are allowed");
        let mut want = vec![0];
        want.extend(clean.redundant.iter().map(|i| i + 1));
        want.extend([m + 1, m + 2]);
        assert_eq!(a.redundant, want);
        assert_eq!(v.report.and_then(|r| r.redundant), Some(want.clone()));
        assert_eq!(a.generators, m + 3);
        assert_eq!((a.pieces, a.pcc, a.claim), (clean.pieces.clone(), clean.pcc.clone(), clean.claim));
        // A duplicate written before the original: the first occurrence is the extreme one.
        let mut cone: Vec<(Pt, Q)> = vec![(pts[2].clone(), q("5/3"))];
        cone.extend(pts.iter().map(|p| (p.clone(), Q::int(1))));
        let a = agree(&with_points(base, &cone)).0.expect("accepted");
        assert!(a.redundant.contains(&3) && !a.redundant.contains(&0), "{:?}", a.redundant);
    }
}

/// Solves m x = b by Cramer's rule.
fn solve(m: &[[Q; 3]; 3], b: &[Q; 3]) -> [Q; 3] {
    let det = |a: &[[Q; 3]; 3]| {
        &a[0][0] * &(&a[1][1] * &a[2][2] - &a[1][2] * &a[2][1])
            - &a[0][1] * &(&a[1][0] * &a[2][2] - &a[1][2] * &a[2][0])
            + &a[0][2] * &(&a[1][0] * &a[2][1] - &a[1][1] * &a[2][0])
    };
    let d = det(m);
    std::array::from_fn(|c| {
        let mut mc = m.clone();
        for r in 0..3 {
            mc[r][c] = b[r].clone();
        }
        det(&mc) / &d
    })
}

#[test]
fn restitution_zero_is_accepted_and_zero_images_are_allowed() {
    // The finder does not converge at gamma = 0 (its images collapse onto u0 = 0); a cone
    // certified at gamma = 1/1000 is effectively invariant at gamma = 0 too for the triangles.
    for kappa in ["3/20", "1/8"] {
        let direct = certify(&Request::new(3, q(kappa), q("0")));
        let mut cert = match direct.result {
            Ok(c) => c,
            Err(_) => {
                certify(&Request::new(3, q(kappa), q("1/1000"))).result.expect("certified at gamma = 1/1000")
            }
        };
        set_body(&mut cert, 3, kappa, "0");
        cert.claim = Claim::EffectivelyInvariant;
        let (a, v) = agree(&cert);
        a.unwrap_or_else(|e| panic!("kappa = {kappa}, gamma = 0: {e}"));
        assert!(v.accepted());
        // The claims about drops need 0 < gamma < 1 (issue 9).
        cert.claim = Claim::CcOrPccFromAllDown;
        let r = agree(&cert).0.expect_err("no drop claim at gamma = 0");
        assert_eq!(r.code, Code::ParameterOutOfRange);
    }
}

/// The ray p* of K ∩ C_j that S_j sends to zero when gamma = 0: R_j p* = -d_0 spans the
/// kernel of I_0.
fn zero_ray(b: &chatter_kernel::model::Polygon<Q>, j: i64) -> Pt {
    let d0 = b.impact_direction(0);
    let p = solve(&b.relabel(j), &[-d0[0].clone(), -d0[1].clone(), -d0[2].clone()]);
    assert!(brute::mat_vec(&b.step(j), &p).iter().all(|c| *c == Q::int(0)), "S_{j} p* = 0");
    project(&p).expect("p* has v < 0")
}

#[test]
fn zero_image_of_a_vertex_passes() {
    // Triangle, kappa = 1/8, gamma = 0: p*_1 = (3, -9) lies strictly inside C_1. Adding it to an
    // invariant cone makes it a vertex of K ∩ C_1 whose image is the zero vector: the kernel
    // must let it pass (rule R2) and go on to report a real failure in K ∩ C_2.
    let b = body(3, "1/8", "0");
    let star = zero_ray(&b, 1);
    assert_eq!(star, (q("3"), q("-9")));
    let mut cert =
        certify(&Request::new(3, q("1/8"), q("1/1000"))).result.expect("certified at gamma = 1/1000");
    set_body(&mut cert, 3, "1/8", "0");
    cert.claim = Claim::EffectivelyInvariant;
    assert!(run(&cert).is_ok());
    let mut pts = points(&cert);
    pts.push(star.clone());
    let with_star = with_points(&cert, &pts.iter().map(|p| (p.clone(), q("1/8"))).collect::<Vec<_>>());
    // p* is a vertex of K ∩ C_1 (the oracle's) ...
    assert!(brute::piece(&with_star, 1).iter().any(|(p, _)| *p == star));
    // ... and every vertex of K ∩ C_1 passes: the first failure is in K ∩ C_2.
    let (r, v) = agree(&with_star);
    let r = r.expect_err("adding p* breaks invariance elsewhere");
    assert_eq!(r.code, Code::ImageOutside, "{r}");
    assert_eq!(verify_outside(&with_star, &r).j, 2, "{r}");
    assert_eq!(v.first_stage, vec![Code::ImageOutside]);
}

#[test]
fn vacuous_cone_is_invariant_but_misses_the_all_down_drops() {
    // A triangle in u0 < 0 meets no C_j: effectively invariant (vacuously, and it does not
    // contain the post-impact translation), but I_0(D) is not in it.
    let mut cert = certified_for(4, "1/6", "1/100");
    let tri = [(q("-3"), q("-1")), (q("-1"), q("-1")), (q("-2"), q("1"))];
    cert = with_points(&cert, &tri.iter().map(|p| (p.clone(), q("1/2"))).collect::<Vec<_>>());
    cert.claim = Claim::EffectivelyInvariant;
    let a = agree(&cert).0.expect("vacuously invariant");
    assert_eq!(a.pieces, vec![0, 0, 0]);
    assert!(!a.contains_translation);
    for claim in [Claim::CcOrPccFromAllDown, Claim::CompleteChatterFromAllDown] {
        cert.claim = claim;
        let (r, v) = agree(&cert);
        let r = r.expect_err("I_0(D) is not in K");
        assert_eq!(r.code, Code::InitialOutside, "{r}");
        assert_eq!(v.first_stage, vec![Code::InitialOutside]);
        // "I_0 maps the all-down generator -m_(k,k+1) = (x, y) to (x', y') outside edge e ..."
        let k: i64 = upto(after(&r.message(), "all-down generator -m_("), ",").parse().expect("k");
        let (x, y) = pair(upto(after(&r.message(), ") = ("), ") to ("), ", ");
        let b = body(4, "1/6", "1/100");
        let g = &b.all_down_generators()[k as usize];
        assert_eq!(project(g), Some((q(&x), q(&y))), "{r}");
        let (ix, iy) = pair(upto(after(&r.message(), ") to ("), ") outside edge "), ", ");
        assert_eq!(project(&brute::mat_vec(&b.impact(0), g)), Some((q(&ix), q(&iy))), "{r}");
        // All earlier generators of D land in K (there are none here: k = 0 is reported).
        assert_eq!(k, 0, "{r}");
    }
}
