//! Simulation speed (issue 4). Targets: at least 20 million impacts per second per core in f64
//! (n = 4, renormalising after every impact) and a 200-impact drop in under 20 microseconds.

use chatter::exact::Q;
use chatter::simulate::{
    Engine, FloatEngine, Model, Options, Shape, Step, random_drop, simulate_exact, simulate_float,
};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;

const IMPACTS: usize = 10_000;

fn model(n: u64, kappa: (i64, i64), gamma: (i64, i64)) -> Model {
    Model::from_body(
        &chatter_kernel::model::Shape::new(n, Q::new(kappa.0, kappa.1), Q::new(gamma.0, gamma.1))
            .expect("valid body"),
    )
}

fn bench(c: &mut Criterion) {
    // The flat square plate at gamma = 1/100 chatters for ever: every step is an impact.
    let square = model(4, (1, 6), (1, 100));
    let fs = &square.float;
    let start = random_drop(fs, 1);
    {
        let mut e = FloatEngine::new(fs, &start);
        assert_eq!(e.run_bare(IMPACTS), IMPACTS, "the benchmark drop must chatter for {IMPACTS} impacts");
        assert!(matches!(e.step(), Step::Impact { .. }));
    }
    let mut g = c.benchmark_group("f64-impacts");
    g.throughput(Throughput::Elements(IMPACTS as u64));
    g.bench_function("square-10000-impacts-renormalised", |b| {
        b.iter(|| {
            let mut e = FloatEngine::new(fs, black_box(&start));
            e.run_bare(IMPACTS)
        })
    });
    let triangle = model(3, (3, 20), (1, 20));
    let t_start = random_drop(&triangle.float, 7);
    g.bench_function("triangle-10000-impacts-renormalised", |b| {
        b.iter(|| {
            let mut e = FloatEngine::new(&triangle.float, black_box(&t_start));
            e.run_bare(IMPACTS)
        })
    });
    g.finish();

    let mut g = c.benchmark_group("drop-200-impacts");
    let opts = Options::new(200);
    g.bench_function("square-f64-classified", |b| {
        let mut seed = 0u64;
        b.iter(|| {
            seed = seed.wrapping_add(1);
            let s = random_drop(fs, seed);
            simulate_float(fs, black_box(&s), &opts).outcome
        })
    });
    g.bench_function("square-exact-classified", |b| {
        let s = chatter::simulate::exact_drop(fs, 1);
        b.iter(|| simulate_exact(&square, black_box(&s), &opts).outcome)
    });
    g.finish();

    // Exact simulation in Q(cos 2 pi/n) (issue 10 §1): one CC drop of 200 impacts per n.
    let mut g = c.benchmark_group("field-exact-200-impacts");
    g.sample_size(10);
    for n in [5u64, 7, 8, 12] {
        let m = Model::new(Shape::Polygon(n), Q::new(1, 200), Q::new(1, 100)).expect("valid body");
        let s = chatter::simulate::exact_drop(&m.float, 1);
        let _ = m.field_system();
        g.bench_function(format!("n{n}-kappa-1/200-gamma-1/100"), |b| {
            b.iter(|| simulate_exact(&m, black_box(&s), &opts).outcome)
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
