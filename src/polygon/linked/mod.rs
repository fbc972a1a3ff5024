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
//! Users hold [`VertexId`]s: the polygon's identity, a key into a `slab` of slots (each
//! slot records the node's current position) and a generation. The identity is drawn
//! from one process-wide counter when the polygon is built or cloned, so a handle from
//! another polygon is refused ([`EditError::ForeignHandle`]) instead of naming
//! whichever vertex sits in the same slot here. Slab keys are reused after removal; the
//! generation (a per-polygon counter, 64 bits, never reused) makes a stale handle an
//! error ([`EditError::StaleHandle`]) instead of an alias of some later vertex. Checking
//! a handle is one comparison more than the slab lookup; no edit touches the counter.
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

mod edits;
pub(crate) use edits::turn_margin;
pub(super) mod sampling;

use super::{ConvexPolygon, EditError, PolygonError};
use crate::kernel::{BoundingBox, Point};
use rand::Rng;
use slab::Slab;
use std::sync::atomic::{AtomicU64, Ordering};

/// A stable handle to a vertex of one [`LinkedPolygon`]. Stays valid until that vertex
/// is removed; afterwards every use is an [`EditError::StaleHandle`]. Given to any other
/// polygon (including a clone of its own), every use is an [`EditError::ForeignHandle`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct VertexId {
    owner: u64,
    generation: u64,
    slot: u32,
}

/// A process-wide unique identity, for the owner of handles (a polygon, a scene).
/// Cloning draws a fresh one: a clone is a new owner, and handles of the original are
/// foreign to it. One relaxed atomic increment per owner built (64 bits: never wraps in
/// practice; `AtomicU64` exists on every target the library builds for, wasm32 included).
#[derive(Debug, PartialEq, Eq)]
pub(crate) struct Identity(u64);

impl Identity {
    pub(crate) fn fresh() -> Self {
        static NEXT: AtomicU64 = AtomicU64::new(1);
        Identity(NEXT.fetch_add(1, Ordering::Relaxed))
    }

    #[inline]
    pub(crate) fn get(&self) -> u64 {
        self.0
    }
}

impl Clone for Identity {
    fn clone(&self) -> Self {
        Identity::fresh()
    }
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
/// Vertex handles ([`VertexId`]) belong to the polygon that issued them: another
/// polygon refuses them with [`EditError::ForeignHandle`]. A clone is another polygon
/// (same vertices, fresh handles: take them from the clone with [`first`](Self::first),
/// [`iter`](Self::iter) or [`next`](Self::next)).
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
/// // A handle of another polygon is refused, never applied to this one.
/// let other = LinkedPolygon::from_points([[10.0, 10.0], [11.0, 10.0], [11.0, 11.0]])?;
/// assert_eq!(p.remove(other.first()), Err(EditError::ForeignHandle));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct LinkedPolygon {
    owner: Identity,
    nodes: Vec<Node>,
    slots: Slab<Slot>,
    next_generation: u64,
    /// Inserts and removals since the arena was built in boundary order (its length for
    /// a shuffled build): each relinks O(1) nodes out of storage order. See
    /// [`arena_disorder`](Self::arena_disorder).
    relinks: usize,
}

impl LinkedPolygon {
    /// Validates and cleans `points` exactly as [`ConvexPolygon::new`] does, and links
    /// them in boundary order.
    ///
    /// # Errors
    /// The [`PolygonError`] that [`ConvexPolygon::new`] gives for the same points.
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
        Self::with_storage_order(polygon, &order, 0)
    }

    instrument_pub! {
        /// Links the vertices of `polygon`, stored in a uniformly random order of the
        /// arena (the thesis's shuffled linked lists, 4.3), so that walking the boundary
        /// jumps around memory as it does after a long edit history. O(n).
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn from_convex_shuffled<R: Rng + ?Sized>(polygon: &ConvexPolygon, rng: &mut R) -> Self {
            let mut order: Vec<u32> = (0..polygon.len() as u32).collect();
            for i in (1..order.len()).rev() {
                order.swap(i, rng.random_range(0..=i));
            }
            Self::with_storage_order(polygon, &order, polygon.len())
        }
    }

    /// Boundary vertex `i` is stored at position `order[i]`.
    fn with_storage_order(polygon: &ConvexPolygon, order: &[u32], relinks: usize) -> Self {
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
            owner: Identity::fresh(),
            nodes,
            slots,
            next_generation: n as u64,
            relinks,
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

    #[inline]
    fn pos(&self, id: VertexId) -> Result<usize, EditError> {
        if id.owner != self.owner.get() {
            return Err(EditError::ForeignHandle);
        }
        match self.slots.get(id.slot as usize) {
            Some(s) if s.generation == id.generation => Ok(s.pos as usize),
            _ => Err(EditError::StaleHandle),
        }
    }

    /// True while `id` names a live vertex of this polygon (false for a removed vertex
    /// and for a handle of another polygon). This asks about a handle, not whether a
    /// point lies in the polygon.
    ///
    /// ```
    /// use polysect::LinkedPolygon;
    /// let mut p = LinkedPolygon::from_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// let q = p.clone();
    /// let v = p.first();
    /// assert!(p.has_vertex(v));
    /// assert!(!q.has_vertex(v)); // a clone is another polygon
    /// p.remove(v)?;
    /// assert!(!p.has_vertex(v));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn has_vertex(&self, id: VertexId) -> bool {
        self.pos(id).is_ok()
    }

    /// The vertex's coordinates.
    ///
    /// # Errors
    /// [`EditError::StaleHandle`] or [`EditError::ForeignHandle`] when `id` is not a
    /// live vertex of this polygon.
    pub fn point(&self, id: VertexId) -> Result<Point, EditError> {
        self.pos(id).map(|p| self.nodes[p].point)
    }

    /// The counter-clockwise successor.
    ///
    /// # Errors
    /// [`EditError::StaleHandle`] or [`EditError::ForeignHandle`] when `id` is not a
    /// live vertex of this polygon.
    pub fn next(&self, id: VertexId) -> Result<VertexId, EditError> {
        self.pos(id).map(|p| self.id_at(self.next_at(p)))
    }

    /// The counter-clockwise predecessor.
    ///
    /// # Errors
    /// [`EditError::StaleHandle`] or [`EditError::ForeignHandle`] when `id` is not a
    /// live vertex of this polygon.
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
    ///
    /// # Panics
    /// Never: [`first`](Self::first) is always a live vertex.
    pub fn iter(&self) -> impl Iterator<Item = (VertexId, Point)> + '_ {
        self.iter_from(self.first()).expect("the first vertex is live")
    }

    /// The axis-aligned bounding box. O(n): one pass over the arena in storage order
    /// (sequential reads, no link chasing); the polygon keeps none, since every edit
    /// would have to maintain it. A [`Scene`](crate::store::Scene) keeps one per polygon
    /// ([`Scene::bounding_box`](crate::store::Scene::bounding_box), O(1)).
    ///
    /// ```
    /// use polysect::{LinkedPolygon, Point};
    /// let p = LinkedPolygon::from_points([[0.0, 1.0], [2.0, 0.0], [3.0, 4.0]])?;
    /// let b = p.bounding_box();
    /// assert_eq!((b.min, b.max), (Point::new(0.0, 0.0), Point::new(3.0, 4.0)));
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn bounding_box(&self) -> BoundingBox {
        // At least three vertices live, so the arena is never empty.
        let first = self.nodes[0].point;
        let mut b = BoundingBox::new(first, first);
        for node in &self.nodes[1..] {
            b.grow(node.point);
        }
        b
    }

    /// An estimate in [0, 1] of how far the arena's storage order is from boundary order:
    /// 0 when built in order and only moved since, 1 when shuffled. Each insert or
    /// removal breaks at most three links out of storage order, so the estimate is
    /// `min(1, 3 · relinks / len)`. Walks along the links slow down with it (cache
    /// misses instead of sequential reads), which the store's cost model prices. O(1).
    pub(crate) fn arena_disorder(&self) -> f64 {
        (3.0 * self.relinks as f64 / self.len() as f64).min(1.0)
    }

    /// True when position i's successor is position i + 1 (and the last position's is 0):
    /// walks may then read positions in order instead of following the links. O(1) for
    /// an arena built in order and only moved or translated since, else O(n) at worst
    /// (it stops at the first link out of order).
    pub(crate) fn in_boundary_order(&self) -> bool {
        if self.relinks == 0 {
            return true;
        }
        let n = self.nodes.len();
        self.nodes
            .iter()
            .enumerate()
            .all(|(i, node)| node.next as usize == if i + 1 == n { 0 } else { i + 1 })
    }

    instrument_pub! {
        /// Vertices the arena can hold without reallocating (nodes and handle slots, the
        /// smaller of the two): with dense storage it tracks the largest size the polygon
        /// has had, never the number of edits.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn capacity(&self) -> usize {
            self.nodes.capacity().min(self.slots.capacity())
        }
    }

    instrument_pub! {
        /// Memory held by the arena in bytes (nodes plus handle slots), for churn tests.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn arena_bytes(&self) -> usize {
            self.nodes.capacity() * std::mem::size_of::<Node>()
                + self.slots.capacity() * std::mem::size_of::<Slot>() * 2
        }
    }

    /// The polygon as a sorted array, starting at [`first`](Self::first). O(n): a copy
    /// in storage order when the arena is in boundary order (built in order and never
    /// relinked since: no dependent loads), else one walk along the links.
    pub fn to_convex(&self) -> ConvexPolygon {
        if self.in_boundary_order() {
            return ConvexPolygon::from_ccw_unchecked(self.nodes.iter().map(|node| node.point).collect());
        }
        let mut pos = 0;
        let walk = (0..self.len()).map(|_| {
            let node = &self.nodes[pos];
            pos = node.next as usize;
            node.point
        });
        ConvexPolygon::from_ccw_unchecked(walk.collect())
    }

    instrument_pub! {
        /// The point stored at position `pos` (positions are `0..len`, valid until the next edit).
        ///
        /// # Panics
        /// `pos` is not below [`len`](Self::len).
        #[inline]
        #[track_caller]
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn point_at(&self, pos: usize) -> Point {
            self.nodes[pos].point
        }
    }

    instrument_pub! {
        /// Position of the counter-clockwise successor of the vertex at `pos`.
        ///
        /// # Panics
        /// `pos` is not below [`len`](Self::len).
        #[inline]
        #[track_caller]
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn next_at(&self, pos: usize) -> usize {
            self.nodes[pos].next as usize
        }
    }

    instrument_pub! {
        /// Position of the counter-clockwise predecessor of the vertex at `pos`.
        ///
        /// # Panics
        /// `pos` is not below [`len`](Self::len).
        #[inline]
        #[track_caller]
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn prev_at(&self, pos: usize) -> usize {
            self.nodes[pos].prev as usize
        }
    }

    instrument_pub! {
        /// The stable handle of the vertex at `pos`.
        ///
        /// # Panics
        /// `pos` is not below [`len`](Self::len).
        #[inline]
        #[track_caller]
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn id_at(&self, pos: usize) -> VertexId {
            let slot = self.nodes[pos].slot;
            VertexId {
                owner: self.owner.get(),
                generation: self.slots[slot as usize].generation,
                slot,
            }
        }
    }

    instrument_pub! {
        /// The current position of a vertex (valid until the next edit).
        ///
        /// # Errors
        /// [`EditError::StaleHandle`] or [`EditError::ForeignHandle`] when `id` is not a
        /// live vertex of this polygon.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn position(&self, id: VertexId) -> Result<usize, EditError> {
            self.pos(id)
        }
    }

    instrument_pub! {
        /// Checks every invariant: links are mutual inverses forming one cycle through all
        /// nodes, slots and nodes point at each other, the arena holds only live vertices,
        /// and the boundary is strictly convex, counter-clockwise, winding once. O(n).
        ///
        /// # Errors
        /// A description of the first violated invariant.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn debug_validate(&self) -> Result<(), String> {
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
            if self.relinks == 0 && (0..n).any(|i| self.next_at(i) != (i + 1) % n) {
                return Err("no relinks recorded, but the arena is not in boundary order".into());
            }
            self.to_convex().debug_validate()
        }
    }
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
mod tests;
