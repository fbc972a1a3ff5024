//! [`Dobkin`]: the Dobkin–Souvaine O(log n) test on sorted arrays (thesis 3.2).
//!
//! # The algorithm
//! 1. **Top and bottom by binary search.** The edge directions of a convex polygon
//!    stored counter-clockwise turn monotonically through one full turn. Each edge
//!    falls in one of four direction classes (east, up, west, down), read off by
//!    comparing its endpoints' coordinates; counted from edge 0's class, the
//!    classes grow monotonically along the array except for the last edges of edge
//!    0's own class, which one `cross` against edge 0 puts at the end. Two binary
//!    searches on that rank find the first downward edge (it starts at the topmost
//!    vertex, the left one if the top is a horizontal edge) and the first upward
//!    edge (it starts at the bottommost vertex, the right one if the bottom is
//!    horizontal). A horizontal top or bottom edge is the edge just before.
//! 2. **Chains.** The *left chain* runs counter-clockwise from the top (left end of a
//!    horizontal top) down to the bottom (left end of a horizontal bottom); every edge
//!    strictly descends. The *right chain* runs from the bottom (right end) up to
//!    the top (right end); every edge strictly ascends. Horizontal edges belong to
//!    neither. The left chain bounds the region `L = {y ∈ [y_bot, y_top], x ≥ x_L(y)}`,
//!    the right chain `R = {y ∈ [y_bot, y_top], x ≤ x_R(y)}`, and `P = L_P ∩ R_P`.
//!    Chains are index ranges into the polygon's array; nothing is copied.
//! 3. **Lemma (Dobkin–Souvaine).** P and Q intersect iff `L_P ∩ R_Q ≠ ∅` and
//!    `L_Q ∩ R_P ≠ ∅`. (On the common y-interval put `h1 = x_R^Q − x_L^P` and
//!    `h2 = x_R^P − x_L^Q`; both are concave and `h1 + h2 ≥ 0` because both polygons
//!    have non-negative width, so if `{h1 ≥ 0}` and `{h2 ≥ 0}` are both non-empty
//!    they cannot be disjoint intervals: a height between them would make the sum
//!    negative.)
//! 4. **Pruning a left chain against a right chain** (the LR-region lemmas, stated
//!    here as a search for the maximum of the concave function `g = x_R − x_L` on
//!    the common y-interval I; the regions meet iff `max g ≥ 0`). Take the median
//!    edge e of the left chain and f of the right chain, with slopes `s_L = dx/dy`
//!    and `s_R`; their comparison is one `cross` on input points. `x_L` is convex
//!    and `x_R` concave in y, so
//!    * if `s_R ≥ s_L`, g is non-decreasing below `min(top(e), top(f))`: the lower
//!      part of the chain whose median ends lower is pruned and I starts there;
//!    * if `s_R < s_L`, g is decreasing above `max(bottom(e), bottom(f))`: the upper
//!      part of the chain whose median starts higher is pruned and I ends there.
//!
//!    When the cut would empty I, the maximum lies at the end of I and a single
//!    height is tested. Each iteration halves one chain, so once both have one
//!    edge left g is linear on I and its two ends are tested. These rules are
//!    applied as one nested decision (the compact form, like the thesis's Code 3.2);
//!    [`DobkinVariant<true>`] tests each rule and its symmetric version by its own
//!    `if` (the thesis's Code 3.1 form) and also cuts the other chain where its median
//!    edge reaches past the new end of I: same predicates, closed tests and
//!    certificates, more instructions per query (docs/results.md).
//! 5. **Height test.** Every end of I is the height of a vertex w of one of the
//!    chains (both ranges always cover I and every cut is at a vertex), so "is
//!    `x_L ≤ x_R` at that height" is one `orient` of w against the other chain's
//!    edge at that height (found by binary search) or one comparison of x
//!    coordinates when both chains have a vertex there.
//!
//! # Certificate
//! * **Disjoint.** The search that failed found g = x_R − x_L negative at its maximum
//!   y*, at a tested vertex w with the other chain's edge at that height. A supporting
//!   slope σ common to both chains at y* (a supergradient of the concave g is 0) gives
//!   parallel supporting lines of the two polygons with a gap, so one of the edges at w
//!   and at the other chain's vertices there separates (the faces' argument in
//!   [`certificate`](super::certificate)); at an end of the common y-interval the
//!   argument is the same with a one-sided σ. The edge of the other chain at y* is
//!   tried first, with the sign of the failed test's own `orient` (only the local test
//!   is evaluated). If the y-ranges are disjoint, the lowest vertex of the Minkowski
//!   difference, the higher polygon's bottom-left minus the lower one's top-right, has
//!   0 strictly below it, so one of its two edges separates: one cross product picks
//!   each, one `orient` tests it. O(1) beyond the test: w bounds I, so it is an
//!   end of its chain's remaining range (a binary search on heights only if not). Under
//!   the exact kernel this always succeeds (the tests check it), which makes it the
//!   completing search of every algorithm's "disjoint".
//! * **Intersecting.** Both searches met at a vertex w inside the other polygon's
//!   region on one side; if w also lies inside the other side's chain at its height
//!   (one binary search on heights and one `orient`), w is a vertex inside. Otherwise
//!   that chain's edge g at w's height passes beyond w at a point Z; if Z is in w's
//!   polygon, it lies in the triangle of w and that polygon's edge r at the same height
//!   on its other chain (one more binary search), so an end of g is in the triangle,
//!   or r and g cross, or g crosses a chord from w to an end of r (resolved by one more
//!   search). Each search's vertex is tried first, then each triangle; where none
//!   holds (2 of 2,700 queries of the test families) only the answer, completed with
//!   [`Barba`](super::Barba)'s witness.
//!
//! # Complexity
//! O(log n + log m) time, O(1) memory, for polygons of n and m vertices, on every
//! input: four binary searches for the extreme vertices, two chain-pair searches
//! that halve a chain per iteration, at most four height tests of O(log) each.
//! On arrays of millions of vertices the cost is cache misses, so the four extreme
//! searches run in lockstep, and so do the two chain-pair searches.
//!
//! # Degeneracies
//! Horizontal top and bottom edges are excluded from the chains (step 1), so no
//! slope is infinite. Touching pairs are intersecting: every test is closed (`≥`,
//! `orient ≠ Cw`). Polygons whose y-ranges meet in a single height reduce to one
//! height test. Equal slopes fall in the `s_R ≥ s_L` case, which is valid for
//! equality.
//!
//! # Precision
//! Every decision is a comparison of input coordinates or an `orient`/`cross`
//! on input points; exact under [`Exact`](crate::Exact). Under [`Fast`](crate::Fast) the
//! searches may misjudge near-degenerate input but always terminate: every loop
//! shrinks an index range.

mod engine;
mod witness;

pub(crate) use witness::separating_certificate;

#[cfg(test)]
mod tests;

use super::engine::{ArrayEngine, array_entry_points};
use super::{ArrayIntersection, Derivation, Probe};
use crate::kernel::Kernel;
use crate::polygon::ConvexPolygon;
use engine::{Outcome, run};
use witness::{meeting, separation};

/// The Dobkin–Souvaine O(log n) test; see the module docs.
///
/// ```
/// use polysect::{ConvexPolygon, intersect::{ArrayIntersection, Dobkin}};
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let touching = ConvexPolygon::new([[2.0, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// let apart = ConvexPolygon::new([[2.5, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// assert!(Dobkin.intersects(&p, &touching));
/// assert!(!Dobkin.intersects(&p, &apart));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct Dobkin;

/// [`Dobkin`] with the pruning rules applied the other way (docs/thesis.md compares
/// them; [`Dobkin`] is `DobkinVariant<false>`):
///
/// * `LEMMA_BY_LEMMA = false` (ours): one nested decision per iteration over the slope
///   comparison and the medians' heights, which cuts one chain, the compact form of the
///   thesis's Code 3.2.
/// * `LEMMA_BY_LEMMA = true`: each pruning rule of step 4 and its symmetric version is
///   tested by its own `if` and every rule that holds is applied, as in the thesis's
///   Code 3.1: besides the cut of the chain whose median ends lower (rises higher), the
///   other chain loses the part below (above) its median edge when that edge reaches
///   past the new end of I, so one iteration may halve both chains.
///
/// Both give the same answers and certificates that verify, with the same predicates
/// and the same closed tests; only the path (and so the cost) differs.
///
/// ```
/// use polysect::{ConvexPolygon, intersect::{ArrayIntersection, DobkinVariant}};
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let touching = ConvexPolygon::new([[2.0, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// let apart = ConvexPolygon::new([[2.5, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// assert!(DobkinVariant::<true>.intersects(&p, &touching));
/// assert!(!DobkinVariant::<true>.intersects(&p, &apart));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct DobkinVariant<const LEMMA_BY_LEMMA: bool>;

/// [`Dobkin`]'s choice.
type Ours = DobkinVariant<false>;

impl ArrayIntersection for Dobkin {
    const NAME: &'static str = "dobkin";

    array_entry_points!(all);
}

impl ArrayEngine for Dobkin {
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

impl<const LEMMA_BY_LEMMA: bool> ArrayIntersection for DobkinVariant<LEMMA_BY_LEMMA> {
    const NAME: &'static str = "dobkin-variant";

    array_entry_points!(all);
}

impl<const LEMMA_BY_LEMMA: bool> ArrayEngine for DobkinVariant<LEMMA_BY_LEMMA> {
    fn intersects_probed<K: Kernel, P: Probe>(
        &self,
        k: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> bool {
        let k = k.within([p.bounding_box(), q.bounding_box()]);
        run::<_, _, _, LEMMA_BY_LEMMA>(k, p.vertices(), q.vertices(), probe, |outcome, _| {
            outcome == Outcome::Meet
        })
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
        let (pv, qv) = (p.vertices(), q.vertices());
        // Each derivation builds its `Derivation` in place (no copy of the certificate
        // on the way out).
        run::<_, _, _, LEMMA_BY_LEMMA>(k, pv, qv, probe, |outcome, searches| match outcome {
            Outcome::Apart(s) => separation(k, searches, s),
            Outcome::Meet => meeting(k, searches),
        })
    }
}
