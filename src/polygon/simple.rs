//! [`SimplePolygon`]: a validated simple polygon (possibly non-convex, either
//! orientation), the input of the crossings query ([`crate::crossings`]).
//!
//! # Validation
//! 1. Every coordinate must be finite.
//! 2. Consecutive duplicates and a repeated closing vertex are removed; at least
//!    three vertices must remain, and not all of them on one line (zero area).
//! 3. A vertex whose neighbours lie on one line with it is dropped when it lies
//!    between them (a straight vertex: the boundary is the same point set without
//!    it) and refused when the boundary turns back on itself there (a spike).
//!    Dropping a straight vertex changes no edge direction, so one pass decides.
//!    After this step adjacent edges meet only at their shared vertex.
//! 4. No two non-adjacent edges may meet (crossing, touching, overlapping or a
//!    vertex repeated further along). This is checked by a plane sweep over the
//!    vertices in lexicographic order (x, then y) that keeps the edges pierced by
//!    the sweep line in an unordered list and tests each inserted edge against
//!    every listed edge whose y-range overlaps its own (the same sweep as
//!    [`crate::crossings::Sweep`], with one polygon).
//!
//! # Complexity
//! O(n log n + Σ r) for n input vertices, where r is the number of edges in the
//! list when an edge is inserted (edges pierced by a vertical line). On the random
//! polygons of [`crate::generate::simple`] r grows far slower than n (a 20,000-vertex
//! polygon validates in milliseconds); the worst case is O(n²), reached by a comb
//! whose n/2 teeth all span one common x-range (every tooth is listed when the next
//! one is inserted). There is no size limit: the cost is that of the sweep, not of
//! an all-pairs test.
//!
//! # Precision
//! Every decision is taken with the [`Exact`] kernel on the input coordinates, so a
//! polygon is accepted or refused independently of rounding. The vertices are
//! stored unchanged (no coordinate is computed).

use crate::kernel::{Exact, Kernel, Orientation, Point, SegmentContact, Sign, segment_contact};
use std::cmp::Ordering;
use std::fmt;

/// Why a vertex list is not a valid simple polygon. Indices are positions in the
/// input list, counting from 0; an edge is named by its two input vertices.
#[derive(Clone, Debug, PartialEq)]
pub enum SimplePolygonError {
    /// A coordinate is NaN or infinite.
    NonFinite { index: usize, point: Point },
    /// Fewer than three vertices after removing consecutive repeats.
    TooFewVertices { distinct: usize },
    /// All vertices lie on one line: the polygon has zero area.
    ZeroArea,
    /// The boundary runs along a line and comes back on itself at this vertex
    /// (a zero-width spike).
    DoublesBack { index: usize },
    /// Two non-adjacent edges meet: the boundary intersects itself.
    SelfIntersection {
        /// The first edge, as (start, end) input vertex indices.
        first: (usize, usize),
        /// The second edge.
        second: (usize, usize),
        /// How they meet.
        contact: SegmentContact,
    },
}

impl fmt::Display for SimplePolygonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SimplePolygonError::NonFinite { index, point } => write!(
                f,
                "vertex {index} has a non-finite coordinate ({}, {})",
                point.x, point.y
            ),
            SimplePolygonError::TooFewVertices { distinct } => write!(
                f,
                "a polygon needs at least 3 distinct vertices, found {distinct}"
            ),
            SimplePolygonError::ZeroArea => {
                write!(f, "all vertices lie on one line: the polygon has zero area")
            }
            SimplePolygonError::DoublesBack { index } => write!(
                f,
                "vertex {index}: the boundary runs back along the line it came on"
            ),
            SimplePolygonError::SelfIntersection {
                first,
                second,
                contact,
            } => {
                let how = match contact {
                    SegmentContact::Crossing => "cross",
                    SegmentContact::Overlapping => "overlap",
                    _ => "touch",
                };
                write!(
                    f,
                    "the boundary intersects itself: edges {}-{} and {}-{} {how}",
                    first.0, first.1, second.0, second.1
                )
            }
        }
    }
}

impl std::error::Error for SimplePolygonError {}

/// A simple polygon: a closed boundary that does not meet itself, in either
/// orientation, convex or not, with at least three vertices and no straight
/// (collinear middle) vertex.
///
/// The vertices are stored in input order and orientation, starting at the first
/// input vertex that survives cleaning.
///
/// # Complexity
/// Construction is O(n log n + Σ r), worst case O(n²); see the [module docs](self).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct SimplePolygon {
    vertices: Vec<Point>,
}

impl SimplePolygon {
    /// Validates and cleans `points` (see the [module docs](self)).
    ///
    /// # Errors
    /// A [`SimplePolygonError`] naming the offending input vertex or edges:
    /// non-finite coordinates, fewer than three vertices, zero area, a spike, or
    /// two edges that meet.
    ///
    /// ```
    /// use polysect::{Point, SimplePolygon};
    /// // A non-convex "L", clockwise, with a repeated closing vertex and a straight vertex.
    /// let l = SimplePolygon::new([[0.0, 0.0], [0.0, 2.0], [1.0, 2.0], [1.0, 1.0], [2.0, 1.0],
    ///                             [2.0, 0.0], [1.0, 0.0], [0.0, 0.0]])?;
    /// assert_eq!(l.len(), 6);
    /// assert!(!l.is_ccw());
    /// // A bowtie crosses itself.
    /// let err = SimplePolygon::new([[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]]).unwrap_err();
    /// assert!(err.to_string().contains("edges 0-1 and 2-3 cross"));
    /// # Ok::<(), polysect::SimplePolygonError>(())
    /// ```
    pub fn new<I, P>(points: I) -> Result<Self, SimplePolygonError>
    where
        I: IntoIterator<Item = P>,
        P: Into<Point>,
    {
        let points: Vec<Point> = points.into_iter().map(Into::into).collect();
        let cleaned = clean(&points)?;
        let vertices: Vec<Point> = cleaned.iter().map(|&(p, _)| p).collect();
        if let Some((e, f, contact)) = find_self_intersection(&vertices) {
            let n = cleaned.len();
            let edge = |e: usize| (cleaned[e].1, cleaned[(e + 1) % n].1);
            let (first, second) = if e < f {
                (edge(e), edge(f))
            } else {
                (edge(f), edge(e))
            };
            return Err(SimplePolygonError::SelfIntersection {
                first,
                second,
                contact,
            });
        }
        Ok(SimplePolygon { vertices })
    }

    /// Wraps a vertex list already known to be simple, with no repeated and no
    /// straight vertex. Nothing is checked; use [`SimplePolygon::debug_validate`] in tests.
    pub fn from_vertices_unchecked(vertices: Vec<Point>) -> Self {
        SimplePolygon { vertices }
    }

    /// The vertices, in input orientation.
    #[inline]
    pub fn vertices(&self) -> &[Point] {
        &self.vertices
    }

    /// Number of vertices (at least 3).
    #[inline]
    #[allow(clippy::len_without_is_empty)]
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Vertex `i` counted cyclically.
    #[inline]
    pub fn vertex(&self, i: usize) -> Point {
        self.vertices[i % self.vertices.len()]
    }

    /// Edge `i`: from vertex `i` to vertex `i + 1` (cyclically).
    #[inline]
    pub fn edge(&self, i: usize) -> (Point, Point) {
        let n = self.vertices.len();
        (self.vertices[i % n], self.vertices[(i + 1) % n])
    }

    /// Consumes the polygon, returning its vertices.
    pub fn into_vertices(self) -> Vec<Point> {
        self.vertices
    }

    /// True when the boundary runs counter-clockwise. Exact: for a simple polygon
    /// the turn at the lexicographically smallest vertex has the orientation's sign.
    pub fn is_ccw(&self) -> bool {
        let v = &self.vertices;
        let n = v.len();
        let (i, _) = v
            .iter()
            .enumerate()
            .min_by(|a, b| a.1.lex_cmp(*b.1))
            .expect("a polygon has vertices");
        Exact.orient(v[(i + n - 1) % n], v[i], v[(i + 1) % n]) == Orientation::Ccw
    }

    /// The same polygon traversed the other way round.
    pub fn reversed(&self) -> SimplePolygon {
        let mut v = self.vertices.clone();
        v.reverse();
        SimplePolygon { vertices: v }
    }

    /// The polygon with every vertex mapped by `f`, validated again.
    pub fn map(&self, f: impl Fn(Point) -> Point) -> Result<SimplePolygon, SimplePolygonError> {
        SimplePolygon::new(self.vertices.iter().map(|&p| f(p)))
    }

    /// Checks the invariant exactly (finite, at least 3 vertices, no straight or
    /// repeated vertex, no self-intersection) by validating a copy.
    pub fn debug_validate(&self) -> Result<(), String> {
        match SimplePolygon::new(self.vertices.iter().copied()) {
            Ok(p) if p.vertices == self.vertices => Ok(()),
            Ok(p) => Err(format!(
                "cleaning changes the vertex list ({} -> {} vertices)",
                self.vertices.len(),
                p.vertices.len()
            )),
            Err(e) => Err(e.to_string()),
        }
    }
}

impl TryFrom<Vec<Point>> for SimplePolygon {
    type Error = SimplePolygonError;
    fn try_from(points: Vec<Point>) -> Result<Self, Self::Error> {
        SimplePolygon::new(points)
    }
}

/// Steps 1–3 of the validation: the cleaned vertices with their input indices.
fn clean(points: &[Point]) -> Result<Vec<(Point, usize)>, SimplePolygonError> {
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(SimplePolygonError::NonFinite {
            index,
            point: points[index],
        });
    }
    let mut v: Vec<(Point, usize)> = Vec::with_capacity(points.len());
    for (i, &p) in points.iter().enumerate() {
        if v.last().is_none_or(|&(q, _)| q != p) {
            v.push((p, i));
        }
    }
    while v.len() > 1 && v[v.len() - 1].0 == v[0].0 {
        v.pop();
    }
    if v.len() < 3 {
        return Err(SimplePolygonError::TooFewVertices { distinct: v.len() });
    }
    let n = v.len();
    if (2..n).all(|i| Exact.orient(v[0].0, v[1].0, v[i].0) == Orientation::Collinear) {
        return Err(SimplePolygonError::ZeroArea);
    }
    let mut keep = Vec::with_capacity(n);
    for i in 0..n {
        let (prev, cur, next) = (v[(i + n - 1) % n].0, v[i].0, v[(i + 1) % n].0);
        if Exact.orient(prev, cur, next) == Orientation::Collinear {
            // (cur − prev) · (next − cur) > 0: cur lies strictly between its neighbours.
            if Exact.dot(prev, cur, cur, next) == Sign::Positive {
                continue;
            }
            return Err(SimplePolygonError::DoublesBack { index: v[i].1 });
        }
        keep.push(v[i]);
    }
    // Not all collinear, and dropping straight vertices keeps every turn: at least
    // three vertices with a non-zero turn remain.
    debug_assert!(keep.len() >= 3);
    Ok(keep)
}

/// An edge in the sweep's list: its index, y-range and endpoints.
#[derive(Clone, Copy)]
struct Listed {
    edge: u32,
    ylo: f64,
    yhi: f64,
    a: Point,
    b: Point,
}

/// Step 4: the first pair of non-adjacent edges found to meet (edge `i` runs from
/// vertex `i` to `i + 1`), with how they meet. `v` has no repeated consecutive and
/// no straight vertex, so adjacent edges meet only at their shared vertex.
fn find_self_intersection(v: &[Point]) -> Option<(usize, usize, SegmentContact)> {
    let n = v.len();
    if n <= 3 {
        return None;
    }
    let mut order: Vec<u32> = (0..n as u32).collect();
    order.sort_unstable_by(|&a, &b| v[a as usize].lex_cmp(v[b as usize]));
    let mut list: Vec<Listed> = Vec::new();
    let mut pos: Vec<u32> = vec![u32::MAX; n];
    let adjacent = |e: usize, f: usize| f == (e + 1) % n || e == (f + 1) % n;
    let mut i = 0;
    while i < n {
        let here = v[order[i] as usize];
        let mut j = i;
        while j < n && v[order[j] as usize] == here {
            j += 1;
        }
        // Insertions (edges whose lexicographically smaller end is here) first, then
        // removals: two edges that meet have overlapping closed lexicographic ranges,
        // so the later-inserted one finds the other in the list.
        for &w in &order[i..j] {
            let w = w as usize;
            for (e, other) in [((w + n - 1) % n, v[(w + n - 1) % n]), (w, v[(w + 1) % n])] {
                if here.lex_cmp(other) != Ordering::Less {
                    continue;
                }
                let (a, b) = (v[e], v[(e + 1) % n]);
                let (ylo, yhi) = (a.y.min(b.y), a.y.max(b.y));
                for l in &list {
                    if l.ylo > yhi || l.yhi < ylo || adjacent(e, l.edge as usize) {
                        continue;
                    }
                    let c = segment_contact(Exact, l.a, l.b, a, b);
                    if c.meets() {
                        return Some((l.edge as usize, e, c));
                    }
                }
                pos[e] = list.len() as u32;
                list.push(Listed {
                    edge: e as u32,
                    ylo,
                    yhi,
                    a,
                    b,
                });
            }
        }
        for &w in &order[i..j] {
            let w = w as usize;
            for (e, other) in [((w + n - 1) % n, v[(w + n - 1) % n]), (w, v[(w + 1) % n])] {
                if here.lex_cmp(other) != Ordering::Greater {
                    continue;
                }
                let at = pos[e] as usize;
                list.swap_remove(at);
                if at < list.len() {
                    pos[list[at].edge as usize] = at as u32;
                }
                pos[e] = u32::MAX;
            }
        }
        i = j;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly(v: &[[f64; 2]]) -> Result<SimplePolygon, SimplePolygonError> {
        SimplePolygon::new(v.iter().copied())
    }

    /// All-pairs check, the definition the sweep must agree with.
    fn brute_self_intersects(v: &[Point]) -> bool {
        let n = v.len();
        (0..n).any(|e| {
            (e + 1..n).any(|f| {
                let adjacent = f == e + 1 || (e == 0 && f == n - 1);
                !adjacent && segment_contact(Exact, v[e], v[(e + 1) % n], v[f], v[(f + 1) % n]).meets()
            })
        })
    }

    #[test]
    fn accepts_non_convex_in_both_orientations() {
        let comb = [
            [0., 0.],
            [5., 0.],
            [5., 3.],
            [4., 3.],
            [4., 1.],
            [3., 1.],
            [3., 3.],
            [2., 3.],
            [2., 1.],
            [1., 1.],
            [1., 3.],
            [0., 3.],
        ];
        let p = poly(&comb).unwrap();
        assert_eq!(p.len(), 12);
        assert!(p.is_ccw());
        let mut rev = comb.to_vec();
        rev.reverse();
        let q = poly(&rev).unwrap();
        assert!(!q.is_ccw());
        assert_eq!(q, p.reversed());
        assert!(p.debug_validate().is_ok());
    }

    #[test]
    fn cleans_repeats_and_straight_vertices() {
        let p = poly(&[
            [0., 0.],
            [0., 0.],
            [1., 0.],
            [2., 0.],
            [2., 2.],
            [0., 2.],
            [0., 1.],
            [0., 0.],
        ])
        .unwrap();
        assert_eq!(
            p.vertices(),
            &[
                Point::new(0., 0.),
                Point::new(2., 0.),
                Point::new(2., 2.),
                Point::new(0., 2.)
            ]
        );
    }

    #[test]
    fn errors_name_what_and_where() {
        use SimplePolygonError::*;
        assert!(matches!(
            poly(&[[0., 0.], [1., f64::NAN], [0., 1.]]),
            Err(NonFinite { index: 1, .. })
        ));
        assert!(matches!(
            poly(&[[0., 0.], [1., f64::INFINITY], [0., 1.]]),
            Err(NonFinite { index: 1, .. })
        ));
        assert_eq!(
            poly(&[[0., 0.], [1., 1.], [0., 0.]]),
            Err(TooFewVertices { distinct: 2 })
        );
        assert_eq!(poly(&[]), Err(TooFewVertices { distinct: 0 }));
        assert_eq!(poly(&[[0., 0.], [1., 1.], [2., 2.]]), Err(ZeroArea));
        assert_eq!(
            poly(&[[0., 0.], [2., 0.], [1., 0.], [1., 1.]]),
            Err(DoublesBack { index: 1 })
        );
        assert_eq!(
            poly(&[[0., 0.], [2., 2.], [2., 0.], [0., 2.]]),
            Err(SelfIntersection {
                first: (0, 1),
                second: (2, 3),
                contact: SegmentContact::Crossing
            })
        );
        // A vertex repeated further along: non-adjacent edges touch.
        let e = poly(&[[0., 0.], [2., 0.], [1., 1.], [2., 2.], [0., 2.], [1., 1.]]).unwrap_err();
        assert!(
            matches!(
                e,
                SelfIntersection {
                    contact: SegmentContact::Touching,
                    ..
                }
            ),
            "{e}"
        );
        assert!(e.to_string().contains("touch"));
        // A vertex on a non-adjacent edge.
        let e = poly(&[[0., 0.], [4., 0.], [4., 4.], [2., 0.], [0., 4.]]).unwrap_err();
        assert!(matches!(e, SelfIntersection { .. }), "{e}");
        // Two collinear overlapping edges.
        let e = poly(&[
            [0., 0.],
            [3., 0.],
            [3., 1.],
            [1., 1.],
            [1., 0.],
            [2., 0.],
            [2., -1.],
            [0., -1.],
        ])
        .unwrap_err();
        assert!(matches!(e, SelfIntersection { .. }), "{e}");
    }

    #[test]
    fn sweep_agrees_with_all_pairs_on_random_grid_polygons() {
        use rand::rngs::SmallRng;
        use rand::{Rng, SeedableRng};
        let mut rng = SmallRng::seed_from_u64(7);
        let (mut valid, mut invalid) = (0, 0);
        for _ in 0..4000 {
            let n = rng.random_range(3..9);
            let pts: Vec<Point> = (0..n)
                .map(|_| Point::new(rng.random_range(0..5) as f64, rng.random_range(0..5) as f64))
                .collect();
            let Ok(cleaned) = clean(&pts) else { continue };
            let v: Vec<Point> = cleaned.iter().map(|c| c.0).collect();
            let sweep = find_self_intersection(&v).is_some();
            assert_eq!(sweep, brute_self_intersects(&v), "{v:?}");
            if sweep { invalid += 1 } else { valid += 1 }
        }
        assert!(valid > 100 && invalid > 100, "{valid} {invalid}");
    }
}
