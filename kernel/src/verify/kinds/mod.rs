//! The kinds of file beyond cone certificates (features `family`, `orbit`, `basin`,
//! `refutation`, `proof`) on the backends: their kernels on one backend ([`Kinds`], part of a
//! [`Backend`](super::Backend)), their runs on several, and the dispatch of their text. A reviewer
//! of point certificates does not read this module.

use super::{Backend, Verdict, verify_on};
use crate::exact::{Field, ParseLimits};
use crate::reject::Rejection;
use crate::syntax::cone::Certificate;
use crate::syntax::{Encoding, Kind, read};

#[cfg(feature = "basin")]
mod basin;
#[cfg(feature = "family")]
mod family;
#[cfg(feature = "orbit")]
mod orbit;
#[cfg(feature = "proof")]
mod proof;
#[cfg(feature = "refutation")]
mod refutation;
#[cfg(feature = "rest")]
mod rest;
#[cfg(feature = "family-rest")]
mod rest_family;

#[cfg(feature = "basin")]
pub use basin::{verify_basin, verify_basin_text_in};
#[cfg(feature = "family")]
pub use family::{verify_convex, verify_convex_on};
#[cfg(feature = "orbit")]
pub use orbit::{verify_orbit, verify_orbit_on};
#[cfg(feature = "proof")]
pub use proof::{verify_proof, verify_proof_text};
#[cfg(feature = "refutation")]
pub use refutation::{verify_refutation, verify_refutation_text, verify_refutation_text_in};
#[cfg(feature = "rest")]
pub use rest::{verify_rest, verify_rest_text_in};
#[cfg(feature = "family-rest")]
pub use rest_family::{verify_rest_family, verify_rest_family_text_in};

#[cfg(feature = "basin")]
use crate::rules::basin::{self as basin_rules, BasinReport};
#[cfg(feature = "family")]
use crate::rules::family as family_rules;
#[cfg(feature = "orbit")]
use crate::rules::orbit as orbit_rules;
#[cfg(any(feature = "family", feature = "orbit"))]
use crate::rules::outcome::Accepted;
#[cfg(feature = "proof")]
use crate::rules::proof::{self as proof_rules, Checked};
#[cfg(feature = "refutation")]
use crate::rules::refutation::{self as refutation_rules, Refuted};
#[cfg(feature = "rest")]
use crate::rules::rest::{self as rest_rules, Rested};
#[cfg(feature = "basin")]
use crate::syntax::basin::BasinCertificate;
#[cfg(feature = "family")]
use crate::syntax::family::ConvexCertificate;
#[cfg(feature = "orbit")]
use crate::syntax::orbit::OrbitCertificate;
#[cfg(feature = "proof")]
use crate::syntax::proof::ProofFile;
#[cfg(feature = "refutation")]
use crate::syntax::refutation::Refutation;
#[cfg(feature = "rest")]
use crate::syntax::rest::TimeToRest;
#[cfg(feature = "family-rest")]
use crate::syntax::rest_family::FamilyTimeToRest;
#[cfg(any(feature = "family", feature = "orbit"))]
use crate::syntax::schema;

/// The kernels of the kinds beyond cone certificates on one bignum library.
#[derive(Clone, Copy)]
pub struct Kinds {
    /// Refutations.
    #[cfg(feature = "refutation")]
    pub refute: fn(&Refutation, ParseLimits) -> Result<Refuted, Rejection>,
    /// Family certificates.
    #[cfg(feature = "family")]
    pub convex: fn(&ConvexCertificate, ParseLimits) -> Result<Accepted, Rejection>,
    /// Orbit certificates.
    #[cfg(feature = "orbit")]
    pub orbit: fn(&OrbitCertificate, ParseLimits) -> Result<Accepted, Rejection>,
    /// Proofs.
    #[cfg(feature = "proof")]
    pub proof: fn(&ProofFile, ParseLimits) -> Result<Checked, Rejection>,
    /// Basin certificates.
    #[cfg(feature = "basin")]
    pub basin: fn(&BasinCertificate, ParseLimits) -> Result<BasinReport, Rejection>,
    /// Time-to-rest certificates.
    #[cfg(feature = "rest")]
    pub rest: fn(&TimeToRest, ParseLimits) -> Result<Rested, Rejection>,
    /// Time-to-rest certificates of general bodies.
    #[cfg(feature = "family-rest")]
    pub rest_family: fn(&FamilyTimeToRest, ParseLimits) -> Result<Rested, Rejection>,
}

impl Kinds {
    /// The kernels on the backend `F`.
    pub const fn of<F: Field>() -> Self {
        Kinds {
            #[cfg(feature = "refutation")]
            refute: refutation_rules::check::<F>,
            #[cfg(feature = "family")]
            convex: family_rules::check::<F>,
            #[cfg(feature = "orbit")]
            orbit: orbit_rules::check::<F>,
            #[cfg(feature = "proof")]
            proof: proof_rules::check::<F>,
            #[cfg(feature = "basin")]
            basin: basin_rules::check::<F>,
            #[cfg(feature = "rest")]
            rest: rest_rules::check::<F>,
            #[cfg(feature = "family-rest")]
            rest_family: crate::rules::rest_family::check::<F>,
        }
    }
}

/// Text whose header names the kind `kind` (not a cone certificate), verified on the given
/// backends: a family or orbit certificate is read and checked; any other kind is refused by the
/// cone reader (`wrong-format`, or `unsupported-version` for a legacy alias).
pub fn verify_text_of(
    kind: Kind,
    text: &str,
    encoding: Encoding,
    limits: ParseLimits,
    backends: &[Backend],
) -> Verdict {
    let verdict = |r: Result<Verdict, Rejection>| r.unwrap_or_else(Verdict::Rejected);
    match kind {
        #[cfg(feature = "family")]
        Kind::Family => verdict(schema(text, encoding).map(|c| verify_convex_on(&c, limits, backends))),
        #[cfg(feature = "orbit")]
        Kind::Orbit => verdict(schema(text, encoding).map(|c| verify_orbit_on(&c, limits, backends))),
        _ => verdict(read::<Certificate>(text, encoding).map(|c| verify_on(&c, limits, backends))),
    }
}
