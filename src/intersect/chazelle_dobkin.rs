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
//!   (completed by [`Dobkin`](super::Dobkin)'s separation, which tests/certificates.rs
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

use super::certificate::{extreme_left, from_faces, from_support, resolve_chords, separates};
use super::{ArrayIntersection, Certificate, Derivation, Probe, Which};
use crate::kernel::{DirectedLine, Kernel, Orientation, Point, Sign};
use crate::polygon::ConvexPolygon;

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

use Orientation::{Ccw, Cw};

/// The pencil misses P: an edge of P at the pivot A whose open outer side holds both
/// tangent points q_L and q_R. That side is a half-plane bounded by a line through A,
/// so it holds every point of the wedge W(A) ⊇ Q other than A, and A ∉ Q: the edge
/// separates. Two orientations per edge.
fn pivot_edge_apart<K: Kernel>(k: K, pv: &[Point], ql: Point, qr: Point) -> Option<Certificate> {
    let n = pv.len();
    [(pv[0], pv[1]), (pv[n - 1], pv[0])]
        .into_iter()
        .find(|&(s, u)| k.orient(s, u, ql) == Cw && k.orient(s, u, qr) == Cw)
        .map(|(from, to)| Certificate::Separated {
            of: Which::P,
            from,
            to,
        })
}

/// A separating edge among the final chains' edges (at most two of F, two of G), P's
/// edges at the pivot and Q's edges just outside G at the tangent points, for a
/// disjoint finish. An edge qualifies as a candidate when the other final chain lies
/// strictly on its outer side (at most three orientations). An edge of F is accepted
/// at once if G holds the minimum of g minus its line ([`bracketed`]); else a candidate
/// is accepted only if the other polygon's vertex deepest towards it, found by an
/// O(log) binary search ([`visible_extreme_outside`] for P's edges, [`extreme_left`] for
/// Q's), lies strictly outside and is extreme ([`separates`]). So every certificate
/// returned here holds for the whole polygons.
fn from_final_edges<K: Kernel>(
    k: K,
    pv: &[Point],
    qv: &[Point],
    f: &Chain<'_>,
    g: &Chain<'_>,
    [ql, qr]: [usize; 2],
) -> Option<Certificate> {
    let outside = |c: &Chain<'_>, s: Point, u: Point| {
        let line = DirectedLine::new(s, u);
        let mut i = c.lo;
        loop {
            if k.orient_line(&line, c.at(i)) != Cw {
                return false;
            }
            if i >= c.hi {
                return true;
            }
            i += 1;
        }
    };
    let (n, m) = (pv.len(), qv.len());
    // The visible chain runs counter-clockwise from q_R to q_L: G's positions 0..=visible.
    // (Both are indices below m: one conditional subtraction instead of a division.)
    let visible = ql + m - qr;
    let visible = if visible >= m { visible - m } else { visible };
    let separated = |s: Point, u: Point| Certificate::Separated {
        of: Which::P,
        from: s,
        to: u,
    };
    // F's edges: first the frame's bracket (no search), else Q's extreme vertex.
    let fr = Frame {
        k,
        a: pv[0],
        ql: qv[ql],
        qr: qv[qr],
    };
    // G's vertices and the visible edges' ends just beyond them, fetched once: G has
    // one or two edges (the pruning stops at two), so these are the positions
    // lo − 1 ..= hi + 1, found from one index by steps.
    let g0 = g.array_index(g.lo);
    let g1 = g.step(g0);
    let g2 = if g.edges() >= 2 { g.step(g1) } else { g1 };
    let w = [g.pts[g0], g.pts[g1], g.pts[g2]];
    let beyond = [
        (g.lo > 0).then(|| g.pts[g.step_back(g0)]),
        (g.hi < visible).then(|| g.pts[g.step(g2)]),
    ];
    let below_g = |s: Point, u: Point| {
        let line = DirectedLine::new(s, u);
        w.iter().all(|&x| k.orient_line(&line, x) == Cw)
    };
    // F's first edge has F's largest slope, so G's right neighbour is the side its
    // bracket may fail on; for the others the left one. Test that side first.
    // F has one or two edges (the pruning stops at two): its vertices, fetched once.
    let fe = f.edges().min(2);
    let f0 = f.array_index(f.lo);
    let f1 = f.step(f0);
    let f2 = if fe >= 2 { f.step(f1) } else { f1 };
    let z = [f.pts[f0], f.pts[f1], f.pts[f2]];
    let mut candidates = [false; 2];
    for i in 0..fe {
        let (s, u) = (z[i], z[i + 1]);
        if below_g(s, u) {
            candidates[i] = true;
            if bracketed(&fr, [w[0], w[2]], beyond, (s, u), i == 0) {
                return Some(separated(s, u));
            }
        }
    }
    for i in 0..fe {
        let (s, u) = (z[i], z[i + 1]);
        if candidates[i] && visible_extreme_outside(k, qv, qr, visible, (s, u)) {
            return Some(separated(s, u));
        }
    }
    // P's edges at the pivot.
    for (s, u) in [(pv[0], pv[1]), (pv[n - 1], pv[0])] {
        if outside(g, s, u) && visible_extreme_outside(k, qv, qr, visible, (s, u)) {
            return Some(separated(s, u));
        }
    }
    // G runs backward along Q: Q's counter-clockwise edge is at(e + 1) → at(e). Then
    // the edges of Q just outside G's ends (at the tangent points).
    let q_edges = (g.lo..g.hi)
        .map(|e| (g.index(e + 1), g.index(e)))
        .chain([(ql, (ql + 1) % m), ((qr + m - 1) % m, qr)]);
    for (s, u) in q_edges {
        let (s, u) = (qv[s], qv[u]);
        if outside(f, s, u) && separates(k, s, u, pv, extreme_left(k, pv, (s, u))) {
            return Some(Certificate::Separated {
                of: Which::Q,
                from: s,
                to: u,
            });
        }
    }
    None
}

/// Whether the final chain G (from `first` to `last`) holds the minimum over the whole
/// visible chain of g − ℓ, where ℓ is the frame's image of the line of F's edge `e`
/// (left to right): the visible edge just left of G (from `before`, if any) is no
/// steeper than ℓ and the one just right of it (to `after`, if any) no less steep. Two slope comparisons, the right one first if
/// `right_first`.
///
/// Then an edge of F whose line has every vertex of G strictly above it (strictly on
/// its outer side) has the whole visible chain strictly above it: g − ℓ is convex and
/// piecewise linear, so its minimum over the chain is at a vertex of G. Q lies in the
/// wedge, above g in the frame, so Q is strictly on the edge's outer side and the edge
/// separates, with no search. This is the case when the maximum of h lies inside the
/// edge's span (h's maximum is where F's slope is among g's slopes there).
fn bracketed<K: Kernel>(
    fr: &Frame<K>,
    [first, last]: [Point; 2],
    [before, after]: [Option<Point>; 2],
    e: (Point, Point),
    right_first: bool,
) -> bool {
    let left = || before.is_none_or(|b| fr.slope_cmp((b, first), e) != Sign::Positive);
    let right = || after.is_none_or(|a| fr.slope_cmp((last, a), e) != Sign::Negative);
    // The side that may fail first: both are pure, only the order of work differs.
    if right_first {
        if !right() {
            return false;
        }
        left()
    } else {
        if !left() {
            return false;
        }
        right()
    }
}

/// Whether Q lies strictly right of P's edge `s` → `u`, by its vertex deepest to the
/// left of the edge, searched on the chain visible from the pivot only: positions `0..=len` counter-clockwise from `qr`.
///
/// If the edge separates, that vertex lies on this chain: the line through it parallel
/// to the edge supports Q and has the pivot (a vertex of P, on the edge's closed inner
/// side) strictly on its other side, so one of its two edges has the pivot strictly
/// outside and is visible. The visible edges' directions span less than π, so the
/// sign of their cross product with the edge's direction changes at most once along
/// the chain: leftness grows, then shrinks, and the first edge along which it stops
/// growing starts at the deepest vertex. One cross product per step. Returns whether
/// that vertex is strictly outside and extreme (the search compared both its edges
/// unless it ends the chain; else [`separates`]), so a `true` proves separation
/// whatever the chain holds.
fn visible_extreme_outside<K: Kernel>(
    k: K,
    qv: &[Point],
    qr: usize,
    len: usize,
    (s, u): (Point, Point),
) -> bool {
    let m = qv.len();
    let index = |j: usize| if qr + j >= m { qr + j - m } else { qr + j };
    let (mut lo, mut hi) = (0, len);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if k.cross_of_short_edges(s, u, qv[index(mid)], qv[index(mid + 1)]) == Ccw {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    if lo > 0 && lo < len {
        // The search compared both edges at the vertex: it is extreme.
        k.orient(s, u, qv[index(lo)]) == Cw
    } else {
        separates(k, s, u, qv, index(lo))
    }
}

/// A contiguous piece of a polygon's boundary, walked forward or backward, with
/// vertex positions `lo..=hi` (so `hi - lo` edges).
#[derive(Clone, Copy, Debug)]
struct Chain<'a> {
    pts: &'a [Point],
    start: usize,
    forward: bool,
    lo: usize,
    hi: usize,
}

impl<'a> Chain<'a> {
    #[inline]
    fn at(&self, i: usize) -> Point {
        // Positions never exceed the polygon's length, so one conditional
        // subtraction replaces a division.
        let len = self.pts.len();
        let i = if i >= len { i - len } else { i };
        let idx = if self.forward {
            let j = self.start + i;
            if j >= len { j - len } else { j }
        } else if i <= self.start {
            self.start - i
        } else {
            self.start + len - i
        };
        self.pts[idx]
    }

    /// [`at`](Chain::at) by reference, for [`Kernel::orient_of`]. (The index is
    /// computed in both bodies on purpose: a shared helper changed the pruning loop's
    /// code, +0.5% exact instructions at 2^10.)
    #[inline]
    fn at_ref(&self, i: usize) -> &'a Point {
        let len = self.pts.len();
        let i = if i >= len { i - len } else { i };
        let idx = if self.forward {
            let j = self.start + i;
            if j >= len { j - len } else { j }
        } else if i <= self.start {
            self.start - i
        } else {
            self.start + len - i
        };
        &self.pts[idx]
    }

    /// The array index of position `i`, computed as in [`at`](Chain::at) (written out
    /// again rather than shared with it: see [`at_ref`](Chain::at_ref)); for the
    /// certificate's fetches, with [`step`](Chain::step) and
    /// [`step_back`](Chain::step_back) for the positions next to it.
    #[inline]
    fn array_index(&self, i: usize) -> usize {
        let len = self.pts.len();
        let i = if i >= len { i - len } else { i };
        if self.forward {
            let j = self.start + i;
            if j >= len { j - len } else { j }
        } else if i <= self.start {
            self.start - i
        } else {
            self.start + len - i
        }
    }

    /// The array index of the position after the one at array index `idx`.
    #[inline]
    fn step(&self, idx: usize) -> usize {
        self.array_step(idx, self.forward)
    }

    /// The array index of the position before the one at array index `idx`.
    #[inline]
    fn step_back(&self, idx: usize) -> usize {
        self.array_step(idx, !self.forward)
    }

    /// The array index next to `idx`, cyclically: the following one if `up`.
    #[inline]
    fn array_step(&self, idx: usize, up: bool) -> usize {
        let len = self.pts.len();
        if up {
            if idx + 1 >= len { 0 } else { idx + 1 }
        } else if idx == 0 {
            len - 1
        } else {
            idx - 1
        }
    }

    #[inline]
    fn edges(&self) -> usize {
        self.hi - self.lo
    }

    /// Position of the middle edge (i, i + 1); both ends are interior vertices
    /// when the chain has at least three edges.
    #[inline]
    fn middle(&self) -> usize {
        self.lo + (self.edges() - 1) / 2
    }

    /// The array index of position `i`.
    #[inline]
    fn index(&self, i: usize) -> usize {
        let len = self.pts.len();
        let i = i % len;
        if self.forward {
            (self.start + i) % len
        } else {
            (self.start + len - i) % len
        }
    }
}

/// How a run ended: the plain call reduces it to the answer, the certified call turns
/// it into a certificate.
#[derive(Clone, Copy, Debug)]
enum Exit<'a> {
    /// The pivot P[0] lies in Q.
    AInside,
    /// The pencil from the pivot does not enter P; `ql` and `qr` are the tangent
    /// points' indices in Q.
    Misses { ql: usize, qr: usize },
    /// The constant-size finish on the chains F and G, and the vertex that decided it
    /// (none: the polygons are disjoint).
    Finish {
        f: Chain<'a>,
        g: Chain<'a>,
        hit: Option<Hit>,
        /// The tangent points, as for [`Exit::Misses`].
        tangents: [usize; 2],
    },
}

impl Exit<'_> {
    #[inline]
    fn meets(&self) -> bool {
        !matches!(self, Exit::Misses { .. } | Exit::Finish { hit: None, .. })
    }
}

/// The chain vertex that decided the finish.
#[derive(Clone, Copy, Debug)]
enum Hit {
    /// Vertex `z` of F lies on or beyond G's edge starting at position `e`: the
    /// segment from the pivot to `z` (a chord of P) meets that edge of Q.
    F { z: usize, e: usize },
    /// Vertex `w` of G lies on the pivot's side of F (or on it), inside the window:
    /// a vertex of Q in P.
    G { w: usize },
}

/// The geometry of one query: the pivot and the pencil's tangent points, which fix
/// the projective frame.
#[derive(Clone, Copy)]
struct Frame<K> {
    k: K,
    a: Point,
    ql: Point,
    qr: Point,
}

impl<K: Kernel> Frame<K> {
    /// x(u) < x(v) in the frame: v lies counter-clockwise of u as seen from A.
    #[inline]
    fn before(&self, u: Point, v: Point) -> bool {
        self.k.orient(self.a, u, v) == Ccw
    }

    /// Direction of `d` within the closed arc from `lo` to `hi` (an arc < π).
    #[inline]
    fn in_arc(&self, d: Point, lo: Point, hi: Point) -> bool {
        self.k.orient(self.a, lo, d) != Cw && self.k.orient(self.a, d, hi) != Cw
    }

    /// [`in_arc`](Frame::in_arc) by reference ([`Kernel::orient_of`]), for the finish,
    /// whose window ends are chain vertices: one of its points is often one of the ends.
    #[inline]
    fn in_window(&self, d: &Point, lo: &Point, hi: &Point) -> bool {
        self.k.orient_of(&self.a, lo, d) != Cw && self.k.orient_of(&self.a, d, hi) != Cw
    }

    /// Sign of slope(u1 u2) − slope(v1 v2) in the frame (both edges left to right).
    ///
    /// The frame sends the pivot `a` to vertical infinity with the line through `a` in
    /// direction c = c1 − c0 (c0, c1 = q_L, q_R) as the line at infinity. With
    /// coordinates z − a = s·c + t·n (any n with c × n < 0), the map
    /// z ↦ (s/t, −1/t) sends rays from `a` to vertical lines, keeps x increasing
    /// counter-clockwise around `a` and y increasing away from `a` on the side
    /// t > 0, which holds the whole wedge when c0, c1 are the tangent points q_L, q_R.
    /// The image of the line through u1, u2 has slope cross(u2 − u1, c) / orient(a, u1, u2)
    /// (n cancels), so for two edges ordered left to right (positive denominators)
    ///
    /// sign(slope_u − slope_v) = sign(cross(u2 − u1, c)·orient(a, v1, v2) − cross(v2 − v1, c)·orient(a, u1, u2)),
    ///
    /// a polynomial of degree 4 in the input coordinates. Each factor is written with
    /// the edge first, orient(a, v1, v2) as (v2 − v1) × (a − v1) and
    /// −orient(a, u1, u2) as (u2 − u1) × (u1 − a) (the same polynomial), so that every
    /// factor crosses a short edge with a long vector: the kernel's
    /// [`Kernel::cross_products_sign_of_short_edges`] decides it (under `Exact`, with a
    /// bound scaled to the edges), and the ten differences are four fewer than with
    /// both orientations' own.
    #[inline]
    fn slope_cmp(&self, u: (Point, Point), v: (Point, Point)) -> Sign {
        let (a, c0, c1) = (self.a, self.ql, self.qr);
        self.k.cross_products_sign_of_short_edges([
            [u.0, u.1, c0, c1],
            [v.0, v.1, v.0, a],
            [v.0, v.1, c0, c1],
            [u.0, u.1, a, u.0],
        ])
    }
}

/// The tangent points of the pencil from `a` to the polygon `q`: the first and the
/// last edge of the block of edges visible from `a`, or `None` when `a` ∈ q.
fn pencil<K: Kernel>(k: K, q: &[Point], a: Point) -> Option<(usize, usize)> {
    let m = q.len();
    // Edge positions stay below 2m, so wrapping is one conditional subtraction.
    let wrap = |i: usize| if i >= m { i - m } else { i };
    let visible = |i: usize| k.orient_of(&q[wrap(i)], &q[wrap(i + 1)], &a) == Cw;
    let (first_vis, last_vis) = (visible(0), visible(m - 1));
    // One visible edge `v` and one invisible edge `n`.
    let (v, n) = if !first_vis && !last_vis {
        // A in the closed angle of q at vertex 0: locate it in the fan around q[0].
        let (mut lo, mut hi) = (1, m - 1);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if k.orient_of(&q[0], &q[mid], &a) != Cw {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        if k.orient_of(&q[lo], &q[hi], &a) != Cw {
            return None; // in the fan triangle (q0, q_lo, q_hi)
        }
        (lo, 0)
    } else if first_vis != last_vis {
        if first_vis { (0, m - 1) } else { (m - 1, 0) }
    } else {
        // A beyond both edges at q[0]: the ray from q[0] away from A crosses the fan.
        let (mut lo, mut hi) = (1, m - 1);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if k.orient_of(&q[0], &q[mid], &a) != Ccw {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        (0, lo)
    };
    // Last visible edge walking counter-clockwise from v to n.
    let d = (n + m - v) % m;
    let (mut lo, mut hi) = (0, d);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if visible(v + mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let last = (v + lo) % m;
    // First visible edge walking counter-clockwise from n to v.
    let d = (v + m - n) % m;
    let (mut lo, mut hi) = (0, d);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if visible(n + mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let first = (n + hi) % m;
    Some((first, last))
}

/// The largest edge extent of the two polygons: every slope comparison crosses edges
/// of P or Q (the short directions) with vectors between their vertices, the
/// contract of [`Kernel::within_short_edges`]. An extent is never NaN (it is a
/// maximum of plain comparisons, which skip a NaN difference), so one comparison
/// picks the larger; an infinite extent comes with infinite boxes, whose bounds the
/// kernel never replaces.
#[inline]
fn short_edges(p: &ConvexPolygon, q: &ConvexPolygon) -> f64 {
    let (ep, eq) = (p.edge_extent(), q.edge_extent());
    if ep > eq { ep } else { eq }
}

/// The side of the union of the polygons' bounding boxes, max(hi) − min(lo) per
/// coordinate, the larger of the two: every computed difference of two vertices is at
/// most this (rounding is monotonic), the contract of [`Kernel::within_differences`].
/// The vertices are finite, so no NaN is lost in the comparisons: the same bounds as
/// [`Kernel::within`] of the two boxes, without its test for non-finite corners.
#[inline]
fn union_side(p: &ConvexPolygon, q: &ConvexPolygon) -> f64 {
    let max = |a: f64, b: f64| if a > b { a } else { b };
    let min = |a: f64, b: f64| if a < b { a } else { b };
    let (bp, bq) = (p.bounding_box(), q.bounding_box());
    let ((lo0, hi0), (lo1, hi1)) = ((bp.min, bp.max), (bq.min, bq.max));
    let wx = max(hi0.x, hi1.x) - min(lo0.x, lo1.x);
    let wy = max(hi0.y, hi1.y) - min(lo0.y, lo1.y);
    max(wx, wy)
}

/// The pruning itself; `e` gives [`short_edges`] of the polygons, for the frame's kernel.
fn run<'a, K: Kernel, P: Probe>(
    k: K,
    pv: &'a [Point],
    qv: &'a [Point],
    e: impl FnOnce() -> f64,
    probe: &mut P,
) -> Exit<'a> {
    let (n, m) = (pv.len(), qv.len());
    let a = pv[0];
    let Some((first, last)) = pencil(k, qv, a) else {
        return Exit::AInside;
    };
    let misses = Exit::Misses {
        ql: (last + 1) % m,
        qr: first,
    };
    // G: the visible chain of Q from q_L = q[last + 1] back to q_R = q[first].
    let g_edges = (last + m - first) % m + 1;
    let mut g = Chain {
        pts: qv,
        start: (last + 1) % m,
        forward: false,
        lo: 0,
        hi: g_edges,
    };
    let (ql, qr) = (g.at(0), g.at(g_edges));
    // The frame's kernel asks `orient` and the slope comparison only, whose factors'
    // short directions are edges of P and Q.
    let fr = Frame {
        k: k.within_short_edges(e),
        a,
        ql,
        qr,
    };
    // The window: directions common to the pencil and to the angle of P at A.
    let (p1, pl) = (pv[1], pv[n - 1]);
    let (mut dlo, k0) = if fr.in_arc(ql, p1, pl) {
        // Largest k with p_k at or clockwise of q_L (p_1 .. p_{n-1} turn counter-clockwise around A).
        let (mut lo, mut hi) = (1, n);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if k.orient(a, pv[mid], ql) != Cw {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        (ql, lo.min(n - 2))
    } else if fr.in_arc(p1, ql, qr) {
        (p1, 1)
    } else {
        return misses; // the pencil does not enter P: P ∩ W(A) = {A} and A ∉ Q
    };
    let (mut dhi, k1) = if fr.in_arc(qr, p1, pl) {
        // Smallest k with p_k at or counter-clockwise of q_R.
        let (mut lo, mut hi) = (0, n - 1);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if k.orient(a, qr, pv[mid]) != Cw {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        (qr, hi.max(2))
    } else if fr.in_arc(pl, ql, qr) {
        (pl, n - 1)
    } else {
        return misses; // unreachable under an exact kernel: the arcs overlap
    };
    let k1 = k1.max(k0 + 1);
    let mut f = Chain {
        pts: pv,
        start: 0,
        forward: true,
        lo: k0,
        hi: k1,
    };

    while f.edges() > 2 || g.edges() > 2 {
        probe.iteration();
        probe.kept(super::Kept::ChazelleDobkin {
            f: super::Span::new(f.start + f.lo, f.edges() + 1),
            g: super::Span::new(g.start + g.pts.len() - g.hi, g.edges() + 1),
            pivot: a,
            tangents: [ql, qr],
            window: [dlo, dhi],
        });
        // Case 1: a middle edge entirely outside the window.
        if f.edges() > 2 {
            let i = f.middle();
            if !fr.before(dlo, f.at(i + 1)) {
                f.lo = i + 1;
                continue;
            }
            if !fr.before(f.at(i), dhi) {
                f.hi = i;
                continue;
            }
        }
        if g.edges() > 2 {
            let j = g.middle();
            if !fr.before(dlo, g.at(j + 1)) {
                g.lo = j + 1;
                continue;
            }
            if !fr.before(g.at(j), dhi) {
                g.hi = j;
                continue;
            }
        }
        if f.edges() > 2 && g.edges() > 2 {
            let (i, j) = (f.middle(), g.middle());
            let (v1, v2, w1, w2) = (f.at(i), f.at(i + 1), g.at(j), g.at(j + 1));
            if fr.slope_cmp((v1, v2), (w1, w2)) != Sign::Positive {
                // Case 2: h non-increasing right of max(a1, b1).
                if !fr.before(v1, w1) {
                    f.hi = i + 1;
                    shrink_hi(&fr, &mut dhi, v2);
                } else {
                    g.hi = j + 1;
                    shrink_hi(&fr, &mut dhi, w2);
                }
            } else if !fr.before(w2, v2) {
                // Case 3: h increasing left of min(a2, b2).
                f.lo = i;
                grow_lo(&fr, &mut dlo, v1);
            } else {
                g.lo = j;
                grow_lo(&fr, &mut dlo, w1);
            }
        } else if g.edges() > 2 {
            // Case 4, G long: the slope of f just right of b2.
            let j = g.middle();
            let (w1, w2) = (g.at(j), g.at(j + 1));
            let e = edge_right_of(&fr, &f, w2);
            let e = (f.at(e), f.at(e + 1));
            if fr.slope_cmp(e, (w1, w2)) != Sign::Positive {
                g.hi = j + 1;
                shrink_hi(&fr, &mut dhi, w2);
            } else {
                g.lo = j;
                grow_lo(&fr, &mut dlo, w1);
            }
        } else {
            // Case 4, F long: the slope of g just right of a2.
            let i = f.middle();
            let (v1, v2) = (f.at(i), f.at(i + 1));
            let e = edge_right_of(&fr, &g, v2);
            let e = (g.at(e), g.at(e + 1));
            if fr.slope_cmp(e, (v1, v2)) != Sign::Negative {
                f.hi = i + 1;
                shrink_hi(&fr, &mut dhi, v2);
            } else {
                f.lo = i;
                grow_lo(&fr, &mut dlo, v1);
            }
        }
    }
    // The finish gets copies of the chains: a reference to the loop's own would take
    // their address and keep them in memory through the loop (2% of a query).
    let hit = finish(&fr, &{ f }, &{ g }, dlo, dhi);
    let tangents = [(last + 1) % m, first];
    Exit::Finish { f, g, hit, tangents }
}

#[inline]
fn shrink_hi<K: Kernel>(fr: &Frame<K>, hi: &mut Point, v: Point) {
    if fr.before(v, *hi) {
        *hi = v;
    }
}

#[inline]
fn grow_lo<K: Kernel>(fr: &Frame<K>, lo: &mut Point, v: Point) {
    if fr.before(*lo, v) {
        *lo = v;
    }
}

/// The position of the edge of a chain of at most two edges that holds the part just
/// right of `x`.
#[inline]
fn edge_right_of<K: Kernel>(fr: &Frame<K>, c: &Chain<'_>, x: Point) -> usize {
    if c.edges() >= 2 && !fr.before(x, c.at(c.lo + 1)) {
        c.lo + 1
    } else {
        c.lo
    }
}

/// Case 5: both chains have at most two edges. h = f − g is concave and piecewise
/// linear with breakpoints at chain vertices, and the window's ends are chain
/// vertices, so h ≥ 0 somewhere iff it is at a chain vertex inside the window.
fn finish<K: Kernel>(fr: &Frame<K>, f: &Chain<'_>, g: &Chain<'_>, dlo: Point, dhi: Point) -> Option<Hit> {
    let k = fr.k;
    for i in f.lo..=f.hi {
        let z = f.at(i);
        if fr.in_window(&z, &dlo, &dhi) {
            let e = edge_right_of(fr, g, z);
            // z on or above g (not strictly on A's side of the edge's line).
            if k.orient(g.at(e), g.at(e + 1), z) != Ccw {
                return Some(Hit::F { z: i, e });
            }
        }
    }
    for j in g.lo..=g.hi {
        let w = g.at(j);
        if fr.in_window(&w, &dlo, &dhi) {
            let e = edge_right_of(fr, f, w);
            // w on or below f (on A's side of the edge's line, or on it).
            if k.orient_of(f.at_ref(e), f.at_ref(e + 1), &w) != Cw {
                return Some(Hit::G { w: j });
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::intersect::{Iterations, Linear, brute_force};
    use crate::{Exact, Fast};

    fn poly(pts: &[[f64; 2]]) -> ConvexPolygon {
        ConvexPolygon::new(pts.iter().copied()).unwrap()
    }

    /// The slope formula against an explicit projective map in floating point.
    #[test]
    fn slope_comparison_matches_the_explicit_frame() {
        let a = Point::new(0.0, 0.0);
        let (ql, qr) = (Point::new(3.0, -1.0), Point::new(1.0, 3.0));
        let c = Point::new(qr.x - ql.x, qr.y - ql.y);
        let nvec = Point::new(c.y, -c.x); // c × n = −|c|² < 0
        let dcn = c.x * nvec.y - c.y * nvec.x;
        let tau = |z: Point| {
            let (u, v) = (z.x - a.x, z.y - a.y);
            let s = (u * nvec.y - v * nvec.x) / dcn;
            let t = (c.x * v - c.y * u) / dcn;
            assert!(t > 0.0, "{z:?} not in the frame's half plane");
            (s / t, -1.0 / t)
        };
        let fr = Frame { k: Exact, a, ql, qr };
        let pts = [
            Point::new(2.0, 0.5),
            Point::new(2.5, 1.5),
            Point::new(1.0, 2.0),
            Point::new(3.0, 0.0),
            Point::new(1.5, 1.0),
            Point::new(4.0, 2.0),
        ];
        for &u1 in &pts {
            for &u2 in &pts {
                for &v1 in &pts {
                    for &v2 in &pts {
                        if !fr.before(u1, u2) || !fr.before(v1, v2) {
                            continue;
                        }
                        let slope = |p: Point, q: Point| {
                            let (tp, tq) = (tau(p), tau(q));
                            (tq.1 - tp.1) / (tq.0 - tp.0)
                        };
                        let (su, sv) = (slope(u1, u2), slope(v1, v2));
                        if (su - sv).abs() < 1e-9 {
                            continue;
                        }
                        assert_eq!(fr.slope_cmp((u1, u2), (v1, v2)), Sign::of(su - sv));
                    }
                }
            }
        }
        // x grows counter-clockwise, y away from A.
        assert!(tau(Point::new(3.0, 0.0)).0 < tau(Point::new(1.0, 2.0)).0);
        assert!(tau(Point::new(1.0, 1.0)).1 < tau(Point::new(2.0, 2.0)).1);
    }

    #[test]
    fn pencil_finds_the_tangent_points() {
        let sq = poly(&[[0., 0.], [1., 0.], [1., 1.], [0., 1.]]);
        // Below the bottom edge: only edge 0 visible.
        assert_eq!(pencil(Exact, sq.vertices(), Point::new(0.5, -1.0)), Some((0, 0)));
        // Beyond the corner (1, 1): edges 1 and 2 visible.
        assert_eq!(pencil(Exact, sq.vertices(), Point::new(2.0, 2.0)), Some((1, 2)));
        // On the extension of the bottom edge: edge 0 is collinear, not visible.
        assert_eq!(pencil(Exact, sq.vertices(), Point::new(-1.0, 0.0)), Some((3, 3)));
        // Inside and on the boundary.
        assert_eq!(pencil(Exact, sq.vertices(), Point::new(0.5, 0.5)), None);
        assert_eq!(pencil(Exact, sq.vertices(), Point::new(1.0, 0.5)), None);
        assert_eq!(pencil(Exact, sq.vertices(), Point::new(0.0, 0.0)), None);
        // Every start vertex, every outside point on a grid: the block is exactly the visible edges.
        for start in 0..4 {
            let r = sq.starting_at(start);
            let v = r.vertices();
            for x in -4..=8 {
                for y in -4..=8 {
                    let a = Point::new(x as f64 * 0.25, y as f64 * 0.25);
                    let vis: Vec<bool> = (0..4)
                        .map(|i| Exact.orient(v[i], v[(i + 1) % 4], a) == Cw)
                        .collect();
                    match pencil(Exact, v, a) {
                        None => assert!(vis.iter().all(|b| !b), "{a:?}"),
                        Some((s, t)) => {
                            let mut i = s;
                            loop {
                                assert!(vis[i], "{a:?} start {start}");
                                if i == t {
                                    break;
                                }
                                i = (i + 1) % 4;
                            }
                            let count = vis.iter().filter(|b| **b).count();
                            assert_eq!((t + 4 - s) % 4 + 1, count, "{a:?}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn hand_cases_and_degenerate_pencils() {
        let sq = poly(&[[0., 0.], [2., 0.], [2., 2.], [0., 2.]]);
        let cases: &[(&[[f64; 2]], bool)] = &[
            (&[[1., 1.], [1.5, 1.], [1., 1.5]], true),             // contained
            (&[[-1., -1.], [3., -1.], [3., 3.], [-1., 3.]], true), // contains
            (&[[2., 2.], [3., 2.], [3., 3.]], true),               // shared vertex
            (&[[2., 0.5], [3., 0.], [3., 1.]], true),              // vertex on edge
            (&[[2., 0.], [3., 0.], [3., 2.], [2., 2.]], true),     // shared edge
            (&[[2., 1.], [3., 1.], [3., 3.], [2., 3.]], true),     // overlapping edges
            (&[[2.5, 0.], [3., 0.], [3., 2.]], false),
            (&[[3., 3.], [4., 3.], [4., 4.]], false),
            (&[[1.5, 3.], [3., 1.5], [3., 3.]], false),
            // pencil lines along an edge of P (window of one direction)
            (&[[3., 0.], [4., 0.], [4., 1.]], false),
            (&[[2., 0.], [4., 0.], [4., 1.]], true),
            (&[[-3., 0.], [-1., 0.], [-2., -1.]], false),
            (&[[-3., 0.], [0., 0.], [-2., -1.]], true),
            (&[[0., 3.], [0., 4.], [-1., 4.]], false),
        ];
        for (q, want) in cases {
            let q = poly(q);
            for s in 0..sq.len() {
                let p = sq.starting_at(s);
                for t in 0..q.len() {
                    let qq = q.starting_at(t);
                    assert_eq!(ChazelleDobkin.intersects(&p, &qq), *want, "{p:?} {qq:?}");
                    assert_eq!(ChazelleDobkin.intersects(&qq, &p), *want, "{qq:?} {p:?}");
                    assert_eq!(brute_force(Exact, &p, &qq), *want);
                }
            }
        }
    }

    #[test]
    fn integer_grid_triangles_and_quads_agree_with_linear() {
        // Every small lattice polygon against a fixed set: heavy on collinear and touching cases.
        let tris: Vec<ConvexPolygon> = {
            let mut v = Vec::new();
            let pts: Vec<[f64; 2]> = (0..4)
                .flat_map(|x| (0..4).map(move |y| [x as f64, y as f64]))
                .collect();
            for i in 0..pts.len() {
                for j in i + 1..pts.len() {
                    for l in j + 1..pts.len() {
                        if let Ok(t) = ConvexPolygon::new([pts[i], pts[j], pts[l]]) {
                            v.push(t);
                        }
                    }
                }
            }
            v
        };
        let others = [
            poly(&[[1., 1.], [2., 1.], [2., 2.], [1., 2.]]),
            poly(&[[0., 0.], [3., 0.], [3., 1.], [1., 3.], [0., 2.]]),
            poly(&[[1., 0.], [2., 1.], [1., 2.], [0., 1.]]),
            poly(&[[4., 0.], [5., 1.], [4., 3.]]),
        ];
        let mut count = 0;
        for t in tris.iter().step_by(3) {
            for o in &others {
                for s in 0..o.len() {
                    let o = o.starting_at(s);
                    let want = Linear.intersects(t, &o);
                    assert_eq!(ChazelleDobkin.intersects(t, &o), want, "{t:?} {o:?}");
                    assert_eq!(ChazelleDobkin.intersects(&o, t), want, "{o:?} {t:?}");
                    count += 1;
                }
            }
        }
        assert!(count > 500);
    }

    #[test]
    fn iterations_are_counted_and_fast_kernel_terminates() {
        let p = crate::generate::regular_polygon(1000, 1.0);
        for (dx, want) in [(-1.4, true), (-1.6, false)] {
            let q = crate::generate::regular_polygon(1000, 0.5)
                .map(|v| Point::new(v.x + dx, v.y))
                .unwrap();
            let mut it = Iterations::default();
            assert_eq!(ChazelleDobkin.intersects_probed(Exact, &p, &q, &mut it), want);
            assert!(it.0 > 0 && it.0 < 60, "{it:?}");
            assert_eq!(ChazelleDobkin.intersects_with(Fast, &p, &q), want);
        }
    }
}
