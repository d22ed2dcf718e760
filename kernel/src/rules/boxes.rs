//! Box certificates (feature `boxes`, docs/certificate-format.md §9): kappa and gamma may be
//! closed intervals, and one cone proves the claim on the whole box B (why the corners suffice:
//! docs/kernel-soundness.md §2, "Boxes"). Rules, in the order they are checked:
//!
//! - R1 (box): version 2 or more (`unsupported-version`), lo <= hi for each interval
//!   (`parameter-out-of-range`), a valid body at every corner, and 0 < gamma_lo, gamma_hi < 1 for
//!   the claims about drops;
//! - R1-R3 of the rod or of the polygon ([`super::rod`], [`super::cone`]): K once, the pieces
//!   once (every corner must give the same C_j, else `internal`), R2 and R3 at every distinct
//!   corner in the order (lo, lo), (hi, lo), (lo, hi), (hi, hi);
//! - R4 on B (`CompleteChatterFromAllDown`, n >= 3): s^3 (p^2 - 4q) and s^3 (q - 1), s =
//!   (1 + kappa)^2, are negative on B by Bernstein bounds with subdivision, at most
//!   [`MAX_PCC_BOXES`] sub-boxes each (`pcc-not-excluded` at the sub-box that fails).

use super::body::{body_error, gamma_range};
use super::outcome::Accepted;
use super::{cone, generators, rod};
use crate::bivariate::{NotNegative, Rect, negative_on};
use crate::exact::{Field, ParseLimits, to_canonical};
use crate::model::pcc_polynomials::pcc_polynomials;
use crate::model::polygon::Polygon;
use crate::model::rod::Rod;
use crate::reject::{Code, Detail, KindDetail, KindInternal, KindLocus, Locus, Needs, Rejection};
use crate::syntax::cone::{Body, Certificate, Claim, Param};
use crate::syntax::numbers::{in_time, number};

/// Sub-boxes the Bernstein subdivision of rule R4 may examine, per polynomial.
pub const MAX_PCC_BOXES: usize = 20_000;

/// The two polynomials of rule R4 on a box.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PccPolynomial {
    /// s^3 (p^2 - 4q), the discriminant.
    Discriminant,
    /// s^3 (q - 1).
    Modulus,
}

/// Rules R1 to R4 on a box of parameters (n = 2, 3, 4, 6).
pub fn check<F: Field>(cert: &Certificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
    if cert.version < 2 {
        let detail = Detail::Needs(Needs::Intervals, cert.version);
        return Err(Rejection::at(Code::UnsupportedVersion, "version", detail));
    }
    let rect =
        Rect { kappa: bounds::<F>("kappa", kappa, limits)?, gamma: bounds::<F>("gamma", gamma, limits)? };
    let corners = corners(&rect);
    let mut accepted = if *n == 2 {
        rod_box(cert, &rect, &corners, limits)?
    } else {
        polygon_box(cert, *n, &rect, &corners, limits)?
    };
    let text = |r: &[F; 2]| [to_canonical(&r[0]), to_canonical(&r[1])];
    accepted.region = Some([text(&rect.kappa), text(&rect.gamma)]);
    Ok(accepted)
}

/// The bounds [lo, hi] of one parameter (lo = hi for a number), lo <= hi.
pub(super) fn bounds<F: Field>(name: &str, p: &Param, limits: ParseLimits) -> Result<[F; 2], Rejection> {
    let path = format!("body.{name}");
    match p {
        Param::Point(s) => {
            let x: F = number(&path, s, limits)?;
            Ok([x.clone(), x])
        }
        Param::Interval(a, b) => {
            let lo: F = number(&format!("{path}[0]"), a, limits)?;
            let hi: F = number(&format!("{path}[1]"), b, limits)?;
            if lo > hi {
                let detail = KindDetail::EmptyInterval(to_canonical(&lo), to_canonical(&hi));
                return Err(Rejection::at(Code::ParameterOutOfRange, path, detail));
            }
            Ok([lo, hi])
        }
    }
}

/// A corner of a box of parameters (docs/certificate-format.md §9): 0 to 3 for (kappa, gamma) at
/// (lo, lo), (hi, lo), (lo, hi), (hi, hi), with its values as canonical text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Corner {
    /// The corner's number.
    pub index: usize,
    /// (kappa, gamma) there.
    pub at: [String; 2],
}

/// A rejection of rule R2 or R3 at the body of a corner (the point kernel's, which names no
/// corner): the corner's number in the locus, its (kappa, gamma) in the failure.
pub(super) fn at_corner(mut e: Rejection, c: &Corner) -> Rejection {
    if let Locus::Piece { corner, .. } | Locus::AllDown { corner, .. } = &mut e.locus {
        *corner = Some(c.index);
    }
    if let Detail::Image(failure) = e.detail.as_mut() {
        failure.corner = Some(c.at.clone());
    }
    e
}

/// The distinct corners (kappa index, gamma index) in the order (lo, lo), (hi, lo), (lo, hi),
/// (hi, hi), with their numbers and values.
pub(super) fn corners<F: Field>(rect: &Rect<F>) -> Vec<(usize, usize, Corner)> {
    let mut out: Vec<(usize, usize, Corner)> = Vec::with_capacity(4);
    for (gi, ki) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
        let at = [to_canonical(&rect.kappa[ki]), to_canonical(&rect.gamma[gi])];
        if !out.iter().any(|c| c.2.at == at) {
            out.push((ki, gi, Corner { index: ki + 2 * gi, at }));
        }
    }
    out
}

/// The model at each corner, `make` building it from (kappa, gamma).
pub(super) fn bodies<F: Field, B>(
    rect: &Rect<F>,
    corners: &[(usize, usize, Corner)],
    make: impl Fn(F, F) -> Result<B, crate::model::polygon::BodyError>,
) -> Result<Vec<B>, Rejection> {
    let at = |(ki, gi): (usize, usize)| {
        make(rect.kappa[ki].clone(), rect.gamma[gi].clone())
            .map_err(|e| body_error(e, &format!("body.kappa[{ki}]"), &format!("body.gamma[{gi}]")))
    };
    corners.iter().map(|(ki, gi, _)| at((*ki, *gi))).collect()
}

/// Range of γ on the box: at gamma_lo when it is 0, else at gamma_hi.
pub(super) fn gamma_on_box<F: Field>(rect: &Rect<F>, claim: Claim) -> Result<(), Rejection> {
    let [g0, g1] = &rect.gamma;
    if g0.is_zero() {
        gamma_range(g0, "body.gamma[0]", claim)
    } else {
        gamma_range(g1, "body.gamma[1]", claim)
    }
}

/// The rod on a box: R1 once, the piece K ∩ C_1 once, R2 and R3 at every corner.
fn rod_box<F: Field>(
    cert: &Certificate,
    rect: &Rect<F>,
    corners: &[(usize, usize, Corner)],
    limits: ParseLimits,
) -> Result<Accepted, Rejection> {
    let rods = bodies(rect, corners, Rod::new)?;
    gamma_on_box(rect, cert.claim)?;
    let gens = generators::read::<F>(&cert.cone, &["u0", "u1"], |i| format!("cone[{i}]"), limits)?;
    let k = rod::interval::<F>(&gens)?;
    in_time(limits, "building K")?;
    if rods.iter().any(|r| r.next_contact_cone() != rods[0].next_contact_cone()) {
        return Err(Rejection::new(Code::Internal, Locus::Nowhere, KindInternal::CornersDiffer(None)));
    }
    let piece = rod::piece(&rods[0], &k);
    for (r, c) in rods.iter().zip(corners) {
        rod::invariance(r, &k, &piece).map_err(|e| at_corner(e, &c.2))?;
    }
    if cert.claim >= Claim::CcOrPccFromAllDown {
        for (r, c) in rods.iter().zip(corners) {
            rod::all_down(r, &k).map_err(|e| at_corner(e, &c.2))?;
        }
    }
    Ok(rod::accepted(&rods.iter().collect::<Vec<_>>(), &k, &gens, cert.claim, &piece))
}

/// A regular polygon on a box: R1 once, the pieces once, R2 and R3 at every corner, R4 on B.
fn polygon_box<F: Field>(
    cert: &Certificate,
    n: u64,
    rect: &Rect<F>,
    corners: &[(usize, usize, Corner)],
    limits: ParseLimits,
) -> Result<Accepted, Rejection> {
    let polygons = bodies(rect, corners, |k, g| Polygon::new(n, k, g))?;
    gamma_on_box(rect, cert.claim)?;
    let gens = generators::read::<F>(&cert.cone, &["u0", "u1", "v"], |i| format!("cone[{i}]"), limits)?;
    let k = cone::cone::<F>(&gens)?;
    in_time(limits, "building K")?;
    for j in 1..polygons[0].n() as i64 {
        if polygons.iter().any(|b| b.next_contact_cone(j) != polygons[0].next_contact_cone(j)) {
            let detail = KindInternal::CornersDiffer(Some(j as usize));
            return Err(Rejection::new(Code::Internal, Locus::Nowhere, detail));
        }
    }
    let pieces = cone::pieces(&polygons[0], &k);
    for (b, c) in polygons.iter().zip(corners) {
        cone::invariance(b, &pieces, &k, limits).map_err(|e| at_corner(e, &c.2))?;
    }
    if cert.claim >= Claim::CcOrPccFromAllDown {
        for (b, c) in polygons.iter().zip(corners) {
            cone::all_down(b, &k).map_err(|e| at_corner(e, &c.2))?;
        }
    }
    let mut accepted = cone::accepted(&polygons.iter().collect::<Vec<_>>(), &k, &gens, cert.claim, &pieces);
    if cert.claim >= Claim::CompleteChatterFromAllDown {
        accepted.pcc_boxes = Some(pcc_on_box(&polygons[0], rect)?);
    }
    Ok(accepted)
}

/// R4 on the box: both polynomials negative on it; the number of sub-boxes examined.
pub(super) fn pcc_on_box<F: Field>(body: &Polygon<F>, rect: &Rect<F>) -> Result<usize, Rejection> {
    let polys = pcc_polynomials(body)
        .map_err(|_| Rejection::new(Code::Internal, Locus::Nowhere, KindInternal::NotARootOnBox))?;
    let mut boxes = 0;
    for (poly, which) in
        [(&polys.discriminant, PccPolynomial::Discriminant), (&polys.modulus, PccPolynomial::Modulus)]
    {
        boxes += negative_on(poly, rect, MAX_PCC_BOXES).map_err(|e| not_negative(e, which))?;
    }
    Ok(boxes)
}

/// The rejection of rule R4 on a box: the point or the sub-box where the polynomial is not shown
/// negative.
fn not_negative<F: Field>(e: NotNegative<F>, polynomial: PccPolynomial) -> Rejection {
    let text = |a: &F, b: &F| Box::new([to_canonical(a), to_canonical(b)]);
    let (kappa, gamma, at_corner) = match &e {
        NotNegative::At(k, g) => (text(k, k), text(g, g), true),
        NotNegative::Undecided(r) => (text(&r.kappa[0], &r.kappa[1]), text(&r.gamma[0], &r.gamma[1]), false),
    };
    let detail = KindDetail::PccBox(polynomial, at_corner, MAX_PCC_BOXES);
    Rejection::new(Code::PccNotExcluded, KindLocus::PccRegion { kappa, gamma }, detail)
}
