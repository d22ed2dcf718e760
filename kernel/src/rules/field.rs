//! Cone certificates of regular polygons whose cos(2 pi/n) is irrational (feature `field`,
//! n = 5, 7, 8, ..., 64; docs/certificate-format.md §12): the body and the generators are read as
//! elements of Q(cos 2 pi/n), and rules R1 to R4 of [`super::cone`] run unchanged over that field
//! (why this is exact: docs/kernel-soundness.md §2, "Number fields"). Rules before them, in order:
//!
//! - body: 3 <= n <= 64 (`unsupported-body`), numbers (not intervals) for kappa and gamma
//!   (`unsupported-body`);
//! - version: a file with field elements says version 3 or more (`unsupported-version`);
//! - numbers: canonical field elements (`bad-number`), then the body and the range of γ as for
//!   every regular polygon, and three coordinates per generator (`wrong-arity`).

use super::body::{body_error, gamma_range};
use super::cone;
use super::generators::Generators;
use super::outcome::Accepted;
use crate::exact::{Algebraic, AlgebraicInt, CosField, Field, GENERATOR, Int, MAX_N, ParseLimits};
use crate::geometry::Scalar;
use crate::model::polygon::Polygon;
use crate::reject::{Code, Detail, KindDetail, Needs, Rejection};
use crate::syntax::cone::{Body, Certificate, Generator, Param};
use crate::syntax::numbers::{in_time, number_error};
use std::sync::Arc;

/// The oldest format version that may write an element of a number field.
pub const FIELD_VERSION: u64 = 3;

impl<F: Field> Scalar for Algebraic<F> {
    type R = AlgebraicInt<F>;
    fn scaled(xs: &[Self]) -> Vec<AlgebraicInt<F>> {
        Algebraic::scaled(xs)
    }
    fn lift(r: &AlgebraicInt<F>) -> Self {
        r.to_algebraic()
    }
    fn text(&self) -> String {
        self.to_string()
    }
}

/// Rules R1 to R4 over Q(cos 2 pi/n), any n from 3 to 64.
pub fn check<F: Field>(cert: &Certificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
    let Some(field) = CosField::<F>::new(*n) else {
        return Err(Rejection::at(Code::UnsupportedBody, "body.n", KindDetail::Contacts(*n, MAX_N)));
    };
    let (Param::Point(k), Param::Point(g)) = (kappa, gamma) else {
        return Err(Rejection::at(Code::UnsupportedBody, "body", KindDetail::IntervalIrrational(*n)));
    };
    let written = cert.numbers().any(|t| t.contains(GENERATOR));
    if cert.version < FIELD_VERSION && written {
        let detail = Detail::Needs(Needs::FieldElements, cert.version);
        return Err(Rejection::at(Code::UnsupportedVersion, "version", detail));
    }
    let kappa = element(&field, "body.kappa", k, limits)?;
    let gamma = element(&field, "body.gamma", g, limits)?;
    let body = Polygon::with_cosine(*n, field.generator(), kappa, gamma)
        .map_err(|e| body_error(e, "body.kappa", "body.gamma"))?;
    gamma_range(body.gamma(), "body.gamma", cert.claim)?;
    let gens = generators(&field, cert, limits)?;
    cone::check(&body, &gens, cert.claim, limits)
}

/// An element of Q(cos 2 pi/n) at `path`, canonical.
pub fn element<F: Field>(
    field: &Arc<CosField<F>>,
    path: &str,
    s: &str,
    limits: ParseLimits,
) -> Result<Algebraic<F>, Rejection> {
    field.parse(s, limits).map_err(|e| number_error(path.to_string(), s, e))
}

/// The generators of a cone certificate ([`vectors`]).
fn generators<'a, F: Field>(
    field: &Arc<CosField<F>>,
    cert: &'a Certificate,
    limits: ParseLimits,
) -> Result<Generators<'a, AlgebraicInt<F>>, Rejection> {
    vectors(field, &cert.cone, &["u0", "u1", "v"], &|i| format!("cone[{i}]"), limits)
}

/// Vectors of field elements (coordinates `names`, vector i at `path(i)`) as vectors of Z\[2c\],
/// each a positive multiple of the vector as written ([`Algebraic::scaled`]), with the largest
/// denominator of their coefficients in bits.
pub fn vectors<'a, F: Field>(
    field: &Arc<CosField<F>>,
    written: &'a [Generator],
    names: &'static [&'static str],
    path: &dyn Fn(usize) -> String,
    limits: ParseLimits,
) -> Result<Generators<'a, AlgebraicInt<F>>, Rejection> {
    let mut vectors = Vec::with_capacity(written.len());
    let mut bits = 0;
    for (i, g) in written.iter().enumerate() {
        in_time(limits, "reading the generators")?;
        if g.0.len() != names.len() {
            let detail = Detail::Arity(names, g.0.len());
            return Err(Rejection::at(Code::WrongArity, path(i), detail));
        }
        let mut v = Vec::with_capacity(names.len());
        for (c, name) in g.0.iter().zip(names) {
            let x = element(field, &format!("{}.{name}", path(i)), c, limits)?;
            bits = x.coeffs().iter().map(|a| a.denom().bit_length()).fold(bits, u64::max);
            v.push(x);
        }
        vectors.push(Algebraic::scaled(&v));
    }
    Ok(Generators { vectors, max_denominator_bits: bits, written })
}
