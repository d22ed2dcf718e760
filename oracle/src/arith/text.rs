//! The canonical text of a field element (docs/certificate-format.md §12): non-zero terms in
//! increasing powers of c, `a`, `a*c` or `a*c^k` with `a` the canonical |coefficient| (left out
//! when 1 and k ≥ 1), the first term's sign as a leading `-`, the others joined by ` + ` or
//! ` - `; zero is `0`. A text is accepted exactly when it follows this grammar, each power is
//! below the degree, and printing the element gives the text back.

use super::field::{Field, Num};
use super::rational::{NumberFault, Rat, parse_rational, rational_text};
use num_traits::{One, Signed, Zero};
use std::sync::Arc;

/// One term of a field element's text: (coefficient, power).
fn parse_term(t: &str, d: usize) -> Result<(Rat, usize), NumberFault> {
    let (coef, power) = match t.find('c') {
        None => (t, None),
        Some(i) => (t[..i].strip_suffix('*').unwrap_or(if i == 0 { "1" } else { "!" }), Some(&t[i + 1..])),
    };
    let a = parse_rational(coef, usize::MAX)?;
    if a.is_negative() {
        return Err(NumberFault::Bad);
    }
    let k = match power {
        None => 0,
        Some("") => 1,
        Some(p) => {
            let digits = p.strip_prefix('^').ok_or(NumberFault::Bad)?;
            if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) || digits.len() > 3 {
                return Err(NumberFault::Bad);
            }
            digits.parse::<usize>().map_err(|_| NumberFault::Bad)?
        }
    };
    if k >= d {
        return Err(NumberFault::Bad);
    }
    Ok((a, k))
}

/// Splits `-?t ( ± t )*` into signed terms.
fn signed_terms(s: &str) -> Vec<(bool, &str)> {
    let (mut negative, mut rest) = match s.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, s),
    };
    let mut out = vec![];
    loop {
        let plus = rest.find(" + ");
        let minus = rest.find(" - ");
        let next = match (plus, minus) {
            (Some(p), Some(m)) => Some((p.min(m), p < m)),
            (Some(p), None) => Some((p, true)),
            (None, Some(m)) => Some((m, false)),
            (None, None) => None,
        };
        match next {
            Some((i, is_plus)) => {
                out.push((negative, &rest[..i]));
                negative = !is_plus;
                rest = &rest[i + 3..];
            }
            None => {
                out.push((negative, rest));
                return out;
            }
        }
    }
}

/// Parses a number of the field: canonical rational text when d = 1, else canonical element text.
pub fn parse_number(s: &str, field: &Arc<Field>, max_digits: usize) -> Result<Num, NumberFault> {
    let d = field.degree();
    if d == 1 || !s.contains('c') {
        return parse_rational(s, max_digits).map(|x| Num::rational(field, x));
    }
    // max-digits bounds the whole element: its coefficients' digits together, the exponents of c
    // not counted, before any coefficient is read (docs/certificate-format.md §2, §12).
    let coefficient_digits =
        |t: &str| t.split('c').next().unwrap_or("").bytes().filter(u8::is_ascii_digit).count();
    if signed_terms(s).iter().map(|(_, t)| coefficient_digits(t)).sum::<usize>() > max_digits {
        return Err(NumberFault::TooLong);
    }
    let mut coef = vec![Rat::zero(); d];
    for (negative, t) in signed_terms(s) {
        let (a, k) = parse_term(t, d)?;
        coef[k] = if negative { -a } else { a };
    }
    let x = Num { field: field.clone(), coef };
    if element_text(&x) != s {
        return Err(NumberFault::Bad);
    }
    Ok(x)
}

/// The canonical text of a field element.
pub fn element_text(x: &Num) -> String {
    let mut out = String::new();
    for (k, a) in x.coef.iter().enumerate().filter(|(_, a)| !a.is_zero()) {
        let sign = if out.is_empty() {
            if a.is_negative() { "-" } else { "" }
        } else if a.is_negative() {
            " - "
        } else {
            " + "
        };
        let m = rational_text(&a.abs());
        let term = match (k, a.abs().is_one()) {
            (0, _) => m,
            (1, true) => "c".to_string(),
            (1, false) => format!("{m}*c"),
            (_, true) => format!("c^{k}"),
            (_, false) => format!("{m}*c^{k}"),
        };
        out.push_str(sign);
        out.push_str(&term);
    }
    if out.is_empty() { "0".to_string() } else { out }
}
