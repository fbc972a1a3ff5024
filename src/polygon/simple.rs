//! [`SimplePolygon`]: a validated simple polygon (possibly non-convex, either
//! orientation), the input of the crossings query ([`crate::crossings`]).
//!
//! See [`SimplePolygon`] for the validation rules, complexity and precision.

use super::{InputIndex, Prefilter, distinct_indices};
use crate::kernel::{Exact, Kernel, Orientation, Point, SegmentContact, Sign, segment_contact};
use std::cmp::Ordering;
use std::fmt;

/// Why a vertex list is not a valid simple polygon. Indices are positions in the
/// input list, counting from 0; an edge is named by its two input vertices.
#[derive(Clone, Debug, PartialEq)]
pub enum SimplePolygonError {
    /// A coordinate is NaN or infinite.
    NonFinite {
        /// Position of the vertex in the input list.
        index: usize,
        /// The vertex as given.
        point: Point,
    },
    /// Fewer than three vertices after removing consecutive repeats.
    TooFewVertices {
        /// How many vertices are left.
        distinct: usize,
    },
    /// All vertices lie on one line: the polygon has zero area.
    ZeroArea,
    /// The boundary runs along a line and comes back on itself at this vertex
    /// (a zero-width spike).
    DoublesBack {
        /// Position of the vertex in the input list.
        index: usize,
    },
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
            SimplePolygonError::NonFinite { index, point } => {
                write!(f, "vertex {index} has a non-finite coordinate {point}")
            }
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
/// # Validation
/// 1. Every coordinate must be finite.
/// 2. Consecutive duplicates and a repeated closing vertex are removed; at least
///    three vertices must remain, and not all of them on one line (zero area).
/// 3. A vertex whose neighbours lie on one line with it is dropped when it lies
///    between them (a straight vertex: the boundary is the same point set without
///    it) and refused when the boundary turns back on itself there (a spike).
///    Dropping a straight vertex changes no edge direction, so one pass decides.
///    After this step adjacent edges meet only at their shared vertex.
/// 4. No two non-adjacent edges may meet (crossing, touching, overlapping or a
///    vertex repeated further along). This is checked by Shamos and Hoey's sweep
///    over the vertices in lexicographic order (x, then y; a vertical edge starts at
///    its lower end), with the edges pierced by the sweep line in an ordered set
///    (a `BTreeSet` ordered by exact orientation tests); only edges that become
///    neighbours in that order are tested, and the leftmost meeting point is always
///    found by two such neighbours. Touchings count: the segments are closed.
///
/// # Complexity
/// O(n log n) time and O(n) memory for n input vertices, in the worst case: a
/// sort, at most 2n set insertions and removals and at most 4n segment tests.
/// There is no size limit.
///
/// # Precision
/// Every decision is taken with the [`Exact`] kernel on the input coordinates, so a
/// polygon is accepted or refused independently of rounding. The vertices are
/// stored unchanged (no coordinate is computed).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SimplePolygon {
    vertices: Vec<Point>,
}

impl SimplePolygon {
    /// Validates and cleans `points` (see the [type docs](SimplePolygon)).
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
        if u32::try_from(points.len()).is_ok() {
            Self::validate::<u32>(points)
        } else {
            Self::validate::<usize>(points)
        }
    }

    /// [`SimplePolygon::new`] on a collected list, with input indices of type `I`. The
    /// cleaned vertices are compacted into `points` itself and only their input indices
    /// are kept beside them (for error messages), so the peak memory is the list plus
    /// one index per vertex and the self-intersection sweep's order.
    fn validate<I: InputIndex>(mut points: Vec<Point>) -> Result<Self, SimplePolygonError> {
        let index = clean::<I>(&points)?;
        // The kept indices increase, so each vertex moves down (or stays).
        for (j, &i) in index.iter().enumerate() {
            points[j] = points[i.get()];
        }
        points.truncate(index.len());
        points.shrink_to_fit();
        let vertices = points;
        if let Some((e, f, contact)) = find_self_intersection(&vertices) {
            let n = index.len();
            let edge = |e: usize| (index[e].get(), index[(e + 1) % n].get());
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
    ///
    /// # Panics
    /// Never: a [`SimplePolygon`] has at least three vertices.
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
    ///
    /// # Errors
    /// The [`SimplePolygonError`] of the mapped vertices.
    pub fn map(&self, f: impl Fn(Point) -> Point) -> Result<SimplePolygon, SimplePolygonError> {
        SimplePolygon::new(self.vertices.iter().map(|&p| f(p)))
    }

    instrument_pub! {
        /// Checks the invariant exactly (finite, at least 3 vertices, no straight or
        /// repeated vertex, no self-intersection) by validating a copy.
        ///
        /// # Errors
        /// A description of the first violation found.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn debug_validate(&self) -> Result<(), String> {
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
}

impl TryFrom<Vec<Point>> for SimplePolygon {
    type Error = SimplePolygonError;
    fn try_from(points: Vec<Point>) -> Result<Self, Self::Error> {
        SimplePolygon::new(points)
    }
}

/// Steps 1–3 of the validation: the input indices of the cleaned vertices, increasing.
fn clean<I: InputIndex>(points: &[Point]) -> Result<Vec<I>, SimplePolygonError> {
    let mut v = distinct_indices::<I>(points).map_err(|e| match e {
        Prefilter::NonFinite { index } => SimplePolygonError::NonFinite {
            index,
            point: points[index],
        },
        Prefilter::TooFew { distinct } => SimplePolygonError::TooFewVertices { distinct },
        Prefilter::AllCollinear => SimplePolygonError::ZeroArea,
    })?;
    let at = |i: I| points[i.get()];
    let n = v.len();
    // Kept vertices are compacted in place: entry w is written after entries i - 1, i
    // and i + 1 are read, and w ≤ i, so only entry 0 (the last vertex's next) can be
    // overwritten before it is read.
    let first = v[0];
    let mut w = 0;
    for i in 0..n {
        let (prev, cur) = (at(v[(i + n - 1) % n]), at(v[i]));
        let next = if i + 1 == n { at(first) } else { at(v[i + 1]) };
        if Exact.orient(prev, cur, next) == Orientation::Collinear {
            // (cur − prev) · (next − cur) > 0: cur lies strictly between its neighbours.
            if Exact.dot(prev, cur, cur, next) == Sign::Positive {
                continue;
            }
            return Err(SimplePolygonError::DoublesBack { index: v[i].get() });
        }
        v[w] = v[i];
        w += 1;
    }
    v.truncate(w);
    // Not all collinear, and dropping straight vertices keeps every turn: at least
    // three vertices with a non-zero turn remain.
    debug_assert!(v.len() >= 3);
    Ok(v)
}

/// An edge in the sweep status, stored left to right (lexicographically), ordered
/// bottom to top along the sweep line. The order is decided by exact orientation
/// tests at the later of the two left endpoints, so it is consistent for every set
/// of edges that do not meet to the left of the sweep line, which is all the
/// status ever holds: the sweep stops at the first meeting it finds, and it finds
/// the leftmost meeting point no later than the event there.
#[derive(Clone, Copy, Debug)]
struct Status {
    l: Point,
    r: Point,
    edge: u32,
}

impl PartialEq for Status {
    fn eq(&self, other: &Self) -> bool {
        self.edge == other.edge
    }
}

impl Eq for Status {}

impl PartialOrd for Status {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Status {
    fn cmp(&self, other: &Self) -> Ordering {
        if self.edge == other.edge {
            return Ordering::Equal;
        }
        // Compare at the later left endpoint: is it above or below the other edge?
        let (early, late, flip) = if self.l.lex_cmp(other.l).is_le() {
            (self, other, false)
        } else {
            (other, self, true)
        };
        let side = |p: Point| match Exact.orient(early.l, early.r, p) {
            Orientation::Ccw => Some(Ordering::Less),
            Orientation::Cw => Some(Ordering::Greater),
            Orientation::Collinear => None,
        };
        // `Less` means `early` is below `late`. A left endpoint on the other edge (a
        // meeting, found by the neighbour tests) falls back to the right endpoint and
        // then to the edge index, so the order stays total.
        let ord = side(late.l)
            .or_else(|| side(late.r))
            .unwrap_or_else(|| early.edge.cmp(&late.edge));
        if flip { ord.reverse() } else { ord }
    }
}

/// Step 4: the first pair of non-adjacent edges found to meet (edge `i` runs from
/// vertex `i` to `i + 1`), with how they meet. `v` has no repeated consecutive and
/// no straight vertex, so adjacent edges meet only at their shared vertex.
///
/// Shamos and Hoey's sweep: vertices in lexicographic order; at each vertex the
/// edges ending there leave the status (an ordered set) and their former
/// neighbours are tested against each other, then the edges starting there enter
/// and are tested against their new neighbours. A vertex repeated further along
/// the boundary is found by the sort. O(n log n) exact orientation tests.
fn find_self_intersection(v: &[Point]) -> Option<(usize, usize, SegmentContact)> {
    use std::collections::BTreeSet;
    use std::ops::Bound::{Excluded, Unbounded};
    let n = v.len();
    if n <= 3 {
        return None;
    }
    let mut order: Vec<u32> = (0..n as u32).collect();
    order.sort_unstable_by(|&a, &b| v[a as usize].lex_cmp(v[b as usize]));
    if let Some(w) = order.windows(2).find(|w| v[w[0] as usize] == v[w[1] as usize]) {
        // Both edges leaving the repeated point meet there (not adjacent: consecutive
        // repeats are gone).
        let (e, f) = (w[0] as usize, w[1] as usize);
        let c = segment_contact(Exact, v[e], v[(e + 1) % n], v[f], v[(f + 1) % n]);
        return Some((e, f, c));
    }
    let key = |e: usize| {
        let (a, b) = (v[e], v[(e + 1) % n]);
        let (l, r) = if a.lex_cmp(b).is_lt() { (a, b) } else { (b, a) };
        Status { l, r, edge: e as u32 }
    };
    let adjacent = |e: usize, f: usize| f == (e + 1) % n || e == (f + 1) % n;
    let test = |a: &Status, b: &Status| -> Option<(usize, usize, SegmentContact)> {
        let (e, f) = (a.edge as usize, b.edge as usize);
        if adjacent(e, f) {
            return None;
        }
        let c = segment_contact(Exact, a.l, a.r, b.l, b.r);
        c.meets().then_some((e, f, c))
    };
    let mut status: BTreeSet<Status> = BTreeSet::new();
    for &w in &order {
        let w = w as usize;
        let here = v[w];
        let edges = [((w + n - 1) % n, v[(w + n - 1) % n]), (w, v[(w + 1) % n])];
        for (e, other) in edges {
            if here.lex_cmp(other) != Ordering::Greater {
                continue;
            }
            let k = key(e);
            status.remove(&k);
            let below = status.range(..k).next_back();
            let above = status.range((Excluded(k), Unbounded)).next();
            if let (Some(a), Some(b)) = (below, above)
                && let Some(hit) = test(a, b)
            {
                return Some(hit);
            }
        }
        for (e, other) in edges {
            if here.lex_cmp(other) != Ordering::Less {
                continue;
            }
            let k = key(e);
            for nb in [
                status.range(..k).next_back(),
                status.range((Excluded(k), Unbounded)).next(),
            ]
            .into_iter()
            .flatten()
            {
                if let Some(hit) = test(&k, nb) {
                    return Some(hit);
                }
            }
            status.insert(k);
        }
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
        // Input indices survive the removal of a repeat (1) and a straight vertex (2).
        assert_eq!(
            poly(&[[0., 0.], [0., 0.], [1., 1.], [2., 2.], [2., 0.], [0., 2.]]),
            Err(SelfIntersection {
                first: (0, 3),
                second: (4, 5),
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
    fn sweep_agrees_with_all_pairs_on_perturbed_valid_polygons() {
        use crate::generate::simple::{PointDistribution, SimpleMethod, random_simple_polygon};
        use rand::rngs::SmallRng;
        use rand::{Rng, SeedableRng};
        let mut rng = SmallRng::seed_from_u64(11);
        let (mut valid, mut invalid) = (0, 0);
        for i in 0..3000 {
            let size = rng.random_range(4..14);
            let dist = PointDistribution::Grid { size };
            let n = rng.random_range(4..(size * size / 2).min(60) as usize);
            let method = SimpleMethod::ALL[i % 2];
            let p = random_simple_polygon(method, dist, n, &mut rng).unwrap();
            // Move one vertex to a random grid point: often a touching or a crossing.
            let mut v = p.into_vertices();
            let k = rng.random_range(0..v.len());
            v[k] = Point::new(rng.random_range(0..size) as f64, rng.random_range(0..size) as f64);
            let Ok(cleaned) = clean::<usize>(&v) else { continue };
            let w: Vec<Point> = cleaned.iter().map(|&i| v[i]).collect();
            let sweep = find_self_intersection(&w);
            assert_eq!(sweep.is_some(), brute_self_intersects(&w), "{w:?}");
            if let Some((e, f, c)) = sweep {
                let m = w.len();
                assert_eq!(
                    segment_contact(Exact, w[e], w[(e + 1) % m], w[f], w[(f + 1) % m]),
                    c
                );
                invalid += 1;
            } else {
                valid += 1;
            }
        }
        assert!(valid > 300 && invalid > 300, "{valid} {invalid}");
    }

    #[test]
    fn sweep_agrees_with_all_pairs_on_random_real_vertex_lists() {
        use rand::rngs::SmallRng;
        use rand::{Rng, SeedableRng};
        let mut rng = SmallRng::seed_from_u64(13);
        let (mut valid, mut invalid) = (0, 0);
        for _ in 0..20000 {
            let n = rng.random_range(4..9);
            let pts: Vec<Point> = (0..n)
                .map(|_| Point::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)))
                .collect();
            let Ok(cleaned) = clean::<usize>(&pts) else {
                continue;
            };
            let v: Vec<Point> = cleaned.iter().map(|&i| pts[i]).collect();
            let sweep = find_self_intersection(&v).is_some();
            assert_eq!(sweep, brute_self_intersects(&v), "{v:?}");
            if sweep { invalid += 1 } else { valid += 1 }
        }
        assert!(valid > 1000 && invalid > 1000, "{valid} {invalid}");
    }

    #[test]
    fn sweep_agrees_with_all_pairs_on_large_perturbed_polygons() {
        use crate::generate::simple::{PointDistribution, SimpleMethod, random_simple_polygon};
        use rand::rngs::SmallRng;
        use rand::{Rng, SeedableRng};
        let mut rng = SmallRng::seed_from_u64(17);
        let dist = PointDistribution::Uniform { min: 0.0, max: 1.0 };
        let (mut valid, mut invalid) = (0, 0);
        for i in 0..200 {
            let n = rng.random_range(100..400);
            let p = random_simple_polygon(SimpleMethod::ALL[i % 2], dist, n, &mut rng).unwrap();
            let mut v = p.into_vertices();
            // Move a vertex by a small random step: sometimes its edges now cross others.
            let k = rng.random_range(0..v.len());
            let step = 10f64.powi(-rng.random_range(1..4));
            v[k].x += rng.random_range(-step..step);
            v[k].y += rng.random_range(-step..step);
            let Ok(cleaned) = clean::<usize>(&v) else { continue };
            let w: Vec<Point> = cleaned.iter().map(|&i| v[i]).collect();
            let sweep = find_self_intersection(&w).is_some();
            assert_eq!(sweep, brute_self_intersects(&w));
            if sweep { invalid += 1 } else { valid += 1 }
        }
        assert!(valid > 20 && invalid > 20, "{valid} {invalid}");
    }

    #[test]
    fn sweep_agrees_with_all_pairs_on_random_grid_polygons() {
        use rand::rngs::SmallRng;
        use rand::{Rng, SeedableRng};
        let mut rng = SmallRng::seed_from_u64(7);
        let (mut valid, mut invalid) = (0, 0);
        for i in 0..20000 {
            let n = if i % 10 == 0 {
                rng.random_range(9..30)
            } else {
                rng.random_range(3..9)
            };
            let pts: Vec<Point> = (0..n)
                .map(|_| Point::new(rng.random_range(0..5) as f64, rng.random_range(0..5) as f64))
                .collect();
            let Ok(cleaned) = clean::<usize>(&pts) else {
                continue;
            };
            let v: Vec<Point> = cleaned.iter().map(|&i| pts[i]).collect();
            let sweep = find_self_intersection(&v).is_some();
            assert_eq!(sweep, brute_self_intersects(&v), "{v:?}");
            if sweep { invalid += 1 } else { valid += 1 }
        }
        assert!(valid > 100 && invalid > 100, "{valid} {invalid}");
    }
}
