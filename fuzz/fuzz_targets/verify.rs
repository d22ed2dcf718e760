//! Fuzzes the untrusted-input path of the trusted crate: RON reading, canonical numbers and the
//! kernel on both backends. Any input must give a verdict (never a panic), and the backends must
//! agree.
#![no_main]

use chatter_kernel::exact::ParseLimits;
use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify_text};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        let limits = ParseLimits { max_digits: 200, ..ParseLimits::default() };
        if let Verdict::Disagree(s) = verify_text(text, limits, &[MALACHITE, NUM]) {
            panic!("backends disagree: {s}");
        }
    }
});
