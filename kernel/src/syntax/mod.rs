//! The syntax layer, written once for every kind of file (docs/certificate-format.md §2, §11):
//! the strict lexical rules ([`strict`]), then the header (`format` and `version`, other fields
//! ignored) naming the kind of the file, then the kind's serde schema with unknown and repeated
//! fields denied, in RON or its JSON twin; the limits and canonical numbers ([`numbers`]). Each
//! kind has its own format string; `("chatter-certificate", 4 | 5)` are legacy aliases of the
//! family and orbit formats (docs/certificate-format.md §13, §14).

pub mod cone;
#[cfg(feature = "json")]
mod json;
#[cfg(feature = "kinds")]
mod kinds;
pub mod numbers;
pub mod strict;

#[cfg(feature = "kinds")]
#[allow(unused_imports)] // empty with only the features `boxes` or `field`
pub use kinds::*;

use crate::reject::{Code, Detail, Locus, Needs, Rejection};
use serde::Deserialize;
use serde::de::DeserializeOwned;

/// The text encodings of the formats: RON, or its JSON twin.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    /// The RON syntax of docs/certificate-format.md §2.
    Ron,
    /// The JSON twin of docs/certificate-format.md §11.
    Json,
}

/// The kinds of file, told apart by their header.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A cone certificate of a regular polygon or the rod (docs/certificate-format.md §1-§9, §12).
    Cone,
    /// A family certificate of a general convex body (§13).
    Family,
    /// An orbit certificate (§14).
    Orbit,
    /// A basin certificate (§15).
    Basin,
    /// A refutation (§10).
    Refutation,
    /// A proof (docs/proof-format.md).
    Proof,
    /// A time-to-rest certificate (§16).
    Rest,
    /// A time-to-rest certificate of a general convex body (§17).
    RestFamily,
}

/// Every header this build knows: (format, versions, kind, the Cargo feature that builds the kind
/// (`""`: always built), whether it is built). Each kind's own format first, then the legacy
/// aliases.
const HEADERS: [(&str, [u64; 2], Kind, &str, bool); 10] = [
    ("chatter-certificate", [1, 3], Kind::Cone, "", true),
    ("chatter-family-certificate", [1, 2], Kind::Family, "family", cfg!(feature = "family")),
    ("chatter-orbit-certificate", [1, 1], Kind::Orbit, "orbit", cfg!(feature = "orbit")),
    ("chatter-basin-certificate", [1, 2], Kind::Basin, "basin", cfg!(feature = "basin")),
    ("chatter-refutation", [1, 1], Kind::Refutation, "refutation", cfg!(feature = "refutation")),
    ("chatter-proof", [1, 1], Kind::Proof, "proof", cfg!(feature = "proof")),
    ("chatter-time-to-rest", [1, 3], Kind::Rest, "rest", cfg!(feature = "rest")),
    ("chatter-family-time-to-rest", [1, 2], Kind::RestFamily, "family-rest", cfg!(feature = "family-rest")),
    ("chatter-certificate", [4, 4], Kind::Family, "family", cfg!(feature = "family")),
    ("chatter-certificate", [5, 5], Kind::Orbit, "orbit", cfg!(feature = "orbit")),
];

impl Kind {
    /// The format string a file of this kind is written with.
    pub fn format(self) -> &'static str {
        HEADERS.iter().find(|h| h.2 == self).map_or("", |h| h.0)
    }
}

/// A serde schema of one kind of file.
pub trait Schema: DeserializeOwned {
    /// The kind.
    const KIND: Kind;
}

/// The header as written: `format` and `version`, `None` when absent.
pub type Header = (Option<String>, Option<u64>);

/// Which kind `(format, version)` names, for a reader of the kind `expected`.
pub fn kind(header: &Header, expected: Kind) -> Result<Kind, Rejection> {
    let Some(format) = &header.0 else { return Err(missing("format")) };
    let known: Vec<_> = HEADERS.iter().filter(|h| h.0 == format).collect();
    if known.is_empty() {
        let detail = Detail::Format(expected.format(), Some(format.clone()));
        return Err(Rejection::at(Code::WrongFormat, "format", detail));
    }
    let Some(version) = header.1 else { return Err(missing("version")) };
    let Some(&&(_, _, kind, feature, built)) = known.iter().find(|h| (h.1[0]..=h.1[1]).contains(&version))
    else {
        let reads = [known[0].1[0], known[known.len() - 1].1[1]];
        return Err(Rejection::at(Code::UnsupportedVersion, "version", Detail::Version(version, reads)));
    };
    if !built {
        let detail = Detail::Needs(Needs::Feature(feature), version);
        return Err(Rejection::at(Code::UnsupportedVersion, "version", detail));
    }
    Ok(kind)
}

fn missing(field: &str) -> Rejection {
    Rejection::at(Code::MissingField, field, Detail::Missing)
}

/// Checks a header held in memory (a file built by a program, not read): it must name `kind`.
pub fn expect(format: &str, version: u64, kind: Kind) -> Result<(), Rejection> {
    let found = self::kind(&(Some(format.to_string()), Some(version)), kind)?;
    if found == kind { Ok(()) } else { Err(other_kind(found, format, version, kind)) }
}

/// A file of the kind `found` given to a reader of `expected`: `unsupported-version` when its
/// format string is `expected`'s (a legacy alias), `wrong-format` otherwise.
fn other_kind(found: Kind, format: &str, version: u64, expected: Kind) -> Rejection {
    if format == expected.format() {
        let detail = Detail::Needs(Needs::Kind(found.format()), version);
        return Rejection::at(Code::UnsupportedVersion, "version", detail);
    }
    let detail = Detail::Format(expected.format(), Some(format.to_string()));
    Rejection::at(Code::WrongFormat, "format", detail)
}

/// The strict syntax, then the header of the text and the kind it names (for a reader of the
/// kind `expected`). The JSON twin needs the feature `json`.
pub fn kind_of(text: &str, encoding: Encoding, expected: Kind) -> Result<(Kind, Header), Rejection> {
    let header: Fields = match encoding {
        Encoding::Ron => {
            strict::check(text, encoding)?;
            ron_header(text)?
        }
        Encoding::Json => json::header(text)?,
    };
    let header = (header.format, header.version);
    Ok((kind(&header, expected)?, header))
}

/// Reads a file of the schema `T`: [`kind_of`], then the full schema. A file of another kind is
/// refused (`wrong-format`, or `unsupported-version` for a legacy alias of the same format).
pub fn read<T: Schema>(text: &str, encoding: Encoding) -> Result<T, Rejection> {
    let (kind, (format, version)) = kind_of(text, encoding, T::KIND)?;
    if kind != T::KIND {
        return Err(other_kind(kind, &format.unwrap_or_default(), version.unwrap_or(0), T::KIND));
    }
    schema(text, encoding)
}

/// The full schema of `T` (unknown and repeated fields denied), once [`kind_of`] has named `T`'s
/// kind.
pub fn schema<T: Schema>(text: &str, encoding: Encoding) -> Result<T, Rejection> {
    match encoding {
        Encoding::Ron => ron::Options::default().from_str(text).map_err(ron_error),
        Encoding::Json => json::schema(text),
    }
}

/// The header's fields, under any struct name.
#[derive(Deserialize)]
struct Fields {
    format: Option<String>,
    version: Option<u64>,
}

/// The RON header read leniently (unknown fields ignored, `Some` implicit), under any struct
/// name: a leading name is blanked, so that every position stays where it is.
fn ron_header(text: &str) -> Result<Fields, Rejection> {
    let lenient = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    let body = text.trim_start();
    let name = body.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(body.len());
    let at = text.len() - body.len();
    let blanked = format!("{}{}{}", &text[..at], " ".repeat(name), &body[name..]);
    lenient.from_str(&blanked).map_err(ron_error)
}

/// A RON error as a rejection: schema errors get their own codes, everything at its position.
fn ron_error(e: ron::error::SpannedError) -> Rejection {
    use ron::Error as E;
    let code = match &e.code {
        E::NoSuchStructField { .. } => Code::UnknownField,
        E::MissingStructField { .. } => Code::MissingField,
        E::NoSuchEnumVariant { .. } => Code::UnknownVariant,
        E::DuplicateStructField { .. } => Code::DuplicateField,
        _ => Code::Syntax,
    };
    let locus = Locus::Text { line: e.span.start.line, column: e.span.start.col };
    Rejection::new(code, locus, Detail::Parser(e.code.to_string()))
}

/// Without the feature `json`, a file in the JSON twin is refused (`syntax`, naming the feature).
#[cfg(not(feature = "json"))]
mod json {
    use crate::reject::{Code, Detail, Locus, Needs, Rejection};
    pub fn header<T>(_: &str) -> Result<T, Rejection> {
        let detail = Detail::Needs(Needs::Feature("json"), 0);
        Err(Rejection::new(Code::Syntax, Locus::Text { line: 1, column: 1 }, detail))
    }
    pub use header as schema;
}
