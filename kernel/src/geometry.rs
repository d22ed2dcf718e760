//! Exact polygons on the projection plane v = -1, kept in homogeneous form: a point is any
//! integer 3-vector g with g_v < 0 (it stands for (g_u0, g_u1) / (-g_v)), a line is a covector.
//! Every test is the sign of a polynomial in the integers, so nothing is ever divided.

use crate::exact::{Field, OrderedField, Ring, scale_to_ints, to_canonical};
use crate::model::linalg::{Vec3, cross, det3, dot};
use std::cmp::Ordering;

/// An exact ordered field with a ring R in which homogeneous vectors are kept: every vector of
/// the field has a positive multiple in R^k (integers for the rationals; the field itself for
/// a number field), and R embeds back into the field.
pub trait Scalar: OrderedField {
    /// The ring of scaled coordinates.
    type R: Ring;
    /// A positive multiple of `xs` with coordinates in R.
    fn scaled(xs: &[Self]) -> Vec<Self::R>;
    /// An element of R as an element of the field.
    fn lift(r: &Self::R) -> Self;
    /// The canonical text of an element.
    fn text(&self) -> String;
}

impl<F: Field> Scalar for F {
    type R = F::Int;
    fn scaled(xs: &[F]) -> Vec<F::Int> {
        scale_to_ints(xs)
    }
    fn lift(r: &F::Int) -> F {
        F::from_int(r)
    }
    fn text(&self) -> String {
        to_canonical(self)
    }
}

/// The point (a_0/w, ..., a_k/w) of a projection plane, from scaled coordinates and w > 0, as text.
pub fn projected<E: Scalar>(coords: &[E::R], w: &E::R) -> Vec<String> {
    let w = E::lift(w);
    coords.iter().map(|x| E::lift(x).over(&w).map_or_else(String::new, |c| c.text())).collect()
}

/// Orientation of the projected points a, b, c: `Greater` when counter-clockwise. With
/// w = -v > 0, orient2d(a/w_a, b/w_b, c/w_c) = -det[a, b, c] / (w_a w_b w_c).
pub fn orient<R: Ring>(a: &Vec3<R>, b: &Vec3<R>, c: &Vec3<R>) -> Ordering {
    det3(a, b, c).sign().reverse()
}

/// Compares the projected points lexicographically by (u0, u1)/(-v).
fn cmp_projected<R: Ring>(a: &Vec3<R>, b: &Vec3<R>) -> Ordering {
    let (wa, wb) = (a[2].negated(), b[2].negated());
    let by = |i: usize| a[i].times(&wb).cmp(&b[i].times(&wa));
    by(0).then_with(|| by(1))
}

/// Convex hull of projected points (Andrew's monotone chain): indices of the extreme points in
/// counter-clockwise order, starting from the lexicographically smallest. Points on edges and
/// repeated points are not extreme. Every input must have v < 0.
pub fn hull<R: Ring>(pts: &[Vec3<R>]) -> Vec<usize> {
    let mut idx: Vec<usize> = (0..pts.len()).collect();
    idx.sort_by(|&i, &j| cmp_projected(&pts[i], &pts[j]).then(i.cmp(&j)));
    idx.dedup_by(|i, j| cmp_projected(&pts[*i], &pts[*j]) == Ordering::Equal);
    if idx.len() < 3 {
        return idx;
    }
    let mut h: Vec<usize> = Vec::with_capacity(2 * idx.len());
    for pass in [idx.clone(), idx.iter().rev().copied().collect()] {
        let start = h.len();
        for i in pass {
            while h.len() >= start + 2
                && orient(&pts[h[h.len() - 2]], &pts[h[h.len() - 1]], &pts[i]) != Ordering::Greater
            {
                h.pop();
            }
            h.push(i);
        }
        h.pop(); // the last point of each chain starts the other one
    }
    h
}

/// A convex polygon with non-empty interior, vertices counter-clockwise.
pub struct ConvexPolygon<R> {
    /// The vertices, counter-clockwise.
    pub vertices: Vec<Vec3<R>>,
    /// `facets[i] . p >= 0` is the inner side of the edge from vertex i to vertex i+1.
    pub facets: Vec<Vec3<R>>,
    /// `chords[i] . p >= 0`: p is left of the ray from vertex 0 through vertex i (i >= 1).
    chords: Vec<Vec3<R>>,
}

impl<R: Ring> ConvexPolygon<R> {
    /// `vertices` must be the output of [`hull`] with at least three points.
    pub fn new(vertices: Vec<Vec3<R>>) -> Self {
        let m = vertices.len();
        let facets = (0..m).map(|i| cross(&vertices[(i + 1) % m], &vertices[i])).collect();
        let chords = vertices.iter().map(|v| cross(v, &vertices[0])).collect();
        ConvexPolygon { vertices, facets, chords }
    }

    /// Whether the projection of q (q_v < 0) lies in the closed polygon: locate q in the fan of
    /// triangles from vertex 0 by bisection, then test the one edge that closes its triangle.
    pub fn contains(&self, q: &Vec3<R>) -> bool {
        let m = self.vertices.len();
        let left = |i: usize| dot(&self.chords[i], q).sign();
        if left(1) == Ordering::Less || left(m - 1) == Ordering::Greater {
            return false;
        }
        let (mut lo, mut hi) = (1, m - 1);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if left(mid) == Ordering::Less { hi = mid } else { lo = mid }
        }
        !dot(&self.facets[lo], q).is_negative()
    }

    /// The first edge whose inner side does not contain q, with the value facet . q (< 0).
    pub fn first_violated(&self, q: &Vec3<R>) -> Option<(usize, R)> {
        self.facets.iter().enumerate().map(|(i, f)| (i, dot(f, q))).find(|(_, d)| d.is_negative())
    }
}

/// Clips a convex polygon (counter-clockwise homogeneous vertices) by the half-plane l . p >= 0
/// (one Sutherland-Hodgman pass). The crossing of edge P->N is dP N - dN P (times the sign of
/// dP), a positive combination of P and N on the line.
pub fn clip<R: Ring>(poly: &[Vec3<R>], l: &Vec3<R>) -> Vec<Vec3<R>> {
    let m = poly.len();
    let d: Vec<R> = poly.iter().map(|p| dot(l, p)).collect();
    if d.iter().all(|x| !x.is_negative()) {
        return poly.to_vec();
    }
    let mut out = Vec::with_capacity(m + 1);
    for i in 0..m {
        let (p, n) = (&poly[i], &poly[(i + 1) % m]);
        let (dp, dn) = (&d[i], &d[(i + 1) % m]);
        if !dp.is_negative() {
            out.push(p.clone());
        }
        if dp.sign() != Ordering::Equal && dn.sign() != Ordering::Equal && dp.sign() != dn.sign() {
            let x: Vec3<R> = std::array::from_fn(|k| dp.times(&n[k]).minus(&dn.times(&p[k])));
            out.push(if dp.is_negative() { x.map(|c| c.negated()) } else { x });
        }
    }
    out
}
