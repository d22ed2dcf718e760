//! Tests of `bodies::convex`: uniform plates, rectangles, boxes and regular polygons as exact
//! general convex bodies (docs/model.md §11), and the affine images the paper's theorem predicts.

use chatter::bodies::convex::{
    flat_inertia, plate_moments, polygon_plate, rectangle_contacts, rectangle_plate, regular_polygon,
    regular_polygon_exact, uniform_box,
};
use chatter::exact::{Algebraic, OrderedField, Q, Ring};
use chatter_kernel::exact::OrderedField as _;
use chatter_kernel::model::{ConvexBody, ConvexBodyError, Mat2, Vec2};
use proptest::prelude::*;

fn pts(raw: &[(i64, i64)]) -> Vec<Vec2<Q>> {
    raw.iter().map(|&(x, y)| [Q::int(x), Q::int(y)]).collect()
}

fn q(a: i64, b: i64) -> Q {
    Q::new(a, b)
}

fn diag(a: Q, b: Q) -> Mat2<Q> {
    [[a, Q::int(0)], [Q::int(0), b]]
}

/// The same body: contacts, inertia and gamma.
fn same<F: OrderedField>(a: &ConvexBody<F>, b: &ConvexBody<F>) -> bool {
    a.contacts() == b.contacts() && a.inertia() == b.inertia() && a.gamma() == b.gamma()
}

/// Second moments about the centroid by a fan of triangles, each with the triangle formula
/// int (r - g)(r - g)^T dA / A = (1/12) sum over its vertices of (v - g)(v - g)^T, and the
/// parallel-axis theorem: independent of the polygon formulas in `bodies::convex`.
fn fan_moments(p: &[Vec2<Q>]) -> (Vec2<Q>, Mat2<Q>) {
    let mut tris = Vec::new();
    for k in 1..p.len() - 1 {
        let (a, b, c) = (&p[0], &p[k], &p[k + 1]);
        let area = ((&b[0] - &a[0]) * (&c[1] - &a[1]) - (&b[1] - &a[1]) * (&c[0] - &a[0])) / Q::int(2);
        let g = [(&a[0] + &b[0] + &c[0]) / Q::int(3), (&a[1] + &b[1] + &c[1]) / Q::int(3)];
        let mut s = diag(Q::int(0), Q::int(0));
        for v in [a, b, c] {
            let d = [&v[0] - &g[0], &v[1] - &g[1]];
            for (r, row) in s.iter_mut().enumerate() {
                for (col, e) in row.iter_mut().enumerate() {
                    *e = &*e + &d[r] * &d[col] / Q::int(12);
                }
            }
        }
        tris.push((area, g, s));
    }
    let total = tris.iter().fold(Q::int(0), |acc, t| acc + &t.0);
    let cx = tris.iter().fold(Q::int(0), |acc, t| acc + &t.0 * &t.1[0]) / &total;
    let cy = tris.iter().fold(Q::int(0), |acc, t| acc + &t.0 * &t.1[1]) / &total;
    let c = [cx, cy];
    let mut s = diag(Q::int(0), Q::int(0));
    for (area, g, st) in &tris {
        let d = [&g[0] - &c[0], &g[1] - &c[1]];
        for r in 0..2 {
            for col in 0..2 {
                s[r][col] = &s[r][col] + area * (&st[r][col] + &d[r] * &d[col]) / &total;
            }
        }
    }
    (c, s)
}

#[test]
fn rectangles_and_boxes_have_the_textbook_inertia() {
    let (a, b, c) = (q(15, 1), q(15, 2), q(4, 5));
    let plate = rectangle_plate(&a, &b, q(1, 2)).unwrap();
    assert_eq!(plate.inertia(), &diag(&b * &b / Q::int(12), &a * &a / Q::int(12)));
    assert_eq!(plate.contacts(), rectangle_contacts(&a, &b).as_slice());
    assert_eq!(plate.contact_point(0), &[q(15, 2), q(-15, 4)], "contact 0 at (a/2, -b/2)");
    let brick = uniform_box(&a, &b, &c, q(1, 2)).unwrap();
    let c2 = &c * &c;
    assert_eq!(brick.inertia(), &diag((&b * &b + &c2) / Q::int(12), (&a * &a + &c2) / Q::int(12)));
    // The same rectangle given in another frame, as a polygon plate.
    let moved: Vec<Vec2<Q>> =
        rectangle_contacts(&a, &b).iter().map(|p| [&p[0] + q(7, 3), &p[1] - q(5, 1)]).collect();
    assert!(same(&polygon_plate(&moved, q(1, 2)).unwrap(), &plate));
    // Degenerate sizes are rejected, not panicking.
    assert_eq!(
        rectangle_plate(&Q::int(0), &b, q(1, 2)).unwrap_err(),
        ConvexBodyError::RepeatedContact { contact: 1 }
    );
}

#[test]
fn plates_of_triangles_match_the_triangle_formula() {
    // (0, 0), (a, 0), (0, b): centroid (a/3, b/3), S = [[a^2/18, -a b/36], [-a b/36, b^2/18]].
    let (a, b) = (6, 9);
    let (c, s) = plate_moments(&pts(&[(0, 0), (a, 0), (0, b)])).unwrap();
    assert_eq!(c, [q(a, 3), q(b, 3)]);
    assert_eq!(s, [[q(a * a, 18), q(-a * b, 36)], [q(-a * b, 36), q(b * b, 18)]]);
    let plate = polygon_plate(&pts(&[(0, 0), (a, 0), (0, b)]), q(1, 5)).unwrap();
    assert_eq!(plate.inertia(), &flat_inertia(&s));
    assert_eq!(plate.inertia()[0][1], q(a * b, 36), "J_xy = -S_xy");
}

#[test]
fn bad_polygons_are_reported() {
    assert_eq!(
        polygon_plate(&pts(&[(0, 0), (0, 3), (4, 0)]), q(1, 2)).unwrap_err(),
        ConvexBodyError::Clockwise
    );
    let collinear = pts(&[(0, 0), (2, 0), (4, 0), (4, 4)]);
    assert_eq!(
        polygon_plate(&collinear, q(1, 2)).unwrap_err(),
        ConvexBodyError::CollinearContacts { contact: 1 }
    );
    assert_eq!(
        polygon_plate(&pts(&[(0, 0), (1, 0)]), q(1, 2)).unwrap_err(),
        ConvexBodyError::TooFewContacts(2)
    );
    assert_eq!(
        polygon_plate(&pts(&[(0, 0), (4, 0), (0, 4)]), q(3, 2)).unwrap_err(),
        ConvexBodyError::GammaOutOfRange
    );
}

/// Strictly convex polygons: the strict hull of random points.
fn polygons() -> impl Strategy<Value = Vec<Vec2<Q>>> {
    prop::collection::vec((-15i64..=15, -15i64..=15), 3..10).prop_filter_map("a proper polygon", |raw| {
        let h = crate::kernel::convex::hull(pts(&raw));
        (h.len() >= 3).then_some(h)
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(120))]

    /// The polygon formulas agree with a fan of triangles, for any convex polygon in any frame.
    #[test]
    fn plate_moments_agree_with_a_fan_of_triangles(p in polygons()) {
        prop_assert_eq!(plate_moments(&p).unwrap(), fan_moments(&p));
    }

    /// The plate of L P is the affine image (docs/model.md §11.7) of the plate of P: contacts
    /// L r_k about the new centroid, inertia B J B^T.
    #[test]
    fn plates_of_affine_images_are_affine_images(
        p in polygons(),
        l in (-5i64..=5, -5i64..=5, -5i64..=5, -5i64..=5),
    ) {
        prop_assume!(l.0 * l.3 - l.1 * l.2 > 0);
        let lm = [[Q::int(l.0), Q::int(l.1)], [Q::int(l.2), Q::int(l.3)]];
        let image_pts: Vec<Vec2<Q>> = p
            .iter()
            .map(|r| [&lm[0][0] * &r[0] + &lm[0][1] * &r[1], &lm[1][0] * &r[0] + &lm[1][1] * &r[1]])
            .collect();
        let body = polygon_plate(&p, q(1, 3)).unwrap();
        let transported = chatter::model::affine::affine_image(&body, &lm).unwrap().body;
        prop_assert!(same(&polygon_plate(&image_pts, q(1, 3)).unwrap(), &transported));
    }
}

#[test]
fn rectangle_plates_are_images_of_the_square_plate() {
    // The uniform square plate of circumradius 1 (kappa = 1/6) under L = [[a/2, a/2], [-b/2, b/2]]
    // is the uniform a x b plate, labels included (docs/model.md §11.7).
    let square = regular_polygon_exact(4, &q(1, 6), &q(1, 4)).unwrap();
    let square_q = ConvexBody::new(
        square.contacts().iter().map(|r| r.clone().map(|x| x.as_rational().unwrap())).collect(),
        diag(q(1, 6), q(1, 6)),
        q(1, 4),
    )
    .unwrap();
    for (a, b) in [(1, 1), (2, 1), (4, 1), (150, 75), (3, 7)] {
        let (a, b) = (Q::int(a), Q::int(b));
        let l = [[&a / Q::int(2), &a / Q::int(2)], [-&b / Q::int(2), &b / Q::int(2)]];
        let image = chatter::model::affine::affine_image(&square_q, &l).unwrap().body;
        assert!(same(&image, &rectangle_plate(&a, &b, q(1, 4)).unwrap()), "a={a} b={b}");
    }
    // A box on a square face is the square body with kappa = (a^2 + c^2) / (6 a^2), transported.
    let (a, c) = (Q::int(3), Q::int(2));
    let kappa = (&a * &a + &c * &c) / (Q::int(6) * &a * &a);
    let sq = ConvexBody::new(square_q.contacts().to_vec(), diag(kappa.clone(), kappa), q(1, 4)).unwrap();
    let l = [[&a / Q::int(2), &a / Q::int(2)], [-&a / Q::int(2), &a / Q::int(2)]];
    assert!(same(
        &chatter::model::affine::affine_image(&sq, &l).unwrap().body,
        &uniform_box(&a, &a, &c, q(1, 4)).unwrap()
    ));
}

#[test]
fn regular_polygon_plates_have_the_kappas_of_section_9() {
    // (2 + cos(2 pi/n)) / 12: triangle 1/8, square 1/6, hexagon 5/24.
    for (n, kappa) in [(3, q(1, 8)), (4, q(1, 6)), (6, q(5, 24))] {
        let body = regular_polygon_exact(n, &kappa, &q(1, 10)).unwrap();
        let plate = polygon_plate(body.contacts(), Algebraic::rational(q(1, 10))).unwrap();
        assert!(same(&plate, &body), "n={n}");
        for r in body.contacts() {
            assert_eq!(
                r[0].times(&r[0]).plus(&r[1].times(&r[1])),
                Algebraic::rational(Q::int(1)),
                "unit circumradius"
            );
        }
    }
}

#[test]
fn every_triangle_plate_is_an_image_of_the_equilateral_plate() {
    // In Q(sqrt 3): L maps the equilateral contacts e_0, e_1 (circumradius 1) onto the centred
    // corners w_0, w_1 of a triangle plate; the transported body is that plate (kappa = 1/8).
    type A = Algebraic<Q>;
    let eq = regular_polygon_exact(3, &q(1, 8), &q(1, 10)).unwrap();
    for raw in [[(0, 0), (7, 1), (2, 5)], [(-3, -1), (4, -2), (1, 6)], [(0, 0), (1, 0), (0, 1)]] {
        let tri: Vec<Vec2<A>> = raw.iter().map(|&(x, y)| [A::from_i64(x), A::from_i64(y)]).collect();
        let plate = polygon_plate(&tri, Algebraic::rational(q(1, 10))).unwrap();
        let (w, e) = (plate.contacts(), eq.contacts());
        // L = [w0 w1] [e0 e1]^{-1} (columns).
        let det = e[0][0].times(&e[1][1]).minus(&e[1][0].times(&e[0][1]));
        let inv = [
            [e[1][1].over(&det).unwrap(), e[1][0].negated().over(&det).unwrap()],
            [e[0][1].negated().over(&det).unwrap(), e[0][0].over(&det).unwrap()],
        ];
        let l: Mat2<A> = std::array::from_fn(|r| {
            std::array::from_fn(|c| w[0][r].times(&inv[0][c]).plus(&w[1][r].times(&inv[1][c])))
        });
        let image = chatter::model::affine::affine_image(&eq, &l).unwrap().body;
        assert!(same(&image, &plate), "{raw:?}");
    }
}

#[test]
fn regular_polygons_need_the_true_cosine_and_sine() {
    let half = q(1, 2);
    assert!(regular_polygon_exact(5, &q(1, 6), &half).is_err());
    assert!(regular_polygon(4, &Q::int(0), &Q::int(-1), q(1, 6), q(1, 2)).is_err(), "sin < 0");
    assert!(regular_polygon(4, &Q::int(0), &Q::int(2), q(1, 6), q(1, 2)).is_err(), "not on the circle");
    // cos(2 pi/3) given as if it were cos(2 pi/6): T_3 = 1 before n = 6.
    let (c, s) = (Algebraic::from_ratio(-1, 2), chatter::exact::CosField::<Q>::new(12).unwrap().generator());
    assert!(
        regular_polygon(6, &c, &s, Algebraic::rational(q(1, 6)), Algebraic::rational(half.clone())).is_err()
    );
    assert!(regular_polygon(3, &c, &s, Algebraic::rational(q(1, 6)), Algebraic::rational(half)).is_ok());
    assert!(regular_polygon(4, &Q::int(0), &Q::int(1), q(-1, 6), q(1, 2)).is_err(), "kappa <= 0");
    assert!(regular_polygon(usize::MAX, &Q::int(0), &Q::int(1), q(1, 6), q(1, 2)).is_err(), "n too large");
}
