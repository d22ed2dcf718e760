//! The oracle's differential tests, in one test binary: each file below was its own binary, and
//! every binary compiled the kernel's and the tool's generic code again at full optimisation (the
//! release build's largest cost in CI, issue 23 §4; docs/measurements.md).

mod common;

mod basin;
mod basin_rest;
mod basin_tree;
mod boundary;
mod corpus;
mod family;
mod mutations;
mod orbit_field;
mod produced;
mod rest_family;
mod rules;
mod time_to_rest;
mod units;
