//! The second, independent backend: num-rational's `BigRational` over num-bigint's `BigInt`.
//! The kernel runs on both; a disagreement is an internal error.

use super::{Field, Int, OrderedField, Ring};
use num_bigint::{BigInt, Sign};
use num_integer::Integer as _;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

ring_by_operators!(BigInt, <BigInt as Zero>::zero(), BigInt::from, |x: &BigInt| match x.sign() {
    Sign::Minus => Ordering::Less,
    Sign::NoSign => Ordering::Equal,
    Sign::Plus => Ordering::Greater,
});

impl Int for BigInt {
    fn gcd(&self, o: &Self) -> Self {
        num_integer::Integer::gcd(self, o)
    }
    fn div_exact(&self, o: &Self) -> Self {
        let (q, r) = self.div_rem(o);
        debug_assert!(Zero::is_zero(&r), "div_exact: inexact division");
        q
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
}

ring_by_operators!(
    BigRational,
    <BigRational as Zero>::zero(),
    |v| BigRational::from_integer(BigInt::from(v)),
    |x: &BigRational| {
        if Zero::is_zero(x) {
            Ordering::Equal
        } else if Signed::is_negative(x) {
            Ordering::Less
        } else {
            Ordering::Greater
        }
    }
);

impl OrderedField for BigRational {
    fn over(&self, o: &Self) -> Option<Self> {
        if Zero::is_zero(o) { None } else { Some(self / o) }
    }
    fn from_ratio(n: i64, d: i64) -> Self {
        BigRational::new(BigInt::from(n), BigInt::from(d))
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
