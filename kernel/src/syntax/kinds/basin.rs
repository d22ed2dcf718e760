//! The schema of basin certificates (docs/basin-certificates.md, docs/certificate-format.md
//! §15): a regular polygon, a box of drops in the paper's coordinates, an embedded orbit
//! certificate and an embedded time-to-rest certificate (both optional), and a partition of the
//! box into leaves, each with the impact prefix that every drop in it follows and where the prefix
//! ends (the orbit certificate's X, a cone of the time-to-rest certificate's graph, or v > 0), or
//! undecided. Format `"chatter-basin-certificate"`, version 1. The numbers stay text.

use super::orbit::{OrbitBody, OrbitCertificate};
use super::rest::TimeToRest;
use crate::syntax::{Kind, Schema};
use serde::Deserialize;

/// Value of the `format` field.
pub const FORMAT: &str = "chatter-basin-certificate";
/// The version: 1 without `Tree` leaves, 2 with them (docs/certificate-format.md §15).
pub const VERSION: u64 = 1;
/// The version that may have `Tree` leaves.
pub const TREE_VERSION: u64 = 2;

/// A basin certificate.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename = "Certificate", deny_unknown_fields)]
pub struct BasinCertificate {
    /// [`FORMAT`].
    pub format: String,
    /// [`VERSION`].
    pub version: u64,
    /// The falling body (the orbit certificate's must be the same).
    pub body: OrbitBody,
    /// The drops: (ω_x, ω_y, φ_x, φ_y, h) in [lo, hi] (five coordinates each), the velocity
    /// (ω_x, ω_y, -1) and position (φ_x, φ_y, h) in the paper's coordinates before the first impact.
    pub drops: DropBox,
    /// The orbit certificate whose set X the CC leaves enter (checked by rules O1-O2); optional
    /// when every leaf is `Icc` or `Undecided` without cuts.
    #[serde(default)]
    pub orbit: Option<OrbitCertificate>,
    /// The time-to-rest certificate whose graph the `Rest` leaves enter (checked by its own rules
    /// and R4); optional, needed by `Rest` leaves.
    #[serde(default)]
    pub rest: Option<TimeToRest>,
    /// The leaves of a bisection of the box (docs/basin-certificates.md §3).
    pub leaves: Vec<Leaf>,
    /// Informational only, never trusted.
    #[serde(default)]
    pub producer: String,
}

/// A box of drops: lower and upper corners, five coordinates each.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DropBox {
    /// Lower corner (ω_x, ω_y, φ_x, φ_y, h).
    pub lo: Vec<String>,
    /// Upper corner.
    pub hi: Vec<String>,
}

/// A leaf: a sub-box named by its bisection path and its verdict.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Leaf {
    /// One digit per bisection: 2k for the lower half of coordinate k, 2k + 1 for the upper.
    pub path: String,
    /// What every drop of the leaf does.
    pub verdict: LeafVerdict,
}

/// What every drop of a leaf does.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum LeafVerdict {
    /// The impacts `first` (absolute contact), then the steps, after which the state lies in X:
    /// complete chatter.
    Cc {
        /// The contact (0..n-1) that lands first.
        first: u64,
        /// The later steps j in 1..n-1 (relative to the contact that landed last).
        steps: Vec<u64>,
        /// Impact counts after which the state is re-enclosed in X's parameters (increasing).
        cuts: Vec<u64>,
    },
    /// The same impacts, after which v > 0: ICC (the paper's Lemma on v).
    Icc {
        /// The contact (0..n-1) that lands first.
        first: u64,
        /// The later steps j in 1..n-1.
        steps: Vec<u64>,
        /// Impact counts after which the state is re-enclosed in X's parameters (increasing).
        cuts: Vec<u64>,
    },
    /// The same impacts (no cuts), after which the velocity lies in the cone K_r of node `node`
    /// of the time-to-rest certificate's graph: complete chatter within its virtual time.
    Rest {
        /// The contact (0..n-1) that lands first.
        first: u64,
        /// The later steps j in 1..n-1.
        steps: Vec<u64>,
        /// The node r of the time-to-rest certificate.
        node: u64,
    },
    /// No verdict claimed.
    Undecided,
    /// The contacts that may land first, each with what follows its impact (version 2):
    /// every path to an end is a prefix as above, ending as its end says.
    Tree {
        /// The contacts J that may land first (absolute, 0..n-1), each with what follows.
        next: Vec<Impact>,
    },
}

/// An impact of a `Tree` leaf: the contact that lands, then what follows.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Impact {
    /// The contact: absolute at the root, else the step j in 1..n-1 from the one that landed last.
    pub contact: u64,
    /// What follows the impact.
    pub then: Then,
}

/// What follows an impact of a `Tree` leaf.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Then {
    /// v > 0: ICC.
    Icc,
    /// The normalised state lies in X (no cuts): CC.
    Cc,
    /// The velocity lies in the cone of node `node` of the time-to-rest certificate: CC.
    Rest {
        /// The node r.
        node: u64,
    },
    /// The contacts that may land next (steps in 1..n-1), each with what follows.
    Impacts {
        /// The next impacts.
        next: Vec<Impact>,
    },
}

impl Schema for BasinCertificate {
    const KIND: Kind = Kind::Basin;
}

impl BasinCertificate {
    /// Every number of the file outside the embedded orbit certificate, with its path.
    pub fn numbers(&self) -> Vec<(String, &str)> {
        let OrbitBody::RegularPolygon { kappa, gamma, .. } = &self.body;
        let mut v = vec![("body.kappa".to_string(), kappa.as_str()), ("body.gamma".into(), gamma.as_str())];
        for (i, s) in self.drops.lo.iter().enumerate() {
            v.push((format!("drops.lo[{i}]"), s.as_str()));
        }
        for (i, s) in self.drops.hi.iter().enumerate() {
            v.push((format!("drops.hi[{i}]"), s.as_str()));
        }
        v
    }
}
