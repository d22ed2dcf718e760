//! Tests of the floating-point finder and its geometry.

use crate::common::body;
use chatter::finder::geometry::{P2, clip, hull, orient, outside_distance, simplify};
use chatter::finder::{FinderConfig, FinderOutcome, Seed, find_cone, images, seed_points};
use chatter::model::FloatBody;
use nalgebra::Vector3;
use proptest::prelude::*;

fn area(p: &[P2]) -> f64 {
    (0..p.len()).map(|i| p[i].x * p[(i + 1) % p.len()].y - p[(i + 1) % p.len()].x * p[i].y).sum::<f64>() / 2.0
}

#[test]
fn hull_is_counter_clockwise_and_handles_signed_zeros() {
    // Regression: -0.0 and 0.0 sorted apart broke the lexicographic order (first bug found).
    let pts = [
        P2::new(-0.0, -2.0),
        P2::new(0.0, -2.0447),
        P2::new(0.0, 0.0447),
        P2::new(0.029, -2.48),
        P2::new(0.0447, 0.72),
    ];
    let h = hull(&pts, 0.0);
    assert!(h.iter().any(|p| p.x == 0.0 && p.y == -2.0447), "the lowest point on x = 0 is extreme: {h:?}");
    for i in 0..h.len() {
        assert!(orient(&h[i], &h[(i + 1) % h.len()], &h[(i + 2) % h.len()]) > 0.0);
    }
}

#[test]
fn hull_keeps_extreme_points_of_nearly_vertical_edges() {
    // Regression: a collinearity tolerance popped a genuine extreme vertex.
    let pts = [P2::new(-6.9e-20, -2.0), P2::new(0.0, -2.0447), P2::new(0.0, 0.0447), P2::new(0.029, -2.48)];
    let h = hull(&pts, 1e-14);
    assert!(h.contains(&P2::new(0.0, -2.0447)), "{h:?}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn simplification_is_an_outer_approximation(
        pts in prop::collection::vec((-10.0f64..10.0, -10.0f64..10.0), 8..60), budget in 3usize..12
    ) {
        let pts: Vec<P2> = pts.into_iter().map(|(x, y)| P2::new(x, y)).collect();
        let h = hull(&pts, 0.0);
        prop_assume!(h.len() >= 3);
        let s = simplify(&h, budget);
        prop_assert!(s.len() <= budget.max(3) || s.len() == h.len());
        prop_assert!(area(&s) >= area(&h) - 1e-9);
        for p in &h {
            prop_assert!(outside_distance(&s, p) <= 1e-9 * (1.0 + p.norm()), "{:?} leaves the simplified polygon", p);
        }
    }

    #[test]
    fn clipping_keeps_exactly_the_inner_part(
        pts in prop::collection::vec((-10.0f64..10.0, -10.0f64..10.0), 3..20),
        a in -1.0f64..1.0, b in -1.0f64..1.0, c in -5.0f64..5.0
    ) {
        let h = hull(&pts.into_iter().map(|(x, y)| P2::new(x, y)).collect::<Vec<_>>(), 0.0);
        prop_assume!(h.len() >= 3);
        let l = Vector3::new(a, b, c);
        let side = |p: &P2| a * p.x + b * p.y - c;
        let out = clip(&h, &l);
        for p in &out {
            prop_assert!(side(p) >= -1e-9);
            prop_assert!(outside_distance(&h, p) <= 1e-9);
        }
        for p in &h {
            if side(p) > 1e-9 {
                prop_assert!(out.contains(p));
            }
        }
    }
}

#[test]
fn square_plate_cone_is_found_and_matches_the_papers_rectangle() {
    let b = body(4, "1/6", "1/100");
    let fb = FloatBody::new(&b);
    let FinderOutcome::Found { cone: polygon, .. } = find_cone(&fb, Seed::AllDown, &FinderConfig::default())
    else {
        panic!("the square plate at gamma = 1/100 has a cone");
    };
    // The paper's cone spanned by p1, p3, s1, s3 projects to 0 <= u0 <= e2 - 1, -e1-1 <= u1 <= e1-1
    // with e1 = 1.7194, e2 = 1.04475 here; the minimal cone containing I_0(D) lies inside it.
    let xmax = polygon.iter().map(|p| p.x).fold(f64::MIN, f64::max);
    let (ymin, ymax) = polygon.iter().fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.y), b.max(p.y)));
    assert!((xmax - 0.04475).abs() < 1e-4, "{xmax}");
    assert!((ymax - 0.7194).abs() < 1e-3 && (ymin + 2.7194).abs() < 1e-3, "{ymin} {ymax}");
    // The polygon is invariant up to the tolerance.
    for q in images(&fb, &polygon).unwrap() {
        assert!(outside_distance(&polygon, &q) < 1e-8);
    }
    for s in seed_points(&fb, Seed::AllDown) {
        assert!(outside_distance(&polygon, &s) < 1e-9);
    }
}

#[test]
fn outcomes_on_both_sides_of_the_square_threshold() {
    // The paper: the square plate chatters for gamma below about 0.03.
    let cfg = FinderConfig::default();
    for (g, found) in [("1/100", true), ("1/50", true), ("3/100", false), ("1/10", false), ("1/2", false)] {
        let fb = FloatBody::new(&body(4, "1/6", g));
        let out = find_cone(&fb, Seed::Translation, &cfg);
        assert_eq!(matches!(out, FinderOutcome::Found { .. }), found, "gamma={g}: {out:?}");
        if !found {
            assert!(matches!(out, FinderOutcome::NoCone { .. }), "gamma={g}: {out:?}");
        }
    }
}

#[test]
fn a_tiny_budget_is_inconclusive() {
    let fb = FloatBody::new(&body(3, "3/20", "1/20"));
    let cfg = FinderConfig { max_iterations: 3, ..FinderConfig::default() };
    let out = find_cone(&fb, Seed::Translation, &cfg);
    assert!(matches!(out, FinderOutcome::Inconclusive { iterations: 3, .. }), "{out:?}");
    assert_eq!(out.label(), "inconclusive");
}
