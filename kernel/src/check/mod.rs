//! The trusted kernel: re-checks a certificate with exact arithmetic over any backend.
//!
//! It depends only on the exact scalars (`crate::exact`) and the certificate schema
//! (`crate::certificate`), recomputes every map and cone from the body, and never uses floating
//! point. Each acceptance rule is documented in docs/certificate-format.md. All geometric tests
//! run on integer-scaled homogeneous vectors: effective invariance is a property of cones, so
//! scaling a generator, a covector or a map by a positive number changes nothing.

mod rod;

use crate::certificate::{Body, Certificate, Claim, Code, FORMAT, Rejection, VERSION};
use crate::exact::{
    Field, Int, ParseLimits, Ring, parse_canonical, parse_canonical_parts, scale_to_ints, to_canonical,
};
use crate::geometry::{ConvexPolygon, clip, hull};
use crate::model::linalg::{Mat3, Vec3, is_zero, mat_vec};
use crate::model::{self, BodyError};

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
    /// For `CompleteChatterFromAllDown`: (p, q, discriminant) of the PCC quadratic, canonical text.
    pub pcc: Option<[String; 3]>,
    /// Whether K contains I_0(-1, -1, -1), the velocity after the first impact of a pure downward
    /// translation (informational: without some such velocity the claim is vacuous).
    pub contains_translation: bool,
}

/// A number's text for messages, abbreviated when long.
fn quote(s: &str) -> String {
    match s.char_indices().nth(24) {
        Some((i, _)) => format!("\"{}...\" ({} characters)", &s[..i], s.chars().count()),
        None => format!("{s:?}"),
    }
}

fn number<F: Field>(field: &str, s: &str, limits: ParseLimits) -> Result<F, Rejection> {
    parse_canonical(s, limits)
        .map_err(|e| Rejection::new(Code::BadNumber, format!("field `{field}`: {}: {e}", quote(s))))
}

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
fn show<F: Field>(q: &Vec3<F::Int>) -> String {
    let w = F::from_int(&q[2].negated());
    let c = |i: usize| to_canonical(&F::from_int(&q[i]).over(&w).expect("v < 0"));
    format!("({}, {})", c(0), c(1))
}

/// Checks that the image `img` of a point lies in K (or is 0); `what` describes the point.
fn check_image<F: Field>(
    k: &ConvexPolygon<F::Int>,
    hull_idx: &[usize],
    img: &Vec3<F::Int>,
    what: &dyn Fn() -> String,
    code_outside: Code,
    code_above: Code,
) -> Result<(), Rejection> {
    if is_zero(img) {
        return Ok(());
    }
    if !img[2].is_negative() {
        let v = to_canonical(&F::from_int(&img[2]));
        return Err(Rejection::new(
            code_above,
            format!("{} to a velocity with v >= 0 (v is {v} times a positive factor)", what()),
        ));
    }
    if k.contains(img) {
        return Ok(());
    }
    let (e, d) = k.first_violated(img).expect("a point outside K violates some edge");
    let m = hull_idx.len();
    // Amount: orient2d(A, B, Q) of the projected points = facet.q / (w_A w_B w_q).
    let (a, b) = (&k.vertices[e], &k.vertices[(e + 1) % m]);
    let w = a[2].times(&b[2]).times(&img[2]).negated();
    let by = F::from_int(&d).over(&F::from_int(&w)).expect("w > 0");
    Err(Rejection::new(
        code_outside,
        format!(
            "{} to {} outside edge {e} of K (generators {} -> {}) by {}",
            what(),
            show::<F>(img),
            hull_idx[e],
            hull_idx[(e + 1) % m],
            to_canonical(&by)
        ),
    ))
}

/// The parsed body: a polygon (n >= 3) or the rod (n = 2).
enum Parsed<F> {
    Polygon(model::Polygon<F>),
    Rod(model::Rod<F>),
}

fn body_error(e: BodyError) -> Rejection {
    match e {
        BodyError::UnsupportedN(_) => Rejection::new(Code::UnsupportedBody, format!("field `body.n`: {e}")),
        BodyError::KappaNotPositive => {
            Rejection::new(Code::ParameterOutOfRange, format!("field `body.kappa`: {e}"))
        }
        BodyError::GammaOutOfRange => {
            Rejection::new(Code::ParameterOutOfRange, format!("field `body.gamma`: {e}"))
        }
    }
}

/// The generators as integer vectors (positive multiples of the given ones): coordinate i of
/// (p_0/q_0, ..., p_k/q_k) becomes p_i prod_{j != i} q_j. Also the largest denominator in bits.
/// Integer generators and the largest denominator in bits.
type Generators<Z> = (Vec<Vec<Z>>, u64);

fn parse_generators<F: Field>(
    cert: &Certificate,
    names: &[&str],
    limits: ParseLimits,
) -> Result<Generators<F::Int>, Rejection> {
    let mut gens = Vec::with_capacity(cert.cone.len());
    let mut bits = 0;
    for (i, g) in cert.cone.iter().enumerate() {
        if g.0.len() != names.len() {
            let msg = format!(
                "field `cone[{i}]`: expected {} coordinates ({}), found {}",
                names.len(),
                names.join(", "),
                g.0.len()
            );
            return Err(Rejection::new(Code::WrongArity, msg));
        }
        let mut parts = Vec::with_capacity(names.len());
        for (c, name) in g.0.iter().zip(names) {
            let (p, q) = parse_canonical_parts::<F::Int>(c, limits).map_err(|e| {
                Rejection::new(Code::BadNumber, format!("field `cone[{i}].{name}`: {}: {e}", quote(c)))
            })?;
            bits = bits.max(q.bit_length());
            parts.push((p, q));
        }
        let scaled = (0..parts.len())
            .map(|k| {
                parts
                    .iter()
                    .enumerate()
                    .fold(F::Int::one(), |acc, (j, (p, q))| acc.times(if j == k { p } else { q }))
            })
            .collect();
        gens.push(scaled);
    }
    Ok((gens, bits))
}

/// The rejection for a generator with v >= 0.
fn not_below(cert: &Certificate, i: usize) -> Rejection {
    let msg = format!("generator cone[{i}] = ({}) has v >= 0", cert.cone[i].0.join(", "));
    Rejection::new(Code::GeneratorNotBelow, msg)
}

/// Checks a certificate exactly over the field `F`. The first failing check is reported.
pub fn check<F: Field>(cert: &Certificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    if cert.format != FORMAT {
        return Err(Rejection::new(Code::WrongFormat, format!("field `format`: expected {FORMAT:?}")));
    }
    if cert.version != VERSION {
        return Err(Rejection::new(
            Code::UnsupportedVersion,
            format!("field `version`: {} is not {VERSION}", cert.version),
        ));
    }
    let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
    let kappa: F = number("body.kappa", kappa, limits)?;
    let gamma: F = number("body.gamma", gamma, limits)?;
    let parsed = if *n == 2 {
        Parsed::Rod(model::Rod::new(kappa, gamma).map_err(body_error)?)
    } else {
        Parsed::Polygon(model::Polygon::new(*n, kappa, gamma).map_err(body_error)?)
    };
    match parsed {
        Parsed::Rod(r) => {
            let (gens, bits) = parse_generators::<F>(cert, &["u0", "u1"], limits)?;
            if let Some(i) = gens.iter().position(|g| !g[0].plus(&g[1]).is_negative()) {
                return Err(not_below(cert, i));
            }
            let gens: Vec<[F::Int; 2]> = gens.into_iter().map(|g| [g[0].clone(), g[1].clone()]).collect();
            rod::check_rod(&r, &gens, cert.claim, bits)
        }
        Parsed::Polygon(body) => {
            let (gens, bits) = parse_generators::<F>(cert, &["u0", "u1", "v"], limits)?;
            if let Some(i) = gens.iter().position(|g| !g[2].is_negative()) {
                return Err(not_below(cert, i));
            }
            let gens: Vec<Vec3<F::Int>> =
                gens.into_iter().map(|g| [g[0].clone(), g[1].clone(), g[2].clone()]).collect();
            check_polygon(&body, &gens, cert.claim, bits)
        }
    }
}

/// The geometric checks R1 (dimension) to R4 for a regular polygon with n >= 3.
fn check_polygon<F: Field>(
    body: &model::Polygon<F>,
    gens: &[Vec3<F::Int>],
    claim: Claim,
    max_denominator_bits: u64,
) -> Result<Accepted, Rejection> {
    let n = body.n() as u64;
    // K: the exact convex hull of the projected generators; it must have an interior.
    let hull_idx = hull(gens);
    if gens.is_empty() {
        return Err(Rejection::new(Code::DegenerateCone, "field `cone` is empty: K must be a 3-D cone"));
    }
    if hull_idx.len() < 3 {
        let msg = format!(
            "the {} generators span only {} distinct extreme ray(s) in a plane or line: K must be a 3-D cone",
            gens.len(),
            hull_idx.len()
        );
        return Err(Rejection::new(Code::DegenerateCone, msg));
    }
    let redundant = (0..gens.len()).filter(|i| !hull_idx.contains(i)).collect();
    let k = ConvexPolygon::new(hull_idx.iter().map(|&i| gens[i].clone()).collect());

    // Condition 2: S_j(K ∩ C_j) ⊆ K, checked on the vertices of each clipped piece.
    let mut pieces = Vec::with_capacity(body.n() - 1);
    for j in 1..body.n() as i64 {
        let s = int_mat(&body.step(j));
        let mut piece = k.vertices.clone();
        for l in body.next_contact_cone(j) {
            piece = clip(&piece, &int_vec(&l));
        }
        for (i, p) in piece.iter().enumerate() {
            let what = || format!("vertex {i} of K∩C_{j}, at {}, maps under S_{j}", show::<F>(p));
            check_image::<F>(&k, &hull_idx, &mat_vec(&s, p), &what, Code::ImageOutside, Code::ImageNotBelow)?;
        }
        pieces.push(piece.len());
    }

    // Stronger claims: I_0(D) ⊆ K, checked on the generators -m_{k,k+1} of D.
    if claim >= Claim::CcOrPccFromAllDown {
        let i0 = int_mat(&body.impact(0));
        for (m, g) in body.all_down_generators().iter().enumerate() {
            let g = int_vec(g);
            let what = || {
                format!("I_0 maps the all-down generator -m_({m},{}) = {}", (m + 1) % body.n(), show::<F>(&g))
            };
            let img = mat_vec(&i0, &g);
            check_image::<F>(&k, &hull_idx, &img, &what, Code::InitialOutside, Code::InitialOutside)?;
        }
    }

    // Strongest claim: PCC excluded by the quadratic factor of S_{n-1} S_1.
    let mut pcc = None;
    if claim >= Claim::CompleteChatterFromAllDown {
        let quad = model::pcc_quadratic(body).map_err(|at_one| {
            Rejection::new(
                Code::Internal,
                format!("model error: det(I - S_(n-1) S_1) = {} is not 0", to_canonical(&at_one)),
            )
        })?;
        let text = [&quad.p, &quad.q, &quad.discriminant].map(to_canonical);
        if !quad.excludes_pcc() {
            let msg = format!(
                "PCC is not excluded: det(tI - S_{} S_1) = (t - 1)(t^2 + ({}) t + ({})) with discriminant {} (needs < 0) and constant term {} (needs < 1)",
                body.n() - 1,
                text[0],
                text[1],
                text[2],
                text[1]
            );
            return Err(Rejection::new(Code::PccNotExcluded, msg));
        }
        pcc = Some(text);
    }

    let down = [F::Int::from_i64(-1), F::Int::from_i64(-1), F::Int::from_i64(-1)];
    let translation = mat_vec(&int_mat(&body.impact(0)), &down);
    let contains_translation = translation[2].is_negative() && k.contains(&translation);
    let generators = gens.len();
    Ok(Accepted { claim, n, generators, redundant, pieces, max_denominator_bits, pcc, contains_translation })
}
