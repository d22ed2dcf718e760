//! The proof shares `chatter map` prints (issue 22 §3, docs/map.md "Proof shares").

use crate::common::q;
use chatter::exact::{Q, QExt};
use chatter::orbit::band::cc_threshold;
use chatter::simulate::Outcome;
use chatter::sweep::grid::{Axis, Grid, Shard, Variable};
use chatter::sweep::point::Tasks;
use chatter::sweep::proofs::{ProofShares, decided, lines, near_threshold, shares};
use chatter::sweep::{Request, run};

#[test]
fn the_threshold_band_is_where_the_exact_cc_threshold_is_within_half_a_width() {
    // Triangle, kappa = 1/8: gamma* is about 0.1459 and the PCC threshold is far below 0.1.
    let kappa = q("1/8");
    let (lo, hi) = cc_threshold(3, &kappa, 40).expect("a CC threshold in (0, 1)");
    let half = Q::new(1, 200);
    let (mut inside, mut outside) = (0, 0);
    let star = (&lo + &hi).to_f64() / 2.0;
    for k in 100..=200 {
        let gamma = Q::new(k, 1000);
        let distance = (gamma.to_f64() - star).abs();
        if (distance - 0.005).abs() < 1e-6 {
            continue; // on the band's edge to f64 accuracy: not decided here
        }
        let expected = distance < 0.005;
        assert_eq!(near_threshold(3, &kappa, &gamma, &half), expected, "gamma = {gamma}");
        if expected { inside += 1 } else { outside += 1 }
    }
    assert!(inside >= 9 && outside >= 80, "{inside} inside, {outside} outside");
}

#[test]
fn the_median_of_the_decided_drops_times_is_the_middle_value() {
    let odd = ProofShares { seconds: vec![1.0, 2.0, 4.0], ..Default::default() };
    let even = ProofShares { seconds: vec![1.0, 2.0, 4.0, 8.0], ..Default::default() };
    assert_eq!(odd.median_seconds(), Some(2.0));
    assert_eq!(even.median_seconds(), Some(3.0));
    assert_eq!(ProofShares::default().median_seconds(), None);
    assert!(!decided(Outcome::NoIccNoPcc) && !decided(Outcome::Undecided) && decided(Outcome::Icc));
}

#[test]
fn a_map_with_proofs_times_every_drop_and_its_shares_add_up_to_the_proved_counts() {
    let grid = Grid {
        n: 3,
        variable: Variable::Kappa,
        x: Axis::parse("0.125:0.135:1").unwrap(),
        gamma: Axis::parse("0.14:0.94:2").unwrap(),
        family: None,
    };
    let tasks = Tasks { certify: false, refute: false, simulate: Some(4), proof_budget: 300 };
    let done = run(&Request { grid, tasks, shard: Shard::ALL }, &|| {});
    assert_eq!(done.len(), 2);
    let mut decided_rows = 0;
    for d in &done {
        assert_eq!(d.proof_times.len(), 4, "one time per drop");
        assert!(d.proof_times.iter().all(|(_, s)| *s > 0.0));
        let proved = d.row.sim.as_ref().and_then(|s| s.proved).expect("proved counts");
        for o in Outcome::ALL {
            let timed = d.proof_times.iter().filter(|(p, _)| *p == o).count() as u64;
            assert_eq!(timed, proved[o.index()], "{o:?} at gamma = {}", d.row.gamma);
        }
        decided_rows += Outcome::ALL.iter().filter(|o| decided(**o)).map(|o| proved[o.index()]).sum::<u64>();
    }
    let s = shares(3, &done, &Q::new(1, 200));
    assert_eq!((s.all.drops, s.all.decided), (8, decided_rows));
    assert_eq!(s.seconds.len() as u64, decided_rows);
    assert!(s.seconds.windows(2).all(|w| w[0] <= w[1]), "sorted");
    // gamma = 0.34 and 0.74 (kappa about 0.13): far from the thresholds, so nothing is in the band.
    assert_eq!((s.band_points, s.off_band), (0, s.all));
    assert!(decided_rows > 0, "the drops above the threshold are proved ICC");
    assert!(lines(3, &done)[0].contains(&format!("{decided_rows} of 8 drops")), "{:?}", lines(3, &done));
}
