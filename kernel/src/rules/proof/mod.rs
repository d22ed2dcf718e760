//! The proof checker (feature `proof`; docs/proof-format.md, why: docs/kernel-soundness.md §3):
//! re-checks a proof about the model for all parameters at once (the square-case lemmas of the
//! paper, `proofs/square.ron`) from the file alone. Rules, in the order they are checked:
//!
//! - the header (`invalid-header` at its field): distinct alphanumeric variables (at most 16),
//!   gamma, kappa and lambda three of them, coordinates M invertible with third row (0, 0, 1),
//!   n in {3, 4, 6}, chi canonical and (1 + kappa)^2 chi = det((1 + kappa) lambda I - (1 +
//!   kappa) S_j), hypotheses in gamma, kappa and lambda not vanishing with chi, kappa among them;
//! - every step in order, at most once per id (`duplicate-name`): `Positive` (a positive
//!   combination of products of atoms, `bad-certificate`, `not-an-identity`), `Identity`
//!   (`not-an-identity`), `Define` (a denominator proved positive, `sign-not-proved`), `Point`,
//!   `Image`, `RootBound` (positive coefficients of chi(b + s)), `Cone` (facets vanishing at the
//!   ends of their edge and positive at the other vertices, `bad-cone`), `Invariant` and
//!   `AllDown` (every sign the clipping and the images need is zero, constant or proved by the
//!   step it names, `sign-not-proved`), `Pcc` (the factorisation, as polynomials), `Witness` (a
//!   verified Sturm sequence and values at a rational point, `bad-witness`);
//! - everywhere: canonical expressions (`bad-expression`, `bad-number`), known names
//!   (`unknown-name`, `misused-name`), and the size limits (`too-large`).
//!
//! Every identity is decided by recomputing a normal form modulo chi; no step carries a verdict
//! supplied by the producer. The rules `Cone`, `Invariant` and `AllDown` compute the model's maps
//! and cones themselves and run the same clipping as the certificate kernel on the named points.

mod algebra;
mod check;
mod clip;
mod context;
pub mod failure;
mod geometric;
mod model;
mod poly;

pub use crate::exact::univariate::{Coeffs, count_roots, derivative, positive_on, rem, sturm_sequence};
pub use crate::syntax::proof::{
    Eigenvalue, FORMAT, Hypothesis, Parameters, ProofBody, ProofFile, Step, VERSION,
};
pub use check::{Checked, check};
pub use clip::{Oracle, Point, clip, parallel};
pub use context::{Context, Frac, MAX_LAMBDA_DEGREE, MAX_VARIABLES};
pub use failure::{ExprError, Failure};
pub use model::{PMat, PVec, SymbolicModel, det, mat_mul, mat_vec};
pub use poly::{MAX_DEGREE, MAX_TERMS, MAX_TOTAL_DEGREE, MAX_WORK, Poly};

/// Reads a proof file (RON): the strict syntax, the header, then the schema (docs/proof-format.md
/// §2); every error names the field or the position.
pub fn read(text: &str) -> Result<ProofFile, crate::reject::Rejection> {
    crate::syntax::read(text, crate::syntax::Encoding::Ron)
}
