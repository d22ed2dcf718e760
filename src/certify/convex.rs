//! Certificates of general convex bodies (docs/model.md §11, format `chatter-family-certificate`): the family
//! finder, the family exactifier, then the kernel on both backends.
//!
//! The search and the exactifier work on the body scaled to size about 1 (contacts / R and
//! J / R^2, R a power of two): the maps are conjugated by D = diag(R, R, 1) (docs/model.md
//! §11.7 with L = I/R), so a family for the scaled body becomes one for the body itself by
//! (omega_x, omega_y, v) -> (omega_x / R, omega_y / R, v), exactly. Without it, a phone measured
//! in millimetres puts every cone within 1e-2 of the axis and the grids lose their precision.

use super::transport::{RegularPreimage, convex_certificate, regular_preimage, transport};
use super::{Attempt, ClaimChoice, Failure, Request, Timings, certify, claims_in, ladder_if, try_claims};
use crate::exact::{ParseLimits, Q, QExt, Ring};
use crate::exactify::family::exactify_family;
use crate::exactify::{ExactifyConfig, ExactifyError};
use crate::finder::family::{FamilyOutcome, FloatFamily, find_family};
use crate::finder::{FinderConfig, Search, Seed};
use chatter_kernel::certificate::{Claim, ConvexCertificate};
use chatter_kernel::model::linalg::{Vec3, mat_vec};
use chatter_kernel::model::{ConvexBody, Mat2, PccExclusion};
use chatter_kernel::verify::{Backend, MALACHITE, NUM, Verdict, verify_convex_on};
use nalgebra::Matrix2;
use std::time::Instant;

/// A certification request for a general convex body.
#[derive(Clone)]
pub struct ConvexRequest {
    /// The body (at gamma, or at the lower end of an interval of gamma).
    pub body: ConvexBody<Q>,
    /// The upper end of an interval [gamma, gamma_hi] the certificate must hold on (`None`: a
    /// single gamma; docs/certificate-format.md §13, version 2).
    pub gamma_hi: Option<Q>,
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
            gamma_hi: None,
            claim: ClaimChoice::Strongest,
            finder: FinderConfig::default(),
            exactify: ExactifyConfig::default(),
            backends: [MALACHITE, NUM],
        }
    }
}

impl ConvexRequest {
    /// The body at each end of the request's gamma: one body, or two for an interval.
    pub fn ends(&self) -> Result<Vec<ConvexBody<Q>>, Failure> {
        let mut out = vec![self.body.clone()];
        if let Some(hi) = self.gamma_hi.as_ref().filter(|hi| *hi != self.body.gamma()) {
            let b = &self.body;
            let body = ConvexBody::new(b.contacts().to_vec(), b.inertia().clone(), hi.clone());
            // Only gamma differs from a valid body, so the error is gamma's range.
            out.push(body.map_err(|e| Failure::GammaOutOfRange(format!("the body at gamma = {hi}: {e}")))?);
        }
        Ok(out)
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
    /// How the certificate was made: [`FAMILY`] or [`TRANSPORTED`] (`None`: not certified).
    pub method: Option<&'static str>,
    /// Facts worth telling the user (e.g. why a weaker claim was certified).
    pub notes: Vec<String>,
}

/// The method of a certificate from the family finder and exactifier (docs/model.md §11.12).
pub const FAMILY: &str = "family finder + exactifier";
/// The method of a certificate transported from a regular polygon's (docs/model.md §11.12, 5.).
pub const TRANSPORTED: &str = "transport from a regular polygon certificate";

/// The normalising map L of the search (docs/model.md §11.12): a rational approximation, on a
/// grid of 2^-20 of its size, of (2 Σ / n)^(-1/2) with Σ = Σ_k r_k r_kᵀ the contacts' second
/// moment, so that the image body has contacts of mean square radius about 1 spread evenly (an
/// affine image of a regular polygon goes back to a rotated regular polygon, up to the rounding).
/// Symmetric positive definite, so det L > 0.
pub fn normaliser(body: &ConvexBody<Q>) -> Mat2<Q> {
    let n = body.n() as f64;
    let mut s = Matrix2::<f64>::zeros();
    for r in body.contacts() {
        let v = nalgebra::Vector2::new(r[0].to_f64(), r[1].to_f64());
        s += v * v.transpose() * (2.0 / n);
    }
    let e = s.symmetric_eigen();
    let inv_sqrt = e.eigenvectors
        * Matrix2::from_diagonal(&e.eigenvalues.map(|x| 1.0 / x.max(f64::MIN_POSITIVE).sqrt()))
        * e.eigenvectors.transpose();
    let size = inv_sqrt.abs().max().max(f64::MIN_POSITIVE);
    let unit = (size.log2().floor() - 20.0).clamp(-1000.0, 1000.0).exp2();
    let round = |x: f64| {
        let q = Q::from_f64_exact((x / unit).round()).unwrap_or_else(|| Q::int(0));
        q.times(&Q::from_f64_exact(unit).expect("a power of two"))
    };
    let off = round(0.5 * (inv_sqrt[(0, 1)] + inv_sqrt[(1, 0)]));
    [[round(inv_sqrt[(0, 0)]), off.clone()], [off, round(inv_sqrt[(1, 1)])]]
}

/// The image of `body` under `l` (det L > 0) and the map T⁻¹ = diag(adj L, 1) that carries
/// generators of the image's cones back to the body's (docs/model.md §11.7).
pub fn normalised(body: &ConvexBody<Q>, l: &Mat2<Q>) -> Option<(ConvexBody<Q>, Mat2<Q>)> {
    let image = crate::model::affine::affine_image(body, l)?;
    let adj = [[l[1][1].clone(), l[0][1].negated()], [l[1][0].negated(), l[0][0].clone()]];
    Some((image.body, adj))
}

/// Generators of the normalised body's cones as generators for the body: g = T⁻¹ g'.
fn carried_back(cones: Vec<Vec<[Q; 3]>>, adj: &Mat2<Q>) -> Vec<Vec<Vec3<Q>>> {
    let back = |[a, b, v]: [Q; 3]| {
        let x = adj[0][0].times(&a).plus(&adj[0][1].times(&b));
        let y = adj[1][0].times(&a).plus(&adj[1][1].times(&b));
        [x, y, v]
    };
    cones.into_iter().map(|c| c.into_iter().map(back).collect()).collect()
}

/// The strongest claim about drops: `CompleteChatterFromAllDown` when every adjacent pair's PCC
/// quadratic excludes PCC (rule K4, Lemma 11.5), else `CcOrPccFromAllDown` with a note.
/// The failure's text starts with `at` (which end of an interval of gamma, or nothing).
fn strongest(
    body: &ConvexBody<Q>,
    at: &str,
    choice: ClaimChoice,
    notes: &mut Vec<String>,
) -> Result<Claim, Failure> {
    let n = body.n();
    for k in 0..n {
        let quad = body
            .pair_pcc_quadratic(k as i64)
            .map_err(|v| Failure::Internal(format!("model error: det(I - I_{k} I_{}) = {v}", (k + 1) % n)))?;
        if quad.exclusion() == PccExclusion::Excluded {
            continue;
        }
        let text = format!(
            "{at}contacts {k} and {}: det(tI - I_{k} I_{}) = (t - 1)(t^2 + ({}) t + ({})), discriminant {}",
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

/// [`strongest`] at every end of the request's gamma: the weakest of them (rule K4 must hold at
/// both ends of an interval).
fn strongest_at(
    ends: &[ConvexBody<Q>],
    choice: ClaimChoice,
    notes: &mut Vec<String>,
) -> Result<Claim, Failure> {
    let mut claim = Claim::CompleteChatterFromAllDown;
    for body in ends {
        let at = if ends.len() > 1 {
            format!("at the end gamma = {} of the interval: ", body.gamma())
        } else {
            String::new()
        };
        claim = claim.min(strongest(body, &at, choice, notes)?);
        if claim < Claim::CompleteChatterFromAllDown {
            break;
        }
    }
    Ok(claim)
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

/// The search, the exactifier and the kernel for one claim. `body` is the normalised body, `adj`
/// carries its generators back to `req.body`, the body of the certificate.
fn family_attempt(
    req: &ConvexRequest,
    bodies: &[ConvexBody<Q>],
    adj: &Mat2<Q>,
    claim: Claim,
    t: &mut Timings,
) -> Attempt<ConvexCertificate> {
    let mut exact_seeds = vec![Vec::new(); bodies[0].n()];
    for body in bodies {
        match seeds(body, claim) {
            Ok(s) => exact_seeds.iter_mut().zip(s).for_each(|(all, s)| all.extend(s)),
            Err(f) => return Attempt::failed(f, None),
        }
    }
    let seed = if claim == Claim::EffectivelyInvariant { Seed::Translation } else { Seed::AllDown };
    let start = Instant::now();
    let outcome = find_family(&FloatFamily::of_ends(bodies), seed, &req.finder);
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
    // Close to the threshold the slack alone can push a cone over v = 0: retry then too.
    let retry = |e: &ExactifyError| {
        matches!(e, ExactifyError::NoConvergence { .. } | ExactifyError::TransitionAbove { .. })
    };
    let ex = ladder_if(&req.exactify, retry, |c| exactify_family(bodies, &polys, &exact_seeds, c));
    t.exactify += start.elapsed();
    let cones = match ex {
        Ok(ex) => carried_back(ex.cones, adj),
        Err(e) => return Attempt::failed(Failure::Exactify(e), summary),
    };
    let producer = format!("chatter {} certify ({FAMILY})", env!("CARGO_PKG_VERSION"));
    let cert = convex_certificate(&req.body, req.gamma_hi.as_ref(), claim, &cones, &producer);
    kernel_check(req, cert, FAMILY, summary, t)
}

/// The kernel on the request's backends; the attempt records the verdict.
fn kernel_check(
    req: &ConvexRequest,
    cert: ConvexCertificate,
    method: &'static str,
    finder: Option<Search<usize>>,
    t: &mut Timings,
) -> Attempt<ConvexCertificate> {
    let start = Instant::now();
    let verdict = verify_convex_on(&cert, ParseLimits::default(), &req.backends);
    t.kernel += start.elapsed();
    match verdict {
        Verdict::Accepted(a) => {
            Attempt { result: Ok(cert), finder, method: Some(method), bits: a.max_denominator_bits }
        }
        Verdict::Rejected(rej) => Attempt::failed(Failure::Kernel(rej), finder),
        Verdict::Disagree(s) => {
            Attempt::failed(Failure::Internal(format!("the backends disagree: {s}")), finder)
        }
    }
}

/// The fallback of docs/model.md §11.12 (5.): the regular pipeline certifies the regular body
/// `pre` at the body's gamma and claim, [`transport`] carries its cone to the body (§11.7), and the
/// kernel checks the family certificate on both backends like any other.
fn transported(
    req: &ConvexRequest,
    pre: &RegularPreimage,
    claim: Claim,
    t: &mut Timings,
) -> Attempt<ConvexCertificate> {
    let gamma = [req.body.gamma().clone(), req.gamma_hi.clone().unwrap_or_else(|| req.body.gamma().clone())];
    let mut r = Request::boxed(pre.n as u64, [pre.kappa.clone(), pre.kappa.clone()], gamma);
    (r.claim, r.finder, r.exactify, r.backends) =
        (ClaimChoice::Exactly(claim), req.finder, req.exactify, req.backends);
    let regular = certify(&r);
    t.finder += regular.timings.finder;
    t.exactify += regular.timings.exactify;
    t.kernel += regular.timings.kernel;
    let cert = match regular.result {
        Ok(c) => c,
        Err(f) => return Attempt::failed(f, regular.finder),
    };
    match transport(&req.body, &cert) {
        Ok(family) => kernel_check(req, family, TRANSPORTED, regular.finder, t),
        Err(e) => Attempt::failed(Failure::Internal(format!("transport: {e}")), regular.finder),
    }
}

/// Whether a failure of the family route may be the pipeline's (search, exactifier, kernel)
/// rather than a fact about the body (a seed above the floor, PCC, gamma) or a bug.
fn worth_a_fallback(f: &Failure) -> bool {
    matches!(f, Failure::Finder(_) | Failure::Exactify(_) | Failure::NoFamily { .. } | Failure::Kernel(_))
}

/// One claim: the family route, then, for an affine image of a regular polygon whose family
/// route failed, the transport; `notes` says which route certified or why both failed.
fn attempt(
    req: &ConvexRequest,
    (body, adj): (&[ConvexBody<Q>], &Mat2<Q>),
    pre: Option<&RegularPreimage>,
    claim: Claim,
    t: &mut Timings,
    notes: &mut Vec<String>,
) -> Attempt<ConvexCertificate> {
    let first = family_attempt(req, body, adj, claim, t);
    let (Some(pre), Err(f)) = (pre, &first.result) else { return first };
    if !worth_a_fallback(f) {
        return first;
    }
    let second = transported(req, pre, claim, t);
    let what = format!("the image of the regular n = {} body with kappa = {}", pre.n, pre.kappa);
    match &second.result {
        Ok(_) => notes.push(format!("certified by {TRANSPORTED}: the body is {what} (docs/model.md §11.7); the family finder + exactifier failed: {f}")),
        Err(g) => notes.push(format!("{TRANSPORT_FAILED} (the body is {what}): {g}")),
    }
    if second.result.is_ok() { second } else { first }
}

/// The start of the note on a failed transport (the bisection's reasons repeat it).
pub const TRANSPORT_FAILED: &str = "transport from the regular polygon failed too";

/// Runs the pipeline for a general body: claims strongest first unless one is asked for.
pub fn certify_convex(req: &ConvexRequest) -> ConvexReport {
    let mut notes = Vec::new();
    let failed = |f, notes| {
        let (timings, finder, method) = (Timings::default(), None, None);
        ConvexReport { result: Err(f), finder, timings, max_denominator_bits: 0, method, notes }
    };
    let ends = match req.ends() {
        Ok(e) => e,
        Err(f) => return failed(f, notes),
    };
    let range = [ends[0].gamma(), ends[ends.len() - 1].gamma()];
    let claims = match claims_in(req.claim, range, |n| strongest_at(&ends, req.claim, n), &mut notes) {
        Ok(c) => c,
        Err(f) => return failed(f, notes),
    };
    let l = normaliser(&req.body);
    let Some(normal) = ends.iter().map(|b| normalised(b, &l)).collect::<Option<Vec<_>>>() else {
        let f = Failure::Internal("the normalising map of the search is not invertible".into());
        return failed(f, notes);
    };
    let adj = normal[0].1.clone();
    let bodies: Vec<ConvexBody<Q>> = normal.into_iter().map(|(b, _)| b).collect();
    let pre = regular_preimage(&req.body);
    let mut extra = Vec::new();
    let run = |c, t: &mut Timings| attempt(req, (&bodies, &adj), pre.as_ref(), c, t, &mut extra);
    let (a, timings, mut notes) = try_claims(req.claim, claims, run, notes);
    notes.append(&mut extra);
    let (result, finder, method) = (a.result, a.finder, a.method);
    ConvexReport { result, finder, timings, max_denominator_bits: a.bits, method, notes }
}
