//! Refutations on several backends (feature `refutation`).

use crate::exact::ParseLimits;
use crate::rules::refutation::Refuted;
use crate::syntax::refutation::Refutation;
use crate::syntax::{Encoding, read};
use crate::verify::{Backend, Verdict, agree};

/// Checks a refutation on the given backends.
pub fn verify_refutation(r: &Refutation, limits: ParseLimits, backends: &[Backend]) -> Verdict<Refuted> {
    agree(backends.iter().map(|b| (b.name, (b.kinds.refute)(r, limits))))
}

/// Reads RON refutation text and checks it on the given backends.
pub fn verify_refutation_text(text: &str, limits: ParseLimits, backends: &[Backend]) -> Verdict<Refuted> {
    verify_refutation_text_in(text, Encoding::Ron, limits, backends)
}

/// Reads refutation text in the given encoding and checks it on the given backends.
pub fn verify_refutation_text_in(
    text: &str,
    encoding: Encoding,
    limits: ParseLimits,
    backends: &[Backend],
) -> Verdict<Refuted> {
    read(text, encoding).map_or_else(Verdict::Rejected, |r| verify_refutation(&r, limits, backends))
}
