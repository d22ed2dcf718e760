//! Tests of `spectral::number_field`: minimal polynomials of cos(2 pi/n) and exact arithmetic.

use chatter::exact::{Q, QExt, QField, Ring};
use chatter::spectral::number_field::{Nf, NumberField, cos_minimal_polynomial};
use chatter_kernel::exact::OrderedField;
use std::cmp::Ordering;

fn euler_phi(n: usize) -> usize {
    (1..=n).filter(|k| num_integer::gcd(*k, n) == 1).count()
}

#[test]
fn minimal_polynomials_of_cosines() {
    for n in 3..=16 {
        let psi = cos_minimal_polynomial(n);
        assert_eq!(psi.degree(), Some(euler_phi(n) / 2), "n = {n}");
        let c = (2.0 * std::f64::consts::PI / n as f64).cos();
        let v: f64 = psi.coeffs().iter().rev().fold(0.0, |acc, a| acc * c + a.to_f64());
        assert!(v.abs() < 1e-9, "cos(2 pi/{n}) is a root");
    }
    // Psi_5 = t^2 + t/2 - 1/4, i.e. 4t^2 + 2t - 1.
    assert_eq!(cos_minimal_polynomial(5).coeffs(), [Q::new(-1, 4), Q::new(1, 2), Q::int(1)]);
}

#[test]
fn arithmetic_in_q_sqrt5() {
    let k = NumberField::cos_2pi_over(5);
    let c = k.generator(); // cos(2 pi/5) = (sqrt 5 - 1)/4
    assert!((c.enclose(&Q::pow10(-20)).0.to_f64() - (0.4 * std::f64::consts::PI).cos()).abs() < 1e-15);
    let sqrt5 = c.times(&OrderedField::from_ratio(4, 1)).plus(&Ring::one());
    assert_eq!(sqrt5.times(&sqrt5), Ring::from_i64(5), "(4c + 1)^2 = 5");
    let phi = sqrt5.plus(&Ring::one()).over(&OrderedField::from_ratio(2, 1)).unwrap();
    assert_eq!(phi.times(&phi), phi.plus(&Ring::one()), "the golden ratio: phi^2 = phi + 1");
    assert_eq!(phi.over(&phi).unwrap(), Ring::one());
    let inv = <Nf as Ring>::one().over(&phi).unwrap();
    assert_eq!(inv, phi.minus(&Ring::one()), "1/phi = phi - 1");
    assert_eq!(sqrt5.minus(&Ring::from_i64(2)).sign(), Ordering::Greater);
    assert_eq!(sqrt5.minus(&QField::from_q(&Q::new(22361, 10000))).sign(), Ordering::Less);
    assert_eq!(sqrt5.minus(&QField::from_q(&Q::new(22360, 10000))).sign(), Ordering::Greater);
    assert!(phi > sqrt5.minus(&Ring::one()));
    assert_eq!(format!("{sqrt5}"), "4 c5 + 1");
}

#[test]
fn heptagon_field_has_degree_three() {
    let k = NumberField::cos_2pi_over(7);
    assert_eq!(k.degree(), 3);
    let c = k.generator();
    // 8c^3 + 4c^2 - 4c - 1 = 0 for c = cos(2 pi/7).
    let e = |x: i64| -> chatter::spectral::number_field::Nf { Ring::from_i64(x) };
    let v = e(8)
        .times(&c)
        .times(&c)
        .times(&c)
        .plus(&e(4).times(&c).times(&c))
        .minus(&e(4).times(&c))
        .minus(&e(1));
    assert!(v.is_zero());
    let inv = <Nf as Ring>::one().over(&c).unwrap();
    assert_eq!(inv.times(&c), Ring::one());
}
