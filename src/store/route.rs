//! How one planned query is answered: the routes the planner chooses between, and the
//! tests behind them. This file knows polygons and intersection algorithms, never the
//! scene; both the cost model (which times these tests) and the scene use it.

use crate::intersect::LinkedEngine;
use crate::intersect::{
    ArrayIntersection, Barba, Certificate, Clm, ClmWorkspace, Linear, LinearLinked, LinkedIntersection,
    Which, barba_certified_vertices, barba_vertices,
};
use crate::kernel::{BoundingBox, Kernel, Point};
use crate::polygon::{ConvexPolygon, LinkedPolygon, PosedVertices};
use rand::SeedableRng;
use rand::rngs::SmallRng;

/// Per-query scratch memory, reused so that queries allocate nothing in the steady state.
#[derive(Clone, Debug, Default)]
pub(crate) struct QueryWorkspace {
    clm: ClmWorkspace,
}

/// The sampled (sublinear) test on two linked polygons: Chazelle–Liu–Magen.
pub(crate) fn sampled_test<K: Kernel>(
    kernel: K,
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    ws: &mut QueryWorkspace,
    rng: &mut SmallRng,
) -> bool {
    Clm.intersects_with_workspace(kernel, p, q, rng, &mut ws.clm)
}

/// The linear test walking both linked polygons (no conversion, no allocation).
pub(crate) fn linear_test<K: Kernel>(kernel: K, p: &LinkedPolygon, q: &LinkedPolygon) -> bool {
    LinearLinked.intersects_in(kernel, p, q, &mut unused_rng(), &mut (), &mut ())
}

/// The linear walk draws no random numbers; the trait wants a generator, and a
/// constant-seeded one costs nothing next to the OS-seeded one of a one-off call.
fn unused_rng() -> SmallRng {
    SmallRng::seed_from_u64(0)
}

/// Barba–Langerman on two snapshots, O(log n).
pub(crate) fn barba_test<K: Kernel>(kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
    Barba.intersects_with(kernel, p, q)
}

/// The linear test on two snapshots: cheaper than Barba–Langerman on small polygons.
pub(crate) fn linear_array_test<K: Kernel>(kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
    Linear.intersects_with(kernel, p, q)
}

/// What the array test reads of one polygon: its snapshot, or a posed polygon's world
/// vertices computed on demand from its shape's array and its pose (no O(n) snapshot
/// per pose), with the world polygon's bounding box.
#[derive(Clone, Copy, Debug)]
pub(crate) enum ArrayRef<'a> {
    Stored(&'a ConvexPolygon),
    Posed(PosedVertices<'a>, BoundingBox),
}

impl ArrayRef<'_> {
    /// The number of vertices.
    pub(crate) fn len(self) -> usize {
        match self {
            ArrayRef::Stored(p) => p.len(),
            ArrayRef::Posed(v, _) => crate::polygon::Vertices::len(&v),
        }
    }

    /// The polygon as an array, O(n): a copy of the snapshot, or a posed view's world
    /// vertices collected (for the linear walk of a pair with a view, itself O(n)).
    fn to_convex(self) -> ConvexPolygon {
        match self {
            ArrayRef::Stored(p) => p.clone(),
            ArrayRef::Posed(v, _) => ConvexPolygon::from_ccw_unchecked(v.to_points()),
        }
    }
}

/// Barba–Langerman through the vertex access of each side (at least one posed view).
#[inline(never)]
fn barba_mixed<K: Kernel>(kernel: K, p: ArrayRef<'_>, q: ArrayRef<'_>) -> bool {
    use ArrayRef::{Posed, Stored};
    match (p, q) {
        (Stored(p), Stored(q)) => barba_test(kernel, p, q),
        (Posed(p, pb), Posed(q, qb)) => barba_vertices(kernel, (&p, pb), (&q, qb)),
        (Posed(p, pb), Stored(q)) => barba_vertices(kernel, (&p, pb), (q.vertices(), q.bounding_box())),
        (Stored(p), Posed(q, qb)) => barba_vertices(kernel, (p.vertices(), p.bounding_box()), (&q, qb)),
    }
}

/// [`barba_mixed`]'s certified call: the certificate names world vertices.
#[inline(never)]
fn barba_mixed_certified<K: Kernel>(kernel: K, p: ArrayRef<'_>, q: ArrayRef<'_>) -> Certificate {
    use ArrayRef::{Posed, Stored};
    match (p, q) {
        (Stored(p), Stored(q)) => Barba.certified_with(kernel, p, q),
        (Posed(p, pb), Posed(q, qb)) => barba_certified_vertices(kernel, (&p, pb), (&q, qb)),
        (Posed(p, pb), Stored(q)) => {
            barba_certified_vertices(kernel, (&p, pb), (q.vertices(), q.bounding_box()))
        }
        (Stored(p), Posed(q, qb)) => {
            barba_certified_vertices(kernel, (p.vertices(), p.bounding_box()), (&q, qb))
        }
    }
}

/// The array test on two snapshots: linear when `linear` (small polygons), else
/// Barba–Langerman.
pub(crate) fn array_test<K: Kernel>(kernel: K, p: ArrayRef<'_>, q: ArrayRef<'_>, linear: bool) -> bool {
    match (p, q) {
        (ArrayRef::Stored(p), ArrayRef::Stored(q)) if linear => linear_array_test(kernel, p, q),
        (ArrayRef::Stored(p), ArrayRef::Stored(q)) => barba_test(kernel, p, q),
        // The linear walk reads every vertex anyway: on the world arrays.
        _ if linear => linear_array_test(kernel, &p.to_convex(), &q.to_convex()),
        _ => barba_mixed(kernel, p, q),
    }
}

/// [`sampled_test`]'s certified call.
pub(crate) fn sampled_certified<K: Kernel>(
    kernel: K,
    p: &LinkedPolygon,
    q: &LinkedPolygon,
    ws: &mut QueryWorkspace,
    rng: &mut SmallRng,
) -> Certificate {
    Clm.certified_with_workspace(kernel, p, q, rng, &mut ws.clm)
}

/// [`linear_test`]'s certified call.
pub(crate) fn linear_certified<K: Kernel>(kernel: K, p: &LinkedPolygon, q: &LinkedPolygon) -> Certificate {
    LinearLinked.certified_in(kernel, p, q, &mut unused_rng(), &mut (), &mut ())
}

/// [`array_test`]'s certified call.
pub(crate) fn array_certified<K: Kernel>(
    kernel: K,
    p: ArrayRef<'_>,
    q: ArrayRef<'_>,
    linear: bool,
) -> Certificate {
    match (p, q) {
        (ArrayRef::Stored(p), ArrayRef::Stored(q)) if linear => Linear.certified_with(kernel, p, q),
        (ArrayRef::Stored(p), ArrayRef::Stored(q)) => Barba.certified_with(kernel, p, q),
        _ if linear => Linear.certified_with(kernel, &p.to_convex(), &q.to_convex()),
        _ => barba_mixed_certified(kernel, p, q),
    }
}

/// How one planned query will be answered; keys are the scene's slots.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Route {
    /// Decided without a test (bounding boxes, or a polygon against itself).
    Known(bool),
    /// Both snapshots are valid: an array test (linear when `true`).
    Arrays(usize, usize, bool),
    /// The linear test walking the linked polygons.
    Linear(usize, usize),
    /// The sampled test on the linked polygons.
    Sampled(usize, usize),
    /// Both polygons converted for this query only, then an array test (linear when
    /// `true`).
    Throwaway(usize, usize, bool),
    /// Separated, proved while planning by a warm start (`warm.rs`): the edge `from` →
    /// `to` of polygon `of` (P is the query's first polygon) has the other strictly
    /// outside.
    Warm { of: Which, from: Point, to: Point },
}
