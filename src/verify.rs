//! Verification of certificate files: read each file, run the kernel on the chosen backends
//! ([`chatter_kernel::verify`]), and report one verdict per file.

use chatter_kernel::certificate::{Code, Locus};
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::{Backend, Verdict, format_of, verify_text};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// The verdict on one file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Status {
    /// Every backend accepts.
    #[serde(rename = "OK")]
    Ok,
    /// Every backend rejects, for the same reason.
    #[serde(rename = "REJECTED")]
    Rejected,
    /// The file cannot be read, or the backends disagree.
    #[serde(rename = "ERROR")]
    Error,
}

impl Status {
    /// The word printed in verdict lines.
    pub fn word(self) -> &'static str {
        match self {
            Status::Ok => "OK",
            Status::Rejected => "REJECTED",
            Status::Error => "ERROR",
        }
    }
}

/// One line of `chatter verify` output.
#[derive(Clone, Debug, Serialize)]
pub struct FileVerdict {
    pub path: String,
    pub status: Status,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub claim: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub n: Option<u64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub generators: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub redundant: Option<Vec<usize>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_denominator_bits: Option<u64>,
    /// Whether K contains the post-impact velocity of a pure downward translation.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contains_translation: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub code: Option<Code>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub locus: Option<Locus>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

impl FileVerdict {
    fn new(path: &Path, status: Status) -> Self {
        FileVerdict {
            path: path.display().to_string(),
            status,
            claim: None,
            n: None,
            generators: None,
            redundant: None,
            max_denominator_bits: None,
            contains_translation: None,
            code: None,
            locus: None,
            reason: None,
        }
    }

    /// Whether the backends disagreed (an internal error).
    pub fn is_internal(&self) -> bool {
        self.code == Some(Code::Internal)
    }

    /// The human-readable line.
    pub fn line(&self) -> String {
        if self.status != Status::Ok {
            return format!(
                "{}: {}: {}",
                self.path,
                self.status.word(),
                self.reason.as_deref().unwrap_or("")
            );
        }
        let red = self.redundant.as_ref().map_or(0, Vec::len);
        let red = if red > 0 { format!(", {red} redundant") } else { String::new() };
        let vacuous = if self.contains_translation == Some(false) {
            "; warning: K does not contain the post-impact velocity of a pure translation"
        } else {
            ""
        };
        format!(
            "{}: OK ({}, n = {}, {} generators{red}, denominators <= {} bits{vacuous})",
            self.path,
            self.claim.unwrap_or("?"),
            self.n.unwrap_or(0),
            self.generators.unwrap_or(0),
            self.max_denominator_bits.unwrap_or(0)
        )
    }
}

/// The verdict on certificate text, reported for `path`.
pub fn verdict_of(path: &Path, verdict: Verdict) -> FileVerdict {
    match verdict {
        Verdict::Accepted(a) => {
            let mut v = FileVerdict::new(path, Status::Ok);
            v.claim = Some(a.claim.name());
            v.n = Some(a.n);
            v.generators = Some(a.generators);
            v.redundant = Some(a.redundant);
            v.max_denominator_bits = Some(a.max_denominator_bits);
            v.contains_translation = Some(a.contains_translation);
            v
        }
        Verdict::Rejected(r) => {
            let mut v = FileVerdict::new(path, Status::Rejected);
            v.code = Some(r.code);
            v.locus = Some(r.locus);
            v.reason = Some(r.message);
            v
        }
        Verdict::Disagree(s) => {
            let mut v = FileVerdict::new(path, Status::Error);
            v.code = Some(Code::Internal);
            v.reason = Some(format!("internal error, backends disagree: {s}"));
            v
        }
    }
}

/// Verifies one file on the given backends.
pub fn verify_file(path: &Path, limits: ParseLimits, backends: &[Backend]) -> FileVerdict {
    match std::fs::read_to_string(path) {
        Ok(text) => {
            let mut v = verdict_of(path, verify_text(&text, limits, backends));
            if v.status == Status::Rejected
                && format_of(&text).as_deref() == Some(chatter_kernel::proof::FORMAT)
            {
                v.reason = v.reason.map(|r| format!("{r} (this file is a proof: use `chatter check-proof`)"));
            }
            v
        }
        Err(e) => {
            let mut v = FileVerdict::new(path, Status::Error);
            v.reason = Some(format!("cannot read: {e}"));
            v
        }
    }
}

/// Expands files and directories (recursively, `*.ron` files only) into a sorted list.
pub fn collect_files(paths: &[PathBuf]) -> std::io::Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    for p in paths {
        if p.is_dir() {
            let mut stack = vec![p.clone()];
            let mut found = Vec::new();
            while let Some(d) = stack.pop() {
                for e in std::fs::read_dir(&d)? {
                    let e = e?.path();
                    if e.is_dir() {
                        stack.push(e);
                    } else if e.extension().is_some_and(|x| x == "ron") {
                        found.push(e);
                    }
                }
            }
            found.sort();
            out.extend(found);
        } else if p.exists() {
            out.push(p.clone());
        } else {
            let msg = format!("{}: no such file or directory", p.display());
            return Err(std::io::Error::new(std::io::ErrorKind::NotFound, msg));
        }
    }
    Ok(out)
}
