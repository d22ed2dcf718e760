//! The schema of time-to-rest certificates of a general convex body (docs/certificate-format.md
//! §17): the body of a family certificate at one γ (version 1) or over an interval of γ (version
//! 2), a claim about all-down drops, a bound B, one entry node per contact and a virtual-time
//! graph whose nodes carry the contact of the last impact (docs/time-to-rest.md §5, "General
//! bodies"). Format `"chatter-family-time-to-rest"`. The numbers stay text here.

use crate::syntax::cone::{Claim, Generator};
use crate::syntax::family::{ConvexBodyText, ConvexCoordinates};
use crate::syntax::{Kind, Schema};
use serde::Deserialize;

/// Value of the `format` field.
pub const FORMAT: &str = "chatter-family-time-to-rest";
/// The version of a body at one γ.
pub const VERSION: u64 = 1;
/// The version that may give γ as an interval [γ₀, γ₁].
pub const INTERVAL_VERSION: u64 = 2;

/// A time-to-rest certificate of a general convex body.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename = "FamilyTimeToRest", deny_unknown_fields)]
pub struct FamilyTimeToRest {
    /// Always [`FORMAT`].
    pub format: String,
    /// Always [`VERSION`].
    pub version: u64,
    /// The falling body, γ a number.
    pub body: ConvexBodyText,
    /// The coordinates of the generators and covectors: (omega_x, omega_y, v) for velocities,
    /// (phi_x, phi_y, h) for configurations.
    pub coordinates: ConvexCoordinates,
    /// `CcOrPccFromAllDown` or `CompleteChatterFromAllDown`.
    pub claim: Claim,
    /// B: the impacts of every all-down drop accumulate within B h/|v| (rule G5).
    pub bound: String,
    /// `entries[i]`: the node entered when the first impact is at contact i (rule G4).
    pub entries: Vec<usize>,
    /// The nodes.
    pub nodes: Vec<FamilyNode>,
    /// Informational only, never trusted.
    #[serde(default)]
    pub producer: String,
}

/// A node: the contact of the last impact, the cone K_r, the covector b_r, the numerator a_r and
/// the successors.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FamilyNode {
    /// i(r): the contact of the impact after which the node holds the velocity.
    pub contact: usize,
    /// Generators of K_r, (omega_x, omega_y, v).
    pub cone: Vec<Generator>,
    /// b_r, applied to velocities.
    pub weight: Generator,
    /// a_r, applied to configurations (phi_x, phi_y, h).
    pub numerator: Generator,
    /// (j, s(r, j)): the node of the velocity after contact j lands next.
    pub next: Vec<(u64, usize)>,
}

impl Schema for FamilyTimeToRest {
    const KIND: Kind = Kind::RestFamily;
}

impl FamilyTimeToRest {
    /// Every number of the file as text, in order (for `max-total-digits`).
    pub fn numbers(&self) -> impl Iterator<Item = &str> {
        let nodes = self.nodes.iter().flat_map(|n| {
            n.cone.iter().chain([&n.weight, &n.numerator]).flat_map(|g| g.0.iter().map(String::as_str))
        });
        self.body.numbers().chain([self.bound.as_str()]).chain(nodes)
    }
}
