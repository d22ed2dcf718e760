//! The proof checker: re-checks a proof file about the model for all parameters at once (the
//! square-case lemmas of the paper, `proofs/square.ron`) from the file alone.
//!
//! Every step is an identity (checked by recomputing a normal form modulo chi), a sign fact with
//! a positivity certificate (a positive combination of products of atoms, each atom a hypothesis
//! or an earlier step), or a root fact with its data (positive coefficients of chi(b + s); a Sturm
//! sequence). Definitions and points only name expressions. The rules `Cone`, `Invariant` and
//! `AllDown` carry no verdict: the checker computes the model's maps and cones itself, runs the
//! same clipping as the certificate kernel on the named points, and requires a step for every
//! sign it needs. No step carries a verdict supplied by the producer. The format is in
//! docs/proof-format.md, the argument in docs/kernel-soundness.md.

mod algebra;
mod check;
mod clip;
mod context;
mod file;
mod model;
mod poly;
mod rules;
pub(crate) mod sturm;

pub use check::{Checked, check};
pub use clip::{Oracle, Point, clip, parallel};
pub use context::{Context, Frac};
pub use file::{Eigenvalue, FORMAT, Hypothesis, Parameters, ProofBody, ProofFile, Step, VERSION, read};
pub use model::{PMat, PVec, SymbolicModel, det, mat_mul, mat_vec};
pub use poly::{MAX_DEGREE, Poly};
pub use sturm::{Coeffs, count_roots, derivative, positive_on, rem, sturm_sequence};
