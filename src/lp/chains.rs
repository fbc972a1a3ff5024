//! [`separate_chains`]: the separating line of two convex chains by a walk along both,
//! instead of the randomized LP of [`separating_line`](super::separating_line).
//!
//! # Problem
//! A and B are each the vertices of a convex polygon in cyclic order (either
//! orientation), such as a contiguous run of a strictly convex polygon's vertices: its
//! hull is the run closed by the chord from its last vertex to its first, and the run
//! in walk order lists that hull's vertices in order. The question is the LP's: do
//! CH(A) and CH(B) intersect (closed sets), and if not, which line through a point of
//! A and a point of B has A on its closed right, B on its closed left, and the most
//! counter-clockwise direction — the same inner common tangent the LP returns (the
//! line is unique; on a collinear edge the tangent point may differ).
//!
//! # The walk
//! The state is a pair (i, j) and the directed line ℓ = aᵢ → bⱼ. A *move* replaces aᵢ by
//! any point of A strictly left of ℓ, or bⱼ by any point of B strictly right of ℓ. Both
//! kinds turn the direction bⱼ − aᵢ strictly clockwise, by less than π: for a′ left of
//! ℓ, (bⱼ − aᵢ) × (bⱼ − a′) = −(bⱼ − aᵢ) × (a′ − aᵢ) < 0, and likewise for B. The walk
//! alternates *phases*: with bⱼ fixed, move i until neither neighbour of aᵢ is strictly
//! left; then the same for j; it stops when a phase makes no move. A phase gallops: it
//! tries the point `stride` places on in its direction (the last one that moved),
//! doubles the stride after a move and halves it after a failed try, turns to the
//! other neighbour when a unit step fails, and ends when both neighbours failed
//! against one line.
//!
//! At the stop, aᵢ ≠ bⱼ and both neighbours of aᵢ are on ℓ's closed right: a convex
//! polygon lies in the cone of its two edges at any vertex, so all of A does; likewise
//! all of B on the closed left. So ℓ separates with closed sides, and the hulls meet iff
//! the parts of A and of B on ℓ (runs of collinear neighbours, two intervals of ℓ)
//! overlap, compared with `dot`, as the LP does. A separating line directed from A's
//! point to B's is the most counter-clockwise separator (the other inner tangent,
//! directed so, has A on its left), so the answer is the LP's.
//!
//! If the hulls are disjoint, every direction bⱼ − aᵢ lies in an open half-circle (the
//! directions from the origin to the Minkowski difference CH(B) − CH(A), which misses
//! the origin), so the clockwise turns add up to less than π. Hence a total turn of π
//! or more proves the hulls meet: after every phase that moved, `cross(a₀, b₀, aᵢ, bⱼ)`
//! (start pair against the current one) not clockwise means the turn is in [π, 2π]
//! modulo 2π; a phase with bⱼ fixed that makes |A| moves visited |A| + 1 points at
//! strictly decreasing angles seen from bⱼ, impossible unless bⱼ ∈ CH(A) (likewise for
//! B). Both answer *intersecting*.
//!
//! # Complexity
//! One `orient` per try (against a line built from two points), one `cross` per phase
//! that moved, and for the verdict four `orient` and (only on collinear neighbours) up
//! to four `dot`; no allocation, and the points the walk does not reach are never
//! read: a stop certifies the whole sets by convexity. Galloping makes a phase
//! O(log d) tries for an index d places from its tangent point; from a start near the
//! answer (the caller's previous tangent points) a few phases do: on CLM's chains a
//! call costs a fraction of the same walk by unit steps and of the LP
//! (docs/results.md). The moves are capped
//! at 2(|A| + |B|) + 8: beyond
//! that (or under a kernel that is not exact, when the final full check fails) the
//! answer is `None` and the caller runs the LP, so the worst case stays linear plus
//! the LP's.
//!
//! # Degeneracies
//! Sets of one or two points, a shared point (aᵢ = bⱼ: every `orient` is zero, so the
//! walk stops there and the verdict is *intersecting*), touching hulls, collinear
//! edges on the separator and separators in any direction follow the same path; the
//! tests (tests/geometry/lp_chains.rs) compare with the LP and an exact brute force on random,
//! touching, one-ulp-gap, collinear and extreme-scale inputs.
//!
//! # Precision
//! Every decision is a kernel predicate on input points (`orient`, `cross`, `dot`):
//! exact under [`Exact`](crate::Exact), and then the answer equals the LP's. The
//! argument above uses the consistency of exact signs (the local-to-global step, the
//! turn count); under a kernel that is not
//! [`EXACT`](crate::Kernel::EXACT) a separation is returned only after every point has
//! been checked against the line, and *intersecting* never: `None` sends the caller to
//! the LP, which handles such kernels.

use super::{Bitangent, Separation};
use crate::kernel::{DirectedLine, Kernel, Orientation, Point, Sign};

/// The separation of the convex chains `a` and `b` (module docs), or `None` when the
/// walk gives no answer (move cap reached, an empty set, or a kernel that is not exact
/// failing the final check or finding the hulls intersecting): then the caller runs the
/// LP. The walk starts at `start = [i, j]` (indices into `a` and `b`; taken modulo the
/// lengths), ideally tangent points of a nearby separator. `work` is incremented by the
/// number of predicates evaluated.
///
/// ```
/// use polysect::Exact;
/// use polysect::kernel::Point;
/// use polysect::lp::{Separation, separate_chains};
/// let a = [Point::new(0.0, 0.0), Point::new(1.0, 1.0), Point::new(0.0, 2.0)];
/// let b = [Point::new(3.0, 0.0), Point::new(3.0, 2.0), Point::new(2.0, 1.0)];
/// let mut work = 0;
/// let Some(Separation::Separated(t)) = separate_chains(Exact, &a, &b, [0, 0], &mut work) else {
///     panic!("disjoint triangles")
/// };
/// // The inner common tangent with `a` on its closed right and `b` on its closed left:
/// // from (0, 2) to (3, 0), the line the LP returns.
/// assert_eq!((t.start, t.end), (a[2], b[0]));
/// let mut ws = polysect::lp::LpWorkspace::default();
/// let mut rng = <rand::rngs::SmallRng as rand::SeedableRng>::seed_from_u64(1);
/// let lp = polysect::lp::separating_line(Exact, &a[..], &b[..], &mut rng, &mut ws).unwrap();
/// let Separation::Separated(u) = lp else { panic!("disjoint triangles") };
/// assert_eq!((u.start, u.end), (t.start, t.end));
/// ```
pub fn separate_chains<K: Kernel>(
    k: K,
    a: &[Point],
    b: &[Point],
    start: [usize; 2],
    work: &mut u64,
) -> Option<Separation> {
    if a.is_empty() || b.is_empty() {
        return None;
    }
    let mut w = Walker {
        k,
        a,
        b,
        i: start[0] % a.len(),
        j: start[1] % b.len(),
        forward: [true, true],
        budget: 2 * (a.len() + b.len()) + 8,
        work: 0,
    };
    let answer = w.run();
    *work += w.work;
    answer
}

/// What one phase of the walk did.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Phase {
    /// No move: the index's two neighbours are on its set's closed side.
    Still,
    /// At least one move, and now no neighbour is strictly on the wrong side.
    Moved,
    /// Went once around its set: a turn of 2π, the hulls meet.
    Around,
    /// The move cap was reached.
    Exhausted,
}

struct Walker<'a, K> {
    k: K,
    a: &'a [Point],
    b: &'a [Point],
    i: usize,
    j: usize,
    /// Per set, the direction of the next first try (the last one that moved).
    forward: [bool; 2],
    /// Moves left before the walk gives up.
    budget: usize,
    work: u64,
}

/// The index `stride` places from `i` in a cyclic sequence of `n` points
/// (`stride <= n`).
#[inline(always)]
fn step_by(n: usize, i: usize, forward: bool, stride: usize) -> usize {
    if forward {
        let c = i + stride;
        if c >= n { c - n } else { c }
    } else if i >= stride {
        i - stride
    } else {
        i + n - stride
    }
}

/// The neighbour of `i` in a cyclic sequence of `n` points.
#[inline(always)]
fn step(n: usize, i: usize, forward: bool) -> usize {
    step_by(n, i, forward, 1)
}

impl<K: Kernel> Walker<'_, K> {
    fn run(&mut self) -> Option<Separation> {
        let (a0, b0) = (self.a[self.i], self.b[self.j]);
        if a0 == b0 {
            return self.intersecting();
        }
        let mut first = true;
        loop {
            // A's phase, then B's: stop when a phase has nothing to move (the other
            // phase ended on the same line).
            for in_b in [false, true] {
                match self.phase(in_b) {
                    Phase::Still if !first || in_b => return self.verdict(),
                    Phase::Still => {}
                    Phase::Moved => {
                        self.work += 1;
                        if self.k.cross(a0, b0, self.a[self.i], self.b[self.j]) != Orientation::Cw {
                            // A total clockwise turn of π or more.
                            return self.intersecting();
                        }
                    }
                    Phase::Around => return self.intersecting(),
                    Phase::Exhausted => return None,
                }
                first = false;
            }
        }
    }

    /// Moves `i` (`in_b`: `j`) while a point of its set lies strictly on the wrong side
    /// of aᵢ → bⱼ (left for A, right for B), galloping: from the current index it tries
    /// the point `stride` places on in the current direction, doubling the stride after
    /// each move and halving it after each failure; when a unit step fails it turns to
    /// the other neighbour. It ends when both neighbours failed against one line.
    #[inline]
    fn phase(&mut self, in_b: bool) -> Phase {
        let (pts, wrong) = if in_b {
            (self.b, Orientation::Cw)
        } else {
            (self.a, Orientation::Ccw)
        };
        let n = pts.len();
        let side = usize::from(in_b);
        let (mut moves, mut stride, mut failed) = (0, 1, 0);
        loop {
            let line = DirectedLine::new(self.a[self.i], self.b[self.j]);
            let at = if in_b { self.j } else { self.i };
            let c = step_by(n, at, self.forward[side], stride);
            self.work += 1;
            if self.k.orient_line(&line, pts[c]) == wrong {
                if in_b {
                    self.j = c;
                } else {
                    self.i = c;
                }
                moves += 1;
                failed = 0;
                if moves >= n {
                    return Phase::Around;
                }
                if self.budget == 0 {
                    return Phase::Exhausted;
                }
                self.budget -= 1;
                stride = (stride * 2).min(n);
            } else if stride > 1 {
                stride /= 2;
            } else {
                failed += 1;
                if failed == 2 {
                    break;
                }
                self.forward[side] = !self.forward[side];
            }
        }
        if moves > 0 { Phase::Moved } else { Phase::Still }
    }

    /// The answer at a stop: ℓ = aᵢ → bⱼ separates with closed sides (module docs);
    /// the hulls meet iff the parts of A and B on ℓ overlap.
    fn verdict(&mut self) -> Option<Separation> {
        let (ai, bj) = (self.a[self.i], self.b[self.j]);
        if ai == bj {
            return self.intersecting();
        }
        let line = DirectedLine::new(ai, bj);
        let [a_back, a_fwd] = self.run_ends(self.a, self.i, &line);
        let [b_back, b_fwd] = self.run_ends(self.b, self.j, &line);
        // aᵢ lies before bⱼ along ℓ; the parts overlap iff some point of A on ℓ is not
        // before some point of B on ℓ. Without collinear neighbours nothing to test.
        for x in [self.i, a_back, a_fwd] {
            for y in [self.j, b_back, b_fwd] {
                if x == self.i && y == self.j {
                    continue;
                }
                self.work += 1;
                if self.k.dot(ai, bj, self.a[x], self.b[y]) != Sign::Positive {
                    return self.intersecting();
                }
            }
        }
        if !K::EXACT {
            // The walk's reasoning assumed consistent signs: check every point.
            self.work += (self.a.len() + self.b.len()) as u64;
            let a_ok = self
                .a
                .iter()
                .all(|&x| self.k.orient_line(&line, x) != Orientation::Ccw);
            let b_ok = self
                .b
                .iter()
                .all(|&y| self.k.orient_line(&line, y) != Orientation::Cw);
            if !(a_ok && b_ok) {
                return None;
            }
        }
        Some(Separation::Separated(Bitangent {
            start: ai,
            end: bj,
            a: self.i,
            b: self.j,
        }))
    }

    /// The last indices backwards and forwards from `at` whose points lie on `line`
    /// (`at` itself when its neighbour is off it), not going around.
    fn run_ends(&mut self, pts: &[Point], at: usize, line: &DirectedLine) -> [usize; 2] {
        let n = pts.len();
        [false, true].map(|forward| {
            let mut end = at;
            for _ in 1..n {
                let c = step(n, end, forward);
                self.work += 1;
                if self.k.orient_line(line, pts[c]) != Orientation::Collinear {
                    break;
                }
                end = c;
            }
            end
        })
    }

    /// Intersecting hulls: certain under an exact kernel; otherwise left to the LP.
    fn intersecting(&self) -> Option<Separation> {
        K::EXACT.then_some(Separation::Intersecting)
    }
}
