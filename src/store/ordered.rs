//! All intersecting pairs streamed in a caller's order, with memory bounded by the
//! scene rather than by the number of pairs.
//!
//! [`Scene::intersecting_pairs`] returns every pair at once: memory grows with the
//! answer, quadratic in N when every box overlaps every other. Here the caller ranks
//! the polygons (the `scene` protocol ranks them by name) and receives, for each
//! polygon `a` in rank order, the polygons after it in rank order that intersect it,
//! sorted by rank: together the pairs sorted by (rank a, rank b). Each step is the
//! one-polygon query ([`Scene::intersecting`]'s broad phase: a binary search and a scan
//! of the boxes in `a`'s vertical slab) restricted to later ranks, so each pair is
//! tested once.
//!
//! # Complexity
//! Memory: O(N) for the ranks plus O(candidates of one polygon) at a time, whatever the
//! number of pairs. Time: O(N log N + Σ_a (slab(a) + candidates(a) · test)), where
//! slab(a) is the number of boxes whose x-extent starts before `a`'s ends and reaches
//! past its start; the banded sweep of [`Scene::intersecting_pairs`] scans fewer boxes
//! in tall scenes, so this is for answers too large to hold, not for frames.
//!
//! # Degeneracies and precision
//! As [`Scene::intersecting_pairs`]: touching polygons intersect, boxes are compared
//! exactly, the scene's kernel decides each pair; a pair whose test fails (a stale
//! polygon cannot occur here) counts as not intersecting, as there.

use super::{PolygonId, Scene};
use crate::kernel::Kernel;

impl<K: Kernel> Scene<K> {
    /// For each polygon `a` of `order` in turn, calls `sink(a, later)` with the polygons
    /// after `a` in `order` that intersect it, in `order`'s order; polygons of the scene
    /// missing from `order`, and stale or foreign ids in it, are skipped. Stops at the
    /// first error `sink` returns. See the module docs for memory and time.
    ///
    /// # Errors
    /// The first error `sink` returns.
    pub fn intersecting_pairs_ordered<E>(
        &mut self,
        order: &[PolygonId],
        mut sink: impl FnMut(PolygonId, &[PolygonId]) -> Result<(), E>,
    ) -> Result<(), E> {
        self.flush_broad_phase();
        // rank[key] = position in `order` + 1; 0 for keys not in it.
        let mut rank: Vec<u32> = Vec::new();
        for (i, &id) in order.iter().enumerate() {
            if let Ok(k) = self.key(id) {
                if rank.len() <= k {
                    rank.resize(k + 1, 0);
                }
                rank[k] = u32::try_from(i + 1).unwrap_or(u32::MAX);
            }
        }
        let rank_of = |k: usize| rank.get(k).copied().unwrap_or(0);
        let mut candidates: Vec<usize> = Vec::new();
        let mut hits: Vec<PolygonId> = Vec::new();
        for &a in order {
            let Ok(ka) = self.key(a) else { continue };
            let ra = rank_of(ka);
            if ra == 0 {
                continue;
            }
            candidates.clear();
            candidates.extend(
                self.broad
                    .overlapping(&self.entries[ka].bbox)
                    .filter(|&k| rank_of(k) > ra),
            );
            candidates.sort_unstable_by_key(|&k| rank_of(k));
            let plan = self.plan(candidates.iter().map(|&k| Ok((ka, k))));
            let answers = self.run_plan(plan);
            hits.clear();
            hits.extend(
                candidates
                    .iter()
                    .zip(answers)
                    .filter(|(_, hit)| matches!(hit, Ok(true)))
                    .map(|(&k, _)| self.id_of(k)),
            );
            sink(a, &hits)?;
        }
        Ok(())
    }
}
