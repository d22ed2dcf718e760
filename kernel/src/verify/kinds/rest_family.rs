//! Time-to-rest certificates of general bodies on several backends (feature `family-rest`).

use crate::exact::ParseLimits;
use crate::rules::rest::Rested;
use crate::syntax::rest_family::FamilyTimeToRest;
use crate::syntax::{Encoding, read};
use crate::verify::{Backend, Verdict, agree};

/// Checks a time-to-rest certificate of a general body on the given backends.
pub fn verify_rest_family(
    c: &FamilyTimeToRest,
    limits: ParseLimits,
    backends: &[Backend],
) -> Verdict<Rested> {
    agree(backends.iter().map(|b| (b.name, (b.kinds.rest_family)(c, limits))))
}

/// Reads the text of a general body's time-to-rest certificate and checks it on the backends.
pub fn verify_rest_family_text_in(
    text: &str,
    encoding: Encoding,
    limits: ParseLimits,
    backends: &[Backend],
) -> Verdict<Rested> {
    read(text, encoding).map_or_else(Verdict::Rejected, |c| verify_rest_family(&c, limits, backends))
}
