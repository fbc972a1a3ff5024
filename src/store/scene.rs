//! [`Scene`]: the store of editable polygons and its query planner.

use super::broad::{BoundingBox, BroadPhase};
use super::planner::{CostModel, PlannerStats, Strategy, array_test};
use crate::intersect::{Clm, ClmWorkspace, LinkedIntersection};
use crate::kernel::{Exact, Kernel, Point};
use crate::polygon::{ConvexPolygon, EditError, LinkedPolygon, PolygonError, VertexId};
use rand::SeedableRng;
use rand::rngs::SmallRng;
#[cfg(feature = "parallel")]
use rayon::prelude::*;
use slab::Slab;
use std::fmt;

/// A handle to a polygon in a [`Scene`]. Carries a generation: after the polygon is
/// removed, every use is [`SceneError::StalePolygon`], even if its slot is reused.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PolygonId {
    key: u32,
    generation: u64,
}

/// Why a scene operation failed. A failed operation changes nothing.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneError {
    /// The polygon handle is stale (the polygon was removed).
    StalePolygon,
    /// A vertex edit was refused.
    Edit(EditError),
    /// A polygon to insert is invalid.
    Polygon(PolygonError),
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SceneError::StalePolygon => write!(f, "the polygon handle is stale (the polygon was removed)"),
            SceneError::Edit(e) => write!(f, "{e}"),
            SceneError::Polygon(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for SceneError {}

impl From<EditError> for SceneError {
    fn from(e: EditError) -> Self {
        SceneError::Edit(e)
    }
}

impl From<PolygonError> for SceneError {
    fn from(e: PolygonError) -> Self {
        SceneError::Polygon(e)
    }
}

#[derive(Clone, Debug)]
struct Entry {
    polygon: LinkedPolygon,
    generation: u64,
    bbox: BoundingBox,
    /// False after an edit that may have shrunk the true box; the stored box still
    /// contains the polygon.
    bbox_tight: bool,
    /// Bumped at every edit.
    version: u64,
    /// The array form, present only while the polygon is unchanged since it was built.
    snapshot: Option<ConvexPolygon>,
    /// Estimated cost of the sampled queries this polygon took part in since its last
    /// edit (the planner's ski-rental account), in nanoseconds.
    rent_ns: f64,
    /// The estimated cost of the last sampled query it took part in.
    last_rent_ns: f64,
    /// Queries (past the bounding boxes) since the last edit.
    queries_since_edit: u32,
    /// Moving average of the number of queries between two edits (infinite until the
    /// first edit: no history, plain ski rental).
    queries_per_edit: f64,
}

impl Entry {
    fn edited(&mut self, stats: &mut PlannerStats) {
        self.version += 1;
        self.rent_ns = 0.0;
        let q = self.queries_since_edit as f64;
        self.queries_per_edit = if self.queries_per_edit.is_finite() {
            0.5 * self.queries_per_edit + 0.5 * q
        } else {
            q
        };
        self.queries_since_edit = 0;
        if self.snapshot.take().is_some() {
            stats.invalidations += 1;
        }
    }
}

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

/// How one planned query will be answered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Route {
    Known(bool),
    Arrays(usize, usize),
    Sampled(usize, usize),
    Throwaway(usize, usize),
}

/// A scene of editable convex polygons with planned intersection queries; see the
/// [module docs](super) for the planner's rule.
///
/// ```
/// use polysect::store::Scene;
/// use polysect::Point;
/// let mut scene = Scene::new();
/// let a = scene.insert_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let b = scene.insert_points([[3.0, 0.0], [4.0, 0.0], [4.0, 1.0]])?;
/// assert!(!scene.intersects(a, b)?);
/// // Pull a's corner (2, 0) out to (3, 0): now they touch.
/// let corner = scene.polygon(a)?.next(scene.polygon(a)?.first())?;
/// scene.move_vertex(a, corner, Point::new(3.0, 0.0))?;
/// assert!(scene.intersects(a, b)?);
/// assert_eq!(scene.intersecting_pairs(), vec![(a, b)]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct Scene<K: Kernel = Exact> {
    kernel: K,
    entries: Slab<Entry>,
    next_generation: u64,
    broad: BroadPhase,
    strategy: Strategy,
    costs: CostModel,
    stats: PlannerStats,
    workspace: QueryWorkspace,
    rng: SmallRng,
}

impl Default for Scene<Exact> {
    fn default() -> Self {
        Scene::new()
    }
}

impl Scene<Exact> {
    /// An empty scene on the exact kernel, with the planner and the default cost model.
    pub fn new() -> Self {
        Scene::with_kernel(Exact)
    }
}

impl<K: Kernel> Scene<K> {
    /// An empty scene deciding predicates with `kernel`.
    pub fn with_kernel(kernel: K) -> Self {
        Scene {
            kernel,
            entries: Slab::new(),
            next_generation: 0,
            broad: BroadPhase::default(),
            strategy: Strategy::Planner,
            costs: CostModel::default(),
            stats: PlannerStats::default(),
            workspace: QueryWorkspace::default(),
            rng: crate::intersect::fresh_rng(),
        }
    }

    /// Reseeds the RNG of the sampled test, which is otherwise seeded from the operating
    /// system (docs/design.md, "Randomness"): the same seed and the same operations give
    /// the same draws. Answers do not depend on it under the exact kernel; running times
    /// and the fast kernel's rare wrong answers do.
    pub fn seed(&mut self, seed: u64) {
        self.rng = SmallRng::seed_from_u64(seed);
    }

    pub fn strategy(&self) -> Strategy {
        self.strategy
    }

    /// Chooses how queries are answered (for comparisons; the planner is the default).
    pub fn set_strategy(&mut self, strategy: Strategy) {
        self.strategy = strategy;
    }

    pub fn costs(&self) -> CostModel {
        self.costs
    }

    pub fn set_costs(&mut self, costs: CostModel) {
        self.costs = costs;
    }

    /// Measures the cost model on this machine ([`CostModel::calibrate`]) and uses it.
    pub fn calibrate(&mut self) -> CostModel {
        self.costs = CostModel::calibrate(self.kernel);
        self.costs
    }

    /// Counters of what the planner did.
    pub fn stats(&self) -> PlannerStats {
        self.stats
    }

    pub fn reset_stats(&mut self) {
        self.stats = PlannerStats::default();
    }

    /// Number of polygons.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// The handles of all polygons, in slot order.
    pub fn ids(&self) -> impl Iterator<Item = PolygonId> + '_ {
        self.entries.iter().map(|(k, e)| PolygonId {
            key: k as u32,
            generation: e.generation,
        })
    }

    /// Number of polygons that currently hold an array snapshot.
    pub fn snapshot_count(&self) -> usize {
        self.entries.iter().filter(|(_, e)| e.snapshot.is_some()).count()
    }

    /// Adds a polygon.
    pub fn insert(&mut self, polygon: LinkedPolygon) -> PolygonId {
        let bbox = BoundingBox::of(polygon.iter().map(|(_, p)| p)).expect("a polygon has vertices");
        let generation = self.next_generation;
        self.next_generation += 1;
        let key = self.entries.insert(Entry {
            polygon,
            generation,
            bbox,
            bbox_tight: true,
            version: 0,
            snapshot: None,
            rent_ns: 0.0,
            last_rent_ns: 0.0,
            queries_since_edit: 0,
            queries_per_edit: f64::INFINITY,
        });
        self.broad.mark(key);
        PolygonId {
            key: key as u32,
            generation,
        }
    }

    /// Validates `points` ([`ConvexPolygon::new`]) and adds the polygon.
    pub fn insert_points<I, P>(&mut self, points: I) -> Result<PolygonId, SceneError>
    where
        I: IntoIterator<Item = P>,
        P: Into<Point>,
    {
        Ok(self.insert(LinkedPolygon::from_points(points)?))
    }

    /// Removes a polygon, returning it.
    pub fn remove(&mut self, id: PolygonId) -> Result<LinkedPolygon, SceneError> {
        let key = self.key(id)?;
        self.broad.mark(key);
        Ok(self.entries.remove(key).polygon)
    }

    fn key(&self, id: PolygonId) -> Result<usize, SceneError> {
        match self.entries.get(id.key as usize) {
            Some(e) if e.generation == id.generation => Ok(id.key as usize),
            _ => Err(SceneError::StalePolygon),
        }
    }

    fn id_of(&self, key: usize) -> PolygonId {
        PolygonId {
            key: key as u32,
            generation: self.entries[key].generation,
        }
    }

    /// The polygon (read-only; edit through the scene so caches stay correct).
    pub fn polygon(&self, id: PolygonId) -> Result<&LinkedPolygon, SceneError> {
        self.key(id).map(|k| &self.entries[k].polygon)
    }

    /// The polygon's bounding box: it always contains the polygon, and is the tightest
    /// box unless an edit since the last conversion may have shrunk the polygon.
    pub fn bounding_box(&self, id: PolygonId) -> Result<BoundingBox, SceneError> {
        self.key(id).map(|k| self.entries[k].bbox)
    }

    /// Number of edits the polygon has had.
    pub fn version(&self, id: PolygonId) -> Result<u64, SceneError> {
        self.key(id).map(|k| self.entries[k].version)
    }

    /// True while the polygon holds a valid array snapshot.
    pub fn has_snapshot(&self, id: PolygonId) -> Result<bool, SceneError> {
        self.key(id).map(|k| self.entries[k].snapshot.is_some())
    }

    /// Inserts a vertex after `after` (see [`LinkedPolygon::insert_after`]). O(1).
    pub fn insert_vertex(
        &mut self,
        id: PolygonId,
        after: VertexId,
        p: Point,
    ) -> Result<VertexId, SceneError> {
        let key = self.key(id)?;
        let e = &mut self.entries[key];
        let v = e.polygon.insert_after(after, p)?;
        e.edited(&mut self.stats);
        self.grow_box(key, p);
        Ok(v)
    }

    /// Removes a vertex (see [`LinkedPolygon::remove`]). O(1).
    pub fn remove_vertex(&mut self, id: PolygonId, v: VertexId) -> Result<Point, SceneError> {
        let key = self.key(id)?;
        let e = &mut self.entries[key];
        let old = e.polygon.remove(v)?;
        e.edited(&mut self.stats);
        if e.bbox.touches_boundary(old) {
            e.bbox_tight = false;
        }
        Ok(old)
    }

    /// Moves a vertex (see [`LinkedPolygon::move_vertex`]). O(1).
    pub fn move_vertex(&mut self, id: PolygonId, v: VertexId, p: Point) -> Result<Point, SceneError> {
        let key = self.key(id)?;
        let e = &mut self.entries[key];
        let old = e.polygon.move_vertex(v, p)?;
        e.edited(&mut self.stats);
        if e.bbox.touches_boundary(old) {
            e.bbox_tight = false;
        }
        self.grow_box(key, p);
        Ok(old)
    }

    /// Translates the polygon by `(dx, dy)`: every vertex becomes `(x + dx, y + dy)`, each
    /// coordinate rounded to nearest (IEEE addition). O(n) to translate and validate, then
    /// O(1) for the bounding box (shifted; rounding is monotone, so the shifted box still
    /// contains, or equals, the translated polygon's box) and no reconversion: a valid
    /// array snapshot is translated in place with the same roundings and stays valid.
    /// Vertex handles stay valid. See docs/store.md for what is exact here.
    ///
    /// # Errors
    /// `StalePolygon`; [`EditError::NonFinite`] when `dx` or `dy` is not finite or a
    /// coordinate would overflow; [`EditError::RoundingBreaksConvexity`] when rounding
    /// would leave the polygon not strictly convex. Nothing changes on error.
    ///
    /// ```
    /// use polysect::store::Scene;
    /// let mut scene = Scene::new();
    /// let a = scene.insert_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// let b = scene.insert_points([[3.0, 0.0], [4.0, 0.0], [4.0, 1.0]])?;
    /// assert!(!scene.intersects(a, b)?);
    /// scene.translate(b, -1.0, 0.5)?; // b's corner (2, 0.5) now lies on a's edge
    /// assert!(scene.intersects(a, b)?);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn translate(&mut self, id: PolygonId, dx: f64, dy: f64) -> Result<(), SceneError> {
        let key = self.key(id)?;
        let e = &mut self.entries[key];
        e.polygon.translate(dx, dy)?;
        e.version += 1;
        if let Some(s) = &mut e.snapshot {
            s.translate_unchecked(dx, dy);
        }
        let shifted = BoundingBox {
            min: Point::new(e.bbox.min.x + dx, e.bbox.min.y + dy),
            max: Point::new(e.bbox.max.x + dx, e.bbox.max.y + dy),
        };
        if shifted.min.is_finite() && shifted.max.is_finite() {
            e.bbox = shifted;
        } else {
            // A loose box reaching past the polygon overflowed: take the true box.
            e.bbox = BoundingBox::of(e.polygon.iter().map(|(_, p)| p)).expect("a polygon has vertices");
            e.bbox_tight = true;
        }
        self.broad.mark(key);
        Ok(())
    }

    fn grow_box(&mut self, key: usize, p: Point) {
        let e = &mut self.entries[key];
        let before = e.bbox;
        e.bbox.grow(p);
        if e.bbox != before {
            self.broad.mark(key);
        }
    }

    /// Builds and keeps the snapshot; the walk also makes the box tight again.
    fn convert(&mut self, key: usize) {
        let e = &mut self.entries[key];
        let snapshot = e.polygon.to_convex();
        self.install_snapshot(key, snapshot);
    }

    fn install_snapshot(&mut self, key: usize, snapshot: ConvexPolygon) {
        let e = &mut self.entries[key];
        if !e.bbox_tight {
            let (min, max) = snapshot.bounding_box();
            e.bbox = BoundingBox { min, max };
            e.bbox_tight = true;
            self.broad.mark(key);
        }
        e.snapshot = Some(snapshot);
        self.stats.conversions += 1;
    }

    /// Ski rental, refined by the polygon's history: convert once the rent paid since the
    /// last edit covers the conversion, unless the queries expected before the next edit
    /// (the average between edits so far, less those already seen; at least as many as
    /// already seen once past the average) would not pay for it.
    fn should_convert(&self, key: usize) -> bool {
        let e = &self.entries[key];
        let cost = self.costs.convert_cost(e.polygon.len());
        if e.rent_ns < cost {
            return false;
        }
        let seen = e.queries_since_edit as f64;
        let expected_more = if e.queries_per_edit > seen {
            e.queries_per_edit - seen
        } else {
            seen
        };
        expected_more * e.last_rent_ns >= cost
    }

    /// Plans one query between live keys: bounding boxes, then the strategy. Keys chosen
    /// for conversion are appended to `pending` (the caller converts them before
    /// answering); later plans treat them as converted.
    fn plan(&mut self, a: usize, b: usize, pending: &mut Vec<usize>) -> Route {
        if a == b {
            return Route::Known(true);
        }
        if !self.entries[a].bbox.overlaps(&self.entries[b].bbox) {
            self.stats.box_rejects += 1;
            return Route::Known(false);
        }
        for k in [a, b] {
            self.entries[k].queries_since_edit = self.entries[k].queries_since_edit.saturating_add(1);
        }
        let has = |s: &Self, k: usize, pending: &Vec<usize>| {
            s.entries[k].snapshot.is_some() || pending.contains(&k)
        };
        match self.strategy {
            Strategy::Sampled => {}
            Strategy::Convert => {
                if !(has(self, a, pending) && has(self, b, pending)) {
                    self.stats.throwaway_conversions += 2;
                    return Route::Throwaway(a, b);
                }
            }
            Strategy::Cached => {
                for k in [a, b] {
                    if !has(self, k, pending) {
                        pending.push(k);
                    }
                }
            }
            Strategy::Planner => {
                for k in [a, b] {
                    if !has(self, k, pending) && self.should_convert(k) {
                        pending.push(k);
                    }
                }
            }
        }
        if has(self, a, pending) && has(self, b, pending) {
            self.stats.array_tests += 1;
            return Route::Arrays(a, b);
        }
        let rent = self
            .costs
            .sampled_cost(self.entries[a].polygon.len().max(self.entries[b].polygon.len()));
        for k in [a, b] {
            if !has(self, k, pending) {
                self.entries[k].rent_ns += rent;
                self.entries[k].last_rent_ns = rent;
            }
        }
        self.stats.sampled_tests += 1;
        Route::Sampled(a, b)
    }

    fn answer(&self, route: Route, ws: &mut QueryWorkspace, rng: &mut SmallRng) -> bool {
        let e = |k: usize| &self.entries[k];
        match route {
            Route::Known(v) => v,
            Route::Arrays(a, b) => array_test(
                self.kernel,
                e(a).snapshot.as_ref().expect("planned snapshot"),
                e(b).snapshot.as_ref().expect("planned snapshot"),
            ),
            Route::Sampled(a, b) => sampled_test(self.kernel, &e(a).polygon, &e(b).polygon, ws, rng),
            Route::Throwaway(a, b) => {
                array_test(self.kernel, &e(a).polygon.to_convex(), &e(b).polygon.to_convex())
            }
        }
    }

    /// Whether polygons `a` and `b` intersect (closed sets: touching counts).
    pub fn intersects(&mut self, a: PolygonId, b: PolygonId) -> Result<bool, SceneError> {
        let (ka, kb) = (self.key(a)?, self.key(b)?);
        let mut pending = Vec::new();
        let route = self.plan(ka, kb, &mut pending);
        for k in pending {
            self.convert(k);
        }
        let mut ws = std::mem::take(&mut self.workspace);
        let mut rng = std::mem::replace(&mut self.rng, SmallRng::seed_from_u64(0));
        let answer = self.answer(route, &mut ws, &mut rng);
        (self.workspace, self.rng) = (ws, rng);
        Ok(answer)
    }

    /// Answers many queries: planned in order, conversions built in parallel, then the
    /// pairs answered in parallel (on rayon's pool with the `parallel` feature, in order
    /// on the calling thread without it). Results are in input order and do not depend
    /// on the number of threads, nor on the feature.
    pub fn intersects_batch(&mut self, pairs: &[(PolygonId, PolygonId)]) -> Vec<Result<bool, SceneError>> {
        let mut pending = Vec::new();
        let routes: Vec<Result<Route, SceneError>> = pairs
            .iter()
            .map(|&(a, b)| {
                let (ka, kb) = (self.key(a)?, self.key(b)?);
                Ok(self.plan(ka, kb, &mut pending))
            })
            .collect();
        self.convert_all(pending);
        let base: u64 = rand::Rng::random(&mut self.rng);
        let this = &*self;
        let answer = |ws: &mut QueryWorkspace, (i, route): (usize, &Result<Route, SceneError>)| {
            let route = route.clone()?;
            let mut rng = SmallRng::seed_from_u64(base ^ (i as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15));
            Ok(this.answer(route, ws, &mut rng))
        };
        #[cfg(feature = "parallel")]
        let answers = routes
            .par_iter()
            .enumerate()
            .map_init(QueryWorkspace::default, answer)
            .collect();
        #[cfg(not(feature = "parallel"))]
        let answers = {
            let mut ws = QueryWorkspace::default();
            routes
                .iter()
                .enumerate()
                .map(|item| answer(&mut ws, item))
                .collect()
        };
        answers
    }

    fn convert_all(&mut self, mut keys: Vec<usize>) {
        keys.sort_unstable();
        keys.dedup();
        #[cfg(feature = "parallel")]
        let keys_iter = keys.par_iter();
        #[cfg(not(feature = "parallel"))]
        let keys_iter = keys.iter();
        let snapshots: Vec<(usize, ConvexPolygon)> = keys_iter
            .map(|&k| (k, self.entries[k].polygon.to_convex()))
            .collect();
        for (k, s) in snapshots {
            self.install_snapshot(k, s);
        }
    }

    fn flush_broad_phase(&mut self) {
        let entries = &self.entries;
        self.broad.flush(|k| entries.get(k).map(|e| e.bbox));
    }

    /// All polygons other than `a` that intersect it, in slot order.
    pub fn intersecting(&mut self, a: PolygonId) -> Result<Vec<PolygonId>, SceneError> {
        let ka = self.key(a)?;
        self.flush_broad_phase();
        let mut candidates: Vec<usize> = self
            .broad
            .overlapping(&self.entries[ka].bbox)
            .filter(|&k| k != ka)
            .collect();
        candidates.sort_unstable();
        let pairs: Vec<(PolygonId, PolygonId)> = candidates.iter().map(|&k| (a, self.id_of(k))).collect();
        let answers = self.intersects_batch(&pairs);
        Ok(pairs
            .into_iter()
            .zip(answers)
            .filter(|(_, hit)| matches!(hit, Ok(true)))
            .map(|((_, b), _)| b)
            .collect())
    }

    /// All intersecting pairs `(a, b)` with `a` before `b` in slot order, sorted.
    pub fn intersecting_pairs(&mut self) -> Vec<(PolygonId, PolygonId)> {
        self.flush_broad_phase();
        let candidates: Vec<(PolygonId, PolygonId)> = self
            .broad
            .overlapping_pairs()
            .into_iter()
            .map(|(a, b)| (self.id_of(a), self.id_of(b)))
            .collect();
        let answers = self.intersects_batch(&candidates);
        candidates
            .into_iter()
            .zip(answers)
            .filter(|(_, hit)| matches!(hit, Ok(true)))
            .map(|(pair, _)| pair)
            .collect()
    }

    /// Pairs of polygons whose bounding boxes overlap (the broad phase's candidates).
    pub fn candidate_pairs(&mut self) -> Vec<(PolygonId, PolygonId)> {
        self.flush_broad_phase();
        self.broad
            .overlapping_pairs()
            .into_iter()
            .map(|(a, b)| (self.id_of(a), self.id_of(b)))
            .collect()
    }

    /// Checks every invariant: each polygon's own, boxes contain their polygons (and equal
    /// them when marked tight), snapshots equal their polygons.
    pub fn debug_validate(&self) -> Result<(), String> {
        for (k, e) in &self.entries {
            e.polygon
                .debug_validate()
                .map_err(|m| format!("polygon {k}: {m}"))?;
            let exact = BoundingBox::of(e.polygon.iter().map(|(_, p)| p)).expect("vertices");
            let b = e.bbox;
            let contains = b.min.x <= exact.min.x
                && b.min.y <= exact.min.y
                && b.max.x >= exact.max.x
                && b.max.y >= exact.max.y;
            if !contains || (e.bbox_tight && b != exact) {
                return Err(format!(
                    "polygon {k}: box {b:?}, true box {exact:?}, tight {}",
                    e.bbox_tight
                ));
            }
            if let Some(s) = &e.snapshot {
                let mut now = e.polygon.to_convex().into_vertices();
                let start = now
                    .iter()
                    .position(|&p| p == s.vertices()[0])
                    .ok_or("snapshot vertex missing")?;
                now.rotate_left(start);
                if now != s.vertices() {
                    return Err(format!("polygon {k}: stale snapshot"));
                }
            }
        }
        Ok(())
    }
}
