//! Basin certificates' machinery (feature `basin`; docs/basin-certificates.md): the partition of
//! the box of drops by bisection paths ([`tree`]), and the drop's state in our coordinates with
//! sin 2π/n enclosed ([`mod@drop`]). The acceptance rules are [`crate::rules::basin`].

pub mod drop;
pub mod tree;

pub use crate::rules::basin::{BasinReport, MAX_LEAVES, MAX_PATH, MAX_PREFIX, check as check_basin};
