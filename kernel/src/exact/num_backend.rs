//! The second, independent backend: num-rational's `BigRational` over num-bigint's `BigInt`.
//! The kernel runs on both; a disagreement is an internal error.

use super::{Field, Int, OrderedField, Ring};
use num_bigint::{BigInt, Sign};
use num_integer::Integer as _;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

impl Ring for BigInt {
    fn zero() -> Self {
        Zero::zero()
    }
    fn from_i64(v: i64) -> Self {
        BigInt::from(v)
    }
    fn plus(&self, o: &Self) -> Self {
        self + o
    }
    fn minus(&self, o: &Self) -> Self {
        self - o
    }
    fn times(&self, o: &Self) -> Self {
        self * o
    }
    fn negated(&self) -> Self {
        -self
    }
    fn sign(&self) -> Ordering {
        match BigInt::sign(self) {
            Sign::Minus => Ordering::Less,
            Sign::NoSign => Ordering::Equal,
            Sign::Plus => Ordering::Greater,
        }
    }
}

impl Int for BigInt {
    fn gcd(&self, o: &Self) -> Self {
        num_integer::Integer::gcd(self, o)
    }
    fn div_exact(&self, o: &Self) -> Self {
        let (q, r) = self.div_rem(o);
        debug_assert!(Zero::is_zero(&r), "div_exact: inexact division");
        q
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
}

impl Ring for BigRational {
    fn zero() -> Self {
        Zero::zero()
    }
    fn from_i64(v: i64) -> Self {
        BigRational::from_integer(BigInt::from(v))
    }
    fn plus(&self, o: &Self) -> Self {
        self + o
    }
    fn minus(&self, o: &Self) -> Self {
        self - o
    }
    fn times(&self, o: &Self) -> Self {
        self * o
    }
    fn negated(&self) -> Self {
        -self
    }
    fn sign(&self) -> Ordering {
        if Zero::is_zero(self) {
            Ordering::Equal
        } else if Signed::is_negative(self) {
            Ordering::Less
        } else {
            Ordering::Greater
        }
    }
    fn one() -> Self {
        One::one()
    }
}

impl OrderedField for BigRational {
    fn over(&self, o: &Self) -> Option<Self> {
        if Zero::is_zero(o) { None } else { Some(self / o) }
    }
    fn from_ratio(n: i64, d: i64) -> Self {
        BigRational::new(BigInt::from(n), BigInt::from(d))
    }
    fn from_q(q: &super::Q) -> Self {
        let parse = |z: malachite::Integer| z.to_string().parse::<BigInt>().expect("decimal digits");
        BigRational::new(parse(super::Field::numer(q)), parse(super::Field::denom(q)))
    }
    fn enclose(&self, _width: &super::Q) -> (super::Q, super::Q) {
        let q: super::Q = self.to_string().parse().expect("num-rational prints canonical p/q");
        (q.clone(), q)
    }
}

impl Field for BigRational {
    type Int = BigInt;
    const BACKEND: &'static str = "num-rational";
    fn from_fraction(n: &BigInt, d: &BigInt) -> Self {
        BigRational::new(n.clone(), d.clone())
    }
    fn numer(&self) -> BigInt {
        num_rational::Ratio::numer(self).clone()
    }
    fn denom(&self) -> BigInt {
        num_rational::Ratio::denom(self).clone()
    }
}
