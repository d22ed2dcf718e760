//! Family certificates of general convex bodies (`chatter-family-certificate`,
//! docs/certificate-format.md §13): regular-polygon certificates transported to affine images
//! (docs/model.md §11.7) verify on both backends exactly where the regular ones do; raised gamma
//! and shrunk cones are rejected; the kernel's rules K1-K4 give typed rejections with a locus;
//! cone certificates (versions 1-3) are unchanged.

use crate::common::{q, root};
use chatter::bodies::convex::polygon_plate;
use chatter::certify::transport::{family, regular_image, transport};
use chatter::certify::{Request, certify};
use chatter::exact::Q;
use chatter::write::write_convex;
use chatter_kernel::certificate::{
    Body, Certificate, Claim, Code, ConvexBodyText, ConvexCertificate, Encoding, Generator, KindLocus, Locus,
    Param, read_convex,
};
use chatter_kernel::exact::{OrderedField, ParseLimits, Ring};
use chatter_kernel::model::{ConvexBody, Vec2};
use chatter_kernel::syntax::Kind;
use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify, verify_convex, verify_convex_on, verify_text};

fn v2(x: &str, y: &str) -> Vec2<Q> {
    [q(x), q(y)]
}

/// A regular-polygon certificate from today's pipeline (strongest claim).
fn regular(n: u64, kappa: &str, gamma: &str) -> Certificate {
    certify(&Request::new(n, q(kappa), q(gamma))).result.expect("the regular body certifies")
}

/// The same certificate with another gamma (the cone unchanged).
fn with_gamma(c: &Certificate, gamma: &str) -> Certificate {
    let mut c = c.clone();
    let Body::RegularPolygon { gamma: g, .. } = &mut c.body;
    *g = Param::Point(gamma.into());
    c
}

fn with_kappa(c: &Certificate, kappa: &str) -> Certificate {
    let mut c = c.clone();
    let Body::RegularPolygon { kappa: k, .. } = &mut c.body;
    *k = Param::Point(kappa.into());
    c
}

fn convex_with_gamma(c: &ConvexCertificate, gamma: &str) -> ConvexCertificate {
    let mut c = c.clone();
    let ConvexBodyText::ConvexPolygon { gamma: g, .. } = &mut c.body;
    *g = gamma.into();
    c
}

/// Both backends, each alone and together, give the same verdict.
fn both(c: &ConvexCertificate) -> Verdict {
    let v = verify_convex(c, ParseLimits::default());
    for b in [MALACHITE, NUM] {
        assert_eq!(verify_convex_on(c, ParseLimits::default(), &[b]), v, "backend {}", b.name);
    }
    v
}

/// The verdict as (accepted claim) or (rejection code), to compare the two forms.
fn outcome(v: &Verdict) -> Result<Claim, Code> {
    match v {
        Verdict::Accepted(a) => Ok(a.claim),
        Verdict::Rejected(r) => Err(r.code),
        Verdict::Disagree(d) => panic!("backends disagree: {d}"),
    }
}

/// The uniform plates of the issue, with the regular polygon they are images of (also used by
/// `certify_convex`).
pub(crate) fn plates(gamma: &Q) -> Vec<(&'static str, u64, ConvexBody<Q>)> {
    let rect = |a: &str, b: &str| {
        let (x, y) = (q(a) / q("2"), q(b) / q("2"));
        polygon_plate(
            &[
                [x.clone(), y.negated()],
                [x.clone(), y.clone()],
                [x.negated(), y.clone()],
                [x.negated(), y.negated()],
            ],
            gamma.clone(),
        )
        .unwrap()
    };
    let parallelogram =
        polygon_plate(&[v2("2", "0"), v2("1", "1"), v2("-2", "0"), v2("-1", "-1")], gamma.clone()).unwrap();
    let triangle = polygon_plate(&[v2("2", "-1"), v2("1", "2"), v2("-3", "-1")], gamma.clone()).unwrap();
    vec![
        ("rectangle 2 x 1", 4, rect("2", "1")),
        ("rectangle 4 x 1", 4, rect("4", "1")),
        ("parallelogram", 4, parallelogram),
        ("irregular triangle", 3, triangle),
    ]
}

pub(crate) fn kappa_of(n: u64) -> &'static str {
    if n == 4 { "1/6" } else { "1/8" }
}

#[test]
fn uniform_plates_are_images_of_the_regular_plates() {
    // The J of each uniform plate equals kappa P L L^T P^T from its first two contacts
    // (docs/model.md §11.7), so the transport applies to it.
    for (name, n, body) in plates(&q("1/50")) {
        let c = body.contacts();
        let image = regular_image(n as usize, &c[0], &c[1], &q(kappa_of(n)), &q("1/50")).unwrap();
        assert_eq!(image.contacts(), body.contacts(), "{name}");
        assert_eq!(image.inertia(), body.inertia(), "{name}");
    }
}

#[test]
fn transported_certificates_of_plates_verify_on_both_backends() {
    for (n, gammas) in [(4, &["1/100", "1/50"][..]), (3, &["3/100", "1/20"][..])] {
        for &g in gammas {
            let cert = regular(n, kappa_of(n), g);
            assert!(matches!(verify(&cert, ParseLimits::default()), Verdict::Accepted(_)));
            for (name, m, body) in plates(&q(g)) {
                if m != n {
                    continue;
                }
                let t = transport(&body, &cert).unwrap();
                match both(&t) {
                    Verdict::Accepted(a) => {
                        assert_eq!(a.claim, cert.claim, "{name} at gamma = {g}");
                        assert_eq!(a.n, n);
                        assert!(a.contains_translation, "{name}");
                    }
                    other => panic!("{name} at gamma = {g}: {other:?}"),
                }
                // The text round-trips through the writer and the reader.
                let text = write_convex(&t);
                assert_eq!(read_convex(&text, Encoding::Ron).unwrap(), t);
                assert_eq!(
                    outcome(&verify_text(&text, ParseLimits::default(), &[MALACHITE, NUM])),
                    Ok(cert.claim)
                );
            }
        }
    }
}

#[test]
fn raising_gamma_rejects_exactly_where_the_regular_certificate_fails() {
    // The cone of the square at gamma = 1/50 and of the triangle at 1/20, checked on a grid of
    // gamma: the transported families are accepted and rejected (with the same code) exactly
    // where the regular certificate with the same cone is.
    let grid = ["1/100", "1/50", "1/40", "1/30", "1/20", "3/50", "1/12", "1/10", "3/20", "1/5"];
    let mut rejected = 0;
    for (n, g0) in [(4, "1/50"), (3, "1/20")] {
        let cert = regular(n, kappa_of(n), g0);
        for g in grid {
            let expected = outcome(&verify(&with_gamma(&cert, g), ParseLimits::default()));
            rejected += usize::from(expected.is_err());
            for (name, m, body) in plates(&q(g)) {
                if m == n {
                    let t = transport(&body, &cert).unwrap();
                    assert_eq!(
                        t,
                        convex_with_gamma(
                            &transport(&plates(&q(g0)).into_iter().find(|p| p.0 == name).unwrap().2, &cert)
                                .unwrap(),
                            g
                        )
                    );
                    assert_eq!(outcome(&both(&t)), expected, "{name}, cone of gamma = {g0}, at gamma = {g}");
                }
            }
        }
    }
    assert!(rejected >= 4, "the grid reaches past the regular certificates' range");
}

#[test]
fn a_shrunk_cone_is_rejected() {
    for (n, g) in [(4, "1/50"), (3, "1/20")] {
        let cert = regular(n, kappa_of(n), g);
        for (name, m, body) in plates(&q(g)) {
            if m != n {
                continue;
            }
            let mut t = transport(&body, &cert).unwrap();
            // Pull every generator of K_1 nine tenths of the way to the cone's centre.
            let gens: Vec<[Q; 3]> =
                t.cones[1].iter().map(|g| std::array::from_fn(|i| g.0[i].parse::<Q>().unwrap())).collect();
            let centre: [Q; 3] = std::array::from_fn(|i| gens.iter().fold(Q::zero(), |s, g| s.plus(&g[i])));
            let k = gens.len() as i64;
            t.cones[1] = gens
                .iter()
                .map(|g| {
                    let p: Vec<String> = (0..3)
                        .map(|i| {
                            g[i].times(&Q::from_ratio(1, 10))
                                .plus(&centre[i].times(&Q::from_ratio(9, 10 * k)))
                                .to_string()
                        })
                        .collect();
                    Generator(p)
                })
                .collect();
            match both(&t) {
                Verdict::Rejected(r) => {
                    assert!(matches!(r.code, Code::ImageOutside | Code::InitialOutside), "{name}: {r}")
                }
                other => panic!("{name}: a shrunk K_1 is accepted: {other:?}"),
            }
        }
    }
}

#[test]
fn regular_polygons_as_general_bodies_verify_exactly_where_todays_certificates_do() {
    // The square (contacts (1, 0), (0, 1), (-1, 0), (0, -1), J = kappa I) and the equilateral
    // triangle up to a rational linear map (J from the Gram matrix, docs/model.md §11.7), with
    // the family from today's certificate, on a grid of (kappa, gamma) with the cone fixed.
    let mut seen = std::collections::BTreeSet::new();
    for (n, k0, g0, r0, r1) in
        [(4, "1/6", "1/50", v2("1", "0"), v2("0", "1")), (3, "3/20", "1/20", v2("2", "-1"), v2("1", "2"))]
    {
        let cert = regular(n, k0, g0);
        for kappa in ["1/10", "1/8", "3/20", "1/6", "1/4"] {
            for gamma in ["1/100", "1/50", "1/20", "1/10", "1/5"] {
                let expected =
                    outcome(&verify(&with_gamma(&with_kappa(&cert, kappa), gamma), ParseLimits::default()));
                let body = regular_image(n as usize, &r0, &r1, &q(kappa), &q(gamma)).unwrap();
                let t = transport(&body, &cert).unwrap();
                assert_eq!(outcome(&both(&t)), expected, "n = {n}, kappa = {kappa}, gamma = {gamma}");
                seen.insert(expected.is_ok());
            }
        }
    }
    assert_eq!(seen.len(), 2, "the grid has accepted and rejected points");
}

#[test]
fn the_family_of_the_square_is_the_rotation_of_k0() {
    // K_i = R^i K_0 for the square (docs/model.md §11.5), R the quarter turn in (omega_x, omega_y).
    let cert = regular(4, "1/6", "1/50");
    let cone: Vec<[Q; 3]> =
        cert.cone.iter().map(|g| std::array::from_fn(|i| g.0[i].parse::<Q>().unwrap())).collect();
    let square = [v2("1", "0"), v2("0", "1"), v2("-1", "0"), v2("0", "-1")];
    let f = family(&square, &cone);
    for i in 1..4 {
        for (a, b) in f[i - 1].iter().zip(&f[i]) {
            // (wx, wy) -> (-wy, wx).
            assert_eq!([a[1].negated(), a[0].clone(), a[2].clone()], *b);
        }
    }
}

#[test]
fn pcc_of_an_adjacent_pair_is_reported_at_its_pair() {
    // The square's cone at gamma = 1/1000 with the claim CompleteChatterFromAllDown, on the 2 x 1
    // rectangle at gamma = 1/1000, where the pair quadratics have real roots.
    let cert = regular(4, "1/6", "1/1000");
    assert_eq!(cert.claim, Claim::CcOrPccFromAllDown);
    let body = &plates(&q("1/1000"))[0].2;
    let mut t = transport(body, &cert).unwrap();
    t.claim = Claim::CompleteChatterFromAllDown;
    match both(&t) {
        Verdict::Rejected(r) => {
            assert_eq!(r.code, Code::PccNotExcluded, "{r}");
            assert!(matches!(r.locus, Locus::Kind(KindLocus::PccPair { .. })), "{r:?}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn rule_k1_to_k3_loci_name_the_cone_and_the_generator() {
    let cert = regular(4, "1/6", "1/50");
    let body = &plates(&q("1/50"))[0].2;
    let good = transport(body, &cert).unwrap();
    // K1: a generator with v = 0 in K_2.
    let mut t = good.clone();
    t.cones[2][1].0[2] = "0".into();
    let Verdict::Rejected(r) = both(&t) else { panic!() };
    assert_eq!(
        (r.code, r.locus),
        (Code::GeneratorNotBelow, Locus::Kind(KindLocus::ConvexGenerator { cone: 2, index: 1 }))
    );
    // K1: a flat cone.
    let mut t = good.clone();
    t.cones[3].truncate(2);
    let Verdict::Rejected(r) = both(&t) else { panic!() };
    assert_eq!((r.code, r.locus), (Code::DegenerateCone, Locus::Kind(KindLocus::ConvexCone { cone: 3 })));
    // Wrong number of cones.
    let mut t = good.clone();
    t.cones.pop();
    let Verdict::Rejected(r) = both(&t) else { panic!() };
    assert_eq!(r.code, Code::WrongArity);
    // The same cone for every contact (no relabelling): K2 fails at some transition.
    let mut t = good.clone();
    t.cones = vec![good.cones[0].clone(); 4];
    let Verdict::Rejected(r) = both(&t) else { panic!() };
    assert!(
        matches!(
            r.locus,
            Locus::Kind(KindLocus::Transition { .. }) | Locus::Kind(KindLocus::ConvexAllDown { .. })
        ),
        "{r:?}"
    );
    // Bad body: clockwise contacts.
    let mut t = good.clone();
    let ConvexBodyText::ConvexPolygon { contacts, .. } = &mut t.body;
    contacts.reverse();
    let Verdict::Rejected(r) = both(&t) else { panic!() };
    assert_eq!(r.code, Code::UnsupportedBody, "{r}");
    // gamma out of range.
    let Verdict::Rejected(r) = both(&convex_with_gamma(&good, "3/2")) else { panic!() };
    assert_eq!(r.code, Code::ParameterOutOfRange, "{r}");
}

#[test]
fn versions_one_to_three_are_unchanged() {
    // Every valid cone certificate (versions 1-3) still verifies, and the family reader refuses
    // it (and the cone reader refuses a family certificate), so the forms never mix.
    let dir = root().join("certificates/valid");
    let mut old = 0;
    for e in std::fs::read_dir(&dir).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_name().unwrap().to_string_lossy().to_string();
        if !name.ends_with(".ron") || name.starts_with("refutation-") {
            continue;
        }
        let text = std::fs::read_to_string(&p).unwrap();
        let kind = chatter_kernel::syntax::kind_of(&text, Encoding::Ron, Kind::Cone).unwrap().0;
        if let Ok(c) = chatter_kernel::certificate::read(&text) {
            assert!(c.version <= 3);
            assert!(
                matches!(verify_text(&text, ParseLimits::default(), &[MALACHITE, NUM]), Verdict::Accepted(_)),
                "{name}"
            );
            assert_eq!(read_convex(&text, Encoding::Ron).unwrap_err().code, Code::WrongFormat);
            old += 1;
        } else if matches!(kind, Kind::Orbit | Kind::Basin | Kind::Rest | Kind::RestFamily) {
            // An orbit, basin or time-to-rest certificate is read by neither of the other readers.
            assert_eq!(read_convex(&text, Encoding::Ron).unwrap_err().code, Code::WrongFormat);
        } else {
            let c = read_convex(&text, Encoding::Ron).unwrap();
            // Version 2 only where gamma is an interval (docs/certificate-format.md §13).
            let interval =
                matches!(&c.body, ConvexBodyText::ConvexPolygon { gamma: Param::Interval(..), .. });
            let version = if interval { 2 } else { 1 };
            assert_eq!((c.format.as_str(), c.version), ("chatter-family-certificate", version), "{name}");
            let r = chatter_kernel::certificate::read(&text).unwrap_err();
            assert_eq!(r.code, Code::WrongFormat, "{name}");
        }
    }
    assert!(old >= 30);
}

/// The family-certificate corpus files are exactly what the transport produces (valid ones accepted,
/// invalid ones rejected); with `CHATTER_WRITE_CORPUS=1` the test rewrites them instead.
#[test]
fn the_convex_corpus_is_what_the_transport_writes() {
    let file = |dir: &str, name: &str| root().join("certificates").join(dir).join(name);
    let rewrite = std::env::var_os("CHATTER_WRITE_CORPUS").is_some_and(|v| v == "1");
    let check = |path: std::path::PathBuf, text: String| {
        if rewrite {
            std::fs::write(&path, text).unwrap();
        } else {
            assert_eq!(std::fs::read_to_string(&path).unwrap(), text, "{} is stale", path.display());
        }
    };
    let read_old = |name: &str| {
        chatter_kernel::certificate::read(&std::fs::read_to_string(file("invalid", name)).unwrap()).unwrap()
    };
    let square = regular(4, "1/6", "1/50");
    let triangle = regular(3, "1/8", "1/20");
    let rect = |g: &str| plates(&q(g)).remove(0).2;
    let tri = |g: &str| plates(&q(g)).remove(3).2;
    let valid = [
        ("convex-rectangle-2x1-gamma1_50.ron", transport(&rect("1/50"), &square).unwrap()),
        ("convex-triangle-irregular-gamma1_20.ron", transport(&tri("1/20"), &triangle).unwrap()),
    ];
    for (name, c) in &valid {
        assert!(matches!(both(c), Verdict::Accepted(_)), "{name}");
        check(file("valid", name), write_convex(c));
    }
    let good = &valid[0].1;
    let mut below = good.clone();
    below.cones[2][1].0[2] = "0".into();
    let mut flat = good.clone();
    flat.cones[3].truncate(2);
    let mut clockwise = good.clone();
    let ConvexBodyText::ConvexPolygon { contacts, .. } = &mut clockwise.body;
    contacts.reverse();
    let invalid = [
        ("convex-generator-v-zero.ron", below),
        ("convex-flat-cone.ron", flat),
        ("convex-clockwise-contacts.ron", clockwise),
        // Claimed EffectivelyInvariant, so that only K2 fails (with CompleteChatterFromAllDown
        // K3 fails too: oracle/findings/corpus-files-breaking-two-rules.md).
        ("convex-gamma-raised.ron", {
            let mut c = transport(&rect("1/5"), &square).unwrap();
            c.claim = Claim::EffectivelyInvariant;
            c
        }),
        (
            "convex-vacuous-cones-all-down-claim.ron",
            transport(&rect("1/100"), &read_old("vacuous-cone-all-down-claim.ron")).unwrap(),
        ),
        (
            "convex-pcc-not-excluded.ron",
            transport(&rect("1/1000"), &read_old("pcc-square-tiny-gamma.ron")).unwrap(),
        ),
    ];
    for (name, c) in &invalid {
        assert!(matches!(both(c), Verdict::Rejected(_)), "{name} is accepted");
        check(file("invalid", name), write_convex(c));
    }
}
