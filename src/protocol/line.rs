//! The line layer shared by every protocol: a [`Channel`] reads input in blocks,
//! tracks line numbers and byte columns, writes one reply line per input line, and
//! flushes the replies before every read that may block.

use std::io::{self, Read, Write};

/// Input is read in blocks of this size.
const INPUT_BLOCK: usize = 64 * 1024;

/// Why a line's parse stopped before its end.
#[derive(Debug)]
pub(crate) enum Stop {
    /// Invalid JSON (or a line that is not an object): the rest of the line is
    /// skipped and the line answered with this error.
    Syntax { column: u64, message: String },
    /// Reading the input or writing the output failed: the session ends.
    Io(io::Error),
}

impl From<io::Error> for Stop {
    fn from(e: io::Error) -> Self {
        Stop::Io(e)
    }
}

/// One side of a line protocol: JSON Lines in from `R`, one reply line per input line
/// out to `W`.
///
/// Input is consumed straight from a fixed block buffer (no line buffer: a line of
/// any length costs only what its parsed values take). Before each read of a new
/// block the replies written so far are flushed, so a client that sends one line and
/// waits for its answer gets it, while a bulk input still leaves in large writes.
pub(crate) struct Channel<R, W> {
    reader: R,
    pub(super) buf: Box<[u8]>,
    pub(super) pos: usize,
    pub(super) end: usize,
    eof: bool,
    /// Input offset of `buf[0]`.
    base: u64,
    /// Input offset of the current line's first byte.
    line_start: u64,
    /// The current line's number, from 1.
    line: u64,
    out: W,
    /// Output written since the last flush.
    dirty: bool,
    /// While a value's verbatim text is being captured: its bytes from earlier blocks
    /// (the rest starts at `buf[capture_from]`).
    pub(super) capture: Option<Vec<u8>>,
    pub(super) capture_from: usize,
    /// Scratch memory for number tokens that straddle blocks and for strings.
    pub(super) scratch: Vec<u8>,
    pub(super) keybuf: Vec<u8>,
    /// The first error found on the current line: column (when there is one) and message.
    error: Option<(Option<u64>, String)>,
    /// The current line's `"id"`, as its verbatim JSON text.
    pub(super) id: Option<String>,
}

impl<R: Read, W: Write> Channel<R, W> {
    pub(crate) fn new(reader: R, out: W) -> Self {
        Channel {
            reader,
            buf: vec![0; INPUT_BLOCK].into_boxed_slice(),
            pos: 0,
            end: 0,
            eof: false,
            base: 0,
            line_start: 0,
            line: 0,
            out,
            dirty: false,
            capture: None,
            capture_from: 0,
            scratch: Vec::new(),
            keybuf: Vec::new(),
            error: None,
            id: None,
        }
    }

    /// Numbers the next line `line + 1` (for callers that feed lines one at a time).
    pub(crate) fn set_line_number(&mut self, line: u64) {
        self.line = line;
    }

    /// Reads the next block; false at the end of the input. Flushes the replies first
    /// (the read may block), and saves a captured value's bytes of the current block.
    pub(super) fn fill(&mut self) -> io::Result<bool> {
        if self.eof {
            return Ok(false);
        }
        if let Some(c) = &mut self.capture {
            c.extend_from_slice(&self.buf[self.capture_from..self.end]);
            self.capture_from = 0;
        }
        if self.dirty {
            self.out.flush()?;
            self.dirty = false;
        }
        self.base += self.end as u64;
        self.pos = 0;
        self.end = 0;
        loop {
            match self.reader.read(&mut self.buf) {
                Ok(0) => {
                    self.eof = true;
                    return Ok(false);
                }
                Ok(n) => {
                    self.end = n;
                    return Ok(true);
                }
                Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
                Err(e) => return Err(e),
            }
        }
    }

    /// The next byte without consuming it; `\n` at the end of the input (both end the line).
    #[inline]
    pub(super) fn peek(&mut self) -> Result<u8, Stop> {
        if self.pos < self.end || self.fill()? {
            Ok(self.buf[self.pos])
        } else {
            Ok(b'\n')
        }
    }

    /// Consumes the byte just peeked (never the end of the line).
    #[inline]
    pub(super) fn bump(&mut self) {
        debug_assert!(self.pos < self.end);
        self.pos += 1;
    }

    /// Skips JSON whitespace within the line and peeks at the next byte.
    #[inline]
    pub(super) fn ws(&mut self) -> Result<u8, Stop> {
        loop {
            let b = self.peek()?;
            if b == b' ' || b == b'\t' || b == b'\r' {
                self.pos += 1;
            } else {
                return Ok(b);
            }
        }
    }

    /// The byte column (from 1) of the next byte in the current line.
    #[inline]
    pub(super) fn column(&self) -> u64 {
        self.base + self.pos as u64 - self.line_start + 1
    }

    /// A syntax stop at `column`.
    pub(super) fn syntax(&self, column: u64, message: impl Into<String>) -> Stop {
        Stop::Syntax {
            column,
            message: message.into(),
        }
    }

    /// Records an error on the current line (only the first one is reported).
    pub(crate) fn fail(&mut self, column: Option<u64>, message: impl Into<String>) {
        if self.error.is_none() {
            self.error = Some((column, message.into()));
        }
    }

    /// The number of the current line (from 1), or of the last one after the input ended.
    pub(crate) fn line_number(&self) -> u64 {
        self.line
    }

    pub(crate) fn has_error(&self) -> bool {
        self.error.is_some()
    }

    /// Starts the next line; false when the input has ended.
    fn begin_line(&mut self) -> io::Result<bool> {
        if self.pos == self.end && !self.fill()? {
            return Ok(false);
        }
        self.line += 1;
        self.line_start = self.base + self.pos as u64;
        self.error = None;
        self.id = None;
        self.capture = None;
        Ok(true)
    }

    /// Consumes the rest of the current line and its terminator.
    fn finish_line(&mut self) -> io::Result<()> {
        loop {
            if self.pos == self.end && !self.fill()? {
                return Ok(());
            }
            let block = &self.buf[self.pos..self.end];
            match block.iter().position(|&b| b == b'\n') {
                Some(i) => {
                    self.pos += i + 1;
                    return Ok(());
                }
                None => self.pos = self.end,
            }
        }
    }

    /// Writes one reply line: `{"id": <id>, <body>}` (the id first when the line had one).
    pub(crate) fn reply(&mut self, body: &str) -> io::Result<()> {
        match &self.id {
            Some(id) => writeln!(self.out, "{{\"id\": {id}, {body}}}")?,
            None => writeln!(self.out, "{{{body}}}")?,
        }
        self.dirty = true;
        Ok(())
    }

    /// A reply whose body `write` produces piece by piece, for answers too large to
    /// hold. The replies before it are flushed first: computing this one may take
    /// long, and a reply once computed must not wait in a buffer for it.
    pub(crate) fn reply_streamed(&mut self, write: impl FnOnce(&mut W) -> io::Result<()>) -> io::Result<()> {
        self.flush()?;
        match &self.id {
            Some(id) => write!(self.out, "{{\"id\": {id}, ")?,
            None => write!(self.out, "{{")?,
        }
        self.dirty = true;
        write(&mut self.out)?;
        writeln!(self.out, "}}")
    }

    /// `message` located on the current line: `line N[, column C]: message`.
    pub(crate) fn located(&self, column: Option<u64>, message: &str) -> String {
        match column {
            Some(c) => format!("line {}, column {c}: {message}", self.line),
            None => format!("line {}: {message}", self.line),
        }
    }

    pub(crate) fn flush(&mut self) -> io::Result<()> {
        self.dirty = false;
        self.out.flush()
    }
}

/// Reads every line: `parse` reads one line's object (recording errors with
/// [`Channel::fail`]), then `each` gets the parsed value or the line's located error
/// message, and returns whether to go on. Stops at the end of the input or at an I/O
/// error.
pub(crate) fn each_line<R: Read, W: Write, T>(
    ch: &mut Channel<R, W>,
    mut parse: impl FnMut(&mut Channel<R, W>) -> Result<T, Stop>,
    mut each: impl FnMut(&mut Channel<R, W>, Result<T, String>) -> io::Result<bool>,
) -> io::Result<()> {
    let result = each_line_unflushed(ch, &mut parse, &mut each);
    if result.is_err() {
        // The replies already written are still delivered when the input or a reply fails.
        let _ = ch.flush();
    }
    result
}

fn each_line_unflushed<R: Read, W: Write, T>(
    ch: &mut Channel<R, W>,
    mut parse: impl FnMut(&mut Channel<R, W>) -> Result<T, Stop>,
    mut each: impl FnMut(&mut Channel<R, W>, Result<T, String>) -> io::Result<bool>,
) -> io::Result<()> {
    while ch.begin_line()? {
        let parsed = match parse(ch) {
            Ok(parsed) if !ch.has_error() => Some(parsed),
            Ok(_) => None,
            Err(Stop::Syntax { column, message }) => {
                ch.fail(Some(column), message);
                None
            }
            Err(Stop::Io(e)) => return Err(e),
        };
        ch.finish_line()?;
        let item = parsed.ok_or_else(|| {
            let (column, message) = ch.error.take().unwrap_or_default();
            ch.located(column, &message)
        });
        if !each(ch, item)? {
            break;
        }
    }
    ch.flush()
}

/// Runs a protocol over every line: `answer` turns a cleanly parsed line into a reply
/// body (`"key": value`) or an error message. One reply line per input line, in order;
/// a bad line never stops the session, an I/O error does.
pub(crate) fn serve<R: Read, W: Write, T>(
    ch: &mut Channel<R, W>,
    parse: impl FnMut(&mut Channel<R, W>) -> Result<T, Stop>,
    mut answer: impl FnMut(T) -> Result<String, String>,
) -> io::Result<()> {
    each_line(ch, parse, |ch, parsed| {
        let body = match parsed.and_then(|t| answer(t).map_err(|m| ch.located(None, &m))) {
            Ok(body) => body,
            Err(text) => format!("\"error\": {}", json_string(&text)),
        };
        ch.reply(&body)?;
        Ok(true)
    })
}

/// `s` as a JSON string literal.
pub(crate) fn json_string(s: &str) -> String {
    serde_json::to_string(s).expect("a string serialises")
}
