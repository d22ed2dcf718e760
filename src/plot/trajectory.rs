//! A simulated drop for a journal reader (the paper's section "Comparison with direct
//! simulation"): (a) the contact heights relative to the centre's, h_k / h_c, over the last impacts, where
//! self-similar chatter repeats the same picture at every impact; (b) log10 of the centre's
//! height at each impact and of the time between impacts against the impact number, where
//! geometric convergence (complete chatter) is a straight descending line.

use super::map::sub;
use super::{Entry, Figure, LABEL, Sample, TICKS, TITLE, err, legend};
use crate::simulate::classify::Run;
use crate::simulate::snapshot::Snapshot;
use crate::simulate::system::FloatSystem;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Impacts shown in panel (a) (the last ones).
pub const WINDOW: usize = 24;
/// Samples per interval between impacts in panel (a).
const SAMPLES: usize = 12;

/// Contact colours (colour-blind safe order of the Tableau palette).
pub const COLOURS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
];

/// The drawing of one simulated drop.
pub struct TrajectoryFigure {
    pub title: String,
    pub n: usize,
    /// Panel (a): per contact, (impact number + fraction of the interval, h_k / h_c).
    pub heights: Vec<Vec<(f64, f64)>>,
    /// Panel (a): impacts in the window, (impact number, contact).
    pub marks: Vec<(f64, usize)>,
    /// Panel (b): (impact number, log10 h_c after the impact, contact).
    pub centre: Vec<(f64, f64, usize)>,
    /// Panel (b): (impact number, log10 of the interval before it).
    pub intervals: Vec<(f64, f64)>,
    /// The impact numbers shown in panel (a).
    pub window: (f64, f64),
}

/// h_k / h_c along the segment q + s p, s = frac · tau (tau the normalised interval).
fn relative_heights(fs: &FloatSystem, st: &Snapshot, tau: f64, frac: f64) -> Vec<f64> {
    let s = frac * tau;
    let q: [f64; 3] = std::array::from_fn(|i| st.q[i] + s * st.p[i]);
    let hc = fs.centre.iter().zip(&q).map(|(c, x)| c * x).sum::<f64>();
    (0..fs.n)
        .map(|k| {
            let h = fs.f[k].iter().zip(&q).map(|(c, x)| c * x).sum::<f64>();
            if hc > 0.0 { (h / hc).max(0.0) } else { 0.0 }
        })
        .collect()
}

/// log10 of the centre's height in a snapshot (scale carried as a power of two).
fn log10_centre(fs: &FloatSystem, st: &Snapshot) -> Option<f64> {
    let hc = fs.centre.iter().zip(&st.q).map(|(c, x)| c * x).sum::<f64>();
    (hc > 0.0).then(|| (hc.log2() + st.q_exp as f64) * std::f64::consts::LOG10_2)
}

impl TrajectoryFigure {
    /// The figure of a run recorded with `Options::record`.
    pub fn new(run: &Run, fs: &FloatSystem, title: String) -> TrajectoryFigure {
        let m = run.records.len();
        let first = m.saturating_sub(WINDOW);
        let mut fig = TrajectoryFigure {
            title,
            n: fs.n,
            heights: vec![Vec::new(); fs.n],
            marks: Vec::new(),
            centre: Vec::new(),
            intervals: Vec::new(),
            window: (first as f64, m.max(1) as f64),
        };
        for (i, rec) in run.records.iter().enumerate() {
            let st = if i == 0 { &run.initial } else { &run.records[i - 1].state };
            let x = (i + 1) as f64;
            fig.intervals.push((x, rec.log2_dt * std::f64::consts::LOG10_2));
            if let Some(h) = log10_centre(fs, &rec.state) {
                fig.centre.push((x, h, rec.contact));
            }
            if i < first {
                continue;
            }
            let tau = (rec.log2_dt + (st.p_exp - st.q_exp) as f64).exp2();
            for j in 0..=SAMPLES {
                let frac = j as f64 / SAMPLES as f64;
                for (k, h) in relative_heights(fs, st, tau, frac).into_iter().enumerate() {
                    fig.heights[k].push((i as f64 + frac, h));
                }
            }
            fig.marks.push((x, rec.contact));
        }
        fig
    }

    fn entries(&self) -> Vec<Entry> {
        let mut e: Vec<Entry> = (0..self.n)
            .map(|k| {
                Entry::new(
                    Sample::Line(COLOURS[k % COLOURS.len()], 3),
                    format!("contact {k}: height h{}", sub(k as u64)),
                )
            })
            .collect();
        e.push(Entry::new(Sample::Dot(BLACK), "(a) an impact, coloured by contact"));
        e.push(Entry::new(
            Sample::Dot(RGBColor(90, 90, 90)),
            "(b) log₁₀ of the centre's height after each impact, coloured by the contact that hit",
        ));
        e.push(Entry::new(Sample::Line(BLACK, 2), "(b) log₁₀ Δt, the time since the previous impact"));
        e.push(Entry::new(
            Sample::Fill(RGBColor(235, 235, 235)),
            "(b) the impacts shown in (a); straight descending lines: geometric convergence, complete chatter",
        ));
        e
    }
}

fn bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = ((hi - lo) * 0.06).max(0.5);
    (lo - pad, hi + pad)
}

impl Figure for TrajectoryFigure {
    fn size(&self) -> (u32, u32) {
        (1250, 900)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), String> {
        root.fill(&WHITE).map_err(err)?;
        let (left, right) = root.split_horizontally(860);
        let left = left.titled(&self.title, (super::FONT, TITLE - 2)).map_err(err)?;
        let (top, bottom) = left.split_vertically(420);
        let (w0, w1) = self.window;
        let ymax = self.heights.iter().flatten().fold(1.0f64, |a, p| a.max(p.1)) * 1.05;
        let mut a = ChartBuilder::on(&top)
            .caption(
                format!(
                    "(a) heights relative to the centre's, impacts {} to {}",
                    w0 as usize + 1,
                    w1 as usize
                ),
                (super::FONT, LABEL - 2),
            )
            .margin(12)
            .x_label_area_size(48)
            .y_label_area_size(70)
            .build_cartesian_2d(w0..w1.max(w0 + 1.0), 0.0..ymax)
            .map_err(err)?;
        a.configure_mesh()
            .light_line_style(RGBColor(238, 238, 238))
            .x_desc("impact number")
            .y_desc("hₖ / centre height")
            .x_label_formatter(&|x| format!("{x:.0}"))
            .axis_desc_style((super::FONT, LABEL - 2))
            .label_style((super::FONT, TICKS))
            .draw()
            .map_err(err)?;
        for (k, pts) in self.heights.iter().enumerate() {
            a.draw_series(LineSeries::new(pts.clone(), COLOURS[k % COLOURS.len()].stroke_width(2)))
                .map_err(err)?;
        }
        a.draw_series(
            self.marks.iter().map(|&(x, k)| Circle::new((x, 0.0), 5, COLOURS[k % COLOURS.len()].filled())),
        )
        .map_err(err)?;
        let last = self.intervals.len().max(1) as f64;
        let (y0, y1) = bounds(self.centre.iter().map(|p| p.1).chain(self.intervals.iter().map(|p| p.1)));
        let mut b = ChartBuilder::on(&bottom)
            .caption(
                "(b) scales: log₁₀ of the centre's height and of the time between impacts",
                (super::FONT, LABEL - 2),
            )
            .margin(12)
            .x_label_area_size(48)
            .y_label_area_size(70)
            .build_cartesian_2d(0.0..last + 1.0, y0..y1)
            .map_err(err)?;
        b.configure_mesh()
            .light_line_style(RGBColor(238, 238, 238))
            .x_desc("impact number")
            .y_desc("log₁₀")
            .x_label_formatter(&|x| format!("{x:.0}"))
            .y_label_formatter(&|y| format!("{y:.0}"))
            .axis_desc_style((super::FONT, LABEL - 2))
            .label_style((super::FONT, TICKS))
            .draw()
            .map_err(err)?;
        b.draw_series(std::iter::once(Rectangle::new(
            [(w0 + 0.5, y0), (w1 + 0.5, y1)],
            RGBColor(235, 235, 235).filled(),
        )))
        .map_err(err)?;
        b.draw_series(LineSeries::new(self.intervals.clone(), BLACK.stroke_width(2))).map_err(err)?;
        b.draw_series(
            self.centre.iter().map(|&(x, y, k)| Circle::new((x, y), 3, COLOURS[k % COLOURS.len()].filled())),
        )
        .map_err(err)?;
        legend(&right.margin(70, 10, 0, 10), &self.entries())
    }
}
