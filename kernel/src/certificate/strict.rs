//! The strict syntax of certificate and proof files (docs/certificate-format.md §2): the subset of
//! RON that the format uses, and nothing else, so that a third-party reader and `chatter verify`
//! agree on every file. Checked before RON parses the text:
//!
//! - tokens: identifiers `[A-Za-z_][A-Za-z0-9_]*`, unsigned decimal integers without leading zeros,
//!   strings `"..."` without escapes (no `\`, no `"`, no control characters inside), and the
//!   punctuation `( ) [ ] : ,`;
//! - between tokens: spaces, tabs, line feeds and carriage returns only;
//! - not allowed: comments, raw or byte strings, escapes, `#![enable(...)]` headers, signs, floats,
//!   hexadecimal, octal or binary integers, a byte order mark, and an empty file.
//!
//! The JSON twin (docs/certificate-format.md §11) has the same tokens with `{ }` instead of
//! `( )` and no identifiers (so no `true`, `false` or `null`); in addition, the top-level value
//! and the value of a key that starts with an upper-case letter (an enum variant with fields)
//! must be objects, so that a struct has one text only (never a positional array).

use super::{Code, Locus, Rejection};

/// The text encodings of the format: RON, or its JSON twin.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    /// The RON syntax of docs/certificate-format.md §2.
    Ron,
    /// The JSON twin of docs/certificate-format.md §11.
    Json,
}

fn reject(line: usize, column: usize, what: &str) -> Rejection {
    let msg = format!("line {line}, column {column}: {what} (docs/certificate-format.md §2: strict syntax)");
    Rejection::new(Code::Syntax, Locus::Text { line, column }, msg)
}

/// What a character that starts no token is, in words.
fn describe(c: char, next: Option<char>) -> String {
    match (c, next) {
        ('/', Some('/' | '*')) => "comments are not part of the format".into(),
        ('#', _) => "extensions (#![enable(...)]) are not part of the format".into(),
        ('\u{feff}', _) => "a byte order mark (U+FEFF) is not part of the format".into(),
        ('-' | '+', _) => "signs outside strings are not part of the format (numbers are strings)".into(),
        ('\'', _) => "character literals are not part of the format".into(),
        ('{' | '}', _) => "maps are not part of the format".into(),
        ('(' | ')', _) => "parentheses are not part of the JSON twin (structs are objects)".into(),
        _ if c.is_ascii_graphic() => format!("the character {c:?} is not part of the format"),
        _ => format!("the character U+{:04X} outside a string is not part of the format", c as u32),
    }
}

/// Checks that `text` uses only the strict RON syntax; the first offence is reported with its
/// position.
pub fn check(text: &str) -> Result<(), Rejection> {
    check_in(text, Encoding::Ron)
}

/// Checks that `text` uses only the strict syntax of the encoding.
pub fn check_in(text: &str, encoding: Encoding) -> Result<(), Rejection> {
    let json = encoding == Encoding::Json;
    let punctuation: &[char] =
        if json { &['{', '}', '[', ']', ':', ','] } else { &['(', ')', '[', ']', ':', ','] };
    // JSON only: whether the next value must be an object, and the first character of the last
    // string read (of a key when a ':' follows).
    let (mut object_next, mut last_initial) = (true, None::<char>);
    if text.trim_matches([' ', '\t', '\n', '\r']).is_empty() {
        return Err(reject(1, 1, "the file is empty"));
    }
    let chars: Vec<char> = text.chars().collect();
    let (mut i, mut line, mut col) = (0, 1, 1);
    let advance = |i: &mut usize, line: &mut usize, col: &mut usize, c: char| {
        *i += 1;
        if c == '\n' {
            *line += 1;
            *col = 1;
        } else {
            *col += 1;
        }
    };
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        let (l0, c0) = (line, col);
        if matches!(c, ' ' | '\t' | '\n' | '\r') {
            advance(&mut i, &mut line, &mut col, c);
        } else if punctuation.contains(&c) {
            if json {
                if object_next && c != '{' {
                    return Err(reject(l0, c0, "a struct or a variant's fields must be a JSON object"));
                }
                object_next = c == ':' && last_initial.is_some_and(|d| d.is_ascii_uppercase());
            }
            advance(&mut i, &mut line, &mut col, c);
        } else if json && object_next && (c == '"' || c == '-' || c.is_ascii_alphanumeric()) {
            return Err(reject(l0, c0, "a struct or a variant's fields must be a JSON object"));
        } else if c == '"' {
            let start = i + 1;
            advance(&mut i, &mut line, &mut col, c);
            loop {
                let Some(&d) = chars.get(i) else { return Err(reject(l0, c0, "a string is not closed")) };
                advance(&mut i, &mut line, &mut col, d);
                match d {
                    '"' => break,
                    '\\' => {
                        return Err(reject(line, col - 1, "escapes in strings are not part of the format"));
                    }
                    _ if d.is_control() => {
                        return Err(reject(
                            line,
                            col - 1,
                            "control characters in strings are not part of the format",
                        ));
                    }
                    _ => {}
                }
            }
            last_initial = chars.get(start).copied();
            if chars.get(i).is_some_and(|d| d.is_alphanumeric() || *d == '_' || *d == '"') {
                return Err(reject(line, col, "a token must not follow a string directly"));
            }
        } else if json && (c.is_ascii_alphabetic() || c == '_') {
            return Err(reject(
                l0,
                c0,
                "literals and names outside strings (true, false, null) are not part of the JSON twin",
            ));
        } else if c.is_ascii_alphabetic() || c == '_' {
            while let Some(&d) = chars.get(i).filter(|d| d.is_ascii_alphanumeric() || **d == '_') {
                advance(&mut i, &mut line, &mut col, d);
            }
            if matches!(chars.get(i), Some('"' | '#')) {
                return Err(reject(l0, c0, "raw strings and byte strings are not part of the format"));
            }
        } else if c.is_ascii_digit() {
            while let Some(&d) = chars.get(i).filter(|d| d.is_ascii_digit()) {
                advance(&mut i, &mut line, &mut col, d);
            }
            let digits = col - c0;
            if c == '0' && digits > 1 {
                return Err(reject(l0, c0, "integers with leading zeros are not part of the format"));
            }
            if chars.get(i).is_some_and(|d| d.is_alphanumeric() || matches!(*d, '.' | '_')) {
                return Err(reject(
                    l0,
                    c0,
                    "only plain decimal integers are part of the format (no 0x, 0b, 0o, _, exponent or fraction)",
                ));
            }
        } else {
            return Err(reject(line, col, &describe(c, next)));
        }
    }
    Ok(())
}
