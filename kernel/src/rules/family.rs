//! Family certificates of a general convex body (feature `family`; docs/model.md §11.5,
//! docs/certificate-format.md §13, why: docs/kernel-soundness.md §6). Rules, in the order they are
//! checked:
//!
//! - the file: the header, a cone claim (`unknown-variant`), at most 64 contacts (`unsupported-body`) and cones (`wrong-arity`),
//!   `max-generators` per cone and `max-total-digits` (`too-large`);
//! - γ: a number, or in version 2 an interval [γ₀, γ₁] (`unsupported-version` in another version)
//!   with canonical ends and γ₀ <= γ₁ (`parameter-out-of-range`);
//! - at each end of γ in turn (one for a number):
//!   - convex body: (A1) strictly convex counter-clockwise contacts, (A2) the origin strictly
//!     inside, J symmetric positive definite, 0 <= γ <= 1 (`unsupported-body`,
//!     `parameter-out-of-range`);
//!   - K0 (with `inertia_tensor`, at the first end): Izz > 0 and J = J_eff = [[Ixx, Ixy], [Ixy,
//!     Iyy]] - b bᵀ / Izz, b = (Ixz, Iyz), exactly (`inertia-not-derived`; docs/model.md
//!     Proposition 11.0);
//!   - range of γ: 0 < γ < 1 for the claims about drops;
//! - then at γ₀, then at γ₁ (a failure at an end of an interval names the end in its locus):
//! - count: one cone per contact, three coordinates per generator (`wrong-arity`);
//! - K1: each K_i is a 3-D cone with every generator in v < 0 (`generator-not-below`,
//!   `degenerate-cone`);
//! - K2: I_j(K_i ∩ C_ij) ⊆ K_j for all i != j, on the vertices of K_i clipped by the four
//!   covectors of C_ij (`image-not-below`, `image-outside`);
//! - K3 (claims about drops): I_i(D) ⊆ K_i for every i (`initial-outside`);
//! - K4 (`CompleteChatterFromAllDown`): for every adjacent pair (k, k+1) the quadratic factor of
//!   det(tI - I_k I_{k+1}) has discriminant < 0 and constant term < 1 (`pcc-not-excluded`).
//!
//! Every geometric test is that of rules R1-R4 ([`super::cone`]) on integer-scaled vectors.

use super::cone::{Cone, R2, R3, Target, check_image, cone_claim, int_mat, int_vec};
use super::generators::{self, Generators};
use super::outcome::Accepted;
use crate::exact::{Field, ParseLimits, Ring, to_canonical};
use crate::geometry::{ConvexPolygon, clip, hull};
use crate::model::convex::{ConvexBody, ConvexBodyError, MAX_CONTACTS};
use crate::model::linalg::{Vec3, mat_vec};
use crate::model::pcc::PccExclusion;
use crate::reject::{
    Code, Detail, KindCounted, KindDetail, KindInternal, KindLocus, Locus, Needs, Rejection,
};
use crate::syntax::cone::{Claim, Param};
use crate::syntax::family::{ConvexBodyText, ConvexCertificate, INTERVAL_VERSION, TensorText};
use crate::syntax::numbers::{at_most, in_time, number, total};
use crate::syntax::{Kind, expect};

/// Checks a family certificate exactly over the field `F`; the first failing check is reported.
/// With gamma an interval [γ₀, γ₁]: the body and the range of γ at γ₀ and at γ₁, then the rules
/// from the count to K4 at γ₀, then at γ₁ (why the two ends suffice: docs/kernel-soundness.md §6,
/// "An interval of γ").
pub fn check<F: Field>(cert: &ConvexCertificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    prelude(cert, limits)?;
    let ends = gammas::<F>(gamma_of(cert), cert.version == INTERVAL_VERSION, cert.version, limits)?;
    let mut bodies = Vec::with_capacity(ends.len());
    for (g, path) in &ends {
        let body = body::<F>(&cert.body, g.clone(), path, limits)?;
        if let (true, ConvexBodyText::ConvexPolygon { inertia_tensor: Some(t), .. }) =
            (bodies.is_empty(), &cert.body)
        {
            derived(&body, t, limits)?;
        }
        gamma_range(cert, &body, path)?;
        bodies.push(body);
    }
    let interval = matches!(gamma_of(cert), Param::Interval(..));
    let mut reports = Vec::with_capacity(ends.len());
    for ((g, _), body) in ends.iter().zip(bodies) {
        let end = interval.then(|| to_canonical(g));
        reports.push(rest(cert, body, limits).map_err(|e| at_end(e, end))?);
    }
    let translation = reports.iter().all(|a| a.contains_translation);
    let mut a = reports.swap_remove(0);
    a.contains_translation = translation;
    Ok(a)
}

/// The range of γ: 0 < γ < 1 for the claims about drops.
fn gamma_range<F: Field>(
    cert: &ConvexCertificate,
    body: &ConvexBody<F>,
    path: &str,
) -> Result<(), Rejection> {
    let g = body.gamma();
    if cert.claim > Claim::EffectivelyInvariant && (g.is_zero() || *g == F::one()) {
        let detail = Detail::GammaForClaim(to_canonical(g), cert.claim, true);
        return Err(Rejection::at(Code::ParameterOutOfRange, path, detail));
    }
    Ok(())
}

fn gamma_of(cert: &ConvexCertificate) -> &Param {
    let ConvexBodyText::ConvexPolygon { gamma, .. } = &cert.body;
    gamma
}

/// The distinct ends of gamma with their paths: one for a number, two for an interval
/// [γ₀, γ₁] (where the file's `version` reads intervals, γ₀ <= γ₁; one when γ₀ = γ₁).
pub(super) fn gammas<F: Field>(
    gamma: &Param,
    intervals: bool,
    version: u64,
    limits: ParseLimits,
) -> Result<Vec<(F, String)>, Rejection> {
    let (a, b) = match gamma {
        Param::Point(s) => return Ok(vec![(number::<F>("body.gamma", s, limits)?, "body.gamma".into())]),
        Param::Interval(a, b) => (a, b),
    };
    if !intervals {
        let detail = Detail::Needs(Needs::Intervals, version);
        return Err(Rejection::at(Code::UnsupportedVersion, "version", detail));
    }
    let lo: F = number("body.gamma[0]", a, limits)?;
    let hi: F = number("body.gamma[1]", b, limits)?;
    if lo > hi {
        let detail = KindDetail::EmptyInterval(to_canonical(&lo), to_canonical(&hi));
        return Err(Rejection::at(Code::ParameterOutOfRange, "body.gamma", detail));
    }
    let mut ends = vec![(lo.clone(), "body.gamma[0]".to_string())];
    if lo != hi {
        ends.push((hi, "body.gamma[1]".into()));
    }
    Ok(ends)
}

/// A rejection of K2, K3 or K4 at one end of an interval of gamma: the end's value in the locus.
pub(super) fn at_end(mut e: Rejection, end: Option<String>) -> Rejection {
    if let Locus::Kind(
        KindLocus::Transition { gamma, .. }
        | KindLocus::ConvexAllDown { gamma, .. }
        | KindLocus::PccPair { gamma, .. },
    ) = &mut e.locus
    {
        *gamma = end;
    }
    e
}

/// K0: J is J_eff of the full tensor (Proposition 11.0): Izz > 0 (with J positive definite,
/// the tensor is then positive definite) and each entry of J equal to its Schur complement's.
pub(super) fn derived<F: Field>(
    body: &ConvexBody<F>,
    t: &TensorText,
    limits: ParseLimits,
) -> Result<(), Rejection> {
    let names = ["Ixx", "Ixy", "Ixz", "Iyy", "Iyz", "Izz"];
    let texts = [&t.0, &t.1, &t.2, &t.3, &t.4, &t.5];
    let mut v = Vec::with_capacity(6);
    for (name, text) in names.iter().zip(texts) {
        v.push(number::<F>(&format!("body.inertia_tensor.{name}"), text, limits)?);
    }
    let fail = |f| Rejection::at(Code::InertiaNotDerived, "body.inertia_tensor", KindDetail::Tensor(f));
    if !v[5].is_positive() {
        return Err(fail(TensorFailure::ZzNotPositive(to_canonical(&v[5]))));
    }
    let (h, b) = ([[&v[0], &v[1]], [&v[1], &v[3]]], [&v[2], &v[4]]);
    for (entry, (r, c)) in ["Jxx", "Jxy", "Jyy"].into_iter().zip([(0, 0), (0, 1), (1, 1)]) {
        let schur = b[r].times(b[c]).over(&v[5]).map(|x| h[r][c].minus(&x));
        let written = &body.inertia()[r][c];
        if schur.as_ref() != Some(written) {
            let derived = schur.map_or_else(String::new, |x| to_canonical(&x));
            return Err(fail(TensorFailure::Differs { entry, written: to_canonical(written), derived }));
        }
    }
    Ok(())
}

/// Why rule K0 fails.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TensorFailure {
    /// Izz <= 0 (as written): no rigid body has this tensor.
    ZzNotPositive(String),
    /// An entry of J (`Jxx`, `Jxy` or `Jyy`) differs from J_eff's (as written, as derived).
    Differs {
        /// The entry.
        entry: &'static str,
        /// J's entry, canonical text.
        written: String,
        /// J_eff's entry, canonical text.
        derived: String,
    },
}

/// The rules after the body, K0 and the range of γ: the count, K1 to K4.
fn rest<F: Field>(
    cert: &ConvexCertificate,
    body: ConvexBody<F>,
    limits: ParseLimits,
) -> Result<Accepted, Rejection> {
    let n = body.n();
    if cert.cones.len() != n {
        return Err(Rejection::at(
            Code::WrongArity,
            "cones",
            KindDetail::ConeCount(cert.cones.len(), n, false),
        ));
    }
    let mut bits = 0;
    let mut cones = Vec::with_capacity(n);
    for (i, written) in cert.cones.iter().enumerate() {
        let gens = generators::read::<F>(
            written,
            &["omega_x", "omega_y", "v"],
            |g| format!("cones[{i}][{g}]"),
            limits,
        )?;
        bits = bits.max(gens.max_denominator_bits);
        cones.push(cone::<F>(i, &gens)?);
    }
    in_time(limits, "building the cones")?;
    let mut pieces = Vec::with_capacity(n * (n - 1));
    for (i, k) in cones.iter().enumerate() {
        for (j, target) in cones.iter().enumerate().filter(|(j, _)| *j != i) {
            pieces.push(transition(&body, i, j, k, target, limits)?);
        }
    }
    if cert.claim >= Claim::CcOrPccFromAllDown {
        for (i, k) in cones.iter().enumerate() {
            all_down(&body, i, k)?;
        }
    }
    if cert.claim >= Claim::CompleteChatterFromAllDown {
        (0..n).try_for_each(|k| pcc(&body, k))?;
    }
    Ok(accepted(cert, &body, &cones, pieces, bits))
}

/// The file's rules before the body: the header, the sizes of the body and of the cones.
fn prelude(cert: &ConvexCertificate, limits: ParseLimits) -> Result<(), Rejection> {
    expect(&cert.format, cert.version, Kind::Family)?;
    cone_claim(cert.claim)?;
    let ConvexBodyText::ConvexPolygon { contacts, .. } = &cert.body;
    if contacts.len() > MAX_CONTACTS {
        let detail = KindDetail::Convex(ConvexBodyError::TooManyContacts(contacts.len()));
        return Err(Rejection::at(Code::UnsupportedBody, "body.contacts", detail));
    }
    for (i, c) in cert.cones.iter().enumerate() {
        at_most("max-generators", c.len(), limits.max_generators, KindCounted::ConeGenerators(i).into())?;
    }
    if cert.cones.len() > MAX_CONTACTS {
        return Err(Rejection::at(
            Code::WrongArity,
            "cones",
            KindDetail::ConeCount(cert.cones.len(), MAX_CONTACTS, true),
        ));
    }
    total(cert.numbers(), limits)
}

/// The body: canonical numbers, and the assumptions of docs/model.md §11.1 checked by
/// [`ConvexBody::new`].
pub(super) fn body<F: Field>(
    text: &ConvexBodyText,
    g: F,
    gamma_path: &str,
    limits: ParseLimits,
) -> Result<ConvexBody<F>, Rejection> {
    let ConvexBodyText::ConvexPolygon { contacts, inertia, .. } = text;
    let mut points = Vec::with_capacity(contacts.len());
    for (k, (x, y)) in contacts.iter().enumerate() {
        in_time(limits, "reading the contacts")?;
        let x = number::<F>(&format!("body.contacts[{k}].x"), x, limits)?;
        let y = number::<F>(&format!("body.contacts[{k}].y"), y, limits)?;
        points.push([x, y]);
    }
    let jxx = number::<F>("body.inertia.Jxx", &inertia.0, limits)?;
    let jxy = number::<F>("body.inertia.Jxy", &inertia.1, limits)?;
    let jyy = number::<F>("body.inertia.Jyy", &inertia.2, limits)?;
    ConvexBody::new(points, [[jxx, jxy.clone()], [jxy, jyy]], g).map_err(|e| {
        let (code, path) = match &e {
            ConvexBodyError::GammaOutOfRange => (Code::ParameterOutOfRange, gamma_path),
            ConvexBodyError::InertiaNotSymmetric | ConvexBodyError::InertiaNotPositiveDefinite => {
                (Code::UnsupportedBody, "body.inertia")
            }
            _ => (Code::UnsupportedBody, "body.contacts"),
        };
        Rejection::at(code, path, KindDetail::Convex(e))
    })
}

/// K1 for cone i: every generator has v < 0, and the generators span a 3-D cone.
pub(super) fn cone<F: Field>(i: usize, gens: &Generators<'_, F::Int>) -> Result<Cone<F::Int>, Rejection> {
    let vectors: Vec<Vec3<F::Int>> =
        gens.vectors.iter().map(|g| [g[0].clone(), g[1].clone(), g[2].clone()]).collect();
    if let Some(g) = vectors.iter().position(|g| !g[2].is_negative()) {
        let detail = Detail::NotBelow(gens.written[g].0.clone());
        return Err(Rejection::new(
            Code::GeneratorNotBelow,
            KindLocus::ConvexGenerator { cone: i, index: g },
            detail,
        ));
    }
    let hull_idx = hull(&vectors);
    if hull_idx.len() < 3 {
        let detail = Detail::Degenerate(vectors.len(), hull_idx.len(), 3);
        return Err(Rejection::new(Code::DegenerateCone, KindLocus::ConvexCone { cone: i }, detail));
    }
    let polygon = ConvexPolygon::new(hull_idx.iter().map(|&g| vectors[g].clone()).collect());
    Ok(Cone { hull: hull_idx, polygon })
}

/// K2 for the pair (i, j): I_j(K_i ∩ C_ij) ⊆ K_j; the number of vertices checked.
fn transition<F: Field>(
    body: &ConvexBody<F>,
    i: usize,
    j: usize,
    k: &Cone<F::Int>,
    target: &Cone<F::Int>,
    limits: ParseLimits,
) -> Result<usize, Rejection> {
    let Some(covectors) = body.next_contact_cone(i as i64, j as i64) else {
        return Err(Rejection::new(Code::Internal, Locus::Nowhere, KindInternal::NoCone(i, j)));
    };
    let piece = covectors.iter().fold(k.polygon.vertices.clone(), |p, l| clip(&p, &int_vec(l)));
    let map = int_mat(&body.impact(j as i64));
    for (v, p) in piece.iter().enumerate() {
        in_time(limits, "checking effective invariance (rule K2)")?;
        let locus =
            |outside| KindLocus::Transition { from: i, to: j, vertex: v, outside, gamma: None }.into();
        let t = Target { point: p, locus: &locus, codes: R2, n: body.n() };
        check_image::<F>(target, &mat_vec(&map, p), &t)?;
    }
    Ok(piece.len())
}

/// K3 for cone i: I_i(D) ⊆ K_i, on the generators -m_{k,k+1} of D.
pub(super) fn all_down<F: Field>(body: &ConvexBody<F>, i: usize, k: &Cone<F::Int>) -> Result<(), Rejection> {
    let map = int_mat(&body.impact(i as i64));
    for (m, g) in body.all_down_generators().iter().enumerate() {
        let g = int_vec(g);
        let locus = |outside| KindLocus::ConvexAllDown { cone: i, generator: m, outside, gamma: None }.into();
        let t = Target { point: &g, locus: &locus, codes: R3, n: body.n() };
        check_image::<F>(k, &mat_vec(&map, &g), &t)?;
    }
    Ok(())
}

/// K4 for the adjacent pair (k, k+1): non-real roots and constant term q < 1 (Lemma 11.5(2)).
pub(super) fn pcc<F: Field>(body: &ConvexBody<F>, k: usize) -> Result<(), Rejection> {
    let pair = (k, (k + 1) % body.n());
    let quad = body.pair_pcc_quadratic(k as i64).map_err(|at_one| {
        let detail = KindInternal::NotARootAtPair(to_canonical(&at_one), pair);
        Rejection::new(Code::Internal, Locus::Nowhere, detail)
    })?;
    match quad.exclusion() {
        PccExclusion::Excluded => Ok(()),
        why => {
            let pqd = Box::new([&quad.p, &quad.q, &quad.discriminant].map(to_canonical));
            Err(Rejection::new(
                Code::PccNotExcluded,
                KindLocus::PccPair { pair: k, gamma: None },
                Detail::Pcc(body.n(), pqd, why),
            ))
        }
    }
}

/// What the accepted certificate reports: redundant generators counted through the cones in
/// order, the pieces, and whether every K_i contains I_i(0, 0, -1).
fn accepted<F: Field>(
    cert: &ConvexCertificate,
    body: &ConvexBody<F>,
    cones: &[Cone<F::Int>],
    pieces: Vec<usize>,
    bits: u64,
) -> Accepted {
    let down = [F::Int::zero(), F::Int::zero(), F::Int::from_i64(-1)];
    let contains = |(i, k): (usize, &Cone<F::Int>)| {
        let t = mat_vec(&int_mat(&body.impact(i as i64)), &down);
        t[2].is_negative() && k.polygon.contains(&t)
    };
    let (mut redundant, mut offset) = (Vec::new(), 0);
    for (k, written) in cones.iter().zip(&cert.cones) {
        let mut extreme = vec![false; written.len()];
        k.hull.iter().for_each(|&g| extreme[g] = true);
        redundant.extend((0..written.len()).filter(|&g| !extreme[g]).map(|g| offset + g));
        offset += written.len();
    }
    let mut a = Accepted::cone(cert.claim, body.n(), offset, pieces);
    a.redundant = redundant;
    a.max_denominator_bits = bits;
    a.contains_translation = cones.iter().enumerate().all(contains);
    a
}
