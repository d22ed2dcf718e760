//! The largest gamma that certifies, by bisection on exact dyadic rationals (issue 13 §4):
//! `chatter certify ... --largest-gamma`. Each step runs the whole pipeline (search, exactifier,
//! kernel on both backends) at the midpoint. The answer is a pair of exact rationals
//! lo < hi, lo certified and hi not; that every gamma below lo certifies is *not* claimed
//! (certifiability need not be monotone in gamma), only that these two pipeline runs came out so.

use crate::exact::{Q, Ring};
use chatter_kernel::certificate::Claim;
use chatter_kernel::exact::OrderedField;
use std::time::{Duration, Instant};

/// The default search interval [2^-12, 1 - 2^-12] (the claims about drops need 0 < gamma < 1).
pub fn default_interval() -> (Q, Q) {
    let eps = Q::new(1, 4096);
    (eps.clone(), Q::int(1).minus(&eps))
}

/// The outcome of a bisection.
#[derive(Clone, Debug)]
pub struct Bisection {
    /// The largest gamma tried that certified, with its claim (`None`: not even the lower end).
    pub certified: Option<(Q, Claim)>,
    /// The smallest gamma above it tried that did not certify, with the reason (`None`: the
    /// upper end certified).
    pub failed: Option<(Q, String)>,
    /// The wall-clock time of every pipeline run, in order.
    pub times: Vec<Duration>,
}

impl Bisection {
    /// The median time of one pipeline run.
    pub fn median_time(&self) -> Duration {
        let mut t = self.times.clone();
        t.sort();
        t.get(t.len() / 2).copied().unwrap_or_default()
    }
}

/// Bisects [lo, hi] `steps` times for the largest gamma at which `certifies` succeeds (it returns
/// the claim certified, or why not). `tick` is called after each run (a progress bar).
pub fn largest_certified_gamma(
    mut certifies: impl FnMut(&Q) -> Result<Claim, String>,
    (lo, hi): (Q, Q),
    steps: usize,
    tick: &dyn Fn(),
) -> Bisection {
    let mut times = Vec::new();
    let mut run = |g: &Q| {
        let start = Instant::now();
        let r = certifies(g);
        times.push(start.elapsed());
        tick();
        r
    };
    let mut good = match run(&lo) {
        Ok(claim) => (lo, claim),
        Err(why) => return Bisection { certified: None, failed: Some((lo, why)), times },
    };
    let mut bad = match run(&hi) {
        Ok(claim) => return Bisection { certified: Some((hi, claim)), failed: None, times },
        Err(why) => (hi, why),
    };
    for _ in 0..steps {
        let mid = good.0.plus(&bad.0).over(&Q::int(2)).expect("2 != 0");
        match run(&mid) {
            Ok(claim) => good = (mid, claim),
            Err(why) => bad = (mid, why),
        }
    }
    Bisection { certified: Some(good), failed: Some(bad), times }
}
