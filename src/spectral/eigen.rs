//! Exact spectral facts of 2x2 and 3x3 matrices over an exact ordered field: the characteristic
//! polynomial, the real eigenvalues with multiplicities (isolated exactly), the number of
//! non-real ones, and the decisions the paper needs: whether the dominant eigenvalue is real
//! and positive in the sense of Elsner-Vandergraft (the paper's Theorem on invariant cones), and
//! whether all eigenvalues are real.

use super::poly::Poly;
use super::roots::{RealRoot, isolate};
use crate::exact::{OrderedField, Q, QExt, Ring};
use chatter_kernel::model::Mat2;
use chatter_kernel::model::linalg::{Mat3, char_poly};
use std::cmp::Ordering;

/// det(tI - M) for a 3x3 matrix: t^3 - tr t^2 + s t - det.
pub fn char_poly3<F: OrderedField>(m: &Mat3<F>) -> Poly<F> {
    let (c2, c1, c0) = char_poly(m);
    Poly::new(vec![c0.negated(), c1, c2.negated(), F::one()])
}

/// det(tI - M) for a 2x2 matrix: t^2 - tr t + det.
pub fn char_poly2<F: OrderedField>(m: &Mat2<F>) -> Poly<F> {
    let tr = m[0][0].plus(&m[1][1]);
    let det = m[0][0].times(&m[1][1]).minus(&m[0][1].times(&m[1][0]));
    Poly::new(vec![det, tr.negated(), F::one()])
}

/// The eigenvalues of a real matrix of size 2 or 3, from its characteristic polynomial.
#[derive(Clone, Debug)]
pub struct Spectrum<F> {
    /// det(tI - M), monic.
    pub char_poly: Poly<F>,
    /// Distinct real eigenvalues in increasing order, with algebraic multiplicities.
    pub real: Vec<(RealRoot<F>, usize)>,
    /// Number of non-real eigenvalues, with multiplicity (0 or 2 here).
    pub non_real: usize,
}

/// Which eigenvalues have the largest modulus.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dominant {
    /// A unique dominant modulus attained by a positive eigenvalue only.
    Positive,
    /// ... by a negative eigenvalue only.
    Negative,
    /// By rho and -rho (multiplicities given).
    PlusMinus { plus: usize, minus: usize },
    /// By a complex-conjugate pair only.
    NonReal,
    /// By a real eigenvalue and a complex pair of the same modulus.
    RealAndNonReal { real_positive: bool },
    /// All eigenvalues are zero.
    Zero,
}

impl Dominant {
    /// Elsner-Vandergraft as stated in the paper: some dominant eigenvalue is real and positive,
    /// with multiplicity at least that of every other dominant eigenvalue.
    pub fn real_positive(self) -> bool {
        match self {
            Dominant::Positive => true,
            Dominant::PlusMinus { plus, minus } => plus >= minus,
            Dominant::RealAndNonReal { real_positive } => real_positive,
            Dominant::Negative | Dominant::NonReal | Dominant::Zero => false,
        }
    }

    /// A stable key for reports: `positive`, `negative`, `plus-minus`, `non-real`,
    /// `positive-and-non-real`, `negative-and-non-real` or `zero`.
    pub fn key(self) -> &'static str {
        match self {
            Dominant::Positive => "positive",
            Dominant::Negative => "negative",
            Dominant::PlusMinus { .. } => "plus-minus",
            Dominant::NonReal => "non-real",
            Dominant::RealAndNonReal { real_positive: true } => "positive-and-non-real",
            Dominant::RealAndNonReal { real_positive: false } => "negative-and-non-real",
            Dominant::Zero => "zero",
        }
    }

    /// The dominant eigenvalue(s) in words, for the text output.
    pub fn describe(self) -> &'static str {
        match self {
            Dominant::Positive => "real and positive",
            Dominant::Negative => "real and negative",
            Dominant::PlusMinus { .. } => "rho and -rho tie",
            Dominant::NonReal => "a complex-conjugate pair",
            Dominant::RealAndNonReal { real_positive: true } => {
                "a positive eigenvalue tied with a complex pair"
            }
            Dominant::RealAndNonReal { real_positive: false } => {
                "a negative eigenvalue tied with a complex pair"
            }
            Dominant::Zero => "zero (nilpotent)",
        }
    }
}

impl<F: OrderedField> Spectrum<F> {
    /// The spectrum of a monic polynomial of degree 2 or 3.
    pub fn of(char_poly: Poly<F>) -> Self {
        let mut real: Vec<(RealRoot<F>, usize)> = Vec::new();
        for (factor, mult) in char_poly.square_free_factors() {
            real.extend(isolate(&factor).into_iter().map(|r| (r, mult)));
        }
        real.sort_by(|a, b| a.0.clone().compare(&mut b.0.clone()));
        let deg = char_poly.degree().unwrap_or(0);
        let non_real = deg - real.iter().map(|(_, m)| m).sum::<usize>();
        Spectrum { char_poly, real, non_real }
    }

    pub fn of3(m: &Mat3<F>) -> Self {
        Spectrum::of(char_poly3(m))
    }

    pub fn of2(m: &Mat2<F>) -> Self {
        Spectrum::of(char_poly2(m))
    }

    pub fn all_real(&self) -> bool {
        self.non_real == 0
    }

    /// The dominant eigenvalue(s), decided exactly.
    pub fn dominant(&mut self) -> Dominant {
        let deg = self.char_poly.degree().unwrap_or(0);
        if self.non_real > 0 {
            if deg < 3 || self.real.is_empty() {
                return Dominant::NonReal;
            }
            // One real root r and a pair z, conj(z): with p = t^3 - c2 t^2 + c1 t - c0 one has
            // r |z|^2 = c0, so for r != 0, r^2 - |z|^2 = (r^3 - c0)/r = c2 r - c1.
            let p = &self.char_poly;
            let (c2, c1) = (p.coeff(2).negated(), p.coeff(1));
            let r = &mut self.real[0].0;
            let rs = r.sign();
            if rs == Ordering::Equal {
                return Dominant::NonReal; // |z|^2 = c1 > 0 = |r|^2
            }
            let test = Poly::new(vec![c1.negated(), c2]);
            return match r.sign_of(&test) {
                Ordering::Greater => {
                    if rs == Ordering::Greater {
                        Dominant::Positive
                    } else {
                        Dominant::Negative
                    }
                }
                Ordering::Less => Dominant::NonReal,
                Ordering::Equal => Dominant::RealAndNonReal { real_positive: rs == Ordering::Greater },
            };
        }
        let k = self.real.len();
        let (mut lo, lo_mult) = (self.real[0].0.clone(), self.real[0].1);
        let (mut hi, hi_mult) = (self.real[k - 1].0.clone(), self.real[k - 1].1);
        let (lo_sign, hi_sign) = (lo.sign(), hi.sign());
        if lo_sign == Ordering::Equal && hi_sign == Ordering::Equal {
            return Dominant::Zero;
        }
        if lo_sign != Ordering::Less {
            return Dominant::Positive; // every eigenvalue >= 0, the largest is > 0
        }
        if hi_sign != Ordering::Greater {
            return Dominant::Negative;
        }
        match lo.negated().compare(&mut hi) {
            Ordering::Less => Dominant::Positive,
            Ordering::Greater => Dominant::Negative,
            Ordering::Equal => Dominant::PlusMinus { plus: hi_mult, minus: lo_mult },
        }
    }

    /// Decimal enclosures of the eigenvalues for display: real ones as intervals, a non-real
    /// pair as its real part and squared modulus (each an interval), all rounded outwards.
    pub fn describe(&mut self, digits: usize) -> Vec<String> {
        let mut out = Vec::new();
        for (r, m) in &mut self.real {
            let (a, b) = r.decimal_enclosure(digits);
            let mult = if *m > 1 { format!(" (multiplicity {m})") } else { String::new() };
            out.push(if r.is_exact() { format!("{}{mult}", r.lo) } else { format!("[{a}, {b}]{mult}") });
        }
        if self.non_real == 2 {
            out.push(self.non_real_pair(digits));
        }
        out
    }

    /// The complex pair a +- bi: exact rational enclosures (lo, hi) of a and of |z|^2, of
    /// width about 10^-(digits+2) (the squared modulus is (0, 0) if it cannot be bounded).
    pub fn non_real_enclosure(&mut self, digits: usize) -> ((Q, Q), (Q, Q)) {
        let p = &self.char_poly;
        let w = Q::pow10(-(digits as i64) - 2);
        let enc = |x: &F| x.enclose(&w);
        if p.degree() == Some(2) {
            // t^2 + a1 t + a0: Re = -a1/2, |z|^2 = a0.
            let (l, h) = enc(&p.coeff(1));
            ((-h / Q::int(2), -l / Q::int(2)), enc(&p.coeff(0)))
        } else {
            // Re z = (c2 - r)/2 and |z|^2 = c0 / r (r != 0), from the real root's interval.
            let r = &mut self.real[0].0;
            r.refine_to(&w);
            let (c2, c0) = (enc(&p.coeff(2).negated()), enc(&p.coeff(0).negated()));
            let re = ((&c2.0 - &r.hi) / Q::int(2), (&c2.1 - &r.lo) / Q::int(2));
            let ends = [&c0.0 / &r.lo, &c0.0 / &r.hi, &c0.1 / &r.lo, &c0.1 / &r.hi];
            let modsq = if r.lo.sign() == r.hi.sign() && r.lo.sign() != Ordering::Equal {
                (ends.iter().min().unwrap().clone(), ends.iter().max().unwrap().clone())
            } else {
                (Q::int(0), Q::int(0))
            };
            (re, modsq)
        }
    }

    /// The complex pair a +- bi as text: enclosures of a and of |z|^2.
    fn non_real_pair(&mut self, digits: usize) -> String {
        let (re, modsq) = self.non_real_enclosure(digits);
        let d = |x: &Q, r| x.decimal(digits, r);
        use crate::exact::Rounding::{Down, Up};
        format!(
            "a complex pair with real part in [{}, {}] and squared modulus in [{}, {}]",
            d(&re.0, Down),
            d(&re.1, Up),
            d(&modsq.0, Down),
            d(&modsq.1, Up)
        )
    }
}
