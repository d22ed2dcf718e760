//! The triangle's band above the CC threshold (issue 15 §3, docs/orbit-certificates.md §7): orbit
//! certificates at band points, checked by the kernel on both backends, against the exact S_1
//! criterion (which fails there) and the candidate criterion "S_1^2 S_2^2 has a real positive
//! dominant eigenvalue" (src/spectral/cycle.rs), decided exactly at the point and through its
//! exact thresholds in gamma.

use chatter::exact::Q;
use chatter::orbit::band::{OrbitVerdict, band_rows, cc_threshold, gamma_at};
use chatter::orbit::{Request, certify_orbit};
use chatter::spectral::criteria::{Family, Profile, cc_criterion, cc_profile};
use chatter::spectral::cycle::{
    CANDIDATE, cycle_criterion, cycle_profile, verdict_from_profile, word_product,
};
use chatter::write::write_orbit;
use chatter_kernel::exact::ParseLimits;
use chatter_kernel::model::Polygon;
use chatter_kernel::model::linalg::mat_mul;
use chatter_kernel::verify::{MALACHITE, NUM, Verdict, verify_orbit, verify_text};

fn triangle(kappa: &Q) -> Family<Q> {
    Family { n: 3, c1: Q::new(-1, 2), kappa: kappa.clone() }
}

fn body(kappa: &Q, gamma: &Q) -> Polygon<Q> {
    Polygon::new(3, kappa.clone(), gamma.clone()).unwrap()
}

/// Certifies the pattern (2, 2, 1, 1) at (kappa, gamma) and re-checks the file on both backends.
fn certified(kappa: &Q, gamma: &Q) -> bool {
    let req = Request {
        n: 3,
        kappa: kappa.clone(),
        gamma: gamma.clone(),
        pattern: Some(vec![2, 2, 1, 1]),
        drops: 0,
        max_depth: 1,
    };
    match certify_orbit(&req, &[MALACHITE, NUM]) {
        Ok(found) => {
            let cert = &found.certificate;
            assert!(matches!(verify_orbit(cert, ParseLimits::default()), Verdict::Accepted(_)));
            // The file as written, read back and checked by each backend on its own.
            let text = write_orbit(cert);
            for backend in [MALACHITE, NUM] {
                let v = verify_text(&text, ParseLimits::default(), &[backend]);
                assert!(matches!(v, Verdict::Accepted(_)), "{}: {v:?}", backend.name);
            }
            // Its pattern is a phase of (2, 2, 1, 1), possibly repeated.
            let p: Vec<u64> = cert.pattern.clone();
            assert!(
                p.len().is_multiple_of(4) && p.iter().filter(|&&j| j == 1).count() * 2 == p.len(),
                "{p:?}"
            );
            true
        }
        Err(_) => false,
    }
}

/// The profile with every threshold isolated to width 10^-12 (so that grid points decide).
fn refined(mut p: Profile<Q>) -> Profile<Q> {
    for t in &mut p.thresholds {
        t.gamma.refine_to(&Q::new(1, 1_000_000_000_000));
    }
    p
}

#[test]
fn the_word_product_is_the_velocity_map_of_one_period_and_its_rotations_share_the_spectrum() {
    let b = body(&Q::new(1, 8), &Q::new(3, 20));
    // S_1^2 S_2^2 written out, and the phase (2, 1, 1, 2) as S_2 S_1^2 S_2: the same spectrum.
    let direct = mat_mul(&mat_mul(&b.step(1), &b.step(1)), &mat_mul(&b.step(2), &b.step(2)));
    assert_eq!(word_product(&b, &CANDIDATE), direct);
    let a = cycle_criterion(&b, &CANDIDATE);
    let r = cycle_criterion(&b, &[2, 1, 1, 2]);
    assert_eq!(a.spectrum.char_poly, r.spectrum.char_poly);
    assert_eq!(a.holds, r.holds);
}

#[test]
fn the_cycle_profile_agrees_with_the_direct_decision_on_a_grid_of_gamma() {
    for kappa in [Q::new(1, 8), Q::new(3, 10)] {
        let prof = refined(cycle_profile(&triangle(&kappa), &CANDIDATE));
        assert!(!prof.thresholds.is_empty(), "kappa = {kappa}: the criterion changes somewhere in (0, 1)");
        let mut decided = 0;
        for k in 1..50 {
            let g = Q::new(k, 50);
            if let Some(v) = verdict_from_profile(&prof, &g) {
                assert_eq!(
                    v,
                    cycle_criterion(&body(&kappa, &g), &CANDIDATE).holds,
                    "kappa = {kappa}, gamma = {g}"
                );
                decided += 1;
            }
        }
        assert!(decided >= 48, "grid points lie outside the refined isolating intervals ({decided})");
    }
}

#[test]
fn the_threshold_enclosure_separates_where_s1_holds_from_where_it_fails() {
    for kappa in [Q::new(1, 20), Q::new(1, 8), Q::new(3, 10)] {
        let (lo, hi) = cc_threshold(3, &kappa, 40).expect("a CC threshold in (0, 1)");
        assert!(cc_criterion(&body(&kappa, &lo)).0, "S_1 holds just below gamma* (kappa = {kappa})");
        assert!(!cc_criterion(&body(&kappa, &hi)).0, "S_1 fails just above gamma* (kappa = {kappa})");
        let g = gamma_at(&(lo.clone(), hi.clone()), 1.0, 100_000);
        assert!(g > hi, "gamma_at stays strictly above the enclosure");
        // The same threshold as the profile's own.
        assert_eq!(cc_profile(&triangle(&kappa)).sup_lower_bound(40), Some(lo));
    }
}

#[test]
fn orbit_certificates_exist_above_gamma_star_where_the_candidate_criterion_holds_and_not_beyond() {
    // kappa = 1/8: gamma* = 0.1458980...; 7441/50000 = 1.02 gamma* certifies (pattern 2, 2, 1, 1),
    // 15319/100000 = 1.05 gamma* does not: there the producer finds no fixed point of R_P at all,
    // and the candidate criterion fails (docs/orbit-certificates.md §7).
    let kappa = Q::new(1, 8);
    let prof = refined(cycle_profile(&triangle(&kappa), &CANDIDATE));
    let (_, star_hi) = cc_threshold(3, &kappa, 40).unwrap();
    for (gamma, expect) in [(Q::new(7441, 50000), true), (Q::new(15319, 100000), false)] {
        assert!(gamma > star_hi, "above the CC threshold");
        let b = body(&kappa, &gamma);
        assert!(!cc_criterion(&b).0, "S_1's criterion fails at gamma = {gamma}");
        let holds = cycle_criterion(&b, &CANDIDATE).holds;
        assert_eq!(verdict_from_profile(&prof, &gamma), Some(holds));
        assert_eq!(certified(&kappa, &gamma), expect, "orbit certificate at gamma = {gamma}");
        assert_eq!(holds, expect, "S_1^2 S_2^2 criterion at gamma = {gamma}");
    }
    // kappa = 3/10 (gamma* = 0.0248601...): 1.05 gamma* certifies, and the criterion holds there.
    let kappa = Q::new(3, 10);
    let gamma = Q::new(261, 10000);
    let b = body(&kappa, &gamma);
    assert!(!cc_criterion(&b).0);
    assert!(cycle_criterion(&b, &CANDIDATE).holds);
    assert!(certified(&kappa, &gamma));
}

#[test]
fn band_rows_reports_the_certificate_the_criteria_and_the_drops_at_one_point() {
    let rows = band_rows(&[Q::new(1, 8)], &[1.02], 2);
    assert_eq!(rows.len(), 1);
    let row = &rows[0];
    assert_eq!(row.gamma, Q::new(7441, 50000));
    assert!(row.gamma > row.gamma_star.1 && row.gamma_star.0 < row.gamma_star.1);
    assert!(!row.cc, "S_1's criterion fails above gamma*");
    assert!(row.cycle, "S_1^2 S_2^2's criterion holds in the band");
    match &row.orbit {
        OrbitVerdict::Certified { pattern, periods, .. } => {
            assert_eq!(*periods, 1);
            assert_eq!(pattern.len(), 4);
        }
        OrbitVerdict::Failed { reason, .. } => panic!("expected a certificate: {reason}"),
    }
    assert_eq!(row.orbit.letter(), "C");
    assert_eq!(row.drops.runs, 2);
    assert_eq!(row.drops.cc + row.drops.pcc + row.drops.icc + row.drops.other, 2);
}

#[test]
fn the_band_ends_where_s1_squared_s2_squared_stops_having_a_real_positive_dominant_eigenvalue() {
    // kappa = 1/8: the criterion's exact threshold lies in [0.15258259, 0.15258261]
    // (docs/orbit-certificates.md §7). 61/400 = 0.1525 (just below it) certifies, 763/5000 =
    // 0.1526 (just above it) has no fixed point of R_P for (2, 2, 1, 1) at all.
    let kappa = Q::new(1, 8);
    let prof = refined(cycle_profile(&triangle(&kappa), &CANDIDATE));
    let edge =
        prof.thresholds.iter().find(|t| t.gamma.lo > Q::new(3, 20)).expect("the band's upper threshold");
    assert!(edge.below && !edge.above);
    let (below, above) = (Q::new(61, 400), Q::new(763, 5000));
    assert!(below < edge.gamma.lo && edge.gamma.hi < above);
    for (gamma, expect) in [(below, true), (above, false)] {
        assert!(!cc_criterion(&body(&kappa, &gamma)).0);
        assert_eq!(cycle_criterion(&body(&kappa, &gamma), &CANDIDATE).holds, expect);
        assert_eq!(certified(&kappa, &gamma), expect, "gamma = {gamma}");
    }
    // Just below gamma* (S_1's criterion holds) the (2, 2, 1, 1) fixed point exists but is a
    // saddle: one eigenvalue of R_P's Jacobian crosses 1 at gamma* (1.00400 at 729/5000).
    let gamma = Q::new(729, 5000);
    assert!(cc_criterion(&body(&kappa, &gamma)).0);
    let req = Request { n: 3, kappa, gamma, pattern: Some(vec![2, 2, 1, 1]), drops: 0, max_depth: 1 };
    match certify_orbit(&req, &[MALACHITE]) {
        Err(chatter::orbit::Failure::NoAttractingCycle(why)) => {
            assert!(why.contains("not attracting"), "{why}")
        }
        other => panic!("expected a saddle, got {:?}", other.map(|f| f.periods)),
    }
}

#[test]
fn the_band_search_finds_the_pentagons_cycle_with_its_share_and_certifies_it() {
    use chatter::orbit::search::{Plan, gamma_grid, search_point};
    let plan = Plan { kappas: Vec::new(), gammas: 0, runs: 300, budget: 3000, icc_stop: 2 };
    let (kappa, gamma) = (Q::new(961, 25600), Q::new(61, 160));
    let p = search_point(5, &kappa, &gamma, &plan, &[MALACHITE, NUM]);
    assert_eq!(p.outcomes.iter().sum::<u64>(), 300);
    assert!(!p.all_icc());
    // Every CC drop that settled is counted under its cycle; the 6-impact cycle is there.
    let six = p.cycles.iter().find(|c| c.pattern.len() == 6).expect("the cycle of 6 impacts");
    let mut steps = six.pattern.clone();
    steps.sort();
    assert_eq!(steps, vec![1, 1, 2, 3, 4, 4]);
    assert!(six.drops >= 1 && six.drops <= p.outcomes[0], "{six:?}, outcomes {:?}", p.outcomes);
    assert!(six.certificate.is_ok(), "{six:?}");
    // The γ grid starts strictly above γ*, increases and stays below 1.
    let star = cc_threshold(5, &kappa, 40).unwrap().1;
    let grid = gamma_grid(&star, 12);
    assert_eq!(grid.len(), 12);
    assert!(grid[0] > star && grid.windows(2).all(|w| w[0] < w[1]) && grid[11] < Q::int(1));
}
