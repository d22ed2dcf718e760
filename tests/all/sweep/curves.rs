use crate::common::q;
use chatter::bodies;
use chatter::sweep::curves::{Crossing, column, curves, draw_crossings, row};
use chatter::sweep::grid::Variable;

#[test]
fn column_crossings_are_the_catalogue_thresholds() {
    // The square plate: the CC criterion's crossing at kappa = 1/6 is the body's CC threshold.
    let c = column(4, &q("1/6"));
    let e = bodies::user(4, &q("1/6")).unwrap();
    let (cc, pcc) = bodies::thresholds(&e, 12);
    assert_eq!(c.cc.len(), 1);
    assert!((c.cc[0].at - cc.midpoint.unwrap()).abs() < 1e-10, "{:?} vs {:?}", c.cc, cc.midpoint);
    assert!((c.pcc[0].at - pcc.unwrap().midpoint.unwrap()).abs() < 1e-10);
    assert!(c.cc.iter().all(|x| c.kind.iter().any(|k| k.at == x.at)), "CC changes are kind changes");
}

#[test]
fn no_false_crossing_from_samples_at_the_ends_or_on_exact_roots() {
    // At rho = 0.14 S_1's dominant eigenvalue is never complex for gamma in (0, 1) (it is at
    // gamma = 1 itself, which a sample at 1 used to report as a threshold).
    let c = column(3, &q("49/2500"));
    assert!(c.kind.iter().all(|x| !x.tag.starts_with("complex")), "{:?}", c.kind);
    // Along gamma = 1/20 the dominant eigenvalue becomes complex exactly at kappa = 1/2 (where
    // kappa + cos(2 pi/3) = 0), a rational root that a sample used to land on.
    let r = row(3, &q("1/20"), &q("1"));
    let complex: Vec<f64> = r.kind.iter().filter(|x| x.tag.starts_with("complex")).map(|x| x.at).collect();
    assert_eq!(complex, vec![0.5], "{:?}", r.kind);
}

#[test]
fn curves_link_columns_and_rows() {
    let c = curves(3, Variable::Rho, (&q("0"), &q("1")), (&q("0"), &q("1")), 24);
    assert!(!c.cc.is_empty() && !c.kind.is_empty() && !c.pcc.is_empty());
    // The CC boundary passes through (sqrt(1/8), (7 - 3 sqrt 5)/2).
    let (x, g) = ((1.0f64 / 8.0).sqrt(), (7.0 - 3.0 * 5f64.sqrt()) / 2.0);
    let near = c.cc.iter().flatten().any(|p| (p.0 - x).abs() < 0.03 && (p.1 - g).abs() < 0.03);
    assert!(near, "no CC curve point near the triangle plate's threshold");
    // The vertical boundary at kappa = 1/2 (rho = 0.7071...) comes from the rows.
    let on = |l: &Vec<(f64, f64)>| l.iter().filter(|p| (p.0 - 0.5f64.sqrt()).abs() < 1e-9).count();
    let vertical = c.kind.iter().any(|l| on(l) > 5);
    assert!(vertical);
}

/// The crossings of the curve `inside(x, g) = false/true` with the lines at i/m (i = 1..m - 1)
/// along one direction: `along(p, t)` is the point at position t on the line at p; bisected to
/// 1e-13 from a sampling in steps of 1/(64 m), tagged by the side below.
fn crossings_of(
    m: u32,
    inside: &dyn Fn(f64, f64) -> bool,
    along: &dyn Fn(f64, f64) -> (f64, f64),
) -> Vec<(f64, Vec<Crossing>)> {
    let on = |p: f64, t: f64| {
        let (x, g) = along(p, t);
        inside(x, g)
    };
    (1..m)
        .map(|i| {
            let p = i as f64 / m as f64;
            let k = 64 * m;
            let mut cs = Vec::new();
            for j in 0..k {
                let (mut a, mut b) = (j as f64 / k as f64, (j + 1) as f64 / k as f64);
                let below = on(p, a);
                if below == on(p, b) {
                    continue;
                }
                while b - a > 1e-13 {
                    let mid = (a + b) / 2.0;
                    if on(p, mid) == below { a = mid } else { b = mid }
                }
                let tag = if below { "in>out" } else { "out>in" };
                cs.push(Crossing { at: (a + b) / 2.0, tag: tag.into() });
            }
            (p, cs)
        })
        .collect()
}

/// The drawn pieces of the curve of `inside` on an m x m grid over (0, 1)^2.
fn drawn(m: u32, inside: &dyn Fn(f64, f64) -> bool) -> Vec<Vec<(f64, f64)>> {
    let cols = crossings_of(m, inside, &|x, g| (x, g));
    let rows = crossings_of(m, inside, &|g, x| (x, g));
    let cell = 1.0 / m as f64;
    draw_crossings(&cols, &rows, (cell, cell))
}

fn to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 { (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

fn length(l: &[(f64, f64)]) -> f64 {
    l.windows(2).map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1)).sum()
}

/// Every point of the true curve (dense samples `truth`) lies within a tenth of a cell of a
/// drawn piece (no gap) and, away from the pieces' ends (their joints), of exactly one (no
/// doubling); the pieces' total length lies in `len` (the curve's, up to 2%: doubled stretches
/// would add theirs), and every drawn point lies on the curve (`off`: distance to it).
fn assert_drawn_once(
    pieces: &[Vec<(f64, f64)>],
    truth: &[(f64, f64)],
    len: (f64, f64),
    off: &dyn Fn((f64, f64)) -> f64,
    m: u32,
) {
    let cell = 1.0 / m as f64;
    let tol = 0.1 * cell;
    let near = |p: (f64, f64), l: &Vec<(f64, f64)>| l.windows(2).any(|w| to_segment(p, w[0], w[1]) < tol);
    let ends: Vec<(f64, f64)> = pieces.iter().flat_map(|l| [l[0], l[l.len() - 1]]).collect();
    for &p in truth {
        let n = pieces.iter().filter(|l| near(p, l)).count();
        assert!(n >= 1, "a gap at {p:?}");
        let joint = ends.iter().any(|e| (e.0 - p.0).hypot(e.1 - p.1) < 2.0 * cell);
        assert!(n == 1 || joint, "{p:?} is drawn by {n} pieces");
    }
    let drawn: f64 = pieces.iter().map(|l| length(l)).sum();
    assert!(
        drawn > 0.98 * len.0 && drawn < 1.02 * len.1,
        "drawn length {drawn} for a curve of length {len:?}"
    );
    for &p in pieces.iter().flatten() {
        assert!(off(p) < tol, "a drawn point {p:?} lies {} off the curve", off(p));
    }
}

#[test]
fn each_stretch_of_a_curve_is_drawn_once_whatever_its_slope() {
    // A circle has every slope: the column-linked and the row-linked pieces both see most of it
    // (issue 26 §1: it was drawn twice, and a dashed curve looked solid).
    let (m, r) = (24, 0.3);
    let circle = |x: f64, g: f64| (x - 0.5).powi(2) + (g - 0.5).powi(2) < r * r;
    let pieces = drawn(m, &circle);
    let truth: Vec<(f64, f64)> = (0..4000)
        .map(|i| std::f64::consts::TAU * i as f64 / 4000.0)
        .map(|a| (0.5 + r * a.cos(), 0.5 + r * a.sin()))
        .collect();
    let len = std::f64::consts::TAU * r;
    let off = |p: (f64, f64)| ((p.0 - 0.5).hypot(p.1 - 0.5) - r).abs();
    assert_drawn_once(&pieces, &truth, (len, len), &off, m);
    // Steep lines (only the rows see them well) and shallow ones, across the grid: each drawn
    // once over the square of the grid lines, and nowhere outside the unit square.
    for (a, b) in [(5.0, -1.6), (0.2, 0.35), (-1.0, 1.03), (-12.0, 7.0)] {
        let line = |x: f64, g: f64| g < a * x + b;
        let inside = |(x, g): (f64, f64), e: f64| x >= e && x <= 1.0 - e && g >= e && g <= 1.0 - e;
        let points = |e: f64| -> Vec<(f64, f64)> {
            (0..=20000)
                .map(|i| i as f64 / 20000.0)
                .map(|x| (x, a * x + b))
                .filter(|&p| inside(p, e))
                .collect()
        };
        let span = |t: &[(f64, f64)]| (t[t.len() - 1].0 - t[0].0).hypot(t[t.len() - 1].1 - t[0].1);
        let truth = points(1.0 / m as f64);
        let len = (span(&truth), span(&points(0.0)));
        let off = |p: (f64, f64)| (p.1 - a * p.0 - b).abs() / a.hypot(1.0);
        assert_drawn_once(&drawn(m, &line), &truth, len, &off, m);
    }
}
