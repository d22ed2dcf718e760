//! Rational enclosures of π and of cos 2π/n from alternating power series (the kernel isolates
//! the root of its minimal polynomial with Sturm sequences instead): consecutive partial sums of
//! an alternating series with decreasing terms bracket its value. All bounds are rounded outward
//! to dyadic rationals so that their size stays proportional to the precision.

use super::rational::{Rat, dyadic_bounds, ratio};
use num_traits::{One, Signed, Zero};

/// Bounds [lo, hi] of arctan(1/m) (m ≥ 2) with hi - lo < 2^-bits, from
/// arctan x = x - x³/3 + x⁵/5 - ...
fn arctan_inverse(m: i64, bits: u32) -> (Rat, Rat) {
    let x = ratio(1, m);
    let x2 = &x * &x;
    let tiny = Rat::new(One::one(), num_bigint::BigInt::one() << (bits + 4));
    let (mut sum, mut power, mut k) = (Rat::zero(), x.clone(), 0i64);
    loop {
        let term = &power / Rat::from_integer((2 * k + 1).into());
        let next = if k % 2 == 0 { &sum + &term } else { &sum - &term };
        if term < tiny {
            let (a, b) = if next < sum { (next, sum) } else { (sum, next) };
            return (dyadic_bounds(&a, bits + 4).0, dyadic_bounds(&b, bits + 4).1);
        }
        sum = next;
        power = &power * &x2;
        k += 1;
    }
}

/// Bounds [lo, hi] of π (Machin: π = 16 arctan(1/5) - 4 arctan(1/239)), width < 2^-(bits - 5).
pub fn pi_bounds(bits: u32) -> (Rat, Rat) {
    let (a_lo, a_hi) = arctan_inverse(5, bits);
    let (b_lo, b_hi) = arctan_inverse(239, bits);
    let (sixteen, four) = (Rat::from_integer(16.into()), Rat::from_integer(4.into()));
    (&sixteen * &a_lo - &four * &b_hi, &sixteen * &a_hi - &four * &b_lo)
}

/// Bounds of cos x for 0 ≤ x ≤ 13/10 (the terms x^{2k}/(2k)! decrease there), width < 2^-bits.
fn cos_point(x: &Rat, bits: u32) -> (Rat, Rat) {
    assert!(!x.is_negative() && *x <= ratio(13, 10), "cos series on [0, 13/10]");
    let x2 = x * x;
    let tiny = Rat::new(One::one(), num_bigint::BigInt::one() << (bits + 4));
    let (mut sum, mut term, mut k) = (Rat::one(), Rat::one(), 0i64);
    loop {
        term = &term * &x2 / Rat::from_integer(((2 * k + 1) * (2 * k + 2)).into());
        let next = if k % 2 == 0 { &sum - &term } else { &sum + &term };
        if term < tiny {
            let (a, b) = if next < sum { (next, sum) } else { (sum, next) };
            return (dyadic_bounds(&a, bits + 4).0, dyadic_bounds(&b, bits + 4).1);
        }
        sum = next;
        k += 1;
    }
}

/// Bounds [lo, hi] of cos 2π/n for n ≥ 5 (so 2π/n < 13/10, where cos decreases), width about
/// 2^-bits: cos is decreasing, so cos([θ_lo, θ_hi]) = [cos θ_hi, cos θ_lo].
pub fn cos_bounds(n: u32, bits: u32) -> (Rat, Rat) {
    assert!(n >= 5, "the series enclosure is for n ≥ 5");
    let (p_lo, p_hi) = pi_bounds(bits + 8);
    let two_over_n = ratio(2, i64::from(n));
    let (t_lo, t_hi) = (&two_over_n * &p_lo, &two_over_n * &p_hi);
    (cos_point(&t_hi, bits + 2).0, cos_point(&t_lo, bits + 2).1)
}
