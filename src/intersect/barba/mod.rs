//! [`Barba`]: the Barba–Langerman O(log n) test on sorted arrays (thesis 3.1).
//!
//! # The algorithm
//! The test keeps two shrinking pieces, `P' = CH(P[a..=b])` and `Q' = CH(Q[c..=d])`
//! (contiguous index ranges of the arrays, never copied), with the invariant
//! **P ∩ Q ≠ ∅ ⇔ P' ∩ Q' ≠ ∅**. Since P' ⊆ P and Q' ⊆ Q, only "no intersection is
//! lost" has to be shown at each pruning step. Each iteration looks at
//! * the triangle `T_P = (P[a], P[mid], P[b]) ⊆ P'` (in the first iteration, while P'
//!   is all of P, the thesis's `(P[0], P[⌊n/3⌋], P[⌊2n/3⌋])`, whose three sides all have
//!   chains of P behind them, so the first pruning of P keeps a third; cheaper than
//!   first/middle/last on intersecting pairs, mixed on disjoint ones, docs/thesis.md,
//!   [`BarbaVariant`]), and
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
//! # Certificate
//! [`ArrayIntersection::certified_probed`](super::ArrayIntersection::certified_probed)
//! runs the same loop (a second instance of it, so the plain call keeps its code) and
//! turns the exit into a certificate where the loop ends (`certified_with`, without a
//! probe, a third instance that also completes it there, so that the certificate is
//! written once in the caller's place; both give the same certificate). A certified
//! run computes the positions of its exit only where it ends, and hands a segment exit
//! its witness's indices as found (`SegmentExit`):
//! * a vertex of T_P in K (step 1) or of K in T_P (step 3): that vertex, inside;
//! * an edge of T_P (a chord of P) meeting an edge of Q (step 4), or T_P meeting the
//!   small Q' of the finish without a vertex of either inside the other: the chord is
//!   reduced to an edge of P by one binary search within P' (the chain beyond it
//!   crosses the line of Q's edge exactly once), giving two crossing edges or an end of
//!   Q's edge inside P. O(log n) more; the plain run never localises P's boundary
//!   there, so this is the certified call's extra work on intersecting pairs. Where
//!   Q' is a segment, the certified finish decides separation from the nine
//!   orientations between T_P and the segment and ends with them (`Exit::Segment`):
//!   they decide every case, and the proper crossing is resolved from them without
//!   computing any of them or the contact again.
//! * disjoint pieces: the last separating line is an edge of Q with P' strictly
//!   outside (or an edge of P with Q' outside). If P's vertex deepest towards it is
//!   extreme in all of P, that edge separates P and Q: the run ended because P''s
//!   farthest point towards the line is a triangle vertex, so only a neighbour outside
//!   P' can lie deeper (at most one predicate). Otherwise P
//!   crosses its line away from P' (a chain pruned by an earlier line) and P's edges
//!   at that vertex are tried, each against Q's extreme vertex (one binary search in
//!   Q; the edge ending there nearly always separates), then P's extreme vertex against
//!   the Q edge (one binary search in P). Otherwise the pieces' separator is not one
//!   for the polygons, and a second run with the roles exchanged usually ends on one
//!   that is (1 ellipse-family pair in 360); failing that,
//!   only the answer is returned and the certified call completes it
//!   ([`Fallback`](super::Fallback)).
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

mod engine;
mod witness;

pub(crate) use witness::meeting_certificate;

#[cfg(test)]
mod tests;

use super::engine::{ArrayEngine, array_entry_points};
use super::{ArrayIntersection, Certificate, Derivation, Probe};
use crate::kernel::{BoundingBox, Kernel};
use crate::polygon::{ConvexPolygon, Vertices};
use engine::{Plain, Range, SMALL_Q, run};
use witness::{Certify, Derive};

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

/// [`Barba`] with the choices the thesis makes where ours differ, one parameter each
/// (docs/thesis.md compares them; [`Barba`] is `BarbaVariant<true, 7, false>`):
///
/// * `THIRDS`: the first T_P at vertices 0, ⌊n/3⌋, ⌊2n/3⌋ of P (thesis §3.1.4), so that
///   the first pruning of P keeps one of three chains (ours, `true`); `false` takes the
///   first, middle and last vertex, whose third side is an edge of P.
/// * `SMALL_Q`: the main loop hands Q' to the constant-size finish once it has fewer
///   than this many vertices, 4 to 7: 4 is the thesis's finish on three edges of Q
///   (§3.1.8), 7 (ours) finishes from at most six vertices.
/// * `P_EDGES_FIRST`: look for a separating line among T_P's edges (step 5) before
///   T_Q's (step 2), the alternative order of §3.1.10; ours (`false`) tries T_Q's first,
///   as the thesis's implementation does.
///
/// Every combination gives the same answers and certificates that verify; only the
/// path (and so the cost) differs.
///
/// ```
/// use polysect::{ConvexPolygon, intersect::{ArrayIntersection, BarbaVariant}};
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let apart = ConvexPolygon::new([[2.5, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// assert!(!BarbaVariant::<true, 4, true>.intersects(&p, &apart));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct BarbaVariant<const THIRDS: bool, const SMALL_Q: usize, const P_EDGES_FIRST: bool>;

/// The choices of a [`BarbaVariant`], as constants the algorithm is compiled with.
trait Variant {
    const THIRDS: bool;
    const SMALL_Q: usize;
    const P_EDGES_FIRST: bool;
}

impl<const T: bool, const S: usize, const E: bool> Variant for BarbaVariant<T, S, E> {
    const THIRDS: bool = T;
    const SMALL_Q: usize = {
        assert!(S >= 4 && S <= SMALL_Q, "SMALL_Q must be in 4..=7");
        S
    };
    const P_EDGES_FIRST: bool = E;
}

/// [`Barba`]'s choices.
type Ours = BarbaVariant<true, SMALL_Q, false>;

/// `pr` with its `thirds` flag known to the compiler to be off when the variant never
/// sets it (ours), so that the choice costs nothing there.
#[inline(always)]
fn known<V: Variant>(pr: Range) -> Range {
    Range {
        thirds: V::THIRDS && pr.thirds,
        ..pr
    }
}

impl ArrayIntersection for Barba {
    const NAME: &'static str = "barba";

    array_entry_points!(plain);

    #[inline]
    fn certified_with<K: Kernel>(&self, k: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Certificate {
        Ours::default().certified_with(k, p, q)
    }
}

impl ArrayEngine for Barba {
    #[inline]
    fn intersects_probed<K: Kernel, P: Probe>(
        &self,
        k: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> bool {
        Ours::default().intersects_probed(k, p, q, probe)
    }

    /// See the module docs' "Certificate" section.
    #[inline]
    fn derive_probed<K: Kernel, P: Probe>(
        &self,
        k: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> Derivation {
        Ours::default().derive_probed(k, p, q, probe)
    }
}

impl<const T: bool, const S: usize, const E: bool> ArrayIntersection for BarbaVariant<T, S, E> {
    const NAME: &'static str = "barba-variant";

    array_entry_points!(plain);

    /// [`ArrayEngine::certified_probed`] without a probe, from
    /// a run that builds the certificate where it ends (the `Certify` mode): the same
    /// certificate, written once instead of passed up as a [`Derivation`] and moved.
    fn certified_with<K: Kernel>(&self, k: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Certificate {
        let k = k.within([p.bounding_box(), q.bounding_box()]);
        run::<K::Within, (), Certify, Self, _, _>(k, p.vertices(), q.vertices(), &mut ())
    }
}

impl<const T: bool, const S: usize, const E: bool> ArrayEngine for BarbaVariant<T, S, E> {
    fn intersects_probed<K: Kernel, P: Probe>(
        &self,
        k: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> bool {
        let k = k.within([p.bounding_box(), q.bounding_box()]);
        run::<K::Within, P, Plain, Self, _, _>(k, p.vertices(), q.vertices(), probe)
    }

    /// See the module docs' "Certificate" section.
    fn derive_probed<K: Kernel, P: Probe>(
        &self,
        k: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> Derivation {
        let k = k.within([p.bounding_box(), q.bounding_box()]);
        run::<K::Within, P, Derive, Self, _, _>(k, p.vertices(), q.vertices(), probe)
    }
}

/// [`Barba`] on polygons read through [`Vertices`] (a posed view computes each vertex it
/// reads), given their bounding boxes (which the exact kernel's filters are scaled to:
/// each must contain its polygon). The same search as on arrays, generic over the
/// access, so that on slices it is the array call's code.
///
/// # Complexity
/// O(log n + log m) vertex reads and predicates for the answer; the certificate of an
/// exit other than a vertex inside reads the polygons as slices
/// ([`Vertices::with_slice`]: O(n + m) for computed vertices).
#[inline]
pub(crate) fn intersects_vertices<K: Kernel, PV: Vertices + ?Sized, QV: Vertices + ?Sized>(
    k: K,
    (pv, pbox): (&PV, BoundingBox),
    (qv, qbox): (&QV, BoundingBox),
) -> bool {
    run::<K::Within, (), Plain, Ours, PV, QV>(k.within([pbox, qbox]), pv, qv, &mut ())
}

/// [`intersects_vertices`] with the certificate [`Barba`]'s certified call gives on the
/// same vertices (every vertex it names is read through the access).
#[inline]
pub(crate) fn certified_vertices<K: Kernel, PV: Vertices + ?Sized, QV: Vertices + ?Sized>(
    k: K,
    (pv, pbox): (&PV, BoundingBox),
    (qv, qbox): (&QV, BoundingBox),
) -> Certificate {
    run::<K::Within, (), Certify, Ours, PV, QV>(k.within([pbox, qbox]), pv, qv, &mut ())
}
