//! The reusable buffers of [`separating_line`](super::separating_line) and the witness
//! of intersecting hulls.

use super::B_BIT;
use super::points::Item;
use crate::kernel::Point;

/// At most this many points make up the witness of intersecting hulls.
pub(super) const WITNESS: usize = 9;

/// A point of the witness of intersecting hulls ([`LpWorkspace::witness`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WitnessPoint {
    /// The point itself.
    pub point: Point,
    /// Whether it belongs to B (else to A).
    pub in_b: bool,
    /// Its index in its set, when known (points collected on the final line are
    /// reported by coordinates only).
    pub index: Option<usize>,
}

/// Scratch memory for [`separating_line`](super::separating_line): the points, copied once and shuffled in place
/// (24 bytes per point). Reuse it across
/// calls so the LP allocates nothing in the steady state.
#[derive(Clone, Debug, Default)]
pub struct LpWorkspace {
    pub(super) items: Vec<Item>,
    /// Whether [`Separation::Intersecting`](super::Separation::Intersecting) answers record their witness.
    pub(super) record: bool,
    /// Whether the caller has put the points in random order already
    /// ([`keep_order`](Self::keep_order)).
    pub(super) keep_order: bool,
    /// The witness of the last recorded [`Separation::Intersecting`](super::Separation::Intersecting) answer.
    pub(super) witness: Witness,
    /// Constraints examined (violation tests and one-dimensional steps) since creation:
    /// the LP's work, for experiments.
    pub work: u64,
    /// Calls whose result failed certification and was recomputed with [`Exact`](crate::Exact). Only an
    /// inconsistent kernel causes this; under [`Exact`](crate::Exact) it stays 0 (the tests check).
    pub redone: u64,
}

impl LpWorkspace {
    /// An empty workspace (it grows to the largest input on first use).
    pub fn new() -> Self {
        Self::default()
    }

    /// Whether answers [`Separation::Intersecting`](super::Separation::Intersecting) record their witness
    /// ([`witness`](Self::witness), [`examined`](Self::examined)). Off by default: a
    /// recorded witness costs a few stores per intersecting answer.
    pub fn record_witness(&mut self, on: bool) {
        self.record = on;
    }

    /// Whether the LP keeps the order of the points as given instead of shuffling
    /// them (off by default). The thesis's variant (its 3.3.5): the caller randomises,
    /// so that points it knows to be in random order already (independent samples)
    /// are not shuffled again. After the two bounding points the LP takes A's and B's
    /// points alternately, each set in the caller's order (A's before B's would find
    /// intersecting hulls only after all of A). The expected-linear bound of the module
    /// docs assumes a uniform order of all points and holds only as far as the
    /// caller's order is random. Answers are the same either way (every decision is
    /// exact); only the work changes.
    pub fn keep_order(&mut self, on: bool) {
        self.keep_order = on;
    }

    /// After an answer [`Separation::Intersecting`](super::Separation::Intersecting) (recorded, see
    /// [`record_witness`](Self::record_witness)): at most nine points of A and B
    /// whose hulls already intersect (CH(A′) ∩ CH(B′) ≠ ∅), so that a constant-size
    /// search finds a point of one set in the other's hull or two crossing segments.
    /// They are the point that made the LP infeasible, the earlier points that bounded
    /// its one-dimensional problem and the two points the optimum before it was tight
    /// on (Seidel's lemma: no separator with a direction in the frame's half-circle H
    /// satisfies these), plus a₀, b₀ and the two bounding points, which rule out every
    /// other direction; or a point shared by both sets; or the points of both sets on a
    /// final line whose intervals overlap.
    pub fn witness(&self) -> impl Iterator<Item = WitnessPoint> + '_ {
        let w = &self.witness.points[..self.witness.len];
        w.iter()
            .enumerate()
            .filter(|&(i, x)| !w[..i].iter().any(|y| y.in_b == x.in_b && y.point == x.point))
            .map(|(_, &x)| x)
    }

    /// Drops the recorded witness: [`witness_points`](Self::witness_points) and
    /// [`examined`](Self::examined) are empty until the next recorded answer
    /// [`Separation::Intersecting`](super::Separation::Intersecting). For a caller that learned of intersecting hulls
    /// elsewhere (a walk along convex chains) and must not read an older LP's witness.
    pub fn forget_witness(&mut self) {
        self.witness.len = 0;
        self.witness.examined = 0;
    }

    /// The points of [`witness`](Self::witness) as recorded, repeats included (at most
    /// nine, in the same order): for callers that drop repeats themselves.
    pub fn witness_points(&self) -> &[WitnessPoint] {
        &self.witness.points[..self.witness.len]
    }

    /// After an answer [`Separation::Intersecting`](super::Separation::Intersecting) (recorded) found where the point p
    /// that made the LP infeasible failed on two points b and c of the other set: five
    /// points whose hulls already intersect, `[p, p₀, b, c, q₀]`, where p₀ is a₀ if p
    /// is of A (else b₀) and q₀ the other. The two points bound the one-dimensional
    /// problem on either side of p in x′ (an upper bound of the other set lies beyond
    /// p in x′ on one side, a lower bound on the other), and p lies strictly beyond
    /// their segment from that set's side: no line with a direction in the frame's
    /// half-circle H has p on its side and b, c on theirs, the frame's points a₀, b₀
    /// (equal x′, b₀ above a₀) rule out the opposite directions, and b, c on both
    /// sides of p rule out the direction of d₀ itself. The earlier points and the
    /// bounding pair are not needed. `None` for every other witness (a mixed pair of
    /// bounds needs the previous optimum's points: [`witness`](Self::witness)).
    pub(crate) fn straddle(&self) -> Option<[WitnessPoint; 5]> {
        let w = &self.witness;
        if w.len != WITNESS || w.points[0].index.is_none() {
            return None;
        }
        let [p, b, c, _, _, a0, b0, _, _] = w.points;
        // The same point twice is a point of both sets or a blocked one: not this case.
        let straddles = b.in_b == c.in_b && b.in_b != p.in_b && b.index != c.index;
        straddles.then_some(if p.in_b {
            [p, b0, b, c, a0]
        } else {
            [p, a0, b, c, b0]
        })
    }

    /// After an answer [`Separation::Intersecting`](super::Separation::Intersecting) (recorded) found where the point p
    /// that made the LP infeasible failed on one point y of the other set and one
    /// point x of its own (a mixed pair of bounds, both on one side of p in x′):
    /// `[y, p, x, t, p₀]`, where t is the previous optimum's tangent point in p's set
    /// and p₀ is a₀ if p is of A (else b₀). Then y lies between the previous optimum's
    /// line (p beyond it, x on or before it) and the ray from p through x, so it
    /// usually lies in the triangle p, x, t (and the caller tests that, falling back
    /// to [`witness`](Self::witness)). `None` for every other witness.
    pub(crate) fn mixed(&self) -> Option<[WitnessPoint; 5]> {
        let w = &self.witness;
        if w.len != WITNESS || w.points[0].index.is_none() {
            return None;
        }
        let [p, b, c, ta, tb, a0, b0, _, _] = w.points;
        if b.in_b == c.in_b {
            return None;
        }
        let (y, x) = if b.in_b == p.in_b { (c, b) } else { (b, c) };
        Some(if p.in_b {
            [y, p, x, tb, b0]
        } else {
            [y, p, x, ta, a0]
        })
    }

    /// After an answer [`Separation::Intersecting`](super::Separation::Intersecting) found by the incremental loop: every
    /// point it had examined (a few dozen, usually), whose hulls intersect; a superset
    /// of [`witness`](Self::witness) that more often holds a point of one set inside
    /// the other's hull. Empty when the answer came from elsewhere.
    pub fn examined(&self) -> impl Iterator<Item = WitnessPoint> + '_ {
        self.items[..self.witness.examined.min(self.items.len())]
            .iter()
            .map(|&it| WitnessPoint::of(it))
    }
}

/// The witness of intersecting hulls, as [`LpWorkspace::witness`] and
/// [`LpWorkspace::examined`] report it.
#[derive(Clone, Debug)]
pub(super) struct Witness {
    pub(super) points: [WitnessPoint; WITNESS],
    pub(super) len: usize,
    /// How many leading items the incremental loop had examined (0 if another step
    /// found the intersection).
    pub(super) examined: usize,
}

impl Default for Witness {
    fn default() -> Self {
        let none = WitnessPoint {
            point: Point::default(),
            in_b: false,
            index: None,
        };
        Witness {
            points: [none; WITNESS],
            len: 0,
            examined: 0,
        }
    }
}

impl Witness {
    /// Records the witness of an infeasible step, each point written in its slot
    /// (no array of the whole witness is built and copied): the violating point and
    /// its one or two bounds, the previous optimum's tangent points (encoded, with
    /// their points), a₀ and b₀, and the bounding pair.
    #[inline(always)]
    pub(super) fn record(
        &mut self,
        [x, q, q2]: [Item; 3],
        [ta, tb]: [(u32, Point); 2],
        [a0, b0]: [Point; 2],
        [al, br]: [Item; 2],
        examined: usize,
    ) {
        let of = |enc: u32, point: Point| WitnessPoint {
            point,
            in_b: enc & B_BIT != 0,
            index: Some((enc & !B_BIT) as usize),
        };
        let w = &mut self.points;
        w[0] = of(x.enc, x.p);
        w[1] = of(q.enc, q.p);
        w[2] = of(q2.enc, q2.p);
        w[3] = of(ta.0, ta.1);
        w[4] = of(tb.0, tb.1);
        w[5] = of(0, a0);
        w[6] = of(B_BIT, b0);
        w[7] = of(al.enc, al.p);
        w[8] = of(br.enc, br.p);
        self.len = WITNESS;
        self.examined = examined;
    }

    pub(super) fn set(&mut self, points: &[WitnessPoint], examined: usize) {
        self.len = points.len().min(WITNESS);
        self.points[..self.len].copy_from_slice(&points[..self.len]);
        self.examined = examined;
    }
}

impl WitnessPoint {
    pub(super) fn of(item: Item) -> Self {
        WitnessPoint {
            point: item.p,
            in_b: item.enc & B_BIT != 0,
            index: Some((item.enc & !B_BIT) as usize),
        }
    }
}
