//! [`Barba`]: the Barba–Langerman O(log n) test on sorted arrays (thesis 3.1).
//!
//! # The algorithm
//! The test keeps two shrinking pieces, `P' = CH(P[a..=b])` and `Q' = CH(Q[c..=d])`
//! (contiguous index ranges of the arrays, never copied), with the invariant
//! **P ∩ Q ≠ ∅ ⇔ P' ∩ Q' ≠ ∅**. Since P' ⊆ P and Q' ⊆ Q, only "no intersection is
//! lost" has to be shown at each pruning step. Each iteration looks at
//! * the triangle `T_P = (P[a], P[mid], P[b]) ⊆ P'`, and
//! * the edge hull `T_Q = H(e0) ∩ H(e1) ∩ H(e2) ⊇ Q'` of the first, middle and last
//!   edges of Q's chain (`H(e)` is the closed half-plane left of edge e); T_Q is a
//!   triangle or unbounded and is never constructed: only its three lines are used.
//!
//! `K = CH(e0, e1, e2) ⊆ Q'` is split off T_Q by three *chords* (end of `e_i` to
//! start of `e_{i+1}`, the last one being Q's closing chord `Q[d] → Q[c]`); the rest
//! of T_Q falls into three *pockets*, one beyond each chord. One iteration decides:
//!
//! 1. **Intersection invariant, a vertex of T_P in T_Q.** If it is strictly beyond
//!    a chord, it is a witness in that pocket; otherwise it lies in K ⊆ Q: answer yes.
//! 2. **Separation invariant, by an edge of T_Q.** All of T_P strictly right of the
//!    line of `e_j`: that line separates T_P from T_Q ⊇ Q'.
//! 3. A vertex of K in T_P: answer yes.
//! 4. **Boundary crossings.** For each edge of T_P whose endpoints are strictly on
//!    opposite sides of the line of `e_j`: if the edge meets the segment `e_j`,
//!    answer yes; otherwise the crossing point X lies before `e_j` or after it
//!    (one `cross`), and if X is inside the other two half-planes (the degree-4
//!    predicate [`line_meet_side`]) X is a witness in the pocket before or after `e_j`.
//! 5. **Separation invariant, by an edge of T_P.** Without a witness T_P and T_Q
//!    are disjoint (a non-empty intersection shows up as a vertex of T_P in T_Q, a
//!    bounded T_Q inside T_P, or a transversal crossing of T_P's boundary with a
//!    line of T_Q), so some edge line of T_P has T_Q strictly on its outer side; it
//!    is the edge that has all of K strictly outside and whose line misses T_Q
//!    (an interval test along the line with [`line_meet_side`]).
//!
//! **Pruning P (separation).** A line ℓ separates T_P strictly from T_Q ⊇ Q', so
//! `P' ∩ Q' ⊆ P' ∩ ℓ⁺`. The part of P's boundary beyond ℓ avoids the three
//! triangle vertices, so it lies inside one of the two chains `P[a..=mid]`,
//! `P[mid..=b]` (the third side of T_P is P''s own closing chord). For an edge line
//! of T_P that chain is the one behind the edge; for a line of T_Q it is the chain
//! holding P''s farthest point towards ℓ strictly inside: the vertex where the edge
//! directions (which turn monotonically) pass the direction of ℓ reversed, found by
//! comparing that direction with the chain's first and last edge (a few `cross`
//! and `dot`). Testing only whether the chain *rises* at both ends, as a reading
//! of the sources suggests, is wrong: a chain can hold both the lowest and the
//! highest point, and then falls at one end. No such chain, or a chain without
//! interior vertices: the answer is no.
//!
//! **Pruning Q (intersection).** Given a witness y ∈ T_P ∩ T_Q strictly beyond
//! chord i, keep the chain of Q from the start of `e_i` to the end of `e_{i+1}`.
//! Proof: take x ∈ P' ∩ Q'. If x is on the pocket side of the chord it lies in the
//! hull of the kept chain. Otherwise the segment xy lies in P' and in T_Q and
//! crosses the chord's line; T_Q meets that line only in the chord itself (the
//! lines of `e_i` and `e_{i+1}` cut it at the chord's ends), whose ends are kept
//! vertices. For the pocket beyond Q's closing chord the same argument leaves only
//! the chord: Q' becomes the segment `[Q[d], Q[c]]`.
//!
//! **Constant-size finish.** Once Q' has at most six vertices (or is that segment)
//! the edge hull is replaced by Q' itself: a separating-axis test between T_P and
//! Q' either finds them intersecting (answer yes) or returns the separating edge,
//! which prunes P as above; when P' is a triangle the test is the answer.
//!
//! **Reuse between iterations** (thesis 3.1.10). A pruning step keeps two of T_P's
//! vertices or two of T_Q's edges, so six of the nine orientations of T_P's
//! vertices against T_Q's lines carry over to the next iteration (a 3×3 cache).
//!
//! # Complexity
//! O(log n + log m) time, O(1) memory, for polygons of n and m vertices, on every
//! input: every iteration halves P' or Q' (or ends the test) and costs O(1)
//! predicates (at most about 70 in the rarest branch, typically under 15).
//!
//! # Degeneracies
//! All tests are closed, so touching is intersecting: a T_P vertex on a line of
//! T_Q counts as inside, an edge of T_P touching `e_j` is an intersection, and the
//! "no chain rises towards ℓ" exit requires strict separation, so a neighbour
//! exactly on the separating line keeps its chain. Parallel lines among `e0, e1,
//! e2` are never intersected with each other; unbounded T_Q needs no special case.
//! T_P degenerates to a segment only when its chain has no interior vertex, and
//! that case is an exit (the chain's hull is an edge of T_P, which is separated).
//!
//! # Precision
//! Decided by `orient`, `cross` and the degree-4 [`line_meet_side`] on input
//! points: exact under [`Exact`](crate::Exact) (which puts a static filter with a
//! proven error bound in front of the degree-4 predicate). Under [`Fast`](crate::Fast) every
//! loop still shrinks a range, so the test terminates; an inconsistent answer in
//! step 5 (no separating edge found) falls back to [`Linear`](super::Linear) on the
//! remaining pieces.

use super::{ArrayIntersection, Linear, Probe};
use crate::kernel::{Kernel, Orientation, Point, Sign, line_meet_side, segments_intersect};
use crate::polygon::ConvexPolygon;

/// The Barba–Langerman O(log n) test; see the module docs.
///
/// ```
/// use polysect::{ConvexPolygon, intersect::{ArrayIntersection, Barba}};
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let touching = ConvexPolygon::new([[2.0, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// let apart = ConvexPolygon::new([[2.5, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// assert!(Barba.intersects(&p, &touching));
/// assert!(!Barba.intersects(&p, &apart));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct Barba;

impl ArrayIntersection for Barba {
    const NAME: &'static str = "barba";

    fn intersects_probed<K: Kernel, P: Probe>(
        &self,
        k: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> bool {
        run(k, p.vertices(), q.vertices(), probe)
    }
}

use Orientation::{Collinear, Cw};

/// `len ≥ 3` consecutive vertices of a polygon from array index `start`.
#[derive(Clone, Copy, Debug)]
struct Range {
    start: usize,
    len: usize,
}

impl Range {
    #[inline]
    fn at(self, v: &[Point], pos: usize) -> Point {
        let i = self.start + pos;
        v[if i >= v.len() { i - v.len() } else { i }]
    }
    #[inline]
    fn sub(self, v: &[Point], from: usize, to: usize) -> Range {
        let s = self.start + from;
        Range {
            start: if s >= v.len() { s - v.len() } else { s },
            len: to - from + 1,
        }
    }
    /// Position of T_P's middle vertex (and of the middle edge of a chain).
    #[inline]
    fn mid(self) -> usize {
        (self.len - 1) / 2
    }
}

/// Below this many vertices Q' is used as it is instead of through its edge hull.
const SMALL_Q: usize = 7;

/// What one iteration of the main loop decided.
enum Step {
    Meet,
    Apart,
    /// Keep chain 0 (`P[a..=mid]`) or 1 (`P[mid..=b]`).
    KeepP(usize),
    /// Keep the pocket beyond chord 0, 1 or 2.
    KeepQ(usize),
    /// Only an inconsistent kernel gets here.
    Stuck,
}

/// Orientations of T_P's vertices (rows) against T_Q's lines (columns), computed
/// lazily and carried over when a step keeps two rows or two columns.
struct SideCache([[Option<Orientation>; 3]; 3]);

impl SideCache {
    fn keep_rows(&mut self, chain: usize) {
        let old = self.0;
        // Chain 0 keeps vertices 0 and 1 as the new 0 and 2; chain 1 keeps 1 and 2.
        self.0 = [old[chain], [None; 3], old[chain + 1]];
    }
    fn keep_cols(&mut self, pocket: usize) {
        for row in &mut self.0 {
            let old = *row;
            *row = [old[pocket], None, old[pocket + 1]];
        }
    }
}

fn run<K: Kernel, P: Probe>(k: K, pv: &[Point], qv: &[Point], probe: &mut P) -> bool {
    let mut pr = Range {
        start: 0,
        len: pv.len(),
    };
    let mut qr = Range {
        start: 0,
        len: qv.len(),
    };
    let mut cache = SideCache([[None; 3]; 3]);
    loop {
        if qr.len < SMALL_Q {
            let mut qs = [Point::default(); SMALL_Q];
            for (i, slot) in qs.iter_mut().enumerate().take(qr.len) {
                *slot = qr.at(qv, i);
            }
            return against_small(k, pv, pr, &qs[..qr.len], probe);
        }
        probe.iteration();
        match step(k, pv, pr, qv, qr, &mut cache) {
            Step::Meet => return true,
            Step::Apart => return false,
            Step::KeepP(chain) => {
                let mid = pr.mid();
                pr = if chain == 0 {
                    pr.sub(pv, 0, mid)
                } else {
                    pr.sub(pv, mid, pr.len - 1)
                };
                cache.keep_rows(chain);
            }
            Step::KeepQ(2) => {
                let chord = [qr.at(qv, 0), qr.at(qv, qr.len - 1)];
                return against_small(k, pv, pr, &chord, probe);
            }
            Step::KeepQ(pocket) => {
                let m1 = (qr.len - 2) / 2;
                qr = if pocket == 0 {
                    qr.sub(qv, 0, m1 + 1)
                } else {
                    qr.sub(qv, m1, qr.len - 1)
                };
                cache.keep_cols(pocket);
            }
            Step::Stuck => return fallback(k, pv, pr, qv, qr),
        }
    }
}

/// One iteration of the main loop (steps 1–5 of the module docs).
fn step<K: Kernel>(k: K, pv: &[Point], pr: Range, qv: &[Point], qr: Range, cache: &mut SideCache) -> Step {
    let mid = pr.mid();
    let t = [pr.at(pv, 0), pr.at(pv, mid), pr.at(pv, pr.len - 1)];
    let m1 = (qr.len - 2) / 2;
    let lines = [
        (qr.at(qv, 0), qr.at(qv, 1)),
        (qr.at(qv, m1), qr.at(qv, m1 + 1)),
        (qr.at(qv, qr.len - 2), qr.at(qv, qr.len - 1)),
    ];
    let chords = [
        (lines[0].1, lines[1].0),
        (lines[1].1, lines[2].0),
        (lines[2].1, lines[0].0),
    ];
    let mut side =
        |i: usize, j: usize| *cache.0[i][j].get_or_insert_with(|| k.orient(lines[j].0, lines[j].1, t[i]));

    // 1. A vertex of T_P inside T_Q: a witness in a pocket, or a point of K ⊆ Q.
    for (i, &ti) in t.iter().enumerate() {
        if (0..3).all(|j| side(i, j) != Cw) {
            return match chords.iter().position(|c| k.orient(c.0, c.1, ti) == Cw) {
                Some(pocket) => Step::KeepQ(pocket),
                None => Step::Meet,
            };
        }
    }
    // 2. A line of T_Q with T_P strictly outside.
    for (j, &line) in lines.iter().enumerate() {
        if (0..3).all(|i| side(i, j) == Cw) {
            return prune_by_line(k, pv, pr, line);
        }
    }
    // 3. A vertex of K inside T_P.
    let kv = [
        lines[0].0, lines[0].1, lines[1].0, lines[1].1, lines[2].0, lines[2].1,
    ];
    if kv
        .iter()
        .any(|&x| (0..3).all(|i| k.orient(t[i], t[(i + 1) % 3], x) != Cw))
    {
        return Step::Meet;
    }
    // 4. Transversal crossings of T_P's edges with T_Q's lines.
    let sides: [[Orientation; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| side(i, j)));
    for a in 0..3 {
        let b = (a + 1) % 3;
        for j in 0..3 {
            let (sa, sb) = (sides[a][j], sides[b][j]);
            if sa == Collinear || sb != sa.reverse() {
                continue;
            }
            let (s, u) = lines[j];
            if segments_intersect(k, t[a], t[b], s, u) {
                return Step::Meet;
            }
            // The crossing X lies on the segment t[a]t[b]: when both ends are on the
            // same side of another line, so is X, without the degree-4 predicate.
            let inside = (0..3)
                .filter(|&l| l != j)
                .all(|l| match (sides[a][l], sides[b][l]) {
                    (Cw, Cw) => false,
                    (x, y) if x != Cw && y != Cw => true,
                    _ => line_meet_side(k, (t[a], t[b]), lines[j], lines[l]) != Cw,
                });
            if inside {
                let before_s = k.orient(t[a], t[b], s);
                let after = k.cross(t[a], t[b], s, u) == before_s.reverse();
                return Step::KeepQ(if after { j } else { (j + 2) % 3 });
            }
        }
    }
    // 5. T_P and T_Q are disjoint: find the edge of T_P whose line misses T_Q.
    for a in 0..3 {
        let b = (a + 1) % 3;
        if kv.iter().all(|&x| k.orient(t[a], t[b], x) == Cw) && line_misses_hull(k, (t[a], t[b]), &lines) {
            return if a == 2 { Step::Apart } else { keep_chain(pr, a) };
        }
    }
    Step::Stuck
}

/// Keeps chain `c` of P' when it has an interior vertex; otherwise P' ∩ Q' = ∅.
fn keep_chain(pr: Range, c: usize) -> Step {
    let mid = pr.mid();
    let interior = if c == 0 { mid >= 2 } else { pr.len - 1 - mid >= 2 };
    if interior { Step::KeepP(c) } else { Step::Apart }
}

/// T_P lies strictly right of the line s→u and Q' on or left of it: keep the chain
/// of P' that holds P''s farthest point towards the line strictly inside, if any.
///
/// The farthest point is where the edge directions pass the direction u→s (they
/// turn monotonically), so chain c holds it strictly inside iff u→s is turned
/// strictly beyond the chain's first edge and strictly before its last edge.
/// Otherwise the farthest point is a triangle vertex, strictly right of the line.
fn prune_by_line<K: Kernel>(k: K, pv: &[Point], pr: Range, (s, u): (Point, Point)) -> Step {
    let mid = pr.mid();
    let last = pr.len - 1;
    let at = |i: usize| pr.at(pv, i);
    let holds_peak = |from: usize, to: usize| {
        let (first, end) = ((at(from), at(from + 1)), (at(to - 1), at(to)));
        !same_direction(k, first, (u, s)) && turn_gt(k, first, end, (u, s))
    };
    if mid >= 2 && holds_peak(0, mid) {
        Step::KeepP(0)
    } else if last - mid >= 2 && holds_peak(mid, last) {
        Step::KeepP(1)
    } else {
        Step::Apart
    }
}

fn same_direction<K: Kernel>(k: K, a: (Point, Point), b: (Point, Point)) -> bool {
    k.cross(a.0, a.1, b.0, b.1) == Collinear && k.dot(a.0, a.1, b.0, b.1) == Sign::Positive
}

/// Whether direction `a` is turned further counter-clockwise from `base` than `c`,
/// with turns measured in [0, 2π).
fn turn_gt<K: Kernel>(k: K, base: (Point, Point), a: (Point, Point), c: (Point, Point)) -> bool {
    let class = |d: (Point, Point)| match k.cross(base.0, base.1, d.0, d.1) {
        Orientation::Ccw => 1,
        Orientation::Cw => 3,
        Orientation::Collinear => {
            if k.dot(base.0, base.1, d.0, d.1) == Sign::Positive {
                0
            } else {
                2
            }
        }
    };
    let (ca, cc) = (class(a), class(c));
    if ca != cc {
        ca > cc
    } else {
        (ca == 1 || ca == 3) && k.cross(c.0, c.1, a.0, a.1) == Orientation::Ccw
    }
}

/// Whether the line through `l` misses T_Q = ∩ H(lines[j]): the line meets T_Q iff
/// it lies inside the half-planes it is parallel to and, when it crosses some line,
/// one of the crossing points lies in all three half-planes (an end of the interval).
fn line_misses_hull<K: Kernel>(k: K, l: (Point, Point), lines: &[(Point, Point); 3]) -> bool {
    let mut crossing = [false; 3];
    for (j, &(s, u)) in lines.iter().enumerate() {
        if k.cross(l.0, l.1, s, u) == Collinear {
            if k.orient(s, u, l.0) == Cw {
                return true;
            }
        } else {
            crossing[j] = true;
        }
    }
    if !crossing.iter().any(|&c| c) {
        return false;
    }
    !(0..3).any(|j| {
        crossing[j]
            && (0..3).all(|m| m == j || !crossing[m] || line_meet_side(k, l, lines[j], lines[m]) != Cw)
    })
}

/// Prunes P' against a Q' of at most six vertices (or a segment) given explicitly.
fn against_small<K: Kernel, P: Probe>(
    k: K,
    pv: &[Point],
    mut pr: Range,
    qs: &[Point],
    probe: &mut P,
) -> bool {
    loop {
        probe.iteration();
        let mid = pr.mid();
        let t = [pr.at(pv, 0), pr.at(pv, mid), pr.at(pv, pr.len - 1)];
        let verdict = match separating_axis(k, &t, qs) {
            None => return true,
            Some(Axis::OfQ(line)) => prune_by_line(k, pv, pr, line),
            Some(Axis::OfTriangle(2)) => Step::Apart,
            Some(Axis::OfTriangle(c)) => keep_chain(pr, c),
        };
        match verdict {
            Step::KeepP(c) => {
                pr = if c == 0 {
                    pr.sub(pv, 0, mid)
                } else {
                    pr.sub(pv, mid, pr.len - 1)
                }
            }
            _ => return false,
        }
    }
}

/// A strictly separating line between a triangle and a small convex set.
enum Axis {
    /// The line of an edge of the small set (directed, the set on or left of it).
    OfQ((Point, Point)),
    /// The line of triangle edge i → i+1 (the small set strictly right of it).
    OfTriangle(usize),
}

/// Separating-axis test between a proper counter-clockwise triangle `t` and a convex
/// polygon or segment `qs` (counter-clockwise, in convex position). Complete: the
/// edges of the Minkowski difference are parallel to edges of `t` or of `qs`
/// (both directions for a segment).
fn separating_axis<K: Kernel>(k: K, t: &[Point; 3], qs: &[Point]) -> Option<Axis> {
    let n = qs.len();
    let q_edges = (0..n).map(|i| (qs[i], qs[(i + 1) % n]));
    let reversed = (0..n).filter(move |_| n == 2).map(|i| (qs[(i + 1) % n], qs[i]));
    for (s, u) in q_edges.chain(reversed) {
        if t.iter().all(|&x| k.orient(s, u, x) == Cw) {
            return Some(Axis::OfQ((s, u)));
        }
    }
    (0..3)
        .find(|&i| qs.iter().all(|&x| k.orient(t[i], t[(i + 1) % 3], x) == Cw))
        .map(Axis::OfTriangle)
}

/// Only for kernels that contradict themselves: the O(n + m) reference on the
/// remaining pieces.
fn fallback<K: Kernel>(k: K, pv: &[Point], pr: Range, qv: &[Point], qr: Range) -> bool {
    let piece =
        |v: &[Point], r: Range| ConvexPolygon::from_ccw_unchecked((0..r.len).map(|i| r.at(v, i)).collect());
    Linear.intersects_with(k, &piece(pv, pr), &piece(qv, qr))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Exact;
    use crate::intersect::{Iterations, brute_force};

    fn poly(pts: &[[f64; 2]]) -> ConvexPolygon {
        ConvexPolygon::new(pts.iter().copied()).unwrap()
    }

    #[test]
    fn hand_cases() {
        let sq = poly(&[[0., 0.], [2., 0.], [2., 2.], [0., 2.]]);
        let cases: &[(&[[f64; 2]], bool)] = &[
            (&[[1., 1.], [1.5, 1.], [1., 1.5]], true),
            (&[[-1., -1.], [3., -1.], [3., 3.], [-1., 3.]], true),
            (&[[2., 2.], [3., 2.], [3., 3.]], true),
            (&[[2., 0.5], [3., 0.], [3., 1.]], true),
            (&[[2., 0.], [3., 0.], [3., 2.], [2., 2.]], true),
            (&[[2.5, 0.], [3., 0.], [3., 2.]], false),
            (&[[3., 3.], [4., 3.], [4., 4.]], false),
            (&[[1.5, 3.], [3., 1.5], [3., 3.]], false),
        ];
        for (q, want) in cases {
            let q = poly(q);
            assert_eq!(Barba.intersects(&sq, &q), *want, "{q:?}");
            assert_eq!(Barba.intersects(&q, &sq), *want, "{q:?}");
        }
    }

    /// A regular 64-gon against squares with edges parallel to its edges (parallel
    /// lines among e0, e1, e2 and between T_P and T_Q), touching from outside along
    /// an edge, at a vertex, and one step apart.
    #[test]
    fn parallel_edges_and_tangencies() {
        let n = 64;
        let big = crate::generate::regular_polygon(n, 1.0);
        let v = big.vertices();
        for i in 0..n {
            let (a, b) = (v[i], v[(i + 1) % n]);
            let d = Point::new(b.x - a.x, b.y - a.y);
            let out = Point::new(d.y, -d.x); // outward normal, same length as the edge
            for (shift, want) in [(0.0, true), (1.0, false)] {
                let a2 = Point::new(a.x + shift * out.x, a.y + shift * out.y);
                let b2 = Point::new(b.x + shift * out.x, b.y + shift * out.y);
                let sq = ConvexPolygon::new([
                    [a2.x, a2.y],
                    [a2.x + out.x, a2.y + out.y],
                    [b2.x + out.x, b2.y + out.y],
                    [b2.x, b2.y],
                ]);
                let Ok(sq) = sq else { continue };
                let truth = brute_force(Exact, &big, &sq);
                if shift == 0.0 {
                    // Rounding may move the copied corners; the oracle decides.
                    assert_eq!(Barba.intersects(&big, &sq), truth, "edge {i}");
                } else {
                    assert_eq!(truth, want);
                }
                assert_eq!(Barba.intersects(&big, &sq), truth, "edge {i} shift {shift}");
                assert_eq!(
                    Barba.intersects(&sq, &big),
                    truth,
                    "edge {i} shift {shift} swapped"
                );
            }
            // A triangle with one vertex exactly on vertex i of the big polygon.
            let tri = poly(&[
                [a.x, a.y],
                [a.x * 2.0, a.y * 2.0 + 0.5],
                [a.x * 2.0 + 0.5, a.y * 2.0],
            ]);
            assert!(Barba.intersects(&big, &tri) && Barba.intersects(&tri, &big));
        }
    }

    #[test]
    fn iterations_are_logarithmic() {
        let n = 1 << 12;
        let big = crate::generate::regular_polygon(n, 1.0);
        let far = crate::generate::regular_polygon(n, 1.0)
            .map(|p| Point::new(p.x + 2.5, p.y))
            .unwrap();
        let mut it = Iterations::default();
        assert!(!Barba.intersects_probed(Exact, &big, &far, &mut it));
        assert!(it.0 <= 4 * 12, "{} iterations", it.0);
    }
}
