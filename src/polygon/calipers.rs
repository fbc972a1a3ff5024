//! Rotating calipers on a convex polygon: the farthest pair of vertices (the
//! diameter), the width, and the minimum-area enclosing rectangle, all from one walk
//! around the boundary; the farthest pair of a point set through its convex hull.
//!
//! # The walk
//! For each edge `e_i = v_i → v_{i+1}` of the counter-clockwise polygon, one caliper
//! `j` stays on the vertex farthest from the line through `e_i` (it advances while the
//! next edge still moves away from that line: `e_i × e_j > 0`). Every pair of
//! antipodal vertices shows up as `(v_i, v_j)` or `(v_{i+1}, v_j)`, plus `v_{j+1}` when
//! `e_j` is parallel to `e_i`; the farthest pair of vertices is antipodal, so the
//! largest of these is the diameter (Shamos). Two more calipers follow the vertices
//! extreme along `e_i` (largest and smallest `v · e_i`); with `j` they give the
//! rectangle with one side on the line of `e_i`, and the smallest such rectangle
//! encloses the polygon with the least area (Freeman and Shapira). The width is the
//! smallest distance from an edge's line to its farthest vertex.
//!
//! # Complexity
//! O(n) for a polygon of n vertices (each caliper goes around at most once);
//! O(n log n) for a set of n points (the hull); the naive oracles (`*_naive`, with `instrument`) are
//! O(n²) or worse.
//!
//! # Degeneracies
//! Ties are real answers: when several pairs are equally far apart, the walk reports
//! the first one it meets starting from vertex 0 (so the same polygon always gives
//! the same pair). A point set of one distinct point has the pair `(p, p)`; a
//! collinear set has its two extreme points.
//!
//! # Precision
//! Every decision is a sign, decided by the kernel: the calipers advance on the signs
//! of cross and dot products of edges, and candidates are compared through the signs
//! of polynomials in the input coordinates — squared distances for the diameter
//! (degree 2), `cross² · |e'|² − cross'² · |e|²` for the width and
//! `dot · cross · |e'|² − dot' · cross' · |e|²` for the rectangle (degree 6). Under
//! [`Exact`] the reported pair, width edge and rectangle edge are exactly right for
//! every finite input. The lengths and the area returned beside them
//! ([`Width::value`], [`Rectangle::area`], [`Rectangle::corners`]) are computed in
//! floating point and are approximate.

use super::hull::hull_indices;
use super::{ConvexPolygon, LinkedPolygon, PolygonError};
use crate::kernel::sealed::Predicates as _;
use crate::kernel::{Exact, Kernel, Orientation, Point, Polynomial, Ring, Sign};
use std::cmp::Ordering;

/// A closed counter-clockwise chain the calipers can walk: a position type, the
/// successor of a position, and the point there.
trait Cycle {
    type Pos: Copy;
    fn len(&self) -> usize;
    fn start(&self) -> Self::Pos;
    fn next(&self, pos: Self::Pos) -> Self::Pos;
    fn at(&self, pos: Self::Pos) -> Point;
}

impl Cycle for [Point] {
    type Pos = usize;
    fn len(&self) -> usize {
        <[Point]>::len(self)
    }
    fn start(&self) -> usize {
        0
    }
    #[inline]
    fn next(&self, i: usize) -> usize {
        if i + 1 == <[Point]>::len(self) { 0 } else { i + 1 }
    }
    #[inline]
    fn at(&self, i: usize) -> Point {
        self[i]
    }
}

impl Cycle for LinkedPolygon {
    type Pos = usize;
    fn len(&self) -> usize {
        LinkedPolygon::len(self)
    }
    fn start(&self) -> usize {
        0
    }
    #[inline]
    fn next(&self, pos: usize) -> usize {
        self.next_at(pos)
    }
    #[inline]
    fn at(&self, pos: usize) -> Point {
        self.point_at(pos)
    }
}

instrument_pub! {
    /// Compares the lengths of segments `ab` and `cd` exactly (squared distances, a
    /// degree-2 polynomial, decided by [`Exact`]).
    ///
    /// ```
    /// use polysect::polygon::calipers::compare_distances;
    /// use polysect::Point;
    /// use std::cmp::Ordering;
    /// let o = Point::new(0.0, 0.0);
    /// // 0.1 + 0.2 is not 0.3 in f64, and the comparison knows it.
    /// assert_eq!(compare_distances(o, Point::new(0.1 + 0.2, 0.0), o, Point::new(0.3, 0.0)), Ordering::Greater);
    /// ```
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    fn compare_distances(a: Point, b: Point, c: Point, d: Point) -> Ordering {
        compare_distances_with(Exact, a, b, c, d)
    }
}

instrument_pub! {
    /// [`compare_distances`] under any kernel.
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    fn compare_distances_with<K: Kernel>(k: K, a: Point, b: Point, c: Point, d: Point) -> Ordering {
        k.sign(&DistanceDiff(a, b, c, d)).to_ordering()
    }
}

/// |b − a|² − |d − c|².
struct DistanceDiff(Point, Point, Point, Point);
impl Polynomial for DistanceDiff {
    #[inline]
    fn eval<R: Ring>(&self) -> R {
        let f = R::from_f64;
        let sq = |p: Point, q: Point| {
            let (dx, dy) = (f(q.x) - f(p.x), f(q.y) - f(p.y));
            dx.clone() * dx + dy.clone() * dy
        };
        sq(self.0, self.1) - sq(self.2, self.3)
    }
}

/// (b − a) × (c − a), (b − a) · (d − c) and |b − a|², as ring values.
fn cross<R: Ring>(a: Point, b: Point, c: Point) -> R {
    let f = R::from_f64;
    (f(b.x) - f(a.x)) * (f(c.y) - f(a.y)) - (f(b.y) - f(a.y)) * (f(c.x) - f(a.x))
}
fn dot<R: Ring>(a: Point, b: Point, c: Point, d: Point) -> R {
    let f = R::from_f64;
    (f(b.x) - f(a.x)) * (f(d.x) - f(c.x)) + (f(b.y) - f(a.y)) * (f(d.y) - f(c.y))
}
fn norm2<R: Ring>(a: Point, b: Point) -> R {
    dot(a, b, a, b)
}

/// Squared height of `c` over edge ab, times |b'−a'|², minus the same for the other
/// edge: `cross(a,b,c)² · |b'−a'|² − cross(a',b',c')² · |b−a|²`.
struct HeightDiff([Point; 3], [Point; 3]);
impl Polynomial for HeightDiff {
    fn eval<R: Ring>(&self) -> R {
        let ([a, b, c], [a2, b2, c2]) = (self.0, self.1);
        let (h, h2) = (cross::<R>(a, b, c), cross::<R>(a2, b2, c2));
        h.clone() * h * norm2(a2, b2) - h2.clone() * h2 * norm2(a, b)
    }
}

/// Area of the rectangle on edge ab (extent `lo → hi` along it, height to `far`),
/// times |b−a|² · |b'−a'|², minus the same for the other edge (dividing out the common
/// factor): `dot·cross·|e'|² − dot'·cross'·|e|²`.
struct AreaDiff([Point; 5], [Point; 5]);
impl Polynomial for AreaDiff {
    fn eval<R: Ring>(&self) -> R {
        let area = |[a, b, lo, hi, far]: [Point; 5]| dot::<R>(a, b, lo, hi) * cross::<R>(a, b, far);
        let ([a, b, ..], [a2, b2, ..]) = (self.0, self.1);
        area(self.0) * norm2(a2, b2) - area(self.1) * norm2(a, b)
    }
}

/// The narrowest strip holding the polygon: its one side is the line through `edge`,
/// the other passes through `vertex`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Width {
    /// Two consecutive vertices (counter-clockwise).
    pub edge: (Point, Point),
    /// A vertex farthest from the edge's line.
    pub vertex: Point,
}

impl Width {
    /// The width (approximate: computed in floating point).
    pub fn value(&self) -> f64 {
        let ((a, b), c) = (self.edge, self.vertex);
        cross::<f64>(a, b, c) / norm2::<f64>(a, b).sqrt()
    }
}

/// The enclosing rectangle of least area: one side lies on the line through `edge`;
/// `low` and `high` are vertices extreme along the edge's direction (smallest and
/// largest `v · (b − a)`), `far` a vertex farthest from the edge's line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rectangle {
    /// The polygon edge the rectangle's side lies on.
    pub edge: (Point, Point),
    /// A vertex with the smallest projection on the edge's direction.
    pub low: Point,
    /// A vertex with the largest projection on the edge's direction.
    pub high: Point,
    /// A vertex farthest from the edge's line.
    pub far: Point,
}

impl Rectangle {
    /// The area (approximate: computed in floating point).
    pub fn area(&self) -> f64 {
        let (a, b) = self.edge;
        dot::<f64>(a, b, self.low, self.high) * cross::<f64>(a, b, self.far) / norm2::<f64>(a, b)
    }

    /// The four corners, counter-clockwise, starting on the edge's line below `low`
    /// (approximate: constructed points, rounded).
    pub fn corners(&self) -> [Point; 4] {
        let (a, b) = self.edge;
        let (ex, ey) = (b.x - a.x, b.y - a.y);
        let l2 = ex * ex + ey * ey;
        // Project onto the edge's line, then shift by the height along the inner normal.
        let along = |p: Point| ((p.x - a.x) * ex + (p.y - a.y) * ey) / l2;
        let on_line = |t: f64| Point::new(a.x + t * ex, a.y + t * ey);
        let h = cross::<f64>(a, b, self.far) / l2;
        let (p0, p1) = (on_line(along(self.low)), on_line(along(self.high)));
        let up = |p: Point| Point::new(p.x - h * ey, p.y + h * ex);
        [p0, p1, up(p1), up(p0)]
    }
}

/// Everything one caliper walk finds.
struct Walk {
    diameter: (Point, Point),
    /// With [`Want::Width`].
    width: Option<Width>,
    /// With [`Want::Rectangle`].
    rectangle: Option<Rectangle>,
}

/// What a walk computes beyond the diameter.
#[derive(Clone, Copy, PartialEq)]
enum Want {
    Diameter,
    Width,
    Rectangle,
}

/// The rotating-calipers walk over a strictly convex counter-clockwise chain of at
/// least three vertices. The width's comparisons are made only when asked for, and the
/// two calipers along the edge run only for the rectangle.
fn walk<C: Cycle + ?Sized, K: Kernel>(k: K, c: &C, want: Want) -> Walk {
    let rect = want == Want::Rectangle;
    let n = c.len();
    let i0 = c.start();
    let (mut i, mut j) = (i0, c.next(i0));
    let (a0, b0) = (c.at(i0), c.at(j));
    let mut best = (a0, b0);
    let mut consider = |p: Point, q: Point| {
        if compare_distances_with(k, p, q, best.0, best.1) == Ordering::Greater {
            best = (p, q);
        }
    };
    // Each caliper advances at most n times in all; the bounds only guard the loops.
    let (mut hi, mut lo) = (i0, i0);
    let mut width: Option<Width> = None;
    let mut rectangle: Option<Rectangle> = None;
    let (mut steps_j, mut steps_hi, mut steps_lo) = (0usize, 0usize, 0usize);
    for _ in 0..n {
        let i1 = c.next(i);
        let (a, b) = (c.at(i), c.at(i1));
        // Farthest from the line ab.
        while steps_j < 2 * n && k.cross(a, b, c.at(j), c.at(c.next(j))) == Orientation::Ccw {
            j = c.next(j);
            steps_j += 1;
        }
        let far = c.at(j);
        consider(a, far);
        consider(b, far);
        let far2 = c.at(c.next(j));
        if k.cross(a, b, far, far2) == Orientation::Collinear {
            consider(a, far2);
            consider(b, far2);
        }
        let w = Width {
            edge: (a, b),
            vertex: far,
        };
        if want == Want::Width
            && width.is_none_or(|cur| {
                let (ca, cb) = cur.edge;
                k.sign(&HeightDiff([a, b, far], [ca, cb, cur.vertex])) == Sign::Negative
            })
        {
            width = Some(w);
        }
        if rect {
            // Largest v · e: advance while the next edge still goes forward along e.
            while steps_hi < 2 * n && k.dot(a, b, c.at(hi), c.at(c.next(hi))) == Sign::Positive {
                hi = c.next(hi);
                steps_hi += 1;
            }
            if rectangle.is_none() {
                lo = hi;
            }
            // Smallest v · e: past the backward edges (a perpendicular one changes nothing).
            while steps_lo < 3 * n && k.dot(a, b, c.at(lo), c.at(c.next(lo))) != Sign::Positive {
                lo = c.next(lo);
                steps_lo += 1;
            }
            let r = Rectangle {
                edge: (a, b),
                low: c.at(lo),
                high: c.at(hi),
                far,
            };
            if rectangle.is_none_or(|cur| {
                let (ca, cb) = cur.edge;
                k.sign(&AreaDiff(
                    [a, b, r.low, r.high, far],
                    [ca, cb, cur.low, cur.high, cur.far],
                )) == Sign::Negative
            }) {
                rectangle = Some(r);
            }
        }
        i = i1;
    }
    Walk {
        diameter: best,
        width,
        rectangle,
    }
}

/// The farthest pair of vertices of a convex polygon (its diameter), by rotating
/// calipers, exactly. O(n).
///
/// ```
/// use polysect::polygon::calipers::farthest_pair;
/// use polysect::{ConvexPolygon, Point};
/// let p = ConvexPolygon::new([[0.0, 0.0], [4.0, 0.0], [4.0, 1.0], [0.0, 1.0]])?;
/// let (a, b) = farthest_pair(&p);
/// assert_eq!((a, b), (Point::new(0.0, 0.0), Point::new(4.0, 1.0)));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
pub fn farthest_pair(polygon: &ConvexPolygon) -> (Point, Point) {
    farthest_pair_with(Exact, polygon)
}

/// [`farthest_pair`] under any kernel.
pub fn farthest_pair_with<K: Kernel>(k: K, polygon: &ConvexPolygon) -> (Point, Point) {
    walk(k, polygon.vertices(), Want::Diameter).diameter
}

/// [`farthest_pair`] on a linked polygon, walking its links (no conversion). O(n).
pub fn farthest_pair_linked(polygon: &LinkedPolygon) -> (Point, Point) {
    walk(Exact, polygon, Want::Diameter).diameter
}

/// The width of a convex polygon (the narrowest strip that holds it), exactly. O(n).
///
/// ```
/// use polysect::polygon::calipers::width;
/// use polysect::{ConvexPolygon, Point};
/// let p = ConvexPolygon::new([[0.0, 0.0], [4.0, 0.0], [4.0, 1.0], [0.0, 1.0]])?;
/// let w = width(&p);
/// assert_eq!(w.value(), 1.0);
/// # Ok::<(), polysect::PolygonError>(())
/// ```
///
/// # Panics
/// Never: a [`ConvexPolygon`] has at least three edges.
pub fn width(polygon: &ConvexPolygon) -> Width {
    walk(Exact, polygon.vertices(), Want::Width)
        .width
        .expect("a polygon has edges")
}

/// The enclosing rectangle of least area of a convex polygon, exactly (its edge and
/// its extreme vertices; the corners are approximate). O(n).
///
/// ```
/// use polysect::polygon::calipers::min_area_rectangle;
/// use polysect::ConvexPolygon;
/// let diamond = ConvexPolygon::new([[1.0, 0.0], [2.0, 1.0], [1.0, 2.0], [0.0, 1.0]])?;
/// assert_eq!(min_area_rectangle(&diamond).area(), 2.0);
/// # Ok::<(), polysect::PolygonError>(())
/// ```
///
/// # Panics
/// Never: a [`ConvexPolygon`] has at least three edges.
pub fn min_area_rectangle(polygon: &ConvexPolygon) -> Rectangle {
    walk(Exact, polygon.vertices(), Want::Rectangle)
        .rectangle
        .expect("a polygon has edges")
}

/// The farthest pair of a point set, through its convex hull (monotone chain, then
/// [`farthest_pair`]'s walk), exactly. O(n log n). One distinct point gives `(p, p)`;
/// collinear points give their two extreme points.
///
/// # Errors
/// `NonFinite` for a NaN or infinite coordinate (with its index), `TooFewVertices {
/// distinct: 0 }` for an empty set.
///
/// ```
/// use polysect::polygon::calipers::farthest_pair_of_points;
/// use polysect::Point;
/// let pts = [[0.0, 0.0], [1.0, 5.0], [2.0, 1.0], [1.0, 1.0]].map(Point::from);
/// assert_eq!(farthest_pair_of_points(&pts)?, (Point::new(0.0, 0.0), Point::new(1.0, 5.0)));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
pub fn farthest_pair_of_points(points: &[Point]) -> Result<(Point, Point), PolygonError> {
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(PolygonError::NonFinite {
            index,
            point: points[index],
        });
    }
    let mut idx: Vec<usize> = (0..points.len()).collect();
    let hull: Vec<Point> = hull_indices(points, &mut idx)
        .into_iter()
        .map(|i| points[i])
        .collect();
    Ok(match (idx.first(), idx.last()) {
        (None, _) | (_, None) => return Err(PolygonError::TooFewVertices { distinct: 0 }),
        // Collinear (or one or two points): sorted along the line, the ends are farthest.
        (Some(&lo), Some(&hi)) if hull.len() < 3 => (points[lo], points[hi]),
        _ => farthest_pair_of_hull(&hull),
    })
}

/// [`farthest_pair`] on a hull given as a strictly convex counter-clockwise vertex
/// list of at least three vertices (not checked).
pub(crate) fn farthest_pair_of_hull(hull: &[Point]) -> (Point, Point) {
    walk(Exact, hull, Want::Diameter).diameter
}

instrument_pub! {
    /// The farthest pair of a point set by comparing every pair: the O(n²) reference the
    /// calipers are tested against. `None` for an empty set; `(p, p)` for one point.
    /// Exact comparisons; of equally far pairs the first in input order is kept.
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    fn farthest_pair_naive(points: &[Point]) -> Option<(Point, Point)> {
        let mut best = (*points.first()?, points[0]);
        for (i, &p) in points.iter().enumerate() {
            for &q in &points[i + 1..] {
                if compare_distances(p, q, best.0, best.1) == Ordering::Greater {
                    best = (p, q);
                }
            }
        }
        Some(best)
    }
}

instrument_pub! {
    /// The width by trying every edge against every vertex: the O(n²) reference.
    ///
    /// # Panics
    /// Never: a [`ConvexPolygon`] has at least three edges.
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    fn width_naive(polygon: &ConvexPolygon) -> Width {
        let v = polygon.vertices();
        let n = v.len();
        let mut best: Option<Width> = None;
        for i in 0..n {
            let (a, b) = (v[i], v[(i + 1) % n]);
            let mut far = v[0];
            for &p in v {
                if Exact.sign(&HeightDiff([a, b, p], [a, b, far])) == Sign::Positive {
                    far = p;
                }
            }
            let w = Width {
                edge: (a, b),
                vertex: far,
            };
            if best.is_none_or(|cur| {
                Exact.sign(&HeightDiff([a, b, far], [cur.edge.0, cur.edge.1, cur.vertex])) == Sign::Negative
            }) {
                best = Some(w);
            }
        }
        best.expect("a polygon has edges")
    }
}

instrument_pub! {
    /// The least-area rectangle by trying every edge against every vertex: the O(n²)
    /// reference.
    ///
    /// # Panics
    /// Never: a [`ConvexPolygon`] has at least three edges.
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    fn min_area_rectangle_naive(polygon: &ConvexPolygon) -> Rectangle {
        let v = polygon.vertices();
        let n = v.len();
        let mut best: Option<Rectangle> = None;
        for i in 0..n {
            let (a, b) = (v[i], v[(i + 1) % n]);
            let (mut low, mut high, mut far) = (a, a, a);
            for &p in v {
                if Exact.dot(a, b, low, p) == Sign::Negative {
                    low = p;
                }
                if Exact.dot(a, b, high, p) == Sign::Positive {
                    high = p;
                }
                if Exact.cross(a, b, far, p) == Orientation::Ccw {
                    far = p;
                }
            }
            let r = Rectangle {
                edge: (a, b),
                low,
                high,
                far,
            };
            if best.is_none_or(|cur| {
                Exact.sign(&AreaDiff(
                    [a, b, low, high, far],
                    [cur.edge.0, cur.edge.1, cur.low, cur.high, cur.far],
                )) == Sign::Negative
            }) {
                best = Some(r);
            }
        }
        best.expect("a polygon has edges")
    }
}

instrument_pub! {
    /// Compares the widths of two strips exactly.
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    fn compare_widths(a: &Width, b: &Width) -> Ordering {
        Exact
            .sign(&HeightDiff(
                [a.edge.0, a.edge.1, a.vertex],
                [b.edge.0, b.edge.1, b.vertex],
            ))
            .to_ordering()
    }
}

instrument_pub! {
    /// Compares the areas of two rectangles exactly.
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    fn compare_areas(a: &Rectangle, b: &Rectangle) -> Ordering {
        Exact
            .sign(&AreaDiff(
                [a.edge.0, a.edge.1, a.low, a.high, a.far],
                [b.edge.0, b.edge.1, b.low, b.high, b.far],
            ))
            .to_ordering()
    }
}
