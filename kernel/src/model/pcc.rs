//! PCC exclusion (the paper's Lemma on PCC): S_{n-1} S_1 fixes m_{0,1}, so its characteristic
//! polynomial is (t - 1)(t^2 + p t + q). PCC of two adjacent contacts is impossible when the
//! quadratic has non-real roots; we also require their modulus sqrt(q) < 1, so that 1 is the
//! dominant eigenvalue as the Lemma's proof assumes.

use super::linalg::{char_poly, mat_mul};
use super::polygon::Polygon;
use crate::exact::OrderedField;

/// The quadratic factor t^2 + p t + q of det(t I - S_{n-1} S_1), with its discriminant.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PccQuadratic<F> {
    /// The coefficient of t.
    pub p: F,
    /// The constant term (the product of the two roots).
    pub q: F,
    /// p^2 - 4 q.
    pub discriminant: F,
}

/// Whether the Lemma on PCC applies, and if not, which of its conditions fails.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PccExclusion {
    /// Complex roots of modulus below 1: PCC is excluded.
    Excluded,
    /// The discriminant is >= 0: all eigenvalues are real (the paper's PCC criterion holds).
    RealRoots,
    /// Complex roots, but of modulus sqrt(q) >= 1 (e.g. gamma = 1): 1 is not the dominant
    /// eigenvalue, so the Lemma's proof does not apply.
    ModulusNotBelowOne,
}

impl<F: OrderedField> PccQuadratic<F> {
    /// Which condition of the Lemma holds or fails (the discriminant is tested first).
    pub fn exclusion(&self) -> PccExclusion {
        if !self.discriminant.is_negative() {
            PccExclusion::RealRoots
        } else if self.q >= F::one() {
            PccExclusion::ModulusNotBelowOne
        } else {
            PccExclusion::Excluded
        }
    }
}

/// Factors det(t I - S_{n-1} S_1) = (t - 1)(t^2 + p t + q). Returns `Err` with the polynomial's
/// value at t = 1 if 1 is not a root (impossible for a correct model).
pub fn pcc_quadratic<F: OrderedField>(body: &Polygon<F>) -> Result<PccQuadratic<F>, F> {
    let last = body.n() as i64 - 1;
    let (tr, s, det) = char_poly(&mat_mul(&body.step(last), &body.step(1)));
    // t^3 - tr t^2 + s t - det = (t - 1)(t^2 + p t + q) = t^3 + (p - 1) t^2 + (q - p) t - q.
    let at_one = F::one().minus(&tr).plus(&s).minus(&det);
    if !at_one.is_zero() {
        return Err(at_one);
    }
    let p = F::one().minus(&tr);
    let q = det;
    let four = F::from_i64(4);
    let discriminant = p.times(&p).minus(&four.times(&q));
    Ok(PccQuadratic { p, q, discriminant })
}
