//! `chatter verify`.

use super::{Env, Outcome, emit};
use crate::verify::{Status, collect_files, verify_file};
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::Backend;
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
Exit status 0 only if every file verifies; 1 if one is rejected; 2 if one cannot be read;\n\
3 if the backends disagree (a bug).")]
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

fn backends(a: BackendArg, env: &Env) -> Vec<Backend> {
    match a {
        BackendArg::Both => env.backends.to_vec(),
        BackendArg::Malachite => vec![env.backends[0]],
        BackendArg::Num => vec![env.backends[1]],
    }
}

pub fn run(a: VerifyArgs, env: &Env) -> Outcome {
    let files = match collect_files(&a.paths) {
        Ok(f) => f,
        Err(e) => return Outcome::Usage(format!("cannot list certificates: {e}")),
    };
    if files.is_empty() {
        return Outcome::Usage("no certificate files (*.ron) found".into());
    }
    let backends = backends(a.backend, env);
    let limits = ParseLimits { max_digits: a.max_digits };
    let bar = ProgressBar::new(files.len() as u64);
    bar.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} {msg}").expect("valid template"));
    if files.len() < 20 {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    let mut verdicts = Vec::with_capacity(files.len());
    for f in &files {
        let v = verify_file(f, limits, &backends);
        if !a.json {
            bar.suspend(|| emit(&v.line()));
        }
        bar.inc(1);
        verdicts.push(v);
    }
    bar.finish_and_clear();
    let count = |s: Status| verdicts.iter().filter(|v| v.status == s).count();
    let (ok, rejected, errors) = (count(Status::Ok), count(Status::Rejected), count(Status::Error));
    if a.json {
        emit(&json!({"files": verdicts, "ok": ok, "rejected": rejected, "errors": errors}).to_string());
    } else if files.len() > 1 {
        eprintln!("{} files: {ok} OK, {rejected} rejected, {errors} errors", files.len());
    }
    if let Some(v) = verdicts.iter().find(|v| v.is_internal()) {
        Outcome::Internal(format!("{}: the backends disagree", v.path))
    } else if errors > 0 {
        Outcome::Usage(format!("{errors} of {} files could not be read", files.len()))
    } else {
        Outcome::from_answer(ok == files.len())
    }
}
