//! Verification speed: the trusted kernel on a 64-generator certificate, per backend and both
//! (targets of issue 2: <= 1 ms median on malachite, <= 3 ms for both backends together), and the
//! proof checker on the square-case proof.

use chatter::exact::{ParseLimits, Q};
use chatter_kernel::certificate::read;
use chatter_kernel::check::check;
use criterion::{Criterion, criterion_group, criterion_main};
use num_rational::BigRational;
use std::hint::black_box;

const PATH: &str =
    concat!(env!("CARGO_MANIFEST_DIR"), "/certificates/valid/n3-kappa3_20-gamma1_20-64-generators.ron");
const SQUARE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/certificates/valid/doc-example-square.ron");
const PROOF: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/proofs/square.ron");

fn bench(c: &mut Criterion) {
    let text = std::fs::read_to_string(PATH).expect("benchmark certificate");
    let cert = read(&text).expect("readable");
    assert_eq!(cert.cone.len(), 64, "the benchmark certificate has 64 generators");
    let limits = ParseLimits::default();
    assert!(check::<Q>(&cert, limits).is_ok());

    let mut g = c.benchmark_group("verify-64-generators");
    g.bench_function("malachite", |b| b.iter(|| check::<Q>(black_box(&cert), limits).is_ok()));
    g.bench_function("num-rational", |b| b.iter(|| check::<BigRational>(black_box(&cert), limits).is_ok()));
    g.bench_function("both", |b| {
        b.iter(|| chatter_kernel::verify::verify(black_box(&cert), limits));
    });
    g.bench_function("read+both", |b| {
        b.iter(|| {
            chatter_kernel::verify::verify_text(
                black_box(&text),
                limits,
                &[chatter_kernel::verify::MALACHITE, chatter_kernel::verify::NUM],
            )
        });
    });
    g.finish();

    let square = read(&std::fs::read_to_string(SQUARE).unwrap()).unwrap();
    c.bench_function("verify-square-example-both", |b| {
        b.iter(|| chatter_kernel::verify::verify(black_box(&square), limits))
    });

    // The square-case proof (proofs/square.ron): read and check, one backend and both.
    let proof_text = std::fs::read_to_string(PROOF).expect("the committed proof");
    let proof = chatter_kernel::proof::read(&proof_text).expect("readable");
    let mut g = c.benchmark_group("check-square-proof");
    g.sample_size(20);
    g.bench_function("malachite", |b| {
        b.iter(|| chatter_kernel::proof::check::<Q>(black_box(&proof), limits).is_ok())
    });
    g.bench_function("num-rational", |b| {
        b.iter(|| chatter_kernel::proof::check::<BigRational>(black_box(&proof), limits).is_ok())
    });
    g.bench_function("read+both", |b| {
        b.iter(|| chatter_kernel::verify::verify_proof_text(black_box(&proof_text), limits))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
