//! [`LinearLinked`]: the O(n + m) separating-edge test of [`Linear`](super::Linear), run
//! straight on [`LinkedPolygon`]s, with no conversion and no scratch memory.
//!
//! For each edge of P, in counter-clockwise order along the links, a pointer to the
//! vertex of Q deepest on the edge's inner side advances counter-clockwise (rotating
//! calipers); the first edge with that vertex strictly outside separates the polygons.
//! Then the same with the roles swapped. The pointer's start, the deepest vertex for
//! the first edge, is a scan of Q's arena in storage order (a maximum needs no
//! boundary order), so only the walks follow links, and an arena still in boundary order
//! (built in order, never relinked) is walked by position arithmetic instead. See [`Linear`](super::Linear) for
//! why this decides intersection.
//!
//! # Complexity
//! O(n + m) time, O(1) memory, every input; a separating edge found early ends it
//! early. Each step of a walk is a dependent load at an arena position, so on small
//! polygons it is the cheapest test (no allocation, no sampling, no LP) and on large
//! shuffled arenas it is bounded by cache misses.
//!
//! # Degeneracies
//! Those of [`Linear`](super::Linear): only strict separation counts, so touching at a
//! vertex, along an edge or by containment is intersection; parallel edges are plateaus
//! where either end gives the same answer.
//!
//! # Precision
//! `orient` and `cross` on input points only: exact under [`Exact`](crate::Exact). Under
//! an inconsistent kernel each pointer advance is capped at m steps, so the test always
//! terminates.

use super::engine::{LinkedEngine, linked_entry_points};
use super::linked::LinkedIntersection;
use super::{Certificate, Derivation, Probe, Which};
use crate::kernel::{Kernel, Orientation};
use crate::polygon::LinkedPolygon;
use rand::Rng;

/// The linear-time test on linked polygons; see the module docs.
///
/// ```
/// use polysect::LinkedPolygon;
/// use polysect::intersect::{LinearLinked, LinkedIntersection};
/// let p = LinkedPolygon::from_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let touching = LinkedPolygon::from_points([[2.0, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// let apart = LinkedPolygon::from_points([[2.5, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// assert!(LinearLinked.intersects(&p, &touching));
/// assert!(!LinearLinked.intersects(&p, &apart));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct LinearLinked;

impl LinkedIntersection for LinearLinked {
    const NAME: &'static str = "linear-linked";
    type Workspace = ();

    linked_entry_points!();
}

impl LinkedEngine for LinearLinked {
    #[inline]
    fn intersects_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        _rng: &mut R,
        _workspace: &mut (),
        probe: &mut P,
    ) -> bool {
        separating_edge_at(kernel, p, q, probe).is_none() && separating_edge_at(kernel, q, p, probe).is_none()
    }

    /// A separated pair is certified by the edge the walk found; an intersecting one
    /// is left to the certified call's completion (the walk saw every edge fail, which
    /// names no witness).
    #[inline]
    fn derive_in<K: Kernel, R: Rng + ?Sized, P: Probe>(
        &self,
        kernel: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        _rng: &mut R,
        _workspace: &mut (),
        probe: &mut P,
    ) -> Derivation {
        for (of, a, b) in [(Which::P, p, q), (Which::Q, q, p)] {
            if let Some((from, to, _)) = separating_edge_at(kernel, a, b, probe) {
                let (from, to) = (a.point_at(from), a.point_at(to));
                return Derivation::Certified(Certificate::Separated { of, from, to });
            }
        }
        Derivation::Answer(true)
    }
}

/// An edge of `a` (counter-clockwise) with every vertex of `b` strictly on its outer
/// (right) side, if there is one: the arena positions of the edge's ends in `a` and of
/// the vertex of `b` deepest on the edge's inner side (the one nearest the edge).
pub(crate) fn separating_edge_at<K: Kernel, P: Probe>(
    k: K,
    a: &LinkedPolygon,
    b: &LinkedPolygon,
    probe: &mut P,
) -> Option<(usize, usize, usize)> {
    let (n, m) = (a.len(), b.len());
    let (s0, t0) = (a.point_at(0), a.point_at(a.next_at(0)));
    // Deepest vertex of b for edge 0: w is deeper than v iff (t0 − s0) × (w − v) > 0.
    let mut j = 0;
    let mut bj = b.point_at(0);
    for i in 1..m {
        let bi = b.point_at(i);
        if k.cross(s0, t0, bj, bi) == Orientation::Ccw {
            (j, bj) = (i, bi);
        }
    }
    // Arenas in boundary order are walked by position arithmetic (no dependent loads).
    let (a_ordered, b_ordered) = (a.in_boundary_order(), b.in_boundary_order());
    let succ = |ordered: bool, p: &LinkedPolygon, i: usize, len: usize| {
        if ordered {
            if i + 1 == len { 0 } else { i + 1 }
        } else {
            p.next_at(i)
        }
    };
    let (mut pos, mut s) = (0, s0);
    for _ in 0..n {
        let next = succ(a_ordered, a, pos, n);
        let t = a.point_at(next);
        let mut steps = 0;
        while steps < m {
            let jn = succ(b_ordered, b, j, m);
            let bn = b.point_at(jn);
            if k.cross(s, t, bj, bn) != Orientation::Ccw {
                break;
            }
            (j, bj) = (jn, bn);
            steps += 1;
        }
        probe.iteration();
        if k.orient(s, t, bj) == Orientation::Cw {
            return Some((pos, next, j));
        }
        (pos, s) = (next, t);
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generate::{self, Family, Relation};
    use crate::intersect::{ArrayIntersection, Linear};
    use crate::kernel::{Exact, Fast};
    use rand::SeedableRng;
    use rand::rngs::SmallRng;

    const SEED: u64 = 0x11ea_11ed;

    /// Every generator family (random, touching, nested, one-ulp gaps), both relations,
    /// sizes from triangles up, shuffled arenas, against `Linear` on the arrays.
    #[test]
    fn equals_linear_on_arrays_for_every_family() {
        let mut rng = SmallRng::seed_from_u64(SEED);
        for &family in Family::ALL {
            for relation in [Relation::Intersecting, Relation::Disjoint, Relation::Any] {
                for n in [3, 4, 5, 8, 17, 64, 300] {
                    for _ in 0..6 {
                        let (p, q) = generate::pair(family, n, relation, &mut rng);
                        let want = Linear.intersects(&p, &q);
                        // Shuffled arenas (walked along the links), arenas in boundary
                        // order (walked by position), and one of each.
                        let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
                        let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
                        let (op, oq) = (LinkedPolygon::from_convex(&p), LinkedPolygon::from_convex(&q));
                        for (x, y) in [(&lp, &lq), (&op, &oq), (&lp, &oq), (&op, &lq)] {
                            assert_eq!(
                                LinearLinked.intersects(x, y),
                                want,
                                "{family:?} {relation:?} n {n}"
                            );
                            assert_eq!(
                                LinearLinked.intersects(y, x),
                                want,
                                "{family:?} {relation:?} n {n}"
                            );
                            // Certified: the walk's separating edge, or the completion.
                            let c = LinearLinked.certified(x, y);
                            assert_eq!(c.intersects(), want, "{family:?} {relation:?} n {n}");
                            assert_eq!(
                                crate::intersect::verify_linked(x, y, &c),
                                Ok(()),
                                "{family:?} {relation:?} n {n}: {c:?}"
                            );
                        }
                        // The fast kernel terminates (its answer may differ near ties).
                        let _ = LinearLinked.intersects_with(Fast, &lp, &lq);
                        let _ = LinearLinked.intersects_with(Exact, &lp, &lq);
                    }
                }
            }
        }
    }

    #[test]
    fn hand_cases_after_edits() {
        let mut sq = LinkedPolygon::from_points([[0., 0.], [2., 0.], [2., 2.], [0., 2.]]).unwrap();
        let apart = LinkedPolygon::from_points([[3., 0.], [4., 0.], [4., 2.]]).unwrap();
        assert!(!LinearLinked.intersects(&sq, &apart));
        // Pull the corner (2, 0) out to (3, 0): a shared vertex.
        let corner = sq.next(sq.first()).unwrap();
        sq.move_vertex(corner, crate::Point::new(3., 0.)).unwrap();
        assert!(LinearLinked.intersects(&sq, &apart));
        assert!(LinearLinked.intersects(&apart, &sq));
        sq.remove(corner).unwrap();
        assert!(!LinearLinked.intersects(&sq, &apart));
    }
}
