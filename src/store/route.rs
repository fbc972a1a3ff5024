//! How one planned query is answered: the routes the planner chooses between, and the
//! tests behind them. This file knows polygons and intersection algorithms, never the
//! scene; both the cost model (which times these tests) and the scene use it.

use crate::intersect::{Algorithm, Clm, ClmWorkspace, LinkedIntersection};
use crate::kernel::Kernel;
use crate::polygon::{ConvexPolygon, LinkedPolygon};
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

/// The fastest array algorithm with the scene's kernel.
pub(crate) fn array_test<K: Kernel>(kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
    Algorithm::fastest_array().intersects_with(kernel, p, q)
}

/// How one planned query will be answered; keys are the scene's slots.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Route {
    /// Decided without a test (bounding boxes, or a polygon against itself).
    Known(bool),
    /// Both snapshots are valid: an array test.
    Arrays(usize, usize),
    /// The sampled test on the linked polygons.
    Sampled(usize, usize),
    /// Both polygons converted for this query only.
    Throwaway(usize, usize),
}
