//! Certificate format v1 (RON): the schema, the reader (two stages: header, then the full
//! version-1 schema with unknown fields denied), the deterministic writer, and the rejection
//! type shared with the kernel. The numbers stay text here; the kernel parses them with the
//! canonical rules on each backend. See docs/certificate-format.md.

mod rejection;

pub use rejection::{Code, Rejection};

use serde::de::{SeqAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;

/// Value of the `format` field.
pub const FORMAT: &str = "chatter-certificate";
/// The one version this build reads and writes.
pub const VERSION: u64 = 1;

/// A certificate, numbers as canonical text.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename = "Certificate", deny_unknown_fields)]
pub struct Certificate {
    /// Always [`FORMAT`].
    pub format: String,
    /// Always [`VERSION`].
    pub version: u64,
    /// The falling body.
    pub body: Body,
    /// The coordinates of the generators.
    pub coordinates: Coordinates,
    /// What the certificate proves.
    pub claim: Claim,
    /// Generators of the cone K.
    pub cone: Vec<Generator>,
    /// Informational only, never trusted.
    #[serde(default)]
    pub producer: String,
}

/// The falling body.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Body {
    /// Regular n-gon of contacts (circumradius 1), kappa = rho^2/R^2, restitution gamma.
    RegularPolygon {
        /// Number of contacts (2 for the rod).
        n: u64,
        /// kappa, canonical rational text.
        kappa: String,
        /// gamma, canonical rational text.
        gamma: String,
    },
}

/// The coordinates of the generators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Coordinates {
    /// (u0, u1, v): normal velocities of contacts 0 and 1 and of the centre of mass.
    ContactVelocities,
}

/// What the certificate proves (each claim includes the checks of the previous ones).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub enum Claim {
    /// K lies in v <= 0 and S_j(K ∩ C_j) ⊆ K for j = 1..n-1 (MODEL §5 conditions 1-2).
    EffectivelyInvariant,
    /// Also I_0(D) ⊆ K: every drop with all contacts moving down ends in CC or PCC.
    CcOrPccFromAllDown,
    /// Also PCC excluded: every drop with all contacts moving down ends in CC.
    CompleteChatterFromAllDown,
}

impl Claim {
    /// The three claims, weakest first.
    pub const ALL: [Claim; 3] =
        [Claim::EffectivelyInvariant, Claim::CcOrPccFromAllDown, Claim::CompleteChatterFromAllDown];

    /// The name used in certificates and output.
    pub fn name(self) -> &'static str {
        match self {
            Claim::EffectivelyInvariant => "EffectivelyInvariant",
            Claim::CcOrPccFromAllDown => "CcOrPccFromAllDown",
            Claim::CompleteChatterFromAllDown => "CompleteChatterFromAllDown",
        }
    }
}

/// One generator of the cone: its coordinates as canonical rational text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Generator(pub Vec<String>);

impl Serialize for Generator {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeTuple;
        let mut t = s.serialize_tuple(self.0.len())?;
        for c in &self.0 {
            t.serialize_element(c)?;
        }
        t.end()
    }
}

impl<'de> Deserialize<'de> for Generator {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Generator;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a tuple of coordinates such as (\"1\", \"-1/2\", \"-1\")")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Generator, A::Error> {
                let mut v = Vec::new();
                while let Some(s) = seq.next_element::<String>()? {
                    v.push(s);
                }
                Ok(Generator(v))
            }
        }
        d.deserialize_tuple(3, V)
    }
}

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
    Rejection::new(code, format!("line {}, column {}: {}", e.span.start.line, e.span.start.col, e.code))
}

/// Reads a certificate: first the header (`format`, `version`), then the full schema of that
/// version. Every error names the field or the position.
pub fn read(text: &str) -> Result<Certificate, Rejection> {
    let lenient = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    let header: Header = lenient.from_str(text).map_err(syntax)?;
    match header.format.as_deref() {
        Some(FORMAT) => {}
        Some(other) => {
            return Err(Rejection::new(
                Code::WrongFormat,
                format!("field `format`: expected {FORMAT:?}, found {other:?}"),
            ));
        }
        None => return Err(Rejection::new(Code::MissingField, "missing field `format`")),
    }
    match header.version {
        Some(VERSION) => {}
        Some(v) => {
            return Err(Rejection::new(
                Code::UnsupportedVersion,
                format!("field `version`: version {v} is not supported (this build reads version {VERSION})"),
            ));
        }
        None => return Err(Rejection::new(Code::MissingField, "missing field `version`")),
    }
    ron::Options::default().from_str(text).map_err(syntax)
}

/// Writes a certificate as RON, one generator per line (deterministic).
pub fn write(c: &Certificate) -> String {
    let q = |s: &str| ron::to_string(s).expect("strings always serialise");
    let Body::RegularPolygon { n, kappa, gamma } = &c.body;
    let mut out = String::new();
    out.push_str("Certificate(\n");
    out.push_str(&format!("    format: {},\n", q(&c.format)));
    out.push_str(&format!("    version: {},\n", c.version));
    out.push_str(&format!("    body: RegularPolygon(n: {n}, kappa: {}, gamma: {}),\n", q(kappa), q(gamma)));
    out.push_str("    coordinates: ContactVelocities,\n");
    out.push_str(&format!("    claim: {},\n", c.claim.name()));
    out.push_str("    cone: [\n");
    for g in &c.cone {
        let coords: Vec<String> = g.0.iter().map(|s| q(s)).collect();
        out.push_str(&format!("        ({}),\n", coords.join(", ")));
    }
    out.push_str("    ],\n");
    out.push_str(&format!("    producer: {},\n", q(&c.producer)));
    out.push_str(")\n");
    out
}
