//! The acceptance rules, one file per kind of verdict, each starting with the list of its rules
//! (the rule names of docs/certificate-format.md) and holding only the decisions. The reading of
//! the file (format, version, limits, numbers) is [`crate::syntax`]; the physics is
//! [`crate::model`]; the words of a rejection are `crate::explain`.
//!
//! - [`cone`]: point certificates of regular polygons (R1-R4), also the rules the other cone
//!   kinds reuse; [`rod`]: the rod (n = 2);
//! - `boxes` (feature `boxes`): parameter intervals; `field` (feature `field`): the number fields
//!   Q(cos 2 pi/n); `family` (feature `family`): general convex bodies (K1-K4);
//!   `orbit` (feature `orbit`): orbit certificates (O1, O2); `refutation` (feature
//!   `refutation`); `proof` (feature `proof`): the proof checker; `rest` (feature `rest`):
//!   time-to-rest certificates (G1-G5); `rest_family` (feature `family-rest`): those of a
//!   general convex body.

#[cfg(feature = "basin")]
pub mod basin;
pub mod body;
#[cfg(feature = "boxes")]
pub mod boxes;
#[cfg(feature = "basin")]
pub mod branches;
pub mod cone;
#[cfg(feature = "family")]
pub mod family;
#[cfg(feature = "field")]
pub mod field;
pub mod generators;
#[cfg(feature = "orbit")]
pub mod orbit;
pub mod outcome;
#[cfg(feature = "proof")]
pub mod proof;
#[cfg(feature = "refutation")]
pub mod refutation;
#[cfg(feature = "rest")]
pub mod rest;
#[cfg(all(feature = "rest", feature = "boxes"))]
pub mod rest_box;
#[cfg(feature = "family-rest")]
pub mod rest_family;
#[cfg(all(feature = "rest", feature = "field"))]
pub mod rest_field;
pub mod rod;
