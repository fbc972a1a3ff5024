//! The engine of [`ChazelleDobkin`](super::ChazelleDobkin): the pencil from the pivot,
//! the projective frame and the chain-shrinking search of the module docs.

use crate::intersect::Probe;
use crate::kernel::{Kernel, Orientation, Point, Sign};
use crate::polygon::ConvexPolygon;
use Orientation::{Ccw, Cw};

/// A contiguous piece of a polygon's boundary, walked forward or backward, with
/// vertex positions `lo..=hi` (so `hi - lo` edges).
#[derive(Clone, Copy, Debug)]
pub(super) struct Chain<'a> {
    pub(super) pts: &'a [Point],
    pub(super) start: usize,
    pub(super) forward: bool,
    pub(super) lo: usize,
    pub(super) hi: usize,
}

impl<'a> Chain<'a> {
    #[inline]
    pub(super) fn at(&self, i: usize) -> Point {
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
    /// code and its instruction count; docs/results.md.)
    #[inline]
    pub(super) fn at_ref(&self, i: usize) -> &'a Point {
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
    pub(super) fn array_index(&self, i: usize) -> usize {
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
    pub(super) fn step(&self, idx: usize) -> usize {
        self.array_step(idx, self.forward)
    }

    /// The array index of the position before the one at array index `idx`.
    #[inline]
    pub(super) fn step_back(&self, idx: usize) -> usize {
        self.array_step(idx, !self.forward)
    }

    /// The array index next to `idx`, cyclically: the following one if `up`.
    #[inline]
    pub(super) fn array_step(&self, idx: usize, up: bool) -> usize {
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
    pub(super) fn edges(&self) -> usize {
        self.hi - self.lo
    }

    /// Position of the middle edge (i, i + 1); both ends are interior vertices
    /// when the chain has at least three edges.
    #[inline]
    pub(super) fn middle(&self) -> usize {
        self.lo + (self.edges() - 1) / 2
    }

    /// The array index of position `i`.
    #[inline]
    pub(super) fn index(&self, i: usize) -> usize {
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
pub(super) enum Exit<'a> {
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
    pub(super) fn meets(&self) -> bool {
        !matches!(self, Exit::Misses { .. } | Exit::Finish { hit: None, .. })
    }
}

/// The chain vertex that decided the finish.
#[derive(Clone, Copy, Debug)]
pub(super) enum Hit {
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
pub(super) struct Frame<K> {
    pub(super) k: K,
    pub(super) a: Point,
    pub(super) ql: Point,
    pub(super) qr: Point,
}

impl<K: Kernel> Frame<K> {
    /// x(u) < x(v) in the frame: v lies counter-clockwise of u as seen from A.
    #[inline]
    pub(super) fn before(&self, u: Point, v: Point) -> bool {
        self.k.orient(self.a, u, v) == Ccw
    }

    /// Direction of `d` within the closed arc from `lo` to `hi` (an arc < π).
    #[inline]
    pub(super) fn in_arc(&self, d: Point, lo: Point, hi: Point) -> bool {
        self.k.orient(self.a, lo, d) != Cw && self.k.orient(self.a, d, hi) != Cw
    }

    /// [`in_arc`](Frame::in_arc) by reference ([`Kernel::orient_of`]), for the finish,
    /// whose window ends are chain vertices: one of its points is often one of the ends.
    #[inline]
    pub(super) fn in_window(&self, d: &Point, lo: &Point, hi: &Point) -> bool {
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
    pub(super) fn slope_cmp(&self, u: (Point, Point), v: (Point, Point)) -> Sign {
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
pub(super) fn pencil<K: Kernel>(k: K, q: &[Point], a: Point) -> Option<(usize, usize)> {
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
pub(super) fn short_edges(p: &ConvexPolygon, q: &ConvexPolygon) -> f64 {
    let (ep, eq) = (p.edge_extent(), q.edge_extent());
    if ep > eq { ep } else { eq }
}

/// The side of the union of the polygons' bounding boxes, max(hi) − min(lo) per
/// coordinate, the larger of the two: every computed difference of two vertices is at
/// most this (rounding is monotonic), the contract of [`Kernel::within_differences`].
/// The vertices are finite, so no NaN is lost in the comparisons: the same bounds as
/// [`Kernel::within`] of the two boxes, without its test for non-finite corners.
#[inline]
pub(super) fn union_side(p: &ConvexPolygon, q: &ConvexPolygon) -> f64 {
    let max = |a: f64, b: f64| if a > b { a } else { b };
    let min = |a: f64, b: f64| if a < b { a } else { b };
    let (bp, bq) = (p.bounding_box(), q.bounding_box());
    let ((lo0, hi0), (lo1, hi1)) = ((bp.min, bp.max), (bq.min, bq.max));
    let wx = max(hi0.x, hi1.x) - min(lo0.x, lo1.x);
    let wy = max(hi0.y, hi1.y) - min(lo0.y, lo1.y);
    max(wx, wy)
}

/// The pruning itself; `e` gives [`short_edges`] of the polygons, for the frame's kernel.
/// `#[inline]` so that it is compiled into its callers' codegen units, as when it lived
/// beside them (called once per query, it is the whole query).
#[inline]
pub(super) fn run<'a, K: Kernel, P: Probe>(
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
        probe.kept(crate::intersect::Kept::ChazelleDobkin {
            f: crate::intersect::Span::new(f.start + f.lo, f.edges() + 1),
            g: crate::intersect::Span::new(g.start + g.pts.len() - g.hi, g.edges() + 1),
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
pub(super) fn shrink_hi<K: Kernel>(fr: &Frame<K>, hi: &mut Point, v: Point) {
    if fr.before(v, *hi) {
        *hi = v;
    }
}

#[inline]
pub(super) fn grow_lo<K: Kernel>(fr: &Frame<K>, lo: &mut Point, v: Point) {
    if fr.before(*lo, v) {
        *lo = v;
    }
}

/// The position of the edge of a chain of at most two edges that holds the part just
/// right of `x`.
#[inline]
pub(super) fn edge_right_of<K: Kernel>(fr: &Frame<K>, c: &Chain<'_>, x: Point) -> usize {
    if c.edges() >= 2 && !fr.before(x, c.at(c.lo + 1)) {
        c.lo + 1
    } else {
        c.lo
    }
}

/// Case 5: both chains have at most two edges. h = f − g is concave and piecewise
/// linear with breakpoints at chain vertices, and the window's ends are chain
/// vertices, so h ≥ 0 somewhere iff it is at a chain vertex inside the window.
pub(super) fn finish<K: Kernel>(
    fr: &Frame<K>,
    f: &Chain<'_>,
    g: &Chain<'_>,
    dlo: Point,
    dhi: Point,
) -> Option<Hit> {
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
