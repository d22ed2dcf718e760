//! The JSON twin of the format (docs/certificate-format.md §11): the same serde types as the RON
//! reader, read by serde_json after the same strict lexical rules (with `{ }` for structs), then
//! the same header check and the same schema with unknown and repeated fields denied.

use super::strict::{Encoding, check_in};
use super::{Code, Locus, Rejection, check_header};
use serde::Deserialize;
use serde::de::DeserializeOwned;
use std::ops::RangeInclusive;

#[derive(Deserialize)]
struct Header {
    format: Option<String>,
    version: Option<u64>,
}

/// A serde_json error as a rejection: the schema errors of serde (unknown, missing or repeated
/// field, unknown variant) get their own codes, as from RON; everything at its position.
pub(crate) fn json_error(e: serde_json::Error) -> Rejection {
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
    Rejection::new(code, Locus::Text { line, column }, format!("line {line}, column {column}: {what}"))
}

/// Reads a file of the JSON twin: the strict syntax, the header (`format`, `version`, other
/// fields ignored), then the full schema of `T`.
pub(crate) fn read<T: DeserializeOwned>(
    text: &str,
    format: &str,
    versions: RangeInclusive<u64>,
) -> Result<T, Rejection> {
    check_in(text, Encoding::Json).map_err(|mut r| {
        r.message = r.message.replace("§2: strict syntax", "§11: strict JSON syntax");
        r
    })?;
    let header: Header = serde_json::from_str(text).map_err(json_error)?;
    check_header(header.format.as_deref(), header.version, format, versions)?;
    serde_json::from_str(text).map_err(json_error)
}

/// The `format` field of JSON text, read leniently (other fields ignored); `None` if the text is
/// not a JSON object with a string `format`.
pub(crate) fn format_of(text: &str) -> Option<String> {
    #[derive(Deserialize)]
    struct Format {
        format: Option<String>,
    }
    serde_json::from_str::<Format>(text).ok().and_then(|h| h.format)
}
