//! Where to put a curve's label: on the curve, its box clear of every curve it must not hide, of
//! the labels already placed and of the frame, and if it can be of the other curves too, near a
//! given fraction of the line's length; where the curve has no such place, beside it with a
//! leader, or nowhere (never over a curve it must not hide); measured in pixels of the plotting
//! area.

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

    /// The data point of a pixel (from the lower-left corner).
    pub fn data(&self, (u, v): (f64, f64)) -> (f64, f64) {
        (
            self.x.0 + u / self.pixels.0 * (self.x.1 - self.x.0),
            self.y.0 + v / self.pixels.1 * (self.y.1 - self.y.0),
        )
    }
}

/// Pixels a label's box keeps from a curve: half the widest stroke (3) and one of antialiasing.
pub const GAP: f64 = 2.5;

/// Pixels between two labels' boxes.
const LABEL_GAP: f64 = 4.0;

/// Pixels between two candidate places along a line.
const STEP: f64 = 1.0;

/// A label's box: its centre (data) and half its size (pixels).
#[derive(Clone, Copy, Debug)]
pub struct LabelBox {
    pub at: (f64, f64),
    pub half: (f64, f64),
}

/// What a label keeps clear of.
#[derive(Clone, Copy, Debug, Default)]
pub struct Clear<'a> {
    /// Curves the box must not cover (the exact and the proved curves).
    pub hard: &'a [&'a Polyline],
    /// Curves it should not cover where it can avoid them (the other level lines).
    pub soft: &'a [&'a Polyline],
    /// Labels already placed.
    pub placed: &'a [LabelBox],
}

/// Pixel distance from `p` to the segment a-b (all in pixels).
fn to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 { (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

/// Pixel distance from `p` to the box of centre `c` and half-size `h` (0 inside).
fn to_box(p: (f64, f64), c: (f64, f64), h: (f64, f64)) -> f64 {
    ((p.0 - c.0).abs() - h.0).max(0.0).hypot(((p.1 - c.1).abs() - h.1).max(0.0))
}

/// Whether the segment a-b meets the box (Liang-Barsky clipping).
fn meets_box(a: (f64, f64), b: (f64, f64), c: (f64, f64), h: (f64, f64)) -> bool {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let sides =
        [(-dx, a.0 - (c.0 - h.0)), (dx, c.0 + h.0 - a.0), (-dy, a.1 - (c.1 - h.1)), (dy, c.1 + h.1 - a.1)];
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in sides {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else if p < 0.0 {
            t0 = t0.max(q / p);
        } else {
            t1 = t1.min(q / p);
        }
    }
    t0 <= t1
}

/// Pixel distance from the segment a-b to the box (0 if they meet): for disjoint convex shapes it
/// is reached at a corner of one of them.
fn segment_to_box(a: (f64, f64), b: (f64, f64), c: (f64, f64), h: (f64, f64)) -> f64 {
    if meets_box(a, b, c, h) {
        return 0.0;
    }
    let corners =
        [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)].map(|(s, t)| (c.0 + s * h.0, c.1 + t * h.1));
    corners.iter().map(|&k| to_segment(k, a, b)).fold(to_box(a, c, h).min(to_box(b, c, h)), f64::min)
}

/// A polyline's segments in pixels.
type Segments = Vec<((f64, f64), (f64, f64))>;

fn segments(frame: &Frame, lines: &[&Polyline]) -> Segments {
    lines.iter().flat_map(|l| l.windows(2)).map(|w| (frame.px(w[0]), frame.px(w[1]))).collect()
}

/// Pixel distance from a box (centre in pixels) to the nearest segment, up to `reach` (beyond it,
/// `reach`: segments whose bounding box is farther are skipped).
fn box_to_segments(c: (f64, f64), h: (f64, f64), segs: &Segments, reach: f64) -> f64 {
    let (rx, ry) = (h.0 + reach, h.1 + reach);
    segs.iter()
        .filter(|(a, b)| {
            a.0.min(b.0) <= c.0 + rx
                && a.0.max(b.0) >= c.0 - rx
                && a.1.min(b.1) <= c.1 + ry
                && a.1.max(b.1) >= c.1 - ry
        })
        .map(|&(a, b)| segment_to_box(a, b, c, h))
        .fold(reach, f64::min)
}

/// Places along `line`, every [`STEP`] pixels: (data point, fraction of the line's pixel length).
fn candidates(frame: &Frame, line: &Polyline) -> Vec<((f64, f64), f64)> {
    let seg = |w: &[(f64, f64)]| {
        let (a, b) = (frame.px(w[0]), frame.px(w[1]));
        (b.0 - a.0).hypot(b.1 - a.1)
    };
    let total: f64 = line.windows(2).map(seg).sum();
    let mut out = Vec::new();
    let mut run = 0.0;
    for w in line.windows(2) {
        let len = seg(w);
        let k = (len / STEP).ceil().max(1.0) as usize;
        for i in 0..k {
            let t = i as f64 / k as f64;
            let p = (w[0].0 + t * (w[1].0 - w[0].0), w[0].1 + t * (w[1].1 - w[0].1));
            out.push((p, if total > 0.0 { (run + t * len) / total } else { 0.0 }));
        }
        run += len;
    }
    if let Some(&last) = line.last() {
        out.push((last, 1.0));
    }
    out
}

/// Pixels by which a box at `c` (pixels) keeps clear of the frame, the `hard` curves' segments
/// and the placed labels (negative: it covers one of them), up to the box's size.
fn hard_clearance(frame: &Frame, c: (f64, f64), h: (f64, f64), hard: &Segments, placed: &[LabelBox]) -> f64 {
    let (w, ht) = frame.pixels;
    let edge = (c.0 - h.0).min(w - c.0 - h.0).min(c.1 - h.1).min(ht - c.1 - h.1);
    let labels = placed
        .iter()
        .map(|l| {
            let q = frame.px(l.at);
            ((c.0 - q.0).abs() - h.0 - l.half.0).max((c.1 - q.1).abs() - h.1 - l.half.1) - LABEL_GAP
        })
        .fold(f64::INFINITY, f64::min);
    (box_to_segments(c, h, hard, h.0 + h.1 + GAP) - GAP).min(labels).min(edge)
}

/// A label's place: its centre (data), and where its leader meets the line (data) when no free
/// place on the line exists and it stands beside it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placed {
    pub at: (f64, f64),
    pub leader: Option<(f64, f64)>,
}

/// The most label heights a label may stand beside its line.
const BESIDE: f64 = 3.0;

/// Directions tried around a place on the line for a label beside it.
const DIRECTIONS: usize = 16;

/// Pixels between two places on the line tried for a label beside it.
const BESIDE_STEP: f64 = 4.0;

/// The place for a label of half-size `half` (pixels) on `line`: among the places whose box
/// keeps clear of the frame, the `hard` curves and the placed labels, those that also keep clear
/// of the `soft` curves, or else those that touch the fewest of them; of these the one nearest
/// to the fraction `target` of the line's length (so labels of neighbouring lines spread along
/// them). If no place on the line keeps clear, the nearest clear place beside it within
/// `BESIDE` label heights whose leader crosses no `hard` curve (`beside`); `None` if there is
/// none either (the label is left out).
pub fn place(frame: &Frame, line: &Polyline, clear: &Clear, half: (f64, f64), target: f64) -> Option<Placed> {
    let hard = segments(frame, clear.hard);
    let soft: Vec<Segments> = clear.soft.iter().map(|l| segments(frame, &[*l])).collect();
    let touched = |c: (f64, f64)| soft.iter().filter(|l| box_to_segments(c, half, l, GAP) < GAP).count();
    let mut best: Option<((usize, f64), (f64, f64))> = None;
    for (p, along) in candidates(frame, line) {
        let c = frame.px(p);
        if hard_clearance(frame, c, half, &hard, clear.placed) < 0.0 {
            continue;
        }
        let key = (touched(c), (along - target).abs());
        if best.is_none_or(|(k, _)| key.0 < k.0 || (key.0 == k.0 && key.1 < k.1)) {
            best = Some((key, p));
        }
    }
    match best {
        Some((_, p)) => Some(Placed { at: p, leader: None }),
        None => beside(frame, line, clear, half, &hard, &touched),
    }
}

/// The nearest place beside `line` (pixels from it, then the fewest soft curves touched) whose
/// box keeps clear of the frame, the `hard` curves and the placed labels, and whose leader (from
/// the line to the box's nearest point) keeps clear of the `hard` curves.
fn beside(
    frame: &Frame,
    line: &Polyline,
    clear: &Clear,
    half: (f64, f64),
    hard: &Segments,
    touched: &dyn Fn((f64, f64)) -> usize,
) -> Option<Placed> {
    let reach = BESIDE * 2.0 * half.1;
    let mut best: Option<((f64, usize), Placed)> = None;
    let mut last: Option<(f64, f64)> = None;
    for (p, _) in candidates(frame, line) {
        let q = frame.px(p);
        if last.is_some_and(|l| (l.0 - q.0).hypot(l.1 - q.1) < BESIDE_STEP) {
            continue;
        }
        last = Some(q);
        for k in 0..DIRECTIONS {
            let a = std::f64::consts::TAU * k as f64 / DIRECTIONS as f64;
            let mut d = half.1;
            while d <= reach + half.0 {
                let c = (q.0 + d * a.cos(), q.1 + d * a.sin());
                d += BESIDE_STEP;
                let gap = to_box(q, c, half);
                if gap < GAP || gap > reach || best.is_some_and(|(k, _)| gap > k.0) {
                    continue;
                }
                if hard_clearance(frame, c, half, hard, clear.placed) < 0.0 || !leader_clear(q, c, half, hard)
                {
                    continue;
                }
                let key = (gap, touched(c));
                if best.is_none_or(|(k, _)| key.0 < k.0 || (key.0 == k.0 && key.1 < k.1)) {
                    best = Some((key, Placed { at: frame.data(c), leader: Some(p) }));
                }
            }
        }
    }
    best.map(|(_, p)| p)
}

/// The point of the box (centre `c`, half-size `h`) nearest to `q` (all in pixels).
pub fn box_point(q: (f64, f64), c: (f64, f64), h: (f64, f64)) -> (f64, f64) {
    (q.0.clamp(c.0 - h.0, c.0 + h.0), q.1.clamp(c.1 - h.1, c.1 + h.1))
}

/// Whether the leader from `q` to the box keeps [`GAP`] pixels from every `hard` segment.
fn leader_clear(q: (f64, f64), c: (f64, f64), h: (f64, f64), hard: &Segments) -> bool {
    let e = box_point(q, c, h);
    let n = ((e.0 - q.0).hypot(e.1 - q.1)).ceil().max(1.0) as usize;
    (0..=n).all(|i| {
        let t = i as f64 / n as f64;
        let p = (q.0 + t * (e.0 - q.0), q.1 + t * (e.1 - q.1));
        box_to_segments(p, (0.0, 0.0), hard, GAP + 1.0) >= GAP
    })
}
