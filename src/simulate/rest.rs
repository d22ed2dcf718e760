//! A rod drop's accumulation time against the bound of docs/time-to-rest.md §2: evidence only
//! (the time is measured on an untrusted simulation; the bound B is the one rule T1 checks).

use super::{Initial, Model, Run, Shape};
use crate::certify::rest::rod_bound;
use crate::exact::Q;

/// A measured drop: the bound B and T|v|/h, with T the time from the first impact to the
/// accumulation point and h, v the centre's height and velocity just before the first impact.
#[derive(Clone, Debug)]
pub struct Measured {
    pub bound: Q,
    pub ratio: f64,
}

/// The measurement of a rod drop with both ends moving down whose run estimated an accumulation
/// time; `None` for other bodies, other starts, or outside the theorem's hypotheses.
pub fn measure(model: &Model, initial: &Initial, run: &Run) -> Option<Measured> {
    if !matches!(model.shape(), Shape::Rod) {
        return None;
    }
    let bound = rod_bound(&model.kappa, &model.gamma)?;
    let accumulation = run.accumulation?;
    let s = model.float_start(initial);
    let (q, p) = (s.q, s.p);
    if p[0] > 0.0 || p[1] > 0.0 {
        return None;
    }
    let landing = |h: f64, u: f64| if u < 0.0 { h / -u } else { f64::INFINITY };
    let t1 = landing(q[0], p[0]).min(landing(q[1], p[1]));
    let v = (p[0] + p[1]) / 2.0;
    // The centre is the mean of the two ends (docs/model.md §7).
    let h = (q[0] + q[1]) / 2.0 + v * t1;
    (t1.is_finite() && h > 0.0).then(|| Measured { bound, ratio: (accumulation - t1) * -v / h })
}
