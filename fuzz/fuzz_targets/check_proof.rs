//! Fuzzes the proof reader and checker of the trusted crate on both backends: any input must
//! give a verdict (never a panic, within the size limits), and the backends must agree.
#![no_main]

use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::{Verdict, verify_proof_text};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        let limits = ParseLimits { max_digits: 200, ..ParseLimits::default() };
        if let Verdict::Disagree(s) = verify_proof_text(text, limits) {
            panic!("backends disagree: {s}");
        }
    }
});
