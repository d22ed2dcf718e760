//! Level lines of a field sampled at the centres of a map's cells (marching squares, the contour
//! crate), in the map's coordinates.
//!
//! The contour crate puts value i of a row at i + 1/2 in its own units, so the grid origin is the
//! map's lower-left corner (x0, g0), not the first centre. It also pads the field with "below"
//! values outside, so that every ring closes: the segments that run into that padding (along the
//! frame, and the diagonal stubs it cuts off the corner cells) are not level lines and are dropped.
//! What remains lies between the cell centres, where linear interpolation along the grid's edges
//! places every crossing.

use crate::sweep::curves::Polyline;
use crate::sweep::grid::Grid;
use crate::sweep::table::Row;

/// The field's values on the grid, row-major in gamma (`values[ig * nx + ix]`), `None` if any
/// point has no value.
fn sampled(grid: &Grid, rows: &[Row], value: &impl Fn(&Row) -> Option<f64>) -> Option<Vec<f64>> {
    let (nx, ny) = (grid.x.steps as usize, grid.gamma.steps as usize);
    let mut values = vec![f64::NAN; nx * ny];
    for r in rows {
        let (ix, ig) = (r.index / ny, r.index % ny);
        if let Some(slot) = values.get_mut(ig * nx + ix) {
            *slot = value(r)?;
        }
    }
    values.iter().all(|v| v.is_finite()).then_some(values)
}

/// The map's x and gamma ranges as f64.
pub fn ranges(g: &Grid) -> ((f64, f64), (f64, f64)) {
    use crate::exact::QExt;
    ((g.x.lo.to_f64(), g.x.hi.to_f64()), (g.gamma.lo.to_f64(), g.gamma.hi.to_f64()))
}

/// Contour lines of `value` over the grid at `levels`: (level, polyline) pairs, each polyline
/// inside the rectangle spanned by the cell centres.
pub fn contours(
    grid: &Grid,
    rows: &[Row],
    value: impl Fn(&Row) -> Option<f64>,
    levels: &[f64],
) -> Vec<(f64, Polyline)> {
    let (nx, ny) = (grid.x.steps as usize, grid.gamma.steps as usize);
    if nx < 2 || ny < 2 {
        return Vec::new();
    }
    let Some(values) = sampled(grid, rows, &value) else { return Vec::new() };
    let ((x0, x1), (g0, g1)) = ranges(grid);
    let (dx, dg) = ((x1 - x0) / nx as f64, (g1 - g0) / ny as f64);
    let builder = contour::ContourBuilder::new(nx, ny, true).x_origin(x0).y_origin(g0).x_step(dx).y_step(dg);
    let Ok(lines) = builder.lines(&values, levels) else { return Vec::new() };
    let centres = Centres { x: (x0 + dx / 2.0, x1 - dx / 2.0), g: (g0 + dg / 2.0, g1 - dg / 2.0), dx, dg };
    let mut out = Vec::new();
    for l in lines {
        let level = l.threshold();
        for ls in l.into_inner().0.0 {
            let pts: Polyline = ls.0.iter().map(|c| (c.x, c.y)).collect();
            out.extend(centres.inside(&pts).into_iter().map(|p| (level, p)));
        }
    }
    out
}

/// The rectangle of cell centres, with the cell size for the tolerance.
struct Centres {
    x: (f64, f64),
    g: (f64, f64),
    dx: f64,
    dg: f64,
}

impl Centres {
    fn contains(&self, (x, g): (f64, f64)) -> bool {
        let (ex, eg) = (1e-9 * self.dx, 1e-9 * self.dg);
        (self.x.0 - ex..=self.x.1 + ex).contains(&x) && (self.g.0 - eg..=self.g.1 + eg).contains(&g)
    }

    /// The runs of consecutive segments with both ends inside the rectangle.
    fn inside(&self, pts: &[(f64, f64)]) -> Vec<Polyline> {
        let mut pieces: Vec<Polyline> = vec![Vec::new()];
        for w in pts.windows(2) {
            if !(self.contains(w[0]) && self.contains(w[1])) {
                pieces.push(Vec::new());
                continue;
            }
            let cur = pieces.last_mut().expect("non-empty");
            if cur.is_empty() {
                cur.push(w[0]);
            }
            cur.push(w[1]);
        }
        pieces.into_iter().filter(|p| p.len() >= 2).collect()
    }
}
