//! General convex bodies in the simulator (docs/model.md §11, §11.10): regular polygons given as
//! general bodies simulate like the regular model, exact energy, `f64` against exact, and the
//! affine image of the square plate (the rectangle plate) against the square.

use crate::common::q;
use chatter::bodies::convex::{polygon_plate, rectangle_plate, regular_polygon_exact, uniform_box};
use chatter::exact::{Q, Ring};
use chatter::simulate::convex::regular_rational;
use chatter::simulate::{
    Engine, ExactEngine, FloatEngine, FloatSystem, Model, Options, Outcome, Shape, SplitMix64, Start, Step,
    System, drive, exact_drop, random_drop,
};
use chatter_kernel::model::{ConvexBody, Mat2};

/// Irregular bodies: a rectangle plate, a box, a triangle plate, a quadrilateral with a
/// non-diagonal J.
fn irregular(gamma: &str) -> Vec<ConvexBody<Q>> {
    let g = || q(gamma);
    let pts = |s: &[(&str, &str)]| s.iter().map(|(x, y)| [q(x), q(y)]).collect::<Vec<_>>();
    vec![
        rectangle_plate(&q("2"), &q("1"), g()).unwrap(),
        uniform_box(&q("150"), &q("75"), &q("8"), g()).unwrap(),
        polygon_plate(&pts(&[("0", "0"), ("4", "0"), ("1", "3")]), g()).unwrap(),
        ConvexBody::new(
            pts(&[("1", "-1/2"), ("3/2", "1"), ("-1", "2/3"), ("-2/3", "-1")]),
            [[q("1/3"), q("-1/10")], [q("-1/10"), q("1/2")]],
            g(),
        )
        .unwrap(),
    ]
}

/// A random rational start in the paper's coordinates: contacts above the floor, v < 0.
fn rational_start(sys: &System, rng: &mut SplitMix64) -> Start<Q> {
    loop {
        let r = |rng: &mut SplitMix64, lo: i64, den: i64| Q::new(lo + (rng.next_u64() % 21) as i64, den);
        let s = Start {
            q: [r(rng, -10, 200), r(rng, -10, 200), r(rng, 10, 10)],
            p: [r(rng, -10, 40), r(rng, -10, 40), r(rng, -20, 10)],
        };
        let q3 = s.q.clone();
        if (0..sys.n()).all(|k| !sys.along(k, &q3).is_negative()) && s.p[2].is_negative() {
            return s;
        }
    }
}

#[test]
fn regular_polygons_as_general_bodies_simulate_like_the_regular_model() {
    let opts = Options::new(200);
    let mut compared = 0;
    for (n, kappa, gamma) in [
        (3, "3/20", "1/20"),
        (3, "1/8", "1/200"),
        (4, "1/6", "1/100"),
        (4, "1", "3/10"),
        (6, "1/40", "1/100"),
        (6, "1/3", "1/2"),
    ] {
        let regular = Model::new(Shape::Polygon(n), q(kappa), q(gamma)).unwrap();
        let general = regular_polygon_exact(n as usize, &q(kappa), &q(gamma)).unwrap();
        let sys = System::convex(&general);
        let fs = FloatSystem::rounded(&sys);
        assert_eq!(
            fs.pcc_possible, regular.float.pcc_possible,
            "n={n} kappa={kappa} gamma={gamma}: PCC rule"
        );
        for seed in 0..25 {
            let a = drive(
                &mut FloatEngine::new(&regular.float, &random_drop(&regular.float, seed)),
                &regular.float,
                &opts,
            );
            let b = drive(&mut FloatEngine::new(&fs, &random_drop(&fs, seed)), &fs, &opts);
            assert_eq!(a.outcome, b.outcome, "n={n} kappa={kappa} gamma={gamma} seed {seed}");
            let k = a.sequence.len().min(b.sequence.len()).min(60);
            assert_eq!(a.sequence[..k], b.sequence[..k], "n={n} kappa={kappa} gamma={gamma} seed {seed}");
            compared += 1;
        }
    }
    assert_eq!(compared, 150);
}

#[test]
fn the_square_as_a_general_body_simulates_exactly_like_the_regular_square() {
    let opts = Options::new(120);
    for (kappa, gamma) in [("1/6", "1/100"), ("1", "3/10"), ("1/10", "1/2")] {
        let regular = Model::new(Shape::Polygon(4), q(kappa), q(gamma)).unwrap();
        let general = Model::new(Shape::Convex(4), q(kappa), q(gamma)).unwrap();
        assert_eq!(general.shape(), Shape::Convex(4));
        for seed in 0..6 {
            let init = chatter::simulate::Initial::RandomDrop { seed };
            let a = chatter::simulate::simulate(&regular, &init, chatter::simulate::Arithmetic::Exact, &opts);
            let b = chatter::simulate::simulate(&general, &init, chatter::simulate::Arithmetic::Exact, &opts);
            assert_eq!(a.outcome, b.outcome, "kappa={kappa} gamma={gamma} seed {seed}");
            let k = a.sequence.len().min(b.sequence.len()).min(60);
            assert_eq!(a.sequence[..k], b.sequence[..k], "kappa={kappa} gamma={gamma} seed {seed}");
        }
    }
}

#[test]
fn the_exact_triangle_in_q_sqrt3_agrees_with_f64() {
    let general = regular_polygon_exact(3, &q("3/20"), &q("1/20")).unwrap();
    let sys = System::convex(&general);
    let fs = FloatSystem::rounded(&sys);
    let opts = Options::new(40);
    for seed in 0..3 {
        let f = drive(&mut FloatEngine::new(&fs, &random_drop(&fs, seed)), &fs, &opts);
        let e = drive(&mut ExactEngine::new(&sys, &exact_drop(&fs, seed)), &fs, &opts);
        assert_eq!(f.sequence, e.sequence, "seed {seed}");
        // General bodies have no certified sets: the exact run's CC is evidence, as f64's.
        assert_eq!(f.evidence, e.evidence, "seed {seed}");
        assert!(e.proved || e.outcome == Outcome::Undecided, "seed {seed}");
    }
}

#[test]
fn exact_energy_decreases_at_every_impact_of_irregular_bodies() {
    for body in irregular("1/10") {
        let sys = System::convex(&body);
        let mut rng = SplitMix64::new(body.n() as u64);
        let mut impacts = 0;
        for _ in 0..3 {
            let mut e = ExactEngine::new(&sys, &rational_start(&sys, &mut rng));
            let mut before = e.energy();
            for _ in 0..25 {
                let Step::Impact { .. } = e.step() else { break };
                let after = e.energy();
                assert!(after < before, "{:?}: {after} >= {before}", body.contacts());
                before = after;
                impacts += 1;
            }
        }
        assert!(impacts >= 3, "too few impacts ({impacts})");
    }
}

#[test]
fn exact_energy_is_conserved_at_gamma_one_for_irregular_bodies() {
    for body in irregular("1") {
        let sys = System::convex(&body);
        let mut rng = SplitMix64::new(7);
        let mut impacts = 0;
        for _ in 0..3 {
            let mut e = ExactEngine::new(&sys, &rational_start(&sys, &mut rng));
            let e0 = e.energy();
            for _ in 0..25 {
                let Step::Impact { .. } = e.step() else { break };
                assert_eq!(e.energy(), e0, "{:?}", body.contacts());
                impacts += 1;
            }
        }
        assert!(impacts >= 3, "too few impacts ({impacts})");
    }
}

#[test]
fn f64_and_exact_agree_on_irregular_bodies() {
    let opts = Options::new(60);
    let mut agreeing = 0;
    for body in irregular("1/20") {
        let m = Model::convex(&body);
        for seed in 0..8 {
            let init = chatter::simulate::Initial::RandomDrop { seed };
            let f = chatter::simulate::simulate(&m, &init, chatter::simulate::Arithmetic::Float, &opts);
            let e = chatter::simulate::simulate(&m, &init, chatter::simulate::Arithmetic::Exact, &opts);
            if f.evidence == Outcome::Simultaneous || e.evidence == Outcome::Simultaneous {
                continue; // a near-tie: the arithmetics may differ
            }
            assert_eq!(f.sequence, e.sequence, "{:?} seed {seed}", body.contacts());
            assert_eq!(f.evidence, e.evidence, "{:?} seed {seed}", body.contacts());
            agreeing += 1;
        }
    }
    assert!(agreeing >= 24, "only {agreeing} runs compared");
}

/// The rectangle plate a x b is the image of the square plate (contacts (±1, 0), (0, ±1),
/// kappa = 1/6) under L = [[a/2, a/2], [-b/2, b/2]] (docs/model.md §11.7): states map by T and
/// contact heights and speeds are unchanged, so transported drops give the same impacts exactly.
#[test]
fn the_rectangle_plate_simulates_transported_drops_exactly_like_the_square() {
    let opts = Options::new(100);
    for (a, b, gamma) in [("2", "1", "1/100"), ("4", "1", "1/20"), ("3", "5", "1/5")] {
        let square = regular_rational(4, q("1/6"), q(gamma)).unwrap();
        let l: Mat2<Q> = [[q(a) / Q::int(2), q(a) / Q::int(2)], [-(q(b) / Q::int(2)), q(b) / Q::int(2)]];
        let image = chatter::model::affine::affine_image(&square, &l).expect("det L > 0");
        let rect = rectangle_plate(&q(a), &q(b), q(gamma)).unwrap();
        assert_eq!(image.body.contacts(), rect.contacts());
        assert_eq!(image.body.inertia(), rect.inertia());
        let (ms, mr) = (Model::convex(&square), Model::convex(&rect));
        for seed in 0..5 {
            let s = exact_drop(&ms.float, seed);
            let t = Start { q: image.velocity(&s.q), p: image.velocity(&s.p) };
            let rs = drive(&mut ExactEngine::new(ms.system(), &s), &ms.float, &opts);
            let rr = drive(&mut ExactEngine::new(mr.system(), &t), &mr.float, &opts);
            assert_eq!(rs.sequence, rr.sequence, "{a} x {b} seed {seed}");
            assert_eq!(rs.outcome, rr.outcome, "{a} x {b} seed {seed}");
        }
    }
}

#[test]
fn the_rectangle_plate_classifies_like_the_square_on_a_grid_of_gamma() {
    let opts = Options::new(200);
    for gamma in ["0", "1/100", "1/20", "1/5", "1/2", "9/10"] {
        let square = Model::convex(&regular_rational(4, q("1/6"), q(gamma)).unwrap());
        let rect = Model::convex(&rectangle_plate(&q("2"), &q("1"), q(gamma)).unwrap());
        assert_eq!(square.float.pcc_possible, rect.float.pcc_possible, "gamma {gamma}");
        let count = |m: &Model| {
            let runs = chatter::simulate::simulate_many(
                m,
                0,
                40,
                chatter::simulate::Arithmetic::Float,
                &opts,
                &|| {},
            );
            chatter::simulate::counts(&runs)
        };
        let (cs, cr) = (count(&square), count(&rect));
        // The dominant outcome agrees (the random drops themselves are not transported here).
        let top = |c: [usize; 6]| (0..6).max_by_key(|&i| c[i]).unwrap();
        assert_eq!(top(cs), top(cr), "gamma {gamma}: square {cs:?}, rectangle {cr:?}");
    }
}
