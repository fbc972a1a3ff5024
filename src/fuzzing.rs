//! Fuzz harnesses: each takes arbitrary bytes, turns them into an input, runs the
//! library on it and panics only when an invariant is broken. The same functions back
//! the seeded random-input driver in `tests/fuzz.rs` (run by CI) and the `cargo fuzz`
//! targets in `fuzz/`.
//!
//! Inputs print as Rust source (`FuzzPoint`'s `Debug`), so a failing case pastes straight
//! into a regression test.

use crate::intersect::{Algorithm, ArrayIntersection, Linear, brute_force};
use crate::kernel::{Exact, Point, Precision};
use crate::polygon::{ConvexPolygon, EditError, LinkedPolygon, PolygonError, convex_hull};
use crate::protocol;
use std::fmt;

/// A point whose `Debug` is the Rust expression that builds it.
#[derive(Clone, Copy, PartialEq)]
pub struct FuzzPoint(pub Point);

fn rust_f64(x: f64) -> String {
    if x.is_nan() {
        "f64::NAN".into()
    } else if x == f64::INFINITY {
        "f64::INFINITY".into()
    } else if x == f64::NEG_INFINITY {
        "f64::NEG_INFINITY".into()
    } else {
        format!("{x:?}")
    }
}

impl fmt::Debug for FuzzPoint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Point::new({}, {})", rust_f64(self.0.x), rust_f64(self.0.y))
    }
}

/// Values that stress the predicates: zeros, ulps, subnormals, the extremes of the
/// exponent range, large offsets.
const SPECIAL: [f64; 16] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    5e-324,
    -5e-324,
    f64::MIN_POSITIVE,
    f64::MAX,
    f64::MIN,
    1.0000000000000002,
    0.9999999999999999,
    1125899906842624.0, // 2^50
    4503599627370496.0, // 2^52
    1e-300,
    1e300,
    f64::NAN,
];

/// Reads bytes as a stream of coordinates: one selector byte, then either a special
/// value, a small integer (exact touchings), a raw bit pattern (anything, NaN included)
/// or a value near 2^50.
pub struct Decoder<'a> {
    bytes: &'a [u8],
}

impl<'a> Decoder<'a> {
    pub fn new(bytes: &'a [u8]) -> Self {
        Decoder { bytes }
    }

    pub fn byte(&mut self) -> Option<u8> {
        let (&b, rest) = self.bytes.split_first()?;
        self.bytes = rest;
        Some(b)
    }

    pub fn f64(&mut self) -> Option<f64> {
        let sel = self.byte()?;
        Some(match sel % 4 {
            0 => SPECIAL[(sel / 4) as usize % SPECIAL.len()],
            1 => (self.byte()? as i8) as f64,
            2 => {
                let mut raw = [0u8; 8];
                for b in &mut raw {
                    *b = self.byte()?;
                }
                f64::from_le_bytes(raw)
            }
            _ => 1125899906842624.0 + (self.byte()? as i8) as f64 * 0.25,
        })
    }

    pub fn point(&mut self) -> Option<Point> {
        Some(Point::new(self.f64()?, self.f64()?))
    }

    /// Up to `max` points (the first byte says how many).
    pub fn points(&mut self, max: usize) -> Vec<Point> {
        let n = self.byte().map_or(0, |b| b as usize % (max + 1));
        (0..n).map_while(|_| self.point()).collect()
    }
}

/// Construction from arbitrary coordinates: never panics; a polygon that is built is
/// valid and made of input vertices; an error names an input index in range; the
/// clockwise list gives the same result. Returns whether a polygon was built.
pub fn polygon_construction(bytes: &[u8]) -> bool {
    let pts = Decoder::new(bytes).points(12);
    let result = ConvexPolygon::new(pts.iter().copied());
    match &result {
        Ok(p) => {
            p.debug_validate()
                .unwrap_or_else(|e| panic!("{e}: {:?}", debug_points(&pts)));
            assert!(p.vertices().iter().all(|v| pts.contains(v)));
        }
        Err(PolygonError::NonFinite { index, .. }) => assert!(!pts[*index].is_finite()),
        Err(
            PolygonError::Reflex { index }
            | PolygonError::OutOfOrder { index }
            | PolygonError::DoublesBack { index },
        ) => {
            assert!(*index < pts.len())
        }
        Err(_) => {}
    }
    let mut reversed = pts.clone();
    reversed.reverse();
    let back = ConvexPolygon::new(reversed);
    assert_eq!(
        result.is_ok(),
        back.is_ok(),
        "orientation changed validity: {:?}",
        debug_points(&pts)
    );
    if let Ok(h) = convex_hull(&pts) {
        h.debug_validate().unwrap();
    }
    result.is_ok()
}

fn debug_points(pts: &[Point]) -> Vec<FuzzPoint> {
    pts.iter().map(|&p| FuzzPoint(p)).collect()
}

/// A sequence of edits on a linked polygon: each accepted edit keeps every invariant,
/// each refused edit changes nothing, stale handles are always refused. Returns whether
/// some edit was accepted.
pub fn edit_sequence(bytes: &[u8]) -> bool {
    let mut d = Decoder::new(bytes);
    let start = d.points(8);
    let Ok(hull) = convex_hull(&start) else {
        return false;
    };
    let mut poly = LinkedPolygon::from_convex(&hull);
    let mut accepted = false;
    let mut removed = Vec::new();
    while let Some(op) = d.byte() {
        let handles: Vec<_> = poly.iter().map(|(id, _)| id).collect();
        let v = handles[op as usize / 4 % handles.len()];
        let before = poly.to_convex();
        let result = match op % 4 {
            0 => d.point().map(|p| poly.insert_after(v, p).map(|_| ())),
            1 => Some(poly.remove(v).map(|_| removed.push(v))),
            2 => d.point().map(|p| poly.move_vertex(v, p).map(|_| ())),
            _ => removed.last().map(|&gone| {
                assert_eq!(poly.point(gone), Err(EditError::StaleHandle));
                Ok(())
            }),
        };
        match result {
            None => break,
            Some(Ok(())) => {
                accepted |= op % 4 != 3;
                poly.debug_validate()
                    .unwrap_or_else(|e| panic!("after op {op}: {e}"))
            }
            Some(Err(_)) => assert_eq!(poly.to_convex(), before, "a refused edit changed the polygon"),
        }
    }
    accepted
}

/// One `check` line from arbitrary bytes: the reply is one JSON object with either
/// `intersects` or `error`, for every algorithm and precision. Returns whether the line
/// was answered (not an error).
pub fn json_line(bytes: &[u8]) -> bool {
    let mut answered = false;
    for &algorithm in Algorithm::ALL {
        for precision in Precision::ALL {
            let reply = protocol::check::check_line(bytes, |p, q| algorithm.intersects(precision, p, q));
            let v: serde_json::Value = serde_json::from_str(&reply).expect("the reply is JSON");
            assert!(
                v.get("intersects").is_some() != v.get("error").is_some(),
                "{reply}"
            );
            answered |= v.get("intersects").is_some();
        }
    }
    answered
}

/// Two polygons from arbitrary coordinates (their hulls): every algorithm agrees with
/// [`Linear`] and the O(n·m) oracle under the exact kernel, and none panics under the
/// fast kernel. Returns whether both hulls existed (the pair was tested).
pub fn algorithms_agree(bytes: &[u8]) -> bool {
    let mut d = Decoder::new(bytes);
    let (a, b) = (d.points(16), d.points(16));
    let (Ok(p), Ok(q)) = (convex_hull(&a), convex_hull(&b)) else {
        return false;
    };
    let truth = brute_force(Exact, &p, &q);
    assert_eq!(
        Linear.intersects(&p, &q),
        truth,
        "linear: {:?} {:?}",
        debug_points(&a),
        debug_points(&b)
    );
    for &algorithm in Algorithm::ALL {
        assert_eq!(
            algorithm.intersects(Precision::Exact, &p, &q),
            truth,
            "{algorithm}: {:?} {:?}",
            debug_points(p.vertices()),
            debug_points(q.vertices())
        );
        let _ = algorithm.intersects(Precision::Fast, &p, &q);
    }
    true
}

/// Two simple polygons, either from arbitrary coordinates (vertex lists, or the same
/// points in star order around their mean, which is simple far more often) or from an
/// adversarial family (zigzags, needle combs, vertical edges, edges on lines through
/// one point, collinear overlaps: [`hard_pair`](crate::generate::hard::hard_pair)) with
/// a size, a seed and exact transformations (swap, reversal, mirroring, scaling by a
/// power of two) read from the bytes: validation never panics, and the sweep, both
/// sweeps it chooses between and the brute force report exactly the same points under
/// the exact kernel, with and without touchings. Returns whether both polygons were
/// valid (the pair was compared).
pub fn crossings_agree(bytes: &[u8]) -> bool {
    use crate::crossings::{
        Brute, CrossingAlgorithm, CrossingOptions, Crossings, ListSweep, Sweep, Touching, TreeSweep,
    };
    use crate::generate::hard::{HardFamily, hard_pair};
    use crate::generate::simple::star_order;
    use crate::polygon::SimplePolygon;
    use rand::SeedableRng;
    let mut d = Decoder::new(bytes);
    let mode = d.byte().unwrap_or(0);
    let (p, q) = if mode % 4 == 3 {
        // An adversarial family.
        let family = HardFamily::ALL[d.byte().unwrap_or(0) as usize % HardFamily::ALL.len()];
        let n = 8 + d.byte().unwrap_or(0) as usize % 64;
        let seed = (0..8).fold(0u64, |s, _| s << 8 | d.byte().unwrap_or(0) as u64);
        let (mut p, mut q) = hard_pair(family, n, &mut rand::rngs::SmallRng::seed_from_u64(seed));
        let t = d.byte().unwrap_or(0);
        let e = (d.byte().unwrap_or(0) as i8 as i32) * 8;
        let s = 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
        let mirror = if t & 4 != 0 { -1.0 } else { 1.0 };
        let map = |poly: &SimplePolygon| poly.map(|v| Point::new(mirror * v.x * s, v.y * s));
        if let (Ok(a), Ok(b)) = (map(&p), map(&q)) {
            (p, q) = (a, b);
        }
        if t & 1 != 0 {
            std::mem::swap(&mut p, &mut q);
        }
        if t & 2 != 0 {
            p = p.reversed();
        }
        (p, q)
    } else {
        let star = mode.is_multiple_of(2);
        let (a, b) = (d.points(24), d.points(24));
        let make = |pts: Vec<Point>| {
            let n = pts.len() as f64;
            let mean = Point::new(
                pts.iter().map(|p| p.x / n).sum(),
                pts.iter().map(|p| p.y / n).sum(),
            );
            let pts = if star && mean.is_finite() {
                star_order(&pts, mean)
            } else {
                pts
            };
            SimplePolygon::new(pts)
        };
        let (Ok(p), Ok(q)) = (make(a), make(b)) else {
            return false;
        };
        (p, q)
    };
    p.debug_validate().unwrap();
    q.debug_validate().unwrap();
    for touching in [Touching::Include, Touching::Exclude] {
        let options = CrossingOptions { touching };
        let brute = Brute.crossings_with_options(Exact, &p, &q, options);
        for (name, got) in [
            ("sweep", Sweep.crossings_with_options(Exact, &p, &q, options)),
            (
                "list-sweep",
                ListSweep.crossings_with_options(Exact, &p, &q, options),
            ),
            (
                "tree-sweep",
                TreeSweep.crossings_with_options(Exact, &p, &q, options),
            ),
        ] {
            assert_eq!(
                got,
                brute,
                "{name}, touching {touching}: {:?} {:?}",
                debug_points(p.vertices()),
                debug_points(q.vertices())
            );
        }
    }
    let _ = CrossingAlgorithm::Sweep.run(Precision::Fast, &p, &q);
    let _ = TreeSweep.crossings_with(crate::kernel::Fast, &p, &q);
    true
}

/// Names the scene harness uses: a few, so that ops meet the same polygons.
const SCENE_NAMES: [&str; 4] = ["a", "b", "\u{e9}", "a\"b"];

/// One `scene` line from the decoder: an op of every kind with names from a small pool,
/// small ids, points and point lists from [`Decoder`] (non-finite values print as
/// `null`), and now and then a mutated byte or a raw byte string.
fn scene_line(d: &mut Decoder<'_>) -> Option<Vec<u8>> {
    use serde_json::json;
    let sel = d.byte()?;
    let name = SCENE_NAMES[(sel as usize / 16) % SCENE_NAMES.len()];
    let other = SCENE_NAMES[d.byte()? as usize % SCENE_NAMES.len()];
    let pt = |p: Point| json!([p.x, p.y]);
    let mut line = match sel % 12 {
        0 | 1 => {
            let mut pts = d.points(10);
            if sel % 12 == 1 {
                // Mostly valid: the hull of the points, either way round.
                pts = convex_hull(&pts).map(|h| h.into_vertices()).unwrap_or(pts);
                if sel % 3 == 0 {
                    pts.reverse();
                }
            }
            json!({"op": "add", "name": name, "points": pts.into_iter().map(pt).collect::<Vec<_>>()})
        }
        2 => json!({"op": "drop", "name": name}),
        3 | 4 => json!({"op": "insert", "name": name, "after": d.byte()? % 12, "point": pt(d.point()?)}),
        5 => json!({"op": "remove", "name": name, "vertex": d.byte()? % 12}),
        6 => json!({"op": "move", "name": name, "vertex": d.byte()? % 12, "to": pt(d.point()?)}),
        7 => json!({"op": "translate", "name": name, "by": pt(d.point()?)}),
        8 => json!({"op": "intersects", "a": name, "b": other}),
        9 => json!({"op": "pairs"}),
        10 => json!({"op": "vertices", "name": name}),
        _ => {
            // Raw bytes up to a newline.
            let n = d.byte()? as usize % 24;
            return Some((0..n).map_while(|_| d.byte()).filter(|&b| b != b'\n').collect());
        }
    }
    .to_string()
    .into_bytes();
    if sel % 5 == 0 {
        let at = d.byte()? as usize % line.len();
        line[at] = d.byte()?;
    }
    Some(line)
}

/// A `scene` session from arbitrary bytes, under a strategy the first byte picks, on
/// both kernels: every line gets one JSON object reply (an answer or a located error),
/// a refused line changes nothing, the names and ids always match the scene exactly
/// (`debug_validate`), and the two kernels agree on everything but query answers.
/// Returns whether some edit or add was accepted.
pub fn scene_ops(bytes: &[u8]) -> bool {
    use crate::protocol::scene::{SceneOptions, SceneSession};
    use crate::store::Strategy;
    let mut d = Decoder::new(bytes);
    let Some(first) = d.byte() else {
        return false;
    };
    let options = SceneOptions {
        strategy: Strategy::ALL[first as usize % Strategy::ALL.len()],
        seed: Some(u64::from(first)),
        certificate: false,
    };
    let mut exact = SceneSession::with_kernel(Exact, options);
    let mut fast = SceneSession::with_kernel(crate::kernel::Fast, options);
    let mut accepted = false;
    let mut number = 0;
    while let Some(line) = scene_line(&mut d) {
        number += 1;
        let before = exact.state();
        let reply = exact.answer_line(&line);
        let shown = String::from_utf8_lossy(&line).into_owned();
        assert!(!reply.contains('\n'), "{shown} -> {reply}");
        let value: serde_json::Value = match serde_json::from_str(&reply) {
            Ok(v) => v,
            // JSON allows numbers beyond f64 (an echoed id); serde_json does not.
            Err(e) if e.to_string().contains("number out of range") => continue,
            Err(e) => panic!("{e}: {shown} -> {reply}"),
        };
        let object = value.as_object().unwrap_or_else(|| panic!("{shown} -> {reply}"));
        let keys: Vec<&str> = object.keys().map(String::as_str).filter(|&k| k != "id").collect();
        match keys.as_slice() {
            ["error"] => {
                let message = object["error"].as_str().unwrap_or_default();
                assert!(
                    message.starts_with(&format!("line {number}")),
                    "{shown} -> {reply}"
                );
                assert_eq!(exact.state(), before, "a refused line changed the scene: {shown}");
            }
            ["ok"] | ["vertex"] => accepted = true,
            ["intersects"] | ["pairs"] | ["ids", "points"] => {}
            _ => panic!("unexpected reply: {shown} -> {reply}"),
        }
        exact
            .debug_validate()
            .unwrap_or_else(|e| panic!("{e} after {shown}"));
        let fast_reply = fast.answer_line(&line);
        if !matches!(keys.as_slice(), ["intersects"] | ["pairs"]) {
            assert_eq!(fast_reply, reply, "the kernels disagree on an edit: {shown}");
        }
    }
    fast.debug_validate().unwrap();
    accepted
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn debug_prints_rust_source() {
        let p = FuzzPoint(Point::new(f64::NAN, -0.0));
        assert_eq!(format!("{p:?}"), "Point::new(f64::NAN, -0.0)");
        let q = FuzzPoint(Point::new(5e-324, f64::NEG_INFINITY));
        assert_eq!(format!("{q:?}"), "Point::new(5e-324, f64::NEG_INFINITY)");
    }
}
