//! Verifying certificates and proofs with `chatter-kernel` alone: no finder, no simulator, no
//! command-line crate. A library user needs only this crate.
//!
//! ```sh
//! cargo run --release -p chatter-kernel --example verify -- certificates/valid/doc-example-square.ron proofs/square.ron
//! ```
//! Prints one verdict per file; exits 0 if every file is accepted, 1 if one is rejected, 2 if one
//! cannot be read, 3 if the two bignum backends disagree.

use chatter_kernel::exact::ParseLimits;
use chatter_kernel::syntax::{Encoding, Kind, kind_of};
use chatter_kernel::verify::{BOTH, Verdict, verify_proof_text, verify_text};
use std::process::ExitCode;

/// The verdict on one file's text: certificates and proofs are told apart by their header.
fn verdict(text: &str) -> (String, u8) {
    let limits = ParseLimits::default();
    let is_proof = matches!(kind_of(text, Encoding::Ron, Kind::Cone), Ok((Kind::Proof, _)));
    let (ok, rejected, disagree) = if is_proof {
        match verify_proof_text(text, limits) {
            Verdict::Accepted(c) => (
                Some(format!("proof {}: {} steps, {} conclusions", c.name, c.steps, c.conclusions.len())),
                None,
                None,
            ),
            Verdict::Rejected(r) => (None, Some(r), None),
            Verdict::Disagree(s) => (None, None, Some(s)),
        }
    } else {
        match verify_text(text, limits, &BOTH) {
            Verdict::Accepted(a) => {
                (Some(format!("certificate: {} for n = {}", a.claim.name(), a.n)), None, None)
            }
            Verdict::Rejected(r) => (None, Some(r), None),
            Verdict::Disagree(s) => (None, None, Some(s)),
        }
    };
    match (ok, rejected, disagree) {
        (Some(s), _, _) => (format!("OK ({s})"), 0),
        (_, Some(r), _) => (format!("REJECTED [{}] at {:?}: {}", r.code.as_str(), r.locus, r.message()), 1),
        (_, _, Some(s)) => (format!("ERROR: the backends disagree: {s}"), 3),
        _ => unreachable!("one verdict"),
    }
}

fn main() -> ExitCode {
    let mut worst = 0;
    for path in std::env::args().skip(1) {
        let (line, code) = match std::fs::read_to_string(&path) {
            Ok(text) => verdict(&text),
            Err(e) => (format!("ERROR: cannot read: {e}"), 2),
        };
        println!("{path}: {line}");
        worst = worst.max(code);
    }
    ExitCode::from(worst)
}
