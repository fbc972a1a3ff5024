//! Constructors for the shapes a program reaches for first: axis-aligned and oriented
//! rectangles, regular polygons, circle approximations and the hull of a point set.
//!
//! # Complexity
//! O(n) for a shape of n vertices (the validation of [`ConvexPolygon::new`]);
//! [`ConvexPolygon::hull_of`] is O(n log n) in the number of points.
//!
//! # Precision and degeneracies
//! [`ConvexPolygon::rectangle`] uses the given coordinates as they are, so it is exact.
//! The other shapes compute their vertices in `f64` (a sine, a cosine, a product and a
//! sum each, so within a few ulps of the ideal positions) and validate the rounded
//! vertices with the exact kernel: a shape that comes back is strictly convex with
//! exactly the vertex count asked for. When rounding at the given scale would merge
//! vertices or break a turn (a tiny radius around a huge centre, or more vertices than
//! `f64` can separate on the circle) the constructor refuses with
//! [`PolygonError::BadParameter`] instead of returning a different polygon. So do
//! non-finite parameters, sizes that are zero or negative, fewer than three vertices,
//! and corners that overflow `f64`. No parameter makes a constructor panic.

use super::{ConvexPolygon, LinkedPolygon, PolygonError, convex_hull};
use crate::kernel::Point;
use std::f64::consts::PI;

fn bad(parameter: &'static str, reason: String) -> PolygonError {
    PolygonError::BadParameter { parameter, reason }
}

fn finite_point(parameter: &'static str, p: Point) -> Result<Point, PolygonError> {
    if p.is_finite() {
        Ok(p)
    } else {
        Err(bad(parameter, format!("must be finite, got {p}")))
    }
}

fn positive(parameter: &'static str, x: f64) -> Result<f64, PolygonError> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(bad(parameter, format!("must be finite and positive, got {x:?}")))
    }
}

fn finite(parameter: &'static str, x: f64) -> Result<f64, PolygonError> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(bad(parameter, format!("must be finite, got {x:?}")))
    }
}

/// The spacing of `f64` values at magnitude `x` (the smallest subnormal at 0).
fn ulp(x: f64) -> f64 {
    let x = x.abs();
    (x.next_up() - x).max(f64::from_bits(1))
}

/// Validates computed vertices: they must be finite and give a strictly convex polygon
/// with all `expected` of them kept. `parameter` names what to change when they do not.
fn exact_shape(
    points: Vec<Point>,
    expected: usize,
    parameter: &'static str,
) -> Result<ConvexPolygon, PolygonError> {
    if let Some(p) = points.iter().find(|p| !p.is_finite()) {
        return Err(bad(
            parameter,
            format!("a vertex overflows f64 (computed {p}); the shape is too large"),
        ));
    }
    match ConvexPolygon::new(points) {
        Ok(polygon) if polygon.len() == expected => Ok(polygon),
        Ok(polygon) => Err(bad(
            parameter,
            format!(
                "rounding to f64 at this scale merges vertices ({expected} asked for, {} distinct \
                 corners remain); use a larger size or fewer vertices",
                polygon.len()
            ),
        )),
        Err(e) => Err(bad(
            parameter,
            format!(
                "rounding to f64 at this scale breaks the shape ({e}); use a larger size or fewer vertices"
            ),
        )),
    }
}

impl ConvexPolygon {
    /// The axis-aligned rectangle with corners `min` and `max`, counter-clockwise from
    /// `min`. Exact: the vertices are the given coordinates.
    ///
    /// # Errors
    /// [`PolygonError::BadParameter`] when a coordinate is not finite or `max` does not
    /// exceed `min` in both coordinates (a rectangle of zero or negative size).
    ///
    /// ```
    /// use polysect::{ConvexPolygon, Point};
    /// let r = ConvexPolygon::rectangle([0.0, 0.0], [4.0, 2.0])?;
    /// assert_eq!(r.vertices(), [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]].map(Point::from));
    /// assert_eq!(r.area(), 8.0);
    /// assert!(ConvexPolygon::rectangle([0.0, 0.0], [4.0, 0.0]).is_err()); // no height
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn rectangle(min: impl Into<Point>, max: impl Into<Point>) -> Result<ConvexPolygon, PolygonError> {
        let min = finite_point("min", min.into())?;
        let max = finite_point("max", max.into())?;
        if !(max.x > min.x && max.y > min.y) {
            return Err(bad(
                "max",
                format!("must exceed min {min} in both coordinates, got {max}"),
            ));
        }
        let corners = vec![min, Point::new(max.x, min.y), max, Point::new(min.x, max.y)];
        exact_shape(corners, 4, "max")
    }

    /// The rectangle centred at `centre` with half-width `half_extents[0]` and
    /// half-height `half_extents[1]`, turned counter-clockwise by `angle` radians about
    /// its centre. The first vertex is the corner that starts at `(−w, −h)` from the
    /// centre. The corners are rounded to `f64` and then validated exactly: a rectangle that
    /// rounding would collapse is refused.
    ///
    /// # Errors
    /// [`PolygonError::BadParameter`] for a non-finite centre or angle, a half-extent
    /// that is not finite and positive, corners that overflow `f64`, or a rectangle so
    /// thin for its position that rounding leaves it without four strictly convex corners.
    ///
    /// ```
    /// use polysect::{ConvexPolygon, Point};
    /// use std::f64::consts::FRAC_PI_2;
    /// let r = ConvexPolygon::oriented_rectangle([10.0, 0.0], [2.0, 1.0], FRAC_PI_2)?;
    /// assert_eq!(r.len(), 4);
    /// // Turned a quarter turn: 2 wide in x, 4 tall in y.
    /// let b = r.bounding_box();
    /// assert!((b.max.x - b.min.x - 2.0).abs() < 1e-12 && (b.max.y - b.min.y - 4.0).abs() < 1e-12);
    /// assert!(r.contains_point(Point::new(10.5, 1.5)));
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn oriented_rectangle(
        centre: impl Into<Point>,
        half_extents: [f64; 2],
        angle: f64,
    ) -> Result<ConvexPolygon, PolygonError> {
        let c = finite_point("centre", centre.into())?;
        let w = positive("half_extents", half_extents[0])?;
        let h = positive("half_extents", half_extents[1])?;
        let angle = finite("angle", angle)?;
        let (s, co) = angle.sin_cos();
        let (ux, uy) = (w * co, w * s);
        let (vx, vy) = (-h * s, h * co);
        let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
            .map(|(a, b)| Point::new(c.x + (a * ux + b * vx), c.y + (a * uy + b * vy)))
            .to_vec();
        exact_shape(corners, 4, "half_extents")
    }

    /// The regular polygon with `n` vertices on the circle of `radius` about `centre`,
    /// counter-clockwise, the first at angle `phase` (radians from the positive x axis).
    /// The vertices are rounded to `f64` (within a few ulps of the circle) and then
    /// validated exactly: a polygon that rounding would collapse is refused.
    ///
    /// # Errors
    /// [`PolygonError::BadParameter`] for `n < 3`, a non-finite centre or phase, a radius
    /// that is not finite and positive, vertices that overflow `f64`, or more vertices
    /// than `f64` can keep strictly convex at this radius and centre (checked before
    /// anything is allocated when they are far too many).
    ///
    /// ```
    /// use polysect::{ConvexPolygon, Point};
    /// let hexagon = ConvexPolygon::regular([0.0, 0.0], 1.0, 6, 0.0)?;
    /// assert_eq!(hexagon.len(), 6);
    /// assert_eq!(hexagon.vertices()[0], Point::new(1.0, 0.0));
    /// assert!(ConvexPolygon::regular([0.0, 0.0], 1.0, 2, 0.0).is_err());
    /// // Eight vertices 1 apart around a centre at 1e20 round onto one point.
    /// assert!(ConvexPolygon::regular([1e20, 0.0], 1.0, 8, 0.0).is_err());
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn regular(
        centre: impl Into<Point>,
        radius: f64,
        n: usize,
        phase: f64,
    ) -> Result<ConvexPolygon, PolygonError> {
        if n < 3 {
            return Err(bad("n", format!("a polygon needs at least 3 vertices, got {n}")));
        }
        let c = finite_point("centre", centre.into())?;
        let r = positive("radius", radius)?;
        let phase = finite("phase", phase)?;
        // The distance of a vertex from the chord through its neighbours; when it is
        // below the spacing of f64 at the polygon's coordinates no rounding can keep the
        // turn, so refuse before allocating n vertices.
        let sagitta = 2.0 * r * (PI / n as f64).sin().powi(2);
        let scale = c.x.abs().max(c.y.abs()) + r;
        if sagitta <= ulp(scale) {
            return Err(bad(
                "n",
                format!(
                    "{n} vertices on a circle of radius {r} about {c} are closer to straight than \
                     f64 resolves there; use fewer vertices or a larger radius"
                ),
            ));
        }
        let mut points = Vec::new();
        points
            .try_reserve_exact(n)
            .map_err(|e| bad("n", format!("cannot allocate {n} vertices: {e}")))?;
        points.extend((0..n).map(|i| {
            let (s, co) = (phase + std::f64::consts::TAU * (i as f64 / n as f64)).sin_cos();
            Point::new(c.x + r * co, c.y + r * s)
        }));
        exact_shape(points, n, "n")
    }

    /// A circle approximation: the regular polygon inscribed in the circle of `radius`
    /// about `centre` (first vertex on the positive x axis), with the fewest vertices
    /// (at least 3) for which no point of the circle is farther than `tolerance` from
    /// the polygon. The polygon lies inside the circle. For a given vertex count use
    /// [`ConvexPolygon::regular`].
    ///
    /// The count is `⌈π / (2·asin(√(tolerance / 2·radius)))⌉`: the gap between an edge
    /// and the arc it cuts off is `radius·(1 − cos(π/n))`, computed here in the
    /// half-angle form so that tolerances far below the radius keep their precision.
    ///
    /// # Errors
    /// [`PolygonError::BadParameter`] for a non-finite centre, a radius or tolerance that
    /// is not finite and positive, or a tolerance so fine that `f64` cannot place that
    /// many vertices strictly convexly at this radius and centre.
    ///
    /// ```
    /// use polysect::ConvexPolygon;
    /// let c = ConvexPolygon::circle([0.0, 0.0], 10.0, 0.01)?;
    /// assert_eq!(c.len(), 71);
    /// // Inside the circle of radius 10, containing the one of radius 10 − 0.01.
    /// let pi = std::f64::consts::PI;
    /// assert!(c.area() < pi * 10.0 * 10.0 && c.area() > pi * 9.99 * 9.99);
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn circle(
        centre: impl Into<Point>,
        radius: f64,
        tolerance: f64,
    ) -> Result<ConvexPolygon, PolygonError> {
        let c = finite_point("centre", centre.into())?;
        let r = positive("radius", radius)?;
        let tolerance = positive("tolerance", tolerance)?;
        let n = circle_vertex_count(r, tolerance);
        match ConvexPolygon::regular(c, r, n, 0.0) {
            Err(PolygonError::BadParameter { reason, .. }) => Err(bad(
                "tolerance",
                format!("tolerance {tolerance} needs {n} vertices: {reason}"),
            )),
            other => other,
        }
    }

    /// The convex hull of any set of points (any order, repeats and interior points
    /// allowed), counter-clockwise from the lowest (then leftmost) point: the same as
    /// [`convex_hull`](super::convex_hull), for any iterator of points. O(n log n).
    ///
    /// # Errors
    /// [`PolygonError::NonFinite`] for a NaN or infinite coordinate (with its index),
    /// [`PolygonError::TooFewVertices`] for fewer than three distinct points,
    /// [`PolygonError::AllCollinear`] when they lie on one line.
    ///
    /// ```
    /// use polysect::{ConvexPolygon, Point};
    /// let h = ConvexPolygon::hull_of([[1.0, 1.0], [0.0, 0.0], [2.0, 0.0], [1.0, 3.0], [1.0, 0.0]])?;
    /// assert_eq!(h.vertices(), [[0.0, 0.0], [2.0, 0.0], [1.0, 3.0]].map(Point::from));
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn hull_of<I, P>(points: I) -> Result<ConvexPolygon, PolygonError>
    where
        I: IntoIterator<Item = P>,
        P: Into<Point>,
    {
        let points: Vec<Point> = points.into_iter().map(Into::into).collect();
        convex_hull(&points)
    }
}

/// The fewest vertices (at least 3) of an inscribed regular polygon whose edges stay
/// within `tolerance` of the circle of radius `r`; `usize::MAX` when that is beyond any
/// count (the caller's resolution check then refuses it).
pub(crate) fn circle_vertex_count(r: f64, tolerance: f64) -> usize {
    let t = tolerance / (2.0 * r);
    // A triangle's gap is r/2 (t = 1/4); any tolerance at least that needs only 3.
    if t >= 0.25 {
        return 3;
    }
    let n = (PI / (2.0 * t.sqrt().asin())).ceil();
    if n.is_finite() && n < usize::MAX as f64 {
        (n as usize).max(3)
    } else {
        usize::MAX
    }
}

/// The same shapes as linked polygons, built through [`ConvexPolygon`] and
/// [`LinkedPolygon::from_convex`] (O(n) more); the errors are the same.
impl LinkedPolygon {
    /// [`ConvexPolygon::rectangle`] as a linked polygon.
    ///
    /// # Errors
    /// As [`ConvexPolygon::rectangle`].
    pub fn rectangle(min: impl Into<Point>, max: impl Into<Point>) -> Result<LinkedPolygon, PolygonError> {
        ConvexPolygon::rectangle(min, max).map(|p| LinkedPolygon::from_convex(&p))
    }

    /// [`ConvexPolygon::oriented_rectangle`] as a linked polygon.
    ///
    /// # Errors
    /// As [`ConvexPolygon::oriented_rectangle`].
    pub fn oriented_rectangle(
        centre: impl Into<Point>,
        half_extents: [f64; 2],
        angle: f64,
    ) -> Result<LinkedPolygon, PolygonError> {
        ConvexPolygon::oriented_rectangle(centre, half_extents, angle).map(|p| LinkedPolygon::from_convex(&p))
    }

    /// [`ConvexPolygon::regular`] as a linked polygon.
    ///
    /// # Errors
    /// As [`ConvexPolygon::regular`].
    ///
    /// ```
    /// use polysect::LinkedPolygon;
    /// let octagon = LinkedPolygon::regular([0.0, 0.0], 5.0, 8, 0.0)?;
    /// assert_eq!(octagon.len(), 8);
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn regular(
        centre: impl Into<Point>,
        radius: f64,
        n: usize,
        phase: f64,
    ) -> Result<LinkedPolygon, PolygonError> {
        ConvexPolygon::regular(centre, radius, n, phase).map(|p| LinkedPolygon::from_convex(&p))
    }

    /// [`ConvexPolygon::circle`] as a linked polygon.
    ///
    /// # Errors
    /// As [`ConvexPolygon::circle`].
    pub fn circle(
        centre: impl Into<Point>,
        radius: f64,
        tolerance: f64,
    ) -> Result<LinkedPolygon, PolygonError> {
        ConvexPolygon::circle(centre, radius, tolerance).map(|p| LinkedPolygon::from_convex(&p))
    }

    /// [`ConvexPolygon::hull_of`] as a linked polygon.
    ///
    /// # Errors
    /// As [`ConvexPolygon::hull_of`].
    pub fn hull_of<I, P>(points: I) -> Result<LinkedPolygon, PolygonError>
    where
        I: IntoIterator<Item = P>,
        P: Into<Point>,
    {
        ConvexPolygon::hull_of(points).map(|p| LinkedPolygon::from_convex(&p))
    }
}
