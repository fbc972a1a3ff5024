//! The contact normal of a colliding pair, for the elastic bounce: the one function the
//! certificate-based normal (the separating edge of the last disjoint frame, or the
//! contact witness) will replace.
//!
//! Today it is the **minimum-overlap axis** of the separating-axis theorem: among the
//! outward edge normals of both polygons, the one along which the two polygons' extents
//! overlap least. For two convex polygons that intersect this is the direction of the
//! shortest translation that separates them (the penetration direction); for disjoint
//! ones it is the axis of largest gap. The answer is oriented from `a` towards `b`.
//!
//! # Complexity
//! O(n + m) for polygons of n and m vertices: as the edges of one polygon are walked
//! counter-clockwise their outward normals turn monotonically, so the other polygon's
//! extreme vertex along each normal moves monotonically too (a rotating two-pointer
//! walk); each polygon's edges are walked once against the other. Both polygons must be
//! given as arrays, so the caller walks linked polygons first, O(n + m) as well: this is
//! response, not detection, and runs only on pairs the store reported as intersecting.
//!
//! # Precision
//! Plain floating point: a normal is a direction for the physics, not a predicate, and
//! nothing is decided from it. On nearly parallel edges rounding can make the extreme
//! vertex walk stop one step early; the overlap found is then within rounding of the
//! minimum.

use crate::kernel::Point;

/// The unit contact normal pointing from `a` towards `b`, or `None` when either slice
/// has fewer than 3 points or every edge is degenerate. Both slices are convex polygons,
/// counter-clockwise, without repeated vertices.
///
/// ```
/// use polysect::serve::contact_normal;
/// use polysect::Point;
/// let square = |x: f64, y: f64| [(x, y), (x + 2.0, y), (x + 2.0, y + 2.0), (x, y + 2.0)]
///     .map(|(x, y)| Point::new(x, y));
/// // b overlaps a by 0.5 along x and 1.5 along y: the normal is +x.
/// let n = contact_normal(&square(0.0, 0.0), &square(1.5, 0.5)).unwrap();
/// assert_eq!(n, [1.0, 0.0]);
/// ```
pub fn contact_normal(a: &[Point], b: &[Point]) -> Option<[f64; 2]> {
    if a.len() < 3 || b.len() < 3 {
        return None;
    }
    // Along a's normals b lies beyond: the direction from a to b is +u.
    let from_a = least_overlap(a, b);
    // Along b's normals a lies beyond: the direction from a to b is -u.
    let from_b = least_overlap(b, a).map(|(o, u)| (o, [-u[0], -u[1]]));
    let best = match (from_a, from_b) {
        (Some(x), Some(y)) => {
            if y.0 < x.0 {
                y
            } else {
                x
            }
        }
        (x, y) => x.or(y)?,
    };
    Some(best.1)
}

/// Over the edges of `p`: the least overlap of `p` and `q` along an outward unit normal
/// of `p` (negative: a gap), with that normal.
fn least_overlap(p: &[Point], q: &[Point]) -> Option<(f64, [f64; 2])> {
    let (n, m) = (p.len(), q.len());
    let dot = |u: [f64; 2], v: Point| u[0] * v.x + u[1] * v.y;
    let mut best: Option<(f64, [f64; 2])> = None;
    let mut j = usize::MAX;
    let mut steps = 0usize;
    for i in 0..n {
        let (s, e) = (p[i], p[(i + 1) % n]);
        let (dx, dy) = (e.x - s.x, e.y - s.y);
        let len = dx.hypot(dy);
        if len == 0.0 || !len.is_finite() {
            continue;
        }
        // Counter-clockwise boundary: the outward normal is the edge turned clockwise.
        let u = [dy / len, -dx / len];
        if j == usize::MAX {
            j = (0..m)
                .min_by(|&x, &y| dot(u, q[x]).total_cmp(&dot(u, q[y])))
                .expect("q has vertices");
        } else {
            // The minimising vertex of q moves counter-clockwise as u turns; the step
            // budget keeps rounding noise from looping.
            while steps < 2 * (n + m) && dot(u, q[(j + 1) % m]) < dot(u, q[j]) {
                j = (j + 1) % m;
                steps += 1;
            }
        }
        let overlap = dot(u, s) - dot(u, q[j]);
        if best.is_none_or(|(o, _)| overlap < o) {
            best = Some((overlap, u));
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generate::{Density, ellipse_polygon};
    use rand::SeedableRng;
    use rand::rngs::SmallRng;

    /// The least overlap over every edge normal of both polygons, by brute force.
    fn brute(a: &[Point], b: &[Point]) -> f64 {
        let mut best = f64::INFINITY;
        for (p, q) in [(a, b), (b, a)] {
            for i in 0..p.len() {
                let (s, e) = (p[i], p[(i + 1) % p.len()]);
                let len = (e.x - s.x).hypot(e.y - s.y);
                let u = [(e.y - s.y) / len, -(e.x - s.x) / len];
                best = best.min(overlap_along(p, q, u));
            }
        }
        best
    }

    /// max over p of u·x minus min over q of u·x.
    fn overlap_along(p: &[Point], q: &[Point], u: [f64; 2]) -> f64 {
        let d = |v: &Point| u[0] * v.x + u[1] * v.y;
        let hi = p.iter().map(d).fold(f64::NEG_INFINITY, f64::max);
        let lo = q.iter().map(d).fold(f64::INFINITY, f64::min);
        hi - lo
    }

    #[test]
    fn squares_give_the_axis_of_least_overlap_from_a_to_b() {
        let sq = |x: f64, y: f64| {
            [(x, y), (x + 2.0, y), (x + 2.0, y + 2.0), (x, y + 2.0)].map(|(x, y)| Point::new(x, y))
        };
        assert_eq!(contact_normal(&sq(0.0, 0.0), &sq(1.5, 0.5)), Some([1.0, 0.0]));
        assert_eq!(contact_normal(&sq(0.0, 0.0), &sq(-1.5, 0.5)), Some([-1.0, 0.0]));
        assert_eq!(contact_normal(&sq(0.0, 0.0), &sq(0.2, 1.8)), Some([0.0, 1.0]));
        assert_eq!(contact_normal(&sq(0.0, 0.0), &sq(0.2, -1.8)), Some([0.0, -1.0]));
        // Disjoint: the axis of the largest gap, still from a to b.
        assert_eq!(contact_normal(&sq(0.0, 0.0), &sq(5.0, 0.5)), Some([1.0, 0.0]));
    }

    #[test]
    fn degenerate_input_gives_none() {
        let tri = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]].map(Point::from);
        assert_eq!(contact_normal(&tri[..2], &tri), None);
        assert_eq!(contact_normal(&tri, &[]), None);
    }

    /// The two-pointer walk finds the same least overlap as trying every normal against
    /// every vertex, on random ellipse polygons at every relative position, and the
    /// normal it returns achieves it and points from a to b.
    #[test]
    fn walk_matches_brute_force_on_random_polygons() {
        let mut rng = SmallRng::seed_from_u64(0xc0_47ac7);
        for case in 0..600 {
            let n = [3, 4, 7, 16, 64, 300][case % 6];
            let m = [3, 5, 9, 33, 128][case % 5];
            let a = ellipse_polygon(&mut rng, n, &Density::Uniform, true).into_vertices();
            let b = ellipse_polygon(&mut rng, m, &Density::Uniform, true).into_vertices();
            let got = contact_normal(&a, &b).expect("valid polygons");
            let want = brute(&a, &b);
            let achieved = overlap_along(&a, &b, got);
            assert!(
                (achieved - want).abs() <= 1e-9,
                "case {case}: normal {got:?} overlaps {achieved}, least overlap {want}"
            );
            assert!((got[0].hypot(got[1]) - 1.0).abs() < 1e-12, "unit length");
        }
    }
}
