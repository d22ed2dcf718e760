//! Validation of a general convex body (docs/model.md §11.1): 3 to 64 contacts forming a strictly
//! convex counter-clockwise polygon with the origin (the centre of mass's projection) strictly
//! inside, a symmetric positive definite J, and 0 <= gamma <= 1. Every check is a sign of an
//! exact polynomial in the data; nothing panics on bad input.

use super::super::rod::{Mat2, Vec2};
use crate::exact::OrderedField;

/// The largest number of contacts a [`super::ConvexBody`] may have.
pub const MAX_CONTACTS: usize = 64;

/// Why contacts, an inertia tensor and a restitution do not define a [`super::ConvexBody`].
/// Contacts are numbered from 0 in the order given; edge k joins contact k to contact k + 1
/// (mod n).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ConvexBodyError {
    /// Fewer than three contacts.
    TooFewContacts(usize),
    /// More than [`MAX_CONTACTS`] contacts.
    TooManyContacts(usize),
    /// Contact `contact + 1` repeats contact `contact`.
    RepeatedContact {
        /// The first of the two equal contacts.
        contact: usize,
    },
    /// Every turn is clockwise: the contacts are listed clockwise.
    Clockwise,
    /// Contacts `contact - 1`, `contact`, `contact + 1` are collinear (not strictly convex).
    CollinearContacts {
        /// The middle contact.
        contact: usize,
    },
    /// The polygon turns clockwise at `contact` (a reflex corner: not convex).
    NotConvex {
        /// The contact where the polygon turns the wrong way.
        contact: usize,
    },
    /// Every turn is counter-clockwise but the polygon winds `turns` > 1 times (a star).
    NotSimple {
        /// How many times the edge directions turn around.
        turns: usize,
    },
    /// The origin (centre of mass) lies on edge `edge` (or is a contact).
    OriginOnEdge {
        /// The edge through the origin.
        edge: usize,
    },
    /// The origin lies outside the polygon, beyond edge `edge`.
    OriginOutside {
        /// An edge with the origin on its outer side.
        edge: usize,
    },
    /// J_xy != J_yx.
    InertiaNotSymmetric,
    /// J is not positive definite (J_xx <= 0 or det J <= 0).
    InertiaNotPositiveDefinite,
    /// gamma outside [0, 1].
    GammaOutOfRange,
}

/// (b - a) x (c - b): positive when a, b, c turn counter-clockwise.
fn turn<F: OrderedField>(a: &Vec2<F>, b: &Vec2<F>, c: &Vec2<F>) -> F {
    let (d1, d2) = (sub(b, a), sub(c, b));
    cross(&d1, &d2)
}

fn sub<F: OrderedField>(a: &Vec2<F>, b: &Vec2<F>) -> Vec2<F> {
    [a[0].minus(&b[0]), a[1].minus(&b[1])]
}

/// a_x b_y - a_y b_x.
fn cross<F: OrderedField>(a: &Vec2<F>, b: &Vec2<F>) -> F {
    a[0].times(&b[1]).minus(&a[1].times(&b[0]))
}

/// Checks that `pts` (3 to [`MAX_CONTACTS`] points) is a strictly convex polygon listed
/// counter-clockwise, wherever the origin is. Used by [`super::ConvexBody::new`], and by callers
/// that shift a polygon to its centroid afterwards.
pub fn check_convex_polygon<F: OrderedField>(pts: &[Vec2<F>]) -> Result<(), ConvexBodyError> {
    let n = pts.len();
    if n < 3 {
        return Err(ConvexBodyError::TooFewContacts(n));
    }
    if n > MAX_CONTACTS {
        return Err(ConvexBodyError::TooManyContacts(n));
    }
    if let Some(k) = (0..n).find(|&k| pts[k] == pts[(k + 1) % n]) {
        return Err(ConvexBodyError::RepeatedContact { contact: k });
    }
    let turns: Vec<F> = (0..n).map(|k| turn(&pts[(k + n - 1) % n], &pts[k], &pts[(k + 1) % n])).collect();
    if turns.iter().all(F::is_negative) {
        return Err(ConvexBodyError::Clockwise);
    }
    if let Some(k) = turns.iter().position(F::is_zero) {
        return Err(ConvexBodyError::CollinearContacts { contact: k });
    }
    if let Some(k) = turns.iter().position(F::is_negative) {
        return Err(ConvexBodyError::NotConvex { contact: k });
    }
    match winding(pts) {
        1 => Ok(()),
        turns => Err(ConvexBodyError::NotSimple { turns }),
    }
}

/// How many times the edge directions d_k = r_{k+1} - r_k wind around, given that each turn is
/// counter-clockwise by less than pi: the number of upward crossings of the positive x-axis
/// (d_k below it, d_{k+1} on or above it; such a crossing is on the positive side because
/// d_k x d_{k+1} > 0).
fn winding<F: OrderedField>(pts: &[Vec2<F>]) -> usize {
    let n = pts.len();
    let d: Vec<Vec2<F>> = (0..n).map(|k| sub(&pts[(k + 1) % n], &pts[k])).collect();
    (0..n).filter(|&k| d[k][1].is_negative() && !d[(k + 1) % n][1].is_negative()).count()
}

/// Checks that the origin lies strictly inside a convex counter-clockwise polygon: strictly left
/// of every edge.
fn check_origin_inside<F: OrderedField>(pts: &[Vec2<F>]) -> Result<(), ConvexBodyError> {
    let n = pts.len();
    for k in 0..n {
        let (a, b) = (&pts[k], &pts[(k + 1) % n]);
        let side = cross(a, b);
        if side.is_zero() {
            // On the edge's line: on the segment iff a . b <= 0 (a or b may be the origin).
            let along = a[0].times(&b[0]).plus(&a[1].times(&b[1]));
            if !along.is_positive() {
                return Err(ConvexBodyError::OriginOnEdge { edge: k });
            }
            return Err(ConvexBodyError::OriginOutside { edge: k });
        }
        if side.is_negative() {
            return Err(ConvexBodyError::OriginOutside { edge: k });
        }
    }
    Ok(())
}

/// J^{-1} of a symmetric positive definite J, after checking it.
pub(super) fn inverse_inertia<F: OrderedField>(j: &Mat2<F>) -> Result<Mat2<F>, ConvexBodyError> {
    if j[0][1] != j[1][0] {
        return Err(ConvexBodyError::InertiaNotSymmetric);
    }
    let det = j[0][0].times(&j[1][1]).minus(&j[0][1].times(&j[1][0]));
    if !j[0][0].is_positive() || !det.is_positive() {
        return Err(ConvexBodyError::InertiaNotPositiveDefinite);
    }
    let e = |x: &F| x.over(&det).ok_or(ConvexBodyError::InertiaNotPositiveDefinite);
    Ok([[e(&j[1][1])?, e(&j[0][1].negated())?], [e(&j[1][0].negated())?, e(&j[0][0])?]])
}

/// Every check of docs/model.md §11.1, contacts first, then J, then gamma.
pub(super) fn check_body<F: OrderedField>(
    contacts: &[Vec2<F>],
    inertia: &Mat2<F>,
    gamma: &F,
) -> Result<(), ConvexBodyError> {
    check_convex_polygon(contacts)?;
    check_origin_inside(contacts)?;
    inverse_inertia(inertia)?;
    if gamma.is_negative() || *gamma > F::one() {
        return Err(ConvexBodyError::GammaOutOfRange);
    }
    Ok(())
}
