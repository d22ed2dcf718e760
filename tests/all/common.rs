//! Helpers shared by the tests.
#![allow(dead_code)]

use chatter::exact::Q;
use chatter_kernel::model::Polygon as Body;
use std::path::PathBuf;

/// A rational from canonical text (panics on bad input: test data only).
pub fn q(s: &str) -> Q {
    s.parse().unwrap_or_else(|e| panic!("bad test number {s:?}: {e}"))
}

/// The exact body of a regular n-gon.
pub fn body(n: u64, kappa: &str, gamma: &str) -> Body<Q> {
    Body::new(n, q(kappa), q(gamma)).expect("valid test body")
}

/// The `chatter` binary built for these tests.
pub fn bin() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_chatter"))
}

/// The repository root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Supported polygon sizes.
pub const NS: [u64; 3] = [3, 4, 6];

/// A spread of kappa and gamma values used across tests.
pub const KAPPAS: [&str; 6] = ["1/40", "1/8", "3/20", "1/6", "1/3", "2"];
pub const GAMMAS: [&str; 6] = ["0", "1/100", "1/20", "3/10", "9/10", "1"];
