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
//!    certificates, 7.5–9.8% more instructions per query (docs/results.md).
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

use super::certificate::{Boundary, from_faces, resolve_chords, separates};
use super::{ArrayIntersection, Certificate, Derivation, Probe, Which};
use crate::kernel::{Kernel, Orientation, Point};
use crate::polygon::ConvexPolygon;

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

/// How both chain-pair searches ended (each search's `verdict` says why).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Outcome {
    /// Search `s` found its regions disjoint: the polygons are disjoint.
    Apart(usize),
    /// Both searches met.
    Meet,
}

/// The witness of two searches that both met: the vertex each tested, if it lies in
/// the other polygon ([`vertex_inside`]), else the edge beside it ([`beside`]); only
/// the answer if none holds.
fn meeting<K: Kernel>(k: K, searches: &[PairSearch<'_>; 2]) -> Derivation {
    let mut missed = [None; 2];
    for (s, slot) in missed.iter_mut().enumerate() {
        if let Some(t) = searches[s].met() {
            match vertex_inside(k, searches, s, t) {
                Ok(c) => return Derivation::Certified(c),
                Err(g) => *slot = g.map(|g| (t, g)),
            }
        }
    }
    match (0..2).find_map(|s| missed[s].and_then(|(t, g)| beside(k, searches, s, t, g))) {
        Some(c) => Derivation::Certified(c),
        None => Derivation::Answer(true),
    }
}

/// The height test where search `s` met tested a vertex w inside one of the other
/// polygon's chains; if w also lies inside that polygon's opposite chain at its height
/// (found by a binary search on heights, then one `orient`), w is a vertex inside.
/// Otherwise `Err` with the position in that opposite chain of its vertex at or next to
/// w's height (`None` if w's height is outside the chain).
fn vertex_inside<K: Kernel>(
    k: K,
    searches: &[PairSearch<'_>; 2],
    s: usize,
    t: Tested,
) -> Result<Certificate, Option<usize>> {
    let other = &searches[1 - s];
    let w = t.w.p;
    let ((inside, pos), of) = match t.w.side {
        // w is a vertex of this search's left-chain polygon A, inside R_B at its height:
        // it is in B iff it is also inside L_B, the other search's left chain.
        Side::Left => {
            let len = other.l.len;
            if !(other.lp(len - 1).y <= w.y && w.y <= other.lp(0).y) {
                return Err(None);
            }
            (other.inside_left_whole(k, w), SEARCH_A[s])
        }
        // w is a vertex of B, inside L_A: it is in A iff also inside R_A.
        Side::Right => {
            let len = other.r.len;
            if !(other.rp(0).y <= w.y && w.y <= other.rp(len - 1).y) {
                return Err(None);
            }
            (other.inside_right_whole(k, w), SEARCH_A[s].other())
        }
    };
    if inside {
        Ok(Certificate::VertexInside { of, point: w })
    } else {
        Err(Some(pos))
    }
}

/// Where [`vertex_inside`] failed: w, a vertex of polygon X on one of its chains, lies
/// inside Y's opposite chain at its height (the search's test) but outside Y's chain on
/// w's side, whose edge g at that height (at position `g` of that chain) passes beyond
/// w at the point Z. If Z is in X, it lies on the horizontal segment from w to X's
/// other chain, inside the triangle of w and X's edge r at that height (one binary
/// search on heights): then an end of g lies in the triangle (a vertex inside), or r
/// meets g (crossing edges), or g crosses a chord from w to an end of r, resolved
/// with [`resolve_chords`]. `None` when Z is not in X (the polygons meet at other
/// heights). Out of line: one query in five gets here.
#[inline(never)]
fn beside<K: Kernel>(
    k: K,
    searches: &[PairSearch<'_>; 2],
    s: usize,
    t: Tested,
    g: usize,
) -> Option<Certificate> {
    let (this, other) = (&searches[s], &searches[1 - s]);
    let w = t.w.p;
    // Both chains are the other search's: X's chain opposite w and Y's on w's side.
    let (x_side, y_side, x_poly, y_poly, x_which) = match t.w.side {
        Side::Left => (Side::Right, Side::Left, other.rv, other.lv, SEARCH_A[s]),
        Side::Right => (Side::Left, Side::Right, other.lv, other.rv, SEARCH_A[s].other()),
    };
    let (x_len, y_len) = match x_side {
        Side::Right => (other.r.len, other.l.len),
        Side::Left => (other.l.len, other.r.len),
    };
    if x_len < 2 || y_len < 2 {
        return None;
    }
    let r = match x_side {
        Side::Right => other.right_position(w.y),
        Side::Left => other.left_position(w.y),
    }
    .min(x_len - 2);
    let g = g.min(y_len - 2);
    let xi = [other.index(x_side, r), other.index(x_side, r + 1)];
    let yi = [other.index(y_side, g), other.index(y_side, g + 1)];
    let iw = this.index(t.w.side, this.position(t.w));
    if x_poly[iw] != w {
        return None;
    }
    let inside = || {
        let tri = [w, x_poly[xi[0]], x_poly[xi[1]]];
        let o = k.orient(tri[0], tri[1], tri[2]);
        if o == Orientation::Collinear {
            return None;
        }
        yi.iter()
            .map(|&i| y_poly[i])
            .find(|&y| (0..3).all(|a| k.orient(tri[a], tri[(a + 1) % 3], y) != o.reverse()))
            .map(|point| Certificate::VertexInside { of: Which::Q, point })
    };
    let found = inside()
        .or_else(|| resolve_chords(k, x_poly, (xi[0], xi[1]), y_poly, (yi[0], yi[1])))
        .or_else(|| {
            xi.iter()
                .filter(|&&i| i != iw)
                .find_map(|&i| resolve_chords(k, x_poly, (iw, i), y_poly, (yi[0], yi[1])))
        })?;
    Some(found.relative_to(x_which))
}

/// The polygon that owns the left chain of each chain-pair search (the other owns the
/// right chain): search 0 is L_P against R_Q, search 1 is L_Q against R_P.
const SEARCH_A: [Which; 2] = [Which::P, Which::Q];

/// Runs both chain-pair searches until one finds its regions disjoint (the polygons
/// are disjoint) or both meet.
/// Then hands the outcome and the searches to `then` (so that they stay on this frame).
#[inline]
fn run<K: Kernel, P: Probe, T, const LEMMA_BY_LEMMA: bool>(
    k: K,
    pv: &[Point],
    qv: &[Point],
    probe: &mut P,
    then: impl FnOnce(Outcome, &[PairSearch<'_>; 2]) -> T,
) -> T {
    let [p_top, p_bottom, q_top, q_bottom] = extremes(k, pv, qv);
    let (pl, pr) = chains(pv, p_top, p_bottom);
    let (ql, qr) = chains(qv, q_top, q_bottom);
    // Both chain pairs advance in lockstep: their memory accesses are
    // independent, so the processor overlaps the cache misses on large arrays.
    let mut searches = [PairSearch::new(pv, pl, qv, qr), PairSearch::new(qv, ql, pv, pr)];
    let [a, b] = &mut searches;
    let (mut ra, mut rb) = (None, None);
    let outcome = loop {
        if ra.is_none() {
            ra = a.step::<K, P, LEMMA_BY_LEMMA>(k, probe);
            if ra == Some(false) {
                break Outcome::Apart(0);
            }
        }
        if rb.is_none() {
            rb = b.step::<K, P, LEMMA_BY_LEMMA>(k, probe);
            if rb == Some(false) {
                break Outcome::Apart(1);
            }
        }
        if ra.is_some() && rb.is_some() {
            break Outcome::Meet;
        }
    };
    then(outcome, &searches)
}

/// A separating edge of two polygons found disjoint by Dobkin's test, or `None` when
/// the test finds them intersecting: [`Barba`](super::Barba)'s certified call falls
/// back on this when its last separating line does not lift to the whole polygons.
pub(crate) fn separating_certificate<K: Kernel>(k: K, pv: &[Point], qv: &[Point]) -> Option<Certificate> {
    run::<_, _, _, false>(k, pv, qv, &mut (), |outcome, searches| match outcome {
        Outcome::Apart(s) => match separation(k, searches, s) {
            Derivation::Certified(c) => Some(c),
            Derivation::Answer(_) => None,
        },
        Outcome::Meet => None,
    })
}

/// The separating edge of search `s`, which found its regions disjoint; only the
/// answer if none is found.
fn separation<K: Kernel>(k: K, searches: &[PairSearch<'_>; 2], s: usize) -> Derivation {
    let found = match searches[s].verdict() {
        Some(Verdict::Apart(why)) => searches[s].separation(k, why),
        _ => None,
    };
    match found {
        Some(c) => Derivation::Certified(c.relative_to(SEARCH_A[s])),
        None => Derivation::Answer(false),
    }
}

/// A chain: `len` consecutive vertices of a polygon starting at array index `start`.
#[derive(Clone, Copy, Debug)]
struct Chain {
    start: usize,
    len: usize,
}

/// The vertex at position `pos` of a chain.
#[inline]
fn at(v: &[Point], c: Chain, pos: usize) -> Point {
    let i = c.start + pos;
    v[if i >= v.len() { i - v.len() } else { i }]
}

/// Direction classes of an edge, counter-clockwise from east, decided by comparing
/// the endpoints' coordinates (no arithmetic).
const EAST: u8 = 0;
const UP: u8 = 1;
const WEST: u8 = 2;
const DOWN: u8 = 3;

#[inline]
fn class(a: Point, b: Point) -> u8 {
    if b.y > a.y {
        UP
    } else if b.y < a.y {
        DOWN
    } else if b.x > a.x {
        EAST
    } else {
        WEST
    }
}

/// The left chain (top to bottom, strictly descending) and the right chain (bottom
/// to top, strictly ascending) of a counter-clockwise polygon, given the first
/// downward edge (`top`) and the first upward edge (`bottom`).
fn chains(v: &[Point], top_left: usize, bottom_right: usize) -> (Chain, Chain) {
    let n = v.len();
    let edge_class = |i: usize| class(v[i], v[(i + 1) % n]);
    let before = |i: usize| (i + n - 1) % n;
    let top_right = if edge_class(before(top_left)) == WEST {
        before(top_left)
    } else {
        top_left
    };
    let bottom_left = if edge_class(before(bottom_right)) == EAST {
        before(bottom_right)
    } else {
        bottom_right
    };
    let span = |from: usize, to: usize| Chain {
        start: from,
        len: (to + n - from) % n + 1,
    };
    (span(top_left, bottom_left), span(bottom_right, top_right))
}

/// The starts of the first downward and the first upward edge of `p` and of `q`
/// (each the first edge of its class following an edge of another class): four
/// binary searches over the edges' turn from edge 0, run in lockstep so that their
/// independent memory accesses overlap. The turn is measured in classes rotated so
/// that edge 0's class is 0; edges of edge 0's class turned less than edge 0 (one
/// `cross`) come last (rank 4), so the rank grows monotonically along the array.
fn extremes<K: Kernel>(k: K, p: &[Point], q: &[Point]) -> [usize; 4] {
    let polys = [p, p, q, q];
    let targets = [DOWN, UP, DOWN, UP];
    let c0 = polys.map(|v| class(v[0], v[1]));
    let goal: [u8; 4] = std::array::from_fn(|s| match (targets[s] + 4 - c0[s]) % 4 {
        0 => 4,
        r => r,
    });
    let rank = |s: usize, i: usize| {
        let v = polys[s];
        let (a, b) = (v[i], v[(i + 1) % v.len()]);
        let r = (class(a, b) + 4 - c0[s]) % 4;
        if r == 0 && i > 0 && k.cross(v[0], v[1], a, b) == Orientation::Cw {
            4
        } else {
            r
        }
    };
    let mut lo = [0; 4];
    let mut hi = polys.map(|v| v.len());
    loop {
        let mut active = false;
        for s in 0..4 {
            if lo[s] < hi[s] {
                active = true;
                let mid = lo[s] + (hi[s] - lo[s]) / 2;
                if rank(s, mid) >= goal[s] {
                    hi[s] = mid;
                } else {
                    lo[s] = mid + 1;
                }
            }
        }
        if !active {
            return std::array::from_fn(|s| lo[s] % polys[s].len());
        }
    }
}

/// Which chain a vertex bounding the y-interval belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Side {
    Left,
    Right,
}

/// A vertex bounding the common y-interval: its chain and its point (its position is
/// found again by [`PairSearch::position`] when a certificate needs it).
#[derive(Clone, Copy, Debug)]
struct Bound {
    side: Side,
    p: Point,
}

/// A height test at the bounding vertex `w`: `other` is the position in the other chain
/// of the vertex at or just below (right chain) or above (left chain) that height, the
/// start of the other chain's edge there.
#[derive(Clone, Copy, Debug)]
struct Tested {
    w: Bound,
    other: usize,
}

/// Why a chain-pair search found its two regions disjoint.
#[derive(Clone, Copy, Debug)]
enum Apart {
    /// The y-ranges are disjoint: `lo` is the higher bottom, `hi` the lower top.
    Heights { lo: Bound, hi: Bound },
    /// g < 0 at its maximum, the height of this test (or of one of these two, where g
    /// is linear on the interval).
    At(Tested, Option<Tested>),
}

/// A decided chain-pair search.
#[derive(Clone, Copy, Debug)]
enum Verdict {
    /// The regions meet: a test found x_L ≤ x_R ([`PairSearch::met`] gives it).
    Meet,
    Apart(Apart),
}

/// The search of step 4 of the module docs: whether the region right of left chain
/// `l` (of polygon `lv`) meets the region left of right chain `r` (of polygon `rv`),
/// one pruning iteration per [`PairSearch::step`].
struct PairSearch<'a> {
    lv: &'a [Point],
    l: Chain,
    rv: &'a [Point],
    r: Chain,
    /// Left positions `i0..=i1` descend from top to bottom; right `j0..=j1` ascend.
    i0: usize,
    i1: usize,
    j0: usize,
    j1: usize,
    /// The vertices whose heights bound the common y-interval I.
    lo: Bound,
    hi: Bound,
    /// Which height test decided the search (read back by [`PairSearch::verdict`]).
    decided: Decided,
}

/// Which test decided a chain-pair search: each test's answer and the position it
/// found in the other chain.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Decided {
    Not,
    /// The y-ranges are disjoint.
    Heights,
    /// The test at `lo`, or at `hi`.
    Lo(bool, usize),
    Hi(bool, usize),
    /// g linear on I: the test at `lo`, then (if it failed) the one at `hi`.
    Both((bool, usize), Option<(bool, usize)>),
}

impl<'a> PairSearch<'a> {
    fn new(lv: &'a [Point], l: Chain, rv: &'a [Point], r: Chain) -> Self {
        let (i0, i1, j0, j1) = (0, l.len - 1, 0, r.len - 1);
        let (lt, lb) = (at(lv, l, i0), at(lv, l, i1));
        let (rb, rt) = (at(rv, r, j0), at(rv, r, j1));
        let bound = |side, p| Bound { side, p };
        let lo = if lb.y >= rb.y {
            bound(Side::Left, lb)
        } else {
            bound(Side::Right, rb)
        };
        let hi = if lt.y <= rt.y {
            bound(Side::Left, lt)
        } else {
            bound(Side::Right, rt)
        };
        PairSearch {
            lv,
            l,
            rv,
            r,
            i0,
            i1,
            j0,
            j1,
            lo,
            hi,
            decided: Decided::Not,
        }
    }

    #[inline]
    fn lp(&self, i: usize) -> Point {
        at(self.lv, self.l, i)
    }

    #[inline]
    fn rp(&self, j: usize) -> Point {
        at(self.rv, self.r, j)
    }

    /// Is `x_L ≤ x_R` at the height of the bounding vertex `w`? With the position in
    /// the other chain of the vertex at or next to that height.
    #[inline]
    fn test<K: Kernel>(&self, k: K, w: Bound) -> (bool, usize) {
        match w.side {
            Side::Left => inside_right_chain(k, &|j| self.rp(j), self.j0, self.j1, w.p),
            Side::Right => inside_left_chain(k, &|i| self.lp(i), self.i0, self.i1, w.p),
        }
    }

    /// Decides the search by one height test, where the maximum of g is.
    #[inline]
    fn at_height<K: Kernel>(&mut self, k: K, lo: bool) -> bool {
        let (inside, other) = self.test(k, if lo { self.lo } else { self.hi });
        self.decided = if lo {
            Decided::Lo(inside, other)
        } else {
            Decided::Hi(inside, other)
        };
        inside
    }

    /// Why the search was decided (its final state, which deciding leaves unchanged,
    /// and the deciding tests). For certificates only.
    #[inline]
    fn verdict(&self) -> Option<Verdict> {
        let at = |w: Bound, (inside, other): (bool, usize)| {
            let t = Tested { w, other };
            if inside {
                Verdict::Meet
            } else {
                Verdict::Apart(Apart::At(t, None))
            }
        };
        Some(match self.decided {
            Decided::Not => return None,
            Decided::Heights => Verdict::Apart(Apart::Heights {
                lo: self.lo,
                hi: self.hi,
            }),
            Decided::Lo(inside, other) => at(self.lo, (inside, other)),
            Decided::Hi(inside, other) => at(self.hi, (inside, other)),
            Decided::Both(lo, None) => at(self.lo, lo),
            Decided::Both(lo, Some(hi)) => match (at(self.lo, lo), at(self.hi, hi)) {
                (Verdict::Apart(Apart::At(a, _)), Verdict::Apart(Apart::At(b, _))) => {
                    Verdict::Apart(Apart::At(a, Some(b)))
                }
                (_, hi) => hi,
            },
        })
    }

    /// The test that decided the search if it met (`verdict` is then `Verdict::Meet`),
    /// read off the deciding test alone: the witness asks only this.
    #[inline]
    fn met(&self) -> Option<Tested> {
        let (w, other) = match self.decided {
            Decided::Lo(true, other) | Decided::Both((true, other), _) => (self.lo, other),
            Decided::Hi(true, other) | Decided::Both(_, Some((true, other))) => (self.hi, other),
            _ => return None,
        };
        Some(Tested { w, other })
    }

    /// Decides the search by the tests at both ends of I (g is linear there).
    #[inline]
    fn at_both_ends<K: Kernel>(&mut self, k: K) -> bool {
        let lo = self.test(k, self.lo);
        let hi = if lo.0 { None } else { Some(self.test(k, self.hi)) };
        self.decided = Decided::Both(lo, hi);
        lo.0 || hi.is_some_and(|h| h.0)
    }

    /// One pruning iteration; `Some(answer)` once the search is decided (then
    /// `verdict` says why).
    fn step<K: Kernel, P: Probe, const LEMMA_BY_LEMMA: bool>(&mut self, k: K, probe: &mut P) -> Option<bool> {
        // Only the heights are read on the way: copying the bounds costs more.
        let (lo_y, hi_y) = (self.lo.p.y, self.hi.p.y);
        if lo_y > hi_y {
            self.decided = Decided::Heights;
            return Some(false);
        }
        if lo_y == hi_y {
            return Some(self.at_height(k, true));
        }
        let (le, re) = (self.i1 - self.i0, self.j1 - self.j0);
        // Both chains linear on I (or, with an inconsistent kernel, a chain that no
        // longer covers I): g is linear, test both ends.
        if (le <= 1 && re <= 1) || le == 0 || re == 0 {
            return Some(self.at_both_ends(k));
        }
        probe.iteration();
        probe.kept(super::Kept::Dobkin {
            left: self.lv,
            l: super::Span::new(self.l.start + self.i0, le + 1),
            right: self.rv,
            r: super::Span::new(self.r.start + self.j0, re + 1),
            heights: [lo_y, hi_y],
        });
        let ke = self.i0 + le / 2; // e = (lp(ke), lp(ke + 1)), top to bottom
        let kf = self.j0 + re / 2; // f = (rp(kf), rp(kf + 1)), bottom to top
        let (e_top, e_bot) = (self.lp(ke), self.lp(ke + 1));
        let (f_bot, f_top) = (self.rp(kf), self.rp(kf + 1));
        let left = |p| Bound { side: Side::Left, p };
        let right = |p| Bound { side: Side::Right, p };
        // Two edges, short next to the polygons at large n: see `cross_of_short_edges`.
        let up = k.cross_of_short_edges(f_bot, f_top, e_bot, e_top) != Orientation::Cw;
        if LEMMA_BY_LEMMA {
            return self.lemma_by_lemma(k, up, [ke, kf], [e_top, e_bot, f_bot, f_top]);
        }
        if up {
            // s_R ≥ s_L: g is non-decreasing below min(top(e), top(f)).
            if e_top.y <= f_top.y {
                if e_top.y >= hi_y {
                    return Some(self.at_height(k, false));
                }
                self.i1 = ke;
                if e_top.y > lo_y {
                    self.lo = left(e_top);
                }
            } else {
                if f_top.y >= hi_y {
                    return Some(self.at_height(k, false));
                }
                self.j0 = kf + 1;
                if f_top.y > lo_y {
                    self.lo = right(f_top);
                }
            }
        } else if e_bot.y >= f_bot.y {
            // s_R < s_L: g is decreasing above max(bottom(e), bottom(f)).
            if e_bot.y <= lo_y {
                return Some(self.at_height(k, true));
            }
            self.i0 = ke + 1;
            if e_bot.y < hi_y {
                self.hi = left(e_bot);
            }
        } else {
            if f_bot.y <= lo_y {
                return Some(self.at_height(k, true));
            }
            self.j1 = kf;
            if f_bot.y < hi_y {
                self.hi = right(f_bot);
            }
        }
        None
    }

    /// One iteration of [`DobkinVariant<true>`]: every pruning rule tested by its own
    /// `if` (the thesis's Code 3.1 form), given the slope comparison `up` (s_R ≥ s_L),
    /// the medians' positions `[ke, kf]` and their points `[e_top, e_bot, f_bot, f_top]`.
    #[inline]
    fn lemma_by_lemma<K: Kernel>(
        &mut self,
        k: K,
        up: bool,
        [ke, kf]: [usize; 2],
        [e_top, e_bot, f_bot, f_top]: [Point; 4],
    ) -> Option<bool> {
        let (lo_y, hi_y) = (self.lo.p.y, self.hi.p.y);
        let left = |p| Bound { side: Side::Left, p };
        let right = |p| Bound { side: Side::Right, p };
        if up {
            // g is non-decreasing below min(top(e), top(f)): if that is at or above the
            // top of I, the maximum is there.
            if e_top.y.min(f_top.y) >= hi_y {
                return Some(self.at_height(k, false));
            }
            // e ends no higher than f: L below e is pruned and I starts at top(e).
            if e_top.y <= f_top.y {
                self.i1 = ke;
                if e_top.y > lo_y {
                    self.lo = left(e_top);
                }
            }
            // Its symmetric version: f ends lower, R below f is pruned.
            if f_top.y < e_top.y {
                self.j0 = kf + 1;
                if f_top.y > lo_y {
                    self.lo = right(f_top);
                }
            }
            // f starts at or below the start of I: R below f is pruned (f covers it).
            if f_bot.y <= self.lo.p.y {
                self.j0 = self.j0.max(kf);
            }
            // Its symmetric version: L below e is pruned.
            if e_bot.y <= self.lo.p.y {
                self.i1 = self.i1.min(ke + 1);
            }
        } else {
            // g is decreasing above max(bottom(e), bottom(f)): if that is at or below
            // the bottom of I, the maximum is there.
            if e_bot.y.max(f_bot.y) <= lo_y {
                return Some(self.at_height(k, true));
            }
            // e starts no lower than f: L above e is pruned and I ends at bottom(e).
            if e_bot.y >= f_bot.y {
                self.i0 = ke + 1;
                if e_bot.y < hi_y {
                    self.hi = left(e_bot);
                }
            }
            // Its symmetric version: f starts higher, R above f is pruned.
            if f_bot.y > e_bot.y {
                self.j1 = kf;
                if f_bot.y < hi_y {
                    self.hi = right(f_bot);
                }
            }
            // f ends at or above the end of I: R above f is pruned (f covers it).
            if f_top.y >= self.hi.p.y {
                self.j1 = self.j1.min(kf + 1);
            }
            // Its symmetric version: L above e is pruned.
            if e_top.y >= self.hi.p.y {
                self.i0 = self.i0.max(ke);
            }
        }
        None
    }

    /// The position of vertex `p` in its chain (chains are strictly monotone in y), for
    /// certificates only. A bound of I is an end of its chain's remaining range (a cut
    /// at a median edge moves the range's end and the bound to the same vertex), so the
    /// two ends are compared first; a binary search on heights otherwise.
    fn position(&self, b: Bound) -> usize {
        match b.side {
            Side::Left if self.lp(self.i1) == b.p => self.i1,
            Side::Left if self.lp(self.i0) == b.p => self.i0,
            Side::Left => first(self.l.len, |i| self.lp(i).y > b.p.y),
            Side::Right if self.rp(self.j0) == b.p => self.j0,
            Side::Right if self.rp(self.j1) == b.p => self.j1,
            Side::Right => first(self.r.len, |j| self.rp(j).y < b.p.y),
        }
    }

    /// The last position of the left chain at or above height `y` (0 if none), by a
    /// binary search on the chain's contiguous pieces: for certificates.
    #[inline]
    fn left_position(&self, y: f64) -> usize {
        chain_partition(self.lv, self.l, |p| p.y >= y).max(1) - 1
    }

    /// The last position of the right chain at or below height `y` (0 if none).
    #[inline]
    fn right_position(&self, y: f64) -> usize {
        chain_partition(self.rv, self.r, |p| p.y <= y).max(1) - 1
    }

    /// [`inside_left_chain`] on the whole left chain, for certificates.
    fn inside_left_whole<K: Kernel>(&self, k: K, w: Point) -> (bool, usize) {
        let lo = self.left_position(w.y);
        (inside_left_at(k, &|i| self.lp(i), lo, self.l.len - 1, w), lo)
    }

    /// [`inside_right_chain`] on the whole right chain, for certificates.
    fn inside_right_whole<K: Kernel>(&self, k: K, w: Point) -> (bool, usize) {
        let lo = self.right_position(w.y);
        (inside_right_at(k, &|j| self.rp(j), lo, self.r.len - 1, w), lo)
    }

    /// The array index of a chain position.
    #[inline]
    fn index(&self, side: Side, pos: usize) -> usize {
        let (v, c) = match side {
            Side::Left => (self.lv, self.l),
            Side::Right => (self.rv, self.r),
        };
        (c.start + pos) % v.len()
    }

    /// A separating edge of the two polygons once this search found its regions
    /// disjoint, named with the left chain's polygon as P (module docs, "Certificate").
    fn separation<K: Kernel>(&self, k: K, why: Apart) -> Option<Certificate> {
        let (a, b) = (self.lv, self.rv);
        match why {
            // The y-ranges are disjoint: the polygon whose bottom is `lo` lies above.
            Apart::Heights { lo, hi } => {
                debug_assert!(lo.p.y > hi.p.y && lo.side != hi.side);
                if lo.side == Side::Left {
                    // A above B: A's bottom-left ends its left chain, B's top-right its
                    // right chain.
                    let x = self.index(Side::Left, self.l.len - 1);
                    let y = self.index(Side::Right, self.r.len - 1);
                    apart_in_height(k, a, x, b, y)
                } else {
                    // B above A: B's bottom-left is its right chain's start or the vertex
                    // before it (a horizontal bottom), A's top-right the left chain's
                    // start or the vertex before it.
                    let x = level_prev(b, self.index(Side::Right, 0));
                    let y = level_prev(a, self.index(Side::Left, 0));
                    apart_in_height(k, b, x, a, y).map(Certificate::swapped)
                }
            }
            Apart::At(t, other) => self
                .separation_at(k, t)
                .or_else(|| other.and_then(|t| self.separation_at(k, t))),
        }
    }

    /// Whether the failed height test at `t` was decided by `orient` of the tested vertex
    /// against the other chain's edge at `t.other` (then that `orient` was `Cw`), rather
    /// than by comparing x coordinates (a vertex at the same height, or the range's
    /// last position): see [`inside_right_at`] and [`inside_left_at`].
    #[inline]
    fn failed_by_orient(&self, t: Tested) -> bool {
        match t.w.side {
            Side::Left => t.other != self.j1 && self.rp(t.other).y != t.w.p.y,
            Side::Right => t.other != self.i1 && self.lp(t.other).y != t.w.p.y,
        }
    }

    /// Candidates at the height of a failed test where g is maximal: the tested vertex
    /// and the other chain's edge there (then their neighbours).
    fn separation_at<K: Kernel>(&self, k: K, t: Tested) -> Option<Certificate> {
        let (a, b) = (self.lv, self.rv);
        let w = self.index(t.w.side, self.position(t.w));
        let (other_side, other_len) = match t.w.side {
            Side::Left => (Side::Right, self.r.len),
            Side::Right => (Side::Left, self.l.len),
        };
        let e0 = self.index(other_side, t.other);
        let mut edge = [e0, e0];
        let mut len = 1;
        if t.other + 1 < other_len {
            edge[1] = self.index(other_side, t.other + 1);
            len = 2;
        }
        let (wv, ev) = if t.w.side == Side::Left { (a, b) } else { (b, a) };
        // The certificate names the left chain's polygon as P.
        let (e_of, w_of) = if t.w.side == Side::Left {
            (Which::Q, Which::P)
        } else {
            (Which::P, Which::Q)
        };
        let edge_of = |of, u: usize, v: usize, poly: &[Point]| Certificate::Separated {
            of,
            from: poly[u],
            to: poly[v],
        };
        if len == 2 {
            // Where g is maximal inside I the other chain's edge there is the separating
            // edge (the slopes bracket it): try it first; then the faces {w} and e as
            // `from_faces` would, without e again: the edges next to e against w, w's
            // edges against e's ends.
            // The failed test found w strictly outside e by this `orient` unless it
            // compared x coordinates instead: only the local test is left then.
            let (e0, e1) = (edge[0], edge[1]);
            if (self.failed_by_orient(t) || k.orient(ev[e0], ev[e1], wv[w]) == Orientation::Cw)
                && deepest_against(k, ev[e0], ev[e1], wv, w)
            {
                return Some(edge_of(e_of, e0, e1, ev));
            }
            for (u, v) in [(ev.prev(e0), e0), (e1, ev.next(e1))] {
                if separates(k, ev[u], ev[v], wv, w) {
                    return Some(edge_of(e_of, u, v, ev));
                }
            }
            for (u, v) in [(wv.prev(w), w), (w, wv.next(w))] {
                if separates(k, wv[u], wv[v], ev, e0) || separates(k, wv[u], wv[v], ev, e1) {
                    return Some(edge_of(w_of, u, v, wv));
                }
            }
        }
        let wide_w = [w, wv.prev(w), wv.next(w)];
        let wide_e = [ev.prev(edge[0]), edge[0], edge[len - 1], ev.next(edge[len - 1])];
        let found = |fw: &[usize], fe: &[usize]| {
            if t.w.side == Side::Left {
                from_faces(k, a, fw, b, fe)
            } else {
                from_faces(k, b, fw, a, fe).map(Certificate::swapped)
            }
        };
        if len == 1
            && let Some(c) = found(&[w], &edge[..1])
        {
            return Some(c);
        }
        found(&wide_w, &wide_e)
    }
}

/// Whether vertex `w` of `b` is locally, hence (convexity) globally, the deepest of `b`
/// against the line `u` → `v`: [`separates`] without its `orient`.
#[inline]
fn deepest_against<K: Kernel>(k: K, u: Point, v: Point, b: &[Point], w: usize) -> bool {
    let x = b[w];
    k.cross(u, v, x, b[b.next(w)]) != Orientation::Ccw && k.cross(u, v, x, b[b.prev(w)]) != Orientation::Ccw
}

/// `v`'s vertex before `i` if the edge from it to `i` is horizontal, else `i`.
#[inline]
fn level_prev(v: &[Point], i: usize) -> usize {
    let j = v.prev(i);
    if v[j].y == v[i].y { j } else { i }
}

/// The separating edge of polygons `xv` and `yv` when all of `xv` lies strictly above
/// all of `yv`, from `xv`'s bottom-left vertex `x` and `yv`'s top-right vertex `y`
/// (named with `xv` as P). `x − y` is the lowest (then leftmost) vertex of the
/// Minkowski difference X − Y, and 0 lies strictly below it, so one of the two edges
/// of X − Y at `x − y` has 0 strictly on its outer side (module docs of
/// [`certificate`](super::certificate)): the edge leaving it is the one of X at `x` or
/// of Y at `y` that turns least from east, the edge arriving the one that turns most
/// from west. Each is a cross product to choose the edge and an `orient` to test it;
/// `None` only if both tests fail (never under the exact kernel).
fn apart_in_height<K: Kernel>(k: K, xv: &[Point], x: usize, yv: &[Point], y: usize) -> Option<Certificate> {
    use Orientation::{Ccw, Cw};
    let (x0, y0) = (xv[x], yv[y]);
    let x_edge = |from: Point, to: Point| Certificate::Separated {
        of: Which::P,
        from,
        to,
    };
    let y_edge = |from: Point, to: Point| Certificate::Separated {
        of: Which::Q,
        from,
        to,
    };
    // Leaving x − y: X's edge x → next(x) or −Y's, parallel to y → next(y) reversed.
    let (xn, yn) = (xv[xv.next(x)], yv[yv.next(y)]);
    if k.cross(x0, xn, yn, y0) == Cw {
        if k.orient(y0, yn, x0) == Cw {
            return Some(y_edge(y0, yn));
        }
    } else if k.orient(x0, xn, y0) == Cw {
        return Some(x_edge(x0, xn));
    }
    // Arriving at x − y: X's edge prev(x) → x or −Y's, parallel to prev(y) → y reversed.
    let (xp, yp) = (xv[xv.prev(x)], yv[yv.prev(y)]);
    if k.cross(xp, x0, y0, yp) == Ccw {
        (k.orient(yp, y0, x0) == Cw).then(|| y_edge(yp, y0))
    } else {
        (k.orient(xp, x0, y0) == Cw).then(|| x_edge(xp, x0))
    }
}

/// The first position in `0..len` (the last if none) where `before` turns false;
/// `before` must be true on a prefix and false after it.
fn first(len: usize, before: impl Fn(usize) -> bool) -> usize {
    let (mut lo, mut hi) = (0, len - 1);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if before(mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}

/// Whether `w` lies on or left of the ascending right chain (positions `j0..=j1`) at
/// the height of `w`, and the position of the chain's vertex at or just below it.
fn inside_right_chain<K: Kernel>(
    k: K,
    rp: &impl Fn(usize) -> Point,
    j0: usize,
    j1: usize,
    w: Point,
) -> (bool, usize) {
    // Last position with y ≤ w.y (clamped to the range).
    let (mut lo, mut hi) = (j0, j1);
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        if rp(mid).y <= w.y {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    (inside_right_at(k, rp, lo, j1, w), lo)
}

/// Whether `w` lies on or left of the ascending right chain at its height, given the
/// position `lo` of the chain's vertex at or just below it (`last`: the last position).
#[inline]
fn inside_right_at<K: Kernel>(k: K, rp: &impl Fn(usize) -> Point, lo: usize, last: usize, w: Point) -> bool {
    let a = rp(lo);
    if a.y == w.y || lo == last {
        return w.x <= a.x;
    }
    k.orient(a, rp(lo + 1), w) != Orientation::Cw
}

/// Whether `w` lies on or right of the descending left chain (positions `i0..=i1`)
/// at the height of `w`, and the position of the chain's vertex at or just above it.
fn inside_left_chain<K: Kernel>(
    k: K,
    lp: &impl Fn(usize) -> Point,
    i0: usize,
    i1: usize,
    w: Point,
) -> (bool, usize) {
    // Last position with y ≥ w.y (clamped to the range).
    let (mut lo, mut hi) = (i0, i1);
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        if lp(mid).y >= w.y {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    (inside_left_at(k, lp, lo, i1, w), lo)
}

/// Whether `w` lies on or right of the descending left chain at its height, given the
/// position `lo` of the chain's vertex at or just above it (`last`: the last position).
#[inline]
fn inside_left_at<K: Kernel>(k: K, lp: &impl Fn(usize) -> Point, lo: usize, last: usize, w: Point) -> bool {
    let a = lp(lo);
    if a.y == w.y || lo == last {
        return a.x <= w.x;
    }
    k.orient(a, lp(lo + 1), w) != Orientation::Cw
}

/// The number of leading positions of chain `c` of `v` whose vertices satisfy `before`
/// (true on a prefix of the chain): `partition_point` on the chain's one or two
/// contiguous pieces of the array.
fn chain_partition(v: &[Point], c: Chain, before: impl Fn(&Point) -> bool) -> usize {
    let end = c.start + c.len;
    if end <= v.len() {
        return v[c.start..end].partition_point(before);
    }
    // Wrapped: the head's last vertex says which piece holds the boundary, so only
    // that piece is searched.
    let head = &v[c.start..];
    if before(&v[v.len() - 1]) {
        head.len() + v[..end - v.len()].partition_point(before)
    } else {
        head.partition_point(before)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Exact;

    fn poly(pts: &[[f64; 2]]) -> ConvexPolygon {
        ConvexPolygon::new(pts.iter().copied()).unwrap()
    }

    #[test]
    fn chains_with_horizontal_top_and_bottom() {
        // A square starting at every vertex: top-left is (0,2), bottom-right (2,0).
        let sq = [[0., 0.], [2., 0.], [2., 2.], [0., 2.]];
        for s in 0..4 {
            let pts: Vec<[f64; 2]> = (0..4).map(|i| sq[(s + i) % 4]).collect();
            let p = poly(&pts);
            let v = p.vertices();
            let [t, b, _, _] = extremes(Exact, v, v);
            let (l, r) = chains(v, t, b);
            assert_eq!(
                (at(v, l, 0), at(v, l, l.len - 1)),
                (Point::new(0., 2.), Point::new(0., 0.))
            );
            assert_eq!(
                (at(v, r, 0), at(v, r, r.len - 1)),
                (Point::new(2., 0.), Point::new(2., 2.))
            );
            assert_eq!((l.len, r.len), (2, 2));
        }
        // A diamond: single top and bottom vertices shared by both chains.
        let d = poly(&[[0., -1.], [1., 0.], [0., 1.], [-1., 0.]]);
        let [t, b, _, _] = extremes(Exact, d.vertices(), d.vertices());
        let (l, r) = chains(d.vertices(), t, b);
        assert_eq!((l.len, r.len), (3, 3));
        assert_eq!(at(d.vertices(), l, 0), Point::new(0., 1.));
        assert_eq!(at(d.vertices(), r, 0), Point::new(0., -1.));
    }

    /// Dobkin's own derivation (no completing search) and its verification, for both
    /// orders of the pair and every start index of small polygons.
    fn certifies_itself(p: &ConvexPolygon, q: &ConvexPolygon, what: &str) {
        let starts = |c: &ConvexPolygon| if c.len() <= 8 { c.len() } else { 2 };
        for (a, b) in [(p, q), (q, p)] {
            for i in 0..starts(a) {
                for j in 0..starts(b) {
                    let (a, b) = (a.starting_at(i), b.starting_at(j));
                    let want = crate::intersect::Linear.intersects(&a, &b);
                    match Dobkin.derive_probed(Exact, &a, &b, &mut ()) {
                        Derivation::Certified(c) => {
                            assert_eq!(c.intersects(), want, "{what}: {c:?}");
                            assert_eq!(
                                crate::intersect::verify(&a, &b, &c),
                                Ok(()),
                                "{what}: {c:?}\n{a:?}\n{b:?}"
                            );
                        }
                        Derivation::Answer(answer) => {
                            assert_eq!(answer, want, "{what}");
                            assert!(answer, "{what}: a disjoint pair not certified\n{a:?}\n{b:?}");
                        }
                    }
                }
            }
        }
    }

    /// `q` moved straight up until its lowest vertex is just above `p`'s highest one
    /// (one ulp where the translation allows it), and `dx` sideways.
    fn stacked(p: &ConvexPolygon, q: &ConvexPolygon, dx: f64) -> Option<ConvexPolygon> {
        let top = p.vertices().iter().map(|v| v.y).fold(f64::MIN, f64::max);
        let bottom = q.vertices().iter().map(|v| v.y).fold(f64::MAX, f64::min);
        let mut dy = top - bottom;
        for _ in 0..64 {
            let moved = q.map(|v| Point::new(v.x + dx, v.y + dy)).ok()?;
            if moved.vertices().iter().all(|v| v.y > top) {
                return Some(moved);
            }
            dy = dy.next_up();
        }
        None
    }

    #[test]
    fn disjoint_heights_certified_from_the_lowest_vertex_of_the_difference() {
        // Horizontal tops and bottoms: squares and triangles stacked with every
        // horizontal offset, one ulp apart and far apart.
        let sq = poly(&[[0., 0.], [2., 0.], [2., 2.], [0., 2.]]);
        let tri_up = poly(&[[0., 0.], [2., 0.], [1., 1.]]);
        let tri_down = poly(&[[1., 0.], [2., 1.], [0., 1.]]);
        for lower in [&sq, &tri_up, &tri_down] {
            for upper in [&sq, &tri_up, &tri_down] {
                for dx in [-3., -2., -1.5, -1., -0.5, 0., 0.5, 1., 1.5, 2., 3.] {
                    let q = stacked(lower, upper, dx).unwrap();
                    certifies_itself(lower, &q, &format!("stacked one ulp apart, dx = {dx}"));
                    let far = q.map(|v| Point::new(v.x, v.y + 5.)).unwrap();
                    certifies_itself(lower, &far, &format!("stacked apart, dx = {dx}"));
                }
            }
        }
        // Every generator family, stacked with random offsets, and carried to the
        // extremes of f64.
        use crate::generate::{self, Family, Relation};
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::SmallRng::seed_from_u64(0xd0b1);
        for &family in Family::ALL {
            for i in 0..24 {
                let n = [3, 4, 5, 7, 12, 40, 300][i % 7];
                let (p, q) = generate::pair(family, n, Relation::Any, &mut rng);
                let b = p.bounding_box();
                let width = b.max.x - b.min.x;
                let dx = rng.random_range(-1.0..1.0) * width;
                let Some(q) = stacked(&p, &q, dx) else { continue };
                let what = format!("{family} n={n} #{i}");
                certifies_itself(&p, &q, &what);
                for scale in [2f64.powi(-1000), 2f64.powi(600)] {
                    if let Some((p, q)) =
                        generate::map_pair(&(p.clone(), q.clone()), |v| Point::new(v.x * scale, v.y * scale))
                    {
                        certifies_itself(&p, &q, &format!("{what} scaled {scale:e}"));
                    }
                }
            }
        }
    }

    #[test]
    fn disjoint_pairs_certified_by_the_search_itself() {
        // The faces at the maximum of g, where the failed test's `orient` is reused:
        // every family's disjoint pairs (touching families: their one-ulp gaps and
        // shared-edge neighbours), and the extremes of f64.
        use crate::generate::{self, Family, Relation};
        use rand::SeedableRng;
        let mut rng = rand::rngs::SmallRng::seed_from_u64(0xd0b2);
        for &family in Family::ALL {
            for i in 0..30 {
                let n = [3, 4, 6, 9, 17, 64, 500][i % 7];
                let (p, q) = generate::pair(family, n, Relation::Disjoint, &mut rng);
                let what = format!("{family} n={n} #{i}");
                certifies_itself(&p, &q, &what);
                let o = 2f64.powi(52);
                if let Some((p, q)) = generate::map_pair(&(p, q), |v| Point::new(v.x + o, v.y - o)) {
                    certifies_itself(&p, &q, &format!("{what} offset 2^52"));
                }
            }
        }
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
            (&[[0., 2.], [2., 2.], [1., 3.]], true), // shared horizontal top edge
            (&[[0., 2.5], [2., 2.5], [1., 3.]], false),
            (&[[2.5, 0.], [3., 0.], [3., 2.]], false),
            (&[[3., 3.], [4., 3.], [4., 4.]], false),
            (&[[1.5, 3.], [3., 1.5], [3., 3.]], false),
        ];
        for (q, want) in cases {
            let q = poly(q);
            assert_eq!(Dobkin.intersects(&sq, &q), *want, "{q:?}");
            assert_eq!(Dobkin.intersects(&q, &sq), *want, "{q:?}");
        }
    }
}
