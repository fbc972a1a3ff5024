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

mod chords;
mod separation;
mod verify;

#[cfg(test)]
mod tests;

pub(crate) use crate::polygon::Boundary;
pub(crate) use chords::{
    Reduced, crossing, edge_between, endpoint_on_other, reduce_chord, resolve_chords, resolve_crossing_chords,
};
pub(crate) use separation::{
    extreme_left, from_faces, from_support, same_direction, separates, supports_left, supports_right, turn_gt,
};
pub use verify::{verify, verify_linked};

use crate::kernel::{Orientation, Point};
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

    /// `"p"` or `"q"`, as in the CLI's JSON (and [`Display`](fmt::Display)).
    #[cfg_attr(not(feature = "protocol"), allow(dead_code))]
    pub(crate) fn name(self) -> &'static str {
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
    pub(crate) fn swapped(self) -> Certificate {
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
