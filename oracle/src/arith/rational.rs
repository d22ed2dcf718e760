//! Canonical rational text (docs/certificate-format.md §2 "Numbers"), parsed and printed by hand.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::str::FromStr;

/// An exact rational.
pub type Rat = num_rational::BigRational;

/// Why a number text is refused: a lexical or canonical-form rule, or the digit limit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NumberFault {
    /// Not canonical `p/q` text (`bad-number`).
    Bad,
    /// More digits than `max-digits` (`too-large`).
    TooLong,
}

/// Whether `t` is a non-empty run of ASCII digits without a leading zero (`0` itself is fine).
fn plain_digits(t: &str) -> bool {
    !t.is_empty() && t.bytes().all(|b| b.is_ascii_digit()) && (t == "0" || !t.starts_with('0'))
}

/// Parses canonical text `-?p(/q)?`: q > 1, gcd(p, q) = 1, no `-0`, at most `max_digits` digits
/// in p and q together (the lexical rules are checked before the length; §2 "Limits").
pub fn parse_rational(s: &str, max_digits: usize) -> Result<Rat, NumberFault> {
    let negative = s.starts_with('-');
    let body = if negative { &s[1..] } else { s };
    let (p, q) = match body.find('/') {
        Some(i) => (&body[..i], Some(&body[i + 1..])),
        None => (body, None),
    };
    if !plain_digits(p) || q.is_some_and(|q| !plain_digits(q)) {
        return Err(NumberFault::Bad);
    }
    if p.len() + q.map_or(0, str::len) > max_digits {
        return Err(NumberFault::TooLong);
    }
    let num = BigInt::from_str(p).map_err(|_| NumberFault::Bad)?;
    if negative && num.is_zero() {
        return Err(NumberFault::Bad);
    }
    let num = if negative { -num } else { num };
    let Some(q) = q else { return Ok(Rat::from_integer(num)) };
    let den = BigInt::from_str(q).map_err(|_| NumberFault::Bad)?;
    if den <= BigInt::one() || !num.gcd(&den).is_one() {
        return Err(NumberFault::Bad);
    }
    Ok(Rat::new_raw(num, den))
}

/// The canonical text of a rational: `p` or `p/q`.
pub fn rational_text(x: &Rat) -> String {
    if x.denom().is_one() { x.numer().to_string() } else { format!("{}/{}", x.numer(), x.denom()) }
}

/// The number of bits of the denominator of a rational (1 has 1 bit).
pub fn denominator_bits(x: &Rat) -> u64 {
    x.denom().bits()
}

/// A rational from an integer fraction (test and sampling helper).
pub fn ratio(p: i64, q: i64) -> Rat {
    Rat::new(BigInt::from(p), BigInt::from(q))
}

/// |x|.
pub fn abs(x: &Rat) -> Rat {
    x.abs()
}

/// floor(x · 2^bits) / 2^bits and the same rounded up: a dyadic enclosure of x.
pub fn dyadic_bounds(x: &Rat, bits: u32) -> (Rat, Rat) {
    let scale = BigInt::one() << bits;
    let scaled = x * Rat::from_integer(scale.clone());
    let lo = scaled.floor().to_integer();
    let hi = scaled.ceil().to_integer();
    (Rat::new(lo, scale.clone()), Rat::new(hi, scale))
}
