//! Certificates of general convex bodies (docs/model.md §11, format version 4): the family
//! finder, the family exactifier, then the kernel on both backends.
//!
//! The search and the exactifier work on the body scaled to size about 1 (contacts / R and
//! J / R^2, R a power of two): the maps are conjugated by D = diag(R, R, 1) (docs/model.md
//! §11.7 with L = I/R), so a family for the scaled body becomes one for the body itself by
//! (omega_x, omega_y, v) -> (omega_x / R, omega_y / R, v), exactly. Without it, a phone measured
//! in millimetres puts every cone within 1e-2 of the axis and the grids lose their precision.

use super::transport::convex_certificate;
use super::{Attempt, ClaimChoice, Failure, Timings, claims_in, ladder, try_claims};
use crate::exact::{OrderedField, ParseLimits, Q, QExt, Ring};
use crate::exactify::ExactifyConfig;
use crate::exactify::family::exactify_family;
use crate::finder::family::{FamilyOutcome, FloatFamily, find_family};
use crate::finder::{FinderConfig, Search, Seed};
use chatter_kernel::certificate::{Claim, ConvexCertificate};
use chatter_kernel::model::linalg::{Vec3, mat_vec};
use chatter_kernel::model::{ConvexBody, PccExclusion};
use chatter_kernel::verify::{Backend, MALACHITE, NUM, Verdict, verify_convex_on};
use std::time::Instant;

/// A certification request for a general convex body.
#[derive(Clone)]
pub struct ConvexRequest {
    pub body: ConvexBody<Q>,
    pub claim: ClaimChoice,
    pub finder: FinderConfig,
    pub exactify: ExactifyConfig,
    /// The two backends the kernel runs on (a disagreement is an internal error).
    pub backends: [Backend; 2],
}

impl ConvexRequest {
    /// The strongest claim for `body`, default budgets, both backends.
    pub fn new(body: ConvexBody<Q>) -> ConvexRequest {
        ConvexRequest {
            body,
            claim: ClaimChoice::Strongest,
            finder: FinderConfig::default(),
            exactify: ExactifyConfig::default(),
            backends: [MALACHITE, NUM],
        }
    }
}

/// The outcome of a certification of a general body.
#[derive(Clone, Debug)]
pub struct ConvexReport {
    pub result: Result<ConvexCertificate, Failure>,
    /// The family search's verdict for the claim finally tried (Found: total vertices).
    pub finder: Option<Search<usize>>,
    pub timings: Timings,
    pub max_denominator_bits: u64,
    /// Facts worth telling the user (e.g. why a weaker claim was certified).
    pub notes: Vec<String>,
}

/// The power of two nearest (in log scale) to the largest contact distance.
pub fn length_scale(body: &ConvexBody<Q>) -> Q {
    let r2 = body.contacts().iter().map(|r| r[0].to_f64().powi(2) + r[1].to_f64().powi(2)).fold(0.0, f64::max);
    let e = (0.5 * r2.log2()).round().clamp(-200.0, 200.0) as i64;
    let two = Q::int(2);
    let p = (0..e.unsigned_abs()).fold(Q::int(1), |acc, _| acc.times(&two));
    if e >= 0 { p } else { Q::int(1).over(&p).expect("2^e > 0") }
}

/// The body with contacts / r and inertia / r^2 (same gamma).
pub fn scaled(body: &ConvexBody<Q>, r: &Q) -> ConvexBody<Q> {
    let d = |x: &Q| x.over(r).expect("r > 0");
    let r2 = r.times(r);
    let contacts = body.contacts().iter().map(|c| [d(&c[0]), d(&c[1])]).collect();
    let inertia = body.inertia().clone().map(|row| row.map(|x| x.over(&r2).expect("r > 0")));
    ConvexBody::new(contacts, inertia, body.gamma().clone()).expect("a scaled valid body is valid")
}

/// Generators of the scaled body's cones as generators for the body: omega divided by r.
fn unscaled(cones: Vec<Vec<[Q; 3]>>, r: &Q) -> Vec<Vec<Vec3<Q>>> {
    let d = |x: &Q| x.over(r).expect("r > 0");
    cones.into_iter().map(|c| c.into_iter().map(|[a, b, v]| [d(&a), d(&b), v]).collect()).collect()
}

/// The strongest claim about drops: `CompleteChatterFromAllDown` when every adjacent pair's PCC
/// quadratic excludes PCC (rule K4, Lemma 11.5), else `CcOrPccFromAllDown` with a note.
fn strongest(body: &ConvexBody<Q>, choice: ClaimChoice, notes: &mut Vec<String>) -> Result<Claim, Failure> {
    let n = body.n();
    for k in 0..n {
        let quad = body
            .pair_pcc_quadratic(k as i64)
            .map_err(|v| Failure::Internal(format!("model error: det(I - I_{k} I_{}) = {v}", (k + 1) % n)))?;
        if quad.exclusion() == PccExclusion::Excluded {
            continue;
        }
        let text = format!(
            "contacts {k} and {}: det(tI - I_{k} I_{}) = (t - 1)(t^2 + ({}) t + ({})), discriminant {}",
            (k + 1) % n,
            (k + 1) % n,
            quad.p,
            quad.q,
            quad.discriminant
        );
        if choice == ClaimChoice::Exactly(Claim::CompleteChatterFromAllDown) {
            return Err(Failure::PccNotExcluded(text));
        }
        notes.push(format!("the PCC Lemma (docs/model.md §11.6) does not apply: {text}"));
        return Ok(Claim::CcOrPccFromAllDown);
    }
    Ok(Claim::CompleteChatterFromAllDown)
}

/// The exact seeds of each K_i: I_i of the drops the claim covers (the downward translation, or
/// the generators of D), zero images left out; `Err` if one leaves with v >= 0.
fn seeds(body: &ConvexBody<Q>, claim: Claim) -> Result<Vec<Vec<Vec3<Q>>>, Failure> {
    let drops = if claim == Claim::EffectivelyInvariant {
        vec![[Q::int(0), Q::int(0), Q::int(-1)]]
    } else {
        body.all_down_generators()
    };
    let show = |p: &Vec3<Q>| format!("({}, {}, {})", p[0], p[1], p[2]);
    let mut out = Vec::with_capacity(body.n());
    for i in 0..body.n() as i64 {
        let m = body.impact(i);
        let mut s = Vec::new();
        for d in &drops {
            let after = mat_vec(&m, d);
            if after.iter().all(Ring::is_zero) {
                continue;
            }
            if !after[2].is_negative() {
                return Err(Failure::SeedNotBelow { seed: show(d), velocity: show(&after) });
            }
            s.push(after);
        }
        out.push(s);
    }
    Ok(out)
}

/// The search, the exactifier and the kernel for one claim. `body` is the scaled body, `r` the
/// scale, `original` the body of the certificate.
fn attempt(
    req: &ConvexRequest,
    body: &ConvexBody<Q>,
    r: &Q,
    claim: Claim,
    t: &mut Timings,
) -> Attempt<ConvexCertificate> {
    let exact_seeds = match seeds(body, claim) {
        Ok(s) => s,
        Err(f) => return Attempt::failed(f, None),
    };
    let seed = if claim == Claim::EffectivelyInvariant { Seed::Translation } else { Seed::AllDown };
    let start = Instant::now();
    let outcome = find_family(&FloatFamily::of(body), seed, &req.finder);
    t.finder += start.elapsed();
    let summary = Some(outcome.summary());
    let polys = match outcome {
        FamilyOutcome::Found { cones, .. } => cones,
        FamilyOutcome::NoCone { iteration, from, to } => {
            return Attempt::failed(Failure::NoFamily { iteration, from, to }, summary);
        }
        FamilyOutcome::Inconclusive { .. } => {
            return Attempt::failed(Failure::Finder(outcome.summary()), summary);
        }
    };
    let start = Instant::now();
    let ex = ladder(&req.exactify, |c| exactify_family(body, &polys, &exact_seeds, c));
    t.exactify += start.elapsed();
    let cones = match ex {
        Ok(ex) => unscaled(ex.cones, r),
        Err(e) => return Attempt::failed(Failure::Exactify(e), summary),
    };
    let producer = format!("chatter {} certify (family finder + exactifier)", env!("CARGO_PKG_VERSION"));
    let cert = convex_certificate(&req.body, claim, &cones, &producer);
    let start = Instant::now();
    let verdict = verify_convex_on(&cert, ParseLimits::default(), &req.backends);
    t.kernel += start.elapsed();
    let method = Some("family finder + exactifier");
    match verdict {
        Verdict::Accepted(a) => Attempt { result: Ok(cert), finder: summary, method, bits: a.max_denominator_bits },
        Verdict::Rejected(rej) => Attempt::failed(Failure::Kernel(rej), summary),
        Verdict::Disagree(s) => {
            Attempt::failed(Failure::Internal(format!("the backends disagree: {s}")), summary)
        }
    }
}

/// Runs the pipeline for a general body: claims strongest first unless one is asked for.
pub fn certify_convex(req: &ConvexRequest) -> ConvexReport {
    let mut notes = Vec::new();
    let g = req.body.gamma();
    let claims = match claims_in(req.claim, [g, g], |n| strongest(&req.body, req.claim, n), &mut notes) {
        Ok(c) => c,
        Err(f) => {
            let timings = Timings::default();
            return ConvexReport { result: Err(f), finder: None, timings, max_denominator_bits: 0, notes };
        }
    };
    let r = length_scale(&req.body);
    let body = scaled(&req.body, &r);
    let (a, timings, notes) = try_claims(req.claim, claims, |c, t| attempt(req, &body, &r, c, t), notes);
    ConvexReport { result: a.result, finder: a.finder, timings, max_denominator_bits: a.bits, notes }
}
