//! Convex hull of a point set by Andrew's monotone chain on the exact kernel.
//!
//! # Complexity
//! O(n log n) for n points (the sort); O(n) extra memory.
//!
//! # Degeneracies
//! Duplicate points are merged; points on a hull edge (collinear with its
//! endpoints) are not vertices; ties in the sort are broken by y, so vertical runs
//! are ordered. Fewer than three non-collinear points have no hull polygon: an error.

use super::{ConvexPolygon, InputIndex, PolygonError};
use crate::kernel::{Exact, Kernel, Orientation, Point};

/// The convex hull of `points` as a [`ConvexPolygon`] (counter-clockwise, starting at
/// the lexicographically smallest point).
///
/// # Errors
/// `NonFinite` for a NaN or infinite coordinate, `TooFewVertices` for fewer than three
/// distinct points, `AllCollinear` when the points lie on one line.
///
/// ```
/// use polysect::polygon::convex_hull;
/// use polysect::Point;
/// let h = convex_hull(&[[0.0, 0.0], [2.0, 0.0], [1.0, 1.0], [2.0, 2.0], [0.0, 2.0], [1.0, 0.0]].map(Point::from))?;
/// assert_eq!(h.len(), 4);
/// # Ok::<(), polysect::PolygonError>(())
/// ```
pub fn convex_hull(points: &[Point]) -> Result<ConvexPolygon, PolygonError> {
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(PolygonError::NonFinite {
            index,
            point: points[index],
        });
    }
    let mut idx: Vec<usize> = (0..points.len()).collect();
    let hull = hull_indices(points, &mut idx);
    if idx.len() < 3 {
        return Err(PolygonError::TooFewVertices { distinct: idx.len() });
    }
    let hull: Vec<Point> = hull.into_iter().map(|i| points[i]).collect();
    if hull.len() < 3 {
        return Err(PolygonError::AllCollinear);
    }
    Ok(ConvexPolygon::from_ccw_unchecked(hull))
}

/// Andrew's monotone chain on indices into `points` (finite): sorts `idx`
/// lexicographically by point and drops repeated points (so `idx.len()` is then the
/// number of distinct points), and returns the hull's vertex indices counter-clockwise
/// from the lexicographically smallest point (fewer than three when the points are
/// collinear). Extra memory: the indices, never a copy of the points.
pub(crate) fn hull_indices<I: InputIndex>(points: &[Point], idx: &mut Vec<I>) -> Vec<I> {
    let at = |i: I| points[i.get()];
    idx.sort_unstable_by(|&a, &b| at(a).lex_cmp(at(b)));
    idx.dedup_by(|a, b| at(*a) == at(*b));
    if idx.len() < 3 {
        return Vec::new();
    }
    let mut hull: Vec<I> = Vec::new();
    // Lower hull left to right, then upper hull right to left; pop non-left turns.
    for pass in 0..2 {
        let floor = hull.len();
        let iter: Box<dyn Iterator<Item = &I>> = if pass == 0 {
            Box::new(idx.iter())
        } else {
            Box::new(idx.iter().rev())
        };
        for &p in iter {
            while hull.len() >= floor + 2
                && Exact.orient(at(hull[hull.len() - 2]), at(hull[hull.len() - 1]), at(p)) != Orientation::Ccw
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop(); // the last point starts the other chain
    }
    hull
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    #[test]
    fn hull_of_grid_with_collinear_points_and_duplicates() {
        let mut pts = Vec::new();
        for x in 0..5 {
            for y in 0..4 {
                pts.push(Point::new(x as f64, y as f64));
                pts.push(Point::new(x as f64, y as f64));
            }
        }
        let h = convex_hull(&pts).unwrap();
        assert_eq!(
            h.vertices(),
            &[
                Point::new(0., 0.),
                Point::new(4., 0.),
                Point::new(4., 3.),
                Point::new(0., 3.)
            ]
        );
    }

    #[test]
    fn degenerate_inputs_are_errors() {
        let line: Vec<Point> = (0..10).map(|i| Point::new(i as f64, 2.0 * i as f64)).collect();
        assert_eq!(convex_hull(&line), Err(PolygonError::AllCollinear));
        assert_eq!(
            convex_hull(&line[..2]),
            Err(PolygonError::TooFewVertices { distinct: 2 })
        );
        let nan = [Point::new(0., 0.), Point::new(f64::NAN, 0.), Point::new(1., 1.)];
        assert!(matches!(
            convex_hull(&nan),
            Err(PolygonError::NonFinite { index: 1, .. })
        ));
    }

    #[test]
    fn hull_contains_every_point_and_is_valid() {
        let mut rng = SmallRng::seed_from_u64(11);
        for round in 0..200 {
            let n = rng.random_range(3..200);
            // Small integer grid: many collinear triples and duplicates.
            let pts: Vec<Point> = (0..n)
                .map(|_| Point::new(rng.random_range(0..8) as f64, rng.random_range(0..8) as f64))
                .collect();
            let Ok(h) = convex_hull(&pts) else { continue };
            h.debug_validate()
                .unwrap_or_else(|e| panic!("round {round}: {e}"));
            let v = h.vertices();
            for &p in &pts {
                for i in 0..v.len() {
                    assert_ne!(Exact.orient(v[i], v[(i + 1) % v.len()], p), Orientation::Cw);
                }
            }
        }
    }
}
