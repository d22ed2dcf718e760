//! Regular n-gons with irrational cos 2π/n (issue 10 §1): `f64` simulation on the float model,
//! exact start checks in Q(cos 2π/n), and the float model against the exact one for n = 3, 4, 6.

use crate::common::q;
use chatter::simulate::{
    Arithmetic, Initial, Model, Options, Outcome, Shape, StartError, counts, random_drop, regular, simulate,
    simulate_float, simulate_many,
};
use chatter::sweep::point::{criteria, float_model};

fn model(n: u64, kappa: &str, gamma: &str) -> Model {
    Model::new(Shape::Polygon(n), q(kappa), q(gamma)).expect("valid body")
}

/// Outcome counts of `runs` random drops from seed 0 in `f64`.
fn batch(m: &Model, runs: u64, budget: usize) -> [usize; Outcome::COUNT] {
    counts(&simulate_many(m, 0, runs, Arithmetic::Float, &Options::new(budget), &|| {}))
}

/// The paper's random drops on the float model end as the exact CC criterion (docs/model.md §6)
/// predicts: all CC where it holds (κ = 1/200), all ICC where it fails (κ = 1/6, and κ = 1/50 for
/// n = 12), with γ = 1/100.
#[test]
fn simulation_runs_and_classifies_for_n_5_7_8_12() {
    for (n, kappa) in [
        (5, "1/200"),
        (7, "1/200"),
        (8, "1/200"),
        (12, "1/200"),
        (5, "1/6"),
        (7, "1/6"),
        (8, "1/6"),
        (12, "1/50"),
    ] {
        let m = model(n, kappa, "1/100");
        assert!(m.exact.is_none(), "n = {n} has no exact model");
        assert_eq!((m.n(), m.shape()), (n as usize, Shape::Polygon(n)));
        let (cc, _) = criteria(n, &q(kappa), &q("1/100"));
        let c = batch(&m, 20, 2000);
        let expected = if cc { [20, 0, 0, 0, 0, 0] } else { [0, 0, 20, 0, 0, 0] };
        assert_eq!(c, expected, "n = {n}, kappa = {kappa}: CC criterion {cc}");
    }
}

/// An independent construction of the same bodies, the sweep's exact-rational polygon with the
/// `f64` cosine taken as a dyadic rational (Chebyshev recurrences in Q, frames exact or from
/// rounded rationals), gives the same outcomes drop by drop.
#[test]
fn float_model_agrees_with_the_rational_cosine_model() {
    for (n, kappa, gamma) in
        [(5, "1/50", "1/100"), (7, "1/200", "1/20"), (8, "1/50", "1/10"), (12, "1/200", "1/100")]
    {
        let m = model(n, kappa, gamma);
        let body = float_model(n, &q(kappa), &q(gamma));
        let other = Model::from_body(&chatter_kernel::model::Shape::Polygon(body));
        for seed in 0..10 {
            let opts = Options::new(500);
            let a = simulate(&m, &Initial::RandomDrop { seed }, Arithmetic::Float, &opts);
            let b = simulate(&other, &Initial::RandomDrop { seed }, Arithmetic::Float, &opts);
            assert_eq!(
                (a.outcome, a.impacts),
                (b.outcome, b.impacts),
                "n={n} kappa={kappa} gamma={gamma} seed={seed}"
            );
            assert_eq!(a.sequence, b.sequence, "n={n} seed={seed}");
        }
    }
}

/// Physics on the float model: v never decreases (the paper's Lemma on v), the energy never
/// increases, and an elastic body (γ = 1) keeps its energy.
#[test]
fn float_model_runs_obey_the_lemma_on_v_and_the_energy_balance() {
    for n in [5, 7, 8, 12, 64] {
        for gamma in ["1/20", "1"] {
            let m = model(n, "1/6", gamma);
            let opts = Options { record: true, ..Options::new(300) };
            let run = simulate(&m, &Initial::RandomDrop { seed: 3 }, Arithmetic::Float, &opts);
            assert!(run.impacts > 0, "n = {n}");
            let e0 = run.initial.energy.to_f64();
            let mut v_prev = f64::NEG_INFINITY;
            for r in &run.records {
                let s = &r.state;
                let v = s.p[2] * 2f64.powi(s.p_exp as i32);
                assert!(v >= v_prev - 1e-12 * v.abs(), "n = {n}: v decreased at impact {}", r.impact);
                v_prev = v;
                let e = s.energy.to_f64();
                if gamma == "1" {
                    assert!((e - e0).abs() <= 1e-9 * e0, "n = {n}: elastic energy {e} vs {e0}");
                } else {
                    assert!(e <= e0 * (1.0 + 1e-12), "n = {n}: energy grew at impact {}", r.impact);
                }
            }
        }
    }
}

/// Bodies with more than six contacts compute their frames on the fly; for n = 5 the table and
/// the computed frames are the same `f64` computation, so runs agree bit for bit.
#[test]
fn computed_frames_give_the_same_runs_as_the_table() {
    let m = model(5, "1/6", "1/20");
    let mut lazy = m.float.clone();
    lazy.frames.clear();
    for seed in 0..10 {
        let start = random_drop(&m.float, seed);
        let (a, b) = (
            simulate_float(&m.float, &start, &Options::new(500)),
            simulate_float(&lazy, &start, &Options::new(500)),
        );
        assert_eq!((a.outcome, &a.sequence, a.time), (b.outcome, &b.sequence, b.time), "seed {seed}");
    }
}

/// The float model of n = 3, 4, 6 simulates like the exact model rounded to `f64`: same outcomes
/// for the paper's random drops.
#[test]
fn float_model_and_exact_model_classify_alike_for_n_3_4_6() {
    for (n, kappa, gamma) in
        [(3, "3/20", "1/20"), (3, "1/8", "1/200"), (4, "1/6", "1/100"), (6, "5/24", "1/50")]
    {
        let exact = model(n, kappa, gamma);
        let float = regular::float_system(n, &q(kappa), &q(gamma)).unwrap();
        for seed in 0..20 {
            let opts = Options::new(1000);
            let a = simulate_float(&exact.float, &random_drop(&exact.float, seed), &opts);
            let b = simulate_float(&float, &random_drop(&float, seed), &opts);
            assert_eq!(a.outcome, b.outcome, "n={n} kappa={kappa} gamma={gamma} seed={seed}");
        }
    }
}

#[test]
fn given_starts_are_checked_exactly_in_the_number_field() {
    let m = model(5, "1/6", "1/100");
    let v = [q("-1"), q("-1"), q("-1")];
    // Contacts 0 and 1 on the floor, the centre at height 1: every other contact is above.
    assert!(m.given_start(&[q("0"), q("0"), q("1")], &v).is_ok());
    // All contacts on the floor, exactly 0 (not a rounding error below it).
    assert!(m.given_start(&[q("0"), q("0"), q("0")], &v).is_ok());
    // Contact 0 at height 1, contact 1 and the centre at 0: contacts 2 and 3 are below the floor.
    let e = m.given_start(&[q("1"), q("0"), q("0")], &v).unwrap_err();
    assert!(matches!(e, StartError::BelowFloor { .. }), "{e}");
    assert_eq!(
        m.given_start(&[q("1"), q("1"), q("1")], &[q("0"), q("0"), q("0")]).unwrap_err(),
        StartError::AtRest
    );
    assert!(matches!(
        m.given_start(&[q("1"), q("1")], &[q("-1"), q("-1")]).unwrap_err(),
        StartError::WrongLength { expected: 3, found: 2 }
    ));
    let start = m.given_start(&[q("1/10"), q("1/5"), q("1")], &v).unwrap();
    let run = simulate(&m, &Initial::Given(Box::new(start)), Arithmetic::Float, &Options::new(200));
    assert!(Outcome::ALL.contains(&run.outcome) && run.impacts > 0);
}
