//! The independent oracle for version-4 certificates (src/oracle/convex.rs) against the kernel's
//! rules K1-K4: the same verdict on every version-4 corpus file, on the pipeline's certificates
//! for random bodies, and on mutations of them (a cone shrunk towards one of its generators,
//! gamma raised, a generator lifted to v = 0, the claim raised). The kernel's code must be one of
//! the oracle's first failing stage.

use crate::common::root;
use chatter::bodies::convex::polygon_plate;
use chatter::certify::convex::{ConvexRequest, certify_convex};
use chatter::exact::{Q, QExt};
use chatter::oracle::convex::{evaluate_convex, pair_quadratic};
use chatter_kernel::certificate::{Claim, ConvexBodyText, ConvexCertificate, Encoding, read_convex};
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::model::{ConvexBody, PccExclusion};
use chatter_kernel::verify::{Verdict, verify_convex};

/// Kernel and oracle agree on `c`; returns whether it was accepted.
fn agree(c: &ConvexCertificate, what: &str) -> bool {
    let o = evaluate_convex(c, ParseLimits::default());
    match verify_convex(c, ParseLimits::default()) {
        Verdict::Accepted(a) => {
            assert!(o.accepted(), "{what}: the kernel accepts, the oracle finds {:?}", o.failing);
            assert_eq!(a.claim, c.claim, "{what}");
            true
        }
        Verdict::Rejected(r) => {
            assert!(!o.accepted(), "{what}: the kernel rejects ({r}), the oracle accepts");
            assert!(
                o.first_stage.contains(&r.code),
                "{what}: kernel {:?}, oracle {:?}",
                r.code,
                o.first_stage
            );
            false
        }
        Verdict::Disagree(d) => panic!("{what}: backends disagree: {d}"),
    }
}

#[test]
fn the_oracle_agrees_with_the_kernel_on_the_version_4_corpus() {
    let mut seen = [0, 0];
    for dir in ["certificates/valid", "certificates/invalid"] {
        for e in std::fs::read_dir(root().join(dir)).unwrap() {
            let p = e.unwrap().path();
            let Ok(text) = std::fs::read_to_string(&p) else { continue };
            let kind =
                chatter_kernel::syntax::kind_of(&text, Encoding::Ron, chatter_kernel::syntax::Kind::Cone);
            if !matches!(kind, Ok((chatter_kernel::syntax::Kind::Family, _))) {
                continue;
            }
            let Ok(c) = read_convex(&text, Encoding::Ron) else { continue };
            let ok = agree(&c, &p.display().to_string());
            assert_eq!(ok, dir.ends_with("valid") && !dir.ends_with("invalid"), "{}", p.display());
            seen[usize::from(ok)] += 1;
        }
    }
    assert!(seen[0] >= 5 && seen[1] >= 2, "{seen:?}");
}

/// A deterministic pseudo-random generator (SplitMix64).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// A rational in [0, 1) with denominator 1000.
    fn unit(&mut self) -> Q {
        Q::new((self.next() % 1000) as i64, 1000)
    }
}

/// A uniform plate of a random convex polygon: n corners at angles 2 pi k / n jittered, radius in
/// [1/2, 3/2), as rationals (rounded cos/sin are fine: any convex polygon will do).
fn random_plate(rng: &mut Rng, n: usize, gamma: Q) -> Option<ConvexBody<Q>> {
    let pts: Vec<[Q; 2]> = (0..n)
        .map(|k| {
            let t = (k as f64 + 0.3 * (rng.unit().to_f64() - 0.5)) * std::f64::consts::TAU / n as f64;
            let r = 0.5 + rng.unit().to_f64();
            let c = |x: f64| Q::new((x * 1000.0).round() as i64, 1000);
            [c(r * t.cos()), c(r * t.sin())]
        })
        .collect();
    polygon_plate(&pts, gamma).ok()
}

/// The mutations of a certificate the test tries.
fn mutations(c: &ConvexCertificate) -> Vec<(String, ConvexCertificate)> {
    let mut out = vec![];
    for i in 0..c.cones.len() {
        // Shrink K_i halfway towards its first generator.
        let mut m = c.clone();
        let g0: Vec<Q> = m.cones[i][0].0.iter().map(|s| s.parse().unwrap()).collect();
        for g in m.cones[i].iter_mut().skip(1) {
            let x: Vec<Q> = g.0.iter().map(|s| s.parse::<Q>().unwrap()).collect();
            g.0 = x.iter().zip(&g0).map(|(a, b)| ((a + b) / Q::int(2)).to_string()).collect();
        }
        out.push((format!("K_{i} shrunk"), m));
    }
    let mut m = c.clone();
    m.cones[0][0].0[2] = "0".into();
    out.push(("a generator at v = 0".into(), m));
    let mut m = c.clone();
    let ConvexBodyText::ConvexPolygon { gamma, .. } = &mut m.body;
    *gamma = (gamma.parse::<Q>().unwrap() * Q::int(3)).to_string();
    out.push(("gamma tripled".into(), m));
    let mut m = c.clone();
    m.claim = Claim::CompleteChatterFromAllDown;
    out.push(("claim raised".into(), m));
    out
}

#[test]
fn the_oracle_agrees_with_the_kernel_on_random_bodies_and_mutations() {
    let mut rng = Rng(2026);
    let (mut accepted, mut rejected) = (0, 0);
    for trial in 0..24 {
        let n = 3 + trial % 4;
        let gamma = Q::new(1 + (rng.next() % 40) as i64, 1000);
        let Some(body) = random_plate(&mut rng, n, gamma) else { continue };
        let Ok(cert) = certify_convex(&ConvexRequest::new(body.clone())).result else { continue };
        assert!(agree(&cert, &format!("trial {trial}")));
        for (what, m) in mutations(&cert) {
            if agree(&m, &format!("trial {trial}, {what}")) {
                accepted += 1;
            } else {
                rejected += 1;
            }
        }
    }
    assert!(rejected >= 20 && accepted >= 1, "accepted {accepted}, rejected {rejected}");
}

#[test]
fn the_oracles_pair_quadratic_is_the_kernels() {
    let mut rng = Rng(7);
    for trial in 0..20 {
        let Some(body) = random_plate(&mut rng, 3 + trial % 5, Q::new(1, 50)) else { continue };
        for k in 0..body.n() as i64 {
            let (o, q) = (pair_quadratic(&body, k), body.pair_pcc_quadratic(k).unwrap());
            assert_eq!((&o.p, &o.q, &o.discriminant), (&q.p, &q.q, &q.discriminant));
            assert_eq!(o.excludes_pcc(), q.exclusion() == PccExclusion::Excluded);
        }
    }
}
