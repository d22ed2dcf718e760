//! The schema of cone certificates (docs/certificate-format.md §2-§9, §12): a regular polygon or
//! the rod, a claim and the generators of a cone K. Format `"chatter-certificate"`, versions 1
//! (points), 2 (parameter intervals) and 3 (number-field elements). The numbers stay text here;
//! the rules parse them with the canonical rules on each backend.

use super::{Kind, Schema};
use serde::de::{SeqAccess, Visitor};
use serde::{Deserialize, Deserializer};
use std::fmt;

/// Value of the `format` field.
pub const FORMAT: &str = "chatter-certificate";
/// The newest version: version 2 adds parameter intervals (box certificates), version 3 elements
/// of the number fields Q(cos 2 pi/n); a file is written with the oldest version that can
/// express it.
pub const VERSION: u64 = 3;
/// The versions of the format.
pub const VERSIONS: std::ops::RangeInclusive<u64> = 1..=VERSION;

/// A certificate, numbers as canonical text.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename = "Certificate", deny_unknown_fields)]
pub struct Certificate {
    /// Always [`FORMAT`].
    pub format: String,
    /// 1 to [`VERSION`].
    pub version: u64,
    /// The falling body.
    pub body: Body,
    /// The coordinates of the generators.
    pub coordinates: Coordinates,
    /// What the certificate proves.
    pub claim: Claim,
    /// Generators of the cone K.
    pub cone: Vec<Generator>,
    /// Optional (issue 24): B, canonical rational text, with T <= B h/|v| for the time T to rest
    /// of every all-down drop (rule T1, rod point certificates only; docs/time-to-rest.md §2).
    #[serde(default)]
    pub time_to_rest_bound: Option<String>,
    /// Informational only, never trusted.
    #[serde(default)]
    pub producer: String,
}

impl Schema for Certificate {
    const KIND: Kind = Kind::Cone;
}

impl Certificate {
    /// Every number of the file as text, in order (for `max-total-digits`).
    pub fn numbers(&self) -> impl Iterator<Item = &str> {
        let Body::RegularPolygon { kappa, gamma, .. } = &self.body;
        let params = kappa.texts().into_iter().chain(gamma.texts());
        params.chain(self.cone.iter().flat_map(|g| g.0.iter().map(String::as_str)))
    }
}

/// The falling body.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
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

/// A parameter: one number (`"1/6"`), or a closed interval of numbers written as a two-element
/// list (`["1/10", "3/25"]`, version 2), each in canonical text.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(untagged, expecting = "a number such as \"1/6\", or an interval such as [\"1/10\", \"3/25\"]")]
pub enum Param {
    /// One value.
    Point(String),
    /// The closed interval [lo, hi].
    Interval(String, String),
}

impl Param {
    /// The numbers as written: one or two.
    pub fn texts(&self) -> Vec<&str> {
        match self {
            Param::Point(s) => vec![s],
            Param::Interval(a, b) => vec![a, b],
        }
    }
}

/// The coordinates of the generators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
pub enum Coordinates {
    /// (u0, u1, v): normal velocities of contacts 0 and 1 and of the centre of mass.
    ContactVelocities,
}

/// What the certificate proves (each claim includes the checks of the previous ones).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash, Deserialize)]
pub enum Claim {
    /// K lies in v <= 0 and S_j(K ∩ C_j) ⊆ K for j = 1..n-1 (docs/model.md §5 conditions 1-2).
    /// The default: the weakest claim.
    #[default]
    EffectivelyInvariant,
    /// Also I_0(D) ⊆ K: every drop with all contacts moving down keeps v <= 0 for ever (not ICC);
    /// a finite accumulation time is not derived (docs/time-to-rest.md).
    CcOrPccFromAllDown,
    /// Also PCC excluded; a finite accumulation time is not derived (docs/time-to-rest.md).
    CompleteChatterFromAllDown,
    /// Orbit certificates only (docs/certificate-format.md §14): every motion whose state right after some impact is,
    /// up to relabelling and the two scalings, a point of the set X ends in complete chatter,
    /// following the pattern periodically (docs/orbit-certificates.md §4). Not a cone claim: it
    /// is not in [`Claim::ALL`] and the cone kernels reject it.
    CompleteChatterFromSet,
}

/// One generator of the cone: its coordinates as canonical rational text.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Generator(pub Vec<String>);

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
