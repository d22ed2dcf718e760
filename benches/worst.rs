//! The heaviest files the default limits allow, one per kind (issue 23 §3, target: each under 5 s
//! on both backends): built by `kernel/tests/all/worst/files.rs` (whose test asserts their verdicts),
//! verified here on both backends, read included.

#[path = "../kernel/tests/all/worst/files.rs"]
mod files;

use chatter_kernel::exact::ParseLimits;
use chatter_kernel::syntax::Encoding;
use chatter_kernel::verify::{BOTH, verify_refutation_text_in, verify_text};
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

fn bench(c: &mut Criterion) {
    let limits = ParseLimits::default();
    let mut g = c.benchmark_group("worst-file-both-backends");
    g.sample_size(10).warm_up_time(Duration::from_millis(1)).measurement_time(Duration::from_secs(1));
    for f in files::files(std::path::Path::new(env!("CARGO_MANIFEST_DIR"))) {
        g.bench_function(f.name, |b| {
            b.iter(|| {
                if f.name.starts_with("refutation") {
                    black_box(verify_refutation_text_in(&f.text, Encoding::Ron, limits, &BOTH));
                } else {
                    black_box(verify_text(&f.text, limits, &BOTH));
                }
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
