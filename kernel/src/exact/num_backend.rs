//! The second, independent backend: num-rational's `BigRational` over num-bigint's `BigInt`.
//! The kernel runs on both; a disagreement is an internal error. The fractions are kept reduced
//! as num-rational keeps them, but with Lehmer's gcd: num-integer's binary gcd is quadratic in the
//! bits with a large constant, the bottleneck of this backend on long numbers (issue 23 §3).

use super::{Field, Int, OrderedField, Ring};
use num_bigint::{BigInt, BigUint, Sign};
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};
use std::cmp::Ordering;

// num-bigint orders its signs Minus < NoSign < Plus.
ring_by_operators!(BigInt, <BigInt as Zero>::zero(), BigInt::from, |x: &BigInt| x.sign().cmp(&Sign::NoSign));

impl Int for BigInt {
    fn gcd(&self, o: &Self) -> Self {
        gcd(self, o)
    }
    fn div_exact(&self, o: &Self) -> Self {
        self / o
    }
    fn div_floor(&self, o: &Self) -> Self {
        num_integer::Integer::div_floor(self, o)
    }
    fn parse_digits(s: &str) -> Option<Self> {
        if s.is_empty() || !s.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        BigInt::parse_bytes(s.as_bytes(), 10)
    }
    fn bit_length(&self) -> u64 {
        self.bits()
    }
    fn pow2(k: u64) -> Self {
        BigInt::from(1u8) << k
    }
}

impl Ring for BigRational {
    fn zero() -> Self {
        <BigRational as Zero>::zero()
    }
    fn from_i64(v: i64) -> Self {
        BigRational::from_integer(BigInt::from(v))
    }
    /// Henrici's sum (Knuth, TAOCP vol. 2, §4.5.1), gcds of the inputs' size: with g = gcd(b, d),
    /// b = g b', d = g d', a/b + c/d = t/(g b' d') for t = a d' + c b', and t shares only the
    /// factors of g2 = gcd(t, g) with the denominator: the sum is (t/g2)/(b' (d/g2)), reduced.
    fn plus(&self, o: &Self) -> Self {
        let (a, b, c, d) = (self.numer(), self.denom(), o.numer(), o.denom());
        let g = gcd(b, d);
        let (b1, d1) = (b / &g, d / &g);
        let t = a * &d1 + c * &b1;
        let g2 = gcd(&t, &g);
        if Zero::is_zero(&t) { Ring::zero() } else { BigRational::new_raw(&t / &g2, b1 * (d / &g2)) }
    }
    fn minus(&self, o: &Self) -> Self {
        self.plus(&-o)
    }
    /// a/b · c/d with the cross gcds gcd(a, d), gcd(c, b) divided out first: reduced.
    fn times(&self, o: &Self) -> Self {
        let (a, b, c, d) = (self.numer(), self.denom(), o.numer(), o.denom());
        if Zero::is_zero(a) || Zero::is_zero(c) {
            return Ring::zero();
        }
        let (g1, g2) = (gcd(a, d), gcd(c, b));
        BigRational::new_raw((a / &g1) * (c / &g2), (b / &g2) * (d / &g1))
    }
    fn negated(&self) -> Self {
        -self
    }
    fn sign(&self) -> Ordering {
        Ring::sign(self.numer())
    }
}

/// gcd(|x|, |y|) by [`lehmer_gcd`].
fn gcd(x: &BigInt, y: &BigInt) -> BigInt {
    BigInt::from(lehmer_gcd(x.magnitude().clone(), y.magnitude().clone()))
}

/// n/d in lowest terms with d > 0 (d != 0), as `BigRational::new` makes it, by [`lehmer_gcd`].
fn reduced(n: BigInt, d: BigInt) -> BigRational {
    let g = gcd(&n, &d);
    let (n, d) = if g.is_one() { (n, d) } else { (n / &g, d / &g) };
    if Ring::is_negative(&d) { BigRational::new_raw(-n, -d) } else { BigRational::new_raw(n, d) }
}

/// gcd(a, b): the common power of two first, gcd(2^i a', 2^j b') = 2^min(i, j) gcd(a', b'), so
/// that the dyadic numbers of orbit and basin enclosures (denominators powers of two) reduce
/// without a division; then Lehmer's method (Knuth, TAOCP vol. 2, §4.5.2, Algorithm L): the
/// quotients of Euclid's algorithm are found from the leading 64 bits while they are certain, and
/// applied to the full numbers as one 2 x 2 step; a division step where they are not.
fn lehmer_gcd(a: BigUint, b: BigUint) -> BigUint {
    let (Some(i), Some(j)) = (a.trailing_zeros(), b.trailing_zeros()) else { return a + b };
    let (x, y) = (a >> i, b >> j);
    let (mut a, mut b) = if x < y { (y, x) } else { (x, y) };
    while b.bits() > 64 {
        let shift = a.bits() - 64;
        let top = |x: &BigUint| i128::from((x >> shift).to_u64().expect("64 bits"));
        let (mut x, mut y) = (top(&a), top(&b));
        let (mut p, mut q, mut r, mut s) = (1i128, 0i128, 0i128, 1i128);
        while y + r != 0 && y + s != 0 && (x + p) / (y + r) == (x + q) / (y + s) {
            let k = (x + p) / (y + r);
            (p, q, r, s, x, y) = (r, s, p - k * r, q - k * s, y, x - k * y);
        }
        if q == 0 {
            (a, b) = (b.clone(), &a % &b);
        } else {
            let (ia, ib) = (BigInt::from(a), BigInt::from(b));
            let step = |u: i128, v: i128| (&ia * u + &ib * v).to_biguint().expect("a remainder, >= 0");
            (a, b) = (step(p, q), step(r, s));
        }
    }
    (if b.is_zero() { a } else { num_integer::Integer::gcd(&b, &(&a % &b)) }) << i.min(j)
}

impl OrderedField for BigRational {
    fn over(&self, o: &Self) -> Option<Self> {
        if Zero::is_zero(o) {
            None
        } else {
            Some(reduced(self.numer() * o.denom(), self.denom() * o.numer()))
        }
    }
    fn from_ratio(n: i64, d: i64) -> Self {
        BigRational::new(BigInt::from(n), BigInt::from(d))
    }
}

impl Field for BigRational {
    type Int = BigInt;
    const BACKEND: &'static str = "num-rational";
    fn from_fraction(n: &BigInt, d: &BigInt) -> Self {
        reduced(n.clone(), d.clone())
    }
    fn numer(&self) -> BigInt {
        num_rational::Ratio::numer(self).clone()
    }
    fn denom(&self) -> BigInt {
        num_rational::Ratio::denom(self).clone()
    }
}
