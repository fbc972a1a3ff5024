//! Poses of a [`Scene`]'s polygons: a posed polygon keeps its shape and its pose, and
//! its entry's polygon is the shape's image (docs/store.md, "Poses").
//!
//! # Complexity
//! A pose is set in O(log n) when the shape's rounding margin proves the rounded image
//! strictly convex ([`proves_convex`], O(1)): the world box from four extreme-vertex
//! searches on the shape's array (`extreme.rs`), the pose recorded, the world polygon
//! built only when something reads it (the linked image by the first reader, O(n)).
//! A snapshot the polygon had stays owed: from [`VIEW_MIN_VERTICES`] vertices the
//! array test reads the world vertices through the pose (`Pose::apply` of the O(log n)
//! vertices its search reads, `polygon::PosedVertices`), so the snapshot is never
//! built; below it, where n images cost about what the four searches do, the pose
//! computes the world array at once (O(n) with a small constant), which gives the box
//! exactly and is the snapshot. Otherwise
//! (first pose, a margin too small for the coordinates' rounding, an overflowing
//! extreme) it is O(n): the image with its exact strict-convexity check, its box and
//! its snapshot. Vertex edits of a posed polygon are O(n) (the new shape's array and
//! margin, its image).
//!
//! # Precision
//! Both paths give the same polygon, box and answers: the world coordinates are
//! `Pose::apply`'s, the box is the rounded image's exactly, and a pose is accepted
//! only when the rounded image is strictly convex (proved, or checked exactly).

use super::super::lazy::LazyLinked;
use super::extreme;
use super::weak::WeakTurns;
use super::{PolygonId, Scene, SceneError};
use crate::kernel::{BoundingBox, Kernel, Point, Pose, PoseError};
use crate::polygon::{ConvexPolygon, EditError, LinkedPolygon};
use std::sync::Arc;

/// A posed polygon's shape (edited in shape coordinates) and its pose. The entry's
/// `polygon` is the shape's image, a twin of `shape` (the same vertex handles), with no
/// translation pending (or a pending pose of this shape, `LazyLinked::remap`).
#[derive(Clone, Debug)]
pub(in crate::store) struct Posed {
    pub(in crate::store) pose: Pose,
    pub(in crate::store) shape: Arc<LinkedPolygon>,
    /// The shape as an array, counter-clockwise from its first position (as
    /// `to_convex` gives it): the extreme-vertex searches read it, and the world
    /// snapshot is its image.
    pub(in crate::store) array: ConvexPolygon,
    /// The least `turn_margin` of the shape's turns (0 when none is proved): a bound on
    /// how far rounding may move the image's vertices and keep it strictly convex.
    pub(in crate::store) margin: f64,
    /// The turns too flat for `margin`, each checked on its own at a pose (`weak.rs`).
    pub(in crate::store) weak: WeakTurns,
    /// The polygon had a snapshot when a lazy pose dropped it: the planner rebuilds it
    /// (from `array`) when the polygon's box next meets another's.
    pub(in crate::store) snapshot_due: bool,
}

/// From this many vertices a posed polygon whose lazy pose left its snapshot owed is
/// read by the array test through its pose ([`PosedVertices`](crate::polygon::PosedVertices):
/// `Pose::apply` of each vertex the O(log n) search reads) instead of settling the
/// snapshot (n applies). Below it the snapshot is built: a search on a small polygon
/// reads a large share of its vertices, some more than once, and the linear walk the
/// cost model picks there reads them all.
pub(in crate::store) const VIEW_MIN_VERTICES: usize = 24;

impl Posed {
    /// Whether the array test reads this polygon through its pose: its snapshot is owed
    /// (never built for this pose) and it has at least [`VIEW_MIN_VERTICES`] vertices.
    #[inline]
    pub(in crate::store) fn reads_through_pose(&self) -> bool {
        self.snapshot_due && self.array.len() >= VIEW_MIN_VERTICES
    }

    /// Whether the rounded image under `pose`, lying in `world`, is proved strictly
    /// convex: by the shape-wide margin, else by the strong turns' margin and each weak
    /// turn on its own (`weak.rs`). O(1), or O(k) for k weak turns.
    fn proves_convex(&self, pose: &Pose, world: &BoundingBox) -> bool {
        proves_convex(self.margin, pose, world) || self.weak.prove(self.array.vertices(), pose, world)
    }

    /// `shape` (strictly convex) under `pose`. O(n): the array and the margin.
    fn new(pose: Pose, shape: LinkedPolygon) -> Posed {
        let (array, margin) = shape_facts(&shape);
        Posed {
            pose,
            shape: Arc::new(shape),
            weak: WeakTurns::of(array.vertices()),
            array,
            margin,
            snapshot_due: false,
        }
    }
}

/// The shape's array and rounding margin. A translation by zero rounds nothing, so
/// `check_translation(0, 0)` is the exact walk over the shape itself.
pub(super) fn shape_facts(shape: &LinkedPolygon) -> (ConvexPolygon, f64) {
    (
        shape.to_convex(),
        shape.check_translation(0.0, 0.0).unwrap_or(0.0),
    )
}

/// Whether a shape whose turns all have margin at least `margin` (`turn_margin`) has a
/// strictly convex rounded image under `pose` when the rounded image lies in `world`.
///
/// # Why
/// The exact image is the shape under a rotation scaled by ρ = √(c² + s²): each turn's
/// determinant is ρ² times the shape's, and each edge's 1-norm at most √2·ρ times the
/// shape's. So if the shape's turn has determinant at least L and edge norms summing to
/// at most S, with margin m ≤ L / (2S + 8), the image's turn has determinant at least
/// ρ²·L and norms at most √2·ρ·S, and moving every image vertex by δ ≤ 1 per coordinate
/// keeps it strictly left when δ·(2√2·ρ·S + 8) < ρ²·L, which holds when
/// δ·√2·max(ρ, 1) < ρ²·m (then the turn-margin argument of `turn_margin` applies:
/// strictly convex, winding once). Rounding moves each coordinate by at most half an
/// ulp of the rounded value, δ ≤ U·max|world| + 2^-1075, and the world box bounds the
/// rounded values.
///
/// # Precision
/// ρ² is bounded below and ρ above with the roundings of their computation widened by
/// several ulps each; outside [2^-600, 2^600] for ρ² (where products could leave the
/// normal range) nothing is proved.
pub(super) fn proves_convex(margin: f64, pose: &Pose, world: &BoundingBox) -> bool {
    if margin <= 0.0 {
        return false;
    }
    rounding_bound(pose, world).is_some_and(|b| b.proves(margin))
}

/// What [`proves_convex`] compares a margin with: δ, the most rounding moves a world
/// coordinate in `world`, and bounds on ρ² = c² + s² (below) and ρ (above). `None` where
/// nothing is proved (coordinates beyond 2^52, ρ² outside [2^-600, 2^600]).
#[derive(Clone, Copy, Debug)]
pub(super) struct RoundingBound {
    pub(super) delta: f64,
    pub(super) rho2_low: f64,
    pub(super) rho_high: f64,
}

impl RoundingBound {
    /// Whether a turn of margin `margin` stays strictly left under every motion of its
    /// vertices by at most δ per coordinate.
    pub(super) fn proves(&self, margin: f64) -> bool {
        const U: f64 = f64::EPSILON / 2.0;
        let need = self.delta * std::f64::consts::SQRT_2 * self.rho_high.max(1.0) * (1.0 + 16.0 * U);
        let have = margin * self.rho2_low * (1.0 - 16.0 * U);
        need < have
    }
}

pub(super) fn rounding_bound(pose: &Pose, world: &BoundingBox) -> Option<RoundingBound> {
    const U: f64 = f64::EPSILON / 2.0;
    let largest = [world.min.x, world.min.y, world.max.x, world.max.y]
        .into_iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    if largest.is_nan() || largest > 2f64.powi(52) {
        return None;
    }
    let delta = largest * U * (1.0 + f64::EPSILON) + f64::from_bits(1);
    let [c, s] = pose.rotation();
    let rho2 = c * c + s * s;
    if !(2f64.powi(-600)..=2f64.powi(600)).contains(&rho2) {
        return None;
    }
    // c² + s² rounds three times: within a factor (1 ± 3.01U); 8U covers it, and the
    // square root, the constant √2 and each product below round once more.
    let rho2_low = rho2 * (1.0 - 8.0 * U);
    let rho_high = (rho2 * (1.0 + 8.0 * U)).sqrt() * (1.0 + 4.0 * U);
    Some(RoundingBound {
        delta,
        rho2_low,
        rho_high,
    })
}

/// The image of `shape` under `pose`, each coordinate correctly rounded, checked exactly.
fn world_of(shape: &LinkedPolygon, pose: &Pose) -> Result<LinkedPolygon, PoseError> {
    shape.mapped_twin(|p| pose.apply(p)).map_err(|e| match e {
        EditError::NonFinite { point } => PoseError::Overflow { point },
        EditError::RoundingBreaksConvexity { point } | EditError::WouldBreakConvexity { point } => {
            PoseError::NotConvex { point }
        }
        // `mapped_twin` refuses nothing else; name a vertex all the same.
        _ => PoseError::NotConvex {
            point: shape.point_at(0),
        },
    })
}

impl<K: Kernel> Scene<K> {
    /// Places the polygon's shape in the world by `pose`, replacing any previous pose
    /// (absolute: nothing drifts however often it is set). The *shape* is the polygon as
    /// it stood when it was first posed, with the vertex edits made since; from then on
    /// [`polygon`](Self::polygon), [`bounding_box`](Self::bounding_box) and every query
    /// (pairs, certificates, contact) read the *world polygon*: each shape vertex mapped
    /// by [`Pose::apply`], each coordinate the exact value rounded to nearest. Vertex
    /// handles are the shape's, valid on the world polygon too. O(n): the image, its
    /// exact strict-convexity check and its box in a few sequential passes; the array
    /// snapshot, when the polygon had one, is rebuilt from the image.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`; [`SceneError::Pose`] with
    /// [`PoseError::Overflow`] when a world coordinate would overflow, or
    /// [`PoseError::NotConvex`] when the rounded image is not strictly convex. Nothing
    /// changes on error.
    ///
    /// ```
    /// use polysect::store::Scene;
    /// use polysect::kernel::Pose;
    /// use polysect::Point;
    /// let mut scene = Scene::new();
    /// let a = scene.insert_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// let b = scene.insert_points([[3.0, 0.0], [4.0, 0.0], [4.0, 1.0]])?;
    /// assert!(!scene.intersects(a, b)?);
    /// // A quarter turn about the origin, then right by 2: b's corners land at (2, 3),
    /// // (2, 4), (1, 4), still apart. A half turn, then right by 6: (4, 0) lands on a's
    /// // corner (2, 0).
    /// scene.set_pose(b, Pose::new([0.0, 1.0], [2.0, 0.0])?)?;
    /// assert!(!scene.intersects(a, b)?);
    /// scene.set_pose(b, Pose::new([-1.0, 0.0], [6.0, 0.0])?)?;
    /// assert!(scene.intersects(a, b)?);
    /// assert_eq!(scene.world_points(b)?[0], Point::new(3.0, 0.0));
    /// assert_eq!(scene.shape(b)?.point_at(0), Point::new(3.0, 0.0));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn set_pose(&mut self, id: PolygonId, pose: Pose) -> Result<(), SceneError> {
        let key = self.key(id)?;
        if self.pose_lazily(key, pose) {
            return Ok(());
        }
        let e = &mut self.entries[key];
        let world = match &e.posed {
            Some(posed) => world_of(&posed.shape, &pose),
            None => world_of(e.polygon.materialized(), &pose),
        }
        .map_err(|err| SceneError::Pose(id, err))?;
        let old = std::mem::replace(&mut e.polygon, LazyLinked::new(world));
        match &mut e.posed {
            Some(posed) => posed.pose = pose,
            None => e.posed = Some(Box::new(Posed::new(pose, old.into_inner()))),
        }
        self.placed(key);
        Ok(())
    }

    /// Sets the pose of an already posed polygon in O(log n) when the margin proves the
    /// rounded image strictly convex: the box from the extreme vertices, the image left
    /// to its readers. False (nothing changed) when it cannot: then the caller checks
    /// the image in full.
    fn pose_lazily(&mut self, key: usize, pose: Pose) -> bool {
        let e = &mut self.entries[key];
        let Some(posed) = e.posed.as_deref_mut() else {
            return false;
        };
        let owed = e.snapshot.is_some() || posed.snapshot_due;
        if owed && posed.array.len() < VIEW_MIN_VERTICES {
            // A small polygon that holds (or owes) a snapshot: its world array, n images,
            // costs about what the four extreme searches do, gives the box exactly, and
            // is the snapshot the planner would build (in the old snapshot's buffer).
            // Taking the old snapshot leaves it owed for the pose in place, so that an
            // early return (the full path, or a refusal that keeps the old pose) builds
            // it again when it is needed.
            let mut world = e
                .snapshot
                .take()
                .map(ConvexPolygon::into_vertices)
                .unwrap_or_default();
            posed.snapshot_due = true;
            world.clear();
            for &p in posed.array.vertices() {
                // An overflowing image: the full path names the shape point.
                let Some(w) = pose.apply(p) else {
                    return false;
                };
                world.push(w);
            }
            let bbox = crate::polygon::box_of(&world);
            if !posed.proves_convex(&pose, &bbox) {
                return false;
            }
            posed.snapshot_due = false;
            e.snapshot = Some(ConvexPolygon::from_ccw_unchecked(world));
            self.accept_lazy_pose(key, pose, bbox);
            return true;
        }
        // An overflowing extreme: the full path names the shape point.
        let Some(bbox) = extreme::image_box(posed.array.vertices(), &pose) else {
            return false;
        };
        if !posed.proves_convex(&pose, &bbox) {
            return false;
        }
        posed.snapshot_due |= e.snapshot.take().is_some();
        self.accept_lazy_pose(key, pose, bbox);
        true
    }

    /// What a lazy pose proved sets: the pose, the image left to its readers, the box,
    /// the version, the broad phase (the snapshot is the caller's: built or owed).
    fn accept_lazy_pose(&mut self, key: usize, pose: Pose, bbox: BoundingBox) {
        let e = &mut self.entries[key];
        let posed = e.posed.as_deref_mut().expect("a posed polygon");
        posed.pose = pose;
        e.polygon.remap(&posed.shape, pose);
        e.bbox = bbox;
        e.bbox_tight = true;
        e.rounding_margin = 0.0;
        e.version += 1;
        self.broad.mark(key);
        #[cfg(test)]
        {
            self.lazy_poses += 1;
        }
    }

    /// Builds the world snapshot a lazy pose left owed (one pass over the shape's
    /// array); O(1) when none is owed, or when the array test reads the polygon through
    /// its pose instead ([`Posed::reads_through_pose`]: the snapshot stays owed).
    pub(in crate::store) fn settle(&mut self, key: usize) {
        let e = &mut self.entries[key];
        let Some(posed) = e.posed.as_deref_mut() else {
            return;
        };
        if posed.reads_through_pose() || !std::mem::take(&mut posed.snapshot_due) {
            return;
        }
        let pose = posed.pose;
        let world = posed
            .array
            .vertices()
            .iter()
            .map(|&p| pose.apply(p).expect("an accepted pose has every image finite"))
            .collect();
        e.snapshot = Some(ConvexPolygon::from_ccw_unchecked(world));
    }

    /// The polygon's pose: `None` while it was never posed.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn pose(&self, id: PolygonId) -> Result<Option<Pose>, SceneError> {
        self.key(id)
            .map(|k| self.entries[k].posed.as_ref().map(|p| p.pose))
    }

    /// The polygon's shape: for a posed polygon the vertices as added and edited, in
    /// shape coordinates (the same vertex handles as the world polygon); otherwise the
    /// polygon itself, as [`polygon`](Self::polygon).
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn shape(&self, id: PolygonId) -> Result<&LinkedPolygon, SceneError> {
        let k = self.key(id)?;
        let e = &self.entries[k];
        Ok(match &e.posed {
            Some(posed) => posed.shape.as_ref(),
            None => e.polygon.get(),
        })
    }

    /// The world polygon's vertices counter-clockwise from the linked polygon's first
    /// position (what every query reads; for a polygon never posed, its own vertices).
    /// O(n).
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn world_points(&self, id: PolygonId) -> Result<Vec<Point>, SceneError> {
        Ok(self.polygon(id)?.to_convex().into_vertices())
    }

    /// A vertex edit of a posed polygon: `edit` on a twin of the shape, then its image
    /// under the pose; both must stay strictly convex, else nothing changes.
    pub(super) fn edit_posed<T>(
        &mut self,
        id: PolygonId,
        key: usize,
        edit: impl FnOnce(&mut LinkedPolygon) -> Result<T, EditError>,
    ) -> Result<T, SceneError> {
        let e = &mut self.entries[key];
        let posed = e.posed.as_mut().expect("a posed polygon");
        let mut shape = posed.shape.translated_twin(&[]);
        let out = edit(&mut shape).map_err(|err| SceneError::Edit(id, err))?;
        let world = world_of(&shape, &posed.pose).map_err(|err| SceneError::Pose(id, err))?;
        (posed.array, posed.margin) = shape_facts(&shape);
        posed.weak = WeakTurns::of(posed.array.vertices());
        posed.shape = Arc::new(shape);
        e.polygon = LazyLinked::new(world);
        e.account.edited();
        self.placed(key);
        Ok(out)
    }

    /// After a posed polygon's world image changed: its box, its snapshot (rebuilt when
    /// it had one), its version, the broad phase.
    pub(super) fn placed(&mut self, key: usize) {
        let e = &mut self.entries[key];
        let world = e.polygon.get();
        e.bbox = world.bounding_box();
        e.bbox_tight = true;
        e.rounding_margin = 0.0;
        e.version += 1;
        let due = e
            .posed
            .as_deref_mut()
            .is_some_and(|p| std::mem::take(&mut p.snapshot_due));
        if e.snapshot.is_some() || due {
            e.snapshot = Some(world.to_convex());
        }
        self.broad.mark(key);
    }
}
