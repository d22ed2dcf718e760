//! `chatter refute`: an exact refutation of a claim at a point, checked by the kernel on both
//! backends before it is written (docs/certificate-format.md §10).

use super::certify_cmd::ClaimArg;
use super::{Env, Outcome, emit, emit_report};
use crate::exact::Q;
use crate::refute::{RefuteConfig, refute};
use crate::report::refute::RefuteReport;
use crate::report::{Timings, ms};
use crate::write::write_refutation as write;
use chatter_kernel::certificate::Claim;
use chatter_kernel::model::Shape;
use chatter_kernel::refute::Refutation;
use chatter_kernel::verify::{Verdict, verify_refutation};
use clap::Args;
use std::path::PathBuf;
use std::time::Instant;

/// Raw arguments of `chatter refute`.
#[derive(Args, Debug)]
#[command(
    after_help = "Derives, exactly, velocities that every convex cone containing the claim's seeds and\n\
satisfying S_j(K ∩ C_j) ⊆ K must contain, until one has v >= 0: then no certificate of the claim\n\
exists at this point. The derivation is checked by the trusted kernel on both backends before it\n\
is written, and `chatter verify` re-checks it.\n\n\
Without --claim (or with `strongest`), tries EffectivelyInvariant first (seeded by the post-impact\n\
velocity of a pure translation; refutes all three claims), then the all-down claims.\n\
Exit status 0 if refuted, 1 if not, 2 on bad input, 3 if the backends disagree.\n\n\
Example:\n  chatter refute --n 4 --kappa 1/6 --gamma 1/10 -o refutation.ron"
)]
pub struct RefuteArgs {
    #[command(flatten)]
    pub body: super::BodyArgs,
    /// The claim to refute.
    #[arg(long, value_enum, default_value = "strongest")]
    pub claim: ClaimArg,
    /// Write the refutation here (only if the kernel accepts it).
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
    /// Print one JSON object instead of the one-line summary.
    #[arg(long)]
    pub json: bool,
    /// With --json: include the wall-clock times (then the output differs from run to run).
    #[arg(long)]
    pub timings: bool,
    /// Iteration budget of the exact cone iteration.
    #[arg(long, default_value_t = RefuteConfig::default().max_iterations)]
    pub max_iterations: usize,
}

fn claims(a: ClaimArg) -> Vec<Claim> {
    match a {
        ClaimArg::Strongest => vec![Claim::EffectivelyInvariant, Claim::CcOrPccFromAllDown],
        ClaimArg::EffectivelyInvariant => vec![Claim::EffectivelyInvariant],
        ClaimArg::CcOrPccFromAllDown => vec![Claim::CcOrPccFromAllDown],
        ClaimArg::CompleteChatterFromAllDown => vec![Claim::CompleteChatterFromAllDown],
    }
}

pub fn run(a: RefuteArgs, env: &Env) -> Outcome {
    let (n, kappa, gamma) = match a.body.parse() {
        Ok(x) => x,
        Err(e) => return Outcome::Usage(e),
    };
    if let Err(e) = Shape::new(n, kappa.clone(), gamma.clone()) {
        let ns = "n = 2 (the rod), 3, 4 or 6 (refutations need a rational cos 2π/n)";
        return Outcome::Usage(super::body_error(&e, n, &kappa, &gamma, ns));
    }
    let cfg = RefuteConfig { max_iterations: a.max_iterations, ..RefuteConfig::default() };
    let start = Instant::now();
    let mut why = Vec::new();
    for claim in claims(a.claim) {
        match refute(n, &kappa, &gamma, claim, &cfg) {
            Ok(r) => return checked(&a, r, env, start, [&kappa, &gamma]),
            Err(e) => why.push(format!("{}: {e}", claim.name())),
        }
    }
    let head = head(n, &kappa, &gamma);
    if a.json {
        emit_report(&RefuteReport::not_refuted(n, &kappa, &gamma, why));
    } else {
        emit(&format!("NOT REFUTED {head}: {}", why.join("; ")));
    }
    Outcome::Negative
}

fn head(n: u64, kappa: &Q, gamma: &Q) -> String {
    format!("n={n} kappa={kappa} gamma={gamma}")
}

/// Checks the refutation with the kernel, then writes and reports it.
fn checked(a: &RefuteArgs, r: Refutation, env: &Env, start: Instant, [kq, gq]: [&Q; 2]) -> Outcome {
    let search = start.elapsed();
    let t = Instant::now();
    let verdict = verify_refutation(&r, Default::default(), &env.backends);
    let kernel = t.elapsed();
    let done = match verdict {
        Verdict::Accepted(done) => done,
        Verdict::Rejected(rej) => {
            return Outcome::Internal(format!("the kernel rejects the refutation chatter produced: {rej}"));
        }
        Verdict::Disagree(s) => return Outcome::Internal(format!("the backends disagree: {s}")),
    };
    if let Some(path) = &a.output
        && let Err(e) = std::fs::write(path, write(&r))
    {
        return Outcome::Usage(format!("cannot write {}: {e}", path.display()));
    }
    let chatter_kernel::certificate::Body::RegularPolygon { n, kappa, gamma } = &r.body;
    let (k, g) = (kappa.texts()[0].to_string(), gamma.texts()[0].to_string());
    let v = if done.v_positive { "v > 0" } else { "v = 0" };
    if a.json {
        let mut report =
            RefuteReport::refuted(kq, gq, &done, a.output.as_ref().map(|p| p.display().to_string()));
        report.timings =
            a.timings.then(|| Timings { search_ms: ms(search), exactify_ms: 0.0, kernel_ms: ms(kernel) });
        emit_report(&report);
    } else {
        let out =
            a.output.as_ref().map_or(" (no -o: not written)".to_string(), |p| format!(" -> {}", p.display()));
        emit(&format!(
            "REFUTED n={n} kappa={k} gamma={g} claim={}: {} derived points, the last ({}) with {v}; search {:.2} ms, kernel {:.2} ms ({} + {}){out}",
            done.claim.name(),
            done.points,
            done.last.iter().map(|x| chatter_kernel::explain::abbreviate(x)).collect::<Vec<_>>().join(", "),
            search.as_secs_f64() * 1e3,
            kernel.as_secs_f64() * 1e3,
            env.backends[0].name,
            env.backends[1].name,
        ));
    }
    Outcome::Success
}
