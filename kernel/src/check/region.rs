//! The parameters of a certificate: a point (kappa, gamma), or a closed box of them (version 2).
//! Every containment rule is checked at the box's corners, which suffices because (1 + kappa)
//! times every map is affine in kappa and in gamma while K, the cones C_j and D do not depend on
//! them (docs/kernel-soundness.md §2, "Boxes").

use super::scalar::Scalar;
use super::{number, show};
use crate::bivariate::Rect;
use crate::certificate::{Body, Certificate, Claim, Code, Param, Rejection};
use crate::exact::{Field, ParseLimits};
use crate::model::{BodyError, Shape};

/// The body at one corner of the region (the region itself when it is a point).
pub(crate) struct Corner<F> {
    /// The exact model at this corner.
    pub shape: Shape<F>,
    /// "at the corner kappa = .., gamma = .." for a box; empty for a point.
    pub label: String,
    /// For a box: 0 to 3 for (kappa, gamma) at (lo, lo), (hi, lo), (lo, hi), (hi, hi).
    pub index: Option<usize>,
}

impl<F> Corner<F> {
    /// `message` prefixed with the corner, for a box.
    pub fn say(&self, message: String) -> String {
        if self.label.is_empty() { message } else { format!("{}: {message}", self.label) }
    }
}

/// The region: the bounds of kappa and gamma, and its distinct corners.
pub(crate) struct Region<F> {
    /// [lo, hi] of kappa and gamma (lo = hi for a point parameter).
    pub rect: Rect<F>,
    /// The distinct corners, in the order (lo, lo), (hi, lo), (lo, hi), (hi, hi) of (kappa, gamma).
    pub corners: Vec<Corner<F>>,
    /// Whether either parameter is an interval.
    pub is_box: bool,
}

/// The bounds of one parameter.
fn bounds<F: Field>(name: &str, p: &Param, limits: ParseLimits) -> Result<[F; 2], Rejection> {
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
                let msg =
                    format!("the interval [{}, {}] is empty (lo > hi)", show::number(&lo), show::number(&hi));
                return Err(Rejection::at_field(Code::ParameterOutOfRange, path, msg));
            }
            Ok([lo, hi])
        }
    }
}

/// The region of a certificate (rule R1 for the body), with the exact model at each corner.
pub(crate) fn region<F: Field>(cert: &Certificate, limits: ParseLimits) -> Result<Region<F>, Rejection> {
    let Body::RegularPolygon { n, kappa, gamma } = &cert.body;
    let is_box = matches!(kappa, Param::Interval(..)) || matches!(gamma, Param::Interval(..));
    if is_box && cert.version < 2 {
        let msg = format!(
            "parameter intervals (box certificates) need version 2; this file says version {}",
            cert.version
        );
        return Err(Rejection::at_field(Code::UnsupportedVersion, "version", msg));
    }
    let k: [F; 2] = bounds("kappa", kappa, limits)?;
    let g: [F; 2] = bounds("gamma", gamma, limits)?;
    let mut corners: Vec<Corner<F>> = Vec::with_capacity(4);
    let mut seen: Vec<(F, F)> = Vec::with_capacity(4);
    for (gi, ki) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
        let point = (k[ki].clone(), g[gi].clone());
        if seen.contains(&point) {
            continue;
        }
        let shape =
            Shape::new(*n, point.0.clone(), point.1.clone()).map_err(|e| body_error(e, ki, gi, is_box))?;
        let label = if is_box {
            format!("at the corner kappa = {}, gamma = {}", show::number(&point.0), show::number(&point.1))
        } else {
            String::new()
        };
        corners.push(Corner { shape, label, index: is_box.then_some(ki + 2 * gi) });
        seen.push(point);
    }
    Ok(Region { rect: Rect { kappa: k, gamma: g }, corners, is_box })
}

/// A body that cannot be modelled, at the bound that fails.
pub(crate) fn body_error(e: BodyError, ki: usize, gi: usize, is_box: bool) -> Rejection {
    let at = |name: &str, i: usize| if is_box { format!("body.{name}[{i}]") } else { format!("body.{name}") };
    let (code, path) = match e {
        BodyError::UnsupportedN(_) => (Code::UnsupportedBody, "body.n".to_string()),
        BodyError::KappaNotPositive => (Code::ParameterOutOfRange, at("kappa", ki)),
        BodyError::GammaOutOfRange => (Code::ParameterOutOfRange, at("gamma", gi)),
    };
    Rejection::at_field(code, path, e)
}

/// The claims about drops need 0 < gamma < 1 (everywhere in the region), the hypothesis of the
/// paper's Theorem on effectively invariant cones: at gamma = 1 energy is conserved and chatter is
/// impossible; at gamma = 0 a drop can stop after finitely many impacts (an image exactly 0), which
/// is neither CC nor PCC. `EffectivelyInvariant`, a property of the cone and the maps, holds for
/// 0 <= gamma <= 1.
pub(crate) fn claim_range<E: Scalar>(region: &Region<E>, claim: Claim) -> Result<(), Rejection> {
    let [g0, g1] = &region.rect.gamma;
    if claim > Claim::EffectivelyInvariant && (g0.is_zero() || *g1 == E::one()) {
        let g = if g0.is_zero() { g0 } else { g1 };
        let path = match (region.is_box, g0.is_zero()) {
            (false, _) => "body.gamma",
            (true, true) => "body.gamma[0]",
            (true, false) => "body.gamma[1]",
        };
        let msg = format!(
            "gamma = {} is outside 0 < gamma < 1, which the claim {} needs (the paper's Theorem on effectively invariant cones assumes it); only EffectivelyInvariant holds for gamma = 0 or 1",
            super::scalar::number(g),
            claim.name()
        );
        return Err(Rejection::at_field(Code::ParameterOutOfRange, path, msg));
    }
    Ok(())
}
