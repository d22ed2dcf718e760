//! Basin certificates on several backends (feature `basin`).

use crate::exact::ParseLimits;
use crate::rules::basin::BasinReport;
use crate::syntax::basin::BasinCertificate;
use crate::syntax::{Encoding, read};
use crate::verify::{Backend, Verdict, agree};

/// Checks a basin certificate on the given backends and compares the verdicts.
pub fn verify_basin(
    cert: &BasinCertificate,
    limits: ParseLimits,
    backends: &[Backend],
) -> Verdict<BasinReport> {
    agree(backends.iter().map(|b| (b.name, (b.kinds.basin)(cert, limits))))
}

/// Reads basin certificate text in the given encoding and checks it on the given backends.
pub fn verify_basin_text_in(
    text: &str,
    encoding: Encoding,
    limits: ParseLimits,
    backends: &[Backend],
) -> Verdict<BasinReport> {
    read(text, encoding).map_or_else(Verdict::Rejected, |c| verify_basin(&c, limits, backends))
}
