//! The incremental LP behind [`separating_line`]; the formulation is in the module docs
//! of [`crate::lp`].
//!
//! `points` holds the input sets and their copy into the workspace, `workspace` the
//! reusable buffers and the witness of intersecting hulls, `incremental` the loop, its
//! one-dimensional steps and the final certification.

mod incremental;
mod points;
mod workspace;

pub use points::{ArenaPoints, PointSet};
pub use workspace::{LpWorkspace, WitnessPoint};

use crate::kernel::{Exact, Kernel, Orientation, Point};
use incremental::{Line, OnLine, StepOut, certify, incremental};
use points::{Item, Layout, Load, Loaded, Source, list_items};
use rand::Rng;
use std::fmt;
use workspace::Witness;

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
