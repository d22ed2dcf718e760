//! PCC: the paper's criterion, the exact pair-chatter proof, and the PCC Lemma guard.

use super::model;
use crate::common::{GAMMAS, KAPPAS, q};
use chatter::exact::{QExt, Ring};
use chatter::simulate::pcc::prove_pair_chatter;
use chatter::simulate::{
    Decision, Engine, ExactEngine, Options, Outcome, Step, exact_drop, random_drop, simulate_exact,
    simulate_float,
};
use chatter_kernel::model::linalg::dot;

#[test]
fn the_flat_triangle_plate_shows_pcc_at_small_gamma() {
    // kappa = (1 + 2 cos^2(pi/3))/12 = 1/8; the paper reports PCC for gamma < 0.01.
    let m = model(3, "1/8", "1/200");
    assert!(m.system().pcc_possible());
    for seed in 0..20 {
        let r = simulate_float(&m.float, &random_drop(&m.float, seed), &Options::new(200));
        assert_eq!(r.outcome, Outcome::Pcc, "seed {seed}: {}", r.decision.describe());
        let Decision::PaperPcc { test, epsilon, .. } = r.decision else { panic!("{:?}", r.decision) };
        assert!(test.holds(epsilon));
        assert!(r.impacts < 30, "PCC is recognised early, before rounding: {}", r.impacts);
        let summary =
            chatter::simulate::pattern::summary_for(&r.sequence, chatter::simulate::Shape::Polygon(3));
        assert!(summary.contains("adjacent pair: PCC-like"), "{summary}");
    }
    for seed in 0..3 {
        let r = simulate_exact(&m, &exact_drop(&m.float, seed), &Options::new(200));
        assert_eq!(r.outcome, Outcome::Pcc, "exact seed {seed}: {}", r.decision.describe());
        let Decision::ExactPair { v_limit, time_bound, .. } = r.decision else { panic!("{:?}", r.decision) };
        assert!(v_limit < 0.0 && time_bound > 0.0);
        assert_eq!(r.decision.key(), "exact-pair-chatter-proof");
    }
}

#[test]
fn the_square_shows_no_pcc() {
    let m = model(4, "1/6", "1/100");
    assert!(!m.system().pcc_possible(), "kappa + cos(pi/2) > 0: an impact lifts the neighbours");
    for seed in 0..20 {
        let r = simulate_float(&m.float, &random_drop(&m.float, seed), &Options::new(200));
        assert_ne!(r.outcome, Outcome::Pcc, "seed {seed}");
        assert_eq!(r.pcc_overruled, 0);
    }
}

#[test]
fn pcc_lemma_guard_agrees_with_the_kernel_quadratic() {
    // Real eigenvalues of S_(n-1) S_1 (kernel) and E < 0 (an impact pulls the neighbour down).
    for n in [3, 4, 6] {
        for kappa in KAPPAS {
            for gamma in GAMMAS {
                let m = model(n, kappa, gamma);
                let body = chatter_kernel::model::Polygon::new(n, q(kappa), q(gamma)).unwrap();
                let quad = chatter_kernel::model::pcc_quadratic(&body).expect("1 is an eigenvalue");
                let e = &m.system().pair_coupling;
                let expected = e.is_negative() && !quad.discriminant.is_negative();
                assert_eq!(m.system().pcc_possible(), expected, "n={n} kappa={kappa} gamma={gamma}");
            }
        }
    }
    // The boundary for the triangle plate: gamma = 17 - 12 sqrt 2 = 0.02944 (E = -(1+gamma)/3).
    assert!(model(3, "1/8", "147/5000").system().pcc_possible());
    assert!(!model(3, "1/8", "59/2000").system().pcc_possible());
}

#[test]
fn exact_pair_proof_bounds_the_time_and_predicts_the_limit_velocity() {
    let m = model(3, "1/8", "1/50");
    let sys = m.system();
    let mut e = ExactEngine::new(sys, &exact_drop(&m.float, 4));
    let mut seq = Vec::new();
    let proof = loop {
        let Step::Impact { contact, .. } = e.step() else { panic!("the drop chatters") };
        seq.push(contact);
        if seq.len() >= 2 {
            let (qs, ps) = e.state();
            if let Ok(p) = prove_pair_chatter(sys, qs, ps, contact, seq[seq.len() - 2]) {
                break p;
            }
        }
        assert!(seq.len() < 40, "no proof: {seq:?}");
    };
    let (i, j) = proof.pair;
    // p* = v* m_(i,j): both pair contacts at rest, v* < 0.
    assert!(dot(&sys.contacts[i], &proof.limit_velocity).is_zero());
    assert!(dot(&sys.contacts[j], &proof.limit_velocity).is_zero());
    assert!(proof.v_limit.is_negative());
    // Keep simulating exactly: only the pair lands, within the bound, and v climbs to v*.
    let mut elapsed = 0.0;
    let mut last_v = f64::NEG_INFINITY;
    for _ in 0..40 {
        let Step::Impact { contact, dt } = e.step() else { panic!("the pair keeps chattering") };
        assert!(contact == i || contact == j);
        elapsed += dt.to_f64();
        let v = dot(&sys.centre, e.state().1);
        assert!(v <= proof.v_limit);
        assert!(v.to_f64() >= last_v);
        last_v = v.to_f64();
    }
    assert!(elapsed <= proof.time_bound.to_f64(), "{elapsed} > {}", proof.time_bound.to_f64());
    assert!((last_v - proof.v_limit.to_f64()).abs() < 1e-12);
}

#[test]
fn exact_pair_proof_refuses_where_the_lemma_excludes_pcc() {
    let m = model(3, "1/8", "3/100");
    let mut e = ExactEngine::new(m.system(), &exact_drop(&m.float, 0));
    let mut prev = None;
    for _ in 0..12 {
        let Step::Impact { contact, .. } = e.step() else { panic!() };
        if let Some(o) = prev {
            let (qs, ps) = e.state();
            let err = prove_pair_chatter(m.system(), qs, ps, contact, o).unwrap_err();
            assert!(err.contains("real eigenvalues"), "{err}");
        }
        prev = Some(contact);
    }
}

#[test]
fn the_paper_criterion_is_overruled_where_the_lemma_excludes_pcc() {
    // gamma = 0.03 > 0.02944: pair phases come within 1e-16 of m_(i,i+1) and still end (complex
    // eigenvalues): the exact run shows complete chatter through successive pair phases, and
    // f64, whose frames keep the pair's heights exact to rounding, follows it.
    let m = model(3, "1/8", "3/100");
    let opts = Options::new(200);
    let e = simulate_exact(&m, &exact_drop(&m.float, 0), &opts);
    let f = simulate_float(&m.float, &random_drop(&m.float, 0), &opts);
    for r in [&e, &f] {
        assert_eq!(r.evidence, Outcome::Cc, "{}", r.decision.describe());
        assert!(r.pcc_overruled >= 3, "{}", r.pcc_overruled);
        assert!(r.sequence.contains(&0) && r.sequence.contains(&1) && r.sequence.contains(&2));
    }
    assert_eq!(e.sequence, f.sequence);
}

#[test]
fn a_budget_ending_in_an_unsettled_pair_phase_is_undecided_never_cc() {
    // A tiny epsilon keeps the paper's criterion from holding after 7 impacts; an adjacent pair
    // alone cannot bring the body to rest, so the verdict is "undecided".
    let m = model(3, "1/8", "1/200");
    let opts = Options { pcc_epsilon: 1e-30, ..Options::new(7) };
    let r = simulate_float(&m.float, &random_drop(&m.float, 0), &opts);
    assert_eq!(r.outcome, Outcome::Undecided, "{}", r.decision.describe());
    let Decision::PairNotSettled { pair, run, .. } = &r.decision else { panic!("{:?}", r.decision) };
    assert_eq!((*pair, *run), ((0, 2), 7));
    assert_eq!(r.decision.key(), "pair-not-settled");
}
