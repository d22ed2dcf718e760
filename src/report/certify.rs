//! `chatter.certify/1`: a certificate made (or not) at a point or on a box of parameters.
//! Build it with [`certify`] (runs the pipeline) or [`of`] (from a pipeline report).

use super::convex::GeneralBodyReport;
use super::finder::FinderReport;
use super::{Interval, Report, Timings, Verdict, ms};
use crate::certify::convex::{ConvexReport, ConvexRequest};
use crate::certify::{self as pipeline, Request};
use crate::exact::Q;
use schemars::JsonSchema;
use serde::Serialize;

/// `chatter certify --json`.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct CertifyReport {
    /// `chatter.certify/1`.
    pub schema: &'static str,
    /// `certified` or `not-certified`.
    pub verdict: Verdict,
    pub n: u64,
    /// kappa: [lo, hi], equal ends for a point certificate (for an irrational kappa, a rational
    /// within 2^-40 below it, see `kappa_field`).
    pub kappa: Interval,
    /// kappa as an element of Q(cos 2 pi/n) in canonical text (docs/certificate-format.md §12),
    /// when it is irrational (`--kappa "1/40 + 1/100*c"`, `--body NAME`); null otherwise.
    pub kappa_field: Option<String>,
    /// gamma: [lo, hi], equal ends for a point certificate.
    pub gamma: Interval,
    /// The claim certified (`EffectivelyInvariant`, `CcOrPccFromAllDown`, `CompleteChatterFromAllDown`).
    pub claim: Option<&'static str>,
    /// What the claim proves, every assumption stated (`claims::proves`); null when not
    /// certified.
    pub proves: Option<&'static str>,
    /// An exact bound B ("p/q") with T <= B h/|v| on the time until the impacts of an all-down drop
    /// accumulate, h and v the centre's height and velocity just before the first impact (rule T1,
    /// docs/time-to-rest.md §2): rod point certificates with a claim about drops; with
    /// `--time-to-rest`, the B of the time-to-rest certificate the kernel accepted (Theorem 5.1,
    /// docs/time-to-rest.md §5); null otherwise (no other cone or family certificate derives a
    /// finite accumulation time).
    pub time_to_rest_bound: Option<String>,
    /// With `certify --time-to-rest FILE`: the time-to-rest certificate tried (docs/time-to-rest.md
    /// §5); null without the option.
    pub time_to_rest: Option<RestReport>,
    /// Generators of the cone.
    pub generators: Option<usize>,
    /// The largest denominator of the certificate's numbers, in bits.
    pub max_denominator_bits: Option<u64>,
    /// The file written (certified with `-o`).
    pub output: Option<String>,
    /// Why no certificate was made.
    pub reason: Option<String>,
    /// How the cone was found.
    pub method: Option<&'static str>,
    /// The float finder's verdict (when it ran).
    pub finder: Option<FinderReport>,
    /// Notes on the claims not certified.
    pub notes: Vec<String>,
    /// A general convex body (docs/model.md §11; `n` is its number of contacts, `kappa` is 0 and
    /// `generators` counts the generators of all its cones), else `null`.
    pub general_body: Option<super::convex::GeneralBodyReport>,
    /// Only with `--timings`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub timings: Option<Timings>,
}

/// A time-to-rest certificate tried by `certify --time-to-rest` (docs/time-to-rest.md §5,
/// docs/certificate-format.md §16, and §17 for a general body).
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct RestReport {
    /// Whether the kernel accepted it on both backends (then it was written to `output`).
    pub accepted: bool,
    /// The file written (accepted only).
    pub output: Option<String>,
    /// Its claim (`CompleteChatterFromAllDown` or `CcOrPccFromAllDown`); null when not accepted.
    pub claim: Option<&'static str>,
    /// B ("p/q"): every all-down drop's impacts accumulate within B h/|v| of its first impact
    /// (Theorem 5.1; also reported as `time_to_rest_bound`); null when not accepted.
    pub bound: Option<String>,
    /// Nodes of the virtual-time graph written; null when not accepted.
    pub nodes: Option<usize>,
    /// What was searched and which check failed, when not accepted (no bound is derived).
    pub reason: Option<String>,
}

impl RestReport {
    /// The report of a producer run whose file (if accepted) was written to `output`.
    pub fn of<C: crate::certify::virtual_time::RestFile>(
        r: &Result<crate::certify::virtual_time::Produced<C>, crate::certify::virtual_time::NotProduced>,
        output: &str,
    ) -> Self {
        match r {
            Ok(p) => RestReport {
                accepted: true,
                output: Some(output.to_string()),
                claim: Some(p.cert.claim().name()),
                bound: Some(p.bound.to_string()),
                nodes: Some(p.nodes),
                reason: None,
            },
            Err(e) => RestReport {
                accepted: false,
                output: None,
                claim: None,
                bound: None,
                nodes: None,
                reason: Some(e.to_string()),
            },
        }
    }
}

impl Report for CertifyReport {
    const SCHEMA: &'static str = "chatter.certify/1";
}

/// The report of a pipeline run on `req`; `output` is the file written, if any; `timings`
/// includes the wall-clock times.
pub fn of(req: &Request, r: &pipeline::Report, output: Option<String>, timings: bool) -> CertifyReport {
    let cert = r.result.as_ref().ok();
    let (kappa_hi, gamma_hi) = req.upper.as_ref().map_or((&req.kappa, &req.gamma), |(k, g)| (k, g));
    let t = &r.timings;
    CertifyReport {
        schema: CertifyReport::SCHEMA,
        verdict: if cert.is_some() { Verdict::Certified } else { Verdict::NotCertified },
        n: req.n,
        kappa: Interval::of(&req.kappa, kappa_hi),
        kappa_field: req.kappa_field.clone(),
        gamma: Interval::of(&req.gamma, gamma_hi),
        claim: cert.map(|c| c.claim.name()),
        proves: cert.and_then(|c| crate::claims::proves_with(c.claim.name(), c.time_to_rest_bound.is_some())),
        time_to_rest_bound: cert.and_then(|c| c.time_to_rest_bound.clone()),
        time_to_rest: None,
        generators: cert.map(|c| c.cone.len()),
        max_denominator_bits: cert.map(|_| r.max_denominator_bits),
        output: output.filter(|_| cert.is_some()),
        reason: r.result.as_ref().err().map(ToString::to_string),
        method: r.method,
        finder: r.finder.as_ref().map(FinderReport::of),
        notes: r.notes.clone(),
        general_body: None,
        timings: timings.then(|| timings_of(t)),
    }
}

fn timings_of(t: &pipeline::Timings) -> Timings {
    Timings { search_ms: ms(t.finder), exactify_ms: ms(t.exactify), kernel_ms: ms(t.kernel) }
}

/// The report of a general body's certification (`description`: how the body was given).
pub fn of_convex(
    description: &str,
    req: &ConvexRequest,
    r: &ConvexReport,
    output: Option<String>,
    timings: bool,
) -> CertifyReport {
    let cert = r.result.as_ref().ok();
    let gamma = req.body.gamma();
    let t = &r.timings;
    CertifyReport {
        schema: CertifyReport::SCHEMA,
        verdict: if cert.is_some() { Verdict::Certified } else { Verdict::NotCertified },
        n: req.body.n() as u64,
        kappa: Interval::of(&Q::int(0), &Q::int(0)),
        kappa_field: None,
        gamma: Interval::of(gamma, req.gamma_hi.as_ref().unwrap_or(gamma)),
        claim: cert.map(|c| c.claim.name()),
        proves: cert.and_then(|c| crate::claims::proves(c.claim.name())),
        time_to_rest_bound: None,
        time_to_rest: None,
        generators: cert.map(|c| c.cones.iter().map(Vec::len).sum()),
        max_denominator_bits: cert.map(|_| r.max_denominator_bits),
        output: output.filter(|_| cert.is_some()),
        reason: r.result.as_ref().err().map(ToString::to_string),
        method: cert.and(r.method),
        finder: r.finder.as_ref().map(FinderReport::of),
        notes: r.notes.clone(),
        general_body: Some(GeneralBodyReport::of(description, &req.body)),
        timings: timings.then(|| timings_of(t)),
    }
}

/// Runs the pipeline on `req` (nothing is written) and reports it without timings; the
/// pipeline's report holds the certificate itself.
pub fn certify(req: &Request) -> (CertifyReport, pipeline::Report) {
    let r = pipeline::certify(req);
    (of(req, &r, None, false), r)
}
