//! Checking a certificate exactly in O(n + m), from the polygons and the certificate
//! alone: no algorithm's code runs here.

use crate::kernel::{Exact, Kernel, Orientation, Point, SegmentContact, segment_contact};
use crate::polygon::{Boundary, ConvexPolygon, LinkedPolygon};

use crate::intersect::{Certificate, CertificateError, Which};
use Orientation::Cw;

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

pub(super) fn verify_on<A: Boundary + ?Sized, B: Boundary + ?Sized>(
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
pub(super) fn find_vertex<A: Boundary + ?Sized>(
    poly: &A,
    of: Which,
    point: Point,
) -> Result<usize, CertificateError> {
    (0..poly.count())
        .find(|&v| poly.at(v) == point)
        .ok_or(CertificateError::NotAVertex { of, point })
}

/// Checks that `from` → `to` is a counter-clockwise edge of `poly`.
pub(super) fn find_edge<A: Boundary + ?Sized>(
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

pub(super) fn check_separated<A: Boundary + ?Sized, B: Boundary + ?Sized>(
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

pub(super) fn check_inside<A: Boundary + ?Sized, B: Boundary + ?Sized>(
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
