//! Tests of `kernel/src/model/convex/pcc.rs`: the pair quadratic of I_k I_{k+1}
//! (docs/model.md §11.6, the generalised Lemma on PCC).

use super::{Rng, bodies, fixed_bodies, height};
use chatter::exact::{Q, QExt};
use chatter_kernel::model::linalg::{Vec3, mat_vec};
use chatter_kernel::model::{ConvexBody, PccExclusion};
use proptest::prelude::*;

/// mu^2 = <f_a, f_b>^2 / (N_a N_b) from the contact coordinates and J^{-1}, without the kernel.
fn mu2(b: &ConvexBody<Q>, a: usize, c: usize) -> Q {
    let j = b.inertia();
    let det = &j[0][0] * &j[1][1] - &j[0][1] * &j[1][0];
    let g = |r: &[Q; 2]| [r[1].clone(), -&r[0]];
    let (ga, gc) = (g(&b.contacts()[a]), g(&b.contacts()[c]));
    // x^T J^{-1} y with J^{-1} = [[j11, -j01], [-j10, j00]] / det.
    let form = |x: &[Q; 2], y: &[Q; 2]| {
        (&x[0] * (&j[1][1] * &y[0] - &j[0][1] * &y[1]) + &x[1] * (&j[0][0] * &y[1] - &j[1][0] * &y[0])) / &det
    };
    let one = Q::int(1);
    let prod = &one + form(&ga, &gc);
    &prod * &prod / ((&one + form(&ga, &ga)) * (&one + form(&gc, &gc)))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    /// (t - 1)(t^2 + p t + q) with q = gamma^2, p = 2 gamma - (1 + gamma)^2 mu^2, discriminant
    /// (1 + gamma)^2 mu^2 ((1 + gamma)^2 mu^2 - 4 gamma); I_k I_{k+1} fixes m_{k,k+1}.
    #[test]
    fn the_pair_quadratic_has_the_closed_form(b in bodies()) {
        let g = b.gamma().clone();
        let one = Q::int(1);
        for k in 0..b.n() {
            let quad = b.pair_pcc_quadratic(k as i64).expect("t = 1 is a root");
            let m = mu2(&b, k, (k + 1) % b.n());
            prop_assert_eq!(&b.coupling_squared(k as i64, k as i64 + 1), &m);
            prop_assert!(m >= Q::int(0) && m < one);
            let c2m = (&one + &g) * (&one + &g) * &m;
            prop_assert_eq!(&quad.q, &(&g * &g));
            prop_assert_eq!(&quad.p, &(Q::int(2) * &g - &c2m));
            prop_assert_eq!(&quad.discriminant, &(&c2m * (&c2m - Q::int(4) * &g)));
            let rest = b.edge_rest_point(k as i64);
            prop_assert_eq!(&mat_vec(&b.pair_map(k as i64), rest), rest);
        }
    }

    /// The speeds (u_k, u_{k+1}) after the impacts at k evolve by themselves (a 2 x 2 block B
    /// with eigenvalues gamma e^{+-i theta}, cos theta = -p / (2 gamma)); when the quadratic has
    /// complex roots, the alternation k, k+1, k, ... stops within ceil(pi / theta) + 1 rounds:
    /// some impact leaves the next contact of the pair not moving down (docs/model.md §11.6).
    #[test]
    fn complex_roots_stop_the_alternation(b in bodies(), seed in any::<u64>()) {
        let mut rng = Rng::new(seed);
        for k in 0..b.n() as i64 {
            let quad = b.pair_pcc_quadratic(k).unwrap();
            if quad.discriminant >= Q::int(0) {
                continue;
            }
            let theta = (-quad.p.to_f64() / (2.0 * b.gamma().to_f64())).clamp(-1.0, 1.0).acos();
            let rounds = (std::f64::consts::PI / theta).ceil() as usize + 1;
            if rounds > 60 {
                continue; // exact numbers would grow too long; rare
            }
            let (ra, rb) = (b.contact_point(k).clone(), b.contact_point(k + 1).clone());
            // Start right after an impact at k (u_k >= 0).
            let mut p: Vec3<Q> = [rng.ratio(-9, 9, 4), rng.ratio(-9, 9, 4), rng.ratio(-9, 0, 4)];
            if height(&ra, &p) < Q::int(0) {
                p = mat_vec(&b.impact(k), &p);
            }
            let (ia, ib) = (b.impact(k), b.impact(k + 1));
            let mut stopped = false;
            for _ in 0..rounds {
                if height(&rb, &p) >= Q::int(0) {
                    stopped = true;
                    break;
                }
                p = mat_vec(&ib, &p);
                if height(&ra, &p) >= Q::int(0) {
                    stopped = true;
                    break;
                }
                p = mat_vec(&ia, &p);
            }
            prop_assert!(stopped, "pair ({}, {}) alternated {} rounds with complex roots", k, k + 1, rounds);
        }
    }
}

#[test]
fn exclusion_needs_complex_roots_and_gamma_below_one() {
    // The square plate (contacts on the unit circle, J = I/6) at gamma = 1: complex roots of
    // modulus 1 (t^2 + 94/49 t + 1 as in docs/model.md §5), which the kernel keeps as "not
    // excluded"; at gamma = 1/1000 the roots are real.
    let sq = |g: Q| {
        let pts = [(1, 0), (0, 1), (-1, 0), (0, -1)].map(|(x, y)| [Q::int(x), Q::int(y)]).to_vec();
        ConvexBody::new(pts, [[Q::new(1, 6), Q::int(0)], [Q::int(0), Q::new(1, 6)]], g).unwrap()
    };
    let elastic = sq(Q::int(1)).pair_pcc_quadratic(0).unwrap();
    assert_eq!(elastic.p, Q::new(94, 49));
    assert_eq!(elastic.exclusion(), PccExclusion::ModulusNotBelowOne);
    assert_eq!(sq(Q::new(1, 1000)).pair_pcc_quadratic(2).unwrap().exclusion(), PccExclusion::RealRoots);
    assert_eq!(sq(Q::new(1, 2)).pair_pcc_quadratic(3).unwrap().exclusion(), PccExclusion::Excluded);
    // Irregular bodies: every pair has its own quadratic.
    for b in fixed_bodies() {
        let ps: Vec<Q> = (0..b.n() as i64).map(|k| b.pair_pcc_quadratic(k).unwrap().p).collect();
        assert!(ps.windows(2).any(|w| w[0] != w[1]), "{ps:?}");
    }
}
