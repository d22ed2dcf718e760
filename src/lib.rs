//! `chatter`: exact certificates that a rigid body dropped flat onto a floor comes to rest by
//! complete chatter (infinitely many impacts in finite time).
//!
//! Layers, from trusted to untrusted:
//! - [`exact`]: exact scalars (malachite main backend, num-rational second backend).
//! - [`certificate`]: the RON certificate schema, reader and writer.
//! - [`kernel`]: the trusted checker (exact model, cones, polygon geometry, PCC exclusion).
//! - [`finder`], [`exactify`]: untrusted floating-point search and its exact rounding.
//! - [`certify`], [`verify`], [`cli`]: the pipeline and the command line.

pub mod bodies;
pub mod certificate;
pub mod certify;
pub mod cli;
pub mod exact;
pub mod exactify;
pub mod finder;
pub mod kernel;
pub mod model;
pub mod simulate;
pub mod spectral;
pub mod symbolic;
pub mod verify;
