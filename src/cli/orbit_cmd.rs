//! `chatter certify-orbit`: an orbit certificate (docs/orbit-certificates.md) for a regular
//! polygon at one parameter point.

use super::{Env, Outcome, emit};
use crate::exact::parse_user_number;
use crate::orbit::{Failure, Request, certify_orbit};
use chatter_kernel::certificate::write_orbit;
use clap::Args;
use std::path::PathBuf;

/// Raw arguments of `chatter certify-orbit`.
#[derive(Args, Debug)]
#[command(after_help = "Numbers are read exactly: 1/8, 0.15 (= 3/20).\n\n\
Proves complete chatter from every state of a set X around an attracting periodic impact\n\
pattern (not from every drop): docs/orbit-certificates.md.\n\n\
Example:\n  chatter certify-orbit --n 3 --kappa 1/8 --gamma 3/20 --pattern 2,2,1,1 -o orbit.ron")]
pub struct OrbitArgs {
    /// Number of contacts (3, 4 or 6).
    #[arg(long, default_value_t = 3)]
    pub n: u64,
    /// kappa = rho^2/R^2.
    #[arg(long)]
    pub kappa: String,
    /// Coefficient of restitution.
    #[arg(long)]
    pub gamma: String,
    /// The pattern's steps j (the next contact is j places on), comma-separated, e.g. 2,2,1,1;
    /// found by simulating random drops when omitted.
    #[arg(long, value_delimiter = ',')]
    pub pattern: Option<Vec<usize>>,
    /// Random drops simulated to find the pattern.
    #[arg(long, default_value_t = 20)]
    pub drops: u64,
    /// The deepest subdivision of X the certificate may ask the kernel for (the kernel examines
    /// at most 8^depth sub-boxes per box; deeper allows larger sets, slower checks).
    #[arg(long, default_value_t = 1)]
    pub max_depth: u64,
    /// Write the certificate here (only if the kernel accepts it).
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
    /// Print one JSON object instead of the one-line summary.
    #[arg(long)]
    pub json: bool,
}

fn failure_kind(f: &Failure) -> &'static str {
    match f {
        Failure::Body(_) => "body",
        Failure::NoPattern(_) => "no-pattern",
        Failure::NoAttractingCycle(_) => "no-attracting-cycle",
        Failure::PatternNotStable(_) => "pattern-not-stable",
        Failure::NoContraction(_) => "no-contraction",
        Failure::Internal(_) => "internal",
    }
}

pub fn run(a: OrbitArgs, env: &Env) -> Outcome {
    let (kappa, gamma) = match (parse_user_number(&a.kappa), parse_user_number(&a.gamma)) {
        (Ok(k), Ok(g)) => (k, g),
        (Err(e), _) => return Outcome::Usage(format!("--kappa: {e}")),
        (_, Err(e)) => return Outcome::Usage(format!("--gamma: {e}")),
    };
    let head = format!("n={} kappa={} gamma={}", a.n, kappa, gamma);
    let req = Request {
        n: a.n,
        kappa,
        gamma,
        pattern: a.pattern.clone(),
        drops: a.drops,
        max_depth: a.max_depth.min(chatter_kernel::orbit::MAX_DEPTH),
    };
    let result = certify_orbit(&req, &env.backends);
    if let (Ok(found), Some(path)) = (&result, &a.output) {
        if let Err(e) = std::fs::write(path, write_orbit(&found.certificate)) {
            return Outcome::Usage(format!("cannot write {}: {e}", path.display()));
        }
    }
    let out = a.output.as_ref().map(|p| p.display().to_string());
    match &result {
        Ok(f) => {
            if a.json {
                let v = serde_json::json!({
                    "command": "certify-orbit",
                    "status": "certified",
                    "n": a.n, "kappa": crate::exact::to_canonical(&req.kappa), "gamma": crate::exact::to_canonical(&req.gamma),
                    "claim": "CompleteChatterFromSet",
                    "pattern": f.pattern,
                    "fixed_point": f.fixed_point,
                    "eigenvalues": f.eigenvalues,
                    "alpha": f.scales[0], "beta": f.scales[1], "ratio": f.scales[2], "period_time": f.scales[3],
                    "delta": f.delta,
                    "sub_boxes": f.boxes,
                    "kernel_seconds": f.kernel_seconds,
                    "output": out,
                });
                emit(&v.to_string());
            } else {
                let written = out.map_or(" (no -o: not written)".to_string(), |p| format!(" -> {p}"));
                emit(&format!(
                    "CERTIFIED {head} claim=CompleteChatterFromSet: pattern {:?}, fixed point ({:.6}, {:.6}, {:.6}), eigenvalues ({:.5}, {:.5}, {:.5}), alpha {:.5}, beta {:.5}, alpha/beta {:.5}; X = x* + A [-delta, delta]^3 with delta = {:e}, {} sub-boxes, kernel {:.2} s ({} + {}){written}",
                    f.pattern,
                    f.fixed_point[0],
                    f.fixed_point[1],
                    f.fixed_point[2],
                    f.eigenvalues[0],
                    f.eigenvalues[1],
                    f.eigenvalues[2],
                    f.scales[0],
                    f.scales[1],
                    f.scales[2],
                    f.delta,
                    f.boxes,
                    f.kernel_seconds,
                    env.backends[0].name,
                    env.backends[1].name
                ));
            }
            Outcome::Success
        }
        Err(e) => {
            if a.json {
                let v = serde_json::json!({
                    "command": "certify-orbit",
                    "status": "not-certified",
                    "n": a.n, "kappa": crate::exact::to_canonical(&req.kappa), "gamma": crate::exact::to_canonical(&req.gamma),
                    "failure": failure_kind(e),
                    "reason": e.to_string(),
                });
                emit(&v.to_string());
            } else {
                emit(&format!("NOT CERTIFIED {head}: {e}"));
            }
            match e {
                Failure::Internal(s) => Outcome::Internal(s.clone()),
                Failure::Body(s) => Outcome::Usage(s.clone()),
                _ => Outcome::Negative,
            }
        }
    }
}
