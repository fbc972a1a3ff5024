//! The boundary of the Minkowski difference D = Q ⊕ (−P), walked in O(n + m) without
//! building it, and the exact tests that certify which of its features is nearest the
//! origin.
//!
//! D's vertices are the differences `q_j − p_i` of the vertex pairs whose normal cones
//! overlap; its edges are the edges of Q (translated by `−p_i`) and of −P (translated
//! by `q_j`), merged by direction. Every question about a feature of D is a question
//! about input points: the origin's side of the D-edge `q_j − p_i → q_{j+1} − p_i` is
//! `orient(q_j, q_{j+1}, p_i)`, and so on (each test below says which). So the walk
//! and the certificates are predicates of the kernel on input points, never on
//! constructed ones.

use crate::kernel::{Kernel, Orientation, Point, Sign};
use std::ops::ControlFlow;

/// `(i + 1) mod n` for `i < n`, without a division (the walk's hot loop).
#[inline(always)]
pub(crate) fn next(i: usize, n: usize) -> usize {
    if i + 1 == n { 0 } else { i + 1 }
}

/// `(i − 1) mod n` for `i < n`.
#[inline(always)]
pub(crate) fn prev(i: usize, n: usize) -> usize {
    if i == 0 { n - 1 } else { i - 1 }
}

/// A feature of the boundary of D, named by the input features it comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Feature {
    /// The D-vertex `q_j − p_i`: vertex `i` of P against vertex `j` of Q.
    Vertices {
        /// The vertex of P.
        p: usize,
        /// The vertex of Q.
        q: usize,
    },
    /// The D-edge of Q's edge `j` (from vertex `j` to `j + 1`) paired with P's vertex `i`.
    EdgeOfQ {
        /// The edge of Q.
        q: usize,
        /// The vertex of P.
        p: usize,
    },
    /// The D-edge of P's edge `i` paired with Q's vertex `j`.
    EdgeOfP {
        /// The edge of P.
        p: usize,
        /// The vertex of Q.
        q: usize,
    },
}

/// The vertex with the smallest (y, x).
fn lowest(v: &[Point]) -> usize {
    let mut best = 0;
    for (k, w) in v.iter().enumerate() {
        let b = v[best];
        if w.y < b.y || (w.y == b.y && w.x < b.x) {
            best = k;
        }
    }
    best
}

/// The vertex with the largest (y, x): the lowest of −P.
fn highest(v: &[Point]) -> usize {
    let mut best = 0;
    for (k, w) in v.iter().enumerate() {
        let b = v[best];
        if w.y > b.y || (w.y == b.y && w.x > b.x) {
            best = k;
        }
    }
    best
}

/// Walks D's boundary counter-clockwise from its lowest vertex, handing every vertex
/// and edge to `visit` (n + m of each) until it breaks.
///
/// The edges of Q and of −P are merged by direction: both start at their lowest
/// vertex, so both first directions lie in [0, π), and since every turn of a strictly
/// convex polygon is less than π, the two current directions always differ by less
/// than π; the sign of their cross product therefore orders them. Parallel edges (a
/// zero cross product) take Q's first, leaving a straight D-vertex between the two.
pub(crate) fn walk<K: Kernel, B>(
    kernel: K,
    p: &[Point],
    q: &[Point],
    visit: impl FnMut(Feature) -> ControlFlow<B>,
) -> Option<B> {
    walk_from(kernel, p, q, (highest(p), lowest(q)), usize::MAX, visit)
}

/// [`walk`] from the D-vertex `q_j − p_i` (`start = (i, j)`), for at most `vertices`
/// vertices (and the edges after them), and never more than once around. The start
/// must be a vertex of D (`p_i` and `q_j` extreme in opposite directions for a common
/// direction) for the features visited to be D's; the tests of the features do not
/// depend on it.
pub(crate) fn walk_from<K: Kernel, B>(
    kernel: K,
    p: &[Point],
    q: &[Point],
    (mut i, mut j): (usize, usize),
    vertices: usize,
    mut visit: impl FnMut(Feature) -> ControlFlow<B>,
) -> Option<B> {
    let (n, m) = (p.len(), q.len());
    let (mut done_p, mut done_q) = (0, 0);
    let mut count = 0;
    while (done_p < n || done_q < m) && count < vertices {
        count += 1;
        if let ControlFlow::Break(b) = visit(Feature::Vertices { p: i, q: j }) {
            return Some(b);
        }
        let q_first = if done_p == n {
            true
        } else if done_q == m {
            false
        } else {
            // Q's edge direction q_{j+1} − q_j against −P's, p_i − p_{i+1}.
            kernel.cross(q[j], q[next(j, m)], p[next(i, n)], p[i]) != Orientation::Cw
        };
        let edge = if q_first {
            let f = Feature::EdgeOfQ { q: j, p: i };
            j = next(j, m);
            done_q += 1;
            f
        } else {
            let f = Feature::EdgeOfP { p: i, q: j };
            i = next(i, n);
            done_p += 1;
            f
        };
        if let ControlFlow::Break(b) = visit(edge) {
            return Some(b);
        }
    }
    None
}

/// Whether the distance from vertex `k` of `other` to the line of edge `e` of `poly`
/// (`poly` counter-clockwise) is the distance between the two polygons, and positive:
/// `other[k]` lies strictly outside the edge, projects onto the closed edge, and is
/// the vertex of `other` deepest towards `poly` across that edge (so the D-edge is a
/// real edge of D, and the origin lies outside its supporting line).
pub(crate) fn edge_is_nearest<K: Kernel>(
    kernel: K,
    poly: &[Point],
    e: usize,
    other: &[Point],
    k: usize,
) -> bool {
    let (n, m) = (poly.len(), other.len());
    let (a, b, v) = (poly[e], poly[next(e, n)], other[k]);
    kernel.orient(a, b, v) == Orientation::Cw
        && kernel.dot(a, b, a, v) != Sign::Negative
        && kernel.dot(b, a, b, v) != Sign::Negative
        && kernel.cross(a, b, v, other[next(k, m)]) != Orientation::Ccw
        && kernel.cross(a, b, v, other[prev(k, m)]) != Orientation::Ccw
}

/// Whether `p[i]` and `q[j]` are a closest pair: `p_i − q_j` lies in Q's normal cone at
/// `q_j` and `q_j − p_i` in P's normal cone at `p_i` (then the origin lies in D's normal
/// cone at the D-vertex `q_j − p_i`, which makes it the point of D nearest the origin).
pub(crate) fn vertices_are_nearest<K: Kernel>(
    kernel: K,
    p: &[Point],
    i: usize,
    q: &[Point],
    j: usize,
) -> bool {
    let (n, m) = (p.len(), q.len());
    let (a, b) = (p[i], q[j]);
    kernel.dot(b, q[next(j, m)], b, a) != Sign::Positive
        && kernel.dot(b, q[prev(j, m)], b, a) != Sign::Positive
        && kernel.dot(a, p[next(i, n)], a, b) != Sign::Positive
        && kernel.dot(a, p[prev(i, n)], a, b) != Sign::Positive
}

/// Whether `feature` certifies the distance between two disjoint polygons.
pub(crate) fn is_nearest<K: Kernel>(kernel: K, p: &[Point], q: &[Point], feature: Feature) -> bool {
    match feature {
        Feature::Vertices { p: i, q: j } => p[i] != q[j] && vertices_are_nearest(kernel, p, i, q, j),
        Feature::EdgeOfQ { q: j, p: i } => edge_is_nearest(kernel, q, j, p, i),
        Feature::EdgeOfP { p: i, q: j } => edge_is_nearest(kernel, p, i, q, j),
    }
}

/// The nearest feature of D to the origin for two disjoint polygons, by the walk;
/// `None` when no feature passes its test (only when a kernel other than the exact one
/// contradicted itself, or the polygons meet).
pub(crate) fn nearest_feature<K: Kernel>(kernel: K, p: &[Point], q: &[Point]) -> Option<Feature> {
    walk(kernel, p, q, |f| {
        if is_nearest(kernel, p, q, f) {
            ControlFlow::Break(f)
        } else {
            ControlFlow::Continue(())
        }
    })
}
