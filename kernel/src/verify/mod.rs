//! The kernel on both bignum backends. The two runs share no arithmetic code: malachite and
//! num-bigint/num-rational are independent libraries, so a disagreement between their verdicts
//! (typed rejections included) reveals a bug in one of them or in the kernel, and is reported as
//! such. [`verify_text`] reads a certificate of any kind (the header names it) and runs the rules
//! of that kind; a reviewer of one kind reads only its branch.

use crate::exact::{Field, ParseLimits};
use crate::model::polygon::is_irrational;
use crate::reject::{Code, Rejection};
#[cfg(any(not(feature = "field"), not(feature = "boxes")))]
use crate::reject::{Detail, Needs};
use crate::rules::outcome::Accepted;
use crate::rules::{cone, rod};
use crate::syntax::cone::{Body, Certificate, Param};
use crate::syntax::{Encoding, Kind, kind_of, schema};
use malachite::rational::Rational;
use num_rational::BigRational;

#[cfg(feature = "field")]
mod field;
#[cfg(feature = "files")]
mod kinds;

#[cfg(feature = "field")]
pub use field::check_in_field;
#[cfg(feature = "files")]
pub use kinds::*;

#[cfg(feature = "boxes")]
use crate::rules::boxes;
#[cfg(feature = "field")]
use crate::rules::field as field_rules;

/// A cone certificate on one backend: the file's rules ([`cone::prelude`]), then the rules of its
/// body: the rod, a polygon with rational or irrational cos(2 pi/n), a point or a box.
pub fn check<F: Field>(cert: &Certificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    cone::prelude(cert, limits)?;
    let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
    match (kappa, gamma) {
        (Param::Point(k), Param::Point(g)) if *n == 2 => rod::check_point::<F>(cert, [k, g], limits),
        #[cfg(feature = "field")]
        _ if is_irrational(*n) => field_rules::check::<F>(cert, limits),
        #[cfg(not(feature = "field"))]
        _ if is_irrational(*n) => Err(not_built(Code::UnsupportedBody, "body.n", "field", cert.version)),
        (Param::Point(k), Param::Point(g)) => cone::check_point::<F>(cert, [k, g], limits),
        #[cfg(feature = "boxes")]
        _ => boxes::check::<F>(cert, limits),
        #[cfg(not(feature = "boxes"))]
        _ => Err(not_built(Code::UnsupportedVersion, "version", "boxes", cert.version)),
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
    /// The other kinds of file ([`Kinds`]).
    #[cfg(feature = "files")]
    pub kinds: Kinds,
}

/// The kernel on the backend `F`.
const fn backend<F: Field>(name: &'static str) -> Backend {
    Backend {
        name,
        check: check::<F>,
        #[cfg(feature = "files")]
        kinds: Kinds::of::<F>(),
    }
}

// The backends are statics, not constants: a constant holding `check::<F>` is copied into every
// crate that names it, which then compiles the whole generic kernel again, twice (about 25 s per
// binary at full optimisation: CI, issue 23 §4). A static is compiled here, once.

/// malachite, the main backend.
pub static MALACHITE: Backend = backend::<Rational>("malachite");
/// num-bigint/num-rational, the independent second backend.
pub static NUM: Backend = backend::<BigRational>("num-rational");

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
pub static BOTH: [Backend; 2] = [backend::<Rational>("malachite"), backend::<BigRational>("num-rational")];

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
    match kind_of(text, encoding, Kind::Cone) {
        Err(r) => Verdict::Rejected(r),
        #[cfg(feature = "files")]
        Ok((kind, _)) if kind != Kind::Cone => verify_text_of(kind, text, encoding, limits, backends),
        // Without those features, the header names a cone certificate or is refused.
        Ok(_) => schema(text, encoding).map_or_else(Verdict::Rejected, |c| verify_on(&c, limits, backends)),
    }
}
