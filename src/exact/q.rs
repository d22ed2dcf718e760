//! `Q`: the project's exact rational, a newtype over malachite's `Rational` whose text form is
//! the canonical `"p/q"` (also in serde), plus the [`Ring`]/[`Int`]/[`Field`] impls for the
//! malachite backend.

use super::{Field, Int, NumberError, OrderedField, ParseLimits, Ring, parse_canonical, to_canonical};
use malachite::base::num::arithmetic::traits::{DivExact, Gcd, Sign, UnsignedAbs};
use malachite::base::num::conversion::traits::{RoundingFrom, SciMantissaAndExponent};
use malachite::base::num::logic::traits::SignificantBits;
use malachite::base::rounding_modes::RoundingMode;
use malachite::rational::Rational;
use malachite::{Integer, Natural};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};
use std::str::FromStr;

/// Direction of rounding when printing decimals.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rounding {
    Down,
    Up,
    Nearest,
}

/// An exact rational number (malachite backend) with canonical `"p/q"` text.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Q(pub Rational);

impl Q {
    pub fn new(n: i64, d: i64) -> Q {
        assert!(d != 0, "Q::new: zero denominator");
        Q(Rational::from_signeds(n, d))
    }
    pub fn int(n: i64) -> Q {
        Q(Rational::from(n))
    }
    /// Nearest `f64` (for untrusted numerical code and display only).
    pub fn to_f64(&self) -> f64 {
        f64::rounding_from(&self.0, RoundingMode::Nearest).0
    }
    /// The exact value of a finite `f64` (every float is a dyadic rational).
    pub fn from_f64_exact(x: f64) -> Option<Q> {
        Rational::try_from(x).ok().map(Q)
    }
    /// Absolute value.
    pub fn abs(&self) -> Q {
        if self.0 < 0u32 { Q(-&self.0) } else { self.clone() }
    }
    /// Bits of the denominator of the reduced form.
    pub fn denominator_bits(&self) -> u64 {
        self.0.to_denominator().significant_bits()
    }
    /// Smallest dyadic `k / 2^bits` that is `>= self`.
    pub fn ceil_dyadic(&self, bits: u64) -> Q {
        let scaled = &self.0 << bits;
        let k = Integer::rounding_from(&scaled, RoundingMode::Ceiling).0;
        Q(Rational::from(k) >> bits)
    }
    /// Largest dyadic `k / 2^bits` that is `<= self`.
    pub fn floor_dyadic(&self, bits: u64) -> Q {
        let scaled = &self.0 << bits;
        let k = Integer::rounding_from(&scaled, RoundingMode::Floor).0;
        Q(Rational::from(k) >> bits)
    }
    /// 10^e.
    pub fn pow10(e: i64) -> Q {
        let p = Rational::from(Natural::from(10u32).pow_u64(e.unsigned_abs()));
        Q(if e >= 0 { p } else { Rational::from(1u32) / p })
    }
    /// A decimal string with `digits` digits after the point, rounded to nearest.
    pub fn to_decimal(&self, digits: usize) -> String {
        self.decimal(digits, Rounding::Nearest)
    }
    /// A decimal string with `digits` digits after the point, rounded as asked (`Down` and `Up`
    /// give guaranteed lower and upper bounds).
    pub fn decimal(&self, digits: usize, rounding: Rounding) -> String {
        let scale = Rational::from(Natural::from(10u32).pow_u64(digits as u64));
        let mode = match rounding {
            Rounding::Down => RoundingMode::Floor,
            Rounding::Up => RoundingMode::Ceiling,
            Rounding::Nearest => RoundingMode::Nearest,
        };
        let k = Integer::rounding_from(&(&self.0 * scale), mode).0;
        let neg = k < 0u32;
        let s = k.unsigned_abs().to_string();
        let s = if s.len() <= digits { format!("{}{}", "0".repeat(digits + 1 - s.len()), s) } else { s };
        let (ip, fp) = s.split_at(s.len() - digits);
        let sign = if neg { "-" } else { "" };
        if digits == 0 { format!("{sign}{ip}") } else { format!("{sign}{ip}.{fp}") }
    }
    /// Rough decimal exponent for display (`log10 |x|`), `None` for zero.
    pub fn log10_abs(&self) -> Option<f64> {
        if self.0 == 0u32 {
            return None;
        }
        let (m, e): (f64, i64) = self.abs().0.sci_mantissa_and_exponent();
        Some(m.log10() + e as f64 * std::f64::consts::LOG10_2)
    }
}

trait PowU64 {
    fn pow_u64(self, e: u64) -> Self;
}
impl PowU64 for Natural {
    fn pow_u64(self, e: u64) -> Natural {
        use malachite::base::num::arithmetic::traits::Pow;
        self.pow(e)
    }
}

impl fmt::Display for Q {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&to_canonical(self))
    }
}

impl fmt::Debug for Q {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}", to_canonical(self))
    }
}

impl FromStr for Q {
    type Err = NumberError;
    /// Strict canonical parse with the default limits.
    fn from_str(s: &str) -> Result<Q, NumberError> {
        parse_canonical(s, ParseLimits::default())
    }
}

impl Serialize for Q {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&to_canonical(self))
    }
}

impl<'de> Deserialize<'de> for Q {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Q, D::Error> {
        let s = String::deserialize(d)?;
        s.parse().map_err(serde::de::Error::custom)
    }
}

macro_rules! q_binop {
    ($tr:ident, $m:ident, $op:tt) => {
        impl $tr<&Q> for &Q {
            type Output = Q;
            fn $m(self, o: &Q) -> Q {
                Q(&self.0 $op &o.0)
            }
        }
        impl $tr<Q> for Q {
            type Output = Q;
            fn $m(self, o: Q) -> Q {
                Q(self.0 $op o.0)
            }
        }
        impl $tr<&Q> for Q {
            type Output = Q;
            fn $m(self, o: &Q) -> Q {
                Q(self.0 $op &o.0)
            }
        }
        impl $tr<Q> for &Q {
            type Output = Q;
            fn $m(self, o: Q) -> Q {
                Q(&self.0 $op o.0)
            }
        }
    };
}
q_binop!(Add, add, +);
q_binop!(Sub, sub, -);
q_binop!(Mul, mul, *);
q_binop!(Div, div, /);

impl Neg for Q {
    type Output = Q;
    fn neg(self) -> Q {
        Q(-self.0)
    }
}
impl Neg for &Q {
    type Output = Q;
    fn neg(self) -> Q {
        Q(-&self.0)
    }
}

impl Ring for Q {
    fn zero() -> Self {
        Q(Rational::from(0u32))
    }
    fn from_i64(v: i64) -> Self {
        Q(Rational::from(v))
    }
    fn plus(&self, o: &Self) -> Self {
        Q(&self.0 + &o.0)
    }
    fn minus(&self, o: &Self) -> Self {
        Q(&self.0 - &o.0)
    }
    fn times(&self, o: &Self) -> Self {
        Q(&self.0 * &o.0)
    }
    fn negated(&self) -> Self {
        Q(-&self.0)
    }
    fn sign(&self) -> Ordering {
        self.0.sign()
    }
}

impl OrderedField for Q {
    fn over(&self, o: &Self) -> Option<Self> {
        if o.0 == 0u32 { None } else { Some(Q(&self.0 / &o.0)) }
    }
    fn from_ratio(n: i64, d: i64) -> Self {
        Q::new(n, d)
    }
    fn from_q(q: &Q) -> Self {
        q.clone()
    }
    fn enclose(&self, _width: &Q) -> (Q, Q) {
        (self.clone(), self.clone())
    }
}

impl Field for Q {
    type Int = Integer;
    const BACKEND: &'static str = "malachite";
    fn from_fraction(n: &Integer, d: &Integer) -> Self {
        Q(Rational::from_integers_ref(n, d))
    }
    fn numer(&self) -> Integer {
        Integer::from_sign_and_abs(self.0 >= 0u32, self.0.to_numerator())
    }
    fn denom(&self) -> Integer {
        Integer::from(self.0.to_denominator())
    }
}

impl Ring for Integer {
    fn zero() -> Self {
        Integer::from(0u32)
    }
    fn from_i64(v: i64) -> Self {
        Integer::from(v)
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
        Sign::sign(self)
    }
}

impl Int for Integer {
    fn gcd(&self, o: &Self) -> Self {
        Integer::from(self.unsigned_abs_ref().gcd(o.unsigned_abs_ref()))
    }
    fn div_exact(&self, o: &Self) -> Self {
        DivExact::div_exact(self, o)
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
}
