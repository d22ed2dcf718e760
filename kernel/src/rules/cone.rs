//! Cone certificates of a regular polygon, n >= 3 (docs/certificate-format.md §5; why they imply
//! their claims: docs/kernel-soundness.md §2). Rules, in the order they are checked:
//!
//! - the file ([`prelude`], every cone certificate): the header, a cone claim (`unknown-variant`
//!   for `CompleteChatterFromSet`), `max-generators` and `max-total-digits` (`too-large`), and
//!   no `time_to_rest_bound` but on the rod at a point (`time-to-rest-not-shown`);
//! - range of γ: the claims about drops need 0 < γ < 1 (`parameter-out-of-range`);
//! - R1: every generator has v < 0 (`generator-not-below`) and K has an interior
//!   (`degenerate-cone`);
//! - R2: S_j(K ∩ C_j) ⊆ K for j = 1..n-1, on the vertices of each piece K ∩ C_j: each image is 0,
//!   or has v < 0 (`image-not-below`) and lies in K (`image-outside`);
//! - R3 (`CcOrPccFromAllDown` and stronger): I_0(D) ⊆ K, on the generators -m_{k,k+1} of D
//!   (`initial-outside`);
//! - R4 (`CompleteChatterFromAllDown`): the quadratic factor t^2 + p t + q of
//!   det(tI - S_{n-1} S_1) has p^2 - 4q < 0 and q < 1 (`pcc-not-excluded`).
//!
//! Before them: the header, the limits and the numbers ([`crate::syntax`]), the body
//! ([`crate::model::polygon`]). The rules are written once over [`Scalar`]: integer-scaled
//! homogeneous vectors for the rationals, the elements themselves for a number field.

use super::body::{body_error, gamma_range};
use super::generators::{self, Generators};
use super::outcome::Accepted;
use crate::exact::{Field, ParseLimits, Ring};
use crate::geometry::{ConvexPolygon, Scalar, clip, hull, projected};
use crate::model::linalg::{Mat3, Vec3, is_zero, mat_vec};
use crate::model::pcc::{PccExclusion, pcc_quadratic};
use crate::model::polygon::Polygon;
use crate::reject::{
    Boundary, Code, Counted, Detail, ImageFailure, Internal, Locus, Rejection, TimeToRestFailure,
};
use crate::syntax::cone::{Body, Certificate, Claim, Param};
use crate::syntax::numbers::{at_most, in_time, number, total};
use crate::syntax::{Kind, expect};

/// The file's rules before the body, for every cone certificate: the header (read from a file
/// already, not when built in memory), a cone claim (`unknown-variant` for the orbit claim),
/// `max-generators`, `max-total-digits`, and a bound B on the time to rest only on the rod at a
/// point (rule T1 covers nothing else, docs/time-to-rest.md §2).
pub fn prelude(cert: &Certificate, limits: ParseLimits) -> Result<(), Rejection> {
    expect(&cert.format, cert.version, Kind::Cone)?;
    cone_claim(cert.claim)?;
    at_most("max-generators", cert.cone.len(), limits.max_generators, Counted::Generators)?;
    total(cert.numbers(), limits)?;
    let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
    match &cert.time_to_rest_bound {
        Some(b) if !(*n == 2 && matches!((kappa, gamma), (Param::Point(_), Param::Point(_)))) => {
            let detail = Detail::TimeToRest(TimeToRestFailure::NotRod, b.clone());
            Err(Rejection::at(Code::TimeToRestNotShown, "time_to_rest_bound", detail))
        }
        _ => Ok(()),
    }
}

/// The claim of a cone (or family) certificate is not the orbit claim `CompleteChatterFromSet`.
pub fn cone_claim(claim: Claim) -> Result<(), Rejection> {
    if claim == Claim::CompleteChatterFromSet {
        return Err(Rejection::at(Code::UnknownVariant, "claim", Detail::OrbitClaim));
    }
    Ok(())
}

/// Rules R1 to R4 for a point certificate with rational cos(2 pi/n) (n = 3, 4, 6), at the
/// parameters (kappa, gamma) as written.
pub fn check_point<F: Field>(
    cert: &Certificate,
    [k, g]: [&str; 2],
    limits: ParseLimits,
) -> Result<Accepted, Rejection> {
    let Body::RegularPolygon { n, .. } = &cert.body;
    let kappa: F = number("body.kappa", k, limits)?;
    let gamma: F = number("body.gamma", g, limits)?;
    let body = Polygon::new(*n, kappa, gamma).map_err(|e| body_error(e, "body.kappa", "body.gamma"))?;
    gamma_range(body.gamma(), "body.gamma", cert.claim)?;
    let gens = generators::read::<F>(&cert.cone, &["u0", "u1", "v"], |i| format!("cone[{i}]"), limits)?;
    check(&body, &gens, cert.claim, limits)
}

/// Rules R1 to R4 on the generators as vectors over `E`'s ring.
pub fn check<E: Scalar>(
    body: &Polygon<E>,
    gens: &Generators<'_, E::R>,
    claim: Claim,
    limits: ParseLimits,
) -> Result<Accepted, Rejection> {
    let k = cone::<E>(gens)?;
    in_time(limits, "building K")?;
    let pieces = pieces(body, &k);
    invariance(body, &pieces, &k, limits)?;
    if claim >= Claim::CcOrPccFromAllDown {
        all_down(body, &k)?;
    }
    let mut accepted = accepted(&[body], &k, gens, claim, &pieces);
    if claim >= Claim::CompleteChatterFromAllDown {
        accepted.pcc = Some(pcc(body)?);
    }
    Ok(accepted)
}

/// K: its extreme generators (indices into the cone, counter-clockwise) and the polygon.
pub struct Cone<R> {
    /// The extreme generators.
    pub hull: Vec<usize>,
    /// The convex polygon over them.
    pub polygon: ConvexPolygon<R>,
}

/// R1: every generator below v = 0, and K a 3-D cone.
pub fn cone<E: Scalar>(gens: &Generators<'_, E::R>) -> Result<Cone<E::R>, Rejection> {
    let vectors: Vec<Vec3<E::R>> =
        gens.vectors.iter().map(|g| [g[0].clone(), g[1].clone(), g[2].clone()]).collect();
    if let Some(i) = vectors.iter().position(|g| !g[2].is_negative()) {
        let detail = Detail::NotBelow(gens.written[i].0.clone());
        return Err(Rejection::new(Code::GeneratorNotBelow, Locus::Generator { index: i }, detail));
    }
    let hull_idx = hull(&vectors);
    if hull_idx.len() < 3 {
        let detail = Detail::Degenerate(vectors.len(), hull_idx.len(), 3);
        return Err(Rejection::new(Code::DegenerateCone, Locus::Cone, detail));
    }
    let polygon = ConvexPolygon::new(hull_idx.iter().map(|&i| vectors[i].clone()).collect());
    Ok(Cone { hull: hull_idx, polygon })
}

/// The pieces K ∩ C_j, j = 1..n-1: K clipped by the four covectors of C_j.
pub fn pieces<E: Scalar>(body: &Polygon<E>, k: &Cone<E::R>) -> Vec<Vec<Vec3<E::R>>> {
    let clipped = |j: usize| {
        let covectors = body.next_contact_cone(j as i64);
        covectors.iter().fold(k.polygon.vertices.clone(), |piece, l| clip(&piece, &int_vec(l)))
    };
    (1..body.n()).map(clipped).collect()
}

/// R2: S_j(K ∩ C_j) ⊆ K for j = 1..n-1, on the vertices of each piece.
pub fn invariance<E: Scalar>(
    body: &Polygon<E>,
    pieces: &[Vec<Vec3<E::R>>],
    k: &Cone<E::R>,
    limits: ParseLimits,
) -> Result<(), Rejection> {
    for (j, piece) in (1..).zip(pieces) {
        let s = int_mat(&body.step(j as i64));
        for (i, p) in piece.iter().enumerate() {
            in_time(limits, "checking effective invariance (rule R2)")?;
            let locus = |outside| Locus::Piece { piece: j, vertex: i, outside, corner: None };
            let t = Target { point: p, locus: &locus, codes: R2, n: body.n() };
            check_image::<E>(k, &mat_vec(&s, p), &t)?;
        }
    }
    Ok(())
}

/// R3: I_0(D) ⊆ K, on the generators -m_{k,k+1} of D.
pub fn all_down<E: Scalar>(body: &Polygon<E>, k: &Cone<E::R>) -> Result<(), Rejection> {
    let i0 = int_mat(&body.impact(0));
    for (m, g) in body.all_down_generators().iter().enumerate() {
        let g = int_vec(g);
        let locus = |outside| Locus::AllDown { generator: m, outside, corner: None };
        let t = Target { point: &g, locus: &locus, codes: R3, n: body.n() };
        check_image::<E>(k, &mat_vec(&i0, &g), &t)?;
    }
    Ok(())
}

/// R4: PCC excluded by the quadratic factor of det(tI - S_{n-1} S_1); (p, q, discriminant).
pub fn pcc<E: Scalar>(body: &Polygon<E>) -> Result<[String; 3], Rejection> {
    let quad = pcc_quadratic(body).map_err(|at_one| {
        let detail = Detail::Internal(Internal::NotARoot(at_one.text()));
        Rejection::new(Code::Internal, Locus::Nowhere, detail)
    })?;
    let pqd = [&quad.p, &quad.q, &quad.discriminant].map(Scalar::text);
    match quad.exclusion() {
        PccExclusion::Excluded => Ok(pqd),
        why => {
            Err(Rejection::new(Code::PccNotExcluded, Locus::Pcc, Detail::Pcc(body.n(), Box::new(pqd), why)))
        }
    }
}

/// What the accepted certificate reports: the extreme generators, the pieces, and whether K
/// contains I_0(-1, -1, -1) (at every body of a box).
pub fn accepted<E: Scalar>(
    bodies: &[&Polygon<E>],
    k: &Cone<E::R>,
    gens: &Generators<'_, E::R>,
    claim: Claim,
    pieces: &[Vec<Vec3<E::R>>],
) -> Accepted {
    let down = [E::R::from_i64(-1), E::R::from_i64(-1), E::R::from_i64(-1)];
    let contains = |b: &&Polygon<E>| {
        let t = mat_vec(&int_mat(&b.impact(0)), &down);
        t[2].is_negative() && k.polygon.contains(&t)
    };
    let mut a =
        Accepted::cone(claim, bodies[0].n(), gens.vectors.len(), pieces.iter().map(Vec::len).collect());
    let mut extreme = vec![false; gens.vectors.len()];
    k.hull.iter().for_each(|&i| extreme[i] = true);
    a.redundant = (0..gens.vectors.len()).filter(|&i| !extreme[i]).collect();
    a.max_denominator_bits = gens.max_denominator_bits;
    a.contains_translation = bodies.iter().all(contains);
    a
}

/// The codes of rule R2 (K2) for an image outside K and for one with v >= 0.
pub const R2: [Code; 2] = [Code::ImageOutside, Code::ImageNotBelow];
/// The code of rule R3 (K3) for an image outside K or with v >= 0.
pub const R3: [Code; 2] = [Code::InitialOutside; 2];

/// Where an image is checked and how a failure is located: the point mapped, the locus from the
/// violated boundary (`None`: the image has v >= 0), the codes (outside, v >= 0), n (a box's
/// rules add the corner to a rejection: `rules/boxes.rs`).
pub struct Target<'a, R> {
    /// The point mapped.
    pub point: &'a Vec3<R>,
    /// The locus, from the boundary violated.
    pub locus: &'a dyn Fn(Option<Boundary>) -> Locus,
    /// The codes when the image is outside and when its v is >= 0.
    pub codes: [Code; 2],
    /// n of the body.
    pub n: usize,
}

/// Checks that `img` is 0, or has v < 0 and lies in K (f_e . img >= 0 for every edge e).
pub fn check_image<E: Scalar>(
    k: &Cone<E::R>,
    img: &Vec3<E::R>,
    t: &Target<'_, E::R>,
) -> Result<(), Rejection> {
    if is_zero(img) || (img[2].is_negative() && k.polygon.contains(img)) {
        return Ok(());
    }
    let mut failure = ImageFailure {
        n: t.n,
        point: projected::<E>(&t.point[..2], &t.point[2].negated()),
        image: None,
        v_zero: img[2].is_zero(),
        by: None,
        corner: None,
    };
    if !img[2].is_negative() {
        return Err(Rejection::new(t.codes[1], (t.locus)(None), Detail::Image(Box::new(failure))));
    }
    // A point with v < 0 outside the convex polygon K violates some edge.
    let Some((e, d)) = k.polygon.first_violated(img) else {
        return Err(Rejection::new(Code::Internal, Locus::Nowhere, Detail::Internal(Internal::NoEdge)));
    };
    let m = k.hull.len();
    // The amount: orient2d(A, B, Q) of the projected points = facet . q / (w_A w_B w_q).
    let (a, b) = (&k.polygon.vertices[e], &k.polygon.vertices[(e + 1) % m]);
    let w = a[2].times(&b[2]).times(&img[2]).negated();
    failure.image = Some(projected::<E>(&img[..2], &img[2].negated()));
    failure.by = E::lift(&d).over(&E::lift(&w)).map(|x| x.text());
    let edge = Boundary::Edge { index: e, from: k.hull[e], to: k.hull[(e + 1) % m] };
    Err(Rejection::new(t.codes[0], (t.locus)(Some(edge)), Detail::Image(Box::new(failure))))
}

/// A positive multiple of a matrix, in the ring of scaled coordinates (integers for Q).
pub fn int_mat<E: Scalar>(m: &Mat3<E>) -> Mat3<E::R> {
    let flat: Vec<E> = m.iter().flatten().cloned().collect();
    let z = E::scaled(&flat);
    std::array::from_fn(|r| std::array::from_fn(|c| z[3 * r + c].clone()))
}

/// A positive multiple of a vector, in the ring of scaled coordinates.
pub fn int_vec<E: Scalar>(v: &Vec3<E>) -> Vec3<E::R> {
    let z = E::scaled(v);
    std::array::from_fn(|i| z[i].clone())
}
