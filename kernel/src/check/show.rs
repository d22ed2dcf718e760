//! Numbers in messages: exact canonical text, abbreviated when long so that a rejection line
//! stays short (a number of more than [`LONG`] characters keeps its first and last digits and
//! says how long it is).

use crate::exact::{Field, to_canonical};

/// Numbers longer than this many characters are abbreviated.
pub const LONG: usize = 40;

/// `text` itself, or its first 16 and last 8 characters with its length.
pub fn abbreviate(text: &str) -> String {
    let n = text.chars().count();
    if n <= LONG {
        return text.to_string();
    }
    let head: String = text.chars().take(16).collect();
    let tail: String = text.chars().skip(n - 8).collect();
    format!("{head}...{tail} ({n} characters)")
}

/// The canonical text of an exact number, abbreviated when long.
pub fn number<F: Field>(x: &F) -> String {
    abbreviate(&to_canonical(x))
}

/// Text from a certificate, quoted, abbreviated when long.
pub fn quote(s: &str) -> String {
    match s.char_indices().nth(24) {
        Some((i, _)) => format!("\"{}...\" ({} characters)", &s[..i], s.chars().count()),
        None => format!("{s:?}"),
    }
}

/// A generator's coordinates as written in the certificate, each abbreviated.
pub fn tuple(coords: &[String]) -> String {
    coords.iter().map(|c| abbreviate(c)).collect::<Vec<_>>().join(", ")
}
