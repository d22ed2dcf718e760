//! The body of a cone certificate (docs/certificate-format.md §3): a model error located at its
//! field, and the rule "range of γ": the claims about drops need 0 < γ < 1 (the hypothesis of the
//! paper's Theorem on effectively invariant cones; at γ = 1 energy is conserved, at γ = 0 a drop
//! can stop after finitely many impacts), while `EffectivelyInvariant` holds for 0 <= γ <= 1.

use crate::geometry::Scalar;
use crate::model::polygon::BodyError;
use crate::reject::{Code, Detail, Rejection};
use crate::syntax::cone::Claim;

/// A body the model rejects, at `body.n`, or at the path of kappa or gamma.
pub fn body_error(e: BodyError, kappa: &str, gamma: &str) -> Rejection {
    let (code, path) = match e {
        BodyError::UnsupportedN(_) => (Code::UnsupportedBody, "body.n"),
        BodyError::KappaNotPositive => (Code::ParameterOutOfRange, kappa),
        BodyError::GammaOutOfRange => (Code::ParameterOutOfRange, gamma),
    };
    Rejection::at(code, path, Detail::Body(e))
}

/// Range of γ: with a claim about drops, γ (at `path`) is neither 0 nor 1.
pub fn gamma_range<E: Scalar>(gamma: &E, path: &str, claim: Claim) -> Result<(), Rejection> {
    if claim > Claim::EffectivelyInvariant && (gamma.is_zero() || *gamma == E::one()) {
        let detail = Detail::GammaForClaim(gamma.text(), claim, false);
        return Err(Rejection::at(Code::ParameterOutOfRange, path, detail));
    }
    Ok(())
}
