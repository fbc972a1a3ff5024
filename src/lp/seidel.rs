//! The incremental LP behind [`separating_line`]; the formulation is in the module docs
//! of [`crate::lp`].

use crate::kernel::{Exact, Kernel, Orientation, Point, Sign};
use crate::polygon::LinkedPolygon;
use rand::Rng;
use std::fmt;

/// A finite indexed set of points: a slice, or arena positions of a [`LinkedPolygon`].
pub trait PointSet {
    fn len(&self) -> usize;
    fn point(&self, i: usize) -> Point;
    fn is_empty(&self) -> bool {
        self.len() == 0
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
}

/// The vertices of `polygon` stored at `positions` (arena positions, `0..len`), read in
/// place: point `i` of the set is `polygon.point_at(positions[i])`.
#[derive(Clone, Copy, Debug)]
pub struct ArenaPoints<'a> {
    pub polygon: &'a LinkedPolygon,
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
    pub start: Point,
    pub end: Point,
    pub a: usize,
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

/// Scratch memory for [`separating_line`]: the random constraint order. Reuse it across
/// calls so the LP allocates nothing in the steady state.
#[derive(Clone, Debug, Default)]
pub struct LpWorkspace {
    order: Vec<u32>,
    /// Constraints examined (violation tests and one-dimensional steps) since creation:
    /// the LP's work, for experiments.
    pub work: u64,
    /// Calls whose result failed certification and was recomputed with [`Exact`]. Only an
    /// inconsistent kernel causes this; under [`Exact`] it stays 0 (the tests check).
    pub redone: u64,
}

impl LpWorkspace {
    pub fn new() -> Self {
        Self::default()
    }
}

const B_BIT: u32 = 1 << 31;

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
    let lp = Lp { k: kernel, a, b };
    Ok(match lp.solve(rng, workspace) {
        Some(s) => s,
        // Only an inconsistent (fast) kernel gets here: redo it exactly.
        None => {
            workspace.redone += 1;
            let exact = Lp { k: Exact, a, b };
            exact.solve(rng, workspace).unwrap_or(Separation::Intersecting)
        }
    })
}

struct Lp<'s, K, A: ?Sized, B: ?Sized> {
    k: K,
    a: &'s A,
    b: &'s B,
}

/// A directed line through two input points.
#[derive(Clone, Copy, Debug)]
struct Line {
    s: Point,
    e: Point,
}

/// The outcome of a one-dimensional step.
enum Step {
    /// The new optimum, tight on the violating point and on `partner` (an encoded index).
    Line(Line, u32),
    /// The constraints seen so far admit no separator: the hulls intersect.
    Infeasible,
    /// The kernel contradicted itself (fast kernel only).
    Inconsistent,
}

/// The outcome of the incremental loop.
enum StepOut {
    Line(Line, u32, u32),
    Infeasible,
    Inconsistent,
}

/// A bound on the slope from the line through the violating point and an earlier point:
/// its direction (normalised to point into H) and whether the earlier point belongs to
/// the other set.
#[derive(Clone, Copy)]
struct Bound {
    from: Point,
    to: Point,
    q: u32,
    opposite: bool,
}

impl<K: Kernel, A: PointSet + ?Sized, B: PointSet + ?Sized> Lp<'_, K, A, B> {
    #[inline]
    fn point(&self, enc: u32) -> Point {
        if enc & B_BIT == 0 {
            self.a.point(enc as usize)
        } else {
            self.b.point((enc & !B_BIT) as usize)
        }
    }

    /// `None` when a final certification fails (inconsistent kernel).
    fn solve<R: Rng + ?Sized>(&self, rng: &mut R, ws: &mut LpWorkspace) -> Option<Separation> {
        let k = self.k;
        let (a0, b0) = (self.a.point(0), self.b.point(0));
        if a0 == b0 {
            return Some(Separation::Intersecting);
        }
        // x′(q) − x′(p) > 0  ⟺  d₀ × (q − p) < 0.
        let x_less = |p: Point, q: Point| k.cross(a0, b0, p, q) == Orientation::Cw;
        let mut il = 0;
        for i in 1..self.a.len() {
            if x_less(self.a.point(i), self.a.point(il)) {
                il = i;
            }
        }
        let mut jr = 0;
        for j in 1..self.b.len() {
            if x_less(self.b.point(jr), self.b.point(j)) {
                jr = j;
            }
        }
        ws.work += (self.a.len() + self.b.len()) as u64;
        let (al, br) = (self.a.point(il), self.b.point(jr));
        let (line, ta, tb) = if !x_less(al, br) {
            // No point of A is x′-left of a point of B: the line through a₀ and b₀
            // (parallel to d₀) separates.
            (Line { s: a0, e: b0 }, 0, 0)
        } else {
            match self.incremental(
                Line { s: al, e: br },
                il as u32,
                jr as u32 | B_BIT,
                a0,
                b0,
                rng,
                ws,
            ) {
                StepOut::Line(l, ta, tb) => (l, ta as usize, tb as usize),
                StepOut::Infeasible => return Some(Separation::Intersecting),
                StepOut::Inconsistent => return None,
            }
        };
        self.certify(line, ta, tb, ws)
    }

    /// Seidel's loop over a random order, starting from the optimum of the two bounding
    /// constraints (A[il] and B[jr], encoded). Returns the final line and the indices of
    /// its tangent points in A and in B.
    #[allow(clippy::too_many_arguments)]
    fn incremental<R: Rng + ?Sized>(
        &self,
        mut line: Line,
        il: u32,
        jr: u32,
        a0: Point,
        b0: Point,
        rng: &mut R,
        ws: &mut LpWorkspace,
    ) -> StepOut {
        let k = self.k;
        let order = &mut ws.order;
        order.clear();
        order.push(il);
        order.push(jr);
        order.extend((0..self.a.len() as u32).filter(|&i| i != il));
        order.extend((0..self.b.len() as u32).map(|j| j | B_BIT).filter(|&j| j != jr));
        for i in (3..order.len()).rev() {
            let j = rng.random_range(2..=i);
            order.swap(i, j);
        }
        let (mut ta, mut tb) = (il, jr & !B_BIT);
        let mut work = 0u64;
        for t in 2..order.len() {
            let enc = order[t];
            let p = self.point(enc);
            let in_b = enc & B_BIT != 0;
            let o = k.orient(line.s, line.e, p);
            work += 1;
            let violated = if in_b {
                o == Orientation::Cw
            } else {
                o == Orientation::Ccw
            };
            if !violated {
                continue;
            }
            work += t as u64;
            match self.step(p, in_b, &order[..t], a0, b0) {
                Step::Line(l, partner) => {
                    line = l;
                    if in_b {
                        tb = enc & !B_BIT;
                        if partner & B_BIT == 0 {
                            ta = partner;
                        }
                    } else {
                        ta = enc;
                        if partner & B_BIT != 0 {
                            tb = partner & !B_BIT;
                        }
                    }
                }
                Step::Infeasible => {
                    ws.work += work;
                    return StepOut::Infeasible;
                }
                Step::Inconsistent => {
                    ws.work += work;
                    return StepOut::Inconsistent;
                }
            }
        }
        ws.work += work;
        StepOut::Line(line, ta, tb)
    }

    /// The one-dimensional LP: the most counter-clockwise direction in H of a line through
    /// `p` that keeps every earlier point on its side.
    fn step(&self, p: Point, p_in_b: bool, earlier: &[u32], a0: Point, b0: Point) -> Step {
        let k = self.k;
        let mut up: Option<Bound> = None;
        let mut lo: Option<Bound> = None;
        for &enc in earlier {
            let q = self.point(enc);
            let q_in_b = enc & B_BIT != 0;
            let opposite = q_in_b != p_in_b;
            if q == p {
                if opposite {
                    return Step::Infeasible; // a point of both sets
                }
                continue;
            }
            // Sign of x′(q − p).
            let sx = match k.cross(a0, b0, p, q) {
                Orientation::Cw => Sign::Positive,
                Orientation::Ccw => Sign::Negative,
                Orientation::Collinear => Sign::Zero,
            };
            // u × (q − p) must be ≥ 0 for q in B, ≤ 0 for q in A; with u = (1, s) that is
            // y′(q − p) − s·x′(q − p).
            let is_upper = match sx {
                Sign::Zero => {
                    let sy = k.dot(a0, b0, p, q);
                    let ok = if q_in_b {
                        sy != Sign::Negative
                    } else {
                        sy != Sign::Positive
                    };
                    if ok {
                        continue;
                    }
                    return Step::Infeasible;
                }
                Sign::Positive => q_in_b,
                Sign::Negative => !q_in_b,
            };
            let (from, to) = if sx == Sign::Positive { (p, q) } else { (q, p) };
            let cand = Bound {
                from,
                to,
                q: enc,
                opposite,
            };
            if is_upper {
                up = Some(match up {
                    None => cand,
                    Some(best) => match k.cross(best.from, best.to, from, to) {
                        // cand's slope is smaller: a tighter upper bound.
                        Orientation::Cw => cand,
                        Orientation::Collinear if opposite && !best.opposite => cand,
                        _ => best,
                    },
                });
            } else {
                lo = Some(match lo {
                    None => cand,
                    Some(best) => match k.cross(best.from, best.to, from, to) {
                        Orientation::Ccw => cand,
                        Orientation::Collinear if opposite && !best.opposite => cand,
                        _ => best,
                    },
                });
            }
        }
        let Some(up) = up else {
            // The bounding constraints always give an upper bound; only an inconsistent
            // kernel loses it.
            return Step::Inconsistent;
        };
        let mut partner = up.q;
        if let Some(lo) = lo {
            match k.cross(lo.from, lo.to, up.from, up.to) {
                Orientation::Cw => return Step::Infeasible,
                Orientation::Collinear if !up.opposite && lo.opposite => partner = lo.q,
                _ => {}
            }
        }
        Step::Line(Line { s: up.from, e: up.to }, partner)
    }

    /// Checks every point against the line and compares the parts of the two sets on it.
    fn certify(&self, line: Line, ta: usize, tb: usize, ws: &mut LpWorkspace) -> Option<Separation> {
        let k = self.k;
        let Line { s, e } = line;
        // Extremes along the line (by u · (x − y)) of the points on it.
        let (mut a_min, mut a_max) = (self.a.point(ta), self.a.point(ta));
        for i in 0..self.a.len() {
            let x = self.a.point(i);
            match k.orient(s, e, x) {
                Orientation::Ccw => return None,
                Orientation::Cw => {}
                Orientation::Collinear => {
                    if k.dot(s, e, a_min, x) == Sign::Negative {
                        a_min = x;
                    } else if k.dot(s, e, a_max, x) == Sign::Positive {
                        a_max = x;
                    }
                }
            }
        }
        let (mut b_min, mut b_max) = (self.b.point(tb), self.b.point(tb));
        for j in 0..self.b.len() {
            let x = self.b.point(j);
            match k.orient(s, e, x) {
                Orientation::Cw => return None,
                Orientation::Ccw => {}
                Orientation::Collinear => {
                    if k.dot(s, e, b_min, x) == Sign::Negative {
                        b_min = x;
                    } else if k.dot(s, e, b_max, x) == Sign::Positive {
                        b_max = x;
                    }
                }
            }
        }
        ws.work += (self.a.len() + self.b.len()) as u64;
        // Tangent points must be on the line (fails only under an inconsistent kernel).
        if k.orient(s, e, self.a.point(ta)) != Orientation::Collinear
            || k.orient(s, e, self.b.point(tb)) != Orientation::Collinear
        {
            return None;
        }
        let overlap =
            k.dot(s, e, a_min, b_max) != Sign::Negative && k.dot(s, e, b_min, a_max) != Sign::Negative;
        Some(if overlap {
            Separation::Intersecting
        } else {
            Separation::Separated(Bitangent {
                start: s,
                end: e,
                a: ta,
                b: tb,
            })
        })
    }
}
