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

/// A cursor over the characters with the 1-based line and column of the next one.
struct Cursor {
    chars: Vec<char>,
    i: usize,
    line: usize,
    col: usize,
}

impl Cursor {
    fn peek(&self, k: usize) -> Option<char> {
        self.chars.get(self.i + k).copied()
    }

    fn bump(&mut self) {
        if self.chars[self.i] == '\n' {
            (self.line, self.col) = (self.line + 1, 1);
        } else {
            self.col += 1;
        }
        self.i += 1;
    }

    fn skip_while(&mut self, keep: impl Fn(char) -> bool) {
        while self.peek(0).is_some_and(&keep) {
            self.bump();
        }
    }
}

/// Checks that `text` uses only the strict syntax of the encoding; the first offence is reported
/// with its position.
pub fn check(text: &str, encoding: Encoding) -> Result<(), Rejection> {
    let json = encoding == Encoding::Json;
    let fail = |line, col, o| Err(reject(line, col, o, json));
    if text.trim_matches([' ', '\t', '\n', '\r']).is_empty() {
        return fail(1, 1, Offence::Empty);
    }
    let open: &[char] = if json { &['{', '}', '[', ']', ':', ','] } else { &['(', ')', '[', ']', ':', ','] };
    // JSON only: whether the next value must be an object, and the first character of the last
    // string read (of a key when a ':' follows).
    let (mut object_next, mut last_initial) = (true, None::<char>);
    // RON only: the last identifier read is `kappa` or `gamma`, and then whether a ':' followed it.
    let (mut parameter, mut parameter_value) = (false, false);
    let mut s = Cursor { chars: text.chars().collect(), i: 0, line: 1, col: 1 };
    while let Some(c) = s.peek(0) {
        let (l0, c0) = (s.line, s.col);
        let starts_value = c == '"' || c == '-' || c.is_ascii_alphanumeric();
        if matches!(c, ' ' | '\t' | '\n' | '\r') {
            s.bump();
        } else if json && object_next && (starts_value || (open.contains(&c) && c != '{')) {
            return fail(l0, c0, Offence::NotObject);
        } else if open.contains(&c) {
            if c == '(' && parameter_value {
                return fail(l0, c0, Offence::TupleInterval);
            }
            (parameter_value, parameter) = (!json && c == ':' && parameter, false);
            object_next = json && c == ':' && last_initial.is_some_and(|d| d.is_ascii_uppercase());
            s.bump();
        } else if c == '"' {
            (parameter, parameter_value) = (false, false);
            s.bump();
            last_initial = s.peek(0);
            loop {
                let Some(d) = s.peek(0) else { return fail(l0, c0, Offence::NotClosed) };
                s.bump();
                // The character's position, counted after it (column 0 of the next line for a line feed).
                let (line, col) = (s.line, s.col - 1);
                match d {
                    '"' => break,
                    '\\' => return fail(line, col, Offence::Escape),
                    _ if d.is_control() => return fail(line, col, Offence::Control),
                    _ => {}
                }
            }
            if s.peek(0).is_some_and(|d| d.is_alphanumeric() || d == '_' || d == '"') {
                return fail(s.line, s.col, Offence::AfterString);
            }
        } else if c.is_ascii_alphabetic() || c == '_' {
            if json {
                return fail(l0, c0, Offence::JsonLiteral);
            }
            s.skip_while(|d| d.is_ascii_alphanumeric() || d == '_');
            let name: String = s.chars[s.i - (s.col - c0)..s.i].iter().collect();
            (parameter, parameter_value) = (name == "kappa" || name == "gamma", false);
            if matches!(s.peek(0), Some('"' | '#')) {
                return fail(l0, c0, Offence::RawString);
            }
        } else if c.is_ascii_digit() {
            (parameter, parameter_value) = (false, false);
            s.skip_while(|d| d.is_ascii_digit());
            if c == '0' && s.col - c0 > 1 {
                return fail(l0, c0, Offence::LeadingZero);
            }
            if s.peek(0).is_some_and(|d| d.is_alphanumeric() || matches!(d, '.' | '_')) {
                return fail(l0, c0, Offence::NotDecimal);
            }
        } else {
            return fail(l0, c0, offence(c, s.peek(1)));
        }
    }
    Ok(())
}
