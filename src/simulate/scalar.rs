//! The exact fields the exact simulator runs in (issue 10 §1): the rationals (the rod and
//! n = 3, 4, 6) and Q(cos 2π/n) for every other regular n-gon, as elements of the kernel's
//! [`Algebraic`] field. Both are [`OrderedField`]s with exact signs; what the simulator needs
//! beyond that is to read a magnitude far outside `f64`'s exponent range ([`SimField::magnitude`])
//! and a rational lower bound of a positive number ([`SimField::rational_below`]).

use super::snapshot::{Scaled, scaled};
use crate::exact::{Algebraic, OrderedField, Q, QExt, Ring};
use std::cmp::Ordering;

/// An exact ordered field of the simulator.
pub trait SimField: OrderedField {
    /// |x| as m · 2^e (m in [1, 2), m = 0 for x = 0), to `f64` precision.
    fn magnitude(&self) -> Scaled;
    /// For x > 0, a rational r with 0 < r ≤ x and x - r ≤ 2^-60 x (x itself for a rational).
    fn rational_below(&self) -> Q;
    /// For x > 0, a rational r with x ≤ r ≤ (1 + 2^-60) x (x itself for a rational).
    fn rational_above(&self) -> Q;

    /// The nearest `f64` (0 on underflow, infinite on overflow).
    fn approx(&self) -> f64 {
        let m = self.magnitude().to_f64();
        if self.is_negative() { -m } else { m }
    }
}

impl SimField for Q {
    fn magnitude(&self) -> Scaled {
        scaled(self)
    }
    fn rational_below(&self) -> Q {
        self.clone()
    }
    fn rational_above(&self) -> Q {
        self.clone()
    }
}

/// An element of Q(cos 2π/n) over malachite.
pub type Nf = Algebraic<Q>;

/// Rational bounds lo ≤ x ≤ hi of a non-zero x, of one sign, with hi - lo ≤ 2^-60 min(|lo|, |hi|):
/// the absolute width of the kernel's enclosure is narrowed until it is small relative to x.
fn relative_enclosure(x: &Nf) -> (Q, Q) {
    let tight = Q::from_f64_exact(2f64.powi(-60)).expect("finite");
    let mut width = Q::from_f64_exact(2f64.powi(-64)).expect("finite");
    loop {
        let (lo, hi) = x.enclose(&width);
        if lo.sign() == hi.sign() && lo.sign() != Ordering::Equal {
            let small = if lo.is_negative() { -&hi } else { lo.clone() };
            if &hi - &lo <= &small * &tight {
                return (lo, hi);
            }
            width = &small * &tight;
        } else {
            width = &width * &tight;
        }
    }
}

impl SimField for Nf {
    fn magnitude(&self) -> Scaled {
        match self.as_rational() {
            Some(r) => scaled(&r),
            None => scaled(&relative_enclosure(self).0),
        }
    }
    fn rational_below(&self) -> Q {
        self.as_rational().unwrap_or_else(|| relative_enclosure(self).0)
    }
    fn rational_above(&self) -> Q {
        self.as_rational().unwrap_or_else(|| relative_enclosure(self).1)
    }
}
