//! Certificates of regular polygons whose cos(2 pi/n) is irrational (n = 5, 7, 8, ...): the body
//! and the generators are read as elements of Q(cos 2 pi/n) (docs/certificate-format.md §12), and
//! rules R1 to R4 run unchanged over that field.

use super::region::{Corner, Region, body_error, claim_range};
use super::{Accepted, Generators, in_time, number_error, polygon};
use crate::bivariate::Rect;
use crate::certificate::{Body, Certificate, Code, Param, Rejection};
use crate::exact::{Algebraic, CosField, Field, Int, MAX_N, ParseLimits};
use crate::model::{Polygon, Shape};
use std::sync::Arc;

/// The oldest format version that may write an element of a number field.
pub const FIELD_VERSION: u64 = 3;

/// Whether n is a regular polygon whose cos(2 pi/n) is irrational (checked in its number field).
pub fn is_irrational(n: u64) -> bool {
    n >= 5 && n != 6
}

/// Rules R1 to R4 over Q(cos 2 pi/n).
pub(super) fn check<F: Field>(cert: &Certificate, limits: ParseLimits) -> Result<Accepted, Rejection> {
    let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
    let field = CosField::<F>::new(*n).ok_or_else(|| {
        let msg = format!("n = {n}: the kernel models regular polygons with 2 to {MAX_N} contacts");
        Rejection::at_field(Code::UnsupportedBody, "body.n", msg)
    })?;
    let (Param::Point(k), Param::Point(g)) = (kappa, gamma) else {
        let msg = format!(
            "parameter intervals (box certificates) are supported only where cos(2 pi/n) is rational (n = 2, 3, 4, 6), not for n = {n}"
        );
        return Err(Rejection::at_field(Code::UnsupportedBody, "body", msg));
    };
    version(cert)?;
    let kappa = element(&field, "body.kappa", k, limits)?;
    let gamma = element(&field, "body.gamma", g, limits)?;
    let body = Polygon::with_cosine(*n, field.generator(), kappa.clone(), gamma.clone())
        .map_err(|e| body_error(e, 0, 0, false))?;
    let corner = Corner { shape: Shape::Polygon(body), label: String::new(), index: None };
    let rect = Rect { kappa: [kappa.clone(), kappa], gamma: [gamma.clone(), gamma] };
    let region = Region { rect, corners: vec![corner], is_box: false };
    claim_range(&region, cert.claim)?;
    let gens = generators(&field, cert, limits)?;
    polygon::check(&region, &gens, cert.claim, limits)
}

/// Field elements (text with the generator c) need version 3.
fn version(cert: &Certificate) -> Result<(), Rejection> {
    let Body::RegularPolygon { kappa, gamma, .. } = &cert.body;
    let texts = kappa.texts().into_iter().chain(gamma.texts());
    let mut all = texts.chain(cert.cone.iter().flat_map(|g| g.0.iter().map(String::as_str)));
    if cert.version < FIELD_VERSION && all.any(|t| t.contains(crate::exact::GENERATOR)) {
        let msg = format!(
            "elements of Q(cos 2 pi/n) need version {FIELD_VERSION}; this file says version {}",
            cert.version
        );
        return Err(Rejection::at_field(Code::UnsupportedVersion, "version", msg));
    }
    Ok(())
}

fn element<F: Field>(
    field: &Arc<CosField<F>>,
    path: &str,
    s: &str,
    limits: ParseLimits,
) -> Result<Algebraic<F>, Rejection> {
    field.parse(s, limits).map_err(|e| number_error(path.to_string(), s, e))
}

/// The generators as vectors of field elements (no scaling: the ring is the field itself), with
/// the largest denominator of their coefficients in bits.
fn generators<'a, F: Field>(
    field: &Arc<CosField<F>>,
    cert: &'a Certificate,
    limits: ParseLimits,
) -> Result<Generators<'a, Algebraic<F>>, Rejection> {
    let names = ["u0", "u1", "v"];
    let mut vectors = Vec::with_capacity(cert.cone.len());
    let mut bits = 0;
    for (i, g) in cert.cone.iter().enumerate() {
        in_time(limits, "reading the generators")?;
        if g.0.len() != names.len() {
            let msg = format!("expected 3 coordinates (u0, u1, v), found {}", g.0.len());
            return Err(Rejection::at_field(Code::WrongArity, format!("cone[{i}]"), msg));
        }
        let mut v = Vec::with_capacity(3);
        for (c, name) in g.0.iter().zip(names) {
            let x = element(field, &format!("cone[{i}].{name}"), c, limits)?;
            bits = x.coeffs().iter().map(|a| a.denom().bit_length()).fold(bits, u64::max);
            v.push(x);
        }
        vectors.push(v);
    }
    Ok(Generators { vectors, max_denominator_bits: bits, cert })
}
