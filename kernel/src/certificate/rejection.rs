//! Why a certificate is rejected: a stable code (for manifests and JSON) and a located message.

use serde::Serialize;
use std::fmt;

/// Stable rejection codes; `as_str` gives the kebab-case name used in JSON and manifests.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Code {
    /// Not RON, or a value of the wrong type.
    Syntax,
    /// A field the format does not have.
    UnknownField,
    /// A required field is absent.
    MissingField,
    /// A field given twice.
    DuplicateField,
    /// An enum value the format does not have.
    UnknownVariant,
    /// `format` is not "chatter-certificate".
    WrongFormat,
    /// A version this build does not read.
    UnsupportedVersion,
    /// A number that is not canonical `p/q` text, or too long.
    BadNumber,
    /// A body this build cannot model exactly (e.g. n = 5).
    UnsupportedBody,
    /// kappa <= 0 or gamma outside [0, 1].
    ParameterOutOfRange,
    /// A generator with the wrong number of coordinates.
    WrongArity,
    /// A generator with v >= 0.
    GeneratorNotBelow,
    /// The generators do not span a 3-D cone (empty, a ray, or a flat fan).
    DegenerateCone,
    /// An image S_j(p) with v >= 0 (condition 1 fails).
    ImageNotBelow,
    /// An image S_j(p) outside K (condition 2 fails).
    ImageOutside,
    /// An image I_0(g) of a generator g of D outside K, or with v >= 0.
    InitialOutside,
    /// The PCC Lemma does not apply (the quadratic factor has real roots, or roots of modulus >= 1).
    PccNotExcluded,
    /// The model contradicts itself or the two backends disagree: a bug in chatter.
    Internal,
}

impl Code {
    /// The stable kebab-case name.
    pub fn as_str(self) -> &'static str {
        match self {
            Code::Syntax => "syntax",
            Code::UnknownField => "unknown-field",
            Code::MissingField => "missing-field",
            Code::DuplicateField => "duplicate-field",
            Code::UnknownVariant => "unknown-variant",
            Code::WrongFormat => "wrong-format",
            Code::UnsupportedVersion => "unsupported-version",
            Code::BadNumber => "bad-number",
            Code::UnsupportedBody => "unsupported-body",
            Code::ParameterOutOfRange => "parameter-out-of-range",
            Code::WrongArity => "wrong-arity",
            Code::GeneratorNotBelow => "generator-not-below",
            Code::DegenerateCone => "degenerate-cone",
            Code::ImageNotBelow => "image-not-below",
            Code::ImageOutside => "image-outside",
            Code::InitialOutside => "initial-outside",
            Code::PccNotExcluded => "pcc-not-excluded",
            Code::Internal => "internal",
        }
    }
}

/// A rejected certificate: the first failing check, exactly.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Rejection {
    /// The stable code.
    pub code: Code,
    /// What failed, exactly.
    pub message: String,
}

impl Rejection {
    /// A rejection with a code and a message.
    pub fn new(code: Code, message: impl Into<String>) -> Self {
        Rejection { code, message: message.into() }
    }
}

impl fmt::Display for Rejection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} [{}]", self.message, self.code.as_str())
    }
}

impl std::error::Error for Rejection {}
