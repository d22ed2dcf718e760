//! `chatter.verify/1`: the kernel's verdict on certificate and refutation files. Build it with
//! [`verify`] (lists and checks the paths) or [`of`] (from verdicts already made).

use super::{Report, Verdict};
use crate::verify::files::list_with;
use crate::verify::{FileVerdict, Options, Status, Summary, verify_all};
use schemars::JsonSchema;
use serde::Serialize;
use std::path::PathBuf;

/// One input file.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct FileReport {
    /// `accepted`, `rejected` (with `code`, `locus`, `reason`) or `error` (unreadable, too
    /// large, or the backends disagree: `reason`).
    pub verdict: Verdict,
    #[serde(flatten)]
    pub file: FileVerdict,
}

impl FileReport {
    /// The report of one file's verdict.
    pub fn of(v: &FileVerdict) -> FileReport {
        let verdict = match v.status {
            Status::Ok => Verdict::Accepted,
            Status::Rejected => Verdict::Rejected,
            Status::Error => Verdict::Error,
        };
        FileReport { verdict, file: v.clone() }
    }
}

/// `chatter verify --json`.
#[derive(Clone, Debug, Serialize, JsonSchema)]
pub struct VerifyReport {
    /// `chatter.verify/1`.
    pub schema: &'static str,
    /// Over all inputs: `error` if one could not be read, else `rejected` if one was
    /// rejected, else `accepted`.
    pub verdict: Verdict,
    pub files: Vec<FileReport>,
    pub summary: Summary,
    /// With `--expect MANIFEST`: every verdict that differs from the manifest.
    pub mismatches: Option<Vec<String>>,
}

impl Report for VerifyReport {
    const SCHEMA: &'static str = "chatter.verify/1";
}

/// The report of verdicts already made.
pub fn of(verdicts: &[FileVerdict], summary: Summary, mismatches: Option<Vec<String>>) -> VerifyReport {
    let verdict = if summary.errors > 0 {
        Verdict::Error
    } else if summary.rejected > 0 {
        Verdict::Rejected
    } else {
        Verdict::Accepted
    };
    VerifyReport {
        schema: VerifyReport::SCHEMA,
        verdict,
        files: verdicts.iter().map(FileReport::of).collect(),
        summary,
        mismatches,
    }
}

/// Lists `paths` (files, and directories searched for certificate files) and checks every file
/// with the kernel under `opts` (`Options::new(vec![MALACHITE, NUM])`: both backends, the default limits).
pub fn verify(paths: &[PathBuf], opts: &Options) -> VerifyReport {
    let listing = list_with(paths, opts.max_file_size);
    let verdicts = verify_all(&listing, opts, |_| {});
    let summary = Summary::of(&verdicts, listing.skipped);
    of(&verdicts, summary, None)
}
