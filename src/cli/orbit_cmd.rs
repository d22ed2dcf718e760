//! `chatter certify-orbit`: an orbit certificate (docs/orbit-certificates.md) for a regular
//! polygon at one parameter point.

use super::{Env, Outcome, emit, emit_report};
use crate::exact::parse_user_number;
use crate::orbit::{Failure, Request, certify_orbit};
use crate::write::write_orbit;
use clap::Args;
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// Raw arguments of `chatter certify-orbit`.
#[derive(Args, Debug)]
#[command(after_help = "Numbers are read exactly: 1/8, 0.15 (= 3/20).\n\n\
Proves complete chatter from every state of a set X around an attracting periodic impact\n\
pattern (not from every drop): docs/orbit-certificates.md.\n\n\
Examples:\n  chatter certify-orbit --n 3 --kappa 1/8 --gamma 3/20 --pattern 2,2,1,1 -o orbit.ron\n  \
chatter certify-orbit --n 5 --kappa 961/25600 --gamma 61/160 --pattern 1,1,2,4,4,3 -o pentagon.ron")]
pub struct OrbitArgs {
    #[command(flatten)]
    pub body: OrbitBody,
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
    /// Print one JSON object (`chatter.certify-orbit/1`) instead of the one-line summary.
    #[arg(long)]
    pub json: bool,
    /// With --json: include the wall-clock times (then the output differs from run to run).
    #[arg(long)]
    pub timings: bool,
}

/// The body, the parameter point and the pattern of an orbit certificate (`certify-orbit` and
/// `basin`, which certifies its set X first).
#[derive(Args, Debug)]
pub struct OrbitBody {
    /// Number of contacts, 3 to 64 (the body's constants in Q(cos 2 pi/n), enclosed by rationals,
    /// where that cosine is irrational).
    #[arg(long, default_value_t = 3)]
    pub n: u64,
    /// kappa = rho^2/R^2.
    #[arg(long, allow_hyphen_values = true)]
    pub kappa: String,
    /// Coefficient of restitution.
    #[arg(long, allow_hyphen_values = true)]
    pub gamma: String,
    /// The orbit's pattern: its steps j (the next contact is j places on), comma-separated, e.g.
    /// 2,2,1,1, each in 1..n-1, at most 64 steps; found by simulating random drops when omitted.
    #[arg(long, allow_hyphen_values = true)]
    pub pattern: Option<String>,
}

impl OrbitBody {
    /// The request these arguments name, with the given search settings, or a usage error
    /// naming the flag.
    pub(super) fn request(&self, drops: u64, max_depth: u64) -> Result<Request, String> {
        if !(3..=crate::exact::MAX_N).contains(&self.n) {
            return Err(format!(
                "--n: {} is not supported here: give 3 <= n <= {} (a regular n-gon)",
                self.n,
                crate::exact::MAX_N
            ));
        }
        let kappa = parse_user_number(&self.kappa).map_err(|e| format!("--kappa: {e}"))?;
        let gamma = parse_user_number(&self.gamma).map_err(|e| format!("--gamma: {e}"))?;
        if let Err(e) = crate::certify::check_body(self.n, &kappa, &gamma) {
            return Err(super::body_error(&e, self.n, &kappa, &gamma, "3 <= n <= 64"));
        }
        let pattern = self.pattern.as_deref().map(|p| parse_pattern(p, self.n)).transpose()?;
        Ok(Request { n: self.n, kappa, gamma, pattern, drops, max_depth })
    }
}

/// The most steps a pattern may have (docs/certificate-format.md §14).
pub const MAX_PATTERN: usize = 64;

/// `--pattern` text: comma-separated steps, each in 1..n-1.
pub(super) fn parse_pattern(text: &str, n: u64) -> Result<Vec<usize>, String> {
    let mut steps = Vec::new();
    for (i, part) in text.split(',').enumerate() {
        let part = part.trim();
        let j: u64 = part.parse().map_err(|_| {
            format!(
                "--pattern: {text:?}: step {} ({part:?}) is not a non-negative integer (write e.g. 2,2,1,1)",
                i + 1
            )
        })?;
        if j == 0 || j >= n {
            return Err(format!(
                "--pattern: {text:?}: step {} is {j}, outside 1..{} (the next contact is j places on, j = 1..n-1 for n = {n})",
                i + 1,
                n - 1
            ));
        }
        steps.push(j as usize);
    }
    if steps.len() > MAX_PATTERN {
        return Err(format!("--pattern: {} steps, more than {MAX_PATTERN}", steps.len()));
    }
    Ok(steps)
}

/// The validated request, or a usage error naming the flag.
fn validate(a: &OrbitArgs) -> Result<Request, String> {
    if a.max_depth > chatter_kernel::orbit::MAX_DEPTH {
        return Err(format!(
            "--max-depth: {} is more than the kernel's limit {}",
            a.max_depth,
            chatter_kernel::orbit::MAX_DEPTH
        ));
    }
    a.body.request(a.drops, a.max_depth)
}

pub fn run(a: OrbitArgs, env: &Env) -> Outcome {
    let req = match validate(&a) {
        Ok(r) => r,
        Err(e) => return Outcome::Usage(e),
    };
    let head = format!("n={} kappa={} gamma={}", req.n, req.kappa, req.gamma);
    let start = Instant::now();
    let result = certify_orbit(&req, &env.backends);
    let elapsed = start.elapsed();
    if let (Ok(found), Some(path)) = (&result, &a.output)
        && let Err(e) = std::fs::write(path, write_orbit(&found.certificate))
    {
        return Outcome::Usage(format!("cannot write {}: {e}", path.display()));
    }
    match &result {
        Err(Failure::Body(s)) => return Outcome::Usage(s.clone()),
        Err(Failure::Internal(s)) => return Outcome::Internal(s.clone()),
        _ => {}
    }
    let out = a.output.as_ref().map(|p| p.display().to_string());
    if a.json {
        let times = a.timings.then(|| {
            let kernel =
                result.as_ref().map_or(Duration::ZERO, |f| Duration::from_secs_f64(f.kernel_seconds));
            (elapsed.saturating_sub(kernel), kernel)
        });
        emit_report(&crate::report::orbit::of(&req, &result, &env.backends, out, times));
        return Outcome::from_answer(result.is_ok());
    }
    match &result {
        Ok(f) => {
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
            Outcome::Success
        }
        Err(e) => {
            let code = crate::report::orbit::Reason::of(e).name();
            emit(&format!("NOT CERTIFIED {head}: [{code}] {e}"));
            Outcome::Negative
        }
    }
}
