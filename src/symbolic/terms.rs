//! Writing polynomials by hand in the producer: `"k l^2 + k - l + 1"` with terms and factors in
//! any order (a term is an optional rational coefficient and factors `x` or `x^e`). The result is
//! printed canonically before it reaches a proof file.

use crate::exact::{Q, parse_user_number};
use chatter_kernel::proof::Poly;

/// One term, e.g. "2 k l^2" or "l e2".
fn term(text: &str, names: &[String]) -> Poly<Q> {
    let n = names.len();
    text.split(' ').fold(Poly::constant(n, Q::int(1)), |acc, f| {
        if f.starts_with(|c: char| c.is_ascii_digit()) {
            let c = parse_user_number(f).unwrap_or_else(|e| panic!("producer: {f:?} in {text:?}: {e}"));
            return acc.scale(&c);
        }
        let (name, e) = f.split_once('^').map_or((f, 1), |(x, e)| (x, e.parse().expect("exponent")));
        let v = names
            .iter()
            .position(|x| x == name)
            .unwrap_or_else(|| panic!("producer: unknown variable {name:?}"));
        acc.mul(&Poly::var(n, v).pow(e))
    })
}

/// The sum of the terms of `text` (split at " + " and " - ").
pub fn lenient(text: &str, names: &[String]) -> Poly<Q> {
    let mut out = Poly::zero(names.len());
    let mut rest = text.trim();
    let mut negative = false;
    if let Some(r) = rest.strip_prefix('-') {
        negative = true;
        rest = r;
    }
    loop {
        let cut = [rest.find(" + "), rest.find(" - ")].into_iter().flatten().min();
        let (t, next) = match cut {
            Some(i) => (&rest[..i], Some((&rest[i + 1..i + 2] == "-", &rest[i + 3..]))),
            None => (rest, None),
        };
        let p = term(t, names);
        out = if negative { out.sub(&p) } else { out.add(&p) };
        match next {
            Some((neg, r)) => {
                negative = neg;
                rest = r;
            }
            None => return out,
        }
    }
}
