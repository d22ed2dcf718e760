//! The schema of refutations (docs/certificate-format.md §10): a body at a point, the claim
//! refuted and a derivation of points. Format `"chatter-refutation"`, version 1. The numbers stay
//! text here; the kernel computes every point itself.

use crate::syntax::cone::{Body, Claim, Coordinates};
use crate::syntax::{Kind, Schema};
use serde::Deserialize;

/// Value of the `format` field.
pub const FORMAT: &str = "chatter-refutation";
/// The version this build reads and writes.
pub const VERSION: u64 = 1;

/// A refutation file.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename = "Refutation", deny_unknown_fields)]
pub struct Refutation {
    /// Always [`FORMAT`].
    pub format: String,
    /// Always [`VERSION`].
    pub version: u64,
    /// The falling body, at a point (no intervals).
    pub body: Body,
    /// The coordinates of the points.
    pub coordinates: Coordinates,
    /// The claim refuted: `EffectivelyInvariant` (seeded by the post-impact velocity of a pure
    /// translation) or an all-down claim (seeded by I_0 of the generators of D).
    pub refutes: Claim,
    /// The derivation, in order; the last point must have v >= 0 and be non-zero.
    pub points: Vec<Step>,
    /// Informational only, never trusted.
    #[serde(default)]
    pub producer: String,
}

/// How a point is derived.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
pub enum Step {
    /// Seed `index`: I_0 of generator `index` of D (all-down claims), or for
    /// `EffectivelyInvariant` (index 0 only) I_0 of the pure downward translation.
    Seed {
        /// The seed's index.
        index: usize,
    },
    /// Sum of coefficient times point over the terms: each point earlier, each coefficient a
    /// canonical rational >= 0, at least one term.
    Combination {
        /// (earlier point, coefficient).
        terms: Vec<(usize, String)>,
    },
    /// S_step applied to the earlier point `of`, which must lie in C_step.
    Image {
        /// j of S_j, 1..n-1.
        step: usize,
        /// The earlier point.
        of: usize,
    },
}

impl Schema for Refutation {
    const KIND: Kind = Kind::Refutation;
}

impl Step {
    /// The step's kind, the id of its locus.
    pub fn kind(&self) -> &'static str {
        match self {
            Step::Seed { .. } => "Seed",
            Step::Combination { .. } => "Combination",
            Step::Image { .. } => "Image",
        }
    }
}
