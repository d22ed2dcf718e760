//! Rationals to and from floats, and rounded decimal text (untrusted, for search and display).

use super::Q;
use malachite::base::num::arithmetic::traits::Pow;
use malachite::base::num::conversion::traits::{RoundingFrom, SciMantissaAndExponent};
use malachite::base::rounding_modes::RoundingMode;
use malachite::rational::Rational;
use malachite::{Integer, Natural};

/// Direction of rounding when printing decimals.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rounding {
    Down,
    Up,
    Nearest,
}

/// Float conversions and decimal printing of [`Q`].
pub trait QExt: Sized {
    /// Nearest `f64` (for untrusted numerical code and display only).
    fn to_f64(&self) -> f64;
    /// The exact value of a finite `f64` (every float is a dyadic rational).
    fn from_f64_exact(x: f64) -> Option<Self>;
    /// Smallest dyadic `k / 2^bits` that is `>= self`.
    fn ceil_dyadic(&self, bits: u64) -> Self;
    /// Largest dyadic `k / 2^bits` that is `<= self`.
    fn floor_dyadic(&self, bits: u64) -> Self;
    /// 10^e.
    fn pow10(e: i64) -> Self;
    /// A decimal string with `digits` digits after the point, rounded to nearest.
    fn to_decimal(&self, digits: usize) -> String {
        self.decimal(digits, Rounding::Nearest)
    }
    /// A decimal string with `digits` digits after the point, rounded as asked (`Down` and `Up`
    /// give guaranteed lower and upper bounds).
    fn decimal(&self, digits: usize, rounding: Rounding) -> String;
    /// Rough decimal exponent for display (`log10 |x|`), `None` for zero.
    fn log10_abs(&self) -> Option<f64>;
}

fn mode(r: Rounding) -> RoundingMode {
    match r {
        Rounding::Down => RoundingMode::Floor,
        Rounding::Up => RoundingMode::Ceiling,
        Rounding::Nearest => RoundingMode::Nearest,
    }
}

fn dyadic(x: &Q, bits: u64, r: Rounding) -> Q {
    let scaled = x.as_rational() << bits;
    let k = Integer::rounding_from(&scaled, mode(r)).0;
    Q::from_rational(Rational::from(k) >> bits)
}

impl QExt for Q {
    fn to_f64(&self) -> f64 {
        f64::rounding_from(self.as_rational(), RoundingMode::Nearest).0
    }
    fn from_f64_exact(x: f64) -> Option<Q> {
        Rational::try_from(x).ok().map(Q::from_rational)
    }
    fn ceil_dyadic(&self, bits: u64) -> Q {
        dyadic(self, bits, Rounding::Up)
    }
    fn floor_dyadic(&self, bits: u64) -> Q {
        dyadic(self, bits, Rounding::Down)
    }
    fn pow10(e: i64) -> Q {
        let p = Rational::from(Natural::from(10u32).pow(e.unsigned_abs()));
        Q::from_rational(if e >= 0 { p } else { Rational::from(1u32) / p })
    }
    fn decimal(&self, digits: usize, rounding: Rounding) -> String {
        let scale = Rational::from(Natural::from(10u32).pow(digits as u64));
        let k = Integer::rounding_from(&(self.as_rational() * scale), mode(rounding)).0;
        let neg = k < 0u32;
        let s = malachite::base::num::arithmetic::traits::UnsignedAbs::unsigned_abs(k).to_string();
        let s = if s.len() <= digits { format!("{}{}", "0".repeat(digits + 1 - s.len()), s) } else { s };
        let (ip, fp) = s.split_at(s.len() - digits);
        let sign = if neg { "-" } else { "" };
        if digits == 0 { format!("{sign}{ip}") } else { format!("{sign}{ip}.{fp}") }
    }
    fn log10_abs(&self) -> Option<f64> {
        if *self.as_rational() == 0u32 {
            return None;
        }
        let (m, e): (f64, i64) = self.abs().as_rational().sci_mantissa_and_exponent();
        Some(m.log10() + e as f64 * std::f64::consts::LOG10_2)
    }
}
