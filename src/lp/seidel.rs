//! The incremental LP behind [`separating_line`]; the formulation is in the module docs
//! of [`crate::lp`].

use crate::kernel::{DirectedLine, Exact, Kernel, Orientation, Point, Sign};
use crate::polygon::LinkedPolygon;
use rand::Rng;
use std::fmt;

/// A finite indexed set of points: a slice, or arena positions of a [`LinkedPolygon`].
pub trait PointSet {
    /// The number of points.
    fn len(&self) -> usize;
    /// Point `i`, for `i < len()`.
    fn point(&self, i: usize) -> Point;
    /// Whether the set has no points.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The points as one contiguous slice, when they are stored so (then the LP copies
    /// them all at once instead of reading each on first use).
    fn as_slice(&self) -> Option<&[Point]> {
        None
    }
}

impl PointSet for [Point] {
    #[inline]
    fn len(&self) -> usize {
        <[Point]>::len(self)
    }
    #[inline]
    fn point(&self, i: usize) -> Point {
        self[i]
    }
    #[inline]
    fn as_slice(&self) -> Option<&[Point]> {
        Some(self)
    }
}

impl PointSet for Vec<Point> {
    #[inline]
    fn len(&self) -> usize {
        Vec::len(self)
    }
    #[inline]
    fn point(&self, i: usize) -> Point {
        self[i]
    }
    #[inline]
    fn as_slice(&self) -> Option<&[Point]> {
        Some(self)
    }
}

impl<T: PointSet + ?Sized> PointSet for &T {
    #[inline]
    fn len(&self) -> usize {
        (**self).len()
    }
    #[inline]
    fn point(&self, i: usize) -> Point {
        (**self).point(i)
    }
    #[inline]
    fn as_slice(&self) -> Option<&[Point]> {
        (**self).as_slice()
    }
}

/// The vertices of `polygon` stored at `positions` (arena positions, `0..len`), read in
/// place: point `i` of the set is `polygon.point_at(positions[i])`.
#[derive(Clone, Copy, Debug)]
pub struct ArenaPoints<'a> {
    /// The polygon whose arena holds the points.
    pub polygon: &'a LinkedPolygon,
    /// Arena positions of the points, each below `polygon.len()`.
    pub positions: &'a [u32],
}

impl PointSet for ArenaPoints<'_> {
    #[inline]
    fn len(&self) -> usize {
        self.positions.len()
    }
    #[inline]
    fn point(&self, i: usize) -> Point {
        self.polygon.point_at(self.positions[i] as usize)
    }
}

/// A separating line through two input points, directed from `start` to `end`, with every
/// point of A on its closed right side and every point of B on its closed left side.
/// `a` and `b` index the tangent points: `A[a]` and `B[b]` lie on the line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bitangent {
    /// The first point defining the line (an input point).
    pub start: Point,
    /// The second point defining the line (an input point), distinct from `start`.
    pub end: Point,
    /// Index in A of A's tangent point.
    pub a: usize,
    /// Index in B of B's tangent point.
    pub b: usize,
}

/// The answer of [`separating_line`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Separation {
    /// CH(A) ∩ CH(B) ≠ ∅ (a shared point, touching boundaries, crossing, containment).
    Intersecting,
    /// The hulls are disjoint; the line is an inner common tangent.
    Separated(Bitangent),
}

/// Invalid input to [`separating_line`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LpError {
    /// A or B has no points (the hull of an empty set is empty: nothing to separate).
    EmptySet,
    /// A or B has 2^31 points or more (indices are packed into 31 bits).
    TooLarge,
}

impl fmt::Display for LpError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LpError::EmptySet => f.write_str("separating_line needs two non-empty point sets"),
            LpError::TooLarge => f.write_str("separating_line accepts fewer than 2^31 points per set"),
        }
    }
}

impl std::error::Error for LpError {}

/// At most this many points make up the witness of intersecting hulls.
const WITNESS: usize = 9;

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

/// Scratch memory for [`separating_line`]: the points, copied once and shuffled in place
/// (24 bytes per point). Reuse it across
/// calls so the LP allocates nothing in the steady state.
#[derive(Clone, Debug, Default)]
pub struct LpWorkspace {
    items: Vec<Item>,
    /// Whether [`Separation::Intersecting`] answers record their witness.
    record: bool,
    /// Whether the caller has put the points in random order already
    /// ([`keep_order`](Self::keep_order)).
    keep_order: bool,
    /// The witness of the last recorded [`Separation::Intersecting`] answer.
    witness: Witness,
    /// Constraints examined (violation tests and one-dimensional steps) since creation:
    /// the LP's work, for experiments.
    pub work: u64,
    /// Calls whose result failed certification and was recomputed with [`Exact`]. Only an
    /// inconsistent kernel causes this; under [`Exact`] it stays 0 (the tests check).
    pub redone: u64,
}

impl LpWorkspace {
    /// An empty workspace (it grows to the largest input on first use).
    pub fn new() -> Self {
        Self::default()
    }

    /// Whether answers [`Separation::Intersecting`] record their witness
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

    /// After an answer [`Separation::Intersecting`] (recorded, see
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
    /// [`Separation::Intersecting`]. For a caller that learned of intersecting hulls
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

    /// After an answer [`Separation::Intersecting`] (recorded) found where the point p
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
    pub fn straddle(&self) -> Option<[WitnessPoint; 5]> {
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

    /// After an answer [`Separation::Intersecting`] (recorded) found where the point p
    /// that made the LP infeasible failed on one point y of the other set and one
    /// point x of its own (a mixed pair of bounds, both on one side of p in x′):
    /// `[y, p, x, t, p₀]`, where t is the previous optimum's tangent point in p's set
    /// and p₀ is a₀ if p is of A (else b₀). Then y lies between the previous optimum's
    /// line (p beyond it, x on or before it) and the ray from p through x, so it
    /// usually lies in the triangle p, x, t (and the caller tests that, falling back
    /// to [`witness`](Self::witness)). `None` for every other witness.
    pub fn mixed(&self) -> Option<[WitnessPoint; 5]> {
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

    /// After an answer [`Separation::Intersecting`] found by the incremental loop: every
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
struct Witness {
    points: [WitnessPoint; WITNESS],
    len: usize,
    /// How many leading items the incremental loop had examined (0 if another step
    /// found the intersection).
    examined: usize,
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
    fn record(
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

    fn set(&mut self, points: &[WitnessPoint], examined: usize) {
        self.len = points.len().min(WITNESS);
        self.points[..self.len].copy_from_slice(&points[..self.len]);
        self.examined = examined;
    }
}

impl WitnessPoint {
    fn of(item: Item) -> Self {
        WitnessPoint {
            point: item.p,
            in_b: item.enc & B_BIT != 0,
            index: Some((item.enc & !B_BIT) as usize),
        }
    }
}

const B_BIT: u32 = 1 << 31;

/// How far ahead of the incremental loop points are read from the input.
const LOOKAHEAD: usize = 12;

/// Decides whether CH(A) and CH(B) intersect and, if not, finds an inner common tangent.
///
/// See the [module docs](crate::lp) for the formulation.
///
/// # Complexity
/// Expected O(|A| + |B|) predicate calls over the random order drawn from `rng`, for every
/// input; worst case quadratic with vanishing probability. No allocation once `workspace`
/// has held an input of this size.
///
/// # Degeneracies
/// Touching hulls (a shared point, a point on the other's edge, overlapping collinear
/// edges) are [`Separation::Intersecting`]. Duplicates, collinear sets and single points
/// are valid input.
///
/// # Precision
/// Every decision is an `orient`, `cross` or `dot` predicate on input points: exact under
/// [`Exact`]. Under [`Fast`](crate::Fast) a result is certified with fast predicates and
/// recomputed with [`Exact`] when that certification fails.
///
/// # Errors
/// [`LpError::EmptySet`] when A or B is empty, [`LpError::TooLarge`] beyond 2^31 − 1 points.
///
/// ```
/// use polysect::{Exact, Kernel, Point, lp::{separating_line, LpWorkspace, Separation}};
/// use rand::{SeedableRng, rngs::SmallRng};
/// let a = [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(0.0, 1.0)];
/// let b = [Point::new(2.0, 2.0), Point::new(3.0, 2.0), Point::new(2.0, 3.0)];
/// let mut rng = SmallRng::seed_from_u64(1);
/// let mut ws = LpWorkspace::new();
/// match separating_line(Exact, &a[..], &b[..], &mut rng, &mut ws)? {
///     Separation::Separated(t) => {
///         // The tangent points lie on the line; A is on its right, B on its left.
///         assert_eq!(Exact.orient(t.start, t.end, a[t.a]), polysect::Orientation::Collinear);
///         assert_eq!(Exact.orient(t.start, t.end, b[t.b]), polysect::Orientation::Collinear);
///     }
///     Separation::Intersecting => unreachable!("the triangles are disjoint"),
/// }
/// let touching = [Point::new(1.0, 0.0), Point::new(5.0, 0.0), Point::new(5.0, 5.0)];
/// assert_eq!(separating_line(Exact, &a[..], &touching[..], &mut rng, &mut ws)?, Separation::Intersecting);
/// # Ok::<(), polysect::lp::LpError>(())
/// ```
pub fn separating_line<K, A, B, R>(
    kernel: K,
    a: &A,
    b: &B,
    rng: &mut R,
    workspace: &mut LpWorkspace,
) -> Result<Separation, LpError>
where
    K: Kernel,
    A: PointSet + ?Sized,
    B: PointSet + ?Sized,
    R: Rng + ?Sized,
{
    if a.is_empty() || b.is_empty() {
        return Err(LpError::EmptySet);
    }
    if a.len() >= B_BIT as usize || b.len() >= B_BIT as usize {
        return Err(LpError::TooLarge);
    }
    let lay = Layout {
        na: a.len(),
        nb: b.len(),
        interleaved: workspace.keep_order,
    };
    let src = Source { a, b };
    let LpWorkspace {
        items,
        work,
        redone,
        record,
        witness,
        ..
    } = workspace;
    // Contiguous inputs are copied at once, and the loops then read the items only.
    let slices = a.as_slice().zip(b.as_slice());
    list_items(lay, items, slices);
    // The examined prefix points into the items, which are about to change (the
    // witness points carry their own coordinates and indices).
    witness.examined = 0;
    // Recording and loading are chosen at compile time, so the plain instance carries
    // no trace of them.
    let first = match (slices.is_some(), *record) {
        (true, false) => solve::<K, R, Loaded, false>(kernel, &Loaded, items, lay, rng, work, witness),
        (true, true) => solve::<K, R, Loaded, true>(kernel, &Loaded, items, lay, rng, work, witness),
        (false, false) => solve::<K, R, _, false>(kernel, &src, items, lay, rng, work, witness),
        (false, true) => solve::<K, R, _, true>(kernel, &src, items, lay, rng, work, witness),
    };
    Ok(match first {
        Some(s) => s,
        // Only an inconsistent (fast) kernel gets here: redo it exactly.
        None => {
            *redone += 1;
            // `solve` reordered the items: list them again (loaded items are not
            // read again by `src`).
            list_items(lay, items, slices);
            let again = if *record {
                solve::<Exact, R, _, true>(Exact, &src, items, lay, rng, work, witness)
            } else {
                solve::<Exact, R, _, false>(Exact, &src, items, lay, rng, work, witness)
            };
            again.unwrap_or(Separation::Intersecting)
        }
    })
}

/// A directed line through two input points, with its direction for
/// [`Kernel::orient_line`] (the loops test many points against one line).
#[derive(Clone, Copy, Debug)]
struct Line {
    s: Point,
    e: Point,
    d: DirectedLine,
}

impl Line {
    #[inline]
    fn new(s: Point, e: Point) -> Self {
        Line {
            s,
            e,
            d: DirectedLine::new(s, e),
        }
    }

    /// `orient(s, e, x)`. A point that defines the line gives two equal products (an
    /// exact zero), which no filter certifies: such points cost a slow path, where
    /// [`ExactWithin`](crate::ExactWithin) answers them by comparing points, and the
    /// decided calls pay no comparison.
    #[inline]
    fn side<K: Kernel>(self, k: K, x: Point) -> Orientation {
        k.orient_line(&self.d, x)
    }
}

/// The outcome of a one-dimensional step.
enum Step {
    /// The new optimum, tight on the violating point and on `partner`; under an exact
    /// kernel also the extremes along it of the earlier points found on it.
    Line(Line, Item, Collinear),
    /// The constraints seen so far admit no separator: the hulls intersect. No line
    /// through the violating point satisfies these one or two earlier points.
    Infeasible(Item, Item),
    /// The kernel contradicted itself (fast kernel only).
    Inconsistent,
}

/// The outcome of the incremental loop.
enum StepOut {
    Line {
        line: Line,
        ta: u32,
        tb: u32,
        on_line: OnLine,
        last_change: usize,
    },
    /// The hulls intersect (the witness is recorded if asked for).
    Infeasible,
    Inconsistent,
}

/// A point copied into the workspace with its origin: index in A, or index in B | `B_BIT`.
#[derive(Clone, Copy, Debug, Default)]
struct Item {
    p: Point,
    enc: u32,
    /// Whether `p` has been read from the input yet.
    loaded: bool,
}

/// Where [`list_items`] puts the points of A and B: A's `na` first, then B's `nb`; or,
/// for a kept order ([`LpWorkspace::keep_order`]), alternately (a₀ b₀ a₁ b₁ …, then
/// the longer set's tail), so that the LP takes them alternately without moving them
/// again.
#[derive(Clone, Copy, Debug)]
struct Layout {
    na: usize,
    nb: usize,
    interleaved: bool,
}

impl Layout {
    /// The slot of A's point `i`.
    #[inline]
    fn a(self, i: usize) -> usize {
        if !self.interleaved {
            i
        } else {
            let m = self.na.min(self.nb);
            if i < m { 2 * i } else { m + i }
        }
    }

    /// The slot of B's point `j`.
    #[inline]
    fn b(self, j: usize) -> usize {
        if !self.interleaved {
            self.na + j
        } else {
            let m = self.na.min(self.nb);
            if j < m { 2 * j + 1 } else { m + j }
        }
    }
}

/// Lists A and B in `items` as `lay` says. Contiguous inputs (`slices`) are copied
/// at once. Otherwise no point is read yet: each is copied into its item when the LP
/// first reaches it, so the repeated passes read contiguous memory, and an LP that
/// stops early (intersecting hulls are usually found within a few dozen points) never
/// touches the rest of the input.
fn list_items(lay: Layout, items: &mut Vec<Item>, slices: Option<(&[Point], &[Point])>) {
    let (na, nb) = (lay.na as u32, lay.nb as u32);
    items.clear();
    items.reserve(lay.na + lay.nb);
    if let Some((a, b)) = slices {
        // Written in place (no per-item capacity check): pairs first when
        // interleaved, then A's rest, then B's rest.
        let loaded = |p, enc| Item { p, enc, loaded: true };
        items.resize(lay.na + lay.nb, Item::default());
        let m = if lay.interleaved { lay.na.min(lay.nb) } else { 0 };
        let (pairs, rest) = items.split_at_mut(2 * m);
        for ((pair, (&pa, &pb)), i) in pairs.chunks_exact_mut(2).zip(a.iter().zip(b)).zip(0..) {
            pair[0] = loaded(pa, i);
            pair[1] = loaded(pb, i | B_BIT);
        }
        let (rest_a, rest_b) = rest.split_at_mut(lay.na - m);
        for ((slot, &p), i) in rest_a.iter_mut().zip(&a[m..]).zip(m as u32..) {
            *slot = loaded(p, i);
        }
        for ((slot, &p), j) in rest_b.iter_mut().zip(&b[m..]).zip(m as u32..) {
            *slot = loaded(p, j | B_BIT);
        }
        return;
    }
    let item = |enc| Item {
        p: Point::new(0.0, 0.0),
        enc,
        loaded: false,
    };
    if lay.interleaved {
        let m = na.min(nb);
        for i in 0..m {
            items.push(item(i));
            items.push(item(i | B_BIT));
        }
        items.extend((m..na).map(item));
        items.extend((m..nb).map(|j| item(j | B_BIT)));
    } else {
        items.extend((0..na).map(item));
        items.extend((0..nb).map(|j| item(j | B_BIT)));
    }
}

/// Where the loops get an item's point.
trait Load {
    /// Whether points are read on first use (else every item holds its point).
    const LAZY: bool;
    /// The point of `it`, read now if it has not been.
    fn load(&self, it: &mut Item) -> Point;
}

/// Items listed with their points.
struct Loaded;

impl Load for Loaded {
    const LAZY: bool = false;
    #[inline(always)]
    fn load(&self, it: &mut Item) -> Point {
        it.p
    }
}

/// Reads items' points from the two input sets on first use.
struct Source<'s, A: ?Sized, B: ?Sized> {
    a: &'s A,
    b: &'s B,
}

impl<A: PointSet + ?Sized, B: PointSet + ?Sized> Load for Source<'_, A, B> {
    const LAZY: bool = true;
    #[inline]
    fn load(&self, it: &mut Item) -> Point {
        if !it.loaded {
            it.p = if it.enc & B_BIT == 0 {
                self.a.point(it.enc as usize)
            } else {
                self.b.point((it.enc & !B_BIT) as usize)
            };
            it.loaded = true;
        }
        it.p
    }
}

/// The LP on `items` (laid out as `lay` says). Moves the bounding points to the
/// front and, unless the layout keeps the caller's order, shuffles the rest. `None`
/// when the final certification fails (inconsistent kernel).
#[allow(clippy::too_many_arguments)]
fn solve<K: Kernel, R: Rng + ?Sized, S: Load, const RECORD: bool>(
    k: K,
    src: &S,
    items: &mut [Item],
    lay: Layout,
    rng: &mut R,
    work: &mut u64,
    witness: &mut Witness,
) -> Option<Separation> {
    let (s_a0, s_b0) = (lay.a(0), lay.b(0));
    let (a0, b0) = (src.load(&mut items[s_a0]), src.load(&mut items[s_b0]));
    if a0 == b0 {
        if RECORD {
            witness.set(&[WitnessPoint::of(items[s_a0]), WitnessPoint::of(items[s_b0])], 0);
        }
        return Some(Separation::Intersecting);
    }
    // x′(q) − x′(p) > 0  ⟺  d₀ × (q − p) < 0.
    let x_less = |p: Point, q: Point| k.cross(a0, b0, p, q) == Orientation::Cw;
    // Bounding constraints: any a ∈ A strictly x′-left of any b ∈ B bound the objective.
    // Scan A and B interleaved, keeping A's x′-minimum and B's x′-maximum so far, and stop
    // at the first such pair (usually within a few points). Only when none exists is the
    // whole input scanned: then the line through a₀ and b₀ separates.
    let (na, nb) = (lay.na, lay.nb);
    let (mut il, mut jr) = (s_a0, s_b0);
    let mut bounded = false;
    // i = 0 is (a₀, b₀) itself: equal x′, not bounding (and an exact zero, which is the
    // slowest case of an exact predicate, so it is not evaluated).
    for i in 1..na.max(nb) {
        if i < na {
            let s = lay.a(i);
            if x_less(src.load(&mut items[s]), items[il].p) {
                il = s;
            }
        }
        if i < nb {
            let s = lay.b(i);
            if x_less(items[jr].p, src.load(&mut items[s])) {
                jr = s;
            }
        }
        *work += 1;
        if x_less(items[il].p, items[jr].p) {
            bounded = true;
            break;
        }
    }
    let (al, br) = (items[il], items[jr]);
    let (line, ta, tb, on_line, checked) = if !bounded {
        // No point of A is x′-left of a point of B: the line through a₀ and b₀
        // (parallel to d₀) separates.
        let (pa, pb) = (items[s_a0].p, items[s_b0].p);
        (
            Line::new(a0, b0),
            items[s_a0].enc,
            items[s_b0].enc,
            OnLine::at(pa, pb),
            items.len(),
        )
    } else {
        // The bounding constraints first, then a uniformly random order of the rest
        // (or the caller's order).
        items.swap(0, il);
        items.swap(1, jr);
        if !lay.interleaved {
            for i in (3..items.len()).rev() {
                items.swap(i, rng.random_range(2..=i));
            }
        }
        match incremental::<K, S, RECORD>(
            k,
            src,
            Line::new(al.p, br.p),
            al,
            br,
            a0,
            b0,
            items,
            work,
            witness,
        ) {
            StepOut::Line {
                line,
                ta,
                tb,
                on_line,
                last_change,
                // An exact kernel's step tested every point before the last change against
                // the final line (and collected those on it): nothing is left to test.
            } => (line, ta, tb, on_line, if K::EXACT { 0 } else { last_change + 1 }),
            StepOut::Infeasible => return Some(Separation::Intersecting),
            StepOut::Inconsistent => return None,
        }
    };
    certify::<K, RECORD>(k, line, ta, tb, on_line, &items[..checked], work, witness)
}

/// The extreme points, along the current line, of each set's points found on it.
#[derive(Clone, Copy, Debug)]
struct OnLine {
    a_min: Point,
    a_max: Point,
    b_min: Point,
    b_max: Point,
}

impl OnLine {
    fn at(pa: Point, pb: Point) -> Self {
        OnLine {
            a_min: pa,
            a_max: pa,
            b_min: pb,
            b_max: pb,
        }
    }

    /// Adds `x`, a point on the directed line (s, e), to its set's extremes.
    #[inline]
    fn add<K: Kernel>(&mut self, k: K, s: Point, e: Point, x: Point, in_b: bool) {
        let (min, max) = if in_b {
            (&mut self.b_min, &mut self.b_max)
        } else {
            (&mut self.a_min, &mut self.a_max)
        };
        if x == *min || x == *max {
            return; // known, and an exact zero would take the kernel's slow path
        }
        if k.dot(s, e, *min, x) == Sign::Negative {
            *min = x;
        } else if k.dot(s, e, *max, x) == Sign::Positive {
            *max = x;
        }
    }
}

/// Points of each set found on a line, by their extremes along it (`None`: none yet):
/// what [`step`] collects of the earlier points for the line it returns, so that under
/// an exact kernel they need no second test.
#[derive(Clone, Copy, Debug, Default)]
struct Collinear {
    a: Option<(Point, Point)>,
    b: Option<(Point, Point)>,
}

impl Collinear {
    /// Adds `x`, a point on the directed line (s, e). Out of line: points on the line
    /// are rare, and the loops that find them are the LP's hottest.
    #[cold]
    #[inline(never)]
    fn add<K: Kernel>(&mut self, k: K, s: Point, e: Point, x: Point, in_b: bool) {
        let slot = if in_b { &mut self.b } else { &mut self.a };
        match slot {
            None => *slot = Some((x, x)),
            Some((min, max)) => {
                if x == *min || x == *max {
                    return;
                }
                if k.dot(s, e, *min, x) == Sign::Negative {
                    *min = x;
                } else if k.dot(s, e, *max, x) == Sign::Positive {
                    *max = x;
                }
            }
        }
    }

    /// Adds the extremes to `on_line` (points on the same line).
    fn merge_into<K: Kernel>(self, k: K, on_line: &mut OnLine, s: Point, e: Point) {
        for (set, in_b) in [(self.a, false), (self.b, true)] {
            if let Some((min, max)) = set {
                on_line.add(k, s, e, min, in_b);
                on_line.add(k, s, e, max, in_b);
            }
        }
    }
}

/// Seidel's loop: `items[0]` and `items[1]` are the bounding constraints (`al` ∈ A
/// strictly x′-left of `br` ∈ B), whose optimum is `line`; the rest is in random order.
/// Returns the final line, its encoded tangent points, the index of the last point that
/// changed the line, and the on-line extremes of the points after it (each of which was
/// tested against the final line).
#[allow(clippy::too_many_arguments)]
fn incremental<K: Kernel, S: Load, const RECORD: bool>(
    k: K,
    src: &S,
    mut line: Line,
    al: Item,
    br: Item,
    a0: Point,
    b0: Point,
    items: &mut [Item],
    work: &mut u64,
    witness: &mut Witness,
) -> StepOut {
    let (mut ta, mut tb) = ((al.enc, al.p), (br.enc, br.p));
    let mut on_line = OnLine::at(al.p, br.p);
    let mut last_change = 1;
    let mut w = 0u64;
    for t in 2..items.len() {
        // Read a point a few items ahead: its cache miss overlaps with this iteration.
        if S::LAZY
            && let Some(ahead) = items.get_mut(t + LOOKAHEAD)
        {
            src.load(ahead);
        }
        let p = src.load(&mut items[t]);
        let enc = items[t].enc;
        let in_b = enc & B_BIT != 0;
        let o = line.side(k, p);
        w += 1;
        let violated = if in_b {
            o == Orientation::Cw
        } else {
            o == Orientation::Ccw
        };
        if !violated {
            if o == Orientation::Collinear {
                on_line.add(k, line.s, line.e, p, in_b);
            }
            continue;
        }
        w += t as u64;
        let guess = if in_b { ta } else { tb };
        let guess = Item {
            p: guess.1,
            enc: guess.0,
            loaded: true,
        };
        match step(k, p, in_b, &items[..t], a0, b0, guess, &mut w) {
            Step::Line(l, partner, collinear) => {
                line = l;
                let partner_in_b = partner.enc & B_BIT != 0;
                if in_b {
                    tb = (enc, p);
                    if !partner_in_b {
                        ta = (partner.enc, partner.p);
                    }
                } else {
                    ta = (enc, p);
                    if partner_in_b {
                        tb = (partner.enc, partner.p);
                    }
                }
                on_line = OnLine::at(ta.1, tb.1);
                if K::EXACT {
                    collinear.merge_into(k, &mut on_line, line.s, line.e);
                }
                last_change = t;
            }
            Step::Infeasible(q, q2) => {
                *work += w;
                if RECORD {
                    witness.record([items[t], q, q2], [ta, tb], [a0, b0], [al, br], t + 1);
                }
                return StepOut::Infeasible;
            }
            Step::Inconsistent => {
                *work += w;
                return StepOut::Inconsistent;
            }
        }
    }
    *work += w;
    StepOut::Line {
        line,
        ta: ta.0,
        tb: tb.0,
        on_line,
        last_change,
    }
}

/// Where an earlier point q puts the slope of a line through the violating point p
/// (see [`step`]).
enum Bound {
    /// An upper bound: the line through p and q, directed into H (`from` x′-left).
    Upper(Point, Point),
    /// A lower bound (q ∈ A x′-right of p, or q ∈ B x′-left of p).
    Lower,
    /// No bound: q and p have the same x′ and q is on its side of every such line.
    Free,
    /// q and p have the same x′ and q is on the wrong side of every such line.
    Blocked,
}

/// Classifies an earlier point `q` (≠ `p`) for the one-dimensional LP through `p`.
#[inline(always)]
fn bound<K: Kernel>(k: K, p: Point, q: Point, q_in_b: bool, a0: Point, b0: Point) -> Bound {
    // Sign of x′(q − p); q − p = ±d₀ (p, q = a₀, b₀) is answered without the kernel.
    let sx = if (p == a0 && q == b0) || (p == b0 && q == a0) {
        Orientation::Collinear
    } else {
        k.cross(a0, b0, p, q)
    };
    // u × (q − p) must be ≥ 0 for q in B, ≤ 0 for q in A; with u = (1, s) that is
    // y′(q − p) − s·x′(q − p): upper bounds are B's points x′-right of p and A's
    // points x′-left of it.
    match sx {
        Orientation::Collinear => {
            let sy = k.dot(a0, b0, p, q);
            let ok = if q_in_b {
                sy != Sign::Negative
            } else {
                sy != Sign::Positive
            };
            if ok { Bound::Free } else { Bound::Blocked }
        }
        // x′(q − p) > 0
        Orientation::Cw if q_in_b => Bound::Upper(p, q),
        Orientation::Ccw if !q_in_b => Bound::Upper(q, p),
        _ => Bound::Lower,
    }
}

/// Whether `q` (of B if `q_in_b`) is strictly on the wrong side of the directed line
/// (`from`, `to`), and whether it is on the line.
#[inline(always)]
fn violates<K: Kernel>(k: K, line: &DirectedLine, q: Point, q_in_b: bool) -> (bool, bool) {
    let o = k.orient_line(line, q);
    let wrong = if q_in_b { Orientation::Cw } else { Orientation::Ccw };
    (o == wrong, o == Orientation::Collinear)
}

/// The one-dimensional LP: the most counter-clockwise direction in H of a line through
/// `p` that keeps every earlier point on its side. (Inlined into each instance of the
/// incremental loop.)
///
/// The optimum is the tightest upper bound, i.e. the line through p and the earlier
/// point it first meets when turned clockwise from the previous optimum's direction.
/// Rather than classifying every earlier point (upper or lower bound: one `cross`) and
/// comparing it with the tightest bound of its kind (a second one), each point is
/// tested against the line through p and the tightest upper bound so far, one
/// `orient`, which almost every point satisfies: only a violating point is
/// classified, and it is either a tighter upper bound (the line turns) or a lower
/// bound above the tightest upper bound (infeasible). A lower bound satisfied by an
/// earlier, steeper line may violate the final one, so the points before the last
/// turn are tested once more against the final line. `guess`, the previous optimum's
/// tangent point in the other set than p's, is usually the final bound or close to
/// it, so that pass is short. Adds the points tested again to `work`. Among points on
/// the final line, one of the other set than p is preferred as the partner (the
/// tangent points must be one of each set).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn step<K: Kernel>(
    k: K,
    p: Point,
    p_in_b: bool,
    earlier: &[Item],
    a0: Point,
    b0: Point,
    guess: Item,
    work: &mut u64,
) -> Step {
    // The tightest upper bound so far: its line and the point; plain locals
    // keep the hot loop free of memory traffic.
    let mut best: Option<(DirectedLine, Item)> = None;
    let g_in_b = guess.enc & B_BIT != 0;
    if guess.p != p
        && let Bound::Upper(from, to) = bound(k, p, guess.p, g_in_b, a0, b0)
    {
        best = Some((DirectedLine::new(from, to), guess));
    }
    // A point of the other set than the bound's on the current line, if any.
    let mut partner: Option<Item> = None;
    // Under an exact kernel, the points on the current line (for `certify`).
    let mut collinear = Collinear::default();
    // The points before this index were tested against an older line, or none.
    let mut recheck = 0;
    for (i, it) in earlier.iter().enumerate() {
        let q = it.p;
        let q_in_b = it.enc & B_BIT != 0;
        let opposite = q_in_b != p_in_b;
        if let Some((line, b)) = best {
            if it.enc == b.enc {
                continue; // the bound itself: on its line, and an exact zero is slow
            }
            // The line passes through p: a copy of p is on it, not a violator, and
            // is compared with p only there (the decided calls pay no comparison).
            let (wrong, on) = violates(k, &line, q, q_in_b);
            if !wrong {
                if on {
                    if K::EXACT {
                        collinear.add(k, line.from(), line.to(), q, q_in_b);
                    }
                    if q == p {
                        if opposite {
                            return Step::Infeasible(*it, *it); // a point of both sets
                        }
                    } else if opposite && partner.is_none() && (b.enc & B_BIT != 0) == p_in_b {
                        partner = Some(*it);
                    }
                }
                continue;
            }
        } else if q == p {
            if opposite {
                return Step::Infeasible(*it, *it); // a point of both sets
            }
            continue;
        }
        match bound(k, p, q, q_in_b, a0, b0) {
            Bound::Upper(from, to) => {
                best = Some((DirectedLine::new(from, to), *it));
                partner = None;
                collinear = Collinear::default();
                recheck = i;
            }
            Bound::Lower => {
                if let Some((_, b)) = best {
                    // Its slope exceeds the tightest upper bound's.
                    return Step::Infeasible(b, *it);
                }
                // Before any upper bound: tested in the second pass.
            }
            // Only an inconsistent kernel gets here with a bound violated.
            Bound::Free => {}
            Bound::Blocked => return Step::Infeasible(*it, *it),
        }
    }
    let Some((line, b)) = best else {
        // The bounding constraints always give an upper bound; only an inconsistent
        // kernel loses it.
        return Step::Inconsistent;
    };
    let b_opposite = (b.enc & B_BIT != 0) != p_in_b;
    *work += recheck as u64;
    for it in &earlier[..recheck] {
        let q = it.p;
        let q_in_b = it.enc & B_BIT != 0;
        if it.enc == b.enc {
            continue; // the bound
        }
        // A copy of p is on the line (of p's set: one of the other set returned
        // above), so it neither violates nor becomes the partner.
        let (wrong, on) = violates(k, &line, q, q_in_b);
        if !wrong {
            if on {
                if K::EXACT {
                    collinear.add(k, line.from(), line.to(), q, q_in_b);
                }
                if !b_opposite && partner.is_none() && q_in_b != p_in_b {
                    partner = Some(*it);
                }
            }
            continue;
        }
        return match bound(k, p, q, q_in_b, a0, b0) {
            Bound::Lower => Step::Infeasible(b, *it),
            Bound::Blocked => Step::Infeasible(*it, *it),
            // A tighter upper bound than the tightest: an inconsistent kernel.
            Bound::Upper(..) | Bound::Free => Step::Inconsistent,
        };
    }
    let partner = if b_opposite { b } else { partner.unwrap_or(b) };
    if K::EXACT {
        // The bound's own point, on its line, was skipped by the tests.
        collinear.add(k, line.from(), line.to(), b.p, b.enc & B_BIT != 0);
    }
    Step::Line(
        Line {
            s: line.from(),
            e: line.to(),
            d: line,
        },
        partner,
        collinear,
    )
}

/// Checks `items` against the line (the points not yet tested against it), adds those
/// on it to `on_line`, and compares the parts of the two sets on the line; overlapping
/// parts are the witness of intersecting hulls.
#[allow(clippy::too_many_arguments)]
fn certify<K: Kernel, const RECORD: bool>(
    k: K,
    line: Line,
    ta: u32,
    tb: u32,
    mut on_line: OnLine,
    items: &[Item],
    work: &mut u64,
    witness: &mut Witness,
) -> Option<Separation> {
    let Line { s, e, d } = line;
    // The tangent points are on the line (this fails only under an inconsistent kernel).
    if k.orient(s, e, on_line.a_min) != Orientation::Collinear
        || k.orient(s, e, on_line.b_min) != Orientation::Collinear
    {
        return None;
    }
    for &Item { p: x, enc, .. } in items {
        let in_b = enc & B_BIT != 0;
        match (k.orient_line(&d, x), in_b) {
            (Orientation::Ccw, false) | (Orientation::Cw, true) => return None,
            (Orientation::Collinear, _) => on_line.add(k, s, e, x, in_b),
            _ => {}
        }
    }
    *work += items.len() as u64;
    let OnLine {
        a_min,
        a_max,
        b_min,
        b_max,
    } = on_line;
    let overlap = k.dot(s, e, a_min, b_max) != Sign::Negative && k.dot(s, e, b_min, a_max) != Sign::Negative;
    Some(if overlap {
        if RECORD {
            let on = |point, in_b| WitnessPoint {
                point,
                in_b,
                index: None,
            };
            witness.set(
                &[
                    on(a_min, false),
                    on(a_max, false),
                    on(b_min, true),
                    on(b_max, true),
                ],
                0,
            );
        }
        Separation::Intersecting
    } else {
        Separation::Separated(Bitangent {
            start: s,
            end: e,
            a: ta as usize,
            b: (tb & !B_BIT) as usize,
        })
    })
}
