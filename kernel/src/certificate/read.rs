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

fn syntax(e: ron::error::SpannedError) -> Rejection {
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

/// Reads a certificate: first the header (`format`, `version`), then the full schema of that
/// version. Every error names the field or the position.
pub fn read(text: &str) -> Result<Certificate, Rejection> {
    let lenient = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    let header: Header = lenient.from_str(text).map_err(syntax)?;
    match header.format.as_deref() {
        Some(FORMAT) => {}
        Some(other) => {
            let msg = format!("expected {FORMAT:?}, found {other:?}");
            return Err(Rejection::at_field(Code::WrongFormat, "format", msg));
        }
        None => return Err(missing("format")),
    }
    match header.version {
        Some(VERSION) => {}
        Some(v) => {
            let msg = format!("version {v} is not supported (this build reads version {VERSION})");
            return Err(Rejection::at_field(Code::UnsupportedVersion, "version", msg));
        }
        None => return Err(missing("version")),
    }
    ron::Options::default().from_str(text).map_err(syntax)
}

fn missing(field: &str) -> Rejection {
    Rejection::new(
        Code::MissingField,
        Locus::Field { path: field.into() },
        format!("missing field `{field}`"),
    )
}
