//! The kinds of files and their rules, after the syntax and the header.

pub mod basin;
pub mod cone;
pub mod family;
pub mod limits;
pub mod numbers;
pub mod orbit;
pub mod refutation;
pub mod rest;
pub mod rest_family;
