//! The real number fields Q(c), c = cos(2 pi/n), of the regular polygons (docs/certificate-format.md
//! §12): an element is a polynomial in c of degree below d = deg Psi_n, Psi_n the minimal polynomial
//! of c, computed (never tabulated) from Chebyshev's T_n. The sign of an element is decided by
//! evaluating it in interval arithmetic on an interval that isolates c, at ever finer precisions
//! until zero is excluded; this always ends for a non-zero element because Psi_n is irreducible.
//!
//! The work is integer arithmetic: y = 2c is an algebraic integer (its minimal polynomial
//! Q(y) = 2^d Psi_n(y/2) is monic with integer coefficients), so a vector of elements has a
//! positive multiple in Z\[y\] ([`AlgebraicInt`]), where sums, products and reductions modulo Q
//! divide nothing. The isolating intervals of y have dyadic ends a/2^s, b/2^s; each precision
//! is computed once per field and kept (roughly doubling s by a Newton step checked by the signs
//! of Q at the new ends, or by bisection), so a sign costs a few integer Horner evaluations.

use super::univariate::{count_roots, derivative, div_rem, eval, mul, rem, sturm_sequence, sub, trim};
use super::{Field, Int, NumberError, OrderedField, ParseLimits, Ring, parse_canonical, to_canonical};
use std::cmp::Ordering;
use std::fmt;
use std::sync::{Arc, Mutex};

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
/// lo < c < hi, or lo = hi = c when c is rational), the minimal polynomial Q of y = 2c and the
/// isolating intervals of y computed so far.
#[derive(Debug)]
pub struct CosField<F: Field> {
    n: u64,
    minpoly: Vec<F>,
    lo: F,
    hi: F,
    /// Q(y) = 2^d Psi_n(y/2): monic, integer coefficients, lowest first.
    ymin: Vec<F::Int>,
    /// Isolating intervals of y, ever more precise (level 0 from [lo, hi]).
    levels: Mutex<Vec<Level<F::Int>>>,
}

/// y in (a/2^s, b/2^s), the only root of Q there, Q(a/2^s) and Q(b/2^s) non-zero and of opposite
/// signs; `unit` = 2^s.
#[derive(Clone, Debug)]
struct Level<Z> {
    a: Z,
    b: Z,
    s: u64,
    unit: Z,
}

/// 2^(s d) q(x/2^s) for an integer polynomial q of degree d (the sign of q at x/2^s).
fn eval_scaled<Z: Int>(q: &[Z], x: &Z, unit: &Z) -> Z {
    let mut acc = Z::zero();
    let mut pw = Z::one();
    for (i, c) in q.iter().enumerate().rev() {
        acc = acc.times(x).plus(&c.times(&pw));
        if i > 0 {
            pw = pw.times(unit);
        }
    }
    acc
}

impl<Z: Int> Level<Z> {
    fn new(a: Z, b: Z, s: u64) -> Self {
        Level { a, b, s, unit: Z::pow2(s) }
    }

    /// One bisection: the half in which Q changes sign.
    fn halved(&self, q: &[Z]) -> Self {
        let two = Z::from_i64(2);
        let (a, b, mid) = (self.a.times(&two), self.b.times(&two), self.a.plus(&self.b));
        let unit = self.unit.times(&two);
        let at = |x: &Z| eval_scaled(q, x, &unit).sign();
        let (sa, sm) = (at(&a), at(&mid));
        if sm == Ordering::Equal {
            // The root is the midpoint, a dyadic rational: impossible for d >= 2 (Q is irreducible).
            unreachable!("an irrational root at a rational point");
        }
        let (a, b) = if sm == sa { (mid, b) } else { (a, mid) };
        Level { a, b, s: self.s + 1, unit }
    }

    /// A Newton step from the midpoint to about twice the precision, kept only if Q changes sign
    /// between the new ends and they lie inside this interval (so they isolate the same root).
    fn newton(&self, q: &[Z]) -> Option<Self> {
        let t = self.s + 1;
        let s2 = 2 * self.s - 32;
        let (m, unit_t) = (self.a.plus(&self.b), self.unit.times(&Z::from_i64(2)));
        let dq: Vec<Z> = q.iter().enumerate().skip(1).map(|(i, c)| c.times(&Z::from_i64(i as i64))).collect();
        // x0 = m/2^t; p0 = 2^(t d) Q(x0), p1 = 2^(t (d-1)) Q'(x0); x1 = (m p1 - p0) / (p1 2^t).
        let (p0, p1) = (eval_scaled(q, &m, &unit_t), eval_scaled(&dq, &m, &unit_t));
        if p1.is_zero() {
            return None;
        }
        let (num, den) = (m.times(&p1).minus(&p0).times(&Z::pow2(s2 - t)), p1);
        let (num, den) = if den.is_negative() { (num.negated(), den.negated()) } else { (num, den) };
        let x = num.div_floor(&den);
        let (a, b) = (x.minus(&Z::one()), x.plus(&Z::from_i64(2)));
        let up = Z::pow2(s2 - self.s);
        if a < self.a.times(&up) || b > self.b.times(&up) {
            return None;
        }
        let unit = Z::pow2(s2);
        let (sa, sb) = (eval_scaled(q, &a, &unit).sign(), eval_scaled(q, &b, &unit).sign());
        (sa != Ordering::Equal && sb != Ordering::Equal && sa != sb).then_some(Level { a, b, s: s2, unit })
    }

    /// The next level: at least about twice the precision (Newton where it converges, else
    /// bisection, which always does).
    fn next(&self, q: &[Z]) -> Self {
        let target = 2 * self.s - 32;
        let mut level = self.clone();
        while level.s < target {
            if let Some(finer) = level.newton(q) {
                return finer;
            }
            level = level.halved(q);
        }
        level
    }

    /// The sign of p(y) (p in Z\[y\], lowest coefficient first) if the interval decides it:
    /// 2^(s (m-1)) p(y) by Horner's rule in interval arithmetic, with 2^s y in [a, b].
    fn sign_of(&self, p: &[Z]) -> Option<Ordering> {
        let Some((top, rest)) = p.split_last() else { return Some(Ordering::Equal) };
        let (mut lo, mut hi) = (top.clone(), top.clone());
        let mut pw = Z::one();
        for c in rest.iter().rev() {
            pw = pw.times(&self.unit);
            let prods = [lo.times(&self.a), lo.times(&self.b), hi.times(&self.a), hi.times(&self.b)];
            let add = c.times(&pw);
            lo = prods.iter().min().expect("four").plus(&add);
            hi = prods.iter().max().expect("four").plus(&add);
        }
        if lo.is_positive() {
            Some(Ordering::Greater)
        } else if hi.is_negative() {
            Some(Ordering::Less)
        } else {
            None
        }
    }
}

impl<F: Field> CosField<F> {
    /// The field of n in 3..=[`MAX_N`]; `None` otherwise.
    pub fn new(n: u64) -> Option<Arc<Self>> {
        if !(3..=MAX_N).contains(&n) {
            return None;
        }
        let minpoly = cos_minimal_polynomial::<F>(n);
        let (lo, hi) = isolate_largest(&minpoly);
        let d = minpoly.len() - 1;
        // Q(y) = sum psi_k 2^(d-k) y^k: integers, as 2 cos(2 pi/n) is an algebraic integer.
        let ymin: Vec<F::Int> = (0..=d)
            .map(|k| {
                let x = minpoly[k].times(&F::from_int(&F::Int::pow2(d as u64 - k as u64)));
                assert!(x.denom() == F::Int::one(), "2 cos(2 pi/n) is an algebraic integer");
                x.numer()
            })
            .collect();
        // Level 0: y = 2c in (2 lo, 2 hi), whose denominators divide 2^64 (bisections of [-1, 1]).
        let at = |x: &F| {
            let scaled = x.times(&F::from_int(&F::Int::pow2(65)));
            assert!(scaled.denom() == F::Int::one(), "the ends of level 0 are multiples of 2^-65");
            scaled.numer()
        };
        let levels = if d >= 2 { vec![Level::new(at(&lo), at(&hi), 64)] } else { Vec::new() };
        Some(Arc::new(CosField { n, minpoly, lo, hi, ymin, levels: Mutex::new(levels) }))
    }

    /// The sign of the element p(y) of Z\[y\] (reduced modulo Q, not all zero unless zero): decided
    /// on the isolating intervals of y, from the coarsest, each computed once and kept.
    fn sign_of(&self, p: &[F::Int]) -> Ordering {
        if p.len() <= 1 {
            return p.first().map_or(Ordering::Equal, Ring::sign);
        }
        for i in 0.. {
            let level = {
                let mut levels = self.levels.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
                while levels.len() <= i {
                    let next = levels.last().expect("level 0").next(&self.ymin);
                    levels.push(next);
                }
                levels[i].clone()
            };
            if let Some(sign) = level.sign_of(p) {
                return sign;
            }
        }
        unreachable!("a non-zero element of a field has a sign")
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
/// a term is `R`, `R*c`, `R*c^k`, `c` or `c^k` with R an unsigned canonical rational. The digit
/// limit applies to the whole element: the digits of all its coefficients together, counted
/// before any of them is converted.
fn parse_terms<F: Field>(s: &str, degree: usize, limits: ParseLimits) -> Result<Vec<F>, NumberError> {
    let (mut negative, mut rest) = match s.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, s),
    };
    let mut terms = Vec::new();
    loop {
        let end = [" + ", " - "].iter().filter_map(|sep| rest.find(sep)).min().unwrap_or(rest.len());
        terms.push((negative, &rest[..end]));
        if end == rest.len() {
            break;
        }
        negative = rest[end..].starts_with(" - ");
        rest = &rest[end + 3..];
    }
    let coefficient =
        |t: &str| t.split_once(GENERATOR).map_or(t, |(r, _)| r).bytes().filter(u8::is_ascii_digit).count();
    let digits: usize = terms.iter().map(|(_, t)| coefficient(t)).sum();
    if digits > limits.max_digits {
        return Err(NumberError::TooLong { digits, max: limits.max_digits });
    }
    let mut coeffs = vec![F::zero(); degree];
    for (negative, t) in terms {
        let (r, k) = parse_term::<F>(t, limits)?;
        if k >= degree {
            return Err(NumberError::PowerTooHigh { power: k, degree });
        }
        coeffs[k] = coeffs[k].plus(&if negative { r.negated() } else { r });
    }
    Ok(coeffs)
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
pub struct Algebraic<F: Field> {
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
        k.sign_of(&integral(std::slice::from_ref(self))[0])
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

/// A positive common multiple of the denominators of the coefficients of `xs`: their product,
/// each distinct denominator once, a denominator dividing the product so far skipped, the
/// product replaced by a denominator it divides (lcm would need gcds, slow on some backends).
fn common_denominator<F: Field>(xs: &[Algebraic<F>]) -> F::Int {
    let mut l = F::Int::one();
    for q in xs.iter().flat_map(|x| x.c.iter().map(Field::denom)) {
        let divides = |a: &F::Int, b: &F::Int| b.minus(&b.div_floor(a).times(a)).is_zero();
        if divides(&q, &l) {
            continue;
        }
        l = if divides(&l, &q) { q } else { l.times(&q) };
    }
    l
}

/// Positive multiples of the elements `xs`, one factor for all, in Z\[y\] (y = 2c): with D a common
/// denominator of the coefficients a_k (of c^k) and d the degree, a_k c^k D 2^(d-1) =
/// (a_k D 2^(d-1-k)) y^k.
fn integral<F: Field>(xs: &[Algebraic<F>]) -> Vec<Vec<F::Int>> {
    let d = xs.iter().find_map(|x| x.field.as_ref()).map_or(1, |k| k.degree());
    let l = common_denominator(xs);
    let twos: Vec<F::Int> = (0..d as u64).map(F::Int::pow2).collect();
    xs.iter()
        .map(|x| {
            let coeff =
                |(k, a): (usize, &F)| a.numer().times(&l.div_exact(&a.denom())).times(&twos[d - 1 - k]);
            x.c.iter().enumerate().map(coeff).collect()
        })
        .collect()
}

impl<F: Field> Algebraic<F> {
    /// Positive multiples of `xs` with one common factor, as elements of Z\[y\], y = 2c (the
    /// homogeneous coordinates of a vector of elements).
    pub fn scaled(xs: &[Self]) -> Vec<AlgebraicInt<F>> {
        let field = xs.iter().find_map(|x| x.field.clone());
        integral(xs).into_iter().map(|c| AlgebraicInt::new(field.clone(), c)).collect()
    }
}

/// An element of the ring Z\[y\], y = 2 cos(2 pi/n): a polynomial in y with integer coefficients,
/// reduced modulo the monic minimal polynomial Q of y (so no arithmetic divides). Integer-scaled
/// coordinates of vectors over Q(cos 2 pi/n), as the integers are for the rationals.
#[derive(Clone)]
pub struct AlgebraicInt<F: Field> {
    field: Option<Arc<CosField<F>>>,
    /// Coefficients in y, lowest first, trimmed, fewer than the field's degree.
    y: Vec<F::Int>,
}

impl<F: Field> AlgebraicInt<F> {
    fn new(field: Option<Arc<CosField<F>>>, mut y: Vec<F::Int>) -> Self {
        while y.last().is_some_and(Ring::is_zero) {
            y.pop();
        }
        let field = if y.len() > 1 { field } else { None };
        AlgebraicInt { field, y }
    }

    /// The same number in Q(c): b_k y^k = b_k 2^k c^k.
    pub fn to_algebraic(&self) -> Algebraic<F> {
        let c =
            self.y.iter().enumerate().map(|(k, b)| F::from_int(&b.times(&F::Int::pow2(k as u64)))).collect();
        Algebraic::new(self.field.clone(), c)
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
}

impl<F: Field> PartialEq for AlgebraicInt<F> {
    fn eq(&self, o: &Self) -> bool {
        self.y == o.y
    }
}
impl<F: Field> Eq for AlgebraicInt<F> {}
impl<F: Field> PartialOrd for AlgebraicInt<F> {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl<F: Field> Ord for AlgebraicInt<F> {
    fn cmp(&self, o: &Self) -> Ordering {
        self.minus(o).sign()
    }
}
impl<F: Field> fmt::Display for AlgebraicInt<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.to_algebraic())
    }
}
impl<F: Field> fmt::Debug for AlgebraicInt<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}", self.to_algebraic())
    }
}

impl<F: Field> Ring for AlgebraicInt<F> {
    fn zero() -> Self {
        AlgebraicInt { field: None, y: Vec::new() }
    }
    fn from_i64(v: i64) -> Self {
        AlgebraicInt::new(None, vec![F::Int::from_i64(v)])
    }
    fn plus(&self, o: &Self) -> Self {
        let at = |p: &[F::Int], i: usize| p.get(i).cloned().unwrap_or_else(F::Int::zero);
        let n = self.y.len().max(o.y.len());
        AlgebraicInt::new(self.field_with(o), (0..n).map(|i| at(&self.y, i).plus(&at(&o.y, i))).collect())
    }
    fn minus(&self, o: &Self) -> Self {
        self.plus(&o.negated())
    }
    fn times(&self, o: &Self) -> Self {
        if self.y.is_empty() || o.y.is_empty() {
            return Self::zero();
        }
        let mut p = vec![F::Int::zero(); self.y.len() + o.y.len() - 1];
        for (i, a) in self.y.iter().enumerate() {
            for (j, b) in o.y.iter().enumerate() {
                p[i + j] = p[i + j].plus(&a.times(b));
            }
        }
        let field = self.field_with(o);
        if let Some(k) = &field {
            // Reduce modulo the monic Q: y^d = -(q_0 + ... + q_{d-1} y^{d-1}).
            let d = k.ymin.len() - 1;
            while p.len() > d {
                let top = p.pop().expect("non-empty");
                let shift = p.len() - d;
                for (j, q) in k.ymin[..d].iter().enumerate() {
                    p[shift + j] = p[shift + j].minus(&top.times(q));
                }
            }
        }
        AlgebraicInt::new(field, p)
    }
    fn negated(&self) -> Self {
        AlgebraicInt { field: self.field.clone(), y: self.y.iter().map(Ring::negated).collect() }
    }
    fn sign(&self) -> Ordering {
        match &self.field {
            None => self.y.first().map_or(Ordering::Equal, Ring::sign),
            Some(k) => k.sign_of(&self.y),
        }
    }
}
