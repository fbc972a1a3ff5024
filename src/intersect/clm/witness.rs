//! Witnesses from the LP's examined points: Radon partitions, straddles, cones and the
//! chords between linked vertices, resolved along the polygons.

use crate::intersect::certificate::{Reduced, endpoint_on_other};
use crate::kernel::{
    DirectedLine, Kernel, Orientation, Point, SegmentContact, point_on_segment, segment_contact,
};
use crate::lp::WitnessPoint;
use crate::polygon::LinkedPolygon;

use crate::intersect::{Certificate, Which};
use Orientation::{Ccw, Collinear, Cw};

/// A vertex named by a witness of intersecting hulls: its coordinates, its polygon,
/// and its arena position when known.
#[derive(Clone, Copy, Debug)]
pub(crate) struct WitnessVertex {
    pub(crate) point: Point,
    pub(crate) of: Which,
    pub(crate) pos: Option<usize>,
}

/// At most this many witness points per polygon.
pub(super) const WITNESS_MAX: usize = 9;

/// At most [`WITNESS_MAX`] vertices of one polygon, sorted lexicographically without
/// repeats, with their positions (`usize::MAX`: unknown), and their convex hull.
pub(super) struct SmallSet {
    pts: [Point; WITNESS_MAX],
    pos: [usize; WITNESS_MAX],
    len: usize,
    /// The hull, counter-clockwise without collinear points (indices into `pts`): one
    /// point, a segment, or a polygon; `None` until [`hull`](Self::hull) runs.
    hull: Option<([u8; WITNESS_MAX], usize)>,
}

impl SmallSet {
    const EMPTY: SmallSet = SmallSet {
        pts: [Point { x: 0.0, y: 0.0 }; WITNESS_MAX],
        pos: [usize::MAX; WITNESS_MAX],
        len: 0,
        hull: None,
    };

    /// Inserts `x` in lexicographic order (insertion sort: a few points), unless it is
    /// there already or the set is full.
    #[inline]
    fn insert(&mut self, x: Point, pos: usize) {
        let n = self.len;
        if n == WITNESS_MAX || self.pts[..n].contains(&x) {
            return;
        }
        let mut i = n;
        while i > 0 && self.pts[i - 1].lex_cmp(x) == std::cmp::Ordering::Greater {
            self.pts[i] = self.pts[i - 1];
            self.pos[i] = self.pos[i - 1];
            i -= 1;
        }
        self.pts[i] = x;
        self.pos[i] = pos;
        self.len = n + 1;
    }

    /// The hull (Andrew's monotone chain on the sorted points), computed once.
    fn hull<K: Kernel>(&mut self, k: K) -> ([u8; WITNESS_MAX], usize) {
        if self.hull.is_none() {
            let (pts, n) = (&self.pts, self.len);
            let mut chain = [0u8; 2 * WITNESS_MAX];
            let mut h = 0;
            if n > 0 {
                for pass in 0..2 {
                    let start = h;
                    for step in 0..n {
                        let i = if pass == 0 { step } else { n - 1 - step };
                        while h >= start + 2
                            && k.orient(pts[chain[h - 2] as usize], pts[chain[h - 1] as usize], pts[i]) != Ccw
                        {
                            h -= 1;
                        }
                        chain[h] = i as u8;
                        h += 1;
                    }
                    h -= 1; // the last point starts the other chain
                }
            }
            // One point gives [0, 0]: keep it once. Points are distinct, so only the
            // closing repeat of the first point remains to drop.
            let mut len = h.max(usize::from(n > 0)).min(WITNESS_MAX);
            while len > 1 && chain[len - 1] == chain[0] {
                len -= 1;
            }
            let mut out = [0u8; WITNESS_MAX];
            out[..len].copy_from_slice(&chain[..len]);
            self.hull = Some((out, len));
        }
        self.hull.expect("computed above")
    }

    /// The first of `xs` in the hull (closed).
    fn first_inside<K: Kernel>(&mut self, k: K, xs: &[Point]) -> Option<Point> {
        let (h, n) = self.hull(k);
        let (pts, h) = (&self.pts, &h[..n]);
        xs.iter().copied().find(|&x| match n {
            0 => false,
            1 => pts[h[0] as usize] == x,
            2 => point_on_segment(k, pts[h[0] as usize], pts[h[1] as usize], x),
            _ => (0..n).all(|i| {
                k.orient(
                    pts[h[i] as usize],
                    pts[h[if i + 1 == n { 0 } else { i + 1 }] as usize],
                    x,
                ) != Cw
            }),
        })
    }
}

/// What [`witness_certificate`] found among a few vertices of P and of Q.
pub(crate) enum Radon {
    /// A vertex of one in the hull of the other's vertices: a vertex inside.
    Inside(Certificate),
    /// A segment between two of P's vertices crosses one between two of Q's: chords to
    /// resolve along the boundaries (the vertices' positions, when known).
    Chords([Option<usize>; 2], [Option<usize>; 2]),
    /// The hulls do not meet (only an inconsistent kernel reports such points).
    Nothing,
}

/// A certificate from a few vertices of P and of Q whose hulls (P's vertices against
/// Q's) intersect, as the LP reports them: a vertex of one in the hull of the other's
/// (so in that polygon), or else two crossing chords.
pub(crate) fn witness_certificate<K: Kernel>(k: K, points: impl Iterator<Item = WitnessVertex>) -> Radon {
    let mut sets = [SmallSet::EMPTY, SmallSet::EMPTY];
    for w in points {
        sets[(w.of == Which::Q) as usize].insert(w.point, w.pos.unwrap_or(usize::MAX));
    }
    let [ps, qs] = &mut sets;
    // Each hull is built only when needed: Q's first, for P's points.
    if let Some(x) = qs.first_inside(k, &ps.pts[..ps.len]) {
        return Radon::Inside(Certificate::VertexInside {
            of: Which::P,
            point: x,
        });
    }
    if let Some(x) = ps.first_inside(k, &qs.pts[..qs.len]) {
        return Radon::Inside(Certificate::VertexInside {
            of: Which::Q,
            point: x,
        });
    }
    let edges = |s: &mut SmallSet| {
        let (h, n) = s.hull(k);
        let count = match n {
            0 | 1 => 0,
            2 => 1,
            _ => n,
        };
        (h, n, count)
    };
    let ((hp, np, cp), (hq, nq, cq)) = (edges(ps), edges(qs));
    let pos = |p: usize| (p != usize::MAX).then_some(p);
    for i in 0..cp {
        let (a, b) = (hp[i] as usize, hp[if i + 1 == np { 0 } else { i + 1 }] as usize);
        for j in 0..cq {
            let (c, d) = (hq[j] as usize, hq[if j + 1 == nq { 0 } else { j + 1 }] as usize);
            if segment_contact(k, ps.pts[a], ps.pts[b], qs.pts[c], qs.pts[d]).meets() {
                return Radon::Chords([pos(ps.pos[a]), pos(ps.pos[b])], [pos(qs.pos[c]), pos(qs.pos[d])]);
            }
        }
    }
    Radon::Nothing
}

/// [`witness_certificate`] for the LP's five-point witness of a point x beyond a chord
/// of the other set ([`LpWorkspace::straddle`](crate::lp::LpWorkspace::straddle)):
/// the segment from x to x₀ (one polygon's) meets the triangle of b, c and y₀ (the
/// other's). A vertex inside is x or x₀ in the triangle, or a triangle vertex on the
/// segment; otherwise the segment crosses an edge of the triangle: two chords. With
/// the triangle's orientation known, x's three orientations decide the usual case.
/// `Radon::Nothing` when the triangle is degenerate (a point on the line of the two
/// others) or the test finds no contact (only an inconsistent kernel): the caller
/// then searches all of the LP's witness points.
pub(crate) fn straddle_certificate<K: Kernel>(
    k: K,
    [x, x0]: [WitnessVertex; 2],
    tri: [WitnessVertex; 3],
) -> Radon {
    debug_assert!(x0.of == x.of && tri.iter().all(|w| w.of != x.of));
    let [b, c, y0] = tri.map(|w| w.point);
    // y₀ is often b or c: collinear without the kernel (whose exact path a zero
    // determinant takes).
    let turn = if y0 == b || y0 == c {
        Collinear
    } else {
        k.orient(b, c, y0)
    };
    if turn == Collinear {
        // y₀ is b or c (it bounded the step): the segments x x₀ and b c meet.
        if y0 != b && y0 != c {
            return Radon::Nothing;
        }
        return match segment_contact(k, x.point, x0.point, b, c) {
            SegmentContact::Disjoint => Radon::Nothing,
            SegmentContact::Crossing => {
                let (xs, ts) = ([x.pos, x0.pos], [tri[0].pos, tri[1].pos]);
                if x.of == Which::P {
                    Radon::Chords(xs, ts)
                } else {
                    Radon::Chords(ts, xs)
                }
            }
            // A touching contact: an endpoint of one segment on the other.
            _ => {
                let on = [
                    (x, (b, c)),
                    (x0, (b, c)),
                    (tri[0], (x.point, x0.point)),
                    (tri[1], (x.point, x0.point)),
                ];
                on.iter()
                    .find(|(w, (u, v))| point_on_segment(k, *u, *v, w.point))
                    .map_or(Radon::Nothing, |(w, _)| {
                        Radon::Inside(Certificate::VertexInside {
                            of: w.of,
                            point: w.point,
                        })
                    })
            }
        };
    }
    let outside = turn.reverse();
    // The triangle's edges, counter-clockwise or clockwise as `turn` says.
    let edges = [(0, 1), (1, 2), (2, 0)];
    let pts = [b, c, y0];
    let inside = |z: Point| edges.iter().all(|&(i, j)| k.orient(pts[i], pts[j], z) != outside);
    for v in [x, x0] {
        if inside(v.point) {
            return Radon::Inside(Certificate::VertexInside {
                of: v.of,
                point: v.point,
            });
        }
    }
    let pos = |w: WitnessVertex| w.pos;
    for (i, j) in edges {
        match segment_contact(k, x.point, x0.point, pts[i], pts[j]) {
            SegmentContact::Disjoint => {}
            SegmentContact::Crossing => {
                let (xs, ts) = ([pos(x), pos(x0)], [pos(tri[i]), pos(tri[j])]);
                return if x.of == Which::P {
                    Radon::Chords(xs, ts)
                } else {
                    Radon::Chords(ts, xs)
                };
            }
            // A touching contact: the triangle's vertex on the segment (x and x₀ are
            // outside the closed triangle).
            _ => {
                for w in [tri[i], tri[j]] {
                    if point_on_segment(k, x.point, x0.point, w.point) {
                        return Radon::Inside(Certificate::VertexInside {
                            of: w.of,
                            point: w.point,
                        });
                    }
                }
            }
        }
    }
    Radon::Nothing
}

/// The vertex `y` inside one of the triangles of `tris` (each of three vertices of the
/// other polygon), as a certificate; degenerate triangles are skipped. Three or four
/// orientations per triangle.
pub(crate) fn in_triangles<K: Kernel>(
    k: K,
    y: WitnessVertex,
    tris: &[[WitnessVertex; 3]],
) -> Option<Certificate> {
    tris.iter().find_map(|t| {
        if t.iter().any(|w| w.of == y.of) {
            return None;
        }
        let [a, b, c] = t.map(|w| w.point);
        // A repeated vertex (often: the LP's bound is its previous tangent point) makes
        // the triangle degenerate, seen without the kernel's exact path for a zero.
        if a == b || b == c || c == a {
            return None;
        }
        let outside = match k.orient(a, b, c) {
            Collinear => return None,
            turn => turn.reverse(),
        };
        let inside = k.orient(a, b, y.point) != outside
            && k.orient(b, c, y.point) != outside
            && k.orient(c, a, y.point) != outside;
        inside.then_some(Certificate::VertexInside {
            of: y.of,
            point: y.point,
        })
    })
}

/// Among `points`, the one left of the directed line `line` and the one right of it
/// whose directions from `x` lie nearest the line's (`x` on the line, the points
/// beyond it seen from x): one orientation for the side, one against the best so far.
/// Points on the line are skipped. Used by [`cone_witness`] twice: through x from a
/// point of the other set, and from x through an end of the cone.
pub(super) fn nearest_beside<K: Kernel>(
    k: K,
    x: Point,
    line: (Point, Point),
    points: impl Iterator<Item = WitnessPoint>,
) -> (Option<WitnessPoint>, Option<WitnessPoint>) {
    let (mut u, mut v): (Option<WitnessPoint>, Option<WitnessPoint>) = (None, None);
    for w in points {
        match k.orient(line.0, line.1, w.point) {
            Ccw => {
                if u.is_none_or(|u| k.orient(x, u.point, w.point) == Cw) {
                    u = Some(w);
                }
            }
            Cw => {
                if v.is_none_or(|v| k.orient(x, v.point, w.point) == Ccw) {
                    v = Some(w);
                }
            }
            Collinear => {}
        }
    }
    (u, v)
}

/// A vertex inside from the points an LP examined before it found their hulls
/// intersecting ([`LpWorkspace::examined`](crate::lp::LpWorkspace::examined)), without
/// building a hull: `x` is the point that made the LP infeasible (the last examined),
/// `examined` yields the examined points (`true`: of the LP's set B), and `of` names
/// the polygon of each set. Before x the optimum line L separated the examined points
/// of x's set (on one closed side) from the others (on the other), and x lies strictly
/// beyond L; so seen from x the points of its own set span less than a half-turn,
/// between two extreme directions lo and hi (one orientation per point, two for a few),
/// and a point y of the other set lies in the hull of x's set as soon as it lies in
/// the cone at x between lo and hi: on its closed side of L, it is then in the
/// triangle x, lo, hi. Each candidate is checked against that triangle exactly (three
/// orientations), so the answer never depends on the invariant, only its chance does.
/// Else (when `chords` asks for them) two crossing segments, each between two of the
/// points.
pub(crate) fn cone_witness<K: Kernel, I: Iterator<Item = WitnessPoint>>(
    k: K,
    x: WitnessPoint,
    examined: impl Fn() -> I,
    of: impl Fn(bool) -> Which,
    chords: bool,
) -> Cone {
    let own = x.in_b;
    // The extreme directions from x among its own set's points: lo the most clockwise,
    // hi the most counter-clockwise.
    let mut ends: Option<(WitnessPoint, WitnessPoint)> = None;
    for w in examined() {
        if w.in_b != own || w.point == x.point {
            continue;
        }
        ends = Some(match ends {
            None => (w, w),
            Some((lo, hi)) => {
                if k.orient(x.point, lo.point, w.point) == Cw {
                    (w, hi)
                } else if k.orient(x.point, hi.point, w.point) == Ccw {
                    (lo, w)
                } else {
                    (lo, hi)
                }
            }
        });
    }
    let Some((lo, hi)) = ends else {
        return Cone::Nothing;
    };
    let (l, h) = (lo.point, hi.point);
    if l != h
        && k.orient(x.point, l, h) == Ccw
        && let Some(w) = examined().find(|w| {
            w.in_b != own
                && k.orient(x.point, l, w.point) != Cw
                && k.orient(x.point, h, w.point) != Ccw
                && k.orient(l, h, w.point) != Cw
        })
    {
        return Cone::Inside(Certificate::VertexInside {
            of: of(w.in_b),
            point: w.point,
        });
    }
    // x itself in the hull of the other set's points: then it lies in a triangle r, u,
    // v for any of them r, where u and v are the points on the left and on the right
    // of the line from r through x whose directions from x are nearest that line's
    // direction beyond x (each side spans less than a half-turn seen from x).
    let mut others = examined().filter(|w| w.in_b != own);
    let Some(r) = others.next() else {
        return Cone::Nothing;
    };
    let (u, v) = nearest_beside(k, x.point, (r.point, x.point), others);
    // r, u, v counter-clockwise: v on the right of r → x, u on its left.
    if let (Some(u), Some(v)) = (u, v)
        && k.orient(r.point, v.point, u.point) == Ccw
        && k.orient(r.point, v.point, x.point) != Cw
        && k.orient(v.point, u.point, x.point) != Cw
        && k.orient(u.point, r.point, x.point) != Cw
    {
        return Cone::Inside(Certificate::VertexInside {
            of: of(x.in_b),
            point: x.point,
        });
    }
    if !chords {
        return Cone::Nothing;
    }
    // Else the hulls' boundaries cross, and (the other set lying on its side of the
    // LP's line) an edge of the other hull crosses a side x e of the cone's triangle:
    // on the ray from x through e, the points of the other set nearest the ray in
    // direction on its left (u) and on its right (v) span a segment that meets the
    // ray inside that hull; it crosses the side when that meeting is before e.
    for e in [hi, lo] {
        let others = examined().filter(|w| w.in_b != own);
        let (u, v) = nearest_beside(k, x.point, (x.point, e.point), others);
        if let (Some(u), Some(v)) = (u, v)
            && segment_contact(k, x.point, e.point, u.point, v.point) == SegmentContact::Crossing
        {
            return Cone::Chords([x, e], [u, v]);
        }
    }
    Cone::Nothing
}

/// What [`cone_witness`] found.
pub(crate) enum Cone {
    /// A vertex inside.
    Inside(Certificate),
    /// Two crossing segments: between two points of the violating point's set (the
    /// violating point first), and two of the other set.
    Chords([WitnessPoint; 2], [WitnessPoint; 2]),
    /// Neither.
    Nothing,
}

/// The edge of a linked polygon between positions `u` and `w`, as its start, if they
/// are consecutive.
#[inline]
pub(super) fn linked_edge(poly: &LinkedPolygon, u: usize, w: usize) -> Option<usize> {
    if poly.next_at(u) == w {
        Some(u)
    } else if poly.next_at(w) == u {
        Some(w)
    } else {
        None
    }
}

/// [`reduce_chord`] for a linked polygon, without random access: the vertex `start`
/// lies strictly on one side σ of the line `s`–`t` (it is an end of a chord crossing
/// the segment st). The boundary's part strictly on side σ is one run of vertices; its
/// ends are the two edges where the boundary crosses the line, at Y1 and Y2, and the
/// polygon meets the line in [Y1, Y2], which holds the crossing X of chord and segment.
/// From a vertex of the run, the walk towards the line reaches one end (distances along
/// the run are unimodal). The run strictly on the other side serves as well (its ends
/// are the same two edges), so the walk starts from the vertex of `starts` (positions,
/// and the points at them) ∪ {`start`} nearest the line on either side, and passes no
/// other vertex of `starts` on that side. That vertex is chosen by the distances as
/// computed in `f64` (one pass over the contiguous points, no predicate), and checked
/// with one exact orientation: the walk's correctness needs only a start strictly on
/// the side it walks, the choice bounds its length. If the end's edge misses the
/// segment, the segment's endpoint nearer its line lies between X and that end, inside
/// the polygon.
pub(super) fn reduce_linked<K: Kernel>(
    k: K,
    poly: &LinkedPolygon,
    start: usize,
    (starts, start_points): (&[u32], &[Point]),
    (s, t): (Point, Point),
) -> Reduced {
    debug_assert_eq!(starts.len(), start_points.len());
    let sigma = k.orient(s, t, poly.point_at(start));
    if sigma == Collinear {
        return Reduced::Fail;
    }
    // The signed distance (times |t − s|) towards side σ, rounded: only a guide.
    let (dx, dy) = (t.x - s.x, t.y - s.y);
    let flip = if sigma == Ccw { 1.0 } else { -1.0 };
    let height = |x: Point| flip * (dx * (x.y - s.y) - dy * (x.x - s.x));
    // The nearest vertex on side σ, and the nearest on the other side (by −height).
    let mut best = (height(poly.point_at(start)), usize::MAX);
    let mut other = (f64::INFINITY, usize::MAX);
    for (i, &x) in start_points.iter().enumerate() {
        let h = height(x);
        if h > 0.0 {
            if h < best.0 {
                best = (h, i);
            }
        } else if -h < other.0 && h < 0.0 {
            other = (-h, i);
        }
    }
    let (mut v, mut sigma) = (start, sigma);
    if other.0 < best.0 && k.orient(s, t, start_points[other.1]) == sigma.reverse() {
        // The run on the other side ends at the other crossing of the line, or the same:
        // either one serves.
        (v, sigma) = (starts[other.1] as usize, sigma.reverse());
    } else if best.1 != usize::MAX && k.orient(s, t, start_points[best.1]) == sigma {
        v = starts[best.1] as usize;
    }
    // x is nearer the line than y (both on side σ).
    let nearer = |x: Point, y: Point| k.cross(s, t, y, x) == sigma.reverse();
    // The walk tests many points against one line: its direction is computed once.
    let line = DirectedLine::new(s, t);
    let on_side = |pos: usize| k.orient_line(&line, poly.point_at(pos)) == sigma;
    let (mut cur, forward) = {
        let (next, prev) = (poly.next_at(v), poly.prev_at(v));
        if !on_side(next) || (on_side(prev) && !nearer(poly.point_at(prev), poly.point_at(next))) {
            (v, true)
        } else {
            (v, false)
        }
    };
    let mut steps = poly.len();
    let edge = loop {
        let nb = if forward {
            poly.next_at(cur)
        } else {
            poly.prev_at(cur)
        };
        if !on_side(nb) {
            break if forward { cur } else { nb };
        }
        cur = nb;
        steps -= 1;
        if steps == 0 {
            return Reduced::Fail;
        }
    };
    let (u, w) = (poly.point_at(edge), poly.point_at(poly.next_at(edge)));
    let contact = segment_contact(k, u, w, s, t);
    if contact.meets() {
        return Reduced::Edge(edge, contact, None);
    }
    let side = k.orient(u, w, s);
    Reduced::Inside(if k.cross(u, w, t, s) == side.reverse() {
        s
    } else {
        t
    })
}

/// An end of the edge `u`–`v` (which crosses the chord `s`–`t` of the other polygon)
/// in the triangle of s, t and a vertex of `points` (the other polygon's) far from the
/// chord's line on that end's side: then that end is a vertex inside. The edge's ends
/// lie within an edge's length of the chord, so the farthest of about 16 of the points
/// (every ⌈len/16⌉-th: spread over a sample in any order) nearly always serves; else
/// the farthest of all. `None` when neither end is found inside that way.
pub(super) fn end_in_triangle<K: Kernel>(
    k: K,
    edge: (Point, Point),
    chord: (Point, Point),
    points: &[Point],
) -> Option<Point> {
    let stride = (points.len() / 16).max(1);
    end_in_triangle_of(k, edge, chord, points.iter().step_by(stride).copied())
        .or_else(|| (stride > 1).then(|| end_in_triangle_of(k, edge, chord, points.iter().copied()))?)
}

/// [`end_in_triangle`] with the farthest of `points` on each side: chosen by
/// distances computed in `f64` (a guide), the triangle tested exactly (three
/// orientations per end).
pub(super) fn end_in_triangle_of<K: Kernel>(
    k: K,
    (u, v): (Point, Point),
    (s, t): (Point, Point),
    points: impl Iterator<Item = Point>,
) -> Option<Point> {
    let (dx, dy) = (t.x - s.x, t.y - s.y);
    let height = |x: Point| dx * (x.y - s.y) - dy * (x.x - s.x);
    // The farthest on the left (positive heights) and on the right.
    let (mut left, mut right) = ((0.0, None), (0.0, None));
    for x in points {
        let h = height(x);
        if h > left.0 {
            left = (h, Some(x));
        } else if h < right.0 {
            right = (h, Some(x));
        }
    }
    [u, v].into_iter().find(|&z| {
        let side = k.orient(s, t, z);
        let w = match side {
            Ccw => left.1,
            Cw => right.1,
            Collinear => None,
        };
        w.is_some_and(|w| {
            let outside = side.reverse();
            k.orient(s, t, w) == side && k.orient(t, w, z) != outside && k.orient(w, s, z) != outside
        })
    })
}

/// [`resolve_chords`] for linked polygons: the segment between positions `a1`, `a2` of
/// P meets the segment between `b1`, `b2` of Q. Chords are reduced to edges by walks
/// ([`reduce_linked`]) that start from the nearest vertex of `p_starts` (of
/// `q_starts`), so each walk stays within one gap between those vertices along the
/// boundary: expected O(n / r) for r random samples. `None` when the segments do not
/// meet or an inconsistent kernel derails a walk.
pub(crate) fn resolve_linked_chords<K: Kernel>(
    k: K,
    p: &LinkedPolygon,
    (a1, a2): (usize, usize),
    p_starts: (&[u32], &[Point]),
    q: &LinkedPolygon,
    (b1, b2): (usize, usize),
    q_starts: (&[u32], &[Point]),
) -> Option<Certificate> {
    let (a, b, s, t) = (p.point_at(a1), p.point_at(a2), q.point_at(b1), q.point_at(b2));
    let contact = segment_contact(k, a, b, s, t);
    if !contact.meets() {
        return None;
    }
    let edge_points = |poly: &LinkedPolygon, e: usize| [poly.point_at(e), poly.point_at(poly.next_at(e))];
    let (p_edge, q_edge) = (linked_edge(p, a1, a2), linked_edge(q, b1, b2));
    if let (Some(e), Some(f)) = (p_edge, q_edge) {
        return Some(Certificate::CrossingEdges {
            p: edge_points(p, e),
            q: edge_points(q, f),
        });
    }
    if contact != SegmentContact::Crossing {
        return endpoint_on_other(k, (a, b), (s, t));
    }
    // P's edge meeting Q's chord, and how they meet (the walk has classified it).
    let (e, edge_contact) = match p_edge {
        Some(e) => (e, contact),
        None => match reduce_linked(k, p, a1, p_starts, (s, t)) {
            Reduced::Edge(e, contact, _) => (e, contact),
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
    let [u, v] = edge_points(p, e);
    if let Some(f) = q_edge {
        return edge_contact.meets().then(|| Certificate::CrossingEdges {
            p: [u, v],
            q: edge_points(q, f),
        });
    }
    match edge_contact {
        SegmentContact::Crossing => {}
        SegmentContact::Disjoint => return None,
        _ => return endpoint_on_other(k, (u, v), (s, t)),
    }
    // Usually an end of P's edge, near the crossing with Q's chord, is inside Q: no
    // second walk.
    if let Some(z) = end_in_triangle(k, (u, v), (s, t), q_starts.1) {
        return Some(Certificate::VertexInside {
            of: Which::P,
            point: z,
        });
    }
    match reduce_linked(k, q, b1, q_starts, (u, v)) {
        Reduced::Edge(f, ..) => Some(Certificate::CrossingEdges {
            p: [u, v],
            q: edge_points(q, f),
        }),
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
