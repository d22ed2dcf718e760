//! The figure of a certified cover (`chatter plot cover DIR`): the boxes of `chatter cover` over
//! (κ, γ), filled by how each ended (certified, by claim; refuted at its corners; undecided), with
//! the exact CC criterion's boundary on top.

use super::map::{CC, CC_OR_PCC, COMPLETE, body_name, draw_lines};
use super::{Entry, Figure, LABEL, Sample, TICKS, TITLE, err, legend};
use crate::exact::{Q, QExt};
use crate::sweep::curves::{Curves, Polyline};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// Fill colours of refuted and undecided boxes.
pub const REFUTED: RGBColor = RGBColor(120, 120, 120);
pub const UNDECIDED: RGBColor = RGBColor(250, 215, 120);

/// One row of boxes.csv.
#[derive(Clone, Debug)]
pub struct CoverBox {
    pub kappa: [f64; 2],
    pub gamma: [f64; 2],
    pub status: String,
    pub claim: String,
}

/// A cover figure.
pub struct CoverFigure {
    pub n: u64,
    pub kappa: [Q; 2],
    pub gamma: [Q; 2],
    pub boxes: Vec<CoverBox>,
    pub curves: Curves,
    pub title: String,
}

/// Reads DIR/boxes.csv (as `chatter cover` writes it).
pub fn read_boxes(dir: &Path) -> Result<Vec<CoverBox>, String> {
    let path = dir.join("boxes.csv");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let number = |s: &str, line: usize| -> Result<f64, String> {
        s.parse::<Q>().map(|q| q.to_f64()).map_err(|e| format!("{}:{line}: {s:?}: {e}", path.display()))
    };
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        if f.len() != 9 {
            return Err(format!("{}:{}: expected 9 fields, found {}", path.display(), i + 1, f.len()));
        }
        out.push(CoverBox {
            kappa: [number(f[1], i + 1)?, number(f[2], i + 1)?],
            gamma: [number(f[3], i + 1)?, number(f[4], i + 1)?],
            status: f[5].to_string(),
            claim: f[6].to_string(),
        });
    }
    Ok(out)
}

fn fill(b: &CoverBox) -> RGBColor {
    match (b.status.as_str(), b.claim.as_str()) {
        ("certified", "CompleteChatterFromAllDown") => COMPLETE,
        ("certified", _) => CC_OR_PCC,
        ("refuted", _) => REFUTED,
        _ => UNDECIDED,
    }
}

impl CoverFigure {
    fn kappa_f64(&self) -> [f64; 2] {
        [self.kappa[0].to_f64(), self.kappa[1].to_f64()]
    }

    fn gamma_f64(&self) -> [f64; 2] {
        [self.gamma[0].to_f64(), self.gamma[1].to_f64()]
    }

    fn legend_entries(&self) -> Vec<Entry> {
        let has =
            |s: &str, c: &str| self.boxes.iter().any(|b| b.status == s && (c.is_empty() || b.claim == c));
        let mut e = Vec::new();
        if has("certified", "CompleteChatterFromAllDown") {
            e.push(Entry::new(Sample::Fill(COMPLETE), "certified box: CompleteChatterFromAllDown"));
        }
        if has("certified", "CcOrPccFromAllDown") {
            e.push(Entry::new(Sample::Fill(CC_OR_PCC), "certified box: CcOrPccFromAllDown"));
        }
        if has("refuted", "") {
            e.push(Entry::new(Sample::Fill(REFUTED), "refuted at its four corners (exact refutations)"));
        }
        if has("undecided", "") {
            e.push(Entry::new(
                Sample::Fill(UNDECIDED),
                "undecided: neither certified nor refuted (a corner not refuted, or the finest size along the axis it would be split)",
            ));
        }
        if super::map::drawn(&inside(&self.curves.cc, self.kappa_f64(), self.gamma_f64())) {
            e.push(Entry::new(
                Sample::Dashed(CC, 3),
                "exact: CC criterion boundary (real positive dominant eigenvalue below)",
            ));
        }
        e
    }
}

impl Figure for CoverFigure {
    fn size(&self) -> (u32, u32) {
        (1250, 820)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        root.fill(&WHITE).map_err(err)?;
        let (left, right) = root.split_horizontally(840);
        let (k, g) = (self.kappa_f64(), self.gamma_f64());
        let mut chart = ChartBuilder::on(&left)
            .caption(&self.title, (super::FONT, TITLE))
            .margin(18)
            .x_label_area_size(62)
            .y_label_area_size(76)
            .build_cartesian_2d(k[0]..k[1], g[0]..g[1])
            .map_err(err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("κ")
            .y_desc("γ")
            .axis_desc_style((super::FONT, LABEL))
            .label_style((super::FONT, TICKS))
            .draw()
            .map_err(err)?;
        let rect = |b: &CoverBox| [(b.kappa[0], b.gamma[0]), (b.kappa[1], b.gamma[1])];
        chart
            .draw_series(self.boxes.iter().map(|b| Rectangle::new(rect(b), fill(b).filled())))
            .map_err(err)?;
        // Outlines only where a box is large enough on the page to show them.
        let (w, h) = left.dim_in_pixel();
        let big = |b: &CoverBox| {
            (b.kappa[1] - b.kappa[0]) / (k[1] - k[0]) * f64::from(w) > 6.0
                && (b.gamma[1] - b.gamma[0]) / (g[1] - g[0]) * f64::from(h) > 6.0
        };
        chart
            .draw_series(
                self.boxes.iter().filter(|b| big(b)).map(|b| Rectangle::new(rect(b), WHITE.stroke_width(1))),
            )
            .map_err(err)?;
        draw_lines(&mut chart, &inside(&self.curves.cc, k, g), CC, 3, true)?;
        legend(&right.margin(70, 10, 0, 10), &self.legend_entries())
    }
}

/// The pieces of the polylines inside [k0, k1] x [g0, g1] (the exact curves are computed along
/// rows from kappa = 0, which a cover's domain need not include).
pub(crate) fn inside(lines: &[Polyline], k: [f64; 2], g: [f64; 2]) -> Vec<Polyline> {
    let ok = |(x, y): &(f64, f64)| (k[0]..=k[1]).contains(x) && (g[0]..=g[1]).contains(y);
    let mut out = Vec::new();
    for l in lines {
        for piece in l.split(|p| !ok(p)) {
            if piece.len() >= 2 {
                out.push(piece.to_vec());
            }
        }
    }
    out
}

/// The figure's title, e.g. "n = 3 (triangle): certified cover, 99.51 % of the CC region".
pub fn title(n: u64, ratio: Option<f64>) -> String {
    match ratio {
        Some(r) if r.is_finite() => {
            format!("n = {n} ({}): certified boxes, {:.2} % of the CC region", body_name(n), 100.0 * r)
        }
        _ => format!("n = {n} ({}): certified boxes", body_name(n)),
    }
}
