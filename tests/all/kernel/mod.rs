//! Tests of `chatter::kernel`.

mod boxes;
mod brute;
mod check;
mod cones;
pub(crate) mod convex;
mod field;
mod impact;
mod pcc;
mod polygon;
mod rod;
