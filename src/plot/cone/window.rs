//! The data window of a panel: every point shown with a margin, both axes to the same scale when
//! that costs at most a factor [`SAME_SCALE`] of empty space, else the stretch is reported (and
//! written on the panel).

use crate::finder::geometry::P2;

/// Pixels of the tick-label areas below and left of a panel.
pub const X_LABELS: u32 = 62;
pub const Y_LABELS: u32 = 84;
/// Largest stretch made up by widening the window instead of stretching an axis.
pub const SAME_SCALE: f64 = 3.0;

/// Columns and rows of panels for `n` panels (one panel: 1 x 1).
pub fn grid(n: usize) -> (usize, usize) {
    let cols = if n <= 1 { 1 } else { 2 };
    (cols, n.div_ceil(cols).max(1))
}

/// The window around `points` for a plotting area of `pixels` (width, height), and the vertical
/// axis's magnification against the horizontal one (1 when both have the same scale).
pub fn fit(points: &[P2], pixels: (f64, f64)) -> (P2, P2, f64) {
    let (mut lo, mut hi) =
        (P2::new(f64::INFINITY, f64::INFINITY), P2::new(f64::NEG_INFINITY, f64::NEG_INFINITY));
    for p in points.iter().filter(|p| p.x.is_finite() && p.y.is_finite()) {
        lo = lo.inf(p);
        hi = hi.sup(p);
    }
    if !lo.x.is_finite() {
        return (P2::new(-1.0, -1.0), P2::new(1.0, 1.0), 1.0);
    }
    let span = (hi - lo).map(|d| d.max(1e-9 * (1.0 + lo.norm())));
    let pad = span * 0.12;
    let (mut lo, mut hi) = (lo - pad, hi + pad);
    // Units per pixel along each axis.
    let (ux, uy) = ((hi.x - lo.x) / pixels.0, (hi.y - lo.y) / pixels.1);
    if ux.max(uy) / ux.min(uy) > SAME_SCALE {
        return (lo, hi, ux / uy);
    }
    let u = ux.max(uy);
    let (cx, cy) = ((lo.x + hi.x) / 2.0, (lo.y + hi.y) / 2.0);
    lo = P2::new(cx - u * pixels.0 / 2.0, cy - u * pixels.1 / 2.0);
    hi = P2::new(cx + u * pixels.0 / 2.0, cy + u * pixels.1 / 2.0);
    (lo, hi, 1.0)
}

/// The plotting area of a panel in a figure of `panels` panels (approximately: the figure's left
/// part less margins, caption and tick labels).
pub fn pixels(panels: usize) -> (f64, f64) {
    let (cols, rows) = grid(panels);
    let (w, h) = (840.0 / cols as f64, if rows > 1 { (460.0 * rows as f64) / rows as f64 } else { 820.0 });
    let caption = if panels > 1 { 30.0 } else { 40.0 };
    (w - 28.0 - Y_LABELS as f64, h - 28.0 - X_LABELS as f64 - caption)
}

/// The note written on a panel whose axes have different scales.
pub fn stretch_note(stretch: f64) -> Option<String> {
    if stretch > SAME_SCALE {
        Some(format!("axes not to scale: vertical stretched {stretch:.0}×"))
    } else if stretch < 1.0 / SAME_SCALE {
        Some(format!("axes not to scale: horizontal stretched {:.0}×", 1.0 / stretch))
    } else {
        None
    }
}
