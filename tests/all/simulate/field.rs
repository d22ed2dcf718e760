//! Exact simulation in Q(cos 2π/n) (issue 10 §1): the generic exact engine on the kernel's field
//! arithmetic, against the rational engine (n = 3, 4, 6, where the field is Q), against `f64`,
//! and by exact invariants (energy balance, exact ties, the PCC proof).

use super::{model as rational_model, random_rational_start};
use crate::common::q;
use chatter::exact::QField;
use chatter::exact::{Q, QExt, Ring};
use chatter::simulate::{
    Arithmetic, Engine, ExactEngine, Initial, Model, Nf, Options, Outcome, Shape, SplitMix64, Start, Step,
    System, exact_drop, simulate, simulate_exact,
};

fn model(n: u64, kappa: &str, gamma: &str) -> Model {
    Model::new(Shape::Polygon(n), q(kappa), q(gamma)).expect("valid body")
}

fn field_system(n: u64, kappa: &str, gamma: &str) -> System<Nf> {
    System::in_field(n, &q(kappa), &q(gamma)).expect("valid body")
}

/// A random start with small rational coordinates that the model accepts, centre moving down.
fn random_start(m: &Model, rng: &mut SplitMix64) -> Start<Q> {
    let mut r = |lo: i64, den: i64| Q::new(lo * den + (rng.next_u64() % (3 * den as u64)) as i64, den);
    loop {
        let pos: Vec<Q> = (0..3).map(|_| r(0, 97)).collect();
        let vel: Vec<Q> = (0..3).map(|_| r(-2, 89)).collect();
        if let (Ok(s), true) = (m.given_start(&pos, &vel), vel[2].is_negative()) {
            return s;
        }
    }
}

/// (contact, exact dt as f64, energy as f64) of the first `k` impacts of an engine.
fn trace<E: Engine>(e: &mut E, k: usize) -> Vec<(usize, f64, f64)> {
    let mut out = Vec::new();
    while out.len() < k {
        match e.step() {
            Step::Impact { contact, dt } => out.push((contact, dt.to_f64(), e.snapshot().energy.to_f64())),
            _ => break,
        }
    }
    out
}

/// The exact pair-chatter proof's read-out after each of the first `k` impacts (for the contact
/// hit and the one hit before it), as text.
fn pair_proofs<E: Engine>(e: &mut E, k: usize) -> Vec<String> {
    let (mut out, mut last) = (Vec::new(), None);
    for _ in 0..k {
        let Step::Impact { contact, .. } = e.step() else { break };
        if let Some(prev) = last {
            out.push(format!("{:?}", e.prove_pair(contact, prev)));
        }
        last = Some(contact);
    }
    out
}

/// For n = 3, 4, 6 the field is Q itself: the field engine (elements of the kernel's Algebraic
/// type) and the rational engine follow the same impacts with the same exact times and energies.
#[test]
fn the_field_engine_equals_the_rational_engine_where_the_cosine_is_rational() {
    for (n, kappa, gamma) in
        [(3, "3/20", "1/20"), (4, "1/40", "1/100"), (6, "1/40", "1/100"), (4, "1", "3/10")]
    {
        let m = rational_model(n, kappa, gamma);
        let fs = field_system(n, kappa, gamma);
        assert_eq!(
            fs.contacts.iter().map(|f| f.clone().map(|x| x.as_rational().unwrap())).collect::<Vec<_>>(),
            m.system().contacts
        );
        let (mut impacts, mut rng) = (0, SplitMix64::new(n));
        for seed in 0..8 {
            let start =
                if seed < 4 { exact_drop(&m.float, seed) } else { random_rational_start(&m, &mut rng) };
            let a = trace(&mut ExactEngine::new(m.system(), &start), 40);
            let b = trace(&mut ExactEngine::new(&fs, &start), 40);
            assert_eq!(a, b, "n={n} kappa={kappa} gamma={gamma} seed={seed}");
            impacts += a.len();
        }
        assert!(impacts >= 15, "n={n}: only {impacts} impacts compared");
    }
}

/// The exact PCC proof (docs/model.md §5; the pair coupling E < 0 only for n = 3, so no other
/// n-gon reaches it) gives the same verdicts, time bounds and limit velocities when it runs on
/// field elements, on runs that end by it (n = 3, κ = 1/8, γ = 147/5000: PCC).
#[test]
fn the_pair_proof_on_field_elements_equals_the_rational_one() {
    let (kappa, gamma) = ("1/8", "147/5000");
    let m = rational_model(3, kappa, gamma);
    let fs = field_system(3, kappa, gamma);
    let mut proved = 0;
    for seed in 0..6 {
        let start = exact_drop(&m.float, seed);
        let a = pair_proofs(&mut ExactEngine::new(m.system(), &start), 120);
        let b = pair_proofs(&mut ExactEngine::new(&fs, &start), 120);
        assert_eq!(a, b, "seed {seed}");
        proved += a.iter().filter(|s| s.starts_with("Some(Ok(")).count();
    }
    assert!(proved > 0, "no run reached a successful pair proof");
}

/// Every impact dissipates energy, exactly, and an elastic body (γ = 1) keeps it exactly: a
/// comparison of field elements, so a rounding error anywhere would show.
#[test]
fn exact_energy_balance_in_the_number_field() {
    for (n, kappa) in [(5, "1/20"), (7, "1/6"), (8, "1/50"), (9, "1/10"), (12, "1/200")] {
        for (gamma, elastic) in [("1/10", false), ("1", true)] {
            let m = model(n, kappa, gamma);
            let sys = m.field_system().expect("irrational cosine");
            let mut rng = SplitMix64::new(n);
            let mut e = ExactEngine::new(sys, &random_start(&m, &mut rng));
            let (mut before, mut impacts) = (e.energy(), 0);
            while let (Step::Impact { .. }, true) = (e.step(), impacts < 25) {
                let after = e.energy();
                if elastic {
                    assert_eq!(after, before, "n={n}: an elastic impact changed the energy");
                } else {
                    assert!(after < before, "n={n} gamma={gamma}: {after} >= {before}");
                }
                before = after;
                impacts += 1;
            }
            assert!(impacts >= 3, "n={n} gamma={gamma}: too few impacts to test ({impacts})");
        }
    }
}

/// Away from near-ties the exact field run and the `f64` float-model run hit the same contacts
/// in the same order, with times equal to about 1e-9.
#[test]
fn field_and_float_runs_agree_on_random_starts() {
    for (n, kappa, gamma) in
        [(5, "1/20", "1/10"), (7, "1/200", "1/50"), (8, "1/6", "1/100"), (12, "1/40", "1/20")]
    {
        let m = model(n, kappa, gamma);
        let sys = m.field_system().expect("irrational cosine");
        let mut rng = SplitMix64::new(100 + n);
        let mut compared = 0;
        for _ in 0..6 {
            let start = random_start(&m, &mut rng);
            let exact = trace(&mut ExactEngine::new(sys, &start), 30);
            let float = trace(&mut chatter::simulate::FloatEngine::new(&m.float, &start.to_f64()), 30);
            // Compare up to the first near-tie (relative gap below 1e-9 between the two runs' times).
            for (a, b) in exact.iter().zip(&float) {
                assert_eq!(a.0, b.0, "n={n}: contacts differ after {compared} equal impacts");
                assert!((a.1 - b.1).abs() <= 1e-9 * a.1.max(1e-300) + 1e-300, "n={n}: dt {} vs {}", a.1, b.1);
                compared += 1;
            }
        }
        assert!(compared >= 30, "n={n}: only {compared} impacts compared");
    }
}

/// The paper's random drops classify alike in both arithmetics (CC where the CC criterion holds,
/// ICC where it fails), and the exact report says which field it ran in.
#[test]
fn exact_field_runs_classify_like_f64() {
    for (n, kappa, gamma, expected) in [
        (5, "1/200", "1/100", Outcome::Cc),
        (7, "1/6", "1/100", Outcome::Icc),
        (8, "1/200", "1/20", Outcome::Cc),
    ] {
        let m = model(n, kappa, gamma);
        for seed in 0..3 {
            let opts = Options::new(200);
            let e = simulate(&m, &Initial::RandomDrop { seed }, Arithmetic::Exact, &opts);
            let f = simulate(&m, &Initial::RandomDrop { seed }, Arithmetic::Float, &opts);
            assert_eq!((e.evidence, f.outcome), (expected, expected), "n={n} kappa={kappa} seed={seed}");
            // Without certified sets the exact run proves only ICC.
            assert_eq!(e.proved, expected == Outcome::Icc, "n={n} kappa={kappa} seed={seed}");
            let k = e.sequence.len().min(f.sequence.len()).min(40);
            assert_eq!(e.sequence[..k], f.sequence[..k], "n={n} seed={seed}");
        }
    }
}

/// A start symmetric under the mirror that swaps contacts 0 and 1 (h0 = h1, u0 = u1) makes
/// mirror-image contacts land at the same instant: the field engine sees an exact tie, which
/// `f64` can only see as a near-tie.
#[test]
fn mirror_symmetric_starts_give_exact_ties_in_the_field() {
    for n in [5, 7, 8, 9] {
        let m = model(n, "1/20", "1/10");
        let start = m
            .given_start(&[q("1/10"), q("1/10"), q("1")], &[q("1/3"), q("1/3"), q("-1")])
            .expect("valid start");
        let run = simulate_exact(&m, &start, &Options::new(200));
        assert_eq!(run.outcome, Outcome::Simultaneous, "n={n}: {:?}", run.decision);
        assert_eq!(run.decision.key(), "exact-tie", "n={n}");
    }
}

/// The simulator's own reading of field elements (cached enclosures of c, `simulate::scalar`)
/// agrees with the kernel: signs of elements built to be tiny (a + b·c with a/b a convergent of
/// -c, down to about 2^-200) and their magnitudes to a relative 2^-50.
#[test]
fn fast_signs_and_magnitudes_agree_with_the_kernel_on_tiny_elements() {
    use chatter::exact::CosField;
    use chatter::simulate::SimField;
    for n in [5u64, 7, 8, 9, 11, 12, 16, 64] {
        let field = CosField::<Q>::new(n).unwrap();
        let c = field.generator();
        for bits in [8i64, 40, 100, 200] {
            let (lo, _) = c.enclose(&Q::from_f64_exact(2f64.powi(-bits as i32)).unwrap());
            for (a, b) in [(lo.clone(), 1), (lo.clone() * Q::int(3), 3), (-lo.clone(), -1)] {
                // x = b·c - a·(b-scaled) is within about 2^-bits of 0, never 0.
                let x = c.times(&Nf::from_q(&Q::int(b))).minus(&Nf::from_q(&a));
                assert_eq!(x.fast_sign(), x.sign(), "n={n} bits={bits}");
                let (klo, khi) = x.enclose(&(x.rational_below().abs() * Q::new(1, 1 << 40)));
                let m = x.magnitude().to_f64();
                let k = ((klo + khi) * Q::new(1, 2)).to_f64().abs();
                assert!((m - k).abs() <= k * 1e-12, "n={n} bits={bits}: {m} vs {k}");
                assert!(x.rational_below() <= x.rational_above());
            }
        }
    }
}
