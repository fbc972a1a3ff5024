//! Uniform sampling of a [`LinkedPolygon`]'s vertices: one random position per vertex
//! (the arena is dense), distinct samples by rejection against an epoch-stamped
//! [`SampleWorkspace`].

use super::{LinkedPolygon, VertexId};
use rand::Rng;

/// Scratch memory for the sampling of [`LinkedPolygon`]s, reused across queries so a
/// query allocates nothing in the steady state. Holds one `u32` stamp per vertex of the
/// largest polygon sampled so far; `SampleWorkspace::default()` is an empty one.
#[derive(Clone, Debug, Default)]
pub struct SampleWorkspace {
    stamps: Vec<u32>,
    epoch: u32,
}

impl SampleWorkspace {
    /// Starts a new round of marks over `n` positions; O(1) amortised.
    fn begin(&mut self, n: usize) {
        if self.stamps.len() < n {
            self.stamps.resize(n, 0);
        }
        self.epoch = self.epoch.wrapping_add(1);
        if self.epoch == 0 {
            self.stamps.iter_mut().for_each(|s| *s = 0);
            self.epoch = 1;
        }
    }

    /// Marks position `i`; true if it was not marked in this round.
    #[inline]
    fn mark(&mut self, i: usize) -> bool {
        let fresh = self.stamps[i] != self.epoch;
        self.stamps[i] = self.epoch;
        fresh
    }
}

impl LinkedPolygon {
    /// A uniformly random vertex. O(1).
    pub fn random_vertex<R: Rng + ?Sized>(&self, rng: &mut R) -> VertexId {
        self.id_at(rng.random_range(0..self.len()))
    }

    /// `k` distinct uniformly random vertices (all of them when `k >= len`), as handles.
    /// Allocates; the crate's queries sample positions into a reused workspace.
    pub fn sample<R: Rng + ?Sized>(&self, k: usize, rng: &mut R) -> Vec<VertexId> {
        let mut out = Vec::with_capacity(k.min(self.len()));
        self.sample_positions(k, rng, &mut SampleWorkspace::default(), &mut out);
        out.into_iter().map(|p| self.id_at(p as usize)).collect()
    }

    instrument_pub! {
        /// Appends to `out` the positions of `min(k, len)` distinct vertices, a uniformly
        /// random subset. Expected O(k): for k ≤ len/2, rejection sampling with marks in
        /// `workspace` (expected fewer than 2k draws); otherwise the len − k excluded
        /// positions are drawn the same way and the rest are listed, O(len) ≤ O(2k).
        /// The order of the returned positions is not uniform; the set is.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn sample_positions<R: Rng + ?Sized>(
            &self,
            k: usize,
            rng: &mut R,
            workspace: &mut SampleWorkspace,
            out: &mut Vec<u32>,
        ) {
            let n = self.len();
            if k >= n {
                out.extend(0..n as u32);
                return;
            }
            workspace.begin(n);
            if 2 * k <= n {
                let mut taken = 0;
                while taken < k {
                    let i = rng.random_range(0..n);
                    if workspace.mark(i) {
                        out.push(i as u32);
                        taken += 1;
                    }
                }
            } else {
                let mut excluded = 0;
                while excluded < n - k {
                    if workspace.mark(rng.random_range(0..n)) {
                        excluded += 1;
                    }
                }
                let epoch = workspace.epoch;
                out.extend((0..n as u32).filter(|&i| workspace.stamps[i as usize] != epoch));
            }
        }
    }
}
