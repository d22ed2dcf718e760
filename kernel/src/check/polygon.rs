//! The acceptance rules R1 (dimension) to R4 for a regular polygon, n >= 3
//! (docs/certificate-format.md §5).

use super::in_time;
use super::show;
use super::{Accepted, Generators};
use crate::certificate::{Boundary, Claim, Code, Locus, Rejection};
use crate::exact::{Field, ParseLimits, Ring, scale_to_ints, to_canonical};
use crate::geometry::{ConvexPolygon, clip, hull};
use crate::model::linalg::{Mat3, Vec3, is_zero, mat_vec};
use crate::model::{PccExclusion, Polygon, pcc_quadratic};

/// A positive integer multiple of a rational matrix.
fn int_mat<F: Field>(m: &Mat3<F>) -> Mat3<F::Int> {
    let flat: Vec<F> = m.iter().flatten().cloned().collect();
    let z = scale_to_ints(&flat);
    std::array::from_fn(|r| std::array::from_fn(|c| z[3 * r + c].clone()))
}

/// A positive integer multiple of a rational vector.
fn int_vec<F: Field>(v: &Vec3<F>) -> Vec3<F::Int> {
    let z = scale_to_ints(v);
    std::array::from_fn(|i| z[i].clone())
}

/// The projection (u0, u1)/(-v) of a homogeneous point with v < 0, as text.
fn shown<F: Field>(q: &Vec3<F::Int>) -> String {
    show::point::<F>(&q[..2], &q[2].negated())
}

/// K: its extreme generators (indices into `cone`, counter-clockwise) and the polygon.
struct Cone<Z> {
    hull: Vec<usize>,
    polygon: ConvexPolygon<Z>,
}

/// Where an image is checked, and how a failure is reported.
struct Target<'a> {
    /// Builds the locus from the violated boundary (`None`: the image has v >= 0).
    locus: &'a dyn Fn(Option<Boundary>) -> Locus,
    /// Describes the point and its map, e.g. "vertex 0 of K∩C_1, at (0, -1), maps under S_1".
    what: &'a dyn Fn() -> String,
    outside: Code,
    above: Code,
}

/// Checks that `img` lies in K (or is 0).
fn check_image<F: Field>(k: &Cone<F::Int>, img: &Vec3<F::Int>, t: &Target<'_>) -> Result<(), Rejection> {
    if is_zero(img) {
        return Ok(());
    }
    if !img[2].is_negative() {
        let v = show::int::<F>(&img[2]);
        let msg = format!("{} to a velocity with v >= 0 (v is {v} times a positive factor)", (t.what)());
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
    let by = F::from_int(&d).over(&F::from_int(&w)).expect("w > 0");
    let edge = Boundary::Edge { index: e, from: k.hull[e], to: k.hull[(e + 1) % m] };
    let msg = format!(
        "{} to {} outside edge {e} of K (generators {} -> {}) by {}",
        (t.what)(),
        shown::<F>(img),
        k.hull[e],
        k.hull[(e + 1) % m],
        show::number(&by)
    );
    Err(Rejection::new(t.outside, (t.locus)(Some(edge)), msg))
}

/// R1: generators below v = 0, and K a 3-D cone.
fn cone<F: Field>(gens: &Generators<'_, F::Int>) -> Result<Cone<F::Int>, Rejection> {
    let vectors: Vec<Vec3<F::Int>> =
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

/// R2: S_j(K ∩ C_j) ⊆ K for j = 1..n-1, on the vertices of each clipped piece. Returns the
/// number of vertices of each piece.
fn invariance<F: Field>(
    body: &Polygon<F>,
    k: &Cone<F::Int>,
    limits: ParseLimits,
) -> Result<Vec<usize>, Rejection> {
    let mut pieces = Vec::with_capacity(body.n() - 1);
    for j in 1..body.n() {
        let s = int_mat(&body.step(j as i64));
        let mut piece = k.polygon.vertices.clone();
        for l in body.next_contact_cone(j as i64) {
            piece = clip(&piece, &int_vec(&l));
        }
        for (i, p) in piece.iter().enumerate() {
            in_time(limits, "checking effective invariance (rule R2)")?;
            let what = || format!("vertex {i} of K∩C_{j}, at {}, maps under S_{j}", shown::<F>(p));
            let locus = |outside| Locus::Piece { piece: j, vertex: i, outside };
            let t = Target {
                locus: &locus,
                what: &what,
                outside: Code::ImageOutside,
                above: Code::ImageNotBelow,
            };
            check_image::<F>(k, &mat_vec(&s, p), &t)?;
        }
        pieces.push(piece.len());
    }
    Ok(pieces)
}

/// R3: I_0(D) ⊆ K, on the generators -m_{k,k+1} of D.
fn all_down<F: Field>(body: &Polygon<F>, k: &Cone<F::Int>) -> Result<(), Rejection> {
    let i0 = int_mat(&body.impact(0));
    for (m, g) in body.all_down_generators().iter().enumerate() {
        let g = int_vec(g);
        let what = || {
            format!("I_0 maps the all-down generator -m_({m},{}) = {}", (m + 1) % body.n(), shown::<F>(&g))
        };
        let locus = |outside| Locus::AllDown { generator: m, outside };
        let t =
            Target { locus: &locus, what: &what, outside: Code::InitialOutside, above: Code::InitialOutside };
        check_image::<F>(k, &mat_vec(&i0, &g), &t)?;
    }
    Ok(())
}

/// R4: PCC excluded by the quadratic factor of S_{n-1} S_1; its (p, q, discriminant) as text.
fn pcc<F: Field>(body: &Polygon<F>) -> Result<[String; 3], Rejection> {
    let quad = pcc_quadratic(body).map_err(|at_one| {
        let msg = format!("model error: det(I - S_(n-1) S_1) = {} is not 0", show::number(&at_one));
        Rejection::new(Code::Internal, Locus::Nowhere, msg)
    })?;
    let full = [&quad.p, &quad.q, &quad.discriminant].map(to_canonical);
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

/// Rules R1 (dimension) to R4 for a regular polygon.
pub(super) fn check<F: Field>(
    body: &Polygon<F>,
    gens: &Generators<'_, F::Int>,
    claim: Claim,
    limits: ParseLimits,
) -> Result<Accepted, Rejection> {
    let k = cone::<F>(gens)?;
    in_time(limits, "building K")?;
    let pieces = invariance(body, &k, limits)?;
    if claim >= Claim::CcOrPccFromAllDown {
        all_down(body, &k)?;
    }
    let pcc = if claim >= Claim::CompleteChatterFromAllDown { Some(pcc(body)?) } else { None };
    let down = [F::Int::from_i64(-1), F::Int::from_i64(-1), F::Int::from_i64(-1)];
    let translation = mat_vec(&int_mat(&body.impact(0)), &down);
    let contains_translation = translation[2].is_negative() && k.polygon.contains(&translation);
    let mut extreme = vec![false; gens.vectors.len()];
    k.hull.iter().for_each(|&i| extreme[i] = true);
    Ok(Accepted {
        claim,
        n: body.n() as u64,
        generators: gens.vectors.len(),
        redundant: (0..gens.vectors.len()).filter(|&i| !extreme[i]).collect(),
        pieces,
        max_denominator_bits: gens.max_denominator_bits,
        pcc,
        contains_translation,
    })
}
