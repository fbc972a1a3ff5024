//! [`Linear`]: the O(n + m) reference test, and the O(n·m) [`brute_force`] oracle.
//!
//! Two closed convex polygons are disjoint iff some edge of one has the whole other
//! polygon strictly on its outer side: 0 lies outside the Minkowski difference P − Q
//! iff some edge of P − Q strictly separates it, and every edge of P − Q is an edge
//! of P or of −Q. For each edge of P the test keeps a pointer to the vertex of Q
//! deepest on the inner side (the extreme vertex in the inward normal direction); as
//! the edge turns counter-clockwise the pointer only moves counter-clockwise
//! (rotating calipers), so one sweep over each polygon suffices.
//!
//! # Complexity
//! O(n + m) time, O(1) memory, for polygons of n and m vertices, every input.
//!
//! # Degeneracies
//! Only strict separation counts, so touching at a vertex, along an edge or by
//! containment is intersection. Edges of Q parallel to the current edge are plateaus
//! of the pointer's objective; stopping at either end gives the same answer.
//!
//! # Certificate
//! A separating edge is the sweep's own answer. For intersecting polygons the sweep
//! only learns that no edge separates; the certified call takes the witness (a vertex
//! inside, or two crossing edges) from [`Barba`](super::Barba), O(log n + log m).
//!
//! # Precision
//! Decided by `orient` and `cross` on input points only: exact under [`Exact`](crate::Exact).
//! The exact kernel answers the walk's `cross`, always of an edge of each polygon, under
//! [`Kernel::within_differences`] of the longer [`ConvexPolygon::edge_extent`]: a
//! semi-static error bound scaled to the longest edge, which decides the cross product
//! of two short, nearly parallel edges where the bound scaled to the boxes (used for
//! everything else) does not. With it the exact kernel's overhead over the fast one
//! stays the same at every size; with the boxes' bound it grows with n (docs/results.md,
//! "Chazelle–Dobkin and Linear, profiled again").
//! Under an inconsistent kernel ([`Fast`](crate::Fast) near degeneracies) each pointer
//! advance is capped at m steps, so the test always terminates.

use super::engine::{ArrayEngine, array_entry_points};
use super::{ArrayIntersection, Certificate, Derivation, Probe, Which};
use crate::kernel::{Kernel, Orientation, Point, segments_intersect};
use crate::polygon::ConvexPolygon;

/// The O(n + m) separating-edge test with rotating pointers; see the module docs.
///
/// ```
/// use polysect::{ConvexPolygon, intersect::{ArrayIntersection, Linear}};
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let touching = ConvexPolygon::new([[2.0, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// let apart = ConvexPolygon::new([[2.5, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// assert!(Linear.intersects(&p, &touching));
/// assert!(!Linear.intersects(&p, &apart));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct Linear;

impl ArrayIntersection for Linear {
    const NAME: &'static str = "linear";

    array_entry_points!(all);
}

impl ArrayEngine for Linear {
    fn intersects_probed<K: Kernel, P: Probe>(
        &self,
        k: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> bool {
        let (k, edges) = kernels(k, p, q);
        let (pv, qv) = (p.vertices(), q.vertices());
        separating_edge(k, edges, pv, qv, probe).is_none()
            && separating_edge(k, edges, qv, pv, probe).is_none()
    }

    /// Disjoint: the separating edge the sweep stopped at. Intersecting: the sweep only
    /// learns that no edge separates, so only the answer (the certified call takes the
    /// witness from [`Barba`](super::Barba), O(log n + log m), small beside the sweep).
    fn derive_probed<K: Kernel, P: Probe>(
        &self,
        k: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> Derivation {
        let (k, edges) = kernels(k, p, q);
        match separating_certificate(k, edges, p.vertices(), q.vertices(), probe) {
            Some(c) => Derivation::Certified(c),
            None => Derivation::Answer(true),
        }
    }
}

/// The query's kernels: `k` within the polygons' boxes, and `k` within their longest
/// edges' differences ([`Kernel::within_differences`]) for the walk's cross products,
/// which are all of an edge of one polygon and an edge of the other.
#[inline]
fn kernels<K: Kernel>(k: K, p: &ConvexPolygon, q: &ConvexPolygon) -> (K::Within, K::Within) {
    let w = p.edge_extent().max(q.edge_extent());
    (
        k.within([p.bounding_box(), q.bounding_box()]),
        k.within_differences(w),
    )
}

/// The certificate of a separating edge of `pv` (then of `qv`), if the sweep finds one.
/// `edges` answers the cross products of an edge of `pv` and an edge of `qv` (`k`
/// itself will do).
pub(crate) fn separating_certificate<K: Kernel, P: Probe>(
    k: K,
    edges: K,
    pv: &[Point],
    qv: &[Point],
    probe: &mut P,
) -> Option<Certificate> {
    let edge = |v: &[Point], e: usize| (v[e], v[(e + 1) % v.len()]);
    if let Some(e) = separating_edge(k, edges, pv, qv, probe) {
        let (from, to) = edge(pv, e);
        return Some(Certificate::Separated {
            of: Which::P,
            from,
            to,
        });
    }
    separating_edge(k, edges, qv, pv, probe).map(|e| {
        let (from, to) = edge(qv, e);
        Certificate::Separated {
            of: Which::Q,
            from,
            to,
        }
    })
}

/// The first edge of `av` that has every vertex of `bv` strictly on its outer (right) side,
/// by a rotating-pointer walk. `edges` answers the walk's cross products, each of an
/// edge of `av` and an edge of `bv`; `k` everything else.
///
/// Under the exact kernel `edges` is [`Kernel::within_differences`] of the longest
/// edge: the walk stops where the two edges turn past each other, so its cross products
/// are of two short, nearly parallel edges, whose value a bound scaled to the boxes
/// (`k`'s) seldom exceeds once the polygons have many vertices (then most calls go
/// out of line; docs/results.md, "Chazelle–Dobkin and Linear, profiled again"). Scaled to the edges
/// it decides them with the two comparisons the fast kernel makes against zero.
fn separating_edge<K: Kernel, P: Probe>(
    k: K,
    edges: K,
    av: &[Point],
    bv: &[Point],
    probe: &mut P,
) -> Option<usize> {
    let (n, m) = (av.len(), bv.len());
    // Deepest vertex of b for edge 0: w is deeper than v iff (a1 − a0) × (w − v) > 0.
    // Not two edges (v, w are any two vertices): the boxes' kernel.
    let mut j = 0;
    for i in 1..m {
        if k.cross(av[0], av[1], bv[j], bv[i]) == Orientation::Ccw {
            j = i;
        }
    }
    for e in 0..n {
        let (s, t) = (av[e], av[(e + 1) % n]);
        let mut steps = 0;
        while steps < m && edges.cross(s, t, bv[j], bv[(j + 1) % m]) == Orientation::Ccw {
            j = (j + 1) % m;
            steps += 1;
        }
        probe.iteration();
        if k.orient(s, t, bv[j]) == Orientation::Cw {
            return Some(e);
        }
    }
    None
}

instrument_pub! {
    /// The O(n·m) oracle: the polygons intersect iff two edges meet (closed segments)
    /// or a vertex of one lies in the other. Exact under the exact kernel; used to check
    /// [`Linear`] and never on a hot path.
    #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
    fn brute_force<K: Kernel>(k: K, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
        let (pv, qv) = (p.vertices(), q.vertices());
        let contains = |v: &[Point], x: Point| edges(v).all(|(a, b)| k.orient(a, b, x) != Orientation::Cw);
        edges(pv).any(|(a, b)| edges(qv).any(|(c, d)| segments_intersect(k, a, b, c, d)))
            || contains(qv, pv[0])
            || contains(pv, qv[0])
    }
}

/// The closed boundary's edges (v[i], v[i + 1]).
fn edges(v: &[Point]) -> impl Iterator<Item = (Point, Point)> + '_ {
    (0..v.len()).map(move |i| (v[i], v[(i + 1) % v.len()]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Exact;

    fn poly(pts: &[[f64; 2]]) -> ConvexPolygon {
        ConvexPolygon::new(pts.iter().copied()).unwrap()
    }

    #[test]
    fn hand_cases() {
        let sq = poly(&[[0., 0.], [2., 0.], [2., 2.], [0., 2.]]);
        let cases: &[(&[[f64; 2]], bool)] = &[
            (&[[1., 1.], [1.5, 1.], [1., 1.5]], true),             // contained
            (&[[-1., -1.], [3., -1.], [3., 3.], [-1., 3.]], true), // contains
            (&[[2., 2.], [3., 2.], [3., 3.]], true),               // shared vertex
            (&[[2., 0.5], [3., 0.], [3., 1.]], true),              // vertex on edge
            (&[[2., 0.], [3., 0.], [3., 2.], [2., 2.]], true),     // shared edge
            (&[[2., 1.], [3., 1.], [3., 3.], [2., 3.]], true),     // overlapping edges
            (&[[2.5, 0.], [3., 0.], [3., 2.]], false),
            (&[[3., 3.], [4., 3.], [4., 4.]], false), // diagonal apart
            (&[[1.5, 3.], [3., 1.5], [3., 3.]], false), // gap across the corner
        ];
        for (q, want) in cases {
            let q = poly(q);
            assert_eq!(Linear.intersects(&sq, &q), *want, "{q:?}");
            assert_eq!(Linear.intersects(&q, &sq), *want);
            assert_eq!(brute_force(Exact, &sq, &q), *want);
        }
    }
}
