//! Time-to-rest certificates over a box of (κ, γ) (features `rest` and `boxes`;
//! docs/certificate-format.md §16, version 3; why the corners suffice: docs/kernel-soundness.md
//! §10, "Boxes"): one graph and one B for every body of the box. Rules, in order:
//!
//! - version: 3 or more (`unsupported-version`), n = 3, 4 or 6 (`unsupported-body`);
//! - the box: lo <= hi for each interval (`parameter-out-of-range`), a valid body at every corner,
//!   0 < γ < 1 on the box (`parameter-out-of-range`);
//! - G1 to G5 of [`super::rest`] at every distinct corner, in the order (lo, lo), (hi, lo),
//!   (lo, hi), (hi, hi) (a failure names its corner);
//! - R4 on the box (`CompleteChatterFromAllDown`), as for box certificates ([`super::boxes`]).

use super::boxes::{at_corner, bodies, bounds, corners, gamma_on_box, pcc_on_box};
use super::rest::{FIELD_VERSION, Failure, Rationals, Rested, contacts, graph};
use crate::bivariate::Rect;
use crate::exact::{Field, ParseLimits, to_canonical};
use crate::model::polygon::{Polygon, is_irrational};
use crate::reject::{Code, KindDetail, KindLocus, Locus, Rejection};
use crate::syntax::cone::{Body, Claim};
use crate::syntax::rest::TimeToRest;
use std::marker::PhantomData;

/// The rules on the box of the file's κ and γ.
pub(super) fn on_box<F: Field>(cert: &TimeToRest, limits: ParseLimits) -> Result<Rested, Rejection> {
    let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
    if cert.version < FIELD_VERSION {
        let detail = KindDetail::Rest(Failure::BoxVersion(cert.version));
        return Err(Rejection::at(Code::UnsupportedVersion, "version", detail));
    }
    if is_irrational(*n) {
        return Err(Rejection::at(Code::UnsupportedBody, "body", KindDetail::IntervalIrrational(*n)));
    }
    let rect =
        Rect { kappa: bounds::<F>("kappa", kappa, limits)?, gamma: bounds::<F>("gamma", gamma, limits)? };
    let corners = corners(&rect);
    let polygons = bodies(&rect, &corners, |k, g| Polygon::new(contacts(cert), k, g))?;
    gamma_on_box(&rect, cert.claim)?;
    let nums = Rationals::<F>(limits, PhantomData);
    for (body, (_, _, corner)) in polygons.iter().zip(&corners) {
        let at = |mut e: Rejection| {
            if let Locus::Kind(KindLocus::RestNode { corner: c, .. }) = &mut e.locus {
                *c = Some(corner.index);
            }
            at_corner(e, corner)
        };
        graph(body, cert, &nums).map_err(at)?;
    }
    if cert.claim == Claim::CompleteChatterFromAllDown {
        pcc_on_box(&polygons[0], &rect)?;
    }
    let text = |r: &[F; 2]| [to_canonical(&r[0]), to_canonical(&r[1])];
    let region = Some([text(&rect.kappa), text(&rect.gamma)]);
    Ok(Rested {
        claim: cert.claim,
        n: *n,
        bound: cert.bound.clone(),
        nodes: cert.nodes.len(),
        region,
        gamma_interval: None,
    })
}
