//! Orbit certificates (docs/orbit-certificates.md §2-§4, docs/certificate-format.md §14): the
//! return map of a pattern evaluated exactly at rational points of X. Exact evaluation can only
//! show a certificate false (a point of X where a condition fails); it cannot prove one.

pub mod map;
pub mod sample;
