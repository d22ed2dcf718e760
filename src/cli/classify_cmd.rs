//! `chatter classify`: every exact criterion at one body, with its evidence
//! (the report is built by [`crate::report::classify`]).

use super::{self as cli, emit, emit_report};
use crate::exact::parse_user_number;
use crate::report::classify::{ClassifyRequest, classify};
use clap::Args;

/// Raw arguments of `chatter classify`.
#[derive(Args, Debug)]
#[command(
    after_help = "Decides the paper's spectral criteria exactly (Sturm sequences, exact number fields for\n\
n = 5, 7, 8, ...) and shows the evidence, the float finder's verdict and whether a certificate\n\
can be produced.\n\nExamples:\n  chatter classify --n 3 --kappa 3/20 --gamma 1/20\n  chatter classify --n 2 --kappa 1/3 --gamma 0.05 --velocity 0.1,-0.5"
)]
pub struct ClassifyArgs {
    #[command(flatten)]
    pub body: super::BodyArgs,
    /// Rod only: initial velocity u0,u1 of the two ends, to decide CC from it (the paper's
    /// theorem on rotating initial velocities).
    #[arg(long, allow_hyphen_values = true)]
    pub velocity: Option<String>,
    /// Decimal digits of the printed enclosures.
    #[arg(long, default_value_t = 12)]
    pub digits: usize,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
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

pub fn run(a: ClassifyArgs) -> cli::Outcome {
    let json = a.json;
    let report = match validate(a).and_then(|r| classify(&r)) {
        Ok(r) => r,
        Err(e) => return cli::Outcome::Usage(e),
    };
    if json {
        emit_report(&report);
    } else {
        report.lines().iter().for_each(|l| emit(l));
    }
    cli::Outcome::Success
}
