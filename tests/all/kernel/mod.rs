//! Tests of `chatter::kernel`.

mod boxes;
mod brute;
mod check;
mod cones;
mod field;
mod impact;
mod pcc;
mod polygon;
mod rod;
