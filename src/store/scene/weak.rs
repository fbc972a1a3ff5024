//! Poses of shapes with a few flat turns: the shape-wide margin proof
//! ([`proves_convex`](super::pose::proves_convex)) for all turns but the weakest few,
//! each of those checked on its own, so that such a pose stays O(log n + k).
//!
//! # Why it proves strict convexity
//! Move every vertex of the exact image W straight to its rounding W′, each coordinate
//! by at most δ. A *strong* turn (margin at least the strong margin, proved against δ)
//! stays strictly left all along the motion, so its exterior angle stays in (0, π). For
//! a *weak* turn at vertex b between edges u = b − a and v = c − b, require of the shape
//! that u · v > 0 (exterior angle below π/2, exactly) and of the image that both edges
//! be longer than 4δ: an edge moves by at most 2√2·δ (2δ per coordinate), less than
//! its length over √2, so its direction turns by less than π/4 all along the motion and
//! the exterior angle, starting in (0, π/2), stays in (−π/2, π); neither edge vanishes.
//! Every exterior angle thus stays in (−π, π) and varies continuously, so the
//! total turning, a multiple of 2π, stays the shape's 2π. At the end every strong turn
//! is strictly left and every weak one is checked strictly left exactly (the orientation
//! of its three rounded vertices): all turns strictly left with total turning 2π is a
//! strictly convex polygon winding once.
//!
//! # Complexity
//! The weak turns are found once per shape (O(n), with its array and margin); a pose
//! checks each in O(1) (three `Pose::apply`, one exact orientation).
//!
//! # Precision
//! The edge bound is a lower bound on the image edge's ∞-norm (≤ its length) with every
//! rounding of its computation widened; the dot product's sign and the orientations are
//! the exact kernel's.

use super::pose::RoundingBound;
use crate::kernel::{BoundingBox, Exact, Kernel, Orientation, Point, Pose, Sign};
use crate::polygon::turn_margin;

/// At most this many turns are checked one by one at each pose.
const MAX_WEAK: usize = 8;

/// Shapes with fewer vertices use the shape-wide margin alone (their poses are O(n)
/// with a small constant anyway).
const MIN_VERTICES: usize = 32;

const U: f64 = f64::EPSILON / 2.0;

/// A turn too flat for the strong margin: the array index of its vertex and a lower
/// bound on the ∞-norm of both its edges in the shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(in crate::store) struct WeakTurn {
    at: usize,
    edge: f64,
}

/// The weakest turns of a shape and the least margin of the others.
#[derive(Clone, Debug, Default, PartialEq)]
pub(in crate::store) struct WeakTurns {
    /// The least margin of the turns not in `turns` (0: nothing to prove with).
    strong: f64,
    turns: Vec<WeakTurn>,
}

impl WeakTurns {
    /// The `MAX_WEAK` weakest turns of the strictly convex counter-clockwise `array`,
    /// when each qualifies (exterior angle below π/2, edges of positive length); else
    /// none (the shape-wide margin alone decides). O(n).
    pub(in crate::store) fn of(array: &[Point]) -> WeakTurns {
        let n = array.len();
        if n < MIN_VERTICES {
            return WeakTurns::default();
        }
        let at = |i: usize| array[i % n];
        let mut margins: Vec<(f64, usize)> = (0..n)
            .map(|i| (turn_margin(at(i + n - 1), at(i), at(i + 1)), i))
            .collect();
        margins.select_nth_unstable_by(MAX_WEAK, |a, b| a.0.total_cmp(&b.0));
        let strong = margins[MAX_WEAK..].iter().fold(f64::INFINITY, |m, t| m.min(t.0));
        let mut turns = Vec::with_capacity(MAX_WEAK);
        for &(_, i) in &margins[..MAX_WEAK] {
            let (a, b, c) = (at(i + n - 1), at(i), at(i + 1));
            if Exact.dot(a, b, b, c) != Sign::Positive {
                return WeakTurns::default();
            }
            let norm = |p: Point, q: Point| (q.x - p.x).abs().max((q.y - p.y).abs());
            // Each difference rounds once (relative error U, or an absolute 2^-1075
            // below the normal range): widened by 4U and the least subnormal.
            let edge = norm(a, b).min(norm(b, c)) * (1.0 - 4.0 * U) - f64::from_bits(1);
            if edge.is_nan() || edge <= 0.0 {
                return WeakTurns::default();
            }
            turns.push(WeakTurn { at: i, edge });
        }
        WeakTurns {
            strong: if strong.is_finite() { strong } else { 0.0 },
            turns,
        }
    }

    /// Whether the rounded image of `array` (the shape these turns are of) under `pose`,
    /// lying in `world`, is strictly convex by the module docs' argument.
    pub(in crate::store) fn prove(&self, array: &[Point], pose: &Pose, world: &BoundingBox) -> bool {
        if self.turns.is_empty() || self.strong <= 0.0 {
            return false;
        }
        let Some(bound) = super::pose::rounding_bound(pose, world) else {
            return false;
        };
        if !bound.proves(self.strong) {
            return false;
        }
        let n = array.len();
        self.turns
            .iter()
            .all(|t| long_enough(t.edge, &bound) && turns_left(array, n, t.at, pose))
    }
}

/// Whether an image edge of a shape edge with ∞-norm at least `edge` is longer than 4δ:
/// its length is at least ρ·edge.
fn long_enough(edge: f64, bound: &RoundingBound) -> bool {
    let rho_low = bound.rho2_low.sqrt() * (1.0 - 4.0 * U);
    edge * rho_low * (1.0 - 8.0 * U) > 4.0 * bound.delta * (1.0 + 8.0 * U)
}

/// Whether the rounded images of the vertices before, at and after `at` turn strictly
/// left (exactly).
fn turns_left(array: &[Point], n: usize, at: usize, pose: &Pose) -> bool {
    let image = |i: usize| pose.apply(array[i % n]);
    match (image(at + n - 1), image(at), image(at + 1)) {
        (Some(a), Some(b), Some(c)) => Exact.orient(a, b, c) == Orientation::Ccw,
        _ => false,
    }
}
