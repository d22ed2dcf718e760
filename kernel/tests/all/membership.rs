//! `chatter_kernel::membership` (issue 22 §1): membership of exact states in the cone K of an
//! accepted cone certificate and in the set X of an accepted orbit certificate, against
//! brute-force facts: the generators and the images I_0(D) lie in K, points beyond an edge do
//! not, x* lies in X and points beyond δ along an axis do not; rejected certificates give no set.
#![cfg(all(feature = "orbit", feature = "field"))]

use chatter_kernel::certificate::{Encoding, read, read_orbit};
use chatter_kernel::exact::{Algebraic, OrderedField, Ring, parse_canonical};
use chatter_kernel::membership::{CertifiedCone, CertifiedOrbit, NotCertified};
use chatter_kernel::model::Polygon;
use chatter_kernel::model::linalg::mat_vec;
use std::path::PathBuf;

/// The main backend's rationals (membership is generic over the backend).
type Q = malachite::rational::Rational;
type Exact = chatter_kernel::membership::Exact<Q>;

fn file(rel: &str) -> String {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    std::fs::read_to_string(root.join(rel)).unwrap()
}

fn e(x: &Q) -> Exact {
    Algebraic::rational(x.clone())
}

fn v(x: [i64; 3], d: i64) -> [Exact; 3] {
    x.map(|c| e(&Q::from_ratio(c, d)))
}

#[test]
fn the_doc_example_cone_contains_its_generators_and_the_all_down_images_and_nothing_beyond() {
    let cert = read(&file("certificates/valid/doc-example-square.ron")).unwrap();
    let (cone, accepted) =
        CertifiedCone::<Q>::new(&cert, Default::default()).unwrap_or_else(|_| panic!("accepted"));
    assert_eq!(accepted.n, 4);
    // K is 0 <= u0/(-v) <= 1/20, -11/4 <= u1/(-v) <= 3/4 (docs/certificate-format.md §1).
    for g in [[0, -55, -20], [1, -55, -20], [1, 15, -20], [0, 15, -20], [1, -20, -40]] {
        assert!(cone.contains(&v(g, 20)), "{g:?}");
        let scaled = v(g.map(|c| 7 * c), 3);
        assert!(cone.contains(&scaled), "positive multiples of {g:?}");
    }
    for g in [[-1, 0, -20], [2, 0, -20], [0, 16, -20], [0, -56, -20], [0, 0, 20], [0, 0, 0]] {
        assert!(!cone.contains(&v(g, 20)), "{g:?}");
    }
    let body = Polygon::<Q>::new(4, Q::from_ratio(1, 6), Q::from_ratio(1, 100)).unwrap();
    for g in body.all_down_generators() {
        let img = mat_vec(&body.impact(0), &g);
        assert!(cone.contains(&img.each_ref().map(e)), "I_0 of {g:?}");
    }
    assert!(cone.applies_to(4, &e(&Q::from_ratio(1, 6)), &e(&Q::from_ratio(1, 100))));
    assert!(!cone.applies_to(4, &e(&Q::from_ratio(1, 6)), &e(&Q::from_ratio(1, 99))));
    assert!(!cone.applies_to(3, &e(&Q::from_ratio(1, 6)), &e(&Q::from_ratio(1, 100))));
}

#[test]
fn a_rejected_certificate_gives_no_set() {
    let cert = read(&file("certificates/invalid/shrunk-rectangle.ron")).unwrap();
    assert!(matches!(CertifiedCone::<Q>::new(&cert, Default::default()), Err(NotCertified::Verdict(_))));
    let orbit = read_orbit(&file("certificates/invalid/orbit-delta-enlarged.ron"), Encoding::Ron).unwrap();
    assert!(matches!(CertifiedOrbit::<Q>::new(&orbit, Default::default()), Err(NotCertified::Verdict(_))));
}

/// The numbers of a parallelepiped orbit certificate: x*, the axes (columns) and δ.
fn parallelepiped(text: &str) -> ([Q; 3], [[Q; 3]; 3], Q) {
    let cert = read_orbit(text, Encoding::Ron).unwrap();
    let chatter_kernel::certificate::OrbitSet::Parallelepiped { centre, axes, delta } = &cert.set else {
        panic!("a parallelepiped")
    };
    let n = |s: &str| parse_canonical::<Q>(s, Default::default()).unwrap();
    let t = |t: &(String, String, String)| [n(&t.0), n(&t.1), n(&t.2)];
    (t(centre), [t(&axes.0), t(&axes.1), t(&axes.2)], n(delta))
}

#[test]
fn the_orbit_set_contains_its_centre_and_stops_at_delta_along_each_axis() {
    let text = file("certificates/valid/orbit-n3-kappa1_8-gamma3_20.ron");
    let cert = read_orbit(&text, Encoding::Ron).unwrap();
    let (orbit, _) =
        CertifiedOrbit::<Q>::new(&cert, Default::default()).unwrap_or_else(|_| panic!("accepted"));
    let (x, axes, delta) = parallelepiped(&text);
    // A state (q, p) with q = (0, a, 1) hc, p = (b, c, -1) w for x = (a, b, c), any hc, w > 0.
    let state = |x: &[Q; 3], hc: i64, w: i64| {
        let (hc, w) = (Q::from_i64(hc), Q::from_i64(w));
        let q = [Q::zero(), x[0].times(&hc), hc.clone()].map(|c| e(&c));
        let p = [x[1].times(&w), x[2].times(&w), w.negated()].map(|c| e(&c));
        (q, p)
    };
    let (q, p) = state(&x, 3, 5);
    assert!(orbit.contains(&q, &p), "x* itself");
    for (k, axis) in axes.iter().enumerate() {
        for (factor, inside) in
            [(Q::one(), true), (Q::from_ratio(-1, 1), true), (Q::from_ratio(1001, 1000), false)]
        {
            let point: [Q; 3] = std::array::from_fn(|i| x[i].plus(&axis[i].times(&delta).times(&factor)));
            let (q, p) = state(&point, 2, 7);
            assert_eq!(orbit.contains(&q, &p), inside, "axis {k}, factor {factor}");
        }
    }
    // Not a post-impact state at contact 0 (h0 > 0), or the centre moving up.
    let (mut q, p) = state(&x, 1, 1);
    q[0] = e(&Q::from_ratio(1, 1000));
    assert!(!orbit.contains(&q, &p));
    let (q, mut p) = state(&x, 1, 1);
    p[2] = e(&Q::one());
    assert!(!orbit.contains(&q, &p));
    assert!(orbit.applies_to(3, &e(&Q::from_ratio(1, 8)), &e(&Q::from_ratio(3, 20))));
    assert!(!orbit.applies_to(3, &e(&Q::from_ratio(1, 8)), &e(&Q::from_ratio(3, 19))));
}

#[test]
fn a_number_field_cone_decides_membership_in_its_field() {
    // Certificates for n = 7 are in Q(cos 2 pi/7); the generators themselves lie in K.
    let text = file("certificates/valid/n7-kappa1_200-gamma1_5-complete-chatter-from-all-down.ron");
    let cert = read(&text).unwrap();
    let (cone, _) = CertifiedCone::<Q>::new(&cert, Default::default()).unwrap_or_else(|_| panic!("accepted"));
    let field = chatter_kernel::exact::CosField::<Q>::new(7).unwrap();
    for g in &cert.cone {
        let p: Vec<Exact> = g.0.iter().map(|s| field.parse(s, Default::default()).unwrap()).collect();
        assert!(cone.contains(&[p[0].clone(), p[1].clone(), p[2].clone()]));
        let beyond = [p[0].clone(), p[1].clone(), p[2].negated()];
        assert!(!cone.contains(&beyond), "v > 0 is never in K");
    }
    let _ = Exact::one().over(&Exact::from_i64(2));
}
