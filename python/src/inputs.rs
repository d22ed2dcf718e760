//! Inputs as the package passes them: exact numbers as text (canonical `p/q`, integers, or the
//! exact decimals `chatter` reads: 0.05 is 1/20), closed intervals as `lo:hi`, claims by name.

use crate::fail::Fail;
use chatter::certify::ClaimChoice;
use chatter::exact::{Q, parse_user_number};
use chatter_kernel::certificate::Claim;

/// An exact number; `field` names the argument in the message.
pub fn number(field: &str, text: &str) -> Result<Q, Fail> {
    parse_user_number(text).map_err(|e| Fail::usage("invalid-number", format!("{field}: {e}")))
}

/// A number `x` (the interval [x, x]) or a closed interval `lo:hi` with lo <= hi.
pub fn range(field: &str, text: &str) -> Result<[Q; 2], Fail> {
    match text.split_once(':') {
        None => {
            let x = number(field, text)?;
            Ok([x.clone(), x])
        }
        Some((a, b)) => {
            let (lo, hi) = (number(field, a)?, number(field, b)?);
            if lo > hi {
                let msg = format!("{field}: the interval [{lo}, {hi}] is empty (lo > hi)");
                return Err(Fail::usage("invalid-number", msg));
            }
            Ok([lo, hi])
        }
    }
}

/// A list of exact numbers (a position or a velocity).
pub fn numbers(field: &str, texts: &[String]) -> Result<Vec<Q>, Fail> {
    texts.iter().map(|t| number(field, t)).collect()
}

/// The claim to certify: `None` or "strongest", a kebab-case name as on the command line, or
/// the certificate's name (e.g. "CompleteChatterFromAllDown").
pub fn claim(text: Option<&str>) -> Result<ClaimChoice, Fail> {
    let exactly = |c: Claim| Ok(ClaimChoice::Exactly(c));
    match text.map(str::trim) {
        None | Some("strongest") => Ok(ClaimChoice::Strongest),
        Some("effectively-invariant" | "EffectivelyInvariant") => exactly(Claim::EffectivelyInvariant),
        Some("cc-or-pcc-from-all-down" | "CcOrPccFromAllDown") => exactly(Claim::CcOrPccFromAllDown),
        Some("complete-chatter-from-all-down" | "CompleteChatterFromAllDown") => {
            exactly(Claim::CompleteChatterFromAllDown)
        }
        Some(other) => Err(Fail::usage(
            "invalid-claim",
            format!(
                "claim: {other:?} is not one of strongest, effectively-invariant, cc-or-pcc-from-all-down, complete-chatter-from-all-down"
            ),
        )),
    }
}
