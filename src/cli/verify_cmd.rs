//! `chatter verify`.

use super::{Env, Outcome, emit, emit_report};
use crate::verify::expect::Manifest;
use crate::verify::files;
use crate::verify::{DEFAULT_MAX_FILE_SIZE, DEFAULT_TIME_LIMIT, Options, Summary, verify_all};
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::Backend;
use clap::{Args, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use std::path::PathBuf;
use std::time::Duration;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum BackendArg {
    /// malachite and num-rational; any disagreement is an internal error.
    Both,
    Malachite,
    Num,
}

/// Raw arguments of `chatter verify`.
#[derive(Args, Debug)]
#[command(
    after_help = "Prints one line per input, `PATH: OK (...)`, `PATH: REJECTED: reason` or `PATH: ERROR: reason`,\n\
then a summary line. A directory is searched recursively for *.ron and *.ron.gz files (any letter\n\
case) and for *.json and *.json.gz files that declare \"format\": \"chatter-certificate\" or\n\
\"chatter-refutation\" (the JSON twin; manifests are skipped); every real path is checked at most\n\
once. Limits (file size, generators, digits, time) are reported as REJECTED with the code\n\
too-large or time-limit, naming the limit.\n\n\
Exit status: 3 if the backends disagree on an input (a bug); else 2 if an input could not be\n\
read; else 1 if one was rejected; else 0. With --expect: 0 if every verdict is the expected one,\n\
1 if any differs (each mismatch is printed), 2 if the manifest cannot be read.\n\n\
Examples:\n  chatter verify square.ron\n  chatter verify certificates/valid\n  chatter verify --expect certificates/invalid/expected.json"
)]
pub struct VerifyArgs {
    /// Certificate files (RON or JSON), or directories searched recursively (default with
    /// --expect: the manifest's directory).
    #[arg(required_unless_present = "expect")]
    pub paths: Vec<PathBuf>,
    /// Compare every verdict with a manifest of expected verdicts (JSON, the form of
    /// certificates/invalid/expected.json) and report every mismatch.
    #[arg(long, value_name = "MANIFEST")]
    pub expect: Option<PathBuf>,
    /// Print one JSON object (summary and one entry per input).
    #[arg(long)]
    pub json: bool,
    /// Bignum backends the kernel runs on.
    #[arg(long, value_enum, default_value = "both")]
    pub backend: BackendArg,
    /// Longest number accepted, in decimal digits (numerator and denominator together).
    #[arg(long, default_value_t = ParseLimits::default().max_digits)]
    pub max_digits: usize,
    /// Most digits of all the numbers of one file together.
    #[arg(long, default_value_t = ParseLimits::default().max_total_digits)]
    pub max_total_digits: usize,
    /// Most generators of one cone.
    #[arg(long, default_value_t = ParseLimits::default().max_generators)]
    pub max_generators: usize,
    /// Largest file read, in bytes (after decompression for gzip'd files).
    #[arg(long, default_value_t = DEFAULT_MAX_FILE_SIZE)]
    pub max_file_size: u64,
    /// Longest time per file, in seconds, over all backends (0: no limit).
    #[arg(long, default_value_t = DEFAULT_TIME_LIMIT.as_secs())]
    pub time_limit: u64,
}

fn backends(a: BackendArg, env: &Env) -> Vec<Backend> {
    match a {
        BackendArg::Both => env.backends.to_vec(),
        BackendArg::Malachite => vec![env.backends[0]],
        BackendArg::Num => vec![env.backends[1]],
    }
}

/// The validated options (second layer of argument parsing).
fn options(a: &VerifyArgs, env: &Env) -> Options {
    let limits = ParseLimits {
        max_digits: a.max_digits,
        max_total_digits: a.max_total_digits,
        max_generators: a.max_generators,
        deadline: None,
    };
    let time_limit = (a.time_limit > 0).then(|| Duration::from_secs(a.time_limit));
    Options { limits, max_file_size: a.max_file_size, time_limit, backends: backends(a.backend, env) }
}

fn progress(n: usize) -> ProgressBar {
    let bar = ProgressBar::new(n as u64);
    bar.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} {msg}").expect("valid template"));
    if n < 20 {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    bar
}

pub fn run(a: VerifyArgs, env: &Env) -> Outcome {
    let manifest = match a.expect.as_deref().map(Manifest::read).transpose() {
        Ok(m) => m,
        Err(e) => return Outcome::Usage(e),
    };
    let paths = match (&manifest, a.paths.is_empty()) {
        (Some(m), true) => vec![m.dir.clone()],
        _ => a.paths.clone(),
    };
    let listing = files::list_with(&paths, a.max_file_size);
    if listing.entries.is_empty() {
        return Outcome::Usage(format!(
            "no certificate files (*.ron, *.ron.gz, or *.json, *.json.gz declaring a certificate) found; {}",
            Summary::of(&[], listing.skipped).line()
        ));
    }
    let opts = options(&a, env);
    let bar = progress(listing.entries.len());
    let verdicts = verify_all(&listing, &opts, |v| {
        if !a.json {
            bar.suspend(|| emit(&v.line()));
        }
        bar.inc(1);
    });
    bar.finish_and_clear();
    let summary = Summary::of(&verdicts, listing.skipped);
    let mismatches = manifest.as_ref().map(|m| m.mismatches(&verdicts));
    if a.json {
        emit_report(&crate::report::verify::of(&verdicts, summary, mismatches.clone()));
    } else {
        emit(&summary.line());
        if let Some(ms) = &mismatches {
            ms.iter().for_each(|m| emit(&format!("MISMATCH {m}")));
            emit(&format!("{} mismatches with the manifest", ms.len()));
        }
    }
    outcome(&summary, &verdicts, mismatches.as_deref())
}

/// The documented exit rule over all inputs (see `--help`).
fn outcome(s: &Summary, verdicts: &[crate::verify::FileVerdict], mismatches: Option<&[String]>) -> Outcome {
    if let Some(v) = verdicts.iter().find(|v| v.is_internal()) {
        return Outcome::Internal(format!("{}: the backends disagree", v.path));
    }
    if let Some(ms) = mismatches {
        return Outcome::from_answer(ms.is_empty());
    }
    if s.errors > 0 {
        let first = verdicts
            .iter()
            .find(|v| v.status == crate::verify::Status::Error)
            .map_or("", |v| v.path.as_str());
        return Outcome::Usage(format!(
            "{} of {} inputs could not be read (the first: {first})",
            s.errors, s.inputs
        ));
    }
    Outcome::from_answer(s.rejected == 0)
}
