//! Which files `chatter verify` looks at (docs/certificate-format.md §7, "Inputs"): a file named
//! on the command line is always checked; a directory is searched recursively for certificate
//! files, in name order: `*.ron` and `*.ron.gz` (in any letter case), and `*.json` and
//! `*.json.gz` files that declare a certificate's or refutation's format (so that a manifest such
//! as `expected.json`, or a `summary.json`, is skipped). Every real path is visited
//! at most once, so symbolic-link loops end and a file reached twice is checked once. A problem
//! with one path (missing, unreadable directory, broken link) becomes one entry, and the others
//! are still listed.

use serde::Serialize;
use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// One input of a verification run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Entry {
    /// A file to check.
    File(PathBuf),
    /// A path that cannot be listed or followed, and why.
    Problem {
        /// The path as found.
        path: PathBuf,
        /// Why (e.g. "no such file or directory").
        message: String,
    },
}

/// Files not checked, by reason (reported in the summary).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, schemars::JsonSchema)]
pub struct Skipped {
    /// Files in a searched directory whose name is not a certificate's (`*.ron`, `*.ron.gz`,
    /// `*.json`, `*.json.gz`).
    pub other_names: usize,
    /// `*.json` and `*.json.gz` files in a searched directory that do not declare a certificate's
    /// or refutation's format (manifests, summaries): see [`declares_format`].
    pub other_json: usize,
    /// Paths whose real path was already visited (links to a file or directory seen before).
    pub seen_before: usize,
}

impl Skipped {
    /// All skipped files.
    pub fn total(&self) -> usize {
        self.other_names + self.other_json + self.seen_before
    }
}

/// The inputs of a run, in order, and what was skipped.
#[derive(Clone, Debug, Default)]
pub struct Listing {
    /// Files and problems, in the order they are reported.
    pub entries: Vec<Entry>,
    /// What was skipped.
    pub skipped: Skipped,
}

/// Whether a file name is a certificate's: `*.ron` or `*.ron.gz`, in any letter case.
pub fn is_certificate_name(p: &Path) -> bool {
    let name = p.file_name().map(|n| n.to_string_lossy().to_lowercase()).unwrap_or_default();
    name.ends_with(".ron") || name.ends_with(".ron.gz")
}

/// Whether a file name is a JSON file's: `*.json` or `*.json.gz`, in any letter case.
pub fn is_json_name(p: &Path) -> bool {
    let name = p.file_name().map(|n| n.to_string_lossy().to_lowercase()).unwrap_or_default();
    name.ends_with(".json") || name.ends_with(".json.gz")
}

/// The encoding of a file by its name: the JSON twin for `*.json` and `*.json.gz` (any letter
/// case), RON for every other name.
pub fn encoding_of(p: &Path) -> chatter_kernel::certificate::Encoding {
    use chatter_kernel::certificate::Encoding;
    if is_json_name(p) { Encoding::Json } else { Encoding::Ron }
}

/// The format strings of the files `chatter verify` checks (docs/certificate-format.md §7).
pub const FORMATS: [&str; 6] = [
    "chatter-certificate",
    "chatter-family-certificate",
    "chatter-orbit-certificate",
    "chatter-basin-certificate",
    "chatter-time-to-rest",
    "chatter-refutation",
];

/// Whether JSON text declares a certificate's or refutation's format: it contains the key
/// `"format"` followed, after optional whitespace, a colon and optional whitespace, by one of the
/// strings of [`FORMATS`] (quoted). Textual, so that a certificate with a syntax error elsewhere
/// is still checked (and rejected) rather than skipped.
pub fn declares_format(text: &str) -> bool {
    let ws = [' ', '\t', '\n', '\r'];
    text.match_indices("\"format\"").any(|(i, key)| {
        let rest = text[i + key.len()..].trim_start_matches(ws);
        rest.strip_prefix(':').is_some_and(|r| {
            let r = r.trim_start_matches(ws);
            FORMATS.iter().any(|f| {
                r.strip_prefix('"').and_then(|r| r.strip_prefix(f)).is_some_and(|r| r.starts_with('"'))
            })
        })
    })
}

/// Whether a `*.json` file found in a directory is to be checked: it declares a certificate's or
/// refutation's format, or it cannot be examined within `max_bytes` (too large, unreadable): then
/// its verdict says why.
fn json_to_check(path: &Path, max_bytes: u64) -> bool {
    match super::read::read_input(path, max_bytes) {
        super::read::Input::Text { text, .. } => declares_format(&text),
        _ => true,
    }
}

/// An I/O error in words, without the OS error number.
pub fn describe(e: &std::io::Error) -> String {
    use std::io::ErrorKind as K;
    match e.kind() {
        K::NotFound => "no such file or directory".into(),
        K::PermissionDenied => "permission denied".into(),
        _ => {
            let s = e.to_string();
            s.split(" (os error").next().unwrap_or(&s).to_lowercase()
        }
    }
}

/// Lists the inputs named by `paths` (files and directories), examining JSON files within the
/// default `max-file-size`.
pub fn list(paths: &[PathBuf]) -> Listing {
    list_with(paths, super::DEFAULT_MAX_FILE_SIZE)
}

/// Lists the inputs named by `paths`; a `*.json` file in a directory is examined (read, within
/// `max_bytes`) to tell a certificate from a manifest.
pub fn list_with(paths: &[PathBuf], max_bytes: u64) -> Listing {
    let mut walk = Walk { max_bytes, ..Walk::default() };
    for p in paths {
        match std::fs::metadata(p) {
            Err(e) => walk.problem(p, describe(&e)),
            Ok(m) if m.is_dir() => walk.directory(p),
            Ok(_) => walk.file(p),
        }
    }
    Listing { entries: walk.entries, skipped: walk.skipped }
}

/// Why an entry of a directory cannot be followed: a broken link, or the I/O error.
fn link_problem(path: &Path, e: &std::io::Error) -> String {
    match std::fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_symlink() => {
            format!("a symbolic link whose target cannot be read: {}", describe(e))
        }
        _ => describe(e),
    }
}

#[derive(Default)]
struct Walk {
    seen: HashSet<PathBuf>,
    entries: Vec<Entry>,
    skipped: Skipped,
    max_bytes: u64,
}

impl Walk {
    fn problem(&mut self, path: &Path, message: String) {
        self.entries.push(Entry::Problem { path: path.to_path_buf(), message });
    }

    /// Whether `path`'s real path is new (then it is marked as seen).
    fn first_visit(&mut self, path: &Path) -> bool {
        let real = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
        let new = self.seen.insert(real);
        if !new {
            self.skipped.seen_before += 1;
        }
        new
    }

    fn file(&mut self, path: &Path) {
        if self.first_visit(path) {
            self.entries.push(Entry::File(path.to_path_buf()));
        }
    }

    fn directory(&mut self, dir: &Path) {
        if !self.first_visit(dir) {
            return;
        }
        let listed = std::fs::read_dir(dir).and_then(|r| r.map(|e| e.map(|e| e.path())).collect());
        let mut children: Vec<PathBuf> = match listed {
            Ok(c) => c,
            Err(e) => return self.problem(dir, format!("cannot list the directory: {}", describe(&e))),
        };
        children.sort();
        for child in children {
            match std::fs::metadata(&child) {
                Ok(m) if m.is_dir() => self.directory(&child),
                Ok(_) if is_json_name(&child) && !json_to_check(&child, self.max_bytes) => {
                    self.skipped.other_json += 1;
                }
                _ if !is_certificate_name(&child) && !is_json_name(&child) => self.skipped.other_names += 1,
                Ok(_) => self.file(&child),
                Err(e) => self.problem(&child, link_problem(&child, &e)),
            }
        }
    }
}
