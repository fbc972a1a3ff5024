//! [`Scene`]: the store of editable polygons and its query planner.

use super::broad::{BoundingBox, BroadPhase};
use super::lazy::LazyLinked;
use super::planner::{Account, CostModel, PlannerStats, Strategy};
use super::route::{
    QueryWorkspace, Route, array_certified, array_test, linear_certified, linear_test, sampled_certified,
    sampled_test,
};
use super::warm::{self, Warm, WarmCache, WarmStats};
use crate::intersect::{Certificate, Which};
use crate::kernel::{Exact, Kernel, Point};
use crate::polygon::{ConvexPolygon, EditError, Identity, LinkedPolygon, PolygonError, VertexId};
use rand::rngs::SmallRng;
use rand::{RngCore, SeedableRng};
#[cfg(feature = "parallel")]
use rayon::prelude::*;
use slab::Slab;
use std::fmt;

/// A handle to a polygon in one [`Scene`]. Carries a generation: after the polygon is
/// removed, every use is [`SceneError::StalePolygon`], even if its slot is reused. It also
/// carries the scene's identity: given to any other scene (a clone included), every use
/// is [`SceneError::ForeignPolygon`]. Handles of one scene order by slot.
///
/// Serialises (serde) as `{"scene": s, "key": k, "generation": g}` and reads back the
/// same, so a handle can be stored and used again with the same scene while the process
/// runs. Scene identities count up within a process, so a handle read back in another
/// process is not meaningful there (it may name that process's scene with the same
/// identity). Displays as `#k (generation g)`, the form error messages use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PolygonId {
    scene: u64,
    key: u32,
    generation: u64,
}

impl fmt::Display for PolygonId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "#{} (generation {})", self.key, self.generation)
    }
}

/// Why a scene operation failed. A failed operation changes nothing.
///
/// Messages name the polygon where there is one (`polygon #3 (generation 5): ...`).
/// [`Error::source`](std::error::Error::source) returns the underlying [`EditError`] or
/// [`PolygonError`]; its text is also part of this error's message, so a reporter that
/// prints the whole chain shows it twice.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneError {
    /// The polygon handle is stale (the polygon was removed).
    /// The polygon handle is stale (the polygon was removed).
    StalePolygon(PolygonId),
    /// The polygon handle belongs to another scene (or to another copy of this one).
    ForeignPolygon(PolygonId),
    /// A vertex edit of this polygon was refused.
    Edit(PolygonId, EditError),
    /// A polygon to insert is invalid.
    Polygon(PolygonError),
}

impl SceneError {
    /// The polygon the error is about, when there is one (none for an invalid polygon
    /// that was never inserted).
    pub fn polygon(&self) -> Option<PolygonId> {
        match self {
            SceneError::StalePolygon(id) | SceneError::ForeignPolygon(id) | SceneError::Edit(id, _) => {
                Some(*id)
            }
            SceneError::Polygon(_) => None,
        }
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SceneError::StalePolygon(id) => {
                write!(f, "polygon {id} is stale (the polygon was removed)")
            }
            SceneError::ForeignPolygon(id) => {
                write!(
                    f,
                    "polygon {id} belongs to another scene (or another copy of this one)"
                )
            }
            SceneError::Edit(id, e) => write!(f, "polygon {id}: {e}"),
            SceneError::Polygon(e) => write!(f, "invalid polygon: {e}"),
        }
    }
}

impl std::error::Error for SceneError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            SceneError::StalePolygon(_) | SceneError::ForeignPolygon(_) => None,
            SceneError::Edit(_, e) => Some(e),
            SceneError::Polygon(e) => Some(e),
        }
    }
}

impl From<PolygonError> for SceneError {
    fn from(e: PolygonError) -> Self {
        SceneError::Polygon(e)
    }
}

#[derive(Clone, Debug)]
struct Entry {
    /// The linked polygon; translations may wait in it until it is read (`lazy.rs`).
    polygon: LazyLinked,
    generation: u64,
    bbox: BoundingBox,
    /// False after an edit that may have shrunk the true box; the stored box still
    /// contains the polygon.
    bbox_tight: bool,
    /// Bumped at every edit.
    version: u64,
    /// The array form, present only while the polygon is unchanged since it was built.
    snapshot: Option<ConvexPolygon>,
    /// The planner's ski-rental account.
    account: Account,
    /// A translation whose rounding moves no coordinate by this much or more keeps the
    /// polygon strictly convex (0: unknown); see `Scene::translate`.
    rounding_margin: f64,
    /// A power of two of which every coordinate is an integer multiple (`grid_of`);
    /// translations on this grid that cannot round are proved exact in O(1).
    grid: f64,
    /// Scratch of the plan being made: chosen for conversion, and what a snapshot would
    /// save the planned queries (and how many) that involve this polygon.
    plan: PlanMark,
}

/// A planned batch: a route per pair (in input order), the polygons to convert first,
/// and the estimated costs of the conversions and of the answers, in nanoseconds.
struct Plan {
    routes: Vec<Result<Route, SceneError>>,
    /// The keys of each query's P and Q, beside its route ((0, 0) for an error).
    keys: Vec<(usize, usize)>,
    chosen: Vec<usize>,
    convert_ns: f64,
    answer_ns: f64,
}

/// Conversions, or answers, run on other threads too only when there are several and
/// their estimated cost reaches this: handing work to other threads costs microseconds,
/// and far more when the machine is busy (the caller waits for a worker to wake up).
const PARALLEL_MIN_NS: f64 = 1e6;

/// Per-polygon marks of one plan, so that planning a batch is O(1) per pair; every
/// field is back at its default when a plan ends.
#[derive(Clone, Copy, Debug, Default)]
struct PlanMark {
    convert: bool,
    touched: bool,
    known_ns: f64,
    known: u32,
}

impl Entry {
    fn edited(&mut self, stats: &mut PlannerStats) {
        self.version += 1;
        self.account.edited();
        self.rounding_margin = 0.0;
        if self.snapshot.take().is_some() {
            stats.invalidations += 1;
        }
    }

    /// Has a snapshot, or will have one before the plan is answered.
    fn will_have_snapshot(&self) -> bool {
        self.snapshot.is_some() || self.plan.convert
    }
}

/// A scene of editable convex polygons with planned intersection queries; see the
/// [module docs](super) for the planner's rule.
///
/// # Handles
/// Every method taking a [`PolygonId`] refuses a handle of a removed polygon
/// ([`SceneError::StalePolygon`]) and a handle of another scene
/// ([`SceneError::ForeignPolygon`]); every method taking a [`VertexId`] refuses a vertex
/// handle of another polygon (`SceneError::Edit(EditError::ForeignHandle)`), also one of
/// a polygon of this scene. A refused call changes nothing. A clone of a scene is another
/// scene: take its handles from [`ids`](Self::ids).
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
    /// Fresh for every scene and every clone: handles name polygons of this scene only.
    identity: Identity,
    kernel: K,
    entries: Slab<Entry>,
    next_generation: u64,
    broad: BroadPhase,
    strategy: Strategy,
    costs: CostModel,
    stats: PlannerStats,
    workspace: QueryWorkspace,
    rng: SmallRng,
    /// Warm starts across frames: on/off, and the last frame's pairs.
    warm_starts: bool,
    warm: WarmCache,
    /// Translations proved exact by the grid (tests only).
    #[cfg(test)]
    exact_skips: u64,
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
            identity: Identity::fresh(),
            kernel,
            entries: Slab::new(),
            next_generation: 0,
            broad: BroadPhase::default(),
            strategy: Strategy::Planner,
            costs: CostModel::default(),
            stats: PlannerStats::default(),
            workspace: QueryWorkspace::default(),
            rng: crate::polygon::queries::fresh_rng(),
            warm_starts: false,
            warm: WarmCache::default(),
            #[cfg(test)]
            exact_skips: 0,
        }
    }

    /// Reseeds the RNG of the sampled test, which is otherwise seeded from the operating
    /// system (without the `os-rng` feature, from a counter; docs/design.md,
    /// "Randomness"): the same seed and the same operations give
    /// the same draws. Answers do not depend on it under the exact kernel; running times
    /// and the fast kernel's rare wrong answers do.
    pub fn seed(&mut self, seed: u64) {
        self.rng = SmallRng::seed_from_u64(seed);
    }

    /// How queries are answered (the planner unless [`set_strategy`](Self::set_strategy)
    /// chose otherwise).
    pub fn strategy(&self) -> Strategy {
        self.strategy
    }

    /// Chooses how queries are answered (for comparisons; the planner is the default).
    pub fn set_strategy(&mut self, strategy: Strategy) {
        self.strategy = strategy;
    }

    /// The cost model the planner uses.
    pub fn costs(&self) -> CostModel {
        self.costs
    }

    /// Replaces the cost model (for example one measured by [`calibrate`](Self::calibrate)
    /// elsewhere and stored).
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

    /// Zeroes the planner's and the warm starts' counters.
    pub fn reset_stats(&mut self) {
        self.stats = PlannerStats::default();
        self.warm.stats = WarmStats::default();
    }

    /// Whether [`intersecting_pairs`](Self::intersecting_pairs) uses warm starts across
    /// frames (off by default; the [module docs](super) and docs/store.md).
    pub fn warm_starts(&self) -> bool {
        self.warm_starts
    }

    /// Turns warm starts across frames on or off (off drops what was kept). Answers
    /// are the same either way; only their cost differs.
    pub fn set_warm_starts(&mut self, on: bool) {
        self.warm_starts = on;
        if !on {
            self.warm.clear();
        }
    }

    /// Counters of the warm starts (cleared by [`reset_stats`](Self::reset_stats)).
    pub fn warm_stats(&self) -> WarmStats {
        self.warm.stats
    }

    /// Number of polygons.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// True when the scene holds no polygon.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// The handles of all polygons, in slot order.
    pub fn ids(&self) -> impl Iterator<Item = PolygonId> + '_ {
        let scene = self.identity.get();
        self.entries.iter().map(move |(k, e)| PolygonId {
            scene,
            key: k as u32,
            generation: e.generation,
        })
    }

    /// Number of polygons that currently hold an array snapshot.
    pub fn snapshot_count(&self) -> usize {
        self.entries.iter().filter(|(_, e)| e.snapshot.is_some()).count()
    }

    /// Heap memory held by the scene's structures, in bytes: the polygons' arenas (with
    /// each translated polygon's fixed list of translations not yet applied, and the
    /// translated copy a shared read built, while it is kept; see
    /// [`polygon`](Self::polygon)), the snapshots, the slots, the broad phase and the warm starts' pairs (per-query
    /// scratch memory, bounded by the largest polygon queried, is not counted). It is
    /// O(slots + vertices + candidate pairs of the last frame) whatever the sequence of
    /// calls: no structure grows with the number of edits or queries.
    /// Slots are the largest number of polygons the scene has held at once.
    pub fn heap_bytes(&self) -> usize {
        let polygons: usize = self
            .entries
            .iter()
            .map(|(_, e)| {
                e.polygon.arena_bytes()
                    + e.snapshot
                        .as_ref()
                        .map_or(0, |s| std::mem::size_of_val(s.vertices()))
            })
            .sum();
        polygons
            + self.entries.capacity() * std::mem::size_of::<Entry>()
            + self.broad.heap_bytes()
            + self.warm.heap_bytes()
    }

    /// Adds a polygon. O(n) for its bounding box.
    ///
    /// # Panics
    /// Never: a [`LinkedPolygon`] always has vertices.
    pub fn insert(&mut self, polygon: LinkedPolygon) -> PolygonId {
        let bbox = BoundingBox::of(polygon.iter().map(|(_, p)| p)).expect("a polygon has vertices");
        let grid = polygon.iter().fold(f64::INFINITY, |g, (_, p)| g.min(grid_of(p)));
        let generation = self.next_generation;
        self.next_generation += 1;
        let key = self.entries.insert(Entry {
            polygon: LazyLinked::new(polygon),
            generation,
            bbox,
            bbox_tight: true,
            version: 0,
            snapshot: None,
            account: Account::default(),
            rounding_margin: 0.0,
            grid,
            plan: PlanMark::default(),
        });
        self.broad.mark(key);
        PolygonId {
            scene: self.identity.get(),
            key: key as u32,
            generation,
        }
    }

    /// Validates `points` ([`ConvexPolygon::new`]) and adds the polygon.
    ///
    /// # Errors
    /// [`SceneError::Polygon`] when the points are not a valid convex polygon.
    pub fn insert_points<I, P>(&mut self, points: I) -> Result<PolygonId, SceneError>
    where
        I: IntoIterator<Item = P>,
        P: Into<Point>,
    {
        Ok(self.insert(LinkedPolygon::from_points(points)?))
    }

    /// Removes a polygon, returning it (its vertex handles stay valid on it).
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn remove(&mut self, id: PolygonId) -> Result<LinkedPolygon, SceneError> {
        let key = self.key(id)?;
        self.broad.mark(key);
        Ok(self.entries.remove(key).polygon.into_inner())
    }

    #[inline]
    fn key(&self, id: PolygonId) -> Result<usize, SceneError> {
        if id.scene != self.identity.get() {
            return Err(SceneError::ForeignPolygon(id));
        }
        match self.entries.get(id.key as usize) {
            Some(e) if e.generation == id.generation => Ok(id.key as usize),
            _ => Err(SceneError::StalePolygon(id)),
        }
    }

    fn id_of(&self, key: usize) -> PolygonId {
        PolygonId {
            scene: self.identity.get(),
            key: key as u32,
            generation: self.entries[key].generation,
        }
    }

    /// The polygon (read-only; edit through the scene so caches stay correct), with every
    /// translation applied. O(1), except after translations not yet applied: then the
    /// first read builds the translated polygon beside the old arena, O(n), kept (and
    /// taken in place of the old arena) until the scene next changes the polygon.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon` (as every method taking a `PolygonId`).
    pub fn polygon(&self, id: PolygonId) -> Result<&LinkedPolygon, SceneError> {
        self.key(id).map(|k| self.entries[k].polygon.get())
    }

    /// The polygon's bounding box: it always contains the polygon, and is the tightest
    /// box unless an edit since the last conversion may have shrunk the polygon.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn bounding_box(&self, id: PolygonId) -> Result<BoundingBox, SceneError> {
        self.key(id).map(|k| self.entries[k].bbox)
    }

    /// Number of edits the polygon has had.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn version(&self, id: PolygonId) -> Result<u64, SceneError> {
        self.key(id).map(|k| self.entries[k].version)
    }

    /// True while the polygon holds a valid array snapshot.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn has_snapshot(&self, id: PolygonId) -> Result<bool, SceneError> {
        self.key(id).map(|k| self.entries[k].snapshot.is_some())
    }

    /// Inserts a vertex after `after` (see [`LinkedPolygon::insert_after`]). O(1).
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`, or the [`EditError`] of the polygon's own edit
    /// (`StaleHandle`, `ForeignHandle` when `after` is not a vertex handle of polygon
    /// `id`, `NonFinite`, `WouldBreakConvexity`).
    pub fn insert_vertex(
        &mut self,
        id: PolygonId,
        after: VertexId,
        p: Point,
    ) -> Result<VertexId, SceneError> {
        let key = self.key(id)?;
        let e = &mut self.entries[key];
        let v = e
            .polygon
            .get_mut()
            .insert_after(after, p)
            .map_err(|err| SceneError::Edit(id, err))?;
        e.edited(&mut self.stats);
        e.grid = e.grid.min(grid_of(p));
        self.grow_box(key, p);
        Ok(v)
    }

    /// Removes a vertex (see [`LinkedPolygon::remove`]). O(1).
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`, or the polygon's [`EditError`] (`StaleHandle`,
    /// `ForeignHandle`, `TooFewVertices`).
    pub fn remove_vertex(&mut self, id: PolygonId, v: VertexId) -> Result<Point, SceneError> {
        let key = self.key(id)?;
        let e = &mut self.entries[key];
        let old = e
            .polygon
            .get_mut()
            .remove(v)
            .map_err(|err| SceneError::Edit(id, err))?;
        e.edited(&mut self.stats);
        if e.bbox.touches_boundary(old) {
            e.bbox_tight = false;
        }
        Ok(old)
    }

    /// Moves a vertex (see [`LinkedPolygon::move_vertex`]). O(1).
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`, or the polygon's [`EditError`] (`StaleHandle`,
    /// `ForeignHandle`, `NonFinite`, `WouldBreakConvexity`).
    pub fn move_vertex(&mut self, id: PolygonId, v: VertexId, p: Point) -> Result<Point, SceneError> {
        let key = self.key(id)?;
        let e = &mut self.entries[key];
        let old = e
            .polygon
            .get_mut()
            .move_vertex(v, p)
            .map_err(|err| SceneError::Edit(id, err))?;
        e.edited(&mut self.stats);
        e.grid = e.grid.min(grid_of(p));
        if e.bbox.touches_boundary(old) {
            e.bbox_tight = false;
        }
        self.grow_box(key, p);
        Ok(old)
    }

    /// Translates the polygon by `(dx, dy)`: every vertex becomes `(x + dx, y + dy)`, each
    /// coordinate rounded to nearest (IEEE addition). The snapshot, if there is one, is
    /// translated at once in place with the same roundings (one sequential pass: it
    /// stays valid, no reconversion); the linked polygon's translation waits, in a list
    /// of at most eight, until the linked polygon is next read or edited, and is then
    /// applied with the same additions in the same order, so every coordinate is
    /// bit-for-bit the eager one. The bounding box shifts in O(1) (rounding is monotone,
    /// so the shifted box still contains, or equals, the translated polygon's box).
    /// The rounded polygon is checked exactly for strict convexity (O(n), on the
    /// snapshot when there is one), except when no sum can round (the polygon and the
    /// vector on a common power-of-two grid) or a margin kept from the last check proves
    /// that this rounding cannot break it: then the call is O(1) without a snapshot, one
    /// pass over the snapshot with one (docs/store.md, "Translation"). Vertex handles stay
    /// valid.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`; [`EditError::NonFinite`] when `dx` or `dy` is not finite or a
    /// coordinate would overflow; [`EditError::RoundingBreaksConvexity`] when rounding
    /// would leave the polygon not strictly convex. Nothing changes on error.
    ///
    /// # Panics
    /// Never: a polygon always has vertices for its box.
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
        let mut exact = false;
        let shifted = BoundingBox {
            min: Point::new(e.bbox.min.x + dx, e.bbox.min.y + dy),
            max: Point::new(e.bbox.max.x + dx, e.bbox.max.y + dy),
        };
        if shifted.min.is_finite() && shifted.max.is_finite() {
            // The box contains every vertex and rounding is monotone: no translated
            // coordinate overflows, and each moves from the exact translate by at most
            // half an ulp of the largest, `delta`. When no sum can round (the grid
            // below), or below the margin left by the last check, the result is
            // strictly convex without looking at a vertex; otherwise check the rounded
            // boundary (on the snapshot when there is one: a sequential read), which
            // also gives the new margin.
            let largest = [shifted.min.x, shifted.min.y, shifted.max.x, shifted.max.y]
                .into_iter()
                .fold(0.0f64, |m, v| m.max(v.abs()));
            let delta = largest * (f64::EPSILON * 0.5) * (1.0 + f64::EPSILON) + f64::from_bits(1);
            // On the grid: every coordinate and the vector are integer multiples of a
            // power of two `h`, and every sum is at most 2^53·h in magnitude, so every
            // sum is exact. An exact translation preserves every orientation and every
            // turn margin (the same differences): nothing to check, nothing to shrink.
            let h = e.grid.min(grid_of(Point::new(dx, dy)));
            let bound = [e.bbox.min.x, e.bbox.min.y, e.bbox.max.x, e.bbox.max.y, dx, dy]
                .into_iter()
                .fold(0.0f64, |m, v| m.max(v.abs()));
            exact = bound <= h * 2f64.powi(52);
            if exact {
                // The margin stands as it is.
            } else if largest <= 2f64.powi(52) && delta < e.rounding_margin {
                e.rounding_margin =
                    (e.rounding_margin - delta) / (1.0 + 2.0 * delta) * (1.0 - 4.0 * f64::EPSILON);
            } else {
                let margin = match &e.snapshot {
                    Some(s) => LinkedPolygon::check_translated_ring(s.vertices(), dx, dy),
                    None => e.polygon.materialized().check_translation(dx, dy),
                };
                e.rounding_margin = margin.map_err(|err| SceneError::Edit(id, err))?;
            }
            // Accepted: the linked polygon applies it when it is next read.
            e.polygon.translate(dx, dy);
            e.bbox = shifted;
            e.grid = h;
        } else {
            let polygon = e.polygon.get_mut();
            polygon
                .translate(dx, dy)
                .map_err(|err| SceneError::Edit(id, err))?;
            e.rounding_margin = 0.0;
            e.grid = e.grid.min(grid_of(Point::new(dx, dy)));
            // A loose box reaching past the polygon overflowed: take the true box.
            e.bbox = BoundingBox::of(polygon.iter().map(|(_, p)| p)).expect("a polygon has vertices");
            e.bbox_tight = true;
        }
        e.version += 1;
        if let Some(s) = &mut e.snapshot {
            s.translate_unchecked(dx, dy);
        }
        self.broad.mark(key);
        #[cfg(test)]
        {
            self.exact_skips += u64::from(exact);
        }
        #[cfg(not(test))]
        let _ = exact;
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
        let snapshot = self.entries[key].polygon.materialized().to_convex();
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

    /// Plans queries between live keys (`Err` entries are passed through): bounding
    /// boxes, then the strategy; returns the routes and the keys to convert before
    /// answering. O(1) per pair and per polygon involved (per-polygon marks), so a batch
    /// is planned in linear time.
    ///
    /// The planner knows every query of the batch before deciding: a polygon without a
    /// snapshot is charged, per query, what its conversion would save that query (all of
    /// it when the other polygon has or will have a snapshot, half when both lack one),
    /// and is converted when [`Account::should_convert`] says so for the batch's total.
    /// Polygons whose partners were chosen are then offered the other half once more.
    fn plan(&mut self, pairs: impl Iterator<Item = Result<(usize, usize), SceneError>>) -> Plan {
        self.plan_warm(pairs, &mut [])
    }

    /// [`plan`](Self::plan) with the last frame's state of each pair (an empty slice
    /// for none): a pair its warm start decides gets [`Route::Warm`] (or the linear walk)
    /// and is left out of the planner's accounts; each state is left as this frame's
    /// where planning decided it, `None` where the answer will.
    fn plan_warm(
        &mut self,
        pairs: impl Iterator<Item = Result<(usize, usize), SceneError>>,
        warm: &mut [Option<Warm>],
    ) -> Plan {
        let mut routes: Vec<Result<Route, SceneError>> = Vec::with_capacity(pairs.size_hint().0);
        let mut touched = Vec::new();
        let mut keys = Vec::with_capacity(routes.capacity());
        for (i, pair) in pairs.enumerate() {
            keys.push(*pair.as_ref().unwrap_or(&(0, 0)));
            let route = pair.map(|(a, b)| {
                let decided = warm.get_mut(i).and_then(|w| self.warm_route(a, b, w));
                decided.unwrap_or_else(|| self.plan_boxes(a, b, &mut touched))
            });
            routes.push(route);
        }
        let mut chosen = Vec::new();
        match self.strategy {
            Strategy::Sampled | Strategy::Convert => {}
            Strategy::Cached => chosen.extend(touched.iter().copied()),
            Strategy::Planner => {
                self.choose(&touched, &mut chosen);
                if !chosen.is_empty() {
                    // A partner chosen now turns the half savings into whole ones.
                    for k in &chosen {
                        self.entries[*k].plan.convert = true;
                    }
                    for route in routes.iter().flatten() {
                        if let Route::Sampled(a, b) = *route {
                            for (k, other) in [(a, b), (b, a)] {
                                let (ek, eo) = (&self.entries[k], &self.entries[other]);
                                if !ek.will_have_snapshot() && eo.plan.convert && eo.snapshot.is_none() {
                                    let half = 0.5 * self.saving(a, b);
                                    self.entries[k].plan.known_ns += half;
                                }
                            }
                        }
                    }
                    self.choose(&touched, &mut chosen);
                }
            }
        }
        let (mut convert_ns, mut answer_ns) = (0.0, 0.0);
        for k in &chosen {
            self.entries[*k].plan.convert = true;
            convert_ns += self.costs.convert_cost(self.entries[*k].polygon.arena());
        }
        for route in routes.iter_mut().flatten() {
            if let Route::Sampled(a, b) = *route {
                let (r, cost) = self.finish_route(a, b);
                *route = r;
                answer_ns += cost;
            }
        }
        for k in touched {
            self.entries[k].plan = PlanMark::default();
        }
        Plan {
            routes,
            keys,
            chosen,
            convert_ns,
            answer_ns,
        }
    }

    /// The warm start of pair (a, b), whose last-frame state is `w`: the route when it
    /// decides the pair, with `w` set to this frame's state; `None` (and `w` cleared)
    /// when the planner must. A kept certificate is checked (O(1) plus the climb); a pair
    /// separated without one is walked linearly, which answers it and finds one.
    fn warm_route(&mut self, a: usize, b: usize, w: &mut Option<Warm>) -> Option<Route> {
        let state = w.take()?;
        if matches!(state, Warm::Intersecting) {
            return None;
        }
        self.entries[a].polygon.materialized();
        self.entries[b].polygon.materialized();
        let (p, q) = (self.entries[a].polygon.get(), self.entries[b].polygon.get());
        let found = match state {
            Warm::Intersecting => return None,
            Warm::Certified { of, from, deep } => {
                let kept = warm::check(self.kernel, p, q, of, from, deep);
                let counter = match kept {
                    Some(_) => &mut self.warm.stats.hits,
                    None => &mut self.warm.stats.misses,
                };
                *counter += 1;
                kept?
            }
            Warm::Separated => {
                self.warm.stats.fills += 1;
                let Some(found) = warm::fill(self.kernel, p, q) else {
                    // They met since: the answer is `true`, proved by the (certified)
                    // linear walk again, only on this frame.
                    *w = Some(Warm::Intersecting);
                    return Some(Route::Linear(a, b));
                };
                found
            }
        };
        *w = Some(found.warm);
        Some(Route::Warm {
            of: found.of,
            from: found.from,
            to: found.to,
        })
    }

    /// The box test; a live pair is left as `Sampled` for now, its polygons marked and
    /// credited with the saving a snapshot would bring.
    fn plan_boxes(&mut self, a: usize, b: usize, touched: &mut Vec<usize>) -> Route {
        if a == b {
            return Route::Known(true);
        }
        if !self.entries[a].bbox.overlaps(&self.entries[b].bbox) {
            self.stats.box_rejects += 1;
            return Route::Known(false);
        }
        let saving = self.saving(a, b);
        for (k, other) in [(a, b), (b, a)] {
            let has_other = self.entries[other].snapshot.is_some();
            let e = &mut self.entries[k];
            e.account.queried();
            if e.snapshot.is_none() {
                if !e.plan.touched {
                    e.plan.touched = true;
                    touched.push(k);
                }
                e.plan.known_ns += if has_other { saving } else { 0.5 * saving };
                e.plan.known += 1;
            }
        }
        Route::Sampled(a, b)
    }

    /// Appends to `chosen` the touched polygons, not yet chosen, that the planner
    /// converts.
    fn choose(&self, touched: &[usize], chosen: &mut Vec<usize>) {
        for &k in touched {
            let e = &self.entries[k];
            let cost = self.costs.convert_cost(e.polygon.arena());
            if !e.plan.convert && e.account.should_convert(cost, e.plan.known_ns, e.plan.known) {
                chosen.push(k);
            }
        }
    }

    /// What snapshots of both polygons would save one query between them.
    fn saving(&self, a: usize, b: usize) -> f64 {
        self.costs
            .saving(self.entries[a].polygon.arena(), self.entries[b].polygon.arena())
    }

    /// The route of a live pair once conversions are chosen, and its estimated cost;
    /// unconverted polygons pay their rent.
    fn finish_route(&mut self, a: usize, b: usize) -> (Route, f64) {
        let (pa, pb) = (self.entries[a].polygon.arena(), self.entries[b].polygon.arena());
        let (na, nb) = (pa.vertices, pb.vertices);
        let (ha, hb) = (
            self.entries[a].will_have_snapshot(),
            self.entries[b].will_have_snapshot(),
        );
        let linear_arrays = self.costs.array_is_linear(na, nb);
        if ha && hb {
            self.stats.array_tests += 1;
            return (Route::Arrays(a, b, linear_arrays), self.costs.array_cost(na, nb));
        }
        if self.strategy == Strategy::Convert {
            self.stats.throwaway_conversions += 2;
            let cost =
                self.costs.convert_cost(pa) + self.costs.convert_cost(pb) + self.costs.array_cost(na, nb);
            return (Route::Throwaway(a, b, linear_arrays), cost);
        }
        let saving = self.costs.saving(pa, pb);
        for (k, has_other) in [(a, hb), (b, ha)] {
            if !self.entries[k].will_have_snapshot() {
                self.entries[k]
                    .account
                    .pay(if has_other { saving } else { 0.5 * saving });
            }
        }
        if self.strategy == Strategy::Planner && self.costs.prefers_linear(pa, pb) {
            self.stats.linear_tests += 1;
            return (Route::Linear(a, b), self.costs.linear_cost(pa, pb));
        }
        self.stats.sampled_tests += 1;
        (Route::Sampled(a, b), self.costs.sampled_cost(pa, pb))
    }

    /// Answers one planned route; `seed` seeds the sampled test's generator (per pair, so
    /// answers and times never depend on the order or the thread).
    fn answer(&self, route: Route, ws: &mut QueryWorkspace, seed: u64) -> bool {
        let e = |k: usize| &self.entries[k];
        let snapshot = |k: usize| e(k).snapshot.as_ref().expect("planned snapshot");
        match route {
            Route::Known(v) => v,
            Route::Warm { .. } => false,
            Route::Arrays(a, b, linear) => array_test(self.kernel, snapshot(a), snapshot(b), linear),
            Route::Linear(a, b) => linear_test(self.kernel, e(a).polygon.get(), e(b).polygon.get()),
            Route::Sampled(a, b) => {
                let mut rng = SmallRng::seed_from_u64(seed);
                sampled_test(self.kernel, e(a).polygon.get(), e(b).polygon.get(), ws, &mut rng)
            }
            Route::Throwaway(a, b, linear) => array_test(
                self.kernel,
                &e(a).polygon.get().to_convex(),
                &e(b).polygon.get().to_convex(),
                linear,
            ),
        }
    }

    /// The certificate of a planned query between keys `a` and `b` (the query's P and
    /// Q): the certified call of the route's test, with the scene's kernel. A pair
    /// rejected by its bounding boxes is known to be disjoint exactly, so its separating
    /// edge is searched with the exact kernel (the array test when both snapshots are
    /// valid, else the sampled test); a polygon against itself is proved by its first
    /// vertex.
    fn answer_certified(
        &self,
        route: Route,
        (a, b): (usize, usize),
        ws: &mut QueryWorkspace,
        seed: u64,
    ) -> Certificate {
        let e = |k: usize| &self.entries[k];
        let snapshot = |k: usize| e(k).snapshot.as_ref().expect("planned snapshot");
        match route {
            Route::Known(true) => {
                let point = e(a).polygon.get().point_at(0);
                Certificate::VertexInside { of: Which::P, point }
            }
            Route::Known(false) => match (&e(a).snapshot, &e(b).snapshot) {
                (Some(p), Some(q)) => array_certified(Exact, p, q, false),
                _ => {
                    let mut rng = SmallRng::seed_from_u64(seed);
                    sampled_certified(Exact, e(a).polygon.get(), e(b).polygon.get(), ws, &mut rng)
                }
            },
            Route::Warm { of, from, to } => Certificate::Separated { of, from, to },
            Route::Arrays(a, b, linear) => array_certified(self.kernel, snapshot(a), snapshot(b), linear),
            Route::Linear(a, b) => linear_certified(self.kernel, e(a).polygon.get(), e(b).polygon.get()),
            Route::Sampled(a, b) => {
                let mut rng = SmallRng::seed_from_u64(seed);
                sampled_certified(self.kernel, e(a).polygon.get(), e(b).polygon.get(), ws, &mut rng)
            }
            Route::Throwaway(a, b, linear) => array_certified(
                self.kernel,
                &e(a).polygon.get().to_convex(),
                &e(b).polygon.get().to_convex(),
                linear,
            ),
        }
    }

    /// Whether polygons `a` and `b` intersect (closed sets: touching counts).
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon` for either handle.
    pub fn intersects(&mut self, a: PolygonId, b: PolygonId) -> Result<bool, SceneError> {
        self.query(a, b, |s, route, _, ws, seed| s.answer(route, ws, seed))
    }

    /// [`intersects`](Self::intersects) with a [`Certificate`] of the answer (`a` is the
    /// certificate's P, `b` its Q; the answer is [`Certificate::intersects`]), planned
    /// exactly as `intersects` plans: the same strategy, conversions and counters, and
    /// the certified call of the test the plan chose. The certificate names vertices of
    /// the polygons as they are now; [`verify_linked`](crate::intersect::verify_linked)
    /// checks it exactly.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon` for either handle.
    ///
    /// # Precision
    /// Under the exact kernel the certificate always verifies; under the fast kernel it
    /// may not, exactly when the fast answer may be wrong (docs/certificates.md).
    ///
    /// ```
    /// use polysect::store::Scene;
    /// use polysect::intersect::verify_linked;
    /// let mut scene = Scene::new();
    /// let a = scene.insert_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// let b = scene.insert_points([[2.0, 1.0], [4.0, 0.0], [4.0, 3.0]])?;
    /// let c = scene.intersects_certified(a, b)?;
    /// assert!(c.intersects()); // (2, 1) lies on a's edge
    /// assert_eq!(verify_linked(scene.polygon(a)?, scene.polygon(b)?, &c), Ok(()));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn intersects_certified(&mut self, a: PolygonId, b: PolygonId) -> Result<Certificate, SceneError> {
        self.query(a, b, |s, route, keys, ws, seed| {
            s.answer_certified(route, keys, ws, seed)
        })
    }

    /// Plans one query, builds the conversions it chose and answers it with `answer`.
    fn query<T>(
        &mut self,
        a: PolygonId,
        b: PolygonId,
        answer: impl FnOnce(&Self, Route, (usize, usize), &mut QueryWorkspace, u64) -> T,
    ) -> Result<T, SceneError> {
        let (ka, kb) = (self.key(a)?, self.key(b)?);
        let mut plan = self.plan(std::iter::once(Ok((ka, kb))));
        for k in plan.chosen {
            self.convert(k);
        }
        let route = plan.routes.pop().expect("one route")?;
        let mut ws = std::mem::take(&mut self.workspace);
        let seed = self.rng.next_u64();
        let answer = answer(self, route, (ka, kb), &mut ws, seed);
        self.workspace = ws;
        Ok(answer)
    }

    /// Answers many queries: planned together (the planner sees the whole batch before
    /// choosing conversions), then conversions built and pairs answered, each in
    /// parallel (with the `parallel` feature) when there are several and their estimated
    /// cost (at least 1 ms) pays for handing work to other threads. Results are in input order and do not depend on the number of threads.
    /// A pair with a stale or foreign handle gets that error in its place; the other
    /// pairs are answered.
    pub fn intersects_batch(&mut self, pairs: &[(PolygonId, PolygonId)]) -> Vec<Result<bool, SceneError>> {
        let plan = self.plan_pairs(pairs);
        self.run_plan(plan)
    }

    /// [`intersects_batch`](Self::intersects_batch) with certificates, as
    /// [`intersects_certified`](Self::intersects_certified) gives them (in each pair, the
    /// first polygon is the certificate's P).
    pub fn intersects_batch_certified(
        &mut self,
        pairs: &[(PolygonId, PolygonId)],
    ) -> Vec<Result<Certificate, SceneError>> {
        let plan = self.plan_pairs(pairs);
        self.run_plan_certified(plan)
    }

    /// Plans a batch given by handles; a stale or foreign handle plans as its error.
    fn plan_pairs(&mut self, pairs: &[(PolygonId, PolygonId)]) -> Plan {
        let keys = pairs.iter().map(|&(a, b)| Ok((self.key(a)?, self.key(b)?)));
        let keys: Vec<Result<(usize, usize), SceneError>> = keys.collect();
        self.plan(keys.into_iter())
    }

    fn run_plan(&mut self, plan: Plan) -> Vec<Result<bool, SceneError>> {
        self.run_plan_with(plan, |s, route, _, ws, seed| s.answer(route, ws, seed))
    }

    fn run_plan_certified(&mut self, plan: Plan) -> Vec<Result<Certificate, SceneError>> {
        self.run_plan_with(plan, |s, route, keys, ws, seed| {
            s.answer_certified(route, keys, ws, seed)
        })
    }

    /// Converts the chosen polygons and answers the routes; the sampled test of route `i`
    /// is seeded from one draw of the scene's generator and `i`, so answers do not
    /// depend on the number of threads.
    #[cfg_attr(not(feature = "parallel"), allow(unused_variables))]
    fn run_plan_with<T: Send>(
        &mut self,
        plan: Plan,
        answer: impl Fn(&Self, Route, (usize, usize), &mut QueryWorkspace, u64) -> T + Sync,
    ) -> Vec<Result<T, SceneError>> {
        let base: u64 = self.rng.next_u64();
        // Without the `parallel` feature everything runs on the calling thread.
        #[cfg(feature = "parallel")]
        let threads = rayon::current_num_threads() > 1;
        #[cfg(not(feature = "parallel"))]
        let threads = false;
        let parallel_convert = threads && plan.chosen.len() > 1 && plan.convert_ns >= PARALLEL_MIN_NS;
        let parallel = threads && plan.routes.len() > 64 && plan.answer_ns >= PARALLEL_MIN_NS;
        self.convert_all(plan.chosen, parallel_convert);
        let mut ws = std::mem::take(&mut self.workspace);
        let this = &*self;
        let keys = &plan.keys;
        let answer = |ws: &mut QueryWorkspace, (i, route): (usize, &Result<Route, SceneError>)| {
            let route = route.clone()?;
            let seed = base ^ (i as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15);
            Ok(answer(this, route, keys[i], ws, seed))
        };
        let answers = match () {
            #[cfg(feature = "parallel")]
            () if parallel => plan
                .routes
                .par_iter()
                .enumerate()
                .with_min_len(64)
                .map_init(QueryWorkspace::default, answer)
                .collect(),
            () => plan
                .routes
                .iter()
                .enumerate()
                .map(|r| answer(&mut ws, r))
                .collect(),
        };
        self.workspace = ws;
        answers
    }

    #[cfg_attr(not(feature = "parallel"), allow(unused_variables))]
    fn convert_all(&mut self, mut keys: Vec<usize>, parallel: bool) {
        keys.sort_unstable();
        keys.dedup();
        for &k in &keys {
            self.entries[k].polygon.materialized();
        }
        let convert = |&k: &usize| (k, self.entries[k].polygon.get().to_convex());
        let snapshots: Vec<(usize, ConvexPolygon)> = match () {
            #[cfg(feature = "parallel")]
            () if parallel => keys.par_iter().with_min_len(16).map(convert).collect(),
            () => keys.iter().map(convert).collect(),
        };
        for (k, s) in snapshots {
            self.install_snapshot(k, s);
        }
    }

    fn flush_broad_phase(&mut self) {
        let entries = &self.entries;
        self.broad.flush(|k| entries.get(k).map(|e| e.bbox));
    }

    /// All polygons other than `a` that intersect it, in slot order.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn intersecting(&mut self, a: PolygonId) -> Result<Vec<PolygonId>, SceneError> {
        let ka = self.key(a)?;
        self.flush_broad_phase();
        let mut candidates: Vec<usize> = self
            .broad
            .overlapping(&self.entries[ka].bbox)
            .filter(|&k| k != ka)
            .collect();
        candidates.sort_unstable();
        let plan = self.plan(candidates.iter().map(|&k| Ok((ka, k))));
        let answers = self.run_plan(plan);
        Ok(candidates
            .into_iter()
            .zip(answers)
            .filter(|(_, hit)| matches!(hit, Ok(true)))
            .map(|(k, _)| self.id_of(k))
            .collect())
    }

    /// All intersecting pairs `(a, b)` with `a` before `b` in slot order, sorted.
    ///
    /// With warm starts ([`set_warm_starts`](Self::set_warm_starts), off by default), a
    /// pair found separated by the last call is first checked against the separating
    /// edge found then; the answer is the same, only its cost differs.
    pub fn intersecting_pairs(&mut self) -> Vec<(PolygonId, PolygonId)> {
        let (candidates, plan, warm) = self.plan_frame();
        let answers = self.run_plan(plan);
        self.keep_frame(
            &candidates,
            warm,
            answers.iter().map(|hit| matches!(hit, Ok(true))),
        );
        candidates
            .into_iter()
            .zip(answers)
            .filter(|(_, hit)| matches!(hit, Ok(true)))
            .map(|((a, b), _)| (self.id_of(a), self.id_of(b)))
            .collect()
    }

    /// The candidate pairs of a frame, their plan, and (with warm starts) each pair's
    /// state as far as planning decided it.
    fn plan_frame(&mut self) -> (Vec<(usize, usize)>, Plan, Vec<Option<Warm>>) {
        self.flush_broad_phase();
        let candidates = self.broad.overlapping_pairs();
        let mut warm = if self.warm_starts {
            let entries = &self.entries;
            self.warm.take(&candidates, |k| entries[k].generation)
        } else {
            Vec::new()
        };
        let plan = self.plan_warm(candidates.iter().map(|&pair| Ok(pair)), &mut warm);
        (candidates, plan, warm)
    }

    /// Keeps this frame's state of every candidate pair: what planning decided, else
    /// what the answer was.
    fn keep_frame(
        &mut self,
        candidates: &[(usize, usize)],
        warm: Vec<Option<Warm>>,
        hits: impl Iterator<Item = bool>,
    ) {
        if !self.warm_starts {
            return;
        }
        let states = warm
            .into_iter()
            .zip(hits)
            .map(|(w, hit)| w.unwrap_or(if hit { Warm::Intersecting } else { Warm::Separated }));
        let entries = &self.entries;
        self.warm.keep(candidates, states, |k| entries[k].generation);
    }

    /// [`intersecting_pairs`](Self::intersecting_pairs), each with the certificate of
    /// its intersection (`a` is the certificate's P). Pairs the broad phase rejects get
    /// none: they are not in the answer.
    pub fn intersecting_pairs_certified(&mut self) -> Vec<(PolygonId, PolygonId, Certificate)> {
        self.candidate_pairs_certified()
            .into_iter()
            .filter_map(|(a, b, c)| Some((a, b, c.ok().filter(Certificate::intersects)?)))
            .collect()
    }

    /// Every candidate pair (boxes overlap) with the certificate of its answer, in one
    /// planned pass: an intersection witness, or for a pair found disjoint its separating
    /// edge (`a` is the certificate's P). What a caller needs that keeps separating
    /// edges for later contacts without asking the disjoint pairs a second time.
    pub fn candidate_pairs_certified(
        &mut self,
    ) -> Vec<(PolygonId, PolygonId, Result<Certificate, SceneError>)> {
        let (candidates, plan, warm) = self.plan_frame();
        let answers = self.run_plan_certified(plan);
        let hits = answers.iter().map(|c| matches!(c, Ok(c) if c.intersects()));
        self.keep_frame(&candidates, warm, hits);
        candidates
            .into_iter()
            .zip(answers)
            .map(|((a, b), c)| (self.id_of(a), self.id_of(b), c))
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
    ///
    /// # Errors
    /// The first invariant found broken, with the polygon's slot.
    ///
    /// # Panics
    /// Never: a polygon always has vertices for its box.
    pub fn debug_validate(&self) -> Result<(), String> {
        for (k, e) in &self.entries {
            let polygon = e.polygon.get();
            polygon
                .debug_validate()
                .map_err(|m| format!("polygon {k}: {m}"))?;
            let exact = BoundingBox::of(polygon.iter().map(|(_, p)| p)).expect("vertices");
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
                let mut now = polygon.to_convex().into_vertices();
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

/// The largest power of two of which both coordinates of `p` are integer multiples
/// (+∞ for the origin; `p` finite). After a translation by a vector on grid `h` of a
/// polygon on grid `h`, every coordinate is still on grid `h`, rounded or not: a sum of
/// magnitude at most 2^53·h is exact, and every float of larger magnitude is a multiple
/// of 2h. So the grid of a polygon is the least of its vertices' and of the vectors
/// it was translated by.
fn grid_of(p: Point) -> f64 {
    let one = |x: f64| {
        if x == 0.0 {
            return f64::INFINITY;
        }
        let bits = x.to_bits() & !(1u64 << 63);
        let (exponent, fraction) = ((bits >> 52) as i32, bits & ((1u64 << 52) - 1));
        // x = m · 2^e with m an integer.
        let (m, e) = if exponent == 0 {
            (fraction, -1074)
        } else {
            (fraction | (1u64 << 52), exponent - 1075)
        };
        let k = e + m.trailing_zeros() as i32;
        if k >= -1022 {
            f64::from_bits(((k + 1023) as u64) << 52)
        } else {
            f64::from_bits(1u64 << (k + 1074))
        }
    };
    one(p.x).min(one(p.y))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generate::regular_polygon;
    use rand::Rng;

    /// The scene skips the convexity check of a translation when the margin kept from
    /// the last check proves rounding harmless. Against a copy translated with the full
    /// check every time, on polygons whose vertices are a few ulps apart (where rounding
    /// does break convexity) and on ordinary ones: the same acceptances, the same
    /// refusals, the same coordinates, and skips actually taken.
    fn snapped(points: &[Point], bits: i32) -> Vec<Point> {
        let g = 2f64.powi(-bits);
        let snap = |x: f64| (x / g).round() * g;
        let pts: Vec<Point> = points.iter().map(|p| Point::new(snap(p.x), snap(p.y))).collect();
        crate::polygon::convex_hull(&pts).unwrap().into_vertices()
    }

    /// `grid_of` is the largest power of two dividing both coordinates.
    #[test]
    fn grid_of_is_the_largest_dividing_power_of_two() {
        let mut rng = SmallRng::seed_from_u64(0x9e1d);
        assert_eq!(grid_of(Point::new(0.0, 0.0)), f64::INFINITY);
        assert_eq!(grid_of(Point::new(3.0, 0.0)), 1.0);
        assert_eq!(grid_of(Point::new(0.75, -6.0)), 0.25);
        assert_eq!(grid_of(Point::new(f64::from_bits(1), 1.0)), f64::from_bits(1));
        assert_eq!(grid_of(Point::new(f64::MAX, 0.0)), 2f64.powi(971));
        assert_eq!(grid_of(Point::new(f64::MIN_POSITIVE, 0.0)), f64::MIN_POSITIVE);
        for _ in 0..10_000 {
            let x = f64::from_bits(rng.random::<u64>() >> 1) * if rng.random_bool(0.5) { 1.0 } else { -1.0 };
            if !x.is_finite() || x == 0.0 {
                continue;
            }
            let g = grid_of(Point::new(x, 0.0));
            assert!(
                g.is_finite() && g > 0.0 && g.to_bits() & ((1u64 << 52) - 1) == 0 || g < f64::MIN_POSITIVE
            );
            // x / g is an odd integer (exact: dividing by a power of two, no underflow
            // below g itself).
            let q = x / g;
            assert_eq!(q, q.trunc(), "{x:e}");
            assert_eq!(q.abs() % 2.0, 1.0, "{x:e}");
        }
    }

    #[test]
    fn skipped_translation_checks_agree_with_full_checks() {
        let mut rng = SmallRng::seed_from_u64(0x7a11);
        let shapes: Vec<Vec<Point>> = vec![
            // A triangle a few ulps wide near 2^20.
            vec![
                Point::new(1048576.0, 1048576.0),
                Point::new(1048576.0 + 4.0 * 2.3283064365386963e-10, 1048576.0),
                Point::new(1048576.0, 1048576.0 + 3.0 * 2.3283064365386963e-10),
            ],
            // Nearly flat turns: the hull of a fine regular polygon far from the origin.
            crate::polygon::convex_hull(
                &regular_polygon(4096, 1e-3)
                    .vertices()
                    .iter()
                    .map(|p| Point::new(p.x + 1e8, p.y - 3e7))
                    .collect::<Vec<_>>(),
            )
            .unwrap()
            .into_vertices(),
            regular_polygon(16, 1.0).into_vertices(),
            regular_polygon(256, 5.0).into_vertices(),
            // On a grid of 2^-20 (dyadic translations are then often exact).
            snapped(regular_polygon(64, 3.0).vertices(), 20),
            snapped(regular_polygon(1024, 0.5).vertices(), 30),
        ];
        let mut skipped = 0;
        let mut refused = 0;
        let mut exact_skips = 0;
        for (s, shape) in shapes.iter().enumerate() {
            let mut scene = Scene::new();
            let id = scene.insert_points(shape.iter().copied()).unwrap();
            let mut copy = scene.polygon(id).unwrap().clone();
            // Half the runs with a snapshot (checked on the array), half without.
            if s % 2 == 0 {
                scene.set_strategy(Strategy::Cached);
                let other = scene.insert_points(shape.iter().copied()).unwrap();
                scene.intersects(id, other).unwrap();
                assert!(scene.has_snapshot(id).unwrap());
            }
            for step in 0..3000 {
                let scale = [1e-12, 1e-6, 1.0, 1e3, 1e7][rng.random_range(0..5)];
                // The grid shapes keep to dyadic vectors (one other would lose the grid).
                let (dx, dy) = if s < 4 && rng.random_bool(0.5) {
                    (rng.random_range(-scale..scale), rng.random_range(-scale..scale))
                } else {
                    // Dyadic: k · 2^-j, exact or rounding depending on j and the size.
                    let j = match s {
                        4 => rng.random_range(10..=20),
                        5 => rng.random_range(20..=30),
                        _ => rng.random_range(-10..60),
                    };
                    let mut d = || rng.random_range(-(1i64 << 20)..(1i64 << 20)) as f64 * 2f64.powi(-j);
                    (d(), d())
                };
                let key = scene.key(id).unwrap();
                let margin_before = scene.entries[key].rounding_margin;
                let got = scene.translate(id, dx, dy);
                let want = copy.translate(dx, dy);
                assert_eq!(
                    got,
                    want.clone().map_err(|e| SceneError::Edit(id, e)),
                    "shape {s} step {step}"
                );
                if want.is_err() {
                    refused += 1;
                } else if margin_before > 0.0 && scene.entries[key].rounding_margin < margin_before {
                    skipped += 1;
                }
                let ours: Vec<Point> = scene.polygon(id).unwrap().iter().map(|(_, p)| p).collect();
                let theirs: Vec<Point> = copy.iter().map(|(_, p)| p).collect();
                assert_eq!(ours, theirs, "shape {s} step {step}");
                if step % 500 == 0 {
                    scene.debug_validate().unwrap();
                }
            }
            scene.debug_validate().unwrap();
            exact_skips += scene.exact_skips;
        }
        assert!(skipped > 1000, "{skipped} checks skipped");
        assert!(
            exact_skips > 500,
            "{exact_skips} translations proved exact by the grid"
        );
        assert!(refused > 10, "{refused} translations refused");
    }

    /// Translations of a polygon wait (up to the list's length) while only its snapshot
    /// is read, and every reader of the linked polygon sees them applied: shared reads
    /// through a twin, edits and conversions in place; the coordinates are eager
    /// translation's, bit for bit.
    #[test]
    fn translations_wait_until_the_linked_polygon_is_read() {
        use super::super::lazy::MAX_PENDING;
        let mut scene = Scene::new();
        scene.set_strategy(Strategy::Cached);
        let a = scene.insert(LinkedPolygon::from_convex(&regular_polygon(64, 1.0)));
        let b = scene.insert(LinkedPolygon::from_convex(&regular_polygon(32, 0.5)));
        let mut eager = scene.polygon(a).unwrap().clone();
        assert!(scene.intersects(a, b).unwrap());
        assert!(scene.has_snapshot(a).unwrap());
        let key = scene.key(a).unwrap();
        let pending = |s: &Scene| s.entries[key].polygon.pending();
        let coords = |p: &LinkedPolygon| -> Vec<(u64, u64)> {
            p.iter().map(|(_, q)| (q.x.to_bits(), q.y.to_bits())).collect()
        };
        let mut max_seen = 0;
        for step in 0..3 * MAX_PENDING + 1 {
            let (dx, dy) = (0.01 + step as f64 * 1e-4, -0.007);
            scene.translate(a, dx, dy).unwrap();
            eager.translate(dx, dy).unwrap();
            max_seen = max_seen.max(pending(&scene));
            // Only the snapshot is read by the array test.
            scene.intersects(a, b).unwrap();
            assert_eq!(scene.stats().array_tests as usize, step + 2);
        }
        assert_eq!(
            max_seen, MAX_PENDING,
            "translations wait, and no more than the list holds"
        );
        assert!(pending(&scene) > 0);
        // A shared read: the twin, with handles valid on the polygon.
        let first = scene.polygon(a).unwrap().first();
        assert_eq!(coords(scene.polygon(a).unwrap()), coords(&eager));
        assert!(pending(&scene) > 0);
        // An edit: applied in place first (the old point is the translated one).
        let p = scene.polygon(a).unwrap().point(first).unwrap();
        assert_eq!(
            scene.move_vertex(a, first, p).unwrap(),
            eager.point(eager.first()).unwrap()
        );
        assert_eq!(pending(&scene), 0);
        assert_eq!(coords(scene.polygon(a).unwrap()), coords(&eager));
        // A translation without a snapshot waits too; a conversion applies it.
        assert!(!scene.has_snapshot(a).unwrap());
        scene.translate(a, 0.25, 0.5).unwrap();
        eager.translate(0.25, 0.5).unwrap();
        assert_eq!(pending(&scene), 1);
        scene.convert(key);
        assert_eq!(pending(&scene), 0);
        assert_eq!(coords(scene.polygon(a).unwrap()), coords(&eager));
        scene.debug_validate().unwrap();
        // Removal returns the translated polygon.
        scene.translate(a, -3.0, 1.0 / 3.0).unwrap();
        eager.translate(-3.0, 1.0 / 3.0).unwrap();
        assert_eq!(coords(&scene.remove(a).unwrap()), coords(&eager));
    }
}
