//! `chatter check-proof`: re-checks proof files with the trusted crate, on both backends.

use super::{Outcome, emit, emit_report};
use crate::report::prove::{CheckProofReport, ProofFileReport};
use crate::verify::format::format_of;
use crate::verify::read::{Input, read_input};
use crate::verify::{DEFAULT_MAX_FILE_SIZE, DEFAULT_TIME_LIMIT, with_time_limit};
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::{Verdict, verify_proof_text};
use clap::Args;
use std::path::PathBuf;

/// Raw arguments of `chatter check-proof`.
#[derive(Args, Debug)]
#[command(after_help = "Prints `FILE: OK` with what the proof establishes and under which hypotheses, or\n\
`FILE: REJECTED: step i `id`: reason`. Exit status 0 only if every step of every file checks; 1 if a\n\
step fails; 2 if a file cannot be read; 3 if the backends disagree (a bug).\n\n\
Example:\n  chatter check-proof proofs/square.ron")]
pub struct CheckProofArgs {
    /// Proof files (e.g. proofs/square.ron).
    #[arg(required = true)]
    pub paths: Vec<PathBuf>,
    /// Print one JSON object per file.
    #[arg(long)]
    pub json: bool,
    /// Longest number accepted, in decimal digits.
    #[arg(long, default_value_t = ParseLimits::default().max_digits)]
    pub max_digits: usize,
    /// Largest file read, in bytes.
    #[arg(long, default_value_t = DEFAULT_MAX_FILE_SIZE)]
    pub max_file_size: u64,
    /// Longest time per file, in seconds, over both backends (0: no limit).
    #[arg(long, default_value_t = DEFAULT_TIME_LIMIT.as_secs())]
    pub time_limit: u64,
}

pub fn run(a: CheckProofArgs) -> Outcome {
    let limits = ParseLimits::digits(a.max_digits);
    let time_limit = (a.time_limit > 0).then(|| std::time::Duration::from_secs(a.time_limit));
    let mut outcome = Outcome::Success;
    let mut reports = Vec::new();
    for path in &a.paths {
        let text = match read_input(path, a.max_file_size) {
            Input::Text { text, .. } => text,
            Input::TooLarge { what } => {
                return Outcome::Usage(format!(
                    "{}: {what}, more than --max-file-size = {}",
                    path.display(),
                    a.max_file_size
                ));
            }
            Input::Unreadable(why) => return Outcome::Usage(format!("{}: {why}", path.display())),
        };
        let p = path.display();
        let owned = text.clone();
        let run = move |deadline| verify_proof_text(&owned, ParseLimits { deadline, ..limits });
        let verdict = with_time_limit(time_limit, run).unwrap_or_else(|| {
            Verdict::Rejected(chatter_kernel::certificate::Rejection::time_limit("checking the proof"))
        });
        match verdict {
            Verdict::Accepted(c) => {
                if a.json {
                    reports.push(ProofFileReport::accepted(&p.to_string(), &c));
                } else {
                    emit(&format!("{p}: OK ({}: {} steps, malachite + num-rational)", c.name, c.steps));
                    emit(&format!("  hypotheses: {}", c.hypotheses.join("; ")));
                    for (i, x) in c.conclusions.iter().enumerate() {
                        emit(&format!("  {}. {x}", i + 1));
                    }
                    if !c.nonempty {
                        emit(
                            "  warning: no Witness shows that the region is not empty; the conclusions may be vacuous",
                        );
                    }
                }
            }
            Verdict::Rejected(r) => {
                if a.json {
                    reports.push(ProofFileReport::rejected(&p.to_string(), &r));
                } else {
                    let certificate =
                        ["chatter-certificate", "chatter-family-certificate", "chatter-orbit-certificate"];
                    let hint = if format_of(&text).is_some_and(|f| certificate.contains(&f.as_str())) {
                        " (this file is a certificate: use `chatter verify`)"
                    } else {
                        ""
                    };
                    emit(&format!("{p}: REJECTED: {}{hint}", r.message()));
                }
                outcome = Outcome::Negative;
            }
            Verdict::Disagree(s) => return Outcome::Internal(format!("{p}: the backends disagree: {s}")),
        }
    }
    if a.json {
        emit_report(&CheckProofReport::of(reports));
    }
    outcome
}
