//! Orbit certificates on several backends (feature `orbit`).

use crate::exact::ParseLimits;
use crate::syntax::orbit::OrbitCertificate;
use crate::verify::{BOTH, Backend, Verdict, agree};

/// Runs the kernel on an orbit certificate on each backend and compares the verdicts.
pub fn verify_orbit_on(cert: &OrbitCertificate, limits: ParseLimits, backends: &[Backend]) -> Verdict {
    agree(backends.iter().map(|b| (b.name, (b.kinds.orbit)(cert, limits))))
}

/// Runs the kernel on an orbit certificate on both backends.
pub fn verify_orbit(cert: &OrbitCertificate, limits: ParseLimits) -> Verdict {
    verify_orbit_on(cert, limits, &BOTH)
}
