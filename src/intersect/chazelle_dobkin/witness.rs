//! The certificates of [`ChazelleDobkin`](super::ChazelleDobkin) (module docs,
//! "Certificate"): separating edges from the pivot and from the final chains.

use super::engine::{Chain, Frame};
use crate::intersect::certificate::{extreme_left, separates};
use crate::intersect::{Certificate, Which};
use crate::kernel::{DirectedLine, Kernel, Orientation, Point, Sign};
use Orientation::{Ccw, Cw};

/// The pencil misses P: an edge of P at the pivot A whose open outer side holds both
/// tangent points q_L and q_R. That side is a half-plane bounded by a line through A,
/// so it holds every point of the wedge W(A) ⊇ Q other than A, and A ∉ Q: the edge
/// separates. Two orientations per edge.
pub(super) fn pivot_edge_apart<K: Kernel>(k: K, pv: &[Point], ql: Point, qr: Point) -> Option<Certificate> {
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
pub(super) fn from_final_edges<K: Kernel>(
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
pub(super) fn bracketed<K: Kernel>(
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
pub(super) fn visible_extreme_outside<K: Kernel>(
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
