//! Verification of certificate files: read, check with the kernel on one or both backends, and
//! report one verdict per file. A disagreement between the backends is an internal error.

use crate::exact::{ParseLimits, Q};
use chatter_kernel::certificate::{Code, Rejection, read};
use chatter_kernel::check::{Accepted, check};
use num_rational::BigRational;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Which bignum libraries to run the kernel on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Backends {
    #[default]
    Both,
    Malachite,
    Num,
}

/// The kernel's verdict, possibly over two backends.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BackendVerdict {
    Accepted(Accepted),
    Rejected(Rejection),
    /// The backends disagree: a bug in chatter or in a bignum library.
    Disagree(String),
}

/// Runs the kernel on both backends and compares the verdicts.
pub fn verify_both(cert: &chatter_kernel::certificate::Certificate, limits: ParseLimits) -> BackendVerdict {
    verify_with(cert, limits, Backends::Both)
}

/// Runs the kernel on the chosen backends.
pub fn verify_with(
    cert: &chatter_kernel::certificate::Certificate,
    limits: ParseLimits,
    backends: Backends,
) -> BackendVerdict {
    let one = |r: Result<Accepted, Rejection>| match r {
        Ok(a) => BackendVerdict::Accepted(a),
        Err(r) => BackendVerdict::Rejected(r),
    };
    match backends {
        Backends::Malachite => one(check::<Q>(cert, limits)),
        Backends::Num => one(check::<BigRational>(cert, limits)),
        Backends::Both => {
            let (a, b) = (check::<Q>(cert, limits), check::<BigRational>(cert, limits));
            if a == b {
                one(a)
            } else {
                BackendVerdict::Disagree(format!("malachite says {a:?}, num-rational says {b:?}"))
            }
        }
    }
}

/// Verifies certificate text.
pub fn verify_text(text: &str, limits: ParseLimits, backends: Backends) -> BackendVerdict {
    match read(text) {
        Ok(cert) => verify_with(&cert, limits, backends),
        Err(r) => BackendVerdict::Rejected(r),
    }
}

/// One line of `chatter verify` output.
#[derive(Clone, Debug, Serialize)]
pub struct FileVerdict {
    pub path: String,
    /// "OK", "REJECTED" or "ERROR" (unreadable file, or backends disagree).
    pub status: &'static str,
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
    pub reason: Option<String>,
}

impl FileVerdict {
    fn new(path: &Path, status: &'static str) -> Self {
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
            reason: None,
        }
    }

    /// The human-readable line.
    pub fn line(&self) -> String {
        match self.status {
            "OK" => {
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
            status => format!("{}: {status}: {}", self.path, self.reason.as_deref().unwrap_or("")),
        }
    }
}

/// Verifies one file.
pub fn verify_file(path: &Path, limits: ParseLimits, backends: Backends) -> FileVerdict {
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) => {
            let mut v = FileVerdict::new(path, "ERROR");
            v.reason = Some(format!("cannot read: {e}"));
            return v;
        }
    };
    match verify_text(&text, limits, backends) {
        BackendVerdict::Accepted(a) => {
            let mut v = FileVerdict::new(path, "OK");
            v.claim = Some(a.claim.name());
            v.n = Some(a.n);
            v.generators = Some(a.generators);
            v.redundant = Some(a.redundant);
            v.max_denominator_bits = Some(a.max_denominator_bits);
            v.contains_translation = Some(a.contains_translation);
            v
        }
        BackendVerdict::Rejected(r) => {
            let mut v = FileVerdict::new(path, "REJECTED");
            v.code = Some(r.code);
            v.reason = Some(r.message);
            v
        }
        BackendVerdict::Disagree(s) => {
            let mut v = FileVerdict::new(path, "ERROR");
            v.code = Some(Code::Internal);
            v.reason = Some(format!("internal error, backends disagree: {s}"));
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
