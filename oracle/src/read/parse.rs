//! A recursive-descent parser of the strict RON subset (docs/certificate-format.md §2) and of the
//! strict JSON subset (§11). Anything outside the grammar is a syntax fault; a JSON key given
//! twice in one object is a duplicate field.

use super::{Encoding, Value};

/// Why a text is not in the strict syntax.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SyntaxFault {
    /// Outside the grammar (`syntax`), with the byte offset and what was expected.
    Syntax(usize, &'static str),
    /// A JSON key given twice in one object (`duplicate-field`).
    DuplicateKey(String),
}

struct Parser<'a> {
    s: &'a [u8],
    text: &'a str,
    at: usize,
}

type R<T> = Result<T, SyntaxFault>;

impl Parser<'_> {
    fn fail<T>(&self, what: &'static str) -> R<T> {
        Err(SyntaxFault::Syntax(self.at, what))
    }

    fn peek(&self) -> Option<u8> {
        self.s.get(self.at).copied()
    }

    fn ws(&mut self) {
        while matches!(self.peek(), Some(b' ' | b'\t' | b'\n' | b'\r')) {
            self.at += 1;
        }
    }

    fn eat(&mut self, c: u8) -> bool {
        let hit = self.peek() == Some(c);
        if hit {
            self.at += 1;
        }
        hit
    }

    fn expect(&mut self, c: u8, what: &'static str) -> R<()> {
        if self.eat(c) { Ok(()) } else { self.fail(what) }
    }

    /// `"` { any character but `"`, `\` and control characters } `"`.
    fn string(&mut self) -> R<String> {
        self.expect(b'"', "a string")?;
        let start = self.at;
        let rest = &self.text[start..];
        for (i, ch) in rest.char_indices() {
            if ch == '"' {
                self.at = start + i + 1;
                return Ok(rest[..i].to_string());
            }
            if ch == '\\' || ch.is_control() {
                self.at = start + i;
                return self.fail("no escapes or control characters in strings");
            }
        }
        self.at = self.s.len();
        self.fail("a closing quote")
    }

    /// `0` or a non-zero digit followed by digits, not followed by an identifier character.
    fn integer(&mut self) -> R<String> {
        let start = self.at;
        while self.peek().is_some_and(|b| b.is_ascii_digit()) {
            self.at += 1;
        }
        let digits = &self.text[start..self.at];
        if digits.is_empty() || (digits.len() > 1 && digits.starts_with('0')) {
            return self.fail("a plain decimal integer");
        }
        if self.peek().is_some_and(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'.') {
            return self.fail("a plain decimal integer");
        }
        Ok(digits.to_string())
    }

    fn ident(&mut self) -> R<String> {
        let start = self.at;
        if !self.peek().is_some_and(|b| b.is_ascii_alphabetic() || b == b'_') {
            return self.fail("an identifier");
        }
        while self.peek().is_some_and(|b| b.is_ascii_alphanumeric() || b == b'_') {
            self.at += 1;
        }
        Ok(self.text[start..self.at].to_string())
    }

    /// `item { ws "," ws item } [ ws "," ]` up to `close` (RON allows a trailing comma).
    fn ron_seq<T>(&mut self, close: u8, mut item: impl FnMut(&mut Self) -> R<T>) -> R<Vec<T>> {
        let mut out = vec![];
        self.ws();
        while !self.eat(close) {
            out.push(item(self)?);
            self.ws();
            if self.eat(b',') {
                self.ws();
            } else {
                self.ws();
                return if self.eat(close) { Ok(out) } else { self.fail("a comma or a closing bracket") };
            }
        }
        Ok(out)
    }

    fn ron_field(&mut self) -> R<(String, Value)> {
        let name = self.ident()?;
        self.ws();
        self.expect(b':', "a colon after a field name")?;
        self.ws();
        Ok((name, self.ron_value()?))
    }

    /// Whether an identifier followed by a colon starts here (an unnamed struct's field).
    fn at_field(&self) -> bool {
        let mut i = self.at;
        if !self.s.get(i).is_some_and(|b| b.is_ascii_alphabetic() || *b == b'_') {
            return false;
        }
        while self.s.get(i).is_some_and(|b| b.is_ascii_alphanumeric() || *b == b'_') {
            i += 1;
        }
        while matches!(self.s.get(i), Some(b' ' | b'\t' | b'\n' | b'\r')) {
            i += 1;
        }
        self.s.get(i) == Some(&b':')
    }

    fn ron_value(&mut self) -> R<Value> {
        match self.peek() {
            Some(b'"') => Ok(Value::Str(self.string()?)),
            Some(b'0'..=b'9') => Ok(Value::Int(self.integer()?)),
            Some(b'[') => {
                self.at += 1;
                Ok(Value::List(self.ron_seq(b']', Self::ron_value)?))
            }
            Some(b'(') => {
                self.at += 1;
                self.ws();
                if self.at_field() {
                    let fields = self.ron_seq(b')', Self::ron_field)?;
                    return Ok(Value::Named { name: String::new(), fields: Some(fields) });
                }
                Ok(Value::Tuple(self.ron_seq(b')', Self::ron_value)?))
            }
            Some(b) if b.is_ascii_alphabetic() || b == b'_' => {
                let name = self.ident()?;
                let save = self.at;
                self.ws();
                if self.eat(b'(') {
                    self.ws();
                    // `Name(field: ...)` or `Name()`: a struct; `Name(value, ...)`: a value wrapped
                    // in an identifier, such as `Some("5/2")` (RON's optional value).
                    if self.at_field() || self.peek() == Some(b')') {
                        let fields = self.ron_seq(b')', Self::ron_field)?;
                        return Ok(Value::Named { name, fields: Some(fields) });
                    }
                    let items = self.ron_seq(b')', Self::ron_value)?;
                    return Ok(Value::Wrapped { name, items });
                }
                self.at = save;
                Ok(Value::Named { name, fields: None })
            }
            _ => self.fail("a value"),
        }
    }

    /// `value { ws "," ws value }` up to `close` (JSON: no trailing comma).
    fn json_seq<T>(&mut self, close: u8, mut item: impl FnMut(&mut Self) -> R<T>) -> R<Vec<T>> {
        let mut out = vec![];
        self.ws();
        if self.eat(close) {
            return Ok(out);
        }
        loop {
            out.push(item(self)?);
            self.ws();
            if self.eat(close) {
                return Ok(out);
            }
            self.expect(b',', "a comma or a closing bracket")?;
            self.ws();
        }
    }

    fn json_object(&mut self) -> R<Value> {
        self.expect(b'{', "an object")?;
        let members = self.json_seq(b'}', |p| {
            let key = p.string()?;
            p.ws();
            p.expect(b':', "a colon after a key")?;
            p.ws();
            let value = if key.starts_with(|c: char| c.is_ascii_uppercase()) {
                p.json_object()?
            } else {
                p.json_value()?
            };
            Ok((key, value))
        })?;
        for (i, (k, _)) in members.iter().enumerate() {
            if members[..i].iter().any(|(e, _)| e == k) {
                return Err(SyntaxFault::DuplicateKey(k.clone()));
            }
        }
        Ok(Value::Object(members))
    }

    fn json_value(&mut self) -> R<Value> {
        match self.peek() {
            Some(b'"') => Ok(Value::JsonStr(self.string()?)),
            Some(b'0'..=b'9') => Ok(Value::Int(self.integer()?)),
            Some(b'[') => {
                self.at += 1;
                Ok(Value::Array(self.json_seq(b']', Self::json_value)?))
            }
            Some(b'{') => self.json_object(),
            _ => self.fail("a value"),
        }
    }
}

/// Parses a whole file in the given encoding.
pub fn parse(text: &str, encoding: Encoding) -> Result<Value, SyntaxFault> {
    let mut p = Parser { s: text.as_bytes(), text, at: 0 };
    p.ws();
    let v = match encoding {
        Encoding::Ron => p.ron_value()?,
        Encoding::Json => p.json_object()?,
    };
    p.ws();
    if p.at != p.s.len() {
        return p.fail("the end of the file");
    }
    Ok(v)
}
