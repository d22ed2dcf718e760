//! `chatter-kernel`: the trusted part of `chatter`.
//!
//! A certificate or proof is trusted because this crate re-checks it, not because a producer
//! says so. The crate is small and separate, and its promises are compiler checks: no unsafe
//! code, no floating-point arithmetic, every public item documented, and no dependency on the
//! untrusted tool; it depends on malachite, num-bigint/num-rational, serde, ron and serde_json
//! only. Each verdict kind is read alone (docs/kernel-soundness.md §4):
//!
//! - [`exact`]: exact scalars on two independent bignum backends, the canonical `"p/q"` text, and
//!   (feature `field`) the number fields Q(cos 2 pi/n);
//! - [`syntax`]: the strict syntax, the header naming the kind of a file, the limits and numbers,
//!   written once; the serde schema of every kind;
//! - [`model`]: the exact impact model (docs/model.md); [`geometry`]: exact convex polygons;
//! - [`rules`]: the acceptance rules, one file per kind; [`reject`]: the typed rejections;
//! - [`verify`]: the kernel on both backends, with a disagreement reported as an internal error;
//! - `membership` (features `orbit` and `field`): whether an exact state lies in the set an
//!   accepted certificate certifies (docs/kernel-soundness.md §8);
//! - `explain` (feature `explain`): the words of a rejection, outside the trusted path;
//! - `conveniences`: names, conversions and serialization that no rule calls, outside every
//!   kind's lines to read.
//!
//! Cargo features select the kinds: point certificates of the rod and of regular polygons with
//! rational cos(2 pi/n) are always built; `boxes`, `field`, `family`, `orbit`, `refutation` and
//! `proof` add the other kinds, `json` the JSON twin of every format, and `explain` the messages.
//! All are in `default`;
//! `--no-default-features` builds the point-certificate kernel.
//!
//! Why acceptance implies each claim is argued in docs/kernel-soundness.md.
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![deny(clippy::float_arithmetic)]

#[cfg(feature = "basin")]
pub mod basin;
#[cfg(feature = "boxes")]
pub mod bivariate;
mod conveniences;
pub mod exact;
#[cfg(feature = "explain")]
pub mod explain;
pub mod geometry;
#[cfg(all(feature = "orbit", feature = "field"))]
pub mod membership;
pub mod model;
#[cfg(feature = "orbit")]
pub mod orbit;
pub mod reject;
pub mod rules;
pub mod syntax;
pub mod verify;

/// The names the tool has always used for the certificate kernel's types: the schemas of the
/// certificate kinds ([`syntax`]) and the typed rejections ([`reject`]).
pub mod certificate {
    pub use crate::reject::{
        Boundary, Code, Counted, Detail, ImageFailure, Internal, Locus, Needs, Rejection,
    };
    #[cfg(feature = "kinds")]
    pub use crate::reject::{KindDetail, KindLocus};
    pub use crate::syntax::Encoding;
    pub use crate::syntax::cone::{
        Body, Certificate, Claim, Coordinates, FORMAT, Generator, Param, VERSION, VERSIONS,
    };
    #[cfg(feature = "family")]
    pub use crate::syntax::family::{ConvexBodyText, ConvexCertificate, ConvexCoordinates};
    #[cfg(feature = "orbit")]
    pub use crate::syntax::orbit::{OrbitBody, OrbitCertificate, OrbitSet, Triple};

    /// Reads a cone certificate (RON): [`crate::syntax::read`].
    pub fn read(text: &str) -> Result<Certificate, Rejection> {
        crate::syntax::read(text, Encoding::Ron)
    }

    /// Reads a cone certificate in the given encoding: [`crate::syntax::read`].
    pub fn read_in(text: &str, encoding: Encoding) -> Result<Certificate, Rejection> {
        crate::syntax::read(text, encoding)
    }

    /// Reads a family certificate in the given encoding: [`crate::syntax::read`].
    #[cfg(feature = "family")]
    pub fn read_convex(text: &str, encoding: Encoding) -> Result<ConvexCertificate, Rejection> {
        crate::syntax::read(text, encoding)
    }

    /// Reads an orbit certificate in the given encoding: [`crate::syntax::read`].
    #[cfg(feature = "orbit")]
    pub fn read_orbit(text: &str, encoding: Encoding) -> Result<OrbitCertificate, Rejection> {
        crate::syntax::read(text, encoding)
    }
}

/// The certificate kernel's entry points by their former names: what an accepted certificate
/// established, and the check of a cone certificate on one backend.
pub mod check {
    pub use crate::model::polygon::is_irrational;
    #[cfg(feature = "boxes")]
    pub use crate::rules::boxes::MAX_PCC_BOXES;
    #[cfg(feature = "family")]
    pub use crate::rules::family::check as check_convex;
    #[cfg(feature = "field")]
    pub use crate::rules::field::FIELD_VERSION;
    pub use crate::rules::outcome::Accepted;
    pub use crate::verify::check;
    #[cfg(feature = "field")]
    pub use crate::verify::check_in_field;
}

/// Refutations (feature `refutation`), by their former path.
#[cfg(feature = "refutation")]
pub mod refute {
    pub use crate::rules::refutation::{Refuted, check};
    pub use crate::syntax::refutation::{FORMAT, Refutation, Step, VERSION};
}

/// Time-to-rest certificates (feature `rest`): the schema and the kernel on one backend.
#[cfg(feature = "rest")]
pub mod rest {
    pub use crate::rules::rest::{FIELD_VERSION, Rested, check};
    #[cfg(feature = "field")]
    pub use crate::rules::rest_field::check_in_field;
    pub use crate::syntax::rest::{FORMAT, Node, TimeToRest, VERSION};
}

/// Time-to-rest certificates of general convex bodies (feature `family-rest`).
#[cfg(feature = "family-rest")]
pub mod rest_family {
    pub use crate::rules::rest_family::check;
    pub use crate::syntax::rest_family::{FORMAT, FamilyNode, FamilyTimeToRest, INTERVAL_VERSION, VERSION};
}

#[cfg(feature = "proof")]
pub use rules::proof;
