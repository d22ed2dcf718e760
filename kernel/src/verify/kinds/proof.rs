//! Proofs on both backends (feature `proof`).

use crate::exact::ParseLimits;
use crate::rules::proof::Checked;
use crate::syntax::proof::ProofFile;
use crate::syntax::{Encoding, read};
use crate::verify::{BOTH, Verdict, agree};

/// Checks a proof on both backends.
pub fn verify_proof(file: &ProofFile, limits: ParseLimits) -> Verdict<Checked> {
    agree(BOTH.iter().map(|b| (b.name, (b.kinds.proof)(file, limits))))
}

/// Reads proof text (RON) and checks it on both backends.
pub fn verify_proof_text(text: &str, limits: ParseLimits) -> Verdict<Checked> {
    read(text, Encoding::Ron).map_or_else(Verdict::Rejected, |f| verify_proof(&f, limits))
}
