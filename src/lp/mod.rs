//! Separating lines between two point sets by a Seidel-style randomized incremental
//! 2D linear program, decided entirely by predicates on input points.
//!
//! [`separating_line`] answers: do the convex hulls CH(A) and CH(B) of two finite point
//! sets intersect (closed sets: touching counts)? If not, it returns a *bitangent*: a
//! line through an input point of A and an input point of B with all of A on its closed
//! right side and all of B on its closed left side (an inner common tangent of the two
//! hulls), plus the indices of the two tangent points. The Chazelle–Liu–Magen test
//! (`intersect::Clm`) runs it on samples and chains of linked polygons, on
//! contiguous copies of their points made once per set (several LPs read the same
//! sample); [`ArenaPoints`] reads a polygon's arena positions in place instead.
//! [`separate_chains`] answers the same question for two convex chains whose points
//! come in order along their hulls, by a walk along both that usually reads a few of
//! their points (CLM's chain-against-chain LPs).
//!
//! # Formulation: no privileged direction
//! The thesis (3.3.4) searches for y = ax + b with A above B, minimising the slope a,
//! and relabels A and B (or runs twice) when the separator is vertical or B is above.
//! Here the frame comes from the data. Let a₀ = A\[0\], b₀ = B\[0\] and d₀ = b₀ − a₀
//! (if a₀ = b₀ the hulls share a point). Every *strict* separator with A on the right
//! and B on the left has its direction u in the open half circle H = {u : d₀ × u < 0}
//! (the directions that point "rightwards" when d₀ points "up"), because b₀ − a₀ must
//! point to the left of u. Writing u = (1, s) in the frame (x′ ⟂ d₀, y′ ∥ d₀), the lines
//! y′ = s·x′ + c with A below and B above form an ordinary 2D LP in (s, c); we
//! **maximise s**, i.e. take the most counter-clockwise feasible direction in H. The
//! optimum is unique and tight on a point of each set: an inner common tangent.
//!
//! The objective is bounded iff some a ∈ A lies strictly left of some b ∈ B in x′; the
//! first two constraints are the x′-leftmost point of A and the x′-rightmost point of B
//! (one O(n) scan, as the thesis's bounding constraints). If no such pair exists, every
//! point of A has x′ ≥ x′(a₀) = x′(b₀) ≥ every point of B, so the line through a₀ and b₀
//! (parallel to d₀) is itself a closed separator: the thesis's "vertical" case, here in
//! a frame that depends on the input and needs no relabelling. Nothing is ever rotated
//! or transformed: the frame exists only inside the predicates below.
//!
//! # Predicates, not coordinates
//! The LP is run combinatorially. The current optimum is always *the line through two
//! input points* (s, e), so
//! * "does p violate the optimum?" is `orient(s, e, p)`;
//! * the sign of x′(q − p) is `cross(a₀, b₀, p, q)`, and of y′(q − p) is `dot(a₀, b₀, p, q)`;
//! * in the one-dimensional subproblem (lines through a violating point p) each earlier
//!   point q bounds the slope by the slope of the line pq, and two such bounds compare
//!   by `cross` of their directions (both normalised to point into H).
//!
//! Every decision is the sign of a polynomial in input coordinates, so under
//! [`Exact`](crate::Exact) the whole computation — verdict, line and tangent points — is exact:
//! no constructed value is ever compared. (The thesis's implementation constructs
//! slopes and intercepts in floating point and needs majority votes for sidedness.)
//!
//! # Verdict
//! A feasible LP only proves a *closed* separator exists; touching hulls also have one
//! (two squares sharing an edge). A final pass certifies the line (every point of A
//! not left, every point of B not right) and collects the points of each set that lie
//! on it: since the line supports both hulls, CH(A) ∩ CH(B) = CH(A ∩ L) ∩ CH(B ∩ L), two
//! intervals on L compared with `dot`. Under an exact kernel
//! (`Predicates::EXACT`) the pass re-tests no point when the
//! incremental loop ran: the loop tested every point after the line's last change
//! against it, and the one-dimensional step that made the line every point before
//! (collecting the ones on it), with the same predicate. Under [`Fast`](crate::Fast) the predicates may
//! be inconsistent; if the certification fails the whole computation is repeated with
//! [`Exact`](crate::Exact), so a fast answer is either certified by fast predicates or exact.
//!
//! # Complexity
//! Expected O(|A| + |B|) predicate evaluations for every input: constraints are
//! processed in a uniformly random order drawn from the caller's RNG (Seidel's
//! backwards analysis: the i-th constraint changes the optimum with probability at
//! most 2/i and then costs O(i)). Worst case (a very unlucky order) O((|A| + |B|)²).
//! Memory: 24 bytes per point (the points are copied once into the reusable
//! [`LpWorkspace`], so the passes read contiguous memory); nothing is allocated
//! once the workspace has grown to the largest input.
//!
//! # Degeneracies
//! Single points, duplicates (within a set or across sets: a shared point is an
//! intersection), collinear sets, all points on one line, separators in any
//! direction (vertical, horizontal, parallel to d₀) and touching hulls are all handled
//! by the same code path; tests/geometry/lp.rs checks each against an exact brute force.

mod chains;
mod seidel;

pub use chains::separate_chains;
// `PointSet` is an API with `instrument` (the crate itself names only its
// implementations).
#[cfg_attr(not(feature = "instrument"), allow(unused_imports))]
pub use seidel::{
    ArenaPoints, Bitangent, LpError, LpWorkspace, PointSet, Separation, WitnessPoint, separating_line,
};
