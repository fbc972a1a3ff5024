//! The LP calls of a query: the LP on two gathered sets, and the chain walk that answers
//! first where it can, each reported to the probe as one LP call.
//!
//! Expected O(|a| + |b|) per call (Seidel's LP; the walk is linear in the chains); the
//! predicates are the kernel's, narrowed to the two sets' boxes.

use crate::intersect::Probe;
use crate::kernel::{Kernel, Point};
use crate::lp::{ArenaPoints, LpError, LpWorkspace, Separation, separate_chains, separating_line};
use crate::polygon::box_of;
use rand::Rng;

/// [`separating_line`] on the gathered points of two sets (the points at their arena
/// positions, index for index), reporting the call to `probe` (constraints and work).
pub(super) fn counted_lp<K: Kernel, R: Rng + ?Sized, P: Probe>(
    k: K,
    (a, a_points): (&ArenaPoints<'_>, &[Point]),
    (b, b_points): (&ArenaPoints<'_>, &[Point]),
    rng: &mut R,
    lp: &mut LpWorkspace,
    probe: &mut P,
) -> Result<Separation, LpError> {
    counted_lp_after(k, (a, a_points), (b, b_points), 0, rng, lp, probe)
}

/// [`counted_lp`], reporting `spent` more work (done on the same decision before).
pub(super) fn counted_lp_after<K: Kernel, R: Rng + ?Sized, P: Probe>(
    k: K,
    (a, a_points): (&ArenaPoints<'_>, &[Point]),
    (b, b_points): (&ArenaPoints<'_>, &[Point]),
    spent: u64,
    rng: &mut R,
    lp: &mut LpWorkspace,
    probe: &mut P,
) -> Result<Separation, LpError> {
    debug_assert!(a_points.len() == a.positions.len() && b_points.len() == b.positions.len());
    let before = lp.work - spent;
    // The LP asks its predicates of these points only: the exact kernel's semi-static
    // filter, with one bound from their boxes, certifies them with two comparisons
    // (one pass over the points, which the LP reads anyway).
    let k = k.within([box_of(a_points), box_of(b_points)]);
    let result = separating_line(k, a_points, b_points, rng, lp);
    probe.lp_call(a, b, lp.work - before, &result);
    result
}

/// The separation of two sets whose points come in boundary order (samples put in
/// order by [`boundary_order`], chains in walk order) by [`separate_chains`] from the
/// indices `start`, reported to `probe` as an LP call on the two sets; the LP (which
/// then shuffles the points itself) when the walk gives no answer, and for a certified
/// query whose intersecting sets have fewer than three points (the LP records the
/// witness; larger sets are convex polygons, which `certify` searches instead). `spent`
/// is work done on the same decision before, reported with it.
#[allow(clippy::too_many_arguments)]
pub(super) fn walk_or_lp<K: Kernel, R: Rng + ?Sized, P: Probe, const CERT: bool>(
    k: K,
    (a, a_points): (&ArenaPoints<'_>, &[Point]),
    (b, b_points): (&ArenaPoints<'_>, &[Point]),
    start: [usize; 2],
    spent: u64,
    rng: &mut R,
    lp: &mut LpWorkspace,
    probe: &mut P,
) -> Result<Separation, LpError> {
    let before = lp.work - spent;
    match separate_chains(k, a_points, b_points, start, &mut lp.work) {
        // A certified query reruns the LP for its witness only where the sets are too
        // small to be convex polygons; otherwise the certificate is searched on the two
        // convex polygons the sets are (`certify`), and no LP witness is left to read.
        Some(Separation::Intersecting) if CERT && a_points.len() >= 3 && b_points.len() >= 3 => {
            lp.forget_witness();
            let result = Separation::Intersecting;
            probe.lp_call(a, b, lp.work - before, &Ok(result));
            return Ok(result);
        }
        Some(Separation::Intersecting) if CERT => {}
        Some(result) => {
            probe.lp_call(a, b, lp.work - before, &Ok(result));
            return Ok(result);
        }
        None => {}
    }
    counted_lp_after(k, (a, a_points), (b, b_points), lp.work - before, rng, lp, probe)
}
