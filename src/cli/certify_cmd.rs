//! `chatter certify`.

use super::{Env, Outcome, emit, emit_report};
use crate::certify::virtual_time::{self, NotProduced, Produced};
use crate::certify::{ClaimChoice, Failure, Report, Request, certify};
use crate::exact::{Q, QExt, Rounding, parse_user_number};
use crate::report::certify::RestReport;
use crate::write::write;
use chatter_kernel::certificate::Claim;
use chatter_kernel::model::BodyError;
use clap::{Args, ValueEnum};
use std::path::PathBuf;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ClaimArg {
    /// The strongest claim that can be certified (tries CompleteChatterFromAllDown first).
    Strongest,
    /// Conditions 1-2: K in v <= 0 and S_j(K ∩ C_j) ⊆ K.
    EffectivelyInvariant,
    /// Also every all-down drop lands in K after its first impact: v <= 0 for ever, no ICC
    /// (impacts one contact at a time: simultaneous impacts are outside the model; finite
    /// accumulation time not derived: docs/time-to-rest.md).
    CcOrPccFromAllDown,
    /// Also PCC excluded (the name is the file format's; finite accumulation time not derived).
    CompleteChatterFromAllDown,
}

impl ClaimArg {
    /// The pipeline's claim choice.
    pub fn choice(self) -> ClaimChoice {
        match self {
            ClaimArg::Strongest => ClaimChoice::Strongest,
            ClaimArg::EffectivelyInvariant => ClaimChoice::Exactly(Claim::EffectivelyInvariant),
            ClaimArg::CcOrPccFromAllDown => ClaimChoice::Exactly(Claim::CcOrPccFromAllDown),
            ClaimArg::CompleteChatterFromAllDown => ClaimChoice::Exactly(Claim::CompleteChatterFromAllDown),
        }
    }
}

/// Raw arguments of `chatter certify`.
#[derive(Args, Debug)]
#[command(after_help = "Numbers are read exactly: 1/6, 0.01 (= 1/100), 1e-2.\n\
Defaults certify the flat homogeneous square plate: n = 4, kappa = 1/6, gamma = 1/100.\n\
General convex bodies (docs/model.md §11: --rectangle, --box, --polygon, --body NAME|FILE) get a\n\
version-4 certificate with one cone per contact.\n\
kappa and gamma may be closed intervals a:b: one cone then certifies every (kappa, gamma) of the\n\
box (a box certificate, docs/certificate-format.md).\n\n\
For n = 5 and 7 to 64 the kernel works in Q(c), c = cos(2 pi/n): --kappa may be an element of it in\n\
canonical text (\"1/40 + 1/100*c\"), and --body NAME takes a catalogue body with its exact kappa.\n\n\
Examples:\n  chatter certify --n 3 --kappa 3/20 --gamma 0.05 -o triangle.ron\n  \
chatter certify --kappa 1/10:3/25 --gamma 1/100:1/50 -o box.ron\n  \
chatter certify --n 5 --kappa \"1/40 + 1/100*c\" --gamma 1/100 -o pentagon.ron\n  \
chatter certify --body dodecahedron --gamma 1/100\n  \
chatter certify --rectangle 2,1 --gamma 1/100 -o rectangle.ron\n  \
chatter certify --box 150,75,8 --largest-gamma")]
pub struct CertifyArgs {
    #[command(flatten)]
    pub body: super::BodyArgs,
    /// A general convex body (docs/model.md §11): --rectangle, --box, --polygon, or --body NAME|FILE.
    /// --body also takes a regular body of the catalogue (`chatter bodies`) by a unique part of
    /// its name, e.g. "pentagon plate" or "dodecahedron": its n and its exact kappa (which may be
    /// irrational, an element of Q(cos 2 pi/n)); give --gamma, not --n or --kappa.
    #[command(flatten)]
    pub general: super::convex_args::ConvexArgs,
    /// The claim to certify.
    #[arg(long, value_enum, default_value = "strongest")]
    pub claim: ClaimArg,
    /// Write the certificate here (only if the kernel accepts it).
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
    /// Print one JSON object instead of the one-line summary.
    #[arg(long)]
    pub json: bool,
    /// With --json: include the wall-clock times (then the output differs from run to run).
    #[arg(long)]
    pub timings: bool,
    /// Iteration budget of the float finder (near the CC threshold the cone converges slowly:
    /// at relative distance 1e-6 below it, about 10,000 to 25,000 iterations for n = 4, 6).
    #[arg(long, default_value_t = crate::finder::FinderConfig::default().max_iterations)]
    pub max_iterations: usize,
    /// Instead of certifying at --gamma: the largest gamma in [1/4096, 4095/4096] that certifies
    /// (the strongest claim about drops, or --claim), by bisection on exact rationals, and 100
    /// simulated drops just above it.
    #[arg(long)]
    pub largest_gamma: bool,
    /// With --largest-gamma: bisection steps after the two ends (1 to 60).
    #[arg(long, default_value_t = 20)]
    pub steps: usize,
    /// Vertex budget of the float polygon (outer approximation beyond it).
    #[arg(long, default_value_t = 40)]
    pub max_vertices: usize,
    /// Also try a time-to-rest certificate (docs/time-to-rest.md §5: a virtual-time graph of
    /// cones with covectors b_r and numerators a_r, version 2 of the file; version 3 where
    /// cos(2 pi/n) is irrational, whose covectors and numerators are elements of Q(cos 2 pi/n))
    /// and write it here if the kernel accepts it on both backends; it bounds the time until every
    /// all-down drop's impacts accumulate by B h/|v| (`time_to_rest_bound`). Regular polygons,
    /// 3 <= n <= 64, at a point with rational kappa and gamma, or, for n = 3, 4, 6, on a box of
    /// them (one graph and one B for the whole box, version 3); general bodies (--body,
    /// --rectangle, --box, --polygon) at one gamma or, with --gamma a:b, for every gamma of the
    /// interval (format chatter-family-time-to-rest, version 2 for an interval; an affine image
    /// of a regular n-gon, n = 3, 4, 6, also gets the regular polygon's certificate transported,
    /// one copy of its graph per contact; the whole search below runs with new nodes enlarged by
    /// 0.3, 0.5 and 0.1, and the least B is kept). Three graphs are
    /// tried in turn (nodes padded by 10^-3, 10^-4, 10^-5), then
    /// nine that merge an image no node holds into the node it enlarges least (area factors
    /// from 1.05 to 2.5; pad 10^-3); each search stops at 200 nodes and 12 rounds of the covector
    /// search (40 x 20 directions each);
    /// the numerators minimise B by a linear program (checked exactly), else they are the exact
    /// least scales times the covectors (N + 1 passes, N nodes); the exit status is 1 when no
    /// such certificate is made (the output says what was searched with each graph), even if the
    /// cone certificate is.
    #[arg(long, value_name = "FILE")]
    pub time_to_rest: Option<PathBuf>,
}

/// Validated arguments.
struct Validated {
    req: Request,
    output: Option<PathBuf>,
    rest: Option<PathBuf>,
    json: bool,
    timings: bool,
}

/// n, kappa (as a rational approximation and, if irrational, as field text) of `--body NAME`.
fn catalogue_body(name: &str) -> Result<(u64, Q, Option<String>), String> {
    let e = crate::bodies::find(name).map_err(|e| format!("--body: {e}"))?;
    let text = e.certificate_kappa().ok_or_else(|| {
        let why = e.why_not_certifiable().unwrap_or_default();
        format!("--body: '{}': {why}; no certificate can name it", e.name)
    })?;
    match crate::certify::field_kappa(e.n, &text).map_err(|m| format!("--body: {m}"))? {
        Some((approx, text)) => Ok((e.n, approx, Some(text))),
        None => Ok((e.n, e.kappa.as_rational().expect("a rational kappa"), None)),
    }
}

/// `--kappa` as an element of Q(cos 2 pi/n) in canonical text, if it is one.
fn field_kappa(body: &super::BodyArgs) -> Result<Option<(Q, String)>, String> {
    if !body.kappa.contains(crate::exact::GENERATOR) || parse_user_number(&body.kappa).is_ok() {
        return Ok(None);
    }
    let (n, _, _) = super::BodyArgs { kappa: "1".into(), ..body.clone() }.parse()?;
    if !chatter_kernel::check::is_irrational(n) {
        return Err(format!(
            "--kappa: {:?} is not a number: give a fraction or a decimal, such as 1/8 or 0.125 (an element of Q(c) such as \"1/40 + 1/100*c\", c = cos(2π/n), only where c is irrational: n = 5, 7, 8, ...)",
            body.kappa
        ));
    }
    crate::certify::field_kappa(n, &body.kappa).map_err(|m| format!("--kappa: {m}"))
}

fn validate(a: CertifyArgs, env: &Env) -> Result<Validated, String> {
    let mut kappa_field = None;
    let (mut n, mut kappa, gamma) = match field_kappa(&a.body)? {
        Some((k, text)) => {
            kappa_field = Some(text);
            let plain = super::BodyArgs { kappa: "1".into(), ..a.body.clone() };
            let (n, _, gamma) = plain.parse_ranges()?;
            (n, [k.clone(), k], gamma)
        }
        None => a.body.parse_ranges()?,
    };
    if let Some(name) = &a.general.body {
        let (bn, k, text) = catalogue_body(name)?;
        (n, kappa, kappa_field) = (bn, [k.clone(), k], text);
    }
    for (k, g) in [(&kappa[0], &gamma[0]), (&kappa[1], &gamma[1])] {
        if let Err(e) = crate::certify::check_body(n, k, g) {
            return Err(match e {
                BodyError::UnsupportedN(n) => format!(
                    "--n: {n} is not supported: certify takes n = 2 (the rod) or a regular polygon with 3 to 64 contacts (general bodies: --rectangle, --box, --polygon, --body)"
                ),
                BodyError::KappaNotPositive => format!("--kappa: {k} is not accepted: kappa must be > 0"),
                BodyError::GammaOutOfRange => {
                    format!("--gamma: {g} is not accepted: gamma must lie in [0, 1]")
                }
            });
        }
    }
    if a.max_vertices < 3 {
        return Err(format!("--max-vertices: {} is not accepted: give at least 3", a.max_vertices));
    }
    let mut req = Request::boxed(n, kappa, gamma);
    req.kappa_field = kappa_field;
    req.claim = a.claim.choice();
    req.finder.max_iterations = a.max_iterations;
    req.finder.max_vertices = a.max_vertices;
    req.backends = env.backends;
    let region = req.upper.is_none() || matches!(n, 3 | 4 | 6);
    if a.time_to_rest.is_some() && !(n >= 3 && region && req.kappa_field.is_none()) {
        return Err("--time-to-rest: time-to-rest certificates take a regular polygon (n >= 3) with rational kappa and gamma, at a point or, for n = 3, 4, 6, on a box".into());
    }
    Ok(Validated { req, output: a.output, rest: a.time_to_rest, json: a.json, timings: a.timings })
}

pub(super) fn ms(d: std::time::Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

fn summary(v: &Validated, r: &Report) -> String {
    let req = &v.req;
    let head = req.describe();
    let t = &r.timings;
    let exactifier =
        if t.exactify.is_zero() { String::new() } else { format!(", exactifier {:.2} ms", ms(t.exactify)) };
    let times = format!(
        "search {:.2} ms{exactifier}, kernel {:.2} ms ({} + {})",
        ms(t.finder),
        ms(t.kernel),
        req.backends[0].name,
        req.backends[1].name
    );
    let notes: String = r.notes.iter().map(|n| format!("\nnote: {n}")).collect();
    match &r.result {
        Ok(c) => {
            let out = v
                .output
                .as_ref()
                .map_or(String::from(" (no -o: not written)"), |p| format!(" -> {}", p.display()));
            format!(
                "CERTIFIED {head} claim={}: {} generators, largest denominator {} bits, by {}; {times}{out}\nproves: {}{notes}",
                c.claim.name(),
                c.cone.len(),
                r.max_denominator_bits,
                r.method.unwrap_or("?"),
                crate::claims::proves_with(c.claim.name(), c.time_to_rest_bound.is_some())
                    .unwrap_or("?")
                    .to_string()
                    + &c.time_to_rest_bound
                        .as_ref()
                        .map_or(String::new(), |b| format!("\ntime_to_rest_bound: {b}"))
            )
        }
        Err(e) => format!("NOT CERTIFIED {head}: {e}; {times}{notes}"),
    }
}

/// Whether the arguments describe a general body (docs/model.md §11) rather than a regular one.
pub(super) fn is_general(a: &CertifyArgs) -> bool {
    match &a.general.body {
        Some(value) => super::convex_args::names_general_body(value),
        None => a.general.given(),
    }
}

pub fn run(a: CertifyArgs, env: &Env) -> Outcome {
    if a.time_to_rest.is_some() && a.largest_gamma {
        return Outcome::Usage(
            "--time-to-rest: takes a body at a point or on a box, not --largest-gamma".into(),
        );
    }
    if a.largest_gamma {
        return super::largest_gamma::run(a, env);
    }
    if is_general(&a) {
        return super::certify_general::run(a, env);
    }
    let v = match validate(a, env) {
        Ok(v) => v,
        Err(e) => return Outcome::Usage(e),
    };
    let report = certify(&v.req);
    if let (Ok(cert), Some(path)) = (&report.result, &v.output)
        && let Err(e) = std::fs::write(path, write(cert))
    {
        return Outcome::Usage(format!("cannot write {}: {e}", path.display()));
    }
    let rest = v.rest.as_ref().map(|path| (path, rest(&v.req)));
    if let Some((path, Ok(p))) = &rest
        && let Err(e) = std::fs::write(path, &p.text)
    {
        return Outcome::Usage(format!("cannot write {}: {e}", path.display()));
    }
    if v.json {
        let output = v.output.as_ref().map(|p| p.display().to_string());
        let mut r = crate::report::certify::of(&v.req, &report, output, v.timings);
        if let Some((path, result)) = &rest {
            r.time_to_rest = Some(RestReport::of(result, &path.display().to_string()));
            if let Ok(p) = result {
                r.time_to_rest_bound = Some(p.bound.to_string());
            }
        }
        emit_report(&r);
    } else {
        emit(&(summary(&v, &report) + &rest.as_ref().map_or(String::new(), |(path, r)| rest_line(path, r))));
    }
    outcome(&report.result, rest.as_ref().map(|r| &r.1))
}

/// The exit outcome of `certify`: the cone certificate and, when asked for, the time-to-rest
/// certificate must both be made.
pub(super) fn outcome<T, C>(
    result: &Result<T, Failure>,
    rest: Option<&Result<Produced<C>, NotProduced>>,
) -> Outcome {
    match (result, rest) {
        (Err(Failure::Internal(s)), _) => Outcome::Internal(s.clone()),
        (_, Some(Err(NotProduced::Disagree(s)))) => {
            Outcome::Internal(format!("the kernel's backends disagree: {s}"))
        }
        (Ok(_), None | Some(Ok(_))) => Outcome::Success,
        _ => Outcome::Negative,
    }
}

/// The time-to-rest producer at the request's point or on its box (docs/time-to-rest.md §5).
fn rest(req: &Request) -> Result<Produced, NotProduced> {
    let (k1, g1) = req.upper.clone().unwrap_or((req.kappa.clone(), req.gamma.clone()));
    let region = virtual_time::Region { kappa: [req.kappa.clone(), k1], gamma: [req.gamma.clone(), g1] };
    virtual_time::produce_on(req.n, &region, &virtual_time::Config::default(), &req.backends)
}

/// The text output's lines about the time-to-rest certificate.
pub(super) fn rest_line<C: virtual_time::RestFile>(
    path: &std::path::Path,
    r: &Result<Produced<C>, NotProduced>,
) -> String {
    match r {
        Ok(p) => format!(
            "\ntime_to_rest_bound: {} (about {}): every all-down drop's impacts accumulate within B h/|v| of its first impact (time-to-rest certificate, claim {}, a virtual-time graph of {} nodes{} accepted by the kernel on both backends) -> {}",
            p.bound,
            p.bound.decimal(6, Rounding::Up),
            p.cert.claim().name(),
            p.nodes,
            if p.cert.transported() {
                ", the regular polygon's graph transported to this affine image of it, one copy per contact,"
            } else {
                ""
            },
            path.display()
        ),
        Err(e) => format!("\ntime to rest: NOT CERTIFIED, no bound derived: {e}"),
    }
}
