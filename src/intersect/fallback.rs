//! Completing answers that an algorithm could not certify from its own findings
//! ([`Derivation::Answer`]): the searches every certified call falls back on.
//!
//! * "disjoint": [`Dobkin`](super::Dobkin)'s separation, O(log n + log m), which always
//!   yields a separating edge under [`Exact`] (docs/certificates.md);
//! * "intersecting": [`Barba`](super::Barba)'s witness, O(log n + log m), which always
//!   yields one under [`Exact`];
//! * the last resort, [`exact_certificate`], O(n + m) with the exact kernel, for when an
//!   inconsistent kernel ([`Fast`](crate::Fast) near degeneracies) leaves the searches
//!   above without a certificate (their answer then contradicts the algorithm's).
//!
//! Each step is reported to the [`Probe`]. Linked polygons are walked into arrays first
//! (O(n + m)); [`Clm`](super::Clm) needs that only under an inconsistent kernel.
//!
//! [`verified_or_exact`] and [`verified_or_exact_linked`] are for callers that must never hand out a
//! certificate that fails [`verify`](super::verify) (the CLI under `--precision fast`):
//! they check it exactly and replace a failing one with [`exact_certificate`]'s.

use super::certificate::{Certificate, Derivation, Which};
use super::engine::{Completer, Completion};
use super::{Fallback, Probe, barba, dobkin, linear};
use crate::kernel::{Exact, Kernel, Orientation, Point, segment_contact};
use crate::polygon::{ConvexPolygon, LinkedPolygon};

/// The searches of the module docs, for the engines' certified calls and Barba's
/// in-place certified run.
impl Completion for Completer {
    /// The certificate of a derivation: its own, or one completed by the searches in
    /// the module docs.
    fn complete<K: Kernel, P: Probe>(
        k: K,
        pv: &[Point],
        qv: &[Point],
        derivation: Derivation,
        probe: &mut P,
    ) -> Certificate {
        let answer = match derivation {
            Derivation::Certified(c) => return c,
            Derivation::Answer(answer) => answer,
        };
        probe.fallback(Fallback::Search);
        let found = if answer {
            barba::meeting_certificate(k, pv, qv)
        } else {
            dobkin::separating_certificate(k, pv, qv)
        };
        found.unwrap_or_else(|| {
            probe.fallback(Fallback::Reference);
            exact_certificate_on(pv, qv)
        })
    }

    /// A certificate passes through unchanged, an answer alone is completed on the
    /// walked arrays.
    #[inline]
    fn complete_linked<K: Kernel, P: Probe>(
        k: K,
        p: &LinkedPolygon,
        q: &LinkedPolygon,
        derivation: Derivation,
        probe: &mut P,
    ) -> Certificate {
        match derivation {
            Derivation::Certified(c) => c,
            answer => Self::complete(
                k,
                p.to_convex().vertices(),
                q.to_convex().vertices(),
                answer,
                probe,
            ),
        }
    }
}

/// A certificate computed with the exact kernel by the O(n + m) reference: the
/// separating edge [`Linear`](super::Linear) finds, or for intersecting polygons
/// [`Barba`](super::Barba)'s witness. Slow beside the O(log n) algorithms' certified
/// calls, but independent of them and of any kernel's mistakes.
///
/// ```
/// use polysect::ConvexPolygon;
/// use polysect::intersect::{exact_certificate, verify};
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let q = ConvexPolygon::new([[1.0, 1.0], [3.0, 1.0], [3.0, 3.0]])?;
/// let c = exact_certificate(&p, &q);
/// assert!(c.intersects());
/// assert_eq!(verify(&p, &q, &c), Ok(()));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
pub fn exact_certificate(p: &ConvexPolygon, q: &ConvexPolygon) -> Certificate {
    exact_certificate_on(p.vertices(), q.vertices())
}

/// `certificate` if [`verify`](super::verify) accepts it, else [`exact_certificate`]'s
/// (whose answer then corrects the one `certificate` claimed): O(n + m). Under the exact
/// kernel every certified call's certificate verifies, so this is for certificates of
/// the fast kernel, which may not near degeneracies.
///
/// ```
/// use polysect::{ConvexPolygon, Point};
/// use polysect::intersect::{Certificate, Which, verified_or_exact, verify};
/// let p = ConvexPolygon::new([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])?;
/// let q = ConvexPolygon::new([[1.0, 0.5], [2.0, 0.0], [2.0, 1.0]])?;
/// // A wrong claim (q's vertex (1, 0.5) lies on p's edge x = 1) is replaced.
/// let wrong = Certificate::Separated { of: Which::P, from: Point::new(1.0, 0.0), to: Point::new(1.0, 1.0) };
/// let c = verified_or_exact(&p, &q, wrong);
/// assert!(c.intersects());
/// assert_eq!(verify(&p, &q, &c), Ok(()));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
pub fn verified_or_exact(p: &ConvexPolygon, q: &ConvexPolygon, certificate: Certificate) -> Certificate {
    match super::verify(p, q, &certificate) {
        Ok(()) => certificate,
        Err(_) => exact_certificate(p, q),
    }
}

/// [`verified_or_exact`] on linked polygons: verified in place; a failing certificate is replaced
/// by [`exact_certificate`]'s on the walked arrays. O(n + m).
pub fn verified_or_exact_linked(
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    certificate: Certificate,
) -> Certificate {
    match super::verify_linked(p, q, &certificate) {
        Ok(()) => certificate,
        Err(_) => exact_certificate(&p.to_convex(), &q.to_convex()),
    }
}

fn exact_certificate_on(pv: &[Point], qv: &[Point]) -> Certificate {
    if let Some(c) = linear::separating_certificate(Exact, Exact, pv, qv, &mut ()) {
        return c;
    }
    barba::meeting_certificate(Exact, pv, qv).unwrap_or_else(|| brute_force_witness(pv, qv))
}

/// Every vertex against the other polygon, then every pair of edges: O(n·m). Reached
/// only if the exact witness derivation of an intersecting pair failed, which its
/// proof rules out (tests/geometry/certificates.rs checks that no certified call under the exact
/// kernel reaches even [`exact_certificate`]).
fn brute_force_witness(pv: &[Point], qv: &[Point]) -> Certificate {
    let k = Exact;
    let next = |v: &[Point], i: usize| v[(i + 1) % v.len()];
    let inside = |poly: &[Point], x: Point| {
        (0..poly.len()).all(|i| k.orient(poly[i], next(poly, i), x) != Orientation::Cw)
    };
    if let Some(&x) = pv.iter().find(|&&x| inside(qv, x)) {
        return Certificate::VertexInside {
            of: Which::P,
            point: x,
        };
    }
    if let Some(&x) = qv.iter().find(|&&x| inside(pv, x)) {
        return Certificate::VertexInside {
            of: Which::Q,
            point: x,
        };
    }
    for e in 0..pv.len() {
        for f in 0..qv.len() {
            if segment_contact(k, pv[e], next(pv, e), qv[f], next(qv, f)).meets() {
                return Certificate::CrossingEdges {
                    p: [pv[e], next(pv, e)],
                    q: [qv[f], next(qv, f)],
                };
            }
        }
    }
    // No contact at all: the pair is disjoint after all, and the reference's edge exists.
    linear::separating_certificate(k, k, pv, qv, &mut ()).unwrap_or(Certificate::VertexInside {
        of: Which::P,
        point: pv[0],
    })
}
