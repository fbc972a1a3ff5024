//! The extreme vertex in a direction d: a vertex v maximising d·v (the rightmost vertex
//! for d = (1, 0), the lowest for d = (0, −1)).
//!
//! # Which vertex, when two tie
//! On a strictly convex polygon at most two vertices maximise d·v, and only when the
//! edge between them is perpendicular to d. Then the query returns the edge's **start**
//! (its first vertex counter-clockwise), on arrays and linked lists alike, so both
//! answer the same vertex. A zero direction has no extreme vertex: `None` (as for a
//! NaN or infinite direction).
//!
//! # On an array: a search over edge directions
//! The edge directions e_i = v_{i+1} − v_i of a counter-clockwise strictly convex
//! polygon turn counter-clockwise once around the circle, starting from e_0. Let t be d
//! turned a quarter counter-clockwise, (−d_y, d_x). Walking counter-clockwise, d·v
//! grows while the edge direction lies strictly before t (within a half turn) and stops
//! growing at the first edge whose direction is at or past t. So the extreme vertex is
//! the start of the first edge e_i whose angle, measured counter-clockwise from e_0 in
//! [0, 2π), is at least the angle of t (vertex 0 when there is none: the wrap-around).
//! "Angle at least" is monotone in i, so a binary search finds it. Angles are never
//! computed: two directions are compared by which half turn from e_0 they lie in (the
//! signs of `cross` and `dot` with e_0) and then by the sign of their `cross`.
//!
//! # On a linked polygon: sample, then climb
//! Of r = ⌈√n⌉ random vertices the query keeps one with the largest d·v (compared
//! exactly: the sign of d·(w − v)), then climbs: along the boundary d·v increases
//! strictly from the minimum to the maximum and decreases strictly back (an edge
//! perpendicular to d can only occur at the two ends), so stepping to the better
//! neighbour until neither is better reaches the maximum. Every vertex passed has a
//! larger d·v than the kept vertex, so none was drawn: expected fewer than n/r of them.
//!
//! # Complexity
//! Arrays: O(log n), at most 2⌈log2 n⌉ + 6 predicates; no allocation. Linked: r
//! comparisons and random accesses plus an expected O(n/r) climb, expected O(√n) for
//! every polygon and direction (over the draws); O(n) in the worst case. No allocation.
//! Walking a 2^20-gon for its rightmost vertex reads all 2^20 vertices; the sampled
//! query evaluates about 1.6·√n = 1,600 predicates on average (counted in
//! tests/geometry/queries.rs; timed in benches/queries.rs).
//!
//! # Precision
//! Every comparison is the sign of a polynomial in the coordinates of the vertices and
//! d (`cross`, `dot`): exact under [`Exact`] for every finite input, even when two
//! dot products differ in the last bit or would overflow in floating point. Under
//! [`Fast`](crate::Fast) a near-tie may pick the other vertex.

use super::sample_count;
use crate::kernel::{Exact, Kernel, Orientation, Point, Sign};
use crate::polygon::{ConvexPolygon, LinkedPolygon, VertexId};
use crate::seeding::fresh_rng;
use rand::Rng;

const ORIGIN: Point = Point::new(0.0, 0.0);

/// A direction given by two points (from, to).
type Dir = (Point, Point);

/// Whether direction `u` lies in the second half turn [π, 2π) counted counter-clockwise
/// from `base`.
#[inline]
fn second_half<K: Kernel>(k: K, base: Dir, u: Dir) -> bool {
    match k.cross(base.0, base.1, u.0, u.1) {
        Orientation::Ccw => false,
        Orientation::Cw => true,
        Orientation::Collinear => k.dot(base.0, base.1, u.0, u.1) == Sign::Negative,
    }
}

/// Whether the angle of `u` from `base` (in [0, 2π)) is less than that of `w`.
#[inline]
fn angle_less<K: Kernel>(k: K, base: Dir, u: Dir, w: Dir) -> bool {
    match (second_half(k, base, u), second_half(k, base, w)) {
        (false, true) => true,
        (true, false) => false,
        _ => k.cross(u.0, u.1, w.0, w.1) == Orientation::Ccw,
    }
}

/// A usable direction: finite and not zero.
#[inline]
fn usable(d: Point) -> bool {
    d.is_finite() && (d.x != 0.0 || d.y != 0.0)
}

impl ConvexPolygon {
    /// The index (into [`vertices`](Self::vertices)) of a vertex maximising `d·v`: the
    /// polygon's farthest vertex in direction `d`, e.g. the rightmost for `(1, 0)`.
    /// When an edge is perpendicular to `d`, both its vertices are extreme and its
    /// start (counter-clockwise) is returned.
    ///
    /// # Complexity
    /// O(log n) for n vertices: a binary search over the edge directions, at most
    /// 2⌈log2 n⌉ + 6 predicates. No allocation.
    ///
    /// # Degeneracies
    /// `None` when `d` is zero or has a NaN or infinite component (no direction).
    ///
    /// # Precision
    /// Exact ([`Exact`] kernel): dot products are compared by the sign of d·(w − v),
    /// never by computed values, so vertices differing by one ulp are told apart.
    ///
    /// ```
    /// use polysect::{ConvexPolygon, Point};
    /// let p = ConvexPolygon::new([[0.0, 0.0], [4.0, 0.0], [5.0, 2.0], [4.0, 4.0], [0.0, 4.0]])?;
    /// assert_eq!(p.extreme_vertex([1.0, 0.0]), Some(2)); // (5, 2), the rightmost
    /// // The top edge (4, 4)–(0, 4) is perpendicular to (0, 1): its start is returned.
    /// assert_eq!(p.extreme_vertex([0.0, 1.0]), Some(3));
    /// assert_eq!(p.vertices()[3], Point::new(4.0, 4.0));
    /// assert_eq!(p.extreme_vertex([0.0, 0.0]), None);
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn extreme_vertex(&self, d: impl Into<Point>) -> Option<usize> {
        self.extreme_vertex_with(Exact, d)
    }

    /// [`extreme_vertex`](Self::extreme_vertex) with the predicates of `kernel`. Under
    /// [`Fast`](crate::Fast) a near-tie may pick another vertex.
    ///
    /// ```
    /// use polysect::{ConvexPolygon, Fast};
    /// let p = ConvexPolygon::new([[0.0, 0.0], [4.0, 0.0], [2.0, 3.0]])?;
    /// assert_eq!(p.extreme_vertex_with(Fast, [0.0, 1.0]), Some(2));
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn extreme_vertex_with<K: Kernel>(&self, kernel: K, d: impl Into<Point>) -> Option<usize> {
        let d = d.into();
        if !usable(d) {
            return None;
        }
        let v = self.vertices();
        let n = v.len();
        let t: Dir = (ORIGIN, Point::new(-d.y, d.x));
        let base: Dir = (v[0], v[1]);
        let edge = |i: usize| -> Dir { (v[i], v[(i + 1) % n]) };
        // The first edge whose angle from e_0 is at least t's; n (wrap to 0) if none.
        let at_or_past = |i: usize| !angle_less(kernel, base, edge(i), t);
        if at_or_past(0) {
            return Some(0);
        }
        let (mut lo, mut hi) = (0, n);
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if at_or_past(mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        Some(hi % n)
    }
}

impl LinkedPolygon {
    /// A vertex maximising `d·v`, by sampling: expected O(√n) without walking the
    /// whole boundary. When an edge is perpendicular to `d` both its vertices are
    /// extreme and its start (counter-clockwise) is returned, the same vertex as
    /// [`ConvexPolygon::extreme_vertex`] on [`to_convex`](Self::to_convex).
    ///
    /// The generator is seeded from the operating system; use
    /// [`extreme_vertex_with`](Self::extreme_vertex_with) to pass a seeded one (the
    /// answer never depends on it under the exact kernel).
    ///
    /// # Complexity
    /// Expected O(√n) for n vertices, for every polygon and direction (over the draws);
    /// O(n) in the worst case. No allocation. See [`polygon::queries`](crate::polygon::queries).
    ///
    /// # Degeneracies
    /// `None` when `d` is zero or has a NaN or infinite component.
    ///
    /// # Precision
    /// Exact ([`Exact`] kernel): comparisons are signs of d·(w − v).
    ///
    /// ```
    /// use polysect::{LinkedPolygon, Point};
    /// use polysect::generate::regular_polygon;
    /// let p = LinkedPolygon::from_convex(&regular_polygon(1 << 16, 1.0));
    /// let right = p.extreme_vertex([1.0, 0.0]).unwrap();
    /// assert_eq!(p.point(right)?, Point::new(1.0, 0.0));
    /// # Ok::<(), polysect::EditError>(())
    /// ```
    pub fn extreme_vertex(&self, d: impl Into<Point>) -> Option<VertexId> {
        self.extreme_vertex_with(Exact, d, &mut fresh_rng())
    }

    /// [`extreme_vertex`](Self::extreme_vertex) with the predicates of `kernel` and
    /// the random draws of `rng`.
    ///
    /// ```
    /// use polysect::{Exact, LinkedPolygon, Point};
    /// use rand::{SeedableRng, rngs::SmallRng};
    /// let p = LinkedPolygon::from_points([[0.0, 0.0], [4.0, 0.0], [5.0, 2.0], [4.0, 4.0], [0.0, 4.0]])?;
    /// let mut rng = SmallRng::seed_from_u64(3);
    /// let low = p.extreme_vertex_with(Exact, [1.0, -1.0], &mut rng).unwrap();
    /// assert_eq!(p.point(low)?, Point::new(4.0, 0.0));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn extreme_vertex_with<K: Kernel, R: Rng + ?Sized>(
        &self,
        kernel: K,
        d: impl Into<Point>,
        rng: &mut R,
    ) -> Option<VertexId> {
        let d = d.into();
        if !usable(d) {
            return None;
        }
        let n = self.len();
        // Sign of d·w − d·v: Positive when w lies farther in direction d than v.
        let better = |v: usize, w: usize| kernel.dot(ORIGIN, d, self.point_at(v), self.point_at(w));
        let mut best = 0;
        for _ in 0..sample_count(n) {
            let pos = rng.random_range(0..n);
            if better(best, pos) == Sign::Positive {
                best = pos;
            }
        }
        // Climb towards the better neighbour (at most n steps, so a fast kernel's
        // inconsistent answers cannot loop).
        let step: fn(&LinkedPolygon, usize) -> usize = if better(best, self.next_at(best)) == Sign::Positive {
            LinkedPolygon::next_at
        } else {
            LinkedPolygon::prev_at
        };
        for _ in 0..n {
            let to = step(self, best);
            if better(best, to) != Sign::Positive {
                break;
            }
            best = to;
        }
        // A tie with a neighbour: the edge between them is perpendicular to d.
        if better(best, self.prev_at(best)) == Sign::Zero {
            best = self.prev_at(best);
        }
        Some(self.id_at(best))
    }
}
