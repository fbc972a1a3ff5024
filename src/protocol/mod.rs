//! The line protocols of the command line, in the library so they are unit-tested and
//! fuzzed: [`check`] (`polysect check` and `polysect crossings`: two polygons per line)
//! and [`scene`] (`polysect scene`: a session of edits and queries). The binary only
//! wires standard input and output to them.
//!
//! # Lines
//! Input is JSON Lines: every line (ended by `\n`, or by the end of the input) gets
//! exactly one reply line, in order. A line must be one JSON object with the protocol's
//! fields; anything else (an empty line, invalid JSON or UTF-8, an array, a missing or
//! mistyped field, a repeated key, an invalid polygon, a refused edit) gets
//! `{"error": "line N[, column C]: ..."}`, where N counts lines from 1 and C counts bytes
//! from 1 within the line (given when the error has a place in the JSON), and the
//! session goes on. Keys the protocol does not know are ignored; every key it knows
//! must have its type wherever it appears.
//!
//! # The id
//! A line's `"id"` (any JSON value) is echoed as the first field of its reply,
//! byte for byte as written (`12345678901234567890123`, `1e400`, `null`, strings with
//! escapes, objects), on answers and error lines alike, whenever the id's own value is
//! valid JSON. A repeated `"id"` is an error that echoes the first.
//!
//! # Numbers
//! Coordinates are parsed to the nearest `f64`, correctly rounded; integer tokens are
//! accepted; a number beyond the `f64` range is an error. Output numbers print so that
//! they parse back to the same `f64` (the shortest such decimal).
//!
//! # Streaming and memory
//! Input is read in 64 KiB blocks and parsed straight from them into typed values (no
//! line buffer and no generic JSON tree): a line costs its parsed points (16 bytes per
//! point), its id text and the polygons built from it. Replies are buffered while
//! more input is already read, and flushed before every read that may block, so a
//! client that writes a line and waits for its reply gets it, and a bulk input is
//! answered in large writes.

pub mod check;
mod json;
mod line;
pub mod scene;

use crate::kernel::Point;
use std::fmt::Write as _;

/// Appends `[x,y]`, each number printed so that it parses back to the same `f64`.
pub(crate) fn write_point(out: &mut String, p: Point) {
    // `{:?}` prints the shortest decimal that round-trips, with an exponent when long;
    // every finite value prints as a valid JSON number.
    let _ = write!(out, "[{:?},{:?}]", p.x, p.y);
}

/// A vertex list as JSON, each number printed so that it parses back to the same `f64`.
///
/// ```
/// use polysect::Point;
/// let text = polysect::protocol::points_json(&[Point::new(0.1, -2.0), Point::new(1e300, 5e-324)]);
/// assert_eq!(text, "[[0.1,-2.0],[1e300,5e-324]]");
/// ```
pub fn points_json(points: &[Point]) -> String {
    let mut out = String::with_capacity(2 + 24 * points.len());
    out.push('[');
    for (i, &p) in points.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        write_point(&mut out, p);
    }
    out.push(']');
    out
}

#[cfg(test)]
mod tests;
