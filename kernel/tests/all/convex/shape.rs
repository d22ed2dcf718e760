//! Tests of `kernel/src/model/convex/shape.rs`: the constructor's typed errors (docs/model.md §11.1).

use super::{bodies, hull};
use chatter_kernel::model::{ConvexBody, ConvexBodyError as E, MAX_CONTACTS, Mat2, Vec2};
use malachite::rational::Rational as Q;
use proptest::prelude::*;

fn pts(raw: &[(i64, i64)]) -> Vec<Vec2<Q>> {
    raw.iter().map(|&(x, y)| [Q::from(x), Q::from(y)]).collect()
}

fn iso(k: i64, d: i64) -> Mat2<Q> {
    [[Q::from_signeds(k, d), Q::from(0)], [Q::from(0), Q::from_signeds(k, d)]]
}

fn make(raw: &[(i64, i64)]) -> Result<ConvexBody<Q>, E> {
    ConvexBody::new(pts(raw), iso(1, 6), Q::from_signeds(1, 2))
}

const SQUARE: [(i64, i64); 4] = [(1, 0), (0, 1), (-1, 0), (0, -1)];

#[test]
fn a_valid_body_is_accepted() {
    let b = make(&SQUARE).unwrap();
    assert_eq!(b.n(), 4);
    assert_eq!(b.contact_point(5), &[Q::from(0), Q::from(1)], "indices are cyclic");
    // Triangles, and the largest allowed number of contacts (a 64-gon on a parabola-like curve).
    assert!(make(&[(3, -1), (0, 2), (-2, -1)]).is_ok());
    let many: Vec<(i64, i64)> =
        (0..MAX_CONTACTS as i64).map(|k| (k - 32, (k - 32) * (k - 32) - 500)).collect();
    // Points on an upward parabola listed by increasing x turn counter-clockwise; the closing
    // edge is the top one. The origin is inside (y from -500 to 524).
    assert!(make(&many).is_ok(), "{:?}", make(&many).err());
}

#[test]
fn contact_counts_outside_3_to_64_are_rejected() {
    assert_eq!(make(&[(1, 0), (-1, 1)]).unwrap_err(), E::TooFewContacts(2));
    assert_eq!(make(&[]).unwrap_err(), E::TooFewContacts(0));
    let many: Vec<(i64, i64)> = (0..65).map(|k| (k - 32, (k - 32) * (k - 32) - 500)).collect();
    assert_eq!(make(&many).unwrap_err(), E::TooManyContacts(65));
}

#[test]
fn bad_polygons_are_rejected_with_their_reason() {
    // Clockwise.
    assert_eq!(make(&[(0, -1), (-1, 0), (0, 1), (1, 0)]).unwrap_err(), E::Clockwise);
    // A repeated contact.
    assert_eq!(make(&[(1, 0), (0, 1), (0, 1), (-1, 0)]).unwrap_err(), E::RepeatedContact { contact: 1 });
    // A contact on the segment between its neighbours (not strictly convex).
    assert_eq!(
        make(&[(1, 0), (1, 1), (0, 1), (-1, 0), (0, -1), (1, -1)]).unwrap_err(),
        E::CollinearContacts { contact: 0 }
    );
    // A reflex corner.
    assert_eq!(make(&[(2, 0), (0, 2), (0, 1), (-2, 0), (0, -2)]).unwrap_err(), E::NotConvex { contact: 2 });
    // A pentagram: every turn counter-clockwise, winding twice.
    let star = [(10, 0), (-8, 6), (3, -10), (3, 10), (-8, -6)];
    assert_eq!(make(&star).unwrap_err(), E::NotSimple { turns: 2 });
}

#[test]
fn the_origin_must_be_strictly_inside() {
    // Outside: the square shifted right.
    assert_eq!(make(&[(3, 0), (2, 1), (1, 0), (2, -1)]).unwrap_err(), E::OriginOutside { edge: 1 });
    // On an edge (x = 0 between (0, -1) and (0, 1)).
    assert_eq!(make(&[(0, -1), (2, -1), (2, 1), (0, 1)]).unwrap_err(), E::OriginOnEdge { edge: 3 });
    // At a contact.
    assert_eq!(make(&[(0, 0), (2, 0), (0, 2)]).unwrap_err(), E::OriginOnEdge { edge: 0 });
    // On the line of an edge but beyond its end: outside.
    assert_eq!(make(&[(1, 0), (2, 0), (2, 1)]).unwrap_err(), E::OriginOutside { edge: 0 });
}

#[test]
fn inertia_and_gamma_are_checked() {
    let q = |a, b| Q::from_signeds(a, b);
    let sq = pts(&SQUARE);
    let asym = [[q(1, 6), q(1, 10)], [q(-1, 10), q(1, 6)]];
    assert_eq!(ConvexBody::new(sq.clone(), asym, q(1, 2)).unwrap_err(), E::InertiaNotSymmetric);
    for bad in [
        [[q(1, 6), q(1, 6)], [q(1, 6), q(1, 6)]],   // singular
        [[q(-1, 6), q(0, 1)], [q(0, 1), q(-1, 6)]], // negative definite
        [[q(1, 6), q(1, 2)], [q(1, 2), q(1, 6)]],   // indefinite
        [[q(0, 1), q(0, 1)], [q(0, 1), q(1, 6)]],   // semidefinite
    ] {
        assert_eq!(ConvexBody::new(sq.clone(), bad, q(1, 2)).unwrap_err(), E::InertiaNotPositiveDefinite);
    }
    for g in [q(-1, 100), q(101, 100), q(2, 1)] {
        assert_eq!(ConvexBody::new(sq.clone(), iso(1, 6), g).unwrap_err(), E::GammaOutOfRange);
    }
    for g in [q(0, 1), q(1, 1)] {
        assert!(ConvexBody::new(sq.clone(), iso(1, 6), g).is_ok());
    }
}

#[test]
fn errors_print_a_reason() {
    let e = make(&[(3, 0), (2, 1), (1, 0), (2, -1)]).unwrap_err();
    assert!(e.to_string().contains("outside"), "{e}");
    assert!(E::Clockwise.to_string().contains("counter-clockwise"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Never a panic on arbitrary data, and acceptance means exactly: the points are their own
    /// strict counter-clockwise hull (up to rotation of the labels), the origin is strictly left
    /// of every edge, J is symmetric positive definite and gamma in [0, 1].
    #[test]
    fn acceptance_is_exactly_the_documented_conditions(
        raw in prop::collection::vec((-6i64..=6, -6i64..=6), 0..9),
        j in (-3i64..=3, -3i64..=3, -3i64..=3, -3i64..=3),
        g in -2i64..=12,
    ) {
        let p = pts(&raw);
        let inertia = [[Q::from(j.0), Q::from(j.1)], [Q::from(j.2), Q::from(j.3)]];
        let gamma = Q::from_signeds(g, 10);
        let got = ConvexBody::new(p.clone(), inertia.clone(), gamma.clone());
        let n = p.len();
        let h = hull(p.clone());
        let is_hull = n >= 3 && h.len() == n && (0..n).any(|s| (0..n).all(|k| p[(k + s) % n] == h[k]));
        let left = |a: &Vec2<Q>, b: &Vec2<Q>| &a[0] * &b[1] - &a[1] * &b[0] > 0;
        let origin_in = (0..n).all(|k| left(&p[k], &p[(k + 1) % n]));
        let pd = j.1 == j.2 && j.0 > 0 && j.0 * j.3 - j.1 * j.2 > 0;
        let g_ok = (0..=10).contains(&g);
        prop_assert_eq!(got.is_ok(), is_hull && origin_in && pd && g_ok, "{:?}", got.err());
    }

    /// Reversing a valid body's contacts is reported as clockwise.
    #[test]
    fn reversed_bodies_are_clockwise(b in bodies()) {
        let mut rev = b.contacts().to_vec();
        rev.reverse();
        prop_assert_eq!(ConvexBody::new(rev, b.inertia().clone(), b.gamma().clone()).unwrap_err(), E::Clockwise);
    }
}
