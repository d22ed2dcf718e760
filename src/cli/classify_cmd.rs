//! `chatter classify`: every exact criterion at one body, with its evidence
//! (the report is built by [`crate::report::classify`]).

use super::{self as cli, emit, emit_report};
use crate::exact::parse_user_number;
use crate::exact::{Q, Ring};
use crate::report::classify::{ClassifyReport, ClassifyRequest, classify};
use crate::report::classify_general::classify_general;
use crate::write::write_orbit;
use clap::Args;
use std::path::PathBuf;

/// Raw arguments of `chatter classify`.
#[derive(Args, Debug)]
#[command(
    after_help = "Decides the paper's spectral criteria exactly (Sturm sequences, exact number fields for\n\
n = 5, 7, 8, ...) and shows the evidence, the float finder's verdict and whether a certificate\n\
can be produced. Where the CC criterion fails but simulated drops end in CC, or 200 more drops\n\
find a periodic pattern (a regular n-gon, 3 <= n <= 64), an orbit certificate\n\
(docs/orbit-certificates.md): CC proved from an explicit set X of post-impact states, not from\n\
every drop.\n\n\
General bodies (--rectangle, --box, --polygon, --body; docs/model.md §11.11): the conjectural\n\
criteria of the products of impact maps once around the polygon in both directions, the PCC\n\
lemma per adjacent pair, simulated drops and the certificate.\n\nExamples:\n  chatter classify --n 3 --kappa 3/20 --gamma 1/20\n  chatter classify --n 3 --kappa 1/8 --gamma 3/20 --orbit-out orbit.ron\n  chatter classify --n 2 --kappa 1/3 --gamma 0.05 --velocity 0.1,-0.5\n  chatter classify --rectangle 2,1 --gamma 1/20\n  chatter classify --body phone --gamma 1/20"
)]
pub struct ClassifyArgs {
    #[command(flatten)]
    pub body: super::BodyArgs,
    #[command(flatten)]
    pub general: super::convex_args::ConvexArgs,
    /// Rod only: initial velocity u0,u1 of the two ends, to decide CC from it (the paper's
    /// theorem on rotating initial velocities).
    #[arg(long, allow_hyphen_values = true)]
    pub velocity: Option<String>,
    /// Decimal digits of the printed enclosures.
    #[arg(long, default_value_t = 12)]
    pub digits: usize,
    /// Where the CC criterion fails but simulated drops end in CC, classify tries an orbit
    /// certificate (docs/orbit-certificates.md); write it here if the kernel accepts it.
    #[arg(long, value_name = "FILE")]
    pub orbit_out: Option<PathBuf>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

/// A general body (docs/model.md §11.11): `None` when none was asked for.
fn general(a: &ClassifyArgs, gamma: &Q) -> Result<Option<ClassifyReport>, String> {
    if !a.general.given() {
        return Ok(None);
    }
    if a.velocity.is_some() {
        return Err("--velocity is for the rod (--n 2), not for general bodies".into());
    }
    if gamma.is_negative() || *gamma > Q::int(1) {
        return Err(format!("--gamma: {gamma} is not accepted: gamma must lie in [0, 1]"));
    }
    match a.general.parse(gamma, a.body.gamma.is_some())? {
        Some(g) => classify_general(&g.description, &g.body, a.digits).map(Some),
        None => Ok(None),
    }
}

fn validate(a: ClassifyArgs) -> Result<ClassifyRequest, String> {
    let (n, kappa, gamma) = a.body.parse()?;
    let velocity = match a.velocity {
        None => None,
        Some(_) if n != 2 => return Err("--velocity is for the rod (--n 2)".into()),
        Some(v) => {
            let parts: Vec<&str> = v.split(',').collect();
            if parts.len() != 2 {
                return Err(format!("--velocity: expected u0,u1, got {v:?}"));
            }
            let p = |s: &str| parse_user_number(s).map_err(|e| format!("--velocity: {e}"));
            Some([p(parts[0])?, p(parts[1])?])
        }
    };
    let r = ClassifyRequest { n, kappa, gamma, velocity, digits: a.digits };
    r.validate()?;
    Ok(r)
}

/// The report of a general body if one was given, else of the regular body (n, kappa, gamma).
fn report(a: ClassifyArgs) -> Result<ClassifyReport, String> {
    let (_, _, gamma) = a.body.parse()?;
    match general(&a, &gamma)? {
        Some(r) => Ok(r),
        None => validate(a).and_then(|r| classify(&r)),
    }
}

/// Writes the orbit certificate to `--orbit-out` if one was accepted; the text line to add when
/// none was.
fn write_orbit_out(report: &mut ClassifyReport, path: &std::path::Path) -> Result<Option<String>, String> {
    let Some(cert) = report.orbit.as_ref().and_then(|o| o.certificate.as_ref()) else {
        return Ok(Some(format!("--orbit-out: no orbit certificate, {} not written", path.display())));
    };
    std::fs::write(path, write_orbit(cert)).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    if let Some(o) = report.orbit.as_mut() {
        o.file = Some(path.display().to_string());
    }
    Ok(None)
}

pub fn run(a: ClassifyArgs) -> cli::Outcome {
    let json = a.json;
    let orbit_out = a.orbit_out.clone();
    let mut report = match report(a) {
        Ok(r) => r,
        Err(e) => return cli::Outcome::Usage(e),
    };
    let note = match orbit_out.as_deref().map(|p| write_orbit_out(&mut report, p)) {
        Some(Err(e)) => return cli::Outcome::Usage(e),
        Some(Ok(note)) => note,
        None => None,
    };
    if json {
        emit_report(&report);
    } else {
        report.lines().iter().for_each(|l| emit(l));
        if let Some(n) = note {
            emit(&n);
        }
    }
    match report.orbit.as_ref().filter(|o| o.failure == Some("internal")) {
        Some(o) => cli::Outcome::Internal(o.reason.clone().unwrap_or_default()),
        None => cli::Outcome::Success,
    }
}
