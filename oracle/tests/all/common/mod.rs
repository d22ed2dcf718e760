//! Shared helpers of the differential tests: the kernel's verdict as plain data, through its
//! top-level text API only (`chatter_kernel::verify::{verify_text, verify_refutation_text,
//! Verdict, MALACHITE}`, with the tool's `chatter::verify::format_of`), and for JSON and gzip'd files through the tool's
//! `chatter::verify::verify_file`. The kernel runs on malachite alone: the differential is kernel
//! against oracle; the kernel's two backends are compared with each other on every corpus file by
//! tests/all/corpus.rs and on random input by tests/all/fuzz_smoke.rs (num-rational is several
//! times slower, and the corpus is read many times: CI, issue 23 §4).
#![allow(dead_code)]

use chatter::verify::format::format_of;
use chatter_kernel::rest::Rested;
use chatter_kernel::verify::{
    MALACHITE, Verdict, verify_basin_text_in, verify_refutation_text, verify_rest_family_text_in,
    verify_rest_text_in, verify_text,
};
use chatter_oracle::compare::{Agreement, Finding, KernelView, differential};
use chatter_oracle::read::Encoding;
use chatter_oracle::verdict::{Judgement, Report};
use std::path::{Path, PathBuf};

/// The repository root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("the oracle lives in the workspace").to_path_buf()
}

fn rejected(code: &str, locus: serde_json::Value, message: String) -> KernelView {
    KernelView { code: Some(code.to_string()), locus: Some(locus), message, ..KernelView::default() }
}

/// The kernel (both backends) on RON text: a certificate, or a refutation when the text's
/// `format` says so.
pub fn kernel_ron(text: &str) -> KernelView {
    if format_of(text).as_deref() == Some("chatter-basin-certificate") {
        return kernel_basin(text);
    }
    if format_of(text).as_deref() == Some("chatter-time-to-rest") {
        return kernel_rest(text);
    }
    if format_of(text).as_deref() == Some("chatter-family-time-to-rest") {
        return kernel_rest_family_in(text, chatter_kernel::syntax::Encoding::Ron);
    }
    if format_of(text).as_deref() == Some("chatter-refutation") {
        return match verify_refutation_text(text, Default::default(), &[MALACHITE]) {
            Verdict::Accepted(a) => KernelView {
                accepted: true,
                report: Report {
                    claim: a.claim.name().to_string(),
                    n: a.n,
                    refutation: Some((a.points, a.last, a.v_positive)),
                    ..Report::default()
                },
                ..KernelView::default()
            },
            Verdict::Rejected(r) => {
                rejected(r.code.as_str(), serde_json::to_value(&r.locus).expect("json"), r.message())
            }
            Verdict::Disagree(d) => KernelView { disagree: Some(d), ..KernelView::default() },
        };
    }
    match verify_text(text, Default::default(), &[MALACHITE]) {
        Verdict::Accepted(a) => KernelView {
            accepted: true,
            report: Report {
                claim: a.claim.name().to_string(),
                n: a.n,
                generators: a.orbit_boxes.is_none().then_some(a.generators),
                redundant: a.orbit_boxes.is_none().then_some(a.redundant),
                pieces: a.orbit_boxes.is_none().then_some(a.pieces),
                max_denominator_bits: a.orbit_boxes.is_none().then_some(a.max_denominator_bits),
                pcc: a.pcc,
                contains_translation: a.orbit_boxes.is_none().then_some(a.contains_translation),
                region: a.region,
                refutation: None,
                basin: None,
                rest_nodes: None,
            },
            pcc_boxes: a.pcc_boxes,
            orbit_boxes: a.orbit_boxes,
            time_to_rest_bound: Some(a.time_to_rest_bound),
            ..KernelView::default()
        },
        Verdict::Rejected(r) => {
            rejected(r.code.as_str(), serde_json::to_value(&r.locus).expect("json"), r.message())
        }
        Verdict::Disagree(d) => KernelView { disagree: Some(d), ..KernelView::default() },
    }
}

/// The kernel (both backends) on a basin certificate in RON: its shares, leaves and bound.
fn kernel_basin(text: &str) -> KernelView {
    use chatter_kernel::syntax::Encoding as KernelEncoding;
    match verify_basin_text_in(text, KernelEncoding::Ron, Default::default(), &[MALACHITE]) {
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
            rejected(r.code.as_str(), serde_json::to_value(&r.locus).expect("json"), r.message())
        }
        Verdict::Disagree(d) => KernelView { disagree: Some(d), ..KernelView::default() },
    }
}

/// The kernel (both backends) on a time-to-rest certificate in RON: its claim, n, nodes and B.
fn kernel_rest(text: &str) -> KernelView {
    kernel_rest_in(text, chatter_kernel::syntax::Encoding::Ron)
}

/// The kernel (both backends) on a time-to-rest certificate in either encoding.
pub fn kernel_rest_in(text: &str, encoding: chatter_kernel::syntax::Encoding) -> KernelView {
    rested(verify_rest_text_in(text, encoding, Default::default(), &[MALACHITE]))
}

/// The kernel (both backends) on a general body's time-to-rest certificate in either encoding.
pub fn kernel_rest_family_in(text: &str, encoding: chatter_kernel::syntax::Encoding) -> KernelView {
    rested(verify_rest_family_text_in(text, encoding, Default::default(), &[MALACHITE]))
}

/// A time-to-rest verdict as plain data: claim, n, nodes, region, B and (a general body over an
/// interval of γ) `gamma_interval`.
fn rested(verdict: Verdict<Rested>) -> KernelView {
    match verdict {
        Verdict::Accepted(a) => KernelView {
            accepted: true,
            report: Report {
                claim: a.claim.name().to_string(),
                n: a.n,
                rest_nodes: Some(a.nodes),
                region: a.region,
                ..Report::default()
            },
            time_to_rest_bound: Some(Some(a.bound)),
            gamma_interval: Some(a.gamma_interval),
            ..KernelView::default()
        },
        Verdict::Rejected(r) => {
            rejected(r.code.as_str(), serde_json::to_value(&r.locus).expect("json"), r.message())
        }
        Verdict::Disagree(d) => KernelView { disagree: Some(d), ..KernelView::default() },
    }
}

/// The kernel on a file through the tool's file reader (JSON, gzip, refutations).
pub fn kernel_file(path: &Path) -> KernelView {
    use chatter::verify::{Options, Status, verify_file};
    let v = verify_file(path, &Options::new(vec![MALACHITE]));
    if v.is_internal() {
        return KernelView { disagree: v.reason, ..KernelView::default() };
    }
    match v.status {
        Status::Ok => KernelView {
            accepted: true,
            report: Report {
                claim: v.claim.unwrap_or_default().to_string(),
                n: v.n.unwrap_or(0),
                generators: v.generators,
                redundant: v.redundant,
                max_denominator_bits: v.max_denominator_bits,
                contains_translation: v.contains_translation,
                region: v.region,
                refutation: v.refutation.map(|r| (r.points, r.last, r.v_positive)),
                basin: match (v.cc_share, v.icc_share, v.undecided_share, v.basin_leaves) {
                    (Some(c), Some(i), Some(u), Some(l)) => Some(([c, i, u], l)),
                    _ => None,
                },
                rest_nodes: v.rest_nodes,
                ..Report::default()
            },
            pcc_boxes: v.pcc_boxes,
            orbit_boxes: v.orbit_boxes,
            time_to_rest_bound: Some(v.time_to_rest_bound),
            gamma_interval: Some(v.gamma_interval),
            ..KernelView::default()
        },
        _ => rejected(
            v.code.map(|c| c.as_str()).unwrap_or("error"),
            serde_json::to_value(&v.locus).expect("json"),
            v.reason.unwrap_or_default(),
        ),
    }
}

/// The kernel on RON text through the tool's file reader (a temporary file): the verdict with
/// what the tool's report adds, such as a family certificate's `gamma_interval`.
pub fn kernel_text_as_file(text: &str) -> KernelView {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static COUNT: AtomicUsize = AtomicUsize::new(0);
    let name = format!("chatter-oracle-{}-{}.ron", std::process::id(), COUNT.fetch_add(1, Ordering::Relaxed));
    let path = std::env::temp_dir().join(name);
    std::fs::write(&path, text).expect("a temporary file");
    let k = kernel_file(&path);
    std::fs::remove_file(&path).expect("the temporary file");
    k
}

/// The text of a file, gunzipped when it is gzip'd (by the tool's reader).
pub fn read_text(path: &Path) -> Option<String> {
    match chatter::verify::read::read_input(path, 64 << 20) {
        chatter::verify::read::Input::Text { text, .. } => Some(text),
        _ => None,
    }
}

/// Both verdicts on a file and their comparison.
pub fn differential_file(path: &Path) -> (KernelView, Judgement, Result<Agreement, Finding>) {
    let name = path.file_name().expect("a file").to_string_lossy().to_string();
    let encoding = Encoding::of_name(&name);
    let plain_ron = encoding == Encoding::Ron && !name.to_ascii_lowercase().ends_with(".gz");
    let text = read_text(path).unwrap_or_default();
    let kernel = if plain_ron { kernel_ron(&text) } else { kernel_file(path) };
    let (oracle, cmp) = differential(&text, encoding, &kernel);
    (kernel, oracle, cmp)
}

/// Both verdicts on RON text and their comparison.
pub fn differential_ron(text: &str) -> (KernelView, Judgement, Result<Agreement, Finding>) {
    let kernel = kernel_ron(text);
    let (oracle, cmp) = differential(text, Encoding::Ron, &kernel);
    (kernel, oracle, cmp)
}
