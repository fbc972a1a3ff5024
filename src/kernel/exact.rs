//! The exact kernel: correct signs for every finite `f64` input.
//!
//! # Layers
//! 1. **Filter.** The predicate is evaluated in `f64` together with a bound on its
//!    rounding error; when the result is farther from zero than the bound, its sign
//!    is the exact sign. `orient` uses Shewchuk's static bound
//!    (`(3 + 16ε)ε · (|l| + |r|)`, plus `f64::MIN_POSITIVE` to absorb underflow);
//!    other predicates are evaluated in [`Interval`] arithmetic with outward
//!    rounding by one ulp per operation. On random input this layer decides
//!    essentially every call.
//! 2. **Adaptive.** `orient` falls back to Shewchuk's adaptive `orient2d` (the
//!    `robust` crate), whose expansion arithmetic is exact as long as no
//!    intermediate product overflows or underflows. That holds when every non-zero
//!    coordinate has magnitude in [2^-400, 2^400] ([`in_adaptive_range`]): every
//!    difference and expansion component is then a multiple of 2^-453 and every
//!    product a multiple of 2^-906 (above the subnormal range) and below 2^804.
//! 3. **Exact fallback.** Outside that range (huge, tiny or subnormal coordinates,
//!    or mixtures of magnitudes), and for predicates other than `orient` whenever the
//!    filter cannot decide, the polynomial is evaluated on the exact dyadic values
//!    `m · 2^e` of the inputs with big integers ([`Dyadic`]). No finite input is
//!    refused and none is misjudged; the cost is paid only by near-degenerate calls.

use super::{Kernel, LineMeetSidePoly, Orientation, Point, Polynomial, Ring, Sign};
use num_bigint::BigInt;
use num_traits::{Signed, Zero};
use std::ops::{Add, Mul, Sub};

/// Shewchuk's `ccwerrboundA`: (3 + 16ε)ε with ε = 2^-53.
const ORIENT_ERR: f64 = (3.0 + 16.0 * (f64::EPSILON / 2.0)) * (f64::EPSILON / 2.0);
const ADAPTIVE_MIN: f64 = f64::from_bits((1023 - 400) << 52); // 2^-400
const ADAPTIVE_MAX: f64 = f64::from_bits((1023 + 400) << 52); // 2^400

/// Exact predicates for every finite input; the default kernel. See the module docs
/// for the three layers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Exact;

impl Kernel for Exact {
    const NAME: &'static str = "exact";

    #[inline]
    fn orient(self, a: Point, b: Point, c: Point) -> Orientation {
        let left = (a.x - c.x) * (b.y - c.y);
        let right = (a.y - c.y) * (b.x - c.x);
        match filtered(left, right, left - right) {
            Some(s) => s.into(),
            None => orient_slow(a, b, c),
        }
    }

    #[inline]
    fn sign<P: Polynomial>(self, poly: &P) -> Sign {
        match poly.eval::<Interval>().certain_sign() {
            Some(s) => s,
            None => sign_slow(poly),
        }
    }

    /// Same shape as `orient` (two products of differences), so the same static filter.
    #[inline]
    fn cross(self, a: Point, b: Point, c: Point, d: Point) -> Orientation {
        let left = (b.x - a.x) * (d.y - c.y);
        let right = (b.y - a.y) * (d.x - c.x);
        filtered(left, right, left - right)
            .unwrap_or_else(|| sign_slow(&super::CrossPoly(a, b, c, d)))
            .into()
    }

    /// A static filter for `D·A + N·B`, each factor a cross product of differences,
    /// then the interval filter and the exact fallback (see [`line_meet_filtered`]).
    #[inline]
    fn line_meet_sign(self, pts: [Point; 6]) -> Sign {
        line_meet_filtered(pts).unwrap_or_else(|| self.sign(&LineMeetSidePoly(pts)))
    }

    /// Same shape as `orient` with a sum instead of a difference: the same static filter.
    #[inline]
    fn dot(self, a: Point, b: Point, c: Point, d: Point) -> Sign {
        let left = (b.x - a.x) * (d.x - c.x);
        let right = (b.y - a.y) * (d.y - c.y);
        filtered(left, right, left + right).unwrap_or_else(|| sign_slow(&super::DotPoly(a, b, c, d)))
    }
}

/// The static filter of [`Exact::line_meet_sign`]: `S = D·A + N·B` with
/// `D = (b−a)×(d−c)`, `N = (c−a)×(d−c)`, `A = (f−e)×(a−e)`, `B = (f−e)×(b−a)`,
/// evaluated in `f64`. With u = 2^-53, every difference carries a relative error
/// ≤ u, each cross product an absolute error ≤ 4.01u·P (P its permanent, the sum of
/// the two products' magnitudes), each product of two of them ≤ 9.1u·P₁P₂ and the
/// sum adds u·|S|, so |S̃ − S| ≤ 10.2u·(P_D·P_A + P_N·P_B); we use 12u. The bound is
/// trusted only when every computed difference is 0 or has magnitude in
/// [2^-250, 2^250]: then no product overflows, products of differences never
/// underflow, and an underflow in a product of two cross products (at most 2^-1074)
/// is far below the 1.8u·2^-1000 left over in the bound; otherwise, and when |S̃| is
/// within the bound, `None`.
#[inline]
fn line_meet_filtered([a, b, c, d, e, f]: [Point; 6]) -> Option<Sign> {
    const U: f64 = f64::EPSILON / 2.0;
    const LO: f64 = f64::from_bits((1023 - 250) << 52); // 2^-250
    const HI: f64 = f64::from_bits((1023 + 250) << 52); // 2^250
    let cross = |ux: f64, uy: f64, vx: f64, vy: f64| {
        let (l, r) = (ux * vy, uy * vx);
        (l - r, l.abs() + r.abs())
    };
    let (bax, bay, dcx, dcy) = (b.x - a.x, b.y - a.y, d.x - c.x, d.y - c.y);
    let (fex, fey, cax, cay, aex, aey) = (f.x - e.x, f.y - e.y, c.x - a.x, c.y - a.y, a.x - e.x, a.y - e.y);
    let diffs = [bax, bay, dcx, dcy, fex, fey, cax, cay, aex, aey];
    if !diffs.iter().all(|&v| v == 0.0 || (LO..=HI).contains(&v.abs())) {
        return None;
    }
    let (den, pd) = cross(bax, bay, dcx, dcy);
    let (num, pn) = cross(cax, cay, dcx, dcy);
    let (side_a, pa) = cross(fex, fey, aex, aey);
    let (side_dir, pb) = cross(fex, fey, bax, bay);
    let s = den * side_a + num * side_dir;
    let bound = 12.0 * U * (pd * pa + pn * pb);
    if s > bound {
        Some(Sign::Positive)
    } else if -s > bound {
        Some(Sign::Negative)
    } else {
        None
    }
}

/// Shewchuk's static filter for `l ± r`, each a product of two differences: the sign
/// of `det` when it is certain, `None` otherwise (including overflow and NaN).
#[inline]
fn filtered(left: f64, right: f64, det: f64) -> Option<Sign> {
    let bound = ORIENT_ERR * (left.abs() + right.abs()) + f64::MIN_POSITIVE;
    if det > bound {
        Some(Sign::Positive)
    } else if -det > bound {
        Some(Sign::Negative)
    } else {
        None
    }
}

#[cold]
#[inline(never)]
fn orient_slow(a: Point, b: Point, c: Point) -> Orientation {
    if in_adaptive_range(&[a.x, a.y, b.x, b.y, c.x, c.y]) {
        let det = robust::orient2d(
            robust::Coord { x: a.x, y: a.y },
            robust::Coord { x: b.x, y: b.y },
            robust::Coord { x: c.x, y: c.y },
        );
        Sign::of(det).into()
    } else {
        sign_slow(&OrientPoly(a, b, c)).into()
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
mod tests {
    use super::*;
    use crate::kernel::Fast;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    /// The static filter of `line_meet_sign` never claims a wrong sign: random
    /// points, nearly parallel lines, crossings on or one ulp off the third line,
    /// tiny and huge magnitudes, all against exact dyadic evaluation.
    #[test]
    fn line_meet_filter_never_claims_a_wrong_sign() {
        let mut rng = SmallRng::seed_from_u64(0x11ee);
        let mut decided = 0;
        for i in 0..40_000 {
            let scale = [1.0, 1e-60, 1e60, 1e-140][(i / 4) % 4];
            let mut r = || {
                Point::new(
                    rng.random_range(-1.0..1.0) * scale,
                    rng.random_range(-1.0..1.0) * scale,
                )
            };
            let (a, b, c, e) = (r(), r(), r(), r());
            let mut d = r();
            if i % 3 == 0 {
                // Nearly parallel to ab.
                d = Point::new(c.x + (b.x - a.x) * 1.5, c.y + (b.y - a.y) * 1.5 + scale * 1e-12);
            }
            // f chosen so that ef passes (nearly) through the crossing of ab and cd.
            let den = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) * (d.x - c.x);
            let num = (c.x - a.x) * (d.y - c.y) - (c.y - a.y) * (d.x - c.x);
            let t = num / den;
            let x = Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
            let mut f = if i % 2 == 0 { x } else { r() };
            if i % 4 == 1 {
                f = Point::new(x.x.next_up(), x.y);
            }
            if !f.is_finite() {
                continue;
            }
            let pts = [a, b, c, d, e, f];
            if let Some(sign) = line_meet_filtered(pts) {
                decided += 1;
                assert_eq!(sign, sign_slow(&LineMeetSidePoly(pts)), "{pts:?}");
            }
        }
        assert!(decided > 5_000, "the filter decides too little: {decided}");
    }

    fn exact_orient(a: Point, b: Point, c: Point) -> Orientation {
        sign_slow(&OrientPoly(a, b, c)).into()
    }

    #[test]
    fn decompose_is_exact() {
        for x in [
            0.0,
            -0.0,
            1.0,
            -1.5,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            1e300,
            0.1,
        ] {
            let (m, e) = decompose(x);
            assert_eq!(
                (m as f64) * 2f64.powi(e as i32 / 2) * 2f64.powi(e as i32 - e as i32 / 2),
                x
            );
        }
    }

    #[test]
    fn range_limits_are_powers_of_two() {
        assert_eq!(ADAPTIVE_MIN, 2f64.powi(-400));
        assert_eq!(ADAPTIVE_MAX, 2f64.powi(400));
    }

    #[test]
    fn orient_matches_exact_fallback_near_collinear_and_at_extremes() {
        let mut rng = SmallRng::seed_from_u64(0x5eed_0001);
        let scales = [
            1.0,
            2f64.powi(-1000),
            2f64.powi(960),
            2f64.powi(-1070),
            2f64.powi(500),
        ];
        let mut fast_wrong = 0;
        for i in 0..20_000 {
            let s = scales[i % scales.len()];
            // Points on a line y = t·x with a one-ulp perturbation, at a large offset.
            let off = if i % 2 == 0 { 0.0 } else { 2f64.powi(40) };
            let t: f64 = rng.random_range(-2.0..2.0);
            let xs: [f64; 3] = [rng.random(), rng.random(), rng.random()];
            let mut p: Vec<Point> = xs
                .iter()
                .map(|&x| Point::new((x + off) * s, (t * x + off) * s))
                .collect();
            if rng.random_bool(0.5) {
                p[2].y = p[2].y.next_up();
            }
            let want = exact_orient(p[0], p[1], p[2]);
            assert_eq!(Exact.orient(p[0], p[1], p[2]), want, "{p:?}");
            assert_eq!(Exact.orient(p[1], p[0], p[2]), want.reverse());
            if Fast.orient(p[0], p[1], p[2]) != want {
                fast_wrong += 1;
            }
        }
        // The fast kernel is measurably wrong on this family; the exact one never is.
        println!("fast kernel wrong on near-collinear triples: {fast_wrong} of 20000");
        assert!(
            fast_wrong > 100,
            "expected the fast kernel to fail often, got {fast_wrong}"
        );
    }

    #[test]
    fn orient_on_subnormals_and_mixed_magnitudes() {
        let tiny = 5e-324;
        let a = Point::new(0.0, 0.0);
        let b = Point::new(tiny, tiny);
        let c = Point::new(2.0 * tiny, 2.0 * tiny);
        assert_eq!(Exact.orient(a, b, c), Orientation::Collinear);
        let c2 = Point::new(2.0 * tiny, 3.0 * tiny);
        assert_eq!(Exact.orient(a, b, c2), Orientation::Ccw);
        // The fast kernel underflows to zero here.
        assert_eq!(Fast.orient(a, b, c2), Orientation::Collinear);
        let big = f64::MAX;
        let p = Point::new(-big, -big);
        let q = Point::new(big, big);
        let r = Point::new(0.0, 0.0);
        assert_eq!(Exact.orient(p, q, r), Orientation::Collinear);
        assert_eq!(Exact.orient(p, q, Point::new(0.0, tiny)), Orientation::Ccw);
        assert_eq!(Exact.orient(p, q, Point::new(tiny, 0.0)), Orientation::Cw);
    }

    #[test]
    fn interval_filter_never_claims_a_wrong_sign() {
        let mut rng = SmallRng::seed_from_u64(7);
        for i in 0..5_000 {
            let e: i32 = rng.random_range(-1070..1000);
            let s = 2f64.powi(e);
            let mut pts: Vec<Point> = (0..4)
                .map(|_| Point::new(rng.random::<f64>() * s, rng.random::<f64>() * s))
                .collect();
            if i % 3 == 0 {
                // Exactly parallel directions, then nudged by one ulp half of the time.
                pts[3] = Point::new(pts[2].x + (pts[1].x - pts[0].x), pts[2].y + (pts[1].y - pts[0].y));
                if i % 2 == 0 {
                    pts[3].y = pts[3].y.next_up();
                }
            }
            let poly = super::super::CrossPoly(pts[0], pts[1], pts[2], pts[3]);
            let exact = poly.eval::<Dyadic>().certain_sign();
            if let Some(s) = poly.eval::<Interval>().certain_sign() {
                assert_eq!(Some(s), exact);
            }
            assert_eq!(Some(Exact.sign(&poly)), exact);
            assert_eq!(
                Some(Exact.cross(pts[0], pts[1], pts[2], pts[3])),
                exact.map(Orientation::from)
            );
            let dot = super::super::DotPoly(pts[0], pts[1], pts[2], pts[3]);
            assert_eq!(
                Some(Exact.dot(pts[0], pts[1], pts[2], pts[3])),
                dot.eval::<Dyadic>().certain_sign()
            );
        }
    }
}
