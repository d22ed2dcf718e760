//! Family certificates on several backends (feature `family`).

use crate::exact::ParseLimits;
use crate::syntax::family::ConvexCertificate;
use crate::verify::{BOTH, Backend, Verdict, agree};

/// Runs the kernel on a family certificate on each backend and compares the verdicts.
pub fn verify_convex_on(cert: &ConvexCertificate, limits: ParseLimits, backends: &[Backend]) -> Verdict {
    agree(backends.iter().map(|b| (b.name, (b.kinds.convex)(cert, limits))))
}

/// Runs the kernel on a family certificate on both backends.
pub fn verify_convex(cert: &ConvexCertificate, limits: ParseLimits) -> Verdict {
    verify_convex_on(cert, limits, &BOTH)
}
