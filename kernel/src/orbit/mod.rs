//! The orbit kernel: checks a version-5 certificate (docs/orbit-certificates.md §3,
//! docs/certificate-format.md §14, docs/kernel-soundness.md §7) exactly over any backend.
//!
//! Rules, in the order they are checked:
//! - O1 (the file): n in {3, 4, 6}, 0 <= gamma <= 1 < ... (the body), claim
//!   `CompleteChatterFromSet`, a pattern of 1 to [`MAX_PATTERN`] steps in 1..n-1,
//!   0 < rho < 1, 0 < lambda < 1, period > 0, a non-degenerate X, subdivision <= [`MAX_DEPTH`];
//! - O2 (conditions 1-3 of docs/orbit-certificates.md §3 on all of X): X, in its parameters
//!   y ∈ [-δ, δ]³, is cut into sub-boxes by bisection (at most `subdivision` times, at most
//!   [`MAX_BOXES`] sub-boxes examined); on each sub-box every quantity of the three conditions is
//!   enclosed by exact interval arithmetic with outward rounding, in the mean-value form
//!   f(c) + ∇f(Y)(Y - c) intersected with the natural enclosure f(Y), and its sign shown.
//!   A sub-box where some sign is not shown is bisected; at the deepest level, or where the sign
//!   is wrong at the sub-box's centre, the certificate is rejected with the condition's code
//!   (`pattern-not-forced`, `set-not-invariant`, `no-contraction`) and the sub-box as locus.

mod interval;
pub mod map;

pub use interval::{Centred, Dual, Iv, PRECISION, round_down, round_up};
pub use map::{Maps, Period, Quantity, Stop, period};

use crate::certificate::{
    Claim, Code, FORMAT, Locus, ORBIT_VERSION, OrbitBody, OrbitCertificate, OrbitSet, Rejection,
};
use crate::check::Accepted;
use crate::exact::{Field, NumberError, ParseLimits, parse_canonical, to_canonical};
use crate::model::{BodyError, Polygon};

/// The longest pattern a certificate may give.
pub const MAX_PATTERN: usize = 64;
/// The deepest subdivision a certificate may ask for (limit `max-orbit-depth`).
pub const MAX_DEPTH: u64 = 10;
/// The most sub-boxes the kernel examines (limit `max-orbit-boxes`).
pub const MAX_BOXES: usize = 20_000;

/// The checked content of an orbit certificate, exact.
#[derive(Clone, Debug)]
pub struct Orbit<F> {
    /// The body's maps.
    pub maps: Maps<F>,
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

/// The return map of the pattern at a rational point x = (a, b, c) of Σ, exactly: `Err` names the
/// first quantity of conditions 1-2 that is not positive there.
pub fn return_map<F: Field>(body: &Polygon<F>, pattern: &[usize], x: &[F; 3]) -> Result<Period<F>, Quantity> {
    let maps = Maps::new(body);
    if pattern.iter().any(|&j| j == 0 || j >= maps.n) {
        return Err(Quantity::Approach { step: 0, contact: 0 });
    }
    let mut check = |q: Quantity, v: &F| if v.is_positive() { Ok(()) } else { Err(Stop::Failed(q)) };
    period(&maps, pattern, x, &mut check).map_err(|s| match s {
        Stop::Failed(q) | Stop::Division(q) => q,
    })
}

fn number<F: Field>(path: &str, s: &str, limits: ParseLimits) -> Result<F, Rejection> {
    parse_canonical(s, limits).map_err(|e| {
        let code = if matches!(e, NumberError::TooLong { .. }) { Code::TooLarge } else { Code::BadNumber };
        Rejection::at_field(code, path, format!("{}: {e}", crate::check::abbreviated(s)))
    })
}

fn out_of_range(path: &str, msg: impl std::fmt::Display) -> Rejection {
    Rejection::at_field(Code::OrbitOutOfRange, path, msg)
}

fn det3<F: Field>(m: &[[F; 3]; 3]) -> F {
    crate::model::linalg::det3(&m[0], &m[1], &m[2])
}

/// The inverse of a non-singular 3x3 matrix (adjugate over the determinant).
fn inverse<F: Field>(m: &[[F; 3]; 3]) -> Option<[[F; 3]; 3]> {
    let det = det3(m);
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

/// Rule O1: reads and checks everything but the three conditions.
pub fn read_orbit_values<F: Field>(
    cert: &OrbitCertificate,
    limits: ParseLimits,
) -> Result<Orbit<F>, Rejection> {
    if cert.format != FORMAT {
        return Err(Rejection::at_field(Code::WrongFormat, "format", format!("expected {FORMAT:?}")));
    }
    if cert.version != ORBIT_VERSION {
        let msg = format!("{} is not {ORBIT_VERSION}, the version of orbit certificates", cert.version);
        return Err(Rejection::at_field(Code::UnsupportedVersion, "version", msg));
    }
    let numbers = cert.numbers();
    let total: usize = numbers.iter().map(|(_, s)| s.len()).sum();
    if total > limits.max_total_digits {
        let msg = format!(
            "{total} characters of numbers, more than the limit max-total-digits = {}: no verdict on the content",
            limits.max_total_digits
        );
        return Err(Rejection::new(Code::TooLarge, Locus::Limit { name: "max-total-digits".into() }, msg));
    }
    let OrbitBody::RegularPolygon { n, kappa, gamma } = &cert.body;
    let kappa: F = number("body.kappa", kappa, limits)?;
    let gamma: F = number("body.gamma", gamma, limits)?;
    let body = Polygon::new(*n, kappa, gamma).map_err(|e| match e {
        BodyError::UnsupportedN(_) => Rejection::at_field(
            Code::UnsupportedBody,
            "body.n",
            format!("n = {n}: orbit certificates need a rational cos(2 pi/n), n in {{3, 4, 6}}"),
        ),
        BodyError::KappaNotPositive => Rejection::at_field(Code::ParameterOutOfRange, "body.kappa", e),
        BodyError::GammaOutOfRange => Rejection::at_field(Code::ParameterOutOfRange, "body.gamma", e),
    })?;
    if cert.claim != Claim::CompleteChatterFromSet {
        let msg = format!(
            "{} is a cone claim; an orbit certificate claims CompleteChatterFromSet",
            cert.claim.name()
        );
        return Err(out_of_range("claim", msg));
    }
    if cert.pattern.is_empty() || cert.pattern.len() > MAX_PATTERN {
        let msg = format!("{} steps; a pattern has 1 to {MAX_PATTERN}", cert.pattern.len());
        return Err(out_of_range("pattern", msg));
    }
    let mut pattern = Vec::with_capacity(cert.pattern.len());
    for (i, &j) in cert.pattern.iter().enumerate() {
        if j == 0 || j >= *n {
            return Err(out_of_range(&format!("pattern[{i}]"), format!("step {j} is not in 1..{}", n - 1)));
        }
        pattern.push(j as usize);
    }
    let bound = |path: &str, s: &str, below_one: bool| -> Result<F, Rejection> {
        let x: F = number(path, s, limits)?;
        if !x.is_positive() || (below_one && x >= F::one()) {
            let range = if below_one { "0 < x < 1" } else { "x > 0" };
            return Err(out_of_range(path, format!("{} is not in {range}", crate::check::abbreviated(s))));
        }
        Ok(x)
    };
    let rho = bound("rho", &cert.rho, true)?;
    let lambda = bound("lambda", &cert.lambda, true)?;
    let period = bound("period", &cert.period, false)?;
    if cert.subdivision > MAX_DEPTH {
        let msg = format!(
            "subdivision {} is deeper than the limit max-orbit-depth = {MAX_DEPTH}: no verdict on the content",
            cert.subdivision
        );
        return Err(Rejection::new(Code::TooLarge, Locus::Limit { name: "max-orbit-depth".into() }, msg));
    }
    let triple = |path: &str, t: &(String, String, String)| -> Result<[F; 3], Rejection> {
        Ok([
            number(&format!("{path}[0]"), &t.0, limits)?,
            number(&format!("{path}[1]"), &t.1, limits)?,
            number(&format!("{path}[2]"), &t.2, limits)?,
        ])
    };
    let (centre, a, delta) = match &cert.set {
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
                return Err(Rejection::at_field(Code::DegenerateSet, "set.delta", "delta must be > 0"));
            }
            (centre, a, delta)
        }
        OrbitSet::Box { lo, hi } => {
            let (lo, hi) = (triple("set.lo", lo)?, triple("set.hi", hi)?);
            if let Some(i) = (0..3).find(|&i| lo[i] >= hi[i]) {
                let msg = format!("lo >= hi in coordinate {i}: the box is empty or flat");
                return Err(Rejection::at_field(Code::DegenerateSet, "set", msg));
            }
            let two = F::from_i64(2);
            let mid = |i: usize| lo[i].plus(&hi[i]).over(&two).unwrap_or_else(F::zero);
            let half = |i: usize| hi[i].minus(&lo[i]).over(&two).unwrap_or_else(F::zero);
            let a =
                std::array::from_fn(|i| std::array::from_fn(|k| if i == k { half(i) } else { F::zero() }));
            ([mid(0), mid(1), mid(2)], a, F::one())
        }
    };
    let a_inv = inverse(&a).ok_or_else(|| {
        Rejection::at_field(Code::DegenerateSet, "set.axes", "the axes are linearly dependent")
    })?;
    let maps = Maps::new(&body);
    Ok(Orbit { maps, pattern, centre, a, a_inv, delta, depth: cert.subdivision, rho, lambda, period })
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

fn locus<F: Field>(b: &SubBox<F>, q: Quantity) -> Locus {
    let sub_box = Box::new(std::array::from_fn(|k| [to_canonical(&b.lo[k]), to_canonical(&b.hi[k])]));
    let (step, contact) = q.step_contact();
    Locus::OrbitBox { sub_box, depth: b.depth, step, contact }
}

fn rejection<F: Field>(b: &SubBox<F>, q: Quantity, wrong: bool) -> Rejection {
    let code = match q.condition() {
        1 => Code::PatternNotForced,
        2 => Code::SetNotInvariant,
        _ => Code::NoContraction,
    };
    let range: Vec<String> = (0..3)
        .map(|k| {
            format!(
                "[{}, {}]",
                crate::check::abbreviated(&to_canonical(&b.lo[k])),
                crate::check::abbreviated(&to_canonical(&b.hi[k]))
            )
        })
        .collect();
    let how = if wrong {
        "fails at the centre of".to_string()
    } else {
        format!("is not shown (interval bounds, {} bisections) on", b.depth)
    };
    let msg =
        format!("condition {}: {} {how} the sub-box y in {}", q.condition(), q.describe(), range.join(" x "));
    Rejection::new(code, locus(b, q), msg)
}

/// Checks an orbit certificate exactly over the field `F`: rule O1, then conditions 1-3 on every
/// sub-box. The first failing check is reported.
pub fn check_orbit<F: Field>(cert: &OrbitCertificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    let orbit = read_orbit_values::<F>(cert, limits)?;
    let boxes = cover(&orbit, limits)?;
    Ok(Accepted {
        claim: Claim::CompleteChatterFromSet,
        n: orbit.maps.n as u64,
        generators: 0,
        redundant: Vec::new(),
        pieces: Vec::new(),
        max_denominator_bits: 0,
        pcc: None,
        // There is no cone K here: the field does not apply (docs/certificate-format.md §14).
        contains_translation: false,
        region: None,
        pcc_boxes: None,
        orbit_boxes: Some(boxes),
    })
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
        crate::check::in_time(limits, "checking the sub-boxes of an orbit certificate")?;
        examined += 1;
        if examined > MAX_BOXES {
            let msg = format!(
                "more than the limit max-orbit-boxes = {MAX_BOXES} sub-boxes examined: no verdict on the content"
            );
            return Err(Rejection::new(Code::TooLarge, Locus::Limit { name: "max-orbit-boxes".into() }, msg));
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
