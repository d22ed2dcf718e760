//! Tests of `chatter::kernel`.

mod cones;
mod impact;
mod pcc;
