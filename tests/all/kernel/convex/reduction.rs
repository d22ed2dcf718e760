//! The general model reduces to today's regular-polygon model (docs/model.md §11.4, §11.6): for
//! n = 3, 4, 6 with contacts on the unit circle and J = kappa I, the maps, rest points, cones,
//! all-down generators and PCC quadratics of `ConvexBody` in the paper's coordinates equal those of
//! `Polygon` in contact coordinates after the change of coordinates W of docs/model.md §2
//! (rows f_0, f_1, (0, 0, 1)), exactly, in Q(sqrt 3) = Q(cos 2 pi/12).

use chatter::bodies::convex::regular_polygon_exact;
use chatter::exact::{Algebraic, Q, Ring};
use chatter_kernel::model::linalg::{Mat3, Vec3, cross, dot, is_zero, mat_mul, mat_vec};
use chatter_kernel::model::{ConvexBody, Polygon, pcc_quadratic};

type A = Algebraic<Q>;

fn bodies(n: u64, kappa: (i64, i64), gamma: (i64, i64)) -> (ConvexBody<A>, Polygon<A>, Mat3<A>) {
    let (k, g) = (Q::new(kappa.0, kappa.1), Q::new(gamma.0, gamma.1));
    let general = regular_polygon_exact(n as usize, &k, &g).unwrap();
    let poly = Polygon::new(n, A::rational(k), A::rational(g)).unwrap();
    let (z, o) = (A::zero(), A::one());
    let w = [general.covector(0).clone(), general.covector(1).clone(), [z.clone(), z, o]];
    (general, poly, w)
}

fn transpose(m: &Mat3<A>) -> Mat3<A> {
    std::array::from_fn(|i| std::array::from_fn(|j| m[j][i].clone()))
}

fn inside(cov: &[Vec3<A>], p: &Vec3<A>) -> bool {
    cov.iter().all(|l| !dot(l, p).is_negative())
}

/// l and m are positive multiples of each other.
fn same_ray(l: &Vec3<A>, m: &Vec3<A>) -> bool {
    is_zero(&cross(l, m)) && dot(l, m).is_positive()
}

const NS: [u64; 3] = [3, 4, 6];
const PARAMS: [((i64, i64), (i64, i64)); 4] =
    [((1, 6), (1, 100)), ((1, 8), (3, 10)), ((5, 24), (9, 10)), ((2, 1), (0, 1))];

#[test]
fn covectors_and_impact_maps_agree_after_w() {
    for n in NS {
        for (k, g) in PARAMS {
            let (b, poly, w) = bodies(n, k, g);
            let wt = transpose(&w);
            for c in 0..n as i64 {
                // u_c = poly.contact(c) . (W p) = f_c . p.
                assert_eq!(&mat_vec(&wt, poly.contact(c)), b.covector(c), "n={n} contact {c}");
                // Polygon's I_c W = W (ConvexBody's I_c).
                assert_eq!(mat_mul(&poly.impact(c), &w), mat_mul(&w, &b.impact(c)), "n={n} I_{c}");
                assert_eq!(
                    poly.rest_point(c, c + 1).unwrap(),
                    mat_vec(&w, b.edge_rest_point(c)),
                    "n={n} m_{c}"
                );
            }
        }
    }
}

#[test]
fn cones_c_0j_agree_after_w_as_covectors_and_as_sets() {
    let grid: Vec<Vec3<A>> = (-2..=2)
        .flat_map(|a| (-2..=2).flat_map(move |b| (-2..=1).map(move |c| [a, b, c].map(A::from_i64))))
        .collect();
    for n in NS {
        let (b, poly, w) = bodies(n, (1, 6), (1, 10));
        let wt = transpose(&w);
        for j in 1..n as i64 {
            let (mine, theirs) = (b.next_contact_cone(0, j).unwrap(), poly.next_contact_cone(j));
            for (s, (l, m)) in mine.iter().zip(&theirs).enumerate() {
                assert!(same_ray(l, &mat_vec(&wt, m)), "n={n} C_{j} covector {s}");
            }
            for p in &grid {
                assert_eq!(inside(&mine, p), inside(&theirs, &mat_vec(&w, p)), "n={n} j={j} p={p:?}");
            }
        }
        // C_{ij} is C_{j-i} after relabelling contact i as 0: R_i W p in C_{j-i}.
        for i in 1..n as i64 {
            for j in (0..n as i64).filter(|&j| j != i) {
                let mine = b.next_contact_cone(i, j).unwrap();
                let theirs = poly.next_contact_cone((j - i).rem_euclid(n as i64));
                for p in &grid {
                    let moved = mat_vec(&poly.relabel(i), &mat_vec(&w, p));
                    assert_eq!(inside(&mine, p), inside(&theirs, &moved), "n={n} i={i} j={j}");
                }
            }
        }
    }
}

#[test]
fn all_down_generators_and_pcc_quadratics_agree() {
    for n in NS {
        for (k, g) in PARAMS {
            let (b, poly, w) = bodies(n, k, g);
            let mine: Vec<Vec3<A>> = b.all_down_generators().iter().map(|x| mat_vec(&w, x)).collect();
            assert_eq!(mine, poly.all_down_generators(), "n={n}");
            let theirs = pcc_quadratic(&poly).unwrap();
            for c in 0..n as i64 {
                assert_eq!(
                    b.pair_pcc_quadratic(c).unwrap(),
                    theirs,
                    "n={n} kappa={k:?} gamma={g:?} pair {c}"
                );
            }
            // S_{n-1} S_1 = I_0 I_1 in contact coordinates (docs/model.md §11.6).
            let s = mat_mul(&poly.step(n as i64 - 1), &poly.step(1));
            assert_eq!(mat_mul(&s, &w), mat_mul(&w, &b.pair_map(0)));
        }
    }
}
