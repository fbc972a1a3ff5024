//! [`LinkedPolygon`]: an editable convex polygon as a doubly linked list in an arena.
//!
//! # Layout
//! Vertices live in a **dense** vector of nodes (point, next, prev, slot): positions
//! `0..len` are exactly the live vertices, in arbitrary order, so a uniform random
//! vertex is one random index (thesis 3.3.1). A removal swap-removes its node: the
//! last node moves into the hole and its two neighbours and its handle are patched,
//! all O(1). Density is an invariant, not a property of the edit history, so
//! sampling stays exactly uniform after any sequence of removals and the storage
//! never holds more than the live vertices (plus `Vec` slack).
//!
//! Users hold [`VertexId`]s: a key into a `slab` of slots (each slot records the
//! node's current position) plus a generation. Slab keys are reused after removal;
//! the generation (a per-polygon counter, 64 bits, never reused) makes a stale handle
//! an error instead of an alias of some later vertex.
//!
//! Algorithms inside the crate walk positions directly (`*_at` methods); positions
//! are valid until the next edit, which the borrow checker enforces for anyone
//! holding `&LinkedPolygon`.
//!
//! # Edits
//! The polygon stays strictly convex and counter-clockwise. Inserting `v` between
//! `a` and its successor `b` is valid iff `v` lies strictly outside edge ab and
//! strictly inside the lines through the neighbouring edges (three orientation tests,
//! exact kernel); moving a vertex is the same test with the vertex's own neighbours;
//! removal is always valid while more than three vertices remain. A refused edit
//! changes nothing.

use super::{ConvexPolygon, EditError, PolygonError};
use crate::kernel::{Exact, Kernel, Orientation, Point};
use rand::Rng;
use slab::Slab;

/// A stable handle to a vertex of a [`LinkedPolygon`]. Stays valid until that vertex
/// is removed; afterwards every use is an [`EditError::StaleHandle`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct VertexId {
    slot: u32,
    generation: u64,
}

#[derive(Clone, Copy, Debug)]
struct Node {
    point: Point,
    next: u32,
    prev: u32,
    slot: u32,
}

#[derive(Clone, Copy, Debug)]
struct Slot {
    pos: u32,
    generation: u64,
}

/// A convex polygon as a doubly linked list of vertices, counter-clockwise, with O(1)
/// validated edits and O(1) uniform vertex sampling. See the module docs for the layout.
///
/// ```
/// use polysect::{LinkedPolygon, Point, EditError};
/// let mut p = LinkedPolygon::from_points([[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]])?;
/// let a = p.first();
/// let b = p.next(a)?;
/// // Outside edge ab and inside the neighbouring edges' lines: accepted.
/// let v = p.insert_after(a, Point::new(2.0, -1.0))?;
/// assert_eq!(p.len(), 5);
/// // Would make the vertex at b reflex: refused, nothing changes.
/// assert!(matches!(p.insert_after(v, Point::new(6.0, 1.0)), Err(EditError::WouldBreakConvexity { .. })));
/// p.remove(v)?;
/// assert_eq!(p.remove(v), Err(EditError::StaleHandle));
/// assert_eq!(p.next(a)?, b);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct LinkedPolygon {
    nodes: Vec<Node>,
    slots: Slab<Slot>,
    next_generation: u64,
}

/// Scratch memory for [`LinkedPolygon::sample_positions`], reused across queries so a
/// query allocates nothing in the steady state. Holds one `u32` stamp per vertex of the
/// largest polygon sampled so far.
#[derive(Clone, Debug, Default)]
pub struct SampleWorkspace {
    stamps: Vec<u32>,
    epoch: u32,
}

impl SampleWorkspace {
    pub fn new() -> Self {
        Self::default()
    }

    /// Starts a new round of marks over `n` positions; O(1) amortised.
    fn begin(&mut self, n: usize) {
        if self.stamps.len() < n {
            self.stamps.resize(n, 0);
        }
        self.epoch = self.epoch.wrapping_add(1);
        if self.epoch == 0 {
            self.stamps.iter_mut().for_each(|s| *s = 0);
            self.epoch = 1;
        }
    }

    /// Marks position `i`; true if it was not marked in this round.
    #[inline]
    fn mark(&mut self, i: usize) -> bool {
        let fresh = self.stamps[i] != self.epoch;
        self.stamps[i] = self.epoch;
        fresh
    }
}

impl LinkedPolygon {
    /// Validates and cleans `points` exactly as [`ConvexPolygon::new`] does, and links
    /// them in boundary order.
    pub fn from_points<I, P>(points: I) -> Result<Self, PolygonError>
    where
        I: IntoIterator<Item = P>,
        P: Into<Point>,
    {
        ConvexPolygon::new(points).map(|p| Self::from_convex(&p))
    }

    /// Links the vertices of `polygon`, stored in boundary order. O(n).
    pub fn from_convex(polygon: &ConvexPolygon) -> Self {
        let order: Vec<u32> = (0..polygon.len() as u32).collect();
        Self::with_storage_order(polygon, &order)
    }

    /// Links the vertices of `polygon`, stored in a uniformly random order of the
    /// arena (the thesis's shuffled linked lists, 4.3), so that walking the boundary
    /// jumps around memory as it does after a long edit history. O(n).
    pub fn from_convex_shuffled<R: Rng + ?Sized>(polygon: &ConvexPolygon, rng: &mut R) -> Self {
        let mut order: Vec<u32> = (0..polygon.len() as u32).collect();
        for i in (1..order.len()).rev() {
            order.swap(i, rng.random_range(0..=i));
        }
        Self::with_storage_order(polygon, &order)
    }

    /// Boundary vertex `i` is stored at position `order[i]`.
    fn with_storage_order(polygon: &ConvexPolygon, order: &[u32]) -> Self {
        let n = polygon.len();
        let mut nodes = vec![
            Node {
                point: Point::default(),
                next: 0,
                prev: 0,
                slot: 0,
            };
            n
        ];
        let mut slots = Slab::with_capacity(n);
        for (i, &v) in polygon.vertices().iter().enumerate() {
            let pos = order[i];
            let slot = slots.insert(Slot {
                pos,
                generation: i as u64,
            }) as u32;
            nodes[pos as usize] = Node {
                point: v,
                next: order[(i + 1) % n],
                prev: order[(i + n - 1) % n],
                slot,
            };
        }
        LinkedPolygon {
            nodes,
            slots,
            next_generation: n as u64,
        }
    }

    /// Number of vertices (at least 3).
    #[inline]
    #[allow(clippy::len_without_is_empty)]
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Some vertex (the one stored first).
    pub fn first(&self) -> VertexId {
        self.id_at(0)
    }

    fn pos(&self, id: VertexId) -> Result<usize, EditError> {
        match self.slots.get(id.slot as usize) {
            Some(s) if s.generation == id.generation => Ok(s.pos as usize),
            _ => Err(EditError::StaleHandle),
        }
    }

    /// True while `id` names a live vertex of this polygon.
    pub fn contains(&self, id: VertexId) -> bool {
        self.pos(id).is_ok()
    }

    /// The vertex's coordinates.
    pub fn point(&self, id: VertexId) -> Result<Point, EditError> {
        self.pos(id).map(|p| self.nodes[p].point)
    }

    /// The counter-clockwise successor.
    pub fn next(&self, id: VertexId) -> Result<VertexId, EditError> {
        self.pos(id).map(|p| self.id_at(self.next_at(p)))
    }

    /// The counter-clockwise predecessor.
    pub fn prev(&self, id: VertexId) -> Result<VertexId, EditError> {
        self.pos(id).map(|p| self.id_at(self.prev_at(p)))
    }

    /// The vertices with their handles, counter-clockwise, starting at `id`. O(n) for
    /// the whole walk.
    ///
    /// # Errors
    /// `StaleHandle` when `id` names no live vertex.
    ///
    /// ```
    /// use polysect::{LinkedPolygon, Point};
    /// let p = LinkedPolygon::from_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// let start = p.next(p.first())?; // (2, 0)
    /// let points: Vec<Point> = p.iter_from(start)?.map(|(_, v)| v).collect();
    /// assert_eq!(points, [Point::new(2., 0.), Point::new(2., 2.), Point::new(0., 2.), Point::new(0., 0.)]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn iter_from(&self, id: VertexId) -> Result<impl Iterator<Item = (VertexId, Point)> + '_, EditError> {
        let start = self.pos(id)?;
        let mut pos = start;
        Ok((0..self.len()).map(move |_| {
            let here = pos;
            pos = self.next_at(pos);
            (self.id_at(here), self.nodes[here].point)
        }))
    }

    /// The vertices counter-clockwise, starting at [`first`](Self::first).
    pub fn iter(&self) -> impl Iterator<Item = (VertexId, Point)> + '_ {
        self.iter_from(self.first()).expect("the first vertex is live")
    }

    /// Inserts `point` as the counter-clockwise successor of `after`. O(1).
    ///
    /// # Errors
    /// `StaleHandle`, `NonFinite`, or `WouldBreakConvexity` when `point` is not strictly
    /// outside edge (after, next) and strictly inside the lines through the two
    /// neighbouring edges. The polygon is unchanged on error.
    pub fn insert_after(&mut self, after: VertexId, point: Point) -> Result<VertexId, EditError> {
        let a = self.pos(after)?;
        if !point.is_finite() {
            return Err(EditError::NonFinite { point });
        }
        let b = self.next_at(a);
        if !self.fits_between(a, b, point) {
            return Err(EditError::WouldBreakConvexity { point });
        }
        let pos = self.nodes.len() as u32;
        let generation = self.bump_generation();
        let slot = self.slots.insert(Slot { pos, generation }) as u32;
        self.nodes.push(Node {
            point,
            next: b as u32,
            prev: a as u32,
            slot,
        });
        self.nodes[a].next = pos;
        self.nodes[b].prev = pos;
        Ok(VertexId { slot, generation })
    }

    /// Removes the vertex, returning its point. O(1).
    ///
    /// # Errors
    /// `StaleHandle`, or `TooFewVertices` when only three vertices remain.
    pub fn remove(&mut self, id: VertexId) -> Result<Point, EditError> {
        let r = self.pos(id)?;
        if self.len() <= 3 {
            return Err(EditError::TooFewVertices);
        }
        let Node {
            point,
            next,
            prev,
            slot,
        } = self.nodes[r];
        self.nodes[prev as usize].next = next;
        self.nodes[next as usize].prev = prev;
        self.slots.remove(slot as usize);
        self.nodes.swap_remove(r);
        if r < self.nodes.len() {
            // The former last node now lives at r: patch its neighbours and its slot.
            let moved = self.nodes[r];
            self.nodes[moved.prev as usize].next = r as u32;
            self.nodes[moved.next as usize].prev = r as u32;
            self.slots[moved.slot as usize].pos = r as u32;
        }
        Ok(point)
    }

    /// Moves the vertex to `point`, returning the old point. O(1).
    ///
    /// # Errors
    /// `StaleHandle`, `NonFinite`, or `WouldBreakConvexity` (the same region test as
    /// insertion, against the vertex's neighbours). Unchanged on error.
    pub fn move_vertex(&mut self, id: VertexId, point: Point) -> Result<Point, EditError> {
        let v = self.pos(id)?;
        if !point.is_finite() {
            return Err(EditError::NonFinite { point });
        }
        let (a, b) = (self.prev_at(v), self.next_at(v));
        if !self.fits_between(a, b, point) {
            return Err(EditError::WouldBreakConvexity { point });
        }
        Ok(std::mem::replace(&mut self.nodes[v].point, point))
    }

    /// Translates every vertex to (x + dx, y + dy), each coordinate rounded to nearest
    /// (IEEE addition), or refuses and changes nothing. O(n).
    ///
    /// Rounding moves each vertex by at most half an ulp of its new coordinates, which is
    /// enough to flatten or flip a turn whose vertices are only a few ulps apart, so the
    /// rounded polygon is validated again, exactly: every turn strictly left and the
    /// boundary winding once. When no addition rounds (checked per coordinate, in
    /// storage order, with the two-sum error) the polygon moved rigidly and the walk is
    /// skipped. Handles and the arena order are unchanged.
    ///
    /// # Errors
    /// `NonFinite` when `dx` or `dy` is not finite or a translated coordinate overflows
    /// (the point is the first overflowing vertex); `RoundingBreaksConvexity` naming the
    /// first rounded vertex (counter-clockwise from [`first`](Self::first)) whose turn is
    /// no longer strictly convex, or the first vertex when the boundary would wind more
    /// than once.
    ///
    /// ```
    /// use polysect::{EditError, LinkedPolygon, Point};
    /// let mut p = LinkedPolygon::from_points([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])?;
    /// p.translate(0.5, -2.0)?;
    /// assert_eq!(p.point(p.first())?, Point::new(0.5, -2.0));
    /// // Near 2^1000 the triangle's vertices would round onto one point: refused.
    /// let mut tiny = LinkedPolygon::from_points([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])?;
    /// assert!(matches!(tiny.translate(2f64.powi(1000), 0.0), Err(EditError::RoundingBreaksConvexity { .. })));
    /// assert_eq!(tiny.point(tiny.first())?, Point::new(0.0, 0.0)); // unchanged
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn translate(&mut self, dx: f64, dy: f64) -> Result<(), EditError> {
        let by = Point::new(dx, dy);
        if !by.is_finite() {
            return Err(EditError::NonFinite { point: by });
        }
        let moved = |p: Point| Point::new(p.x + dx, p.y + dy);
        // One pass in storage order: overflow, and whether every addition is exact
        // (Knuth's two-sum error is zero). An exact translation preserves every
        // orientation, so only a rounded one needs the boundary walk below.
        let mut exact = true;
        for node in &self.nodes {
            let (p, q) = (node.point, moved(node.point));
            if !q.is_finite() {
                return Err(EditError::NonFinite { point: q });
            }
            exact &= two_sum_error(p.x, dx, q.x) == 0.0 && two_sum_error(p.y, dy, q.y) == 0.0;
        }
        if !exact {
            self.check_translated(moved)?;
        }
        for node in &mut self.nodes {
            node.point = moved(node.point);
        }
        Ok(())
    }

    /// Checks exactly that the polygon with every vertex mapped by `f` is strictly convex,
    /// counter-clockwise and winds once, walking the boundary from position 0.
    fn check_translated(&self, f: impl Fn(Point) -> Point) -> Result<(), EditError> {
        use super::convex::upper;
        let start = 0;
        let (mut a, mut b) = (f(self.point_at(self.prev_at(start))), f(self.point_at(start)));
        let mut pos = start;
        let mut windings = 0;
        for _ in 0..self.len() {
            let next = self.next_at(pos);
            let c = f(self.point_at(next));
            if Exact.orient(a, b, c) != Orientation::Ccw {
                return Err(EditError::RoundingBreaksConvexity { point: b });
            }
            if !upper(a, b) && upper(b, c) {
                windings += 1;
            }
            (a, b, pos) = (b, c, next);
        }
        if windings != 1 {
            return Err(EditError::RoundingBreaksConvexity {
                point: f(self.point_at(start)),
            });
        }
        Ok(())
    }

    /// Whether `v` may sit between the vertices at positions a and b = next(a) (or
    /// replace the single vertex between them): strictly right of a→b, strict left
    /// turns at a and at b.
    fn fits_between(&self, a: usize, b: usize, v: Point) -> bool {
        let (pa, pb) = (self.nodes[a].point, self.nodes[b].point);
        let before_a = self.nodes[self.prev_at(a)].point;
        let after_b = self.nodes[self.next_at(b)].point;
        Exact.orient(pa, pb, v) == Orientation::Cw
            && Exact.orient(before_a, pa, v) == Orientation::Ccw
            && Exact.orient(v, pb, after_b) == Orientation::Ccw
    }

    fn bump_generation(&mut self) -> u64 {
        let g = self.next_generation;
        self.next_generation += 1;
        g
    }

    /// Vertices the arena can hold without reallocating (nodes and handle slots, the
    /// smaller of the two): with dense storage it tracks the largest size the polygon
    /// has had, never the number of edits.
    pub fn capacity(&self) -> usize {
        self.nodes.capacity().min(self.slots.capacity())
    }

    /// Memory held by the arena in bytes (nodes plus handle slots), for churn tests.
    pub fn arena_bytes(&self) -> usize {
        self.nodes.capacity() * std::mem::size_of::<Node>()
            + self.slots.capacity() * std::mem::size_of::<Slot>() * 2
    }

    /// A uniformly random vertex. O(1).
    pub fn random_vertex<R: Rng + ?Sized>(&self, rng: &mut R) -> VertexId {
        self.id_at(rng.random_range(0..self.len()))
    }

    /// `k` distinct uniformly random vertices (all of them when `k >= len`), as handles.
    /// Allocates; queries use [`sample_positions`](Self::sample_positions) with a workspace.
    pub fn sample<R: Rng + ?Sized>(&self, k: usize, rng: &mut R) -> Vec<VertexId> {
        let mut out = Vec::with_capacity(k.min(self.len()));
        self.sample_positions(k, rng, &mut SampleWorkspace::new(), &mut out);
        out.into_iter().map(|p| self.id_at(p as usize)).collect()
    }

    /// Appends to `out` the positions of `min(k, len)` distinct vertices, a uniformly
    /// random subset. Expected O(k): for k ≤ len/2, rejection sampling with marks in
    /// `workspace` (expected fewer than 2k draws); otherwise the len − k excluded
    /// positions are drawn the same way and the rest are listed, O(len) ≤ O(2k).
    /// The order of the returned positions is not uniform; the set is.
    pub fn sample_positions<R: Rng + ?Sized>(
        &self,
        k: usize,
        rng: &mut R,
        workspace: &mut SampleWorkspace,
        out: &mut Vec<u32>,
    ) {
        let n = self.len();
        if k >= n {
            out.extend(0..n as u32);
            return;
        }
        workspace.begin(n);
        if 2 * k <= n {
            let mut taken = 0;
            while taken < k {
                let i = rng.random_range(0..n);
                if workspace.mark(i) {
                    out.push(i as u32);
                    taken += 1;
                }
            }
        } else {
            let mut excluded = 0;
            while excluded < n - k {
                if workspace.mark(rng.random_range(0..n)) {
                    excluded += 1;
                }
            }
            let epoch = workspace.epoch;
            out.extend((0..n as u32).filter(|&i| workspace.stamps[i as usize] != epoch));
        }
    }

    /// The polygon as a sorted array, starting at [`first`](Self::first). O(n).
    pub fn to_convex(&self) -> ConvexPolygon {
        ConvexPolygon::from_ccw_unchecked(self.iter().map(|(_, p)| p).collect())
    }

    /// The point stored at position `pos` (positions are `0..len`, valid until the next edit).
    #[inline]
    pub fn point_at(&self, pos: usize) -> Point {
        self.nodes[pos].point
    }

    /// Position of the counter-clockwise successor of the vertex at `pos`.
    #[inline]
    pub fn next_at(&self, pos: usize) -> usize {
        self.nodes[pos].next as usize
    }

    /// Position of the counter-clockwise predecessor of the vertex at `pos`.
    #[inline]
    pub fn prev_at(&self, pos: usize) -> usize {
        self.nodes[pos].prev as usize
    }

    /// The stable handle of the vertex at `pos`.
    #[inline]
    pub fn id_at(&self, pos: usize) -> VertexId {
        let slot = self.nodes[pos].slot;
        VertexId {
            slot,
            generation: self.slots[slot as usize].generation,
        }
    }

    /// The current position of a vertex (valid until the next edit).
    pub fn position(&self, id: VertexId) -> Result<usize, EditError> {
        self.pos(id)
    }

    /// Checks every invariant: links are mutual inverses forming one cycle through all
    /// nodes, slots and nodes point at each other, the arena holds only live vertices,
    /// and the boundary is strictly convex, counter-clockwise, winding once. O(n).
    pub fn debug_validate(&self) -> Result<(), String> {
        let n = self.nodes.len();
        if n < 3 {
            return Err(format!("{n} vertices"));
        }
        if self.slots.len() != n {
            return Err(format!("{} slots for {n} nodes", self.slots.len()));
        }
        for (i, node) in self.nodes.iter().enumerate() {
            if node.next as usize >= n || node.prev as usize >= n {
                return Err(format!("node {i} links out of range"));
            }
            if self.nodes[node.next as usize].prev as usize != i {
                return Err(format!("node {i}: next.prev is not node {i}"));
            }
            match self.slots.get(node.slot as usize) {
                Some(s) if s.pos as usize == i => {}
                _ => return Err(format!("node {i}: its slot does not point back")),
            }
        }
        let mut pos = 0;
        for step in 1..=n {
            pos = self.next_at(pos);
            if pos == 0 && step != n {
                return Err(format!("the cycle through node 0 has {step} nodes, not {n}"));
            }
        }
        if pos != 0 {
            return Err("the boundary walk does not close".into());
        }
        self.to_convex().debug_validate()
    }
}

/// The rounding error of `s = a + b` (Knuth's two-sum): zero exactly when the sum was
/// exact. `a`, `b` and `s` finite.
fn two_sum_error(a: f64, b: f64, s: f64) -> f64 {
    let bb = s - a;
    (a - (s - bb)) + (b - bb)
}

/// Serialised as its vertex list, counter-clockwise from [`LinkedPolygon::first`];
/// deserialised through the same validation as [`LinkedPolygon::from_points`].
#[cfg(feature = "serde")]
impl serde::Serialize for LinkedPolygon {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.to_convex().serialize(s)
    }
}

#[cfg(feature = "serde")]
impl<'de> serde::Deserialize<'de> for LinkedPolygon {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        ConvexPolygon::deserialize(d).map(|p| LinkedPolygon::from_convex(&p))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand::rngs::SmallRng;

    fn square() -> LinkedPolygon {
        LinkedPolygon::from_points([[0., 0.], [4., 0.], [4., 4.], [0., 4.]]).unwrap()
    }

    #[test]
    fn removal_keeps_storage_dense_and_links_valid() {
        let mut rng = SmallRng::seed_from_u64(3);
        let n = 64;
        let pts: Vec<Point> = (0..n)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                Point::new(a.cos(), a.sin())
            })
            .collect();
        let mut p = LinkedPolygon::from_convex_shuffled(&ConvexPolygon::new(pts).unwrap(), &mut rng);
        p.debug_validate().unwrap();
        while p.len() > 3 {
            let v = p.random_vertex(&mut rng);
            p.remove(v).unwrap();
            p.debug_validate().unwrap();
            assert_eq!(p.point(v), Err(EditError::StaleHandle));
        }
        assert_eq!(p.remove(p.first()), Err(EditError::TooFewVertices));
    }

    #[test]
    fn stale_handles_never_alias_reused_slots() {
        let mut p = square();
        let a = p.first();
        let v = p.insert_after(a, Point::new(2., -1.)).unwrap();
        p.remove(v).unwrap();
        // The slab reuses the slot; the old handle must not see the new vertex.
        let w = p.insert_after(a, Point::new(2., -0.5)).unwrap();
        assert_eq!(v.slot, w.slot);
        assert_eq!(p.point(v), Err(EditError::StaleHandle));
        assert_eq!(
            p.move_vertex(v, Point::new(2., -0.25)),
            Err(EditError::StaleHandle)
        );
        assert_eq!(p.point(w), Ok(Point::new(2., -0.5)));
        let other = square();
        assert!(other.contains(other.first()));
    }

    #[test]
    fn refused_edits_change_nothing() {
        let mut p = square();
        let before: Vec<_> = p.iter().collect();
        let a = p.first(); // (0, 0); next is (4, 0)
        for bad in [
            Point::new(2., 0.),   // on the edge: collinear vertex
            Point::new(2., 1.),   // inside
            Point::new(5., -1.),  // beyond the line through the next edge
            Point::new(-1., -1.), // beyond the line through the previous edge
            Point::new(0., 0.),   // duplicate of a
            Point::new(f64::NAN, 0.),
        ] {
            assert!(p.insert_after(a, bad).is_err(), "{bad:?}");
            assert_eq!(p.iter().collect::<Vec<_>>(), before);
        }
        let b = p.next(a).unwrap(); // (4, 0)
        for bad in [
            Point::new(2., 2.),
            Point::new(4., 4.),
            Point::new(6., 5.),
            Point::new(0., -1.),
        ] {
            assert!(p.move_vertex(b, bad).is_err(), "{bad:?}");
            assert_eq!(p.iter().collect::<Vec<_>>(), before);
        }
        assert_eq!(p.move_vertex(b, Point::new(5., -1.)), Ok(Point::new(4., 0.)));
        p.debug_validate().unwrap();
    }

    #[cfg(feature = "serde")]
    #[test]
    fn serde_round_trip_validates() {
        let p = square();
        let text = serde_json::to_string(&p).unwrap();
        assert_eq!(
            text,
            r#"[{"x":0.0,"y":0.0},{"x":4.0,"y":0.0},{"x":4.0,"y":4.0},{"x":0.0,"y":4.0}]"#
        );
        let back: LinkedPolygon = serde_json::from_str(&text).unwrap();
        assert_eq!(back.to_convex(), p.to_convex());
        let bad = r#"[{"x":0,"y":0},{"x":4,"y":0},{"x":4,"y":4},{"x":2,"y":1},{"x":0,"y":4}]"#;
        let err = serde_json::from_str::<LinkedPolygon>(bad)
            .unwrap_err()
            .to_string();
        assert!(err.contains("vertex 3 is reflex"), "{err}");
    }

    #[test]
    fn moves_on_a_triangle_keep_orientation() {
        let mut t = LinkedPolygon::from_points([[0., 0.], [1., 0.], [0., 1.]]).unwrap();
        let v = t.next(t.first()).unwrap();
        // Moving (1,0) across the opposite side would flip the triangle: refused.
        assert!(t.move_vertex(v, Point::new(-1., 2.)).is_err());
        assert!(t.move_vertex(v, Point::new(3., 3.)).is_ok());
        t.debug_validate().unwrap();
    }

    #[test]
    fn sample_positions_are_distinct_and_complete() {
        let mut rng = SmallRng::seed_from_u64(9);
        let pts: Vec<Point> = (0..100)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / 100.0;
                Point::new(a.cos(), a.sin())
            })
            .collect();
        let p = LinkedPolygon::from_convex(&ConvexPolygon::new(pts).unwrap());
        let mut ws = SampleWorkspace::new();
        for k in [0, 1, 10, 50, 51, 99, 100, 500] {
            let mut out = Vec::new();
            p.sample_positions(k, &mut rng, &mut ws, &mut out);
            assert_eq!(out.len(), k.min(100));
            let mut s = out.clone();
            s.sort();
            s.dedup();
            assert_eq!(s.len(), out.len(), "k = {k}");
        }
    }
}
