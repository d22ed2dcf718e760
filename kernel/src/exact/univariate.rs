//! Univariate polynomials over the rationals of a backend (coefficients lowest degree first,
//! without trailing zeros), and root counts by Sturm's theorem: V(a) - V(b) distinct roots in
//! (a, b] for p(a), p(b) != 0. Used by the number fields (isolating cos 2 pi/n) and by the proof
//! checker (verifying a Sturm sequence given in a proof).

use super::Field;
use std::cmp::Ordering;

/// Coefficients, lowest degree first, without trailing zeros.
pub type Coeffs<F> = Vec<F>;

/// Why a Sturm sequence does not count roots (docs/proof-format.md, `Witness`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SturmError {
    /// The sequence does not start with the polynomial and its derivative.
    Start,
    /// Element 1 is not the derivative.
    Derivative,
    /// Element `i` is not minus the remainder of the two before it.
    Remainder(usize),
    /// The last element does not divide the one before it.
    LastDivides,
    /// lo >= hi.
    EmptyInterval,
    /// The polynomial vanishes at an end of the interval.
    RootAtEnd,
}

/// `p` without trailing zero coefficients.
pub fn trim<F: Field>(mut p: Coeffs<F>) -> Coeffs<F> {
    while p.last().is_some_and(F::is_zero) {
        p.pop();
    }
    p
}

/// `a b`.
pub fn mul<F: Field>(a: &[F], b: &[F]) -> Coeffs<F> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut out = vec![F::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] = out[i + j].plus(&x.times(y));
        }
    }
    trim(out)
}

/// `a - b`.
pub fn sub<F: Field>(a: &[F], b: &[F]) -> Coeffs<F> {
    let at = |p: &[F], i: usize| p.get(i).cloned().unwrap_or_else(F::zero);
    trim((0..a.len().max(b.len())).map(|i| at(a, i).minus(&at(b, i))).collect())
}

/// The quotient and remainder of a by b (b non-zero).
pub fn div_rem<F: Field>(a: &[F], b: &[F]) -> (Coeffs<F>, Coeffs<F>) {
    let mut r = trim(a.to_vec());
    let lb = b.last().expect("non-zero divisor");
    let mut q = vec![F::zero(); r.len().saturating_sub(b.len()) + 1];
    while r.len() >= b.len() && !r.is_empty() {
        let shift = r.len() - b.len();
        let f = r.last().expect("non-empty").over(lb).expect("lead != 0");
        for (i, c) in b.iter().enumerate() {
            r[i + shift] = r[i + shift].minus(&f.times(c));
        }
        q[shift] = f;
        r.pop();
        r = trim(r);
    }
    (trim(q), r)
}

/// The remainder of a by b (b non-zero).
pub fn rem<F: Field>(a: &[F], b: &[F]) -> Coeffs<F> {
    div_rem(a, b).1
}

/// The derivative.
pub fn derivative<F: Field>(p: &[F]) -> Coeffs<F> {
    trim(p.iter().enumerate().skip(1).map(|(i, c)| c.times(&F::from_i64(i as i64))).collect())
}

/// p(x) by Horner's rule.
pub fn eval<F: Field>(p: &[F], x: &F) -> F {
    p.iter().rev().fold(F::zero(), |acc, c| acc.times(x).plus(c))
}

/// Sign changes of the sequence at x (zeros skipped).
fn variations<F: Field>(seq: &[Coeffs<F>], x: &F) -> usize {
    let signs: Vec<Ordering> =
        seq.iter().map(|p| eval(p, x).sign()).filter(|s| *s != Ordering::Equal).collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// The Sturm sequence of `p`: p, p', then minus the remainders, until a remainder vanishes.
pub fn sturm_sequence<F: Field>(p: &[F]) -> Vec<Coeffs<F>> {
    let mut seq = vec![trim(p.to_vec()), derivative(p)];
    while seq.last().is_some_and(|x| !x.is_empty()) {
        let r: Coeffs<F> = rem(&seq[seq.len() - 2], &seq[seq.len() - 1]).iter().map(F::negated).collect();
        if r.is_empty() {
            break;
        }
        seq.push(r);
    }
    if seq.last().is_some_and(Vec::is_empty) {
        seq.pop();
    }
    seq
}

/// Checks that `seq` is the Sturm sequence of `p` and returns the number of distinct roots in
/// (lo, hi].
pub fn count_roots<F: Field>(p: &[F], seq: &[Coeffs<F>], lo: &F, hi: &F) -> Result<usize, SturmError> {
    if seq.len() < 2 || seq[0] != trim(p.to_vec()) {
        return Err(SturmError::Start);
    }
    if seq[1] != derivative(p) {
        return Err(SturmError::Derivative);
    }
    for i in 2..seq.len() {
        let want: Coeffs<F> = rem(&seq[i - 2], &seq[i - 1]).iter().map(F::negated).collect();
        if seq[i] != want || want.is_empty() {
            return Err(SturmError::Remainder(i));
        }
    }
    if !rem(&seq[seq.len() - 2], &seq[seq.len() - 1]).is_empty() {
        return Err(SturmError::LastDivides);
    }
    if lo >= hi {
        return Err(SturmError::EmptyInterval);
    }
    if eval(p, lo).is_zero() || eval(p, hi).is_zero() {
        return Err(SturmError::RootAtEnd);
    }
    Ok(variations(seq, lo).saturating_sub(variations(seq, hi)))
}

/// Whether `p` is positive on (lo, hi]: p(hi) > 0 and no root in (lo, hi] (so p keeps the sign
/// of p(hi) there).
pub fn positive_on<F: Field>(p: &[F], lo: &F, hi: &F) -> bool {
    match p.len() {
        0 => false,
        1 => p[0].is_positive(),
        _ => eval(p, hi).is_positive() && count_roots(p, &sturm_sequence(p), lo, hi) == Ok(0),
    }
}
