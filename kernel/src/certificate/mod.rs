//! Certificate format v1 and v2 (RON, and its JSON twin): the schema, the reader (two stages:
//! header, then the full schema with unknown fields denied), the deterministic writer, and the
//! rejection type shared with the kernel. The numbers stay text here; the kernel parses them with the
//! canonical rules on each backend. See docs/certificate-format.md.

pub mod convex;
mod json;
pub mod orbit;
mod read;
mod rejection;
mod strict;
mod write;

pub use convex::{
    CONVEX_VERSION, ConvexBodyText, ConvexCertificate, ConvexCoordinates, read_convex, version_of,
    write_convex,
};
pub(crate) use json::{format_of as json_format_of, read as read_json};
pub use orbit::{ORBIT_VERSION, OrbitBody, OrbitCertificate, OrbitSet, read_orbit, write_orbit};
pub use read::{Syntax, read, read_in, read_with};
pub(crate) use read::{check_header, ron_error};
pub use rejection::{Boundary, Code, Locus, Rejection};
pub use strict::Encoding;
pub(crate) use strict::check as check_strict;
pub use write::{quoted, write};

use serde::de::{SeqAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;

/// Value of the `format` field.
pub const FORMAT: &str = "chatter-certificate";
/// The newest version this build reads and writes: version 2 adds parameter intervals (box
/// certificates), version 3 elements of the number fields Q(cos 2 pi/n); a file is written with
/// the oldest version that can express it.
pub const VERSION: u64 = 3;
/// The versions this build reads.
pub const VERSIONS: std::ops::RangeInclusive<u64> = 1..=VERSION;

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
        /// kappa: a number, or a closed interval (version 2).
        kappa: Param,
        /// gamma: a number, or a closed interval (version 2).
        gamma: Param,
    },
}

impl Certificate {
    /// The oldest format version that can express this certificate: 3 when a number is an element
    /// of a number field (its text names the generator c), else that of the body.
    pub fn version_needed(&self) -> u64 {
        let Body::RegularPolygon { kappa, gamma, .. } = &self.body;
        let params = kappa.texts().into_iter().chain(gamma.texts());
        let mut texts = params.chain(self.cone.iter().flat_map(|g| g.0.iter().map(String::as_str)));
        if texts.any(|t| t.contains(crate::exact::GENERATOR)) { 3 } else { self.body.version_needed() }
    }
}

impl Body {
    /// The oldest format version that can express this body: 2 with a parameter interval, else 1.
    pub fn version_needed(&self) -> u64 {
        let Body::RegularPolygon { kappa, gamma, .. } = self;
        if matches!(kappa, Param::Interval(..)) || matches!(gamma, Param::Interval(..)) { 2 } else { 1 }
    }
}

/// A parameter: one number (`"1/6"`), or a closed interval of numbers written as a two-element
/// list (`["1/10", "3/25"]`, version 2), each in canonical text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Param {
    /// One value.
    Point(String),
    /// The closed interval [lo, hi].
    Interval(String, String),
}

impl Param {
    /// The value of a point parameter.
    pub fn as_point(&self) -> Option<&str> {
        match self {
            Param::Point(s) => Some(s),
            Param::Interval(..) => None,
        }
    }

    /// The numbers as written: one or two.
    pub fn texts(&self) -> Vec<&str> {
        match self {
            Param::Point(s) => vec![s],
            Param::Interval(a, b) => vec![a, b],
        }
    }
}

impl From<&str> for Param {
    fn from(s: &str) -> Self {
        Param::Point(s.to_string())
    }
}

impl From<String> for Param {
    fn from(s: String) -> Self {
        Param::Point(s)
    }
}

impl Serialize for Param {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Param::Point(x) => s.serialize_str(x),
            Param::Interval(a, b) => [a, b].serialize(s),
        }
    }
}

impl<'de> Deserialize<'de> for Param {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Param;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number such as \"1/6\", or an interval such as [\"1/10\", \"3/25\"]")
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<Param, E> {
                Ok(Param::Point(v.to_string()))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Param, A::Error> {
                use serde::de::Error;
                let lo: String = seq.next_element()?.ok_or_else(|| A::Error::invalid_length(0, &self))?;
                let hi: String = seq.next_element()?.ok_or_else(|| A::Error::invalid_length(1, &self))?;
                if seq.next_element::<String>()?.is_some() {
                    return Err(A::Error::invalid_length(3, &self));
                }
                Ok(Param::Interval(lo, hi))
            }
        }
        d.deserialize_any(V)
    }
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
    /// K lies in v <= 0 and S_j(K ∩ C_j) ⊆ K for j = 1..n-1 (docs/model.md §5 conditions 1-2).
    EffectivelyInvariant,
    /// Also I_0(D) ⊆ K: every drop with all contacts moving down ends in CC or PCC.
    CcOrPccFromAllDown,
    /// Also PCC excluded: every drop with all contacts moving down ends in CC.
    CompleteChatterFromAllDown,
    /// Orbit certificates only (version 5): every motion whose state right after some impact is,
    /// up to relabelling and the two scalings, a point of the set X ends in complete chatter,
    /// following the pattern periodically (docs/orbit-certificates.md §4). Not a cone claim: it
    /// is not in [`Claim::ALL`] and the cone kernels reject it.
    CompleteChatterFromSet,
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
            Claim::CompleteChatterFromSet => "CompleteChatterFromSet",
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
