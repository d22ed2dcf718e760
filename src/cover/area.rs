//! The area of the exact CC region in a box of parameters: for each kappa, the measure of the
//! gammas where the exact CC criterion holds (between the exact thresholds of the spectral
//! module), integrated over kappa by the composite Simpson rule. The result is a float (the
//! thresholds are algebraic numbers, enclosed to 2^-40), with an error estimate from halving the
//! step.

use crate::exact::{Q, QExt};
use crate::spectral::criteria::{Family, cc_profile, rod_cc_profile};
use chatter_kernel::model::rational_cos;
use rayon::prelude::*;

/// The measure of { gamma in [g0, g1] : the CC criterion holds at (kappa, gamma) }.
pub fn cc_length(n: u64, kappa: &Q, g: [f64; 2]) -> f64 {
    let profile = if n == 2 {
        rod_cc_profile(kappa)
    } else {
        cc_profile(&Family { n, c1: rational_cos::<Q>(n).expect("n in 2, 3, 4, 6"), kappa: kappa.clone() })
    };
    // Sample i (the criterion's value) holds between threshold i-1 and threshold i, where the
    // thresholds are the roots at which the value changes; samples between roots that do not
    // change it are merged by the profile.
    let mut cuts: Vec<f64> = vec![0.0];
    for t in &profile.thresholds {
        let mut r = t.gamma.clone();
        while &r.hi - &r.lo > Q::new(1, 1 << 40) {
            r.bisect();
        }
        cuts.push(((&r.lo + &r.hi) / Q::int(2)).to_f64());
    }
    cuts.push(1.0);
    let mut holds = profile.near_zero;
    let mut length = 0.0;
    for w in cuts.windows(2) {
        if holds {
            length += (w[1].min(g[1]) - w[0].max(g[0])).max(0.0);
        }
        holds = !holds;
    }
    length
}

/// The area of the CC region in [k0, k1] x [g0, g1] by Simpson's rule on `intervals` (even)
/// steps in kappa, and the difference to the same rule on half as many (an error estimate).
pub fn cc_area(n: u64, kappa: &[Q; 2], gamma: &[Q; 2], intervals: usize) -> (f64, f64) {
    let m = intervals.max(2) & !1;
    let g = [gamma[0].to_f64(), gamma[1].to_f64()];
    let width = &kappa[1] - &kappa[0];
    let values: Vec<f64> = (0..=m)
        .into_par_iter()
        .map(|i| cc_length(n, &(&kappa[0] + &(&width * &Q::new(i as i64, m as i64))), g))
        .collect();
    let simpson = |step: usize| {
        let pts: Vec<f64> = values.iter().step_by(step).copied().collect();
        let k = pts.len() - 1;
        let h = width.to_f64() / k as f64;
        let inner: f64 =
            pts[1..k].iter().enumerate().map(|(i, v)| if i % 2 == 0 { 4.0 * v } else { 2.0 * v }).sum();
        h / 3.0 * (pts[0] + pts[k] + inner)
    };
    let fine = simpson(1);
    let coarse = if m >= 4 && (m / 2).is_multiple_of(2) { simpson(2) } else { fine };
    (fine, (fine - coarse).abs())
}
