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
        .x_label_formatter(&super::tick)
        .y_label_formatter(&super::tick)
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
    draw_marks(&mut chart, &panel.marks, panel)?;
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

/// Where a mark's label goes, in pixels from the mark (its top-left corner), when no place clear
/// of every outline is found: on the side of the certified set's centre; `stacked` labels of
/// marks at the same place go one line further.
pub fn label_offset(mark: P2, centre: P2, chars: usize, stacked: usize) -> (i32, i32) {
    let dx = if mark.x > centre.x { -18 - 12 * chars as i32 } else { 18 };
    let dy = if mark.y > centre.y { 22 + 26 * stacked as i32 } else { -48 - 26 * stacked as i32 };
    (dx, dy)
}

type Px = (f64, f64);

/// Whether the segment a-b meets the box (x0, y0, x1, y1) (pixels).
fn meets(a: Px, b: Px, (x0, y0, x1, y1): (f64, f64, f64, f64)) -> bool {
    let inside = |p: Px| p.0 >= x0 && p.0 <= x1 && p.1 >= y0 && p.1 <= y1;
    if inside(a) || inside(b) {
        return true;
    }
    let side = |p: Px, q: Px, r: Px| ((q.0 - p.0) * (r.1 - p.1) - (q.1 - p.1) * (r.0 - p.0)).signum();
    let cross = |c: Px, d: Px| side(a, b, c) * side(a, b, d) <= 0.0 && side(c, d, a) * side(c, d, b) <= 0.0;
    let corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)];
    (0..4).any(|i| cross(corners[i], corners[(i + 1) % 4]))
}

/// The first label box (top-left offset from the mark, pixels) of size `size` that meets no
/// segment of `outlines` and stays in `area`: rings of growing distance around the mark, each
/// starting in the direction `toward` (the set's centre) and turning by 45° either way.
fn clear_spot(mark: Px, toward: Px, size: Px, outlines: &[Vec<Px>], area: (Px, Px)) -> Option<(i32, i32)> {
    let base = (toward.1 - mark.1).atan2(toward.0 - mark.0);
    for r in [14.0, 30.0, 50.0, 75.0, 105.0, 140.0] {
        for k in [0.0, 1.0, -1.0, 2.0, -2.0, 3.0, -3.0, 4.0] {
            let (dx, dy) = (
                (base + k * std::f64::consts::FRAC_PI_4).cos(),
                (base + k * std::f64::consts::FRAC_PI_4).sin(),
            );
            let c =
                (mark.0 + dx * (r + size.0 / 2.0 * dx.abs()), mark.1 + dy * (r + size.1 / 2.0 * dy.abs()));
            let b = (c.0 - size.0 / 2.0, c.1 - size.1 / 2.0, c.0 + size.0 / 2.0, c.1 + size.1 / 2.0);
            let within = b.0 >= area.0.0 && b.1 >= area.0.1 && b.2 <= area.1.0 && b.3 <= area.1.1;
            let clear = outlines.iter().all(|o| (0..o.len()).all(|i| !meets(o[i], o[(i + 1) % o.len()], b)));
            if within && clear {
                return Some(((b.0 - mark.0).round() as i32, (b.1 - mark.1).round() as i32));
            }
        }
    }
    None
}

fn draw_marks<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    marks: &[Mark],
    panel: &Panel,
) -> Result<(), String> {
    let k = &panel.k;
    let centre =
        k.iter().fold(P2::new(0.0, 0.0), |s, p| P2::new(s.x + p.x, s.y + p.y)) / k.len().max(1) as f64;
    let (xr, yr) = chart.plotting_area().get_pixel_range();
    let area = ((f64::from(xr.start), f64::from(yr.start)), (f64::from(xr.end), f64::from(yr.end)));
    let (outlines, marks_px, centre_px) = {
        let px = |p: &P2| {
            let (x, y) = chart.backend_coord(&(p.x, p.y));
            (f64::from(x), f64::from(y))
        };
        let outlines: Vec<Vec<Px>> = std::iter::once(k)
            .chain(panel.images.iter().map(|r| &r.polygon))
            .map(|poly| poly.iter().map(px).collect())
            .collect();
        (outlines, marks.iter().map(|m| px(&m.at)).collect::<Vec<_>>(), px(&centre))
    };
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
        // Labels of marks at the same place are stacked; a label goes where its white box meets
        // no outline of K or of an image (over hatching only), else toward K's centre.
        let stacked = marks[..i].iter().filter(|o| (o.at - m.at).norm() < 1e-9 * (1.0 + m.at.norm())).count();
        let chars = m.label.chars().count();
        let size = (12.0 * chars as f64 + 6.0, 26.0 + 26.0 * stacked as f64);
        let spot = clear_spot(marks_px[i], centre_px, size, &outlines, area);
        let (bx, by) = spot.unwrap_or_else(|| label_offset(m.at, centre, chars, stacked));
        let (dx, dy) = (bx + 3, by + 2 + 26 * stacked as i32);
        let box_ = Rectangle::new([(dx - 3, dy - 2), (dx + 12 * chars as i32 + 3, dy + 24)], WHITE.filled());
        let tag = EmptyElement::at(at)
            + box_
            + Text::new(m.label.clone(), (dx, dy), (super::FONT, LABEL).into_font());
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
