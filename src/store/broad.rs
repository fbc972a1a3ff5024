//! Bounding boxes and the R-tree broad phase.

use crate::kernel::Point;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{AABB, RTree};

/// A closed axis-aligned box. `overlaps` and `grow` use comparisons only (exact).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BoundingBox {
    pub min: Point,
    pub max: Point,
}

impl BoundingBox {
    /// The box of a non-empty point set.
    pub fn of(points: impl IntoIterator<Item = Point>) -> Option<BoundingBox> {
        let mut it = points.into_iter();
        let first = it.next()?;
        let mut b = BoundingBox {
            min: first,
            max: first,
        };
        for p in it {
            b.grow(p);
        }
        Some(b)
    }

    /// Extends the box to contain `p`.
    #[inline]
    pub fn grow(&mut self, p: Point) {
        self.min.x = self.min.x.min(p.x);
        self.min.y = self.min.y.min(p.y);
        self.max.x = self.max.x.max(p.x);
        self.max.y = self.max.y.max(p.y);
    }

    /// True when the closed boxes share a point.
    #[inline]
    pub fn overlaps(&self, o: &BoundingBox) -> bool {
        self.min.x <= o.max.x && o.min.x <= self.max.x && self.min.y <= o.max.y && o.min.y <= self.max.y
    }

    /// True when `p` lies on the box's boundary (removing or moving it may shrink the box).
    #[inline]
    pub fn touches_boundary(&self, p: Point) -> bool {
        p.x == self.min.x || p.x == self.max.x || p.y == self.min.y || p.y == self.max.y
    }

    fn rectangle(&self) -> Rectangle<[f64; 2]> {
        Rectangle::from_corners([self.min.x, self.min.y], [self.max.x, self.max.y])
    }
}

type Entry = GeomWithData<Rectangle<[f64; 2]>, usize>;

/// The R-tree over polygon boxes, keyed by the scene's slab key. Updates are deferred:
/// `mark` records a changed key, `flush` brings the tree up to date.
#[derive(Clone, Debug, Default)]
pub(crate) struct BroadPhase {
    tree: RTree<Entry>,
    /// The box each key is indexed under, so it can be removed again.
    indexed: Vec<Option<BoundingBox>>,
    dirty: Vec<usize>,
}

impl BroadPhase {
    /// Records that `key`'s box changed (or the key was added or removed).
    pub fn mark(&mut self, key: usize) {
        if self.indexed.len() <= key {
            self.indexed.resize(key + 1, None);
        }
        self.dirty.push(key);
    }

    /// Brings the tree up to date with `current(key)` for every dirty key.
    pub fn flush(&mut self, current: impl Fn(usize) -> Option<BoundingBox>) {
        if self.dirty.is_empty() {
            return;
        }
        self.dirty.sort_unstable();
        self.dirty.dedup();
        if self.dirty.len() * 2 > self.tree.size() {
            // Most of the tree changed: rebuild it in O(N log N) instead.
            for key in std::mem::take(&mut self.dirty) {
                self.indexed[key] = current(key);
            }
            let entries: Vec<Entry> = self
                .indexed
                .iter()
                .enumerate()
                .filter_map(|(k, b)| b.map(|b| GeomWithData::new(b.rectangle(), k)))
                .collect();
            self.tree = RTree::bulk_load(entries);
            return;
        }
        for key in std::mem::take(&mut self.dirty) {
            let now = current(key);
            if now == self.indexed[key] {
                continue;
            }
            if let Some(old) = self.indexed[key] {
                self.tree.remove(&GeomWithData::new(old.rectangle(), key));
            }
            if let Some(b) = now {
                self.tree.insert(GeomWithData::new(b.rectangle(), key));
            }
            self.indexed[key] = now;
        }
    }

    /// Keys whose boxes overlap `b` (closed). The tree must be flushed.
    pub fn overlapping(&self, b: &BoundingBox) -> impl Iterator<Item = usize> + '_ {
        let env = AABB::from_corners([b.min.x, b.min.y], [b.max.x, b.max.y]);
        self.tree.locate_in_envelope_intersecting(env).map(|e| e.data)
    }

    /// All pairs of keys (a < b) whose boxes overlap. The tree must be flushed.
    pub fn overlapping_pairs(&self) -> Vec<(usize, usize)> {
        let mut pairs: Vec<(usize, usize)> = self
            .tree
            .intersection_candidates_with_other_tree(&self.tree)
            .filter(|(a, b)| a.data < b.data)
            .map(|(a, b)| (a.data, b.data))
            .collect();
        pairs.sort_unstable();
        pairs
    }
}
