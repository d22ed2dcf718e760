//! Fuzzes the untrusted-input path: RON reading, canonical numbers and the kernel on both
//! backends. Any input must give a verdict (never a panic), and the backends must agree.
#![no_main]

use chatter::exact::ParseLimits;
use chatter::verify::{BackendVerdict, Backends, verify_text};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        let limits = ParseLimits { max_digits: 200 };
        if let BackendVerdict::Disagree(s) = verify_text(text, limits, Backends::Both) {
            panic!("backends disagree: {s}");
        }
    }
});
