//! The `check` and `crossings` line protocols: each line `{"p": [[x, y], ...], "q":
//! [[x, y], ...]}` (other keys ignored, `"id"` echoed verbatim) gets one reply line:
//! `{"intersects": true|false}` or `{"points": [[x, y], ...]}`, or `{"error": ...}`.

use super::line::{Channel, Stop, each_line, serve};
use super::{certified_answer_json, points_json};
use crate::intersect::Certificate;
use crate::kernel::Point;
use crate::polygon::{ConvexPolygon, SimplePolygon};
use std::io::{self, Read, Write};

/// The expected shape, for messages.
const SHAPE: &str = r#"{"p": [[x, y], ...], "q": [[x, y], ...]}"#;

/// One line's two vertex lists, as given.
#[derive(Debug, Default)]
pub(crate) struct PairLine {
    p: Option<Vec<Point>>,
    q: Option<Vec<Point>>,
}

impl PairLine {
    /// Both lists, or the error for the missing one.
    fn lists(self) -> Result<(Vec<Point>, Vec<Point>), String> {
        match (self.p, self.q) {
            (Some(p), Some(q)) => Ok((p, q)),
            (None, _) => Err("missing field `p`".into()),
            (_, None) => Err("missing field `q`".into()),
        }
    }
}

/// Reads one line's object into two vertex lists.
pub(crate) fn parse_pair<R: Read, W: Write>(ch: &mut Channel<R, W>) -> Result<PairLine, Stop> {
    let mut pair = PairLine::default();
    ch.object(SHAPE, &["p", "q"], |ch, key| {
        let (name, slot) = if key == 0 {
            ("p", &mut pair.p)
        } else {
            ("q", &mut pair.q)
        };
        *slot = ch.points(name)?;
        Ok(())
    })?;
    Ok(pair)
}

/// Validates both lists as convex polygons; errors name the polygon (`p` or `q`).
pub(crate) fn convex_pair(pair: PairLine) -> Result<(ConvexPolygon, ConvexPolygon), String> {
    let (p, q) = pair.lists()?;
    // Each list is validated and dropped before the next, so only one raw list and one
    // polygon under construction are alive at a time.
    let p = ConvexPolygon::new(p).map_err(|e| format!("p: {e}"))?;
    let q = ConvexPolygon::new(q).map_err(|e| format!("q: {e}"))?;
    Ok((p, q))
}

fn simple_pair(pair: PairLine) -> Result<(SimplePolygon, SimplePolygon), String> {
    let (p, q) = pair.lists()?;
    let p = SimplePolygon::new(p).map_err(|e| format!("p: {e}"))?;
    let q = SimplePolygon::new(q).map_err(|e| format!("q: {e}"))?;
    Ok((p, q))
}

/// Runs the `check` protocol from `input` to `output`: one reply line per input line,
/// `{"intersects": true|false}` from `answer`, or `{"error": "line N[, column C]: ..."}`.
/// Replies are flushed whenever the next input line is not already read.
///
/// # Errors
/// Only I/O errors (reading `input`, writing `output`); bad lines get error lines.
///
/// ```
/// use polysect::intersect::{ArrayIntersection, Barba};
/// let input = br#"{"id": 7, "p": [[0,0],[1,0],[0,1]], "q": [[1,0],[2,0],[2,1]]}
/// [[[0,0],[1,0],[0,1]], [[5,5],[6,5],[5,6]]]
/// "#;
/// let mut out = Vec::new();
/// polysect::protocol::check::check(&input[..], &mut out, |p, q| Barba.intersects(p, q))?;
/// let out = String::from_utf8(out).unwrap();
/// let lines: Vec<&str> = out.lines().collect();
/// assert_eq!(lines[0], r#"{"id": 7, "intersects": true}"#);
/// assert!(lines[1].starts_with(r#"{"error": "line 2, column 1: expected a JSON object"#));
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn check<R: Read, W: Write>(
    input: R,
    output: W,
    mut answer: impl FnMut(&ConvexPolygon, &ConvexPolygon) -> bool,
) -> io::Result<()> {
    let mut ch = Channel::new(input, output);
    serve(&mut ch, parse_pair, |pair| {
        let (p, q) = convex_pair(pair)?;
        Ok(format!("\"intersects\": {}", answer(&p, &q)))
    })
}

/// What [`check_expected`] found.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    /// Lines answered and compared with their `"expected"` field.
    pub compared: u64,
    /// Of those, the answers that differ from `"expected"`.
    pub disagreed: u64,
    /// Lines answered with an error instead (bad JSON, invalid polygon, no `"expected"`).
    pub errors: u64,
}

/// The `check` protocol comparing each answer with the line's `"expected"` field (a
/// boolean, as `polysect gen` writes it): the reply is `{"intersects": A, "agrees":
/// A == expected}`; a line without `"expected"`, or with a non-boolean one, is an error
/// line. `polysect check --verify-expected`.
///
/// # Errors
/// Only I/O errors; bad lines get error lines (and are counted in [`Tally::errors`]).
///
/// ```
/// use polysect::intersect::{ArrayIntersection, Barba};
/// let input = br#"{"expected": true, "p": [[0,0],[1,0],[0,1]], "q": [[1,0],[2,0],[2,1]]}
/// {"expected": true, "p": [[0,0],[1,0],[0,1]], "q": [[5,5],[6,5],[5,6]]}
/// {"p": [[0,0],[1,0],[0,1]], "q": [[5,5],[6,5],[5,6]]}
/// "#;
/// let mut out = Vec::new();
/// let tally = polysect::protocol::check::check_expected(&input[..], &mut out, |p, q| Barba.intersects(p, q))?;
/// let out = String::from_utf8(out).unwrap();
/// let lines: Vec<&str> = out.lines().collect();
/// assert_eq!(lines[0], r#"{"intersects": true, "agrees": true}"#);
/// assert_eq!(lines[1], r#"{"intersects": false, "agrees": false}"#);
/// assert!(lines[2].contains("missing field `expected`"));
/// assert_eq!((tally.compared, tally.disagreed, tally.errors), (2, 1, 1));
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn check_expected<R: Read, W: Write>(
    input: R,
    output: W,
    mut answer: impl FnMut(&ConvexPolygon, &ConvexPolygon) -> bool,
) -> io::Result<Tally> {
    let mut ch = Channel::new(input, output);
    let mut tally = Tally::default();
    serve(&mut ch, parse_expected, |(pair, expected)| {
        let outcome = (|| {
            let expected =
                expected.ok_or("missing field `expected` (--verify-expected compares the answer with it)")?;
            let (p, q) = convex_pair(pair)?;
            Ok::<_, String>((answer(&p, &q), expected))
        })();
        match outcome {
            Ok((got, expected)) => {
                tally.compared += 1;
                tally.disagreed += u64::from(got != expected);
                Ok(format!("\"intersects\": {got}, \"agrees\": {}", got == expected))
            }
            Err(message) => Err(message),
        }
    })?;
    // Lines that failed to parse never reached the closure above.
    tally.errors = ch.line_number() - tally.compared;
    Ok(tally)
}

/// Reads one line's object: the two vertex lists and the optional `"expected"`.
fn parse_expected<R: Read, W: Write>(ch: &mut Channel<R, W>) -> Result<(PairLine, Option<bool>), Stop> {
    let mut pair = PairLine::default();
    let mut expected = None;
    ch.object(SHAPE, &["p", "q", "expected"], |ch, key| {
        match key {
            0 => pair.p = ch.points("p")?,
            1 => pair.q = ch.points("q")?,
            _ => expected = ch.boolean("expected")?,
        }
        Ok(())
    })?;
    Ok((pair, expected))
}

/// Runs `check --certificate`: as [`check`], each answer with the certificate that
/// `answer` gives for the two polygons as cleaned, `{"intersects": BOOL, "certificate":
/// {...}}` ([`super::certified_answer_json`]).
///
/// # Errors
/// Only I/O errors; bad lines get error lines.
///
/// ```
/// use polysect::intersect::{ArrayIntersection, Barba};
/// let input = br#"{"p": [[0,0],[1,0],[0,1]], "q": [[2,0],[3,0],[3,1]]}"#;
/// let mut out = Vec::new();
/// polysect::protocol::check::check_certified(&input[..], &mut out, |p, q| Barba.certified(p, q))?;
/// assert!(String::from_utf8(out).unwrap().starts_with(r#"{"intersects": false, "certificate": {"separating_edge": "#));
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn check_certified<R: Read, W: Write>(
    input: R,
    output: W,
    mut answer: impl FnMut(&ConvexPolygon, &ConvexPolygon) -> Certificate,
) -> io::Result<()> {
    let mut ch = Channel::new(input, output);
    serve(&mut ch, parse_pair, |pair| {
        let (p, q) = convex_pair(pair)?;
        Ok(certified_answer_json(&answer(&p, &q)))
    })
}

/// Runs the `crossings` protocol: one reply line per input line, `{"points": [[x, y],
/// ...]}` from `answer` on two simple polygons, or an error line.
///
/// # Errors
/// Only I/O errors; bad lines get error lines.
pub fn crossings<R: Read, W: Write>(
    input: R,
    output: W,
    mut answer: impl FnMut(&SimplePolygon, &SimplePolygon) -> Vec<Point>,
) -> io::Result<()> {
    let mut ch = Channel::new(input, output);
    serve(&mut ch, parse_pair, |pair| {
        let (p, q) = simple_pair(pair)?;
        Ok(format!("\"points\": {}", points_json(&answer(&p, &q))))
    })
}

/// Answers one `check` line (without its terminator) as [`check`] would, returning the
/// reply without its newline; the line is numbered 1 in messages.
pub fn check_line(line: &[u8], answer: impl FnMut(&ConvexPolygon, &ConvexPolygon) -> bool) -> String {
    one_line(line, |input, out| check(input, out, answer))
}

/// Answers one `check --certificate` line as [`check_certified`] would.
pub fn check_certified_line(
    line: &[u8],
    answer: impl FnMut(&ConvexPolygon, &ConvexPolygon) -> Certificate,
) -> String {
    one_line(line, |input, out| check_certified(input, out, answer))
}

/// Answers one `crossings` line as [`crossings`] would.
pub fn crossings_line(
    line: &[u8],
    answer: impl FnMut(&SimplePolygon, &SimplePolygon) -> Vec<Point>,
) -> String {
    one_line(line, |input, out| crossings(input, out, answer))
}

pub(crate) fn one_line(line: &[u8], run: impl FnOnce(&[u8], &mut Vec<u8>) -> io::Result<()>) -> String {
    // A newline inside `line` would start a second line: answer only up to it.
    let line = line.split(|&b| b == b'\n').next().unwrap_or_default();
    let mut out = Vec::new();
    let input: &[u8] = if line.is_empty() { b"\n" } else { line };
    run(input, &mut out).expect("reading a slice and writing a Vec cannot fail");
    let mut text = String::from_utf8(out).expect("replies are UTF-8");
    if text.ends_with('\n') {
        text.pop();
    }
    text
}

/// Reads `check` lines and hands each line's number and its two vertex lists, as given
/// (not validated: the caller decides which polygon type they must be), or the line's
/// error message, to `each`, until the input ends or `each` returns false.
///
/// # Errors
/// Only I/O errors of `input`.
pub fn for_each_pair<R: Read>(
    input: R,
    mut each: impl FnMut(u64, Result<(Vec<Point>, Vec<Point>), String>) -> bool,
) -> io::Result<()> {
    for_each_pair_with_id(input, |line, _, pair| each(line, pair))
}

/// [`for_each_pair`], handing `each` also the line's `"id"` as its verbatim JSON text
/// (`None` when the line has none, or when it is not valid JSON).
///
/// # Errors
/// Only I/O errors of `input`.
pub fn for_each_pair_with_id<R: Read>(
    input: R,
    mut each: impl FnMut(u64, Option<&str>, Result<(Vec<Point>, Vec<Point>), String>) -> bool,
) -> io::Result<()> {
    let mut ch = Channel::new(input, io::sink());
    let mut line = 0;
    each_line(&mut ch, parse_pair, |ch, parsed| {
        line += 1;
        Ok(each(
            line,
            ch.id.as_deref(),
            parsed.and_then(|pair| pair.lists().map_err(|m| format!("line {line}: {m}"))),
        ))
    })
}
