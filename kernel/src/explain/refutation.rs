//! The words of the rejections of refutations.

use super::abbreviate;
use crate::reject::{KindLocus, Locus};
use crate::rules::refutation::Failure;

/// The words of a failure of a refutation (at a locus): a step's failure names the point.
pub(super) fn words(f: &Failure, locus: &Locus) -> String {
    let words = match f {
        Failure::NotAtPoint => {
            return "a refutation is made at a point: kappa and gamma must be numbers".into();
        }
        Failure::NoPoints => return "no points".into(),
        Failure::LastBelow(v) => {
            return format!("the last point has v = {} < 0: nothing is refuted", abbreviate(v));
        }
        Failure::LastZero => return "the last point is zero: nothing is refuted".into(),
        Failure::NotEarlier(i) => format!("point {i} is not an earlier point"),
        Failure::NoSeed { index, seeds } => format!("there is no seed {index} ({seeds} seeds)"),
        Failure::NoTerms => "no terms".into(),
        Failure::Coefficient { text, error } => format!("{text:?}: {error}"),
        Failure::Negative(i) => format!("the coefficient of point {i} is negative"),
        Failure::NoMap { step, maps } => format!("S_{step} does not exist (1..{maps})"),
        Failure::NotInCone { of, step, inequality } => {
            format!("point {of} is not in C_{step} (inequality {inequality} fails)")
        }
    };
    match locus {
        Locus::Kind(KindLocus::Step { index, id }) => format!("point {index} ({id}): {words}"),
        _ => words,
    }
}
