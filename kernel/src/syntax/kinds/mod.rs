//! The schemas of the kinds of file beyond cone certificates, one file each, re-exported as
//! `syntax::basin`, `syntax::family`, ... A reviewer of point certificates does not read them.

#[cfg(feature = "basin")]
pub mod basin;
#[cfg(feature = "family")]
pub mod family;
#[cfg(feature = "orbit")]
pub mod orbit;
#[cfg(feature = "proof")]
pub mod proof;
#[cfg(feature = "refutation")]
pub mod refutation;
#[cfg(feature = "rest")]
pub mod rest;
#[cfg(feature = "family-rest")]
pub mod rest_family;
