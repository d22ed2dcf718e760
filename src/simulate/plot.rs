//! The SVG plot of a trajectory: every contact's height against time.
//!
//! Heights are shown relative to the height of the centre of mass (h_k / h_c, scale-free, so
//! geometric shrinking does not flatten the picture). With an accumulation point (CC, PCC) the
//! time axis is -log10 of the time left to it, so each impact gets room however short its
//! interval; otherwise it is plain time since the start.

use super::classify::{Record, Run};
use super::record::log2_remaining;
use super::snapshot::Snapshot;
use super::system::FloatSystem;
use plotters::coord::Shift;
use plotters::prelude::*;

/// At most this many impacts are drawn (the first ones).
pub const MAX_PLOTTED_IMPACTS: usize = 4000;
/// Samples per interval between impacts.
const SAMPLES: usize = 6;

const COLOURS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
];

/// h_k / h_c along the segment q + s p, s = frac · τ (τ the normalised interval).
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

fn log2_add(a: f64, b: f64) -> f64 {
    let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
    hi + (lo - hi).exp2().ln_1p() / std::f64::consts::LN_2
}

/// The curves to draw: every contact's relative height along the segments between impacts, and a
/// mark per impact, against -log10 of the time left (`log_axis`) or the time since the drop.
struct Traces {
    log_axis: bool,
    lines: Vec<Vec<(f64, f64)>>,
    marks: Vec<(f64, usize)>,
}

impl Traces {
    /// Samples the first [`MAX_PLOTTED_IMPACTS`] segments of `run`: segment i goes from state i
    /// (0 = start) to impact i + 1.
    fn new(run: &Run, fs: &FloatSystem) -> Traces {
        let m = run.records.len().min(MAX_PLOTTED_IMPACTS);
        let rem = log2_remaining(run);
        let log_axis = run.tail_log2.is_some() && m > 0;
        let mut tr = Traces { log_axis, lines: vec![Vec::new(); fs.n], marks: Vec::new() };
        for (i, rec) in run.records.iter().enumerate().take(m) {
            let st = if i == 0 { &run.initial } else { &run.records[i - 1].state };
            let t0 = if i == 0 { 0.0 } else { run.records[i - 1].time };
            let tau = (rec.log2_dt + (st.p_exp - st.q_exp) as f64).exp2();
            for j in 0..=SAMPLES {
                let frac = j as f64 / SAMPLES as f64;
                let x = tr.sample_x(rec, rem[i], t0, j);
                if !x.is_finite() {
                    continue;
                }
                for (k, h) in relative_heights(fs, st, tau, frac).into_iter().enumerate() {
                    tr.lines[k].push((x, h));
                }
            }
            let x = if log_axis { tr.x_of(rem[i].expect("remaining"), 0.0) } else { rec.time };
            tr.marks.push((x, rec.contact));
        }
        tr
    }

    /// The x coordinate: -log10 of the time left on the log axis, else the time since the drop.
    fn x_of(&self, log2_left: f64, time: f64) -> f64 {
        if self.log_axis { -log2_left * std::f64::consts::LOG10_2 } else { time }
    }

    /// x of sample j (of [`SAMPLES`]) of the segment ending at `rec`, which starts at time `t0`
    /// with log2 `after` of the time left at its end.
    fn sample_x(&self, rec: &Record, after: Option<f64>, t0: f64, j: usize) -> f64 {
        let frac = j as f64 / SAMPLES as f64;
        if self.log_axis {
            let after = after.expect("log axis has remaining times");
            let left = if j == SAMPLES { after } else { log2_add(after, (1.0 - frac).log2() + rec.log2_dt) };
            self.x_of(left, 0.0)
        } else {
            self.x_of(0.0, t0 + frac * (rec.time - t0))
        }
    }

    /// The plotted ranges (x0, x1) and y1 (heights from 0), never empty.
    fn ranges(&self) -> (f64, f64, f64) {
        let pts = || self.lines.iter().flatten();
        let (mut x0, mut x1) =
            pts().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.0), b.max(p.0)));
        if !(x0.is_finite() && x1.is_finite()) {
            (x0, x1) = (0.0, 1.0);
        }
        if x1 - x0 < 1e-12 {
            x1 = x0 + 1.0;
        }
        let y1 = pts().fold(1.0f64, |a, p| a.max(p.1)) * 1.05;
        (x0, x1, y1)
    }
}

/// Renders the plot of `run` (which must carry records) as an SVG document.
pub fn svg(run: &Run, fs: &FloatSystem, title: &str) -> Result<String, String> {
    let traces = Traces::new(run, fs);
    let mut out = String::new();
    draw(SVGBackend::with_string(&mut out, (1000, 600)).into_drawing_area(), title, traces)?;
    Ok(out)
}

/// Draws the traces with axes, labels and a legend.
fn draw(root: DrawingArea<SVGBackend<'_>, Shift>, title: &str, traces: Traces) -> Result<(), String> {
    let (x0, x1, y1) = traces.ranges();
    let x_label =
        if traces.log_axis { "-log10(time left to the accumulation point)" } else { "time since the drop" };
    let err = |e: &dyn std::fmt::Display| format!("plot: {e}");
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 20))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(x0..x1, 0.0..y1)
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc("contact height / centre height")
        .draw()
        .map_err(|e| err(&e))?;
    for (k, pts) in traces.lines.into_iter().enumerate() {
        let colour = COLOURS[k % COLOURS.len()];
        chart
            .draw_series(LineSeries::new(pts, colour.stroke_width(1)))
            .map_err(|e| err(&e))?
            .label(format!("contact {k}"))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
    }
    let marks =
        traces.marks.iter().map(|&(x, k)| Circle::new((x, 0.0), 3, COLOURS[k % COLOURS.len()].filled()));
    chart.draw_series(marks).map_err(|e| err(&e))?;
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))
}
