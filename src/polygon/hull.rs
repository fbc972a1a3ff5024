//! Convex hull of a point set by Andrew's monotone chain on the exact kernel, and
//! [`HullAlgorithm`], which names it beside Graham's scan ([`super::graham`]) for the
//! callers that choose at run time (the `hull` protocol, benches, tests).
//!
//! # Complexity
//! O(n log n) for n points (the sort); O(n) extra memory.
//!
//! # Degeneracies
//! Duplicate points are merged; points on a hull edge (collinear with its
//! endpoints) are not vertices; ties in the sort are broken by y, so vertical runs
//! are ordered. Fewer than three non-collinear points have no hull polygon: an error.

use super::graham::graham_indices;
use super::{ConvexPolygon, InputIndex, PolygonError};
use crate::kernel::{Exact, Kernel, Orientation, Point};
use std::fmt;
use std::str::FromStr;

/// A convex hull algorithm, chosen at run time. Both are exact and give the same hull.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum HullAlgorithm {
    /// Graham's scan ([`graham_scan`](super::graham_scan)): angular sort around the
    /// lowest point.
    Graham,
    /// Andrew's monotone chain ([`convex_hull`]): lexicographic sort, two chains.
    #[default]
    Monotone,
}

impl HullAlgorithm {
    /// Both algorithms, in the order the CLI lists them.
    pub const ALL: [HullAlgorithm; 2] = [HullAlgorithm::Graham, HullAlgorithm::Monotone];

    /// The name the CLI's `--algorithm` takes: `graham` or `monotone`.
    pub fn name(self) -> &'static str {
        match self {
            HullAlgorithm::Graham => "graham",
            HullAlgorithm::Monotone => "monotone",
        }
    }
}

impl fmt::Display for HullAlgorithm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for HullAlgorithm {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        HullAlgorithm::ALL
            .into_iter()
            .find(|a| a.name() == s)
            .ok_or_else(|| format!("unknown hull algorithm '{s}' (valid: graham, monotone)"))
    }
}

/// The hull of a point set as a vertex list, degenerate sets included:
/// counter-clockwise, strictly convex, starting at the lowest vertex (the leftmost of
/// those). One distinct point gives `[p]`; a collinear set gives its two extreme
/// points, the lowest (then leftmost) first. Every algorithm gives the same list.
/// O(n log n).
///
/// # Errors
/// `NonFinite` for a NaN or infinite coordinate (with its index), `TooFewVertices {
/// distinct: 0 }` for an empty set.
///
/// ```
/// use polysect::polygon::{HullAlgorithm, hull_vertices};
/// use polysect::Point;
/// let pts = [[0.0, 2.0], [2.0, 0.0], [1.0, 1.0], [2.0, 2.0], [0.0, 0.5]].map(Point::from);
/// for algorithm in HullAlgorithm::ALL {
///     let hull = hull_vertices(&pts, algorithm)?;
///     assert_eq!(hull, [[2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [0.0, 0.5]].map(Point::from));
/// }
/// let line = [[0.0, 3.0], [1.0, 2.0], [3.0, 0.0]].map(Point::from);
/// assert_eq!(hull_vertices(&line, HullAlgorithm::Graham)?, [[3.0, 0.0], [0.0, 3.0]].map(Point::from));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
pub fn hull_vertices(points: &[Point], algorithm: HullAlgorithm) -> Result<Vec<Point>, PolygonError> {
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(PolygonError::NonFinite {
            index,
            point: points[index],
        });
    }
    if points.is_empty() {
        return Err(PolygonError::TooFewVertices { distinct: 0 });
    }
    let lower = |a: &Point, b: &Point| a.y.total_cmp(&b.y).then(a.x.total_cmp(&b.x));
    let mut hull: Vec<Point> = match algorithm {
        HullAlgorithm::Graham => graham_indices(points).into_iter().map(|i| points[i]).collect(),
        HullAlgorithm::Monotone => {
            let mut idx: Vec<usize> = (0..points.len()).collect();
            let hull = hull_indices(points, &mut idx);
            if hull.len() >= 3 {
                hull.into_iter().map(|i| points[i]).collect()
            } else {
                // Fewer than three distinct points, or collinear: the two ends of the
                // lexicographic order (one point when they coincide).
                let (first, last) = (points[idx[0]], points[idx[idx.len() - 1]]);
                if first == last {
                    vec![first]
                } else if lower(&first, &last).is_lt() {
                    vec![first, last]
                } else {
                    vec![last, first]
                }
            }
        }
    };
    if let Some(start) = (0..hull.len()).min_by(|&a, &b| lower(&hull[a], &hull[b])) {
        hull.rotate_left(start);
    }
    Ok(hull)
}

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
