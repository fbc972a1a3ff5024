//! Contact geometry between the scene's polygons ([`crate::contact`]): one pair's
//! contact or distance, or every intersecting pair of a frame.

use super::{PolygonId, Scene, SceneError};
use crate::contact::{Contact, Distance, contact_with, distance_with};
use crate::kernel::Kernel;
use crate::polygon::ConvexPolygon;
use std::borrow::Cow;

impl<K: Kernel> Scene<K> {
    /// The polygon as an array: its snapshot when it has one, else a conversion (O(n)).
    fn array(&self, key: usize) -> Cow<'_, ConvexPolygon> {
        let e = &self.entries[key];
        match &e.snapshot {
            Some(s) => Cow::Borrowed(s),
            None => Cow::Owned(e.polygon.get().to_convex()),
        }
    }

    /// The contact of polygons `a` (the contact's P) and `b` (its Q), decided by the
    /// scene's kernel: their distance and a closest pair, or the penetration depth, its
    /// normal (the direction to move `b`) and the overlap polygon
    /// ([`contact_with`](crate::contact::contact_with)). O(n + m) on top of
    /// converting a polygon without a snapshot; snapshots are used, never made.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon` for either handle.
    ///
    /// ```
    /// use polysect::store::Scene;
    /// let mut scene = Scene::new();
    /// let a = scene.insert_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// let b = scene.insert_points([[3.0, 0.0], [4.0, 0.0], [4.0, 1.0]])?;
    /// let polysect::contact::Contact::Separated(s) = scene.contact(a, b)? else { unreachable!() };
    /// assert_eq!(s.distance, Some(1.0));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn contact(&mut self, a: PolygonId, b: PolygonId) -> Result<Contact, SceneError> {
        let (ka, kb) = (self.key(a)?, self.key(b)?);
        let (p, q) = (self.array(ka), self.array(kb));
        Ok(contact_with(self.kernel, &p, &q))
    }

    /// The distance and a closest pair of polygons `a` (P) and `b` (Q), decided by the
    /// scene's kernel, or `None` when they meet: the distance and pair of
    /// [`contact`](Self::contact)'s separation, without its exact rationals
    /// ([`distance_with`](crate::contact::distance_with): no big integers nearly
    /// always). Posed polygons are read where they stand. O(log n + log m) on ordinary
    /// input on top of converting a polygon without a snapshot (O(n)); snapshots are
    /// used, never made.
    ///
    /// # Errors
    /// `StalePolygon`, `ForeignPolygon` for either handle.
    ///
    /// ```
    /// use polysect::store::Scene;
    /// let mut scene = Scene::new();
    /// let a = scene.insert_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// let b = scene.insert_points([[3.0, 0.0], [4.0, 0.0], [4.0, 1.0]])?;
    /// let d = scene.distance(a, b)?.expect("apart");
    /// assert_eq!(d.distance, Some(1.0));
    /// assert_eq!(d.closest, [[2.0, 0.0].into(), [3.0, 0.0].into()]);
    /// let c = scene.insert_points([[1.0, 1.0], [5.0, 1.0], [5.0, 5.0]])?;
    /// assert_eq!(scene.distance(a, c)?, None);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn distance(&mut self, a: PolygonId, b: PolygonId) -> Result<Option<Distance>, SceneError> {
        let (ka, kb) = (self.key(a)?, self.key(b)?);
        let (p, q) = (self.array(ka), self.array(kb));
        Ok(distance_with(self.kernel, &p, &q))
    }

    /// Every intersecting pair of [`intersecting_pairs`](Self::intersecting_pairs) with
    /// its contact (`a` the contact's P).
    pub fn contacts(&mut self) -> Vec<(PolygonId, PolygonId, Contact)> {
        let pairs = self.intersecting_pairs();
        pairs
            .into_iter()
            .filter_map(|(a, b)| Some((a, b, self.contact(a, b).ok()?)))
            .collect()
    }
}
