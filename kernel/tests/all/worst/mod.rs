//! The heaviest files the default limits allow, one per kind (issue 23 §3): built here
//! (`files.rs`), each verified on both backends with the verdict asserted. Their times are measured
//! by `cargo bench --bench worst`, never asserted in a test.
#![cfg(all(feature = "boxes", feature = "field", feature = "family", feature = "refutation"))]

mod files;

use chatter_kernel::exact::ParseLimits;
use chatter_kernel::syntax::Encoding;
use chatter_kernel::verify::{BOTH, Verdict, verify_refutation_text_in, verify_text};
use std::path::Path;

fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

/// Whether both backends accept the file (a disagreement fails the test).
fn accepted(name: &str, text: &str) -> bool {
    let limits = ParseLimits::default();
    if name.starts_with("refutation") {
        match verify_refutation_text_in(text, Encoding::Ron, limits, &BOTH) {
            Verdict::Accepted(_) => true,
            Verdict::Rejected(_) => false,
            Verdict::Disagree(d) => panic!("{name}: the backends disagree: {d}"),
        }
    } else {
        match verify_text(text, limits, &BOTH) {
            Verdict::Accepted(_) => true,
            Verdict::Rejected(_) => false,
            Verdict::Disagree(d) => panic!("{name}: the backends disagree: {d}"),
        }
    }
}

/// Ignored by default: on the num backend the refutations still take tens of seconds
/// (docs/measurements.md, "Heaviest files"); run with `--ignored`.
#[test]
#[ignore = "over a minute on the 2-core machine (the refutations on num-rational)"]
fn every_heavy_file_is_within_the_default_limits_and_keeps_its_verdict() {
    let limits = ParseLimits::default();
    for f in files::files(root()) {
        let numbers: Vec<&str> = f.text.split('"').skip(1).step_by(2).collect();
        let total: usize = numbers
            .iter()
            .filter(|s| s.bytes().all(|b| b.is_ascii_digit() || b == b'-' || b == b'/'))
            .map(|s| s.len())
            .sum();
        assert!(total <= limits.max_total_digits, "{}: {total} characters of numbers", f.name);
        let longest = numbers.iter().map(|s| s.bytes().filter(u8::is_ascii_digit).count()).max().unwrap_or(0);
        assert!(longest > 1_000, "{}: the file is heavy ({longest} digits in its longest number)", f.name);
        let start = std::time::Instant::now();
        // Two files have no slack: the rod's certificate with moved κ and γ (image-outside) and
        // the n = 6 refutation with a moved body (step-failed at its step 25), and both backends
        // say so; every other file keeps its verdict, accepted.
        let no_slack = ["rod-body", "refutation-n6-body"].contains(&f.name);
        assert_eq!(accepted(f.name, &f.text), !no_slack, "{}", f.name);
        eprintln!(
            "{}: {longest} digits, {total} characters of numbers, {:.2?} (both backends; not asserted)",
            f.name,
            start.elapsed()
        );
    }
}
