//! Tests of the cones of `chatter_kernel::model`: the points m_{k,l}, the cones C_j and the all-down cone D.

use crate::common::{NS, body, q};
use chatter::exact::Q;
use chatter::model::square_paper_to_contact;
use chatter_kernel::model::linalg::{Vec3, dot, mat_vec};
use proptest::prelude::*;

#[test]
fn rest_points_put_two_contacts_on_the_floor_at_unit_height() {
    for n in NS {
        let b = body(n, "1/6", "1/100");
        for k in 0..n as i64 {
            let m = b.rest_point(k, k + 1).expect("adjacent");
            assert_eq!(m[2], Q::int(1), "h_c = 1");
            assert_eq!(dot(b.contact(k), &m), Q::int(0));
            assert_eq!(dot(b.contact(k + 1), &m), Q::int(0));
            for l in 0..n as i64 {
                if l.rem_euclid(n as i64) != k && l.rem_euclid(n as i64) != (k + 1) % n as i64 {
                    assert!(dot(b.contact(l), &m) > Q::int(0), "the other contacts are above the floor");
                }
            }
        }
    }
    // Opposite contacts of even polygons cannot both touch with the centre at height 1.
    assert!(body(4, "1/6", "1/100").rest_point(0, 2).is_none());
    assert!(body(6, "1/6", "1/100").rest_point(1, 4).is_none());
}

#[test]
fn square_rest_points_are_the_papers() {
    // Paper, equations (squarefelt1-4), in (phi_x, phi_y, h).
    let m = square_paper_to_contact::<Q>();
    let paper = [((0, 1), [-1, 1, 1]), ((1, 2), [-1, -1, 1]), ((2, 3), [1, -1, 1]), ((3, 0), [1, 1, 1])];
    let b = body(4, "1/6", "1/100");
    for ((k, l), p) in paper {
        let p = p.map(Q::int);
        assert_eq!(b.rest_point(k, l).unwrap(), mat_vec(&m, &p), "m_({k},{l})");
    }
}

#[test]
fn the_four_generators_of_every_cj_satisfy_its_inequalities() {
    for n in NS {
        for (k, g) in [("1/6", "1/100"), ("2", "9/10")] {
            let b = body(n, k, g);
            for j in 1..n as i64 {
                let cov = b.next_contact_cone(j);
                for (gi, gener) in chatter::model::next_contact_generators(&b, j).iter().enumerate() {
                    let mut zeros = 0;
                    for (li, l) in cov.iter().enumerate() {
                        let d = dot(l, gener);
                        assert!(d >= Q::int(0), "n={n} j={j} generator {gi} violates inequality {li}");
                        zeros += usize::from(d == Q::int(0));
                    }
                    assert!(zeros >= 2, "n={n} j={j}: generator {gi} is an extreme ray (on two facets)");
                }
            }
        }
    }
}

#[test]
fn square_c1_is_contact_one_moving_down() {
    let b = body(4, "1/6", "1/100");
    let cov = b.next_contact_cone(1);
    for a in -3..=3 {
        for c in -3..=3 {
            for v in -3..=3 {
                let p = [Q::int(a), Q::int(c), Q::int(v)];
                let inside = cov.iter().all(|l| dot(l, &p) >= Q::int(0));
                assert_eq!(inside, a >= 0 && c <= 0 && v <= 0, "p = {p:?}");
            }
        }
    }
}

/// Which contact reaches the floor first from heights h (contact 0 at 0) moving with velocity p.
fn first_hit(b: &chatter_kernel::model::Polygon<Q>, h: &Vec3<Q>, p: &Vec3<Q>) -> Option<(i64, bool)> {
    let mut best: Option<(Q, i64)> = None;
    let mut tie = false;
    for k in 1..b.n() as i64 {
        let (hk, uk) = (dot(b.contact(k), h), dot(b.contact(k), p));
        if uk < Q::int(0) {
            let t = -hk / uk;
            match &best {
                Some((bt, _)) if t > *bt => {}
                Some((bt, _)) if t == *bt => tie = true,
                _ => {
                    tie = false;
                    best = Some((t, k));
                }
            }
        }
    }
    best.map(|(_, k)| (k, tie))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// The paper's Lemma on C_j, checked kinematically: from a configuration with contact 0 on
    /// the floor and the others above it, moving with a velocity that takes contact 0 up and
    /// the centre down, the contact that hits first is some j with p in C_j.
    #[test]
    fn the_contact_that_hits_next_lies_in_its_cone(
        n in prop::sample::select(vec![3u64, 4, 6]),
        h1 in 0i64..40, hc in 1i64..40, u0 in 0i64..30, u1 in -30i64..30, v in -30i64..0,
    ) {
        let b = body(n, "1/6", "1/100");
        let h = [Q::int(0), Q::new(h1, 10), Q::new(hc, 10)];
        // Contact 0 on the floor, every other contact at or above it.
        prop_assume!((1..n as i64).all(|k| dot(b.contact(k), &h) >= Q::int(0)));
        let p = [Q::new(u0, 7), Q::new(u1, 7), Q::new(v, 7)];
        if let Some((j, tie)) = first_hit(&b, &h, &p) {
            prop_assume!(!tie);
            let inside = b.next_contact_cone(j).iter().all(|l| dot(l, &p) >= Q::int(0));
            prop_assert!(inside, "n={} contact {} hits first but p = {:?} is not in C_{}", n, j, p, j);
        }
    }
}

#[test]
fn all_down_generators_span_d() {
    for n in NS {
        let b = body(n, "3/20", "1/20");
        let gens = b.all_down_generators();
        assert_eq!(gens.len(), n as usize);
        for (m, g) in gens.iter().enumerate() {
            assert_eq!(g[2], Q::int(-1));
            for k in 0..n as i64 {
                let u = dot(b.contact(k), g);
                let on = k == m as i64 || k == (m as i64 + 1) % n as i64;
                assert_eq!(u == Q::int(0), on, "n={n}: -m_({m},{}) has u_{k} = {u}", m + 1);
                assert!(u <= Q::int(0));
            }
        }
        // D is invariant under relabelling: R_j permutes its generators.
        for j in 1..n as i64 {
            for g in &gens {
                let r = mat_vec(&b.relabel(j), g);
                assert!(gens.contains(&r), "R_{j} maps a generator of D onto a generator");
            }
        }
    }
    let _ = q("1");
}
