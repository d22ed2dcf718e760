//! Tests of `bodies`: kappa derived from geometry, the catalogue's thresholds and comparisons;
//! [`convex`]: the general convex bodies of `bodies::convex`; [`general`]: the named ones;
//! [`inertia`]: full inertia tensors and J_eff against a 3-D impulse computation; [`rule_k0`]: the
//! kernel's check that a family certificate's J is J_eff of the tensor it records.

mod convex;
mod general;
mod inertia;
mod rule_k0;

use chatter::bodies::{self, PaperValue, catalogue, platonic, prism, thresholds, uniform_rod};
use chatter::exact::{Q, Ring};
use chatter::spectral::number_field::Nf;
use chatter::spectral::poly::Poly;
use chatter::spectral::roots::isolate;
use chatter_kernel::exact::OrderedField as _;
use std::cmp::Ordering;

fn rational(x: &Nf) -> Q {
    x.as_rational().expect("a rational kappa")
}

#[test]
fn plate_kappas_follow_from_the_polygon_moments() {
    // (1 + 2 cos^2(pi/n))/12 = (2 + cos(2 pi/n))/12 (docs/model.md §9), exactly in Q(cos 2pi/n).
    for n in 3..=12 {
        let e = prism(n, &Q::int(0)).unwrap();
        let c1 = bodies::cosine(n);
        let closed = Nf::from_i64(2).plus(&c1).over(&Nf::from_i64(12)).unwrap();
        assert_eq!(e.kappa, closed, "n = {n}");
        let (mx, my) = chatter::bodies::solids::plate_second_moments(n, &c1);
        assert_eq!(mx, my, "n = {n}: a regular plate is isotropic");
    }
    assert_eq!(rational(&prism(3, &Q::int(0)).unwrap().kappa), Q::new(1, 8));
    assert_eq!(rational(&prism(4, &Q::int(0)).unwrap().kappa), Q::new(1, 6));
    assert_eq!(rational(&prism(6, &Q::int(0)).unwrap().kappa), Q::new(5, 24));
    // A square prism of height 1: 1/6 + 1/12.
    assert_eq!(rational(&prism(4, &Q::int(1)).unwrap().kappa), Q::new(1, 4));
    assert_eq!(rational(&uniform_rod().kappa), Q::new(1, 3));
}

#[test]
fn platonic_kappas_match_the_model_formulas() {
    // kappa = 4 c sin^2(pi/n) with c = 1/20, 1/6, 1/10, (95+39 sqrt5)/300, (3+sqrt5)/20.
    let s5 = 5f64.sqrt();
    for (name, n, exact, approx) in [
        ("tetrahedron", 3, Some(Q::new(3, 20)), 0.15),
        ("cube", 4, Some(Q::new(1, 3)), 1.0 / 3.0),
        ("octahedron", 3, Some(Q::new(3, 10)), 0.3),
        ("dodecahedron", 5, None, (14.0 + 5.0 * s5) / 30.0),
        ("icosahedron", 3, None, 3.0 * (3.0 + s5) / 20.0),
    ] {
        let e = platonic(name, n).unwrap();
        assert!(e.derivation.contains("equals 4 c sin^2(pi/n) exactly"), "{name}: {}", e.derivation);
        if let Some(q) = exact {
            assert_eq!(rational(&e.kappa), q, "{name}");
        }
        assert!((bodies::kappa_f64(&e) - approx).abs() < 1e-12, "{name}");
    }
    assert!(platonic("dodecahedron", 3).is_err(), "faces of the dodecahedron are pentagons");
}

#[test]
fn the_catalogue_and_its_thresholds() {
    let cat = catalogue().unwrap();
    assert_eq!(cat.len(), 12);
    let find = |s: &str| cat.iter().find(|e| e.name.starts_with(s)).unwrap();
    // The rod: 7 - 4 sqrt 3.
    let (cc, pcc) = thresholds(find("uniform rod"), 12);
    assert!(pcc.is_none());
    assert_eq!(cc.kind, "below");
    assert!((cc.midpoint.unwrap() - (7.0 - 4.0 * 3f64.sqrt())).abs() < 1e-12);
    // The flat triangle plate's CC criterion ends at the +-rho tie, a root of g^2 - 7g + 1:
    // (7 - 3 sqrt 5)/2 = 0.1459..., far above the paper's 0.04.
    let tri = find("flat triangle");
    let (cc, pcc) = thresholds(tri, 12);
    let mut r = isolate(&Poly::new(vec![Q::int(1), Q::int(-7), Q::int(1)])).swap_remove(0);
    let [lo, hi] = cc.interval.clone().unwrap();
    let (lo, hi): (Q, Q) = (lo.parse().unwrap(), hi.parse().unwrap());
    assert_eq!(r.sign_of(&Poly::new(vec![-lo, Q::int(1)])), Ordering::Greater, "lo < threshold");
    assert_eq!(r.sign_of(&Poly::new(vec![-hi, Q::int(1)])), Ordering::Less, "threshold < hi");
    assert_eq!(bodies::compare(tri.paper_cc, &cc).unwrap().status, "disagrees");
    assert_eq!(bodies::compare(tri.paper_pcc, &pcc.unwrap()).unwrap().status, "disagrees");
    // The octahedron agrees with the paper on both; the square plate's CC threshold too.
    let oct = find("octahedron");
    let (cc, pcc) = thresholds(oct, 12);
    assert!(bodies::compare(oct.paper_cc, &cc).unwrap().agrees());
    assert!(bodies::compare(oct.paper_pcc, &pcc.unwrap()).unwrap().agrees());
    let sq = find("flat square");
    let (cc, pcc) = thresholds(sq, 12);
    assert!(bodies::compare(sq.paper_cc, &cc).unwrap().agrees());
    assert_eq!(sq.paper_pcc, Some(PaperValue::Never));
    assert_eq!(pcc.unwrap().kind, "below", "the PCC criterion holds near gamma = 0 for the square");
    // Heavy bodies never meet the CC criterion.
    for name in ["cube", "dodecahedron", "icosahedron", "flat hexagon", "flat octagon"] {
        assert_eq!(thresholds(find(name), 12).0.kind, "never", "{name}");
    }
}

#[test]
fn the_triangle_plate_is_certified_where_the_paper_says_it_does_not_chatter() {
    // Exact certificates at gamma = 1/10 and 7/50 (the paper: CC only below 0.04).
    for g in ["1/10", "7/50"] {
        let r =
            chatter::certify::certify(&chatter::certify::Request::new(3, Q::new(1, 8), g.parse().unwrap()));
        let c = r.result.unwrap_or_else(|e| panic!("gamma = {g}: {e}"));
        assert_eq!(c.claim, chatter_kernel::certificate::Claim::CompleteChatterFromAllDown);
    }
}
