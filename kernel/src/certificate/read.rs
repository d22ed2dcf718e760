//! The reader: first the header (`format`, `version`), then the full schema of that version with
//! unknown fields denied. Every error names the field or the position.

use super::{Certificate, Code, FORMAT, Locus, Rejection, VERSIONS};
use serde::Deserialize;
use std::ops::RangeInclusive;

#[derive(Deserialize)]
#[serde(rename = "Certificate")]
struct Header {
    format: Option<String>,
    version: Option<u64>,
}

/// A RON error as a rejection: schema errors get their own code, everything at its position.
pub(crate) fn ron_error(e: ron::error::SpannedError) -> Rejection {
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
    readable: RangeInclusive<u64>,
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
        Some(v) if readable.contains(&v) => Ok(()),
        Some(v) => {
            let reads = if readable.start() == readable.end() {
                format!("version {}", readable.start())
            } else {
                format!("versions {} to {}", readable.start(), readable.end())
            };
            let msg = format!("version {v} is not supported (this build reads {reads})");
            Err(Rejection::at_field(Code::UnsupportedVersion, "version", msg))
        }
        None => Err(missing("version")),
    }
}

/// Which RON syntax a reader accepts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Syntax {
    /// Only the subset the format uses (docs/certificate-format.md §2): the default.
    #[default]
    Strict,
    /// Anything RON accepts (comments, escapes, raw strings, ...).
    Lenient,
}

/// Reads a RON certificate in the strict syntax: see [`read_with`].
pub fn read(text: &str) -> Result<Certificate, Rejection> {
    read_with(text, Syntax::Strict)
}

/// Reads a certificate in the given encoding (RON or its JSON twin) in the strict syntax.
pub fn read_in(text: &str, encoding: super::Encoding) -> Result<Certificate, Rejection> {
    match encoding {
        super::Encoding::Ron => read(text),
        super::Encoding::Json => {
            super::read_json::<super::convex::VersionOnly>(text, FORMAT, ALL_VERSIONS)
                .and_then(not_convex)?;
            super::read_json(text, FORMAT, VERSIONS)
        }
    }
}

/// Every version this build reads: 1-3 here, 4 (`ConvexPolygon` bodies) with
/// [`super::read_convex`], 5 (orbit certificates) with [`super::read_orbit`]. A header with version 4 is told where to go, not "unsupported".
const ALL_VERSIONS: RangeInclusive<u64> = 1..=super::ORBIT_VERSION;

/// Rejects version 4 in the reader of versions 1-3 (`chatter verify` dispatches on the version).
fn not_convex(h: super::convex::VersionOnly) -> Result<(), Rejection> {
    if h.version == Some(super::CONVEX_VERSION) {
        let msg = "version 4 certificates have a ConvexPolygon body and are read by read_convex (chatter verify reads both)";
        return Err(Rejection::at_field(Code::UnsupportedVersion, "version", msg));
    }
    if h.version == Some(super::ORBIT_VERSION) {
        let msg = "version 5 certificates are orbit certificates and are read by read_orbit (chatter verify reads them)";
        return Err(Rejection::at_field(Code::UnsupportedVersion, "version", msg));
    }
    Ok(())
}

/// Reads a RON certificate: the syntax, then the header (`format`, `version`), then the full
/// schema of that version. Every error names the field or the position.
pub fn read_with(text: &str, syntax: Syntax) -> Result<Certificate, Rejection> {
    if syntax == Syntax::Strict {
        super::strict::check(text)?;
    }
    let lenient = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    let header: Header = lenient.from_str(text).map_err(ron_error)?;
    check_header(header.format.as_deref(), header.version, FORMAT, ALL_VERSIONS)?;
    not_convex(super::convex::VersionOnly { version: header.version })?;
    ron::Options::default().from_str(text).map_err(ron_error)
}

fn missing(field: &str) -> Rejection {
    Rejection::new(
        Code::MissingField,
        Locus::Field { path: field.into() },
        format!("missing field `{field}`"),
    )
}
