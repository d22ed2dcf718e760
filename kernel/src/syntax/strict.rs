//! The strict syntax of every file (docs/certificate-format.md §2; §11 for the JSON twin): the
//! subset of RON that the formats use, and nothing else, so that a third-party reader and
//! `chatter verify` agree on every file. Checked before RON or JSON parses the text:
//!
//! - tokens: identifiers `[A-Za-z_][A-Za-z0-9_]*`, unsigned decimal integers without leading zeros,
//!   strings `"..."` without escapes (no `\`, no `"`, no control characters inside), and the
//!   punctuation `( ) [ ] : ,`;
//! - between tokens: spaces, tabs, line feeds and carriage returns only;
//! - not allowed: comments, raw or byte strings, escapes, `#![enable(...)]` headers, signs, floats,
//!   hexadecimal, octal or binary integers, a byte order mark, and an empty file;
//! - a tuple `(...)` as the value of `kappa` or `gamma`: a parameter interval is a list
//!   `["lo", "hi"]` (§2, §9). The schemas tell tuples from lists everywhere else (RON refuses
//!   one for the other), but a parameter, a string or an interval, is read by its first token, and
//!   RON hands a tuple and a list to that reader alike.
//!
//! The JSON twin has the same tokens with `{ }` instead of `( )` and no identifiers (so no
//! `true`, `false` or `null`); the top-level value and the value of a key that starts with an
//! upper-case letter (an enum variant with fields) must be objects.

use super::Encoding;
use crate::reject::{Code, Detail, Locus, Rejection};

/// What breaks the strict syntax.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Offence {
    /// Only whitespace, or nothing.
    Empty,
    /// A string without its closing quote.
    NotClosed,
    /// A `\` in a string.
    Escape,
    /// A control character in a string.
    Control,
    /// A token directly after a string.
    AfterString,
    /// `true`, `false`, `null` or a name in the JSON twin.
    JsonLiteral,
    /// `r"..."`, `b"..."`.
    RawString,
    /// An integer with leading zeros.
    LeadingZero,
    /// An integer that is not plain decimal (0x, _, exponent, fraction).
    NotDecimal,
    /// A struct or variant's fields that are not a JSON object.
    NotObject,
    /// A comment.
    Comment,
    /// A `#![enable(...)]` header.
    Extension,
    /// A byte order mark.
    ByteOrderMark,
    /// A sign outside a string.
    Sign,
    /// A character literal.
    CharLiteral,
    /// `{` or `}` in RON.
    Map,
    /// `(` or `)` in JSON.
    Parenthesis,
    /// A tuple `(...)` as the value of `kappa` or `gamma` (an interval is a list).
    TupleInterval,
    /// Any other character outside a string.
    Character(char),
}

fn reject(line: usize, column: usize, offence: Offence, json: bool) -> Rejection {
    Rejection::new(Code::Syntax, Locus::Text { line, column }, Detail::Lexical(offence, json))
}

/// The 1-based line and column (in characters) of the byte `at` of `text`.
fn position(text: &str, at: usize) -> (usize, usize) {
    let before = &text[..at];
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (before.matches('\n').count() + 1, before[line_start..].chars().count() + 1)
}

/// What a character that starts no token is.
fn offence(c: char, next: Option<char>) -> Offence {
    match (c, next) {
        ('/', Some('/' | '*')) => Offence::Comment,
        ('#', _) => Offence::Extension,
        ('\u{feff}', _) => Offence::ByteOrderMark,
        ('-' | '+', _) => Offence::Sign,
        ('\'', _) => Offence::CharLiteral,
        ('{' | '}', _) => Offence::Map,
        ('(' | ')', _) => Offence::Parenthesis,
        _ => Offence::Character(c),
    }
}

/// Checks that `text` uses only the strict syntax of the encoding; the first offence is reported
/// with its position (computed only then).
pub fn check(text: &str, encoding: Encoding) -> Result<(), Rejection> {
    let json = encoding == Encoding::Json;
    let chars: Vec<(usize, char)> = text.char_indices().collect();
    let (at, peek) =
        (|i: usize| chars.get(i).map_or(text.len(), |c| c.0), |i: usize| chars.get(i).map(|c| c.1));
    let skip = |mut i: usize, keep: fn(char) -> bool| {
        while peek(i).is_some_and(keep) {
            i += 1;
        }
        i
    };
    // The offence at character `i`; inside a string, at the character before `i` (column 0 of the
    // next line for a line feed).
    let fail = |i: usize, back: usize, o| {
        let (line, column) = position(text, at(i));
        Err(reject(line, column - back, o, json))
    };
    if text.trim_matches([' ', '\t', '\n', '\r']).is_empty() {
        return fail(0, 0, Offence::Empty);
    }
    let open: &[char] = if json { &['{', '}', '[', ']', ':', ','] } else { &['(', ')', '[', ']', ':', ','] };
    // JSON only: whether the next value must be an object, and the first character of the last
    // string read (of a key when a ':' follows).
    let (mut object_next, mut last_initial) = (true, None::<char>);
    // RON only: the last identifier read is `kappa` or `gamma`, and then whether a ':' followed it.
    let (mut parameter, mut parameter_value) = (false, false);
    let mut i = 0;
    while let Some(c) = peek(i) {
        let start = i;
        let starts_value = c == '"' || c == '-' || c.is_ascii_alphanumeric();
        if matches!(c, ' ' | '\t' | '\n' | '\r') {
            i += 1;
        } else if json && object_next && (starts_value || (open.contains(&c) && c != '{')) {
            return fail(i, 0, Offence::NotObject);
        } else if open.contains(&c) {
            if c == '(' && parameter_value {
                return fail(i, 0, Offence::TupleInterval);
            }
            (parameter_value, parameter) = (!json && c == ':' && parameter, false);
            object_next = json && c == ':' && last_initial.is_some_and(|d| d.is_ascii_uppercase());
            i += 1;
        } else if c == '"' {
            (parameter, parameter_value, last_initial) = (false, false, peek(i + 1));
            i += 1;
            loop {
                let Some(d) = peek(i) else { return fail(start, 0, Offence::NotClosed) };
                i += 1;
                match d {
                    '"' => break,
                    '\\' => return fail(i, 1, Offence::Escape),
                    _ if d.is_control() => return fail(i, 1, Offence::Control),
                    _ => {}
                }
            }
            if peek(i).is_some_and(|d| d.is_alphanumeric() || d == '_' || d == '"') {
                return fail(i, 0, Offence::AfterString);
            }
        } else if c.is_ascii_alphabetic() || c == '_' {
            if json {
                return fail(i, 0, Offence::JsonLiteral);
            }
            i = skip(i, |d| d.is_ascii_alphanumeric() || d == '_');
            let name = &text[at(start)..at(i)];
            (parameter, parameter_value) = (name == "kappa" || name == "gamma", false);
            if matches!(peek(i), Some('"' | '#')) {
                return fail(start, 0, Offence::RawString);
            }
        } else if c.is_ascii_digit() {
            (parameter, parameter_value) = (false, false);
            i = skip(i, |d| d.is_ascii_digit());
            if c == '0' && i - start > 1 {
                return fail(start, 0, Offence::LeadingZero);
            }
            if peek(i).is_some_and(|d| d.is_alphanumeric() || matches!(d, '.' | '_')) {
                return fail(start, 0, Offence::NotDecimal);
            }
        } else {
            return fail(i, 0, offence(c, peek(i + 1)));
        }
    }
    Ok(())
}
