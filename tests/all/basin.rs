//! Basin certificates (issue 27, docs/basin-certificates.md), from the tool's side: drops drawn
//! inside the leaves of the corpus certificate, simulated with the exact engine, have the
//! impacts the leaf states (and the ICC leaves end ICC, proved); `chatter basin` writes a file
//! that `chatter verify` accepts with the shares it printed.

use crate::common::{bin, root};
use chatter::exact::{Q, QExt};
use chatter::simulate::{Model, Options, Outcome, Shape, SplitMix64, Start, simulate_exact};
use chatter_kernel::rules::basin::leaf_box;
use chatter_kernel::syntax::basin::{BasinCertificate, LeafVerdict};
use chatter_kernel::syntax::orbit::OrbitBody;
use chatter_kernel::syntax::{Encoding, read};

fn corpus() -> BasinCertificate {
    let path = root().join("certificates/basin/valid/basin-n3-kappa1_8-gamma3_20.ron");
    read(&std::fs::read_to_string(path).unwrap(), Encoding::Ron).unwrap()
}

fn f(x: &malachite::rational::Rational) -> f64 {
    Q::from_rational(x.clone()).to_f64()
}

#[test]
fn exact_simulations_of_drops_inside_decided_leaves_follow_their_certified_impacts() {
    let cert = corpus();
    let OrbitBody::RegularPolygon { n, kappa, gamma } = &cert.body;
    let model = Model::new(Shape::Polygon(*n), kappa.parse().unwrap(), gamma.parse().unwrap()).unwrap();
    let num = |s: &String| chatter_kernel::exact::parse_canonical(s, Default::default()).unwrap();
    let lo: [malachite::rational::Rational; 5] = std::array::from_fn(|k| num(&cert.drops.lo[k]));
    let hi: [malachite::rational::Rational; 5] = std::array::from_fn(|k| num(&cert.drops.hi[k]));
    let mut rng = SplitMix64::new(27);
    let mut checked = [0usize; 2];
    for leaf in cert.leaves.iter().filter(|l| l.verdict != LeafVerdict::Undecided).take(6) {
        let (LeafVerdict::Cc { first, steps, .. } | LeafVerdict::Icc { first, steps, .. }) = &leaf.verdict
        else {
            continue;
        };
        let cc = matches!(leaf.verdict, LeafVerdict::Cc { .. });
        let (l, h) = leaf_box(&lo, &hi, &leaf.path);
        let mut expected = vec![*first as u8];
        for &j in steps {
            let last = expected[expected.len() - 1] as u64;
            expected.push(((last + j) % n) as u8);
        }
        for _ in 0..2 {
            // A point of the middle half of the leaf (so that the f64 change of coordinates, exact
            // to ~1e-16, stays inside the leaf).
            let y: [f64; 5] = std::array::from_fn(|k| {
                let (a, b) = (f(&l[k]), f(&h[k]));
                a + (b - a) * (0.25 + 0.5 * rng.open01())
            });
            let fs = &model.float;
            let start =
                Start { q: fs.from_paper(&[y[2], y[3], y[4]]), p: fs.from_paper(&[y[0], y[1], -1.0]) };
            let exact = Start {
                q: start.q.map(|x| Q::from_f64_exact(x).unwrap()),
                p: start.p.map(|x| Q::from_f64_exact(x).unwrap()),
            };
            let run = simulate_exact(&model, &exact, &Options::new(expected.len() + 4));
            assert!(run.sequence.len() >= expected.len() || !cc, "{}: {:?}", leaf.path, run.outcome);
            let m = expected.len().min(run.sequence.len());
            assert_eq!(run.sequence[..m], expected[..m], "leaf {}", leaf.path);
            if !cc {
                assert_eq!((run.outcome, run.proved), (Outcome::Icc, true), "leaf {}", leaf.path);
            }
            checked[usize::from(!cc)] += 1;
        }
    }
    assert!(checked[0] + checked[1] >= 2, "{checked:?}");
}

#[test]
fn chatter_basin_writes_a_certificate_that_verify_accepts_with_the_same_shares() {
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("b.ron");
    let o = std::process::Command::new(bin())
        .args(["basin", "--n", "3", "--kappa", "1/8", "--gamma", "3/20", "--pattern", "2,2,1,1"])
        .args(["--box", "1/20,1/20,1/20,1/20,21/20:50001/1000000,50001/1000000,50001/1000000,50001/1000000,1050001/1000000"])
        .args(["--depth", "2", "-o", out.to_str().unwrap()])
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&o.stdout).to_string();
    assert_eq!(o.status.code(), Some(0), "{said}{}", String::from_utf8_lossy(&o.stderr));
    assert!(said.contains("cc_share 1,"), "{said}");
    let v =
        std::process::Command::new(bin()).args(["verify", "--json", out.to_str().unwrap()]).output().unwrap();
    let json: serde_json::Value = serde_json::from_slice(&v.stdout).unwrap();
    let file = &json["files"][0];
    assert_eq!(file["cc_share"], "1", "{json}");
    assert_eq!(
        (file["icc_share"].as_str(), file["undecided_share"].as_str()),
        (Some("0"), Some("0")),
        "{json}"
    );
}
