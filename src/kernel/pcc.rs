//! PCC exclusion (the paper's Lemma on PCC): S_{n-1} S_1 fixes m_{0,1}, so its characteristic
//! polynomial is (t - 1)(t^2 + p t + q). PCC of two adjacent contacts is impossible when the
//! quadratic has non-real roots; we also require their modulus sqrt(q) < 1, so that 1 is the
//! dominant eigenvalue as the Lemma's proof assumes.

use super::impact::Body;
use super::linalg::{char_poly, mat_mul};
use crate::exact::OrderedField;

/// The quadratic factor t^2 + p t + q of det(t I - S_{n-1} S_1), with its discriminant.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PccQuadratic<F> {
    pub p: F,
    pub q: F,
    pub discriminant: F,
}

impl<F: OrderedField> PccQuadratic<F> {
    /// Whether the Lemma excludes PCC: complex roots of modulus < 1.
    pub fn excludes_pcc(&self) -> bool {
        self.discriminant.is_negative() && self.q < F::one()
    }
}

/// Factors det(t I - S_{n-1} S_1) = (t - 1)(t^2 + p t + q). Returns `Err` with the polynomial's
/// value at t = 1 if 1 is not a root (impossible for a correct model).
pub fn pcc_quadratic<F: OrderedField>(body: &Body<F>) -> Result<PccQuadratic<F>, F> {
    let last = body.n as i64 - 1;
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
