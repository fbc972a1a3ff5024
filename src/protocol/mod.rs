//! The line protocols of the command line, in the library so they are unit-tested and
//! fuzzed: [`check`] (`polysect check` and `polysect crossings`: two polygons per line),
//! [`contact`] (`polysect contact`: distance or depth and overlap per line),
//! [`hull`] (`polysect hull`: a point set per line) and [`scene`] (`polysect scene`: a session of edits and queries). The binary only
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
pub mod contact;
pub mod hull;
mod json;
mod line;
pub mod scene;

use crate::intersect::Certificate;
use crate::kernel::Point;
use std::fmt::Write as _;

/// Appends `[x,y]`, each number printed so that it parses back to the same `f64`.
pub(crate) fn write_point(out: &mut String, p: Point) {
    // `{:?}` prints the shortest decimal that round-trips, with an exponent when long;
    // every finite value prints as a valid JSON number.
    let _ = write!(out, "[{:?},{:?}]", p.x, p.y);
}

/// Appends the reply body of a certified answer: `"intersects": BOOL, "certificate":
/// {...}` in the CLI contract's form (`check --certificate`, the scene's `intersects`
/// with `--certificate`), every coordinate printed so that it parses back to the same
/// `f64`. [`certificate_from_json`](crate::certificate_json::certificate_from_json)
/// reads the certificate object back.
///
/// ```
/// use polysect::Point;
/// use polysect::intersect::{Certificate, Which};
/// let c = Certificate::Separated { of: Which::Q, from: Point::new(0.1, 5e-324), to: Point::new(-0.0, 1e300) };
/// assert_eq!(
///     polysect::protocol::certified_answer_json(&c),
///     r#""intersects": false, "certificate": {"separating_edge": {"of": "q", "from": [0.1,5e-324], "to": [-0.0,1e300]}}"#
/// );
/// ```
pub fn certified_answer_json(certificate: &Certificate) -> String {
    let mut out = String::with_capacity(128);
    let _ = write!(
        out,
        "\"intersects\": {}, \"certificate\": {{",
        certificate.intersects()
    );
    match *certificate {
        Certificate::Separated { of, from, to } => {
            let _ = write!(
                out,
                "\"separating_edge\": {{\"of\": \"{}\", \"from\": ",
                of.name()
            );
            write_point(&mut out, from);
            out.push_str(", \"to\": ");
            write_point(&mut out, to);
        }
        Certificate::VertexInside { of, point } => {
            let _ = write!(out, "\"vertex_inside\": {{\"of\": \"{}\", \"point\": ", of.name());
            write_point(&mut out, point);
        }
        Certificate::CrossingEdges { p, q } => {
            out.push_str("\"crossing_edges\": {\"p\": ");
            out.push_str(&points_json(&p));
            out.push_str(", \"q\": ");
            out.push_str(&points_json(&q));
        }
    }
    out.push_str("}}");
    out
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
