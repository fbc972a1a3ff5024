//! Layer 0 of the exact kernel: [`ExactWithin`], the semi-static filter for a query that
//! names the bounding boxes of its points; its undecided calls go to
//! [`Exact`](super::Exact)'s predicates (`predicates.rs`).

use super::predicates;
use super::static_filter::{
    ORIENT_ERR, certain, cross_products, cross_products_from_differences, dot_products, factor_differences,
    nonzero_sign, orient_products,
};
use crate::kernel::{BoundingBox, DirectedLine, Kernel, Orientation, Point, Polynomial, Sign};

/// The exact kernel for one query whose points lie in known boxes ([`Kernel::within`]):
/// [`Exact`](super::Exact) behind a *semi-static* filter.
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
/// that sign: the same two comparisons the [`Fast`](crate::Fast) kernel makes against
/// zero. Anything else (a value within the bound, NaN, a bound out of its range,
/// which is `+∞`) goes to [`Exact`](super::Exact)'s own layers, out of line, except that a degree-4
/// call first tries [`Exact`](super::Exact)'s static filter inline (its derivation at
/// `cross_products_filtered`; it refuses what it cannot vouch for, including
/// overflow and underflow, and those calls go on out of line), and that
/// [`Kernel::cross_products_sign_of_short_edges`] (Chazelle–Dobkin's slope comparison,
/// whose factors are short edges times long vectors, seldom decided by `B₄` at large
/// n) tries a bound scaled to the edges inline instead. The default value has
/// infinite bounds: every call goes to [`Exact`](super::Exact).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExactWithin {
    /// `B₂`, or `+∞` when not valid.
    pub(super) two: f64,
    /// `B₄`, or `+∞` when not valid.
    pub(super) four: f64,
    /// `−B₂` and `−B₄`, kept so that a call compares without negating.
    pub(super) neg_two: f64,
    pub(super) neg_four: f64,
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
    /// The kernel for queries on points inside the union of `boxes` .
    /// Boxes with non-finite corners give infinite bounds (every call goes to [`Exact`](super::Exact)).
    #[inline]
    pub fn new([b0, b1]: [BoundingBox; 2]) -> ExactWithin {
        let ((lo0, hi0), (lo1, hi1)) = ((b0.min, b0.max), (b1.min, b1.max));
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
    #[inline]
    pub fn for_differences(w: f64) -> ExactWithin {
        // A negative `w` promises nothing about magnitudes: NaN fails both range tests.
        ExactWithin::from_side(if w >= 0.0 { w } else { f64::NAN })
    }

    /// The bounds for differences at most `|w|` (NaN or infinite: `+∞`).
    #[inline(always)]
    pub(super) fn from_side(w: f64) -> ExactWithin {
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
}

impl crate::kernel::sealed::Predicates for ExactWithin {
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
        predicates::sign(poly)
    }

    /// `cross`'s semi-static test, then [`Exact`](super::Exact)'s static filter inline (valid for
    /// any input: `certain` refuses overflow), then out of line. Written out beside
    /// `cross` rather than sharing a generic body: with the shared body (a const
    /// parameter choosing the inline filter) the compiler inlined `cross` differently
    /// and Linear's exact overhead rose (docs/results.md).
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
    /// [`Exact`](super::Exact)'s static filter and what follows it out of line.
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
/// algorithms ask such questions once or twice per query, and [`Exact`](super::Exact) would find
/// the zero only after its filters); everything else goes to [`Exact`](super::Exact)'s static
/// filter and what follows it.
#[cold]
#[inline(never)]
pub(super) fn orient_within_slow(a: Point, b: Point, c: Point) -> Orientation {
    // `b == c` first: the pruning loops' repeated points are mostly the last two
    // (a vertex two polygons share, asked about from a third point).
    if b == c || a == b || a == c {
        return Orientation::Collinear;
    }
    predicates::orient(a, b, c)
}

/// [`orient_within_slow`] of points read through references ([`Kernel::orient_of`]).
#[cold]
#[inline(never)]
pub(super) fn orient_within_slow_of(a: &Point, b: &Point, c: &Point) -> Orientation {
    orient_within_slow(*a, *b, *c)
}

#[cold]
#[inline(never)]
pub(super) fn cross_within_slow(a: Point, b: Point, c: Point, d: Point) -> Orientation {
    if a == b || c == d {
        return Orientation::Collinear;
    }
    predicates::cross(a, b, c, d)
}

#[cold]
#[inline(never)]
pub(super) fn dot_within_slow(a: Point, b: Point, c: Point, d: Point) -> Sign {
    predicates::dot(a, b, c, d)
}

/// Hands the factors of an undecided degree-4 call to [`cross_products_within_slow`]
/// point by point (registers and the argument area, written on this path only):
/// passed as an array, the array had to be in memory before the comparison, which cost
/// the algorithms' hot paths sixteen stores per call.
#[inline(always)]
pub(super) fn cross_products_out_of_line(factors: [[Point; 4]; 4]) -> Sign {
    let [
        [a0, b0, c0, d0],
        [a1, b1, c1, d1],
        [a2, b2, c2, d2],
        [a3, b3, c3, d3],
    ] = factors;
    cross_products_within_slow(a0, b0, c0, d0, a1, b1, c1, d1, a2, b2, c2, d2, a3, b3, c3, d3)
}

/// [`ExactWithin::cross_products_sign`]'s undecided calls, the sixteen points of its
/// factors in order: [`Exact`](super::Exact)'s static filter and what follows it.
#[cold]
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub(super) fn cross_products_within_slow(
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
    predicates::cross_products_sign([
        [a0, b0, c0, d0],
        [a1, b1, c1, d1],
        [a2, b2, c2, d2],
        [a3, b3, c3, d3],
    ])
}

/// [`ExactWithin::cross_products_sign_of_short_edges`]'s calls that `B₄` leaves open
/// (with `B₂` and `B₄` of the kernel, and the sixteen points of the factors in order):
/// the bound scaled to the short directions' lengths (derivation at the method), then
/// [`Exact`](super::Exact)'s static filter and what follows it. Out of line: on a kernel from
/// [`Kernel::within_short_edges`] the per-query bound leaves almost nothing to it, and
/// the per-call bound's dozen instructions and registers stay out of the caller's loop.
#[cold]
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub(super) fn short_edges_within_slow(
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
        predicates::cross_products_sign(factors)
    }
}
