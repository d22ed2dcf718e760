//! Exact interval arithmetic with outward rounding, and its first-order automatic
//! differentiation (docs/kernel-soundness.md §7).
//!
//! An [`Iv`] is a closed interval [lo, hi] of exact rationals. After every operation the ends are
//! rounded *outward* to dyadic rationals m 2^e with |m| < 2^(PRECISION+2) (lo down, hi up), so the
//! numbers stay short whatever the depth of the computation; rounding outward only enlarges the
//! interval, so every enclosure stays an enclosure. The rounding is exact integer arithmetic
//! (the backend's exact floor division of p 2^s by q), no floating point. A [`Dual`] carries an interval for a
//! value and one for each of its three partial derivatives, with the usual rules of forward
//! differentiation applied to intervals: if the inputs enclose a function and its gradient on a
//! box, the outputs do too.

use crate::exact::{Field, Int, Ring};
use std::cmp::Ordering;

/// Mantissa bits kept by the outward rounding.
pub const PRECISION: u64 = 64;

/// floor(num / den) for den > 0: the backend's exact floor division.
fn floor_div<Z: Int>(num: &Z, den: &Z) -> Z {
    num.div_floor(den)
}

/// The largest dyadic m 2^e <= x with |m| < 2^(PRECISION+2) on the grid of x's magnitude.
pub fn round_down<F: Field>(x: &F) -> F {
    if x.is_zero() {
        return F::zero();
    }
    let (p, q) = (x.numer(), x.denom());
    let (pb, qb) = (p.bit_length(), q.bit_length());
    // Already short: a power-of-two denominator and a short numerator.
    if pb <= PRECISION + 1 && F::Int::pow2(qb - 1) == q {
        return x.clone();
    }
    // 2^(pb-1) <= |p| < 2^pb, 2^(qb-1) <= q < 2^qb, so |x| < 2^(pb-qb+1); scale by 2^s, s = PRECISION - (pb - qb).
    let s = PRECISION as i64 - (pb as i64 - qb as i64);
    let (num, den) = if s >= 0 {
        (p.times(&F::Int::pow2(s as u64)), q)
    } else {
        (p, q.times(&F::Int::pow2(s.unsigned_abs())))
    };
    let m = floor_div(&num, &den);
    if s >= 0 {
        F::from_fraction(&m, &F::Int::pow2(s as u64))
    } else {
        F::from_int(&m.times(&F::Int::pow2(s.unsigned_abs())))
    }
}

/// The smallest dyadic >= x on the same grid: -round_down(-x).
pub fn round_up<F: Field>(x: &F) -> F {
    round_down(&x.negated()).negated()
}

/// A closed interval [lo, hi] of rationals, lo <= hi.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Iv<F> {
    /// Lower end.
    pub lo: F,
    /// Upper end.
    pub hi: F,
}

fn min_max<F: Field>(xs: [F; 4]) -> (F, F) {
    let [a, b, c, d] = xs;
    let lo = a.clone().min(b.clone()).min(c.clone()).min(d.clone());
    let hi = a.max(b).max(c).max(d);
    (lo, hi)
}

impl<F: Field> Iv<F> {
    /// [lo, hi] rounded outward (the caller guarantees lo <= hi).
    pub fn new(lo: F, hi: F) -> Self {
        Iv { lo: round_down(&lo), hi: round_up(&hi) }
    }
    /// The point x, enclosed.
    pub fn point(x: &F) -> Self {
        Iv::new(x.clone(), x.clone())
    }
    /// The point x itself, not rounded (an exact constant of the model).
    pub fn exact(x: &F) -> Self {
        Iv { lo: x.clone(), hi: x.clone() }
    }
    /// Whether the interval is one point.
    pub fn is_point(&self) -> bool {
        self.lo == self.hi
    }
    /// 0.
    pub fn zero() -> Self {
        Iv { lo: F::zero(), hi: F::zero() }
    }
    /// Sum.
    pub fn plus(&self, o: &Self) -> Self {
        Iv::new(self.lo.plus(&o.lo), self.hi.plus(&o.hi))
    }
    /// Difference.
    pub fn minus(&self, o: &Self) -> Self {
        Iv::new(self.lo.minus(&o.hi), self.hi.minus(&o.lo))
    }
    /// Negation (exact).
    pub fn negated(&self) -> Self {
        Iv { lo: self.hi.negated(), hi: self.lo.negated() }
    }
    /// Product.
    pub fn times(&self, o: &Self) -> Self {
        let (lo, hi) =
            min_max([self.lo.times(&o.lo), self.lo.times(&o.hi), self.hi.times(&o.lo), self.hi.times(&o.hi)]);
        Iv::new(lo, hi)
    }
    /// Product with an exact scalar.
    pub fn scaled(&self, c: &F) -> Self {
        let (a, b) = (self.lo.times(c), self.hi.times(c));
        if a <= b { Iv::new(a, b) } else { Iv::new(b, a) }
    }
    /// Quotient; `None` when `o` contains 0.
    pub fn over(&self, o: &Self) -> Option<Self> {
        if !o.excludes_zero() {
            return None;
        }
        let inv = |x: &F| F::one().over(x);
        let (lo, hi) = min_max([
            self.lo.times(&inv(&o.lo)?),
            self.lo.times(&inv(&o.hi)?),
            self.hi.times(&inv(&o.lo)?),
            self.hi.times(&inv(&o.hi)?),
        ]);
        Some(Iv::new(lo, hi))
    }
    /// 0 is not in the interval.
    pub fn excludes_zero(&self) -> bool {
        self.lo.is_positive() || self.hi.is_negative()
    }
    /// The intersection with `o`, or `self` when they are disjoint (cannot happen for two
    /// enclosures of the same number).
    pub fn meet(&self, o: &Self) -> Self {
        let lo = self.lo.clone().max(o.lo.clone());
        let hi = self.hi.clone().min(o.hi.clone());
        if lo.cmp(&hi) == Ordering::Greater { self.clone() } else { Iv { lo, hi } }
    }
}

/// A value and its gradient with respect to `D` parameters (three for orbit certificates, five
/// for the drops of basin certificates), all as intervals.
#[derive(Clone, Debug)]
pub struct Dual<F, const D: usize = 3> {
    /// Enclosure of the value.
    pub v: Iv<F>,
    /// Enclosures of the partial derivatives.
    pub d: [Iv<F>; D],
}

impl<F: Field, const D: usize> Dual<F, D> {
    /// A constant (zero gradient).
    pub fn constant(c: &F) -> Self {
        Dual { v: Iv::point(c), d: std::array::from_fn(|_| Iv::zero()) }
    }
    /// Sum.
    pub fn plus(&self, o: &Self) -> Self {
        Dual { v: self.v.plus(&o.v), d: std::array::from_fn(|i| self.d[i].plus(&o.d[i])) }
    }
    /// Difference.
    pub fn minus(&self, o: &Self) -> Self {
        Dual { v: self.v.minus(&o.v), d: std::array::from_fn(|i| self.d[i].minus(&o.d[i])) }
    }
    /// Negation.
    pub fn negated(&self) -> Self {
        Dual { v: self.v.negated(), d: std::array::from_fn(|i| self.d[i].negated()) }
    }
    /// Product: (fg)' = f'g + fg'.
    pub fn times(&self, o: &Self) -> Self {
        Dual {
            v: self.v.times(&o.v),
            d: std::array::from_fn(|i| self.d[i].times(&o.v).plus(&self.v.times(&o.d[i]))),
        }
    }
    /// Product with an exact scalar.
    pub fn scaled(&self, c: &F) -> Self {
        Dual { v: self.v.scaled(c), d: std::array::from_fn(|i| self.d[i].scaled(c)) }
    }
    /// Quotient: (f/g)' = (f' - (f/g) g')/g; `None` when g's enclosure contains 0.
    pub fn over(&self, o: &Self) -> Option<Self> {
        let q = self.v.over(&o.v)?;
        let mut d: [Iv<F>; D] = std::array::from_fn(|_| Iv::zero());
        for (i, di) in d.iter_mut().enumerate() {
            *di = self.d[i].minus(&q.times(&o.d[i])).over(&o.v)?;
        }
        Some(Dual { v: q, d })
    }
}

/// A quantity over a box Y = c + [-r, r] of parameters: an enclosure of its value at the centre c
/// (`c`), and of its value and gradient over Y (`b`). After every operation the value over Y is
/// intersected with the mean-value form c + ∇f(Y)(Y - c) (mean value theorem: the operations
/// are smooth on Y, as every divisor's enclosure excludes 0), which keeps the enclosures of
/// long computations tight (docs/kernel-soundness.md §7).
#[derive(Clone, Debug)]
pub struct Centred<F, const D: usize = 3> {
    /// Enclosure of f(c).
    pub c: Iv<F>,
    /// Enclosure of f and ∇f over Y.
    pub b: Dual<F, D>,
    /// The symmetric intervals [-r_k, r_k] (`None` for a constant).
    pub r: Option<std::sync::Arc<[Iv<F>; D]>>,
}

impl<F: Field, const D: usize> Centred<F, D> {
    /// The seed x = c + (y - c) with the given gradient: value `c` at the centre, `over` on Y.
    pub fn seed(c: Iv<F>, over: Iv<F>, d: [Iv<F>; D], r: std::sync::Arc<[Iv<F>; D]>) -> Self {
        Centred { c, b: Dual { v: over, d }, r: Some(r) }.tightened()
    }

    fn tightened(mut self) -> Self {
        if let Some(r) = &self.r {
            let mut v = self.c.clone();
            for (dk, rk) in self.b.d.iter().zip(r.iter()) {
                v = v.plus(&dk.times(rk));
            }
            self.b.v = self.b.v.meet(&v);
        }
        self
    }

    fn with(c: Iv<F>, b: Dual<F, D>, x: &Self, y: &Self) -> Self {
        let r = x.r.clone().or_else(|| y.r.clone());
        Centred { c, b, r }.tightened()
    }

    /// A constant.
    pub fn constant(k: &F) -> Self {
        Centred { c: Iv::point(k), b: Dual::constant(k), r: None }
    }
    /// Sum.
    pub fn plus(&self, o: &Self) -> Self {
        Self::with(self.c.plus(&o.c), self.b.plus(&o.b), self, o)
    }
    /// Difference.
    pub fn minus(&self, o: &Self) -> Self {
        Self::with(self.c.minus(&o.c), self.b.minus(&o.b), self, o)
    }
    /// Product.
    pub fn times(&self, o: &Self) -> Self {
        Self::with(self.c.times(&o.c), self.b.times(&o.b), self, o)
    }
    /// Product with an exact scalar.
    pub fn scaled(&self, k: &F) -> Self {
        Centred { c: self.c.scaled(k), b: self.b.scaled(k), r: self.r.clone() }
    }
    /// A constant known by an enclosure `k` (zero gradient; docs/kernel-soundness.md §7.1).
    pub fn enclosed(k: &Iv<F>) -> Self {
        Centred { c: k.clone(), b: Dual { v: k.clone(), d: std::array::from_fn(|_| Iv::zero()) }, r: None }
    }
    /// Product with a constant known by an enclosure `k`: [`Self::scaled`] when `k` is a point,
    /// else interval products (each encloses the product for every constant in `k`).
    pub fn scaled_by(&self, k: &Iv<F>) -> Self {
        if k.is_point() {
            return self.scaled(&k.lo);
        }
        let b = Dual { v: self.b.v.times(k), d: std::array::from_fn(|i| self.b.d[i].times(k)) };
        Centred { c: self.c.times(k), b, r: self.r.clone() }
    }
    /// Quotient; `None` when the divisor's enclosure over Y contains 0.
    pub fn over(&self, o: &Self) -> Option<Self> {
        Some(Self::with(self.c.over(&o.c)?, self.b.over(&o.b)?, self, o))
    }
}
