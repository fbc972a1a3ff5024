//! The page's edits: a vertex moved, inserted or removed through the store's validated
//! edits, with wire vertex ids checked and the body's mass and inertia brought up to
//! date. The page sends world points (the pointer); a posed polygon's edits take shape
//! coordinates, so the target goes through the inverse of the body's pose (in `f64`,
//! then snapped to the grid: the vertex lands within rounding of the pointer). The store
//! checks that the shape and its world image both stay strictly convex (O(n) for a
//! posed polygon: the new shape's array and its image).

use super::*;

/// One polygon's wire vertex ids: id → vertex handle for the live vertices, and the next
/// id to hand out. Ids are never reused; a removed vertex's entry is dropped, so the map
/// holds as many entries as the polygon has vertices (a hash map: its capacity stays
/// within a small factor of the most vertices it has held at once, whatever the number
/// of insertions and removals).
#[derive(Debug)]
pub(super) struct VertexIds {
    map: HashMap<u32, VertexId>,
    next: u32,
}

impl VertexIds {
    /// Ids 0, 1, ... for `vertices`, in order.
    pub(super) fn new(vertices: impl Iterator<Item = VertexId>) -> VertexIds {
        let map: HashMap<u32, VertexId> = (0u32..).zip(vertices).collect();
        let next = map.len() as u32;
        VertexIds { map, next }
    }

    /// The entries the map has room for (its memory), for the tests.
    #[cfg(test)]
    pub(super) fn capacity(&self) -> usize {
        self.map.capacity()
    }

    /// The number of live ids.
    #[cfg(test)]
    pub(super) fn len(&self) -> usize {
        self.map.len()
    }
}

impl Simulation {
    fn body(&self, polygon: usize) -> Result<&Body, EditFailure> {
        self.bodies.get(polygon).ok_or_else(|| {
            EditFailure::Invalid(format!(
                "no polygon {polygon} (the scene has {} polygons, numbered from 0)",
                self.bodies.len()
            ))
        })
    }

    fn vertex(&self, polygon: usize, vertex: u32) -> Result<VertexId, EditFailure> {
        let ids = &self.body(polygon)?.ids;
        match ids.map.get(&vertex) {
            Some(v) => Ok(*v),
            None if vertex < ids.next => Err(EditFailure::Invalid(format!(
                "vertex {vertex} of polygon {polygon} was removed"
            ))),
            None => Err(EditFailure::Invalid(format!(
                "polygon {polygon} has no vertex {vertex}"
            ))),
        }
    }

    /// Validates an edit target (a world point), maps it into polygon `polygon`'s shape
    /// through the inverse of its pose and snaps it to the grid.
    fn target(&self, polygon: usize, point: [f64; 2]) -> Result<Point, EditFailure> {
        for axis in 0..2 {
            if !(AREA_MIN[axis]..=AREA_MAX[axis]).contains(&point[axis]) {
                return Err(EditFailure::Invalid(format!(
                    "point ({:?}, {:?}) is outside the area [{:?}, {:?}] × [{:?}, {:?}]",
                    point[0], point[1], AREA_MIN[0], AREA_MAX[0], AREA_MIN[1], AREA_MAX[1]
                )));
            }
        }
        let pose = self.bodies[polygon].pose;
        let ([c, s], [tx, ty]) = (pose.rotation(), pose.translation());
        let (rx, ry) = (point[0] - tx, point[1] - ty);
        // The inverse of x ↦ R·x + t, with R = [[c, −s], [s, c]] of scale c² + s².
        let scale = c * c + s * s;
        Ok(Point::new(
            snap((c * rx + s * ry) / scale),
            snap((c * ry - s * rx) / scale),
        ))
    }

    fn edited(&mut self, polygon: usize) {
        let id = self.bodies[polygon].id;
        let shape = on_scene!(&self.store, s => s.shape(id)).expect("live polygon");
        (self.bodies[polygon].mass, self.bodies[polygon].inertia) =
            mass_and_inertia(shape.iter().map(|(_, p)| p));
    }

    /// Moves vertex `vertex` (a wire id) of polygon `polygon` to the world point `to`
    /// (mapped into the shape, snapped to the grid) through [`Scene::move_vertex`]. O(n):
    /// the store's check of the posed polygon, the new mass and inertia.
    ///
    /// # Errors
    /// `Invalid` for an unknown polygon or vertex or a point outside the area; `Refused`
    /// when the store refuses the move (it would break convexity).
    pub fn move_vertex(&mut self, polygon: usize, vertex: u32, to: [f64; 2]) -> Result<Edit, EditFailure> {
        let v = self.vertex(polygon, vertex)?;
        let p = self.target(polygon, to)?;
        let id = self.bodies[polygon].id;
        on_scene!(&mut self.store, s => s.move_vertex(id, v, p)).map_err(|e| refused_at(e, to))?;
        self.edited(polygon);
        Ok(Edit {
            polygon,
            kind: "move",
            vertex,
            after: None,
            point: Some([p.x, p.y]),
        })
    }

    /// Inserts `point` after vertex `after` (its counter-clockwise successor) through
    /// [`Scene::insert_vertex`]; the new vertex takes the polygon's next wire id.
    ///
    /// # Errors
    /// As [`move_vertex`](Self::move_vertex) (`Refused` also for a point on an edge or
    /// inside the polygon), and `Invalid` once the polygon has handed
    /// out [`MAX_VERTEX_IDS`] ids, has [`MAX_VERTICES`] vertices, or the scene has
    /// [`MAX_TOTAL_VERTICES`] in all.
    pub fn insert_vertex(
        &mut self,
        polygon: usize,
        after: u32,
        point: [f64; 2],
    ) -> Result<Edit, EditFailure> {
        let a = self.vertex(polygon, after)?;
        let p = self.target(polygon, point)?;
        let next = self.bodies[polygon].ids.next;
        if next as usize >= MAX_VERTEX_IDS {
            return Err(EditFailure::Invalid(format!(
                "polygon {polygon} has used all its {MAX_VERTEX_IDS} vertex ids; start a new scene"
            )));
        }
        let id = self.bodies[polygon].id;
        if on_scene!(&self.store, s => s.polygon(id)).map_or(0, |p| p.len()) >= MAX_VERTICES {
            return Err(EditFailure::Invalid(format!(
                "polygon {polygon} already has {MAX_VERTICES} vertices, the page's limit"
            )));
        }
        if self.vertices >= MAX_TOTAL_VERTICES {
            return Err(EditFailure::Invalid(format!(
                "the scene already has {} vertices, the page's limit in all; remove one first",
                self.vertices
            )));
        }
        let v =
            on_scene!(&mut self.store, s => s.insert_vertex(id, a, p)).map_err(|e| refused_at(e, point))?;
        let ids = &mut self.bodies[polygon].ids;
        ids.map.insert(next, v);
        ids.next = next + 1;
        self.vertices += 1;
        self.edited(polygon);
        Ok(Edit {
            polygon,
            kind: "insert",
            vertex: next,
            after: Some(after),
            point: Some([p.x, p.y]),
        })
    }

    /// Removes vertex `vertex` through [`Scene::remove_vertex`].
    ///
    /// # Errors
    /// `Invalid` for an unknown polygon or vertex; `Refused` when only three remain.
    pub fn remove_vertex(&mut self, polygon: usize, vertex: u32) -> Result<Edit, EditFailure> {
        let v = self.vertex(polygon, vertex)?;
        let id = self.bodies[polygon].id;
        on_scene!(&mut self.store, s => s.remove_vertex(id, v)).map_err(refused)?;
        self.bodies[polygon].ids.map.remove(&vertex);
        self.vertices -= 1;
        self.edited(polygon);
        Ok(Edit {
            polygon,
            kind: "remove",
            vertex,
            after: None,
            point: None,
        })
    }
}

/// A refusal of an edit at the world point `at`: the store names the point in the
/// polygon's own (shape) coordinates, so the page's message adds the pointer's.
fn refused_at(e: SceneError, at: [f64; 2]) -> EditFailure {
    match refused(e) {
        EditFailure::Refused(reason) => EditFailure::Refused(format!(
            "{reason} (in the polygon's own coordinates; the pointer is at ({:?}, {:?}))",
            at[0], at[1]
        )),
        invalid => invalid,
    }
}

/// The page names polygons by index: the reason is the edit's own message, without the
/// store's handle.
fn refused(e: SceneError) -> EditFailure {
    match e {
        SceneError::Edit(_, crate::EditError::StaleHandle) | SceneError::StalePolygon(_) => {
            EditFailure::Invalid(e.to_string())
        }
        SceneError::Edit(_, reason) => EditFailure::Refused(reason.to_string()),
        e => EditFailure::Refused(e.to_string()),
    }
}
