//! `chatter certify`.

use super::{Env, Outcome, emit};
use crate::certify::{ClaimChoice, Failure, Report, Request, certify};
use crate::finder::Search;
use chatter_kernel::certificate::{Claim, write};
use chatter_kernel::model::BodyError;
use clap::{Args, ValueEnum};
use serde_json::json;
use std::path::PathBuf;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ClaimArg {
    /// The strongest claim that can be certified (tries complete chatter first).
    Strongest,
    /// Conditions 1-2: K in v <= 0 and S_j(K ∩ C_j) ⊆ K.
    EffectivelyInvariant,
    /// Also every all-down drop lands in K after its first impact: CC or PCC.
    CcOrPccFromAllDown,
    /// Also PCC excluded: every all-down drop ends in complete chatter.
    CompleteChatterFromAllDown,
}

/// Raw arguments of `chatter certify`.
#[derive(Args, Debug)]
#[command(after_help = "Numbers are read exactly: 1/6, 0.01 (= 1/100), 1e-2.\n\
Defaults certify the flat homogeneous square plate: n = 4, kappa = 1/6, gamma = 1/100.\n\
kappa and gamma may be closed intervals a:b: one cone then certifies every (kappa, gamma) of the\n\
box (a box certificate, docs/certificate-format.md).\n\n\
Examples:\n  chatter certify --n 3 --kappa 3/20 --gamma 0.05 -o triangle.ron\n  \
chatter certify --kappa 1/10:3/25 --gamma 1/100:1/50 -o box.ron")]
pub struct CertifyArgs {
    #[command(flatten)]
    pub body: super::BodyArgs,
    /// The claim to certify.
    #[arg(long, value_enum, default_value = "strongest")]
    pub claim: ClaimArg,
    /// Write the certificate here (only if the kernel accepts it).
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
    /// Print one JSON object instead of the one-line summary.
    #[arg(long)]
    pub json: bool,
    /// Iteration budget of the float finder (near the CC threshold the cone converges slowly:
    /// at relative distance 1e-6 below it, about 10,000 to 25,000 iterations for n = 4, 6).
    #[arg(long, default_value_t = crate::finder::FinderConfig::default().max_iterations)]
    pub max_iterations: usize,
    /// Vertex budget of the float polygon (outer approximation beyond it).
    #[arg(long, default_value_t = 40)]
    pub max_vertices: usize,
}

/// Validated arguments.
struct Validated {
    req: Request,
    output: Option<PathBuf>,
    json: bool,
}

fn validate(a: CertifyArgs, env: &Env) -> Result<Validated, String> {
    let (n, kappa, gamma) = a.body.parse_ranges()?;
    for (k, g) in [(&kappa[0], &gamma[0]), (&kappa[1], &gamma[1])] {
        if let Err(e) = crate::certify::check_body(n, k, g) {
            let flag = match e {
                BodyError::UnsupportedN(_) => "--n",
                BodyError::KappaNotPositive => "--kappa",
                BodyError::GammaOutOfRange => "--gamma",
            };
            return Err(format!("{flag}: {e}"));
        }
    }
    if a.max_vertices < 3 {
        return Err("--max-vertices must be at least 3".into());
    }
    let mut req = Request::boxed(n, kappa, gamma);
    req.claim = match a.claim {
        ClaimArg::Strongest => ClaimChoice::Strongest,
        ClaimArg::EffectivelyInvariant => ClaimChoice::Exactly(Claim::EffectivelyInvariant),
        ClaimArg::CcOrPccFromAllDown => ClaimChoice::Exactly(Claim::CcOrPccFromAllDown),
        ClaimArg::CompleteChatterFromAllDown => ClaimChoice::Exactly(Claim::CompleteChatterFromAllDown),
    };
    req.finder.max_iterations = a.max_iterations;
    req.finder.max_vertices = a.max_vertices;
    req.backends = env.backends;
    Ok(Validated { req, output: a.output, json: a.json })
}

fn ms(d: std::time::Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

fn finder_json(f: &Option<Search<usize>>) -> serde_json::Value {
    match f {
        None => serde_json::Value::Null,
        Some(Search::Found { cone, iterations }) => {
            json!({"outcome": "found", "iterations": iterations, "vertices": cone})
        }
        Some(Search::NoCone { iteration, step }) => {
            json!({"outcome": "no-cone", "iteration": iteration, "step": step})
        }
        Some(Search::Inconclusive { iterations, reason }) => {
            json!({"outcome": "inconclusive", "iterations": iterations, "reason": reason})
        }
    }
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
                "CERTIFIED {head} claim={}: {} generators, largest denominator {} bits, by {}; {times}{out}{notes}",
                c.claim.name(),
                c.cone.len(),
                r.max_denominator_bits,
                r.method.unwrap_or("?")
            )
        }
        Err(e) => format!("NOT CERTIFIED {head}: {e}; {times}{notes}"),
    }
}

/// A parameter in JSON: its text, or [lo, hi] for a box.
fn param_json(lo: &crate::exact::Q, hi: Option<&crate::exact::Q>) -> serde_json::Value {
    match hi {
        Some(hi) => json!([lo.to_string(), hi.to_string()]),
        None => json!(lo.to_string()),
    }
}

pub fn run(a: CertifyArgs, env: &Env) -> Outcome {
    let v = match validate(a, env) {
        Ok(v) => v,
        Err(e) => return Outcome::Usage(e),
    };
    let report = certify(&v.req);
    if let (Ok(cert), Some(path)) = (&report.result, &v.output) {
        if let Err(e) = std::fs::write(path, write(cert)) {
            return Outcome::Usage(format!("cannot write {}: {e}", path.display()));
        }
    }
    if v.json {
        let t = &report.timings;
        let obj = json!({
            "status": if report.result.is_ok() { "certified" } else { "not-certified" },
            "n": v.req.n,
            "kappa": param_json(&v.req.kappa, v.req.upper.as_ref().map(|u| &u.0)),
            "gamma": param_json(&v.req.gamma, v.req.upper.as_ref().map(|u| &u.1)),
            "claim": report.result.as_ref().ok().map(|c| c.claim.name()),
            "generators": report.result.as_ref().ok().map(|c| c.cone.len()),
            "max_denominator_bits": report.result.as_ref().ok().map(|_| report.max_denominator_bits),
            "output": v.output.as_ref().filter(|_| report.result.is_ok()).map(|p| p.display().to_string()),
            "reason": report.result.as_ref().err().map(ToString::to_string),
            "method": report.method,
            "finder": finder_json(&report.finder),
            "timings_ms": {"finder": ms(t.finder), "exactify": ms(t.exactify), "kernel": ms(t.kernel)},
            "notes": report.notes,
        });
        emit(&obj.to_string());
    } else {
        emit(&summary(&v, &report));
    }
    match &report.result {
        Ok(_) => Outcome::Success,
        Err(Failure::Internal(s)) => Outcome::Internal(s.clone()),
        Err(_) => Outcome::Negative,
    }
}
