//! Rational functions over Q in the proof variables, and normal forms modulo the
//! characteristic polynomial chi(lambda).

use super::mpoly::{L, MPoly};
use crate::exact::Q;
use std::fmt;

/// num / den with den != 0. Not reduced (no multivariate gcd): equality is tested by
/// cross-multiplication, which is exact.
#[derive(Clone)]
pub struct RatFn {
    pub num: MPoly,
    pub den: MPoly,
}

impl RatFn {
    pub fn new(num: MPoly, den: MPoly) -> Self {
        assert!(!den.is_zero(), "RatFn with zero denominator");
        RatFn { num, den }.tidy()
    }
    pub fn poly(p: MPoly) -> Self {
        RatFn { num: p, den: MPoly::int(1) }
    }
    pub fn int(c: i64) -> Self {
        RatFn::poly(MPoly::int(c))
    }
    pub fn q(c: Q) -> Self {
        RatFn::poly(MPoly::constant(c))
    }
    pub fn var(i: usize) -> Self {
        RatFn::poly(MPoly::var(i))
    }

    /// Folds a constant denominator into the numerator, and cancels equal num and den.
    fn tidy(self) -> Self {
        if let Some(c) = self.den.as_constant() {
            return RatFn { num: self.num.scale(&(Q::int(1) / c)), den: MPoly::int(1) };
        }
        if self.num == self.den {
            return RatFn::int(1);
        }
        self
    }

    pub fn add(&self, o: &Self) -> Self {
        if self.den == o.den {
            return RatFn::new(self.num.add(&o.num), self.den.clone());
        }
        RatFn::new(self.num.mul(&o.den).add(&o.num.mul(&self.den)), self.den.mul(&o.den))
    }
    pub fn sub(&self, o: &Self) -> Self {
        self.add(&o.neg())
    }
    pub fn neg(&self) -> Self {
        RatFn { num: self.num.neg(), den: self.den.clone() }
    }
    pub fn mul(&self, o: &Self) -> Self {
        RatFn::new(self.num.mul(&o.num), self.den.mul(&o.den))
    }
    /// Quotient; `o` must be non-zero.
    pub fn div(&self, o: &Self) -> Self {
        assert!(!o.num.is_zero(), "division by zero rational function");
        RatFn::new(self.num.mul(&o.den), self.den.mul(&o.num))
    }
    pub fn pow(&self, n: u32) -> Self {
        RatFn::new(self.num.pow(n), self.den.pow(n))
    }
    pub fn is_zero(&self) -> bool {
        self.num.is_zero()
    }
    /// Exact equality of rational functions.
    pub fn equals(&self, o: &Self) -> bool {
        self.num.mul(&o.den) == o.num.mul(&self.den)
    }

    /// Substitutes a rational function for variable `v`.
    pub fn subst(&self, v: usize, by: &RatFn) -> RatFn {
        let sub = |p: &MPoly| -> (MPoly, u32) {
            // p(by) * by.den^deg as a polynomial.
            let deg = p.degree_in(v);
            let mut acc = MPoly::zero();
            for d in 0..=deg {
                let term = p.coeff_in(v, d).mul(&by.num.pow(d)).mul(&by.den.pow(deg - d));
                acc = acc.add(&term);
            }
            (acc, deg)
        };
        let (n, dn) = sub(&self.num);
        let (d, dd) = sub(&self.den);
        // num(by)/den(by) = (n / b^dn) / (d / b^dd) = n b^dd / (d b^dn).
        let b = &by.den;
        if dn >= dd { RatFn::new(n, d.mul(&b.pow(dn - dd))) } else { RatFn::new(n.mul(&b.pow(dd - dn)), d) }
    }

    /// The value at rational points (`None` if the denominator vanishes there).
    pub fn eval(&self, at: &[Q; 6]) -> Option<Q> {
        let d = self.den.eval(at);
        if d == Q::int(0) { None } else { Some(self.num.eval(at) / d) }
    }
}

impl fmt::Display for RatFn {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den == MPoly::int(1) {
            write!(f, "{}", self.num)
        } else {
            write!(f, "({}) / ({})", self.num, self.den)
        }
    }
}

impl fmt::Debug for RatFn {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self}")
    }
}

/// Pseudo-remainder of `p` by `chi` as polynomials in lambda: lead(chi)^e p = q chi + r with
/// deg_lambda r < deg_lambda chi. Since lead(chi) = kappa + 1 never vanishes for kappa > 0,
/// p vanishes at every root lambda of chi exactly when r = 0.
pub fn prem_lambda(p: &MPoly, chi: &MPoly) -> MPoly {
    let n = chi.degree_in(L);
    let lc = chi.coeff_in(L, n);
    let mut r = p.clone();
    while !r.is_zero() && r.degree_in(L) >= n {
        let d = r.degree_in(L);
        let lr = r.coeff_in(L, d);
        let shift = MPoly::var(L).pow(d - n);
        r = r.mul(&lc).sub(&lr.mul(&shift).mul(chi));
    }
    r
}

/// Whether a rational function vanishes at every root lambda of chi (its numerator's normal form
/// modulo chi is zero). The denominator must not vanish there (the caller proves that).
pub fn zero_mod_chi(e: &RatFn, chi: &MPoly) -> bool {
    prem_lambda(&e.num, chi).is_zero()
}
