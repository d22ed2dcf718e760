//! `chatter-kernel`: the trusted part of `chatter`.
//!
//! A certificate or proof is trusted because this crate re-checks it, not because a producer
//! says so. The crate is small and separate, and its promises are compiler checks: no unsafe
//! code, no floating-point arithmetic, every public item documented, and no dependency on the
//! untrusted tool (finder, exactifier, simulator, plots, command line); it depends on malachite,
//! num-bigint/num-rational, serde, ron and serde_json only.
//!
//! - [`exact`]: exact scalars behind one ordered-field interface, on two independent bignum
//!   backends, and the canonical `"p/q"` text of a rational.
//! - [`certificate`]: the certificate schema, its reader and writer, and typed rejections.
//! - [`model`]: the exact impact model of the rod and of regular polygons (docs/model.md).
//! - [`geometry`]: exact convex polygons on the plane v = -1, with integer arithmetic only.
//! - [`check`]: the certificate kernel (the acceptance rules of docs/certificate-format.md).
//! - [`orbit`]: orbit certificates (version 5): the return map of an impact pattern and the
//!   three conditions over a set of the section, by exact interval arithmetic.
//! - [`verify`]: the kernel on both backends, with a disagreement reported as an internal error.
//! - [`membership`]: whether an exact state lies in the set an accepted certificate certifies.
//!
//! Why acceptance implies each claim is argued in docs/kernel-soundness.md.
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![deny(clippy::float_arithmetic)]

pub mod bivariate;
pub mod certificate;
pub mod check;
pub mod exact;
pub mod geometry;
pub mod membership;
pub mod model;
pub mod orbit;
pub mod proof;
pub mod refute;
pub mod verify;
