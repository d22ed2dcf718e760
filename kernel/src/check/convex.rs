//! The acceptance rules of a `ConvexPolygon` certificate (format version 4): a general convex
//! body and a family of cones K_0, ..., K_{n-1} (docs/model.md §11.5, docs/certificate-format.md
//! §13, docs/kernel-soundness.md §6). Rules, in the order they are checked:
//!
//! - K1: each K_i is a 3-D cone with every generator in v < 0 (so K_i is pointed and lies in
//!   v <= 0: condition 1 of the Definition in docs/model.md §11.5);
//! - K2: I_j(K_i ∩ C_ij) ⊆ K_j for all i != j (condition 2; C_ij by Lemma 11.3, clipped exactly
//!   as rule R2 clips K by C_j);
//! - K3 (claims from all-down starts): I_i(D) ⊆ K_i for every i, on the generators -m_{k,k+1}
//!   of D (Lemma 11.2(4));
//! - K4 (`CompleteChatterFromAllDown`): PCC excluded for every adjacent pair (k, k+1) by the pair
//!   quadratic of I_k I_{k+1} (Lemma 11.5; non-adjacent pairs need nothing, Lemma 11.5(1)).
//!
//! Like rules R1-R4, every geometric test runs on integer-scaled homogeneous vectors: the cones
//! do not change under positive scaling, so generators, covectors and maps are scaled to
//! integers and containment is a sign of an integer polynomial.

use super::polygon::{Cone, Target, check_image, int_mat, int_vec};
use super::{Accepted, in_time, number, number_error, show};
use crate::certificate::{
    Claim, Code, ConvexBodyText, ConvexCertificate, FORMAT, Locus, Rejection, convex::CONVEX_VERSION,
};
use crate::exact::{Field, Int, ParseLimits, Ring, parse_canonical_parts, to_canonical};
use crate::geometry::{ConvexPolygon, clip, hull};
use crate::model::PccExclusion;
use crate::model::linalg::{Vec3, mat_vec};
use crate::model::{ConvexBody, ConvexBodyError, MAX_CONTACTS};

/// The names of the coordinates (omega_x, omega_y, v), for paths and messages.
const NAMES: [&str; 3] = ["omega_x", "omega_y", "v"];

/// Checks a version-4 certificate exactly over the field `F`. The first failing check is
/// reported.
pub fn check_convex<F: Field>(cert: &ConvexCertificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    header(cert)?;
    size(cert, limits)?;
    let body = body::<F>(cert, limits)?;
    claim_range(&body, cert.claim)?;
    let n = body.n();
    if cert.cones.len() != n {
        let msg = format!("expected one cone per contact ({n}), found {}", cert.cones.len());
        return Err(Rejection::at_field(Code::WrongArity, "cones", msg));
    }
    let mut bits = 0;
    let mut cones = Vec::with_capacity(n);
    for i in 0..n {
        let gens = generators::<F>(cert, i, limits, &mut bits)?;
        cones.push(cone::<F>(cert, i, gens)?);
    }
    in_time(limits, "building the cones")?;
    let mut pieces = Vec::with_capacity(n * (n - 1));
    for (i, k) in cones.iter().enumerate() {
        for (j, target) in cones.iter().enumerate() {
            if i != j {
                pieces.push(transition(&body, i, j, k, target, limits)?);
            }
        }
    }
    if cert.claim >= Claim::CcOrPccFromAllDown {
        for (i, k) in cones.iter().enumerate() {
            all_down(&body, i, k)?;
        }
    }
    if cert.claim >= Claim::CompleteChatterFromAllDown {
        for k in 0..n {
            pcc(&body, k)?;
        }
    }
    let down = [F::Int::zero(), F::Int::zero(), F::Int::from_i64(-1)];
    let contains_translation = cones.iter().enumerate().all(|(i, k)| {
        let t = mat_vec(&int_mat(&body.impact(i as i64)), &down);
        t[2].is_negative() && k.polygon.contains(&t)
    });
    let mut redundant = Vec::new();
    let mut offset = 0;
    for (i, k) in cones.iter().enumerate() {
        let len = cert.cones[i].len();
        let mut extreme = vec![false; len];
        k.hull.iter().for_each(|&g| extreme[g] = true);
        redundant.extend((0..len).filter(|&g| !extreme[g]).map(|g| offset + g));
        offset += len;
    }
    Ok(Accepted {
        claim: cert.claim,
        n: n as u64,
        generators: offset,
        redundant,
        pieces,
        max_denominator_bits: bits,
        pcc: None,
        contains_translation,
        region: None,
        pcc_boxes: None,
        orbit_boxes: None,
    })
}

/// `format` and `version` (the reader has checked them already; a certificate built in memory
/// has not).
fn header(cert: &ConvexCertificate) -> Result<(), Rejection> {
    if cert.format != FORMAT {
        return Err(Rejection::at_field(Code::WrongFormat, "format", format!("expected {FORMAT:?}")));
    }
    if cert.version != CONVEX_VERSION {
        let msg = format!("{} is not {CONVEX_VERSION}, the version of ConvexPolygon bodies", cert.version);
        return Err(Rejection::at_field(Code::UnsupportedVersion, "version", msg));
    }
    super::not_orbit_claim(cert.claim)
}

/// The limits before any arithmetic: at most [`MAX_CONTACTS`] contacts (else the body is
/// unsupported), at most max-generators generators per cone, at most max-total-digits characters
/// of numbers in the file.
fn size(cert: &ConvexCertificate, limits: ParseLimits) -> Result<(), Rejection> {
    let ConvexBodyText::ConvexPolygon { contacts, .. } = &cert.body;
    if contacts.len() > MAX_CONTACTS {
        let msg = format!("{} contacts, more than {MAX_CONTACTS}", contacts.len());
        return Err(Rejection::at_field(Code::UnsupportedBody, "body.contacts", msg));
    }
    let too_large = |name: &str, msg: String| {
        Rejection::new(
            Code::TooLarge,
            Locus::Limit { name: name.into() },
            format!("{msg}: no verdict on the content"),
        )
    };
    if let Some((i, c)) = cert.cones.iter().enumerate().find(|(_, c)| c.len() > limits.max_generators) {
        let msg = format!(
            "cone {i} has {} generators, more than the limit max-generators = {}",
            c.len(),
            limits.max_generators
        );
        return Err(too_large("max-generators", msg));
    }
    if cert.cones.len() > MAX_CONTACTS {
        let msg = format!("{} cones, more than {MAX_CONTACTS} (one per contact)", cert.cones.len());
        return Err(Rejection::at_field(Code::WrongArity, "cones", msg));
    }
    let total: usize = cert.numbers().map(str::len).sum();
    if total > limits.max_total_digits {
        let msg = format!(
            "{total} characters of numbers, more than the limit max-total-digits = {}",
            limits.max_total_digits
        );
        return Err(too_large("max-total-digits", msg));
    }
    Ok(())
}

/// The body: canonical numbers, and the assumptions (A1), (A2), J symmetric positive definite
/// and 0 <= gamma <= 1 of docs/model.md §11.1, checked by [`ConvexBody::new`].
fn body<F: Field>(cert: &ConvexCertificate, limits: ParseLimits) -> Result<ConvexBody<F>, Rejection> {
    let ConvexBodyText::ConvexPolygon { contacts, inertia, gamma } = &cert.body;
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
    let g = number::<F>("body.gamma", gamma, limits)?;
    let j = [[jxx, jxy.clone()], [jxy, jyy]];
    ConvexBody::new(points, j, g).map_err(|e| {
        let (code, path) = match &e {
            ConvexBodyError::GammaOutOfRange => (Code::ParameterOutOfRange, "body.gamma"),
            ConvexBodyError::InertiaNotSymmetric | ConvexBodyError::InertiaNotPositiveDefinite => {
                (Code::UnsupportedBody, "body.inertia")
            }
            _ => (Code::UnsupportedBody, "body.contacts"),
        };
        Rejection::at_field(code, path, format!("{e} (docs/model.md §11.1)"))
    })
}

/// The claims about drops need 0 < gamma < 1, as for regular polygons (rule "range of γ").
fn claim_range<F: Field>(body: &ConvexBody<F>, claim: Claim) -> Result<(), Rejection> {
    let g = body.gamma();
    if claim > Claim::EffectivelyInvariant && (g.is_zero() || *g == F::one()) {
        let msg = format!(
            "gamma = {} is outside 0 < gamma < 1, which the claim {} needs (Theorem 11.4 assumes it); only EffectivelyInvariant holds for gamma = 0 or 1",
            show::number(g),
            claim.name()
        );
        return Err(Rejection::at_field(Code::ParameterOutOfRange, "body.gamma", msg));
    }
    Ok(())
}

/// The generators of K_i as integer vectors (positive multiples), tracking the largest
/// denominator in bits.
fn generators<F: Field>(
    cert: &ConvexCertificate,
    i: usize,
    limits: ParseLimits,
    bits: &mut u64,
) -> Result<Vec<Vec3<F::Int>>, Rejection> {
    let mut out = Vec::with_capacity(cert.cones[i].len());
    for (g, gen_) in cert.cones[i].iter().enumerate() {
        in_time(limits, "reading the generators")?;
        if gen_.0.len() != 3 {
            let msg = format!("expected 3 coordinates ({}), found {}", NAMES.join(", "), gen_.0.len());
            return Err(Rejection::at_field(Code::WrongArity, format!("cones[{i}][{g}]"), msg));
        }
        let mut parts = Vec::with_capacity(3);
        for (c, name) in gen_.0.iter().zip(NAMES) {
            let (p, q) = parse_canonical_parts::<F::Int>(c, limits)
                .map_err(|e| number_error(format!("cones[{i}][{g}].{name}"), c, e))?;
            *bits = (*bits).max(q.bit_length());
            parts.push((p, q));
        }
        let v = super::common_denominator(&parts);
        out.push([v[0].clone(), v[1].clone(), v[2].clone()]);
    }
    Ok(out)
}

/// K1 for cone i: every generator has v < 0, and the generators span a 3-D cone. A cone whose
/// generators all have v < 0 is pointed and lies in v <= 0.
fn cone<F: Field>(
    cert: &ConvexCertificate,
    i: usize,
    gens: Vec<Vec3<F::Int>>,
) -> Result<Cone<F::Int>, Rejection> {
    if let Some(g) = gens.iter().position(|g| !g[2].is_negative()) {
        let msg = format!("generator cones[{i}][{g}] = ({}) has v >= 0", show::tuple(&cert.cones[i][g].0));
        return Err(Rejection::new(
            Code::GeneratorNotBelow,
            Locus::ConvexGenerator { cone: i, index: g },
            msg,
        ));
    }
    let hull_idx = hull(&gens);
    if hull_idx.len() < 3 {
        let msg = format!(
            "the {} generators of K_{i} span only {} distinct extreme ray(s) in a plane or line: K_{i} must be a 3-D cone",
            gens.len(),
            hull_idx.len()
        );
        return Err(Rejection::new(Code::DegenerateCone, Locus::ConvexCone { cone: i }, msg));
    }
    let polygon = ConvexPolygon::new(hull_idx.iter().map(|&g| gens[g].clone()).collect());
    Ok(Cone { hull: hull_idx, polygon })
}

/// The projection (omega_x, omega_y)/(-v) of a homogeneous point with v < 0, as text.
fn shown<F: Field>(q: &Vec3<F::Int>) -> String {
    super::scalar::point::<F>(&q[..2], &q[2].negated())
}

/// K2 for the pair (i, j): I_j(K_i ∩ C_ij) ⊆ K_j, on the vertices of K_i clipped by the four
/// covectors of C_ij (Lemma 11.3, (11.3)). Returns the number of vertices checked.
fn transition<F: Field>(
    body: &ConvexBody<F>,
    i: usize,
    j: usize,
    k: &Cone<F::Int>,
    target: &Cone<F::Int>,
    limits: ParseLimits,
) -> Result<usize, Rejection> {
    let Some(covectors) = body.next_contact_cone(i as i64, j as i64) else {
        let msg = format!("model error: no cone C_({i},{j})");
        return Err(Rejection::new(Code::Internal, Locus::Nowhere, msg));
    };
    let mut piece = k.polygon.vertices.clone();
    for l in &covectors {
        piece = clip(&piece, &int_vec(l));
    }
    let map = int_mat(&body.impact(j as i64));
    for (v, p) in piece.iter().enumerate() {
        in_time(limits, "checking effective invariance (rule K2)")?;
        let what =
            || format!("vertex {v} of K_{i}∩C_({i},{j}), at {}, maps under I_{j} into K_{j}", shown::<F>(p));
        let locus = |outside| Locus::Transition { from: i, to: j, vertex: v, outside };
        let t =
            Target { locus: &locus, what: &what, outside: Code::ImageOutside, above: Code::ImageNotBelow };
        check_image::<F>(target, &mat_vec(&map, p), &t)?;
    }
    Ok(piece.len())
}

/// K3 for cone i: I_i(D) ⊆ K_i, on the generators -m_{k,k+1} of D.
fn all_down<F: Field>(body: &ConvexBody<F>, i: usize, k: &Cone<F::Int>) -> Result<(), Rejection> {
    let map = int_mat(&body.impact(i as i64));
    let n = body.n();
    for (m, g) in body.all_down_generators().iter().enumerate() {
        let g = int_vec(g);
        let what = || {
            let m1 = (m + 1) % n;
            format!("I_{i} maps the all-down generator -m_({m},{m1}) = {} into K_{i}", shown::<F>(&g))
        };
        let locus = |outside| Locus::ConvexAllDown { cone: i, generator: m, outside };
        let t =
            Target { locus: &locus, what: &what, outside: Code::InitialOutside, above: Code::InitialOutside };
        check_image::<F>(k, &mat_vec(&map, &g), &t)?;
    }
    Ok(())
}

/// K4 for the adjacent pair (k, k+1): the quadratic factor of det(tI - I_k I_{k+1}) has non-real
/// roots and constant term q < 1 (Lemma 11.5(2); the kernel keeps §5's conservative q < 1).
fn pcc<F: Field>(body: &ConvexBody<F>, k: usize) -> Result<(), Rejection> {
    let k1 = (k + 1) % body.n();
    let quad = body.pair_pcc_quadratic(k as i64).map_err(|at_one| {
        let msg = format!(
            "model error: det(I - I_{k} I_{k1}) = {} is not 0",
            show::abbreviate(&to_canonical(&at_one))
        );
        Rejection::new(Code::Internal, Locus::Nowhere, msg)
    })?;
    let why = match quad.exclusion() {
        PccExclusion::Excluded => return Ok(()),
        PccExclusion::RealRoots => "the discriminant is >= 0 (real roots)",
        PccExclusion::ModulusNotBelowOne => "the roots are complex but of modulus sqrt(q) >= 1",
    };
    let text = [&quad.p, &quad.q, &quad.discriminant].map(|x| show::abbreviate(&to_canonical(x)));
    let msg = format!(
        "PCC of contacts {k} and {k1} is not excluded: det(tI - I_{k} I_{k1}) = (t - 1)(t^2 + ({}) t + ({})) with discriminant {} (needs < 0) and constant term {} (needs < 1): {why}",
        text[0], text[1], text[2], text[1]
    );
    Err(Rejection::new(Code::PccNotExcluded, Locus::PccPair { pair: k }, msg))
}
