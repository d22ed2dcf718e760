//! The SVG plot of a trajectory: every contact's height against time.
//!
//! Heights are shown relative to the height of the centre of mass (h_k / h_c, scale-free, so
//! geometric shrinking does not flatten the picture). With an accumulation point (CC, PCC) the
//! time axis is -log10 of the time left to it, so each impact gets room however short its
//! interval; otherwise it is plain time since the start.

use super::classify::Run;
use super::engine::Snapshot;
use super::record::log2_remaining;
use super::system::FloatSystem;
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

/// Renders the plot of `run` (which must carry records) as an SVG document.
pub fn svg(run: &Run, fs: &FloatSystem, title: &str) -> Result<String, String> {
    let m = run.records.len().min(MAX_PLOTTED_IMPACTS);
    let rem = log2_remaining(run);
    let log_axis = run.tail_log2.is_some() && m > 0;
    // Segment i goes from state i (0 = start) to impact i + 1.
    let mut lines: Vec<Vec<(f64, f64)>> = vec![Vec::new(); fs.n];
    let mut marks: Vec<(f64, usize)> = Vec::new();
    let x_of =
        |log2_left: f64, time: f64| if log_axis { -log2_left * std::f64::consts::LOG10_2 } else { time };
    for (i, rec) in run.records.iter().enumerate().take(m) {
        let st = if i == 0 { &run.initial } else { &run.records[i - 1].state };
        let t0 = if i == 0 { 0.0 } else { run.records[i - 1].time };
        let tau = (rec.log2_dt + (st.p_exp - st.q_exp) as f64).exp2();
        for j in 0..=SAMPLES {
            let frac = j as f64 / SAMPLES as f64;
            let x = if log_axis {
                let after = rem[i].expect("log axis has remaining times");
                let left =
                    if j == SAMPLES { after } else { log2_add(after, (1.0 - frac).log2() + rec.log2_dt) };
                x_of(left, 0.0)
            } else {
                x_of(0.0, t0 + frac * (rec.time - t0))
            };
            if !x.is_finite() {
                continue;
            }
            for (k, h) in relative_heights(fs, st, tau, frac).into_iter().enumerate() {
                lines[k].push((x, h));
            }
        }
        let x = if log_axis { x_of(rem[i].expect("remaining"), 0.0) } else { rec.time };
        marks.push((x, rec.contact));
    }
    let pts = || lines.iter().flatten();
    let (mut x0, mut x1) =
        pts().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.0), b.max(p.0)));
    if !(x0.is_finite() && x1.is_finite()) {
        (x0, x1) = (0.0, 1.0);
    }
    if x1 - x0 < 1e-12 {
        x1 = x0 + 1.0;
    }
    let y1 = pts().fold(1.0f64, |a, p| a.max(p.1)) * 1.05;
    let x_label =
        if log_axis { "-log10(time left to the accumulation point)" } else { "time since the drop" };

    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, (1000, 600)).into_drawing_area();
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
        for (k, pts) in lines.into_iter().enumerate() {
            let colour = COLOURS[k % COLOURS.len()];
            chart
                .draw_series(LineSeries::new(pts, colour.stroke_width(1)))
                .map_err(|e| err(&e))?
                .label(format!("contact {k}"))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
        }
        chart
            .draw_series(
                marks.iter().map(|&(x, k)| Circle::new((x, 0.0), 3, COLOURS[k % COLOURS.len()].filled())),
            )
            .map_err(|e| err(&e))?;
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))?;
    }
    Ok(out)
}
