//! [`Certificate`]s: answers that anyone can check exactly without trusting the
//! algorithm that produced them, and [`verify`], the check.
//!
//! # The three certificates, and why one always exists
//! Two closed convex polygons P and Q either share a point or they do not.
//!
//! * **Disjoint**: some edge of P or of Q has the whole other polygon strictly on its
//!   outer side ([`Certificate::Separated`]). This is the separating axis theorem for
//!   convex polygons: 0 lies outside the Minkowski difference P − Q, a convex polygon
//!   whose every edge is an edge of P or of −Q translated by a vertex of the other
//!   polygon (the one extreme against that edge). A point outside a convex polygon is
//!   strictly outside the line of one of its edges, and "0 strictly outside edge e − w"
//!   reads "the vertex w of the other polygon, and with it that whole polygon, lies
//!   strictly on the outer side of e".
//! * **Intersecting**: a vertex of one polygon lies in the other, boundary included
//!   ([`Certificate::VertexInside`]), or an edge of P and an edge of Q share a point
//!   ([`Certificate::CrossingEdges`]). If no vertex of P lies in Q, then P ⊄ Q, so P has
//!   points inside and outside Q; P is connected, so ∂Q meets P. If ∂Q meets ∂P, some
//!   edge of Q meets some edge of P. Otherwise ∂Q lies in the interior of P, so Q ⊆ P
//!   and every vertex of Q lies in P.
//!
//! Coordinates in a certificate are always input vertices, never constructed points,
//! and edges are two consecutive vertices in counter-clockwise order (the order the
//! polygons are stored in after cleaning).
//!
//! # Checking
//! [`verify`] (arrays) and [`verify_linked`] (linked polygons) check a certificate
//! with the [`Exact`] kernel in O(n + m), independently of every algorithm. Run them
//! whenever an answer matters more than the microseconds: the certificate of a fast
//! kernel's answer may be wrong, and a wrong one is always caught.
//!
//! # How the algorithms derive them
//! Each algorithm has a certified call beside its boolean one
//! ([`ArrayIntersection::certified_with`](super::ArrayIntersection::certified_with),
//! [`LinkedIntersection::certified_with`](super::LinkedIntersection::certified_with),
//! [`Algorithm::certified`](super::Algorithm::certified)); docs/certificates.md says how each
//! one turns what it found into a certificate. The shared steps live here:
//!
//! * [`separates`]: an edge and an opposite vertex that is locally (hence globally, by
//!   convexity) the deepest against it prove separation in O(1).
//! * [`from_faces`]: given the faces (one or two vertices) where a common closed
//!   separating line supports both polygons, one of the few edges at those faces is a
//!   separating edge (the Minkowski argument above, at the vertex of P − Q extreme in
//!   the line's normal direction); O(1).
//! * [`resolve_chords`]: a chord of P (two of its vertices) that meets a chord of Q is
//!   turned into a vertex inside or two crossing edges by at most two binary searches,
//!   O(log n + log m).
//!
//! Where an algorithm's findings give no certificate at that cost, it returns only its
//! answer ([`Derivation::Answer`]) and the certified call completes it with a search
//! that always certifies that answer under [`Exact`]: [`Dobkin`](super::Dobkin)'s
//! separation for "disjoint", [`Barba`](super::Barba)'s witness for "intersecting",
//! and [`exact_certificate`](super::exact_certificate) as the last resort when an
//! inconsistent kernel leaves even those without one.

use crate::kernel::{
    DirectedLine, Exact, Kernel, Orientation, Point, SegmentContact, Sign, point_on_segment, segment_contact,
};
use crate::lp::WitnessPoint;
use crate::polygon::{ConvexPolygon, LinkedPolygon};
use std::fmt;

use Orientation::{Ccw, Collinear, Cw};

/// One of the two polygons of a query: `P` is the first argument, `Q` the second.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Which {
    /// The first polygon of the query.
    P,
    /// The second polygon of the query.
    Q,
}

impl Which {
    /// The other polygon.
    #[inline]
    pub fn other(self) -> Which {
        match self {
            Which::P => Which::Q,
            Which::Q => Which::P,
        }
    }

    /// `"p"` or `"q"`, as in the CLI's JSON.
    pub fn name(self) -> &'static str {
        match self {
            Which::P => "p",
            Which::Q => "q",
        }
    }
}

impl fmt::Display for Which {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Which::P => "P",
            Which::Q => "Q",
        })
    }
}

/// A proof of an intersection test's answer, checkable exactly by [`verify`]; see the
/// module docs for why one always exists.
///
/// ```
/// use polysect::{ConvexPolygon, Point};
/// use polysect::intersect::{ArrayIntersection, Barba, Certificate, Linear, Which, verify};
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let q = ConvexPolygon::new([[3.0, 0.0], [4.0, 0.0], [4.0, 1.0]])?;
/// // The reference names the first separating edge of P it meets: x = 2, from (2, 0)
/// // up to (2, 2), with Q strictly on its outer side.
/// let c = Linear.certified(&p, &q);
/// assert_eq!(c, Certificate::Separated { of: Which::P, from: Point::new(2.0, 0.0), to: Point::new(2.0, 2.0) });
/// assert_eq!(verify(&p, &q, &c), Ok(()));
/// // Other algorithms may name another separating edge; every one verifies.
/// let c = Barba.certified(&p, &q);
/// assert!(!c.intersects());
/// assert_eq!(verify(&p, &q, &c), Ok(()));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Certificate {
    /// The polygons are disjoint: `from` → `to` is an edge of polygon `of` (consecutive
    /// vertices, counter-clockwise) and the other polygon lies strictly on its outer
    /// (right) side.
    Separated {
        /// The polygon the edge belongs to.
        of: Which,
        /// The edge's first vertex.
        from: Point,
        /// The edge's second vertex (the counter-clockwise successor of `from`).
        to: Point,
    },
    /// The polygons intersect: `point` is a vertex of polygon `of` lying in the other
    /// polygon, boundary included.
    VertexInside {
        /// The polygon the vertex belongs to.
        of: Which,
        /// The vertex.
        point: Point,
    },
    /// The polygons intersect: `p` is an edge of P and `q` an edge of Q (consecutive
    /// vertices, counter-clockwise) and the two closed segments share a point.
    CrossingEdges {
        /// An edge of P, from a vertex to its counter-clockwise successor.
        p: [Point; 2],
        /// An edge of Q, from a vertex to its counter-clockwise successor.
        q: [Point; 2],
    },
}

impl Certificate {
    /// The answer the certificate proves.
    #[inline]
    pub fn intersects(&self) -> bool {
        !matches!(self, Certificate::Separated { .. })
    }

    /// The same certificate for the query with P and Q exchanged.
    #[inline]
    pub fn swapped(self) -> Certificate {
        match self {
            Certificate::Separated { of, from, to } => Certificate::Separated {
                of: of.other(),
                from,
                to,
            },
            Certificate::VertexInside { of, point } => Certificate::VertexInside {
                of: of.other(),
                point,
            },
            Certificate::CrossingEdges { p, q } => Certificate::CrossingEdges { p: q, q: p },
        }
    }

    /// The certificate as the caller of a query with P and Q given as `(first, second)`
    /// sees it, when it was derived with `a` in the role of P: unchanged if `a` is P.
    #[inline]
    pub(crate) fn relative_to(self, a: Which) -> Certificate {
        match a {
            Which::P => self,
            Which::Q => self.swapped(),
        }
    }
}

/// What an algorithm's certified run derived from its own findings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Derivation {
    /// A certificate of the answer.
    Certified(Certificate),
    /// Only the answer: what the algorithm found gives no certificate at the cost the
    /// algorithm allows itself; the certified call completes it with a slower search
    /// (and reports that to the [`Probe`](super::Probe)).
    Answer(bool),
}

/// Why [`verify`] rejected a certificate. Every variant names the polygon and the
/// points involved; the `Display` text says what is wrong.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CertificateError {
    /// A certificate coordinate is not a vertex of the polygon it names.
    NotAVertex {
        /// The polygon the certificate names.
        of: Which,
        /// The coordinate that is not one of its vertices.
        point: Point,
    },
    /// `from` and `to` are vertices but not consecutive: `from`'s counter-clockwise
    /// successor is `next`.
    NotAnEdge {
        /// The polygon the certificate names.
        of: Which,
        /// The edge's claimed first vertex.
        from: Point,
        /// The edge's claimed second vertex.
        to: Point,
        /// `from`'s actual counter-clockwise successor.
        next: Point,
    },
    /// `from` → `to` is an edge walked clockwise (`to` precedes `from`); edges are given
    /// counter-clockwise, so that their outer side is their right side.
    Clockwise {
        /// The polygon the certificate names.
        of: Which,
        /// The edge's claimed first vertex.
        from: Point,
        /// The edge's claimed second vertex (in fact `from`'s predecessor).
        to: Point,
    },
    /// A vertex of the other polygon is not strictly on the outer side of the edge.
    NotSeparating {
        /// The polygon the edge belongs to.
        of: Which,
        /// The edge's first vertex.
        from: Point,
        /// The edge's second vertex.
        to: Point,
        /// A vertex of the other polygon not strictly outside.
        vertex: Point,
        /// Where that vertex is: on the edge's line (`Collinear`) or inside (`Ccw`).
        side: Orientation,
    },
    /// The vertex lies strictly outside the other polygon: strictly right of its edge
    /// `from` → `to`.
    Outside {
        /// The polygon the vertex belongs to.
        of: Which,
        /// The vertex.
        point: Point,
        /// The first vertex of the other polygon's edge it is outside of.
        from: Point,
        /// That edge's second vertex.
        to: Point,
    },
    /// The two edges have no common point.
    EdgesDisjoint {
        /// The edge of P.
        p: [Point; 2],
        /// The edge of Q.
        q: [Point; 2],
    },
}

impl fmt::Display for CertificateError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let pt = |p: &Point| format!("({:?}, {:?})", p.x, p.y);
        match self {
            CertificateError::NotAVertex { of, point } => {
                write!(f, "{} is not a vertex of {of}", pt(point))
            }
            CertificateError::NotAnEdge { of, from, to, next } => write!(
                f,
                "{} → {} is not an edge of {of}: the vertex after {} (counter-clockwise) is {}",
                pt(from),
                pt(to),
                pt(from),
                pt(next)
            ),
            CertificateError::Clockwise { of, from, to } => write!(
                f,
                "{} → {} runs clockwise along {of}; edges are given counter-clockwise ({} → {})",
                pt(from),
                pt(to),
                pt(to),
                pt(from)
            ),
            CertificateError::NotSeparating {
                of,
                from,
                to,
                vertex,
                side,
            } => {
                let where_ = match side {
                    Ccw => "on its inner side",
                    Collinear => "on its line",
                    Cw => "strictly outside", // never reported
                };
                write!(
                    f,
                    "edge {} → {} of {of} does not separate: vertex {} of {} lies {where_}",
                    pt(from),
                    pt(to),
                    pt(vertex),
                    of.other()
                )
            }
            CertificateError::Outside { of, point, from, to } => write!(
                f,
                "vertex {} of {of} is outside {}: strictly right of its edge {} → {}",
                pt(point),
                of.other(),
                pt(from),
                pt(to)
            ),
            CertificateError::EdgesDisjoint { p, q } => write!(
                f,
                "edge {} → {} of P and edge {} → {} of Q have no common point",
                pt(&p[0]),
                pt(&p[1]),
                pt(&q[0]),
                pt(&q[1])
            ),
        }
    }
}

impl std::error::Error for CertificateError {}

/// Cyclic access to a convex polygon's boundary: a slice of counter-clockwise vertices
/// (indices mod n) or a [`LinkedPolygon`] (arena positions, which are exactly `0..len`).
pub(crate) trait Boundary {
    fn count(&self) -> usize;
    fn at(&self, v: usize) -> Point;
    fn next(&self, v: usize) -> usize;
    fn prev(&self, v: usize) -> usize;
}

impl Boundary for [Point] {
    #[inline]
    fn count(&self) -> usize {
        self.len()
    }
    #[inline]
    fn at(&self, v: usize) -> Point {
        self[v]
    }
    #[inline]
    fn next(&self, v: usize) -> usize {
        if v + 1 == self.len() { 0 } else { v + 1 }
    }
    #[inline]
    fn prev(&self, v: usize) -> usize {
        if v == 0 { self.len() - 1 } else { v - 1 }
    }
}

impl Boundary for LinkedPolygon {
    #[inline]
    fn count(&self) -> usize {
        self.len()
    }
    #[inline]
    fn at(&self, v: usize) -> Point {
        self.point_at(v)
    }
    #[inline]
    fn next(&self, v: usize) -> usize {
        self.next_at(v)
    }
    #[inline]
    fn prev(&self, v: usize) -> usize {
        self.prev_at(v)
    }
}

/// Checks `certificate` for the query "do `p` and `q` intersect?" exactly, with no
/// trust in whoever produced it. `Ok(())` means the certificate proves its answer
/// ([`Certificate::intersects`]).
///
/// # Complexity
/// O(n + m) for polygons of n and m vertices: the named vertices are found by a scan,
/// then a separating edge is tested against every vertex of the other polygon, or a
/// vertex against every edge of the other polygon, or two edges against each other.
///
/// # Precision
/// Every test is an [`Exact`] predicate on input coordinates; vertices are matched by
/// exact `f64` equality (a point one ulp away from a vertex is not that vertex).
///
/// # Errors
/// A [`CertificateError`] saying what is wrong: a coordinate that is not a vertex, two
/// vertices that are not an edge or are given clockwise, a vertex of the other polygon
/// on the wrong side of a claimed separating edge, a vertex outside the polygon it is
/// claimed to lie in, or two claimed crossing edges that do not meet.
///
/// ```
/// use polysect::{ConvexPolygon, Point};
/// use polysect::intersect::{Certificate, CertificateError, Which, verify};
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let q = ConvexPolygon::new([[1.0, 1.0], [3.0, 1.0], [3.0, 3.0]])?;
/// let inside = Certificate::VertexInside { of: Which::Q, point: Point::new(1.0, 1.0) };
/// assert_eq!(verify(&p, &q, &inside), Ok(()));
/// let wrong = Certificate::Separated { of: Which::P, from: Point::new(2.0, 0.0), to: Point::new(2.0, 2.0) };
/// assert!(matches!(verify(&p, &q, &wrong), Err(CertificateError::NotSeparating { .. })));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
pub fn verify(
    p: &ConvexPolygon,
    q: &ConvexPolygon,
    certificate: &Certificate,
) -> Result<(), CertificateError> {
    verify_on(p.vertices(), q.vertices(), certificate)
}

/// [`verify`] for linked polygons, walking them in place (no conversion).
///
/// # Errors
/// As [`verify`].
pub fn verify_linked(
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    certificate: &Certificate,
) -> Result<(), CertificateError> {
    verify_on(p, q, certificate)
}

fn verify_on<A: Boundary + ?Sized, B: Boundary + ?Sized>(
    p: &A,
    q: &B,
    certificate: &Certificate,
) -> Result<(), CertificateError> {
    let k = Exact;
    match *certificate {
        Certificate::Separated { of, from, to } => match of {
            Which::P => check_separated(k, p, q, of, from, to),
            Which::Q => check_separated(k, q, p, of, from, to),
        },
        Certificate::VertexInside { of, point } => match of {
            Which::P => check_inside(k, p, q, of, point),
            Which::Q => check_inside(k, q, p, of, point),
        },
        Certificate::CrossingEdges { p: pe, q: qe } => {
            find_edge(p, Which::P, pe[0], pe[1])?;
            find_edge(q, Which::Q, qe[0], qe[1])?;
            match segment_contact(k, pe[0], pe[1], qe[0], qe[1]) {
                SegmentContact::Disjoint => Err(CertificateError::EdgesDisjoint { p: pe, q: qe }),
                _ => Ok(()),
            }
        }
    }
}

/// The position of vertex `point` of `poly` (a scan; exact equality).
fn find_vertex<A: Boundary + ?Sized>(poly: &A, of: Which, point: Point) -> Result<usize, CertificateError> {
    (0..poly.count())
        .find(|&v| poly.at(v) == point)
        .ok_or(CertificateError::NotAVertex { of, point })
}

/// Checks that `from` → `to` is a counter-clockwise edge of `poly`.
fn find_edge<A: Boundary + ?Sized>(
    poly: &A,
    of: Which,
    from: Point,
    to: Point,
) -> Result<(), CertificateError> {
    let v = find_vertex(poly, of, from)?;
    find_vertex(poly, of, to)?;
    let next = poly.at(poly.next(v));
    if next == to {
        Ok(())
    } else if poly.at(poly.prev(v)) == to {
        Err(CertificateError::Clockwise { of, from, to })
    } else {
        Err(CertificateError::NotAnEdge { of, from, to, next })
    }
}

fn check_separated<A: Boundary + ?Sized, B: Boundary + ?Sized>(
    k: Exact,
    a: &A,
    b: &B,
    of: Which,
    from: Point,
    to: Point,
) -> Result<(), CertificateError> {
    find_edge(a, of, from, to)?;
    for v in 0..b.count() {
        let vertex = b.at(v);
        let side = k.orient(from, to, vertex);
        if side != Cw {
            return Err(CertificateError::NotSeparating {
                of,
                from,
                to,
                vertex,
                side,
            });
        }
    }
    Ok(())
}

fn check_inside<A: Boundary + ?Sized, B: Boundary + ?Sized>(
    k: Exact,
    a: &A,
    b: &B,
    of: Which,
    point: Point,
) -> Result<(), CertificateError> {
    find_vertex(a, of, point)?;
    for v in 0..b.count() {
        let (from, to) = (b.at(v), b.at(b.next(v)));
        if k.orient(from, to, point) == Cw {
            return Err(CertificateError::Outside { of, point, from, to });
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------
// Derivation helpers shared by the algorithms.
// ---------------------------------------------------------------------------------

/// Whether the edge `u` → `v` of one polygon separates the other polygon `b`, given
/// that polygon's vertex `w`: `w` is strictly right of the edge's line and neither of
/// its neighbours lies deeper on the inner side (`w` is extreme against the edge, and
/// on a convex polygon a local extreme is global). Three predicates.
#[inline]
pub(crate) fn separates<K: Kernel, B: Boundary + ?Sized>(k: K, u: Point, v: Point, b: &B, w: usize) -> bool {
    let x = b.at(w);
    k.orient(u, v, x) == Cw
        && k.cross(u, v, x, b.at(b.next(w))) != Ccw
        && k.cross(u, v, x, b.at(b.prev(w))) != Ccw
}

/// A separating edge at the faces where one closed separating line supports both
/// polygons: `face_a` holds the vertices of `a` extreme in the line's normal direction
/// (towards `b`), `face_b` those of `b` extreme the other way (one vertex, or the two
/// ends of an edge parallel to the line; extra vertices only cost time). Tries the
/// edges of `b` at `face_b` against `face_a`, then the edges of `a` at `face_a`
/// against `face_b`, each with [`separates`].
///
/// Some candidate succeeds whenever the faces are right and the polygons disjoint: the
/// vertex of a − b extreme in the line's normal direction lies at the faces, and one
/// of the edges of a − b next to that face separates 0 (module docs). The certificate
/// names `a` as [`Which::P`].
pub(crate) fn from_faces<K: Kernel, A: Boundary + ?Sized, B: Boundary + ?Sized>(
    k: K,
    a: &A,
    face_a: &[usize],
    b: &B,
    face_b: &[usize],
) -> Option<Certificate> {
    for &x in face_b {
        for (u, v) in [(b.prev(x), x), (x, b.next(x))] {
            let (pu, pv) = (b.at(u), b.at(v));
            if face_a.iter().any(|&y| separates(k, pu, pv, a, y)) {
                return Some(Certificate::Separated {
                    of: Which::Q,
                    from: pu,
                    to: pv,
                });
            }
        }
    }
    for &y in face_a {
        for (u, v) in [(a.prev(y), y), (y, a.next(y))] {
            let (pu, pv) = (a.at(u), a.at(v));
            if face_b.iter().any(|&x| separates(k, pu, pv, b, x)) {
                return Some(Certificate::Separated {
                    of: Which::P,
                    from: pu,
                    to: pv,
                });
            }
        }
    }
    None
}

/// [`from_faces`] for a closed separating line `s` → `e` through (or parallel to the
/// support at) the extreme vertices `a0` of `a` (on the right) and `b0` of `b` (on the
/// left): each face is the vertex plus a neighbour whose edge to it is parallel to the
/// line.
pub(crate) fn from_support<K: Kernel, A: Boundary + ?Sized, B: Boundary + ?Sized>(
    k: K,
    (s, e): (Point, Point),
    a: &A,
    a0: usize,
    b: &B,
    b0: usize,
) -> Option<Certificate> {
    let face = |poly: &dyn Fn(usize) -> Point, v: usize, prev: usize, next: usize| {
        let mut f = [v, v, v];
        let mut len = 1;
        for nb in [prev, next] {
            if k.cross(s, e, poly(v), poly(nb)) == Collinear {
                f[len] = nb;
                len += 1;
            }
        }
        (f, len)
    };
    let (fa, la) = face(&|i| a.at(i), a0, a.prev(a0), a.next(a0));
    let (fb, lb) = face(&|i| b.at(i), b0, b.prev(b0), b.next(b0));
    from_faces(k, a, &fa[..la], b, &fb[..lb])
}

/// `v` is a vertex of the convex polygon whose directed line `s` → `e` has the polygon on
/// its closed right side: neither neighbour of `v` lies strictly left of the line through
/// `v` parallel to it, so (by convexity) no vertex does. Two predicates.
#[inline]
pub(crate) fn supports_right<K: Kernel, A: Boundary + ?Sized>(
    k: K,
    (s, e): (Point, Point),
    a: &A,
    v: usize,
) -> bool {
    let x = a.at(v);
    k.cross(s, e, x, a.at(a.next(v))) != Ccw && k.cross(s, e, x, a.at(a.prev(v))) != Ccw
}

/// As [`supports_right`], for a polygon on the closed left side.
#[inline]
pub(crate) fn supports_left<K: Kernel, A: Boundary + ?Sized>(
    k: K,
    (s, e): (Point, Point),
    a: &A,
    v: usize,
) -> bool {
    let x = a.at(v);
    k.cross(s, e, x, a.at(a.next(v))) != Cw && k.cross(s, e, x, a.at(a.prev(v))) != Cw
}

/// Whether directions `a` and `b` (each from its first point to its second) are equal.
#[inline]
pub(crate) fn same_direction<K: Kernel>(k: K, a: (Point, Point), b: (Point, Point)) -> bool {
    k.cross(a.0, a.1, b.0, b.1) == Collinear && k.dot(a.0, a.1, b.0, b.1) == Sign::Positive
}

/// Whether direction `a` is turned further counter-clockwise from `base` than `c`,
/// with turns measured in [0, 2π).
#[inline]
pub(crate) fn turn_gt<K: Kernel>(k: K, base: (Point, Point), a: (Point, Point), c: (Point, Point)) -> bool {
    turn_gt_classed(k, base, (a, turn_class(k, base, a)), c)
}

/// The quadrant of direction `d`'s turn from `base`: 0 (none), 1 (in (0, π)), 2 (π) or
/// 3 (in (π, 2π)).
#[inline]
fn turn_class<K: Kernel>(k: K, base: (Point, Point), d: (Point, Point)) -> u8 {
    match k.cross(base.0, base.1, d.0, d.1) {
        Ccw => 1,
        Cw => 3,
        Collinear => {
            if k.dot(base.0, base.1, d.0, d.1) == Sign::Positive {
                0
            } else {
                2
            }
        }
    }
}

/// [`turn_gt`] with `a`'s [`turn_class`] computed once by the caller.
#[inline]
fn turn_gt_classed<K: Kernel>(
    k: K,
    base: (Point, Point),
    (a, ca): ((Point, Point), u8),
    c: (Point, Point),
) -> bool {
    let cc = turn_class(k, base, c);
    if ca != cc {
        ca > cc
    } else {
        (ca == 1 || ca == 3) && k.cross(c.0, c.1, a.0, a.1) == Ccw
    }
}

/// A vertex of the convex polygon `v` (counter-clockwise) farthest to the left of the
/// directed line `s` → `e`, by binary search: O(log n) predicates.
///
/// Leftness grows along edges turned less than the reversed direction e → s (counted
/// from edge 0's direction, in [0, 2π)) and shrinks along the others, so the extreme
/// vertex starts the first edge turned at least that far.
pub(crate) fn extreme_left<K: Kernel>(k: K, v: &[Point], (s, e): (Point, Point)) -> usize {
    let n = v.len();
    let base = (v[0], v[1]);
    let target = (e, s);
    let target = (target, turn_class(k, base, target));
    // First index i in 0..n with turn(edge i) ≥ turn(target); n if none.
    let reached = |i: usize| !turn_gt_classed(k, base, target, (v[i], v[if i + 1 == n { 0 } else { i + 1 }]));
    let (mut lo, mut hi) = (0, n);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if reached(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo % n
}

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
fn crossing_edge<K: Kernel>(
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
const ROUND: f64 = 4_503_599_627_370_496.0;

/// Chains at least this long are searched by [`regula_falsi`] first: on shorter ones its
/// arithmetic costs more than the probes it saves (docs/certificates.md, "Barba, eighth
/// round").
const INTERPOLATE_FROM: usize = 1 << 11;

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
fn regula_falsi<K: Kernel>(
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
fn resolve_crossing<K: Kernel>(
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

/// A vertex named by a witness of intersecting hulls: its coordinates, its polygon,
/// and its arena position when known.
#[derive(Clone, Copy, Debug)]
pub(crate) struct WitnessVertex {
    pub(crate) point: Point,
    pub(crate) of: Which,
    pub(crate) pos: Option<usize>,
}

/// At most this many witness points per polygon.
const WITNESS_MAX: usize = 9;

/// At most [`WITNESS_MAX`] vertices of one polygon, sorted lexicographically without
/// repeats, with their positions (`usize::MAX`: unknown), and their convex hull.
struct SmallSet {
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
fn nearest_beside<K: Kernel>(
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
fn linked_edge(poly: &LinkedPolygon, u: usize, w: usize) -> Option<usize> {
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
fn reduce_linked<K: Kernel>(
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
fn end_in_triangle<K: Kernel>(
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
fn end_in_triangle_of<K: Kernel>(
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A witness point at (x, y) of polygon `of`, at arena position `pos`.
    fn w(x: f64, y: f64, of: Which, pos: usize) -> WitnessVertex {
        WitnessVertex {
            point: Point::new(x, y),
            of,
            pos: Some(pos),
        }
    }

    fn poly(pts: &[[f64; 2]]) -> ConvexPolygon {
        ConvexPolygon::new(pts.iter().copied()).unwrap()
    }

    const SQ: [[f64; 2]; 4] = [[0., 0.], [2., 0.], [2., 2.], [0., 2.]];

    #[test]
    fn verify_accepts_each_kind_and_names_what_is_wrong() {
        let p = poly(&SQ);
        let q = poly(&[[3., 0.], [4., 0.], [4., 1.]]);
        let pt = Point::new;
        let sep = Certificate::Separated {
            of: Which::P,
            from: pt(2., 0.),
            to: pt(2., 2.),
        };
        assert_eq!(verify(&p, &q, &sep), Ok(()));
        assert!(!sep.intersects());
        // The same edge walked clockwise.
        let cw = Certificate::Separated {
            of: Which::P,
            from: pt(2., 2.),
            to: pt(2., 0.),
        };
        let e = verify(&p, &q, &cw).unwrap_err();
        assert!(matches!(e, CertificateError::Clockwise { .. }));
        assert!(e.to_string().contains("clockwise"), "{e}");
        // Not consecutive.
        let diag = Certificate::Separated {
            of: Which::P,
            from: pt(0., 0.),
            to: pt(2., 2.),
        };
        let e = verify(&p, &q, &diag).unwrap_err();
        assert_eq!(
            e.to_string(),
            "(0.0, 0.0) → (2.0, 2.0) is not an edge of P: the vertex after (0.0, 0.0) (counter-clockwise) is (2.0, 0.0)"
        );
        // The wrong polygon.
        let wrong = Certificate::Separated {
            of: Which::Q,
            from: pt(2., 0.),
            to: pt(2., 2.),
        };
        assert_eq!(
            verify(&p, &q, &wrong).unwrap_err().to_string(),
            "(2.0, 0.0) is not a vertex of Q"
        );
        // An edge that does not separate: Q lies on its inner side.
        let bad = Certificate::Separated {
            of: Which::P,
            from: pt(0., 2.),
            to: pt(0., 0.),
        };
        assert!(matches!(
            verify(&p, &q, &bad),
            Err(CertificateError::NotSeparating { side: Ccw, .. })
        ));

        let r = poly(&[[1., 1.], [3., 1.], [3., 3.]]);
        let inside = Certificate::VertexInside {
            of: Which::Q,
            point: pt(1., 1.),
        };
        assert_eq!(verify(&p, &r, &inside), Ok(()));
        let outside = Certificate::VertexInside {
            of: Which::Q,
            point: pt(3., 3.),
        };
        assert_eq!(
            verify(&p, &r, &outside).unwrap_err().to_string(),
            "vertex (3.0, 3.0) of Q is outside P: strictly right of its edge (2.0, 0.0) → (2.0, 2.0)"
        );
        let cross = Certificate::CrossingEdges {
            p: [pt(2., 0.), pt(2., 2.)],
            q: [pt(1., 1.), pt(3., 1.)],
        };
        assert_eq!(verify(&p, &r, &cross), Ok(()));
        let apart = Certificate::CrossingEdges {
            p: [pt(0., 0.), pt(2., 0.)],
            q: [pt(3., 1.), pt(3., 3.)],
        };
        assert!(matches!(
            verify(&p, &r, &apart),
            Err(CertificateError::EdgesDisjoint { .. })
        ));
        // Linked polygons in shuffled arena order verify the same way.
        use rand::SeedableRng;
        let mut rng = rand::rngs::SmallRng::seed_from_u64(3);
        let (lp, lr) = (
            LinkedPolygon::from_convex_shuffled(&p, &mut rng),
            LinkedPolygon::from_convex_shuffled(&r, &mut rng),
        );
        assert_eq!(verify_linked(&lp, &lr, &cross), Ok(()));
        // (The arena order decides which offending edge is named.)
        assert!(matches!(
            verify_linked(&lp, &lr, &outside),
            Err(CertificateError::Outside { .. })
        ));
    }

    /// `reduce_chord` where its triangle test misses, on concrete points (a 10-gon with
    /// integer coordinates, the chord from (8, 0) to (−8, 0) over the top, the segment's
    /// other end at (0, −1)): ends outside the triangle (0, 4, 8) but in the polygon, one
    /// of them on the chord from vertex 0 to vertex 2 and one an ulp beyond that chord,
    /// are found inside by the search; an end an ulp outside the polygon gives an edge
    /// that meets the segment. At scales 1, 2^600 and 2^-600 (exact).
    #[test]
    fn chord_reduction_past_the_triangle_test() {
        let base = [
            (8., 0.),
            (8., 3.),
            (7., 5.),
            (5., 7.),
            (0., 8.),
            (-5., 7.),
            (-7., 5.),
            (-8., 3.),
            (-8., 0.),
            (0., -4.),
        ];
        let far = (0., -1.);
        // Each end, and whether it lies in the polygon.
        let ends = [
            ((6., 5.), true),
            ((7.5, 2.5), true),
            ((f64::from_bits(7.5f64.to_bits() + 1), 2.5), true),
            ((f64::from_bits(8f64.to_bits() + 1), 1.), false),
        ];
        for scale in [1.0, 2f64.powi(600), 2f64.powi(-600)] {
            let pt = |(x, y): (f64, f64)| Point::new(x * scale, y * scale);
            let pv: Vec<Point> = base.iter().map(|&v| pt(v)).collect();
            let n = pv.len();
            let inside = |x: Point| (0..n).all(|i| Exact.orient(pv[i], pv[(i + 1) % n], x) != Cw);
            for (k, &(near, in_p)) in ends.iter().enumerate() {
                let (s, t) = (pt(far), pt(near));
                match reduce_chord(Exact, &pv, (0, 8), (s, t), None, None) {
                    Reduced::Inside(x) => {
                        assert!(in_p && x == t && inside(x), "×{scale} {near:?}");
                    }
                    Reduced::Edge(e, contact, _) => {
                        assert!(!in_p && contact.meets(), "×{scale} {near:?}");
                        assert!(
                            segment_contact(Exact, pv[e], pv[(e + 1) % n], s, t).meets(),
                            "×{scale} {near:?}: edge {e}"
                        );
                    }
                    Reduced::Beyond(_) | Reduced::Fail => panic!("×{scale} {near:?}: failed"),
                }
                // The triangle test misses every end; the triangle (0, 2, 4) holds the
                // first two only (the second on its edge), the third is an ulp beyond it.
                let in_triangle = |a: usize, b: usize, c: usize| {
                    [(a, b), (b, c), (c, a)]
                        .iter()
                        .all(|&(u, v)| Exact.orient(pv[u], pv[v], t) != Cw)
                };
                assert!(!in_triangle(0, 4, 8), "×{scale} {near:?}");
                assert_eq!(in_triangle(0, 2, 4), k < 2, "×{scale} {near:?}");
                assert_eq!(inside(t), in_p, "×{scale} {near:?}");
            }
        }
    }

    /// The chain search finds the crossing edge a scan finds, on every family's polygons
    /// (touching, one-ulp, nested and ordinary pairs, up to 2^12 vertices, so that long
    /// chains take the regula falsi probes) for lines through two vertices,
    /// with the side of the edge's end; and every chord of P crossing a chord of Q properly resolves to a certificate
    /// that verifies, at ordinary scale and scaled by 2^600 and 2^-600.
    #[test]
    fn chain_search_finds_the_crossing_and_chords_resolve() {
        use crate::generate::{self, Family, Relation, map_pair};
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::SmallRng::seed_from_u64(0x1e7);
        let (mut searches, mut resolved) = (0, 0);
        for &family in Family::ALL {
            // 2^12: chains long enough for `regula_falsi`.
            for log2 in [3, 6, 10, 12] {
                for relation in [Relation::Intersecting, Relation::Any] {
                    let Ok(base) = generate::try_pair(family, 1 << log2, relation, &mut rng) else {
                        continue;
                    };
                    for scale in [1.0, 2f64.powi(600), 2f64.powi(-600)] {
                        let Some((p, q)) = map_pair(&base, |v| Point::new(v.x * scale, v.y * scale)) else {
                            continue;
                        };
                        let (pv, qv) = (p.vertices(), q.vertices());
                        let (n, m) = (pv.len(), qv.len());
                        for _ in 0..20 {
                            // A chord of P and a line through two vertices of Q.
                            let (i, len) = (rng.random_range(0..n), rng.random_range(2..n));
                            let j = (i + len) % n;
                            let (c, d) = (rng.random_range(0..m), rng.random_range(0..m));
                            let (s, t) = (qv[c], qv[d]);
                            let line = DirectedLine::new(s, t);
                            let at = |off: usize| pv[(i + off) % n];
                            let sigma = Exact.orient_line(&line, at(0));
                            let end = Exact.orient_line(&line, at(len));
                            if c == d || sigma == Collinear || end != sigma.reverse() {
                                continue;
                            }
                            let sides: Vec<bool> = (0..=len)
                                .map(|o| Exact.orient_line(&line, at(o)) == sigma)
                                .collect();
                            let Some(first_off) = sides.iter().position(|&x| !x) else {
                                unreachable!("the chain ends off sigma's side");
                            };
                            // One crossing (a convex chain): sides hold until first_off.
                            let Ok((lo, o_next)) =
                                crossing_edge(Exact, &line, &at, (at(0), at(len)), len, sigma, &|_, _| false)
                            else {
                                unreachable!("no probe is accepted");
                            };
                            if sides[first_off..].iter().all(|&x| !x) {
                                assert_eq!(lo + 1, first_off, "{family:?} 2^{log2} ×{scale}");
                                assert_eq!(o_next, Exact.orient_line(&line, at(lo + 1)));
                                searches += 1;
                            }
                            if segment_contact(Exact, pv[i], pv[j], s, t) == SegmentContact::Crossing {
                                let cert = resolve_chords(Exact, pv, (i, j), qv, (c, d))
                                    .unwrap_or_else(|| panic!("{family:?} 2^{log2} ×{scale}: none"));
                                assert_eq!(verify(&p, &q, &cert), Ok(()), "{family:?} 2^{log2} ×{scale}");
                                resolved += 1;
                            }
                        }
                    }
                }
            }
        }
        assert!(
            searches > 300 && resolved > 80,
            "{searches} searches, {resolved} resolved"
        );
    }

    #[test]
    fn resolve_chords_turns_diagonals_into_witnesses() {
        // Two squares rotated against each other: the diagonals cross at the centre.
        let p = poly(&[[0., 0.], [4., 0.], [4., 4.], [0., 4.]]);
        let q = poly(&[[2., -1.], [5., 2.], [2., 5.], [-1., 2.]]);
        let c = resolve_chords(Exact, p.vertices(), (0, 2), q.vertices(), (0, 2)).unwrap();
        assert_eq!(verify(&p, &q, &c), Ok(()), "{c:?}");
        // A thin cross: no vertex inside, only crossing edges.
        let h = poly(&[[-10., -1.], [10., -1.], [10., 1.], [-10., 1.]]);
        let v = poly(&[[-1., -10.], [1., -10.], [1., 10.], [-1., 10.]]);
        let c = resolve_chords(Exact, h.vertices(), (0, 2), v.vertices(), (1, 3)).unwrap();
        assert!(matches!(c, Certificate::CrossingEdges { .. }), "{c:?}");
        assert_eq!(verify(&h, &v, &c), Ok(()));
        // Disjoint segments: no certificate.
        let far = poly(&[[20., 20.], [21., 20.], [21., 21.]]);
        assert_eq!(
            resolve_chords(Exact, h.vertices(), (0, 2), far.vertices(), (0, 1)),
            None
        );
    }

    /// The positions of a linked polygon in boundary order.
    fn boundary_order(lp: &LinkedPolygon) -> Vec<usize> {
        let mut at = lp.position(lp.first()).unwrap();
        (0..lp.len())
            .map(|_| {
                let here = at;
                at = lp.next_at(at);
                here
            })
            .collect()
    }

    /// Chords of crossing polygons resolved by walks on linked polygons, with the walks'
    /// starts chosen by `f64` distances: at ordinary scale, where those distances
    /// overflow (2^1000: every one is infinite or NaN) and where they underflow to zero
    /// (2^-1000), so that the exact check and the fallback to the chord's own end are
    /// used. Every certificate found verifies, and chords that meet always give one.
    #[test]
    fn linked_chords_resolve_at_every_scale() {
        use crate::generate::{Family, Relation, map_pair, pair};
        use rand::SeedableRng;
        let mut rng = rand::rngs::SmallRng::seed_from_u64(0x11c4);
        let scales = [1.0, 2f64.powi(1000), 2f64.powi(-1000)];
        let mut resolved = [0; 3];
        for round in 0..6 {
            let base = pair(Family::Rotated, 40 + 7 * round, Relation::Intersecting, &mut rng);
            for (&scale, resolved) in scales.iter().zip(&mut resolved) {
                let Some((p, q)) = map_pair(&base, |v| Point::new(v.x * scale, v.y * scale)) else {
                    continue;
                };
                let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
                let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
                let (op, oq) = (boundary_order(&lp), boundary_order(&lq));
                // Every fifth vertex serves as a walk's possible start.
                let starts = |lp: &LinkedPolygon, o: &[usize]| -> (Vec<u32>, Vec<Point>) {
                    o.iter().step_by(5).map(|&i| (i as u32, lp.point_at(i))).unzip()
                };
                let (sp, sq) = (starts(&lp, &op), starts(&lq, &oq));
                for i in (0..op.len()).step_by(2) {
                    for j in (0..oq.len()).step_by(2) {
                        let a = (op[i], op[(i + 7) % op.len()]);
                        let b = (oq[j], oq[(j + 9) % oq.len()]);
                        let meets = segment_contact(
                            Exact,
                            lp.point_at(a.0),
                            lp.point_at(a.1),
                            lq.point_at(b.0),
                            lq.point_at(b.1),
                        )
                        .meets();
                        let c = resolve_linked_chords(Exact, &lp, a, (&sp.0, &sp.1), &lq, b, (&sq.0, &sq.1));
                        assert_eq!(c.is_some(), meets, "scale {scale}, chords {a:?} {b:?}");
                        if let Some(c) = c {
                            assert_eq!(verify_linked(&lp, &lq, &c), Ok(()), "scale {scale}: {c:?}");
                            *resolved += 1;
                        }
                    }
                }
            }
        }
        assert!(
            resolved.iter().all(|&r| r > 20),
            "chords resolved per scale: {resolved:?}"
        );
    }

    /// The LP's witness points: a vertex inside (on a vertex, on an edge, strictly
    /// inside), repeats, and crossing segments with no vertex inside.
    #[test]
    fn witness_points_give_a_vertex_inside_or_chords() {
        let (p, q) = (Which::P, Which::Q);
        // A point of P on an edge of Q's triangle (touching), repeated.
        let pts = [
            w(1., 0., p, 0),
            w(1., 0., p, 0),
            w(5., 5., p, 1),
            w(0., 0., q, 2),
            w(2., 0., q, 3),
            w(0., 2., q, 4),
        ];
        match witness_certificate(Exact, pts.into_iter()) {
            Radon::Inside(Certificate::VertexInside { of, point }) => {
                assert_eq!((of, point), (Which::P, Point::new(1., 0.)));
            }
            _ => panic!("expected a vertex inside"),
        }
        // A vertex of Q strictly inside P's triangle, P's points listed after Q's.
        let pts = [
            w(1., 1., q, 0),
            w(9., 9., q, 1),
            w(0., 0., p, 2),
            w(4., 0., p, 3),
            w(0., 4., p, 4),
        ];
        assert!(matches!(
            witness_certificate(Exact, pts.into_iter()),
            Radon::Inside(Certificate::VertexInside { of: Which::Q, .. })
        ));
        // Two crossing segments, no vertex inside: the chords with their positions.
        let pts = [
            w(-1., 0., p, 7),
            w(1., 0., p, 8),
            w(0., -1., q, 5),
            w(0., 1., q, 6),
        ];
        match witness_certificate(Exact, pts.into_iter()) {
            Radon::Chords(a, b) => {
                let (mut a, mut b) = (a.map(Option::unwrap), b.map(Option::unwrap));
                a.sort_unstable();
                b.sort_unstable();
                assert_eq!((a, b), ([7, 8], [5, 6]));
            }
            _ => panic!("expected crossing chords"),
        }
        // Apart: nothing.
        let pts = [w(0., 0., p, 0), w(1., 0., p, 1), w(5., 5., q, 2), w(6., 5., q, 3)];
        assert!(matches!(
            witness_certificate(Exact, pts.into_iter()),
            Radon::Nothing
        ));
        // A one-ulp gap between a vertex of P and Q's edge: no contact.
        let below = -f64::from_bits(1);
        let pts = [
            w(1., below, p, 0),
            w(1., -3., p, 1),
            w(0., 0., q, 2),
            w(2., 0., q, 3),
            w(1., 2., q, 4),
        ];
        assert!(matches!(
            witness_certificate(Exact, pts.into_iter()),
            Radon::Nothing
        ));
    }

    #[test]
    fn last_step_witnesses_give_a_vertex_inside_or_chords() {
        let (p, q) = (Which::P, Which::Q);
        let tri = [w(0., 0., q, 0), w(4., 0., q, 1), w(0., 4., q, 2)];
        // x on the triangle's edge (touching): a vertex inside.
        match straddle_certificate(Exact, [w(2., 2., p, 5), w(9., 9., p, 6)], tri) {
            Radon::Inside(Certificate::VertexInside { of, point }) => {
                assert_eq!((of, point), (Which::P, Point::new(2., 2.)));
            }
            _ => panic!("expected a vertex inside"),
        }
        // x one ulp beyond that edge: the segment from x crosses the triangle's edges.
        let beyond = 2f64 + f64::EPSILON * 2.0;
        match straddle_certificate(Exact, [w(beyond, 2., p, 5), w(-1., 1., p, 6)], tri) {
            Radon::Chords(a, b) => {
                assert_eq!(a, [Some(5), Some(6)]);
                assert!(b.iter().all(Option::is_some));
            }
            _ => panic!("expected crossing chords"),
        }
        // y₀ equal to a bound: segment against segment, touching at a vertex.
        let seg = [w(0., 0., q, 0), w(4., 0., q, 1), w(4., 0., q, 1)];
        match straddle_certificate(Exact, [w(2., 0., p, 5), w(2., 3., p, 6)], seg) {
            Radon::Inside(Certificate::VertexInside { of, point }) => {
                assert_eq!((of, point), (Which::P, Point::new(2., 0.)));
            }
            _ => panic!("expected a vertex inside"),
        }
        // ... and crossing properly; extreme coordinates are carried exactly.
        let big = f64::MAX / 4.0;
        let seg = [w(-big, 0., q, 0), w(big, 0., q, 1), w(big, 0., q, 1)];
        assert!(matches!(
            straddle_certificate(Exact, [w(0., big, p, 5), w(1., -big, p, 6)], seg),
            Radon::Chords(..)
        ));
        // The mixed case: y in a triangle of the other polygon, boundary included, and
        // not one ulp outside it; degenerate triangles are skipped.
        let tiny = f64::from_bits(1);
        let tri = [w(0., 0., p, 0), w(4. * tiny, 0., p, 1), w(0., 4. * tiny, p, 2)];
        let line = [w(0., 0., p, 0), w(1., 1., p, 1), w(2., 2., p, 2)];
        assert_eq!(
            in_triangles(Exact, w(2. * tiny, 2. * tiny, q, 9), &[line, tri]),
            Some(Certificate::VertexInside {
                of: Which::Q,
                point: Point::new(2. * tiny, 2. * tiny)
            })
        );
        assert_eq!(
            in_triangles(Exact, w(3. * tiny, 2. * tiny, q, 9), &[line, tri]),
            None
        );
        // A repeated vertex (the LP's bound equal to its previous tangent point) is
        // skipped by comparing points, even for y at that vertex; the next triangle
        // still counts, here with y one ulp inside its hypotenuse's end.
        let repeated = [w(0., 0., p, 0), w(4. * tiny, 0., p, 1), w(4. * tiny, 0., p, 1)];
        assert_eq!(in_triangles(Exact, w(4. * tiny, 0., q, 9), &[repeated]), None);
        assert_eq!(
            in_triangles(Exact, w(3. * tiny, tiny, q, 9), &[repeated, tri]),
            Some(Certificate::VertexInside {
                of: Which::Q,
                point: Point::new(3. * tiny, tiny)
            })
        );
        assert_eq!(
            in_triangles(Exact, w(3. * tiny, 2. * tiny, q, 9), &[repeated, tri]),
            None
        );
    }

    #[test]
    fn faces_of_a_common_support_line_give_the_separating_edge() {
        let p = poly(&SQ);
        let q = poly(&[[3., 3.], [4., 3.], [4., 4.]]);
        // The line x + y = 5.5... through no vertex: faces (2,2) of P and (3,3) of Q.
        let c = from_faces(Exact, p.vertices(), &[2], q.vertices(), &[0]).unwrap();
        assert_eq!(verify(&p, &q, &c), Ok(()), "{c:?}");
    }

    /// The cone search on hand-made examined sets (A's points, then B's, the violating
    /// point x of A last): a point of B in the cone's triangle (inside, and exactly on
    /// its side), none when it is one ulp outside, x in a triangle of B's points, and
    /// two crossing segments when B's hull only crosses the triangle.
    #[test]
    fn cone_witness_finds_points_in_the_triangle_or_crossing_segments() {
        let a = |x: f64, y: f64, i: usize| WitnessPoint {
            point: Point::new(x, y),
            in_b: false,
            index: Some(i),
        };
        let b = |x: f64, y: f64, i: usize| WitnessPoint {
            point: Point::new(x, y),
            in_b: true,
            index: Some(i),
        };
        let x = a(0.0, 2.0, 3);
        let own = [a(-2.0, 0.0, 0), a(2.0, 0.0, 1), a(0.0, -1.0, 2)];
        let of = |in_b: bool| if in_b { Which::Q } else { Which::P };
        let run = |others: &[WitnessPoint], chords: bool| {
            let pts: Vec<WitnessPoint> = own.iter().chain(others).chain([&x]).copied().collect();
            cone_witness(Exact, x, || pts.clone().into_iter(), of, chords)
        };
        let inside = |c: Cone| match c {
            Cone::Inside(Certificate::VertexInside { of, point }) => Some((of, point)),
            _ => None,
        };
        // Strictly inside, and on the side x → (2, 0) (the line x + y = 2).
        assert_eq!(
            inside(run(&[b(5.0, 5.0, 0), b(0.0, 1.0, 1)], false)),
            Some((Which::Q, Point::new(0.0, 1.0)))
        );
        assert_eq!(
            inside(run(&[b(5.0, 5.0, 0), b(1.0, 1.0, 1)], false)),
            Some((Which::Q, Point::new(1.0, 1.0)))
        );
        // One ulp beyond that side: not inside, and no segment asked for.
        let up = f64::from_bits(1f64.to_bits() + 1);
        assert!(matches!(
            run(&[b(5.0, 5.0, 0), b(1.0, up, 1)], false),
            Cone::Nothing
        ));
        // x in the triangle of B's points, none of which is in the cone's triangle.
        assert_eq!(
            inside(run(&[b(-1.0, 1.9, 0), b(1.0, 1.9, 1), b(0.0, 3.0, 2)], false)),
            Some((Which::P, Point::new(0.0, 2.0)))
        );
        // B's segment y = 1.5 crosses the triangle: two crossing segments.
        match run(&[b(-1.0, 1.5, 0), b(1.0, 1.5, 1)], true) {
            Cone::Chords([s, e], [u, v]) => {
                assert_eq!(s, x);
                assert!(!s.in_b && !e.in_b && u.in_b && v.in_b);
                assert_eq!(
                    segment_contact(Exact, s.point, e.point, u.point, v.point),
                    SegmentContact::Crossing
                );
            }
            _ => panic!("no crossing segments"),
        }
        // x's own set seen as one point (repeated): no cone, and B's point on the segment
        // from x to it is not taken for inside; x itself in B's triangle still is.
        let single = [a(2.0, 0.0, 0), a(2.0, 0.0, 1)];
        let run1 = |others: &[WitnessPoint]| {
            let pts: Vec<WitnessPoint> = single.iter().chain(others).chain([&x]).copied().collect();
            cone_witness(Exact, x, || pts.clone().into_iter(), of, false)
        };
        assert!(matches!(run1(&[b(1.0, 1.0, 0), b(5.0, 5.0, 1)]), Cone::Nothing));
        assert_eq!(
            inside(run1(&[b(-1.0, 1.9, 0), b(1.0, 1.9, 1), b(0.0, 3.0, 2)])),
            Some((Which::P, Point::new(0.0, 2.0)))
        );
    }

    /// An end of an edge crossing a chord in the triangle of the chord and the farthest
    /// point on its side: strictly inside, exactly on a side, and none when the only
    /// point on that side makes a triangle that misses it by one ulp.
    #[test]
    fn end_in_triangle_is_exact() {
        let pt = Point::new;
        let (s, t) = (pt(0.0, 0.0), pt(4.0, 0.0));
        let edge = (pt(2.0, -0.5), pt(2.5, 0.5));
        assert_eq!(
            end_in_triangle(Exact, edge, (s, t), &[pt(1.0, 1.0), pt(2.0, 3.0), pt(9.0, -9.0)]),
            Some(pt(2.0, -0.5))
        );
        // Only a point above the chord: the end above it.
        let w = pt(2.5, 3.0);
        assert_eq!(end_in_triangle(Exact, edge, (s, t), &[w]), Some(pt(2.5, 0.5)));
        // On the side s–w of the triangle s, t, w with w = (5, 1): (2.5, 0.5) is on it.
        assert_eq!(
            end_in_triangle(Exact, edge, (s, t), &[pt(5.0, 1.0)]),
            Some(pt(2.5, 0.5))
        );
        // One ulp above that side: outside.
        let above = pt(2.5, f64::from_bits(0.5f64.to_bits() + 1));
        assert_eq!(
            end_in_triangle(Exact, (edge.0, above), (s, t), &[pt(5.0, 1.0)]),
            None
        );
        assert_eq!(end_in_triangle(Exact, edge, (s, t), &[]), None);
        // 32 points: every other one is tried first. Near the chord's line (heights
        // 2^-40 above it), none of those makes a triangle holding the end (2.5, 0.5),
        // but the one between them (index 1) does: found by the pass over all.
        let low = 2f64.powi(-40);
        let mut many: Vec<Point> = (0..32).map(|i| pt(f64::from(i) * 0.1, low)).collect();
        many[1] = pt(2.5, 3.0);
        assert_eq!(end_in_triangle(Exact, edge, (s, t), &many), Some(pt(2.5, 0.5)));
        // The same point at index 2 is among the first tried; one ulp outside the
        // triangle s, t, (5, 1) the end is outside with every point tried.
        many.swap(1, 2);
        assert_eq!(end_in_triangle(Exact, edge, (s, t), &many), Some(pt(2.5, 0.5)));
        many[2] = pt(5.0, 1.0);
        assert_eq!(end_in_triangle(Exact, edge, (s, t), &many), Some(pt(2.5, 0.5)));
        assert_eq!(end_in_triangle(Exact, (edge.0, above), (s, t), &many), None);
    }
}
