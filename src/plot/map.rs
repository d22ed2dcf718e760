//! The paper's map panels: the cone finder's verdict as background (figure "sajatertekek", left:
//! white found, light grey inconclusive, dark grey no cone), the exact curves where S_1's dominant
//! eigenvalue changes sign or becomes complex, the CC criterion's and the PCC criterion's
//! boundaries, certified points; and the simulation maps (figure "simulations": level curves of
//! the mean impact count of the random drops, the 200 level separating ICC, PCC found).

use super::contour::ranges;
use super::{Entry, Figure, LABEL, Sample, TICKS, TITLE, err, legend};
use crate::sweep::curves::{Curves, Polyline};
use crate::sweep::grid::{Grid, Variable};
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

/// The horizontal axis's name: ρ, κ, or a body family's parameter.
pub fn x_name(grid: &Grid) -> String {
    match (grid.variable, &grid.family) {
        (_, Some(f)) => f.kind.names().1.to_string(),
        (Variable::Rho, None) => "ρ = √κ".into(),
        (_, None) => "κ".into(),
    }
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

/// The body's name for titles.
pub fn body_name(n: u64) -> &'static str {
    match n {
        3 => "triangle",
        4 => "square",
        5 => "pentagon",
        6 => "hexagon",
        7 => "heptagon",
        8 => "octagon",
        9 => "nonagon",
        10 => "decagon",
        _ => "regular polygon",
    }
}

/// Subscript digits for labels such as S₁ and C₂.
pub fn sub(k: u64) -> String {
    k.to_string().chars().map(|c| char::from_u32(0x2080 + c.to_digit(10).unwrap_or(0)).unwrap_or(c)).collect()
}

/// The chart of a map figure (data coordinates: x, gamma).
pub type MapChart<'a, 'b, DB> = ChartContext<
    'a,
    DB,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// Whether any of the polylines can be drawn (two points or more).
pub fn drawn(lines: &[Polyline]) -> bool {
    lines.iter().any(|l| l.len() >= 2)
}

/// The legend entries of the background: one per finder verdict that occurs, and what the
/// finder starts from.
fn background_entries(rows: &[Row], family: bool) -> Vec<Entry> {
    let verdicts = if family {
        [
            ("found", FOUND, "family finder: effectively invariant cones found"),
            ("inconclusive", INCONCLUSIVE, "family finder: inconclusive (budget exhausted)"),
            ("no-cone", NO_CONE, "family finder: no family contains the seeds"),
        ]
    } else {
        [
            ("found", FOUND, "cone finder: effectively invariant cone found"),
            ("inconclusive", INCONCLUSIVE, "cone finder: inconclusive (budget exhausted)"),
            ("no-cone", NO_CONE, "cone finder: no cone contains the seed"),
        ]
    };
    let seed = if family {
        "the finder's seeds: Iᵢ(0, 0, −1), the velocities after the first impact of a flat drop"
    } else {
        "the finder's seed: −U₀u₃, the velocity after the first impact of a flat drop (the paper's)"
    };
    let mut e: Vec<Entry> = verdicts
        .into_iter()
        .filter(|(v, ..)| rows.iter().any(|r| r.finder == *v))
        .map(|(_, c, text)| Entry::new(Sample::Fill(c), text))
        .collect();
    if !e.is_empty() {
        e.push(Entry::new(Sample::Note, seed));
    }
    e
}

/// Draws the lines and returns their legend entry if any was drawn.
pub(crate) fn curve_entry<DB: DrawingBackend>(
    chart: &mut MapChart<'_, '_, DB>,
    lines: &[Polyline],
    sample: Sample,
    text: String,
) -> Result<Option<Entry>, String> {
    let (colour, width, dashed) = match sample {
        Sample::Line(c, w) => (c, w, false),
        Sample::Dashed(c, w) => (c, w, true),
        _ => return Err("plot: a curve is drawn as a line".into()),
    };
    draw_lines(chart, lines, colour, width, dashed)?;
    Ok(drawn(lines).then(|| Entry::new(sample, text)))
}

impl MapFigure {
    /// The exact curves, certified and refuted points (figure "sajatertekek", left).
    fn draw_cones<DB: DrawingBackend>(
        &self,
        chart: &mut MapChart<'_, '_, DB>,
        radius: i32,
        centre: &dyn Fn(&Row) -> (f64, f64),
    ) -> Result<Vec<Entry>, String> {
        let m = sub(self.grid.n - 1);
        let mut e = Vec::new();
        let kind = "exact: S₁'s dominant eigenvalue changes sign or becomes complex";
        e.extend(curve_entry(chart, &self.curves.kind, Sample::Line(KIND, 2), kind.into())?);
        let cc = if self.grid.family.is_some() {
            "exact: boundary of the conjectural CC criterion (the product around the contacts has a real positive dominant eigenvalue)"
        } else {
            "exact: CC criterion boundary (real positive dominant eigenvalue below)"
        };
        e.extend(curve_entry(chart, &self.curves.cc, Sample::Dashed(CC, 3), cc.into())?);
        let pcc = format!("exact: PCC criterion boundary (S{m}S₁ has real eigenvalues: PCC possible)");
        e.extend(curve_entry(chart, &self.curves.pcc, Sample::Dashed(PCC, 3), pcc)?);
        chart
            .draw_series(self.rows.iter().filter_map(|r| {
                r.claim.as_deref().map(|c| Circle::new(centre(r), radius, claim_colour(c).filled()))
            }))
            .map_err(err)?;
        for c in ["CompleteChatterFromAllDown", "CcOrPccFromAllDown", "EffectivelyInvariant"] {
            if self.rows.iter().any(|r| r.claim.as_deref() == Some(c)) {
                e.push(Entry::new(Sample::Dot(claim_colour(c)), format!("certified: {c}")));
            }
        }
        let refuted: Vec<&Row> = self.rows.iter().filter(|r| r.refuted == Some(true)).collect();
        chart
            .draw_series(
                refuted.iter().map(|r| Cross::new(centre(r), radius + 1, REFUTED_MARK.stroke_width(1))),
            )
            .map_err(err)?;
        if !refuted.is_empty() {
            e.push(Entry::new(Sample::Star(REFUTED_MARK), "refuted: an exact refutation (no cone)"));
        }
        Ok(e)
    }
}

/// The (ρ or κ, γ) plane of a map figure with its caption and axes, no mesh (map, basin map).
pub(crate) fn plane_chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    title: &str,
    x: (f64, f64),
    g: (f64, f64),
    x_desc: &str,
) -> Result<MapChart<'a, 'a, DB>, String> {
    let mut chart = ChartBuilder::on(area)
        .caption(title, (super::FONT, TITLE))
        .margin(18)
        .x_label_area_size(62)
        .y_label_area_size(76)
        .build_cartesian_2d(x.0..x.1, g.0..g.1)
        .map_err(err)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(x_desc)
        .y_desc("γ")
        .axis_desc_style((super::FONT, LABEL))
        .label_style((super::FONT, TICKS))
        .draw()
        .map_err(err)?;
    Ok(chart)
}

pub(crate) fn draw_lines<DB: DrawingBackend>(
    chart: &mut MapChart<'_, '_, DB>,
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
        let mut chart = plane_chart(&left, &self.title, (x0, x1), (g0, g1), &x_name(&self.grid))?;
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
        let mut entries = background_entries(&self.rows, self.grid.family.is_some());
        entries.extend(match self.panel {
            Panel::Cones => {
                let (w, _) = left.dim_in_pixel();
                let radius = ((w as f64 / self.grid.x.steps as f64) / 6.0).clamp(1.0, 3.0) as i32;
                self.draw_cones(&mut chart, radius, &centre)?
            }
            Panel::Simulations => super::simulations::draw(self, &mut chart)?,
        });
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
        if !self.points.is_empty() {
            entries.push(Entry::new(Sample::Star(BLACK), "marked parameter point"));
        }
        legend(&right.margin(70, 10, 0, 10), &entries)
    }
}
