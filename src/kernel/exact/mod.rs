//! The exact kernel: correct signs for every finite `f64` input.
//!
//! # Layers
//! 0. **Semi-static filter** ([`ExactWithin`], inline), for a query that names the
//!    bounding boxes of its points ([`Kernel::within`]; the array algorithms do):
//!    one error bound per query from the boxes' size, so a call is certified by
//!    comparing its computed value with ±bound, the comparisons the fast kernel makes
//!    against zero. Calls it cannot decide (nearly degenerate relative to the boxes:
//!    short edges of large polygons, coincident points) go on to layer 1. A caller
//!    that knows every difference to be at most some `w` (the cross product of two
//!    edges, `w` the longest edge's [`ConvexPolygon::edge_extent`](crate::ConvexPolygon::edge_extent))
//!    may ask [`Kernel::within_differences`] for the same bound scaled to `w`.
//! 1. **Static filter** (inline). The predicate is evaluated in `f64` together with a
//!    bound on its rounding error; when the result is farther from zero than the
//!    bound, its sign is the exact sign. `orient`, `cross` and `dot` (two products
//!    `l`, `r` of differences) certify `l ∓ r` when `|l ∓ r| > 2ε₀(1 + 2^-30)·|l| +
//!    2·f64::MIN_POSITIVE`, ε₀ = (3 + 16u)u, u = 2^-53, which implies Shewchuk's
//!    condition (derivation at `certain`); [`Kernel::cross_products_sign`] (degree 4)
//!    uses `12u·(P₀P₁ + P₂P₃)` with Pᵢ the magnitude of factor i's two products
//!    (derivation at `cross_products_filtered`). On ordinary input this layer decides
//!    every call but those with coincident points. It is written so that the answer
//!    is the same sign test of the computed value that [`Fast`](super::Fast) makes,
//!    and the certificate a separate branch that ordinary input always takes the
//!    same way: the algorithms' unpredictable branches wait no longer than under
//!    `Fast`.
//! 2. **Out of line** (`#[cold]`), when the filter cannot decide:
//!    * *Fixed rescaling.* Two-product calls whose products overflowed, or all
//!      underflowed, are filtered again on their differences times 2^-600 or 2^600
//!      (`fixed_rescale_sign`): uniformly huge or tiny input (2^±600, near
//!      `f64::MAX`) is decided here in a few instructions.
//!    * *Scaled differences.* Every predicate here is a homogeneous polynomial in
//!      differences of inputs. The differences the filter computed are multiplied by
//!      the power of two that puts the largest in [1, 2) and the filter runs again
//!      (`scaled_differences` says why that stays valid even where it rounds tiny
//!      differences). This decides well-conditioned calls whose products overflowed
//!      or underflowed: coordinates near 2^±600, subnormal, or huge and tiny mixed,
//!      as long as no difference overflows. Subnormal values are scaled through their
//!      integer mantissas: x86 processors handle subnormal operands in microcode.
//!    * *Structural zeros.* Coincident points (a repeated point in `orient`, a zero
//!      vector in `cross` or `dot`, one segment crossed with itself) answer zero
//!      without arithmetic. Algorithms ask such questions on every input (a chain's
//!      end against itself).
//!    * *Rescaled coordinates.* The inputs themselves are scaled so that the largest
//!      magnitude lies in [1, 2), when that is exact (the smallest non-zero one stays
//!      normal: inputs spanning at most 2^1022), and filtered again (this catches
//!      differences that overflowed near ±`f64::MAX`).
//!    * *Adaptive.* `orient`, and `cross` and `dot` when their coordinate differences
//!      are exact, go to Shewchuk's adaptive `orient2d` (the `robust` crate), whose
//!      expansion arithmetic is exact as long as no intermediate product overflows or
//!      underflows. That holds when every non-zero (rescaled) coordinate has magnitude
//!      in [2^-400, 2^400] : every difference and expansion
//!      component is then a multiple of 2^-453 and every product a multiple of
//!      2^-906 (above the subnormal range) and below 2^804. Degree-4 predicates and
//!      [`Kernel::sign`] try [`Interval`] arithmetic with outward rounding instead.
//! 3. **Exact fallback.** Everything still undecided (nearly degenerate calls whose
//!    inputs span more than 2^400, nearly parallel `cross` with inexact differences,
//!    nearly degenerate degree-4 calls) is evaluated on the exact dyadic values
//!    `m · 2^e` of the inputs with big integers ([`Dyadic`]). No finite input is
//!    refused and none is misjudged; the cost is paid only by near-degenerate calls.
//!
//! # Cost
//! Measured in docs/results.md ("The exact kernel's overhead", "At extreme scales"),
//! in instructions (callgrind) and time. The semi-static filter, the static filter
//! inline where the algorithms cross short edges ([`Kernel::cross_of_short_edges`]),
//! the slope comparison's bound scaled to the edges
//! ([`Kernel::cross_products_sign_of_short_edges`]) and orientations by reference
//! ([`Kernel::orient_of`]) keep the exact kernel within a small constant factor of the
//! fast one's instructions for every algorithm, the same factor at every size. Input at
//! extreme scales (2^±600, 2^1016) costs a constant factor more than the same input at
//! scale 1, by the fixed rescaling.
//! Predicates that mix magnitudes more than 2^1022 apart within one call fall to big
//! integers when nearly degenerate.

mod area;
mod dyadic;
mod interval;
mod out_of_line;
mod predicates;
mod semi_static;
mod static_filter;

#[cfg(test)]
use area::area_sign;
pub(crate) use area::area_sign_of;
pub(crate) use dyadic::Dyadic;
pub(crate) use semi_static::ExactWithin;

use super::{BoundingBox, DirectedLine, Kernel, Orientation, Point, Polynomial, Sign};

/// Exact predicates for every finite input; the default kernel. See the module docs
/// for the layers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Exact;

impl Kernel for Exact {
    const NAME: &'static str = "exact";

    /// The static filter, written so that the answer is the sign of the computed
    /// determinant (as under [`Fast`](super::Fast)) and the certificate a separate
    /// branch; an uncertain determinant is replaced by ±1 or 0 from `orient_slow`.
    #[inline]
    fn orient(self, a: Point, b: Point, c: Point) -> Orientation {
        predicates::orient(a, b, c)
    }

    /// Same shape as `orient` (two products of differences), so the same static filter.
    #[inline]
    fn cross(self, a: Point, b: Point, c: Point, d: Point) -> Orientation {
        predicates::cross(a, b, c, d)
    }

    /// Same shape as `orient` with a sum instead of a difference: the same static filter.
    #[inline]
    fn dot(self, a: Point, b: Point, c: Point, d: Point) -> Sign {
        predicates::dot(a, b, c, d)
    }
}

impl crate::kernel::sealed::Predicates for Exact {
    const EXACT: bool = true;

    type Within = ExactWithin;

    #[inline]
    fn within(self, boxes: [BoundingBox; 2]) -> ExactWithin {
        ExactWithin::new(boxes)
    }

    #[inline]
    fn within_differences(self, w: f64) -> ExactWithin {
        ExactWithin::for_differences(w)
    }

    /// The static filter on the products with the line's start as the pivot (see
    /// [`DirectedLine`]): the same bound as `orient`'s.
    #[inline]
    fn orient_line(self, line: &DirectedLine, c: Point) -> Orientation {
        predicates::orient_line(line, c)
    }

    /// The interval filter, then the exact fallback, out of line.
    #[inline]
    fn sign<P: Polynomial>(self, poly: &P) -> Sign {
        predicates::sign(poly)
    }

    /// A static filter (see `cross_products_filtered`), then rescaling, intervals and
    /// the exact fallback out of line.
    #[inline(always)]
    fn cross_products_sign(self, factors: [[Point; 4]; 4]) -> Sign {
        predicates::cross_products_sign(factors)
    }
}

#[cfg(test)]
mod tests;
