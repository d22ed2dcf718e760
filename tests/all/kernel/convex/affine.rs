//! Tests of `kernel/src/model/convex/affine.rs`: the affine transport of a body and of its maps
//! and cones (docs/model.md §11.7, the paper's Theorem on affine images).

use super::{Rng, bodies, height, inside};
use chatter::exact::Q;
use chatter_kernel::model::linalg::{Mat3, Vec3, cross, dot, identity, is_zero, mat_mul};
use chatter_kernel::model::{ConvexBody, Mat2};
use proptest::prelude::*;

fn linear_maps() -> impl Strategy<Value = Mat2<Q>> {
    ((-6i64..=6, -6i64..=6, -6i64..=6, -6i64..=6), 1i64..=3)
        .prop_map(|((a, b, c, d), den)| [[Q::new(a, den), Q::new(b, den)], [Q::new(c, den), Q::new(d, den)]])
        .prop_filter("orientation preserving", |l| &l[0][0] * &l[1][1] - &l[0][1] * &l[1][0] > Q::int(0))
}

fn same_ray(l: &Vec3<Q>, m: &Vec3<Q>) -> bool {
    is_zero(&cross(l, m)) && dot(l, m) > Q::int(0)
}

fn mat_eq_conj(t: &Mat3<Q>, a: &Mat3<Q>, image: &Mat3<Q>) -> bool {
    // image = T a T^{-1}  <=>  image T = T a.
    mat_mul(image, t) == mat_mul(t, a)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(120))]

    /// Contacts L r_k, contact speeds unchanged (f'_k . T p = f_k . p), I'_k = T I_k T^{-1},
    /// m'_{k,l} = T m_{k,l}, C'_{ij} = T C_{ij} (covectors T^{-T} l up to a positive factor, and
    /// as sets), D' = T D, the same pair quadratics.
    #[test]
    fn images_carry_maps_cones_and_quadratics(b in bodies(), l in linear_maps(), seed in any::<u64>()) {
        let mut rng = Rng::new(seed);
        let img = chatter::model::affine::affine_image(&b, &l).expect("det L > 0");
        let (c, t) = (&img.body, &img.velocity_map);
        let n = b.n() as i64;
        prop_assert_eq!(c.n(), b.n());
        for k in 0..n {
            let r = b.contact_point(k);
            let lr = [&l[0][0] * &r[0] + &l[0][1] * &r[1], &l[1][0] * &r[0] + &l[1][1] * &r[1]];
            prop_assert_eq!(c.contact_point(k), &lr);
            prop_assert_eq!(&img.covector(b.covector(k)), c.covector(k));
            prop_assert!(mat_eq_conj(t, &b.impact(k), &c.impact(k)), "I_{}", k);
            prop_assert_eq!(&img.velocity(b.edge_rest_point(k)), c.edge_rest_point(k));
            prop_assert_eq!(b.pair_pcc_quadratic(k).unwrap(), c.pair_pcc_quadratic(k).unwrap());
            prop_assert_eq!(&img.velocity(&b.all_down_generators()[k as usize]), &c.all_down_generators()[k as usize]);
        }
        for i in 0..n {
            for j in (0..n).filter(|&j| j != i) {
                let (old, new) = (b.next_contact_cone(i, j).unwrap(), c.next_contact_cone(i, j).unwrap());
                for (s, (lo, ln)) in old.iter().zip(&new).enumerate() {
                    prop_assert!(same_ray(&img.covector(lo), ln), "C_({},{}) covector {}", i, j, s);
                }
                for _ in 0..5 {
                    let p: Vec3<Q> = [Q::int(rng.int(-4, 4)), Q::int(rng.int(-4, 4)), Q::int(rng.int(-4, 1))];
                    prop_assert_eq!(inside(&old, &p), inside(&new, &img.velocity(&p)));
                }
            }
        }
        // Heights and speeds are the same numbers on both bodies.
        let p: Vec3<Q> = [rng.ratio(-9, 9, 4), rng.ratio(-9, 9, 4), rng.ratio(-9, 9, 4)];
        for k in 0..n {
            prop_assert_eq!(height(b.contact_point(k), &p), height(c.contact_point(k), &img.velocity(&p)));
        }
    }
}

#[test]
fn reflections_and_singular_maps_have_no_image() {
    let pts = [(2, 0), (0, 1), (-1, 0), (0, -3)].map(|(x, y)| [Q::int(x), Q::int(y)]).to_vec();
    let b = ConvexBody::new(pts, [[Q::int(1), Q::int(0)], [Q::int(0), Q::int(2)]], Q::new(1, 3)).unwrap();
    let reflect = [[Q::int(1), Q::int(0)], [Q::int(0), Q::int(-1)]];
    let singular = [[Q::int(1), Q::int(2)], [Q::int(2), Q::int(4)]];
    assert!(chatter::model::affine::affine_image(&b, &reflect).is_none());
    assert!(chatter::model::affine::affine_image(&b, &singular).is_none());
}

#[test]
fn the_inertia_transforms_by_the_cofactor_matrix() {
    // J' = B J B^T with B = P L P^T = det(L) L^{-T}; T = diag(L / det L, 1).
    let pts = [(2, 0), (0, 1), (-1, 0), (0, -3)].map(|(x, y)| [Q::int(x), Q::int(y)]).to_vec();
    let j = [[Q::new(1, 2), Q::new(1, 5)], [Q::new(1, 5), Q::new(1, 3)]];
    let b = ConvexBody::new(pts, j, Q::new(1, 3)).unwrap();
    let l = [[Q::int(2), Q::int(1)], [Q::int(0), Q::int(3)]]; // det 6
    let img = chatter::model::affine::affine_image(&b, &l).unwrap();
    // B = [[3, 0], [-1, 2]]; B J B^T computed by hand.
    let bj = [[Q::new(3, 2), Q::new(3, 5)], [Q::new(-1, 2) + Q::new(2, 5), Q::new(-1, 5) + Q::new(2, 3)]];
    let want = [
        [&bj[0][0] * Q::int(3), &bj[0][0] * Q::int(-1) + &bj[0][1] * Q::int(2)],
        [&bj[1][0] * Q::int(3), &bj[1][0] * Q::int(-1) + &bj[1][1] * Q::int(2)],
    ];
    assert_eq!(img.body.inertia(), &want);
    let s = Q::new(1, 6);
    let t = [
        [Q::int(2) * &s, s.clone(), Q::int(0)],
        [Q::int(0), Q::int(3) * &s, Q::int(0)],
        [Q::int(0), Q::int(0), Q::int(1)],
    ];
    assert_eq!(img.velocity_map, t);
    // T^{-T} = diag(B, 1).
    let tinv_t = [
        [Q::int(3), Q::int(0), Q::int(0)],
        [Q::int(-1), Q::int(2), Q::int(0)],
        [Q::int(0), Q::int(0), Q::int(1)],
    ];
    assert_eq!(img.covector_map, tinv_t);
    assert_eq!(
        mat_mul(&{ std::array::from_fn(|r| std::array::from_fn(|c| tinv_t[c][r].clone())) }, &t),
        identity()
    );
}
