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
//!      in [2^-400, 2^400] ([`in_adaptive_range`]): every difference and expansion
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
//! in instructions (callgrind) and time. With the semi-static filter, and the static
//! filter inline where the algorithms cross short edges
//! ([`Kernel::cross_of_short_edges`]), exact/fast instructions at n = 2^10 / 2^14 /
//! 2^18: Barba 1.11 / 1.14 / 1.13, Dobkin 1.11 / 1.11 / 1.12, Linear 1.13 / 1.13 /
//! 1.13 (its walk under the edges' bound), Chazelle–Dobkin 1.16 / 1.14 / 1.14 with its
//! slope comparison's bound scaled to the edges
//! ([`Kernel::cross_products_sign_of_short_edges`]; 1.23 at 2^18 before) and its
//! searches' orientations by reference ([`Kernel::orient_of`]; 1.18 / 1.16 / 1.16
//! before) (before the semi-static filter: 1.3–1.6×). Validation plus the crossings sweep at 2^±600 and 2^1016 cost
//! 1.38–1.46× the instructions of the same input at scale 1 (before the fixed
//! rescaling: 1.65×).
//! Predicates that mix magnitudes more than 2^1022 apart within one call fall to big
//! integers when nearly degenerate.

use super::{
    CrossPoly, CrossProductsPoly, DirectedLine, DotPoly, Kernel, Orientation, Point, Polynomial, Ring, Sign,
};
use num_bigint::BigInt;
use num_traits::{Signed, Zero};
use std::ops::{Add, Mul, Sub};

/// Shewchuk's `ccwerrboundA`: (3 + 16ε)ε with ε = 2^-53.
const ORIENT_ERR: f64 = (3.0 + 16.0 * (f64::EPSILON / 2.0)) * (f64::EPSILON / 2.0);
const ADAPTIVE_MIN: f64 = f64::from_bits((1023 - 400) << 52); // 2^-400
const ADAPTIVE_MAX: f64 = f64::from_bits((1023 + 400) << 52); // 2^400

/// Exact predicates for every finite input; the default kernel. See the module docs
/// for the layers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Exact;

impl Kernel for Exact {
    const NAME: &'static str = "exact";
    const EXACT: bool = true;
    type Within = ExactWithin;

    #[inline]
    fn within(self, boxes: [(Point, Point); 2]) -> ExactWithin {
        ExactWithin::new(boxes)
    }

    #[inline]
    fn within_differences(self, w: f64) -> ExactWithin {
        ExactWithin::for_differences(w)
    }

    /// The static filter, written so that the answer is the sign of the computed
    /// determinant (as under [`Fast`](super::Fast)) and the certificate a separate
    /// branch; an uncertain determinant is replaced by ±1 or 0 from `orient_slow`.
    #[inline]
    fn orient(self, a: Point, b: Point, c: Point) -> Orientation {
        let (left, right) = orient_products(a, b, c);
        let mut det = left - right;
        if !certain(det, left) {
            det = as_value(orient_slow(a, b, c));
        }
        Sign::of(det).into()
    }

    /// The static filter on the products with the line's start as the pivot (see
    /// [`DirectedLine`]): the same bound as `orient`'s.
    #[inline]
    fn orient_line(self, line: &DirectedLine, c: Point) -> Orientation {
        let (left, right) = line.products(c);
        let mut det = left - right;
        if !certain(det, left) {
            det = as_value(orient_slow(line.from(), line.to(), c));
        }
        Sign::of(det).into()
    }

    /// The interval filter, then the exact fallback. Kept out of line: the kernel's
    /// own predicates never come here on ordinary input, and inlining an interval
    /// evaluation into an algorithm's loop costs it registers and code size.
    #[inline(never)]
    fn sign<P: Polynomial>(self, poly: &P) -> Sign {
        match poly.eval::<Interval>().certain_sign() {
            Some(s) => s,
            None => sign_slow(poly),
        }
    }

    /// Same shape as `orient` (two products of differences), so the same static filter.
    #[inline]
    fn cross(self, a: Point, b: Point, c: Point, d: Point) -> Orientation {
        let (left, right) = cross_products(a, b, c, d);
        if !certain(left - right, left) {
            return cross_slow(a, b, c, d).into();
        }
        if left > right {
            Orientation::Ccw
        } else {
            Orientation::Cw
        }
    }

    /// Same shape as `orient` with a sum instead of a difference: the same static filter.
    #[inline]
    fn dot(self, a: Point, b: Point, c: Point, d: Point) -> Sign {
        let (left, right) = dot_products(a, b, c, d);
        let mut det = left + right;
        if !certain(det, left) {
            det = as_value(dot_slow(a, b, c, d));
        }
        Sign::of(det)
    }

    /// A static filter (see `cross_products_filtered`), then rescaling, intervals and
    /// the exact fallback out of line.
    #[inline(always)]
    fn cross_products_sign(self, factors: [[Point; 4]; 4]) -> Sign {
        match cross_products_filtered(&factors) {
            Some(s) => s,
            None => cross_products_slow(factors),
        }
    }
}

/// The exact kernel for one query whose points lie in known boxes ([`Kernel::within`]):
/// [`Exact`] behind a *semi-static* filter.
///
/// Let `w` be the larger side of the union of the boxes, computed in `f64`, and
/// `P = w·w`. Every coordinate difference the predicates compute is at most `w` in
/// magnitude (rounding is monotonic), so every product of two differences is at most
/// `P` (again by monotonicity: |fl(d·d′)| ≤ fl(w·w)). [`ExactWithin::for_differences`]
/// takes `w` from a caller that knows every computed difference to be at most `w`
/// (the edges of polygons, [`Kernel::within_differences`]); nothing below uses more.
/// The filter's two bounds, computed once:
///
/// * two products (`orient`, `cross`, `dot`): Shewchuk's error bound ε₀·(|l| + |r|)
///   with |l| + |r| ≤ 2P, so `B₂ = 2ε₀(1 + 2^-30)·P + 2·f64::MIN_POSITIVE` (the
///   margin covers the bound's own roundings, the last term underflowing products, as
///   in the static filter). Valid for `P ≤ 2^1020`: then |l ∓ r| ≤ 2^1021 cannot
///   overflow.
/// * degree 4 ([`Kernel::cross_products_sign`]): the static filter's analysis with
///   each factor's magnitude Pᵢ ≤ 2P(1 + 3u) bounds the error by 81.7u·P², to which
///   underflow adds at most 2^-1070·P + 2^-1073; `B₄ = 96u·P²` covers both when
///   `P ∈ [2^-400, 2^250]` (then nothing overflows either).
///
/// A predicate whose computed value `v` satisfies `v > B` or `v < −B` is decided by
/// that sign: the same two comparisons the [`Fast`](super::Fast) kernel makes against
/// zero. Anything else (a value within the bound, NaN, a bound out of its range,
/// which is `+∞`) goes to [`Exact`]'s own layers, out of line, except that a degree-4
/// call first tries [`Exact`]'s static filter inline (its derivation at
/// `cross_products_filtered`; it refuses what it cannot vouch for, including
/// overflow and underflow, and those calls go on out of line), and that
/// [`Kernel::cross_products_sign_of_short_edges`] (Chazelle–Dobkin's slope comparison,
/// whose factors are short edges times long vectors, seldom decided by `B₄` at large
/// n) tries a bound scaled to the edges inline instead. The default value has
/// infinite bounds: every call goes to [`Exact`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExactWithin {
    /// `B₂`, or `+∞` when not valid.
    two: f64,
    /// `B₄`, or `+∞` when not valid.
    four: f64,
    /// `−B₂` and `−B₄`, kept so that a call compares without negating.
    neg_two: f64,
    neg_four: f64,
}

impl Default for ExactWithin {
    fn default() -> Self {
        ExactWithin {
            two: f64::INFINITY,
            four: f64::INFINITY,
            neg_two: f64::NEG_INFINITY,
            neg_four: f64::NEG_INFINITY,
        }
    }
}

impl ExactWithin {
    /// The kernel for queries on points inside the union of `boxes` (each `(min, max)`).
    /// Boxes with non-finite corners give infinite bounds (every call goes to [`Exact`]).
    ///
    /// ```
    /// use polysect::{ExactWithin, Kernel, Orientation, Point};
    /// let b = (Point::new(0.0, 0.0), Point::new(1.0, 1.0));
    /// let k = ExactWithin::new([b, b]);
    /// let (o, x, y) = (Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(0.0, 1.0));
    /// assert_eq!(k.orient(o, x, y), Orientation::Ccw);
    /// assert_eq!(k.orient(o, x, Point::new(0.5, 0.0)), Orientation::Collinear);
    /// ```
    #[inline]
    pub fn new([(lo0, hi0), (lo1, hi1)]: [(Point, Point); 2]) -> ExactWithin {
        // The union's side per coordinate, max(hi) − min(lo): rounding is monotonic, so
        // it is the largest computed difference of a corner's coordinate and another's
        // (as before this took all four), hence of two points in the boxes. The plain
        // comparisons (an instruction each) may drop a NaN corner; `finite` brings it
        // back: zero when every corner is finite, NaN when one is NaN or infinite (or
        // when a box's side overflows, and then the union's side is infinite anyway).
        // So a non-finite corner makes the side NaN, which fails both range tests.
        let max = |a: f64, b: f64| if a > b { a } else { b };
        let min = |a: f64, b: f64| if a < b { a } else { b };
        let wx = max(hi0.x, hi1.x) - min(lo0.x, lo1.x);
        let wy = max(hi0.y, hi1.y) - min(lo0.y, lo1.y);
        let finite = ((hi0.x - lo0.x) + (hi1.x - lo1.x) + ((hi0.y - lo0.y) + (hi1.y - lo1.y))) * 0.0;
        ExactWithin::from_side(max(wx, wy) + finite)
    }

    /// The kernel for calls whose coordinate differences, as computed in `f64`, are
    /// all at most `w` in magnitude ([`Kernel::within_differences`]): the bounds of
    /// [`new`](ExactWithin::new) with `w` given instead of taken from boxes. Their
    /// derivation (on the type) uses only that every computed difference is at most
    /// `w`, which [`new`](ExactWithin::new) proves for points in its boxes and the
    /// caller promises here. A `w` that is negative, NaN or infinite, or too large for
    /// a bound's range, gives that bound `+∞`.
    ///
    /// The cross product of two edges of polygons whose
    /// [`edge_extent`](crate::ConvexPolygon::edge_extent) is at most `w` computes the
    /// edges' own differences, each at most `w`: under this kernel it is decided by
    /// `|l − r| > B₂` with `B₂ ≈ 6.7·10^-16·w²`, where the boxes' bound has the boxes'
    /// side in place of the (much shorter) longest edge.
    ///
    /// ```
    /// use polysect::{ExactWithin, Kernel, Orientation, Point};
    /// let k = ExactWithin::for_differences(1.0);
    /// // Two unit edges, 2^40 apart: the boxes' bound would be 2^80 times larger.
    /// let (a, b) = (Point::new(0.0, 0.0), Point::new(1.0, 0.0));
    /// let (c, d) = (Point::new(1e12, 0.0), Point::new(1e12 + 1.0, 1e-9));
    /// assert_eq!(k.cross(a, b, c, d), Orientation::Ccw);
    /// assert!(k.two_products_bound() < 1e-15);
    /// ```
    #[inline]
    pub fn for_differences(w: f64) -> ExactWithin {
        // A negative `w` promises nothing about magnitudes: NaN fails both range tests.
        ExactWithin::from_side(if w >= 0.0 { w } else { f64::NAN })
    }

    /// The bounds for differences at most `|w|` (NaN or infinite: `+∞`).
    #[inline(always)]
    fn from_side(w: f64) -> ExactWithin {
        const TWO_MAX: f64 = f64::from_bits((1023 + 1020) << 52); // 2^1020
        const FOUR_MIN: f64 = f64::from_bits((1023 - 400) << 52); // 2^-400
        const FOUR_MAX: f64 = f64::from_bits((1023 + 250) << 52); // 2^250
        const C2: f64 = 2.0 * ORIENT_ERR * (1.0 + 1.0 / (1u64 << 30) as f64);
        const C4: f64 = 96.0 * (f64::EPSILON / 2.0);
        let p = w * w;
        // `p <= MAX` is false for NaN and infinity.
        let two = if p <= TWO_MAX {
            C2 * p + 2.0 * f64::MIN_POSITIVE
        } else {
            f64::INFINITY
        };
        let four = if (FOUR_MIN..=FOUR_MAX).contains(&p) {
            C4 * p * p
        } else {
            f64::INFINITY
        };
        ExactWithin {
            two,
            four,
            neg_two: -two,
            neg_four: -four,
        }
    }

    /// The two-product bound `B₂` (`+∞` when not valid).
    pub fn two_products_bound(&self) -> f64 {
        self.two
    }

    /// The degree-4 bound `B₄` (`+∞` when not valid).
    pub fn degree_four_bound(&self) -> f64 {
        self.four
    }

    /// The bound of [`Kernel::cross_products_sign_of_short_edges`] for
    /// `m = m₀m₁ + m₂m₃` (see there), from the two bounds the kernel keeps, so that it
    /// costs no field: `8B₂·m + (0·B₄ + 2^-1010·B₂ + 2^-1072)`. As `B₂ ≥ 6u·P` (less
    /// two roundings), the first term is at least `48u·P·m` (less one rounding) and the
    /// second at least `2^-1060·P` (less one rounding of at most 2^-1075): at least
    /// `2^-1069·P` for `P ≥ 2^-6`; for smaller `P` the underflow terms it must cover,
    /// `2^-1070.9·w² + 2^-1074` (see there), are below `2^-1072`. `0·B₄` is zero for a
    /// finite `B₄`, that is `P ∈ [2^-400, 2^250]`, and NaN outside, where the bound must
    /// not decide: NaN fails both comparisons. It uses `B₄` only as that range flag, so
    /// it stays valid on a kernel from [`Kernel::within_short_edges`], whose `B₄` is
    /// replaced by a smaller (finite) bound.
    #[inline(always)]
    pub(crate) fn short_edges_bound(&self, m: f64) -> f64 {
        const SCALE: f64 = f64::from_bits((1023 - 1010) << 52); // 2^-1010
        const FLOOR: f64 = f64::from_bits(1 << 2); // 2^-1072
        self.two * (8.0 * m) + (self.four * 0.0 + (self.two * SCALE + FLOOR))
    }
}

impl Kernel for ExactWithin {
    const NAME: &'static str = "exact";
    const EXACT: bool = true;
    type Within = ExactWithin;

    #[inline]
    fn within(self, boxes: [(Point, Point); 2]) -> ExactWithin {
        ExactWithin::new(boxes)
    }

    #[inline]
    fn within_differences(self, w: f64) -> ExactWithin {
        ExactWithin::for_differences(w)
    }

    #[inline]
    fn orient(self, a: Point, b: Point, c: Point) -> Orientation {
        let (left, right) = orient_products(a, b, c);
        let det = left - right;
        if det > self.two {
            Orientation::Ccw
        } else if det < self.neg_two {
            Orientation::Cw
        } else {
            orient_within_slow(a, b, c)
        }
    }

    /// `orient`'s test, with the references handed to the out-of-line path.
    #[inline]
    fn orient_of(self, a: &Point, b: &Point, c: &Point) -> Orientation {
        let (left, right) = orient_products(*a, *b, *c);
        let det = left - right;
        if det > self.two {
            Orientation::Ccw
        } else if det < self.neg_two {
            Orientation::Cw
        } else if *b == *c {
            // A repeated point: zero, without the call (Chazelle–Dobkin's finish asks
            // whether each chain vertex lies in the window, whose ends are chain
            // vertices: about once per query).
            Orientation::Collinear
        } else {
            orient_within_slow_of(a, b, c)
        }
    }

    /// The semi-static filter on the products with the line's start as the pivot
    /// (see [`DirectedLine`]): every difference is still one of two points in the
    /// boxes, so the bound `B₂` holds.
    #[inline]
    fn orient_line(self, line: &DirectedLine, c: Point) -> Orientation {
        let (left, right) = line.products(c);
        let det = left - right;
        if det > self.two {
            Orientation::Ccw
        } else if det < self.neg_two {
            Orientation::Cw
        } else {
            orient_within_slow(line.from(), line.to(), c)
        }
    }

    #[inline]
    fn sign<P: Polynomial>(self, poly: &P) -> Sign {
        Exact.sign(poly)
    }

    #[inline]
    fn cross(self, a: Point, b: Point, c: Point, d: Point) -> Orientation {
        let (left, right) = cross_products(a, b, c, d);
        let det = left - right;
        if det > self.two {
            Orientation::Ccw
        } else if det < self.neg_two {
            Orientation::Cw
        } else {
            cross_within_slow(a, b, c, d)
        }
    }

    /// `cross`'s semi-static test, then [`Exact`]'s static filter inline (valid for
    /// any input: `certain` refuses overflow), then out of line. Written out beside
    /// `cross` rather than sharing a generic body: with the shared body (a const
    /// parameter choosing the inline filter) the compiler inlined `cross` differently
    /// and Linear's exact/fast instructions rose from 1.134 to 1.199 at 2^10.
    #[inline]
    fn cross_of_short_edges(self, a: Point, b: Point, c: Point, d: Point) -> Orientation {
        let (left, right) = cross_products(a, b, c, d);
        let det = left - right;
        if det > self.two {
            Orientation::Ccw
        } else if det < self.neg_two {
            Orientation::Cw
        } else if certain(det, left) {
            nonzero_sign(det).into()
        } else {
            cross_within_slow(a, b, c, d)
        }
    }

    #[inline]
    fn dot(self, a: Point, b: Point, c: Point, d: Point) -> Sign {
        let (left, right) = dot_products(a, b, c, d);
        let det = left + right;
        if det > self.two {
            Sign::Positive
        } else if det < self.neg_two {
            Sign::Negative
        } else {
            dot_within_slow(a, b, c, d)
        }
    }

    #[inline(always)]
    fn cross_products_sign(self, factors: [[Point; 4]; 4]) -> Sign {
        let cross = |[ux, uy, vx, vy]: [f64; 4]| ux * vy - uy * vx;
        let d = factors.map(factor_differences);
        let s = cross(d[0]) * cross(d[1]) + cross(d[2]) * cross(d[3]);
        if s > self.four {
            return Sign::Positive;
        } else if s < self.neg_four {
            return Sign::Negative;
        }
        // The static filter, inline: at large n the semi-static bound cannot decide
        // most calls of Chazelle–Dobkin's slope comparison, whose factors are short
        // edges times long vectors. Its magnitudes are computed here, on this path
        // only (computed beside `s`, they cost every call a dozen instructions); its
        // value is `s` again, the same operations on the same differences.
        let (s, bound, valid) = cross_products_from_differences(d);
        if valid && s.abs() > bound {
            nonzero_sign(s)
        } else {
            cross_products_out_of_line(factors)
        }
    }

    /// This kernel with `B₄` replaced by `ExactWithin::short_edges_bound` of
    /// `M = 2·fl(e·e)`, `e = e()`, when that is smaller (the other bounds unchanged). Every call
    /// within the contract has `mᵢ ≤ e` for each factor's short direction, so its own
    /// computed `m = fl(fl(m₀m₁) + fl(m₂m₃))` is at most `fl(fl(e·e) + fl(e·e)) = M`
    /// (rounding is monotonic), and the bound is monotonic in `m`: `M`'s bound is at
    /// least the call's, which the derivation at
    /// [`cross_products_sign_of_short_edges`](Kernel::cross_products_sign_of_short_edges)
    /// proves valid. The replaced `B₄` is finite only where the old one was (an
    /// infinite `B₄` makes the bound NaN, and the comparison keeps `B₄`), and the
    /// short-edge bound does not depend on `B₄`'s value, so it stays valid when this
    /// is applied again. A negative or NaN `e` promises nothing: the bound is NaN
    /// and `B₄` is kept.
    #[inline]
    fn within_short_edges(self, e: impl FnOnce() -> f64) -> ExactWithin {
        let e = e();
        let e = if e >= 0.0 { e } else { f64::NAN };
        let bound = self.short_edges_bound(2.0 * (e * e));
        let four = if bound < self.four { bound } else { self.four };
        ExactWithin {
            four,
            neg_four: -four,
            ..self
        }
    }

    /// The semi-static test, then a bound scaled to the short directions, inline;
    /// [`Exact`]'s static filter and what follows it out of line.
    ///
    /// With mᵢ = max(|bᵢ.x − aᵢ.x|, |bᵢ.y − aᵢ.y|) (computed differences) and `w` the
    /// boxes' side, every computed difference of `dᵢ − cᵢ` is at most `w` (see the type's
    /// docs), so factor i's product magnitude is Pᵢ ≤ 2mᵢw, and the static filter's
    /// analysis (at `cross_products_filtered`) bounds the rounding error by
    /// 10.2u·(P₀P₁ + P₂P₃) ≤ 40.8u·w²·(m₀m₁ + m₂m₃). Underflow adds at most 2^-1074 per
    /// factor times the other factor (≤ 2.02w²), four times, plus 2^-1075 per product
    /// of factors: below 2^-1070.9·w² + 2^-1074. The bound used
    /// (`ExactWithin::short_edges_bound`) is at least
    /// `48u·P·(m₀m₁ + m₂m₃) + 2^-1069·P + 2^-1072` (P = fl(w²); the margins cover its
    /// own roundings, and an underflowing m₀m₁ loses at most 48u·P·2^-1074), and it is
    /// finite only where `B₄` is, `P ∈ [2^-400, 2^250]`: no difference exceeds 2^125,
    /// no value overflows. Elsewhere every undecided call goes out of line. For edges
    /// of length `e` it is about `B₄·e²/w²`.
    #[inline(always)]
    fn cross_products_sign_of_short_edges(self, factors: [[Point; 4]; 4]) -> Sign {
        let cross = |[ux, uy, vx, vy]: [f64; 4]| ux * vy - uy * vx;
        let d = factors.map(factor_differences);
        let s = cross(d[0]) * cross(d[1]) + cross(d[2]) * cross(d[3]);
        if s > self.four {
            return Sign::Positive;
        } else if s < self.neg_four {
            return Sign::Negative;
        }
        let [
            [a0, b0, c0, d0],
            [a1, b1, c1, d1],
            [a2, b2, c2, d2],
            [a3, b3, c3, d3],
        ] = factors;
        short_edges_within_slow(
            self.two, self.four, a0, b0, c0, d0, a1, b1, c1, d1, a2, b2, c2, d2, a3, b3, c3, d3,
        )
    }
}

/// [`ExactWithin`]'s undecided calls: a repeated point answers zero at once (the
/// algorithms ask such questions once or twice per query, and [`Exact`] would find
/// the zero only after its filters); everything else goes to [`Exact`]'s static
/// filter and what follows it.
#[cold]
#[inline(never)]
fn orient_within_slow(a: Point, b: Point, c: Point) -> Orientation {
    // `b == c` first: the pruning loops' repeated points are mostly the last two
    // (a vertex two polygons share, asked about from a third point).
    if b == c || a == b || a == c {
        return Orientation::Collinear;
    }
    Exact.orient(a, b, c)
}

/// [`orient_within_slow`] of points read through references ([`Kernel::orient_of`]).
#[cold]
#[inline(never)]
fn orient_within_slow_of(a: &Point, b: &Point, c: &Point) -> Orientation {
    orient_within_slow(*a, *b, *c)
}

#[cold]
#[inline(never)]
fn cross_within_slow(a: Point, b: Point, c: Point, d: Point) -> Orientation {
    if a == b || c == d {
        return Orientation::Collinear;
    }
    Exact.cross(a, b, c, d)
}

#[cold]
#[inline(never)]
fn dot_within_slow(a: Point, b: Point, c: Point, d: Point) -> Sign {
    Exact.dot(a, b, c, d)
}

/// Hands the factors of an undecided degree-4 call to [`cross_products_within_slow`]
/// point by point (registers and the argument area, written on this path only):
/// passed as an array, the array had to be in memory before the comparison, which cost
/// the algorithms' hot paths sixteen stores per call.
#[inline(always)]
fn cross_products_out_of_line(factors: [[Point; 4]; 4]) -> Sign {
    let [
        [a0, b0, c0, d0],
        [a1, b1, c1, d1],
        [a2, b2, c2, d2],
        [a3, b3, c3, d3],
    ] = factors;
    cross_products_within_slow(a0, b0, c0, d0, a1, b1, c1, d1, a2, b2, c2, d2, a3, b3, c3, d3)
}

/// [`ExactWithin::cross_products_sign`]'s undecided calls, the sixteen points of its
/// factors in order: [`Exact`]'s static filter and what follows it.
#[cold]
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn cross_products_within_slow(
    a0: Point,
    b0: Point,
    c0: Point,
    d0: Point,
    a1: Point,
    b1: Point,
    c1: Point,
    d1: Point,
    a2: Point,
    b2: Point,
    c2: Point,
    d2: Point,
    a3: Point,
    b3: Point,
    c3: Point,
    d3: Point,
) -> Sign {
    Exact.cross_products_sign([
        [a0, b0, c0, d0],
        [a1, b1, c1, d1],
        [a2, b2, c2, d2],
        [a3, b3, c3, d3],
    ])
}

/// [`ExactWithin::cross_products_sign_of_short_edges`]'s calls that `B₄` leaves open
/// (with `B₂` and `B₄` of the kernel, and the sixteen points of the factors in order):
/// the bound scaled to the short directions' lengths (derivation at the method), then
/// [`Exact`]'s static filter and what follows it. Out of line: on a kernel from
/// [`Kernel::within_short_edges`] the per-query bound leaves almost nothing to it, and
/// the per-call bound's dozen instructions and registers stay out of the caller's loop.
#[cold]
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn short_edges_within_slow(
    two: f64,
    four: f64,
    a0: Point,
    b0: Point,
    c0: Point,
    d0: Point,
    a1: Point,
    b1: Point,
    c1: Point,
    d1: Point,
    a2: Point,
    b2: Point,
    c2: Point,
    d2: Point,
    a3: Point,
    b3: Point,
    c3: Point,
    d3: Point,
) -> Sign {
    let k = ExactWithin {
        two,
        four,
        neg_two: -two,
        neg_four: -four,
    };
    let factors = [
        [a0, b0, c0, d0],
        [a1, b1, c1, d1],
        [a2, b2, c2, d2],
        [a3, b3, c3, d3],
    ];
    let cross = |[ux, uy, vx, vy]: [f64; 4]| ux * vy - uy * vx;
    let d = factors.map(factor_differences);
    let s = cross(d[0]) * cross(d[1]) + cross(d[2]) * cross(d[3]);
    // Plain comparisons: a NaN difference (outside the boxes' contract) gives a NaN
    // `s`, which fails both tests below.
    let short = |[ux, uy, _, _]: [f64; 4]| {
        let (x, y) = (ux.abs(), uy.abs());
        if x > y { x } else { y }
    };
    let bound = k.short_edges_bound(short(d[0]) * short(d[1]) + short(d[2]) * short(d[3]));
    if s > bound {
        Sign::Positive
    } else if s < -bound {
        Sign::Negative
    } else {
        Exact.cross_products_sign(factors)
    }
}

/// The static filter for `det = l − r` or `det = l + r`, `l` and `r` each a product of
/// two differences of inputs (`orient`, `cross`, `dot`): the sign of `det` when it is
/// certain, `None` otherwise (including overflow and NaN).
///
/// The test is `|det| > C·|l| + 2·f64::MIN_POSITIVE` (see [`certain`]).
#[inline(always)]
fn two_products_filtered(det: f64, l: f64) -> Option<Sign> {
    if certain(det, l) {
        Some(nonzero_sign(det))
    } else {
        None
    }
}

/// True when the sign of `det` (`l ∓ r`, computed in `f64`) is certain; it is then
/// non-zero.
///
/// Shewchuk's static filter certifies the sign when `|det| ≥ ε₀·fl(|l| + |r|)` with
/// ε₀ = (3 + 16u)u, u = 2^-53 (`ORIENT_ERR`), whenever `l` and `r` have the same sign;
/// with opposite signs there is no cancellation and rounding keeps every sign. Products
/// that underflow add at most 2^-1075 each, which `f64::MIN_POSITIVE` absorbs. We bound
/// `|r|` by one product instead of adding both: `|r| ≤ |l| + |l ∓ r|` and
/// `|l ∓ r| ≤ (1 + u)|det|`, so Shewchuk's condition holds when
/// `|det|·(1 − ε₀(1 + u)²) ≥ 2ε₀(1 + u)·|l| + MIN`, which the computed test with
/// `C = 2ε₀(1 + 2^-30)` and `2·MIN` implies (the margin covers the test's own two
/// roundings). One addition fewer than `|l| + |r|` on every call of the hot
/// predicates. The analysis assumes finite differences and products, so `det` must be
/// finite too: a difference that overflows (`f64::MAX − (−f64::MAX)`) times a tiny
/// one is an infinite `r` whose exact value is tiny, next to a finite `l`. The bound
/// therefore also adds 2^-60·|det| (a larger bound is still a valid one), which is
/// infinite exactly when `det` is: without a second branch, `|det| > bound` fails for
/// an infinite `det` as it does for an infinite `l` (infinite bound) and for NaN.
#[inline(always)]
fn certain(det: f64, l: f64) -> bool {
    let m = det.abs();
    m > two_products_bound(l, m)
}

/// The right-hand side of [`certain`], for `m = |det|`.
#[inline(always)]
fn two_products_bound(l: f64, m: f64) -> f64 {
    const C: f64 = 2.0 * ORIENT_ERR * (1.0 + 1.0 / (1u64 << 30) as f64);
    const INFINITE_WITH_DET: f64 = 1.0 / (1u64 << 60) as f64;
    C * l.abs() + (INFINITE_WITH_DET * m + 2.0 * f64::MIN_POSITIVE)
}

/// A number of sign `s`: the slow paths' answers take the place of the computed
/// determinant, so that the fast and the slow path end in the same sign test (the
/// one [`Fast`](super::Fast) makes) instead of merging enum values.
#[inline(always)]
fn as_value(s: Sign) -> f64 {
    match s {
        Sign::Negative => -1.0,
        Sign::Zero => 0.0,
        Sign::Positive => 1.0,
    }
}

/// The sign of a value known to be non-zero (one comparison instead of two).
#[inline(always)]
fn nonzero_sign(x: f64) -> Sign {
    if x > 0.0 { Sign::Positive } else { Sign::Negative }
}

/// The two products of `orient`: (a − c) × (b − c) = left − right.
#[inline(always)]
fn orient_products(a: Point, b: Point, c: Point) -> (f64, f64) {
    ((a.x - c.x) * (b.y - c.y), (a.y - c.y) * (b.x - c.x))
}

/// The two products of `cross`: (b − a) × (d − c) = left − right.
#[inline(always)]
fn cross_products(a: Point, b: Point, c: Point, d: Point) -> (f64, f64) {
    ((b.x - a.x) * (d.y - c.y), (b.y - a.y) * (d.x - c.x))
}

/// The two products of `dot`: (b − a) · (d − c) = left + right.
#[inline(always)]
fn dot_products(a: Point, b: Point, c: Point, d: Point) -> (f64, f64) {
    ((b.x - a.x) * (d.x - c.x), (b.y - a.y) * (d.y - c.y))
}

#[inline(always)]
fn orient_filtered(a: Point, b: Point, c: Point) -> Option<Sign> {
    let (left, right) = orient_products(a, b, c);
    two_products_filtered(left - right, left)
}

#[inline(always)]
fn cross_filtered(a: Point, b: Point, c: Point, d: Point) -> Option<Sign> {
    let (left, right) = cross_products(a, b, c, d);
    two_products_filtered(left - right, left)
}

#[inline(always)]
fn dot_filtered(a: Point, b: Point, c: Point, d: Point) -> Option<Sign> {
    let (left, right) = dot_products(a, b, c, d);
    two_products_filtered(left + right, left)
}

/// The differences `[b.x − a.x, b.y − a.y, d.x − c.x, d.y − c.y]` of one factor
/// `(b − a) × (d − c)` of [`Kernel::cross_products_sign`].
#[inline(always)]
fn factor_differences([a, b, c, d]: [Point; 4]) -> [f64; 4] {
    [b.x - a.x, b.y - a.y, d.x - c.x, d.y - c.y]
}

/// One factor from its differences `[ux, uy, vx, vy]`: its value `ux·vy − uy·vx` and the
/// magnitude `|l| + |r|` of its two products.
#[inline(always)]
fn cross_and_magnitude([ux, uy, vx, vy]: [f64; 4]) -> (f64, f64) {
    let (l, r) = (ux * vy, uy * vx);
    (l - r, l.abs() + r.abs())
}

/// The static filter of [`Kernel::cross_products_sign`]: `S = C₀·C₁ + C₂·C₃` in `f64`.
///
/// With u = 2^-53 and no overflow or underflow: each difference carries a relative
/// error ≤ u, each product of two differences ≤ γ₃ (γₖ = ku/(1 − ku)), so each factor
/// `C̃ᵢ` is within (γ₃ + u(1 + γ₃))·Pᵢ ≤ 4.01u·Pᵢ of `Cᵢ`, with Pᵢ = |lᵢ| + |rᵢ| the
/// magnitude of its products and |C̃ᵢ| ≤ 1.01·Pᵢ; each product `C̃ᵢC̃ⱼ`, rounded, is
/// within 9.1u·PᵢPⱼ of `CᵢCⱼ`, and the final sum adds u·|S̃|. So
/// |S̃ − S| ≤ 10.2u·(P₀P₁ + P₂P₃), and the computed magnitudes differ from the true ones
/// by a factor of at most 1 + 12u; the bound used is 12u times the computed sum Σ.
///
/// Validity: every computed Pᵢ ≥ 2^-480, so an underflowing product of differences
/// (absolute error ≤ 2^-1075) adds at most u²·Pᵢ to its factor, and Σ ≥ 2^-960, so an
/// underflowing product of factors adds at most 2^-114·Σ; Σ ≤ 2^1020, so nothing
/// overflowed (a non-finite difference or product makes some Pᵢ or Σ infinite or
/// NaN, and the comparisons fail) and |S̃| ≤ 2^1021. Both extras fit in the 1.8u·Σ
/// left over. Otherwise, and when |S̃| is within the bound, `None`.
#[inline(always)]
fn cross_products_filtered(factors: &[[Point; 4]; 4]) -> Option<Sign> {
    let (s, bound, valid) = cross_products_bounded(factors);
    if s.abs() > bound && valid {
        Some(nonzero_sign(s))
    } else {
        None
    }
}

/// `S̃`, the error bound of [`cross_products_filtered`] and whether the bound is valid.
#[inline(always)]
fn cross_products_bounded(factors: &[[Point; 4]; 4]) -> (f64, f64, bool) {
    cross_products_from_differences(factors.map(factor_differences))
}

/// [`cross_products_bounded`] from the factors' differences (computed in `f64`, or
/// those scaled exactly by a power of two: the analysis is the same).
#[inline(always)]
fn cross_products_from_differences(d: [[f64; 4]; 4]) -> (f64, f64, bool) {
    const TINY_FACTOR: f64 = f64::from_bits((1023 - 480) << 52); // 2^-480
    const HUGE_SUM: f64 = f64::from_bits((1023 + 1020) << 52); // 2^1020
    let (c0, p0) = cross_and_magnitude(d[0]);
    let (c1, p1) = cross_and_magnitude(d[1]);
    let (c2, p2) = cross_and_magnitude(d[2]);
    let (c3, p3) = cross_and_magnitude(d[3]);
    let s = c0 * c1 + c2 * c3;
    let sum = p0 * p1 + p2 * p3;
    // Plain comparisons rather than `f64::min`: a NaN magnitude makes `sum` NaN, which
    // fails the range test anyway.
    let min = |x: f64, y: f64| if x < y { x } else { y };
    let valid = min(min(p0, p1), min(p2, p3)) >= TINY_FACTOR && sum <= HUGE_SUM;
    let bound = 12.0 * (f64::EPSILON / 2.0) * sum;
    (s, bound, valid)
}

/// The inputs of one predicate call scaled by a common power of two so that the
/// largest magnitude lies in [1, 2), when that is exact for every input (the smallest
/// non-zero magnitude stays in the normal range). Also says whether every non-zero
/// scaled input lies in Shewchuk's exact range [2^-400, 2^400].
struct Rescaled<const N: usize> {
    points: [Point; N],
    adaptive: bool,
}

/// The binary exponent of a finite `x > 0`: `x ∈ [2^e, 2^(e+1))`, subnormals included.
#[inline]
fn exponent(x: f64) -> i32 {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    if biased == 0 {
        -1074 + (63 - bits.leading_zeros() as i32)
    } else {
        biased - 1023
    }
}

/// 2^k for k in the normal exponent range [-1022, 1023].
#[inline]
fn pow2(k: i32) -> f64 {
    debug_assert!((-1022..=1023).contains(&k));
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// The power of two k that puts the largest magnitude among `values` in [1, 2), and
/// the exponent the smallest non-zero magnitude then has; `None` when every value is
/// zero, some value is not finite, or scaling by 2^k would be inexact (the smallest
/// non-zero magnitude would leave the normal range: the values span more than 2^1022).
fn scaling_exponent(values: impl Iterator<Item = f64>) -> Option<(i32, i32)> {
    let (mut hi, mut lo, mut nan) = (0.0f64, f64::INFINITY, false);
    for v in values {
        let m = v.abs();
        nan |= m.is_nan();
        hi = if m > hi { m } else { hi };
        lo = if m != 0.0 && m < lo { m } else { lo };
    }
    if nan || hi == 0.0 || hi == f64::INFINITY {
        return None;
    }
    let k = -exponent(hi);
    let lo_scaled = exponent(lo) + k;
    (lo_scaled >= -1022).then_some((k, lo_scaled))
}

/// Factors whose product, applied left to right, multiplies by 2^k for k ∈ [-1023, 1074]
/// (see [`scaling_exponent`]): one normal power of two where there is one, else two.
/// Exact whenever the result is normal: scaling down, the first product stays above
/// the final one; scaling up, below it.
#[inline]
fn scale_factors(k: i32) -> (f64, f64) {
    if (-1022..=1023).contains(&k) {
        (pow2(k), 1.0)
    } else {
        (pow2(k / 2), pow2(k - k / 2))
    }
}

/// `x · 2^k`, exact when the result is normal (see [`scale_factors`]).
#[inline]
fn scaled_by(x: f64, k: i32) -> f64 {
    let (s1, s2) = scale_factors(k);
    scale_with(x, k, s1, s2)
}

/// `x · s1 · s2` with `(s1, s2) = scale_factors(k)`. A subnormal `x` (m · 2^-1074, m
/// its integer mantissa) scaled up (k > 0) is scaled as the integer m times
/// 2^(k − 1074) instead: the same exact product, but without a subnormal operand,
/// which x86 processors handle in microcode at about a hundred times the cost of a
/// multiplication. Scaled down, a subnormal only rounds further (towards zero), and
/// 2^(k − 1074) would not be a valid factor.
#[inline(always)]
fn scale_with(x: f64, k: i32, s1: f64, s2: f64) -> f64 {
    if x.abs() >= f64::MIN_POSITIVE || x == 0.0 || k <= 0 {
        return x * s1 * s2;
    }
    let bits = x.to_bits();
    let m = (bits & ((1u64 << 52) - 1)) as f64;
    let (t1, t2) = scale_factors(k - 1074);
    let y = m * t1 * t2;
    if bits >> 63 == 1 { -y } else { y }
}

impl<const N: usize> Rescaled<N> {
    /// `None` when every input is zero, some input is not finite, or scaling would be
    /// inexact (the inputs span more than 2^1022 in magnitude).
    #[inline]
    fn new(points: [Point; N]) -> Option<Rescaled<N>> {
        let (k, lo) = scaling_exponent(points.iter().flat_map(|p| [p.x, p.y]))?;
        let (s1, s2) = scale_factors(k);
        let s = |v: f64| scale_with(v, k, s1, s2);
        Some(Rescaled {
            points: points.map(|p| Point::new(s(p.x), s(p.y))),
            adaptive: lo >= -400,
        })
    }
}

/// The differences of one predicate call, computed in `f64` as the static filter
/// computes them, multiplied by the power of two that puts the largest in [1, 2).
/// `None` when a difference overflowed (inputs near ±`f64::MAX`) or all are zero.
///
/// The static filters stay valid on the result: every predicate here is a homogeneous
/// polynomial in such differences, and the scaling is exact except for differences
/// that it moves below the normal range, which it rounds with an absolute error of at
/// most 2^-1075. Each such error, times a difference below 2 in magnitude, adds at most
/// 2^-1074 to a product: far inside the `2·f64::MIN_POSITIVE` that the two-product
/// filter adds to its bound, and a relative 2^-593 of a factor that the degree-4
/// filter accepts (its factors' magnitudes are at least 2^-480). Everything else is
/// the unscaled computation, exactly scaled.
#[inline(always)]
fn scaled_differences<const N: usize>(d: [f64; N]) -> Option<[f64; N]> {
    let hi = d
        .iter()
        .fold(0.0f64, |hi, v| if v.abs() > hi { v.abs() } else { hi });
    if hi == 0.0 || !hi.is_finite() {
        return None;
    }
    let k = -exponent(hi);
    let mut out = d;
    if (-1022..=1022).contains(&k) {
        // The largest difference is normal: one multiplication each by a normal power
        // of two (a subnormal difference next to it is rare: mixed magnitudes).
        let s = pow2(k);
        for v in &mut out {
            *v *= s;
        }
    } else {
        let (s1, s2) = scale_factors(k);
        for v in &mut out {
            *v = scale_with(*v, k, s1, s2);
        }
    }
    Some(out)
}

/// The sign of the signed area of the closed polygon through `points` (twice the
/// area: Σ xᵢ·yᵢ₊₁ − xᵢ₊₁·yᵢ, positive for counter-clockwise), exactly, for every
/// finite input: no overflow at any magnitude, no rounding at any size.
///
/// The points are scaled by a power of two so that the largest magnitude lies in
/// [1, 2) (exact unless they span more than 2^1022) and summed in `f64` with an error
/// bound (recursive summation of n terms: at most γₙ₊₂ times the sum of the terms'
/// product magnitudes, plus 2^-1074 per underflowing product; we use twice that);
/// only when the sum is within the bound, or scaling is inexact, are the terms summed
/// exactly with big integers. O(n) either way; the exact sum costs more per term.
/// Fewer than three points have area zero.
///
/// # Panics
/// On NaN or infinite coordinates.
pub fn area_sign(points: &[Point]) -> Sign {
    area_sign_of(points.len(), |i| points[i])
}

/// [`area_sign`] of the closed polygon whose `n` vertices are `at(0)`, …, `at(n − 1)`,
/// for callers that hold the vertices in another form (indices into an input list).
///
/// # Panics
/// On NaN or infinite coordinates.
pub fn area_sign_of(n: usize, at: impl Fn(usize) -> Point) -> Sign {
    if n < 3 {
        return Sign::Zero;
    }
    let edges = || (0..n).map(|i| (at(i), at(if i + 1 == n { 0 } else { i + 1 })));
    if let Some((k, _)) = scaling_exponent((0..n).flat_map(|i| {
        let p = at(i);
        [p.x, p.y]
    })) {
        let s = |p: Point| Point::new(scaled_by(p.x, k), scaled_by(p.y, k));
        let (mut sum, mut magnitude) = (0.0f64, 0.0f64);
        for (a, b) in edges() {
            let (a, b) = (s(a), s(b));
            let (l, r) = (a.x * b.y, a.y * b.x);
            sum += l - r;
            magnitude += l.abs() + r.abs();
        }
        let u = f64::EPSILON / 2.0;
        let count = n as f64;
        let bound = 2.0 * ((count + 2.0) * u * magnitude + 2.0 * count * f64::from_bits(1));
        if sum.abs() > bound {
            return Sign::of(sum);
        }
    } else {
        assert!((0..n).all(|i| at(i).is_finite()), "area of non-finite points");
    }
    let f = Dyadic::from_f64;
    edges()
        .map(|(a, b)| f(a.x) * f(b.y) - f(a.y) * f(b.x))
        .fold(f(0.0), |acc, t| acc + t)
        .certain_sign()
        .expect("dyadic arithmetic is exact")
}

/// The first out-of-line step of the two-product predicates (`l ∓ r` with
/// `l = d[0]·d[3]`, `r = d[1]·d[2]` for `orient` and `cross`; `l = d[0]·d[2]`,
/// `r = d[1]·d[3]` with a sum for `dot`): calls whose products overflowed or all
/// underflowed (uniformly huge or tiny inputs, 2^±600) are filtered again on their
/// differences times a *fixed* power of two, 2^-600 or 2^600, chosen by the case:
/// a few instructions where [`scaled_differences`] finds the exact exponent.
///
/// Overflow (`|l|` or `|r|` not below 2^1000, or NaN): every difference is below
/// 2^1024, so the scaled ones are below 2^424 and no product overflows. Scaling down
/// is exact except for scaled differences below the normal range, rounded with an
/// absolute error of at most 2^-1075; each, times a scaled difference below 2^424,
/// moves a product by at most 2^-651, so the bound adds 2^-640 (a larger bound stays
/// valid). Underflow (`|l|` and `|r|` below 2^-900): scaling up by 2^600 is exact
/// (subnormal differences become normal), and a scaled difference that overflows
/// makes a product non-finite, which [`certain`] refuses. `None` when neither case
/// applies or the filter still cannot decide.
#[inline(always)]
fn fixed_rescale_sign(d: [f64; 4], dot: bool) -> Option<Sign> {
    const HUGE: f64 = f64::from_bits((1023 + 1000) << 52); // 2^1000
    const TINY: f64 = f64::from_bits((1023 - 900) << 52); // 2^-900
    const DOWN: f64 = f64::from_bits((1023 - 600) << 52); // 2^-600
    const UP: f64 = f64::from_bits((1023 + 600) << 52); // 2^600
    const LOST: f64 = f64::from_bits((1023 - 640) << 52); // 2^-640
    let products = |d: [f64; 4]| {
        if dot {
            (d[0] * d[2], d[1] * d[3])
        } else {
            (d[0] * d[3], d[1] * d[2])
        }
    };
    let (l, r) = products(d);
    let (scale, extra) = if !(l.abs() < HUGE && r.abs() < HUGE) {
        (DOWN, LOST)
    } else if l.abs() < TINY && r.abs() < TINY {
        (UP, 0.0)
    } else {
        return None;
    };
    let (l, r) = products(d.map(|v| v * scale));
    let det = if dot { l + r } else { l - r };
    let m = det.abs();
    (m > two_products_bound(l, m) + extra).then(|| nonzero_sign(det))
}

#[cold]
#[inline(never)]
fn orient_slow(a: Point, b: Point, c: Point) -> Sign {
    let d = [a.x - c.x, a.y - c.y, b.x - c.x, b.y - c.y];
    if let Some(s) = fixed_rescale_sign(d, false) {
        return s;
    }
    if let Some([dx1, dy1, dx2, dy2]) = scaled_differences(d) {
        let (l, r) = (dx1 * dy2, dy1 * dx2);
        if certain(l - r, l) {
            return nonzero_sign(l - r);
        }
    }
    if a == b || a == c || b == c {
        return Sign::Zero;
    }
    if let Some(r) = Rescaled::new([a, b, c]) {
        let [a, b, c] = r.points;
        if let Some(s) = orient_filtered(a, b, c) {
            return s;
        }
        if r.adaptive {
            return robust_orient(a, b, c);
        }
    }
    sign_slow(&OrientPoly(a, b, c))
}

/// Shewchuk's adaptive `orient2d`; exact when every non-zero coordinate is in
/// [2^-400, 2^400].
#[inline]
fn robust_orient(a: Point, b: Point, c: Point) -> Sign {
    Sign::of(robust::orient2d(
        robust::Coord { x: a.x, y: a.y },
        robust::Coord { x: b.x, y: b.y },
        robust::Coord { x: c.x, y: c.y },
    ))
}

/// `x − y` when the floating-point difference is exact (Knuth's two-difference has
/// no error term), `None` otherwise.
#[inline]
fn exact_difference(x: f64, y: f64) -> Option<f64> {
    let d = x - y;
    let y_virtual = x - d;
    let x_virtual = d + y_virtual;
    let error = (x - x_virtual) + (y_virtual - y);
    (error == 0.0).then_some(d)
}

/// The directions `b − a` and `d − c` of a scaled call, when both are exact and
/// Shewchuk's predicate is exact on them (as coordinates).
fn exact_directions(r: &Rescaled<4>) -> Option<(Point, Point)> {
    if !r.adaptive {
        return None;
    }
    let [a, b, c, d] = r.points;
    Some((
        Point::new(exact_difference(b.x, a.x)?, exact_difference(b.y, a.y)?),
        Point::new(exact_difference(d.x, c.x)?, exact_difference(d.y, c.y)?),
    ))
}

#[cold]
#[inline(never)]
fn cross_slow(a: Point, b: Point, c: Point, d: Point) -> Sign {
    let diffs = [b.x - a.x, b.y - a.y, d.x - c.x, d.y - c.y];
    if let Some(s) = fixed_rescale_sign(diffs, false) {
        return s;
    }
    if let Some([ux, uy, vx, vy]) = scaled_differences(diffs) {
        let (l, r) = (ux * vy, uy * vx);
        if certain(l - r, l) {
            return nonzero_sign(l - r);
        }
    }
    if a == b || c == d || (a == c && b == d) || (a == d && b == c) {
        return Sign::Zero;
    }
    if let Some(r) = Rescaled::new([a, b, c, d]) {
        let [sa, sb, sc, sd] = r.points;
        if let Some(s) = cross_filtered(sa, sb, sc, sd) {
            return s;
        }
        // u × v = orient(u, v, 0): exact when u and v are.
        if let Some((u, v)) = exact_directions(&r) {
            return robust_orient(u, v, Point::new(0.0, 0.0));
        }
    }
    sign_slow(&CrossPoly(a, b, c, d))
}

#[cold]
#[inline(never)]
fn dot_slow(a: Point, b: Point, c: Point, d: Point) -> Sign {
    let diffs = [b.x - a.x, b.y - a.y, d.x - c.x, d.y - c.y];
    if let Some(s) = fixed_rescale_sign(diffs, true) {
        return s;
    }
    if let Some([ux, uy, vx, vy]) = scaled_differences(diffs) {
        let (l, r) = (ux * vx, uy * vy);
        if certain(l + r, l) {
            return nonzero_sign(l + r);
        }
    }
    if a == b || c == d {
        return Sign::Zero;
    }
    if let Some(r) = Rescaled::new([a, b, c, d]) {
        let [sa, sb, sc, sd] = r.points;
        if let Some(s) = dot_filtered(sa, sb, sc, sd) {
            return s;
        }
        // u · v = (u.x, −u.y) × (v.y, v.x) = orient((u.x, −u.y), (v.y, v.x), 0).
        if let Some((u, v)) = exact_directions(&r) {
            return robust_orient(Point::new(u.x, -u.y), Point::new(v.y, v.x), Point::new(0.0, 0.0));
        }
    }
    sign_slow(&DotPoly(a, b, c, d))
}

#[cold]
#[inline(never)]
fn cross_products_slow(factors: [[Point; 4]; 4]) -> Sign {
    let d = factors.map(factor_differences);
    if let Some(sd) = scaled_differences(std::array::from_fn::<f64, 16, _>(|i| d[i / 4][i % 4])) {
        let (s, bound, valid) =
            cross_products_from_differences(std::array::from_fn(|i| std::array::from_fn(|j| sd[4 * i + j])));
        if valid && s.abs() > bound {
            return nonzero_sign(s);
        }
    }
    // A factor whose two points of a pair coincide is exactly zero.
    let zero = |[a, b, c, d]: [Point; 4]| a == b || c == d;
    let [f0, f1, f2, f3] = factors;
    if (zero(f0) || zero(f1)) && (zero(f2) || zero(f3)) {
        return Sign::Zero;
    }
    let flat: [Point; 16] = std::array::from_fn(|i| factors[i / 4][i % 4]);
    let scaled =
        Rescaled::new(flat).map(|r| std::array::from_fn(|i| std::array::from_fn(|j| r.points[4 * i + j])));
    let factors = scaled.unwrap_or(factors);
    if scaled.is_some()
        && let Some(s) = cross_products_filtered(&factors)
    {
        return s;
    }
    let poly = CrossProductsPoly(factors);
    match poly.eval::<Interval>().certain_sign() {
        Some(s) => s,
        None => sign_slow(&poly),
    }
}

#[cold]
#[inline(never)]
fn sign_slow<P: Polynomial>(poly: &P) -> Sign {
    poly.eval::<Dyadic>()
        .certain_sign()
        .expect("dyadic arithmetic is exact")
}

/// True when every value is zero or has magnitude in [2^-400, 2^400], the range in
/// which Shewchuk's adaptive predicates are exact (no intermediate overflow or underflow).
#[doc(hidden)]
#[inline]
pub fn in_adaptive_range(values: &[f64]) -> bool {
    values.iter().all(|&v| {
        let m = v.abs();
        v == 0.0 || (ADAPTIVE_MIN..=ADAPTIVE_MAX).contains(&m)
    })
}

/// The orientation polynomial (a − c) × (b − c), for the exact fallback and for tests.
pub(crate) struct OrientPoly(pub Point, pub Point, pub Point);

impl Polynomial for OrientPoly {
    fn eval<R: Ring>(&self) -> R {
        let f = R::from_f64;
        let (a, b, c) = (self.0, self.1, self.2);
        (f(a.x) - f(c.x)) * (f(b.y) - f(c.y)) - (f(a.y) - f(c.y)) * (f(b.x) - f(c.x))
    }
}

/// A closed interval of reals, with every operation rounded outward by one ulp,
/// so the true value of a polynomial always lies inside the computed interval.
#[doc(hidden)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    pub lo: f64,
    pub hi: f64,
}

impl Interval {
    #[inline]
    fn widened(lo: f64, hi: f64) -> Interval {
        Interval {
            lo: lo.next_down(),
            hi: hi.next_up(),
        }
    }
}

impl Add for Interval {
    type Output = Interval;
    #[inline]
    fn add(self, o: Interval) -> Interval {
        Interval::widened(self.lo + o.lo, self.hi + o.hi)
    }
}

impl Sub for Interval {
    type Output = Interval;
    #[inline]
    fn sub(self, o: Interval) -> Interval {
        Interval::widened(self.lo - o.hi, self.hi - o.lo)
    }
}

impl Mul for Interval {
    type Output = Interval;
    #[inline]
    fn mul(self, o: Interval) -> Interval {
        let p = [self.lo * o.lo, self.lo * o.hi, self.hi * o.lo, self.hi * o.hi];
        if p.iter().any(|x| x.is_nan()) {
            return Interval {
                lo: f64::NEG_INFINITY,
                hi: f64::INFINITY,
            };
        }
        let lo = p[0].min(p[1]).min(p[2]).min(p[3]);
        let hi = p[0].max(p[1]).max(p[2]).max(p[3]);
        Interval::widened(lo, hi)
    }
}

impl Ring for Interval {
    #[inline]
    fn from_f64(x: f64) -> Self {
        Interval { lo: x, hi: x }
    }
    #[inline]
    fn certain_sign(&self) -> Option<Sign> {
        if self.lo > 0.0 {
            Some(Sign::Positive)
        } else if self.hi < 0.0 {
            Some(Sign::Negative)
        } else {
            None
        }
    }
}

/// An exact dyadic rational `mantissa · 2^exponent` with a big-integer mantissa:
/// every finite `f64` is one, and `+ - *` on them are exact.
#[doc(hidden)]
#[derive(Clone, Debug, PartialEq)]
pub struct Dyadic {
    mantissa: BigInt,
    exponent: i64,
}

impl Dyadic {
    fn align(self, other: Dyadic) -> (BigInt, BigInt, i64) {
        let e = self.exponent.min(other.exponent);
        let a = self.mantissa << (self.exponent - e) as usize;
        let b = other.mantissa << (other.exponent - e) as usize;
        (a, b, e)
    }
}

impl Dyadic {
    /// The mantissa and the exponent: the value is `mantissa · 2^exponent`.
    pub fn parts(&self) -> (&BigInt, i64) {
        (&self.mantissa, self.exponent)
    }
}

/// Splits a finite `f64` into an integer mantissa and a power-of-two exponent.
fn decompose(x: f64) -> (i64, i64) {
    let bits = x.to_bits();
    let negative = bits >> 63 == 1;
    let biased = ((bits >> 52) & 0x7ff) as i64;
    let fraction = (bits & ((1u64 << 52) - 1)) as i64;
    let (m, e) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1i64 << 52), biased - 1075)
    };
    (if negative { -m } else { m }, e)
}

impl Add for Dyadic {
    type Output = Dyadic;
    fn add(self, o: Dyadic) -> Dyadic {
        let (a, b, e) = self.align(o);
        Dyadic {
            mantissa: a + b,
            exponent: e,
        }
    }
}

impl Sub for Dyadic {
    type Output = Dyadic;
    fn sub(self, o: Dyadic) -> Dyadic {
        let (a, b, e) = self.align(o);
        Dyadic {
            mantissa: a - b,
            exponent: e,
        }
    }
}

impl Mul for Dyadic {
    type Output = Dyadic;
    fn mul(self, o: Dyadic) -> Dyadic {
        Dyadic {
            mantissa: self.mantissa * o.mantissa,
            exponent: self.exponent + o.exponent,
        }
    }
}

impl Ring for Dyadic {
    /// # Panics
    /// On NaN or infinity, which validated inputs never contain.
    fn from_f64(x: f64) -> Self {
        assert!(x.is_finite(), "exact arithmetic on a non-finite value");
        let (m, e) = decompose(x);
        Dyadic {
            mantissa: BigInt::from(m),
            exponent: e,
        }
    }
    fn certain_sign(&self) -> Option<Sign> {
        Some(if self.mantissa.is_zero() {
            Sign::Zero
        } else if self.mantissa.is_positive() {
            Sign::Positive
        } else {
            Sign::Negative
        })
    }
}

#[cfg(test)]
mod tests;
