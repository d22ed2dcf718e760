//! Differential fuzzing of the certificate kernel against the independent oracle
//! (`chatter-oracle`, which shares no code with the kernel).
//!
//! Each input is decoded (`chatter_oracle::mutate::decode`) into a base file of the corpus
//! (`certificates/valid` and `certificates/invalid`, every plain `.ron` file: certificates of all
//! kinds, time-to-rest certificates among them, and refutations) and up to eight structure-aware
//! edits of its value tree (numbers perturbed, scaled, negated or spoilt, generators dropped,
//! duplicated, swapped or interpolated, claims, n, versions, steps and indices changed, fields
//! swapped, parameters widened, a weight, scale, bound, generator or successor edited). The
//! mutated text is verified by the kernel on both backends (`chatter_kernel::verify::verify_text`,
//! `verify_basin_text_in`, `verify_rest_text_in` or `verify_refutation_text` with MALACHITE and
//! NUM) and judged by the oracle; a finding (a panic) is a disagreement of
//! `chatter_oracle::compare::compare`: the backends disagree, the kernel accepts what the oracle finds false, the kernel rejects what the oracle accepts (where
//! the oracle is two-sided and the kernel does not say "not shown"), the codes are incompatible,
//! the reports differ, or an orbit condition the kernel says fails at a sub-box's centre holds
//! there exactly. A panic of either side is a finding too.
//!
//! Run: `cd fuzz && RUSTC_BOOTSTRAP=1 cargo fuzz run oracle --sanitizer none -- -max_total_time=300`.
#![no_main]

use chatter_kernel::syntax::{Encoding as KernelEncoding, Kind, kind_of};
use chatter_kernel::verify::{
    MALACHITE, NUM, Verdict, verify_basin_text_in, verify_refutation_text, verify_rest_text_in, verify_text,
};
use chatter_oracle::compare::{KernelView, differential};
use chatter_oracle::mutate::{decode, mutated};
use chatter_oracle::read::{Encoding, Value, parse::parse};
use chatter_oracle::verdict::Report;
use libfuzzer_sys::fuzz_target;
use std::sync::OnceLock;

/// The plain RON files of the corpus, parsed, sorted by name.
fn corpus() -> &'static [(String, Value)] {
    static CORPUS: OnceLock<Vec<(String, Value)>> = OnceLock::new();
    CORPUS.get_or_init(|| {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../certificates");
        let mut files: Vec<_> = ["valid", "invalid"]
            .iter()
            .flat_map(|d| {
                std::fs::read_dir(root.join(d)).expect("the corpus").map(|e| e.expect("entry").path())
            })
            .filter(|p| p.extension().is_some_and(|x| x == "ron"))
            .collect();
        files.sort();
        let bases: Vec<(String, Value)> = files
            .iter()
            .filter_map(|p| {
                let text = std::fs::read_to_string(p).ok()?;
                Some((p.file_name()?.to_string_lossy().into_owned(), parse(&text, Encoding::Ron).ok()?))
            })
            .collect();
        assert!(bases.len() > 100, "the corpus has {} parsable files", bases.len());
        bases
    })
}

/// The kernel's verdict on RON text as plain data.
fn kernel(text: &str) -> KernelView {
    let rejected = |code: &str, locus: serde_json::Value, message: String| KernelView {
        code: Some(code.into()),
        locus: Some(locus),
        message,
        ..KernelView::default()
    };
    if kind_of(text, KernelEncoding::Ron, Kind::Basin).is_ok_and(|(kind, _)| kind == Kind::Basin) {
        return match verify_basin_text_in(text, KernelEncoding::Ron, Default::default(), &[MALACHITE, NUM]) {
            Verdict::Accepted(a) => KernelView {
                accepted: true,
                report: Report {
                    n: a.n,
                    basin: Some(([a.cc_share, a.icc_share, a.undecided_share], a.leaves)),
                    ..Report::default()
                },
                orbit_boxes: Some(a.orbit_boxes),
                time_to_rest_bound: Some(a.time_to_rest_bound),
                ..KernelView::default()
            },
            Verdict::Rejected(r) => {
                rejected(r.code.as_str(), serde_json::to_value(&r.locus).unwrap(), r.message())
            }
            Verdict::Disagree(d) => KernelView { disagree: Some(d), ..KernelView::default() },
        };
    }
    if kind_of(text, KernelEncoding::Ron, Kind::Rest).is_ok_and(|(kind, _)| kind == Kind::Rest) {
        return match verify_rest_text_in(text, KernelEncoding::Ron, Default::default(), &[MALACHITE, NUM]) {
            Verdict::Accepted(a) => KernelView {
                accepted: true,
                report: Report {
                    claim: a.claim.name().into(),
                    n: a.n,
                    rest_nodes: Some(a.nodes),
                    ..Report::default()
                },
                time_to_rest_bound: Some(Some(a.bound)),
                ..KernelView::default()
            },
            Verdict::Rejected(r) => {
                rejected(r.code.as_str(), serde_json::to_value(&r.locus).unwrap(), r.message())
            }
            Verdict::Disagree(d) => KernelView { disagree: Some(d), ..KernelView::default() },
        };
    }
    if kind_of(text, KernelEncoding::Ron, Kind::Refutation).is_ok_and(|(kind, _)| kind == Kind::Refutation) {
        return match verify_refutation_text(text, Default::default(), &[MALACHITE, NUM]) {
            Verdict::Accepted(a) => KernelView {
                accepted: true,
                report: Report {
                    claim: a.claim.name().into(),
                    n: a.n,
                    refutation: Some((a.points, a.last, a.v_positive)),
                    ..Report::default()
                },
                ..KernelView::default()
            },
            Verdict::Rejected(r) => {
                rejected(r.code.as_str(), serde_json::to_value(&r.locus).unwrap(), r.message())
            }
            Verdict::Disagree(d) => KernelView { disagree: Some(d), ..KernelView::default() },
        };
    }
    match verify_text(text, Default::default(), &[MALACHITE, NUM]) {
        Verdict::Accepted(a) => {
            let cone = a.orbit_boxes.is_none();
            KernelView {
                accepted: true,
                report: Report {
                    claim: a.claim.name().into(),
                    n: a.n,
                    generators: cone.then_some(a.generators),
                    redundant: cone.then_some(a.redundant),
                    pieces: cone.then_some(a.pieces),
                    max_denominator_bits: cone.then_some(a.max_denominator_bits),
                    pcc: a.pcc,
                    contains_translation: cone.then_some(a.contains_translation),
                    region: a.region,
                    refutation: None,
                    basin: None,
                    rest_nodes: None,
                },
                pcc_boxes: a.pcc_boxes,
                orbit_boxes: a.orbit_boxes,
                time_to_rest_bound: Some(a.time_to_rest_bound),
                ..KernelView::default()
            }
        }
        Verdict::Rejected(r) => {
            rejected(r.code.as_str(), serde_json::to_value(&r.locus).unwrap(), r.message())
        }
        Verdict::Disagree(d) => KernelView { disagree: Some(d), ..KernelView::default() },
    }
}

fuzz_target!(|data: &[u8]| {
    let corpus = corpus();
    let plan = decode(data);
    let (name, base) = &corpus[usize::from(plan.base) % corpus.len()];
    let text = mutated(base, &plan.edits);
    let k = kernel(&text);
    if let (_, Err(f)) = differential(&text, Encoding::Ron, &k) {
        panic!("{f}\nbase {name}, edits {:?}\n{text}", plan.edits);
    }
});
