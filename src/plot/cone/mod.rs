//! Certificates on the plane v = -1 (figure "sajatertekek", right; docs/model.md §5): for a
//! regular polygon ([`regular`], rational or in a number field through f64 enclosures), the cone
//! K, the cones C_j of velocities from which contact j hits next, the images S_j(K ∩ C_j) that must
//! lie in K, the velocities I_0(D) after the first impact of the all-down drops and the dominant
//! eigenvectors of S_1 and S_{n-1}; for a general body ([`convex`]), one panel per contact; for an
//! orbit certificate ([`orbit`]), the set X projected on the velocity plane with its image under
//! the return map. Everything here is f64, for display only.

pub mod convex;
mod hatch;
pub mod orbit;
pub mod regular;
mod window;

use super::map::sub;
use super::{Entry, Figure, LABEL, Sample, TICKS, TITLE, err, legend};
use crate::finder::geometry::P2;
use chatter_kernel::certificate::Encoding;
use chatter_kernel::syntax::{Kind, kind_of};
use plotters::coord::Shift;
use plotters::prelude::*;

/// Colours by index (C_j and the images coming from contact j).
pub const STEP: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
];

/// The colour of index j.
pub fn colour(j: usize) -> RGBColor {
    STEP[j % STEP.len()]
}

/// A polygon of a panel with its name (drawn at its centre) and legend text.
#[derive(Clone, Debug)]
pub struct Region {
    /// Short name drawn on the region, e.g. "C₁" (empty: none).
    pub name: String,
    pub colour: RGBColor,
    pub polygon: Vec<P2>,
    pub legend: String,
}

/// The shape of a marked point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Marker {
    Cross,
    Square,
    Dot,
}

/// A marked point with its label.
#[derive(Clone, Debug)]
pub struct Mark {
    pub label: String,
    pub at: P2,
    pub marker: Marker,
    pub legend: String,
}

/// One plane of a figure.
#[derive(Clone, Debug)]
pub struct Panel {
    /// Caption above the panel (empty for a single panel).
    pub title: String,
    /// The certified set (K, K_i, or X projected) and its legend text.
    pub k: Vec<P2>,
    pub k_legend: String,
    /// Regions behind everything (the cones C_j), light fill, dashed outline, named.
    pub regions: Vec<Region>,
    /// Images that must lie in K, filled and outlined.
    pub images: Vec<Region>,
    /// Dots (the first impacts of all-down drops) and their legend text.
    pub seeds: Vec<P2>,
    pub seeds_legend: String,
    pub marks: Vec<Mark>,
    /// The data window; see `window::fit`.
    pub window: (P2, P2),
    /// The vertical axis's magnification against the horizontal one (1 = same scale).
    pub stretch: f64,
}

/// A figure of one or more panels.
pub struct ConeFigure {
    pub title: String,
    pub axes: (String, String),
    pub panels: Vec<Panel>,
    /// Legend lines without a sample (e.g. what the axes are).
    pub notes: Vec<String>,
}

impl ConeFigure {
    /// Reads a certificate of any version (RON or its JSON twin) and computes its drawing.
    pub fn from_certificate(text: &str) -> Result<ConeFigure, String> {
        let encoding = if text.trim_start().starts_with('{') { Encoding::Json } else { Encoding::Ron };
        match kind_of(text, encoding, Kind::Cone).map(|k| k.0) {
            Ok(Kind::Family) => convex::figure(text, encoding),
            Ok(Kind::Orbit) => orbit::figure(text, encoding),
            _ => regular::figure(text, encoding),
        }
    }

    fn entries(&self) -> Vec<Entry> {
        let mut e: Vec<Entry> = Vec::new();
        let mut push = |entry: Entry| {
            if !e.iter().any(|x| x.text == entry.text) {
                e.push(entry);
            }
        };
        for p in &self.panels {
            push(Entry::new(Sample::Line(BLACK, 3), p.k_legend.clone()));
        }
        // Regions and images in the order of their names (contact 0, 1, ... whatever the panel).
        let mut regions: Vec<&Region> = self.panels.iter().flat_map(|p| &p.regions).collect();
        regions.sort_by(|a, b| a.legend.cmp(&b.legend));
        for r in regions {
            push(Entry::new(Sample::Hatch(light_line(r.colour)), r.legend.clone()));
        }
        let mut images: Vec<&Region> =
            self.panels.iter().flat_map(|p| &p.images).filter(|r| r.polygon.len() >= 2).collect();
        images.sort_by(|a, b| a.legend.cmp(&b.legend));
        for r in images {
            push(Entry::new(Sample::Line(r.colour, 2), r.legend.clone()));
        }
        for p in self.panels.iter().filter(|p| !p.seeds.is_empty()) {
            push(Entry::new(Sample::Dot(SEED), p.seeds_legend.clone()));
        }
        for p in &self.panels {
            for m in &p.marks {
                let sample = match m.marker {
                    Marker::Cross => Sample::Star(BLACK),
                    Marker::Square => Sample::Square(BLACK),
                    Marker::Dot => Sample::Dot(BLACK),
                };
                push(Entry::new(sample, m.legend.clone()));
            }
        }
        e.extend(self.notes.iter().map(|n| Entry::new(Sample::Note, n.clone())));
        e
    }
}

/// The grey of the seed dots.
const SEED: RGBColor = RGBColor(90, 90, 90);

/// An image's fill.
fn medium(c: RGBColor) -> RGBColor {
    let f = |c: u8| (255.0 - (255.0 - c as f64) * 0.35).round() as u8;
    RGBColor(f(c.0), f(c.1), f(c.2))
}

/// Subscript of a contact or step index.
pub fn s(j: usize) -> String {
    sub(j as u64)
}

fn closed(p: &[P2]) -> Vec<(f64, f64)> {
    p.iter().chain(p.first()).map(|v| (v.x, v.y)).collect()
}

/// A hatching line's colour: the region's, lightened.
fn light_line(c: RGBColor) -> RGBColor {
    let f = |c: u8| (255.0 - (255.0 - c as f64) * 0.55).round() as u8;
    RGBColor(f(c.0), f(c.1), f(c.2))
}

fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    axes: &(String, String),
    caption: (&str, u32),
) -> Result<(), String> {
    let (lo, hi) = panel.window;
    let mut chart = ChartBuilder::on(area)
        .caption(caption.0, (super::FONT, caption.1))
        .margin(14)
        .x_label_area_size(window::X_LABELS)
        .y_label_area_size(window::Y_LABELS)
        .build_cartesian_2d(lo.x..hi.x, lo.y..hi.y)
        .map_err(err)?;
    chart
        .configure_mesh()
        .light_line_style(RGBColor(235, 235, 235))
        .x_desc(axes.0.as_str())
        .y_desc(axes.1.as_str())
        .x_labels(6)
        .axis_desc_style((super::FONT, LABEL))
        .label_style((super::FONT, TICKS))
        .draw()
        .map_err(err)?;
    for (j, r) in panel.regions.iter().enumerate() {
        let angle = std::f64::consts::PI * (0.25 + 0.3 * j as f64);
        for seg in hatch::lines(&r.polygon, panel.window, angle) {
            chart.draw_series(LineSeries::new(seg, light_line(r.colour).stroke_width(1))).map_err(err)?;
        }
        chart
            .draw_series(DashedLineSeries::new(closed(&r.polygon), 7, 5, r.colour.stroke_width(1)))
            .map_err(err)?;
    }
    for r in &panel.images {
        let pts: Vec<(f64, f64)> = r.polygon.iter().map(|v| (v.x, v.y)).collect();
        chart.draw_series(std::iter::once(Polygon::new(pts, medium(r.colour).filled()))).map_err(err)?;
        chart.draw_series(LineSeries::new(closed(&r.polygon), r.colour.stroke_width(2))).map_err(err)?;
    }
    chart.draw_series(LineSeries::new(closed(&panel.k), BLACK.stroke_width(3))).map_err(err)?;
    let polys: Vec<Vec<P2>> = panel.regions.iter().map(|r| r.polygon.clone()).collect();
    let avoid: Vec<&[P2]> = std::iter::once(panel.k.as_slice())
        .chain(panel.images.iter().map(|r| r.polygon.as_slice()))
        .collect();
    let mut placed = Vec::new();
    for (j, r) in panel.regions.iter().enumerate().filter(|(_, r)| !r.name.is_empty()) {
        if let Some(at) = hatch::name_spot(&polys, j, &avoid, &placed, panel.window) {
            placed.push(at);
            let style = (super::FONT, LABEL).into_font().color(&r.colour);
            let tag = EmptyElement::at(at)
                + Rectangle::new([(-14, -13), (14, 13)], WHITE.filled())
                + Text::new(r.name.clone(), (-10, -11), style);
            chart.draw_series(std::iter::once(tag)).map_err(err)?;
        }
    }
    chart.draw_series(panel.seeds.iter().map(|p| Circle::new((p.x, p.y), 5, SEED.filled()))).map_err(err)?;
    draw_marks(&mut chart, &panel.marks, panel.window)?;
    if let Some(note) = window::stretch_note(panel.stretch) {
        let style = (super::FONT, TICKS).into_font().color(&BLACK);
        let at = (lo.x, hi.y);
        let tag = EmptyElement::at(at) + Text::new(note, (8, 6), style);
        chart.draw_series(std::iter::once(tag)).map_err(err)?;
    }
    Ok(())
}

type Chart<'a, DB> = ChartContext<
    'a,
    DB,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

fn draw_marks<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    marks: &[Mark],
    window: (P2, P2),
) -> Result<(), String> {
    for (i, m) in marks.iter().enumerate() {
        let at = (m.at.x, m.at.y);
        match m.marker {
            Marker::Cross => chart.draw_series(std::iter::once(Cross::new(at, 9, BLACK.stroke_width(3)))),
            Marker::Square => chart.draw_series(std::iter::once(
                EmptyElement::at(at) + Rectangle::new([(-7, -7), (7, 7)], BLACK.stroke_width(3)),
            )),
            Marker::Dot => chart.draw_series(std::iter::once(Circle::new(at, 5, BLACK.filled()))),
        }
        .map_err(err)?;
        // Labels of marks at the same place are stacked; in the right half they go left.
        let stacked = marks[..i].iter().filter(|o| (o.at - m.at).norm() < 1e-9 * (1.0 + m.at.norm())).count();
        let right = 2.0 * m.at.x > window.0.x + window.1.x;
        let low = 2.0 * m.at.y < window.0.y + window.1.y;
        let dx = if right { -14 - 12 * m.label.chars().count() as i32 } else { 12 };
        let dy = if low { 10 + 24 * stacked as i32 } else { -30 - 24 * stacked as i32 };
        let tag =
            EmptyElement::at(at) + Text::new(m.label.clone(), (dx, dy), (super::FONT, LABEL).into_font());
        chart.draw_series(std::iter::once(tag)).map_err(err)?;
    }
    Ok(())
}

impl Figure for ConeFigure {
    fn size(&self) -> (u32, u32) {
        let rows = window::grid(self.panels.len()).1 as u32;
        (1250, if rows > 1 { 460 * rows + 60 } else { 820 })
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        root.fill(&WHITE).map_err(err)?;
        let root = root.titled(&self.title, (super::FONT, TITLE - 4)).map_err(err)?;
        let (left, right) = root.split_horizontally(840);
        if self.panels.len() == 1 {
            draw_panel(&left, &self.panels[0], &self.axes, ("", LABEL))?;
        } else {
            let (cols, rows) = window::grid(self.panels.len());
            for (area, panel) in left.split_evenly((rows, cols)).iter().zip(&self.panels) {
                draw_panel(area, panel, &self.axes, (&panel.title, LABEL - 2))?;
            }
        }
        legend(&right.margin(70, 10, 0, 10), &self.entries())
    }
}
