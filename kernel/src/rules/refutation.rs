//! Refutations (feature `refutation`; docs/certificate-format.md §10, why: docs/kernel-soundness.md
//! §2 "Refutations"): an exact derivation of velocities that every convex cone K containing the
//! claim's seeds and satisfying S_j(K ∩ C_j) ⊆ K must contain, ending in a non-zero velocity with
//! v >= 0. No certificate of the claim can then exist at this point: every non-zero vector of a
//! certificate's cone has v < 0. Rules, in the order they are checked:
//!
//! - the file: the header, a body at a point (`parameter-out-of-range`), at most max-generators
//!   points (`too-large`), the numbers, a body the model accepts (`parameter-out-of-range`);
//! - steps (`step-failed` at the step): a `Seed` names a seed of the claim; a `Combination` has at
//!   least one term, each an earlier point with a canonical coefficient >= 0; an `Image` applies
//!   an existing S_j to an earlier point that satisfies the inequalities of C_j;
//! - the end (`step-failed` at the last step): the last point is non-zero with v >= 0.
//!
//! The points are computed here from the body, never read from the file.

use crate::exact::{Field, NumberError, OrderedField, ParseLimits, parse_canonical, to_canonical};
use crate::model::Shape;
use crate::reject::{Code, Detail, KindCounted, KindDetail, KindLocus, Rejection};
use crate::syntax::cone::{Body, Claim, Param};
use crate::syntax::numbers::{at_most, in_time, number};
use crate::syntax::refutation::{Refutation, Step};
use crate::syntax::{Kind, expect};

/// What an accepted refutation established.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refuted {
    /// The claim refuted (and every stronger one).
    pub claim: Claim,
    /// Number of contacts.
    pub n: u64,
    /// Number of derived points.
    pub points: usize,
    /// The last point, canonical text.
    pub last: Vec<String>,
    /// Whether its v is > 0 (else = 0): then every cone containing the seeds and invariant in the
    /// paper's sense even violates the paper's condition v <= 0.
    pub v_positive: bool,
}

/// Why a refutation is rejected (besides the header, numbers and limits).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Failure {
    /// kappa or gamma is an interval.
    NotAtPoint,
    /// A point that is not an earlier point.
    NotEarlier(usize),
    /// A seed that does not exist.
    NoSeed {
        /// The seed named.
        index: usize,
        /// The seeds of the claim.
        seeds: usize,
    },
    /// A combination without terms.
    NoTerms,
    /// A coefficient that is not a canonical number.
    Coefficient {
        /// The text.
        text: String,
        /// Why.
        error: NumberError,
    },
    /// A negative coefficient, of this point.
    Negative(usize),
    /// A map S_step that does not exist (`maps` maps).
    NoMap {
        /// The step named.
        step: usize,
        /// The number of maps, n - 1.
        maps: usize,
    },
    /// Point `of` does not satisfy inequality `inequality` of C_step.
    NotInCone {
        /// The point.
        of: usize,
        /// j of C_j.
        step: usize,
        /// The inequality.
        inequality: usize,
    },
    /// The last point has v < 0 (its value).
    LastBelow(String),
    /// The last point is zero.
    LastZero,
    /// No points.
    NoPoints,
}

/// The model as matrices and covectors of the body's dimension d (2 for the rod, else 3).
struct Maps<F> {
    seeds: Vec<Vec<F>>,
    steps: Vec<Vec<Vec<F>>>,
    cones: Vec<Vec<Vec<F>>>,
    /// v as a covector: (0, 0, 1), or (1/2, 1/2) for the rod.
    v: Vec<F>,
}

fn apply<F: OrderedField>(m: &[Vec<F>], x: &[F]) -> Vec<F> {
    m.iter().map(|row| row.iter().zip(x).fold(F::zero(), |acc, (a, b)| acc.plus(&a.times(b)))).collect()
}

fn dot<F: OrderedField>(a: &[F], b: &[F]) -> F {
    a.iter().zip(b).fold(F::zero(), |acc, (x, y)| acc.plus(&x.times(y)))
}

fn maps<F: Field>(shape: &Shape<F>, claim: Claim) -> Maps<F> {
    let rows = |m: &[Vec<F>]| m.to_vec();
    let (i0, down, d, steps, cones, v) = match shape {
        Shape::Rod(r) => {
            let m2 = |m: [[F; 2]; 2]| m.iter().map(|r| r.to_vec()).collect::<Vec<_>>();
            let half = F::from_ratio(1, 2);
            (
                m2(r.impact(0)),
                vec![F::from_i64(-1); 2],
                r.all_down_generators().iter().map(|g| g.to_vec()).collect::<Vec<_>>(),
                vec![m2(r.step())],
                vec![r.next_contact_cone().iter().map(|l| l.to_vec()).collect()],
                vec![half.clone(), half],
            )
        }
        Shape::Polygon(p) => {
            let m3 = |m: [[F; 3]; 3]| m.iter().map(|r| r.to_vec()).collect::<Vec<_>>();
            let js = 1..p.n() as i64;
            (
                m3(p.impact(0)),
                vec![F::from_i64(-1); 3],
                p.all_down_generators().iter().map(|g| g.to_vec()).collect(),
                js.clone().map(|j| m3(p.step(j))).collect(),
                js.map(|j| p.next_contact_cone(j).iter().map(|l| l.to_vec()).collect()).collect(),
                vec![F::zero(), F::zero(), F::one()],
            )
        }
    };
    let drops = if claim == Claim::EffectivelyInvariant { vec![down] } else { d };
    Maps { seeds: drops.iter().map(|g| apply(&rows(&i0), g)).collect(), steps, cones, v }
}

/// Checks a refutation exactly over `F`; the first failing step is reported.
pub fn check<F: Field>(r: &Refutation, limits: ParseLimits) -> Result<Refuted, Rejection> {
    expect(&r.format, r.version, Kind::Refutation)?;
    let Body::RegularPolygon { n, kappa: Param::Point(k), gamma: Param::Point(g) } = &r.body else {
        return Err(Rejection::at(
            Code::ParameterOutOfRange,
            "body",
            KindDetail::Refutation(Failure::NotAtPoint),
        ));
    };
    at_most("max-generators", r.points.len(), limits.max_generators, KindCounted::Points.into())?;
    let shape = Shape::new(*n, number("body.kappa", k, limits)?, number("body.gamma", g, limits)?)
        .map_err(|e| Rejection::at(Code::ParameterOutOfRange, "body", Detail::Body(e)))?;
    let m = maps(&shape, r.refutes);
    let mut pts: Vec<Vec<F>> = Vec::with_capacity(r.points.len());
    for (index, s) in r.points.iter().enumerate() {
        in_time(limits, "checking a refutation")?;
        let fail = |f: Failure| {
            Rejection::new(
                Code::StepFailed,
                KindLocus::Step { index, id: s.kind().into() },
                KindDetail::Refutation(f),
            )
        };
        pts.push(point(&m, &pts, s, limits).map_err(fail)?);
    }
    let Some(last) = pts.last() else {
        return Err(Rejection::at(Code::StepFailed, "points", KindDetail::Refutation(Failure::NoPoints)));
    };
    let v = dot(&m.v, last);
    if v.is_negative() || last.iter().all(|x| x.is_zero()) {
        let index = pts.len() - 1;
        let f = if v.is_negative() { Failure::LastBelow(to_canonical(&v)) } else { Failure::LastZero };
        let locus = KindLocus::Step { index, id: r.points[index].kind().into() };
        return Err(Rejection::new(Code::StepFailed, locus, KindDetail::Refutation(f)));
    }
    Ok(Refuted {
        claim: r.refutes,
        n: *n,
        points: pts.len(),
        last: last.iter().map(to_canonical).collect(),
        v_positive: v.is_positive(),
    })
}

/// The point derived by step `s` from the earlier points `pts`.
fn point<F: Field>(m: &Maps<F>, pts: &[Vec<F>], s: &Step, limits: ParseLimits) -> Result<Vec<F>, Failure> {
    let earlier = |i: usize| pts.get(i).ok_or(Failure::NotEarlier(i));
    match s {
        Step::Seed { index } => {
            m.seeds.get(*index).cloned().ok_or(Failure::NoSeed { index: *index, seeds: m.seeds.len() })
        }
        Step::Combination { terms } => {
            if terms.is_empty() {
                return Err(Failure::NoTerms);
            }
            let mut sum = vec![F::zero(); m.v.len()];
            for (i, c) in terms {
                let c: F = parse_canonical(c, limits)
                    .map_err(|error| Failure::Coefficient { text: c.clone(), error })?;
                if c.is_negative() {
                    return Err(Failure::Negative(*i));
                }
                sum = sum.iter().zip(earlier(*i)?).map(|(a, b)| a.plus(&c.times(b))).collect();
            }
            Ok(sum)
        }
        Step::Image { step, of } => {
            let j = step.wrapping_sub(1);
            let (Some(s_j), Some(c_j)) = (m.steps.get(j), m.cones.get(j)) else {
                return Err(Failure::NoMap { step: *step, maps: m.steps.len() });
            };
            let x = earlier(*of)?;
            if let Some(l) = c_j.iter().position(|l| dot(l, x).is_negative()) {
                return Err(Failure::NotInCone { of: *of, step: *step, inequality: l });
            }
            Ok(apply(s_j, x))
        }
    }
}
