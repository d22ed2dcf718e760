//! `chatter verify --expect MANIFEST` (docs/certificate-format.md §7, "Manifests"): every input
//! is compared with the verdict a manifest expects, and every mismatch is reported, so that a CI
//! job over a certificate corpus needs no scripting.
//!
//! A manifest is a JSON list of entries, the form of `certificates/invalid/expected.json`:
//! `file` (a path relative to the manifest's directory), `verdict` (`"OK"`, `"REJECTED"` or
//! `"ERROR"`; when absent, `"REJECTED"` if `code` is given and `"OK"` otherwise), and optionally
//! `code` (the rejection code), `locus` (the structured locus, compared exactly), `message` (a
//! part of the message) and `why` (free text, never compared).

use super::{FileVerdict, Status};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One expected verdict.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Expected {
    /// The file, relative to the manifest's directory.
    pub file: String,
    /// The expected status.
    #[serde(default)]
    pub verdict: Option<Status>,
    /// The expected rejection code.
    #[serde(default)]
    pub code: Option<String>,
    /// The expected locus (as `chatter verify --json` writes it).
    #[serde(default)]
    pub locus: Option<serde_json::Value>,
    /// A part of the expected message.
    #[serde(default)]
    pub message: Option<String>,
    /// Why the file has this verdict (documentation only).
    #[serde(default)]
    pub why: Option<String>,
}

impl Expected {
    /// The expected status (see the module documentation for the default).
    pub fn status(&self) -> Status {
        self.verdict.unwrap_or(if self.code.is_some() { Status::Rejected } else { Status::Ok })
    }
}

/// A manifest: its directory and its entries by real path.
pub struct Manifest {
    /// The manifest's directory (the default input when no path is given).
    pub dir: PathBuf,
    entries: BTreeMap<PathBuf, Expected>,
}

/// The real path of `p` (or `p` itself when it does not exist).
fn real(p: &Path) -> PathBuf {
    std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf())
}

impl Manifest {
    /// Reads a manifest; an error in words when it cannot be read or is malformed.
    pub fn read(path: &Path) -> Result<Manifest, String> {
        let text = std::fs::read_to_string(path).map_err(|e| {
            format!("cannot read the manifest {}: {}", path.display(), super::files::describe(&e))
        })?;
        let list: Vec<Expected> = serde_json::from_str(&text).map_err(|e| {
            format!("the manifest {} is not a list of expected verdicts: {e}", path.display())
        })?;
        let dir = path.parent().map_or_else(|| PathBuf::from("."), Path::to_path_buf);
        let dir = if dir.as_os_str().is_empty() { PathBuf::from(".") } else { dir };
        let mut entries = BTreeMap::new();
        for e in list {
            let key = real(&dir.join(&e.file));
            if entries.insert(key, e.clone()).is_some() {
                return Err(format!("the manifest {} lists {} twice", path.display(), e.file));
            }
        }
        Ok(Manifest { dir, entries })
    }

    /// Every mismatch between the verdicts and the manifest, one line each: files whose verdict
    /// differs, files checked but not listed, files listed but not checked.
    pub fn mismatches(&self, verdicts: &[FileVerdict]) -> Vec<String> {
        let mut out = Vec::new();
        let mut checked = std::collections::BTreeSet::new();
        for v in verdicts {
            let key = real(Path::new(&v.path));
            match self.entries.get(&key) {
                Some(e) => out.extend(compare(e, v).map(|m| format!("{}: {m}", v.path))),
                None => out.push(format!("{}: not in the manifest (got {})", v.path, got(v))),
            }
            checked.insert(key);
        }
        for (key, e) in &self.entries {
            if !checked.contains(key) {
                out.push(format!(
                    "{}: listed in the manifest but not checked",
                    self.dir.join(&e.file).display()
                ));
            }
        }
        out
    }
}

/// The verdict in short: `OK`, `REJECTED [code]`, `ERROR`.
fn got(v: &FileVerdict) -> String {
    match v.code {
        Some(c) if v.status == Status::Rejected => format!("REJECTED [{}]", c.as_str()),
        _ => v.status.word().to_string(),
    }
}

/// What differs between an expected verdict and the actual one, if anything.
fn compare(e: &Expected, v: &FileVerdict) -> Option<String> {
    let expected = match &e.code {
        Some(c) => format!("{} [{c}]", e.status().word()),
        None => e.status().word().to_string(),
    };
    let code_differs = e.code.as_deref().is_some_and(|c| v.code.map(|x| x.as_str()) != Some(c));
    if e.status() != v.status || code_differs {
        return Some(format!("expected {expected}, got {}: {}", got(v), v.reason.as_deref().unwrap_or("")));
    }
    if let Some(want) = &e.locus {
        let have = serde_json::to_value(&v.locus).unwrap_or_default();
        if *want != have {
            return Some(format!("expected the locus {want}, got {have}"));
        }
    }
    if let Some(part) = &e.message {
        let reason = v.reason.as_deref().unwrap_or("");
        if !reason.contains(part.as_str()) {
            return Some(format!("expected a message containing {part:?}, got {reason:?}"));
        }
    }
    None
}
