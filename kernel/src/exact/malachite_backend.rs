//! The main backend: malachite's `Rational` over its `Integer`. The kernel runs on both backends;
//! a disagreement is an internal error.

use super::{Field, Int, OrderedField, Ring};
use malachite::Integer;
use malachite::base::num::arithmetic::traits::{DivExact, DivMod, Gcd, Sign};
use malachite::base::num::logic::traits::SignificantBits;
use malachite::rational::Rational;
use std::cmp::Ordering;
use std::str::FromStr;

ring_by_operators!(Rational, Rational::from(0u32), Rational::from, Sign::sign);

impl OrderedField for Rational {
    fn over(&self, o: &Self) -> Option<Self> {
        if *o == 0u32 { None } else { Some(self / o) }
    }
    fn from_ratio(n: i64, d: i64) -> Self {
        Rational::from_signeds(n, d)
    }
}

impl Field for Rational {
    type Int = Integer;
    const BACKEND: &'static str = "malachite";
    fn from_fraction(n: &Integer, d: &Integer) -> Self {
        Rational::from_integers_ref(n, d)
    }
    fn numer(&self) -> Integer {
        Integer::from_sign_and_abs(*self >= 0u32, self.to_numerator())
    }
    fn denom(&self) -> Integer {
        Integer::from(self.to_denominator())
    }
}

ring_by_operators!(Integer, Integer::from(0u32), Integer::from, Sign::sign);

impl Int for Integer {
    fn gcd(&self, o: &Self) -> Self {
        Integer::from(self.unsigned_abs_ref().gcd(o.unsigned_abs_ref()))
    }
    fn div_exact(&self, o: &Self) -> Self {
        DivExact::div_exact(self, o)
    }
    fn div_floor(&self, o: &Self) -> Self {
        DivMod::div_mod(self, o).0
    }
    fn parse_digits(s: &str) -> Option<Self> {
        if s.is_empty() || !s.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        Integer::from_str(s).ok()
    }
    fn bit_length(&self) -> u64 {
        self.significant_bits()
    }
    fn pow2(k: u64) -> Self {
        Integer::from(1u32) << k
    }
}
