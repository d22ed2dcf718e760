//! The words of a rejection (feature `explain`), rendered from its typed code, locus and detail.
//! Nothing here decides a verdict: the rules never import this module, and a reviewer of the
//! kernel need not read it. Numbers longer than [`LONG`] characters are abbreviated so that a
//! rejection line stays short; the exact values are in the locus and the detail.

#[cfg(feature = "basin")]
mod basin;
mod certificate;
#[cfg(feature = "orbit")]
mod orbit;
#[cfg(feature = "proof")]
mod proof;
#[cfg(feature = "refutation")]
mod refutation;
#[cfg(feature = "rest")]
mod rest;

use crate::exact::NumberError;
use crate::model::polygon::BodyError;
use crate::reject::{Detail, Locus, Rejection};
#[cfg(feature = "kinds")]
#[allow(unused_imports)] // which of the two a kind needs depends on the features
use crate::reject::{KindDetail, KindLocus};
use std::fmt;

/// Numbers longer than this many characters are abbreviated.
pub const LONG: usize = 40;

/// `text` itself, or its first 16 and last 8 characters with its length.
pub fn abbreviate(text: &str) -> String {
    let n = text.chars().count();
    if n <= LONG {
        return text.to_string();
    }
    let head: String = text.chars().take(16).collect();
    let tail: String = text.chars().skip(n - 8).collect();
    format!("{head}...{tail} ({n} characters)")
}

/// Text from a file, quoted, abbreviated when long.
pub fn quote(s: &str) -> String {
    match s.char_indices().nth(24) {
        Some((i, _)) => format!("\"{}...\" ({} characters)", &s[..i], s.chars().count()),
        None => format!("{s:?}"),
    }
}

/// Coordinates as "(x, y, ...)", each abbreviated.
pub fn tuple(coords: &[String]) -> String {
    format!("({})", coords.iter().map(|c| abbreviate(c)).collect::<Vec<_>>().join(", "))
}

impl Rejection {
    /// What failed, in words and exact numbers (long numbers abbreviated), prefixed by the field
    /// or the position it concerns.
    pub fn message(&self) -> String {
        let words = words(&self.detail, &self.locus);
        match (&self.locus, self.detail.as_ref()) {
            (Locus::Field { path }, Detail::Missing) => format!("missing field `{path}`"),
            (Locus::Field { path }, _) => format!("field `{path}`: {words}"),
            (Locus::Text { line, column }, _) => format!("line {line}, column {column}: {words}"),
            _ => words,
        }
    }
}

/// The words of a detail (at a locus).
fn words(detail: &Detail, locus: &Locus) -> String {
    match detail {
        #[cfg(feature = "orbit")]
        Detail::Kind(KindDetail::Orbit(f)) => orbit::words(f, locus),
        #[cfg(feature = "basin")]
        Detail::Kind(KindDetail::Basin(f)) => basin::words(f, locus),
        #[cfg(feature = "refutation")]
        Detail::Kind(KindDetail::Refutation(f)) => refutation::words(f, locus),
        #[cfg(feature = "rest")]
        Detail::Kind(KindDetail::Rest(f)) => rest::words(f, locus),
        #[cfg(feature = "proof")]
        Detail::Kind(KindDetail::Proof(f)) => match locus {
            Locus::Kind(KindLocus::Step { index, id }) => format!("step {index} `{id}`: {f}"),
            _ => f.to_string(),
        },
        _ => certificate::words(detail, locus),
    }
}

impl fmt::Display for Rejection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} [{}]", self.message(), self.code.as_str())
    }
}

impl std::error::Error for Rejection {}

impl fmt::Display for NumberError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NumberError::Empty => write!(f, "empty number"),
            NumberError::Whitespace => write!(f, "whitespace is not allowed in a number"),
            NumberError::PlusSign => write!(f, "a leading '+' is not canonical"),
            NumberError::InvalidCharacter(c) => write!(f, "invalid character {c:?}"),
            NumberError::MissingDigits => write!(f, "missing digits"),
            NumberError::LeadingZero => write!(f, "leading zeros are not canonical"),
            NumberError::NegativeZero => write!(f, "\"-0\" is not canonical (write \"0\")"),
            NumberError::ZeroDenominator => write!(f, "zero denominator"),
            NumberError::UnitDenominator { canonical } => {
                write!(f, "denominator 1 is not canonical (write {canonical:?})")
            }
            NumberError::NotReduced { canonical } => {
                write!(f, "not in lowest terms (canonical form {canonical:?})")
            }
            NumberError::NotCanonical { canonical } => {
                write!(f, "not the canonical text of this field element (write {canonical:?})")
            }
            NumberError::PowerTooHigh { power, degree } => write!(
                f,
                "c^{power}: an element of a field of degree {degree} is written with powers of c below {degree}"
            ),
            NumberError::TooLong { digits, max } => {
                write!(f, "number has {digits} digits, more than the limit max-digits = {max}")
            }
        }
    }
}

impl std::error::Error for NumberError {}

impl fmt::Display for BodyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BodyError::UnsupportedN(n) => write!(
                f,
                "n = {n} is not supported here: this exact model needs a rational cos(2*pi/n), i.e. n in {{3, 4, 6}} (or n = 2, the rod); certificates (certify, verify) work in Q(cos 2*pi/n) for every n from 3 to 64"
            ),
            BodyError::KappaNotPositive => write!(f, "kappa must be > 0"),
            BodyError::GammaOutOfRange => write!(f, "gamma must lie in [0, 1]"),
        }
    }
}

impl std::error::Error for BodyError {}
