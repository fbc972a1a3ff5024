//! Edits of a [`LinkedPolygon`]: insert, remove, move and translate, each checked in
//! O(1) against the neighbours (a translation, against its rounding) and refused, changing
//! nothing, when it would break strict convexity.

use super::{Identity, LinkedPolygon, Node, Slot, VertexId};
use crate::kernel::{Exact, Kernel, Orientation, Point};
use crate::polygon::EditError;

impl LinkedPolygon {
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

    /// The image of this polygon with every vertex mapped by `f`, built beside it as a
    /// twin (as [`translated_twin`](Self::translated_twin): the same owner and links, so
    /// every vertex handle of this polygon is valid on it), checked exactly to be
    /// strictly convex, counter-clockwise and winding once. `f` returns `None` where the
    /// image overflows. For a holder of a shape that shows its placed image through a
    /// shared reference and never edits the image itself. O(n): one pass in storage
    /// order, one walk along the links.
    ///
    /// # Errors
    /// [`EditError::NonFinite`] naming the first vertex (in storage order) whose image
    /// overflows; [`EditError::RoundingBreaksConvexity`] naming the first image vertex
    /// where the image is not strictly convex.
    pub(crate) fn mapped_twin(&self, f: impl Fn(Point) -> Option<Point>) -> Result<LinkedPolygon, EditError> {
        let mut nodes = self.nodes.clone();
        for node in &mut nodes {
            node.point = f(node.point).ok_or(EditError::NonFinite { point: node.point })?;
        }
        let twin = LinkedPolygon {
            owner: Identity(self.owner.get()),
            nodes,
            slots: self.slots.clone(),
            next_generation: self.next_generation,
            relinks: self.relinks,
        };
        twin.check_translation(0.0, 0.0)?;
        Ok(twin)
    }

    /// A twin (same identity, same vertex handles, same storage order) with every vertex
    /// mapped by `f`, nothing checked: the caller has proved the image strictly convex,
    /// counter-clockwise and winding once (a pose accepted by the scene). O(n), one
    /// sequential pass.
    pub(crate) fn mapped_twin_unchecked(&self, f: impl Fn(Point) -> Point) -> LinkedPolygon {
        let mut nodes = self.nodes.clone();
        for node in &mut nodes {
            node.point = f(node.point);
        }
        LinkedPolygon {
            owner: Identity(self.owner.get()),
            nodes,
            slots: self.slots.clone(),
            next_generation: self.next_generation,
            relinks: self.relinks,
        }
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
}

/// The rounding error of `s = a + b` (Knuth's two-sum): zero exactly when the sum was
/// exact. `a`, `b` and `s` finite.
pub(super) fn two_sum_error(a: f64, b: f64, s: f64) -> f64 {
    let bb = s - a;
    (a - (s - bb)) + (b - bb)
}

/// Checks exactly that the boundary `ring` (counter-clockwise, the vertex before its
/// first is `last`) with every vertex mapped by `f` is strictly convex,
/// counter-clockwise and winds once; the error names the first failing mapped vertex
/// from the ring's start, or its first vertex when the boundary would wind more than
/// once. On success returns the mapped boundary's rounding margin: the least
/// [`turn_margin`] of its turns.
pub(super) fn check_rounded_ring(
    last: Point,
    mut ring: impl Iterator<Item = Point>,
    f: impl Fn(Point) -> Point,
) -> Result<f64, EditError> {
    use crate::polygon::convex::upper;
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
