//! Orbit certificates for every n (issue 22 §2; docs/kernel-soundness.md §7.1): the body's
//! constants as rational enclosures. The number-field path agrees with the rational path for
//! n = 3, 4, 6; enclosures of irrational constants contain the exact elements of Q(cos 2π/n) and
//! are narrow; the checker's verdicts survive widening the constants to proper intervals.

#![cfg(all(feature = "orbit", feature = "field"))]

use chatter_kernel::certificate::{Encoding, read_orbit};
use chatter_kernel::exact::{Algebraic, CosField, OrderedField, ParseLimits, Ring, parse_canonical};
use chatter_kernel::model::Polygon;
use chatter_kernel::orbit::constants::{WIDTH_BITS, enclose, enclosed_maps, field_maps};
use chatter_kernel::orbit::map::Maps;
use chatter_kernel::orbit::{Iv, cover, read_orbit_values};
use std::path::PathBuf;

type Q = malachite::rational::Rational;
type Nq = num_rational::BigRational;

fn file(rel: &str) -> String {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    std::fs::read_to_string(root.join(rel)).unwrap()
}

fn q(s: &str) -> Q {
    parse_canonical(s, ParseLimits::default()).unwrap()
}

/// Every constant of the maps, in order.
fn constants<K: Clone>(m: &Maps<K>) -> Vec<K> {
    m.contacts.iter().flatten().chain(m.impact0.iter().flatten()).cloned().collect()
}

fn number_field_path_agrees_with_the_rational_path<F: chatter_kernel::exact::Field>() {
    for n in [3, 4, 6] {
        let (kappa, gamma) = (F::from_ratio(1, 8), F::from_ratio(3, 20));
        let rational = Maps::new(&Polygon::new(n, kappa.clone(), gamma.clone()).unwrap()).map(Iv::exact);
        let field = field_maps(n, kappa.clone(), gamma.clone()).unwrap();
        assert_eq!(field, rational, "n = {n}: Q(cos 2π/n) = Q, the same exact points");
        assert_eq!(enclosed_maps(n, kappa, gamma).unwrap(), rational, "n = {n}");
        assert!(constants(&field).iter().all(Iv::is_point));
    }
}

#[test]
fn the_number_field_path_agrees_with_the_rational_path_for_n_3_4_6_on_both_backends() {
    number_field_path_agrees_with_the_rational_path::<Q>();
    number_field_path_agrees_with_the_rational_path::<Nq>();
}

#[test]
fn enclosures_of_irrational_constants_contain_the_exact_elements_and_are_narrow() {
    const { assert!(WIDTH_BITS >= 64, "narrower than the outward rounding's grid") };
    for n in [5u64, 7, 8, 9, 12, 64] {
        let field = CosField::<Q>::new(n).unwrap();
        let (kappa, gamma) =
            (Algebraic::rational(Q::from_ratio(961, 25600)), Algebraic::rational(Q::from_ratio(61, 160)));
        let body = Polygon::with_cosine(n, field.generator(), kappa, gamma).unwrap();
        let exact = constants(&Maps::new(&body));
        let enclosed = constants(&field_maps(n, Q::from_ratio(961, 25600), Q::from_ratio(61, 160)).unwrap());
        assert_eq!(exact.len(), enclosed.len());
        let mut proper = 0;
        for (x, iv) in exact.iter().zip(&enclosed) {
            let (lo, hi) = (Algebraic::rational(iv.lo.clone()), Algebraic::rational(iv.hi.clone()));
            assert!(lo <= *x && *x <= hi, "n = {n}: {x:?} not in [{}, {}]", iv.lo, iv.hi);
            // Outward rounding to 64-bit mantissas: relative width about 2^-62 at worst.
            let scale = iv.hi.clone().max(iv.lo.negated()).max(Q::from_ratio(1, 1));
            assert!(iv.hi.minus(&iv.lo) <= Q::from_ratio(1, 1 << 60).times(&scale), "n = {n}: {iv:?}");
            if !iv.is_point() {
                proper += 1;
            }
            assert_eq!(enclose(x), *iv);
        }
        // Contact 0 = (1, 0, 0) and contact 1 = (0, 1, 0) are exact; every other contact is not.
        assert!(proper >= n as usize - 2, "n = {n}: {proper} proper enclosures");
    }
}

#[test]
fn n_beyond_max_n_is_unsupported() {
    let e = enclosed_maps(65, Q::from_ratio(1, 8), Q::from_ratio(1, 2)).unwrap_err();
    assert_eq!(e, chatter_kernel::model::polygon::BodyError::UnsupportedN(65));
}

/// Every constant widened by `w` on each side: a proper interval, as for irrational constants.
fn widened(m: &Maps<Iv<Q>>, w: &Q) -> Maps<Iv<Q>> {
    m.map(|c| Iv { lo: c.lo.minus(w), hi: c.hi.plus(w) })
}

#[test]
fn the_triangle_certificates_verdicts_survive_constants_known_only_by_intervals() {
    let w = Q::from_ratio(1, 1 << 60).times(&Q::from_ratio(1, 1 << 10));
    let limits = ParseLimits::default();
    for (rel, accepted) in [
        ("certificates/valid/orbit-n3-kappa1_8-gamma3_20.ron", true),
        ("certificates/valid/orbit-box-n3-kappa1_8-gamma3_20.ron", true),
        ("certificates/invalid/orbit-centre-off-orbit.ron", false),
        ("certificates/invalid/orbit-rho-too-small.ron", false),
        ("certificates/invalid/orbit-pattern-step-changed.ron", false),
    ] {
        let cert = read_orbit(&file(rel), Encoding::Ron).unwrap();
        let mut orbit = read_orbit_values::<Q>(&cert, limits).unwrap();
        let exact = cover(&orbit, limits);
        orbit.maps = widened(&orbit.maps, &w);
        let wide = cover(&orbit, limits);
        assert_eq!(exact.is_ok(), accepted, "{rel}: {exact:?}");
        match (exact, wide) {
            (Ok(a), Ok(b)) => assert_eq!(a, b, "{rel}: the same sub-boxes shown"),
            (Err(a), Err(b)) => assert_eq!(a.code, b.code, "{rel}"),
            (a, b) => panic!("{rel}: exact constants {a:?}, widened {b:?}"),
        }
    }
    // Much wider constants cannot show the valid certificate's signs: the widths are used.
    let cert =
        read_orbit(&file("certificates/valid/orbit-n3-kappa1_8-gamma3_20.ron"), Encoding::Ron).unwrap();
    let mut orbit = read_orbit_values::<Q>(&cert, limits).unwrap();
    orbit.maps = widened(&orbit.maps, &Q::from_ratio(1, 100));
    assert!(cover(&orbit, limits).is_err());
}

const PENTAGON: &str = "certificates/valid/orbit-n5-kappa961_25600-gamma61_160.ron";

#[test]
fn the_pentagon_return_map_in_q_cos_2pi_5_lies_in_the_kernels_enclosures() {
    use chatter_kernel::orbit::map::period;
    use chatter_kernel::orbit::{Centred, return_map};
    let limits = ParseLimits::default();
    let cert = read_orbit(&file(PENTAGON), Encoding::Ron).unwrap();
    let orbit = read_orbit_values::<Q>(&cert, limits).unwrap();
    assert_eq!(orbit.maps.n, 5);
    // Exactly, in Q(cos 2π/5), at the rational point x*.
    let field = CosField::<Q>::new(5).unwrap();
    let (kappa, gamma) = (Algebraic::rational(q("961/25600")), Algebraic::rational(q("61/160")));
    let body = Polygon::with_cosine(5, field.generator(), kappa, gamma).unwrap();
    let x = orbit.centre.clone().map(Algebraic::rational);
    let exact = return_map(&body, &orbit.pattern, &x).expect("conditions 1-2 hold at x*");
    assert!(exact.next.iter().all(|e| e.field_n() == Some(5)), "irrational: {:?}", exact.next);
    // The kernel's enclosures at the same point (a box of radius 0), from the enclosed constants.
    let zero = || [Iv::zero(), Iv::zero(), Iv::zero()];
    let r = std::sync::Arc::new(zero());
    let seeds: [Centred<Q>; 3] = std::array::from_fn(|i| {
        Centred::seed(Iv::exact(&orbit.centre[i]), Iv::exact(&orbit.centre[i]), zero(), r.clone())
    });
    let enclosed = period(&orbit.maps, &orbit.pattern, &seeds, &mut |_, _| Ok(())).unwrap();
    let pairs = exact.next.iter().zip(&enclosed.next).chain([
        (&exact.alpha, &enclosed.alpha),
        (&exact.beta, &enclosed.beta),
        (&exact.time, &enclosed.time),
    ]);
    for (e, iv) in pairs {
        let (lo, hi) = (&iv.b.v.lo, &iv.b.v.hi);
        assert!(
            Algebraic::rational(lo.clone()) <= *e && *e <= Algebraic::rational(hi.clone()),
            "{e:?} not in [{lo}, {hi}]"
        );
        assert!(hi.minus(lo) < Q::from_ratio(1, 1_000_000_000_000), "[{lo}, {hi}] is narrow");
    }
    // x* is (nearly) a fixed point: R_P(x*) - x* is small but not zero.
    let moved = exact.next[0].minus(&x[0]);
    assert!(moved != Algebraic::rational(Q::from_ratio(0, 1)));
    let tiny = Algebraic::rational(Q::from_ratio(1, 1 << 30));
    assert!(moved < tiny && moved.negated() < tiny, "{moved:?}");
}

#[test]
fn the_pentagon_certificate_is_accepted_on_both_backends_with_the_same_sub_boxes() {
    let limits = ParseLimits::default();
    let cert = read_orbit(&file(PENTAGON), Encoding::Ron).unwrap();
    let a = cover(&read_orbit_values::<Q>(&cert, limits).unwrap(), limits).unwrap();
    let b = cover(&read_orbit_values::<Nq>(&cert, limits).unwrap(), limits).unwrap();
    assert_eq!((a, b), (8, 8));
}

/// Issue 24: an accepted orbit certificate reports B = T̄/(1 − ρ) of its Theorem (the impacts
/// accumulate within B h/|v|), the same on both backends, computed here by hand from the file.
#[test]
fn accepted_orbit_certificates_report_their_time_to_rest_bound() {
    use chatter_kernel::verify::{Verdict, verify_orbit};
    for rel in [
        PENTAGON,
        "certificates/valid/orbit-n3-kappa1_8-gamma3_20.ron",
        "certificates/valid/orbit-n8-kappa1_100-gamma2_5.ron",
    ] {
        let cert = read_orbit(&file(rel), Encoding::Ron).unwrap();
        let Verdict::Accepted(a) = verify_orbit(&cert, ParseLimits::default()) else { panic!("{rel}") };
        let (rho, period) = (q(&cert.rho), q(&cert.period));
        let b = period / (Q::from(1) - rho);
        assert_eq!(a.time_to_rest_bound, Some(b.to_string()), "{rel}");
    }
}
