//! The overlap polygon P ∩ Q, exactly: its candidate vertices are the ends of the chords
//! each edge of one polygon cuts from the other (the O(log n) segment queries of
//! [`ConvexPolygon::segment_chord`]), constructed as exact rationals, then their exact
//! convex hull without collinear vertices.
//!
//! Every vertex of P ∩ Q is a vertex of P in Q, a vertex of Q in P, or a crossing of
//! an edge of each; each is an end of the chord that one of its polygon's edges cuts
//! from the other polygon (a chord end is an input vertex, a query endpoint or the
//! crossing of two edge lines), so the hull of all chord ends is P ∩ Q.

use super::construct::{Exact2, cross, exact, minus};
use crate::kernel::{Point, Sign};
use crate::polygon::{ChordEnd, ConvexPolygon};
use std::cmp::Ordering;

/// The exact crossing of the lines `a → b` and `c → d` (not parallel).
fn line_crossing(a: Point, b: Point, c: Point, d: Point) -> Exact2 {
    let (a, b, c, d) = (exact(a), exact(b), exact(c), exact(d));
    let r = minus(&b, &a);
    let s = minus(&d, &c);
    let t = cross(&minus(&c, &a), &s).div(&cross(&r, &s));
    [&a[0] + &(&r[0] * &t), &a[1] + &(&r[1] * &t)]
}

/// The chord ends that the edges of `cutter` cut from `other`, appended to `out`.
fn chord_ends(cutter: &ConvexPolygon, other: &ConvexPolygon, out: &mut Vec<Exact2>) {
    let (v, w) = (cutter.vertices(), other.vertices());
    let (n, m) = (v.len(), w.len());
    for i in 0..n {
        let (a, b) = (v[i], v[(i + 1) % n]);
        // Validated polygons have distinct consecutive vertices, so the query is valid.
        let Ok(Some(chord)) = other.segment_chord(a, b) else {
            continue;
        };
        for (end, query) in [(chord.from, a), (chord.to, b)] {
            out.push(match end {
                ChordEnd::Query => exact(query),
                ChordEnd::Vertex(k) => exact(w[k]),
                ChordEnd::Edge(k) => line_crossing(a, b, w[k], w[(k + 1) % m]),
            });
        }
    }
}

fn lex(a: &Exact2, b: &Exact2) -> Ordering {
    a[0].cmp(&b[0]).then_with(|| a[1].cmp(&b[1]))
}

fn turn(a: &Exact2, b: &Exact2, c: &Exact2) -> Sign {
    cross(&minus(b, a), &minus(c, a)).sign()
}

/// The exact convex hull of `points`, counter-clockwise from the lexicographically
/// smallest, without repeated or collinear vertices (one point, or two for collinear
/// input). Andrew's monotone chain with exact turns.
pub(crate) fn exact_hull(mut points: Vec<Exact2>) -> Vec<Exact2> {
    points.sort_by(lex);
    points.dedup_by(|a, b| lex(a, b) == Ordering::Equal);
    if points.len() < 3 {
        return points;
    }
    let mut hull: Vec<Exact2> = Vec::with_capacity(points.len() + 1);
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &Exact2>> = if pass == 0 {
            Box::new(points.iter())
        } else {
            Box::new(points.iter().rev())
        };
        for p in iter {
            while hull.len() >= start + 2
                && turn(&hull[hull.len() - 2], &hull[hull.len() - 1], p) != Sign::Positive
            {
                hull.pop();
            }
            hull.push(p.clone());
        }
        // The chain's last point starts the other chain.
        hull.pop();
    }
    hull
}

/// P ∩ Q exactly: counter-clockwise, no repeated or collinear vertices; empty when they
/// do not meet. O((n + m) log(n + m)) predicates plus the exact hull of at most
/// 2(n + m) rational points.
pub(crate) fn overlap(p: &ConvexPolygon, q: &ConvexPolygon) -> Vec<Exact2> {
    let mut ends = Vec::new();
    chord_ends(p, q, &mut ends);
    chord_ends(q, p, &mut ends);
    exact_hull(ends)
}
