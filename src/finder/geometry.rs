//! Floating-point convex polygons on the projection plane v = -1 (untrusted search only).

use nalgebra::{Vector2, Vector3};

pub type P2 = Vector2<f64>;

fn cross2(a: &P2, b: &P2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// orient2d(a, b, c) > 0 when counter-clockwise.
pub fn orient(a: &P2, b: &P2, c: &P2) -> f64 {
    cross2(&(b - a), &(c - a))
}

/// Convex hull (counter-clockwise); points within `eps` of each other are merged first.
pub fn hull(points: &[P2], eps: f64) -> Vec<P2> {
    // `+ 0.0` turns -0.0 into 0.0, so the lexicographic order agrees with geometry.
    let mut p: Vec<P2> = points
        .iter()
        .filter(|q| q.x.is_finite() && q.y.is_finite())
        .map(|q| P2::new(q.x + 0.0, q.y + 0.0))
        .collect();
    p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    p.dedup_by(|a, b| (*a - *b).norm() <= eps);
    if p.len() < 3 {
        return p;
    }
    let mut h: Vec<P2> = Vec::with_capacity(2 * p.len());
    for pass in [p.clone(), p.iter().rev().copied().collect()] {
        let start = h.len();
        for q in pass {
            while h.len() >= start + 2 {
                let (a, b) = (h[h.len() - 2], h[h.len() - 1]);
                if orient(&a, &b, &q) > 0.0 {
                    break;
                }
                h.pop();
            }
            h.push(q);
        }
        h.pop();
    }
    h
}

/// The plane point of a 3-vector with v < 0.
pub fn project(p: &Vector3<f64>) -> P2 {
    P2::new(p.x / -p.z, p.y / -p.z)
}

/// The 3-vector (x, y, -1) of a plane point.
pub fn lift(p: &P2) -> Vector3<f64> {
    Vector3::new(p.x, p.y, -1.0)
}

/// Clips a convex polygon (any number of vertices) by the half-plane l . (x, y, -1) >= 0.
pub fn clip(poly: &[P2], l: &Vector3<f64>) -> Vec<P2> {
    let m = poly.len();
    let d: Vec<f64> = poly.iter().map(|p| l.dot(&lift(p))).collect();
    if d.iter().all(|&x| x >= 0.0) {
        return poly.to_vec();
    }
    let mut out = Vec::with_capacity(m + 1);
    for i in 0..m {
        let j = (i + 1) % m;
        if d[i] >= 0.0 {
            out.push(poly[i]);
        }
        if (d[i] > 0.0 && d[j] < 0.0) || (d[i] < 0.0 && d[j] > 0.0) {
            let t = d[i] / (d[i] - d[j]);
            out.push(poly[i] + (poly[j] - poly[i]) * t);
        }
    }
    out
}

/// Largest outward distance of q from the edges of a convex polygon (<= 0 inside). For a
/// degenerate polygon (a point or a segment) the distance to it.
pub fn outside_distance(poly: &[P2], q: &P2) -> f64 {
    match poly.len() {
        0 => f64::INFINITY,
        1 => (q - poly[0]).norm(),
        2 => {
            let (a, b) = (poly[0], poly[1]);
            let ab = b - a;
            let t = ((q - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
            (q - (a + ab * t)).norm()
        }
        m => (0..m)
            .map(|i| {
                let (a, b) = (poly[i], poly[(i + 1) % m]);
                -orient(&a, &b, q) / (b - a).norm()
            })
            .fold(f64::NEG_INFINITY, f64::max),
    }
}

/// Largest |coordinate| of the polygon, at least 1 (a scale for tolerances).
pub fn scale(poly: &[P2]) -> f64 {
    poly.iter().map(|p| p.x.abs().max(p.y.abs())).fold(1.0, f64::max)
}

/// Outer approximation with at most `max_vertices` vertices: repeatedly removes the edge whose
/// removal (extending its two neighbouring edges to their intersection) adds the least area.
pub fn simplify(poly: &[P2], max_vertices: usize) -> Vec<P2> {
    let mut p = poly.to_vec();
    while p.len() > max_vertices.max(3) {
        let m = p.len();
        let mut best: Option<(f64, usize, P2)> = None;
        for i in 0..m {
            // Edge i: p[i] -> p[i+1]; neighbours: p[i-1] -> p[i] and p[i+1] -> p[i+2].
            let (a, b, c, d) = (p[(i + m - 1) % m], p[i], p[(i + 1) % m], p[(i + 2) % m]);
            let (u, w) = (b - a, d - c);
            let den = cross2(&u, &w);
            if den <= 1e-300 {
                continue; // the neighbours do not meet beyond the edge
            }
            let t = cross2(&(c - b), &w) / den;
            if !(t >= 0.0 && t.is_finite()) {
                continue;
            }
            let x = b + u * t;
            let area = 0.5 * orient(&b, &x, &c).abs();
            if best.is_none_or(|(ba, _, _)| area < ba) {
                best = Some((area, i, x));
            }
        }
        let Some((_, i, x)) = best else { break };
        let j = (i + 1) % m;
        p[i] = x;
        p.remove(j);
    }
    p
}
