//! The band search of issue 22 §2: for a regular n-gon, κ across a grid that covers where the CC
//! threshold γ*(κ) exists and beyond, γ from just above γ* up to where every drop is ICC; at each
//! point many random drops with long budgets (`f64` evidence), every periodic pattern that CC
//! drops settle into with its share of the drops, and an orbit certificate tried for each (the
//! kernel's verdict on both backends). What it does not find is not shown absent: it reports
//! what it searched.

use super::band::{canonical, cc_threshold};
use super::{Request, certify_orbit_from};
use crate::exact::{Q, QExt};
use crate::simulate::{Arithmetic, Initial, Model, Options, Outcome, Shape, pattern, simulate};
use chatter_kernel::verify::Backend;

/// What to search.
#[derive(Clone, Debug)]
pub struct Plan {
    /// The κ grid.
    pub kappas: Vec<Q>,
    /// Points in γ per κ (γ* < γ < 1, denser next to γ*).
    pub gammas: usize,
    /// Random drops per point (seeds 1..=runs).
    pub runs: u64,
    /// Impact budget per drop.
    pub budget: usize,
    /// Stop a κ after this many consecutive points where every drop is ICC.
    pub icc_stop: usize,
}

impl Plan {
    /// The full search: 12 values of κ from 1/100 to 1/3, 12 values of γ, 300 drops of 3000
    /// impacts each.
    pub fn full() -> Plan {
        let k = |a: i64, b: i64| Q::new(a, b);
        let kappas = vec![
            k(1, 100),
            k(1, 50),
            k(1, 40),
            k(1, 30),
            k(961, 25600),
            k(1, 20),
            k(1, 15),
            k(1, 10),
            k(1, 8),
            k(1, 6),
            k(1, 4),
            k(1, 3),
        ];
        Plan { kappas, gammas: 12, runs: 300, budget: 3000, icc_stop: 2 }
    }
}

/// A periodic pattern that CC drops settled into, its share, and the certificate attempt.
#[derive(Clone, Debug)]
pub struct Cycle {
    /// The pattern's steps (canonical phase: the largest rotation).
    pub pattern: Vec<usize>,
    /// Drops that settled into it (and ended CC, evidence).
    pub drops: u64,
    /// The kernel's verdict: `Ok((periods, sub-boxes))` when accepted on every backend asked,
    /// else the producer's reason.
    pub certificate: Result<(usize, usize), String>,
    /// Wall time of the attempt, seconds.
    pub seconds: f64,
}

/// One point of the search.
#[derive(Clone, Debug)]
pub struct PointResult {
    /// κ.
    pub kappa: Q,
    /// The lower end of the enclosure of γ*(κ), if the threshold exists in (0, 1).
    pub gamma_star: Option<Q>,
    /// γ.
    pub gamma: Q,
    /// Drops: CC, PCC, ICC, other (evidence).
    pub outcomes: [u64; 4],
    /// The cycles of CC drops, commonest first.
    pub cycles: Vec<Cycle>,
}

impl PointResult {
    /// Whether every drop ended ICC.
    pub fn all_icc(&self) -> bool {
        self.outcomes[2] == self.outcomes.iter().sum::<u64>()
    }
}

/// The γ grid above `start`: start + (1 - start)(k/(m+1))², k = 1..m, rounded to k/10⁵ strictly
/// above `start`.
pub fn gamma_grid(start: &Q, m: usize) -> Vec<Q> {
    let s = start.to_f64();
    let mut out: Vec<Q> = Vec::new();
    for k in 1..=m {
        let t = k as f64 / (m + 1) as f64;
        let mut g = Q::new(((s + (1.0 - s) * t * t) * 1e5).round() as i64, 100_000);
        while g <= *start {
            g = &g + &Q::new(1, 100_000);
        }
        if out.last().is_none_or(|last| *last < g) && g < Q::int(1) {
            out.push(g);
        }
    }
    out
}

/// Drops at one point: outcome counts and the canonical cycles of the CC drops with counts.
pub fn settle(n: u64, kappa: &Q, gamma: &Q, runs: u64, budget: usize) -> ([u64; 4], Vec<(Vec<usize>, u64)>) {
    let (mut outcomes, mut cycles) = ([0u64; 4], Vec::<(Vec<usize>, u64)>::new());
    let Ok(model) = Model::new(Shape::Polygon(n), kappa.clone(), gamma.clone()) else {
        return (outcomes, cycles);
    };
    for seed in 1..=runs {
        let run = simulate(&model, &Initial::RandomDrop { seed }, Arithmetic::Float, &Options::new(budget));
        let slot = match run.outcome {
            Outcome::Cc => 0,
            Outcome::Pcc => 1,
            Outcome::Icc => 2,
            _ => 3,
        };
        outcomes[slot] += 1;
        let Some(p) = pattern::find(&run.sequence).filter(|_| slot == 0) else { continue };
        let steps = canonical(&pattern::steps(&p.cycle, n as usize));
        match cycles.iter_mut().find(|(q, _)| *q == steps) {
            Some((_, k)) => *k += 1,
            None => cycles.push((steps, 1)),
        }
    }
    cycles.sort_by_key(|c| std::cmp::Reverse(c.1));
    (outcomes, cycles)
}

/// Tries an orbit certificate for a cycle at one point (δ halved as the producer does).
fn certify(n: u64, kappa: &Q, gamma: &Q, pattern: &[usize], count: u64, backends: &[Backend]) -> Cycle {
    let req = Request {
        n,
        kappa: kappa.clone(),
        gamma: gamma.clone(),
        pattern: Some(pattern.to_vec()),
        drops: 0,
        max_depth: 1,
    };
    let start = std::time::Instant::now();
    let certificate =
        certify_orbit_from(&req, backends, &[]).map(|f| (f.periods, f.boxes)).map_err(|e| e.to_string());
    Cycle { pattern: pattern.to_vec(), drops: count, certificate, seconds: start.elapsed().as_secs_f64() }
}

/// One point: drops, then a certificate attempt per cycle found.
pub fn search_point(n: u64, kappa: &Q, gamma: &Q, plan: &Plan, backends: &[Backend]) -> PointResult {
    let (outcomes, found) = settle(n, kappa, gamma, plan.runs, plan.budget);
    let cycles = found.iter().map(|(p, k)| certify(n, kappa, gamma, p, *k, backends)).collect();
    PointResult { kappa: kappa.clone(), gamma_star: None, gamma: gamma.clone(), outcomes, cycles }
}

/// The search at one κ: γ from just above γ* (from 1/100 where no threshold exists in (0, 1))
/// until `plan.icc_stop` consecutive points have every drop ICC.
pub fn search_kappa(n: u64, kappa: &Q, plan: &Plan, backends: &[Backend]) -> Vec<PointResult> {
    let star = cc_threshold(n, kappa, 40).map(|t| t.1);
    let start = star.clone().unwrap_or_else(|| Q::new(1, 100));
    let (mut out, mut icc_run) = (Vec::new(), 0);
    for gamma in gamma_grid(&start, plan.gammas) {
        let mut p = search_point(n, kappa, &gamma, plan, backends);
        p.gamma_star = star.clone();
        icc_run = if p.all_icc() { icc_run + 1 } else { 0 };
        out.push(p);
        if icc_run >= plan.icc_stop {
            break;
        }
    }
    out
}
