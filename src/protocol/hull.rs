//! The `hull` line protocol: each line `{"points": [[x, y], ...]}` (other keys
//! ignored, `"id"` echoed verbatim) gets one reply line
//! `{"hull": [[x, y], ...], "diameter": [[x, y], [x, y]]}` or `{"error": ...}`.
//!
//! # Answers
//! `hull` is [`hull_vertices`]: counter-clockwise, strictly convex (no repeated and no
//! collinear vertices), starting at the lowest vertex, the leftmost of those.
//! `diameter` is a farthest pair of the points (rotating calipers on the hull, exact),
//! the two listed in their order in `hull`.
//!
//! Degenerate sets are answered, not refused: one distinct point `p` (given once or
//! repeated) gives `"hull": [p], "diameter": [p, p]`; points on one line give the two
//! extreme points as both the hull and the diameter, the lowest (then leftmost) first.
//! An empty `points` array is an error.

use super::line::{Channel, Stop, serve};
use super::{points_json, write_point};
use crate::kernel::Point;
use crate::polygon::calipers::farthest_pair_of_hull;
use crate::polygon::{HullAlgorithm, PolygonError, hull_vertices};
use std::io::{self, Read, Write};

/// The expected shape, for messages.
const SHAPE: &str = r#"{"points": [[x, y], ...]}"#;

fn parse_points<R: Read, W: Write>(ch: &mut Channel<R, W>) -> Result<Option<Vec<Point>>, Stop> {
    let mut points = None;
    ch.object(SHAPE, &["points"], |ch, _| {
        points = ch.points("points")?;
        Ok(())
    })?;
    Ok(points)
}

/// One line's answer body: `"hull": [...], "diameter": [a, b]`, or the error message.
fn answer(points: Option<Vec<Point>>, algorithm: HullAlgorithm) -> Result<String, String> {
    let points = points.ok_or("missing field `points`")?;
    let hull = hull_vertices(&points, algorithm).map_err(|e| match e {
        PolygonError::TooFewVertices { .. } => {
            "`points` is empty: a hull needs at least one point".to_string()
        }
        PolygonError::NonFinite { index, .. } => format!("point {index} has a non-finite coordinate"),
        other => other.to_string(),
    })?;
    let (a, b) = match hull.len() {
        1 => (hull[0], hull[0]),
        2 => (hull[0], hull[1]),
        _ => {
            let (a, b) = farthest_pair_of_hull(&hull);
            let at = |p: Point| hull.iter().position(|&q| q == p);
            if at(a) <= at(b) { (a, b) } else { (b, a) }
        }
    };
    let mut body = format!("\"hull\": {}, \"diameter\": [", points_json(&hull));
    write_point(&mut body, a);
    body.push(',');
    write_point(&mut body, b);
    body.push(']');
    Ok(body)
}

/// Runs the `hull` protocol from `input` to `output` with `algorithm`: one reply line
/// per input line, in order; a bad line gets `{"error": "line N[, column C]: ..."}`
/// and the session goes on. Replies are flushed whenever the next input line is not
/// already read.
///
/// # Errors
/// Only I/O errors (reading `input`, writing `output`); bad lines get error lines.
///
/// ```
/// use polysect::polygon::HullAlgorithm;
/// let input = br#"{"id": "a", "points": [[0,0],[2,0],[1,1],[2,2],[0,2]]}
/// {"points": [[1,1],[1,1]]}
/// {"points": []}
/// "#;
/// let mut out = Vec::new();
/// polysect::protocol::hull::hull(&input[..], &mut out, HullAlgorithm::Graham)?;
/// let out = String::from_utf8(out).unwrap();
/// let lines: Vec<&str> = out.lines().collect();
/// assert_eq!(
///     lines[0],
///     r#"{"id": "a", "hull": [[0.0,0.0],[2.0,0.0],[2.0,2.0],[0.0,2.0]], "diameter": [[0.0,0.0],[2.0,2.0]]}"#
/// );
/// assert_eq!(lines[1], r#"{"hull": [[1.0,1.0]], "diameter": [[1.0,1.0],[1.0,1.0]]}"#);
/// assert!(lines[2].starts_with(r#"{"error": "line 3: `points` is empty"#));
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn hull<R: Read, W: Write>(input: R, output: W, algorithm: HullAlgorithm) -> io::Result<()> {
    let mut ch = Channel::new(input, output);
    serve(&mut ch, parse_points, |points| answer(points, algorithm))
}

/// Answers one `hull` line (without its terminator) as [`hull`] would, returning the
/// reply without its newline; the line is numbered 1 in messages.
pub fn hull_line(line: &[u8], algorithm: HullAlgorithm) -> String {
    super::check::one_line(line, |input, out| hull(input, out, algorithm))
}
