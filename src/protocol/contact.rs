//! The `contact` line protocol: each `check` line `{"p": [...], "q": [...]}` gets
//! `{"intersects": false, "distance": D, "closest": [[x,y],[x,y]]}` or
//! `{"intersects": true, "depth": D, "normal": [nx,ny], "overlap": [[x,y],...], "area": A}`
//! (module docs of [`crate::contact`] for the values), or `{"error": ...}`; `"id"`
//! echoed as in `check`. A distance, depth or area whose correctly rounded value
//! overflows prints as `null`.
//!
//! [`contact_with_kernel`] answers pairs that do not meet by
//! [`distance_with`] (no big integers nearly always)
//! and the others by [`contact_with`]: the same reply,
//! byte for byte, as [`contact_json`] of the full contact.

use super::check::{convex_pair, one_line, parse_pair};
use super::line::{Channel, serve};
use super::{points_json, write_point};
use crate::contact::{Contact, Distance, contact_with, distance_with};
use crate::kernel::{Kernel, Point};
use crate::polygon::ConvexPolygon;
use std::fmt::Write as _;
use std::io::{self, Read, Write};

/// A number that parses back to the same `f64`, or `null`.
fn number(out: &mut String, x: Option<f64>) {
    match x {
        Some(x) => {
            let _ = write!(out, "{x:?}");
        }
        None => out.push_str("null"),
    }
}

/// The reply body of one contact answer, in the contract's field order.
///
/// ```
/// use polysect::contact::contact;
/// use polysect::ConvexPolygon;
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let q = ConvexPolygon::new([[3.0, 0.0], [4.0, 0.0], [4.0, 1.0]])?;
/// assert_eq!(
///     polysect::protocol::contact::contact_json(&contact(&p, &q)),
///     r#""intersects": false, "distance": 1.0, "closest": [[2.0,0.0],[3.0,0.0]]"#
/// );
/// # Ok::<(), polysect::PolygonError>(())
/// ```
pub fn contact_json(contact: &Contact) -> String {
    let mut out = String::with_capacity(96);
    match contact {
        Contact::Separated(s) => write_separated(&mut out, s.distance, s.closest),
        Contact::Overlapping(o) => {
            out.push_str("\"intersects\": true, \"depth\": ");
            number(&mut out, o.depth);
            out.push_str(", \"normal\": ");
            write_point(&mut out, Point::new(o.normal[0], o.normal[1]));
            out.push_str(", \"overlap\": ");
            out.push_str(&points_json(&o.overlap));
            out.push_str(", \"area\": ");
            number(&mut out, o.area);
        }
    }
    out
}

/// The reply body of a pair that does not meet: `"intersects": false`, the distance
/// and the closest pair.
fn write_separated(out: &mut String, distance: Option<f64>, closest: [Point; 2]) {
    out.push_str("\"intersects\": false, \"distance\": ");
    number(out, distance);
    out.push_str(", \"closest\": [");
    write_point(out, closest[0]);
    out.push(',');
    write_point(out, closest[1]);
    out.push(']');
}

/// The reply body of a [`Distance`]: the same as [`contact_json`] of the separated
/// contact it comes from (the same distance and closest pair).
///
/// ```
/// use polysect::contact::{contact, distance};
/// use polysect::protocol::contact::{contact_json, distance_json};
/// use polysect::ConvexPolygon;
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let q = ConvexPolygon::new([[3.0, 0.5], [4.0, 0.0], [4.0, 1.0]])?;
/// let d = distance(&p, &q).expect("apart");
/// assert_eq!(distance_json(&d), contact_json(&contact(&p, &q)));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
pub fn distance_json(distance: &Distance) -> String {
    let mut out = String::with_capacity(96);
    write_separated(&mut out, distance.distance, distance.closest);
    out
}

/// The reply body for `p` and `q` under `kernel`: [`distance_json`] of
/// [`distance_with`] when they do not meet, else [`contact_json`] of [`contact_with`];
/// byte for byte [`contact_json`] of [`contact_with`] either way (both find the same
/// feature, and the roundings are correct), without the exact rationals of a
/// separated pair.
pub fn contact_reply<K: Kernel>(kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> String {
    match distance_with(kernel, p, q) {
        Some(d) => distance_json(&d),
        None => contact_json(&contact_with(kernel, p, q)),
    }
}

/// [`contact`] answering every line by [`contact_reply`] under `kernel` (what
/// `polysect contact` runs).
///
/// # Errors
/// Only I/O errors; bad lines get error lines.
pub fn contact_with_kernel<K: Kernel, R: Read, W: Write>(kernel: K, input: R, output: W) -> io::Result<()> {
    let mut ch = Channel::new(input, output);
    serve(&mut ch, parse_pair, |pair| {
        let (p, q) = convex_pair(pair)?;
        Ok(contact_reply(kernel, &p, &q))
    })
}

/// Runs the `contact` protocol from `input` to `output`: one reply line per input line
/// ([`contact_json`] of `answer`'s contact for the two polygons as cleaned), or an error
/// line as in [`check`](super::check::check).
///
/// # Errors
/// Only I/O errors; bad lines get error lines.
///
/// ```
/// use polysect::contact::contact;
/// // Moving q up or right by 1 separates them (a tie): the first in the walk's order.
/// let input = br#"{"id": 1, "p": [[0,0],[2,0],[2,2],[0,2]], "q": [[1,1],[3,1],[3,3],[1,3]]}"#;
/// let mut out = Vec::new();
/// polysect::protocol::contact::contact(&input[..], &mut out, contact)?;
/// assert_eq!(
///     String::from_utf8(out).unwrap(),
///     "{\"id\": 1, \"intersects\": true, \"depth\": 1.0, \"normal\": [0.0,1.0], \
///      \"overlap\": [[1.0,1.0],[2.0,1.0],[2.0,2.0],[1.0,2.0]], \"area\": 1.0}\n"
/// );
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn contact<R: Read, W: Write>(
    input: R,
    output: W,
    mut answer: impl FnMut(&ConvexPolygon, &ConvexPolygon) -> Contact,
) -> io::Result<()> {
    let mut ch = Channel::new(input, output);
    serve(&mut ch, parse_pair, |pair| {
        let (p, q) = convex_pair(pair)?;
        Ok(contact_json(&answer(&p, &q)))
    })
}

/// Answers one `contact` line as [`contact`] would, returning the reply without its
/// newline; the line is numbered 1 in messages.
pub fn contact_line(line: &[u8], answer: impl FnMut(&ConvexPolygon, &ConvexPolygon) -> Contact) -> String {
    one_line(line, |input, out| contact(input, out, answer))
}
