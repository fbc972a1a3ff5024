//! Queries through a shared reference: answers that read only what the scene already
//! holds (boxes, snapshots, the linked polygons with their translations applied by a
//! shared read) and change nothing, so a `&Scene` can be queried from several threads
//! at once (docs/store.md, "Queries through a shared reference"). They do not plan: no
//! conversion, no counters, no history for the planner, no broad-phase repair, no warm
//! starts; each call draws its own generator and its own scratch (one of each for a
//! whole search or frame).
//!
//! # Complexity
//! Per pair: O(1) when the boxes are disjoint; with both snapshots the array test
//! (O(log n)); otherwise the cheaper of the linear walk and the sampled test by the
//! cost model, as the planner would choose without converting (expected O(√n) for
//! large polygons). The scene's broad phase is repaired only through `&mut`, so the
//! shared searches find their candidates from the boxes themselves: a scan of the P
//! boxes for [`Scene::intersecting_shared`], a sweep over them sorted by their left
//! sides for [`Scene::intersecting_pairs_shared`] (O(P log P + c), c the pairs whose
//! x-ranges overlap).
//!
//! # Precision
//! The scene's kernel decides, as for [`Scene::intersects`]: exact under
//! [`Exact`](crate::Exact), whatever the draws.

use super::route::{QueryWorkspace, array_test, linear_test, sampled_test};
use super::scene::{PolygonId, Scene, SceneError};
use crate::kernel::{Kernel, Point};
use crate::seeding::fresh_rng;
use rand::rngs::SmallRng;

/// What one shared call keeps across the pairs it answers: the sampled test's scratch
/// and a generator, drawn when a pair first needs it.
#[derive(Default)]
struct Scratch {
    workspace: QueryWorkspace,
    rng: Option<SmallRng>,
}

impl<K: Kernel> Scene<K> {
    /// Whether polygons `a` and `b` intersect (closed sets: touching counts), through
    /// `&self`: the same answer as [`intersects`](Self::intersects) under the exact
    /// kernel, without planning (module docs: nothing changes, nothing is converted, the
    /// planner's counters and history are not fed). For a scene shared between threads,
    /// or read while borrowed elsewhere.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon` for either handle.
    ///
    /// ```
    /// use polysect::store::Scene;
    /// let mut scene = Scene::new();
    /// let a = scene.insert_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// let b = scene.insert_points([[2.0, 1.0], [4.0, 0.0], [4.0, 3.0]])?;
    /// let shared = &scene;
    /// let answers = std::thread::scope(|s| {
    ///     let t = s.spawn(|| shared.intersects_shared(a, b));
    ///     (shared.intersects_shared(b, a), t.join().unwrap())
    /// });
    /// assert_eq!(answers, (Ok(true), Ok(true)));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn intersects_shared(&self, a: PolygonId, b: PolygonId) -> Result<bool, SceneError> {
        let (ka, kb) = (self.key(a)?, self.key(b)?);
        Ok(self.pair_shared(ka, kb, &mut Scratch::default()))
    }

    /// [`intersecting`](Self::intersecting) through `&self`: all polygons other than `a`
    /// that intersect it, in slot order (the same list), found by a scan of the boxes.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn intersecting_shared(&self, a: PolygonId) -> Result<Vec<PolygonId>, SceneError> {
        let ka = self.key(a)?;
        let mut scratch = Scratch::default();
        let bbox = self.entries[ka].bbox;
        Ok(self
            .entries
            .iter()
            .filter(|&(k, e)| k != ka && e.bbox.overlaps(&bbox))
            .filter(|&(k, _)| self.pair_shared(ka, k, &mut scratch))
            .map(|(k, _)| self.id_of(k))
            .collect())
    }

    /// [`intersecting_pairs`](Self::intersecting_pairs) through `&self`: all
    /// intersecting pairs `(a, b)` with `a` before `b` in slot order, sorted (the same
    /// list), the candidates from a sweep over the boxes (module docs). Without warm
    /// starts and without the broad phase's kept order, so a frame costs the sort.
    pub fn intersecting_pairs_shared(&self) -> Vec<(PolygonId, PolygonId)> {
        let mut order: Vec<usize> = self.entries.iter().map(|(k, _)| k).collect();
        order.sort_unstable_by(|&a, &b| self.entries[a].bbox.min.x.total_cmp(&self.entries[b].bbox.min.x));
        let mut scratch = Scratch::default();
        let mut pairs = Vec::new();
        for (i, &ka) in order.iter().enumerate() {
            let bbox = self.entries[ka].bbox;
            for &kb in &order[i + 1..] {
                let other = &self.entries[kb].bbox;
                if other.min.x > bbox.max.x {
                    break;
                }
                if other.overlaps(&bbox) && self.pair_shared(ka, kb, &mut scratch) {
                    pairs.push((ka.min(kb), ka.max(kb)));
                }
            }
        }
        pairs.sort_unstable();
        pairs
            .into_iter()
            .map(|(a, b)| (self.id_of(a), self.id_of(b)))
            .collect()
    }

    /// The shared answer for the polygons in slots `ka` and `kb` (module docs).
    fn pair_shared(&self, ka: usize, kb: usize, scratch: &mut Scratch) -> bool {
        if ka == kb {
            return true;
        }
        let (ea, eb) = (&self.entries[ka], &self.entries[kb]);
        if !ea.bbox.overlaps(&eb.bbox) {
            return false;
        }
        if let (Some(p), Some(q)) = (ea.array(), eb.array()) {
            let linear = self.costs.array_is_linear(p.len(), q.len());
            return array_test(self.kernel, p, q, linear);
        }
        let (p, q) = (ea.polygon.get(), eb.polygon.get());
        if self.costs.prefers_linear(ea.polygon.arena(), eb.polygon.arena()) {
            return linear_test(self.kernel, p, q);
        }
        let Scratch { workspace, rng } = scratch;
        sampled_test(self.kernel, p, q, workspace, rng.get_or_insert_with(fresh_rng))
    }

    /// [`contains_point`](Self::contains_point) through `&self`: the same answer, with
    /// a generator of its own for the sampled search (module docs).
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn contains_point_shared(&self, id: PolygonId, point: impl Into<Point>) -> Result<bool, SceneError> {
        let e = &self.entries[self.key(id)?];
        let x = point.into();
        if !e.bbox.contains_point(x) {
            return Ok(false);
        }
        Ok(match &e.snapshot {
            Some(s) => s.contains_point_with(self.kernel, x),
            None => e
                .polygon
                .get()
                .contains_point_with(self.kernel, x, &mut fresh_rng()),
        })
    }
}
