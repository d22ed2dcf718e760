//! `chatter`: exact certificates that a rigid body dropped flat onto a floor comes to rest by
//! complete chatter (infinitely many impacts in finite time).
//!
//! The trusted checker is the separate crate [`chatter_kernel`] (exact scalars, the certificate
//! format, the kernel, the proof checker); this crate is the untrusted tool around it:
//! - [`finder`], [`exactify`]: floating-point search and its exact rounding;
//! - [`spectral`], [`bodies`], [`simulate`], [`symbolic`]: criteria, the catalogue, simulation
//!   and the producer of the square-case proof;
//! - [`sweep`]: the paper's maps over (rho, gamma) as data, in parallel and in shards;
//! - [`prove`]: drops decided with proofs (exact runs entering kernel-checked certified sets);
//! - `plot`, `reproduce` (feature `cli`): the figures, and the paper's results regenerated with a report;
//! - [`certify`], [`verify`], `cli` (feature `cli`): the pipeline and the command line;
//! - [`report`]: the typed, versioned reports every `--json` output prints (docs/json.md), on
//!   the shared vocabulary of [`json`].

pub mod basin;
pub mod bodies;
pub mod certify;
pub mod claims;
#[cfg(feature = "cli")]
pub mod cli;
pub mod convert;
pub mod cover;
pub mod exact;
pub mod exactify;
pub mod finder;
pub mod json;
pub mod model;
pub mod orbit;
#[cfg(feature = "cli")]
pub mod plot;
pub mod prove;
pub mod refute;
pub mod report;
#[cfg(feature = "cli")]
pub mod reproduce;
pub mod simulate;
pub mod spectral;
pub mod sweep;
pub mod symbolic;
pub mod verify;
pub mod write;

pub use chatter_kernel::{certificate, check, geometry};
