//! Closed point containment: is the point x in the polygon, boundary included?
//!
//! # The fan around one vertex
//! Take a vertex a of the polygon (counter-clockwise, strictly convex). Seen from a, the
//! other vertices a⁺ = next(a), …, a⁻ = prev(a) are sorted by angle, within an angle
//! smaller than π. A point x ≠ a can only lie in the polygon if it lies in the closed
//! wedge at a (not strictly right of a→a⁺, not strictly right of a⁻→a). Then the ray
//! from a through x leaves the polygon through one edge v→w of that fan: v is the last
//! vertex (from a⁺ on) not strictly left of the line a→x, w its successor. Along
//! a⁺ … a⁻ the side of the line a→x goes right (or on) … then left, at most one vertex
//! on it, so "not strictly left of a→x" is monotone and a binary search finds v on an
//! array. The answer:
//! * v on the line a→x: the ray leaves the polygon at the vertex v, so x is inside iff
//!   it lies on the segment a–v, that is (v − x)·(v − a) ≥ 0;
//! * otherwise x is inside iff it is not strictly right of the edge v→w.
//!
//! # On a simple polygon
//! [`SimplePolygon::contains_point`] counts crossings, O(n): a point on an edge is
//! inside; otherwise the edges that straddle the horizontal line through x (half-open:
//! one endpoint strictly above, the other not) are counted when they pass to the right of
//! x, which is the side of x relative to the edge (`orient`, read by the edge's
//! direction). An odd count is inside. No intersection point is constructed.
//!
//! # On a linked polygon
//! There is nothing to binary-search, so the query samples (module docs of
//! [`queries`](super)): of r = ⌈√n⌉ random vertices, it keeps the one not strictly
//! left of a→x that comes last counter-clockwise from a (one `orient` decides whether
//! a vertex comes after another, as all lie within an angle below π at a), starting
//! from a⁺, and walks forward from it to v. Every vertex passed on the walk lies between
//! the kept vertex and v, where no drawn vertex lies: expected O(n/r) steps.
//!
//! # Complexity
//! Arrays: at most 3 + ⌈log2 n⌉ `orient` calls and one more predicate; no allocation.
//! Linked: r + O(1) `orient` calls, r random accesses, and an expected O(n/r) walk:
//! expected O(√n) for every polygon (over the draws); O(n) in the worst case (an
//! absurdly unlucky draw). No allocation. Under the fast kernel the walk is capped at
//! n steps.
//!
//! # Degeneracies
//! Closed sets: a vertex, a point on an edge, and every point of the polygon's interior
//! are inside. A point one ulp outside an edge is outside. A NaN or infinite point is
//! in no polygon (every polygon is a bounded set of finite points): `false`.
//!
//! # Precision
//! Only `orient` and `dot` predicates on the polygon's vertices and x: exact under
//! [`Exact`], for every finite input; under [`Fast`](crate::Fast) a point within
//! rounding distance of the boundary may be misjudged.

use super::sample_count;
use crate::kernel::{Exact, Kernel, Orientation, Point, Sign, point_on_segment};
use crate::polygon::{ConvexPolygon, LinkedPolygon, SimplePolygon};
use crate::seeding::fresh_rng;
use rand::Rng;

/// The answer once the exit edge v→w of the ray a→x is known (module docs).
#[inline]
fn decide<K: Kernel>(k: K, a: Point, v: Point, w: Point, x: Point) -> bool {
    if k.orient(a, x, v) == Orientation::Collinear {
        // The ray from a through x leaves the polygon at the vertex v.
        k.dot(x, v, a, v) != Sign::Negative
    } else {
        k.orient(v, w, x) != Orientation::Cw
    }
}

/// Whether x is outside the closed wedge at a between the edges prev→a and a→next.
#[inline]
fn outside_wedge<K: Kernel>(k: K, prev: Point, a: Point, next: Point, x: Point) -> bool {
    k.orient(a, next, x) == Orientation::Cw || k.orient(prev, a, x) == Orientation::Cw
}

impl ConvexPolygon {
    /// Whether `point` lies in the polygon, boundary included, decided exactly.
    ///
    /// # Complexity
    /// O(log n) for n vertices: a binary search for the triangle of the fan at vertex 0
    /// that the point falls in, at most ⌈log2 n⌉ + 4 predicates. No allocation.
    ///
    /// # Degeneracies
    /// The polygon is a closed set: vertices and points on edges are inside. A NaN or
    /// infinite point is inside no polygon (`false`).
    ///
    /// # Precision
    /// Exact ([`Exact`] kernel) for every finite input; see
    /// [`contains_point_with`](Self::contains_point_with) to choose the kernel.
    ///
    /// ```
    /// use polysect::ConvexPolygon;
    /// let square = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// assert!(square.contains_point([1.0, 1.0]));
    /// assert!(square.contains_point([2.0, 0.5])); // on an edge
    /// assert!(square.contains_point([2.0, 2.0])); // a vertex
    /// assert!(!square.contains_point([2.0f64.next_up(), 1.0])); // one ulp outside
    /// assert!(!square.contains_point([f64::NAN, 1.0]));
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn contains_point(&self, point: impl Into<Point>) -> bool {
        self.contains_point_with(Exact, point)
    }

    /// [`contains_point`](Self::contains_point) with the predicates of `kernel`.
    /// Under [`Fast`](crate::Fast), a point within rounding distance of the boundary
    /// may be misjudged.
    ///
    /// ```
    /// use polysect::{ConvexPolygon, Fast};
    /// let t = ConvexPolygon::new([[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]])?;
    /// assert!(t.contains_point_with(Fast, [1.0, 1.0]));
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn contains_point_with<K: Kernel>(&self, kernel: K, point: impl Into<Point>) -> bool {
        let x = point.into();
        let v = self.vertices();
        let n = v.len();
        let a = v[0];
        if !x.is_finite() {
            return false;
        }
        if x == a {
            return true;
        }
        if outside_wedge(kernel, v[n - 1], a, v[1], x) {
            return false;
        }
        // The last i in 1..n with v[i] not strictly left of a→x; v[1] qualifies (wedge).
        let (mut lo, mut hi) = (1, n);
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if kernel.orient(a, x, v[mid]) == Orientation::Ccw {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        decide(kernel, a, v[lo], v[(lo + 1) % n], x)
    }
}

impl LinkedPolygon {
    /// Whether `point` lies in the polygon, boundary included, decided exactly, by
    /// sampling: expected O(√n) without converting the polygon to an array.
    ///
    /// The generator is seeded from the operating system; use
    /// [`contains_point_with`](Self::contains_point_with) to pass a seeded one (the
    /// answer never depends on it, only the time does).
    ///
    /// # Complexity
    /// Expected O(√n) for n vertices, for every polygon and point (over the random
    /// draws); O(n) in the worst case. No allocation. See [`polygon::queries`](crate::polygon::queries).
    ///
    /// # Degeneracies
    /// Closed set: vertices and points on edges are inside; a NaN or infinite point is
    /// not.
    ///
    /// # Precision
    /// Exact ([`Exact`] kernel) for every finite input.
    ///
    /// ```
    /// use polysect::LinkedPolygon;
    /// let p = LinkedPolygon::from_points([[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]])?;
    /// assert!(p.contains_point([4.0, 1.0])); // on an edge
    /// assert!(!p.contains_point([4.5, 1.0]));
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn contains_point(&self, point: impl Into<Point>) -> bool {
        self.contains_point_with(Exact, point, &mut fresh_rng())
    }

    /// [`contains_point`](Self::contains_point) with the predicates of `kernel` and the
    /// random draws of `rng` (seed it to reproduce a run's time exactly). Under the
    /// exact kernel the answer never depends on the draws; under
    /// [`Fast`](crate::Fast) a point within rounding distance of the boundary may be
    /// misjudged.
    ///
    /// ```
    /// use polysect::{Exact, LinkedPolygon};
    /// use polysect::generate::regular_polygon;
    /// use rand::{SeedableRng, rngs::SmallRng};
    /// let p = LinkedPolygon::from_convex(&regular_polygon(1 << 16, 1.0));
    /// let mut rng = SmallRng::seed_from_u64(1);
    /// assert!(p.contains_point_with(Exact, [1.0, 0.0], &mut rng)); // a vertex
    /// assert!(p.contains_point_with(Exact, [0.5, -0.5], &mut rng));
    /// assert!(!p.contains_point_with(Exact, [1.0, 1.0], &mut rng));
    /// ```
    pub fn contains_point_with<K: Kernel, R: Rng + ?Sized>(
        &self,
        kernel: K,
        point: impl Into<Point>,
        rng: &mut R,
    ) -> bool {
        let x = point.into();
        let n = self.len();
        // The fan's apex: the vertex stored first (any vertex would do).
        let a_pos = 0;
        let a = self.point_at(a_pos);
        if !x.is_finite() {
            return false;
        }
        if x == a {
            return true;
        }
        let next = self.next_at(a_pos);
        if outside_wedge(
            kernel,
            self.point_at(self.prev_at(a_pos)),
            a,
            self.point_at(next),
            x,
        ) {
            return false;
        }
        // The drawn vertex not strictly left of a→x that comes last counter-clockwise.
        let mut best = next;
        let mut best_point = self.point_at(next);
        for _ in 0..sample_count(n) {
            let pos = rng.random_range(0..n);
            let p = self.point_at(pos);
            if pos != a_pos
                && kernel.orient(a, x, p) != Orientation::Ccw
                && kernel.orient(a, best_point, p) == Orientation::Ccw
            {
                (best, best_point) = (pos, p);
            }
        }
        // Walk forward to the last vertex not strictly left of a→x.
        for _ in 0..n {
            let following = self.next_at(best);
            if following == a_pos || kernel.orient(a, x, self.point_at(following)) == Orientation::Ccw {
                break;
            }
            best = following;
        }
        decide(
            kernel,
            a,
            self.point_at(best),
            self.point_at(self.next_at(best)),
            x,
        )
    }
}

impl SimplePolygon {
    /// Whether `point` lies in the polygon (the region its boundary encloses), boundary
    /// included, decided exactly by counting crossings.
    ///
    /// # Complexity
    /// O(n) for n vertices: one `orient` per edge (two for the edges that straddle the
    /// point's height). No allocation.
    ///
    /// # Degeneracies
    /// A closed set: vertices and points on edges are inside. Horizontal edges, vertices
    /// at the point's height and collinear runs are handled by the half-open rule (an
    /// edge counts when exactly one endpoint lies strictly above the point). A NaN or
    /// infinite point is not inside.
    ///
    /// # Precision
    /// Exact ([`Exact`] kernel): only `orient` and coordinate comparisons.
    ///
    /// ```
    /// use polysect::SimplePolygon;
    /// // An L shape: the notch (1.5, 1.5) is outside, the inner corner (1, 1) on the boundary.
    /// let l = SimplePolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]])?;
    /// assert!(l.contains_point([0.5, 1.5]));
    /// assert!(l.contains_point([1.0, 1.0]));
    /// assert!(!l.contains_point([1.5, 1.5]));
    /// # Ok::<(), polysect::SimplePolygonError>(())
    /// ```
    pub fn contains_point(&self, point: impl Into<Point>) -> bool {
        self.contains_point_with(Exact, point)
    }

    /// [`contains_point`](Self::contains_point) with the predicates of `kernel`.
    ///
    /// ```
    /// use polysect::{Fast, SimplePolygon};
    /// let t = SimplePolygon::new([[0.0, 0.0], [0.0, 4.0], [4.0, 0.0]])?; // clockwise
    /// assert!(t.contains_point_with(Fast, [1.0, 1.0]));
    /// # Ok::<(), polysect::SimplePolygonError>(())
    /// ```
    pub fn contains_point_with<K: Kernel>(&self, kernel: K, point: impl Into<Point>) -> bool {
        let x = point.into();
        if !x.is_finite() {
            return false;
        }
        let mut inside = false;
        for i in 0..self.len() {
            let (a, b) = self.edge(i);
            if point_on_segment(kernel, a, b, x) {
                return true;
            }
            if (a.y > x.y) != (b.y > x.y) {
                // Not on the edge, so not on its line at this height: a strict side.
                let left = kernel.orient(a, b, x) == Orientation::Ccw;
                if (b.y > a.y) == left {
                    inside = !inside;
                }
            }
        }
        inside
    }
}
