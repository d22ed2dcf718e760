//! The band above the CC threshold (issue 15 §3, docs/orbit-certificates.md §7): at a regular
//! n-gon's (kappa, gamma) above the exact S_1 threshold gamma*(kappa), whether the orbit producer
//! certifies, why not otherwise, what random drops do, and the exact verdict of a cycle criterion
//! (S_1^2 S_2^2 for the triangle). Also the largest gamma where the producer certifies, by
//! bisection on exact rationals: a lower bound on the band's upper edge for this producer, not
//! the band's exact edge.

use super::{Failure, Found, Request, certify_orbit_from};
use crate::bodies::cosine;
use crate::exact::{Q, QExt};
use crate::simulate::{Arithmetic, Initial, Model, Options, Outcome, Shape, pattern, simulate};
use crate::spectral::criteria::{Family, cc_profile};
use crate::spectral::cycle::cycle_criterion;
use chatter_kernel::model::{Polygon, rational_cos};
use chatter_kernel::verify::Backend;

/// An enclosure [lo, hi] of the CC threshold gamma*(kappa) (the supremum of the gammas where S_1
/// has a real positive dominant eigenvalue), of width <= 2^-`bits`; `None` if the criterion
/// holds up to gamma = 1 or nowhere. Exact for every n (in Q(cos 2 pi/n) where it is irrational).
pub fn cc_threshold(n: u64, kappa: &Q, bits: u32) -> Option<(Q, Q)> {
    let lo = match rational_cos::<Q>(n) {
        Some(c1) => cc_profile(&Family { n, c1, kappa: kappa.clone() }).sup_lower_bound(bits),
        None => {
            let fam = Family {
                n,
                c1: cosine(n as usize),
                kappa: <crate::spectral::number_field::Nf as crate::exact::QField>::from_q(kappa),
            };
            cc_profile(&fam).sup_lower_bound(bits)
        }
    }?;
    let eps = Q::from_rational(malachite::rational::Rational::from(1u32) >> i64::from(bits));
    let hi = &lo + &eps;
    Some((lo, hi))
}

/// A rational near gamma* times `ratio` with denominator `den`, strictly above `above`.
pub fn gamma_at(threshold: &(Q, Q), ratio: f64, den: i64) -> Q {
    let g = (threshold.0.to_f64() * ratio * den as f64).round() as i64;
    let mut q = Q::new(g, den);
    while q <= threshold.1 {
        q = &q + &Q::new(1, den);
    }
    q
}

/// What random drops did at one point.
#[derive(Clone, Debug, Default)]
pub struct Drops {
    pub runs: u64,
    pub cc: u64,
    pub pcc: u64,
    pub icc: u64,
    /// Undecided or simultaneous impacts.
    pub other: u64,
    /// The settled patterns (steps) with how many drops settled into each, most frequent first.
    pub patterns: Vec<(Vec<usize>, u64)>,
}

impl Drops {
    /// `CC 20/20` style summary, with the commonest pattern.
    pub fn text(&self) -> String {
        let mut parts = Vec::new();
        for (name, k) in [("CC", self.cc), ("PCC", self.pcc), ("ICC", self.icc), ("other", self.other)] {
            if k > 0 {
                parts.push(format!("{name} {k}"));
            }
        }
        let pat = self
            .patterns
            .first()
            .map(|(p, k)| format!(", pattern {} x{k}", steps_text(p)))
            .unwrap_or_default();
        format!("{}/{}{pat}", parts.join(" "), self.runs)
    }
}

/// Steps as `2,2,1,1`.
pub fn steps_text(p: &[usize]) -> String {
    p.iter().map(|j| j.to_string()).collect::<Vec<_>>().join(",")
}

/// A canonical phase of a cycle of steps: the lexicographically largest rotation.
pub fn canonical(p: &[usize]) -> Vec<usize> {
    (0..p.len().max(1))
        .map(|r| p[r..].iter().chain(&p[..r]).copied().collect::<Vec<_>>())
        .max()
        .unwrap_or_default()
}

/// Simulates `runs` random drops (seeds 1..=runs, `f64`, `budget` impacts each).
pub fn drops(n: u64, kappa: &Q, gamma: &Q, runs: u64, budget: usize) -> Drops {
    let mut d = Drops { runs, ..Drops::default() };
    let Ok(model) = Model::new(Shape::Polygon(n), kappa.clone(), gamma.clone()) else { return d };
    for seed in 1..=runs {
        let run = simulate(&model, &Initial::RandomDrop { seed }, Arithmetic::Float, &Options::new(budget));
        match run.outcome {
            Outcome::Cc => d.cc += 1,
            Outcome::Pcc => d.pcc += 1,
            Outcome::Icc => d.icc += 1,
            _ => d.other += 1,
        }
        if let Some(p) = pattern::find(&run.sequence) {
            let steps = canonical(&pattern::steps(&p.cycle, n as usize));
            match d.patterns.iter_mut().find(|(q, _)| *q == steps) {
                Some((_, k)) => *k += 1,
                None => d.patterns.push((steps, 1)),
            }
        }
    }
    d.patterns.sort_by_key(|p| std::cmp::Reverse(p.1));
    d
}

/// The orbit producer's answer at one point, summarised.
#[derive(Clone, Debug)]
pub enum OrbitVerdict {
    Certified {
        pattern: Vec<usize>,
        periods: usize,
        fixed_point: [f64; 3],
        eigenvalues: [(f64, f64); 3],
        margin: f64,
        delta: f64,
        boxes: usize,
    },
    Failed {
        kind: &'static str,
        reason: String,
    },
}

impl OrbitVerdict {
    fn of(r: &Result<Found, Failure>) -> Self {
        match r {
            Ok(f) => OrbitVerdict::Certified {
                pattern: f.certificate.pattern.iter().map(|&j| j as usize).collect(),
                periods: f.periods,
                fixed_point: f.fixed_point,
                eigenvalues: f.complex_eigenvalues,
                margin: f.margin,
                delta: f.delta,
                boxes: f.boxes,
            },
            Err(e) => OrbitVerdict::Failed { kind: failure_kind(e), reason: e.to_string() },
        }
    }

    pub fn certified(&self) -> bool {
        matches!(self, OrbitVerdict::Certified { .. })
    }

    /// `C` (certified), `C(k)` (certified with the pattern repeated k times), or the failure's
    /// letter: `N` no attracting cycle, `S` pattern not stable, `X` no contraction, `P` no
    /// pattern, `E` other.
    pub fn letter(&self) -> String {
        match self {
            OrbitVerdict::Certified { periods: 1, .. } => "C".into(),
            OrbitVerdict::Certified { periods, .. } => format!("C({periods})"),
            OrbitVerdict::Failed { kind, .. } => match *kind {
                "no-attracting-cycle" => "N",
                "pattern-not-stable" => "S",
                "no-contraction" => "X",
                "no-pattern" => "P",
                _ => "E",
            }
            .into(),
        }
    }
}

/// The failure's stable name (as `chatter certify-orbit --json`).
pub fn failure_kind(f: &Failure) -> &'static str {
    match f {
        Failure::Body(_) => "body",
        Failure::NoPattern(_) => "no-pattern",
        Failure::NoAttractingCycle(_) => "no-attracting-cycle",
        Failure::PatternNotStable(_) => "pattern-not-stable",
        Failure::NoContraction(_) => "no-contraction",
        Failure::Internal(_) => "internal",
    }
}

/// One measured point of the band.
#[derive(Clone, Debug)]
pub struct Point {
    pub gamma: Q,
    pub orbit: OrbitVerdict,
    pub drops: Drops,
    /// The exact verdict of the cycle criterion (the word's dominant eigenvalue real positive),
    /// when a word was given.
    pub cycle: Option<bool>,
    /// The exact CC criterion (S_1) at the point (false above gamma*).
    pub cc: bool,
}

/// Measures one point: the orbit producer (pattern given, or the commonest pattern of the drops),
/// the drops, the S_1 criterion and the cycle criterion of `word`, all at (n, kappa, gamma).
#[allow(clippy::too_many_arguments)]
pub fn point(
    n: u64,
    kappa: &Q,
    gamma: &Q,
    pattern: Option<Vec<usize>>,
    runs: u64,
    word: Option<&[i64]>,
    backends: &[Backend],
    hints: &mut Vec<[f64; 3]>,
) -> Point {
    let drops = drops(n, kappa, gamma, runs, 600);
    let pattern = pattern.or_else(|| drops.patterns.first().map(|(p, _)| p.clone()));
    let orbit = match pattern {
        Some(p) => {
            let req = Request {
                n,
                kappa: kappa.clone(),
                gamma: gamma.clone(),
                pattern: Some(p),
                drops: 0,
                max_depth: 1,
            };
            let r = certify_orbit_from(&req, backends, hints);
            if let Ok(f) = &r {
                hints.insert(0, f.fixed_point);
                hints.truncate(4);
            }
            OrbitVerdict::of(&r)
        }
        None => OrbitVerdict::Failed { kind: "no-pattern", reason: "no drop settled into a pattern".into() },
    };
    let (cc, cycle) = match Polygon::<Q>::new(n, kappa.clone(), gamma.clone()) {
        Ok(b) => (crate::spectral::criteria::cc_criterion(&b).0, word.map(|w| cycle_criterion(&b, w).holds)),
        Err(_) => (false, None),
    };
    Point { gamma: gamma.clone(), orbit, drops, cycle, cc }
}

/// Whether the producer certifies at gamma (pattern given).
pub fn certifies(
    n: u64,
    kappa: &Q,
    gamma: &Q,
    pattern: &[usize],
    backends: &[Backend],
    hints: &mut Vec<[f64; 3]>,
) -> bool {
    let req = Request {
        n,
        kappa: kappa.clone(),
        gamma: gamma.clone(),
        pattern: Some(pattern.to_vec()),
        drops: 0,
        max_depth: 1,
    };
    match certify_orbit_from(&req, backends, hints) {
        Ok(f) => {
            hints.insert(0, f.fixed_point);
            hints.truncate(4);
            true
        }
        Err(_) => false,
    }
}

/// Bisection on exact rationals between `lo` (certifies) and `hi` (does not) for `steps` steps:
/// the final (lo, hi). The producer certifies at lo; whether every gamma in [gamma*, lo] has a
/// certificate is not claimed (only the points tried), and hi failing says nothing about the
/// existence of certificates there.
pub fn edge(
    n: u64,
    kappa: &Q,
    pattern: &[usize],
    mut lo: Q,
    mut hi: Q,
    steps: usize,
    backends: &[Backend],
) -> (Q, Q) {
    let mut hints = Vec::new();
    for _ in 0..steps {
        let mid = (&lo + &hi) / Q::int(2);
        if certifies(n, kappa, &mid, pattern, backends, &mut hints) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (lo, hi)
}

/// One row of the triangle's band table (docs/orbit-certificates.md §7), for `chatter reproduce`.
#[derive(Clone, Debug)]
pub struct Row {
    pub kappa: Q,
    /// An exact enclosure of gamma*(kappa) of width 2^-60 ([`cc_threshold`]).
    pub gamma_star: (Q, Q),
    /// The requested gamma / gamma*.
    pub ratio: f64,
    /// The rational gamma tried (denominator 10^5, strictly above gamma*).
    pub gamma: Q,
    /// The producer's answer for (2, 2, 1, 1): certified = accepted by the kernel on both backends.
    pub orbit: OrbitVerdict,
    /// The exact S_1^2 S_2^2 criterion at (kappa, gamma) (src/spectral/cycle.rs).
    pub cycle: bool,
    /// The exact S_1 criterion at (kappa, gamma): false, as gamma > gamma*.
    pub cc: bool,
    /// `runs` random `f64` drops (600 impacts each).
    pub drops: Drops,
}

/// The n = 3 band table at r gamma*(kappa), up to ~90 s a point (docs/orbit-certificates.md §7.1, §7.5).
pub fn band_rows(kappas: &[Q], ratios: &[f64], runs: u64) -> Vec<Row> {
    use chatter_kernel::verify::{MALACHITE, NUM};
    let mut rows = Vec::new();
    for kappa in kappas {
        let Some(th) = cc_threshold(3, kappa, 60) else { continue };
        let mut hints = Vec::new();
        for &ratio in ratios {
            let gamma = gamma_at(&th, ratio, 100_000);
            let word = crate::spectral::cycle::CANDIDATE;
            let p = point(
                3,
                kappa,
                &gamma,
                Some(vec![2, 2, 1, 1]),
                runs,
                Some(&word),
                &[MALACHITE, NUM],
                &mut hints,
            );
            rows.push(Row {
                kappa: kappa.clone(),
                gamma_star: th.clone(),
                ratio,
                gamma,
                orbit: p.orbit,
                cycle: p.cycle.unwrap_or(false),
                cc: p.cc,
                drops: p.drops,
            });
        }
    }
    rows
}
