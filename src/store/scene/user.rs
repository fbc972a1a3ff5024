//! User data on a [`Scene`]'s polygons: one `u128` per polygon, chosen by the caller
//! (an index into the caller's own tables, a packed pair of ids, a hash), so that a
//! [`PolygonId`] met in an answer need not be mapped back by hand. It is the
//! polygon's own: it stays through vertex edits, translations, poses and snapshots,
//! and goes with the polygon when it is removed. O(1) to read and to set; 16 bytes
//! per polygon (docs/store.md, "User data").

use super::{PolygonId, Scene, SceneError};
use crate::kernel::Kernel;
use crate::polygon::LinkedPolygon;

impl<K: Kernel> Scene<K> {
    /// Adds a polygon carrying `user_data` ([`insert`](Self::insert) gives 0). O(n) for
    /// its bounding box.
    ///
    /// ```
    /// use polysect::LinkedPolygon;
    /// use polysect::store::Scene;
    /// // The caller's own bodies, found again from each intersecting pair.
    /// let bodies = ["crate", "wall", "lamp"];
    /// let mut scene = Scene::new();
    /// for (i, corners) in [
    ///     [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
    ///     [[2.0, 1.0], [4.0, 1.0], [4.0, 3.0], [2.0, 3.0]],
    ///     [[9.0, 9.0], [10.0, 9.0], [10.0, 10.0], [9.0, 10.0]],
    /// ]
    /// .into_iter()
    /// .enumerate()
    /// {
    ///     scene.insert_with_user_data(LinkedPolygon::from_points(corners)?, i as u128);
    /// }
    /// let touching: Vec<(&str, &str)> = scene
    ///     .intersecting_pairs()
    ///     .into_iter()
    ///     .map(|(a, b)| Ok((bodies[scene.user_data(a)? as usize], bodies[scene.user_data(b)? as usize])))
    ///     .collect::<Result<_, polysect::store::SceneError>>()?;
    /// assert_eq!(touching, [("crate", "wall")]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn insert_with_user_data(&mut self, polygon: LinkedPolygon, user_data: u128) -> PolygonId {
        let id = self.insert(polygon);
        self.entries[id.key as usize].user_data = user_data;
        id
    }

    /// The polygon's user data (0 unless set at insertion or by
    /// [`set_user_data`](Self::set_user_data)).
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`.
    pub fn user_data(&self, id: PolygonId) -> Result<u128, SceneError> {
        self.key(id).map(|k| self.entries[k].user_data)
    }

    /// Sets the polygon's user data and returns the value it replaces. Nothing else
    /// changes: not the version, the snapshot, the box or the planner's history.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon`; nothing changes on error.
    ///
    /// ```
    /// use polysect::store::Scene;
    /// let mut scene = Scene::new();
    /// let a = scene.insert_points([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])?;
    /// assert_eq!(scene.set_user_data(a, 7)?, 0);
    /// scene.translate(a, 5.0, 0.0)?;
    /// assert_eq!(scene.user_data(a)?, 7);
    /// scene.remove(a)?;
    /// assert!(scene.user_data(a).is_err()); // stale
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn set_user_data(&mut self, id: PolygonId, user_data: u128) -> Result<u128, SceneError> {
        let key = self.key(id)?;
        Ok(std::mem::replace(&mut self.entries[key].user_data, user_data))
    }
}
