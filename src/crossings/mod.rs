//! Crossing points of two simple polygons: every point where the boundaries of P
//! and Q meet.
//!
//! # Output
//! The distinct points where an edge of P meets an edge of Q, sorted
//! lexicographically (x, then y) and deduplicated exactly (no epsilon):
//! * a **proper crossing** (the edges' interiors cross at one point): the point is
//!   constructed in `f64` by [`crossing_point`], within the bound documented there;
//! * a **touching** (a vertex on a vertex, or a vertex on the other polygon's edge):
//!   the input vertex itself, bit for bit;
//! * a **collinear overlap** (two edges share a part of positive length): its two
//!   endpoints, each an input vertex, bit for bit.
//!
//! A negative zero coordinate is reported as `0.0`, so equal points print equally.
//! Polygons are cleaned on construction ([`SimplePolygon`] has no straight vertex),
//! so every maximal shared stretch of the two boundaries is the overlap of exactly
//! one pair of edges and is reported by its two endpoints only.
//!
//! # Algorithms
//! | algorithm | time | notes |
//! |---|---|---|
//! | [`Sweep`] | O(k log k + Σ r), worst case O(n·m) | Žalik's sweep with two lists of pierced edges; k = n + m vertices, r = length of the other polygon's list at each insertion |
//! | [`Brute`] | O(n·m) | every edge pair; the reference |
//!
//! Both test each candidate pair of edges with the same function (a bounding-box
//! rejection, then [`segment_contact`] with the caller's kernel), so under the
//! [`Exact`] kernel they report the same points bit for bit; the test suite checks
//! that on random and degenerate inputs. Under [`Fast`] a near-degenerate pair may be
//! misclassified (a touching missed or a near miss reported), and the two algorithms
//! may then differ by such points.

pub mod brute;
pub mod sweep;

pub use brute::Brute;
pub use sweep::{Sweep, SweepWorkspace};

use crate::kernel::{
    Exact, Fast, Kernel, Point, Precision, SegmentContact, point_on_segment, segment_contact,
};
use crate::polygon::SimplePolygon;
use std::fmt;
use std::str::FromStr;

/// A crossings algorithm on two simple polygons.
pub trait Crossings {
    /// The name used by the CLI's `--algorithm` and by benches.
    const NAME: &'static str;

    /// The points where the boundaries of `p` and `q` meet (see the [module docs](self)),
    /// deciding predicates with `kernel`.
    fn crossings_with<K: Kernel>(&self, kernel: K, p: &SimplePolygon, q: &SimplePolygon) -> Vec<Point>;

    /// The same with the exact kernel.
    ///
    /// ```
    /// use polysect::crossings::{Crossings, Sweep};
    /// use polysect::{Point, SimplePolygon};
    /// let p = SimplePolygon::new([[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]])?;
    /// // A triangle crossing P's right edge, with a vertex on P's top edge.
    /// let q = SimplePolygon::new([[3.0, 1.0], [6.0, 1.0], [2.0, 4.0]])?;
    /// assert_eq!(
    ///     Sweep.crossings(&p, &q),
    ///     vec![Point::new(2.0, 4.0), Point::new(4.0, 1.0), Point::new(4.0, 2.5)]
    /// );
    /// # Ok::<(), polysect::SimplePolygonError>(())
    /// ```
    fn crossings(&self, p: &SimplePolygon, q: &SimplePolygon) -> Vec<Point> {
        self.crossings_with(Exact, p, q)
    }
}

/// Every crossings algorithm, by name: what the CLI, the tests and the benches iterate over.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum CrossingAlgorithm {
    /// [`Sweep`] (the default).
    #[default]
    Sweep,
    /// [`Brute`].
    Brute,
}

impl CrossingAlgorithm {
    /// Every algorithm, in the order tables list them.
    pub const ALL: &'static [CrossingAlgorithm] = &[CrossingAlgorithm::Sweep, CrossingAlgorithm::Brute];

    pub fn name(self) -> &'static str {
        match self {
            CrossingAlgorithm::Sweep => Sweep::NAME,
            CrossingAlgorithm::Brute => Brute::NAME,
        }
    }

    /// Runs the algorithm with the kernel named by `precision`.
    pub fn run(self, precision: Precision, p: &SimplePolygon, q: &SimplePolygon) -> Vec<Point> {
        match precision {
            Precision::Fast => self.run_with(Fast, p, q),
            Precision::Exact => self.run_with(Exact, p, q),
        }
    }

    /// Runs the algorithm with a kernel chosen at compile time.
    pub fn run_with<K: Kernel>(self, k: K, p: &SimplePolygon, q: &SimplePolygon) -> Vec<Point> {
        match self {
            CrossingAlgorithm::Sweep => Sweep.crossings_with(k, p, q),
            CrossingAlgorithm::Brute => Brute.crossings_with(k, p, q),
        }
    }
}

impl fmt::Display for CrossingAlgorithm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for CrossingAlgorithm {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        CrossingAlgorithm::ALL
            .iter()
            .copied()
            .find(|a| a.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = CrossingAlgorithm::ALL.iter().map(|a| a.name()).collect();
                format!("unknown algorithm '{s}' (valid: {})", names.join(", "))
            })
    }
}

/// Appends the points where edge p1p2 of P and edge q1q2 of Q meet: nothing, one
/// constructed crossing, one input vertex (a touching) or two input vertices (the
/// ends of a collinear overlap). Both algorithms call this with P's edge first and
/// each edge in its polygon's direction, so they construct identical values.
#[inline]
pub(crate) fn edge_pair_points<K: Kernel>(
    k: K,
    p1: Point,
    p2: Point,
    q1: Point,
    q2: Point,
    out: &mut Vec<Point>,
) {
    // Exact rejection on input coordinates: disjoint bounding boxes cannot meet.
    if p1.x.max(p2.x) < q1.x.min(q2.x)
        || q1.x.max(q2.x) < p1.x.min(p2.x)
        || p1.y.max(p2.y) < q1.y.min(q2.y)
        || q1.y.max(q2.y) < p1.y.min(p2.y)
    {
        return;
    }
    match segment_contact(k, p1, p2, q1, q2) {
        SegmentContact::Disjoint => {}
        SegmentContact::Crossing => out.push(positive_zero(crossing_point(p1, p2, q1, q2))),
        SegmentContact::Touching => {
            // The single common point is an endpoint of one of the segments.
            if let Some(c) = [q1, q2]
                .into_iter()
                .find(|&c| point_on_segment(k, p1, p2, c))
                .or_else(|| [p1, p2].into_iter().find(|&c| point_on_segment(k, q1, q2, c)))
            {
                out.push(positive_zero(c));
            }
        }
        SegmentContact::Overlapping => {
            // Along a line lexicographic order is the order of the points on it.
            let (pa, pb) = lex_sorted(p1, p2);
            let (qa, qb) = lex_sorted(q1, q2);
            let lo = if pa.lex_cmp(qa).is_ge() { pa } else { qa };
            let hi = if pb.lex_cmp(qb).is_le() { pb } else { qb };
            out.push(positive_zero(lo));
            out.push(positive_zero(hi));
        }
    }
}

#[inline]
fn lex_sorted(a: Point, b: Point) -> (Point, Point) {
    if a.lex_cmp(b).is_le() { (a, b) } else { (b, a) }
}

/// `-0.0` becomes `0.0`; every other value is unchanged.
#[inline]
fn positive_zero(p: Point) -> Point {
    Point::new(p.x + 0.0, p.y + 0.0)
}

/// Sorts lexicographically and removes exact repeats: the final step of both algorithms.
pub(crate) fn sort_dedup(points: &mut Vec<Point>) {
    points.sort_unstable_by(|a, b| a.lex_cmp(*b));
    points.dedup();
}

/// 2^k for k in the normal exponent range [-1022, 1023].
fn pow2(k: i32) -> f64 {
    debug_assert!((-1022..=1023).contains(&k));
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// Multiplies by 2^k for any k in [-2044, 2046], exactly unless the result leaves the
/// normal range.
fn scale(x: f64, k: i32) -> f64 {
    let half = k / 2;
    x * pow2(half) * pow2(k - half)
}

/// The crossing point of segments p1p2 and q1q2, constructed in `f64`. Meant for
/// segments whose interiors cross at one point ([`SegmentContact::Crossing`]); for
/// any other input it returns a point of the intersection of their bounding boxes.
///
/// # Method
/// The coordinates are scaled by a power of two so that the largest magnitude is
/// in [1/2, 1) (exact, so the 2^±1000 range neither overflows nor underflows), the
/// shorter segment a→b (by max-norm) is parameterised, with the other segment c→e:
/// t = ((c − a) × (e − c)) / ((b − a) × (e − c)), clamped to [0, 1], and
/// p = a + t (b − a). The result is clamped into the intersection of the two
/// segments' bounding boxes, which holds the true point, and scaled back.
///
/// # Precision
/// With u = 2^-53, ℓ₁ ≤ ℓ₂ the lengths of the segments, θ the angle between them
/// and κ = 1 / |sin θ| the condition number of the intersection, the distance from
/// the returned point to the true crossing is at most
///
/// ‖p̃ − p‖ ≤ u · (3κ · (3ℓ₁ + ℓ₂) + 3ℓ₁ + 2‖p‖∞) + O(u²)
///
/// (first-order analysis: each cross product is within γ₃ = 3u/(1 − 3u) of its
/// terms' magnitude, |c − a| ≤ |b − a| + |e − c|, the max-norm choice of the
/// shorter segment costs at most a factor √2, and two roundings in a + t(b − a)), plus,
/// only when coordinates of very different magnitudes meet in one pair, the loss
/// of the smaller ones to subnormal range after scaling (at most 2^-1074 relative
/// to the largest coordinate). For well-conditioned crossings this is a few ulps of
/// the segment lengths; for nearly parallel edges it grows like 1/θ, but the point
/// never leaves the bounding boxes of the two segments. The test suite checks the
/// bound exactly (with exact arithmetic on the inputs) on random and ill-conditioned
/// crossings. Touching points and overlap ends are never constructed: they are
/// input vertices, reported exactly.
pub fn crossing_point(p1: Point, p2: Point, q1: Point, q2: Point) -> Point {
    let m = [p1.x, p1.y, p2.x, p2.y, q1.x, q1.y, q2.x, q2.y]
        .into_iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    // Scale so that the largest magnitude is in [1/2, 1).
    let k = if m == 0.0 || !m.is_finite() {
        0
    } else {
        let e = ((m.to_bits() >> 52) & 0x7ff) as i32;
        let exp = if e == 0 {
            // Subnormal: the exponent of the leading bit.
            -1074 + (63 - m.to_bits().leading_zeros() as i32)
        } else {
            e - 1023
        };
        -(exp + 1)
    };
    let s = |p: Point| Point::new(scale(p.x, k), scale(p.y, k));
    let (a1, a2, b1, b2) = (s(p1), s(p2), s(q1), s(q2));
    let len = |a: Point, b: Point| (b.x - a.x).abs().max((b.y - a.y).abs());
    let ((a, b), (c, e)) = if len(a1, a2) <= len(b1, b2) {
        ((a1, a2), (b1, b2))
    } else {
        ((b1, b2), (a1, a2))
    };
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let (ex, ey) = (e.x - c.x, e.y - c.y);
    let (wx, wy) = (c.x - a.x, c.y - a.y);
    let den = dx * ey - dy * ex;
    let num = wx * ey - wy * ex;
    let mut t = num / den;
    if !t.is_finite() {
        t = 0.5;
    }
    let t = t.clamp(0.0, 1.0);
    let mut x = a.x + t * dx;
    let mut y = a.y + t * dy;
    // The true point lies in both bounding boxes.
    let lo_x = a1.x.min(a2.x).max(b1.x.min(b2.x));
    let hi_x = a1.x.max(a2.x).min(b1.x.max(b2.x));
    let lo_y = a1.y.min(a2.y).max(b1.y.min(b2.y));
    let hi_y = a1.y.max(a2.y).min(b1.y.max(b2.y));
    if lo_x <= hi_x {
        x = x.clamp(lo_x, hi_x);
    }
    if lo_y <= hi_y {
        y = y.clamp(lo_y, hi_y);
    }
    Point::new(scale(x, -k), scale(y, -k))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn names_round_trip() {
        for &a in CrossingAlgorithm::ALL {
            assert_eq!(a.name().parse::<CrossingAlgorithm>(), Ok(a));
            assert_eq!(a.to_string(), a.name());
        }
        assert!(
            "bentley"
                .parse::<CrossingAlgorithm>()
                .unwrap_err()
                .contains("sweep, brute")
        );
        assert_eq!(CrossingAlgorithm::default(), CrossingAlgorithm::Sweep);
    }

    #[test]
    fn crossing_point_is_exact_on_simple_cases_and_scales() {
        assert_eq!(
            crossing_point(p(0., 0.), p(2., 2.), p(0., 2.), p(2., 0.)),
            p(1., 1.)
        );
        assert_eq!(
            crossing_point(p(0., 0.), p(4., 0.), p(1., -1.), p(1., 3.)),
            p(1., 0.)
        );
        for e in [-1070, -1000, -500, 0, 500, 1000, 1020] {
            let s = 2f64.powi(e);
            let q = crossing_point(p(0., 0.), p(2. * s, 2. * s), p(0., 2. * s), p(2. * s, 0.));
            assert_eq!(q, p(s, s), "2^{e}");
        }
        // Near f64::MAX the differences would overflow without scaling.
        let m = f64::MAX / 2.0;
        let q = crossing_point(p(-m, -m), p(m, m), p(-m, m), p(m, -m));
        assert_eq!(q, p(0., 0.));
    }

    #[test]
    fn pair_points_cover_every_contact() {
        let mut out = Vec::new();
        edge_pair_points(Exact, p(0., 0.), p(4., 0.), p(1., 0.), p(1., 3.), &mut out);
        assert_eq!(out, vec![p(1., 0.)]);
        out.clear();
        edge_pair_points(Exact, p(0., 0.), p(4., 0.), p(6., 0.), p(2., 0.), &mut out);
        assert_eq!(out, vec![p(2., 0.), p(4., 0.)]);
        out.clear();
        edge_pair_points(Exact, p(1., -0.0), p(1., 3.), p(0., 0.), p(4., 0.), &mut out);
        assert_eq!(out.len(), 1);
        assert!(out[0].y.is_sign_positive());
        out.clear();
        edge_pair_points(Exact, p(0., 0.), p(1., 0.), p(0., 1.), p(1., 1.), &mut out);
        assert!(out.is_empty());
    }
}
