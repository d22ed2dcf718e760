//! Exact scalars for the tool: everything of [`chatter_kernel::exact`], plus untrusted
//! conveniences the kernel does not need: the rational [`Q`] with operators and serde, numbers
//! typed by a user (decimals, scientific notation), conversions between rationals and floats or
//! rounded decimals, and [`QField`] (rationals into any exact field, rational enclosures).

mod float;
mod q;
mod user;

pub use chatter_kernel::exact::*;
pub use float::{QExt, Rounding};
pub use q::Q;
pub use user::parse_user_number;

use num_rational::BigRational;

/// An exact ordered field that contains the rationals, with rational enclosures of its elements
/// (the tool's conversions; the kernel never needs them).
pub trait QField: chatter_kernel::exact::OrderedField {
    /// Any rational, exactly.
    fn from_q(q: &Q) -> Self;
    /// Rational bounds lo <= self <= hi with hi - lo <= width (lo = hi = self for a rational).
    fn enclose(&self, width: &Q) -> (Q, Q);
    /// The nearest float (for the untrusted float search): the midpoint of an enclosure of
    /// width 2^-60, rounded.
    fn nearest_f64(&self) -> f64 {
        let (lo, hi) = self.enclose(&Q::new(1, 1 << 60));
        ((lo + hi) / Q::int(2)).to_f64()
    }
}

/// The exact ordered fields the tool computes in: the kernel's [`chatter_kernel::exact::OrderedField`]
/// with the conversions of [`QField`]. It shadows the kernel's trait of the same name in this
/// module, so that generic code bounded by it may convert rationals; implement the kernel's trait
/// and [`QField`], and this one follows.
pub trait OrderedField: chatter_kernel::exact::OrderedField + QField {}

impl<T: chatter_kernel::exact::OrderedField + QField> OrderedField for T {}

impl QField for BigRational {
    fn from_q(q: &Q) -> Self {
        let parse = |z: malachite::Integer| z.to_string().parse().expect("decimal digits");
        BigRational::new(parse(Field::numer(q)), parse(Field::denom(q)))
    }
    fn enclose(&self, _width: &Q) -> (Q, Q) {
        let q: Q = self.to_string().parse().expect("num-rational prints canonical p/q");
        (q.clone(), q)
    }
}

impl<F: Field + QField> QField for Algebraic<F> {
    fn from_q(q: &Q) -> Self {
        Algebraic::rational(F::from_q(q))
    }
    fn enclose(&self, width: &Q) -> (Q, Q) {
        let (a, b) = self.bounds(&F::from_q(width));
        (a.enclose(width).0, b.enclose(width).1)
    }
}
