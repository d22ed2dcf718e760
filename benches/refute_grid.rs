//! The refutation target of issue 11: on the grid kappa in {1/50, ..., 50/50} x gamma in
//! {1/200, ..., 60/200}, for n = 3, 4, 6, an exact refutation (checked by the kernel on both
//! backends) at >= 99% of the points where the exact CC criterion fails, and none where it holds.
//! Prints the success rate, the failures and the median time per point.
//!
//! `cargo bench --bench refute_grid` (add `-- quick` for every fifth kappa).

use chatter::exact::Q;
use chatter::refute::{RefuteConfig, refute};
use chatter::spectral::criteria::cc_criterion;
use chatter_kernel::certificate::Claim;
use chatter_kernel::model::Polygon;
use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify_refutation};
use rayon::prelude::*;
use std::time::Instant;

fn main() {
    let quick = std::env::args().any(|a| a == "quick");
    let step = if quick { 5 } else { 1 };
    for n in [3u64, 4, 6] {
        let points: Vec<(Q, Q, bool)> = (1..=50)
            .step_by(step)
            .flat_map(|k| (1..=60).map(move |g| (Q::new(k, 50), Q::new(g, 200))))
            .map(|(k, g)| {
                let holds = cc_criterion(&Polygon::new(n, k.clone(), g.clone()).unwrap()).0;
                (k, g, holds)
            })
            .collect();
        let start = Instant::now();
        let results: Vec<(bool, bool, f64, String)> = points
            .par_iter()
            .map(|(k, g, holds)| {
                let t = Instant::now();
                let r = refute(n, k, g, Claim::EffectivelyInvariant, &RefuteConfig::default())
                    .or_else(|_| refute(n, k, g, Claim::CcOrPccFromAllDown, &RefuteConfig::default()));
                let ok = match &r {
                    Ok(r) => matches!(
                        verify_refutation(r, Default::default(), &[MALACHITE, NUM]),
                        Verdict::Accepted(_)
                    ),
                    Err(_) => false,
                };
                let why = r.err().map_or(String::new(), |e| format!("kappa={k} gamma={g}: {e}"));
                (*holds, ok, t.elapsed().as_secs_f64() * 1e3, why)
            })
            .collect();
        let fails: Vec<_> = results.iter().filter(|r| !r.0).collect();
        let refuted = fails.iter().filter(|r| r.1).count();
        let wrong = results.iter().filter(|r| r.0 && r.1).count();
        let mut ms: Vec<f64> = fails.iter().map(|r| r.2).collect();
        ms.sort_by(f64::total_cmp);
        println!(
            "n = {n}: {} points, CC criterion fails at {}, refuted {} ({:.2}%), refuted where the criterion holds: {wrong}; median {:.1} ms, max {:.1} ms per point; wall {:.1} s",
            results.len(),
            fails.len(),
            refuted,
            100.0 * refuted as f64 / fails.len().max(1) as f64,
            ms.get(ms.len() / 2).copied().unwrap_or(f64::NAN),
            ms.last().copied().unwrap_or(f64::NAN),
            start.elapsed().as_secs_f64()
        );
        for r in fails.iter().filter(|r| !r.1).take(12) {
            println!("  not refuted: {}", r.3);
        }
    }
}
