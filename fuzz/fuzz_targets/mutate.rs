//! Structure-aware fuzzing of the certificate kernel against the independent brute-force oracle
//! `chatter::oracle`.
//!
//! The input bytes choose a valid certificate of `certificates/valid` (read once, at the first
//! input; every file of that directory that the reader accepts) and up to 12 mutations
//! (`chatter::oracle::mutation::decode`): a number of a generator, kappa or gamma changed by ±1 in
//! its numerator or denominator and reduced to canonical form; a generator scaled by a positive
//! factor or negated; generators dropped, duplicated, swapped, reversed or rotated; a generator
//! added near an existing one (its projection moved by up to 4/10^e) or between two; the claim
//! upgraded or changed; n switched among 3, 4 and 6. The mutated certificate is written with the
//! kernel's writer, read back (it must round-trip), verified on both backends
//! (`chatter_kernel::verify::verify_text` with MALACHITE and NUM) and compared with the oracle
//! (`chatter::oracle::check_text_and_oracle`). A finding (a panic) is:
//!
//! - `backends-disagree`: malachite and num-rational give different verdicts;
//! - `accepted-false`: the kernel accepts while the oracle finds a failing rule;
//! - `oracle-accepts`: the oracle accepts every rule while the kernel rejects;
//! - `wrong-code`: the kernel's code is not among the oracle's first failing stage;
//! - `wrong-report`: both accept, with different reports (redundant generators, piece sizes,
//!   largest denominator, PCC quadratic, translation);
//! - `round-trip`: the writer's text does not read back as the same certificate.
//!
//! Run: `cd fuzz && RUSTC_BOOTSTRAP=1 cargo fuzz run mutate --sanitizer none -- -max_total_time=1800`.
#![no_main]

use chatter::oracle::{check_text_and_oracle, mutation};
use chatter::write::write;
use chatter_kernel::certificate::{Certificate, read};
use chatter_kernel::exact::ParseLimits;
use libfuzzer_sys::fuzz_target;
use std::sync::OnceLock;

/// The valid corpus, sorted by file name.
fn corpus() -> &'static [(String, Certificate)] {
    static CORPUS: OnceLock<Vec<(String, Certificate)>> = OnceLock::new();
    CORPUS.get_or_init(|| {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../certificates/valid");
        let mut files: Vec<_> = std::fs::read_dir(&dir)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            .map(|e| e.expect("directory entry").path())
            .filter(|p| p.extension().is_some_and(|x| x == "ron"))
            .collect();
        files.sort();
        let certs: Vec<(String, Certificate)> = files
            .iter()
            .filter_map(|p| {
                let text = std::fs::read_to_string(p).ok()?;
                Some((p.file_name()?.to_string_lossy().into_owned(), read(&text).ok()?))
            })
            .collect();
        assert!(!certs.is_empty(), "no readable certificate in {}", dir.display());
        certs
    })
}

fuzz_target!(|data: &[u8]| {
    let corpus = corpus();
    let plan = mutation::decode(data);
    let (name, base) = &corpus[plan.pick % corpus.len()];
    let cert = mutation::mutated(base, &plan.steps);
    if let Err(f) = check_text_and_oracle(&cert, ParseLimits::default()) {
        panic!("{f}\nbase {name}, mutations {:?}\n{}", plan.steps, write(&cert));
    }
});
