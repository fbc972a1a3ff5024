//! [`ChazelleDobkin`]: the O(log n + log m) intersection test after Chazelle and
//! Dobkin (1987): a pivot vertex, its pencil of tangents, the two chains the pencil
//! cuts out (the *L sets*), and a pruning loop that halves one chain per iteration by
//! comparing the chains' middle edges.
//!
//! # The algorithm
//! Let P have n and Q have m vertices, both counter-clockwise; the pivot A is vertex 0
//! of P.
//!
//! 1. **Pivot and pencil.** If A ∈ Q the answer is yes. Otherwise the *pencil* of A
//!    is the pair of tangent lines from A to Q; it bounds the wedge W(A) ⊇ Q (angle
//!    strictly between 0 and π) and touches Q at the tangent points q_L and q_R.
//!    They are the ends of the block of edges of Q *visible* from A (A strictly
//!    outside the edge's line), a contiguous cyclic block. One edge inside the block
//!    and one outside it come from locating A in the fan of Q around vertex 0 (the
//!    intersection of Q with the line through A and vertex 0: IGL by binary search);
//!    two binary searches on the cyclic edge sequence then find the block's ends.
//! 2. **L sets.** Q can meet P only inside W(A), and P ∩ W(A) is the part of P
//!    seen from A through the pencil. Its far boundary is the chain F of P between
//!    the edges the two pencil lines cross (found by binary search over the fan of P
//!    around A; this is IGL for a line through a vertex). The part of Q that faces A
//!    is the chain G of visible edges, from q_L to q_R. F and G are the L sets.
//!    If the pencil does not enter P (the angle of P at A and W(A) share only A)
//!    the answer is no.
//! 3. **Pruning.** Send A to infinity by a projective map τ whose line at infinity
//!    passes through A outside W(A) (we take the line through A parallel to q_L q_R).
//!    Rays from A become vertical lines, W(A) becomes a vertical slab, τ(P ∩ W(A))
//!    becomes the region below the concave function f whose graph is F, and τ(Q)
//!    the region above the convex function g whose graph is G. So P and Q intersect
//!    iff f(x) ≥ g(x) for some x in the window D (the directions common to W(A) and
//!    the angle of P at A). h = f − g is concave. Take the middle edges e_F (over
//!    [a1, a2]) and e_G (over [b1, b2]) with τ-slopes s_F, s_G:
//!    * **case 1**, a middle edge lies outside the window: drop the half of its
//!      chain beyond it;
//!    * **case 2**, s_F ≤ s_G: h is non-increasing on [max(a1, b1), ∞), so the part
//!      of the chain whose middle edge starts later that lies right of its middle
//!      edge can go;
//!    * **case 3**, s_F > s_G: symmetrically, h is increasing on (−∞, min(a2, b2)],
//!      so the part left of the middle edge that ends earlier can go;
//!    * **case 4**, one chain is down to at most two edges: compare the other
//!      chain's middle edge with the short chain's edge at the same place (same
//!      argument, one chain only);
//!    * **case 5**, both chains have at most two edges: h is piecewise linear with
//!      its breakpoints at the chains' vertices and its window ends at chain vertices,
//!      so the answer is whether some chain vertex in the window lies on the other
//!      side (or on) the other chain's edge above/below it: at most six orientation
//!      tests.
//!
//!    Each of cases 1–4 keeps at most ⌈k/2⌉ + 1 of a chain's k ≥ 3 edges.
//!
//! # Where the sources are vague, and what we decided
//! The paper's version uses a second pencil (pivot B on Q, tangents to P) to bound
//! the search to the quadrilateral AXBY, falls back to a pentagon when X or Y is
//! undefined, and prunes with five cases on where the middle edges' lines cross the
//! quadrilateral. In the projective frame above the first pencil alone gives a
//! slab and two monotone chains, so the second pencil, the quadrilateral and the
//! pentagon are not needed, and every comparison "which crossing comes first along
//! the boundary" becomes an orientation or a slope comparison. The source's
//! description also stops pruning when either chain has fewer than six vertices and
//! finishes with all pairs of edges, which is not logarithmic when the other chain
//! is long; case 4 keeps pruning the long chain. See docs/algorithms.md.
//!
//! # Certificate
//! * A ∈ Q: A is a vertex inside.
//! * The finish found a vertex w of G on A's side of F inside the window: w is a vertex
//!   of Q inside P (the ray from A to w stays in P up to F).
//! * The finish found a vertex z of F on or beyond G: the segment from A to z (a chord of
//!   P) meets G's edge there, resolved into a vertex inside or two crossing edges by at
//!   most two binary searches.
//! * The pencil misses P: an edge of P at A whose open outer side holds both tangent
//!   points holds the whole wedge W(A) ⊇ Q (a half-plane bounded by a line through A,
//!   and A ∉ Q), so it separates (two orientations per edge). Else a pencil line
//!   through A supports both polygons, and an edge at A or at the tangent point may
//!   separate (O(1)).
//! * The finish found h < 0 on the window: the final chains' edges (≤ 2 of F, ≤ 2 of G)
//!   P's edges at A and Q's edges just outside G at the tangent points are candidates when the other
//!   final chain lies strictly on their outer side (≤ 3 orientations). An edge of F is
//!   accepted with no search when the visible edges just beyond G's ends bracket its
//!   slope in the frame (two slope comparisons): g minus the edge's line is convex, so
//!   its minimum over the whole visible chain is then at a vertex of G, and Q lies
//!   above g. This holds when h's maximum lies inside the edge's span (about three
//!   queries in four on the Rotated pairs). Otherwise a candidate is accepted when the
//!   other polygon's vertex extreme against it (one O(log) binary search, for an edge
//!   of P only on the chain of Q visible from A) is strictly outside and extreme. So
//!   every accepted edge separates the whole polygons. Then the faces at the final chains' vertices and the pencil lines
//!   (O(1)). The maximum of h in the projective frame need not be where the polygons
//!   are closest, so all of these can fail; then only the answer is returned
//!   (completed by [`Dobkin`](crate::intersect::Dobkin)'s separation, which tests/geometry/certificates.rs
//!   counts: 0 of 2,700 disjoint queries on the generator families).
//!
//! # Complexity
//! O(log n + log m) time, O(1) memory, on every input: three binary searches on Q,
//! two on P, at most about 2·(log₂ n + log₂ m) pruning iterations (each reported to
//! the [`Probe`]), and a constant finish.
//!
//! # Degeneracies
//! Closed sets throughout: A on the boundary of Q is "inside"; edges of Q collinear
//! with A are not visible, so q_L and q_R are the tangent points nearest A; a pencil
//! line along an edge of P gives a window of a single direction, handled by the
//! finish like any other window; ties in the angular order and equal slopes fall on
//! the side whose argument still holds (non-strict monotonicity); every final test
//! counts "on the line" as contact.
//!
//! # Precision
//! Every decision is the sign of a polynomial in input coordinates: `orient`, and
//! one degree-4 slope comparison in the projective frame (below), a kernel predicate
//! ([`Kernel::cross_products_sign_of_short_edges`]). Nothing is constructed, so the test is exact
//! under [`Exact`](crate::Exact). Under
//! [`Fast`](crate::Fast) wrong signs near degeneracies can give wrong answers but
//! every step still shortens a chain, so the test always terminates.

mod engine;
mod witness;

#[cfg(test)]
mod tests;

use super::certificate::{from_faces, from_support, resolve_chords};
use super::engine::{ArrayEngine, array_entry_points};
use super::{ArrayIntersection, Certificate, Derivation, Probe, Which};
use crate::kernel::Kernel;
use crate::polygon::ConvexPolygon;
use engine::{Exit, Hit, run, short_edges, union_side};
use witness::{from_final_edges, pivot_edge_apart};

/// The Chazelle–Dobkin O(log n + log m) test; see the module docs.
///
/// ```
/// use polysect::{ConvexPolygon, intersect::{ArrayIntersection, ChazelleDobkin}};
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let touching = ConvexPolygon::new([[2.0, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// let apart = ConvexPolygon::new([[2.5, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// assert!(ChazelleDobkin.intersects(&p, &touching));
/// assert!(!ChazelleDobkin.intersects(&p, &apart));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct ChazelleDobkin;

impl ArrayIntersection for ChazelleDobkin {
    const NAME: &'static str = "chazelle-dobkin";

    array_entry_points!(all);
}

impl ArrayEngine for ChazelleDobkin {
    fn intersects_probed<K: Kernel, P: Probe>(
        &self,
        k: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> bool {
        let k = k.within_differences(union_side(p, q));
        run(k, p.vertices(), q.vertices(), || short_edges(p, q), probe).meets()
    }

    /// See the module docs' "Certificate" section.
    fn derive_probed<K: Kernel, P: Probe>(
        &self,
        k: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> Derivation {
        let k = k.within_differences(union_side(p, q));
        let (pv, qv) = (p.vertices(), q.vertices());
        let exit = run(k, pv, qv, || short_edges(p, q), probe);
        let found = match exit {
            Exit::AInside => Some(Certificate::VertexInside {
                of: Which::P,
                point: pv[0],
            }),
            // An edge of P at A with the wedge outside, else a pencil line supporting both.
            Exit::Misses { ql, qr } => pivot_edge_apart(k, pv, qv[ql], qv[qr]).or_else(|| {
                [ql, qr]
                    .into_iter()
                    .find_map(|t| from_support(k, (pv[0], qv[t]), pv, 0, qv, t))
            }),
            Exit::Finish {
                f, g, hit: Some(hit), ..
            } => match hit {
                Hit::F { z, e } => resolve_chords(k, pv, (0, f.index(z)), qv, (g.index(e), g.index(e + 1))),
                Hit::G { w } => Some(Certificate::VertexInside {
                    of: Which::Q,
                    point: qv[g.index(w)],
                }),
            },
            Exit::Finish {
                f,
                g,
                hit: None,
                tangents,
            } => from_final_edges(k, pv, qv, &f, &g, tangents)
                .or_else(|| {
                    let face_f = [f.index(f.lo), f.index(f.lo + 1), f.index(f.hi), 0];
                    let face_g = [g.index(g.lo), g.index(g.lo + 1), g.index(g.hi)];
                    from_faces(k, pv, &face_f, qv, &face_g)
                })
                .or_else(|| {
                    tangents
                        .into_iter()
                        .find_map(|t| from_support(k, (pv[0], qv[t]), pv, 0, qv, t))
                }),
        };
        found.map_or(Derivation::Answer(exit.meets()), Derivation::Certified)
    }
}
