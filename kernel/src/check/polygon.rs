//! The acceptance rules R1 (dimension) to R4 for a regular polygon, n >= 3
//! (docs/certificate-format.md §5).

use super::in_time;
use super::region::{Corner, Region};
use super::scalar::{self, Scalar};
use super::show;
use super::{Accepted, Generators};
use crate::bivariate::{NotNegative, negative_on};
use crate::certificate::{Boundary, Claim, Code, Locus, Rejection};
use crate::exact::{Field, ParseLimits, Ring, to_canonical};
use crate::geometry::{ConvexPolygon, clip, hull};
use crate::model::linalg::{Mat3, Vec3, is_zero, mat_vec};
use crate::model::{PccExclusion, Polygon, Shape, pcc_polynomials, pcc_quadratic};

/// A positive multiple of a matrix, in the ring of scaled coordinates (integers for Q).
pub(super) fn int_mat<E: Scalar>(m: &Mat3<E>) -> Mat3<E::R> {
    let flat: Vec<E> = m.iter().flatten().cloned().collect();
    let z = E::scaled(&flat);
    std::array::from_fn(|r| std::array::from_fn(|c| z[3 * r + c].clone()))
}

/// A positive multiple of a vector, in the ring of scaled coordinates.
pub(super) fn int_vec<E: Scalar>(v: &Vec3<E>) -> Vec3<E::R> {
    let z = E::scaled(v);
    std::array::from_fn(|i| z[i].clone())
}

/// The projection (u0, u1)/(-v) of a homogeneous point with v < 0, as text.
fn shown<E: Scalar>(q: &Vec3<E::R>) -> String {
    scalar::point::<E>(&q[..2], &q[2].negated())
}

/// K: its extreme generators (indices into `cone`, counter-clockwise) and the polygon.
pub(super) struct Cone<Z> {
    pub(super) hull: Vec<usize>,
    pub(super) polygon: ConvexPolygon<Z>,
}

/// Where an image is checked, and how a failure is reported.
pub(super) struct Target<'a> {
    /// Builds the locus from the violated boundary (`None`: the image has v >= 0).
    pub(super) locus: &'a dyn Fn(Option<Boundary>) -> Locus,
    /// Describes the point and its map, e.g. "vertex 0 of K∩C_1, at (0, -1), maps under S_1".
    pub(super) what: &'a dyn Fn() -> String,
    pub(super) outside: Code,
    pub(super) above: Code,
}

/// Checks that `img` lies in K (or is 0).
pub(super) fn check_image<E: Scalar>(
    k: &Cone<E::R>,
    img: &Vec3<E::R>,
    t: &Target<'_>,
) -> Result<(), Rejection> {
    if is_zero(img) {
        return Ok(());
    }
    if !img[2].is_negative() {
        // Homogeneous coordinates are defined up to a positive factor: only the sign of v is told.
        let v = if img[2].is_zero() { "v = 0" } else { "v > 0" };
        let msg =
            format!("{} to a velocity with v >= 0 (here {v}): the centre of mass stops falling", (t.what)());
        return Err(Rejection::new(t.above, (t.locus)(None), msg));
    }
    if k.polygon.contains(img) {
        return Ok(());
    }
    let (e, d) = k.polygon.first_violated(img).expect("a point outside K violates some edge");
    let m = k.hull.len();
    // Amount: orient2d(A, B, Q) of the projected points = facet.q / (w_A w_B w_q).
    let (a, b) = (&k.polygon.vertices[e], &k.polygon.vertices[(e + 1) % m]);
    let w = a[2].times(&b[2]).times(&img[2]).negated();
    let by = E::lift(&d).over(&E::lift(&w)).expect("w > 0");
    let edge = Boundary::Edge { index: e, from: k.hull[e], to: k.hull[(e + 1) % m] };
    let msg = format!(
        "{} to {} outside edge {e} of K (generators {} -> {}) by {}",
        (t.what)(),
        shown::<E>(img),
        k.hull[e],
        k.hull[(e + 1) % m],
        scalar::number(&by)
    );
    Err(Rejection::new(t.outside, (t.locus)(Some(edge)), msg))
}

/// R1: generators below v = 0, and K a 3-D cone.
fn cone<E: Scalar>(gens: &Generators<'_, E::R>) -> Result<Cone<E::R>, Rejection> {
    let vectors: Vec<Vec3<E::R>> =
        gens.vectors.iter().map(|g| [g[0].clone(), g[1].clone(), g[2].clone()]).collect();
    if let Some(i) = vectors.iter().position(|g| !g[2].is_negative()) {
        return Err(gens.not_below(i));
    }
    if vectors.is_empty() {
        let msg = "field `cone` is empty: K must be a 3-D cone";
        return Err(Rejection::new(Code::DegenerateCone, Locus::Cone, msg));
    }
    let hull_idx = hull(&vectors);
    if hull_idx.len() < 3 {
        let msg = format!(
            "the {} generators span only {} distinct extreme ray(s) in a plane or line: K must be a 3-D cone",
            vectors.len(),
            hull_idx.len()
        );
        return Err(Rejection::new(Code::DegenerateCone, Locus::Cone, msg));
    }
    let polygon = ConvexPolygon::new(hull_idx.iter().map(|&i| vectors[i].clone()).collect());
    Ok(Cone { hull: hull_idx, polygon })
}

/// The pieces K ∩ C_j, j = 1..n-1, as the vertices of each clipped polygon. C_j depends only on
/// n, not on kappa or gamma (docs/model.md §4): the pieces are computed from the first corner,
/// and every other corner must give the same covectors (else the model contradicts itself).
fn pieces<E: Scalar>(bodies: &[&Polygon<E>], k: &Cone<E::R>) -> Result<Vec<Vec<Vec3<E::R>>>, Rejection> {
    let first = bodies[0];
    let mut out = Vec::with_capacity(first.n() - 1);
    for j in 1..first.n() as i64 {
        let covectors = first.next_contact_cone(j);
        if bodies.iter().any(|b| b.next_contact_cone(j) != covectors) {
            let msg = format!("model error: C_{j} differs between the corners of the box");
            return Err(Rejection::new(Code::Internal, Locus::Nowhere, msg));
        }
        let mut piece = k.polygon.vertices.clone();
        for l in &covectors {
            piece = clip(&piece, &int_vec(l));
        }
        out.push(piece);
    }
    Ok(out)
}

/// R2 at one corner: S_j(K ∩ C_j) ⊆ K for j = 1..n-1, on the vertices of each piece.
fn invariance<E: Scalar>(
    body: &Polygon<E>,
    corner: &Corner<E>,
    pieces: &[Vec<Vec3<E::R>>],
    k: &Cone<E::R>,
    limits: ParseLimits,
) -> Result<(), Rejection> {
    for (j, piece) in (1..).zip(pieces) {
        let s = int_mat(&body.step(j as i64));
        for (i, p) in piece.iter().enumerate() {
            in_time(limits, "checking effective invariance (rule R2)")?;
            let what =
                || corner.say(format!("vertex {i} of K∩C_{j}, at {}, maps under S_{j}", shown::<E>(p)));
            let locus = |outside| Locus::Piece { piece: j, vertex: i, outside, corner: corner.index };
            let t = Target {
                locus: &locus,
                what: &what,
                outside: Code::ImageOutside,
                above: Code::ImageNotBelow,
            };
            check_image::<E>(k, &mat_vec(&s, p), &t)?;
        }
    }
    Ok(())
}

/// R3 at one corner: I_0(D) ⊆ K, on the generators -m_{k,k+1} of D.
fn all_down<E: Scalar>(body: &Polygon<E>, corner: &Corner<E>, k: &Cone<E::R>) -> Result<(), Rejection> {
    let i0 = int_mat(&body.impact(0));
    for (m, g) in body.all_down_generators().iter().enumerate() {
        let g = int_vec(g);
        let what = || {
            let m1 = (m + 1) % body.n();
            corner.say(format!("I_0 maps the all-down generator -m_({m},{m1}) = {}", shown::<E>(&g)))
        };
        let locus = |outside| Locus::AllDown { generator: m, outside, corner: corner.index };
        let t =
            Target { locus: &locus, what: &what, outside: Code::InitialOutside, above: Code::InitialOutside };
        check_image::<E>(k, &mat_vec(&i0, &g), &t)?;
    }
    Ok(())
}

/// R4: PCC excluded by the quadratic factor of S_{n-1} S_1; its (p, q, discriminant) as text.
fn pcc<E: Scalar>(body: &Polygon<E>) -> Result<[String; 3], Rejection> {
    let quad = pcc_quadratic(body).map_err(|at_one| {
        let msg = format!("model error: det(I - S_(n-1) S_1) = {} is not 0", scalar::number(&at_one));
        Rejection::new(Code::Internal, Locus::Nowhere, msg)
    })?;
    let full = [&quad.p, &quad.q, &quad.discriminant].map(Scalar::text);
    let text = full.clone().map(|t| show::abbreviate(&t));
    let why = match quad.exclusion() {
        PccExclusion::Excluded => return Ok(full),
        PccExclusion::RealRoots => "the discriminant is >= 0 (real roots)",
        PccExclusion::ModulusNotBelowOne => "the roots are complex but of modulus sqrt(q) >= 1",
    };
    let msg = format!(
        "PCC is not excluded: det(tI - S_{} S_1) = (t - 1)(t^2 + ({}) t + ({})) with discriminant {} (needs < 0) and constant term {} (needs < 1): {why}",
        body.n() - 1,
        text[0],
        text[1],
        text[2],
        text[1]
    );
    Err(Rejection::new(Code::PccNotExcluded, Locus::Pcc, msg))
}

/// R4 on a box: the discriminant and q - 1 of the PCC quadratic, as polynomials in (kappa,
/// gamma) times (1 + kappa)^6, are negative on the whole box (Bernstein bounds, subdivided up to
/// [`MAX_PCC_BOXES`] boxes). Returns the number of boxes examined.
pub(super) fn pcc_on_box<F: Field>(body: &Polygon<F>, region: &Region<F>) -> Result<usize, Rejection> {
    let polys = pcc_polynomials(body).map_err(|_| {
        Rejection::new(
            Code::Internal,
            Locus::Nowhere,
            "model error: t = 1 is not a root of det(tI - S_(n-1) S_1)",
        )
    })?;
    let mut boxes = 0;
    for (poly, what) in [(&polys.discriminant, "the discriminant p^2 - 4q"), (&polys.modulus, "q - 1")] {
        boxes += negative_on(poly, &region.rect, MAX_PCC_BOXES).map_err(|e| pcc_box_rejection(e, what))?;
    }
    Ok(boxes)
}

/// Sub-boxes the Bernstein subdivision of rule R4 may examine, per polynomial.
pub const MAX_PCC_BOXES: usize = 20_000;

fn pcc_box_rejection<F: Field>(e: NotNegative<F>, what: &str) -> Rejection {
    let text = |x: &F| to_canonical(x);
    let (kappa, gamma, msg) = match e {
        NotNegative::At(k, g) => {
            let msg = format!(
                "PCC is not excluded on the box: at kappa = {}, gamma = {}, {what} of the PCC quadratic is >= 0",
                show::number(&k),
                show::number(&g)
            );
            ([text(&k), text(&k)], [text(&g), text(&g)], msg)
        }
        NotNegative::Undecided(r) => {
            let msg = format!(
                "PCC exclusion not shown on the box: {what} of the PCC quadratic is not proved negative on kappa in [{}, {}], gamma in [{}, {}] within {MAX_PCC_BOXES} sub-boxes",
                show::number(&r.kappa[0]),
                show::number(&r.kappa[1]),
                show::number(&r.gamma[0]),
                show::number(&r.gamma[1])
            );
            ([text(&r.kappa[0]), text(&r.kappa[1])], [text(&r.gamma[0]), text(&r.gamma[1])], msg)
        }
    };
    let locus = Locus::PccRegion { kappa: Box::new(kappa), gamma: Box::new(gamma) };
    Rejection::new(Code::PccNotExcluded, locus, msg)
}

/// The polygon model at each corner.
fn polygons<E: Scalar>(region: &Region<E>) -> Vec<&Polygon<E>> {
    region
        .corners
        .iter()
        .map(|c| match &c.shape {
            Shape::Polygon(p) => p,
            Shape::Rod(_) => unreachable!("every corner has the same n"),
        })
        .collect()
}

/// Rules R1 (dimension) to R4 for a regular polygon, at a point or on a box.
pub(super) fn check<E: Scalar>(
    region: &Region<E>,
    gens: &Generators<'_, E::R>,
    claim: Claim,
    limits: ParseLimits,
) -> Result<Accepted, Rejection> {
    let bodies = polygons(region);
    let k = cone::<E>(gens)?;
    in_time(limits, "building K")?;
    let pieces = pieces(&bodies, &k)?;
    for (body, corner) in bodies.iter().zip(&region.corners) {
        invariance(body, corner, &pieces, &k, limits)?;
    }
    if claim >= Claim::CcOrPccFromAllDown {
        for (body, corner) in bodies.iter().zip(&region.corners) {
            all_down(body, corner, &k)?;
        }
    }
    let (mut pcc_text, mut pcc_boxes) = (None, None);
    if claim >= Claim::CompleteChatterFromAllDown {
        if region.is_box {
            pcc_boxes = Some(E::pcc_on_box(bodies[0], region)?);
        } else {
            pcc_text = Some(pcc(bodies[0])?);
        }
    }
    let down = [E::R::from_i64(-1), E::R::from_i64(-1), E::R::from_i64(-1)];
    let contains_translation = bodies.iter().all(|b| {
        let t = mat_vec(&int_mat(&b.impact(0)), &down);
        t[2].is_negative() && k.polygon.contains(&t)
    });
    let mut extreme = vec![false; gens.vectors.len()];
    k.hull.iter().for_each(|&i| extreme[i] = true);
    Ok(Accepted {
        claim,
        n: bodies[0].n() as u64,
        generators: gens.vectors.len(),
        redundant: (0..gens.vectors.len()).filter(|&i| !extreme[i]).collect(),
        pieces: pieces.iter().map(Vec::len).collect(),
        max_denominator_bits: gens.max_denominator_bits,
        pcc: pcc_text,
        contains_translation,
        region: None,
        pcc_boxes,
        orbit_boxes: None,
    })
}
