//! The schema of time-to-rest certificates (docs/certificate-format.md §16): a regular polygon at
//! a point, a claim about all-down drops, a bound B and a virtual-time graph (docs/time-to-rest.md
//! §5). Format `"chatter-time-to-rest"`, versions 1 (a scale c_r per node), 2 (a numerator
//! a_r per node) and 3 (version 2, also about a body with irrational cos 2π/n, whose numbers are
//! elements of Q(cos 2π/n)). The numbers stay text here.

use crate::syntax::cone::{Body, Claim, Coordinates, Generator};
use crate::syntax::{Kind, Schema};
use serde::Deserialize;

/// Value of the `format` field.
pub const FORMAT: &str = "chatter-time-to-rest";
/// The version the tool writes for n = 3, 4, 6; version 1 is read too, and version 3
/// (`rules::rest::FIELD_VERSION`) for every n.
pub const VERSION: u64 = 2;

/// A time-to-rest certificate.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename = "TimeToRest", deny_unknown_fields)]
pub struct TimeToRest {
    /// Always [`FORMAT`].
    pub format: String,
    /// 1, 2 ([`VERSION`]) or 3.
    pub version: u64,
    /// The falling body, at a point.
    pub body: Body,
    /// The coordinates of the generators and covectors.
    pub coordinates: Coordinates,
    /// `CcOrPccFromAllDown` or `CompleteChatterFromAllDown`.
    pub claim: Claim,
    /// B: the impacts of every all-down drop accumulate within B h/|v| (rule G5).
    pub bound: String,
    /// The nodes; node 0 is entered at the first impact (rule G4).
    pub nodes: Vec<Node>,
    /// Informational only, never trusted.
    #[serde(default)]
    pub producer: String,
}

/// A node of the graph: the cone K_r, the covector b_r, the scale c_r (version 1) or the
/// numerator a_r (version 2), and the successors.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Node {
    /// Generators of K_r, (u0, u1, v).
    pub cone: Vec<Generator>,
    /// b_r, applied to configurations (h0, h1, hc) and velocities (u0, u1, v).
    pub weight: Generator,
    /// Version 1: c_r >= 1, and a_r = c_r b_r (`""` when absent).
    #[serde(default)]
    pub scale: String,
    /// Version 2: a_r, applied to configurations (empty when absent).
    #[serde(default)]
    pub numerator: Generator,
    /// (j, s(r, j)): the node of the velocity after an impact j places on.
    pub next: Vec<(u64, usize)>,
}

impl Schema for TimeToRest {
    const KIND: Kind = Kind::Rest;
}

impl TimeToRest {
    /// Every number of the file as text, in order (for `max-total-digits`).
    pub fn numbers(&self) -> impl Iterator<Item = &str> {
        let Body::RegularPolygon { kappa, gamma, .. } = &self.body;
        let nodes = self.nodes.iter().flat_map(|n| {
            let gens =
                n.cone.iter().chain([&n.weight, &n.numerator]).flat_map(|g| g.0.iter().map(String::as_str));
            gens.chain([n.scale.as_str()])
        });
        kappa.texts().into_iter().chain(gamma.texts()).chain([self.bound.as_str()]).chain(nodes)
    }
}
