//! Exact scalars: the ordered-ring and ordered-field traits that the model and the rules are
//! generic over, their two independent backends (malachite's `Rational`, the main one, and
//! num-rational's `BigRational`), the canonical `"p/q"` text of a rational, and (feature
//! `field`) the number fields Q(cos 2 pi/n) with their own root isolation.
//!
//! Arithmetic methods have distinct names (`plus`, `times`, ...) rather than operator
//! traits, so generic code needs no higher-ranked bounds and reads the same on both backends.

/// Implements [`Ring`] for a type whose arithmetic operators on references are exact: `zero`,
/// `from_i64` and `sign` given, `plus`, `minus`, `times` and `negated` by the operators.
macro_rules! ring_by_operators {
    ($t:ty, $zero:expr, $from:expr, $sign:expr) => {
        impl Ring for $t {
            fn zero() -> Self {
                $zero
            }
            fn from_i64(v: i64) -> Self {
                $from(v)
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
                $sign(self)
            }
        }
    };
}

mod canonical;
#[cfg(feature = "field")]
mod cos_field;
mod malachite_backend;
mod num_backend;
#[cfg(any(feature = "field", feature = "proof"))]
pub mod univariate;

pub use canonical::{NumberError, ParseLimits, parse_canonical, parse_canonical_parts, to_canonical};
#[cfg(feature = "field")]
pub use cos_field::{Algebraic, AlgebraicInt, CosField, GENERATOR, MAX_N, cos_minimal_polynomial};

use std::cmp::Ordering;
use std::fmt::{Debug, Display};

/// An exact ordered commutative ring (the integers of a backend, or a field viewed as a ring).
pub trait Ring: Clone + Eq + Ord + Debug + Display + Send + Sync + 'static {
    /// The additive identity.
    fn zero() -> Self;
    /// The image of an `i64`.
    fn from_i64(v: i64) -> Self;
    /// `self + o`.
    fn plus(&self, o: &Self) -> Self;
    /// `self - o`.
    fn minus(&self, o: &Self) -> Self;
    /// `self * o`.
    fn times(&self, o: &Self) -> Self;
    /// `-self`.
    fn negated(&self) -> Self;
    /// Sign as an ordering against zero.
    fn sign(&self) -> Ordering;

    /// The multiplicative identity.
    fn one() -> Self {
        Self::from_i64(1)
    }
    /// `self == 0`.
    fn is_zero(&self) -> bool {
        self.sign() == Ordering::Equal
    }
    /// `self > 0`.
    fn is_positive(&self) -> bool {
        self.sign() == Ordering::Greater
    }
    /// `self < 0`.
    fn is_negative(&self) -> bool {
        self.sign() == Ordering::Less
    }
}

/// Exact integers of a backend.
pub trait Int: Ring {
    /// Non-negative greatest common divisor (gcd(0, 0) = 0).
    fn gcd(&self, o: &Self) -> Self;
    /// Exact quotient; the caller guarantees `o` divides `self`.
    fn div_exact(&self, o: &Self) -> Self;
    /// The quotient rounded towards minus infinity (`o` non-zero).
    fn div_floor(&self, o: &Self) -> Self;
    /// Parses a non-empty string of ASCII decimal digits (no sign).
    fn parse_digits(s: &str) -> Option<Self>;
    /// Number of bits of the absolute value (0 for zero).
    fn bit_length(&self) -> u64;
    /// 2^k, by a shift (the dyadic enclosures of orbit, basin and number-field checks).
    fn pow2(k: u64) -> Self;
}

/// An exact ordered field: the rationals, or an exact real number field such as Q(sqrt 5).
pub trait OrderedField: Ring {
    /// Quotient; `None` when dividing by zero.
    fn over(&self, o: &Self) -> Option<Self>;
    /// The rational n / d (d != 0).
    fn from_ratio(n: i64, d: i64) -> Self;
}

/// The rationals of a backend: an ordered field with integer numerators and denominators.
pub trait Field: OrderedField {
    /// The integers of the same backend.
    type Int: Int;
    /// Name of the bignum library behind this field.
    const BACKEND: &'static str;
    /// `n / d`, reduced; `d` must be non-zero.
    fn from_fraction(n: &Self::Int, d: &Self::Int) -> Self;
    /// Numerator of the reduced form (carries the sign).
    fn numer(&self) -> Self::Int;
    /// Denominator of the reduced form (always positive).
    fn denom(&self) -> Self::Int;

    /// The integer `n` as a rational.
    fn from_int(n: &Self::Int) -> Self {
        Self::from_fraction(n, &Self::Int::one())
    }
}

/// Least common multiple of positive integers (1 for an empty list).
pub fn lcm_all<'a, Z: Int>(xs: impl IntoIterator<Item = &'a Z>) -> Z {
    let mut l = Z::one();
    for x in xs {
        let g = l.gcd(x);
        l = l.times(&x.div_exact(&g));
    }
    l
}

/// Scales a list of rationals by the positive lcm of their denominators, giving integers with
/// the same ratios and signs (a positive multiple of the same vector).
pub fn scale_to_ints<F: Field>(xs: &[F]) -> Vec<F::Int> {
    let dens: Vec<F::Int> = xs.iter().map(Field::denom).collect();
    let l = lcm_all(dens.iter());
    xs.iter().zip(&dens).map(|(x, d)| x.numer().times(&l.div_exact(d))).collect()
}
