//! The grid target of issue 10 §3: for each n = 5..12 on the grid kappa in {1/200, ..., 10/200},
//! gamma in {1/50, ..., 25/50}, `certify` (default budgets) at every point, beside the exact CC
//! criterion (decided in Q(cos 2 pi/n)). Prints per n: the points where the criterion holds, the
//! certificates there, the certificates where it fails (must be 0), and the median certify and
//! verify (kernel on both backends) times; then every point where the criterion holds and no
//! certificate was made.
//!
//! `cargo bench --bench field_grid` (add `-- quick` for every other kappa and every fifth gamma,
//! or `-- n=7` for one n).

use chatter::certify::{Request, certify};
use chatter::exact::{ParseLimits, Q};
use chatter::sweep::point::criteria;
use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify_on};
use rayon::prelude::*;
use std::time::Instant;

/// One grid point's outcome.
struct Point {
    kappa: Q,
    gamma: Q,
    cc: bool,
    certified: Option<String>,
    why: String,
    certify_ms: f64,
    verify_ms: Option<f64>,
}

fn run(n: u64, kappa: Q, gamma: Q) -> Point {
    let cc = criteria(n, &kappa, &gamma).0;
    let t = Instant::now();
    let report = certify(&Request::new(n, kappa.clone(), gamma.clone()));
    let certify_ms = t.elapsed().as_secs_f64() * 1e3;
    let (certified, why, verify_ms) = match &report.result {
        Ok(cert) => {
            let t = Instant::now();
            let v = verify_on(cert, ParseLimits::default(), &[MALACHITE, NUM]);
            let ms = t.elapsed().as_secs_f64() * 1e3;
            assert!(matches!(v, Verdict::Accepted(_)), "n = {n}: the kernel rejects its own certificate");
            (Some(cert.claim.name().to_string()), String::new(), Some(ms))
        }
        Err(e) => (None, e.to_string(), None),
    };
    Point { kappa, gamma, cc, certified, why, certify_ms, verify_ms }
}

fn median(mut xs: Vec<f64>) -> f64 {
    if xs.is_empty() {
        return f64::NAN;
    }
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let quick = args.iter().any(|a| a == "quick");
    let only: Option<u64> = args.iter().find_map(|a| a.strip_prefix("n=")).and_then(|s| s.parse().ok());
    let (kstep, gstep) = if quick { (2, 5) } else { (1, 1) };
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!("load average at start: {}", load.trim());
    println!(
        "n  points  cc-holds  certified-where-holds  certified-where-fails  median-certify-ms  median-verify-ms  wall-s"
    );
    let mut misses = Vec::new();
    for n in (5..=12).filter(|n| only.is_none_or(|o| o == *n)) {
        let grid: Vec<(Q, Q)> = (1..=10)
            .step_by(kstep)
            .flat_map(|k| (1..=25).step_by(gstep).map(move |g| (Q::new(k, 200), Q::new(g, 50))))
            .collect();
        let t = Instant::now();
        let pts: Vec<Point> = grid.into_par_iter().with_max_len(1).map(|(k, g)| run(n, k, g)).collect();
        let holds = pts.iter().filter(|p| p.cc).count();
        let good = pts.iter().filter(|p| p.cc && p.certified.is_some()).count();
        let bad = pts.iter().filter(|p| !p.cc && p.certified.is_some()).count();
        let cm = median(pts.iter().map(|p| p.certify_ms).collect());
        let cc_ms = median(pts.iter().filter(|p| p.certified.is_some()).map(|p| p.certify_ms).collect());
        let vm = median(pts.iter().filter_map(|p| p.verify_ms).collect());
        println!(
            "{n:<2} {:>6}  {holds:>8}  {good:>21}  {bad:>21}  {cm:>17.1} / {cc_ms:>9.1}  {vm:>16.1}  {:>6.1}",
            pts.len(),
            t.elapsed().as_secs_f64()
        );
        for p in pts.iter().filter(|p| p.cc != p.certified.is_some()) {
            misses.push(format!(
                "n = {n} kappa = {} gamma = {}: criterion {}, {}",
                p.kappa,
                p.gamma,
                if p.cc { "holds" } else { "fails" },
                p.certified.clone().unwrap_or_else(|| format!("not certified: {}", p.why))
            ));
        }
    }
    for m in &misses {
        println!("{m}");
    }
}
