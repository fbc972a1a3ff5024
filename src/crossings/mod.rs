//! Crossing points of two simple polygons: every point where the boundaries of P
//! and Q meet.
//!
//! # Output
//! The distinct points where an edge of P meets an edge of Q, sorted
//! lexicographically (x, then y) and deduplicated exactly (no epsilon):
//! * a **proper crossing** (the edges' interiors cross at one point): the exact
//!   crossing with each coordinate rounded to the nearest `f64` ([`crossing_point`]);
//! * a **touching** (a vertex on a vertex, or a vertex on the other polygon's edge):
//!   the input vertex itself, bit for bit;
//! * a **collinear overlap** (two edges share a part of positive length): its two
//!   endpoints, each an input vertex, bit for bit.
//!
//! A negative zero coordinate is reported as `0.0`, so equal points print equally.
//! Polygons are cleaned on construction ([`SimplePolygon`] has no straight vertex),
//! so every maximal shared stretch of the two boundaries is the overlap of exactly
//! one pair of edges and is reported by its two endpoints only.
//! [`Touching::Exclude`] keeps only the proper crossings and the overlap ends: a pair
//! of edges whose single common point is an endpoint of one of them contributes
//! nothing (docs/crossings.md has the decision).
//!
//! # Algorithms
//! n and m are the polygons' sizes, k = n + m, c the number of reported points.
//!
//! | algorithm | time | notes |
//! |---|---|---|
//! | [`Sweep`] | O((k + c) log k) on every input | runs [`ListSweep`] when its counted work fits a budget of O(k log k), [`TreeSweep`] otherwise |
//! | [`ListSweep`] | O(k log k + W), W ≤ 2nm | Žalik's sweep with two unordered lists of pierced edges; W = Σ r, r the other list's length at each insertion |
//! | [`TreeSweep`] | O((k + c) log k) expected | red–blue sweep over the vertices, one treap of both polygons' pierced edges repaired lazily with exact orientation tests |
//! | [`Brute`] | O(n·m) | every edge pair; the reference |
//!
//! All test each candidate pair of edges with the same function (a bounding-box
//! rejection, then [`segment_contact`] with the caller's kernel) and construct
//! crossings with the same correctly rounded function, so under the [`Exact`] kernel
//! they report the same points bit for bit; the test suite and the fuzz harness check
//! that on random, degenerate and adversarial inputs. Under [`Fast`] a
//! near-degenerate pair may be misclassified (a touching missed or a near miss
//! reported), and the algorithms may then differ by such points ([`TreeSweep`]
//! orders its status with exact predicates whatever the kernel, so its cost bound
//! holds for both).

mod brute;
mod events;
mod lists;
mod point;
mod status;
mod sweep;
mod tree;

pub use brute::Brute;
#[cfg(feature = "instrument")]
pub use lists::ListWork;
#[cfg(feature = "cli")]
pub(crate) use lists::every_candidate;
pub use lists::{ListSweep, ListWorkspace};
pub use point::crossing_point;
pub use sweep::{Sweep, SweepWorkspace};
pub use tree::TreeSweep;

use crate::kernel::{
    Exact, Fast, Kernel, Point, Precision, SegmentContact, point_on_segment, segment_contact,
};
use crate::polygon::SimplePolygon;
use std::fmt;
use std::str::FromStr;

/// Which contacts are reported.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Touching {
    /// Every point where the boundaries meet (the default).
    #[default]
    Include,
    /// Only proper crossings and the ends of collinear overlaps: a pair of edges whose only common point is an endpoint of one of
    /// them contributes nothing (see the [module docs](self)).
    Exclude,
}

impl Touching {
    /// Both modes, in the order the CLI lists them.
    /// Both modes, in the order the CLI lists them.
    pub const ALL: [Touching; 2] = [Touching::Include, Touching::Exclude];

    /// The name used by the CLI's `--touching`.
    pub fn name(self) -> &'static str {
        match self {
            Touching::Include => "include",
            Touching::Exclude => "exclude",
        }
    }
}

impl fmt::Display for Touching {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Touching {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Touching::ALL
            .into_iter()
            .find(|t| t.name() == s)
            .ok_or_else(|| format!("unknown touching mode '{s}' (valid: include, exclude)"))
    }
}

/// What a crossings query reports; `CrossingOptions::default()` is every contact.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct CrossingOptions {
    /// Whether contacts that touch without crossing are reported.
    pub touching: Touching,
}

/// A crossings algorithm on two simple polygons.
pub trait Crossings {
    /// The name used by the CLI's `--algorithm` and by benches.
    const NAME: &'static str;

    /// The points where the boundaries of `p` and `q` meet (see the [module docs](self)),
    /// as selected by `options`, deciding predicates with `kernel`.
    fn crossings_with_options<K: Kernel>(
        &self,
        kernel: K,
        p: &SimplePolygon,
        q: &SimplePolygon,
        options: CrossingOptions,
    ) -> Vec<Point>;

    /// Every point where the boundaries meet, deciding predicates with `kernel`.
    fn crossings_with<K: Kernel>(&self, kernel: K, p: &SimplePolygon, q: &SimplePolygon) -> Vec<Point> {
        self.crossings_with_options(kernel, p, q, CrossingOptions::default())
    }

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

    /// The name used by the CLI's `--algorithm` and by benches.
    pub fn name(self) -> &'static str {
        match self {
            CrossingAlgorithm::Sweep => Sweep::NAME,
            CrossingAlgorithm::Brute => Brute::NAME,
        }
    }

    /// Runs the algorithm with the kernel named by `precision`.
    pub fn run(self, precision: Precision, p: &SimplePolygon, q: &SimplePolygon) -> Vec<Point> {
        self.run_with_options(precision, p, q, CrossingOptions::default())
    }

    /// Runs the algorithm with the kernel named by `precision` and `options`.
    pub fn run_with_options(
        self,
        precision: Precision,
        p: &SimplePolygon,
        q: &SimplePolygon,
        options: CrossingOptions,
    ) -> Vec<Point> {
        match precision {
            Precision::Fast => self.run_with(Fast, p, q, options),
            Precision::Exact => self.run_with(Exact, p, q, options),
        }
    }

    /// Runs the algorithm with a kernel chosen at compile time.
    pub fn run_with<K: Kernel>(
        self,
        k: K,
        p: &SimplePolygon,
        q: &SimplePolygon,
        options: CrossingOptions,
    ) -> Vec<Point> {
        match self {
            CrossingAlgorithm::Sweep => Sweep.crossings_with_options(k, p, q, options),
            CrossingAlgorithm::Brute => Brute.crossings_with_options(k, p, q, options),
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
    options: CrossingOptions,
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
        SegmentContact::Crossing => out.push(point::proper_crossing(p1, p2, q1, q2)),
        SegmentContact::Touching if options.touching == Touching::Exclude => {}
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

/// Sorts lexicographically and removes exact repeats: the final step of every algorithm.
/// The points are finite with no `-0.0`, so the order of their keys ([`lex_key`]) is
/// the lexicographic order and equal keys are equal points.
pub(crate) fn sort_dedup(points: &mut Vec<Point>) {
    points.sort_unstable_by_key(|&p| lex_key(p));
    points.dedup();
}

/// An integer whose order is the lexicographic order of finite points (x, then y):
/// each coordinate's bits mapped so that unsigned order is numeric order (`-0.0`
/// before `0.0`).
#[inline]
pub(crate) fn lex_key(p: Point) -> u128 {
    let key = |v: f64| {
        let b = v.to_bits();
        if b >> 63 == 1 { !b } else { b | 1 << 63 }
    };
    (key(p.x) as u128) << 64 | key(p.y) as u128
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

    const D: CrossingOptions = CrossingOptions {
        touching: Touching::Include,
    };

    #[test]
    fn pair_points_cover_every_contact() {
        let mut out = Vec::new();
        edge_pair_points(Exact, p(0., 0.), p(4., 0.), p(1., 0.), p(1., 3.), D, &mut out);
        assert_eq!(out, vec![p(1., 0.)]);
        out.clear();
        edge_pair_points(Exact, p(0., 0.), p(4., 0.), p(6., 0.), p(2., 0.), D, &mut out);
        assert_eq!(out, vec![p(2., 0.), p(4., 0.)]);
        out.clear();
        edge_pair_points(Exact, p(1., -0.0), p(1., 3.), p(0., 0.), p(4., 0.), D, &mut out);
        assert_eq!(out.len(), 1);
        assert!(out[0].y.is_sign_positive());
        out.clear();
        edge_pair_points(Exact, p(0., 0.), p(1., 0.), p(0., 1.), p(1., 1.), D, &mut out);
        assert!(out.is_empty());
    }
}
