//! Root counts of a univariate polynomial over Q from a Sturm sequence given in the proof:
//! the checker verifies the sequence (p_0 = p, p_1 = p', p_{i+1} = -rem(p_{i-1}, p_i), the last
//! remainder zero) and counts sign changes (Sturm's theorem: V(a) - V(b) distinct roots in (a, b],
//! for p(a), p(b) != 0).

use crate::exact::Field;
use std::cmp::Ordering;

/// Coefficients, lowest degree first, without trailing zeros.
pub type Coeffs<F> = Vec<F>;

fn trim<F: Field>(mut p: Coeffs<F>) -> Coeffs<F> {
    while p.last().is_some_and(F::is_zero) {
        p.pop();
    }
    p
}

/// The derivative.
pub fn derivative<F: Field>(p: &Coeffs<F>) -> Coeffs<F> {
    trim(p.iter().enumerate().skip(1).map(|(i, c)| c.times(&F::from_i64(i as i64))).collect())
}

/// The remainder of a by b (b non-zero).
pub fn rem<F: Field>(a: &Coeffs<F>, b: &Coeffs<F>) -> Coeffs<F> {
    let mut r = trim(a.clone());
    let lb = b.last().expect("non-zero divisor");
    while r.len() >= b.len() && !r.is_empty() {
        let shift = r.len() - b.len();
        let f = r.last().expect("non-empty").over(lb).expect("lead != 0");
        for (i, c) in b.iter().enumerate() {
            r[i + shift] = r[i + shift].minus(&f.times(c));
        }
        r.pop();
        r = trim(r);
    }
    r
}

fn eval<F: Field>(p: &Coeffs<F>, x: &F) -> F {
    p.iter().rev().fold(F::zero(), |acc, c| acc.times(x).plus(c))
}

/// Sign changes of the sequence at x (zeros skipped).
fn variations<F: Field>(seq: &[Coeffs<F>], x: &F) -> usize {
    let signs: Vec<Ordering> =
        seq.iter().map(|p| eval(p, x).sign()).filter(|s| *s != Ordering::Equal).collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// The Sturm sequence of `p`: p, p', then minus the remainders, until a remainder vanishes.
pub fn sturm_sequence<F: Field>(p: &Coeffs<F>) -> Vec<Coeffs<F>> {
    let mut seq = vec![trim(p.clone()), derivative(p)];
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

/// Whether `p` is positive on (lo, hi]: p(lo) != 0, p(hi) > 0 and no root in (lo, hi] (so p keeps
/// the sign of p(hi) there).
pub fn positive_on<F: Field>(p: &Coeffs<F>, lo: &F, hi: &F) -> bool {
    if p.is_empty() {
        return false;
    }
    if p.len() == 1 {
        return p[0].is_positive();
    }
    eval(p, hi).is_positive() && count_roots(p, &sturm_sequence(p), lo, hi) == Ok(0)
}

/// Checks that `seq` is the Sturm sequence of `p` and returns the number of distinct roots in
/// (lo, hi]; errors say which element is wrong.
pub fn count_roots<F: Field>(p: &Coeffs<F>, seq: &[Coeffs<F>], lo: &F, hi: &F) -> Result<usize, String> {
    if seq.len() < 2 || seq[0] != trim(p.clone()) {
        return Err("the sequence must start with the polynomial and its derivative".into());
    }
    if seq[1] != derivative(p) {
        return Err("element 1 of the sequence is not the derivative".into());
    }
    for i in 2..seq.len() {
        let want: Coeffs<F> = rem(&seq[i - 2], &seq[i - 1]).iter().map(F::negated).collect();
        if seq[i] != want || want.is_empty() {
            return Err(format!(
                "element {i} of the sequence is not minus the remainder of the two before it"
            ));
        }
    }
    if !rem(&seq[seq.len() - 2], &seq[seq.len() - 1]).is_empty() {
        return Err("the last element does not divide the one before it".into());
    }
    if lo >= hi {
        return Err("the interval is empty".into());
    }
    if eval(p, lo).is_zero() || eval(p, hi).is_zero() {
        return Err("the polynomial vanishes at an end of the interval".into());
    }
    Ok(variations(seq, lo).saturating_sub(variations(seq, hi)))
}
