//! The near-threshold target of issue 11 §4: at kappa in {1/10, 1/6, 1/4} (n = 3),
//! {1/10, 1/6, 1/5} (n = 4) and {1/50, 1/20} (n = 6), point certificates at relative distance
//! d = 1e-3, ..., 1e-7 below the exact threshold gamma* (the supremum of the CC region at kappa,
//! an algebraic number enclosed to 2^-100 by the spectral module). Prints, per point, whether
//! `certify` succeeded, the claim, the generator count, the largest number of digits in a
//! generator, and the time; then the smallest distance certified per kappa.
//!
//! `cargo bench --bench near_threshold` (add `-- quick` for d = 1e-4 and 1e-6 only).

use chatter::certify::{Request, certify};
use chatter::exact::{Q, QExt};
use chatter::spectral::criteria::{Family, cc_profile};
use chatter_kernel::model::rational_cos;
use std::time::Instant;

/// gamma* (a rational lower bound within 2^-100 of it).
fn threshold(n: u64, kappa: &Q) -> Option<Q> {
    let fam = Family { n, c1: rational_cos::<Q>(n).expect("n in 3, 4, 6"), kappa: kappa.clone() };
    cc_profile(&fam).sup_lower_bound(100)
}

/// A short dyadic rational at most gamma* (1 - d), within gamma* d / 1000 of it.
fn below(star: &Q, d: f64) -> Q {
    let d = Q::from_f64_exact(d).expect("finite");
    let target = star * &(Q::int(1) - &d);
    let tol = star * &d / Q::int(1000);
    (0..).map(|bits| target.floor_dyadic(bits)).find(|g| &target - g <= tol).expect("dyadic floors converge")
}

fn main() {
    let quick = std::env::args().any(|a| a == "quick");
    let ds: &[f64] = if quick { &[1e-4, 1e-6] } else { &[1e-3, 1e-4, 1e-5, 1e-6, 1e-7] };
    let cases: [(u64, &[(i64, i64)]); 3] =
        [(3, &[(1, 10), (1, 6), (1, 4)]), (4, &[(1, 10), (1, 6), (1, 5)]), (6, &[(1, 50), (1, 20)])];
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!("load average at start: {}", load.trim());
    for (n, kappas) in cases {
        for &(a, b) in kappas {
            let kappa = Q::new(a, b);
            let Some(star) = threshold(n, &kappa) else {
                println!("n = {n} kappa = {kappa}: no CC threshold in (0, 1)");
                continue;
            };
            let mut best = None;
            for &d in ds {
                let gamma = below(&star, d);
                let t = Instant::now();
                let report = certify(&Request::new(n, kappa.clone(), gamma.clone()));
                let secs = t.elapsed().as_secs_f64();
                let line = match &report.result {
                    Ok(c) => {
                        best = Some(d);
                        let digits =
                            c.cone.iter().flat_map(|g| g.0.iter()).map(String::len).max().unwrap_or(0);
                        format!(
                            "OK {} ({} generators, up to {digits} characters)",
                            c.claim.name(),
                            c.cone.len()
                        )
                    }
                    Err(e) => format!("FAILED: {e}"),
                };
                println!(
                    "n = {n} kappa = {kappa} gamma* = {:.12} d = {d:.0e}: {line}; {secs:.2} s",
                    star.to_f64()
                );
            }
            match best {
                Some(d) => println!("n = {n} kappa = {kappa}: certified down to d = {d:.0e}"),
                None => println!("n = {n} kappa = {kappa}: nothing certified"),
            }
        }
    }
}
