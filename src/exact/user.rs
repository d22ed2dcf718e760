//! Exact parsing of numbers typed by a user: fractions (`1/6`, `2/4`), decimals (`0.01`, `.5`)
//! and scientific notation (`1e-2`, `2.5E3`), all read exactly (`0.01` is 1/100, never a float).
//! Certificates use the strict canonical form instead ([`super::parse_canonical`]).

use super::Q;
use malachite::Integer;
use malachite::base::num::arithmetic::traits::Pow;
use malachite::rational::Rational;
use std::str::FromStr;

/// Longest input accepted (characters), so a typo cannot request a gigantic number.
const MAX_LEN: usize = 1000;
/// Largest decimal exponent accepted in scientific notation.
const MAX_EXP: i64 = 10_000;

fn digits(s: &str) -> bool {
    !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit())
}

fn pow10(e: u64) -> Rational {
    Rational::from(Integer::from(10u32).pow(e))
}

/// Parses a user number exactly.
pub fn parse_user_number(input: &str) -> Result<Q, String> {
    let s = input.trim();
    if s.is_empty() {
        return Err("empty number".into());
    }
    if s.len() > MAX_LEN {
        return Err(format!("number longer than {MAX_LEN} characters"));
    }
    let (neg, body) = match s.as_bytes()[0] {
        b'-' => (true, &s[1..]),
        b'+' => (false, &s[1..]),
        _ => (false, s),
    };
    let value = if let Some((p, q)) = body.split_once('/') {
        if !digits(p) || !digits(q) {
            return Err(format!("{input:?} is not a fraction p/q of non-negative integers"));
        }
        let q = Integer::from_str(q).expect("digits");
        if q == 0u32 {
            return Err(format!("{input:?} has a zero denominator"));
        }
        Rational::from_integers(Integer::from_str(p).expect("digits"), q)
    } else {
        let (mantissa, exp) = match body.find(['e', 'E']) {
            Some(i) => {
                let e: i64 =
                    body[i + 1..].parse().map_err(|_| format!("{input:?} has a malformed exponent"))?;
                if e.unsigned_abs() > MAX_EXP.unsigned_abs() {
                    return Err(format!("{input:?} has an exponent beyond +-{MAX_EXP}"));
                }
                (&body[..i], e)
            }
            None => (body, 0),
        };
        let (ip, fp) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        if (ip.is_empty() && fp.is_empty())
            || !(ip.is_empty() || digits(ip))
            || !(fp.is_empty() || digits(fp))
        {
            return Err(format!("{input:?} is not a number (examples: 1/6, 0.01, 1e-2)"));
        }
        let all = format!("{ip}{fp}");
        let m = Rational::from(Integer::from_str(&all).expect("digits"));
        let e = exp - fp.len() as i64;
        if e >= 0 { m * pow10(e as u64) } else { m / pow10(e.unsigned_abs()) }
    };
    Ok(Q::from_rational(if neg { -value } else { value }))
}
