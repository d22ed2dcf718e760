//! Reading the numbers of a file: canonical text, with `bad-number` or `too-large` naming where.

use super::limits::Limits;
use crate::arith::rational::{NumberFault, parse_rational};
use crate::arith::text::parse_number;
use crate::arith::{Field, Num, Rat};
use crate::verdict::{Checked, Fail};
use std::sync::Arc;

/// The failure for a refused number at `path`.
fn fault(path: &str, s: &str, f: NumberFault) -> Fail {
    match f {
        NumberFault::Bad => Fail::new("bad-number", format!("field `{path}`: {s:?} is not canonical")),
        NumberFault::TooLong => Fail::new("too-large", format!("field `{path}`: more than max-digits")),
    }
}

/// A canonical rational.
pub fn rational(path: &str, s: &str, limits: &Limits) -> Checked<Rat> {
    parse_rational(s, limits.max_digits).map_err(|f| fault(path, s, f))
}

/// A canonical element of the field (a rational when the field is Q).
pub fn element(path: &str, s: &str, field: &Arc<Field>, limits: &Limits) -> Checked<Num> {
    parse_number(s, field, limits.max_digits).map_err(|f| fault(path, s, f))
}

/// The largest denominator, in bits, of the coefficients of some elements.
pub fn denominator_bits<'a>(xs: impl Iterator<Item = &'a Num>) -> u64 {
    xs.flat_map(|x| x.coef.iter()).map(crate::arith::rational::denominator_bits).max().unwrap_or(0)
}
