//! The map target of issue 12: n = 3, a 100 x 100 grid over rho in (0, 1), gamma in (0, 1) with
//! --certify, at most 60 s wall on 2 cores; points per second; and the wall-time ratio of one
//! thread to two (at least 1.8). Each configuration runs `repeats` times (default 2) and the best
//! wall time counts (the machine is shared).
//!
//! `cargo bench --bench map` (add `-- STEPS REPEATS` for another grid size or repeat count).

use chatter::exact::Q;
use chatter::sweep::grid::{Axis, Grid, Shard, Variable};
use chatter::sweep::point::Tasks;
use chatter::sweep::{Request, run};
use std::time::Instant;

fn best_wall(req: &Request, threads: usize, repeats: usize) -> f64 {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("thread pool");
    (0..repeats)
        .map(|_| {
            let start = Instant::now();
            let done = pool.install(|| run(req, &|| {}));
            assert_eq!(done.len(), req.grid.len());
            start.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with('-')).collect();
    let steps: u32 = args.first().and_then(|s| s.parse().ok()).unwrap_or(100);
    let repeats: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(2);
    let axis = Axis { lo: Q::int(0), hi: Q::int(1), steps };
    let grid = Grid { n: 3, variable: Variable::Rho, x: axis.clone(), gamma: axis, family: None };
    let req = Request {
        grid,
        tasks: Tasks { certify: true, refute: false, simulate: None, proof_budget: 0 },
        shard: Shard::ALL,
    };
    let points = req.grid.len() as f64;
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "map n = 3, {steps} x {steps} grid, --certify; best of {repeats}; load average before: {}",
        load.trim()
    );
    let two = best_wall(&req, 2, repeats);
    let one = best_wall(&req, 1, repeats);
    let ratio = one / two;
    println!(
        "  --jobs 2: {two:.2} s wall, {:.0} points/s (target <= 60 s: {})",
        points / two,
        if two <= 60.0 { "met" } else { "MISSED" }
    );
    println!("  --jobs 1: {one:.2} s wall, {:.0} points/s", points / one);
    println!(
        "  ratio jobs 1 / jobs 2: {ratio:.2} (target >= 1.8: {})",
        if ratio >= 1.8 { "met" } else { "MISSED" }
    );
}
