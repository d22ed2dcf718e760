//! The real number fields Q(c), c = cos(2 pi/n), of the regular polygons (docs/certificate-format.md
//! §12): an element is a polynomial in c of degree below d = deg Psi_n, Psi_n the minimal polynomial
//! of c, computed (never tabulated) from Chebyshev's T_n. The sign of an element is decided by
//! evaluating it in interval arithmetic on a rational interval that isolates c, halved until zero
//! is excluded; this always ends for a non-zero element because Psi_n is irreducible.

use super::univariate::{count_roots, derivative, div_rem, eval, mul, rem, sturm_sequence, sub, trim};
use super::{Field, NumberError, OrderedField, ParseLimits, Ring, parse_canonical, to_canonical};
use std::cmp::Ordering;
use std::fmt;
use std::sync::Arc;

/// The largest n whose field the kernel builds (deg Psi_n = phi(n)/2 <= 32).
pub const MAX_N: u64 = 64;

/// The name of the generator c = cos(2 pi/n) in the text of an element.
pub const GENERATOR: &str = "c";

/// Coefficients, lowest degree first, no trailing zeros.
type Coeffs<F> = Vec<F>;

fn quotient<F: Field>(a: &[F], b: &[F]) -> Coeffs<F> {
    div_rem(a, b).0
}

fn monic<F: Field>(p: &[F]) -> Coeffs<F> {
    let lead = p.last().expect("non-zero").clone();
    p.iter().map(|c| c.over(&lead).expect("lead != 0")).collect()
}

fn gcd<F: Field>(a: &[F], b: &[F]) -> Coeffs<F> {
    let (mut x, mut y) = (trim(a.to_vec()), trim(b.to_vec()));
    while !y.is_empty() {
        (x, y) = (y.clone(), rem(&x, &y));
    }
    monic(&x)
}

/// Psi_n, monic: the square-free part of T_n(x) - 1 has the roots cos(2 pi k/n), k = 0..n-1,
/// each once; dividing by Psi_d for every proper divisor d of n leaves those with gcd(k, n) = 1.
pub fn cos_minimal_polynomial<F: Field>(n: u64) -> Vec<F> {
    let one = F::one();
    match n {
        1 => return vec![one.negated(), one],
        2 => return vec![one.clone(), one],
        _ => {}
    }
    let (mut t0, mut t1) = (vec![one.clone()], vec![F::zero(), one.clone()]);
    for _ in 1..n {
        let next = sub(&mul(&[F::zero(), F::from_i64(2)], &t1), &t0);
        (t0, t1) = (t1, next);
    }
    let p = sub(&t1, &[one]);
    let mut psi = quotient(&p, &gcd(&p, &derivative(&p)));
    for d in (1..n).filter(|d| n.is_multiple_of(*d)) {
        psi = quotient(&psi, &cos_minimal_polynomial::<F>(d));
    }
    monic(&psi)
}

/// Q(cos 2 pi/n) with an isolating interval [lo, hi] of c, a root of Psi_n (rational endpoints,
/// lo < c < hi, or lo = hi = c when c is rational).
#[derive(Debug)]
pub struct CosField<F> {
    n: u64,
    minpoly: Vec<F>,
    lo: F,
    hi: F,
}

impl<F: Field> CosField<F> {
    /// The field of n in 3..=[`MAX_N`]; `None` otherwise.
    pub fn new(n: u64) -> Option<Arc<Self>> {
        if !(3..=MAX_N).contains(&n) {
            return None;
        }
        let minpoly = cos_minimal_polynomial::<F>(n);
        let (lo, hi) = isolate_largest(&minpoly);
        Some(Arc::new(CosField { n, minpoly, lo, hi }))
    }

    /// n.
    pub fn n(&self) -> u64 {
        self.n
    }

    /// The degree d of Q(c) over Q.
    pub fn degree(&self) -> usize {
        self.minpoly.len() - 1
    }

    /// Psi_n, monic, lowest coefficient first.
    pub fn minimal_polynomial(&self) -> &[F] {
        &self.minpoly
    }

    /// c = cos(2 pi/n) itself.
    pub fn generator(self: &Arc<Self>) -> Algebraic<F> {
        if self.degree() == 1 {
            return Algebraic::rational(self.minpoly[0].negated());
        }
        Algebraic::new(Some(self.clone()), vec![F::zero(), F::one()])
    }

    /// The element whose coefficients in c are `coeffs` (lowest first, reduced modulo Psi_n).
    pub fn element(self: &Arc<Self>, coeffs: Vec<F>) -> Algebraic<F> {
        Algebraic::new(Some(self.clone()), rem(&trim(coeffs), &self.minpoly))
    }

    /// Parses the canonical text of an element (§12 of the format): e.g. `"1/2"`, `"c"`,
    /// `"-1/4 + 3/2*c - c^2"`; anything but the canonical spelling is rejected.
    pub fn parse(self: &Arc<Self>, s: &str, limits: ParseLimits) -> Result<Algebraic<F>, NumberError> {
        if !s.contains(GENERATOR) {
            return parse_canonical::<F>(s, limits).map(Algebraic::rational);
        }
        let coeffs = parse_terms::<F>(s, self.degree(), limits)?;
        let x = self.element(coeffs);
        let canonical = x.to_string();
        if canonical != s {
            return Err(NumberError::NotCanonical { canonical });
        }
        Ok(x)
    }

    /// The isolating interval.
    fn interval(&self) -> (F, F) {
        (self.lo.clone(), self.hi.clone())
    }

    /// An interval around c halved `steps` times (by the sign of Psi_n at the midpoint; Psi_n
    /// changes sign at its simple root c, so c stays inside).
    fn halved(&self, (mut lo, mut hi): (F, F), steps: usize) -> (F, F) {
        let at_lo = eval(&self.minpoly, &lo).sign();
        for _ in 0..steps {
            let mid = lo.plus(&hi).over(&F::from_i64(2)).expect("2 != 0");
            if eval(&self.minpoly, &mid).sign() == at_lo {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        (lo, hi)
    }
}

/// An interval (lo, hi] holding the largest root of `p` and no other, hi - lo <= 2^-64 (for
/// degree 1, the root itself twice). The roots of Psi_n lie in (-1, 1): Sturm counts on (lo, 1].
fn isolate_largest<F: Field>(p: &[F]) -> (F, F) {
    if p.len() == 2 {
        let r = p[0].negated().over(&p[1]).expect("lead != 0");
        return (r.clone(), r);
    }
    let p = p.to_vec();
    let seq = sturm_sequence(&p);
    let count = |a: &F, b: &F| count_roots(&p, &seq, a, b).expect("no root at a rational");
    let (mut lo, mut top) = (F::from_i64(-1), F::one());
    while count(&lo, &top) > 1 {
        let mid = lo.plus(&top).over(&F::from_i64(2)).expect("2 != 0");
        if count(&mid, &top) >= 1 { lo = mid } else { top = mid }
    }
    // One root in (lo, top], simple, and p(lo), p(top) != 0: bisect by the sign change.
    let width = F::from_ratio(1, 1 << 62).over(&F::from_i64(4)).expect("4 != 0");
    let at_lo = eval(&p, &lo).sign();
    while top.minus(&lo) > width {
        let mid = lo.plus(&top).over(&F::from_i64(2)).expect("2 != 0");
        if eval(&p, &mid).sign() == at_lo { lo = mid } else { top = mid }
    }
    (lo, top)
}

/// Reads `t_0 + t_1 + ...`: terms joined by " + " or " - ", the first with an optional '-';
/// a term is `R`, `R*c`, `R*c^k`, `c` or `c^k` with R an unsigned canonical rational.
fn parse_terms<F: Field>(s: &str, degree: usize, limits: ParseLimits) -> Result<Vec<F>, NumberError> {
    let mut coeffs = vec![F::zero(); degree];
    let (mut negative, mut rest) = match s.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, s),
    };
    loop {
        let end = [" + ", " - "].iter().filter_map(|sep| rest.find(sep)).min().unwrap_or(rest.len());
        let (r, k) = parse_term::<F>(&rest[..end], limits)?;
        if k >= degree {
            return Err(NumberError::PowerTooHigh { power: k, degree });
        }
        coeffs[k] = coeffs[k].plus(&if negative { r.negated() } else { r });
        if end == rest.len() {
            return Ok(coeffs);
        }
        negative = rest[end..].starts_with(" - ");
        rest = &rest[end + 3..];
    }
}

/// One unsigned term: its coefficient and its power of c.
fn parse_term<F: Field>(t: &str, limits: ParseLimits) -> Result<(F, usize), NumberError> {
    let (coeff, power) = match t.split_once(GENERATOR) {
        None => (t, None),
        Some(("", p)) => ("1", Some(p)),
        Some((r, p)) => {
            let last = r.chars().last().unwrap_or('*');
            (r.strip_suffix('*').ok_or(NumberError::InvalidCharacter(last))?, Some(p))
        }
    };
    if coeff.starts_with('-') {
        return Err(NumberError::InvalidCharacter('-'));
    }
    let r = parse_canonical::<F>(coeff, limits)?;
    let k = match power {
        None => 0,
        Some("") => 1,
        Some(p) => {
            let digits = p.strip_prefix('^').ok_or(NumberError::MissingDigits)?;
            let ok = !digits.is_empty() && digits.len() <= 2 && digits.bytes().all(|b| b.is_ascii_digit());
            if !ok {
                return Err(NumberError::InvalidCharacter(digits.chars().next().unwrap_or('^')));
            }
            digits.parse::<usize>().map_err(|_| NumberError::MissingDigits)?
        }
    };
    Ok((r, k))
}

/// An element of Q(cos 2 pi/n), or a rational (which belongs to every such field and carries no
/// field).
#[derive(Clone)]
pub struct Algebraic<F> {
    field: Option<Arc<CosField<F>>>,
    /// Coefficients in c, lowest first, trimmed, fewer than the field's degree.
    c: Vec<F>,
}

impl<F: Field> Algebraic<F> {
    fn new(field: Option<Arc<CosField<F>>>, c: Vec<F>) -> Self {
        let c = trim(c);
        let field = if c.len() > 1 { field } else { None };
        Algebraic { field, c }
    }

    /// A rational.
    pub fn rational(x: F) -> Self {
        Algebraic::new(None, vec![x])
    }

    /// The coefficients in c, lowest first (empty for zero).
    pub fn coeffs(&self) -> &[F] {
        &self.c
    }

    /// The n of the field Q(cos 2 pi/n) the element lives in (`None` for a rational).
    pub fn field_n(&self) -> Option<u64> {
        self.field.as_ref().map(|k| k.n)
    }

    /// The rational value, when the element is rational.
    pub fn as_rational(&self) -> Option<F> {
        (self.c.len() <= 1).then(|| self.c.first().cloned().unwrap_or_else(F::zero))
    }

    fn field_with(&self, o: &Self) -> Option<Arc<CosField<F>>> {
        match (&self.field, &o.field) {
            (Some(a), Some(b)) => {
                assert_eq!(a.n, b.n, "elements of two different fields are never combined");
                Some(a.clone())
            }
            (a, b) => a.clone().or_else(|| b.clone()),
        }
    }

    /// Bounds of the value for c in [lo, hi] (Horner in interval arithmetic).
    fn bounds_on(&self, lo: &F, hi: &F) -> (F, F) {
        let mut acc = (F::zero(), F::zero());
        for a in self.c.iter().rev() {
            let p = [acc.0.times(lo), acc.0.times(hi), acc.1.times(lo), acc.1.times(hi)];
            let mn = p.iter().min().expect("four").clone();
            let mx = p.iter().max().expect("four").clone();
            acc = (mn.plus(a), mx.plus(a));
        }
        acc
    }

    /// Rational bounds of the value, narrower than `width` (exact for a rational).
    pub fn bounds(&self, width: &F) -> (F, F) {
        let Some(k) = &self.field else {
            let x = self.as_rational().expect("rational");
            return (x.clone(), x);
        };
        let mut around = k.interval();
        loop {
            let (a, b) = self.bounds_on(&around.0, &around.1);
            if b.minus(&a) <= *width {
                return (a, b);
            }
            around = k.halved(around, 16);
        }
    }
}

impl<F: Field> PartialEq for Algebraic<F> {
    fn eq(&self, o: &Self) -> bool {
        self.c == o.c
    }
}
impl<F: Field> Eq for Algebraic<F> {}
impl<F: Field> PartialOrd for Algebraic<F> {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl<F: Field> Ord for Algebraic<F> {
    fn cmp(&self, o: &Self) -> Ordering {
        self.minus(o).sign()
    }
}

/// The canonical text: terms by increasing power, zero terms left out, a unit coefficient of a
/// power of c left out, signs between terms as " + " and " - ".
impl<F: Field> fmt::Display for Algebraic<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for (k, a) in self.c.iter().enumerate().filter(|(_, a)| !a.is_zero()) {
            let abs = if a.is_negative() { a.negated() } else { a.clone() };
            let sign = match (first, a.is_negative()) {
                (true, true) => "-",
                (true, false) => "",
                (false, true) => " - ",
                (false, false) => " + ",
            };
            let r = to_canonical(&abs);
            let term = match (k, r.as_str()) {
                (0, _) => r,
                (1, "1") => GENERATOR.to_string(),
                (1, _) => format!("{r}*{GENERATOR}"),
                (_, "1") => format!("{GENERATOR}^{k}"),
                _ => format!("{r}*{GENERATOR}^{k}"),
            };
            write!(f, "{sign}{term}")?;
            first = false;
        }
        if first { write!(f, "0") } else { Ok(()) }
    }
}
impl<F: Field> fmt::Debug for Algebraic<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.field {
            Some(k) => write!(f, "{self} (c = cos(2 pi/{}))", k.n),
            None => write!(f, "{self}"),
        }
    }
}

impl<F: Field> Ring for Algebraic<F> {
    fn zero() -> Self {
        Algebraic { field: None, c: Vec::new() }
    }
    fn from_i64(v: i64) -> Self {
        Algebraic::rational(F::from_i64(v))
    }
    fn plus(&self, o: &Self) -> Self {
        let n = self.c.len().max(o.c.len());
        let at = |p: &[F], i: usize| p.get(i).cloned().unwrap_or_else(F::zero);
        Algebraic::new(self.field_with(o), (0..n).map(|i| at(&self.c, i).plus(&at(&o.c, i))).collect())
    }
    fn minus(&self, o: &Self) -> Self {
        self.plus(&o.negated())
    }
    fn times(&self, o: &Self) -> Self {
        let field = self.field_with(o);
        let p = mul(&self.c, &o.c);
        let p = match &field {
            Some(k) => rem(&p, &k.minpoly),
            None => p,
        };
        Algebraic::new(field, p)
    }
    fn negated(&self) -> Self {
        Algebraic { field: self.field.clone(), c: self.c.iter().map(F::negated).collect() }
    }
    fn sign(&self) -> Ordering {
        let Some(k) = &self.field else { return self.c.first().map_or(Ordering::Equal, Ring::sign) };
        let mut around = k.interval();
        loop {
            let (a, b) = self.bounds_on(&around.0, &around.1);
            if a.is_positive() {
                return Ordering::Greater;
            }
            if b.is_negative() {
                return Ordering::Less;
            }
            around = k.halved(around, 16);
        }
    }
}

impl<F: Field> OrderedField for Algebraic<F> {
    fn over(&self, o: &Self) -> Option<Self> {
        if o.c.is_empty() {
            return None;
        }
        let Some(k) = &o.field else {
            let r = o.c[0].clone();
            let c = self.c.iter().map(|x| x.over(&r).expect("r != 0")).collect();
            return Some(Algebraic::new(self.field.clone(), c));
        };
        // Extended Euclid: s o + t Psi_n = g (a non-zero constant, Psi_n irreducible), 1/o = s/g.
        let (mut r0, mut r1) = (k.minpoly.clone(), o.c.clone());
        let (mut s0, mut s1): (Coeffs<F>, Coeffs<F>) = (Vec::new(), vec![F::one()]);
        while !r1.is_empty() {
            let q = quotient(&r0, &r1);
            let r = sub(&r0, &mul(&q, &r1));
            let s = sub(&s0, &mul(&q, &s1));
            (r0, r1, s0, s1) = (r1, r, s1, s);
        }
        let g = r0[0].clone();
        let inv = s0.iter().map(|x| x.over(&g).expect("g != 0")).collect();
        Some(self.times(&k.element(inv)))
    }
    fn from_ratio(n: i64, d: i64) -> Self {
        Algebraic::rational(F::from_ratio(n, d))
    }
}
