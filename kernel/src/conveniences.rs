//! Conveniences of the public API that no rule calls: the names of claims, conversions, an
//! accessor, the default limits and a shorthand for them, and the serialization of codes for the
//! tool's reports. No verdict depends on them, and no file read to trust one reaches this module
//! (`kernel/tests/all/size.rs`), so it is outside every kind's lines to read
//! (docs/kernel-soundness.md §4). It holds no `Deserialize` impl: how a file is read is decided in
//! `syntax/` only.

use crate::exact::OrderedField;
use crate::exact::ParseLimits;
use crate::model::pcc::{PccExclusion, PccQuadratic};
use crate::model::polygon::Polygon;
use crate::reject::Code;
use crate::syntax::cone::{Claim, Param};
use serde::{Serialize, Serializer};

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

impl Param {
    /// The value of a point parameter.
    pub fn as_point(&self) -> Option<&str> {
        match self {
            Param::Point(s) => Some(s),
            Param::Interval(..) => None,
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

impl<F> Polygon<F> {
    /// kappa = rho^2 / R^2.
    pub fn kappa(&self) -> &F {
        &self.kappa
    }
}

/// The default limits of docs/certificate-format.md §2 ("Limits"). A limit can only reject a
/// file, never make one pass, so no verdict's soundness depends on these values.
impl Default for ParseLimits {
    fn default() -> Self {
        ParseLimits {
            max_digits: 10_000,
            max_total_digits: 2_000_000,
            max_generators: 100_000,
            deadline: None,
        }
    }
}

impl ParseLimits {
    /// The defaults with another per-number digit limit.
    pub fn digits(max_digits: usize) -> Self {
        ParseLimits { max_digits, ..Default::default() }
    }
}

impl<F: OrderedField> PccQuadratic<F> {
    /// Whether the Lemma on PCC excludes PCC: complex roots of modulus < 1.
    pub fn excludes_pcc(&self) -> bool {
        self.exclusion() == PccExclusion::Excluded
    }
}

impl Serialize for Code {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}
