//! Time-to-rest certificates on several backends (feature `rest`).

use crate::exact::ParseLimits;
use crate::rules::rest::Rested;
use crate::syntax::rest::TimeToRest;
use crate::syntax::{Encoding, read};
use crate::verify::{Backend, Verdict, agree};

/// Checks a time-to-rest certificate on the given backends.
pub fn verify_rest(c: &TimeToRest, limits: ParseLimits, backends: &[Backend]) -> Verdict<Rested> {
    agree(backends.iter().map(|b| (b.name, (b.kinds.rest)(c, limits))))
}

/// Reads time-to-rest text in the given encoding and checks it on the given backends.
pub fn verify_rest_text_in(
    text: &str,
    encoding: Encoding,
    limits: ParseLimits,
    backends: &[Backend],
) -> Verdict<Rested> {
    read(text, encoding).map_or_else(Verdict::Rejected, |c| verify_rest(&c, limits, backends))
}
