//! `chatter.certify-orbit/1`: an orbit certificate (format `chatter-orbit-certificate`, docs/orbit-certificates.md)
//! made, or not, at one parameter point. Build it with [`certify`] (runs the producer) or [`of`]
//! (from the producer's result); [`Reason::of`] maps each failure of the producer to a
//! machine-readable code.

use super::{Number, Report, Verdict, ms};
use crate::exact::{Q, Ring};
use crate::orbit::{Failure, Found, Request};
use chatter_kernel::certificate::OrbitSet;
use chatter_kernel::verify::Backend;
use schemars::JsonSchema;
use serde::Serialize;

/// Why no orbit certificate was made: one code per failure of the producer (`crate::orbit::Failure`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, JsonSchema)]
#[serde(rename_all = "kebab-case")]
pub enum Reason {
    /// The body cannot be modelled (n, kappa, gamma, pattern steps); the command line reports
    /// this as a usage error (`chatter.error/1`, exit status 2) instead.
    Body,
    /// No simulated drop settled into a periodic impact pattern (no `--pattern` given).
    NoPattern,
    /// No attracting fixed point of the return map R_P was found for any phase of the pattern.
    NoAttractingCycle,
    /// The kernel found the pattern not forced (condition 1) on every set tried.
    PatternNotStable,
    /// The fixed point does not contract (complex eigenvalues, alpha, beta or alpha/beta not
    /// below 1), or the kernel found no set tried invariant and contracting (conditions 2-3).
    NoContraction,
    /// The two backends disagree (a bug); the command line reports this as an internal error
    /// (`chatter.error/1`, exit status 3) instead.
    Internal,
}

impl Reason {
    /// The code of a failure of the producer.
    pub fn of(f: &Failure) -> Reason {
        match f {
            Failure::Body(_) => Reason::Body,
            Failure::NoPattern(_) => Reason::NoPattern,
            Failure::NoAttractingCycle(_) => Reason::NoAttractingCycle,
            Failure::PatternNotStable(_) => Reason::PatternNotStable,
            Failure::NoContraction(_) => Reason::NoContraction,
            Failure::Internal(_) => Reason::Internal,
        }
    }

    /// The code as printed (`no-attracting-cycle`, ...).
    pub fn name(self) -> &'static str {
        match self {
            Reason::Body => "body",
            Reason::NoPattern => "no-pattern",
            Reason::NoAttractingCycle => "no-attracting-cycle",
            Reason::PatternNotStable => "pattern-not-stable",
            Reason::NoContraction => "no-contraction",
            Reason::Internal => "internal",
        }
    }
}

/// The producer's floating-point view of the attracting cycle (untrusted; the kernel's exact
/// check is what certifies).
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct Diagnostics {
    /// The fixed point x* = (a, b, c) of R_P on the section (f64).
    pub fixed_point: [f64; 3],
    /// The eigenvalues of the Jacobian of R_P at x*, largest modulus first (f64).
    pub eigenvalues: [f64; 3],
    /// alpha = hc(q_m) at x*: the position scale per period.
    pub alpha: f64,
    /// beta = -v(p_m) at x*: the velocity scale per period.
    pub beta: f64,
    /// alpha/beta at x*: the flight-time ratio per period.
    pub ratio: f64,
    /// T(x*): the period's flight time in the units of x.
    pub period_time: f64,
}

impl Diagnostics {
    /// The producer's view of the cycle behind a certificate it made.
    pub fn of(f: &Found) -> Diagnostics {
        Diagnostics {
            fixed_point: f.fixed_point,
            eigenvalues: f.eigenvalues,
            alpha: f.scales[0],
            beta: f.scales[1],
            ratio: f.scales[2],
            period_time: f.scales[3],
        }
    }
}

/// The certificate made: its exact numbers (the file holds them all).
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct OrbitCertificateReport {
    /// The claim: always `CompleteChatterFromSet`.
    pub claim: &'static str,
    /// The pattern's steps, in the phase certified.
    pub pattern: Vec<u64>,
    /// The centre x* of the set X (a rational near the fixed point).
    pub centre: [Number; 3],
    /// X = x* + A [-delta, delta]^3 (A: the rounded eigenvectors, in the file).
    pub delta: Number,
    /// The deepest bisection of X the kernel may use.
    pub subdivision: u64,
    /// The bound rho on alpha/beta.
    pub rho: Number,
    /// The bound lambda on alpha and beta.
    pub lambda: Number,
    /// The bound on the period's flight time T.
    pub period: Number,
}

/// What the trusted kernel accepted.
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct KernelReport {
    /// The sub-boxes of X on which the kernel showed every sign (docs/certificate-format.md §14).
    pub sub_boxes: usize,
    /// The bignum backends that each accepted the certificate.
    pub backends: Vec<&'static str>,
    /// B = T̄/(1 − ρ) ("p/q", derived by the kernel): from a post-impact state in X with centre
    /// height h and velocity v < 0, the impacts accumulate within B h/|v| (issue 24).
    pub time_to_rest_bound: Option<String>,
}

/// Wall-clock times in milliseconds, only with `--timings`.
#[derive(Clone, Debug, PartialEq, Serialize, JsonSchema)]
pub struct OrbitTimings {
    /// Everything before the final check: pattern, fixed point, basis, and the kernel's trials
    /// (first backend) of each candidate set until one was accepted.
    pub search_ms: f64,
    /// The final check of the accepted certificate on every backend (0 when none was accepted).
    pub kernel_ms: f64,
}

/// `chatter certify-orbit --json`.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct CertifyOrbitReport {
    /// `chatter.certify-orbit/1`.
    pub schema: &'static str,
    /// `certified` or `not-certified`.
    pub verdict: Verdict,
    /// Number of contacts (3 to 64).
    pub n: u64,
    pub kappa: Number,
    pub gamma: Number,
    /// The pattern asked for (`--pattern`), null when it was to be found by simulating drops.
    pub requested_pattern: Option<Vec<u64>>,
    /// Random drops simulated to find the pattern (when not given).
    pub drops: u64,
    /// The deepest subdivision the producer could ask the kernel for.
    pub max_depth: u64,
    /// The certificate made (`certified`), else null.
    pub certificate: Option<OrbitCertificateReport>,
    /// The producer's float diagnostics at the fixed point (`certified`), else null.
    pub diagnostics: Option<Diagnostics>,
    /// The kernel's acceptance (`certified`), else null.
    pub kernel: Option<KernelReport>,
    /// The file written (`certified` with `-o`), else null.
    pub output: Option<String>,
    /// Why no certificate was made (`not-certified`), else null.
    pub reason: Option<Reason>,
    /// The producer's explanation of `reason`, in words (`not-certified`), else null.
    pub message: Option<String>,
    /// Only with `--timings`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub timings: Option<OrbitTimings>,
}

impl Report for CertifyOrbitReport {
    const SCHEMA: &'static str = "chatter.certify-orbit/1";
}

fn number(text: &str) -> Number {
    Number::parse(text).unwrap_or_else(|| Number { exact: text.to_string(), f64: f64::NAN })
}

fn certificate_of(f: &Found) -> OrbitCertificateReport {
    let c = &f.certificate;
    let (centre, delta) = match &c.set {
        OrbitSet::Parallelepiped { centre, delta, .. } => {
            ([number(&centre.0), number(&centre.1), number(&centre.2)], number(delta))
        }
        // The producer writes parallelepipeds; a box is x* = (lo + hi)/2, delta = 1.
        OrbitSet::Box { lo, hi } => {
            let mid = |a: &str, b: &str| match (a.parse::<Q>(), b.parse::<Q>()) {
                (Ok(a), Ok(b)) => Number::of(&a.plus(&b).times(&Q::new(1, 2))),
                _ => number(a),
            };
            ([mid(&lo.0, &hi.0), mid(&lo.1, &hi.1), mid(&lo.2, &hi.2)], Number::of(&Q::int(1)))
        }
    };
    OrbitCertificateReport {
        claim: c.claim.name(),
        pattern: c.pattern.clone(),
        centre,
        delta,
        subdivision: c.subdivision,
        rho: number(&c.rho),
        lambda: number(&c.lambda),
        period: number(&c.period),
    }
}

/// The report of the producer's `result` on `req`, checked on `backends`; `output` is the file
/// written, if any; `times` (search, final kernel check) only when timings were asked for.
pub fn of(
    req: &Request,
    result: &Result<Found, Failure>,
    backends: &[Backend],
    output: Option<String>,
    times: Option<(std::time::Duration, std::time::Duration)>,
) -> CertifyOrbitReport {
    let found = result.as_ref().ok();
    let failure = result.as_ref().err();
    CertifyOrbitReport {
        schema: CertifyOrbitReport::SCHEMA,
        verdict: if found.is_some() { Verdict::Certified } else { Verdict::NotCertified },
        n: req.n,
        kappa: Number::of(&req.kappa),
        gamma: Number::of(&req.gamma),
        requested_pattern: req.pattern.as_ref().map(|p| p.iter().map(|&j| j as u64).collect()),
        drops: req.drops,
        max_depth: req.max_depth,
        certificate: found.map(certificate_of),
        diagnostics: found.map(Diagnostics::of),
        kernel: found.map(|f| KernelReport {
            sub_boxes: f.boxes,
            backends: backends.iter().map(|b| b.name).collect(),
            time_to_rest_bound: f.time_to_rest_bound.clone(),
        }),
        output: output.filter(|_| found.is_some()),
        reason: failure.map(Reason::of),
        message: failure.map(ToString::to_string),
        timings: times.map(|(search, kernel)| OrbitTimings { search_ms: ms(search), kernel_ms: ms(kernel) }),
    }
}

/// Runs the producer on `req` with the kernel on `backends` (nothing is written) and reports it
/// without timings; the producer's result holds the certificate itself.
pub fn certify(req: &Request, backends: &[Backend]) -> (CertifyOrbitReport, Result<Found, Failure>) {
    let result = crate::orbit::certify_orbit(req, backends);
    (of(req, &result, backends, None, None), result)
}
