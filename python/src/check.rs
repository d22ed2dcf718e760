//! `verify`: a file or text through chatter's verifier (bounded reading, both backends, the
//! time limit), the verdict as the entry of `files` of `chatter verify --json`
//! (`chatter::report::verify::FileReport`: `"verdict"` and the file's fields).

use crate::fail::Fail;
use chatter::report::verify::FileReport;
use chatter::verify::{FileVerdict, Options, Status, text, verify_file};
use chatter_kernel::certificate::Encoding;
use chatter_kernel::verify::{MALACHITE, NUM};
use serde_json::Value;
use std::path::Path;

fn options() -> Options {
    Options::new(vec![MALACHITE, NUM])
}

/// The verdict: accepted and rejected are answers; unreadable input and disagreeing backends
/// are exceptions.
fn verdict(v: FileVerdict) -> Result<Value, Fail> {
    let reason = v.reason.clone().unwrap_or_default();
    if v.is_internal() {
        return Err(Fail::internal("internal", format!("{}: {reason}", v.path)));
    }
    if v.status == Status::Error {
        return Err(Fail::usage("unreadable", format!("{}: {reason}", v.path)));
    }
    serde_json::to_value(FileReport::of(&v)).map_err(|e| Fail::internal("internal", e.to_string()))
}

/// Verifies a file (RON or JSON by its name, gzip'd or not).
pub fn verify_path(path: &str) -> Result<Value, Fail> {
    verdict(verify_file(Path::new(path), &options()))
}

/// Verifies text: the JSON twin when it starts with `{`, else RON.
pub fn verify_text(t: &str) -> Result<Value, Fail> {
    let encoding = if t.trim_start().starts_with('{') { Encoding::Json } else { Encoding::Ron };
    verdict(text::verify_text(t, encoding, &options()))
}
