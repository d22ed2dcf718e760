//! The exact fields the exact simulator runs in (issue 10 §1): the rationals (the rod and
//! n = 3, 4, 6) and Q(cos 2π/n) for every other regular n-gon, as elements of the kernel's
//! [`Algebraic`] field. Both are [`OrderedField`]s with exact signs; what the simulator needs
//! beyond that is to read a magnitude far outside `f64`'s exponent range ([`SimField::magnitude`])
//! and a rational lower bound of a positive number ([`SimField::rational_below`]).

use super::snapshot::{Scaled, scaled};
use crate::exact::{Algebraic, CosField, OrderedField, Q, QField, Ring};
use std::cell::RefCell;
use std::cmp::Ordering;
use std::collections::HashMap;

/// An exact ordered field of the simulator.
pub trait SimField: OrderedField {
    /// |x| as m · 2^e (m in [1, 2), m = 0 for x = 0), to `f64` precision.
    fn magnitude(&self) -> Scaled;
    /// For x > 0, a rational r with 0 < r ≤ x and x - r ≤ 2^-60 x (x itself for a rational).
    fn rational_below(&self) -> Q;
    /// For x > 0, a rational r with x ≤ r ≤ (1 + 2^-60) x (x itself for a rational).
    fn rational_above(&self) -> Q;
    /// x = 0, read from the representation (no sign computation).
    fn is_exactly_zero(&self) -> bool;
    /// The exact sign, as [`crate::exact::Ring::sign`], computed with the simulator's cached
    /// enclosures of the field's generator.
    fn fast_sign(&self) -> Ordering;
    /// x < 0 by [`SimField::fast_sign`].
    fn below_zero(&self) -> bool {
        self.fast_sign() == Ordering::Less
    }

    /// The same number as an element of the kernel's [`Algebraic`] scalars (a rational, or an
    /// element of Q(cos 2π/n)), for the kernel's membership tests (issue 22 §1).
    fn to_exact(&self) -> Nf;

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
    fn is_exactly_zero(&self) -> bool {
        self.is_zero()
    }
    fn fast_sign(&self) -> Ordering {
        self.sign()
    }
    fn to_exact(&self) -> Nf {
        Nf::rational(self.clone())
    }
}

/// An element of Q(cos 2π/n) over malachite.
pub type Nf = Algebraic<Q>;

/// 2^e as a rational.
fn pow2(e: i64) -> Q {
    let two = Q::int(2);
    let mut r = Q::int(1);
    let (mut b, mut k) = (if e < 0 { Q::new(1, 2) } else { two }, e.unsigned_abs());
    while k > 0 {
        if k & 1 == 1 {
            r = &r * &b;
        }
        b = &b * &b;
        k >>= 1;
    }
    r
}

/// Rational bounds of c = cos 2π/n of width at most 2^-bits, cached per thread and field (the
/// kernel's enclosure starts from its isolating interval at every call; the simulator reads
/// thousands of magnitudes in one field).
fn cos_enclosure(n: u64, bits: i64) -> (Q, Q) {
    thread_local! {
        static CACHE: RefCell<HashMap<u64, (i64, Q, Q)>> = RefCell::new(HashMap::new());
    }
    CACHE.with(|cache| {
        let mut cache = cache.borrow_mut();
        if let Some((_, lo, hi)) = cache.get(&n).filter(|(b, _, _)| *b >= bits) {
            return (lo.clone(), hi.clone());
        }
        let field = CosField::<Q>::new(n).expect("an element's field exists");
        let (lo, hi) = field.generator().enclose(&pow2(-bits));
        cache.insert(n, (bits, lo.clone(), hi.clone()));
        (lo, hi)
    })
}

/// Bounds of Σ a_i c^i for c in [lo, hi] (Horner in interval arithmetic).
fn horner(coeffs: &[Q], lo: &Q, hi: &Q) -> (Q, Q) {
    let mut acc = (Q::int(0), Q::int(0));
    for a in coeffs.iter().rev() {
        let p = [&acc.0 * lo, &acc.0 * hi, &acc.1 * lo, &acc.1 * hi];
        let mn = p.iter().min().expect("four").clone();
        let mx = p.iter().max().expect("four").clone();
        acc = (mn + a, mx + a);
    }
    acc
}

/// Rational bounds lo ≤ x ≤ hi of an irrational x (never 0) that pass `good`: c is enclosed
/// ever more tightly (from 2^-64 times the largest coefficient's scale, |c| < 1) until they do.
/// `good` must hold of every narrow enough interval of one sign around x.
fn enclosure(x: &Nf, good: impl Fn(&Q, &Q) -> bool) -> (Q, Q) {
    let n = x.field_n().expect("an irrational element has a field");
    let top = x.coeffs().iter().map(|a| scaled(a).e).max().unwrap_or(0);
    let mut bits = (64 - top).max(128);
    loop {
        let (c_lo, c_hi) = cos_enclosure(n, bits);
        let (lo, hi) = horner(x.coeffs(), &c_lo, &c_hi);
        if lo.sign() == hi.sign() && lo.sign() != Ordering::Equal && good(&lo, &hi) {
            return (lo, hi);
        }
        bits += bits / 2;
    }
}

/// Rational bounds lo ≤ x ≤ hi of an irrational x, of one sign, with
/// hi - lo ≤ 2^-60 min(|lo|, |hi|).
fn relative_enclosure(x: &Nf) -> (Q, Q) {
    let tight = pow2(-60);
    enclosure(x, |lo, hi| {
        let small = if lo.is_negative() { -hi } else { lo.clone() };
        hi - lo <= &small * &tight
    })
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
    fn is_exactly_zero(&self) -> bool {
        self.coeffs().is_empty()
    }
    fn fast_sign(&self) -> Ordering {
        match self.as_rational() {
            Some(r) => r.sign(),
            None => enclosure(self, |lo, hi| lo.sign() == hi.sign()).0.sign(),
        }
    }
    fn to_exact(&self) -> Nf {
        self.clone()
    }
}
