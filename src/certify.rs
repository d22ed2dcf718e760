//! The certification pipeline: float finder -> exactifier -> trusted kernel (both backends).
//! A certificate is returned only if the kernel accepts it on both backends.

use crate::exact::{ParseLimits, Q, QExt, Ring};
use crate::exactify::{ExactifyConfig, ExactifyError, exactify};
use crate::finder::{FinderConfig, FinderOutcome, Seed, find_cone};
use crate::model::{FloatBody, body, translation_down};
use crate::verify::{BackendVerdict, verify_both};
use chatter_kernel::certificate::{
    Body as CertBody, Certificate, Claim, Coordinates, FORMAT, Generator, VERSION,
};
use chatter_kernel::model::Polygon as Body;
use chatter_kernel::model::linalg::mat_vec;
use chatter_kernel::model::pcc_quadratic;
use chatter_kernel::model::{Rod, mat2_vec};
use std::time::{Duration, Instant};

/// Which claim to certify.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClaimChoice {
    /// The strongest claim that the pipeline can certify.
    Strongest,
    Exactly(Claim),
}

/// A certification request.
#[derive(Clone, Debug)]
pub struct Request {
    pub n: u64,
    pub kappa: Q,
    pub gamma: Q,
    pub claim: ClaimChoice,
    pub finder: FinderConfig,
    pub exactify: ExactifyConfig,
}

impl Request {
    pub fn new(n: u64, kappa: Q, gamma: Q) -> Self {
        Request {
            n,
            kappa,
            gamma,
            claim: ClaimChoice::Strongest,
            finder: FinderConfig::default(),
            exactify: ExactifyConfig::default(),
        }
    }
}

/// Time spent per phase.
#[derive(Clone, Copy, Debug, Default)]
pub struct Timings {
    pub finder: Duration,
    pub exactify: Duration,
    pub kernel: Duration,
}

/// Why no certificate was produced.
#[derive(Clone, Debug)]
pub enum Failure {
    /// The body is invalid or unsupported.
    Body(String),
    /// `CompleteChatterFromAllDown` was requested but the PCC Lemma does not apply.
    PccNotExcluded(String),
    /// The float finder found no cone or ran out of budget.
    Finder(FinderOutcome),
    Exactify(ExactifyError),
    /// The kernel rejected the exactified cone (a bug in the untrusted side).
    Kernel(String),
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::Body(s) => write!(f, "invalid body: {s}"),
            Failure::PccNotExcluded(s) => {
                write!(f, "PCC is not excluded, so complete chatter cannot be certified: {s}")
            }
            Failure::Finder(FinderOutcome::NoCone { iteration, step }) => write!(
                f,
                "no effectively invariant cone contains the seed (an image under S_{step} has v >= 0 at iteration {iteration})"
            ),
            Failure::Finder(FinderOutcome::Inconclusive { iterations, reason }) => {
                write!(f, "finder inconclusive after {iterations} iterations: {reason}")
            }
            Failure::Finder(FinderOutcome::Found { .. }) => write!(f, "finder succeeded"),
            Failure::Exactify(e) => write!(f, "exactifier failed: {e}"),
            Failure::Kernel(s) => write!(f, "kernel rejected the exactified cone: {s}"),
        }
    }
}

/// The outcome of a certification.
#[derive(Clone, Debug)]
pub struct Report {
    pub result: Result<Certificate, Failure>,
    /// The finder's verdict for the seed that was finally used.
    pub finder: Option<FinderOutcome>,
    pub timings: Timings,
    pub max_denominator_bits: u64,
    /// Facts worth telling the user (e.g. why a weaker claim was certified).
    pub notes: Vec<String>,
}

fn seed_of(claim: Claim) -> Seed {
    if claim == Claim::EffectivelyInvariant { Seed::Translation } else { Seed::AllDown }
}

/// The exact points the cone must contain for a claim.
fn exact_seeds(b: &Body<Q>, seed: Seed) -> Vec<[Q; 3]> {
    let i0 = b.impact(0);
    match seed {
        Seed::Translation => vec![mat_vec(&i0, &translation_down())],
        Seed::AllDown => b.all_down_generators().iter().map(|g| mat_vec(&i0, g)).collect(),
    }
}

/// Certifies one claim (no fallback).
fn certify_claim(
    req: &Request,
    b: &Body<Q>,
    fb: &FloatBody,
    claim: Claim,
    t: &mut Timings,
) -> (Result<Certificate, Failure>, Option<FinderOutcome>, u64) {
    let seed = seed_of(claim);
    let start = Instant::now();
    let outcome = find_cone(fb, seed, &req.finder);
    t.finder += start.elapsed();
    let FinderOutcome::Found { polygon, .. } = &outcome else {
        return (Err(Failure::Finder(outcome.clone())), Some(outcome), 0);
    };
    let start = Instant::now();
    let ex = exactify(b, polygon, &exact_seeds(b, seed), &req.exactify);
    t.exactify += start.elapsed();
    let ex = match ex {
        Ok(ex) => ex,
        Err(e) => return (Err(Failure::Exactify(e)), Some(outcome), 0),
    };
    let cone = ex.generators.iter().map(|g| Generator(g.iter().map(Q::to_string).collect())).collect();
    let cert = certificate(req, claim, cone, "float finder + exactifier");
    let (result, bits) = kernel_check(cert, t);
    (result, Some(outcome), bits)
}

/// Runs the kernel on both backends: the certificate and its largest denominator in bits if
/// accepted, else why not.
fn kernel_check(cert: Certificate, t: &mut Timings) -> (Result<Certificate, Failure>, u64) {
    let start = Instant::now();
    let verdict = verify_both(&cert, ParseLimits::default());
    t.kernel += start.elapsed();
    match verdict {
        BackendVerdict::Accepted(a) => (Ok(cert), a.max_denominator_bits),
        BackendVerdict::Rejected(r) => (Err(Failure::Kernel(r.to_string())), 0),
        BackendVerdict::Disagree(s) => (Err(Failure::Kernel(s)), 0),
    }
}

/// The rod's report: every claim is tried strongest first (with two contacts PCC is CC, so the
/// all-down claims coincide).
fn certify_rod_report(req: &Request, mut timings: Timings) -> Report {
    let claims: Vec<Claim> = match req.claim {
        ClaimChoice::Exactly(c) => vec![c],
        ClaimChoice::Strongest => vec![Claim::CompleteChatterFromAllDown, Claim::EffectivelyInvariant],
    };
    let mut notes = vec![
        "rod (n = 2): exact interval iteration, no float search; with two contacts PCC is CC".to_string(),
    ];
    let mut last = None;
    for claim in claims {
        let result = certify_rod(req, claim, &mut timings);
        if let Ok(c) = result {
            let (result, max_denominator_bits) = kernel_check(c, &mut timings);
            return Report { result, finder: None, timings, max_denominator_bits, notes };
        }
        if let (Err(e), ClaimChoice::Strongest) = (&result, req.claim) {
            notes.push(format!("{} not certified: {e}", claim.name()));
        }
        last = Some(result);
    }
    let result = last.expect("at least one claim");
    let finder = match &result {
        Err(Failure::Finder(f)) => Some(f.clone()),
        _ => None,
    };
    Report { result, finder, timings, max_denominator_bits: 0, notes }
}

fn claims_requested_pcc(req: &Request) -> bool {
    req.claim == ClaimChoice::Exactly(Claim::CompleteChatterFromAllDown)
}

/// The rod (n = 2): K = [lo, hi] in s = u0 / (-(u0 + u1)) on the line v = -1 is grown exactly
/// by the images of the ends of K ∩ C_1 until they stay inside. When a cone exists the iterates
/// converge to the attracting eigenvector of S_1; a small outward slack on every grown end lets
/// the iteration stop. No float search is needed in one dimension.
fn certify_rod(req: &Request, claim: Claim, t: &mut Timings) -> Result<Certificate, Failure> {
    let rod = Rod::new(req.kappa.clone(), req.gamma.clone()).map_err(|e| Failure::Body(e.to_string()))?;
    let s_of = |p: &[Q; 2]| -> Option<Q> {
        let w = -(&p[0] + &p[1]);
        (w > Q::int(0)).then(|| &p[0] / &w)
    };
    let point = |s: &Q| -> [Q; 2] { [s.clone(), -(s + &Q::int(1))] }; // u0 + u1 = -1, s = u0
    let i0 = rod.impact(0);
    let seeds: Vec<[Q; 2]> = match claim {
        Claim::EffectivelyInvariant => vec![[Q::int(-1), Q::int(-1)]],
        _ => vec![[Q::int(0), Q::int(-1)], [Q::int(-1), Q::int(0)]],
    };
    let start = Instant::now();
    let seed_s: Vec<Q> = seeds.iter().map(|g| s_of(&mat2_vec(&i0, g)).expect("post-impact v < 0")).collect();
    let (mut lo, mut hi) = (seed_s.iter().min().unwrap().clone(), seed_s.iter().max().unwrap().clone());
    let step = rod.step();
    let max_iter = req.finder.max_iterations;
    let mut done = false;
    for it in 0..max_iter {
        let mut ends = vec![];
        if hi >= Q::int(0) {
            ends.push(if lo < Q::int(0) { Q::int(0) } else { lo.clone() });
            ends.push(hi.clone());
        }
        let mut grew = false;
        for e in ends {
            let img = mat2_vec(&step, &point(&e));
            let Some(s) = s_of(&img) else {
                t.finder += start.elapsed();
                return Err(Failure::Finder(FinderOutcome::NoCone { iteration: it, step: 1 }));
            };
            // A grown end goes a little beyond the image (the orbit approaches the attracting
            // eigenvector from inside and would never stop), rounded outwards to a dyadic.
            let slack = (&hi - &lo + s.abs()) * Q::new(1, 1 << 20);
            if s < lo {
                lo = (&s - &slack).floor_dyadic(40);
                grew = true;
            } else if s > hi {
                hi = (&s + &slack).ceil_dyadic(40);
                grew = true;
            }
        }
        if !grew && lo < hi {
            done = true;
            break;
        }
        if !grew {
            // A single ray (a fixed point): widen to a 2-D cone and continue.
            hi = &hi + &Q::new(1, 1 << 20);
        }
    }
    t.finder += start.elapsed();
    if !done {
        let reason = format!("the exact interval iteration did not settle within {max_iter} iterations");
        return Err(Failure::Finder(FinderOutcome::Inconclusive { iterations: max_iter, reason }));
    }
    // Generators on v = -1: (u0, u1) = 2 (s, -1 - s).
    let cone = [lo, hi].into_iter().map(|s| {
        let p = point(&s);
        Generator(vec![(&p[0] * &Q::int(2)).to_string(), (&p[1] * &Q::int(2)).to_string()])
    });
    Ok(certificate(req, claim, cone.collect(), "exact interval iteration"))
}

fn certificate(req: &Request, claim: Claim, cone: Vec<Generator>, how: &str) -> Certificate {
    Certificate {
        format: FORMAT.to_string(),
        version: VERSION,
        body: CertBody::RegularPolygon {
            n: req.n,
            kappa: req.kappa.to_string(),
            gamma: req.gamma.to_string(),
        },
        coordinates: Coordinates::ContactVelocities,
        claim,
        cone,
        producer: format!("chatter {} certify ({how})", env!("CARGO_PKG_VERSION")),
    }
}

/// Runs the pipeline.
pub fn certify(req: &Request) -> Report {
    let mut timings = Timings::default();
    let mut notes = Vec::new();
    if req.n == 2 {
        return certify_rod_report(req, timings);
    }
    let b = match body(req.n, &req.kappa, &req.gamma) {
        Ok(b) => b,
        Err(e) => {
            let result = Err(Failure::Body(e.to_string()));
            return Report { result, finder: None, timings, max_denominator_bits: 0, notes };
        }
    };
    let fb = FloatBody::new(&b);
    let quad = pcc_quadratic(&b).expect("S_(n-1) S_1 always fixes m_(0,1)");
    let pcc_excluded = quad.excludes_pcc();
    let pcc_text = format!(
        "det(tI - S_{} S_1) = (t - 1)(t^2 + ({}) t + ({})), discriminant {} ({})",
        b.n() - 1,
        quad.p,
        quad.q,
        quad.discriminant,
        if quad.discriminant.is_negative() { "complex roots" } else { "real roots" }
    );
    if claims_requested_pcc(req) && !pcc_excluded {
        let result = Err(Failure::PccNotExcluded(pcc_text));
        return Report { result, finder: None, timings, max_denominator_bits: 0, notes };
    }
    if !pcc_excluded {
        notes.push(format!("the PCC Lemma does not apply: {pcc_text}"));
        if b.n() >= 4 {
            notes.push(format!(
                "this contradicts the paper, which states that the Lemma's condition (all eigenvalues real) is never met for n >= 4; here n = {}",
                b.n()
            ));
        }
    }
    let claims: Vec<Claim> = match req.claim {
        ClaimChoice::Exactly(c) => vec![c],
        ClaimChoice::Strongest if pcc_excluded => {
            vec![Claim::CompleteChatterFromAllDown, Claim::EffectivelyInvariant]
        }
        ClaimChoice::Strongest => vec![Claim::CcOrPccFromAllDown, Claim::EffectivelyInvariant],
    };
    let mut last = None;
    for claim in claims {
        let (result, finder, bits) = certify_claim(req, &b, &fb, claim, &mut timings);
        if result.is_ok() {
            return Report { result, finder, timings, max_denominator_bits: bits, notes };
        }
        if let (Err(e), ClaimChoice::Strongest) = (&result, req.claim) {
            notes.push(format!("{} not certified: {e}", claim.name()));
        }
        last = Some((result, finder));
    }
    let (result, finder) = last.expect("at least one claim");
    Report { result, finder, timings, max_denominator_bits: 0, notes }
}
