//! The `check` and `crossings` line protocols: each line `{"p": [[x, y], ...], "q":
//! [[x, y], ...]}` (other keys ignored, `"id"` echoed verbatim) gets one reply line:
//! `{"intersects": true|false}` or `{"points": [[x, y], ...]}`, or `{"error": ...}`.

use super::line::{Channel, Stop, each_line, serve};
use super::points_json;
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
fn convex_pair(pair: PairLine) -> Result<(ConvexPolygon, ConvexPolygon), String> {
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

/// Answers one `crossings` line as [`crossings`] would.
pub fn crossings_line(
    line: &[u8],
    answer: impl FnMut(&SimplePolygon, &SimplePolygon) -> Vec<Point>,
) -> String {
    one_line(line, |input, out| crossings(input, out, answer))
}

fn one_line(line: &[u8], run: impl FnOnce(&[u8], &mut Vec<u8>) -> io::Result<()>) -> String {
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

/// Reads `check` lines and hands each line's number and its two validated polygons
/// (or the error message) to `each`, until the input ends or `each` returns false.
///
/// # Errors
/// Only I/O errors of `input`.
pub fn for_each_pair<R: Read>(
    input: R,
    mut each: impl FnMut(u64, Result<(ConvexPolygon, ConvexPolygon), String>) -> bool,
) -> io::Result<()> {
    let mut ch = Channel::new(input, io::sink());
    let mut line = 0;
    each_line(&mut ch, parse_pair, |_, parsed| {
        line += 1;
        Ok(each(
            line,
            parsed.and_then(|pair| convex_pair(pair).map_err(|m| format!("line {line}: {m}"))),
        ))
    })
}
