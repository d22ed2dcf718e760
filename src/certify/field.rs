//! Certification where cos(2 pi/n) is irrational (n = 5, 7, 8, ...): the exact maps live in
//! Q(cos 2 pi/n) (the kernel's [`Algebraic`] over malachite), the float finder runs on their
//! float copies, the exactifier keeps a rational cone K and computes the images of its pieces in
//! the field, and the kernel re-checks the certificate in the field on both backends.

use super::{
    Attempt, Failure, Report, Request, Timings, attempt_polygon, claims_for, pcc_at_point, polygon_strongest,
    report, run_claims,
};
use crate::exact::{Algebraic, CosField, MAX_N, ParseLimits, Q};
use chatter_kernel::model::Polygon;
use std::sync::Arc;

/// The exact body of the request in its field.
fn body(req: &Request) -> Result<Polygon<Algebraic<Q>>, Failure> {
    if req.upper.is_some() {
        let msg = "parameter intervals (box certificates) are supported only where cos(2 pi/n) is rational (n = 2, 3, 4, 6)";
        return Err(Failure::Body(msg.into()));
    }
    let n = req.n;
    let field: Arc<CosField<Q>> = CosField::new(n)
        .ok_or_else(|| Failure::Body(format!("n = {n}: regular polygons have 2 to {MAX_N} contacts here")))?;
    let kappa = match &req.kappa_field {
        Some(text) => field.parse(text, ParseLimits::default()).map_err(|e| {
            Failure::Body(format!("kappa {text:?} is not an element of Q(cos 2 pi/{n}): {e}"))
        })?,
        None => Algebraic::rational(req.kappa.clone()),
    };
    let gamma = Algebraic::rational(req.gamma.clone());
    Polygon::with_cosine(n, field.generator(), kappa, gamma).map_err(|e| Failure::Body(e.to_string()))
}

/// The pipeline in Q(cos 2 pi/n).
pub(super) fn certify(req: &Request) -> Report {
    let mut notes = Vec::new();
    let failed = |f, notes| report(Attempt::failed(f, None), Timings::default(), notes);
    let body = match body(req) {
        Ok(b) => b,
        Err(f) => return failed(f, notes),
    };
    let strongest = |notes: &mut Vec<String>| polygon_strongest(req, body.n(), pcc_at_point(&body)?, notes);
    let claims = match claims_for(req, strongest, &mut notes) {
        Ok(c) => c,
        Err(f) => return failed(f, notes),
    };
    let bodies = [body.clone()];
    run_claims(req, claims, |claim, t| attempt_polygon(req, &bodies, claim, t), notes)
}
