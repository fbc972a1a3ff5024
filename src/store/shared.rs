//! Queries through a shared reference: answers that read only what the scene already
//! holds (boxes, snapshots, the linked polygons with their translations applied by a
//! shared read) and change nothing, so a `&Scene` can be queried from several threads
//! at once (docs/store.md, "Queries through a shared reference"). They do not plan: no
//! conversion, no counters, no history for the planner, no broad-phase repair, no warm
//! starts; each call draws its own generator and its own scratch.
//!
//! # Complexity
//! Per pair: O(1) when the boxes are disjoint; with both snapshots the array test
//! (O(log n)); otherwise the cheaper of the linear walk and the sampled test by the
//! cost model, as the planner would choose without converting (expected O(√n) for
//! large polygons), plus one scratch allocation for the sampled test.
//!
//! # Precision
//! The scene's kernel decides, as for [`Scene::intersects`]: exact under
//! [`Exact`](crate::Exact), whatever the draws.

use super::route::{QueryWorkspace, array_test, linear_test, sampled_test};
use super::scene::{PolygonId, Scene, SceneError};
use crate::kernel::{Kernel, Point};
use crate::seeding::fresh_rng;

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
        if ka == kb {
            return Ok(true);
        }
        let (ea, eb) = (&self.entries[ka], &self.entries[kb]);
        if !ea.bbox.overlaps(&eb.bbox) {
            return Ok(false);
        }
        if let (Some(p), Some(q)) = (ea.array(), eb.array()) {
            let linear = self.costs.array_is_linear(p.len(), q.len());
            return Ok(array_test(self.kernel, p, q, linear));
        }
        let (p, q) = (ea.polygon.get(), eb.polygon.get());
        if self.costs.prefers_linear(ea.polygon.arena(), eb.polygon.arena()) {
            return Ok(linear_test(self.kernel, p, q));
        }
        let mut ws = QueryWorkspace::default();
        Ok(sampled_test(self.kernel, p, q, &mut ws, &mut fresh_rng()))
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
