//! Regions that may overlap, told apart in print: each convex region is hatched with thin lines
//! of its colour at its own angle (where two overlap, both hatchings show), and its name is put
//! where it alone covers the window, as far inside as possible.

use crate::finder::geometry::P2;

/// The hatching's spacing, as a fraction of the window's diagonal.
const SPACING: f64 = 1.0 / 45.0;

/// Window coordinates scaled to [0, 1]^2 (so angles and spacing are those seen on the page).
struct Unit {
    lo: P2,
    span: P2,
}

impl Unit {
    fn to(&self, p: &P2) -> P2 {
        P2::new((p.x - self.lo.x) / self.span.x, (p.y - self.lo.y) / self.span.y)
    }
    fn back(&self, p: &P2) -> (f64, f64) {
        (self.lo.x + p.x * self.span.x, self.lo.y + p.y * self.span.y)
    }
}

/// The part [t0, t1] of the line o + t d inside a convex polygon (counter-clockwise or not).
fn clip_line(poly: &[P2], o: P2, d: P2) -> Option<(f64, f64)> {
    let m = poly.len();
    if m < 3 {
        return None;
    }
    let area: f64 = (0..m).map(|i| poly[i].perp(&poly[(i + 1) % m])).sum();
    let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
    for i in 0..m {
        let (a, b) = (poly[i], poly[(i + 1) % m]);
        // Inside: the sign of (b - a) x (p - a) equals the orientation's.
        let e = b - a;
        let num = e.perp(&(o - a)) * area.signum();
        let den = e.perp(&d) * area.signum();
        if den.abs() < 1e-15 {
            if num < 0.0 {
                return None;
            }
        } else if den > 0.0 {
            t0 = t0.max(-num / den);
        } else {
            t1 = t1.min(-num / den);
        }
    }
    (t0 < t1).then_some((t0, t1))
}

/// Hatch lines (as data-coordinate segments) of a convex region of the window (lo, hi), at
/// `angle` radians on the page.
pub fn lines(poly: &[P2], (lo, hi): (P2, P2), angle: f64) -> Vec<[(f64, f64); 2]> {
    let unit = Unit { lo, span: hi - lo };
    let p: Vec<P2> = poly.iter().map(|v| unit.to(v)).collect();
    let d = P2::new(angle.cos(), angle.sin());
    let normal = P2::new(-d.y, d.x);
    let mut out = Vec::new();
    let count = (2.0f64.sqrt() / SPACING).ceil() as i64;
    for k in -count..=count {
        let o = P2::new(0.5, 0.5) + normal * (k as f64 * SPACING);
        if let Some((t0, t1)) = clip_line(&p, o, d) {
            out.push([unit.back(&(o + d * t0)), unit.back(&(o + d * t1))]);
        }
    }
    out
}

fn inside(poly: &[P2], q: P2) -> bool {
    let m = poly.len();
    if m < 3 {
        return false;
    }
    let signs: Vec<f64> = (0..m).map(|i| (poly[(i + 1) % m] - poly[i]).perp(&(q - poly[i]))).collect();
    signs.iter().all(|&s| s >= 0.0) || signs.iter().all(|&s| s <= 0.0)
}

/// Page distance (window units scaled to [0, 1]) from q to the polygon's boundary.
fn depth(poly: &[P2], q: P2) -> f64 {
    let m = poly.len();
    (0..m)
        .map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % m]);
            let e = b - a;
            let t = ((q - a).dot(&e) / e.norm_squared().max(1e-300)).clamp(0.0, 1.0);
            (q - (a + e * t)).norm()
        })
        .fold(f64::INFINITY, f64::min)
}

/// Where to write the name of region `j`: a point of a 40 x 40 sample of the window inside it,
/// preferring points no other region covers, then the farthest from its boundary and from the
/// polygons `avoid` (the cone and its images).
pub fn name_spot(
    regions: &[Vec<P2>],
    j: usize,
    avoid: &[&[P2]],
    placed: &[(f64, f64)],
    (lo, hi): (P2, P2),
) -> Option<(f64, f64)> {
    let unit = Unit { lo, span: hi - lo };
    let polys: Vec<Vec<P2>> = regions.iter().map(|r| r.iter().map(|v| unit.to(v)).collect()).collect();
    let avoid: Vec<Vec<P2>> = avoid.iter().map(|r| r.iter().map(|v| unit.to(v)).collect()).collect();
    let placed: Vec<P2> = placed.iter().map(|&(x, y)| unit.to(&P2::new(x, y))).collect();
    let mut best: Option<((bool, f64), P2)> = None;
    for a in 1..40 {
        for b in 1..40 {
            let q = P2::new(a as f64 / 40.0, b as f64 / 40.0);
            if !inside(&polys[j], q) {
                continue;
            }
            let alone = !polys.iter().enumerate().any(|(i, p)| i != j && inside(p, q));
            let clear =
                avoid.iter().filter(|a| a.len() >= 2).map(|a| depth(a, q)).fold(f64::INFINITY, f64::min);
            let names = placed.iter().map(|p| (p - q).norm() - 0.08).fold(f64::INFINITY, f64::min);
            let score = (alone, depth(&polys[j], q).min(clear).min(names));
            if best.as_ref().is_none_or(|(s, _)| (score.0 && !s.0) || (score.0 == s.0 && score.1 > s.1)) {
                best = Some((score, q));
            }
        }
    }
    best.map(|(_, q)| unit.back(&q))
}
