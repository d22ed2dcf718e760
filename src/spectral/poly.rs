//! Univariate polynomials over an exact ordered field: arithmetic, gcd, square-free
//! decomposition, Sturm sequences. Small and written out so that it can be audited.

use crate::exact::{OrderedField, Q, Ring};
use std::cmp::Ordering;
use std::fmt;

/// A polynomial with coefficients lowest degree first and no trailing zeros (zero is `[]`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Poly<F> {
    c: Vec<F>,
}

impl<F: OrderedField> Poly<F> {
    pub fn new(mut c: Vec<F>) -> Self {
        while c.last().is_some_and(Ring::is_zero) {
            c.pop();
        }
        Poly { c }
    }
    pub fn zero() -> Self {
        Poly { c: Vec::new() }
    }
    pub fn constant(x: F) -> Self {
        Poly::new(vec![x])
    }
    /// The polynomial t.
    pub fn var() -> Self {
        Poly::new(vec![F::zero(), F::one()])
    }
    pub fn coeffs(&self) -> &[F] {
        &self.c
    }
    pub fn is_zero(&self) -> bool {
        self.c.is_empty()
    }
    /// Degree (`None` for the zero polynomial).
    pub fn degree(&self) -> Option<usize> {
        self.c.len().checked_sub(1)
    }
    pub fn lead(&self) -> Option<&F> {
        self.c.last()
    }
    /// Coefficient of t^i (zero beyond the degree).
    pub fn coeff(&self, i: usize) -> F {
        self.c.get(i).cloned().unwrap_or_else(F::zero)
    }

    /// Value at x (Horner).
    pub fn eval(&self, x: &F) -> F {
        self.c.iter().rev().fold(F::zero(), |acc, a| acc.times(x).plus(a))
    }
    /// Value at a rational point.
    pub fn eval_q(&self, x: &Q) -> F {
        self.eval(&F::from_q(x))
    }
    /// Sign at a rational point.
    pub fn sign_at(&self, x: &Q) -> Ordering {
        self.eval_q(x).sign()
    }

    pub fn add(&self, o: &Self) -> Self {
        let n = self.c.len().max(o.c.len());
        Poly::new((0..n).map(|i| self.coeff(i).plus(&o.coeff(i))).collect())
    }
    pub fn sub(&self, o: &Self) -> Self {
        let n = self.c.len().max(o.c.len());
        Poly::new((0..n).map(|i| self.coeff(i).minus(&o.coeff(i))).collect())
    }
    pub fn mul(&self, o: &Self) -> Self {
        if self.is_zero() || o.is_zero() {
            return Poly::zero();
        }
        let mut c = vec![F::zero(); self.c.len() + o.c.len() - 1];
        for (i, a) in self.c.iter().enumerate() {
            for (j, b) in o.c.iter().enumerate() {
                c[i + j] = c[i + j].plus(&a.times(b));
            }
        }
        Poly::new(c)
    }
    pub fn scale(&self, s: &F) -> Self {
        Poly::new(self.c.iter().map(|a| a.times(s)).collect())
    }
    pub fn neg(&self) -> Self {
        Poly::new(self.c.iter().map(Ring::negated).collect())
    }
    pub fn pow(&self, e: usize) -> Self {
        (0..e).fold(Poly::constant(F::one()), |acc, _| acc.mul(self))
    }
    /// p(-t).
    pub fn reflect(&self) -> Self {
        Poly::new(
            self.c
                .iter()
                .enumerate()
                .map(|(i, a)| if i % 2 == 1 { a.negated() } else { a.clone() })
                .collect(),
        )
    }
    pub fn derivative(&self) -> Self {
        Poly::new(self.c.iter().enumerate().skip(1).map(|(i, a)| a.times(&F::from_i64(i as i64))).collect())
    }
    /// The monic multiple (zero stays zero).
    pub fn monic(&self) -> Self {
        match self.lead() {
            None => Poly::zero(),
            Some(l) => self.scale(&F::one().over(l).expect("non-zero lead")),
        }
    }

    /// Euclidean division: (q, r) with self = q d + r and deg r < deg d. `d` must be non-zero.
    pub fn div_rem(&self, d: &Self) -> (Self, Self) {
        let dd = d.degree().expect("division by the zero polynomial");
        let inv = F::one().over(d.lead().expect("non-zero")).expect("non-zero lead");
        let mut r = self.c.clone();
        let mut q = vec![F::zero(); self.c.len().saturating_sub(dd)];
        while r.len() > dd && !r.is_empty() {
            let k = r.len() - 1 - dd;
            let f = r[r.len() - 1].times(&inv);
            for (i, b) in d.c.iter().enumerate() {
                r[k + i] = r[k + i].minus(&f.times(b));
            }
            q[k] = f;
            r.pop();
            while r.last().is_some_and(Ring::is_zero) {
                r.pop();
            }
        }
        (Poly::new(q), Poly::new(r))
    }
    pub fn rem(&self, d: &Self) -> Self {
        self.div_rem(d).1
    }
    /// Exact quotient (panics in debug builds if `d` does not divide).
    pub fn div_exact(&self, d: &Self) -> Self {
        let (q, r) = self.div_rem(d);
        debug_assert!(r.is_zero(), "inexact polynomial division");
        q
    }

    /// Monic greatest common divisor (gcd(0, 0) = 0).
    pub fn gcd(&self, o: &Self) -> Self {
        let (mut a, mut b) = (self.clone(), o.clone());
        while !b.is_zero() {
            let r = a.rem(&b);
            a = b;
            b = r;
        }
        a.monic()
    }

    /// The monic square-free part p / gcd(p, p').
    pub fn square_free(&self) -> Self {
        if self.degree().unwrap_or(0) == 0 {
            return self.monic();
        }
        self.div_exact(&self.gcd(&self.derivative())).monic()
    }

    /// Square-free factorisation (Yun): monic pairwise coprime factors f_i with multiplicity i,
    /// so that self = lead * prod f_i^i. Constant factors are omitted.
    pub fn square_free_factors(&self) -> Vec<(Self, usize)> {
        let mut out = Vec::new();
        if self.degree().unwrap_or(0) == 0 {
            return out;
        }
        let p = self.monic();
        let d = p.derivative();
        let a0 = p.gcd(&d);
        let mut b = p.div_exact(&a0);
        let mut c = d.div_exact(&a0);
        let mut dd = c.sub(&b.derivative());
        let mut i = 1;
        while b.degree().unwrap_or(0) > 0 {
            let a = b.gcd(&dd);
            if a.degree().unwrap_or(0) > 0 {
                out.push((a.clone(), i));
            }
            b = b.div_exact(&a);
            c = dd.div_exact(&a);
            dd = c.sub(&b.derivative());
            i += 1;
        }
        out
    }

    /// The Sturm sequence p, p', -rem(p_{k-1}, p_k), ... .
    pub fn sturm(&self) -> Vec<Self> {
        let mut s = vec![self.clone(), self.derivative()];
        while !s[s.len() - 1].is_zero() {
            let r = s[s.len() - 2].rem(&s[s.len() - 1]).neg();
            s.push(r);
        }
        s.pop();
        s
    }
}

/// Sign changes in a sequence of signs, zeros skipped.
fn variations(signs: impl Iterator<Item = Ordering>) -> usize {
    let mut last = Ordering::Equal;
    let mut v = 0;
    for s in signs.filter(|s| *s != Ordering::Equal) {
        if last != Ordering::Equal && s != last {
            v += 1;
        }
        last = s;
    }
    v
}

/// A point of the extended real line.
#[derive(Clone, Debug)]
pub enum Point {
    NegInf,
    At(Q),
    PosInf,
}

/// Sign variations of a Sturm sequence at a point.
pub fn sturm_variations<F: OrderedField>(seq: &[Poly<F>], x: &Point) -> usize {
    variations(seq.iter().map(|p| match x {
        Point::At(x) => p.sign_at(x),
        Point::PosInf => p.lead().map_or(Ordering::Equal, Ring::sign),
        Point::NegInf => {
            let s = p.lead().map_or(Ordering::Equal, Ring::sign);
            if p.degree().unwrap_or(0) % 2 == 1 { s.reverse() } else { s }
        }
    }))
}

/// Number of distinct real roots in (a, b] (Sturm's theorem; `seq` from a square-free p).
pub fn count_roots<F: OrderedField>(seq: &[Poly<F>], a: &Point, b: &Point) -> usize {
    sturm_variations(seq, a).saturating_sub(sturm_variations(seq, b))
}

impl<F: OrderedField + fmt::Display> fmt::Display for Poly<F> {
    /// Highest degree first, in the variable `t`, e.g. `t^3 - 1/2 t + 3`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.show("t"))
    }
}

impl<F: OrderedField + fmt::Display> Poly<F> {
    /// The polynomial in the variable `var`, highest degree first.
    pub fn show(&self, var: &str) -> String {
        if self.is_zero() {
            return "0".into();
        }
        let mut out = String::new();
        for (i, a) in self.c.iter().enumerate().rev() {
            if a.is_zero() {
                continue;
            }
            let neg = a.is_negative();
            let abs = if neg { a.negated() } else { a.clone() };
            let text = abs.to_string();
            let complex = text.contains(['+', ' ']) || text.chars().skip(1).any(|c| c == '-');
            let coef = match (i, abs == F::one()) {
                (0, _) => {
                    if complex {
                        format!("({text})")
                    } else {
                        text
                    }
                }
                (_, true) => String::new(),
                _ => {
                    if complex {
                        format!("({text}) ")
                    } else {
                        format!("{text} ")
                    }
                }
            };
            let mono = match i {
                0 => String::new(),
                1 => var.to_string(),
                _ => format!("{var}^{i}"),
            };
            let sign = match (out.is_empty(), neg) {
                (true, true) => "-",
                (true, false) => "",
                (false, true) => " - ",
                (false, false) => " + ",
            };
            out.push_str(&format!("{sign}{coef}{mono}"));
        }
        out
    }
}
