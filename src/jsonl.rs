//! The JSON Lines protocol of `polysect check` and `polysect crossings`: one input
//! line in, one output line out, an `{"error": ...}` line for anything invalid.
//!
//! Numbers are parsed to the nearest `f64`, correctly rounded (serde_json's
//! `float_roundtrip`), so a one-ulp gap in the input stays a one-ulp gap; integer
//! tokens are accepted as coordinates; a number beyond the `f64` range is an error.
//! Output numbers are printed so that they parse back to the same `f64`.

use crate::kernel::Point;
use crate::polygon::{ConvexPolygon, SimplePolygon};
use serde::Deserialize;
use serde_json::Value;

/// One input line: two vertex lists and an optional `id` that is echoed back.
#[derive(Debug, Deserialize)]
struct PairLine {
    p: Vec<[f64; 2]>,
    q: Vec<[f64; 2]>,
    #[serde(default)]
    id: Option<Value>,
}

/// An input line parsed into two vertex lists, or the message for its error line.
#[derive(Debug)]
pub struct ParsedPair {
    pub p: Vec<Point>,
    pub q: Vec<Point>,
    pub id: Option<Value>,
}

/// Parses one line (without its line terminator) of `{"p": [[x, y], ...], "q": [...]}`.
/// The error is a message for the user and names what is wrong.
pub fn parse_pair(line: &[u8]) -> Result<ParsedPair, LineError> {
    let text = std::str::from_utf8(line).map_err(|e| LineError {
        id: None,
        message: format!("line is not valid UTF-8 (byte {})", e.valid_up_to()),
    })?;
    if text.trim().is_empty() {
        return Err(LineError {
            id: None,
            message: "empty line: expected {\"p\": [[x, y], ...], \"q\": [[x, y], ...]}".into(),
        });
    }
    let value: Value = serde_json::from_str(text).map_err(|e| LineError {
        id: None,
        message: format!("invalid JSON: {e}"),
    })?;
    let id = value.get("id").cloned();
    let pair: PairLine = serde_json::from_value(value).map_err(|e| LineError {
        id: id.clone(),
        message: format!("expected {{\"p\": [[x, y], ...], \"q\": [[x, y], ...]}}: {e}"),
    })?;
    let points = |v: Vec<[f64; 2]>| v.into_iter().map(Point::from).collect::<Vec<_>>();
    Ok(ParsedPair {
        p: points(pair.p),
        q: points(pair.q),
        id: pair.id,
    })
}

/// An error line: the message and the input's `id`, if it had one.
#[derive(Debug, Clone, PartialEq)]
pub struct LineError {
    pub id: Option<Value>,
    pub message: String,
}

/// Formats an output object: `{"id": ..., "<key>": <json>}` with the id first when present.
pub fn output_line(id: Option<&Value>, key: &str, json: &str) -> String {
    match id {
        Some(id) => format!("{{\"id\": {id}, \"{key}\": {json}}}"),
        None => format!("{{\"{key}\": {json}}}"),
    }
}

/// Formats an error line.
pub fn error_line(e: &LineError) -> String {
    let msg = serde_json::to_string(&e.message).expect("a string serialises");
    output_line(e.id.as_ref(), "error", &msg)
}

/// Validates both polygons of a parsed pair; errors name the polygon (`p` or `q`).
pub fn convex_pair(pair: &ParsedPair) -> Result<(ConvexPolygon, ConvexPolygon), LineError> {
    let make = |name: &str, pts: &[Point]| {
        ConvexPolygon::new(pts.iter().copied()).map_err(|e| LineError {
            id: pair.id.clone(),
            message: format!("{name}: {e}"),
        })
    };
    Ok((make("p", &pair.p)?, make("q", &pair.q)?))
}

/// Answers one `check` line: `{"intersects": true|false}` or `{"error": ...}`.
pub fn check_line(line: &[u8], answer: impl Fn(&ConvexPolygon, &ConvexPolygon) -> bool) -> String {
    let result = parse_pair(line).and_then(|pair| {
        let (p, q) = convex_pair(&pair)?;
        Ok((pair.id, answer(&p, &q)))
    });
    match result {
        Ok((id, hit)) => output_line(id.as_ref(), "intersects", if hit { "true" } else { "false" }),
        Err(e) => error_line(&e),
    }
}

/// Validates both polygons of a parsed pair as simple polygons; errors name the
/// polygon (`p` or `q`).
pub fn simple_pair(pair: &ParsedPair) -> Result<(SimplePolygon, SimplePolygon), LineError> {
    let make = |name: &str, pts: &[Point]| {
        SimplePolygon::new(pts.iter().copied()).map_err(|e| LineError {
            id: pair.id.clone(),
            message: format!("{name}: {e}"),
        })
    };
    Ok((make("p", &pair.p)?, make("q", &pair.q)?))
}

/// Answers one `crossings` line: `{"points": [[x, y], ...]}` or `{"error": ...}`.
pub fn crossings_line(line: &[u8], answer: impl Fn(&SimplePolygon, &SimplePolygon) -> Vec<Point>) -> String {
    let result = parse_pair(line).and_then(|pair| {
        let (p, q) = simple_pair(&pair)?;
        Ok((pair.id, answer(&p, &q)))
    });
    match result {
        Ok((id, points)) => output_line(id.as_ref(), "points", &points_json(&points)),
        Err(e) => error_line(&e),
    }
}

/// A vertex list as JSON, each number printed so that it parses back to the same `f64`.
pub fn points_json(points: &[Point]) -> String {
    let pairs: Vec<[f64; 2]> = points.iter().map(|&p| p.into()).collect();
    serde_json::to_string(&pairs).expect("finite numbers serialise")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::intersect::{Algorithm, ArrayIntersection, Linear};

    fn check(line: &str) -> String {
        check_line(line.as_bytes(), |p, q| Linear.intersects(p, q))
    }

    #[test]
    fn answers_and_echoes_ids() {
        assert_eq!(
            check(r#"{"p": [[0,0],[1,0],[0,1]], "q": [[1,0],[2,0],[2,1]]}"#),
            r#"{"intersects": true}"#
        );
        assert_eq!(
            check(r#"{"id": "a", "p": [[0,0],[1,0],[0,1]], "q": [[1.5,0],[2,0],[2,1]], "extra": 1}"#),
            r#"{"id": "a", "intersects": false}"#
        );
    }

    #[test]
    fn every_bad_line_is_an_error_line() {
        for (line, needle) in [
            ("", "empty line"),
            ("   ", "empty line"),
            ("{", "invalid JSON"),
            ("[1, 2]", "expected"),
            (r#"{"p": [[0,0],[1,0],[0,1]]}"#, "missing field `q`"),
            (r#"{"p": [[0,0],[1,0],[0,1,2]], "q": []}"#, "expected"),
            (
                r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,1]]}"#,
                "q: a polygon needs at least 3",
            ),
            (
                r#"{"p": [[0,0],[4,0],[4,4],[2,1],[0,4]], "q": [[0,0],[1,0],[0,1]]}"#,
                "p: vertex 3 is reflex",
            ),
            (
                r#"{"p": [[0,0],[1e400,0],[0,1]], "q": [[0,0],[1,0],[0,1]]}"#,
                "invalid JSON",
            ),
            (
                r#"{"p": [[0,0],["1",0],[0,1]], "q": [[0,0],[1,0],[0,1]]}"#,
                "expected",
            ),
        ] {
            let out = check(line);
            let v: Value = serde_json::from_str(&out).unwrap();
            let msg = v["error"].as_str().unwrap_or_else(|| panic!("{line} -> {out}"));
            assert!(msg.contains(needle), "{line} -> {msg}");
        }
        let out = check_line(b"{\"p\": \xff}", |_, _| true);
        assert!(out.contains("not valid UTF-8"), "{out}");
    }

    #[test]
    fn parsing_is_correctly_rounded() {
        // 2^53 + 1 is a tie between 2^53 and 2^53 + 2 (round to even: 2^53); the extra
        // digits push it above the tie.
        let pair = parse_pair(br#"{"p": [[9007199254740993.0000000000000001, 0.1]], "q": []}"#).unwrap();
        assert_eq!(pair.p[0].x, 9007199254740994.0);
        assert_eq!(pair.p[0].y, 0.1);
        let big_int = parse_pair(br#"{"p": [[123456789012345678901234567890, -0]], "q": []}"#).unwrap();
        assert_eq!(big_int.p[0].x, 123456789012345678901234567890.0);
        assert!(Algorithm::ALL.contains(&Algorithm::Linear));
    }

    #[test]
    fn crossings_lines_answer_and_report_errors() {
        use crate::crossings::{Crossings, Sweep};
        let cross = |line: &str| crossings_line(line.as_bytes(), |p, q| Sweep.crossings(p, q));
        assert_eq!(
            cross(r#"{"id": 7, "p": [[0,0],[2,0],[2,2],[0,2]], "q": [[1,1],[3,1],[3,3]]}"#),
            r#"{"id": 7, "points": [[2.0,1.0],[2.0,2.0]]}"#
        );
        assert_eq!(
            cross(r#"{"p": [[0,0],[1,0],[0,1]], "q": [[5,5],[6,5],[5,6]]}"#),
            r#"{"points": []}"#
        );
        for (line, needle) in [
            (
                r#"{"p": [[0,0],[2,2],[2,0],[0,2]], "q": [[0,0],[1,0],[0,1]]}"#,
                "p: the boundary intersects itself",
            ),
            (
                r#"{"p": [[0,0],[1,0],[0,1]], "q": [[0,0],[1,1]]}"#,
                "q: a polygon needs at least 3",
            ),
            ("{", "invalid JSON"),
        ] {
            let out = cross(line);
            assert!(out.contains(needle), "{line} -> {out}");
        }
    }

    #[test]
    fn printed_numbers_round_trip() {
        let pts = [Point::new(0.1, 5e-324), Point::new(f64::MAX, -1.0f64.next_up())];
        let text = points_json(&pts);
        let back: Vec<[f64; 2]> = serde_json::from_str(&text).unwrap();
        assert_eq!(back, vec![[0.1, 5e-324], [f64::MAX, -1.0f64.next_up()]]);
    }
}
