//! Issue 15 §3 (docs/orbit-certificates.md §7): the band above the CC threshold.
//!
//! ```text
//! cargo run --release --features research --example orbit_band -- band [DROPS]      # n = 3: kappa grid x ratios gamma/gamma*
//! cargo run --release --features research --example orbit_band -- edge [STEPS]      # n = 3: bisection of the producer's edge
//! cargo run --release --features research --example orbit_band -- cycle             # n = 3: thresholds of S_1^2 S_2^2
//! cargo run --release --features research --example orbit_band -- search N [DROPS]  # n = 4, 5, 6: drops just above gamma*
//! cargo run --release --features research --example orbit_band -- sweep N [DROPS] [BUDGET] [GAMMAS]  # issue 22 §2: the band search
//! cargo run --release --features research --example orbit_band -- pcc [N KAPPA G,G]  # default n = 4, kappa = 1/6: PCC orbit search
//! cargo run --release --features research --example orbit_band -- words N KAPPA R L  # patterns of length <= L whose
//!                                                              # period map passes the cycle criterion at r gamma*
//! ```
//!
//! Every orbit verdict is the trusted kernel's on both backends (malachite and num-rational);
//! the drops are `f64` random drops (seeds 1..=DROPS, 600 impacts); the criteria are exact.

use chatter::exact::{Q, QExt};
use chatter::orbit::band::{Drops, OrbitVerdict, cc_threshold, drops, edge, gamma_at, point, steps_text};
use chatter::orbit::{FloatMaps, eigenvalues, eigenvector, fixed_points, float_period};
use chatter::spectral::criteria::Family;
use chatter::spectral::cycle::{CANDIDATE, cycle_profile};
use chatter_kernel::model::Polygon;
use chatter_kernel::verify::{MALACHITE, NUM};

const KAPPAS: [(i64, i64); 9] = [(1, 20), (1, 10), (1, 8), (3, 20), (1, 5), (1, 4), (3, 10), (7, 20), (2, 5)];
const RATIOS: [f64; 10] = [1.005, 1.01, 1.02, 1.03, 1.05, 1.075, 1.1, 1.15, 1.2, 1.3];

fn arg(k: usize) -> Option<String> {
    std::env::args().nth(k)
}

fn main() {
    let mode = arg(1).unwrap_or_else(|| "band".into());
    match mode.as_str() {
        "band" => band(arg(2).and_then(|s| s.parse().ok()).unwrap_or(10)),
        "edge" => edges(arg(2).and_then(|s| s.parse().ok()).unwrap_or(10)),
        "cycle" => cycle(),
        "search" => search(
            arg(2).and_then(|s| s.parse().ok()).unwrap_or(4),
            arg(3).and_then(|s| s.parse().ok()).unwrap_or(20),
        ),
        "sweep" => sweep(
            arg(2).and_then(|s| s.parse().ok()).unwrap_or(5),
            arg(3).and_then(|s| s.parse().ok()).unwrap_or(300),
            arg(4).and_then(|s| s.parse().ok()).unwrap_or(3000),
            arg(5).and_then(|s| s.parse().ok()).unwrap_or(24),
        ),
        "pcc" => pcc(
            arg(2).and_then(|s| s.parse().ok()).unwrap_or(4),
            arg(3).map(|s| ratio(&s)).unwrap_or(Q::new(1, 6)),
            arg(4)
                .map(|s| s.split(',').map(ratio).collect())
                .unwrap_or_else(|| vec![Q::new(1, 1000), Q::new(1, 500), Q::new(1, 250), Q::new(5, 1000)]),
        ),
        "words" => words(
            arg(2).and_then(|s| s.parse().ok()).unwrap_or(4),
            arg(3).map(|s| ratio(&s)).unwrap_or(Q::new(1, 6)),
            arg(4).and_then(|s| s.parse().ok()).unwrap_or(1.005),
            arg(5).and_then(|s| s.parse().ok()).unwrap_or(6),
        ),
        other => eprintln!("unknown mode {other}: band | edge | cycle | search | pcc | words"),
    }
}

/// `a/b` (or an integer) as an exact rational.
fn ratio(s: &str) -> Q {
    let mut it = s.split('/').map(|t| t.trim().parse::<i64>().expect("a/b"));
    let a = it.next().expect("a/b");
    Q::new(a, it.next().unwrap_or(1))
}

fn eig_text(e: &[(f64, f64); 3]) -> String {
    let v: Vec<String> = e
        .iter()
        .map(|z| if z.1 == 0.0 { format!("{:.4}", z.0) } else { format!("{:.4}{:+.4}i", z.0, z.1) })
        .collect();
    v.join(", ")
}

/// n = 3: every kappa of the grid, every ratio: certified or why not, drops, S_1^2 S_2^2.
fn band(runs: u64) {
    println!(
        "n = 3; gamma = gamma* x r rounded to k/10^5 (strictly above gamma*); {runs} f64 drops per point"
    );
    println!("kappa | gamma* | r | gamma | orbit | S1^2S2^2 | drops | detail");
    for (a, b) in KAPPAS {
        let kappa = Q::new(a, b);
        let Some(th) = cc_threshold(3, &kappa, 60) else {
            println!("{kappa} | no threshold in (0, 1)");
            continue;
        };
        let mut hints = Vec::new();
        for r in RATIOS {
            let gamma = gamma_at(&th, r, 100_000);
            let start = std::time::Instant::now();
            let p = point(3, &kappa, &gamma, None, runs, Some(&CANDIDATE), &[MALACHITE, NUM], &mut hints);
            let detail = match &p.orbit {
                OrbitVerdict::Certified {
                    pattern, fixed_point, eigenvalues, margin, delta, boxes, ..
                } => format!(
                    "pattern {} x* = ({:.4}, {:.4}, {:.4}), eig {}, margin {:.3}, delta {:.1e}, {} boxes",
                    steps_text(pattern),
                    fixed_point[0],
                    fixed_point[1],
                    fixed_point[2],
                    eig_text(eigenvalues),
                    margin,
                    delta,
                    boxes
                ),
                OrbitVerdict::Failed { reason, .. } => reason.clone(),
            };
            println!(
                "{kappa} | {:.6} | {r} | {gamma} | {} | {} | {} | {detail} ({:.1} s)",
                th.0.to_f64(),
                p.orbit.letter(),
                match p.cycle {
                    Some(true) => "holds",
                    Some(false) => "fails",
                    None => "-",
                },
                p.drops.text(),
                start.elapsed().as_secs_f64()
            );
        }
    }
}

/// n = 3: bisection between the largest ratio that certified and the next (pattern 2,2,1,1).
fn edges(steps: usize) {
    println!(
        "n = 3, pattern 2,2,1,1: bisection of the largest gamma where the producer certifies ({steps} steps)"
    );
    println!("kappa | gamma* | certified at lo | fails at hi | lo/gamma* | S1^2S2^2 threshold above gamma*");
    for (a, b) in KAPPAS {
        let kappa = Q::new(a, b);
        let Some(th) = cc_threshold(3, &kappa, 60) else { continue };
        let pattern = [2, 2, 1, 1];
        // The first ratio that fails, from below.
        let mut lo: Option<Q> = None;
        let mut hi: Option<Q> = None;
        let mut hints = Vec::new();
        // From 1.02 gamma* up (nearer gamma* the producer needs more periods and time).
        for r in RATIOS.into_iter().filter(|&r| r >= 1.02) {
            let g = gamma_at(&th, r, 100_000);
            if chatter::orbit::band::certifies(3, &kappa, &g, &pattern, &[MALACHITE], &mut hints) {
                lo = Some(g);
            } else if lo.is_some() {
                hi = Some(g);
                break;
            }
        }
        let next = next_cycle_threshold(&kappa, &th);
        match (lo, hi) {
            (Some(lo), Some(hi)) => {
                let (l, h) = edge(3, &kappa, &pattern, lo, hi, steps, &[MALACHITE]);
                println!(
                    "{kappa} | {:.6} | {} ({:.6}) | {} ({:.6}) | {:.4} | {next}",
                    th.0.to_f64(),
                    l,
                    l.to_f64(),
                    h,
                    h.to_f64(),
                    l.to_f64() / th.0.to_f64()
                );
            }
            (lo, hi) => println!("{kappa} | {:.6} | {lo:?} | {hi:?} | - | {next}", th.0.to_f64()),
        }
    }
}

/// The first threshold of the S_1^2 S_2^2 criterion above gamma*, as text.
fn next_cycle_threshold(kappa: &Q, th: &(Q, Q)) -> String {
    let fam = Family { n: 3, c1: Q::new(-1, 2), kappa: kappa.clone() };
    let prof = cycle_profile(&fam, &CANDIDATE);
    prof.thresholds
        .iter()
        .find(|t| t.gamma.lo > th.1)
        .map(|t| {
            let mut r = t.gamma.clone();
            let (lo, hi) = r.decimal_enclosure(8);
            format!("[{lo}, {hi}] ({}, {} -> {})", t.source, t.below, t.above)
        })
        .unwrap_or_else(|| "none".into())
}

/// n = 3: every threshold of the S_1^2 S_2^2 criterion in (0, 1) for each kappa.
fn cycle() {
    println!("n = 3: where S_1^2 S_2^2 has a real positive dominant eigenvalue (exact thresholds in gamma)");
    for (a, b) in KAPPAS {
        let kappa = Q::new(a, b);
        let th = cc_threshold(3, &kappa, 60);
        let fam = Family { n: 3, c1: Q::new(-1, 2), kappa: kappa.clone() };
        let prof = cycle_profile(&fam, &CANDIDATE);
        let ts: Vec<String> = prof
            .thresholds
            .iter()
            .map(|t| {
                let mut r = t.gamma.clone();
                let (lo, hi) = r.decimal_enclosure(8);
                format!("[{lo}, {hi}] {} ({} -> {})", t.source, t.below, t.above)
            })
            .collect();
        println!(
            "kappa = {kappa}: gamma* = {:.8}; S1^2S2^2 near 0: {}; thresholds: {}",
            th.map(|t| t.0.to_f64()).unwrap_or(f64::NAN),
            prof.near_zero,
            ts.join("; ")
        );
    }
}

/// n = 4, 5, 6: drops just above gamma* (where S_1's criterion fails), patterns, and an orbit
/// certificate for the commonest CC pattern (n = 4, 6).
fn search(n: u64, runs: u64) {
    let kappas: Vec<Q> = match n {
        4 => vec![Q::new(1, 20), Q::new(1, 10), Q::new(1, 6), Q::new(1, 4), Q::new(1, 3)],
        5 => vec![Q::new(1, 20), Q::new(1, 10), Q::new(1, 6), Q::new(1, 4), Q::new(1, 3)],
        _ => vec![Q::new(1, 20), Q::new(1, 10), Q::new(1, 6), Q::new(1, 4), Q::new(1, 3)],
    };
    let ratios = [1.005, 1.02, 1.05, 1.1, 1.2];
    println!("n = {n}: {runs} f64 drops per point (600 impacts), gamma = gamma* x r");
    println!("kappa | gamma* | r | gamma | drops | orbit");
    for kappa in kappas {
        let Some(th) = cc_threshold(n, &kappa, 60) else {
            println!("{kappa} | no CC threshold in (0, 1)");
            continue;
        };
        let mut hints = Vec::new();
        for r in ratios {
            let gamma = gamma_at(&th, r, 100_000);
            let d: Drops = drops(n, &kappa, &gamma, runs, 600);
            let orbit = if n != 5 && d.cc > 0 {
                let p = point(n, &kappa, &gamma, None, runs, None, &[MALACHITE, NUM], &mut hints);
                match &p.orbit {
                    OrbitVerdict::Certified { pattern, eigenvalues, delta, .. } => format!(
                        "{}: pattern {}, eig {}, delta {:.1e}",
                        p.orbit.letter(),
                        steps_text(pattern),
                        eig_text(eigenvalues),
                        delta
                    ),
                    OrbitVerdict::Failed { reason, .. } => format!("{}: {reason}", p.orbit.letter()),
                }
            } else {
                "-".into()
            };
            println!("{kappa} | {:.6} | {r} | {gamma} | {} | {orbit}", th.0.to_f64(), d.text());
        }
    }
}

/// The band search of issue 22 §2 (`chatter::orbit::search`): per κ, γ from γ* up to where every
/// drop is ICC; the CC drops' cycles with their shares, and a certificate tried for each. Every
/// one of the `gammas` values is scanned (bands are islands: no early stop).
fn sweep(n: u64, runs: u64, budget: usize, gammas: usize) {
    use chatter::orbit::search::{Plan, search_kappa};
    let plan = Plan { runs, budget, gammas, icc_stop: gammas, ..Plan::full() };
    println!(
        "n = {n}: {runs} f64 drops per point ({budget} impacts), {} gammas per kappa from gamma*",
        plan.gammas
    );
    println!("kappa | gamma* | gamma | CC PCC ICC other | cycles (share: certificate, seconds)");
    let (mut points, mut certified, start) = (0, 0, std::time::Instant::now());
    for kappa in &plan.kappas {
        for p in search_kappa(n, kappa, &plan, &[MALACHITE, NUM]) {
            points += 1;
            let cycles: Vec<String> = p
                .cycles
                .iter()
                .map(|c| {
                    let verdict = match &c.certificate {
                        Ok((k, boxes)) => {
                            certified += 1;
                            format!("CERTIFIED ({k} period(s), {boxes} sub-boxes)")
                        }
                        Err(e) => format!("not certified: {}", e.chars().take(80).collect::<String>()),
                    };
                    format!(
                        "{} ({}/{}: {verdict}, {:.1} s)",
                        steps_text(&c.pattern),
                        c.drops,
                        runs,
                        c.seconds
                    )
                })
                .collect();
            let star = p.gamma_star.as_ref().map_or("none".to_string(), |g| format!("{:.6}", g.to_f64()));
            let [cc, pcc, icc, other] = p.outcomes;
            println!("{kappa} | {star} | {} | {cc} {pcc} {icc} {other} | {}", p.gamma, cycles.join("; "));
        }
    }
    println!("n = {n}: {points} points, {certified} certificates, {:.0} s", start.elapsed().as_secs_f64());
}

/// Below the PCC threshold (default n = 4, kappa = 1/6): fixed points of the two-contact patterns
/// (steps 1, n-1) and the PCC velocity map S_{n-1} S_1.
fn pcc(n: u64, kappa: Q, gammas: Vec<Q>) {
    let m = n as usize - 1;
    for g in gammas {
        let body = Polygon::new(n, kappa.clone(), g.clone()).expect("polygon");
        let maps = FloatMaps::new(&body);
        let d = drops(n, &kappa, &g, 20, 2000);
        println!("n = {n}, kappa = {kappa}, gamma = {g}: drops {}", d.text());
        for pattern in [vec![1, m], vec![m, 1], vec![1, m, 1, m]] {
            let fps = fixed_points(&maps, &pattern, &[[0.01, 0.01, -0.01]]);
            if fps.is_empty() {
                println!(
                    "  pattern {}: no fixed point of R_P found (iteration or Newton)",
                    steps_text(&pattern)
                );
            }
            for f in fps {
                println!(
                    "  pattern {}: x* = ({:.6e}, {:.6e}, {:.6e}), eig {}, margin {:.3e}, alpha {:.5}, beta {:.5}",
                    steps_text(&f.pattern),
                    f.x[0],
                    f.x[1],
                    f.x[2],
                    eig_text(&f.eigenvalues),
                    f.margin,
                    f.scales[0],
                    f.scales[1]
                );
            }
        }
        pcc_orbit(&body, &maps, m);
    }
}

/// The PCC cycle of the square is the point x = 0 of the section (a = h_1/h_c -> 0 and
/// (u_0, u_1)/(-v) -> 0): not an interior fixed point, so not a candidate for an orbit certificate
/// (condition 3 needs alpha <= lambda < 1, and alpha -> 1 there). Its pull is measured directly:
/// the velocity over one period of (1, 3) is S_3 S_1, whose eigenvalue 1 (u_0 = u_1 = 0) leaves
/// v alone; start at p = e_1 + eps e_2 (e_2 the eigenvector of the next eigenvalue) with a small
/// a, iterate R_(1,3) in f64 and watch the flight time per period T_k and alpha_k.
fn pcc_orbit(body: &Polygon<Q>, maps: &FloatMaps, last: usize) {
    let s: [[f64; 3]; 3] = {
        let m = chatter_kernel::model::linalg::mat_mul(&body.step(last as i64), &body.step(1));
        std::array::from_fn(|r| std::array::from_fn(|c| m[r][c].to_f64()))
    };
    let e = eigenvalues(&s);
    println!("  S_{last} S_1 eigenvalues {}", eig_text(&e));
    let unit = e.iter().position(|z| (z.0 - 1.0).abs() < 1e-9 && z.1 == 0.0);
    let Some(i1) = unit else {
        println!("  no eigenvalue 1");
        return;
    };
    let others: Vec<usize> = (0..3).filter(|&i| i != i1).collect();
    if e[others[0]].1 != 0.0 {
        println!("  the other two eigenvalues are not real: no PCC cycle (the PCC lemma)");
        return;
    }
    let e1 = eigenvector(&s, e[i1]).map(|z| z.0);
    let e2 = eigenvector(&s, e[others[0]]).map(|z| z.0);
    println!(
        "  e_1 (eigenvalue 1) = ({:.4e}, {:.4e}, {:.4e}); e_2 (eigenvalue {:.5}) = ({:.4}, {:.4}, {:.4})",
        e1[0], e1[1], e1[2], e[others[0]].0, e2[0], e2[1], e2[2]
    );
    let e3 = eigenvector(&s, e[others[1]]).map(|z| z.0);
    println!(
        "  e_3 (eigenvalue {:.3e}) = ({:.4}, {:.4}, {:.4}); after the impact at contact 0 the alternation needs u_0 > 0 > u_1: e_2 has u_0 u_1 {} 0, e_3 has u_0 u_1 {} 0",
        e[others[1]].0,
        e3[0],
        e3[1],
        e3[2],
        if e2[0] * e2[1] > 0.0 { ">" } else { "<" },
        if e3[0] * e3[1] > 0.0 { ">" } else { "<" }
    );
    for sign in [1.0, -1.0] {
        for (a0, eps) in [(1e-3, 1e-3), (1e-6, 1e-3), (1e-3, 1e-6)] {
            let p: [f64; 3] = std::array::from_fn(|i| e1[i] / -e1[2] + sign * eps * e2[i]);
            let mut x = [a0, p[0] / -p[2], p[1] / -p[2]];
            let (mut hc, mut time, mut last_t) = (1.0_f64, 0.0_f64, f64::NAN);
            let mut vel = 1.0_f64;
            let mut broke = None;
            let mut ratio = f64::NAN;
            for k in 0..60 {
                match float_period(maps, &[1, last], &x, true) {
                    Some((y, [alpha, beta, t], _)) => {
                        let t_abs = t * hc / vel;
                        if k > 0 {
                            ratio = t_abs / last_t;
                        }
                        last_t = t_abs;
                        time += t_abs;
                        hc *= alpha;
                        vel *= beta;
                        x = y;
                    }
                    None => {
                        let (_, _, m) = float_period(maps, &[1, last], &x, false).unwrap_or((
                            [0.0; 3],
                            [0.0; 3],
                            f64::NAN,
                        ));
                        broke = Some((k, m));
                        break;
                    }
                }
            }
            match broke {
                Some((k, m)) => println!(
                    "  start a = {a0:e}, p = e_1 {} {eps:e} e_2: the pattern (1,{last}) breaks in period {k} (margin {m:.3e}); elapsed {time:.4e}, h_c {hc:.4e}, last T ratio {ratio:.4}",
                    if sign > 0.0 { "+" } else { "-" }
                ),
                None => println!(
                    "  start a = {a0:e}, p = e_1 {} {eps:e} e_2: 60 periods of (1,{last}); elapsed {time:.4e}, h_c {hc:.4e} (x = ({:.2e}, {:.2e}, {:.2e})), T ratio per period {ratio:.4}",
                    if sign > 0.0 { "+" } else { "-" },
                    x[0],
                    x[1],
                    x[2]
                ),
            }
        }
    }
}

/// An exact decision of the cycle criterion for a word, at one body.
type Decide = Box<dyn Fn(&[i64]) -> bool>;

/// Every primitive pattern (up to rotation) of length <= `len` whose period's velocity map (the
/// product of the steps, the first step applied first) has a real positive dominant eigenvalue,
/// decided exactly at gamma = r gamma*: a necessary condition for CC following that pattern.
fn words(n: u64, kappa: Q, r: f64, len: usize) {
    let Some(th) = cc_threshold(n, &kappa, 60) else {
        println!("n = {n}, kappa = {kappa}: no CC threshold in (0, 1)");
        return;
    };
    let gamma = gamma_at(&th, r, 100_000);
    println!(
        "n = {n}, kappa = {kappa}, gamma* = {:.8}, gamma = {gamma} (r = {r}): primitive patterns (time order) of length <= {len} whose period map has a real positive dominant eigenvalue",
        th.0.to_f64()
    );
    let holds: Decide = match chatter_kernel::model::rational_cos::<Q>(n) {
        Some(c1) => {
            let b = Family { n, c1, kappa: kappa.clone() }.at(&gamma);
            Box::new(move |w: &[i64]| chatter::spectral::cycle::cycle_criterion(&b, w).holds)
        }
        None => {
            let b = Family {
                n,
                c1: chatter::bodies::cosine(n as usize),
                kappa: <chatter::spectral::number_field::Nf as chatter::exact::QField>::from_q(&kappa),
            }
            .at(&gamma);
            Box::new(move |w: &[i64]| chatter::spectral::cycle::cycle_criterion(&b, w).holds)
        }
    };
    let (mut tried, mut found) = (0, Vec::new());
    for l in 1..=len {
        let total = (n as usize - 1).pow(l as u32);
        for code in 0..total {
            let p: Vec<usize> =
                (0..l).map(|i| 1 + (code / (n as usize - 1).pow(i as u32)) % (n as usize - 1)).collect();
            if chatter::orbit::band::canonical(&p) != p || (1..l).any(|d| l % d == 0 && p[d..] == p[..l - d])
            {
                continue;
            }
            tried += 1;
            let word: Vec<i64> = p.iter().rev().map(|&j| j as i64).collect();
            if holds(&word) {
                found.push(steps_text(&p));
            }
        }
    }
    println!("{tried} patterns tried; the criterion holds for {}: {}", found.len(), found.join(" | "));
}
