//! [`Scene`]: the store of editable polygons: handles, errors, the per-polygon entries
//! and the edits. Planning is in `planner.rs`, answering in `query.rs`, both more
//! methods of [`Scene`].

use super::broad::BroadPhase;
use super::cost::{Account, CostModel, PlannerStats, Strategy};
use super::lazy::LazyLinked;
use super::route::{ArrayRef, QueryWorkspace};
use super::warm::{WarmCache, WarmStats};
use crate::kernel::BoundingBox;
use crate::kernel::{Exact, Kernel, Point, PoseError};
use crate::polygon::{
    ConvexPolygon, EditError, Identity, LinkedPolygon, PolygonError, PosedVertices, VertexId,
};
use pose::Posed;
use rand::SeedableRng;
use rand::rngs::SmallRng;
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
    /// A pose of this polygon (set, moved by a translation, or kept through a vertex
    /// edit) was refused: the image overflows or is not strictly convex once rounded.
    Pose(PolygonId, PoseError),
}

impl SceneError {
    /// The polygon the error is about, when there is one (none for an invalid polygon
    /// that was never inserted).
    pub fn polygon(&self) -> Option<PolygonId> {
        match self {
            SceneError::StalePolygon(id)
            | SceneError::ForeignPolygon(id)
            | SceneError::Edit(id, _)
            | SceneError::Pose(id, _) => Some(*id),
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
            SceneError::Pose(id, e) => write!(f, "polygon {id}: {e}"),
        }
    }
}

impl std::error::Error for SceneError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            SceneError::StalePolygon(_) | SceneError::ForeignPolygon(_) => None,
            SceneError::Edit(_, e) => Some(e),
            SceneError::Polygon(e) => Some(e),
            SceneError::Pose(_, e) => Some(e),
        }
    }
}

impl From<PolygonError> for SceneError {
    fn from(e: PolygonError) -> Self {
        SceneError::Polygon(e)
    }
}

#[derive(Clone, Debug)]
pub(super) struct Entry {
    /// The linked polygon; translations may wait in it until it is read (`lazy.rs`).
    pub(super) polygon: LazyLinked,
    pub(super) generation: u64,
    pub(super) bbox: BoundingBox,
    /// False after an edit that may have shrunk the true box; the stored box still
    /// contains the polygon.
    pub(super) bbox_tight: bool,
    /// Bumped at every edit.
    pub(super) version: u64,
    /// The array form, present only while the polygon is unchanged since it was built.
    pub(super) snapshot: Option<ConvexPolygon>,
    /// What answering without a snapshot has cost this polygon's queries since its last
    /// edit (the planner converts once that reaches the conversion's cost).
    pub(super) account: Account,
    /// A translation whose rounding moves no coordinate by this much or more keeps the
    /// polygon strictly convex (0: unknown); see `Scene::translate`.
    pub(super) rounding_margin: f64,
    /// A power of two of which every coordinate is an integer multiple (`grid_of`);
    /// translations on this grid that cannot round are proved exact in O(1).
    pub(super) grid: f64,
    /// Scratch of the plan being made: chosen for conversion, and what a snapshot would
    /// save the planned queries (and how many) that involve this polygon.
    pub(super) plan: PlanMark,
    /// The shape and the pose of a posed polygon (`polygon` is then its world image).
    pub(super) posed: Option<Box<Posed>>,
    /// The caller's value for this polygon (`user.rs`); nothing in the scene reads it.
    pub(super) user_data: u128,
}

/// Per-polygon marks of one plan, so that planning a batch is O(1) per pair; every
/// field is back at its default when a plan ends.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct PlanMark {
    pub(super) convert: bool,
    pub(super) touched: bool,
    pub(super) known_ns: f64,
    pub(super) known: u32,
}

impl Entry {
    pub(super) fn edited(&mut self, stats: &mut PlannerStats) {
        self.version += 1;
        self.account.edited();
        self.rounding_margin = 0.0;
        if self.snapshot.take().is_some() {
            stats.invalidations += 1;
        }
    }

    /// Has a snapshot, or a posed polygon's owed one (built when the planner next
    /// meets it): what a caller sees as holding one.
    pub(super) fn holds_snapshot(&self) -> bool {
        self.snapshot.is_some() || self.posed.as_ref().is_some_and(|p| p.snapshot_due)
    }

    /// What the array test reads: the snapshot, or (a posed polygon whose lazy pose
    /// left its snapshot owed, large enough that reading vertices through the pose beats
    /// building the array) the world vertices through the pose. `None` without either.
    #[inline]
    pub(super) fn array(&self) -> Option<ArrayRef<'_>> {
        if let Some(s) = &self.snapshot {
            return Some(ArrayRef::Stored(s));
        }
        let posed = self.posed.as_deref().filter(|p| p.reads_through_pose())?;
        // The owed snapshot is the image of `array` under `pose`, every image finite and
        // the rounded image strictly convex (the lazy pose proved it); `bbox` is its box.
        let view = PosedVertices::new_unchecked(posed.array.vertices(), posed.pose);
        Some(ArrayRef::Posed(view, self.bbox))
    }

    /// Whether [`array`](Self::array) is `Some`.
    #[inline]
    pub(super) fn has_array(&self) -> bool {
        self.snapshot.is_some() || self.posed.as_deref().is_some_and(|p| p.reads_through_pose())
    }

    /// Has an array (a snapshot or a posed view), or will have one before the plan is
    /// answered.
    pub(super) fn will_have_snapshot(&self) -> bool {
        self.has_array() || self.plan.convert
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
    pub(super) identity: Identity,
    pub(super) kernel: K,
    pub(super) entries: Slab<Entry>,
    pub(super) next_generation: u64,
    pub(super) broad: BroadPhase,
    pub(super) strategy: Strategy,
    pub(super) costs: CostModel,
    pub(super) stats: PlannerStats,
    pub(super) workspace: QueryWorkspace,
    pub(super) rng: SmallRng,
    /// Warm starts across frames: on/off, and the last frame's pairs.
    pub(super) warm_starts: bool,
    pub(super) warm: WarmCache,
    /// Translations proved exact by the grid (tests only).
    #[cfg(test)]
    pub(super) exact_skips: u64,
    /// Poses set without building the image (tests only).
    #[cfg(test)]
    pub(super) lazy_poses: u64,
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
            rng: crate::seeding::fresh_rng(),
            warm_starts: false,
            warm: WarmCache::default(),
            #[cfg(test)]
            exact_skips: 0,
            #[cfg(test)]
            lazy_poses: 0,
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

    instrument_pub! {
        /// Counters of the warm starts (cleared by [`reset_stats`](Self::reset_stats)).
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn warm_stats(&self) -> WarmStats {
            self.warm.stats
        }
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

    instrument_pub! {
        /// Number of polygons that currently hold an array snapshot.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn snapshot_count(&self) -> usize {
            self.entries.iter().filter(|(_, e)| e.holds_snapshot()).count()
        }
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
                    + e.posed.as_ref().map_or(0, |p| {
                        p.shape.arena_bytes() + std::mem::size_of_val(p.array.vertices())
                    })
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
            posed: None,
            user_data: 0,
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

    /// Removes a polygon, returning it as [`polygon`](Self::polygon) shows it (for a
    /// posed polygon, its world polygon; its vertex handles stay valid on it).
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn remove(&mut self, id: PolygonId) -> Result<LinkedPolygon, SceneError> {
        let key = self.key(id)?;
        self.broad.mark(key);
        Ok(self.entries.remove(key).polygon.into_inner())
    }

    #[inline]
    pub(super) fn key(&self, id: PolygonId) -> Result<usize, SceneError> {
        if id.scene != self.identity.get() {
            return Err(SceneError::ForeignPolygon(id));
        }
        match self.entries.get(id.key as usize) {
            Some(e) if e.generation == id.generation => Ok(id.key as usize),
            _ => Err(SceneError::StalePolygon(id)),
        }
    }

    pub(super) fn id_of(&self, key: usize) -> PolygonId {
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

    instrument_pub! {
        /// True while the polygon holds a valid array snapshot.
        ///
        /// # Errors
        /// `StalePolygon`, `ForeignPolygon`.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn has_snapshot(&self, id: PolygonId) -> Result<bool, SceneError> {
            self.key(id).map(|k| self.entries[k].holds_snapshot())
        }
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
        if self.entries[key].posed.is_some() {
            return self.edit_posed(id, key, |shape| shape.insert_after(after, p));
        }
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
        if self.entries[key].posed.is_some() {
            return self.edit_posed(id, key, |shape| shape.remove(v));
        }
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
        if self.entries[key].posed.is_some() {
            return self.edit_posed(id, key, |shape| shape.move_vertex(v, p));
        }
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
        if let Some(posed) = &self.entries[key].posed {
            let pose = posed
                .pose
                .translated(dx, dy)
                .map_err(|err| SceneError::Pose(id, err))?;
            return self.set_pose(id, pose);
        }
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
    pub(super) fn convert(&mut self, key: usize) {
        let snapshot = self.entries[key].polygon.materialized().to_convex();
        self.install_snapshot(key, snapshot);
    }

    pub(super) fn install_snapshot(&mut self, key: usize, snapshot: ConvexPolygon) {
        let e = &mut self.entries[key];
        if !e.bbox_tight {
            e.bbox = snapshot.bounding_box();
            e.bbox_tight = true;
            self.broad.mark(key);
        }
        e.snapshot = Some(snapshot);
        if let Some(p) = e.posed.as_deref_mut() {
            p.snapshot_due = false;
        }
        self.stats.conversions += 1;
    }

    pub(super) fn flush_broad_phase(&mut self) {
        let entries = &self.entries;
        self.broad.flush(|k| entries.get(k).map(|e| e.bbox));
    }

    instrument_pub! {
        /// Checks every invariant: each polygon's own, boxes contain their polygons (and equal
        /// them when marked tight), snapshots equal their polygons.
        ///
        /// # Errors
        /// The first invariant found broken, with the polygon's slot.
        ///
        /// # Panics
        /// Never: a polygon always has vertices for its box.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn debug_validate(&self) -> Result<(), String> {
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
                if let Some(posed) = &e.posed {
                    posed
                        .shape
                        .debug_validate()
                        .map_err(|m| format!("polygon {k}: shape: {m}"))?;
                    if posed.array.vertices() != posed.shape.to_convex().vertices() {
                        return Err(format!("polygon {k}: the shape's array is stale"));
                    }
                    if posed.shape.len() != polygon.len() {
                        return Err(format!("polygon {k}: world and shape sizes differ"));
                    }
                    for pos in 0..polygon.len() {
                        let (w, sp) = (polygon.point_at(pos), posed.shape.point_at(pos));
                        if posed.pose.apply(sp) != Some(w) || polygon.id_at(pos) != posed.shape.id_at(pos) {
                            return Err(format!(
                                "polygon {k}: world vertex {pos} is not the shape's image"
                            ));
                        }
                    }
                }
                if e.posed.as_ref().is_some_and(|p| p.snapshot_due) && e.snapshot.is_some() {
                    return Err(format!("polygon {k}: a snapshot both owed and held"));
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

mod extreme;
mod pose;
mod user;
mod weak;

#[cfg(test)]
mod tests;
#[cfg(test)]
mod view_tests;
