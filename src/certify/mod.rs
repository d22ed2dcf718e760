//! The certification pipeline: search -> exact cone -> trusted kernel (both backends).
//! A certificate is returned only if the kernel accepts it on both backends.
//!
//! Regular polygons: float finder, then exactifier. The rod: an exact search
//! ([`crate::finder::rod`]). Claims are tried strongest first unless one is asked for.

pub mod bisect;
pub mod convex;
mod field;
pub mod rest;
pub mod transport;
pub mod virtual_time;

use crate::exact::{OrderedField, ParseLimits, Q, QField};
use crate::exactify::{Exact, Exactified, ExactifyConfig, ExactifyError, exactify};
use crate::finder::geometry::P2;
use crate::finder::rod::{RodCone, find_rod_cone_box, s_of};
use crate::finder::{FinderConfig, Search, Seed, find_cone};
use crate::model::{FloatBody, translation_down};
use chatter_kernel::bivariate::{NotNegative, Rect, negative_on};
use chatter_kernel::certificate::{
    Body as CertBody, Certificate, Claim, Coordinates, FORMAT, Generator, Param, Rejection,
};
use chatter_kernel::check::MAX_PCC_BOXES;
use chatter_kernel::model::linalg::{Vec3, mat_vec};
use chatter_kernel::model::{
    PccExclusion, PccQuadratic, Polygon, Rod, Shape, Vec2, mat2_vec, pcc_polynomials, pcc_quadratic,
};
use chatter_kernel::verify::{Backend, MALACHITE, NUM, Verdict, verify_on};
use std::time::{Duration, Instant};

/// Which claim to certify.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClaimChoice {
    /// The strongest claim that the pipeline can certify.
    Strongest,
    /// The strongest claim about drops (`CcOrPccFromAllDown` or `CompleteChatterFromAllDown`),
    /// never `EffectivelyInvariant` alone.
    StrongestAboutDrops,
    Exactly(Claim),
}

/// A certification request: a point (kappa, gamma), or a box of parameters.
#[derive(Clone)]
pub struct Request {
    pub n: u64,
    pub kappa: Q,
    pub gamma: Q,
    /// For a box certificate: the upper corner (kappa, gamma) of the box [kappa, kappa_hi] x
    /// [gamma, gamma_hi]; `None` for a point.
    pub upper: Option<(Q, Q)>,
    pub claim: ClaimChoice,
    pub finder: FinderConfig,
    pub exactify: ExactifyConfig,
    /// The two backends the kernel runs on (a disagreement is an internal error).
    pub backends: [Backend; 2],
    /// Where cos(2 pi/n) is irrational, kappa as an element of Q(cos 2 pi/n) in canonical text
    /// (docs/certificate-format.md §12), for bodies whose kappa is irrational; `kappa` then holds
    /// a rational approximation, for display only.
    pub kappa_field: Option<String>,
}

/// The distinct corners (kappa, gamma) of [κ_lo, κ_hi] × [γ_lo, γ_hi] in the kernel's order:
/// (lo, lo), (hi, lo), (lo, hi), (hi, hi); one for a point.
pub fn corners(kappa: &[Q; 2], gamma: &[Q; 2]) -> Vec<(Q, Q)> {
    let mut out: Vec<(Q, Q)> = Vec::new();
    for (gi, ki) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
        let c = (kappa[ki].clone(), gamma[gi].clone());
        if !out.contains(&c) {
            out.push(c);
        }
    }
    out
}

impl Request {
    pub fn new(n: u64, kappa: Q, gamma: Q) -> Self {
        Request {
            n,
            kappa,
            gamma,
            upper: None,
            claim: ClaimChoice::Strongest,
            finder: FinderConfig::default(),
            exactify: ExactifyConfig::default(),
            backends: [MALACHITE, NUM],
            kappa_field: None,
        }
    }
}

impl Request {
    /// The budgets of a survey over many points or boxes (`chatter map`, `chatter cover`): the
    /// float finder stops after 3,000 iterations and the exactifier after 60 rounds without
    /// retries, so that no single point close to the CC threshold holds up the run (with the
    /// defaults of [`Request::new`] one such point took 12 s of a 15 s map). `chatter certify`
    /// keeps the larger budgets, which certify points within 1e-6 of the threshold.
    pub fn survey(mut self) -> Self {
        self.finder.max_iterations = 3000;
        self.exactify.max_rounds = 60;
        self.exactify.retry = false;
        self
    }

    /// A request for the box [kappa0, kappa1] x [gamma0, gamma1] (a point when both are equal).
    pub fn boxed(n: u64, kappa: [Q; 2], gamma: [Q; 2]) -> Self {
        let [k0, k1] = kappa;
        let [g0, g1] = gamma;
        let upper = (k0 != k1 || g0 != g1).then_some((k1, g1));
        Request { upper, ..Request::new(n, k0, g0) }
    }

    /// The distinct corners (kappa, gamma) in the kernel's order: (lo, lo), (hi, lo), (lo, hi),
    /// (hi, hi); one for a point.
    pub fn corners(&self) -> Vec<(Q, Q)> {
        let (k1, g1) = self.upper.clone().unwrap_or((self.kappa.clone(), self.gamma.clone()));
        corners(&[self.kappa.clone(), k1], &[self.gamma.clone(), g1])
    }

    /// "n=4 kappa=1/6 gamma=1/100", or with intervals for a box.
    pub fn describe(&self) -> String {
        match &self.upper {
            None => {
                let kappa = self.kappa_field.clone().unwrap_or_else(|| self.kappa.to_string());
                format!("n={} kappa={kappa} gamma={}", self.n, self.gamma)
            }
            Some((k1, g1)) => {
                format!("n={} kappa=[{}, {k1}] gamma=[{}, {g1}]", self.n, self.kappa, self.gamma)
            }
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
    /// A claim about drops was requested at gamma = 0 or 1.
    GammaOutOfRange(String),
    /// A drop the claim covers leaves with v >= 0 after its first impact (the body separates),
    /// so no cone in v < 0 can contain it and the claim cannot hold.
    SeedNotBelow {
        seed: String,
        velocity: String,
    },
    /// The search found no cone or ran out of budget (Found carries the number of rays).
    Finder(Search<usize>),
    Exactify(ExactifyError),
    /// The family search of a general body (docs/model.md §11.9) found a vertex of
    /// K_from ∩ C_(from,to) whose image under I_to has v >= 0: no family contains the seeds.
    NoFamily {
        iteration: usize,
        from: usize,
        to: usize,
    },
    /// The kernel rejected the exact cone (a bug in the untrusted side).
    Kernel(Rejection),
    /// The backends disagree: a bug in chatter or a bignum library.
    Internal(String),
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::Body(s) => write!(f, "invalid body: {s}"),
            Failure::GammaOutOfRange(s) => write!(f, "{s}"),
            Failure::PccNotExcluded(s) => {
                write!(f, "PCC is not excluded, so complete chatter cannot be certified: {s}")
            }
            Failure::SeedNotBelow { seed, velocity } => write!(
                f,
                "the drop with velocity {seed} has velocity {velocity} after its first impact, with v >= 0: the centre of mass no longer moves down, the body separates (ICC), so no cone can contain it"
            ),
            Failure::Finder(Search::NoCone { iteration, step }) => write!(
                f,
                "no effectively invariant cone contains the seed (an image under S_{step} has v >= 0 at iteration {iteration})"
            ),
            Failure::Finder(Search::Inconclusive { iterations, reason }) => {
                write!(f, "search inconclusive after {iterations} iterations: {reason}")
            }
            Failure::Finder(Search::Found { .. }) => write!(f, "search succeeded"),
            Failure::Exactify(e) => write!(f, "exactifier failed: {e}"),
            Failure::NoFamily { iteration, from, to } => write!(
                f,
                "no family of effectively invariant cones contains the seeds (a vertex of K_{from} ∩ C_({from},{to}) maps under I_{to} to v >= 0 at iteration {iteration})"
            ),
            Failure::Kernel(r) => write!(f, "kernel rejected the exact cone: {r}"),
            Failure::Internal(s) => write!(f, "internal error: {s}"),
        }
    }
}

/// The outcome of a certification.
#[derive(Clone, Debug)]
pub struct Report {
    pub result: Result<Certificate, Failure>,
    /// The search's verdict for the claim finally tried (Found carries the number of rays).
    pub finder: Option<Search<usize>>,
    /// How the cone was found.
    pub method: Option<&'static str>,
    pub timings: Timings,
    pub max_denominator_bits: u64,
    /// Facts worth telling the user (e.g. why a weaker claim was certified).
    pub notes: Vec<String>,
}

/// One claim's attempt (a regular-polygon certificate, or `C`).
struct Attempt<C = Certificate> {
    result: Result<C, Failure>,
    finder: Option<Search<usize>>,
    method: Option<&'static str>,
    bits: u64,
}

impl<C> Attempt<C> {
    fn failed(f: Failure, finder: Option<Search<usize>>) -> Self {
        Attempt { result: Err(f), finder, method: None, bits: 0 }
    }
}

fn certificate(req: &Request, claim: Claim, cone: Vec<Generator>, how: &str) -> Certificate {
    let param = |lo: &Q, hi: Option<&Q>| match hi {
        Some(hi) if hi != lo => Param::Interval(lo.to_string(), hi.to_string()),
        _ => Param::Point(lo.to_string()),
    };
    let (k1, g1) = (req.upper.as_ref().map(|u| &u.0), req.upper.as_ref().map(|u| &u.1));
    let body = match &req.upper {
        None => CertBody::RegularPolygon {
            n: req.n,
            kappa: req.kappa_field.clone().map_or_else(|| param(&req.kappa, None), Param::Point),
            gamma: param(&req.gamma, None),
        },
        Some(_) => {
            CertBody::RegularPolygon { n: req.n, kappa: param(&req.kappa, k1), gamma: param(&req.gamma, g1) }
        }
    };
    let mut cert = Certificate {
        format: FORMAT.to_string(),
        version: 1,
        body,
        coordinates: Coordinates::ContactVelocities,
        claim,
        cone,
        time_to_rest_bound: rest::bound_for(req, claim).map(|b| b.to_string()),
        producer: format!("chatter {} certify ({how})", env!("CARGO_PKG_VERSION")),
    };
    cert.version = crate::write::VersionNeeded::version_needed(&cert);
    cert
}

fn generator(coords: &[Q]) -> Generator {
    Generator(coords.iter().map(Q::to_string).collect())
}

/// Runs the kernel on the request's backends; the attempt records the verdict.
fn kernel_check(req: &Request, cert: Certificate, method: &'static str, t: &mut Timings) -> Attempt {
    let start = Instant::now();
    let verdict = verify_on(&cert, ParseLimits::default(), &req.backends);
    t.kernel += start.elapsed();
    let finder = Some(Search::Found { cone: cert.cone.len(), iterations: 0 });
    match verdict {
        Verdict::Accepted(a) => {
            Attempt { result: Ok(cert), finder, method: Some(method), bits: a.max_denominator_bits }
        }
        Verdict::Rejected(r) => Attempt::failed(Failure::Kernel(r), finder),
        Verdict::Disagree(s) => {
            Attempt::failed(Failure::Internal(format!("the backends disagree: {s}")), finder)
        }
    }
}

/// The seed velocities a claim must contain: the drops it covers, before their first impact.
fn drops_of<T, const D: usize>(claim: Claim, translation: [T; D], all_down: Vec<[T; D]>) -> Vec<[T; D]> {
    if claim == Claim::EffectivelyInvariant { vec![translation] } else { all_down }
}

fn show<const D: usize>(p: &[Q; D]) -> String {
    format!("({})", p.iter().map(ToString::to_string).collect::<Vec<_>>().join(", "))
}

/// The rod at every corner: the exact search, then the kernel.
fn attempt_rod(req: &Request, rods: &[Rod<Q>], claim: Claim, t: &mut Timings) -> Attempt {
    let down = [Q::int(-1), Q::int(-1)];
    let mut seeds = Vec::new();
    for rod in rods {
        let i0 = rod.impact(0);
        for d in drops_of(claim, down.clone(), rod.all_down_generators().to_vec()) {
            let after: Vec2<Q> = mat2_vec(&i0, &d);
            if after.iter().all(|x| *x == Q::int(0)) {
                continue; // at rest after one impact: inside every cone
            }
            match s_of(&after) {
                Some(s) => seeds.push(s),
                None => {
                    return Attempt::failed(
                        Failure::SeedNotBelow { seed: show(&d), velocity: show(&after) },
                        None,
                    );
                }
            }
        }
    }
    if seeds.is_empty() {
        seeds.push(Q::new(-1, 2));
    }
    let start = Instant::now();
    let search = find_rod_cone_box(rods, &seeds, &req.finder);
    t.finder += start.elapsed();
    let Search::Found { cone, .. } = &search else {
        return Attempt::failed(Failure::Finder(search.map(|_| 2)), Some(search.map(|_| 2)));
    };
    let gens = RodCone::generators(cone).iter().map(|g| generator(g)).collect();
    kernel_check(req, certificate(req, claim, gens, cone.method), cone.method, t)
}

/// The exactifier with `cfg`, then, while the offsets fail to converge (close to the threshold,
/// where the maps barely contract, success depends on the grid in a way no single setting
/// wins), with finer normals and grid, then with a larger slack, then with the finest, then the
/// first and the finer without overshoot (docs/bodies.md); the first success, else the first
/// error.
fn exactify_ladder<E: Exact>(
    bodies: &[Polygon<E>],
    polygon: &[P2],
    seeds: &[Vec3<E>],
    cfg: &ExactifyConfig,
) -> Result<Exactified, ExactifyError> {
    ladder(cfg, |c| exactify(bodies, polygon, seeds, c))
}

/// The retries of [`exactify_ladder`] for any exactifier `run`.
fn ladder<T>(
    cfg: &ExactifyConfig,
    run: impl Fn(&ExactifyConfig) -> Result<T, ExactifyError>,
) -> Result<T, ExactifyError> {
    ladder_if(cfg, |e| matches!(e, ExactifyError::NoConvergence { .. }), run)
}

/// [`ladder`], retrying after the errors `retry_on` accepts.
fn ladder_if<T>(
    cfg: &ExactifyConfig,
    retry_on: impl Fn(&ExactifyError) -> bool,
    run: impl Fn(&ExactifyConfig) -> Result<T, ExactifyError>,
) -> Result<T, ExactifyError> {
    let finer = ExactifyConfig {
        normal_bits: cfg.normal_bits + 2,
        grid_bits: cfg.grid_bits + 8,
        slack_bits: cfg.slack_bits + 4,
        ..*cfg
    };
    let coarser = ExactifyConfig { slack_bits: cfg.slack_bits.saturating_sub(4), ..*cfg };
    let finest = ExactifyConfig {
        normal_bits: cfg.normal_bits + 8,
        grid_bits: cfg.grid_bits + 24,
        slack_bits: cfg.slack_bits + 16,
        ..*cfg
    };
    let creeping = [*cfg, finer].map(|c| ExactifyConfig { overshoot: false, ..c });
    let first = run(cfg);
    if !cfg.retry || !first.as_ref().is_err_and(&retry_on) {
        return first;
    }
    [finer, coarser, finest].iter().chain(&creeping).map(run).find(Result::is_ok).unwrap_or(first)
}

/// A regular polygon at every corner: float finder, exactifier, kernel.
fn attempt_polygon<E: Exact>(req: &Request, bodies: &[Polygon<E>], claim: Claim, t: &mut Timings) -> Attempt {
    let seed = if claim == Claim::EffectivelyInvariant { Seed::Translation } else { Seed::AllDown };
    let mut exact_seeds: Vec<Vec3<E>> = Vec::new();
    let down = translation_down().map(|x| E::from_q(&x));
    for b in bodies {
        let i0 = b.impact(0);
        exact_seeds
            .extend(drops_of(claim, down.clone(), b.all_down_generators()).iter().map(|g| mat_vec(&i0, g)));
    }
    let fb = FloatBody::corners(bodies);
    let start = Instant::now();
    let outcome = find_cone(&fb, seed, &req.finder);
    t.finder += start.elapsed();
    let summary = Some(outcome.map(Vec::len));
    let Search::Found { cone: polygon, .. } = &outcome else {
        return Attempt::failed(Failure::Finder(outcome.map(Vec::len)), summary);
    };
    let start = Instant::now();
    let ex = exactify_ladder(bodies, polygon, &exact_seeds, &req.exactify);
    t.exactify += start.elapsed();
    let ex = match ex {
        Ok(ex) => ex,
        Err(e) => return Attempt::failed(Failure::Exactify(e), summary),
    };
    let cone = ex.generators.iter().map(|g| generator(g)).collect();
    let how = "float finder + exactifier";
    let mut attempt = kernel_check(req, certificate(req, claim, cone, how), how, t);
    attempt.finder = summary;
    attempt
}

/// The PCC quadratic as text, e.g. for notes.
fn pcc_text<E: OrderedField>(b: &Polygon<E>, quad: &PccQuadratic<E>) -> String {
    let kind = match quad.exclusion() {
        PccExclusion::Excluded => "complex roots of modulus below 1".to_string(),
        PccExclusion::RealRoots => "real roots".to_string(),
        PccExclusion::ModulusNotBelowOne => format!("complex roots of modulus sqrt({}) >= 1", quad.q),
    };
    format!(
        "det(tI - S_{} S_1) = (t - 1)(t^2 + ({}) t + ({})), discriminant {} ({kind})",
        b.n() - 1,
        quad.p,
        quad.q,
        quad.discriminant
    )
}

/// Whether the PCC Lemma applies on the whole box (the kernel's rule R4 on a box), with a text
/// for notes.
fn pcc_on_box(req: &Request, b: &Polygon<Q>) -> Result<(bool, String), Failure> {
    let polys =
        pcc_polynomials(b).map_err(|_| Failure::Internal("model error: t = 1 is not a root".into()))?;
    let (k1, g1) = req.upper.clone().expect("a box");
    let rect = Rect { kappa: [req.kappa.clone(), k1], gamma: [req.gamma.clone(), g1] };
    for (p, what) in [(&polys.discriminant, "discriminant"), (&polys.modulus, "q - 1")] {
        if let Err(e) = negative_on(p, &rect, MAX_PCC_BOXES) {
            let why = match e {
                NotNegative::At(k, g) => {
                    format!("the PCC quadratic's {what} is >= 0 at kappa = {k}, gamma = {g}")
                }
                NotNegative::Undecided(r) => format!(
                    "the PCC quadratic's {what} is not proved negative on kappa in [{}, {}], gamma in [{}, {}]",
                    r.kappa[0], r.kappa[1], r.gamma[0], r.gamma[1]
                ),
            };
            return Ok((false, why));
        }
    }
    Ok((true, "complex roots of modulus below 1 on the whole box (Bernstein bounds)".into()))
}

/// PCC exclusion at a point (rule R4): whether it holds, its text, and whether the roots are real.
fn pcc_at_point<E: OrderedField>(b: &Polygon<E>) -> Result<(bool, String, bool), Failure> {
    let quad = pcc_quadratic(b)
        .map_err(|v| Failure::Internal(format!("model error: det(I - S_(n-1) S_1) = {v}")))?;
    Ok((quad.excludes_pcc(), pcc_text(b, &quad), quad.exclusion() == PccExclusion::RealRoots))
}

/// The strongest claim a polygon can carry by the PCC Lemma (at a point or on a box), with notes;
/// `Err` if `CompleteChatterFromAllDown` was asked for and the Lemma does not apply.
fn polygon_strongest(
    req: &Request,
    n: usize,
    (excluded, text, real_roots): (bool, String, bool),
    notes: &mut Vec<String>,
) -> Result<Claim, Failure> {
    if excluded {
        return Ok(Claim::CompleteChatterFromAllDown);
    }
    if req.claim == ClaimChoice::Exactly(Claim::CompleteChatterFromAllDown) {
        return Err(Failure::PccNotExcluded(text));
    }
    notes.push(format!("the PCC Lemma does not apply: {text}"));
    if real_roots && n >= 4 {
        notes.push(format!("this contradicts the paper, which states that the Lemma's condition (all eigenvalues real) is never met for n >= 4; here n = {n}"));
    }
    Ok(Claim::CcOrPccFromAllDown)
}

/// The claims to try, strongest first, with notes; `Err` if the requested claim is impossible.
/// `strongest` gives the strongest claim about drops (called only when 0 < gamma < 1).
fn claims_for(
    req: &Request,
    strongest: impl FnOnce(&mut Vec<String>) -> Result<Claim, Failure>,
    notes: &mut Vec<String>,
) -> Result<Vec<Claim>, Failure> {
    let g1 = req.upper.as_ref().map_or(&req.gamma, |u| &u.1);
    claims_in(req.claim, [&req.gamma, g1], strongest, notes)
}

/// [`claims_for`] for a claim choice and gamma in [g0, g1].
fn claims_in(
    choice: ClaimChoice,
    [g0, g1]: [&Q; 2],
    strongest: impl FnOnce(&mut Vec<String>) -> Result<Claim, Failure>,
    notes: &mut Vec<String>,
) -> Result<Vec<Claim>, Failure> {
    if *g0 == Q::int(0) || *g1 == Q::int(1) {
        let g = if *g0 == Q::int(0) { g0 } else { g1 };
        let why = format!(
            "gamma = {g}: the claims about drops need 0 < gamma < 1 (the paper's Theorem on effectively invariant cones); only EffectivelyInvariant can be certified"
        );
        return match choice {
            ClaimChoice::Exactly(Claim::EffectivelyInvariant) | ClaimChoice::Strongest => {
                notes.push(why);
                Ok(vec![Claim::EffectivelyInvariant])
            }
            ClaimChoice::Exactly(_) | ClaimChoice::StrongestAboutDrops => Err(Failure::GammaOutOfRange(why)),
        };
    }
    let strongest = strongest(notes)?;
    Ok(match choice {
        ClaimChoice::Exactly(c) => vec![c],
        ClaimChoice::Strongest => vec![strongest, Claim::EffectivelyInvariant],
        ClaimChoice::StrongestAboutDrops => vec![strongest],
    })
}

/// The strongest claim about drops for the shapes at the corners of a request over Q.
fn strongest_rational(req: &Request, shapes: &[Shape<Q>], notes: &mut Vec<String>) -> Result<Claim, Failure> {
    match &shapes[0] {
        Shape::Rod(_) => {
            notes.push("rod (n = 2): exact search, no float search; with two contacts PCC is CC".into());
            Ok(Claim::CompleteChatterFromAllDown)
        }
        Shape::Polygon(b) if req.upper.is_some() => {
            let (ok, text) = pcc_on_box(req, b)?;
            polygon_strongest(req, b.n(), (ok, text, false), notes)
        }
        Shape::Polygon(b) => polygon_strongest(req, b.n(), pcc_at_point(b)?, notes),
    }
}

/// The exact models at the corners of the request (one for a point).
fn shapes(req: &Request) -> Result<Vec<Shape<Q>>, Failure> {
    if let Some((k1, g1)) = &req.upper
        && (*k1 < req.kappa || *g1 < req.gamma)
    {
        return Err(Failure::Body("an interval is empty (its upper end is below its lower end)".into()));
    }
    req.corners()
        .into_iter()
        .map(|(k, g)| Shape::new(req.n, k, g).map_err(|e| Failure::Body(e.to_string())))
        .collect()
}

fn report(a: Attempt, timings: Timings, notes: Vec<String>) -> Report {
    Report {
        result: a.result,
        finder: a.finder,
        method: a.method,
        timings,
        max_denominator_bits: a.bits,
        notes,
    }
}

/// The report of [`try_claims`].
fn run_claims(
    req: &Request,
    claims: Vec<Claim>,
    attempt: impl FnMut(Claim, &mut Timings) -> Attempt,
    notes: Vec<String>,
) -> Report {
    let (a, timings, notes) = try_claims(req.claim, claims, attempt, notes);
    report(a, timings, notes)
}

/// Tries the claims in order until one is certified (or an internal error stops the run): the
/// last attempt, the time spent and the notes.
fn try_claims<C>(
    choice: ClaimChoice,
    claims: Vec<Claim>,
    mut attempt: impl FnMut(Claim, &mut Timings) -> Attempt<C>,
    mut notes: Vec<String>,
) -> (Attempt<C>, Timings, Vec<String>) {
    let mut timings = Timings::default();
    let mut last = None;
    for claim in claims {
        let a = attempt(claim, &mut timings);
        let stop = a.result.is_ok() || matches!(a.result, Err(Failure::Internal(_)));
        if !stop && let (Err(e), ClaimChoice::Strongest) = (&a.result, choice) {
            notes.push(format!("{} not certified: {e}", claim.name()));
        }
        last = Some(a);
        if stop {
            break;
        }
    }
    (last.expect("at least one claim"), timings, notes)
}

/// Whether `certify` can model the body: n from 2 to 64 (in Q(cos 2 pi/n) where cos 2 pi/n is
/// irrational), kappa > 0, gamma in [0, 1].
pub fn check_body(n: u64, kappa: &Q, gamma: &Q) -> Result<(), chatter_kernel::model::BodyError> {
    if chatter_kernel::check::is_irrational(n) && n <= crate::exact::MAX_N {
        let field = crate::exact::CosField::<Q>::new(n).expect("3 <= n <= MAX_N");
        let (k, g) = (
            crate::exact::Algebraic::rational(kappa.clone()),
            crate::exact::Algebraic::rational(gamma.clone()),
        );
        return Polygon::with_cosine(n, field.generator(), k, g).map(|_| ());
    }
    Shape::new(n, kappa.clone(), gamma.clone()).map(|_| ())
}

/// kappa given as the canonical text of an element of Q(cos 2 pi/n) (docs/certificate-format.md
/// §12, e.g. "1/40 + 1/100*c"): `None` when the text does not name the generator `c`, else a
/// rational within 2^-40 below it (for validation and display) and the text, which
/// [`Request::kappa_field`] carries into the certificate. Errors are messages without a prefix.
pub fn field_kappa(n: u64, text: &str) -> Result<Option<(Q, String)>, String> {
    if !text.contains(crate::exact::GENERATOR) {
        return Ok(None);
    }
    let field = crate::exact::CosField::<Q>::new(n)
        .filter(|f| f.degree() > 1)
        .ok_or_else(|| format!("{text:?} names c = cos(2 pi/{n}), which is rational or out of range here"))?;
    let k = field
        .parse(text, ParseLimits::default())
        .map_err(|e| {
            format!(
                "{text:?} is neither a number (1/8, 0.125) nor an element of Q(c), c = cos(2π/{n}), in canonical text (\"1/40 + 1/100*c\"): {e}"
            )
        })?;
    let (lo, _) = k.enclose(&Q::new(1, 1 << 40));
    Ok(Some((lo, text.to_string())))
}

/// Runs the pipeline.
pub fn certify(req: &Request) -> Report {
    if chatter_kernel::check::is_irrational(req.n) {
        return field::certify(req);
    }
    let mut notes = Vec::new();
    let failed = |f, notes| report(Attempt::failed(f, None), Timings::default(), notes);
    let shapes = match shapes(req) {
        Ok(s) => s,
        Err(f) => return failed(f, notes),
    };
    let claims = match claims_for(req, |notes| strongest_rational(req, &shapes, notes), &mut notes) {
        Ok(c) => c,
        Err(f) => return failed(f, notes),
    };
    if let Shape::Rod(_) = &shapes[0] {
        let rods: Vec<Rod<Q>> = shapes
            .iter()
            .filter_map(|s| if let Shape::Rod(r) = s { Some(r.clone()) } else { None })
            .collect();
        return run_claims(req, claims, |claim, t| attempt_rod(req, &rods, claim, t), notes);
    }
    let bodies: Vec<Polygon<Q>> = shapes
        .iter()
        .filter_map(|s| if let Shape::Polygon(b) = s { Some(b.clone()) } else { None })
        .collect();
    run_claims(req, claims, |claim, t| attempt_polygon(req, &bodies, claim, t), notes)
}
