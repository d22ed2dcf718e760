//! Geometry on the plane v = -1 (docs/model.md §5, "Geometry"): a velocity with v < 0 is the
//! point (u0, u1)/(-v), a cone below the floor a convex polygon. Everything here is brute force
//! on points with exact coordinates: gift wrapping for hulls, and the vertices of an intersection
//! of half-planes as the pairwise intersections of their lines that satisfy every constraint.

use crate::arith::Num;
use std::cmp::Ordering;

/// A point of the plane v = -1.
pub type Pt = (Num, Num);

/// orient(a, b, c) = (b - a) × (c - a): > 0 when a, b, c turn counter-clockwise.
pub fn orient(a: &Pt, b: &Pt, c: &Pt) -> Num {
    let (ux, uy) = (&b.0 - &a.0, &b.1 - &a.1);
    let (wx, wy) = (&c.0 - &a.0, &c.1 - &a.1);
    &(&ux * &wy) - &(&uy * &wx)
}

/// The point of a vector (x, y, v) with v < 0, `None` otherwise.
pub fn project(g: &[Num; 3]) -> Option<Pt> {
    if !g[2].is_negative() {
        return None;
    }
    let w = g[2].neg();
    Some((&g[0] / &w, &g[1] / &w))
}

/// The vector (x, y, -1) of a point.
pub fn lift(p: &Pt) -> [Num; 3] {
    [p.0.clone(), p.1.clone(), Num::int(&p.0.field, -1)]
}

/// Lexicographic order of points (x, then y).
fn lex(a: &Pt, b: &Pt) -> Ordering {
    a.0.cmp(&b.0).then_with(|| a.1.cmp(&b.1))
}

/// Squared distance.
fn dist2(a: &Pt, b: &Pt) -> Num {
    let (x, y) = (&b.0 - &a.0, &b.1 - &a.1);
    &(&x * &x) + &(&y * &y)
}

/// Whether some three of the points are not on one line.
pub fn spans_plane(pts: &[Pt]) -> bool {
    let Some(a) = pts.first() else { return false };
    let Some(b) = pts.iter().find(|p| *p != a) else { return false };
    pts.iter().any(|c| !orient(a, b, c).is_zero())
}

/// The hull's vertices by gift wrapping, counter-clockwise from the lexicographically smallest
/// point, as indices of first occurrences. Needs a set that spans the plane. The result is then
/// verified (strict left turns, every point left of or on every edge); a wrong hull panics.
pub fn hull(pts: &[Pt]) -> Vec<usize> {
    assert!(spans_plane(pts), "the hull of a flat set");
    let first = |p: &Pt| pts.iter().position(|q| q == p).expect("present");
    let start = (0..pts.len()).min_by(|&i, &j| lex(&pts[i], &pts[j]).then(i.cmp(&j))).expect("non-empty");
    let mut out = vec![start];
    loop {
        let cur = &pts[*out.last().expect("non-empty")];
        let mut best: Option<usize> = None;
        for (i, p) in pts.iter().enumerate().filter(|(_, p)| *p != cur) {
            best = Some(match best {
                None => i,
                Some(b) => {
                    let o = orient(cur, &pts[b], p);
                    if o.is_negative() || (o.is_zero() && dist2(cur, p) > dist2(cur, &pts[b])) {
                        i
                    } else {
                        b
                    }
                }
            });
        }
        let next = first(&pts[best.expect("another point")]);
        if next == start {
            break;
        }
        out.push(next);
        assert!(out.len() <= pts.len(), "gift wrapping does not close");
    }
    verify_hull(pts, &out);
    out
}

/// Panics unless `h` is a strictly convex counter-clockwise polygon containing every point.
fn verify_hull(pts: &[Pt], h: &[usize]) {
    let m = h.len();
    assert!(m >= 3, "a hull spanning the plane has three vertices");
    for i in 0..m {
        let (a, b, c) = (&pts[h[i]], &pts[h[(i + 1) % m]], &pts[h[(i + 2) % m]]);
        assert!(orient(a, b, c).is_positive(), "not a strict left turn");
        assert!(pts.iter().all(|p| !orient(a, b, p).is_negative()), "a point right of a hull edge");
    }
}

/// The half-plane a x + b y + c ≥ 0.
#[derive(Clone, Debug)]
pub struct HalfPlane {
    /// Coefficient of x.
    pub a: Num,
    /// Coefficient of y.
    pub b: Num,
    /// Constant.
    pub c: Num,
}

impl HalfPlane {
    /// The left of the directed line p → q: { x : orient(p, q, x) ≥ 0 }.
    pub fn left_of(p: &Pt, q: &Pt) -> HalfPlane {
        let (a, b) = ((&p.1 - &q.1), (&q.0 - &p.0));
        let c = (&(&a * &p.0) + &(&b * &p.1)).neg();
        HalfPlane { a, b, c }
    }

    /// The section of the half-space ℓ · p ≥ 0 by the plane v = -1 (p = (x, y, -1)).
    pub fn of_covector(l: &[Num; 3]) -> HalfPlane {
        HalfPlane { a: l[0].clone(), b: l[1].clone(), c: l[2].neg() }
    }

    /// a x + b y + c.
    pub fn value(&self, p: &Pt) -> Num {
        &(&(&self.a * &p.0) + &(&self.b * &p.1)) + &self.c
    }

    /// Whether p satisfies the constraint.
    pub fn holds(&self, p: &Pt) -> bool {
        !self.value(p).is_negative()
    }

    /// The boundary lines' common point, `None` when parallel (or not lines).
    pub fn meet(&self, o: &HalfPlane) -> Option<Pt> {
        let det = &(&self.a * &o.b) - &(&self.b * &o.a);
        if det.is_zero() {
            return None;
        }
        let x = &(&(&self.b * &o.c) - &(&o.b * &self.c)) / &det;
        let y = &(&(&o.a * &self.c) - &(&self.a * &o.c)) / &det;
        Some((x, y))
    }
}

/// The edge half-planes of a convex polygon given counter-clockwise.
pub fn edges(poly: &[Pt]) -> Vec<HalfPlane> {
    (0..poly.len()).map(|i| HalfPlane::left_of(&poly[i], &poly[(i + 1) % poly.len()])).collect()
}

/// The distinct vertices of {polygon} ∩ {extra constraints}: candidates are the polygon's
/// vertices and the meeting points of each extra line with every edge line and every other extra
/// line; a candidate is a vertex when it satisfies every constraint.
pub fn clip_vertices(poly: &[Pt], extra: &[HalfPlane]) -> Vec<Pt> {
    let sides = edges(poly);
    let mut candidates: Vec<Pt> = poly.to_vec();
    for (i, e) in extra.iter().enumerate() {
        for h in sides.iter().chain(&extra[i + 1..]) {
            candidates.extend(e.meet(h));
        }
    }
    let mut out: Vec<Pt> = vec![];
    for p in candidates {
        if extra.iter().chain(&sides).all(|h| h.holds(&p)) && !out.contains(&p) {
            out.push(p);
        }
    }
    out
}

/// Whether a point lies in the polygon of the given edge half-planes.
pub fn inside(sides: &[HalfPlane], p: &Pt) -> bool {
    sides.iter().all(|h| h.holds(p))
}
