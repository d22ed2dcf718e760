//! The kernel's tests, in one test binary: each file below was its own binary, and every binary
//! compiled the kernel's generic code again at full optimisation (most of the release build's
//! time in CI, issue 23 §4; docs/measurements.md). A file whose kind is not built (a Cargo feature
//! of `chatter-kernel`) is left out by its own `#![cfg(...)]`.

mod backends;
mod basin;
mod bivariate;
mod boundary;
mod canonical;
mod convex;
mod grammar;
mod membership;
mod orbit_field;
mod point_kernel;
mod proof_check;
mod proof_hostile;
mod proof_poly;
mod rest;
mod size;
mod syntax;
mod units;
mod worst;
