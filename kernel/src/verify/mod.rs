//! The kernel on both bignum backends. The two runs share no arithmetic code: malachite and
//! num-bigint/num-rational are independent libraries, so a disagreement between their verdicts
//! (typed rejections included) reveals a bug in one of them or in the kernel, and is reported as
//! such. [`verify_text`] reads a certificate of any kind (the header names it) and runs the rules
//! of that kind; a reviewer of one kind reads only its branch.

use crate::exact::{Field, ParseLimits};
use crate::model::polygon::is_irrational;
#[cfg(any(not(feature = "field"), not(feature = "boxes")))]
use crate::reject::Needs;
use crate::reject::{Code, Detail, Rejection, TimeToRestFailure};
use crate::rules::outcome::Accepted;
use crate::rules::{cone, rod};
use crate::syntax::cone::{Body, Certificate, Param};
use crate::syntax::{Encoding, Kind, kind_of, read, schema};
use malachite::rational::Rational;
use num_rational::BigRational;

#[cfg(feature = "basin")]
mod basin;
#[cfg(feature = "family")]
mod family;
#[cfg(feature = "field")]
mod field;
#[cfg(feature = "orbit")]
mod orbit;
#[cfg(feature = "proof")]
mod proof;
#[cfg(feature = "refutation")]
mod refutation;

#[cfg(feature = "basin")]
pub use basin::{verify_basin, verify_basin_text_in};
#[cfg(feature = "family")]
pub use family::{verify_convex, verify_convex_on};
#[cfg(feature = "field")]
pub use field::check_in_field;
#[cfg(feature = "orbit")]
pub use orbit::{verify_orbit, verify_orbit_on};
#[cfg(feature = "proof")]
pub use proof::{verify_proof, verify_proof_text};
#[cfg(feature = "refutation")]
pub use refutation::{verify_refutation, verify_refutation_text, verify_refutation_text_in};

#[cfg(feature = "boxes")]
use crate::rules::boxes;
#[cfg(feature = "family")]
use crate::rules::family as family_rules;
#[cfg(feature = "field")]
use crate::rules::field as field_rules;
#[cfg(feature = "orbit")]
use crate::rules::orbit as orbit_rules;
#[cfg(feature = "proof")]
use crate::rules::proof::{self as proof_rules, Checked};
#[cfg(feature = "refutation")]
use crate::rules::refutation::{self as refutation_rules, Refuted};
#[cfg(feature = "family")]
use crate::syntax::family::ConvexCertificate;
#[cfg(feature = "orbit")]
use crate::syntax::orbit::OrbitCertificate;
#[cfg(feature = "proof")]
use crate::syntax::proof::ProofFile;
#[cfg(feature = "refutation")]
use crate::syntax::refutation::Refutation;

/// A cone certificate on one backend: the file's rules ([`cone::prelude`]), then the rules of its
/// body: the rod, a polygon with rational or irrational cos(2 pi/n), a point or a box.
pub fn check<F: Field>(cert: &Certificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    cone::prelude(cert, limits)?;
    rod_only_bound(cert)?;
    let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
    if is_irrational(*n) {
        #[cfg(feature = "field")]
        return field_rules::check::<F>(cert, limits);
        #[cfg(not(feature = "field"))]
        return Err(not_built(Code::UnsupportedBody, "body.n", "field", cert.version));
    }
    match (kappa, gamma) {
        (Param::Point(k), Param::Point(g)) if *n == 2 => rod::check_point::<F>(cert, [k, g], limits),
        (Param::Point(k), Param::Point(g)) => cone::check_point::<F>(cert, [k, g], limits),
        #[cfg(feature = "boxes")]
        _ => boxes::check::<F>(cert, limits),
        #[cfg(not(feature = "boxes"))]
        _ => Err(not_built(Code::UnsupportedVersion, "version", "boxes", cert.version)),
    }
}

/// Rule T1 covers only the rod at a point (docs/time-to-rest.md §2); elsewhere B is refused.
fn rod_only_bound(cert: &Certificate) -> Result<(), Rejection> {
    let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
    let rod_point = *n == 2 && matches!((kappa, gamma), (Param::Point(_), Param::Point(_)));
    match &cert.time_to_rest_bound {
        Some(b) if !rod_point => {
            let detail = Detail::TimeToRest(TimeToRestFailure::NotRod, b.clone());
            Err(Rejection::at(Code::TimeToRestNotShown, "time_to_rest_bound", detail))
        }
        _ => Ok(()),
    }
}

/// A file this build cannot check without the Cargo feature `feature`.
#[cfg(any(not(feature = "field"), not(feature = "boxes")))]
fn not_built(code: Code, path: &str, feature: &'static str, version: u64) -> Rejection {
    Rejection::at(code, path, Detail::Needs(Needs::Feature(feature), version))
}

/// A named backend: the kernel of every kind on one bignum library.
#[derive(Clone, Copy)]
pub struct Backend {
    /// The bignum library's name.
    pub name: &'static str,
    /// Cone certificates.
    pub check: fn(&Certificate, ParseLimits) -> Result<Accepted, Rejection>,
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
    pub basin: fn(
        &crate::syntax::basin::BasinCertificate,
        ParseLimits,
    ) -> Result<crate::rules::basin::BasinReport, Rejection>,
}

/// The kernel on the backend `F`.
const fn backend<F: Field>(name: &'static str) -> Backend {
    Backend {
        name,
        check: check::<F>,
        #[cfg(feature = "refutation")]
        refute: refutation_rules::check::<F>,
        #[cfg(feature = "family")]
        convex: family_rules::check::<F>,
        #[cfg(feature = "orbit")]
        orbit: orbit_rules::check::<F>,
        #[cfg(feature = "proof")]
        proof: proof_rules::check::<F>,
        #[cfg(feature = "basin")]
        basin: crate::rules::basin::check::<F>,
    }
}

/// malachite, the main backend.
pub const MALACHITE: Backend = backend::<Rational>("malachite");
/// num-bigint/num-rational, the independent second backend.
pub const NUM: Backend = backend::<BigRational>("num-rational");

/// The kernel's verdict, possibly over several backends (on a certificate, `T` = [`Accepted`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Verdict<T = Accepted> {
    /// Every backend accepts, with identical reports.
    Accepted(T),
    /// Every backend rejects, with identical rejections.
    Rejected(Rejection),
    /// The backends disagree: a bug in chatter or in a bignum library.
    Disagree(String),
}

/// Compares the verdicts of several runs: identical verdicts, or a disagreement naming the first
/// two that differ. A run that ran out of time gives no verdict on the content, so it is the
/// verdict (`time-limit`), never a disagreement.
pub fn agree<T: PartialEq + std::fmt::Debug>(
    runs: impl IntoIterator<Item = (&'static str, Result<T, Rejection>)>,
) -> Verdict<T> {
    let mut first: Option<(&str, Result<T, Rejection>)> = None;
    let mut differ = None;
    for (name, r) in runs {
        if let Err(e) = &r
            && e.code == Code::TimeLimit
        {
            return Verdict::Rejected(e.clone());
        }
        match &first {
            None => first = Some((name, r)),
            Some((n0, f)) if *f != r && differ.is_none() => {
                differ = Some(format!("{n0} says {f:?}, {name} says {r:?}"))
            }
            Some(_) => {}
        }
    }
    match (differ, first) {
        (Some(d), _) => Verdict::Disagree(d),
        (None, Some((_, Ok(a)))) => Verdict::Accepted(a),
        (None, Some((_, Err(r)))) => Verdict::Rejected(r),
        (None, None) => Verdict::Disagree("no backend was run".into()),
    }
}

/// Both backends (malachite and num-rational).
pub const BOTH: [Backend; 2] = [MALACHITE, NUM];

/// Runs the kernel on a cone certificate on each backend and compares the verdicts.
pub fn verify_on(cert: &Certificate, limits: ParseLimits, backends: &[Backend]) -> Verdict {
    agree(backends.iter().map(|b| (b.name, (b.check)(cert, limits))))
}

/// Runs the kernel on a cone certificate on both backends.
pub fn verify(cert: &Certificate, limits: ParseLimits) -> Verdict {
    verify_on(cert, limits, &BOTH)
}

/// Reads RON certificate text of any kind and verifies it on the given backends.
pub fn verify_text(text: &str, limits: ParseLimits, backends: &[Backend]) -> Verdict {
    verify_text_in(text, Encoding::Ron, limits, backends)
}

/// Reads certificate text in the given encoding (RON or its JSON twin): the header names the
/// kind, the kind's schema is read, and its rules run on the given backends.
pub fn verify_text_in(text: &str, encoding: Encoding, limits: ParseLimits, backends: &[Backend]) -> Verdict {
    let verdict = |r: Result<Verdict, Rejection>| r.unwrap_or_else(Verdict::Rejected);
    match kind_of(text, encoding, Kind::Cone) {
        Err(r) => Verdict::Rejected(r),
        Ok((Kind::Cone, _)) => verdict(schema(text, encoding).map(|c| verify_on(&c, limits, backends))),
        #[cfg(feature = "family")]
        Ok((Kind::Family, _)) => {
            verdict(schema(text, encoding).map(|c| verify_convex_on(&c, limits, backends)))
        }
        #[cfg(feature = "orbit")]
        Ok((Kind::Orbit, _)) => {
            verdict(schema(text, encoding).map(|c| verify_orbit_on(&c, limits, backends)))
        }
        Ok(_) => verdict(read::<Certificate>(text, encoding).map(|c| verify_on(&c, limits, backends))),
    }
}
