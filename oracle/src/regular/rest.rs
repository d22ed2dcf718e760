//! Rule T1 (docs/time-to-rest.md §2, docs/certificate-format.md §8): the optional bound B on the
//! time to rest of a rod point certificate, T ≤ B h/|v| for every all-down drop.
//!
//! Derived here from the rod's impacts (docs/model.md §7): an impact at one end with pre-impact
//! speed w sends the other end down faster by σ w, σ = (1 + γ)(1 − κ)/(1 + κ), and the hitting end
//! up at γ w. The ends alternate, so the pre-impact speeds obey w_{m+1} = σ w_m − γ w_{m−1}, with
//! characteristic polynomial λ² − σλ + γ = (λ − σ/2)² − Δ/4, Δ = σ² − 4γ. The theorem needs real
//! roots (Δ ≥ 0) and σ > 0 (κ < 1); it bounds T by h/(λ_1 |v|) with λ_1 = σ/2 + √Δ/2 the larger
//! root, so B is shown when 1/B ≤ λ_1, i.e. 1/B − σ/2 ≤ √Δ/2. The oracle decides that without a
//! square root by completing the square: with d = 1/B − σ/2, the inequality holds when d ≤ 0, and
//! for d > 0 exactly when d² ≤ Δ/4 (both sides non-negative). Everything is exact rational
//! arithmetic, with divisions (the kernel multiplies the test out instead).

use super::rod::Rod;
use crate::arith::Rat;
use crate::arith::rational::rational_text;
use crate::claim::Claim;
use crate::kinds::limits::Limits;
use crate::kinds::numbers::rational;
use crate::verdict::{Checked, Fail};
use num_traits::{One, Signed};

/// Why B is not shown, for messages.
fn not_shown(b: &Rat, why: &str) -> Fail {
    Fail::new(
        "time-to-rest-not-shown",
        format!("time_to_rest_bound {} is not shown: {why}", rational_text(b)),
    )
}

/// σ = (1 + γ)(1 − κ)/(1 + κ) of the rod.
pub fn sigma(rod: &Rod) -> Rat {
    let one = Rat::one();
    (&one + &rod.gamma) * (&one - &rod.kappa) / (&one + &rod.kappa)
}

/// Whether 1/B ≤ λ_1 for real roots (Δ = σ² − 4γ ≥ 0), by completing the square.
pub fn below_largest_root(rod: &Rod, b: &Rat) -> bool {
    let sigma = sigma(rod);
    let half = &sigma / Rat::from_integer(2.into());
    let d = b.recip() - &half;
    let quarter_delta = &half * &half - &rod.gamma;
    !d.is_positive() || &d * &d <= quarter_delta
}

/// Rule T1 on the text of B (a canonical rational): the number first (`bad-number`,
/// `too-large`), then a claim about drops, B > 0, σ > 0, Δ ≥ 0 and 1/B ≤ λ_1
/// (`time-to-rest-not-shown`). Returns B's canonical text.
pub fn time_to_rest(rod: &Rod, claim: Claim, text: &str, limits: &Limits) -> Checked<String> {
    let b = rational("time_to_rest_bound", text, limits)?;
    if !claim.about_drops() {
        return Err(not_shown(&b, "EffectivelyInvariant says nothing about drops"));
    }
    if !b.is_positive() {
        return Err(not_shown(&b, "B must be positive"));
    }
    let sigma = sigma(rod);
    if !sigma.is_positive() {
        return Err(not_shown(&b, "sigma <= 0 (kappa >= 1)"));
    }
    if &sigma * &sigma < Rat::from_integer(4.into()) * &rod.gamma {
        return Err(not_shown(&b, "sigma^2 < 4 gamma: the roots are not real"));
    }
    if !below_largest_root(rod, &b) {
        return Err(not_shown(
            &b,
            "1/B exceeds lambda_1, the larger root of lambda^2 - sigma lambda + gamma",
        ));
    }
    Ok(rational_text(&b))
}
