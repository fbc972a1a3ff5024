//! Chords: a segment between two vertices of one polygon that crosses the other,
//! reduced to a vertex inside or two crossing edges.

use crate::kernel::{
    DirectedLine, Kernel, Orientation, Point, SegmentContact, point_on_segment, segment_contact,
};

use crate::intersect::{Certificate, Which};
use Orientation::{Collinear, Cw};

/// The start of the edge between positions `i` and `j` of a polygon of `n` vertices, if
/// they are consecutive (in either order).
#[inline]
pub(crate) fn edge_between(n: usize, i: usize, j: usize) -> Option<usize> {
    if j == if i + 1 == n { 0 } else { i + 1 } {
        Some(i)
    } else if i == if j + 1 == n { 0 } else { j + 1 } {
        Some(j)
    } else {
        None
    }
}

/// What [`reduce_chord`] found.
pub(crate) enum Reduced {
    /// The edge starting at this index meets the segment, as classified; for a
    /// crossing, also what starts the reduction of the segment (if a chord) against
    /// the edge: the edge's end strictly right of the segment, and the side of the
    /// segment's first end against the edge.
    Edge(usize, SegmentContact, Option<(Point, Orientation)>),
    /// This endpoint of the segment lies in the polygon.
    Inside(Point),
    /// This vertex of the chain lies in the triangle of the segment and the caller's
    /// `apex`, so in the segment's polygon.
    Beyond(Point),
    /// Only an inconsistent kernel gets here.
    Fail,
}

/// The chord `av[i]`–`av[j]` of a convex polygon (not an edge) crosses the segment `s`–`t`
/// properly (a single point X inside both, every endpoint strictly off the other's
/// line). Finds an edge of the polygon meeting the segment, or an endpoint of the
/// segment inside the polygon, with one binary search on the chain from `i` to `j`.
///
/// The chain runs counter-clockwise from `av[i]` to `av[j]`, on the right of the chord, and
/// crosses the line st exactly once (its ends are strictly on opposite sides), at a point
/// Y of some edge. On the line, the segment [X, Y] lies in the polygon. If the segment
/// st does not reach Y, its endpoint on the chain's side lies strictly between X and Y.
/// That endpoint is first tested against the triangle of the chord and the chain's
/// middle vertex (two orientations): inside it, it is inside the polygon.
///
/// The search ([`crossing_edge`]) ends at an edge whose ends are known on either side of
/// the line, so its contact with the segment takes two orientations more.
///
/// `known`, when the caller has them: the segment's end strictly right of the chord
/// `av[i]` → `av[j]` and the side of `av[i]` against the line s → t.
///
/// `apex`, when the caller has one: a point of the segment's polygon, used when it is
/// strictly right of s → t (one orientation): the triangle (s, apex, t) lies in that
/// polygon. The regula falsi probes on that side of the line are tested in the
/// triangle (two orientations), and the first inside ends the search (`Reduced::Beyond`): the chain has a vertex in the
/// segment's polygon, a witness as good as the crossing edge.
pub(crate) fn reduce_chord<K: Kernel>(
    k: K,
    av: &[Point],
    (i, j): (usize, usize),
    (s, t): (Point, Point),
    known: Option<(Point, Orientation)>,
    apex: Option<Point>,
) -> Reduced {
    let n = av.len();
    let (a, b) = (av[i], av[j]);
    let line = DirectedLine::new(s, t);
    let (near, sigma) = match known {
        Some(known) => known,
        None => {
            let near = if k.orient(a, b, s) == Cw {
                s
            } else if k.orient(a, b, t) == Cw {
                t
            } else {
                return Reduced::Fail;
            };
            (near, k.orient_line(&line, a))
        }
    };
    let len = if j >= i { j - i } else { j + n - i };
    let at = |off: usize| {
        let idx = i + off;
        av[if idx >= n { idx - n } else { idx }]
    };
    // The triangle of the chord and the chain's middle vertex lies in the polygon, and
    // `near` is strictly on its side of the chord: two orientations often show it
    // inside (a short segment crossing a long chord), without the search.
    let m = at(len / 2);
    if len >= 2 && k.orient(a, m, near) != Cw && k.orient(m, b, near) != Cw {
        return Reduced::Inside(near);
    }
    // The search probes offsets 1 to len − 1 only: where they do not pass the array's
    // end, it reads them from a slice, with no wrap-around test per probe.
    // A probe strictly on sigma's side is strictly right of s → t when sigma is
    // clockwise; otherwise the probes not strictly on it are right of s → t or on it,
    // and on it inside the triangle only between s and t: the apex must be strictly
    // right of s → t (checked once, only where the regula falsi probes run).
    let apex = apex.filter(|&q| len >= INTERPOLATE_FROM && k.orient(s, t, q) == Cw);
    let in_triangle = |x: Point, on_sigma: bool| match apex {
        Some(q) => on_sigma == (sigma == Cw) && k.orient(s, q, x) != Cw && k.orient(q, t, x) != Cw,
        None => false,
    };
    let searched = if i + len <= n {
        let chain = &av[i..i + len];
        crossing_edge(
            k,
            &line,
            &|off: usize| chain[off],
            (a, b),
            len,
            sigma,
            &in_triangle,
        )
    } else {
        crossing_edge(k, &line, &at, (a, b), len, sigma, &in_triangle)
    };
    let (lo, o_next) = match searched {
        Ok(found) => found,
        Err(x) => return Reduced::Beyond(x),
    };
    let e = if i + lo >= n { i + lo - n } else { i + lo };
    let (u, v) = (av[e], at(lo + 1));
    // u is strictly on a's side of the line; v strictly on the other (the edge crosses
    // the line at an interior point) or on it.
    if o_next == Collinear {
        return match segment_contact(k, u, v, s, t) {
            SegmentContact::Disjoint => Reduced::Inside(near),
            contact => Reduced::Edge(e, contact, None),
        };
    }
    let (os, ot) = (k.orient(u, v, s), k.orient(u, v, t));
    if os == ot && os != Collinear {
        Reduced::Inside(near)
    } else if os != Collinear && ot != Collinear {
        // u is on a's side of the line s → t, v strictly on the other.
        let right = if sigma == Cw { u } else { v };
        Reduced::Edge(e, SegmentContact::Crossing, Some((right, os)))
    } else {
        Reduced::Edge(e, SegmentContact::Touching, None)
    }
}

/// The chain `at(0..=len)` has `at(0)` strictly on side `sigma` of `line` and `at(len)`
/// strictly on the other side, and crosses the line once: the offset `lo` of the edge
/// `at(lo)` → `at(lo + 1)` where it does (`at(lo)` on side `sigma`, `at(lo + 1)` not),
/// with the side of `at(lo + 1)`. `ends` are `at(0)` and `at(len)` (the caller's `at`
/// may not reach `at(len)`). One exact orientation per probe against the line's
/// precomputed direction, turned so that `sigma`'s side is its left (each probe then
/// asks only whether the point is strictly left); the side of `at(lo + 1)` is computed
/// once at the end (one orientation more, unless it is `at(len)`), not carried through
/// the probes.
///
/// On chains of at least [`INTERPOLATE_FROM`] edges the first probes are placed by
/// [`regula_falsi`], bisection finishing the bracket it leaves: at most twice
/// bisection's probes, far fewer on the long chains of round polygons
/// (docs/certificates.md, "Barba, eighth round"). Every decision is the exact
/// orientation.
#[inline]
pub(super) fn crossing_edge<K: Kernel>(
    k: K,
    line: &DirectedLine,
    at: &impl Fn(usize) -> Point,
    ends: (Point, Point),
    len: usize,
    sigma: Orientation,
    in_other: &impl Fn(Point, bool) -> bool,
) -> Result<(usize, Orientation), Point> {
    let left = if sigma == Orientation::Ccw {
        *line
    } else {
        DirectedLine::new(line.to(), line.from())
    };
    let (mut lo, mut hi) = if len >= INTERPOLATE_FROM {
        regula_falsi(k, &left, at, ends, len, in_other)?
    } else {
        (0, len)
    };
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if k.orient_line(&left, at(mid)) == Orientation::Ccw {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let o_hi = if hi == len {
        sigma.reverse()
    } else {
        k.orient_line(line, at(hi))
    };
    Ok((lo, o_hi))
}

/// 2^52: a float in [0, 2^52) plus this, rounded, has the integer in its low bits.
pub(super) const ROUND: f64 = 4_503_599_627_370_496.0;

/// Chains at least this long are searched by [`regula_falsi`] first: on shorter ones its
/// arithmetic costs more than the probes it saves (docs/certificates.md, "Barba, eighth
/// round").
pub(super) const INTERPOLATE_FROM: usize = 1 << 11;

/// The first ⌈log₂(len + 1)⌉ probes of [`crossing_edge`]'s search, placed by regula
/// falsi on the chain `at(0..=len)` whose ends `(at(0), at(len))` are strictly left of
/// `left` and not: the bracket `(lo, hi)` it leaves, `at(lo)` strictly left and `at(hi)`
/// not, or the first probe `x` that `in_other(x, strictly left)` accepts. Each probe goes where the line through the bracket's ends' signed distances to
/// `left` (in `f64`: the products the orientation's filter computes) meets zero, kept
/// strictly inside the bracket; the decision is the exact orientation. Near the
/// crossing the distance is nearly linear in the position on a smooth, evenly sampled
/// chain, so the bracket closes in a few probes there (about 6 on chains of 87,381
/// edges, against bisection's 16 or 17).
#[inline(always)]
pub(super) fn regula_falsi<K: Kernel>(
    k: K,
    left: &DirectedLine,
    at: &impl Fn(usize) -> Point,
    (first, last): (Point, Point),
    len: usize,
    in_other: &impl Fn(Point, bool) -> bool,
) -> Result<(usize, usize), Point> {
    let distance = |x: Point| {
        let (l, r) = left.products(x);
        l - r
    };
    let (mut lo, mut hi) = (0, len);
    let (mut d_lo, mut d_hi) = (distance(first), distance(last));
    let mut budget = usize::BITS - len.leading_zeros();
    while hi - lo > 1 && budget > 0 {
        budget -= 1;
        let w = (hi - lo) as i64 as f64;
        // The interpolated offset, rounded down (less a half, then to nearest), kept in
        // [1, w − 1] (a NaN fails the first test and gives 1), then converted by adding
        // 2^52 (exact for offsets below 2^52): a few instructions, where a saturating
        // cast takes a dozen.
        let t = w * (d_lo / (d_lo - d_hi)) - 0.5;
        let t = if t > 1.0 { t } else { 1.0 };
        let t = if t < w - 1.0 { t } else { w - 1.0 };
        let mid = lo + ((t + ROUND).to_bits() - ROUND.to_bits()) as usize;
        let x = at(mid);
        let on_left = k.orient_line(left, x) == Orientation::Ccw;
        if in_other(x, on_left) {
            return Err(x);
        }
        if on_left {
            lo = mid;
            d_lo = distance(x);
        } else {
            hi = mid;
            d_hi = distance(x);
        }
    }
    Ok((lo, hi))
}

/// An endpoint of one segment on the other segment, as a vertex-inside certificate: the
/// segment `pv[i]`–`pv[j]` lies in P and `qv[c]`–`qv[d]` in Q (chords or edges).
pub(crate) fn endpoint_on_other<K: Kernel>(
    k: K,
    (a, b): (Point, Point),
    (s, t): (Point, Point),
) -> Option<Certificate> {
    for x in [s, t] {
        if point_on_segment(k, a, b, x) {
            return Some(Certificate::VertexInside {
                of: Which::Q,
                point: x,
            });
        }
    }
    for x in [a, b] {
        if point_on_segment(k, s, t, x) {
            return Some(Certificate::VertexInside {
                of: Which::P,
                point: x,
            });
        }
    }
    None
}

/// Turns "the segment between vertices `i` and `j` of P meets the segment between
/// vertices `c` and `d` of Q" into a certificate: chords are segments between any two
/// vertices (edges included), and each lies in its polygon, so their common point is
/// in both. An endpoint of one on the other is a vertex inside; two edges are crossing
/// edges; a chord is replaced by an edge with [`reduce_chord`] (one binary search).
///
/// `None` when the segments do not meet (only an inconsistent kernel or a wrong caller
/// gets here).
///
/// # Complexity
/// O(log n + log m): at most one binary search per chord.
pub(crate) fn resolve_chords<K: Kernel>(
    k: K,
    pv: &[Point],
    (i, j): (usize, usize),
    qv: &[Point],
    (c, d): (usize, usize),
) -> Option<Certificate> {
    let (a, b, s, t) = (pv[i], pv[j], qv[c], qv[d]);
    let contact = segment_contact(k, a, b, s, t);
    if !contact.meets() {
        return None;
    }
    if let (Some(e), Some(f)) = (edge_between(pv.len(), i, j), edge_between(qv.len(), c, d)) {
        return Some(crossing(pv, e, qv, f));
    }
    if contact != SegmentContact::Crossing {
        return endpoint_on_other(k, (a, b), (s, t));
    }
    resolve_crossing_chords(k, pv, (i, j), qv, (c, d))
}

/// [`resolve_chords`] for a caller that knows the two segments cross properly (one
/// point, every endpoint strictly off the other's line): the contact is not computed
/// again. O(log n + log m).
pub(crate) fn resolve_crossing_chords<K: Kernel>(
    k: K,
    pv: &[Point],
    (i, j): (usize, usize),
    qv: &[Point],
    (c, d): (usize, usize),
) -> Option<Certificate> {
    resolve_crossing(k, pv, (i, j), qv, (c, d), None)
}

#[inline]
pub(super) fn resolve_crossing<K: Kernel>(
    k: K,
    pv: &[Point],
    (i, j): (usize, usize),
    qv: &[Point],
    (c, d): (usize, usize),
    known: Option<(Point, Orientation)>,
) -> Option<Certificate> {
    let (s, t) = (qv[c], qv[d]);
    let q_edge = edge_between(qv.len(), c, d);
    let (e, contact, known_q) = match edge_between(pv.len(), i, j) {
        Some(e) => (e, SegmentContact::Crossing, None),
        None => match reduce_chord(k, pv, (i, j), (s, t), known, None) {
            Reduced::Edge(e, contact, next) => (e, contact, next),
            Reduced::Inside(x) => {
                return Some(Certificate::VertexInside {
                    of: Which::Q,
                    point: x,
                });
            }
            Reduced::Beyond(x) => {
                return Some(Certificate::VertexInside {
                    of: Which::P,
                    point: x,
                });
            }
            Reduced::Fail => return None,
        },
    };
    if let Some(f) = q_edge {
        return Some(crossing(pv, e, qv, f));
    }
    let (u, v) = (pv[e], pv[(e + 1) % pv.len()]);
    if contact != SegmentContact::Crossing {
        return endpoint_on_other(k, (u, v), (s, t));
    }
    match reduce_chord(k, qv, (c, d), (u, v), known_q, None) {
        Reduced::Edge(f, ..) => Some(crossing(pv, e, qv, f)),
        Reduced::Inside(x) => Some(Certificate::VertexInside {
            of: Which::P,
            point: x,
        }),
        Reduced::Beyond(x) => Some(Certificate::VertexInside {
            of: Which::Q,
            point: x,
        }),
        Reduced::Fail => None,
    }
}

#[inline]
pub(crate) fn crossing(pv: &[Point], e: usize, qv: &[Point], f: usize) -> Certificate {
    Certificate::CrossingEdges {
        p: [pv[e], pv[(e + 1) % pv.len()]],
        q: [qv[f], qv[(f + 1) % qv.len()]],
    }
}
