//! The paper's map panels: the cone finder's verdict as background (figure "sajatertekek", left:
//! white found, light grey inconclusive, dark grey no cone), the exact curves where S_1's dominant
//! eigenvalue changes sign or becomes complex, the CC criterion's and the PCC criterion's
//! boundaries, certified points; and the simulation maps (figure "simulations": level curves of
//! the mean impact count of the random drops, the 200 level separating ICC, PCC found).

use super::{Entry, Figure, LABEL, Sample, TICKS, TITLE, err, legend};
use crate::exact::QExt;
use crate::sweep::curves::{Curves, Polyline};
use crate::sweep::grid::{Grid, Variable};
use crate::sweep::point::PAPER_BUDGET;
use crate::sweep::table::Row;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Background colours of the finder's verdicts (the paper's scheme).
pub const FOUND: RGBColor = RGBColor(255, 255, 255);
pub const INCONCLUSIVE: RGBColor = RGBColor(205, 205, 205);
pub const NO_CONE: RGBColor = RGBColor(120, 120, 120);
/// Curve colours.
pub const KIND: RGBColor = RGBColor(0, 0, 0);
pub const CC: RGBColor = RGBColor(215, 25, 28);
pub const PCC: RGBColor = RGBColor(30, 90, 200);
pub const LEVEL: RGBColor = RGBColor(0, 100, 40);
/// Marks of certified points, by claim.
pub const COMPLETE: RGBColor = RGBColor(0, 150, 60);
pub const CC_OR_PCC: RGBColor = RGBColor(240, 140, 0);
pub const INVARIANT: RGBColor = RGBColor(140, 60, 170);
/// Marks of refuted points (an exact refutation, `map --refute`).
pub const REFUTED_MARK: RGBColor = RGBColor(20, 20, 20);

/// What a map figure shows on top of the finder's background.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Panel {
    /// Figure "sajatertekek", left: exact eigenvalue curves and certified points.
    Cones,
    /// Figure "simulations": level curves of the mean impact count of random drops.
    Simulations,
}

/// A map figure.
pub struct MapFigure {
    pub grid: Grid,
    pub rows: Vec<Row>,
    pub curves: Curves,
    pub panel: Panel,
    pub title: String,
    /// Extra labelled points (e.g. the paper's point D).
    pub points: Vec<(f64, f64, String)>,
}

/// Level curves of the mean impact count drawn on simulation maps (the last separates ICC).
pub const LEVELS: [f64; 5] = [25.0, 50.0, 100.0, 150.0, PAPER_BUDGET as f64 - 0.5];

fn x_name(v: Variable) -> &'static str {
    match v {
        Variable::Rho => "ρ = √κ",
        Variable::Kappa => "κ",
    }
}

fn ranges(g: &Grid) -> ((f64, f64), (f64, f64)) {
    ((g.x.lo.to_f64(), g.x.hi.to_f64()), (g.gamma.lo.to_f64(), g.gamma.hi.to_f64()))
}

fn verdict_colour(finder: &str) -> RGBColor {
    match finder {
        "found" => FOUND,
        "inconclusive" => INCONCLUSIVE,
        _ => NO_CONE,
    }
}

fn claim_colour(claim: &str) -> RGBColor {
    match claim {
        "CompleteChatterFromAllDown" => COMPLETE,
        "CcOrPccFromAllDown" => CC_OR_PCC,
        _ => INVARIANT,
    }
}

/// Contour lines of `value` over the grid at `levels` (marching squares, the contour crate).
pub fn contours(
    grid: &Grid,
    rows: &[Row],
    value: impl Fn(&Row) -> Option<f64>,
    levels: &[f64],
) -> Vec<(f64, Polyline)> {
    let (nx, ny) = (grid.x.steps as usize, grid.gamma.steps as usize);
    let mut values = vec![0.0; nx * ny];
    for r in rows {
        let (ix, ig) = (r.index / ny, r.index % ny);
        values[ig * nx + ix] = value(r).unwrap_or(f64::NAN);
    }
    if values.iter().any(|v| v.is_nan()) || nx < 2 || ny < 2 {
        return Vec::new();
    }
    let ((x0, x1), (g0, g1)) = ranges(grid);
    let (dx, dg) = ((x1 - x0) / nx as f64, (g1 - g0) / ny as f64);
    let builder = contour::ContourBuilder::new(nx, ny, true)
        .x_origin(x0 + dx / 2.0)
        .y_origin(g0 + dg / 2.0)
        .x_step(dx)
        .y_step(dg);
    let Ok(lines) = builder.lines(&values, levels) else { return Vec::new() };
    let frame = [x0 + dx / 2.0, x1 - dx / 2.0, g0 + dg / 2.0, g1 - dg / 2.0];
    let mut out = Vec::new();
    for l in lines {
        let level = l.threshold();
        for ls in l.into_inner().0.0 {
            let pts: Polyline = ls.0.iter().map(|c| (c.x, c.y)).collect();
            out.extend(off_frame(&pts, frame).into_iter().map(|p| (level, p)));
        }
    }
    out
}

/// The pieces of a contour line that do not run along the frame of cell centres (marching
/// squares closes its rings there; those edges are not level curves).
fn off_frame(pts: &[(f64, f64)], [xa, xb, ya, yb]: [f64; 4]) -> Vec<Polyline> {
    let eps = 1e-9 * (xb - xa).abs().max(yb - ya).max(1e-12);
    let same_edge = |a: (f64, f64), b: (f64, f64)| {
        [(a.0, b.0, xa), (a.0, b.0, xb), (a.1, b.1, ya), (a.1, b.1, yb)]
            .iter()
            .any(|(u, v, e)| (u - e).abs() < eps && (v - e).abs() < eps)
    };
    let mut pieces: Vec<Polyline> = vec![Vec::new()];
    for w in pts.windows(2) {
        if same_edge(w[0], w[1]) {
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

/// The body's name for titles.
pub fn body_name(n: u64) -> &'static str {
    match n {
        3 => "triangle",
        4 => "square",
        5 => "pentagon",
        6 => "hexagon",
        _ => "polygon",
    }
}

/// Subscript digits for labels such as S₁ and C₂.
pub fn sub(k: u64) -> String {
    k.to_string().chars().map(|c| char::from_u32(0x2080 + c.to_digit(10).unwrap_or(0)).unwrap_or(c)).collect()
}

impl MapFigure {
    fn legend_entries(&self) -> Vec<Entry> {
        let mut e = vec![
            Entry::new(Sample::Fill(FOUND), "cone finder: effectively invariant cone found"),
            Entry::new(Sample::Fill(INCONCLUSIVE), "cone finder: inconclusive"),
            Entry::new(Sample::Fill(NO_CONE), "cone finder: no cone contains the seed −U₀u₃"),
        ];
        match self.panel {
            Panel::Cones => {
                e.push(Entry::new(
                    Sample::Line(KIND, 2),
                    "exact: S₁'s dominant eigenvalue changes sign or becomes complex",
                ));
                e.push(Entry::new(
                    Sample::Dashed(CC, 3),
                    "exact: CC criterion boundary (real positive dominant eigenvalue below)",
                ));
                e.push(Entry::new(
                    Sample::Dashed(PCC, 3),
                    format!(
                        "exact: PCC criterion boundary (S{}S₁ has real eigenvalues: PCC possible)",
                        sub(self.grid.n - 1)
                    ),
                ));
                let claims = ["CompleteChatterFromAllDown", "CcOrPccFromAllDown", "EffectivelyInvariant"];
                for c in claims {
                    if self.rows.iter().any(|r| r.claim.as_deref() == Some(c)) {
                        e.push(Entry::new(Sample::Dot(claim_colour(c)), format!("certified: {c}")));
                    }
                }
                if self.rows.iter().any(|r| r.refuted == Some(true)) {
                    e.push(Entry::new(Sample::Star(REFUTED_MARK), "refuted: an exact refutation (no cone)"));
                }
            }
            Panel::Simulations => {
                e.push(Entry::new(
                    Sample::Line(LEVEL, 1),
                    "mean number of impacts of the random drops (levels 25, 50, 100, 150)",
                ));
                e.push(Entry::new(Sample::Line(LEVEL, 3), "level 200: above it some drops end in ICC"));
                e.push(Entry::new(Sample::Line(PCC, 3), "PCC found in half of the drops"));
                e.push(Entry::new(
                    Sample::Dashed(PCC, 3),
                    format!("exact: PCC possible (S{}S₁ has real eigenvalues)", sub(self.grid.n - 1)),
                ));
                e.push(Entry::new(
                    Sample::Dashed(CC, 3),
                    "exact: CC criterion boundary (conjectured CC/ICC divide)",
                ));
            }
        }
        if !self.points.is_empty() {
            e.push(Entry::new(Sample::Star(BLACK), "marked parameter point"));
        }
        e
    }
}

pub(crate) fn draw_lines<DB: DrawingBackend>(
    chart: &mut ChartContext<
        '_,
        DB,
        Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
    >,
    lines: &[Polyline],
    colour: RGBColor,
    width: u32,
    dashed: bool,
) -> Result<(), String> {
    for l in lines.iter().filter(|l| l.len() >= 2) {
        if dashed {
            chart
                .draw_series(DashedLineSeries::new(l.clone(), 9, 6, colour.stroke_width(width)))
                .map_err(err)?;
        } else {
            chart.draw_series(LineSeries::new(l.clone(), colour.stroke_width(width))).map_err(err)?;
        }
    }
    Ok(())
}

impl Figure for MapFigure {
    fn size(&self) -> (u32, u32) {
        (1250, 820)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        root.fill(&WHITE).map_err(err)?;
        let (left, right) = root.split_horizontally(840);
        let ((x0, x1), (g0, g1)) = ranges(&self.grid);
        let mut chart = ChartBuilder::on(&left)
            .caption(&self.title, (super::FONT, TITLE))
            .margin(18)
            .x_label_area_size(62)
            .y_label_area_size(76)
            .build_cartesian_2d(x0..x1, g0..g1)
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(x_name(self.grid.variable))
            .y_desc("γ")
            .axis_desc_style((super::FONT, LABEL))
            .label_style((super::FONT, TICKS))
            .draw()
            .map_err(err)?;
        let (dx, dg) = ((x1 - x0) / self.grid.x.steps as f64, (g1 - g0) / self.grid.gamma.steps as f64);
        let ny = self.grid.gamma.steps as usize;
        let centre =
            |r: &Row| (x0 + ((r.index / ny) as f64 + 0.5) * dx, g0 + ((r.index % ny) as f64 + 0.5) * dg);
        chart
            .draw_series(self.rows.iter().map(|r| {
                let (x, g) = centre(r);
                Rectangle::new(
                    [(x - dx / 2.0, g - dg / 2.0), (x + dx / 2.0, g + dg / 2.0)],
                    verdict_colour(&r.finder).filled(),
                )
            }))
            .map_err(err)?;
        match self.panel {
            Panel::Cones => {
                draw_lines(&mut chart, &self.curves.kind, KIND, 2, false)?;
                draw_lines(&mut chart, &self.curves.cc, CC, 3, true)?;
                draw_lines(&mut chart, &self.curves.pcc, PCC, 3, true)?;
                let (w, _) = left.dim_in_pixel();
                let radius = ((w as f64 / self.grid.x.steps as f64) / 6.0).clamp(1.0, 3.0) as i32;
                chart
                    .draw_series(self.rows.iter().filter_map(|r| {
                        r.claim.as_deref().map(|c| Circle::new(centre(r), radius, claim_colour(c).filled()))
                    }))
                    .map_err(err)?;
                chart
                    .draw_series(
                        self.rows
                            .iter()
                            .filter(|r| r.refuted == Some(true))
                            .map(|r| Cross::new(centre(r), radius + 1, REFUTED_MARK.stroke_width(1))),
                    )
                    .map_err(err)?;
            }
            Panel::Simulations => {
                for (i, (level, line)) in
                    contours(&self.grid, &self.rows, |r| r.sim.as_ref().map(|s| s.mean_impacts()), &LEVELS)
                        .into_iter()
                        .enumerate()
                {
                    let width = if level > 199.0 { 3 } else { 1 };
                    chart
                        .draw_series(LineSeries::new(line.clone(), LEVEL.stroke_width(width)))
                        .map_err(err)?;
                    if line.len() >= 6 {
                        let at = LEVELS.iter().position(|l| *l == level).unwrap_or(i) as f64;
                        let (x, g) = line[((0.15 + 0.17 * at) * line.len() as f64) as usize % line.len()];
                        let label = format!("{}", level.round());
                        let style = (super::FONT, 16).into_font().color(&LEVEL);
                        let tag = EmptyElement::at((x, g))
                            + Rectangle::new([(-2, -2), (9 * label.len() as i32 + 2, 17)], WHITE.filled())
                            + Text::new(label, (0, 0), style);
                        chart.draw_series(std::iter::once(tag)).map_err(err)?;
                    }
                }
                let pcc_share = |r: &Row| r.sim.as_ref().map(|s| s.counts[1] as f64 / s.runs as f64);
                let found: Vec<Polyline> =
                    contours(&self.grid, &self.rows, pcc_share, &[0.5]).into_iter().map(|(_, l)| l).collect();
                draw_lines(&mut chart, &found, PCC, 3, false)?;
                draw_lines(&mut chart, &self.curves.pcc, PCC, 3, true)?;
                draw_lines(&mut chart, &self.curves.cc, CC, 3, true)?;
            }
        }
        for (x, g, label) in &self.points {
            chart
                .draw_series(std::iter::once(Cross::new((*x, *g), 8, BLACK.stroke_width(3))))
                .map_err(err)?;
            chart
                .draw_series(std::iter::once(Text::new(
                    label.clone(),
                    (*x + dx, *g + dg),
                    (super::FONT, LABEL).into_font(),
                )))
                .map_err(err)?;
        }
        legend(&right.margin(70, 10, 0, 10), &self.legend_entries())
    }
}
