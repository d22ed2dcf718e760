//! The certify target of issue 2, measured over the grid n in {3, 4}, kappa in {1/40, ..., 8/40},
//! gamma in {1/100, ..., 40/100}: of the points where the float finder reports success, at least
//! 99% must also get an exact certificate, and the median certify time per point must be at
//! most 50 ms. Points run one at a time so that the times are per point.
//!
//! `cargo bench --bench certify_grid` (add `-- all-down` for the I_0(D) seed).

use chatter::certify::{ClaimChoice, Request, certify};
use chatter::exact::Q;
use chatter::finder::Search;
use chatter_kernel::certificate::Claim;
use indicatif::ProgressBar;
use std::time::Instant;

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    if v.is_empty() { f64::NAN } else { v[v.len() / 2] }
}

fn main() {
    let all_down = std::env::args().any(|a| a == "all-down");
    let claim = if all_down { Claim::CcOrPccFromAllDown } else { Claim::EffectivelyInvariant };
    let mut points = Vec::new();
    for n in [3u64, 4] {
        for k in 1..=8 {
            for g in 1..=40 {
                points.push((n, Q::new(k, 40), Q::new(g, 100)));
            }
        }
    }
    let bar = ProgressBar::new(points.len() as u64);
    let (mut found, mut certified, mut no_cone, mut inconclusive) = (0, 0, 0, 0);
    let (mut all_ms, mut found_ms) = (Vec::new(), Vec::new());
    let mut failures = Vec::new();
    for (n, kappa, gamma) in &points {
        let mut req = Request::new(*n, kappa.clone(), gamma.clone());
        req.claim = ClaimChoice::Exactly(claim);
        let start = Instant::now();
        let report = certify(&req);
        let ms = start.elapsed().as_secs_f64() * 1e3;
        all_ms.push(ms);
        match &report.finder {
            Some(Search::Found { .. }) => {
                found += 1;
                found_ms.push(ms);
                match &report.result {
                    Ok(_) => certified += 1,
                    Err(e) => failures.push(format!("n={n} kappa={kappa} gamma={gamma}: {e}")),
                }
            }
            Some(Search::NoCone { .. }) => no_cone += 1,
            _ => inconclusive += 1,
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    for f in &failures {
        println!("not certified although the finder succeeded: {f}");
    }
    let max = all_ms.iter().copied().fold(0.0, f64::max);
    println!("claim {}: {} grid points", claim.name(), points.len());
    println!("finder: {found} found, {no_cone} no cone, {inconclusive} inconclusive");
    println!(
        "certified {certified} of {found} finder successes ({:.2}%; target >= 99%)",
        100.0 * certified as f64 / found.max(1) as f64
    );
    println!(
        "certify time per point: median {:.3} ms over all points, median {:.3} ms over finder successes (target <= 50 ms), max {:.1} ms",
        median(&mut all_ms),
        median(&mut found_ms),
        max
    );
}
