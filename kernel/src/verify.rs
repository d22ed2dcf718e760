//! The kernel on both bignum backends. The two runs share no arithmetic code: malachite and
//! num-bigint/num-rational are independent libraries, so a disagreement between their verdicts
//! (messages included) reveals a bug in one of them or in the kernel, and is reported as such.

use crate::certificate::{
    CONVEX_VERSION, Certificate, ConvexCertificate, Encoding, ORBIT_VERSION, OrbitCertificate, read_convex,
    read_in, read_orbit, version_of,
};
use crate::check::{Accepted, check, check_convex};
use crate::exact::{ParseLimits, Q};
use num_rational::BigRational;

/// A kernel run on one backend: `check::<F>` for some backend `F`.
pub type Checker = fn(&Certificate, ParseLimits) -> Result<Accepted, crate::certificate::Rejection>;

/// The kernel on a version-4 (`ConvexPolygon`) certificate on one backend: `check_convex::<F>`.
pub type ConvexChecker =
    fn(&ConvexCertificate, ParseLimits) -> Result<Accepted, crate::certificate::Rejection>;

/// The kernel on a version-5 (orbit) certificate on one backend: `orbit::check_orbit::<F>`.
pub type OrbitChecker = fn(&OrbitCertificate, ParseLimits) -> Result<Accepted, crate::certificate::Rejection>;

/// The refutation checker on one backend: `refute::check::<F>` for some backend `F`.
pub type RefutationChecker = fn(
    &crate::refute::Refutation,
    ParseLimits,
) -> Result<crate::refute::Refuted, crate::certificate::Rejection>;

/// A named backend.
#[derive(Clone, Copy)]
pub struct Backend {
    /// The bignum library's name.
    pub name: &'static str,
    /// The kernel on it.
    pub check: Checker,
    /// The refutation checker on it.
    pub refute: RefutationChecker,
    /// The kernel on version-4 (`ConvexPolygon`) certificates on it.
    pub convex: ConvexChecker,
    /// The kernel on version-5 (orbit) certificates on it.
    pub orbit: OrbitChecker,
}

/// malachite, the main backend.
pub const MALACHITE: Backend = Backend {
    name: "malachite",
    check: check::<Q>,
    refute: crate::refute::check::<Q>,
    convex: check_convex::<Q>,
    orbit: crate::orbit::check_orbit::<Q>,
};
/// num-bigint/num-rational, the independent second backend.
pub const NUM: Backend = Backend {
    name: "num-rational",
    check: check::<BigRational>,
    refute: crate::refute::check::<BigRational>,
    convex: check_convex::<BigRational>,
    orbit: crate::orbit::check_orbit::<BigRational>,
};

/// The kernel's verdict, possibly over two backends (on a certificate, `T` = [`Accepted`]; on a
/// proof, `T` = [`crate::proof::Checked`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Verdict<T = Accepted> {
    /// Every backend accepts, with identical reports.
    Accepted(T),
    /// Every backend rejects, with identical reasons.
    Rejected(crate::certificate::Rejection),
    /// The backends disagree: a bug in chatter or in a bignum library.
    Disagree(String),
}

/// Compares the verdicts of several runs: identical verdicts (messages included), or a
/// disagreement naming the first two that differ. A run that ran out of time gives no verdict on
/// the content, so it is the verdict (`time-limit`), never a disagreement.
pub fn agree<T: PartialEq + std::fmt::Debug>(
    runs: impl IntoIterator<Item = (&'static str, Result<T, crate::certificate::Rejection>)>,
) -> Verdict<T> {
    let mut first: Option<(&str, Result<T, crate::certificate::Rejection>)> = None;
    let mut differ = None;
    for (name, r) in runs {
        if let Err(e) = &r {
            if e.code == crate::certificate::Code::TimeLimit {
                return Verdict::Rejected(e.clone());
            }
        }
        match &first {
            None => first = Some((name, r)),
            Some((n0, f)) if *f != r && differ.is_none() => {
                differ = Some(format!("{n0} says {f:?}, {name} says {r:?}"));
            }
            Some(_) => {}
        }
    }
    if let Some(d) = differ {
        return Verdict::Disagree(d);
    }
    match first {
        Some((_, Ok(a))) => Verdict::Accepted(a),
        Some((_, Err(r))) => Verdict::Rejected(r),
        None => Verdict::Disagree("no backend was run".into()),
    }
}

/// Runs the kernel on each backend and compares the verdicts.
pub fn verify_on(cert: &Certificate, limits: ParseLimits, backends: &[Backend]) -> Verdict {
    agree(backends.iter().map(|b| (b.name, (b.check)(cert, limits))))
}

/// Runs the kernel on a version-4 (`ConvexPolygon`) certificate on each backend and compares the
/// verdicts.
pub fn verify_convex_on(cert: &ConvexCertificate, limits: ParseLimits, backends: &[Backend]) -> Verdict {
    agree(backends.iter().map(|b| (b.name, (b.convex)(cert, limits))))
}

/// Runs the kernel on a version-5 (orbit) certificate on each backend and compares the verdicts.
pub fn verify_orbit_on(cert: &OrbitCertificate, limits: ParseLimits, backends: &[Backend]) -> Verdict {
    agree(backends.iter().map(|b| (b.name, (b.orbit)(cert, limits))))
}

/// Runs the kernel on a version-5 (orbit) certificate on both backends (malachite and num-rational).
pub fn verify_orbit(cert: &OrbitCertificate, limits: ParseLimits) -> Verdict {
    verify_orbit_on(cert, limits, &[MALACHITE, NUM])
}

/// Runs the kernel on a version-4 certificate on both backends (malachite and num-rational).
pub fn verify_convex(cert: &ConvexCertificate, limits: ParseLimits) -> Verdict {
    verify_convex_on(cert, limits, &[MALACHITE, NUM])
}

/// Runs the kernel on both backends (malachite and num-rational).
pub fn verify(cert: &Certificate, limits: ParseLimits) -> Verdict {
    verify_on(cert, limits, &[MALACHITE, NUM])
}

/// Reads RON certificate text and verifies it on the given backends.
pub fn verify_text(text: &str, limits: ParseLimits, backends: &[Backend]) -> Verdict {
    verify_text_in(text, Encoding::Ron, limits, backends)
}

/// Reads certificate text in the given encoding (RON or its JSON twin) and verifies it on the
/// given backends: after reading, the same checks on the same values.
pub fn verify_text_in(text: &str, encoding: Encoding, limits: ParseLimits, backends: &[Backend]) -> Verdict {
    if version_of(text, encoding) == Some(CONVEX_VERSION) {
        return match read_convex(text, encoding) {
            Ok(cert) => verify_convex_on(&cert, limits, backends),
            Err(r) => Verdict::Rejected(r),
        };
    }
    if version_of(text, encoding) == Some(ORBIT_VERSION) {
        return match read_orbit(text, encoding) {
            Ok(cert) => verify_orbit_on(&cert, limits, backends),
            Err(r) => Verdict::Rejected(r),
        };
    }
    match read_in(text, encoding) {
        Ok(cert) => verify_on(&cert, limits, backends),
        Err(r) => Verdict::Rejected(r),
    }
}

/// Checks a proof on both backends (malachite and num-rational).
pub fn verify_proof(file: &crate::proof::ProofFile, limits: ParseLimits) -> Verdict<crate::proof::Checked> {
    agree([
        ("malachite", crate::proof::check::<Q>(file, limits)),
        ("num-rational", crate::proof::check::<BigRational>(file, limits)),
    ])
}

/// Reads proof text and checks it on both backends.
pub fn verify_proof_text(text: &str, limits: ParseLimits) -> Verdict<crate::proof::Checked> {
    match crate::proof::read(text) {
        Ok(file) => verify_proof(&file, limits),
        Err(r) => Verdict::Rejected(r),
    }
}

/// Checks a refutation on the given backends.
pub fn verify_refutation(
    r: &crate::refute::Refutation,
    limits: ParseLimits,
    backends: &[Backend],
) -> Verdict<crate::refute::Refuted> {
    agree(backends.iter().map(|b| (b.name, (b.refute)(r, limits))))
}

/// Reads RON refutation text and checks it on the given backends.
pub fn verify_refutation_text(
    text: &str,
    limits: ParseLimits,
    backends: &[Backend],
) -> Verdict<crate::refute::Refuted> {
    verify_refutation_text_in(text, Encoding::Ron, limits, backends)
}

/// Reads refutation text in the given encoding and checks it on the given backends.
pub fn verify_refutation_text_in(
    text: &str,
    encoding: Encoding,
    limits: ParseLimits,
    backends: &[Backend],
) -> Verdict<crate::refute::Refuted> {
    match crate::refute::read_in(text, encoding) {
        Ok(r) => verify_refutation(&r, limits, backends),
        Err(r) => Verdict::Rejected(r),
    }
}

/// The `format` field of text in the given encoding, read leniently (unknown fields ignored).
pub fn format_of_in(text: &str, encoding: Encoding) -> Option<String> {
    match encoding {
        Encoding::Ron => format_of(text),
        Encoding::Json => crate::certificate::json_format_of(text),
    }
}

/// The `format` field of a certificate, refutation or proof file, read leniently (any struct
/// name, unknown fields ignored), to tell the kinds apart; `None` if the text is not RON with a
/// `format`.
pub fn format_of(text: &str) -> Option<String> {
    #[derive(serde::Deserialize)]
    struct Header {
        format: Option<String>,
    }
    let lenient = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    // The struct name in the text must match the one deserialised: try both.
    #[derive(serde::Deserialize)]
    #[serde(rename = "Certificate")]
    struct CertificateHeader {
        format: Option<String>,
    }
    #[derive(serde::Deserialize)]
    #[serde(rename = "Proof")]
    struct ProofHeader {
        format: Option<String>,
    }
    #[derive(serde::Deserialize)]
    #[serde(rename = "Refutation")]
    struct RefutationHeader {
        format: Option<String>,
    }
    lenient
        .from_str::<CertificateHeader>(text)
        .map(|h| h.format)
        .or_else(|_| lenient.from_str::<ProofHeader>(text).map(|h| h.format))
        .or_else(|_| lenient.from_str::<RefutationHeader>(text).map(|h| h.format))
        .or_else(|_| lenient.from_str::<Header>(text).map(|h| h.format))
        .ok()
        .flatten()
}
