//! The canonical text form of an exact rational: `"p/q"` in lowest terms with `q > 1`, or `"p"`
//! when the denominator is 1. Everything else is rejected, with the canonical spelling when
//! there is one.

use super::{Field, Int, Ring};

/// Limits on the work an untrusted file may ask for (docs/certificate-format.md §2, "Limits").
/// A file beyond a limit is rejected with code `too-large` or `time-limit`, naming the limit;
/// no limit can make a false certificate pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ParseLimits {
    /// `max-digits`: largest number of decimal digits in one number (numerator and denominator
    /// together; for an element of a number field, of all its coefficients together).
    pub max_digits: usize,
    /// `max-total-digits`: largest number of digits of all the numbers of a file together.
    pub max_total_digits: usize,
    /// `max-generators`: largest number of generators of a cone.
    pub max_generators: usize,
    /// `time-limit`: when to give up, checked between the steps of the work (each number, each
    /// image, each proof step); `None` for no time limit.
    pub deadline: Option<std::time::Instant>,
}

impl ParseLimits {
    /// Whether the deadline has passed.
    pub fn expired(&self) -> bool {
        self.deadline.is_some_and(|d| std::time::Instant::now() >= d)
    }
}

/// Why a string is not a canonical rational.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NumberError {
    /// The empty string.
    Empty,
    /// Whitespace anywhere.
    Whitespace,
    /// A leading `+`.
    PlusSign,
    /// A character other than digits, `-` and `/`.
    InvalidCharacter(char),
    /// A numerator or denominator without digits.
    MissingDigits,
    /// Leading zeros.
    LeadingZero,
    /// `-0`.
    NegativeZero,
    /// Denominator 0.
    ZeroDenominator,
    /// Denominator 1 (the canonical text has none).
    UnitDenominator {
        /// The canonical text of the same number.
        canonical: String,
    },
    /// Not in lowest terms.
    NotReduced {
        /// The canonical text of the same number.
        canonical: String,
    },
    /// A field element not in its canonical spelling (docs/certificate-format.md §12).
    NotCanonical {
        /// The canonical text of the same element.
        canonical: String,
    },
    /// A power of c at or above the degree of Q(c) over Q.
    PowerTooHigh {
        /// The power written.
        power: usize,
        /// The degree of the field.
        degree: usize,
    },
    /// More digits than the limit.
    TooLong {
        /// Digits found.
        digits: usize,
        /// The limit.
        max: usize,
    },
}

/// Checks the lexical shape of a run of digits: non-empty, ASCII digits, no leading zero
/// (a lone "0" is allowed only where `zero_ok`).
fn check_digits(s: &str, zero_ok: bool) -> Result<(), NumberError> {
    if s.is_empty() {
        return Err(NumberError::MissingDigits);
    }
    // Whitespace is refused before (parse_canonical_parts).
    if let Some(c) = s.chars().find(|c| !c.is_ascii_digit()) {
        return Err(if c == '+' { NumberError::PlusSign } else { NumberError::InvalidCharacter(c) });
    }
    if s == "0" {
        return if zero_ok { Ok(()) } else { Err(NumberError::ZeroDenominator) };
    }
    if s.starts_with('0') {
        return Err(NumberError::LeadingZero);
    }
    Ok(())
}

/// Parses a canonical rational (`-?p(/q)?`, lowest terms, `q > 1`) into its numerator and
/// (positive) denominator, without building a rational.
pub fn parse_canonical_parts<Z: Int>(s: &str, limits: ParseLimits) -> Result<(Z, Z), NumberError> {
    if s.is_empty() {
        return Err(NumberError::Empty);
    }
    if s.chars().any(char::is_whitespace) {
        return Err(NumberError::Whitespace);
    }
    let (negative, body) = match s.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, s.strip_prefix('+').map_or(Ok(s), |_| Err(NumberError::PlusSign))?),
    };
    let (p, q) = match body.split_once('/') {
        Some((p, q)) => (p, Some(q)),
        None => (body, None),
    };
    // Lexical checks are linear; only then the length limit, before any bignum work.
    check_digits(p, true)?;
    if let Some(q) = q {
        check_digits(q, false)?;
    }
    let digits = p.len() + q.map_or(0, str::len);
    if digits > limits.max_digits {
        return Err(NumberError::TooLong { digits, max: limits.max_digits });
    }
    if negative && p == "0" {
        return Err(NumberError::NegativeZero);
    }
    let sign = if negative { "-" } else { "" };
    let mut num = Z::parse_digits(p).ok_or(NumberError::MissingDigits)?;
    if negative {
        num = num.negated();
    }
    let Some(q) = q else { return Ok((num, Z::one())) };
    if p == "0" {
        return Err(NumberError::NotReduced { canonical: "0".to_string() });
    }
    if q == "1" {
        return Err(NumberError::UnitDenominator { canonical: format!("{sign}{p}") });
    }
    let den = Z::parse_digits(q).ok_or(NumberError::MissingDigits)?;
    let g = num.gcd(&den);
    if g != Z::one() {
        let (rn, rd) = (num.div_exact(&g), den.div_exact(&g));
        let canonical = if rd == Z::one() { rn.to_string() } else { format!("{rn}/{rd}") };
        return Err(NumberError::NotReduced { canonical });
    }
    Ok((num, den))
}

/// Parses a canonical rational into the field `F` (see [`parse_canonical_parts`]).
pub fn parse_canonical<F: Field>(s: &str, limits: ParseLimits) -> Result<F, NumberError> {
    let (n, d) = parse_canonical_parts::<F::Int>(s, limits)?;
    Ok(F::from_fraction(&n, &d))
}

/// The canonical text of a rational: `"p/q"` reduced with `q > 1`, or `"p"`.
pub fn to_canonical<F: Field>(x: &F) -> String {
    let d = x.denom();
    if d == F::Int::one() { x.numer().to_string() } else { format!("{}/{}", x.numer(), d) }
}
