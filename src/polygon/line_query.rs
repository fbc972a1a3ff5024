//! Where a line, a ray or a segment meets a convex polygon, in O(log n) on the
//! sorted array ([`ConvexPolygon::line_chord`], [`ConvexPolygon::ray_chord`],
//! [`ConvexPolygon::segment_chord`]): the "intersection with a line" step that
//! Chazelle–Dobkin's test and ray casting are built on.
//!
//! # The answer
//! The intersection of a closed convex polygon with a line is a segment (a *chord*),
//! a point, or nothing. The query `a → b` is directed, and the answer is a [`Chord`]:
//! where it begins (`from`) and ends (`to`) along `a → b`, each as a boundary
//! feature — a vertex the line passes through exactly ([`ChordEnd::Vertex`]) or an
//! edge it crosses in its interior ([`ChordEnd::Edge`]) — or, for rays and segments,
//! the query's own endpoint when it lies inside the polygon ([`ChordEnd::Query`]: `a`
//! for `from`, `b` for `to`). Features are exact and combinatorial; the points and
//! parameters they stand for are constructed only on request ([`Chord::parameters`],
//! [`Chord::points`], approximate).
//!
//! Degeneracies, decided: a line touching one vertex has `from == to ==
//! Vertex(i)`; a line along an edge has the edge's two vertices, in the order of
//! `a → b`. A ray's or segment's start `a` gives `from = Query` exactly when it lies
//! in the polygon past the line's entry point; when `a` *is* the entry point, `from` is
//! the entry feature (likewise `to` and `b` with the exit point). So a ray starting on
//! the exit point is `Query → exit`, one point. `a == b` is an error: the direction is
//! undefined.
//!
//! # Algorithm
//! With `d = b − a`, the signed distance of the vertices from the line rises along the
//! edges with `d × e > 0` and falls along the others: the vertices farthest right and
//! left of the line are where the edge directions, measured counter-clockwise from `d`,
//! pass 0 and π. The directions are a rotated sorted sequence, so one binary search
//! finds the smallest (the rightmost vertex) and a second the first at or beyond π
//! (the leftmost vertex). If both lie on one side the line misses; otherwise each of
//! the two chains between them is monotone in the signed distance, and a binary search
//! on each finds the edge (or vertex) it crosses: the chain from the rightmost vertex
//! counter-clockwise to the leftmost one holds the exit, the other chain the entry.
//! For rays and segments, the chord is then clipped by comparing the parameters of
//! `a` and `b` with those of the chord's ends, exactly (below).
//!
//! # Complexity
//! O(log n) predicates for n vertices (four binary searches); no allocation.
//!
//! # Precision
//! Every decision is a sign from the exact kernel: orientations, cross and dot
//! products of input points. Comparing the parameter of a query endpoint `q` with a
//! chord end needs no constructed point either: against a vertex `v` on the line it is
//! the sign of `d · (v − q)`; against a crossed edge it is the side of the edge's line
//! `q` lies on (before the exit means the inner side, before the entry the outer side).

use super::ConvexPolygon;
use crate::kernel::{Exact, Kernel, Orientation, Point, Sign};
use std::fmt;

/// One end of a [`Chord`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ChordEnd {
    /// The query passes exactly through vertex `i`.
    Vertex(usize),
    /// The query crosses the interior of edge `i` (from vertex `i` to vertex `i + 1`,
    /// cyclically).
    Edge(usize),
    /// The query's own endpoint, inside the polygon: `a` when it is `from`, `b` when it
    /// is `to`.
    Query,
}

/// The part of a directed line, ray or segment `a → b` inside a convex polygon:
/// from `from` to `to` along `a → b` (equal ends: a single point).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Chord {
    /// Where the chord starts along `a → b`.
    pub from: ChordEnd,
    /// Where the chord ends along `a → b`.
    pub to: ChordEnd,
}

/// Why a line query has no answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LineQueryError {
    /// A coordinate of `a` or `b` is NaN or infinite.
    NonFinite,
    /// `a == b`: the query has no direction.
    SamePoint,
}

impl fmt::Display for LineQueryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LineQueryError::NonFinite => write!(f, "a query point has a non-finite coordinate"),
            LineQueryError::SamePoint => write!(f, "the two query points coincide: no direction"),
        }
    }
}

impl std::error::Error for LineQueryError {}

impl Chord {
    /// The chord's ends as parameters `t` of `a + t (b − a)`, `from` ≤ `to`
    /// (approximate: computed in floating point, with the directions scaled so that
    /// huge and tiny coordinates stay in range; `Query` ends are exactly 0 and 1).
    pub fn parameters(&self, polygon: &ConvexPolygon, a: Point, b: Point) -> (f64, f64) {
        // Directions are scaled by their largest coordinate first, so that squares and
        // products stay in range for huge and tiny coordinates.
        let unit = |x: f64, y: f64| {
            let s = x.abs().max(y.abs());
            (x / s, y / s, s)
        };
        let (dx, dy, s) = unit(b.x - a.x, b.y - a.y);
        let t = |end: ChordEnd, query: f64| {
            let v = polygon.vertices();
            let n = v.len();
            match end {
                ChordEnd::Query => query,
                ChordEnd::Vertex(i) => {
                    let (px, py) = ((v[i].x - a.x) / s, (v[i].y - a.y) / s);
                    (px * dx + py * dy) / (dx * dx + dy * dy)
                }
                ChordEnd::Edge(i) => {
                    let (p, q) = (v[i], v[(i + 1) % n]);
                    let (ex, ey, _) = unit(q.x - p.x, q.y - p.y);
                    let (px, py) = ((p.x - a.x) / s, (p.y - a.y) / s);
                    (px * ey - py * ex) / (dx * ey - dy * ex)
                }
            }
        };
        (t(self.from, 0.0), t(self.to, 1.0))
    }

    /// The chord's ends as points (approximate where constructed: a vertex or a query
    /// endpoint is exact, a point inside an edge is rounded).
    pub fn points(&self, polygon: &ConvexPolygon, a: Point, b: Point) -> (Point, Point) {
        let (t0, t1) = self.parameters(polygon, a, b);
        let at = |end: ChordEnd, t: f64, query: Point| match end {
            ChordEnd::Vertex(i) => polygon.vertices()[i],
            ChordEnd::Query => query,
            ChordEnd::Edge(_) => Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)),
        };
        (at(self.from, t0, a), at(self.to, t1, b))
    }
}

/// The parameter of a chord end minus that of a point `q` on the line, as a sign
/// (exact; see the module docs). `entering` says which end: the entry or the exit.
fn end_minus(
    polygon: &ConvexPolygon,
    (a, b): (Point, Point),
    end: ChordEnd,
    q: Point,
    entering: bool,
) -> Sign {
    let v = polygon.vertices();
    match end {
        ChordEnd::Vertex(i) => Exact.dot(a, b, q, v[i]),
        ChordEnd::Edge(i) => {
            let side = Exact.orient(v[i], v[(i + 1) % v.len()], q);
            // Before the exit: inner side; before the entry: outer side.
            let before = if entering {
                Orientation::Cw
            } else {
                Orientation::Ccw
            };
            if side == Orientation::Collinear {
                Sign::Zero
            } else if side == before {
                Sign::Positive
            } else {
                Sign::Negative
            }
        }
        ChordEnd::Query => unreachable!("a line chord has boundary ends only"),
    }
}

fn validate(a: Point, b: Point) -> Result<(), LineQueryError> {
    if !a.is_finite() || !b.is_finite() {
        Err(LineQueryError::NonFinite)
    } else if a == b {
        Err(LineQueryError::SamePoint)
    } else {
        Ok(())
    }
}

impl ConvexPolygon {
    /// Where the line through `a` and `b`, directed from `a` to `b`, meets the polygon
    /// (closed: touching counts). `None` when it misses. O(log n), exact.
    ///
    /// # Errors
    /// `SamePoint` when `a == b`, `NonFinite` for a NaN or infinite coordinate.
    ///
    /// ```
    /// use polysect::polygon::{Chord, ChordEnd};
    /// use polysect::{ConvexPolygon, Point};
    /// let square = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// let (a, b) = (Point::new(-5.0, 1.0), Point::new(-4.0, 1.0)); // y = 1, going right
    /// let chord = square.line_chord(a, b)?.unwrap();
    /// assert_eq!(chord, Chord { from: ChordEnd::Edge(3), to: ChordEnd::Edge(1) });
    /// assert_eq!(chord.parameters(&square, a, b), (5.0, 7.0));
    /// // Through a corner only: a single point.
    /// let touch = square.line_chord(Point::new(0.0, 4.0), Point::new(4.0, 0.0))?.unwrap();
    /// assert_eq!(touch, Chord { from: ChordEnd::Vertex(2), to: ChordEnd::Vertex(2) });
    /// assert_eq!(square.line_chord(Point::new(0.0, 5.0), Point::new(5.0, 0.0))?, None);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn line_chord(&self, a: Point, b: Point) -> Result<Option<Chord>, LineQueryError> {
        validate(a, b)?;
        Ok(line_chord(self, a, b))
    }

    /// Where the ray from `a` through `b` (all `a + t (b − a)`, `t ≥ 0`) meets the
    /// polygon. `from` is [`ChordEnd::Query`] when `a` lies inside (past the boundary
    /// point where the line enters). O(log n), exact.
    ///
    /// # Errors
    /// `SamePoint` when `a == b`, `NonFinite` for a NaN or infinite coordinate.
    ///
    /// ```
    /// use polysect::polygon::{Chord, ChordEnd};
    /// use polysect::{ConvexPolygon, Point};
    /// let square = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// // Cast from the centre to the right: it leaves through edge 1.
    /// let hit = square.ray_chord(Point::new(1.0, 1.0), Point::new(3.0, 1.0))?.unwrap();
    /// assert_eq!(hit, Chord { from: ChordEnd::Query, to: ChordEnd::Edge(1) });
    /// // Pointing away from the square: no hit.
    /// assert_eq!(square.ray_chord(Point::new(3.0, 1.0), Point::new(4.0, 1.0))?, None);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn ray_chord(&self, a: Point, b: Point) -> Result<Option<Chord>, LineQueryError> {
        validate(a, b)?;
        let Some(c) = line_chord(self, a, b) else {
            return Ok(None);
        };
        let ab = (a, b);
        if end_minus(self, ab, c.to, a, false) == Sign::Negative {
            return Ok(None);
        }
        let from = if end_minus(self, ab, c.from, a, true) == Sign::Negative {
            ChordEnd::Query
        } else {
            c.from
        };
        Ok(Some(Chord { from, to: c.to }))
    }

    /// Where the segment from `a` to `b` meets the polygon. Either end is
    /// [`ChordEnd::Query`] when that endpoint lies inside. O(log n), exact.
    ///
    /// # Errors
    /// `SamePoint` when `a == b`, `NonFinite` for a NaN or infinite coordinate.
    ///
    /// ```
    /// use polysect::polygon::{Chord, ChordEnd};
    /// use polysect::{ConvexPolygon, Point};
    /// let square = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// let inside = square.segment_chord(Point::new(-1.0, 1.0), Point::new(1.0, 1.0))?.unwrap();
    /// assert_eq!(inside, Chord { from: ChordEnd::Edge(3), to: ChordEnd::Query });
    /// // Stops one short of the square.
    /// assert_eq!(square.segment_chord(Point::new(-2.0, 1.0), Point::new(-1.0, 1.0))?, None);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn segment_chord(&self, a: Point, b: Point) -> Result<Option<Chord>, LineQueryError> {
        let Some(c) = self.ray_chord(a, b)? else {
            return Ok(None);
        };
        let ab = (a, b);
        if c.from != ChordEnd::Query && end_minus(self, ab, c.from, b, true) == Sign::Positive {
            return Ok(None);
        }
        let to = if end_minus(self, ab, c.to, b, false) == Sign::Positive {
            ChordEnd::Query
        } else {
            c.to
        };
        Ok(Some(Chord { from: c.from, to }))
    }
}

/// The line query on valid input (`a ≠ b`, finite).
fn line_chord(polygon: &ConvexPolygon, a: Point, b: Point) -> Option<Chord> {
    let v = polygon.vertices();
    let n = v.len();
    if n < 3 {
        // Only an unchecked list can be this short; it bounds no region.
        return None;
    }
    let at = |i: usize| v[i % n];
    let side = |i: usize| Exact.orient(a, b, at(i));
    // Edge i's direction measured counter-clockwise from d = b − a: which half-turn
    // (0: [0, π), 1: [π, 2π)), then the order within a half.
    let half = |i: usize| match Exact.cross(a, b, at(i), at(i + 1)) {
        Orientation::Ccw => 0,
        Orientation::Cw => 1,
        Orientation::Collinear => u8::from(Exact.dot(a, b, at(i), at(i + 1)) != Sign::Positive),
    };
    let less = |i: usize, j: usize| {
        let (hi, hj) = (half(i), half(j));
        hi < hj || (hi == hj && Exact.cross(at(i), at(i + 1), at(j), at(j + 1)) == Orientation::Ccw)
    };
    // The edge of smallest direction (a rotated sorted sequence of distinct angles).
    let (mut lo, mut hi) = (0, n - 1);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if less(hi, mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    let m = lo; // vertex m: farthest right of the line
    // The first edge (from m on) in the upper half-turn: its start is farthest left.
    let (mut lo, mut hi) = (0, n); // half(m + lo) == 0, half(m + hi) == 1 (hi = n: none yet)
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if half(m + mid) == 0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let k = (m + hi) % n;
    let (top, bottom) = (side(k), side(m));
    if top == Orientation::Cw || bottom == Orientation::Ccw {
        return None;
    }
    if top == Orientation::Collinear {
        // Touching on the left side: at vertex k, or along edge k−1 (same direction as
        // d) or edge k (the opposite direction).
        let prev = (k + n - 1) % n;
        return Some(if side(prev) == Orientation::Collinear {
            Chord {
                from: ChordEnd::Vertex(prev),
                to: ChordEnd::Vertex(k),
            }
        } else if side(k + 1) == Orientation::Collinear {
            Chord {
                from: ChordEnd::Vertex((k + 1) % n),
                to: ChordEnd::Vertex(k),
            }
        } else {
            Chord {
                from: ChordEnd::Vertex(k),
                to: ChordEnd::Vertex(k),
            }
        });
    }
    if bottom == Orientation::Collinear {
        let prev = (m + n - 1) % n;
        return Some(if side(m + 1) == Orientation::Collinear {
            Chord {
                from: ChordEnd::Vertex(m),
                to: ChordEnd::Vertex((m + 1) % n),
            }
        } else if side(prev) == Orientation::Collinear {
            Chord {
                from: ChordEnd::Vertex(m),
                to: ChordEnd::Vertex(prev),
            }
        } else {
            Chord {
                from: ChordEnd::Vertex(m),
                to: ChordEnd::Vertex(m),
            }
        });
    }
    // A proper crossing. On the chain from `start` of `len` edges, the side is
    // `first` at offset 0 and not at offset `len`: find the last offset with `first`.
    let crossing = |start: usize, len: usize, first: Orientation| {
        let (mut lo, mut hi) = (0, len);
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if side(start + mid) == first {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let j = (start + lo) % n;
        if side(j + 1) == Orientation::Collinear {
            ChordEnd::Vertex((j + 1) % n)
        } else {
            ChordEnd::Edge(j)
        }
    };
    let up = (k + n - m) % n; // edges from m to k
    let to = crossing(m, up, Orientation::Cw);
    let from = crossing(k, n - up, Orientation::Ccw);
    Some(Chord { from, to })
}

instrument_pub! {
    /// [`ConvexPolygon::line_chord`] by visiting every vertex and edge: the O(n)
    /// reference the binary searches are tested against. (On a vertex list that is not
    /// strictly convex, built with `from_ccw_unchecked`, the answer is unspecified.)
    ///
    /// # Errors
    /// As [`ConvexPolygon::line_chord`].
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    fn line_chord_linear(
        polygon: &ConvexPolygon,
        a: Point,
        b: Point,
    ) -> Result<Option<Chord>, LineQueryError> {
        validate(a, b)?;
        let v = polygon.vertices();
        let n = v.len();
        let side: Vec<Orientation> = v.iter().map(|&p| Exact.orient(a, b, p)).collect();
        let on: Vec<usize> = (0..n).filter(|&i| side[i] == Orientation::Collinear).collect();
        let (mut enter, mut exit) = (None, None);
        for i in 0..n {
            let (s, t) = (side[i], side[(i + 1) % n]);
            // Right to left (counter-clockwise) is where the line leaves; left to right,
            // where it enters.
            if s == Orientation::Cw && t == Orientation::Ccw {
                exit = Some(ChordEnd::Edge(i));
            }
            if s == Orientation::Ccw && t == Orientation::Cw {
                enter = Some(ChordEnd::Edge(i));
            }
        }
        for &i in &on {
            let (p, q) = (side[(i + n - 1) % n], side[(i + 1) % n]);
            if p == Orientation::Cw && q == Orientation::Ccw {
                exit = Some(ChordEnd::Vertex(i));
            }
            if p == Orientation::Ccw && q == Orientation::Cw {
                enter = Some(ChordEnd::Vertex(i));
            }
        }
        Ok(match (enter, exit, on.as_slice()) {
            (Some(from), Some(to), _) => Some(Chord { from, to }),
            (None, None, []) => None,
            (None, None, &[i]) => Some(Chord {
                from: ChordEnd::Vertex(i),
                to: ChordEnd::Vertex(i),
            }),
            (None, None, &[i, j]) => {
                // Along an edge: ordered by the direction of the line.
                let (from, to) = if Exact.dot(a, b, v[i], v[j]) == Sign::Positive {
                    (i, j)
                } else {
                    (j, i)
                };
                Some(Chord {
                    from: ChordEnd::Vertex(from),
                    to: ChordEnd::Vertex(to),
                })
            }
            // Only a list that is not strictly convex (built unchecked) gets here.
            _ => None,
        })
    }
}
