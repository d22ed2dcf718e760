//! `Q`: the tool's exact rational, a newtype over malachite's `Rational` (the kernel's main
//! backend) whose text form is the canonical `"p/q"` (also in serde), with operators and the
//! kernel's [`Ring`]/[`OrderedField`]/[`Field`] traits. The kernel itself runs on malachite's
//! `Rational` directly; conversions to and from floats are in `float`.

use super::{Field, NumberError, ParseLimits, QField, Ring, parse_canonical, to_canonical};
use chatter_kernel::exact::OrderedField;
use malachite::Integer;
use malachite::base::num::arithmetic::traits::Sign;
use malachite::base::num::logic::traits::SignificantBits;
use malachite::rational::Rational;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};
use std::str::FromStr;

/// An exact rational number (malachite backend) with canonical `"p/q"` text.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Q(Rational);

impl Q {
    /// The rational n / d; panics if d = 0 (a programming error, never input).
    pub fn new(n: i64, d: i64) -> Q {
        assert!(d != 0, "Q::new: zero denominator");
        Q(Rational::from_signeds(n, d))
    }
    /// The integer n.
    pub fn int(n: i64) -> Q {
        Q(Rational::from(n))
    }
    /// Wraps a malachite rational.
    pub fn from_rational(r: Rational) -> Q {
        Q(r)
    }
    /// The malachite rational inside.
    pub fn as_rational(&self) -> &Rational {
        &self.0
    }
    /// Absolute value.
    pub fn abs(&self) -> Q {
        if self.0 < 0u32 { Q(-&self.0) } else { self.clone() }
    }
    /// Bits of the denominator of the reduced form.
    pub fn denominator_bits(&self) -> u64 {
        self.0.to_denominator().significant_bits()
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
        Sign::sign(&self.0)
    }
}

impl OrderedField for Q {
    fn over(&self, o: &Self) -> Option<Self> {
        if o.0 == 0u32 { None } else { Some(Q(&self.0 / &o.0)) }
    }
    fn from_ratio(n: i64, d: i64) -> Self {
        Q::new(n, d)
    }
}

impl QField for Q {
    fn from_q(q: &Q) -> Self {
        q.clone()
    }
    fn enclose(&self, _width: &Q) -> (Q, Q) {
        (self.clone(), self.clone())
    }
    fn nearest_f64(&self) -> f64 {
        super::QExt::to_f64(self)
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
