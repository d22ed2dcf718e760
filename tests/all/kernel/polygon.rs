//! Tests of `chatter_kernel::geometry`: exact homogeneous geometry against brute force on projected
//! rational points (the 2-D helpers of `kernel::brute`, which share nothing with the kernel).

use super::brute::{HalfPlane, Pt, ccw_hull, extreme_points, full_dimensional, in_hull, orient2, twice_area};
use crate::common::q;
use chatter::exact::{Q, Ring};
use chatter_kernel::geometry::{ConvexPolygon, clip, hull, orient};
use chatter_kernel::model::linalg::{Vec3, dot};
use malachite::Integer;
use num_bigint::BigInt;
use proptest::prelude::*;
use proptest::sample::Index;
use std::cmp::Ordering;

// ---------------------------------------------------------------------------------------------
// Helpers.

fn zq() -> Q {
    Q::int(0)
}

/// An integer of any backend as a rational (both print plain decimal integers).
fn to_q<R: Ring>(x: &R) -> Q {
    q(&x.to_string())
}

/// The projected point (u0, u1) / (-v) of a homogeneous vector with v < 0.
fn proj<R: Ring>(g: &Vec3<R>) -> Pt {
    let w = -to_q(&g[2]);
    assert!(w > zq(), "projected points need v < 0: {g:?}");
    (to_q(&g[0]) / &w, to_q(&g[1]) / &w)
}

/// A homogeneous integer vector (a k, b k, -w k) for the point (a / w, b / w).
fn hom<R: Ring>(a: i64, b: i64, w: i64, k: i64) -> Vec3<R> {
    assert!(w > 0 && k > 0);
    [R::from_i64(a * k), R::from_i64(b * k), R::from_i64(-w * k)]
}

/// A positive integer multiple of (x, y, -1) for a rational point.
fn hom_q<R: Ring>(p: &Pt, k: i64) -> Vec3<R> {
    let d = lcm(den(&p.0), den(&p.1)) * k;
    let x = &p.0 * &Q::int(d);
    let y = &p.1 * &Q::int(d);
    [R::from_i64(int_of(&x)), R::from_i64(int_of(&y)), R::from_i64(-d)]
}

fn den(x: &Q) -> i64 {
    let s = x.to_string();
    s.split_once('/').map_or(1, |(_, d)| d.parse().expect("small denominator"))
}

fn int_of(x: &Q) -> i64 {
    x.to_string().parse().expect("an integer")
}

fn lcm(a: i64, b: i64) -> i64 {
    fn gcd(a: i64, b: i64) -> i64 {
        if b == 0 { a.abs() } else { gcd(b, a % b) }
    }
    a / gcd(a, b) * b
}

fn sorted(mut v: Vec<Pt>) -> Vec<Pt> {
    v.sort();
    v
}

/// The projected points of `pts[i]` for the listed indices.
fn proj_all<R: Ring>(pts: &[Vec3<R>], idx: &[usize]) -> Vec<Pt> {
    idx.iter().map(|&i| proj(&pts[i])).collect()
}

/// Checks `hull` against the brute-force extreme points, and its order.
fn check_hull<R: Ring>(pts: &[Vec3<R>]) -> Vec<usize> {
    let h = hull(pts);
    let projected: Vec<Pt> = pts.iter().map(proj).collect();
    let got = proj_all(pts, &h);
    // Indices are valid and distinct, points distinct.
    assert!(h.iter().all(|&i| i < pts.len()));
    let mut sorted_idx = h.clone();
    sorted_idx.sort();
    sorted_idx.dedup();
    assert_eq!(sorted_idx.len(), h.len(), "repeated index in {h:?}");
    assert_eq!(sorted(got.clone()), sorted(extreme_points(&projected)), "hull of {pts:?}: {h:?}");
    // Of repeated points, the first occurrence is the one reported.
    for &i in &h {
        assert!(!projected[..i].contains(&projected[i]), "index {i} repeats an earlier point in {h:?}");
    }
    if full_dimensional(&projected) {
        assert!(h.len() >= 3);
        // Counter-clockwise, strictly convex, from the lexicographically smallest point.
        assert_eq!(got, ccw_hull(&projected));
        let m = h.len();
        for i in 0..m {
            let (a, b, c) = (&pts[h[i]], &pts[h[(i + 1) % m]], &pts[h[(i + 2) % m]]);
            assert_eq!(orient(a, b, c), Ordering::Greater, "triple {i} of {h:?}");
        }
        // The brute-force evaluator's K (supporting half-planes) has the same vertices.
        let k = super::brute::supporting_half_planes(&projected);
        assert_eq!(sorted(super::brute::polygon_vertices(&k)), sorted(got.clone()));
        assert_eq!(k.len(), h.len(), "one supporting line per edge");
        // Every input point is in the hull.
        for p in &projected {
            assert!(in_hull(p, &got));
        }
    } else {
        assert!(h.len() < 3, "a degenerate set gave {h:?}");
    }
    h
}

// ---------------------------------------------------------------------------------------------
// orient.

#[test]
fn orient_matches_rational_orientation_and_ignores_scaling() {
    let pts: Vec<Vec3<Integer>> = vec![
        hom(0, 0, 1, 1),
        hom(1, 0, 1, 3),
        hom(0, 1, 1, 2),
        hom(1, 1, 2, 5),
        hom(2, 2, 4, 1),
        hom(-3, 5, 3, 7),
    ];
    for a in &pts {
        for b in &pts {
            for c in &pts {
                let want = orient2(&proj(a), &proj(b), &proj(c)).cmp(&zq());
                assert_eq!(orient(a, b, c), want);
                assert_eq!(orient(b, a, c), want.reverse());
                assert_eq!(orient(b, c, a), want);
            }
        }
    }
    let (a, b, c) = (hom::<Integer>(0, 0, 1, 1), hom(1, 0, 1, 1), hom(0, 1, 1, 1));
    assert_eq!(orient(&a, &b, &c), Ordering::Greater);
    assert_eq!(orient(&a, &c, &b), Ordering::Less);
    // (1/2, 1/2) written as (1, 1, -2) and (2, 2, -4) lies on the segment (1,0)-(0,1).
    assert_eq!(orient(&b, &c, &hom(1, 1, 2, 2)), Ordering::Equal);
}

// ---------------------------------------------------------------------------------------------
// hull.

#[test]
fn hull_of_scaled_copies_and_duplicates() {
    // (1,2,-1) and (2,4,-2) are the same projected point.
    let pts: Vec<Vec3<Integer>> = vec![
        [1, 2, -1].map(Integer::from),
        [2, 4, -2].map(Integer::from),
        [0, 0, -1].map(Integer::from),
        [3, 0, -3].map(Integer::from),
        [0, 0, -5].map(Integer::from),
    ];
    let h = check_hull(&pts);
    assert_eq!(h, vec![2, 3, 0]);
    // Only one distinct point, or two.
    let one: Vec<Vec3<Integer>> = vec![[1, 2, -1].map(Integer::from), [3, 6, -3].map(Integer::from)];
    assert_eq!(check_hull(&one), vec![0]);
    let two: Vec<Vec3<Integer>> =
        vec![[1, 2, -1].map(Integer::from), [0, 0, -1].map(Integer::from), [2, 4, -2].map(Integer::from)];
    assert_eq!(check_hull(&two).len(), 2);
    assert!(check_hull::<Integer>(&[]).is_empty());
}

#[test]
fn hull_of_collinear_points_has_fewer_than_three() {
    // (k, 2k + 1) for several k, with scalings and repeats: only the two ends are extreme.
    let pts: Vec<Vec3<Integer>> =
        vec![hom(3, 7, 1, 2), hom(0, 1, 1, 1), hom(-2, -3, 1, 3), hom(1, 3, 1, 5), hom(3, 7, 1, 1)];
    let h = check_hull(&pts);
    assert_eq!(sorted(proj_all(&pts, &h)), vec![(q("-2"), q("-3")), (q("3"), q("7"))]);
    // Vertical line, rational points.
    let v: Vec<Vec3<Integer>> = vec![hom(1, 1, 2, 1), hom(1, -5, 2, 1), hom(2, 7, 4, 3)];
    assert_eq!(check_hull(&v).len(), 2);
}

#[test]
fn hull_drops_points_on_edges_and_inside() {
    // Square 0..2 with edge midpoints, the centre, and a scaled corner.
    let pts: Vec<Vec3<Integer>> = vec![
        hom(1, 0, 1, 1),
        hom(0, 0, 1, 1),
        hom(2, 0, 1, 1),
        hom(1, 1, 1, 4),
        hom(2, 2, 1, 1),
        hom(0, 2, 1, 1),
        hom(2, 1, 1, 1),
        hom(4, 4, 2, 3),
    ];
    assert_eq!(check_hull(&pts), vec![1, 2, 4, 5]);
}

#[test]
fn hull_agrees_between_backends_on_a_fixed_set() {
    let raw = [(3, -1, 2, 1), (-4, 2, 3, 2), (0, 5, 1, 1), (6, 6, 4, 3), (-1, -6, 1, 2), (2, 2, 3, 1)];
    let a: Vec<Vec3<Integer>> = raw.iter().map(|&(x, y, w, k)| hom(x, y, w, k)).collect();
    let b: Vec<Vec3<BigInt>> = raw.iter().map(|&(x, y, w, k)| hom(x, y, w, k)).collect();
    assert_eq!(check_hull(&a), check_hull(&b));
}

/// Small random homogeneous points with v < 0, plus scaled repeats of some of them.
fn point_set() -> impl Strategy<Value = Vec<(i64, i64, i64, i64)>> {
    (
        prop::collection::vec((-6i64..=6, -6i64..=6, 1i64..=4, 1i64..=3), 0..11),
        prop::collection::vec((any::<Index>(), 1i64..=4), 0..4),
    )
        .prop_map(|(mut pts, reps)| {
            if !pts.is_empty() {
                for (i, k) in reps {
                    let (a, b, w, _) = pts[i.index(pts.len())];
                    pts.push((a, b, w, k));
                }
            }
            pts
        })
}

/// Points on one random line a x + b y = c (with a lattice of rational parameters).
fn collinear_set() -> impl Strategy<Value = Vec<(i64, i64, i64, i64)>> {
    ((-3i64..=3, -3i64..=3), (-2i64..=2, -2i64..=2), prop::collection::vec((-4i64..=4, 1i64..=3), 1..7))
        .prop_map(|((px, py), (dx, dy), ts)| {
            ts.into_iter().map(|(t, k)| (px * 2 + t * dx, py * 2 + t * dy, 2, k)).collect()
        })
}

fn to_hom<R: Ring>(raw: &[(i64, i64, i64, i64)]) -> Vec<Vec3<R>> {
    raw.iter().map(|&(a, b, w, k)| hom(a, b, w, k)).collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn hull_matches_brute_force(raw in point_set()) {
        let a = check_hull::<Integer>(&to_hom(&raw));
        let b = check_hull::<BigInt>(&to_hom(&raw));
        prop_assert_eq!(a, b);
    }

    #[test]
    fn hull_of_collinear_sets_is_degenerate(raw in collinear_set()) {
        let pts = to_hom::<Integer>(&raw);
        let h = check_hull(&pts);
        prop_assert!(h.len() < 3);
        let d = super::brute::distinct(&pts.iter().map(proj).collect::<Vec<_>>()).len();
        prop_assert_eq!(h.len(), d.min(2));
    }
}

// ---------------------------------------------------------------------------------------------
// ConvexPolygon: contains and first_violated.

/// A polygon from the hull of `raw` (at least 3 extreme points), and its projected vertices.
fn polygon<R: Ring>(raw: &[(i64, i64, i64, i64)]) -> Option<(ConvexPolygon<R>, Vec<Pt>)> {
    let pts = to_hom::<R>(raw);
    let h = hull(&pts);
    if h.len() < 3 {
        return None;
    }
    let verts: Vec<Vec3<R>> = h.iter().map(|&i| pts[i].clone()).collect();
    let projected = verts.iter().map(proj).collect();
    Some((ConvexPolygon::new(verts), projected))
}

/// Checks `contains` and `first_violated` for one query point against every edge in rationals.
fn check_query<R: Ring>(poly: &ConvexPolygon<R>, verts: &[Pt], g: &Vec3<R>) -> bool {
    let p = proj(g);
    let m = verts.len();
    assert_eq!(poly.facets.len(), m);
    let side: Vec<Q> = (0..m).map(|i| orient2(&verts[i], &verts[(i + 1) % m], &p)).collect();
    let inside = side.iter().all(|s| *s >= zq());
    assert_eq!(poly.contains(g), inside, "contains({p:?}) in {verts:?}");
    assert_eq!(in_hull(&p, verts), inside);
    // Each facet value is orient2d of the projected points times w_A w_B w_p (all w > 0).
    let w = |v: &Vec3<R>| -to_q(&v[2]);
    for (i, s) in side.iter().enumerate() {
        let (a, b) = (&poly.vertices[i], &poly.vertices[(i + 1) % m]);
        assert_eq!(to_q(&dot(&poly.facets[i], g)), s * &(w(a) * w(b) * w(g)));
    }
    let want = side.iter().position(|s| *s < zq());
    match poly.first_violated(g) {
        None => assert_eq!(want, None),
        Some((e, d)) => {
            assert_eq!(Some(e), want);
            assert!(d.is_negative());
            assert_eq!(d, dot(&poly.facets[e], g));
        }
    }
    inside
}

/// Query points for a polygon with projected vertices `verts`: vertices, points on edges and
/// on their extensions, interior combinations, and the given random points.
fn queries(verts: &[Pt], random: &[(i64, i64, i64, i64)]) -> Vec<(Pt, Option<bool>)> {
    let m = verts.len();
    let mut out = vec![];
    let third = q("1/3");
    for i in 0..m {
        let (a, b) = (&verts[i], &verts[(i + 1) % m]);
        out.push((a.clone(), Some(true)));
        for (t, on) in [("1/2", true), ("1/3", true), ("7/5", false), ("-1/4", false)] {
            let t = q(t);
            let p = (a.0.clone() + &t * &(&b.0 - &a.0), a.1.clone() + &t * &(&b.1 - &a.1));
            out.push((p, Some(on)));
        }
        // Strictly inside: the centroid of three vertices; and just outside beyond a vertex.
        let c = &verts[(i + 2) % m];
        out.push((((&a.0 + &b.0 + &c.0) * &third, (&a.1 + &b.1 + &c.1) * &third), Some(true)));
    }
    out.extend(random.iter().map(|&(a, b, w, _)| ((Q::new(a, w), Q::new(b, w)), None)));
    out
}

fn check_polygon_queries<R: Ring>(
    raw: &[(i64, i64, i64, i64)],
    random: &[(i64, i64, i64, i64)],
) -> (usize, usize) {
    let Some((poly, verts)) = polygon::<R>(raw) else { return (0, 0) };
    let (mut ins, mut outs) = (0, 0);
    for (k, (p, expect)) in queries(&verts, random).into_iter().enumerate() {
        let g = hom_q::<R>(&p, 1 + (k as i64 % 3));
        let inside = check_query(&poly, &verts, &g);
        if let Some(e) = expect {
            assert_eq!(inside, e, "{p:?} in {verts:?}");
        }
        if inside { ins += 1 } else { outs += 1 }
    }
    (ins, outs)
}

#[test]
fn contains_on_a_fixed_hexagon_with_boundary_points() {
    let raw = [(2, 0, 1, 1), (1, 2, 1, 2), (-1, 2, 1, 1), (-2, 0, 1, 3), (-1, -2, 1, 1), (1, -2, 1, 1)];
    let (ins, outs) = check_polygon_queries::<Integer>(&raw, &[(0, 0, 1, 1), (3, 3, 1, 1), (1, 1, 1, 1)]);
    assert!(ins > 0 && outs > 0);
    let (poly, _) = polygon::<Integer>(&raw).expect("a hexagon");
    // The hull starts at (-2, 0): edges (-2,0)->(-1,-2)->(1,-2)->(2,0)->(1,2)->(-1,2)->(-2,0).
    // (2, 1) is inside edges 0..2 and first outside edge 3, (2,0)->(1,2).
    let g = hom::<Integer>(2, 1, 1, 1);
    assert!(!poly.contains(&g));
    let (e, d) = poly.first_violated(&g).expect("outside");
    assert_eq!(e, 3);
    // orient2d((2,0), (1,2), (2,1)) = cross((-1,2), (0,1)) = -1, times w = 1 * 2 * 1
    // ((1,2) is stored as (2,4,-2)).
    assert_eq!(d, Integer::from(-2));
    check_polygon_queries::<BigInt>(&raw, &[(0, 0, 1, 1), (3, 3, 1, 1)]);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn contains_matches_every_facet(raw in point_set(),
                                    random in prop::collection::vec((-7i64..=7, -7i64..=7, 1i64..=3, 1i64..=1), 0..12)) {
        check_polygon_queries::<Integer>(&raw, &random);
    }

    #[test]
    fn contains_matches_every_facet_bigint(raw in point_set(),
                                           random in prop::collection::vec((-7i64..=7, -7i64..=7, 1i64..=3, 1i64..=1), 0..6)) {
        check_polygon_queries::<BigInt>(&raw, &random);
    }
}

// ---------------------------------------------------------------------------------------------
// clip.

/// The projected half-plane of the covector l: l . (x, y, -1) >= 0.
fn half_plane<R: Ring>(l: &Vec3<R>) -> HalfPlane {
    HalfPlane::from_covector(&[to_q(&l[0]), to_q(&l[1]), to_q(&l[2])])
}

/// Brute-force clip of a convex polygon (projected vertices in order) by a half-plane: the
/// vertices inside, and the crossings of edges whose ends are strictly on opposite sides.
fn brute_clip(verts: &[Pt], h: &HalfPlane) -> Vec<Pt> {
    let m = verts.len();
    let mut cand = vec![];
    for i in 0..m {
        let (a, b) = (&verts[i], &verts[(i + 1) % m]);
        let (da, db) = (h.eval(a), h.eval(b));
        if da >= zq() {
            cand.push(a.clone());
        }
        if (da > zq() && db < zq()) || (da < zq() && db > zq()) {
            let t = &da / &(&da - &db);
            cand.push((a.0.clone() + &t * &(&b.0 - &a.0), a.1.clone() + &t * &(&b.1 - &a.1)));
        }
    }
    cand
}

/// Clips and checks the result against brute force; returns the clipped polygon.
fn check_clip<R: Ring>(poly: &[Vec3<R>], l: &Vec3<R>) -> Vec<Vec3<R>> {
    let h = half_plane(l);
    let verts: Vec<Pt> = poly.iter().map(proj).collect();
    let out = clip(poly, l);
    let got: Vec<Pt> = out.iter().map(proj).collect();
    // Every output point satisfies the half-plane (exactly, homogeneously) and is in the polygon.
    for (g, p) in out.iter().zip(&got) {
        assert!(!dot(l, g).is_negative(), "{p:?} violates {h:?}");
        assert!(h.contains(p));
        assert!(in_hull(p, &verts), "{p:?} is not in {verts:?}");
    }
    let want = brute_clip(&verts, &h);
    assert_eq!(sorted(extreme_points(&got)), sorted(extreme_points(&want)), "clip {verts:?} by {h:?}");
    // Area: shoelace of the output in its own order equals the area of the brute-force hull.
    assert_eq!(twice_area(&got), twice_area(&ccw_hull(&want)), "clip {verts:?} by {h:?}: {got:?}");
    // A polygon that was strictly convex stays strictly convex, counter-clockwise, no repeats.
    if poly.len() >= 3 && full_dimensional(&verts) {
        assert_eq!(super::brute::distinct(&got).len(), got.len(), "repeated points: {got:?}");
        if got.len() >= 3 {
            let m = out.len();
            for i in 0..m {
                assert_eq!(orient(&out[i], &out[(i + 1) % m], &out[(i + 2) % m]), Ordering::Greater);
            }
        }
    }
    // Everything inside means unchanged; nothing inside means empty.
    if verts.iter().all(|p| h.contains(p)) {
        assert_eq!(got, verts);
    }
    if verts.iter().all(|p| h.eval(p) < zq()) {
        assert!(out.is_empty());
    }
    out
}

/// Kinds of clipping lines.
#[derive(Clone, Debug)]
enum Line {
    /// l = (a, b, c): a x + b y >= c.
    Random(i64, i64, i64),
    /// Through two vertices (indices taken modulo the polygon size), either side.
    ThroughVertices(Index, Index, bool),
    /// Through one vertex and a random point, either side.
    ThroughVertex(Index, (i64, i64), bool),
    /// Far away: everything or nothing survives.
    Missing(bool),
}

fn line() -> impl Strategy<Value = Line> {
    prop_oneof![
        3 => (-5i64..=5, -5i64..=5, -8i64..=8).prop_map(|(a, b, c)| Line::Random(a, b, c)),
        2 => (any::<Index>(), any::<Index>(), any::<bool>()).prop_map(|(a, b, s)| Line::ThroughVertices(a, b, s)),
        2 => (any::<Index>(), (-6i64..=6, -6i64..=6), any::<bool>()).prop_map(|(a, p, s)| Line::ThroughVertex(a, p, s)),
        1 => any::<bool>().prop_map(Line::Missing),
    ]
}

fn covector<R: Ring>(poly: &[Vec3<R>], l: &Line) -> Vec3<R> {
    let i = |x: i64| R::from_i64(x);
    let cross = chatter_kernel::model::linalg::cross::<R>;
    let flip = |v: Vec3<R>, s: bool| if s { v } else { v.map(|c| c.negated()) };
    match l {
        Line::Random(a, b, c) => [i(*a), i(*b), i(*c)],
        Line::ThroughVertices(a, b, s) => {
            flip(cross(&poly[a.index(poly.len())], &poly[b.index(poly.len())]), *s)
        }
        Line::ThroughVertex(a, (x, y), s) => flip(cross(&poly[a.index(poly.len())], &hom(*x, *y, 1, 1)), *s),
        // x >= 1000 or x >= -1000 (the polygons live in a small box).
        Line::Missing(s) => [i(1), i(0), i(if *s { 1000 } else { -1000 })],
    }
}

fn clip_case<R: Ring>(raw: &[(i64, i64, i64, i64)], lines: &[Line]) {
    let pts = to_hom::<R>(raw);
    let h = hull(&pts);
    if h.len() < 3 {
        return;
    }
    let mut poly: Vec<Vec3<R>> = h.iter().map(|&i| pts[i].clone()).collect();
    let original: Vec<Pt> = poly.iter().map(proj).collect();
    let mut constraints: Vec<HalfPlane> = vec![];
    for l in lines {
        // Lines through vertices of the current polygon (of the original one once it is empty).
        let base = if poly.is_empty() { h.iter().map(|&i| pts[i].clone()).collect() } else { poly.clone() };
        let cov = covector(&base, l);
        constraints.push(half_plane(&cov));
        poly = check_clip(&poly, &cov);
    }
    // After several clips: compare with the intersection computed from scratch.
    let mut all = super::brute::supporting_half_planes(&original);
    all.extend(constraints);
    let want = super::brute::polygon_vertices(&all);
    let got: Vec<Pt> = poly.iter().map(proj).collect();
    assert_eq!(
        sorted(extreme_points(&got)),
        sorted(extreme_points(&want)),
        "{original:?} clipped by {lines:?}"
    );
    assert_eq!(twice_area(&ccw_hull(&got)), twice_area(&ccw_hull(&want)));
}

#[test]
fn clip_fixed_cases() {
    // The square 0..2 (counter-clockwise from (0,0)).
    let sq: Vec<Vec3<Integer>> = vec![hom(0, 0, 1, 1), hom(2, 0, 1, 2), hom(2, 2, 1, 1), hom(0, 2, 1, 3)];
    // x + y <= 2 (through two opposite vertices): the lower-left triangle.
    let tri = check_clip(&sq, &[-1, -1, -2].map(Integer::from));
    assert_eq!(
        sorted(tri.iter().map(proj).collect()),
        sorted(vec![(q("0"), q("0")), (q("2"), q("0")), (q("0"), q("2"))])
    );
    // x <= 1: a rectangle of area 2 with two new vertices.
    let rect = check_clip(&sq, &[-1, 0, -1].map(Integer::from));
    assert_eq!(twice_area(&rect.iter().map(proj).collect::<Vec<_>>()), q("4"));
    // x + y >= 4 touches the corner (2, 2) only; x + y >= 5 misses; x >= -1 keeps everything.
    let corner = check_clip(&sq, &[1, 1, 4].map(Integer::from));
    assert_eq!(corner.iter().map(proj).collect::<Vec<_>>(), vec![(q("2"), q("2"))]);
    assert!(check_clip(&sq, &[1, 1, 5].map(Integer::from)).is_empty());
    assert_eq!(check_clip(&sq, &[1, 0, -1].map(Integer::from)), sq);
    // x >= 2: the right edge only.
    let edge = check_clip(&sq, &[1, 0, 2].map(Integer::from));
    assert_eq!(sorted(edge.iter().map(proj).collect()), vec![(q("2"), q("0")), (q("2"), q("2"))]);
    // Clipping the segment further, across its middle: the upper half, a degenerate polygon.
    let half = check_clip(&edge, &[0, 1, 1].map(Integer::from));
    assert_eq!(
        sorted(super::brute::distinct(&half.iter().map(proj).collect::<Vec<_>>())),
        vec![(q("2"), q("1")), (q("2"), q("2"))]
    );
    // The same on num-bigint.
    let sq_b: Vec<Vec3<BigInt>> = vec![hom(0, 0, 1, 1), hom(2, 0, 1, 2), hom(2, 2, 1, 1), hom(0, 2, 1, 3)];
    assert_eq!(check_clip(&sq_b, &[-1, -1, -2].map(BigInt::from)).len(), 3);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn clip_matches_brute_force(raw in point_set(), lines in prop::collection::vec(line(), 1..5)) {
        clip_case::<Integer>(&raw, &lines);
    }

    #[test]
    fn clip_matches_brute_force_bigint(raw in point_set(), lines in prop::collection::vec(line(), 1..3)) {
        clip_case::<BigInt>(&raw, &lines);
    }
}
