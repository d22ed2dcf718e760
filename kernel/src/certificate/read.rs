//! The reader: first the header (`format`, `version`), then the full schema of that version with
//! unknown fields denied. Every error names the field or the position.

use super::{Certificate, Code, FORMAT, Locus, Rejection, VERSION};
use serde::Deserialize;

#[derive(Deserialize)]
#[serde(rename = "Certificate")]
struct Header {
    format: Option<String>,
    version: Option<u64>,
}

/// A RON error as a rejection: schema errors get their own code, everything at its position.
pub(crate) fn syntax(e: ron::error::SpannedError) -> Rejection {
    use ron::Error as E;
    let code = match &e.code {
        E::NoSuchStructField { .. } => Code::UnknownField,
        E::MissingStructField { .. } => Code::MissingField,
        E::NoSuchEnumVariant { .. } => Code::UnknownVariant,
        E::DuplicateStructField { .. } => Code::DuplicateField,
        _ => Code::Syntax,
    };
    let (line, column) = (e.span.start.line, e.span.start.col);
    Rejection::new(code, Locus::Text { line, column }, format!("line {line}, column {column}: {}", e.code))
}

/// Checks the header fields read leniently: the right format, a version this build reads.
pub(crate) fn check_header(
    format: Option<&str>,
    version: Option<u64>,
    expected: &str,
    readable: u64,
) -> Result<(), Rejection> {
    match format {
        Some(f) if f == expected => {}
        Some(other) => {
            let msg = format!("expected {expected:?}, found {other:?}");
            return Err(Rejection::at_field(Code::WrongFormat, "format", msg));
        }
        None => return Err(missing("format")),
    }
    match version {
        Some(v) if v == readable => Ok(()),
        Some(v) => {
            let msg = format!("version {v} is not supported (this build reads version {readable})");
            Err(Rejection::at_field(Code::UnsupportedVersion, "version", msg))
        }
        None => Err(missing("version")),
    }
}

/// Reads a certificate: first the header (`format`, `version`), then the full schema of that
/// version. Every error names the field or the position.
pub fn read(text: &str) -> Result<Certificate, Rejection> {
    let lenient = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    let header: Header = lenient.from_str(text).map_err(syntax)?;
    check_header(header.format.as_deref(), header.version, FORMAT, VERSION)?;
    ron::Options::default().from_str(text).map_err(syntax)
}

fn missing(field: &str) -> Rejection {
    Rejection::new(
        Code::MissingField,
        Locus::Field { path: field.into() },
        format!("missing field `{field}`"),
    )
}
