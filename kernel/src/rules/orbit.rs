//! Orbit certificates (feature `orbit`; docs/orbit-certificates.md §3, docs/certificate-format.md
//! §14, why: docs/kernel-soundness.md §7). Rules, in the order they are checked:
//!
//! - O1 (the file): the header, `max-total-digits`, the body n in 3..=MAX_N with feature `field`
//!   (its constants enclosed, docs/kernel-soundness.md §7.1), else n in {3, 4, 6} (`unsupported-body`)
//!   with kappa > 0 and 0 <= gamma <= 1 (`parameter-out-of-range`), the claim
//!   `CompleteChatterFromSet`, a pattern of 1 to [`MAX_PATTERN`] steps in 1..n-1, 0 < rho < 1,
//!   0 < lambda < 1, period > 0 (`orbit-out-of-range`), subdivision <= [`MAX_DEPTH`]
//!   (`too-large`), a non-degenerate X (`degenerate-set`);
//! - O2 (conditions 1-3 of docs/orbit-certificates.md §3 on all of X): X, in its parameters
//!   y ∈ [-δ, δ]³, is cut into sub-boxes by bisection (at most `subdivision` times, at most
//!   [`MAX_BOXES`] sub-boxes examined); on each sub-box every quantity of the three conditions is
//!   enclosed by exact interval arithmetic with outward rounding, in the mean-value form
//!   f(c) + ∇f(Y)(Y - c) intersected with the natural enclosure f(Y), and its sign shown. A
//!   sub-box where some sign is not shown is bisected; at the deepest level, or where the sign is
//!   wrong at the sub-box's centre, the certificate is rejected with the condition's code
//!   (`pattern-not-forced`, `set-not-invariant`, `no-contraction`) and the sub-box as locus.

use super::outcome::Accepted;
use crate::exact::{Field, ParseLimits, to_canonical};
use crate::model::linalg::det3;
use crate::model::polygon::BodyError;
use crate::orbit::constants::enclosed_maps;
use crate::orbit::interval::{Centred, Iv};
use crate::orbit::map::{Maps, Quantity, Stop, period};
use crate::reject::{Code, Detail, KindCounted, KindDetail, KindLocus, Rejection};
use crate::syntax::cone::Claim;
use crate::syntax::numbers::{at_most, in_time, number, total};
use crate::syntax::orbit::{OrbitBody, OrbitCertificate, OrbitSet, Triple};
use crate::syntax::{Kind, expect};

/// The longest pattern a certificate may give.
pub const MAX_PATTERN: usize = 64;
/// The deepest subdivision a certificate may ask for (limit `max-orbit-depth`).
pub const MAX_DEPTH: u64 = 10;
/// The most sub-boxes the kernel examines (limit `max-orbit-boxes`).
pub const MAX_BOXES: usize = 20_000;

/// Why an orbit certificate is rejected (besides numbers, limits and the body's parameters).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Failure {
    /// n is not modelled (3..=MAX_N with feature `field`, else 3, 4 or 6).
    Unsupported(u64),
    /// A cone claim.
    ConeClaim(Claim),
    /// A pattern of this many steps (not 1 to [`MAX_PATTERN`]).
    PatternLength(usize),
    /// A step j not in 1..n-1.
    Step {
        /// The step.
        step: u64,
        /// n.
        n: u64,
    },
    /// rho or lambda not in (0, 1), or period not > 0.
    Bound {
        /// The number as written.
        text: String,
        /// Whether it must be below 1.
        below_one: bool,
    },
    /// delta <= 0.
    DeltaNotPositive,
    /// A box with lo >= hi in this coordinate.
    Flat(usize),
    /// Linearly dependent axes.
    Singular,
    /// A quantity of conditions 1-3 wrong at the centre of the sub-box of the locus (`wrong`), or
    /// not shown there at the deepest subdivision.
    Condition {
        /// The quantity.
        quantity: Quantity,
        /// Whether its sign is wrong at the sub-box's centre.
        wrong: bool,
    },
}

fn fail(code: Code, path: &str, f: Failure) -> Rejection {
    Rejection::at(code, path, KindDetail::Orbit(f))
}

/// Checks an orbit certificate exactly over the field `F`: rule O1, then conditions 1-3 on every
/// sub-box. The first failing check is reported.
pub fn check<F: Field>(cert: &OrbitCertificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    let orbit = read_orbit_values::<F>(cert, limits)?;
    let boxes = cover(&orbit, limits)?;
    let mut a = Accepted::cone(Claim::CompleteChatterFromSet, orbit.maps.n, 0, Vec::new());
    a.orbit_boxes = Some(boxes);
    a.time_to_rest_bound = time_to_rest(&orbit).map(|b| crate::exact::to_canonical(&b));
    Ok(a)
}

/// B = T̄/(1 − ρ): from a state of X with centre height h and velocity v < 0 right after an
/// impact, the impacts accumulate within time B h/|v| (docs/orbit-certificates.md §4, Theorem:
/// period k lasts at most (h/|v|) ρ^k T̄). Rule O1 has shown 0 < ρ < 1 and T̄ > 0, so B > 0.
fn time_to_rest<F: Field>(orbit: &Orbit<F>) -> Option<F> {
    orbit.period.over(&F::one().minus(&orbit.rho))
}

/// The checked content of an orbit certificate, exact.
#[derive(Clone, Debug)]
pub struct Orbit<F> {
    /// The body's maps, enclosed (exact points for rational cos 2π/n).
    pub maps: Maps<Iv<F>>,
    /// The pattern's steps.
    pub pattern: Vec<usize>,
    /// x*.
    pub centre: [F; 3],
    /// A (rows).
    pub a: [[F; 3]; 3],
    /// A^-1 (rows).
    pub a_inv: [[F; 3]; 3],
    /// δ.
    pub delta: F,
    /// The deepest subdivision.
    pub depth: u64,
    /// ρ.
    pub rho: F,
    /// λ.
    pub lambda: F,
    /// T̄.
    pub period: F,
}

/// Rule O1: reads and checks everything but the three conditions.
pub fn read_orbit_values<F: Field>(
    cert: &OrbitCertificate,
    limits: ParseLimits,
) -> Result<Orbit<F>, Rejection> {
    expect(&cert.format, cert.version, Kind::Orbit)?;
    total(cert.numbers().into_iter().map(|(_, s)| s), limits)?;
    let OrbitBody::RegularPolygon { n, kappa, gamma } = &cert.body;
    let kappa: F = number("body.kappa", kappa, limits)?;
    let gamma: F = number("body.gamma", gamma, limits)?;
    let maps = enclosed_maps(*n, kappa, gamma).map_err(|e| match e {
        BodyError::UnsupportedN(_) => fail(Code::UnsupportedBody, "body.n", Failure::Unsupported(*n)),
        BodyError::KappaNotPositive => {
            Rejection::at(Code::ParameterOutOfRange, "body.kappa", Detail::Body(e))
        }
        BodyError::GammaOutOfRange => Rejection::at(Code::ParameterOutOfRange, "body.gamma", Detail::Body(e)),
    })?;
    if cert.claim != Claim::CompleteChatterFromSet {
        return Err(fail(Code::OrbitOutOfRange, "claim", Failure::ConeClaim(cert.claim)));
    }
    let pattern = pattern(&cert.pattern, *n)?;
    let bound = |path: &str, s: &str, below_one: bool| -> Result<F, Rejection> {
        let x: F = number(path, s, limits)?;
        if !x.is_positive() || (below_one && x >= F::one()) {
            return Err(fail(Code::OrbitOutOfRange, path, Failure::Bound { text: s.to_string(), below_one }));
        }
        Ok(x)
    };
    let rho = bound("rho", &cert.rho, true)?;
    let lambda = bound("lambda", &cert.lambda, true)?;
    let period = bound("period", &cert.period, false)?;
    at_most("max-orbit-depth", cert.subdivision as usize, MAX_DEPTH as usize, KindCounted::Depth.into())?;
    let (centre, a, delta) = set::<F>(&cert.set, limits)?;
    let a_inv = inverse(&a).ok_or_else(|| fail(Code::DegenerateSet, "set.axes", Failure::Singular))?;
    Ok(Orbit { maps, pattern, centre, a, a_inv, delta, depth: cert.subdivision, rho, lambda, period })
}

/// The pattern: 1 to [`MAX_PATTERN`] steps, each in 1..n-1.
fn pattern(steps: &[u64], n: u64) -> Result<Vec<usize>, Rejection> {
    if steps.is_empty() || steps.len() > MAX_PATTERN {
        return Err(fail(Code::OrbitOutOfRange, "pattern", Failure::PatternLength(steps.len())));
    }
    let step = |(i, &j): (usize, &u64)| {
        if j == 0 || j >= n {
            return Err(fail(Code::OrbitOutOfRange, &format!("pattern[{i}]"), Failure::Step { step: j, n }));
        }
        Ok(j as usize)
    };
    steps.iter().enumerate().map(step).collect()
}

/// X as (x*, A, δ).
type Set<F> = ([F; 3], [[F; 3]; 3], F);

/// X as (x*, A, δ): a parallelepiped as given (δ > 0), or a box [lo, hi] (lo < hi) as its centre,
/// diag((hi - lo)/2) and 1.
fn set<F: Field>(set: &OrbitSet, limits: ParseLimits) -> Result<Set<F>, Rejection> {
    let triple = |path: &str, t: &Triple| -> Result<[F; 3], Rejection> {
        Ok([
            number(&format!("{path}[0]"), &t.0, limits)?,
            number(&format!("{path}[1]"), &t.1, limits)?,
            number(&format!("{path}[2]"), &t.2, limits)?,
        ])
    };
    match set {
        OrbitSet::Parallelepiped { centre, axes, delta } => {
            let centre = triple("set.centre", centre)?;
            let cols = [
                triple("set.axes[0]", &axes.0)?,
                triple("set.axes[1]", &axes.1)?,
                triple("set.axes[2]", &axes.2)?,
            ];
            let a: [[F; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|k| cols[k][i].clone()));
            let delta: F = number("set.delta", delta, limits)?;
            if !delta.is_positive() {
                return Err(fail(Code::DegenerateSet, "set.delta", Failure::DeltaNotPositive));
            }
            Ok((centre, a, delta))
        }
        OrbitSet::Box { lo, hi } => {
            let (lo, hi) = (triple("set.lo", lo)?, triple("set.hi", hi)?);
            if let Some(i) = (0..3).find(|&i| lo[i] >= hi[i]) {
                return Err(fail(Code::DegenerateSet, "set", Failure::Flat(i)));
            }
            let two = F::from_i64(2);
            let mid = |i: usize| lo[i].plus(&hi[i]).over(&two).unwrap_or_else(F::zero);
            let half = |i: usize| hi[i].minus(&lo[i]).over(&two).unwrap_or_else(F::zero);
            let a =
                std::array::from_fn(|i| std::array::from_fn(|k| if i == k { half(i) } else { F::zero() }));
            Ok(([mid(0), mid(1), mid(2)], a, F::one()))
        }
    }
}

/// The inverse of a non-singular 3x3 matrix (adjugate over the determinant).
fn inverse<F: Field>(m: &[[F; 3]; 3]) -> Option<[[F; 3]; 3]> {
    let det = det3(&m[0], &m[1], &m[2]);
    if det.is_zero() {
        return None;
    }
    let c = |r: usize, k: usize| {
        let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
        let (k1, k2) = ((k + 1) % 3, (k + 2) % 3);
        m[r1][k1].times(&m[r2][k2]).minus(&m[r1][k2].times(&m[r2][k1]))
    };
    // inverse[i][j] = cofactor(j, i) / det.
    let mut inv: [[F; 3]; 3] = std::array::from_fn(|_| std::array::from_fn(|_| F::zero()));
    for (i, row) in inv.iter_mut().enumerate() {
        for (j, e) in row.iter_mut().enumerate() {
            *e = c(j, i).over(&det)?;
        }
    }
    Some(inv)
}

/// A sub-box of [-δ, δ]³: [lo_k, hi_k] for k = 0..2, at a depth.
#[derive(Clone, Debug)]
struct SubBox<F> {
    lo: [F; 3],
    hi: [F; 3],
    depth: u64,
}

/// What a sub-box's check found.
enum Found {
    /// Every sign shown.
    Shown,
    /// A sign not shown on the sub-box (bisect, or reject at the deepest level).
    Unshown(Quantity),
    /// A sign wrong at the sub-box's centre.
    Wrong(Quantity),
}

/// The quantities of the three conditions over the sub-box `b`, in the order they are needed,
/// as [`Centred`] enclosures (value at the centre, value and gradient over the sub-box).
/// `Err(Failed)`: a sign is wrong at the centre; `Err(Division)`: a divisor is not shown nonzero.
fn quantities<F: Field>(orbit: &Orbit<F>, b: &SubBox<F>) -> Result<Vec<(Quantity, Centred<F>)>, Stop> {
    let two = F::from_i64(2);
    let centre: [F; 3] = std::array::from_fn(|k| b.lo[k].plus(&b.hi[k]).over(&two).unwrap_or_else(F::zero));
    let radius: [F; 3] = std::array::from_fn(|k| b.hi[k].minus(&b.lo[k]).over(&two).unwrap_or_else(F::zero));
    let r =
        std::sync::Arc::new(std::array::from_fn(|k| Iv { lo: radius[k].negated(), hi: radius[k].clone() }));
    let x: [Centred<F>; 3] = std::array::from_fn(|i| {
        let mut at_c = Iv::point(&orbit.centre[i]);
        let mut over = at_c.clone();
        for (k, ck) in centre.iter().enumerate() {
            at_c = at_c.plus(&Iv::point(ck).scaled(&orbit.a[i][k]));
            over = over.plus(&Iv { lo: b.lo[k].clone(), hi: b.hi[k].clone() }.scaled(&orbit.a[i][k]));
        }
        Centred::seed(at_c, over, std::array::from_fn(|k| Iv::point(&orbit.a[i][k])), r.clone())
    });
    let mut out = Vec::new();
    let mut check = |q: Quantity, v: &Centred<F>| {
        // A sign that is wrong at the centre is wrong: no subdivision can show it.
        if v.c.hi.is_negative() || (q.strict() && !v.c.hi.is_positive()) {
            return Err(Stop::Failed(q));
        }
        out.push((q, v.clone()));
        Ok(())
    };
    let per = period(&orbit.maps, &orbit.pattern, &x, &mut check)?;
    let mut more = Vec::new();
    for i in 0..3 {
        let mut g = Centred::constant(&F::zero());
        for k in 0..3 {
            g = g.plus(&per.next[k].minus(&Centred::constant(&orbit.centre[k])).scaled(&orbit.a_inv[i][k]));
        }
        let delta = Centred::constant(&orbit.delta);
        more.push((Quantity::Inside { coordinate: i, upper: true }, delta.minus(&g)));
        more.push((Quantity::Inside { coordinate: i, upper: false }, g.plus(&delta)));
    }
    let lambda = Centred::constant(&orbit.lambda);
    more.push((Quantity::VelocityBound, lambda.minus(&per.beta)));
    more.push((Quantity::RatioBound, per.beta.scaled(&orbit.rho).minus(&per.alpha)));
    more.push((Quantity::PositionBound, lambda.minus(&per.alpha)));
    more.push((Quantity::TimeBound, Centred::constant(&orbit.period).minus(&per.time)));
    for (q, v) in more {
        check(q, &v)?;
    }
    Ok(out)
}

/// Checks every quantity on one sub-box.
fn examine<F: Field>(orbit: &Orbit<F>, b: &SubBox<F>) -> Found {
    let all = match quantities(orbit, b) {
        Ok(v) => v,
        Err(Stop::Failed(q)) => return Found::Wrong(q),
        Err(Stop::Division(q)) => return Found::Unshown(q),
    };
    for (q, v) in &all {
        let enc = &v.b.v;
        let shown = if q.strict() { enc.lo.is_positive() } else { !enc.lo.is_negative() };
        if !shown {
            return Found::Unshown(*q);
        }
    }
    Found::Shown
}

/// The rejection of a sub-box where `quantity` is wrong at the centre, or not shown.
fn rejection<F: Field>(b: &SubBox<F>, quantity: Quantity, wrong: bool) -> Rejection {
    let code = match quantity.condition() {
        1 => Code::PatternNotForced,
        2 => Code::SetNotInvariant,
        _ => Code::NoContraction,
    };
    let sub_box = Box::new(std::array::from_fn(|k| [to_canonical(&b.lo[k]), to_canonical(&b.hi[k])]));
    let (step, contact) = quantity.step_contact();
    let locus = KindLocus::OrbitBox { sub_box, depth: b.depth, step, contact };
    Rejection::new(code, locus, KindDetail::Orbit(Failure::Condition { quantity, wrong }))
}

/// Conditions 1-3 on all of X by bisection: the number of sub-boxes on which every sign was
/// shown.
pub fn cover<F: Field>(orbit: &Orbit<F>, limits: ParseLimits) -> Result<usize, Rejection> {
    let d = orbit.delta.clone();
    let root =
        SubBox { lo: std::array::from_fn(|_| d.negated()), hi: std::array::from_fn(|_| d.clone()), depth: 0 };
    let mut stack = vec![root];
    let (mut examined, mut shown) = (0usize, 0usize);
    while let Some(b) = stack.pop() {
        in_time(limits, "checking the sub-boxes of an orbit certificate")?;
        examined += 1;
        if examined > MAX_BOXES {
            return Err(Rejection::limit("max-orbit-boxes", examined, MAX_BOXES, KindCounted::Boxes.into()));
        }
        match examine(orbit, &b) {
            Found::Shown => shown += 1,
            Found::Wrong(q) => return Err(rejection(&b, q, true)),
            Found::Unshown(q) if b.depth >= orbit.depth => return Err(rejection(&b, q, false)),
            Found::Unshown(_) => {
                let two = F::from_i64(2);
                let mid: [F; 3] =
                    std::array::from_fn(|k| b.lo[k].plus(&b.hi[k]).over(&two).unwrap_or_else(F::zero));
                // Children in reverse order, so that the first (all lower halves) is examined first.
                for child in (0..8).rev() {
                    let pick = |k: usize| child >> k & 1 == 1;
                    let lo = std::array::from_fn(|k| if pick(k) { mid[k].clone() } else { b.lo[k].clone() });
                    let hi = std::array::from_fn(|k| if pick(k) { b.hi[k].clone() } else { mid[k].clone() });
                    stack.push(SubBox { lo, hi, depth: b.depth + 1 });
                }
            }
        }
    }
    Ok(shown)
}
