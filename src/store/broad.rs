//! Bounding boxes and the sort-and-sweep broad phase.
//!
//! # Sort and sweep
//! The boxes are kept sorted by their left side. All overlapping pairs: a sweep in
//! about √N/2 horizontal bands, each box against the following boxes of its bands that
//! start before it ends, their vertical extents compared; O(N + B + X) for N boxes
//! listed B times in all and X pairs overlapping along x within a band (in a scene whose
//! boxes are small against the world, both are small multiples of N; boxes all in one
//! band degrade to the plain sweep, O(N + pairs overlapping along x)). The boxes overlapping one box: a binary search on the running maximum of
//! the right sides finds the first box that can reach it, then a scan up to its right
//! side, O(log N + the boxes in that slab).
//!
//! # Updates
//! Edits only mark keys dirty (a per-key flag: one entry per key at most, whatever the
//! number of edits). The next query re-reads the dirty boxes; if few changed, the
//! sorted order is repaired by insertion sort (boxes that moved a little move a few
//! places), with a budget of shifts beyond which, as when most boxes moved far, the
//! order is sorted again from scratch, O(N log N). While nothing changes the last
//! sweep's pairs are reused. We measured this against an R-tree (`rstar`, re-inserting
//! few changed boxes, bulk-loading when more than half changed): on 2,000 moving boxes
//! the R-tree's bulk load and self-join took most of a frame (docs/store.md).
//!
//! Every comparison is between input coordinates (exact); touching boxes overlap.

use crate::kernel::BoundingBox;

/// One box in sweep order.
#[derive(Clone, Copy, Debug)]
struct Slab {
    min_x: f64,
    max_x: f64,
    min_y: f64,
    max_y: f64,
    key: u32,
}

/// The sort-and-sweep broad phase over polygon boxes, keyed by the scene's slot key;
/// see the module docs. Memory is O(largest key + pairs of the last sweep).
#[derive(Clone, Debug, Default)]
pub(crate) struct BroadPhase {
    /// The box each key is indexed under (`None`: no polygon), and whether the key is
    /// listed in `dirty`.
    indexed: Vec<(Option<BoundingBox>, bool)>,
    dirty: Vec<usize>,
    /// The indexed boxes sorted by left side.
    sorted: Vec<Slab>,
    /// `reach[i]`: the largest right side among `sorted[..=i]`.
    reach: Vec<f64>,
    /// The overlapping pairs of the last sweep, valid while nothing changed.
    pairs: Vec<(usize, usize)>,
    pairs_valid: bool,
    /// Scratch of the sweep: per horizontal band, indices into `sorted`.
    bands: Vec<Vec<u32>>,
}

impl BroadPhase {
    /// Records that `key`'s box changed (or the key was added or removed). O(1).
    pub fn mark(&mut self, key: usize) {
        if self.indexed.len() <= key {
            self.indexed.resize(key + 1, (None, false));
        }
        if !self.indexed[key].1 {
            self.indexed[key].1 = true;
            self.dirty.push(key);
        }
    }

    /// Heap bytes held.
    pub fn heap_bytes(&self) -> usize {
        self.indexed.capacity() * std::mem::size_of::<(Option<BoundingBox>, bool)>()
            + self.dirty.capacity() * std::mem::size_of::<usize>()
            + self.sorted.capacity() * std::mem::size_of::<Slab>()
            + self.reach.capacity() * std::mem::size_of::<f64>()
            + self.pairs.capacity() * std::mem::size_of::<(usize, usize)>()
            + self.bands.iter().map(|b| b.capacity() * 4).sum::<usize>()
    }

    /// Brings the sorted boxes up to date with `current(key)` for every dirty key.
    pub fn flush(&mut self, current: impl Fn(usize) -> Option<BoundingBox>) {
        if self.dirty.is_empty() {
            return;
        }
        let mut changed = false;
        for key in self.dirty.drain(..) {
            let now = current(key);
            let slot = &mut self.indexed[key];
            slot.1 = false;
            if slot.0 != now {
                slot.0 = now;
                changed = true;
            }
        }
        if !changed {
            return;
        }
        self.pairs_valid = false;
        // Re-read every box in the current order (dropping removed keys, adding new
        // ones at the end), then repair the order.
        let indexed = &self.indexed;
        let mut listed = 0;
        self.sorted.retain_mut(|s| match indexed[s.key as usize].0 {
            Some(b) => {
                *s = Slab::of(b, s.key);
                listed += 1;
                true
            }
            None => false,
        });
        let total = indexed.iter().filter(|(b, _)| b.is_some()).count();
        if listed < total {
            let mut present = vec![false; indexed.len()];
            for s in &self.sorted {
                present[s.key as usize] = true;
            }
            for (k, (b, _)) in indexed.iter().enumerate() {
                if let (Some(b), false) = (b, present[k]) {
                    self.sorted.push(Slab::of(*b, k as u32));
                }
            }
        }
        let budget = 8 * self.sorted.len() + 64;
        if !insertion_sort(&mut self.sorted, budget) {
            self.sorted
                .sort_unstable_by(|a, b| a.min_x.total_cmp(&b.min_x).then(a.key.cmp(&b.key)));
        }
        self.reach.clear();
        let mut m = f64::NEG_INFINITY;
        self.reach.extend(self.sorted.iter().map(|s| {
            m = m.max(s.max_x);
            m
        }));
    }

    /// Keys whose boxes overlap `b` (closed), in no particular order. The broad phase
    /// must be flushed.
    pub fn overlapping(&self, b: &BoundingBox) -> impl Iterator<Item = usize> + '_ {
        let first = self.reach.partition_point(|&r| r < b.min.x);
        let (bx, by0, by1) = (b.max.x, b.min.y, b.max.y);
        let bx0 = b.min.x;
        self.sorted[first..]
            .iter()
            .take_while(move |s| s.min_x <= bx)
            .filter(move |s| s.max_x >= bx0 && s.min_y <= by1 && by0 <= s.max_y)
            .map(|s| s.key as usize)
    }

    /// All pairs of keys (a < b) whose boxes overlap, sorted. The broad phase must be
    /// flushed. Reuses the last sweep while nothing changed.
    pub fn overlapping_pairs(&mut self) -> Vec<(usize, usize)> {
        if !self.pairs_valid {
            self.sweep();
            self.pairs_valid = true;
        }
        self.pairs.clone()
    }

    /// The sweep, in horizontal bands: about √N / 2 bands of equal height over the boxes'
    /// vertical extent; each box is listed (in left-side order) in every band it meets,
    /// each band swept on its own, and a pair reported only in the band holding the
    /// lower end of the two boxes' common vertical interval, so exactly once. A box
    /// then meets only the boxes of its own bands along x, not all those of its vertical
    /// slab. Band membership uses a monotone floating-point map of y (the same one for
    /// listing and for reporting); every overlap decision is an exact comparison.
    fn sweep(&mut self) {
        self.pairs.clear();
        let n = self.sorted.len();
        if n < 2 {
            return;
        }
        let (lo, hi) = self
            .sorted
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
                (lo.min(s.min_y), hi.max(s.max_y))
            });
        let bands = ((n as f64).sqrt() / 2.0).clamp(1.0, 1024.0) as usize;
        let scale = bands as f64 / (hi - lo);
        let band_of = |y: f64| -> usize {
            let b = (y - lo) * scale;
            if b.is_finite() && b > 0.0 {
                (b as usize).min(bands - 1)
            } else {
                0
            }
        };
        self.bands.resize_with(bands.max(self.bands.len()), Vec::new);
        for band in &mut self.bands {
            band.clear();
        }
        for (i, s) in self.sorted.iter().enumerate() {
            for band in &mut self.bands[band_of(s.min_y)..=band_of(s.max_y)] {
                band.push(i as u32);
            }
        }
        let sorted = &self.sorted;
        for (j, band) in self.bands[..bands].iter().enumerate() {
            for (t, &ia) in band.iter().enumerate() {
                let a = &sorted[ia as usize];
                for &ib in &band[t + 1..] {
                    let b = &sorted[ib as usize];
                    if b.min_x > a.max_x {
                        break;
                    }
                    if a.min_y <= b.max_y && b.min_y <= a.max_y && band_of(a.min_y.max(b.min_y)) == j {
                        let (p, q) = (a.key.min(b.key), a.key.max(b.key));
                        self.pairs.push((p as usize, q as usize));
                    }
                }
            }
        }
        self.pairs.sort_unstable();
    }
}

impl Slab {
    fn of(b: BoundingBox, key: u32) -> Slab {
        Slab {
            min_x: b.min.x,
            max_x: b.max.x,
            min_y: b.min.y,
            max_y: b.max.y,
            key,
        }
    }

    fn before(&self, o: &Slab) -> bool {
        self.min_x.total_cmp(&o.min_x).then(self.key.cmp(&o.key)).is_lt()
    }
}

/// Sorts `v` by left side (then key) by insertion, giving up (false, `v` a permutation
/// of its input) once more than `budget` shifts were needed.
fn insertion_sort(v: &mut [Slab], budget: usize) -> bool {
    let mut shifts = 0;
    for i in 1..v.len() {
        let mut j = i;
        while j > 0 && v[j].before(&v[j - 1]) {
            v.swap(j, j - 1);
            j -= 1;
            shifts += 1;
            if shifts > budget {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    fn random_box(rng: &mut SmallRng, side: f64) -> BoundingBox {
        let (x, y) = (rng.random_range(0.0..side), rng.random_range(0.0..side));
        let (w, h) = (rng.random_range(0.0..3.0), rng.random_range(0.0..3.0));
        // Integer corners now and then, so that boxes touch exactly.
        let r = |v: f64| if rng_bool(x) { v.round() } else { v };
        BoundingBox {
            min: Point::new(r(x), r(y)),
            max: Point::new(r(x + w), r(y + h)),
        }
    }

    fn rng_bool(x: f64) -> bool {
        (x * 7.0).fract() < 0.5
    }

    fn all_pairs(boxes: &[Option<BoundingBox>]) -> Vec<(usize, usize)> {
        let mut want = Vec::new();
        for a in 0..boxes.len() {
            for b in a + 1..boxes.len() {
                if let (Some(p), Some(q)) = (boxes[a], boxes[b])
                    && p.overlaps(&q)
                {
                    want.push((a, b));
                }
            }
        }
        want
    }

    /// Degenerate layouts for the bands: every box on one horizontal line (zero height
    /// in all), a box spanning everything, boxes touching exactly at band-like
    /// coordinates, huge and tiny coordinates.
    #[test]
    fn sweep_on_degenerate_layouts() {
        let b = |x0: f64, y0: f64, x1: f64, y1: f64| {
            Some(BoundingBox {
                min: Point::new(x0, y0),
                max: Point::new(x1, y1),
            })
        };
        let layouts: Vec<Vec<Option<BoundingBox>>> = vec![
            (0..50).map(|i| b(i as f64, 3.0, i as f64 + 1.0, 3.0)).collect(),
            (0..50)
                .map(|i| b(i as f64, i as f64, i as f64 + 1.0, i as f64 + 1.0))
                .chain([b(-1e300, -1e300, 1e300, 1e300)])
                .collect(),
            (0..64)
                .map(|i| {
                    b(
                        (i % 8) as f64,
                        (i / 8) as f64,
                        (i % 8) as f64 + 1.0,
                        (i / 8) as f64 + 1.0,
                    )
                })
                .collect(),
            (0..40)
                .map(|i| b(0.0, i as f64 * 1e-300, 1.0, (i + 1) as f64 * 1e-300))
                .chain([b(0.0, -1.7e308, 1.0, 1.7e308), None, b(5.0, 5.0, 5.0, 5.0)])
                .collect(),
        ];
        for (l, boxes) in layouts.iter().enumerate() {
            let mut broad = BroadPhase::default();
            for k in 0..boxes.len() {
                broad.mark(k);
            }
            broad.flush(|k| boxes[k]);
            assert_eq!(broad.overlapping_pairs(), all_pairs(boxes), "layout {l}");
        }
    }

    /// Pairs and single-box queries against all pairs, under inserts, removals, small
    /// and large moves, and flushes with nothing changed.
    #[test]
    fn sweep_equals_all_pairs_under_updates() {
        let mut rng = SmallRng::seed_from_u64(0xb0a);
        let mut boxes: Vec<Option<BoundingBox>> = vec![None; 300];
        let mut broad = BroadPhase::default();
        for round in 0..60 {
            let moves = if round % 7 == 0 {
                250
            } else {
                rng.random_range(0..12)
            };
            for _ in 0..moves {
                let k = rng.random_range(0..boxes.len());
                boxes[k] = match (boxes[k], rng.random_range(0..4)) {
                    (_, 0) => None,
                    (Some(b), 1) => {
                        let d = rng.random_range(-0.5..0.5);
                        Some(BoundingBox {
                            min: Point::new(b.min.x + d, b.min.y),
                            max: Point::new(b.max.x + d, b.max.y),
                        })
                    }
                    _ => Some(random_box(&mut rng, 40.0)),
                };
                broad.mark(k);
            }
            broad.flush(|k| boxes[k]);
            let want = all_pairs(&boxes);
            assert_eq!(broad.overlapping_pairs(), want, "round {round}");
            assert_eq!(broad.overlapping_pairs(), want, "round {round}, reused");
            for (k, b) in boxes.iter().enumerate().take(20) {
                if let Some(b) = b {
                    let mut got: Vec<usize> = broad.overlapping(b).collect();
                    got.sort_unstable();
                    let want: Vec<usize> = (0..boxes.len())
                        .filter(|&j| boxes[j].is_some_and(|c| c.overlaps(b)))
                        .collect();
                    assert_eq!(got, want, "round {round} box {k}");
                }
            }
        }
    }
}
