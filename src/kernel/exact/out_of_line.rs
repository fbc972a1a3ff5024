//! Layer 2 of the exact kernel, out of line (`#[cold]`): fixed and exact rescaling,
//! structural zeros, Shewchuk's adaptive `orient2d` in its safe range, intervals for
//! degree 4, then the exact fallback (layer 3, [`Dyadic`]) for what is still undecided.

use super::dyadic::Dyadic;
use super::interval::Interval;
use super::static_filter::{
    certain, cross_filtered, cross_products_filtered, cross_products_from_differences, dot_filtered,
    factor_differences, nonzero_sign, orient_filtered, two_products_bound,
};
use crate::kernel::{CrossPoly, CrossProductsPoly, DotPoly, Point, Polynomial, Ring, Sign};

/// The range in which Shewchuk's adaptive predicates are exact (no intermediate
/// overflow or underflow); the unit tests check the bounds the filters rely on.
#[cfg(test)]
pub(super) const ADAPTIVE_MIN: f64 = f64::from_bits((1023 - 400) << 52); // 2^-400
#[cfg(test)]
pub(super) const ADAPTIVE_MAX: f64 = f64::from_bits((1023 + 400) << 52); // 2^400

/// The inputs of one predicate call scaled by a common power of two so that the
/// largest magnitude lies in [1, 2), when that is exact for every input (the smallest
/// non-zero magnitude stays in the normal range). Also says whether every non-zero
/// scaled input lies in Shewchuk's exact range [2^-400, 2^400].
pub(super) struct Rescaled<const N: usize> {
    pub(super) points: [Point; N],
    pub(super) adaptive: bool,
}

/// The binary exponent of a finite `x > 0`: `x ∈ [2^e, 2^(e+1))`, subnormals included.
#[inline]
pub(super) fn exponent(x: f64) -> i32 {
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
pub(super) fn pow2(k: i32) -> f64 {
    debug_assert!((-1022..=1023).contains(&k));
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// The power of two k that puts the largest magnitude among `values` in [1, 2), and
/// the exponent the smallest non-zero magnitude then has; `None` when every value is
/// zero, some value is not finite, or scaling by 2^k would be inexact (the smallest
/// non-zero magnitude would leave the normal range: the values span more than 2^1022).
pub(super) fn scaling_exponent(values: impl Iterator<Item = f64>) -> Option<(i32, i32)> {
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
pub(super) fn scale_factors(k: i32) -> (f64, f64) {
    if (-1022..=1023).contains(&k) {
        (pow2(k), 1.0)
    } else {
        (pow2(k / 2), pow2(k - k / 2))
    }
}

/// `x · 2^k`, exact when the result is normal (see [`scale_factors`]).
#[inline]
pub(super) fn scaled_by(x: f64, k: i32) -> f64 {
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
pub(super) fn scale_with(x: f64, k: i32, s1: f64, s2: f64) -> f64 {
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
    pub(super) fn new(points: [Point; N]) -> Option<Rescaled<N>> {
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
pub(super) fn scaled_differences<const N: usize>(d: [f64; N]) -> Option<[f64; N]> {
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
pub(super) fn fixed_rescale_sign(d: [f64; 4], dot: bool) -> Option<Sign> {
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
pub(super) fn orient_slow(a: Point, b: Point, c: Point) -> Sign {
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
pub(super) fn robust_orient(a: Point, b: Point, c: Point) -> Sign {
    Sign::of(robust::orient2d(
        robust::Coord { x: a.x, y: a.y },
        robust::Coord { x: b.x, y: b.y },
        robust::Coord { x: c.x, y: c.y },
    ))
}

/// `x − y` when the floating-point difference is exact (Knuth's two-difference has
/// no error term), `None` otherwise.
#[inline]
pub(super) fn exact_difference(x: f64, y: f64) -> Option<f64> {
    let d = x - y;
    let y_virtual = x - d;
    let x_virtual = d + y_virtual;
    let error = (x - x_virtual) + (y_virtual - y);
    (error == 0.0).then_some(d)
}

/// The directions `b − a` and `d − c` of a scaled call, when both are exact and
/// Shewchuk's predicate is exact on them (as coordinates).
pub(super) fn exact_directions(r: &Rescaled<4>) -> Option<(Point, Point)> {
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
pub(super) fn cross_slow(a: Point, b: Point, c: Point, d: Point) -> Sign {
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
pub(super) fn dot_slow(a: Point, b: Point, c: Point, d: Point) -> Sign {
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
pub(super) fn cross_products_slow(factors: [[Point; 4]; 4]) -> Sign {
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
pub(super) fn sign_slow<P: Polynomial>(poly: &P) -> Sign {
    poly.eval::<Dyadic>()
        .certain_sign()
        .expect("dyadic arithmetic is exact")
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
