//! Poses of a [`Scene`]'s polygons: a posed polygon keeps its shape and its pose, and
//! its entry's polygon is the shape's image (docs/store.md, "Poses"). Setting a pose is
//! O(n): the image, its exact strict-convexity check, its box and, when the polygon had
//! one, its snapshot.

use super::super::lazy::LazyLinked;
use super::{PolygonId, Scene, SceneError};
use crate::kernel::{Kernel, Point, Pose, PoseError};
use crate::polygon::{EditError, LinkedPolygon};

/// A posed polygon's shape (edited in shape coordinates) and its pose. The entry's
/// `polygon` is the shape's image, a twin of `shape` (the same vertex handles), with no
/// translation pending.
#[derive(Clone, Debug)]
pub(in crate::store) struct Posed {
    pub(in crate::store) pose: Pose,
    pub(in crate::store) shape: LinkedPolygon,
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
        let e = &mut self.entries[key];
        let world = match &e.posed {
            Some(posed) => world_of(&posed.shape, &pose),
            None => world_of(e.polygon.materialized(), &pose),
        }
        .map_err(|err| SceneError::Pose(id, err))?;
        let old = std::mem::replace(&mut e.polygon, LazyLinked::new(world));
        match &mut e.posed {
            Some(posed) => posed.pose = pose,
            None => {
                e.posed = Some(Box::new(Posed {
                    pose,
                    shape: old.into_inner(),
                }));
            }
        }
        self.placed(key);
        Ok(())
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
            Some(posed) => &posed.shape,
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
        posed.shape = shape;
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
        if e.snapshot.is_some() {
            e.snapshot = Some(world.to_convex());
        }
        self.broad.mark(key);
    }
}
