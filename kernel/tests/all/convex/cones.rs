//! Tests of `kernel/src/model/convex/cones.rs`: rest points m_{k,l}, the cones C_{ij} (the
//! generalised Lemma on C_j, docs/model.md §11.4) checked against brute-force kinematics, and D.

use super::{Rng, bodies, fixed_bodies, height, inside};
use chatter_kernel::model::ConvexBody;
use chatter_kernel::model::linalg::{Vec3, det3, dot};
use malachite::rational::Rational as Q;
use proptest::prelude::*;

fn zero() -> Q {
    Q::from(0)
}

/// Heights of all contacts for the configuration q, straight from the contact coordinates.
fn heights(b: &ConvexBody<Q>, q: &Vec3<Q>) -> Vec<Q> {
    b.contacts().iter().map(|r| height(r, q)).collect()
}

/// A configuration with contact i on the floor and every other contact at or above it: a random
/// small rotation phi, and h chosen so that h_i = 0 (rejection sampling; `None` if unlucky).
fn configuration_on(b: &ConvexBody<Q>, i: usize, rng: &mut Rng) -> Option<Vec3<Q>> {
    for _ in 0..64 {
        let (px, py) = (rng.ratio(-30, 30, 9), rng.ratio(-30, 30, 9));
        let r = &b.contacts()[i];
        let h = -(&px * &r[1] - &py * &r[0]);
        let q = [px, py, h];
        if heights(b, &q).iter().all(|x| *x >= zero()) {
            return Some(q);
        }
    }
    None
}

/// The contacts that land first (all ties) moving from q with velocity p, with their time t > 0,
/// among the contacts other than i that move down; `None` if none moves down.
fn first_landing(b: &ConvexBody<Q>, i: usize, q: &Vec3<Q>, p: &Vec3<Q>) -> Option<(Q, Vec<usize>)> {
    let mut best: Option<(Q, Vec<usize>)> = None;
    for (k, r) in b.contacts().iter().enumerate().filter(|(k, _)| *k != i) {
        let u = height(r, p);
        if u >= zero() {
            continue;
        }
        let t = height(r, q) / (-u);
        match &mut best {
            Some((bt, ks)) if t == *bt => ks.push(k),
            Some((bt, _)) if t > *bt => {}
            _ => best = Some((t, vec![k])),
        }
    }
    best
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(160))]

    /// The Lemma, forwards: after an impact at i (contact i on the floor, the others at or above
    /// it, u_i >= 0, v <= 0), the contact j that lands next satisfies p in C_{ij}. Every sampled
    /// state is drawn without the kernel's rest points or cones.
    #[test]
    fn the_contact_that_lands_next_lies_in_its_cone(b in bodies(), seed in any::<u64>()) {
        let mut rng = Rng::new(seed);
        let mut checked = 0;
        for i in 0..b.n() {
            for _ in 0..40 {
                let Some(q) = configuration_on(&b, i, &mut rng) else { continue };
                let p: Vec3<Q> = [rng.ratio(-20, 20, 5), rng.ratio(-20, 20, 5), rng.ratio(-20, 0, 5)];
                if height(&b.contacts()[i], &p) < zero() {
                    continue; // contact i must move up (or stay) after its impact
                }
                let Some((t, js)) = first_landing(&b, i, &q, &p) else { continue };
                if t == zero() {
                    continue; // a contact already on the floor moving down: a simultaneous impact
                }
                for j in js {
                    let cone = b.next_contact_cone(i as i64, j as i64).unwrap();
                    prop_assert!(inside(&cone, &p), "i={} j={} p={:?} q={:?}", i, j, p, q);
                    checked += 1;
                }
            }
        }
        prop_assert!(checked > 0, "no state was sampled");
    }

    /// The Lemma, backwards: every p = a g1 + b g2 + c g3 + d g4 (a, b, c, d >= 0) is realised:
    /// from q0 = (a + b) m_{i-1,i} + (c + d) m_{i,i+1} (contact i on the floor, the others at or
    /// above) the body reaches q0 + p with contact j on the floor and no contact below it.
    #[test]
    fn every_point_of_c_ij_is_reached(b in bodies(), seed in any::<u64>()) {
        let mut rng = Rng::new(seed);
        let n = b.n() as i64;
        for i in 0..n {
            for j in (0..n).filter(|&j| j != i) {
                let g = b.next_contact_generators(i, j).unwrap();
                let w: Vec<Q> = (0..4).map(|_| rng.ratio(0, 9, 4)).collect();
                let p = (0..4).fold([zero(), zero(), zero()], |acc, s| {
                    [&acc[0] + &w[s] * &g[s][0], &acc[1] + &w[s] * &g[s][1], &acc[2] + &w[s] * &g[s][2]]
                });
                let (am, ap) = (b.edge_rest_point(i - 1), b.edge_rest_point(i));
                let (x, y) = (&w[0] + &w[1], &w[2] + &w[3]);
                let q0: Vec3<Q> = [&x * &am[0] + &y * &ap[0], &x * &am[1] + &y * &ap[1], &x * &am[2] + &y * &ap[2]];
                let q1: Vec3<Q> = [&q0[0] + &p[0], &q0[1] + &p[1], &q0[2] + &p[2]];
                let (h0, h1) = (heights(&b, &q0), heights(&b, &q1));
                prop_assert_eq!(&h0[i as usize], &zero());
                prop_assert_eq!(&h1[j as usize], &zero());
                prop_assert!(h0.iter().chain(&h1).all(|h| *h >= zero()), "i={} j={}", i, j);
                prop_assert!(p[2] <= zero());
                prop_assert!(inside(&b.next_contact_cone(i, j).unwrap(), &p));
            }
        }
    }

    /// The covectors describe exactly the cone of the four generators: p satisfies the four
    /// inequalities iff it is a non-negative combination of three independent generators
    /// (Caratheodory), decided by Cramer's rule.
    #[test]
    fn covectors_and_generators_describe_the_same_cone(b in bodies(), seed in any::<u64>()) {
        let mut rng = Rng::new(seed);
        let n = b.n() as i64;
        for i in 0..n {
            for j in (0..n).filter(|&j| j != i) {
                let g = b.next_contact_generators(i, j).unwrap();
                let cov = b.next_contact_cone(i, j).unwrap();
                for (s, gs) in g.iter().enumerate() {
                    prop_assert!(inside(&cov, gs), "generator {} of C_({},{})", s, i, j);
                }
                for _ in 0..25 {
                    let p: Vec3<Q> = [Q::from(rng.int(-4, 4)), Q::from(rng.int(-4, 4)), Q::from(rng.int(-4, 1))];
                    prop_assert_eq!(inside(&cov, &p), in_cone(&g, &p), "i={} j={} p={:?}", i, j, p);
                }
            }
        }
    }
}

/// Whether p is a non-negative combination of some three linearly independent generators.
fn in_cone(g: &[Vec3<Q>; 4], p: &Vec3<Q>) -> bool {
    let triples = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]];
    triples.iter().any(|t| {
        let (a, b, c) = (&g[t[0]], &g[t[1]], &g[t[2]]);
        let d = det3(a, b, c);
        if d == zero() {
            return false;
        }
        let coef = [det3(p, b, c) / &d, det3(a, p, c) / &d, det3(a, b, p) / &d];
        coef.iter().all(|x| *x >= zero())
    })
}

#[test]
fn rest_points_put_two_contacts_on_the_floor() {
    for b in fixed_bodies() {
        let n = b.n() as i64;
        for k in 0..n {
            let m = b.edge_rest_point(k);
            assert_eq!(b.rest_point(k, k + 1).as_ref(), Some(m));
            assert_eq!(m[2], Q::from(1));
            for (l, h) in heights(&b, m).iter().enumerate() {
                let on = l as i64 == k || l as i64 == (k + 1) % n;
                assert_eq!(*h == zero(), on, "m_({k},{}) height of contact {l}", k + 1);
                assert!(*h >= zero());
            }
            // Consecutive rest points turn counter-clockwise (docs/model.md §11.3).
            let (a, c) = (b.edge_rest_point(k - 1), b.edge_rest_point(k + 1));
            assert!(det3(a, m, c) > zero());
        }
    }
    // Opposite corners of a centred rectangle are collinear with the origin: no rest point.
    let sq: Vec<[Q; 2]> =
        [(1, 1), (-1, 1), (-1, -1), (1, -1)].iter().map(|&(x, y)| [Q::from(x), Q::from(y)]).collect();
    let iso = [[Q::from_signeds(1, 3), zero()], [zero(), Q::from_signeds(1, 3)]];
    let b = ConvexBody::new(sq, iso, Q::from_signeds(1, 2)).unwrap();
    assert!(b.rest_point(0, 2).is_none());
    assert!(b.next_contact_cone(1, 1).is_none() && b.next_contact_generators(2, 6).is_none());
}

#[test]
fn neighbouring_cones_are_half_space_triples() {
    // C_{i,i+1} = {u_i >= 0, u_{i+1} <= 0, v <= 0}; C_{i,i-1} = {u_i >= 0, u_{i-1} <= 0, v <= 0}.
    let mut rng = Rng::new(7);
    for b in fixed_bodies() {
        for i in 0..b.n() as i64 {
            for (j, _) in [(i + 1, 0), (i - 1, 0)] {
                let cone = b.next_contact_cone(i, j).unwrap();
                for _ in 0..200 {
                    let p: Vec3<Q> =
                        [Q::from(rng.int(-3, 3)), Q::from(rng.int(-3, 3)), Q::from(rng.int(-3, 3))];
                    let (ui, uj) = (dot(b.covector(i), &p), dot(b.covector(j), &p));
                    let want = ui >= zero() && uj <= zero() && p[2] <= zero();
                    assert_eq!(inside(&cone, &p), want, "i={i} j={j} p={p:?}");
                }
            }
        }
    }
}

#[test]
fn all_down_generators_span_d() {
    let mut rng = Rng::new(11);
    for b in fixed_bodies() {
        let gens = b.all_down_generators();
        assert_eq!(gens.len(), b.n());
        for (m, g) in gens.iter().enumerate() {
            let speeds = heights(&b, g);
            assert!(speeds.iter().all(|u| *u <= zero()));
            assert_eq!(
                speeds.iter().filter(|u| **u == zero()).count(),
                2,
                "-m_({m},{}) rests two contacts",
                m + 1
            );
        }
        // D = cone of the generators: its section v = -1 is a convex polygon around the section
        // of (0, 0, -1) (every contact moving down at unit speed), so p is in D iff it lies in the
        // cone over one triangle ((0, 0, -1), -m_{k,k+1}, -m_{k+1,k+2}) of the fan.
        for _ in 0..300 {
            let p: Vec3<Q> = [Q::from(rng.int(-5, 5)), Q::from(rng.int(-5, 5)), Q::from(rng.int(-5, 5))];
            let down = heights(&b, &p).iter().all(|u| *u <= zero());
            let n = gens.len();
            let spanned = (0..n).any(|k| {
                let (a, c) = (&gens[k], &gens[(k + 1) % n]);
                let (z, e3) = (zero(), [zero(), zero(), Q::from(-1)]);
                let d = det3(&e3, a, c);
                d != z
                    && [det3(&p, a, c), det3(&e3, &p, c), det3(&e3, a, &p)]
                        .iter()
                        .all(|x| (x.clone() / &d) >= zero())
            });
            assert_eq!(down, spanned, "p = {p:?}");
        }
    }
}
