//! Where to put a curve's label: on the curve, as far as possible from every other curve, from the
//! labels already placed and from the frame, measured in pixels of the plotting area.

use crate::sweep::curves::Polyline;

/// The plotting area: data ranges and their size in pixels.
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    pub x: (f64, f64),
    pub y: (f64, f64),
    pub pixels: (f64, f64),
}

impl Frame {
    /// A data point in pixels from the lower-left corner.
    pub fn px(&self, (x, y): (f64, f64)) -> (f64, f64) {
        (
            (x - self.x.0) / (self.x.1 - self.x.0) * self.pixels.0,
            (y - self.y.0) / (self.y.1 - self.y.0) * self.pixels.1,
        )
    }

    /// Pixels from a point to the nearest edge of the frame.
    fn edge_distance(&self, p: (f64, f64)) -> f64 {
        let (x, y) = self.px(p);
        x.min(self.pixels.0 - x).min(y).min(self.pixels.1 - y)
    }
}

/// Pixel distance from `p` to the segment a-b (all in pixels).
fn to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 { (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

/// Pixel distance from `p` (data) to the nearest of the polylines.
pub fn to_lines(frame: &Frame, p: (f64, f64), lines: &[&Polyline]) -> f64 {
    let q = frame.px(p);
    lines
        .iter()
        .flat_map(|l| l.windows(2))
        .map(|w| to_segment(q, frame.px(w[0]), frame.px(w[1])))
        .fold(f64::INFINITY, f64::min)
}

/// The point of `line` (a vertex or a segment's midpoint) for a label of half-size `half`
/// (pixels): among the points whose label keeps clear of the `avoid` lines, the labels already
/// placed and the frame, the one nearest to the fraction `target` of the line's length (so labels
/// of neighbouring lines spread along them); if none keeps clear, the clearest. `None` if the
/// line has no point.
pub fn place(
    frame: &Frame,
    line: &Polyline,
    avoid: &[&Polyline],
    placed: &[(f64, f64)],
    half: (f64, f64),
    target: f64,
) -> Option<(f64, f64)> {
    let mids = line.windows(2).map(|w| ((w[0].0 + w[1].0) / 2.0, (w[0].1 + w[1].1) / 2.0));
    let mut candidates: Vec<(f64, f64)> = line.iter().copied().chain(mids).collect();
    let along = |p: &(f64, f64)| position(frame, line, *p);
    candidates.sort_by(|a, b| along(a).total_cmp(&along(b)));
    let reach = half.0.hypot(half.1);
    let clearance = |p: (f64, f64)| {
        let q = frame.px(p);
        let labels = placed
            .iter()
            .map(|&l| {
                let r = frame.px(l);
                (q.0 - r.0).hypot(q.1 - r.1) - 2.0 * reach
            })
            .fold(f64::INFINITY, f64::min);
        let edge = frame.edge_distance(p) - reach;
        (to_lines(frame, p, avoid) - reach).min(labels).min(edge)
    };
    let clear = candidates
        .iter()
        .filter(|p| clearance(**p) >= 0.0)
        .min_by(|a, b| (along(a) - target).abs().total_cmp(&(along(b) - target).abs()));
    clear.copied().or_else(|| {
        candidates.into_iter().map(|p| (clearance(p), p)).max_by(|a, b| a.0.total_cmp(&b.0)).map(|(_, p)| p)
    })
}

/// The fraction of the line's pixel length at which `p` (a vertex or a midpoint) lies.
fn position(frame: &Frame, line: &Polyline, p: (f64, f64)) -> f64 {
    let px: Vec<(f64, f64)> = line.iter().map(|&v| frame.px(v)).collect();
    let seg = |w: &[(f64, f64)]| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1);
    let total: f64 = px.windows(2).map(seg).sum();
    let q = frame.px(p);
    let mut run = 0.0;
    let mut best = (f64::INFINITY, 0.0);
    for w in px.windows(2) {
        let d = to_segment(q, w[0], w[1]);
        if d < best.0 {
            let t = (q.0 - w[0].0).hypot(q.1 - w[0].1);
            best = (d, run + t);
        }
        run += seg(w);
    }
    if total > 0.0 { best.1 / total } else { 0.0 }
}
