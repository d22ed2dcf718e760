//! Issue 24 (docs/time-to-rest.md §4): below the CC threshold, the periodic patterns that
//! all-down drops settle into, the orbit certificates made for them, and the share of drops proved
//! CC with a bound on the time to rest.
//!
//! ```text
//! cargo run --release --features research --example time_to_rest -- patterns N KAPPA GAMMA [DROPS] [BUDGET]
//! cargo run --release --features research --example time_to_rest -- measure N KAPPA GAMMA [RUNS] [BUDGET]
//! cargo run --release --features research --example time_to_rest -- grid [RUNS] [BUDGET]
//! cargo run --release --features research --example time_to_rest -- bench-grid [RUNS] [BUDGET] [survey|full] [N]
//! ```
//!
//! `patterns`: `f64` random drops (evidence), their primitive cycles of steps with counts and
//! transients, then an orbit certificate per cycle (kernel on both backends), timed.
//! `measure`: the drops run exactly against a cone certificate and the orbit certificates made
//! for their cycles (`chatter::prove::prove_many`, as `chatter simulate --exact --runs`); per
//! drop proved CC, the proved bound t* <= t_k + B h/|v| against the accumulation time of an `f64`
//! run of the same drop (1000 impacts). `grid`: `measure` over a few n = 3, 4 points below the
//! CC threshold. `bench-grid`: the grid of `cargo bench --bench certify_grid` (n = 3, 4, κ = k/40,
//! γ = g/100; only n = N with the fifth argument): at each point where a cone certificate with
//! claim `CompleteChatterFromAllDown` is made (as `chatter simulate --exact` makes it), the share of
//! RUNS drops (default 20) proved CC with a bound (issue 24 §2 target), orbit certificates made
//! with the survey (default) or full budgets; one line per point, then the totals.

use chatter::exact::{Q, QExt};
use chatter::orbit::band::cc_threshold;
use chatter::prove::{Effort, add_orbit_for, cone, prove_many};
use chatter::simulate::certified::{Certified, pattern_text, primitive_cycle};
use chatter::simulate::pattern;
use chatter::simulate::{
    Arithmetic, Decision, Initial, Model, Options, Outcome, Shape, simulate, simulate_many,
};
use std::collections::BTreeMap;
use std::time::Instant;

fn arg(k: usize) -> Option<String> {
    std::env::args().nth(k)
}

fn ratio(s: &str) -> Q {
    chatter::exact::parse_user_number(s).expect("a number")
}

fn model(n: u64, kappa: &Q, gamma: &Q) -> Model {
    Model::new(Shape::Polygon(n), kappa.clone(), gamma.clone()).expect("a valid body")
}

/// γ / γ*(κ) with γ* the CC threshold (the enclosure's lower end).
fn threshold_text(n: u64, kappa: &Q, gamma: &Q) -> String {
    match cc_threshold(n, kappa, 40) {
        Some((lo, _)) => {
            format!("gamma* = {:.6}, gamma/gamma* = {:.4}", lo.to_f64(), gamma.to_f64() / lo.to_f64())
        }
        None => "gamma* unknown".into(),
    }
}

/// min / median / max of a non-empty list.
fn spread(mut xs: Vec<f64>) -> String {
    if xs.is_empty() {
        return "-".into();
    }
    xs.sort_by(f64::total_cmp);
    let median =
        if xs.len() % 2 == 1 { xs[xs.len() / 2] } else { (xs[xs.len() / 2 - 1] + xs[xs.len() / 2]) / 2.0 };
    format!("{:.9} / {:.9} / {:.9}", xs[0], median, xs[xs.len() - 1])
}

fn patterns(n: u64, kappa: Q, gamma: Q, drops: u64, budget: usize) {
    let m = model(n, &kappa, &gamma);
    println!("n = {n}, kappa = {kappa}, gamma = {gamma} ({})", threshold_text(n, &kappa, &gamma));
    let briefs = simulate_many(&m, 0, drops, Arithmetic::Float, &Options::new(budget), &|| {});
    let mut outcomes = BTreeMap::new();
    let mut cycles: BTreeMap<Vec<usize>, Vec<usize>> = BTreeMap::new();
    for b in &briefs {
        *outcomes.entry(b.outcome.name()).or_insert(0) += 1;
        let run =
            simulate(&m, &Initial::RandomDrop { seed: b.seed }, Arithmetic::Float, &Options::new(budget));
        if let Some(p) = pattern::find(&run.sequence) {
            let steps = primitive_cycle(&pattern::steps(&p.cycle, n as usize));
            cycles.entry(steps).or_default().push(p.transient);
        }
    }
    println!("  {drops} f64 drops, {budget} impacts: {outcomes:?}");
    for (c, transients) in &cycles {
        let t: Vec<f64> = transients.iter().map(|&x| x as f64).collect();
        let start = Instant::now();
        let made = add_orbit_for(&mut Certified::empty(), &m, c, Effort::Full);
        let verdict = match made {
            Ok(_) => "certified".to_string(),
            Err(e) => format!("not certified: {e}"),
        };
        println!(
            "  steps {}: {} drops, transient min/median/max {}; orbit certificate {verdict} ({:.2} s)",
            pattern_text(c),
            transients.len(),
            spread(t).replace(".000000000", ""),
            start.elapsed().as_secs_f64()
        );
    }
}

/// Proves `runs` drops and prints the share proved CC and bound / f64 accumulation time.
fn measure(n: u64, kappa: Q, gamma: Q, runs: u64, budget: usize) {
    let m = model(n, &kappa, &gamma);
    let start = Instant::now();
    let sets = cone(&m, Effort::Full);
    let proved = prove_many(&m, 0, runs, &Options::new(budget), sets, Some(Effort::Full), &|| {});
    let elapsed = start.elapsed().as_secs_f64();
    let mut counts = BTreeMap::new();
    let (mut factors, mut entries, mut tails) = (Vec::new(), Vec::new(), Vec::new());
    let (mut violations, mut worst) = (0, 0.0f64);
    for b in &proved.briefs {
        let key = if b.proved { b.outcome.name() } else { "undecided" };
        *counts.entry(key).or_insert(0) += 1;
        let (Outcome::Cc, true, Some(bound)) = (b.outcome, b.proved, &b.rest_by) else { continue };
        entries.push(b.impacts as f64);
        let initial = Initial::RandomDrop { seed: b.seed };
        let f = simulate(&m, &initial, Arithmetic::Float, &Options { record: true, ..Options::new(1000) });
        let Some(t) = f.accumulation.filter(|_| f.outcome == Outcome::Cc) else { continue };
        let factor = bound.to_f64() / t;
        if factor < 1.0 {
            violations += 1;
            worst = worst.min(factor - 1.0);
        }
        factors.push(factor);
        if let Some(tf) = tail_factor(&m, &proved.sets, &initial, &f) {
            tails.push(tf);
        }
    }
    let cc = counts.get("CC").copied().unwrap_or(0);
    println!(
        "n = {n}, kappa = {kappa}, gamma = {gamma} ({}): {runs} drops, budget {budget}: {counts:?}; \
         proved CC with a bound: {cc} ({:.1}%); entry impact min/median/max {}; bound / f64 accumulation \
         time min/median/max {} over {} drops, {violations} below 1 (lowest factor - 1: {worst:.2e}); after the entry, B h/|v| / f64 time left \
         min/median/max {}; sets: {}; {elapsed:.1} s",
        threshold_text(n, &kappa, &gamma),
        100.0 * cc as f64 / runs as f64,
        spread(entries).replace(".000000000", ""),
        spread(factors.clone()),
        factors.len(),
        spread(tails),
        proved.sets.sets().iter().map(|s| s.name.clone()).collect::<Vec<_>>().join("; "),
    );
    for note in &proved.sets.notes {
        println!("  note: {note}");
    }
}

/// The part of the bound after the entry at impact k, B h/|v| (B of the orbit set entered, h/|v|
/// of the `f64` run after impact k), against the `f64` time left after impact k (the intervals
/// after it, and the tail estimate): the tightness of B on this drop.
fn tail_factor(m: &Model, sets: &Certified, initial: &Initial, f: &chatter::simulate::Run) -> Option<f64> {
    let opts = Options { after_cone: true, ..Options::new(1000) };
    let run = chatter::simulate::simulate_with(m, initial, Arithmetic::Exact, &opts, Some(sets));
    let Decision::Certified { after, name, .. } = &run.decision else { return None };
    let b = sets.sets().iter().find(|s| &s.name == name)?.time_to_rest_bound.as_ref()?.to_f64();
    let s = &f.records.get(after - 1)?.state;
    let ratio = s.q[2] / s.p[2].abs() * ((s.q_exp - s.p_exp) as f64).exp2();
    let left: f64 = f.records[*after..].iter().map(|r| r.log2_dt.exp2()).sum::<f64>() + f.tail_log2?.exp2();
    Some(b * ratio / left)
}

/// n = 3 and n = 4 points below the CC threshold.
const GRID: [(u64, &str, &str); 10] = [
    (3, "1/20", "1/10"),
    (3, "1/10", "1/10"),
    (3, "1/8", "1/20"),
    (3, "1/8", "1/8"),
    (3, "1/5", "1/20"),
    (3, "1/4", "1/50"),
    (4, "1/10", "1/100"),
    (4, "1/8", "1/20"),
    (4, "1/6", "1/50"),
    (4, "1/6", "1/200"),
];

/// One point of `bench-grid`: None without a cone certificate, else (drops proved CC with a
/// bound, drops proved no-ICC-no-PCC, orbit sets made).
fn bench_point(m: &Model, runs: u64, budget: usize, effort: Effort) -> Option<(usize, usize, usize)> {
    let sets = cone(m, Effort::Full);
    if sets.sets().is_empty() {
        return None;
    }
    let proved = prove_many(m, 0, runs, &Options::new(budget), sets, Some(effort), &|| {});
    let bounded =
        proved.briefs.iter().filter(|b| b.proved && b.outcome == Outcome::Cc && b.rest_by.is_some());
    let cone_only = proved.briefs.iter().filter(|b| b.proved && b.outcome == Outcome::NoIccNoPcc).count();
    let orbits = proved.sets.sets().iter().filter(|s| s.kind == chatter::simulate::SetKind::Orbit).count();
    Some((bounded.count(), cone_only, orbits))
}

/// The §2 target of issue 24 over the grid of `benches/certify_grid.rs`.
fn bench_grid(runs: u64, budget: usize, effort: Effort, only: Option<u64>) {
    let (mut points, mut all, mut some, mut drops, mut bounded) = (0, 0, 0, 0, 0);
    let start = Instant::now();
    for n in [3u64, 4].into_iter().filter(|n| only.is_none_or(|o| o == *n)) {
        for k in 1..=8 {
            for g in 1..=40 {
                let (kappa, gamma) = (Q::new(k, 40), Q::new(g, 100));
                let t = Instant::now();
                let Some((b, c, o)) = bench_point(&model(n, &kappa, &gamma), runs, budget, effort) else {
                    continue;
                };
                points += 1;
                all += usize::from(b as u64 == runs);
                some += usize::from(b > 0);
                drops += runs as usize;
                bounded += b;
                println!(
                    "n = {n}, kappa = {kappa}, gamma = {gamma}: {b}/{runs} proved CC with a bound, {c} no-ICC-no-PCC, {o} orbit sets ({:.1} s)",
                    t.elapsed().as_secs_f64()
                );
            }
        }
    }
    let pct = |a: usize, b: usize| 100.0 * a as f64 / b.max(1) as f64;
    println!(
        "points with a cone certificate: {points}; every drop bounded at {all} ({:.1}%); some drop bounded at {some} ({:.1}%); drops bounded {bounded} of {drops} ({:.1}%); {:.0} s",
        pct(all, points),
        pct(some, points),
        pct(bounded, drops),
        start.elapsed().as_secs_f64()
    );
}

fn main() {
    let mode = arg(1).unwrap_or_else(|| "patterns".into());
    let num = |k: usize, d: u64| arg(k).and_then(|s| s.parse().ok()).unwrap_or(d);
    let body = || {
        (
            num(2, 3),
            arg(3).map(|s| ratio(&s)).unwrap_or(Q::new(1, 8)),
            arg(4).map(|s| ratio(&s)).unwrap_or(Q::new(1, 10)),
        )
    };
    match mode.as_str() {
        "patterns" => {
            let (n, k, g) = body();
            patterns(n, k, g, num(5, 100), num(6, 600) as usize)
        }
        "measure" => {
            let (n, k, g) = body();
            measure(n, k, g, num(5, 1000), num(6, 300) as usize)
        }
        "grid" => {
            for (n, k, g) in GRID {
                measure(n, ratio(k), ratio(g), num(2, 100), num(3, 300) as usize);
            }
        }
        "bench-grid" => {
            let effort = if arg(4).as_deref() == Some("full") { Effort::Full } else { Effort::Survey };
            bench_grid(num(2, 20), num(3, 300) as usize, effort, arg(5).and_then(|s| s.parse().ok()))
        }
        m => eprintln!("unknown mode {m}: patterns, measure, grid or bench-grid"),
    }
}
