//! The JSON twin of the formats (docs/certificate-format.md §11, feature `json`): the strict
//! syntax of its text, its header and its schemas, with serde_json's errors as the same typed
//! rejections as RON's.

use super::{Encoding, Fields, Schema, strict};
use crate::reject::{Code, Detail, Locus, Rejection};

/// The strict syntax of the JSON twin, then its header.
pub fn header(text: &str) -> Result<Fields, Rejection> {
    strict::check(text, Encoding::Json)?;
    serde_json::from_str(text).map_err(error)
}

/// The full schema of `T` in the JSON twin.
pub fn schema<T: Schema>(text: &str) -> Result<T, Rejection> {
    serde_json::from_str(text).map_err(error)
}

/// A serde_json error as a rejection: serde's schema errors (by the fixed prefixes of its
/// messages) get the same codes as from RON; everything at its position.
fn error(e: serde_json::Error) -> Rejection {
    let (line, column) = (e.line(), e.column());
    let full = e.to_string();
    let what = full.strip_suffix(&format!(" at line {line} column {column}")).unwrap_or(&full);
    let codes = [
        ("unknown field", Code::UnknownField),
        ("missing field", Code::MissingField),
        ("duplicate field", Code::DuplicateField),
        ("unknown variant", Code::UnknownVariant),
    ];
    let code = codes.iter().find(|(prefix, _)| what.starts_with(prefix)).map_or(Code::Syntax, |c| c.1);
    Rejection::new(code, Locus::Text { line, column }, Detail::Parser(what.to_string()))
}
