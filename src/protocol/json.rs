//! JSON values read straight off a [`Channel`] into typed values: the line's top-level
//! object with its known keys, point lists, points, strings, integer ids, and a
//! validating skip (optionally capturing the value's verbatim text) for everything
//! else. No generic JSON tree is ever built.
//!
//! Strict JSON (RFC 8259) within one line: a raw newline ends the line wherever it
//! is. Numbers are parsed to the nearest `f64`, correctly rounded (serde_json's parser
//! with `float_roundtrip`, on the token's bytes); integer tokens are coordinates like
//! any other; a number beyond the `f64` range is an error. Strings are validated
//! (escapes, surrogate pairs, UTF-8, no control characters).
//!
//! # Complexity
//! O(length of the line) time. Memory: the typed values (16 bytes a point), the id's
//! text, the longest string or number token, and for skipped values one byte per level
//! of nesting (an explicit stack, never recursion, so any depth is fine).

use super::line::{Channel, Stop};
use crate::kernel::Point;
use std::collections::HashSet;
use std::io::{Read, Write};

/// What a JSON value starting with byte `b` is, for messages.
pub(crate) fn kind(b: u8) -> &'static str {
    match b {
        b'{' => "an object",
        b'[' => "an array",
        b'"' => "a string",
        b'-' | b'0'..=b'9' => "a number",
        b't' | b'f' => "a boolean",
        b'n' => "null",
        b'\n' => "the end of the line",
        _ => "an invalid character",
    }
}

fn value_start(b: u8) -> bool {
    matches!(b, b'{' | b'[' | b'"' | b'-' | b'0'..=b'9' | b't' | b'f' | b'n')
}

fn number_byte(b: u8) -> bool {
    b.is_ascii_digit() || matches!(b, b'-' | b'+' | b'.' | b'e' | b'E')
}

/// `-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?`, and whether it is an integer
/// (neither fraction nor exponent).
fn json_number(t: &[u8]) -> Option<bool> {
    let mut i = usize::from(t.first() == Some(&b'-'));
    let digits = |i: &mut usize| {
        let s = *i;
        while *i < t.len() && t[*i].is_ascii_digit() {
            *i += 1;
        }
        *i - s
    };
    match t.get(i) {
        Some(b'0') => i += 1,
        Some(b'1'..=b'9') => {
            digits(&mut i);
        }
        _ => return None,
    }
    let mut integer = true;
    if t.get(i) == Some(&b'.') {
        i += 1;
        integer = false;
        if digits(&mut i) == 0 {
            return None;
        }
    }
    if matches!(t.get(i), Some(b'e' | b'E')) {
        i += 1;
        integer = false;
        if matches!(t.get(i), Some(b'+' | b'-')) {
            i += 1;
        }
        if digits(&mut i) == 0 {
            return None;
        }
    }
    (i == t.len()).then_some(integer)
}

/// A token or key for a message: valid UTF-8 text, shortened when long.
pub(crate) fn shown(bytes: &[u8]) -> String {
    let text = String::from_utf8_lossy(bytes);
    if text.chars().count() > 40 {
        let head: String = text.chars().take(40).collect();
        format!("{head}...")
    } else {
        text.into_owned()
    }
}

/// A parsed number token.
pub(crate) enum Number {
    /// A finite value (the nearest `f64`).
    Finite(f64),
    /// Beyond the `f64` range; the token, shortened.
    OutOfRange(String),
}

/// A parsed integer id.
pub(crate) enum Integer {
    Value(u64),
    /// The token, shortened, and why it is not an id.
    Invalid(String, &'static str),
}

/// Bit of the `"id"` key in the seen-keys mask.
const ID_BIT: u64 = 1 << 63;

impl<R: Read, W: Write> Channel<R, W> {
    /// Reads the line's top-level object. `"id"` is captured verbatim; each key of
    /// `keys` is handed to `field` with its index (the value must be consumed); other
    /// keys are skipped. A repeated key is an error naming it; so is a line that is
    /// empty or not an object (`shape` describes the expected object). The line must
    /// end after the object.
    pub(crate) fn object(
        &mut self,
        shape: &str,
        keys: &[&str],
        mut field: impl FnMut(&mut Self, usize) -> Result<(), Stop>,
    ) -> Result<(), Stop> {
        debug_assert!(keys.len() < 63);
        let b = self.ws()?;
        if b == b'\n' {
            self.fail(None, format!("empty line: expected {shape}"));
            return Ok(());
        }
        if b != b'{' {
            let at = self.column();
            if !value_start(b) {
                return Err(self.syntax(at, format!("invalid JSON: expected a JSON object {shape}")));
            }
            // Valid JSON of the wrong kind, or invalid JSON: say which.
            self.skip_value()?;
            return Err(self.syntax(at, format!("expected a JSON object {shape}, found {}", kind(b))));
        }
        self.bump();
        let mut seen = 0u64;
        let mut unknown: HashSet<Vec<u8>> = HashSet::new();
        let mut b = self.ws()?;
        if b == b'}' {
            self.bump();
        } else {
            loop {
                let at = self.column();
                let mut key = std::mem::take(&mut self.keybuf);
                key.clear();
                self.key_into(b, &mut key)?;
                self.ws()?;
                let known = keys.iter().position(|k| k.as_bytes() == key.as_slice());
                let bit = match known {
                    Some(i) => 1u64 << i,
                    None if key == b"id" => ID_BIT,
                    None => 0,
                };
                let repeated = if bit != 0 {
                    let r = seen & bit != 0;
                    seen |= bit;
                    r
                } else {
                    !unknown.insert(key.clone())
                };
                if repeated {
                    self.fail(Some(at), format!("repeated key `{}`", shown(&key)));
                    self.skip_value()?;
                } else if bit == ID_BIT {
                    self.capture_id()?;
                } else if let Some(i) = known {
                    field(self, i)?;
                } else {
                    self.skip_value()?;
                }
                self.keybuf = key;
                match self.ws()? {
                    b',' => {
                        self.bump();
                        b = self.ws()?;
                    }
                    b'}' => {
                        self.bump();
                        break;
                    }
                    other => {
                        let at = self.column();
                        return Err(self.syntax(
                            at,
                            format!(
                                "invalid JSON: expected ',' or '}}' after a value, found {}",
                                kind(other)
                            ),
                        ));
                    }
                }
            }
        }
        let b = self.ws()?;
        if b != b'\n' {
            let at = self.column();
            return Err(self.syntax(at, "invalid JSON: trailing characters after the object"));
        }
        Ok(())
    }

    /// Skips the id's value, keeping its verbatim text.
    fn capture_id(&mut self) -> Result<(), Stop> {
        self.capture = Some(Vec::new());
        self.capture_from = self.pos;
        let skipped = self.skip_value();
        let mut text = self.capture.take().unwrap_or_default();
        skipped?;
        text.extend_from_slice(&self.buf[self.capture_from..self.pos]);
        // Strings were validated as UTF-8 and everything else is ASCII.
        self.id = String::from_utf8(text).ok();
        Ok(())
    }

    /// Skips one JSON value, validating it. Keeps an explicit stack, so any nesting
    /// depth is fine.
    pub(crate) fn skip_value(&mut self) -> Result<(), Stop> {
        let mut stack: Vec<u8> = Vec::new();
        'value: loop {
            let b = self.ws()?;
            let at = self.column();
            match b {
                b'{' => {
                    self.bump();
                    if self.ws()? == b'}' {
                        self.bump();
                    } else {
                        stack.push(b'{');
                        self.member_key()?;
                        continue 'value;
                    }
                }
                b'[' => {
                    self.bump();
                    if self.ws()? == b']' {
                        self.bump();
                    } else {
                        stack.push(b'[');
                        continue 'value;
                    }
                }
                b'"' => {
                    let mut s = std::mem::take(&mut self.scratch);
                    s.clear();
                    let r = self.string_into(&mut s);
                    self.scratch = s;
                    r?;
                }
                b'-' | b'0'..=b'9' => self.number_token(|_, _| ())?,
                b't' => self.literal(b"true")?,
                b'f' => self.literal(b"false")?,
                b'n' => self.literal(b"null")?,
                other => {
                    return Err(self.syntax(
                        at,
                        format!("invalid JSON: expected a value, found {}", kind(other)),
                    ));
                }
            }
            // A value is complete: close the containers it completes.
            while let Some(&top) = stack.last() {
                let c = self.ws()?;
                let at = self.column();
                match (top, c) {
                    (b'[', b',') => {
                        self.bump();
                        continue 'value;
                    }
                    (b'{', b',') => {
                        self.bump();
                        self.ws()?;
                        self.member_key()?;
                        continue 'value;
                    }
                    (b'[', b']') | (b'{', b'}') => {
                        self.bump();
                        stack.pop();
                    }
                    (b'[', other) => {
                        return Err(self.syntax(
                            at,
                            format!("invalid JSON: expected ',' or ']', found {}", kind(other)),
                        ));
                    }
                    (_, other) => {
                        return Err(self.syntax(
                            at,
                            format!("invalid JSON: expected ',' or '}}', found {}", kind(other)),
                        ));
                    }
                }
            }
            return Ok(());
        }
    }

    /// Inside an object being skipped: a key and its colon.
    fn member_key(&mut self) -> Result<(), Stop> {
        let b = self.ws()?;
        let mut s = std::mem::take(&mut self.scratch);
        s.clear();
        let r = self.key_into(b, &mut s);
        self.scratch = s;
        r
    }

    /// A key (the next byte, `b`, must open it) decoded into `out`, and its colon.
    fn key_into(&mut self, b: u8, out: &mut Vec<u8>) -> Result<(), Stop> {
        if b != b'"' {
            let at = self.column();
            return Err(self.syntax(
                at,
                format!("invalid JSON: expected a key (a string), found {}", kind(b)),
            ));
        }
        self.string_into(out)?;
        if self.ws()? != b':' {
            let at = self.column();
            return Err(self.syntax(at, "invalid JSON: expected ':' after the key"));
        }
        self.bump();
        Ok(())
    }

    fn literal(&mut self, word: &[u8]) -> Result<(), Stop> {
        let at = self.column();
        for &w in word {
            if self.peek()? != w {
                return Err(self.syntax(at, "invalid JSON: expected a value (true, false or null?)"));
            }
            self.bump();
        }
        Ok(())
    }

    /// Reads a string (the next byte is its opening quote), appending its decoded text
    /// to `out`, which must hold valid UTF-8 afterwards.
    pub(crate) fn string_into(&mut self, out: &mut Vec<u8>) -> Result<(), Stop> {
        let at = self.column();
        let start = out.len();
        self.bump();
        loop {
            if self.pos == self.end && !self.fill()? {
                return Err(self.syntax(at, "invalid JSON: unterminated string"));
            }
            let block = &self.buf[self.pos..self.end];
            let n = block
                .iter()
                .position(|&b| b == b'"' || b == b'\\' || b < 0x20)
                .unwrap_or(block.len());
            out.extend_from_slice(&block[..n]);
            self.pos += n;
            if self.pos == self.end {
                continue;
            }
            match self.buf[self.pos] {
                b'"' => {
                    self.pos += 1;
                    break;
                }
                b'\\' => {
                    self.pos += 1;
                    self.escape(out)?;
                }
                b'\n' => return Err(self.syntax(at, "invalid JSON: unterminated string")),
                _ => {
                    let here = self.column();
                    return Err(self.syntax(here, "invalid JSON: control character in a string"));
                }
            }
        }
        if std::str::from_utf8(&out[start..]).is_err() {
            return Err(self.syntax(at, "invalid UTF-8 in a string"));
        }
        Ok(())
    }

    fn escape(&mut self, out: &mut Vec<u8>) -> Result<(), Stop> {
        let at = self.column() - 1;
        let c = self.peek()?;
        if c != b'\n' {
            self.bump();
        }
        let decoded = match c {
            b'"' => '"',
            b'\\' => '\\',
            b'/' => '/',
            b'b' => '\u{8}',
            b'f' => '\u{c}',
            b'n' => '\n',
            b'r' => '\r',
            b't' => '\t',
            b'u' => {
                let hi = self.hex4(at)?;
                let code = if (0xd800..0xdc00).contains(&hi) {
                    for expected in [b'\\', b'u'] {
                        if self.peek()? != expected {
                            return Err(self.syntax(at, "invalid JSON: unpaired surrogate in a \\u escape"));
                        }
                        self.bump();
                    }
                    let lo = self.hex4(at)?;
                    if !(0xdc00..0xe000).contains(&lo) {
                        return Err(self.syntax(at, "invalid JSON: unpaired surrogate in a \\u escape"));
                    }
                    0x10000 + ((hi - 0xd800) << 10) + (lo - 0xdc00)
                } else {
                    hi
                };
                char::from_u32(code)
                    .ok_or_else(|| self.syntax(at, "invalid JSON: unpaired surrogate in a \\u escape"))?
            }
            _ => return Err(self.syntax(at, "invalid JSON: invalid escape in a string")),
        };
        let mut utf8 = [0u8; 4];
        out.extend_from_slice(decoded.encode_utf8(&mut utf8).as_bytes());
        Ok(())
    }

    fn hex4(&mut self, at: u64) -> Result<u32, Stop> {
        let mut v = 0;
        for _ in 0..4 {
            let d = (self.peek()? as char)
                .to_digit(16)
                .ok_or_else(|| self.syntax(at, "invalid JSON: \\u needs four hex digits"))?;
            self.bump();
            v = v * 16 + d;
        }
        Ok(v)
    }

    /// Reads a number token (the next byte starts it) and hands its bytes to `f`.
    fn with_token<T>(&mut self, f: impl FnOnce(&[u8]) -> T) -> Result<T, Stop> {
        let start = self.pos;
        let run = self.buf[start..self.end].iter().position(|&b| !number_byte(b));
        if let Some(n) = run {
            self.pos = start + n;
            return Ok(f(&self.buf[start..self.pos]));
        }
        // The token reaches the end of the block: gather it across blocks.
        let mut s = std::mem::take(&mut self.scratch);
        s.clear();
        s.extend_from_slice(&self.buf[start..self.end]);
        self.pos = self.end;
        while self.fill()? {
            let block = &self.buf[..self.end];
            let n = block.iter().position(|&b| !number_byte(b)).unwrap_or(block.len());
            s.extend_from_slice(&block[..n]);
            self.pos = n;
            if n < self.end {
                break;
            }
        }
        let result = f(&s);
        self.scratch = s;
        Ok(result)
    }

    /// Reads a number token, checks the JSON grammar and hands its text and whether it
    /// is an integer to `f`.
    fn number_token<T>(&mut self, f: impl FnOnce(&str, bool) -> T) -> Result<T, Stop> {
        let at = self.column();
        self.with_token(|token| match json_number(token) {
            // The grammar is ASCII.
            Some(integer) => Ok(f(std::str::from_utf8(token).unwrap_or("0"), integer)),
            None => Err(format!("invalid JSON: invalid number `{}`", shown(token))),
        })?
        .map_err(|m| self.syntax(at, m))
    }

    /// A number as the nearest `f64`.
    fn number(&mut self) -> Result<Number, Stop> {
        let at = self.column();
        self.with_token(|token| {
            // serde_json's parser (with `float_roundtrip`) rounds correctly and reads the
            // bytes directly; it refuses what is not a JSON number and what overflows.
            match serde_json::from_slice::<f64>(token) {
                Ok(x) if x == 0.0 && token.first() == Some(&b'-') => Ok(Number::Finite(-0.0)),
                Ok(x) => Ok(Number::Finite(x)),
                Err(_) if json_number(token).is_some() => Ok(Number::OutOfRange(shown(token))),
                Err(_) => Err(format!("invalid JSON: invalid number `{}`", shown(token))),
            }
        })?
        .map_err(|m| self.syntax(at, m))
    }

    /// Records a type error at `at` for a value starting with `b` and skips the value
    /// (a syntax error inside it still stops the line).
    fn wrong_type(&mut self, at: u64, b: u8, message: String) -> Result<(), Stop> {
        if !value_start(b) {
            return Err(self.syntax(at, format!("invalid JSON: expected a value, found {}", kind(b))));
        }
        self.fail(Some(at), message);
        self.skip_value()
    }

    /// An array of `[x, y]` points. `None` after a recorded error (the value is consumed).
    pub(crate) fn points(&mut self, field: &str) -> Result<Option<Vec<Point>>, Stop> {
        let b = self.ws()?;
        let at = self.column();
        if b != b'[' {
            let m = format!("`{field}` must be an array of [x, y] points, found {}", kind(b));
            self.wrong_type(at, b, m)?;
            return Ok(None);
        }
        self.bump();
        let mut points = Vec::new();
        let mut ok = true;
        if self.ws()? == b']' {
            self.bump();
            return Ok(Some(points));
        }
        let mut index = 0usize;
        loop {
            match self.point_at(field, Some(index))? {
                Some(p) if ok => points.push(p),
                Some(_) => {}
                None => {
                    ok = false;
                    points = Vec::new();
                }
            }
            index += 1;
            if !self.array_continues()? {
                break;
            }
        }
        Ok(ok.then_some(points))
    }

    /// After an array element: consumes `,` (true: another element follows) or `]`
    /// (false: the array ended).
    fn array_continues(&mut self) -> Result<bool, Stop> {
        match self.ws()? {
            b',' => {
                self.bump();
                Ok(true)
            }
            b']' => {
                self.bump();
                Ok(false)
            }
            other => {
                let at = self.column();
                Err(self.syntax(
                    at,
                    format!("invalid JSON: expected ',' or ']', found {}", kind(other)),
                ))
            }
        }
    }

    /// One `[x, y]` point. `None` after a recorded error (the value is consumed).
    pub(crate) fn point(&mut self, field: &str) -> Result<Option<Point>, Stop> {
        self.point_at(field, None)
    }

    fn point_at(&mut self, field: &str, index: Option<usize>) -> Result<Option<Point>, Stop> {
        // The value's name for messages, built only when one is needed.
        let name = || match index {
            Some(i) => format!("`{field}`[{i}]"),
            None => format!("`{field}`"),
        };
        let b = self.ws()?;
        let at = self.column();
        if b != b'[' {
            let m = format!("{} must be a point [x, y], found {}", name(), kind(b));
            self.wrong_type(at, b, m)?;
            return Ok(None);
        }
        self.bump();
        let mut xy = [0.0; 2];
        let mut count = 0usize;
        let mut ok = true;
        if self.ws()? == b']' {
            self.bump();
        } else {
            loop {
                let c = self.ws()?;
                let at_c = self.column();
                if matches!(c, b'-' | b'0'..=b'9') {
                    match self.number()? {
                        Number::Finite(x) => {
                            if count < 2 {
                                xy[count] = x;
                            }
                        }
                        Number::OutOfRange(t) => {
                            ok = false;
                            self.fail(
                                Some(at_c),
                                format!("{}: the number {t} is beyond the f64 range", name()),
                            );
                        }
                    }
                } else {
                    ok = false;
                    let m = format!("{}[{count}] must be a number, found {}", name(), kind(c));
                    self.wrong_type(at_c, c, m)?;
                }
                count += 1;
                if !self.array_continues()? {
                    break;
                }
            }
        }
        if ok && count != 2 {
            self.fail(
                Some(at),
                format!("{} must be a point [x, y], found {count} numbers", name()),
            );
            ok = false;
        }
        Ok(ok.then(|| Point::new(xy[0], xy[1])))
    }

    /// A string value. `None` after a recorded error (the value is consumed).
    pub(crate) fn string(&mut self, field: &str) -> Result<Option<String>, Stop> {
        let b = self.ws()?;
        let at = self.column();
        if b != b'"' {
            let m = format!("`{field}` must be a string, found {}", kind(b));
            self.wrong_type(at, b, m)?;
            return Ok(None);
        }
        let mut s = Vec::new();
        self.string_into(&mut s)?;
        Ok(String::from_utf8(s).ok())
    }

    /// A non-negative integer written as an integer token. `None` after a recorded
    /// error (the value is consumed).
    pub(crate) fn integer(&mut self, field: &str) -> Result<Option<u64>, Stop> {
        let b = self.ws()?;
        let at = self.column();
        if !matches!(b, b'-' | b'0'..=b'9') {
            let m = format!("`{field}` must be an integer vertex id, found {}", kind(b));
            self.wrong_type(at, b, m)?;
            return Ok(None);
        }
        let parsed = self.number_token(|text, integer| {
            if !integer {
                Integer::Invalid(
                    shown(text.as_bytes()),
                    "an id is an integer, without fraction or exponent",
                )
            } else if text.starts_with('-') {
                Integer::Invalid(shown(text.as_bytes()), "an id is not negative")
            } else {
                match text.parse() {
                    Ok(v) => Integer::Value(v),
                    Err(_) => Integer::Invalid(shown(text.as_bytes()), "no vertex has an id this large"),
                }
            }
        })?;
        match parsed {
            Integer::Value(v) => Ok(Some(v)),
            Integer::Invalid(text, why) => {
                self.fail(Some(at), format!("`{field}` is {text}: {why}"));
                Ok(None)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn number_grammar() {
        for ok in [
            "0",
            "-0",
            "1",
            "12",
            "1.5",
            "-1.5e3",
            "1E+2",
            "0.0e-0",
            "123456789012345678901234567890",
        ] {
            assert!(json_number(ok.as_bytes()).is_some(), "{ok}");
        }
        for bad in [
            "", "-", "01", "1.", ".5", "+1", "1e", "1e+", "--1", "1.5.2", "1e5e5", "0x10", "1-2",
        ] {
            assert!(json_number(bad.as_bytes()).is_none(), "{bad}");
        }
        assert_eq!(json_number(b"12"), Some(true));
        assert_eq!(json_number(b"1.0"), Some(false));
        assert_eq!(json_number(b"1e2"), Some(false));
    }

    #[test]
    fn kinds_and_shown_tokens() {
        assert_eq!(kind(b'{'), "an object");
        assert_eq!(kind(b'7'), "a number");
        assert_eq!(shown(&[b'9'; 100]).len(), 43);
    }
}
