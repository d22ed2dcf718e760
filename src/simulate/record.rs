//! Trajectories: the time left to the accumulation point after each impact, and the CSV file
//! (one row per impact).

use super::classify::Run;
use super::snapshot::LOG2_ZERO;
use super::system::Shape;
use std::fmt::Write;

/// log2(a + b) from log2 a and log2 b, without leaving `f64`'s range.
fn log2_add(a: f64, b: f64) -> f64 {
    let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
    if lo <= LOG2_ZERO { hi } else { hi + (lo - hi).exp2().ln_1p() / std::f64::consts::LN_2 }
}

/// For each record, log2 of the time from that impact to the accumulation point: the sum of the
/// later intervals plus the estimated tail, summed in log space so that times far below 1e-308
/// keep their relative accuracy. `None` without an accumulation point (ICC, ties, undecided).
pub fn log2_remaining(run: &Run) -> Vec<Option<f64>> {
    let Some(tail) = run.tail_log2 else { return vec![None; run.records.len()] };
    let mut out = vec![None; run.records.len()];
    let mut acc = tail;
    for i in (0..run.records.len()).rev() {
        out[i] = Some(acc);
        acc = log2_add(acc, run.records[i].log2_dt);
    }
    out
}

/// The CSV header for a shape.
pub fn csv_header(shape: Shape) -> String {
    let (qn, pn) = shape.coordinate_names();
    format!(
        "impact,contact,time,log2_dt,log2_time_to_accumulation,{},log2_q_scale,{},log2_p_scale,log2_energy",
        qn.join(","),
        pn.join(",")
    )
}

/// The trajectory as CSV: the header, then one row per impact with the post-impact state in our
/// coordinates as normalised mantissas and log2 scales (physical h0 = h0 · 2^log2_q_scale).
pub fn csv(run: &Run, shape: Shape) -> String {
    let dim = shape.dim();
    let rem = log2_remaining(run);
    let mut s = csv_header(shape);
    s.push('\n');
    let opt = |x: Option<f64>| x.map_or(String::new(), |v| format!("{v:.6}"));
    for (r, left) in run.records.iter().zip(rem) {
        let st = &r.state;
        let _ = write!(s, "{},{},{:.17e},{:.6},{}", r.impact, r.contact, r.time, r.log2_dt, opt(left));
        for x in &st.q[..dim] {
            let _ = write!(s, ",{x:.17e}");
        }
        let _ = write!(s, ",{}", st.q_exp);
        for x in &st.p[..dim] {
            let _ = write!(s, ",{x:.17e}");
        }
        let _ = writeln!(s, ",{},{:.6}", st.p_exp, st.energy.log2());
    }
    s
}
