//! Polynomials in (kappa, gamma) and Bernstein bounds (`chatter_kernel::bivariate`), against
//! brute-force evaluation, and the PCC polynomials against the point model.
#![cfg(feature = "boxes")]

use chatter_kernel::bivariate::{Bi, NotNegative, Rect, negative_on};
use chatter_kernel::exact::{OrderedField, Ring};
use chatter_kernel::model::{Polygon, pcc_polynomials, pcc_quadratic};
use malachite::rational::Rational as Q;
use num_rational::BigRational;
use proptest::prelude::*;

fn q(n: i64, d: i64) -> Q {
    Q::from_ratio(n, d)
}

/// sum c_ij kappa^i gamma^j from a small integer table.
fn poly(c: &[Vec<i64>]) -> Bi<Q> {
    let k = Bi::bilinear(Q::zero(), Q::one(), Q::zero(), Q::zero());
    let g = Bi::bilinear(Q::zero(), Q::zero(), Q::one(), Q::zero());
    let mut out = Bi::constant(Q::zero());
    for (i, row) in c.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            let mut term = Bi::constant(Q::from_i64(*x));
            for _ in 0..i {
                term = term.times(&k);
            }
            for _ in 0..j {
                term = term.times(&g);
            }
            out = out.plus(&term);
        }
    }
    out
}

fn rect(k0: Q, k1: Q, g0: Q, g1: Q) -> Rect<Q> {
    Rect { kappa: [k0, k1], gamma: [g0, g1] }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Every value on the box lies between the least and the greatest Bernstein coefficient, and
    /// the corner coefficients are the values at the corners.
    #[test]
    fn bernstein_coefficients_bound_the_values(
        c in prop::collection::vec(prop::collection::vec(-20i64..20, 4), 3),
        k0 in -8i64..8, dk in 1i64..6, g0 in -8i64..8, dg in 1i64..6,
        s in 0i64..=12, t in 0i64..=12,
    ) {
        let p = poly(&c);
        let r = rect(q(k0, 4), q(k0 + dk, 4), q(g0, 3), q(g0 + dg, 3));
        let b = p.bernstein(&r);
        let lo = b.iter().flatten().min().unwrap().clone();
        let hi = b.iter().flatten().max().unwrap().clone();
        let at = |x: &Q, y: &Q| p.at(x, y);
        let x = r.kappa[0].plus(&r.kappa[1].minus(&r.kappa[0]).times(&q(s, 12)));
        let y = r.gamma[0].plus(&r.gamma[1].minus(&r.gamma[0]).times(&q(t, 12)));
        let v = at(&x, &y);
        prop_assert!(lo <= v && v <= hi);
        let (dk, dg) = (b.len() - 1, b[0].len() - 1);
        prop_assert_eq!(&b[0][0], &at(&r.kappa[0], &r.gamma[0]));
        prop_assert_eq!(&b[dk][dg], &at(&r.kappa[1], &r.gamma[1]));
        prop_assert_eq!(&b[dk][0], &at(&r.kappa[1], &r.gamma[0]));
        prop_assert_eq!(&b[0][dg], &at(&r.kappa[0], &r.gamma[1]));
    }

    /// The integer Bernstein coefficients used by `negative_on` (no fraction reduced, issue 23
    /// §3) have the signs of the rational ones, on boxes with unrelated denominators.
    #[test]
    fn the_integer_bernstein_coefficients_have_the_signs_of_the_rational_ones(
        c in prop::collection::vec(prop::collection::vec(-20i64..20, 4), 4),
        k0 in -50i64..50, dk in 1i64..40, kd in 1i64..30, g0 in -50i64..50, dg in 1i64..40, gd in 1i64..30,
    ) {
        let p = poly(&c).times(&Bi::constant(q(3, 7)));
        let r = rect(q(k0, kd), q(k0, kd).plus(&q(dk, 17)), q(g0, gd), q(g0, gd).plus(&q(dg, 13)));
        let signs = |b: Vec<Vec<Q>>| b.iter().flatten().map(Ring::sign).collect::<Vec<_>>();
        let scaled = p.bernstein_scaled(&r).iter().flatten().map(Ring::sign).collect::<Vec<_>>();
        prop_assert_eq!(signs(p.bernstein(&r)), scaled);
    }

    /// `negative_on` never claims a polynomial negative on a box where it is not: whenever it
    /// succeeds, a grid of points of the box is negative.
    #[test]
    fn negative_on_agrees_with_a_grid(
        c in prop::collection::vec(prop::collection::vec(-9i64..9, 3), 3),
    ) {
        let p = poly(&c);
        let r = rect(q(0, 1), q(1, 1), q(0, 1), q(1, 1));
        let grid_negative = (0..=8).all(|i| (0..=8).all(|j| p.at(&q(i, 8), &q(j, 8)).is_negative()));
        match negative_on(&p, &r, 2000) {
            Ok(_) => prop_assert!(grid_negative),
            Err(NotNegative::At(x, y)) => prop_assert!(!p.at(&x, &y).is_negative()),
            Err(NotNegative::Undecided(_)) => {}
        }
    }
}

#[test]
fn a_positive_bump_inside_the_box_is_found_at_a_subdivision_corner() {
    // 1/1000 - (kappa - 1/2)^2 - (gamma - 1/2)^2: negative at every corner, positive at the centre.
    let k = poly(&[vec![0], vec![1]]).minus(&Bi::constant(q(1, 2)));
    let g = poly(&[vec![0, 1]]).minus(&Bi::constant(q(1, 2)));
    let p = Bi::constant(q(1, 1000)).minus(&k.times(&k)).minus(&g.times(&g));
    let r = rect(q(0, 1), q(1, 1), q(0, 1), q(1, 1));
    for corner in [(0, 0), (1, 0), (0, 1), (1, 1)] {
        assert!(p.at(&Q::from_i64(corner.0), &Q::from_i64(corner.1)).is_negative());
    }
    assert_eq!(negative_on(&p, &r, 100), Err(NotNegative::At(q(1, 2), q(1, 2))));
}

#[test]
fn a_polynomial_that_touches_zero_is_not_proved_negative() {
    // -(kappa - gamma)^2 is 0 on the diagonal: never strictly negative on the box.
    let d = poly(&[vec![0, -1], vec![1]]);
    let p = d.times(&d).negated();
    let r = rect(q(0, 1), q(1, 1), q(0, 1), q(1, 1));
    assert!(matches!(negative_on(&p, &r, 100), Err(NotNegative::At(..))));
    // Strictly negative: -(kappa - gamma)^2 - 1/10^6 is proved with subdivision.
    let p = p.minus(&Bi::constant(q(1, 1_000_000)));
    let boxes = negative_on(&p, &r, 20_000).expect("negative everywhere");
    assert!(boxes > 1, "needs subdivision: {boxes}");
    // The same with too small a budget is undecided, never a false proof.
    assert!(matches!(negative_on(&p, &r, 4), Err(NotNegative::Undecided(_))));
}

#[test]
fn pcc_polynomials_agree_with_the_point_model() {
    // s^3 (p^2 - 4q) and s^3 (q - 1), s = (1 + kappa)^2, at many points, for n = 3, 4, 6.
    for n in [3, 4, 6] {
        let polys = pcc_polynomials(&Polygon::new(n, q(1, 7), q(1, 3)).unwrap()).unwrap();
        for (kn, kd) in [(1, 100), (1, 6), (1, 3), (2, 1), (7, 3)] {
            for (gn, gd) in [(0, 1), (1, 1000), (1, 20), (1, 2), (1, 1)] {
                let (k, g) = (q(kn, kd), q(gn, gd));
                let quad = pcc_quadratic(&Polygon::new(n, k.clone(), g.clone()).unwrap()).unwrap();
                let one_k = Q::one().plus(&k);
                let s = one_k.times(&one_k);
                let s3 = s.times(&s).times(&s);
                assert_eq!(polys.discriminant.at(&k, &g), s3.times(&quad.discriminant), "n={n} k={k} g={g}");
                assert_eq!(polys.modulus.at(&k, &g), s3.times(&quad.q.minus(&Q::one())), "n={n} k={k} g={g}");
            }
        }
    }
}

#[test]
fn the_pcc_polynomials_are_the_same_on_both_backends() {
    let a = pcc_polynomials(&Polygon::new(4, q(1, 6), q(1, 100)).unwrap()).unwrap();
    let b = pcc_polynomials(
        &Polygon::new(4, BigRational::from_ratio(1, 6), BigRational::from_ratio(1, 100)).unwrap(),
    )
    .unwrap();
    for (kn, gn) in [(1, 3), (5, 7), (2, 9)] {
        let (x, y) = (q(kn, 11), q(gn, 13));
        let (xb, yb) = (BigRational::from_ratio(kn, 11), BigRational::from_ratio(gn, 13));
        assert_eq!(a.discriminant.at(&x, &y).to_string(), b.discriminant.at(&xb, &yb).to_string());
    }
}
