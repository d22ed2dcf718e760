//! `chatter verify`.

use super::{EXIT_INTERNAL, EXIT_NEGATIVE, EXIT_OK, emit, usage_error};
use crate::exact::ParseLimits;
use crate::verify::{Backends, collect_files, verify_file};
use clap::{Args, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::json;
use std::path::PathBuf;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum BackendArg {
    /// malachite and num-rational; any disagreement is an internal error.
    Both,
    Malachite,
    Num,
}

/// Raw arguments of `chatter verify`.
#[derive(Args, Debug)]
#[command(after_help = "Prints one line per file: `PATH: OK (...)` or `PATH: REJECTED: reason`.\n\
Exit status 0 only if every file verifies.")]
pub struct VerifyArgs {
    /// Certificate files, or directories searched recursively for *.ron files.
    #[arg(required = true)]
    pub paths: Vec<PathBuf>,
    /// Print one JSON object (summary and one entry per file).
    #[arg(long)]
    pub json: bool,
    /// Bignum backends the kernel runs on.
    #[arg(long, value_enum, default_value = "both")]
    pub backend: BackendArg,
    /// Longest number accepted in a certificate, in decimal digits.
    #[arg(long, default_value_t = ParseLimits::default().max_digits)]
    pub max_digits: usize,
}

pub fn run(a: VerifyArgs) -> u8 {
    let files = match collect_files(&a.paths) {
        Ok(f) => f,
        Err(e) => return usage_error(format!("cannot list certificates: {e}")),
    };
    if files.is_empty() {
        return usage_error("no certificate files (*.ron) found");
    }
    let backends = match a.backend {
        BackendArg::Both => Backends::Both,
        BackendArg::Malachite => Backends::Malachite,
        BackendArg::Num => Backends::Num,
    };
    let limits = ParseLimits { max_digits: a.max_digits };
    let bar = ProgressBar::new(files.len() as u64);
    bar.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} {msg}").expect("valid template"));
    if files.len() < 20 {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    let mut verdicts = Vec::with_capacity(files.len());
    for f in &files {
        let v = verify_file(f, limits, backends);
        if !a.json {
            bar.suspend(|| emit(&v.line()));
        }
        bar.inc(1);
        verdicts.push(v);
    }
    bar.finish_and_clear();
    let count = |s: &str| verdicts.iter().filter(|v| v.status == s).count();
    let (ok, rejected, errors) = (count("OK"), count("REJECTED"), count("ERROR"));
    if a.json {
        emit(&json!({"files": verdicts, "ok": ok, "rejected": rejected, "errors": errors}).to_string());
    } else if files.len() > 1 {
        eprintln!("{} files: {ok} OK, {rejected} rejected, {errors} errors", files.len());
    }
    let internal = verdicts.iter().any(|v| v.code == Some(chatter_kernel::certificate::Code::Internal));
    if internal {
        EXIT_INTERNAL
    } else if ok == files.len() {
        EXIT_OK
    } else {
        EXIT_NEGATIVE
    }
}
