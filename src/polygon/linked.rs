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

use super::{ConvexPolygon, EditError, PolygonError};
use crate::kernel::{Exact, Kernel, Orientation, Point};
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

/// Scratch memory for [`LinkedPolygon::sample_positions`], reused across queries so a
/// query allocates nothing in the steady state. Holds one `u32` stamp per vertex of the
/// largest polygon sampled so far.
#[derive(Clone, Debug, Default)]
pub struct SampleWorkspace {
    stamps: Vec<u32>,
    epoch: u32,
}

impl SampleWorkspace {
    /// An empty workspace; it grows to the largest polygon sampled with it.
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

    /// Links the vertices of `polygon`, stored in a uniformly random order of the
    /// arena (the thesis's shuffled linked lists, 4.3), so that walking the boundary
    /// jumps around memory as it does after a long edit history. O(n).
    pub fn from_convex_shuffled<R: Rng + ?Sized>(polygon: &ConvexPolygon, rng: &mut R) -> Self {
        let mut order: Vec<u32> = (0..polygon.len() as u32).collect();
        for i in (1..order.len()).rev() {
            order.swap(i, rng.random_range(0..=i));
        }
        Self::with_storage_order(polygon, &order, polygon.len())
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
        let owner = self.owner.get();
        self.nodes.push(Node {
            point,
            next: b as u32,
            prev: a as u32,
            slot,
        });
        self.nodes[a].next = pos;
        self.nodes[b].prev = pos;
        self.relinks = self.relinks.saturating_add(1);
        Ok(VertexId {
            owner,
            generation,
            slot,
        })
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
        self.relinks = self.relinks.saturating_add(1);
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
        if exact {
            self.translate_unchecked(dx, dy);
            return Ok(());
        }
        self.translate_finite(dx, dy).map(|_| ())
    }

    /// [`translate`](Self::translate) when the caller knows that no translated coordinate
    /// overflows (`dx`, `dy` finite, and, say, the translated bounding box finite): the
    /// rounded boundary checked along the links ([`check_translation`](Self::check_translation)),
    /// then every vertex translated. O(n).
    ///
    /// Returns the translated polygon's rounding margin ([`turn_margin`], the least over its
    /// turns): any later translation whose
    /// rounding moves no coordinate by `margin` or more keeps it strictly convex.
    pub(crate) fn translate_finite(&mut self, dx: f64, dy: f64) -> Result<f64, EditError> {
        let margin = self.check_translation(dx, dy)?;
        self.translate_unchecked(dx, dy);
        Ok(margin)
    }

    /// Whether translating by `(dx, dy)`, each coordinate rounded, keeps the polygon
    /// strictly convex, counter-clockwise and winding once, decided exactly on the
    /// rounded coordinates by a walk along the links; changes nothing. On success, the
    /// translated polygon's rounding margin (as [`translate_finite`](Self::translate_finite)).
    /// No translated coordinate may overflow (the caller's guarantee). O(n).
    pub(crate) fn check_translation(&self, dx: f64, dy: f64) -> Result<f64, EditError> {
        let mut pos = 0;
        let walk = (0..self.len()).map(|_| {
            let here = self.point_at(pos);
            pos = self.next_at(pos);
            here
        });
        check_rounded_ring(self.point_at(self.prev_at(0)), walk, |p| {
            Point::new(p.x + dx, p.y + dy)
        })
    }

    /// [`check_translation`](Self::check_translation) on `ring`, a convex polygon's
    /// vertices counter-clockwise (an array snapshot of a linked polygon: the same points,
    /// read sequentially instead of along the links). O(n).
    pub(crate) fn check_translated_ring(ring: &[Point], dx: f64, dy: f64) -> Result<f64, EditError> {
        let Some(&last) = ring.last() else {
            return Ok(0.0);
        };
        check_rounded_ring(last, ring.iter().copied(), |p| Point::new(p.x + dx, p.y + dy))
    }

    /// Translates every vertex without checking anything: for callers that have proved
    /// the rounded polygon strictly convex (a margin from [`translate_finite`]) and no
    /// coordinate overflowing. O(n), one sequential pass.
    pub(crate) fn translate_unchecked(&mut self, dx: f64, dy: f64) {
        for node in &mut self.nodes {
            node.point = Point::new(node.point.x + dx, node.point.y + dy);
        }
    }

    /// Applies the translations `steps` in order to every vertex, unchecked: each
    /// coordinate gets the same IEEE additions, in the same order, as one
    /// [`translate_unchecked`](Self::translate_unchecked) per step, so the result is
    /// bit-for-bit theirs, in one sequential pass over the arena. For callers that have
    /// checked every step when it was asked for. O(n · steps).
    pub(crate) fn translate_steps_unchecked(&mut self, steps: &[Point]) {
        for node in &mut self.nodes {
            let mut p = node.point;
            for d in steps {
                p = Point::new(p.x + d.x, p.y + d.y);
            }
            node.point = p;
        }
    }

    /// The polygon as [`translate_steps_unchecked`](Self::translate_steps_unchecked)
    /// would leave it, built beside it: the same polygon at the same stage of its
    /// history, so it keeps the owner's identity and every vertex handle of this polygon
    /// is valid on it (unlike a clone, which is another polygon). For a holder that must
    /// show translated coordinates through a shared reference and later replaces this
    /// polygon with the copy; never two live owners of edits. O(n · steps).
    pub(crate) fn translated_twin(&self, steps: &[Point]) -> LinkedPolygon {
        let mut twin = LinkedPolygon {
            owner: Identity(self.owner.get()),
            nodes: self.nodes.clone(),
            slots: self.slots.clone(),
            next_generation: self.next_generation,
            relinks: self.relinks,
        };
        twin.translate_steps_unchecked(steps);
        twin
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
            owner: self.owner.get(),
            generation: self.slots[slot as usize].generation,
            slot,
        }
    }

    /// The current position of a vertex (valid until the next edit).
    ///
    /// # Errors
    /// [`EditError::StaleHandle`] or [`EditError::ForeignHandle`] when `id` is not a
    /// live vertex of this polygon.
    pub fn position(&self, id: VertexId) -> Result<usize, EditError> {
        self.pos(id)
    }

    /// Checks every invariant: links are mutual inverses forming one cycle through all
    /// nodes, slots and nodes point at each other, the arena holds only live vertices,
    /// and the boundary is strictly convex, counter-clockwise, winding once. O(n).
    ///
    /// # Errors
    /// A description of the first violated invariant.
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
        if self.relinks == 0 && (0..n).any(|i| self.next_at(i) != (i + 1) % n) {
            return Err("no relinks recorded, but the arena is not in boundary order".into());
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

/// Checks exactly that the boundary `ring` (counter-clockwise, the vertex before its
/// first is `last`) with every vertex mapped by `f` is strictly convex,
/// counter-clockwise and winds once; the error names the first failing mapped vertex
/// from the ring's start, or its first vertex when the boundary would wind more than
/// once. On success returns the mapped boundary's rounding margin: the least
/// [`turn_margin`] of its turns.
fn check_rounded_ring(
    last: Point,
    mut ring: impl Iterator<Item = Point>,
    f: impl Fn(Point) -> Point,
) -> Result<f64, EditError> {
    use super::convex::upper;
    let Some(first) = ring.next() else {
        return Ok(0.0);
    };
    let (mut a, mut b) = (f(last), f(first));
    let mut windings = 0;
    let mut margin = f64::INFINITY;
    for c in ring.map(&f).chain(std::iter::once(f(first))) {
        if Exact.orient(a, b, c) != Orientation::Ccw {
            return Err(EditError::RoundingBreaksConvexity { point: b });
        }
        if !upper(a, b) && upper(b, c) {
            windings += 1;
        }
        margin = margin.min(turn_margin(a, b, c));
        (a, b) = (b, c);
    }
    if windings != 1 {
        return Err(EditError::RoundingBreaksConvexity { point: f(first) });
    }
    Ok(margin)
}

/// A lower bound on `L / (2·S + 8)` for the turn a → b → c: L a lower bound on the exact
/// determinant D = (b − a) × (c − b), S an upper bound on ‖b − a‖₁ + ‖c − b‖₁; zero when
/// the floating-point evaluation cannot certify D > 0.
///
/// # Why it is a rounding margin
/// Move every vertex by at most δ ≤ 1 in each coordinate: each edge vector moves by at
/// most 2δ per coordinate, so D changes by at most 2δ·(‖u‖₁ + ‖v‖₁) + 8δ² ≤ δ·(2S + 8).
/// If δ is below this bound for every turn, every turn stays strictly left all along the
/// straight-line motion, so the total turning, a multiple of 2π that varies
/// continuously, stays 2π: the moved polygon is strictly convex and winds once. A
/// rounded translation moves every vertex by at most half an ulp of its new coordinates
/// from the exact translate, which preserves D. After such a move the bound for the
/// moved polygon is at least (m − δ) / (1 + 2δ) for the old bound m, which the caller
/// uses to skip checks of the next translations.
///
/// # Precision
/// D is evaluated in floating point as u_x·v_y − u_y·v_x on rounded differences; its
/// error is below 3.01ε·(|u_x·v_y| + |u_y·v_x|) (Shewchuk's bound for orient2d); we
/// subtract 8ε times that sum, and widen S by a factor 1 + 8ε, then shrink the ratio by
/// 1 − 8ε, so every rounding is covered with room to spare. Where the products could
/// leave the normal range (overflow, or underflow that voids relative bounds) the margin
/// is zero: no check is ever skipped on its strength.
pub(crate) fn turn_margin(a: Point, b: Point, c: Point) -> f64 {
    const EPS: f64 = f64::EPSILON / 2.0;
    let (ux, uy, vx, vy) = (b.x - a.x, b.y - a.y, c.x - b.x, c.y - b.y);
    let (l, r) = (ux * vy, uy * vx);
    let size = l.abs() + r.abs();
    if size.is_nan() || size < 1e-270 {
        return 0.0;
    }
    let lower = (l - r) - 8.0 * EPS * (l.abs() + r.abs());
    let s = (ux.abs() + uy.abs() + vx.abs() + vy.abs()) * (1.0 + 8.0 * EPS);
    let m = lower / (2.0 * s + 8.0) * (1.0 - 8.0 * EPS);
    if m.is_finite() && m > 0.0 { m } else { 0.0 }
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
        assert!(other.has_vertex(other.first()));
    }

    #[test]
    fn a_handle_of_another_polygon_is_refused_by_every_method() {
        let mut a = square();
        let b = LinkedPolygon::from_points([[10., 10.], [11., 10.], [11., 11.]]).unwrap();
        // The same slot and generation exist in `a`: only the owner tells them apart.
        let vb = b.next(b.first()).unwrap();
        let twin = a.next(a.first()).unwrap();
        assert_eq!((vb.slot, vb.generation), (twin.slot, twin.generation));
        let copy = a.clone();
        let from_copy = copy.first();
        let before: Vec<_> = a.iter().map(|(_, p)| p).collect();
        for foreign in [vb, from_copy] {
            assert!(!a.has_vertex(foreign));
            assert_eq!(a.point(foreign), Err(EditError::ForeignHandle));
            assert_eq!(a.next(foreign), Err(EditError::ForeignHandle));
            assert_eq!(a.prev(foreign), Err(EditError::ForeignHandle));
            assert_eq!(a.position(foreign), Err(EditError::ForeignHandle));
            assert!(matches!(a.iter_from(foreign), Err(EditError::ForeignHandle)));
            assert_eq!(
                a.insert_after(foreign, Point::new(2., -1.)),
                Err(EditError::ForeignHandle)
            );
            assert_eq!(a.remove(foreign), Err(EditError::ForeignHandle));
            assert_eq!(
                a.move_vertex(foreign, Point::new(5., -1.)),
                Err(EditError::ForeignHandle)
            );
        }
        assert_eq!(a.iter().map(|(_, p)| p).collect::<Vec<_>>(), before);
        // The original's handles are foreign to the clone too, and each polygon still
        // accepts its own.
        assert_eq!(copy.point(a.first()), Err(EditError::ForeignHandle));
        assert!(copy.has_vertex(from_copy) && a.has_vertex(twin) && b.has_vertex(vb));
        // A removed vertex of this polygon stays stale, not foreign.
        let v = a.insert_after(a.first(), Point::new(2., -1.)).unwrap();
        a.remove(v).unwrap();
        assert_eq!(a.point(v), Err(EditError::StaleHandle));
        a.debug_validate().unwrap();
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
        assert_eq!(text, "[[0.0,0.0],[4.0,0.0],[4.0,4.0],[0.0,4.0]]");
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
