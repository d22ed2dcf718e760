//! The limits of docs/certificate-format.md §2 ("Limits") and the canonical numbers ("Numbers"),
//! checked the same way for every kind of file: a limit is checked before the work it bounds,
//! and a number that cannot be read is `too-large` beyond max-digits, `bad-number` otherwise.

use crate::exact::{Field, Int, NumberError, ParseLimits, parse_canonical, parse_canonical_parts};
use crate::reject::{Code, Counted, Detail, Rejection};

/// The rejection of the text of a number at `path`.
pub fn number_error(path: String, text: &str, error: NumberError) -> Rejection {
    let code = if matches!(error, NumberError::TooLong { .. }) { Code::TooLarge } else { Code::BadNumber };
    Rejection::at(code, path, Detail::Number(text.to_string(), error))
}

/// The canonical rational `text` of the field at `path`.
pub fn number<F: Field>(path: &str, text: &str, limits: ParseLimits) -> Result<F, Rejection> {
    parse_canonical(text, limits).map_err(|e| number_error(path.to_string(), text, e))
}

/// The canonical rational `text` as (numerator, positive denominator); `path` names the field.
pub fn parts<Z: Int>(
    path: impl Fn() -> String,
    text: &str,
    limits: ParseLimits,
) -> Result<(Z, Z), Rejection> {
    parse_canonical_parts(text, limits).map_err(|e| number_error(path(), text, e))
}

/// `max-generators` (or the limit `name`): at most `limit` items.
pub fn at_most(name: &str, count: usize, limit: usize, what: Counted) -> Result<(), Rejection> {
    if count > limit { Err(Rejection::limit(name, count, limit, what)) } else { Ok(()) }
}

/// `max-total-digits`: the characters of all numbers of the file together (signs and slashes
/// count), before any arithmetic.
pub fn total<'a>(numbers: impl Iterator<Item = &'a str>, limits: ParseLimits) -> Result<(), Rejection> {
    let total: usize = numbers.map(str::len).sum();
    at_most("max-total-digits", total, limits.max_total_digits, Counted::Characters)
}

/// `time-limit` once the deadline has passed, while doing `during`.
pub fn in_time(limits: ParseLimits, during: &str) -> Result<(), Rejection> {
    if limits.expired() { Err(Rejection::time_limit(during)) } else { Ok(()) }
}
