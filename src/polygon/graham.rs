//! Convex hull of a point set by Graham's scan, as the lecture notes give it: sort the
//! points by angle around a pivot of the set, then walk them keeping only left turns.
//!
//! # The sort
//! The pivot is the lowest point of the set, the leftmost of those ([`pivot_index`]).
//! Every other point lies in the half-turn of directions [0, π) seen from it, so
//! "`a` before `b`" is the exact orientation `orient(pivot, a, b) = Ccw` — no angle is
//! computed. Points on one ray from the pivot come nearest first, except on the last
//! ray, where they come farthest first ([`angular_order`]); this is the order that
//! makes the sorted list a simple polygon (the notes' angular-sort polygon), and the
//! scan uses it unchanged.
//!
//! # The scan
//! Points are pushed in order; before each push, the top of the stack is popped while
//! it does not make a strict left turn. At the end, points on the last ray (which
//! came farthest first) are popped the same way against the pivot. What remains is
//! the hull, counter-clockwise from the pivot, strictly convex.
//!
//! # Complexity
//! O(n log n) for n points (the sort); O(n) extra memory (indices, not copies).
//!
//! # Degeneracies
//! Repeated points are merged (the first copy is kept); points on a hull edge are not
//! vertices. A set of one distinct point has the hull `[p]`; a collinear set has its
//! two extreme points, pivot first.
//!
//! # Precision
//! Every decision (the sort, the turns, "nearer on a ray") is a sign from the exact
//! kernel; coordinates are only compared, never computed.

use super::{ConvexPolygon, PolygonError};
use crate::kernel::{Exact, Kernel, Orientation, Point, Sign};
use std::cmp::Ordering;

instrument_pub! {
    /// The index of the lowest point (smallest y), the leftmost of those (smallest x);
    /// the first such index when the point repeats. `None` for an empty set. Points must
    /// be finite.
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    fn pivot_index(points: &[Point]) -> Option<usize> {
        (0..points.len()).min_by(|&a, &b| {
            let (p, q) = (points[a], points[b]);
            p.y.total_cmp(&q.y).then(p.x.total_cmp(&q.x))
        })
    }
}

/// The order of the angular sort: `a` before `b` around `pivot` (both in the
/// half-turn [0, π) from it), nearer first on a common ray. Exact.
fn by_angle(pivot: Point, a: Point, b: Point) -> Ordering {
    match Exact.orient(pivot, a, b) {
        Orientation::Ccw => Ordering::Less,
        Orientation::Cw => Ordering::Greater,
        // Same ray: a is nearer when b − a points away from the pivot.
        Orientation::Collinear => match Exact.dot(pivot, a, a, b) {
            Sign::Positive => Ordering::Less,
            Sign::Negative => Ordering::Greater,
            Sign::Zero => Ordering::Equal,
        },
    }
}

instrument_pub! {
    /// The points' indices in angular order around the pivot ([`pivot_index`]), pivot
    /// first: counter-clockwise by the angle seen from the pivot, nearer first on each ray
    /// except the last, where the farther come first. Copies of the pivot are dropped;
    /// other repeated points stay (consecutive). With at least three non-collinear
    /// points, the points in this order are the vertices of a simple polygon (the notes'
    /// angular sort). Exact; O(n log n). Points must be finite.
    ///
    /// ```
    /// use polysect::polygon::angular_order;
    /// use polysect::Point;
    /// // The pivot (0, 0); (1, 1) and (2, 2) lie on the last ray: farthest first.
    /// let pts = [[2.0, 2.0], [1.0, 1.0], [0.0, 0.0], [3.0, 1.0], [2.0, 0.0]].map(Point::from);
    /// assert_eq!(angular_order(&pts), [2, 4, 3, 0, 1]);
    /// ```
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    fn angular_order(points: &[Point]) -> Vec<usize> {
        let Some(pivot) = pivot_index(points) else {
            return Vec::new();
        };
        let o = points[pivot];
        let mut rest: Vec<usize> = (0..points.len()).filter(|&i| points[i] != o).collect();
        rest.sort_by(|&a, &b| by_angle(o, points[a], points[b]).then(a.cmp(&b)));
        // The last ray: the trailing run collinear with the pivot and the last point,
        // reversed (farthest first). When every point is on one ray, that ray is the last.
        if let Some(&last) = rest.last() {
            let run = rest
                .iter()
                .rev()
                .take_while(|&&i| Exact.orient(o, points[last], points[i]) == Orientation::Collinear)
                .count();
            let len = rest.len();
            rest[len - run..].reverse();
        }
        let mut order = Vec::with_capacity(rest.len() + 1);
        order.push(pivot);
        order.extend(rest);
        order
    }
}

/// Graham's scan on finite points: the hull's vertex indices, counter-clockwise from
/// the pivot ([`pivot_index`]); one index for a single distinct point, two for a
/// collinear set, none for an empty one.
pub(crate) fn graham_indices(points: &[Point]) -> Vec<usize> {
    let order = angular_order(points);
    let Some((&pivot, rest)) = order.split_first() else {
        return Vec::new();
    };
    let at = |i: usize| points[i];
    // Every point on one ray: that ray is also the last, so its farthest point came first.
    match (rest.first(), rest.last()) {
        (None, _) | (_, None) => return vec![pivot],
        (Some(&first), Some(&last))
            if Exact.orient(at(pivot), at(first), at(last)) == Orientation::Collinear =>
        {
            return vec![pivot, first];
        }
        _ => {}
    }
    let mut hull = vec![pivot];
    for &p in rest {
        if at(p) == at(*hull.last().expect("the pivot stays")) {
            continue;
        }
        while hull.len() >= 2
            && Exact.orient(at(hull[hull.len() - 2]), at(hull[hull.len() - 1]), at(p)) != Orientation::Ccw
        {
            hull.pop();
        }
        hull.push(p);
    }
    // The last ray came farthest first: its nearer points are not vertices.
    while hull.len() >= 3
        && Exact.orient(at(hull[hull.len() - 2]), at(hull[hull.len() - 1]), at(pivot)) != Orientation::Ccw
    {
        hull.pop();
    }
    hull
}

/// The convex hull of `points` by Graham's scan, as a [`ConvexPolygon`]
/// (counter-clockwise, starting at the lowest point, the leftmost of those). The
/// same polygon as [`convex_hull`](super::convex_hull), which starts at the leftmost
/// point instead.
///
/// # Errors
/// `NonFinite` for a NaN or infinite coordinate, `TooFewVertices` for fewer than three
/// distinct points, `AllCollinear` when the points lie on one line.
///
/// ```
/// use polysect::polygon::graham_scan;
/// use polysect::Point;
/// let h = graham_scan(&[[0.0, 2.0], [2.0, 0.0], [1.0, 1.0], [2.0, 2.0], [0.0, 0.5]].map(Point::from))?;
/// assert_eq!(h.vertices(), [[2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [0.0, 0.5]].map(Point::from));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
pub fn graham_scan(points: &[Point]) -> Result<ConvexPolygon, PolygonError> {
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(PolygonError::NonFinite {
            index,
            point: points[index],
        });
    }
    let hull = graham_indices(points);
    match hull.len() {
        0 | 1 => Err(PolygonError::TooFewVertices { distinct: hull.len() }),
        2 => {
            // Collinear: two distinct points, or more on one line.
            let mut distinct: Vec<Point> = points.to_vec();
            distinct.sort_by(|a, b| a.lex_cmp(*b));
            distinct.dedup();
            Err(if distinct.len() < 3 {
                PolygonError::TooFewVertices {
                    distinct: distinct.len(),
                }
            } else {
                PolygonError::AllCollinear
            })
        }
        _ => Ok(ConvexPolygon::from_ccw_unchecked(
            hull.into_iter().map(|i| points[i]).collect(),
        )),
    }
}
