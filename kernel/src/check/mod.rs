//! The certificate kernel: re-checks a certificate with exact arithmetic over any backend.
//!
//! It recomputes every map and cone from the body and never uses floating point. Each acceptance
//! rule is documented in docs/certificate-format.md, and why it implies its claim in
//! docs/kernel-soundness.md. All geometric tests run on integer-scaled homogeneous vectors:
//! effective invariance is a property of cones, so scaling a generator, a covector or a map by a
//! positive number changes nothing.

mod convex;
pub use convex::check_convex;
mod polygon;
pub use polygon::MAX_PCC_BOXES;
mod field;
pub use field::{FIELD_VERSION, is_irrational};
mod region;
mod rod;
mod scalar;
mod show;
pub(crate) use show::abbreviate as abbreviated;

use crate::certificate::{Body, Certificate, Claim, Code, FORMAT, Locus, Rejection, VERSIONS};
use crate::exact::{Field, Int, NumberError, ParseLimits, parse_canonical, parse_canonical_parts};
use crate::model::Shape;

/// What an accepted certificate established.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Accepted {
    /// The claim established.
    pub claim: Claim,
    /// Number of contacts.
    pub n: u64,
    /// Number of generators in the file.
    pub generators: usize,
    /// Indices of generators that are not extreme rays of K (allowed, reported).
    pub redundant: Vec<usize>,
    /// For j = 1..n-1, the number of vertices of K ∩ C_j whose images were checked.
    pub pieces: Vec<usize>,
    /// Largest denominator among the generators' coordinates, in bits.
    pub max_denominator_bits: u64,
    /// For `CompleteChatterFromAllDown` with n >= 3: (p, q, discriminant) of the PCC quadratic,
    /// canonical text.
    pub pcc: Option<[String; 3]>,
    /// Whether K contains the velocity after the first impact of a pure downward translation
    /// (informational: without some such velocity the claim is vacuous); for a box, at every
    /// corner. Orbit certificates have no cone: always false there (not applicable).
    pub contains_translation: bool,
    /// For a box certificate: the bounds [lo, hi] of kappa and of gamma, canonical text.
    pub region: Option<[[String; 2]; 2]>,
    /// For `CompleteChatterFromAllDown` on a box: the number of sub-boxes on which PCC exclusion
    /// was shown by Bernstein bounds.
    pub pcc_boxes: Option<usize>,
    /// For an orbit certificate (version 5): the number of sub-boxes of X on which conditions
    /// 1-3 were shown.
    pub orbit_boxes: Option<usize>,
}

/// Checks a certificate exactly over the field `F`. The first failing check is reported.
pub fn check<F: Field>(cert: &Certificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    header(cert)?;
    size(cert, limits)?;
    let Body::RegularPolygon { n, .. } = &cert.body;
    if field::is_irrational(*n) {
        return field::check::<F>(cert, limits);
    }
    let region = region::region::<F>(cert, limits)?;
    region::claim_range(&region, cert.claim)?;
    let gens = generators::<F>(cert, region.corners[0].shape.coordinates(), limits)?;
    let mut accepted = match &region.corners[0].shape {
        Shape::Rod(_) => rod::check(&region, &gens, cert.claim, limits)?,
        Shape::Polygon(_) => polygon::check(&region, &gens, cert.claim, limits)?,
    };
    if region.is_box {
        let text = |r: &[F; 2]| [crate::exact::to_canonical(&r[0]), crate::exact::to_canonical(&r[1])];
        accepted.region = Some([text(&region.rect.kappa), text(&region.rect.gamma)]);
    }
    Ok(accepted)
}

/// The checks of [`check`] run in the number field Q(cos 2 pi/n) whatever n (3 to 64), also where
/// cos 2 pi/n is rational (a field of degree 1): a second path for n = 3, 4, 6, against which the
/// field path is tested. Point certificates of regular polygons only.
pub fn check_in_field<F: Field>(cert: &Certificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    header(cert)?;
    size(cert, limits)?;
    field::check::<F>(cert, limits)
}

/// The limits on the whole file, before any arithmetic: the number of generators and the
/// digits of all numbers together (a number's length counts its sign and slash: an upper bound).
fn size(cert: &Certificate, limits: ParseLimits) -> Result<(), Rejection> {
    let too_large = |name: &str, msg: String| {
        Rejection::new(
            Code::TooLarge,
            Locus::Limit { name: name.into() },
            format!("{msg}: no verdict on the content"),
        )
    };
    if cert.cone.len() > limits.max_generators {
        let msg = format!(
            "{} generators, more than the limit max-generators = {}",
            cert.cone.len(),
            limits.max_generators
        );
        return Err(too_large("max-generators", msg));
    }
    let Body::RegularPolygon { kappa, gamma, .. } = &cert.body;
    let params = kappa.texts().into_iter().chain(gamma.texts());
    let total: usize =
        params.chain(cert.cone.iter().flat_map(|g| g.0.iter().map(String::as_str))).map(str::len).sum();
    if total > limits.max_total_digits {
        let msg = format!(
            "{total} characters of numbers, more than the limit max-total-digits = {}",
            limits.max_total_digits
        );
        return Err(too_large("max-total-digits", msg));
    }
    Ok(())
}

/// `time-limit` once the deadline has passed.
pub(crate) fn in_time(limits: ParseLimits, during: &str) -> Result<(), Rejection> {
    if limits.expired() { Err(Rejection::time_limit(during)) } else { Ok(()) }
}

/// A number that cannot be read: `too-large` beyond max-digits, `bad-number` otherwise.
fn number_error(path: String, s: &str, e: NumberError) -> Rejection {
    let code = if matches!(e, NumberError::TooLong { .. }) { Code::TooLarge } else { Code::BadNumber };
    Rejection::at_field(code, path, format!("{}: {e}", show::quote(s)))
}

/// `format` and `version` (the reader has checked them already; a certificate built in memory
/// has not).
fn header(cert: &Certificate) -> Result<(), Rejection> {
    if cert.format != FORMAT {
        return Err(Rejection::at_field(Code::WrongFormat, "format", format!("expected {FORMAT:?}")));
    }
    if !VERSIONS.contains(&cert.version) {
        let msg = format!("{} is not one of the versions this build reads ({VERSIONS:?})", cert.version);
        return Err(Rejection::at_field(Code::UnsupportedVersion, "version", msg));
    }
    not_orbit_claim(cert.claim)
}

/// The orbit claim is not a cone claim: a cone certificate that names it is rejected.
pub(crate) fn not_orbit_claim(claim: Claim) -> Result<(), Rejection> {
    if claim == Claim::CompleteChatterFromSet {
        let msg = "CompleteChatterFromSet is the claim of orbit certificates (version 5), not of a cone";
        return Err(Rejection::at_field(Code::UnknownVariant, "claim", msg));
    }
    Ok(())
}

/// A canonical number of a field of the body.
fn number<F: Field>(path: &str, s: &str, limits: ParseLimits) -> Result<F, Rejection> {
    parse_canonical(s, limits).map_err(|e| number_error(path.to_string(), s, e))
}

/// The generators as integer vectors, positive multiples of the given ones, with the largest
/// denominator in bits.
pub(crate) struct Generators<'a, Z> {
    /// Integer coordinates: coordinate i of (p_0/q_0, ..., p_k/q_k) is p_i prod_{j != i} q_j.
    pub vectors: Vec<Vec<Z>>,
    /// Largest denominator, in bits.
    pub max_denominator_bits: u64,
    /// The certificate (for messages).
    pub cert: &'a Certificate,
}

impl<Z> Generators<'_, Z> {
    /// The rejection for generator `i` with v >= 0 (rule R1).
    pub fn not_below(&self, i: usize) -> Rejection {
        let msg = format!("generator cone[{i}] = ({}) has v >= 0", show::tuple(&self.cert.cone[i].0));
        Rejection::new(Code::GeneratorNotBelow, Locus::Generator { index: i }, msg)
    }
}

fn generators<'a, F: Field>(
    cert: &'a Certificate,
    names: &[&str],
    limits: ParseLimits,
) -> Result<Generators<'a, F::Int>, Rejection> {
    let mut vectors = Vec::with_capacity(cert.cone.len());
    let mut bits = 0;
    for (i, g) in cert.cone.iter().enumerate() {
        in_time(limits, "reading the generators")?;
        if g.0.len() != names.len() {
            let msg =
                format!("expected {} coordinates ({}), found {}", names.len(), names.join(", "), g.0.len());
            return Err(Rejection::at_field(Code::WrongArity, format!("cone[{i}]"), msg));
        }
        let mut parts = Vec::with_capacity(names.len());
        for (c, name) in g.0.iter().zip(names) {
            let (p, q) = parse_canonical_parts::<F::Int>(c, limits)
                .map_err(|e| number_error(format!("cone[{i}].{name}"), c, e))?;
            bits = bits.max(q.bit_length());
            parts.push((p, q));
        }
        vectors.push(common_denominator(&parts));
    }
    Ok(Generators { vectors, max_denominator_bits: bits, cert })
}

/// (p_0/q_0, ..., p_k/q_k) times prod q_j: integers, a positive multiple (all q_j > 0).
fn common_denominator<Z: Int>(parts: &[(Z, Z)]) -> Vec<Z> {
    (0..parts.len())
        .map(|k| {
            parts.iter().enumerate().fold(Z::one(), |acc, (j, (p, q))| acc.times(if j == k { p } else { q }))
        })
        .collect()
}
