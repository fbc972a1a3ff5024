//! [`Pose`]: a rotation (with scale) and a translation that place a shape in the world,
//! applied with each world coordinate correctly rounded.
//!
//! A pose is `(c, s, tx, ty)`; it maps a shape point `(x, y)` to
//! `(c·x − s·y + tx, s·x + c·y + ty)`. For a rotation by θ, `c = cos θ` and `s = sin θ`;
//! any other finite pair, not both zero, also scales by `√(c² + s²)` (rounded cosines and
//! sines are such pairs: their scale is within an ulp of 1, and the map is still applied
//! exactly as written, never normalised).
//!
//! # Precision
//! [`Pose::apply`] returns each coordinate as the exact value of the expression above
//! rounded once to the nearest double, ties to even (an exact zero is `+0`), or `None`
//! when that rounding overflows. So a pose set absolutely every frame never drifts, and
//! the image of a point depends only on the point and the pose.
//!
//! # Complexity
//! O(1). The fast path computes the two products exactly (a product and its error by
//! Dekker's two-product), adds the three leading terms with two-sums (exact) and the
//! four small error terms in plain arithmetic under a certified bound, and accepts the
//! rounded sum when the bound proves that no rounding midpoint lies within reach: about
//! twenty floating-point operations. It falls back to exact rationals
//! ([`Rational`](super::Rational), a few big-integer products and one division) when
//! the bound cannot decide: exact ties and values within about 2⁻¹⁰⁰ of a midpoint
//! relative to the terms, products below 2⁻⁹⁶⁰ (where the product's error is not
//! representable), factors above 2⁹⁹⁵ (where the splitting would overflow), and
//! results near overflow or in the subnormal range.
//!
//! # Degeneracies
//! Cancellation (`c·x ≈ s·y`) is handled like any other input: the error terms carry
//! what the leading sum loses, and the bound is relative to them, not to the result.

use super::{Point, Rational};
use std::fmt;

/// A rotation (with the scale `√(c² + s²)`) followed by a translation. Every field is
/// finite and `(c, s) ≠ (0, 0)`. [`apply`](Self::apply) rounds each coordinate of an
/// image once from its exact value (nearest, ties to even), so a pose set absolutely
/// every frame never drifts: O(1), about twenty floating-point operations, with exact
/// rationals only where a certified bound cannot decide the rounding (ties, values
/// within about 2⁻¹⁰⁰ of a midpoint, extreme exponents).
///
/// ```
/// use polysect::kernel::Pose;
/// use polysect::Point;
/// let quarter = Pose::new([0.0, 1.0], [10.0, 0.0])?; // turn by 90°, then move by (10, 0)
/// assert_eq!(quarter.apply(Point::new(1.0, 2.0)), Some(Point::new(8.0, 1.0)));
/// // Each coordinate is the exact value rounded once: 0.1·3 − 0 + 0 rounds to 0.30000000000000004.
/// let scale = Pose::new([0.1, 0.0], [0.0, 0.0])?;
/// assert_eq!(scale.apply(Point::new(3.0, 0.0)).unwrap().x, 0.30000000000000004);
/// assert!(Pose::new([0.0, 0.0], [1.0, 1.0]).is_err());
/// # Ok::<(), polysect::kernel::PoseError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    c: f64,
    s: f64,
    tx: f64,
    ty: f64,
}

/// Why a pose was refused.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PoseError {
    /// A component is NaN or infinite.
    NonFinite {
        /// The rotation `[c, s]` as given.
        rotation: [f64; 2],
        /// The translation `[tx, ty]` as given.
        translation: [f64; 2],
    },
    /// `c = s = 0`: the map would collapse every shape onto one point.
    ZeroRotation,
    /// The image of this shape point has a coordinate that overflows.
    Overflow {
        /// The shape point whose image overflows.
        point: Point,
    },
    /// The rounded image is not strictly convex (or not counter-clockwise, winding once)
    /// at this world point.
    NotConvex {
        /// The first world point (counter-clockwise) where the image breaks convexity.
        point: Point,
    },
}

impl fmt::Display for PoseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PoseError::NonFinite {
                rotation,
                translation,
            } => write!(
                f,
                "pose components must be finite: rotation [{}, {}], translation [{}, {}]",
                rotation[0], rotation[1], translation[0], translation[1]
            ),
            PoseError::ZeroRotation => write!(f, "pose rotation [0, 0]: cosine and sine are both zero"),
            PoseError::Overflow { point } => {
                write!(f, "the pose maps shape point {point} outside the finite range")
            }
            PoseError::NotConvex { point } => write!(
                f,
                "the posed polygon, each coordinate rounded, is not strictly convex at {point}"
            ),
        }
    }
}

impl std::error::Error for PoseError {}

impl Default for Pose {
    fn default() -> Self {
        Pose::identity()
    }
}

impl Pose {
    /// The identity: rotation `[1, 0]`, translation `[0, 0]`.
    pub const fn identity() -> Pose {
        Pose {
            c: 1.0,
            s: 0.0,
            tx: 0.0,
            ty: 0.0,
        }
    }

    /// The pose with rotation `[c, s]` and translation `[tx, ty]`.
    ///
    /// # Errors
    /// [`PoseError::NonFinite`] when a component is not finite, [`PoseError::ZeroRotation`]
    /// when `c = s = 0`.
    pub fn new(rotation: [f64; 2], translation: [f64; 2]) -> Result<Pose, PoseError> {
        let [c, s] = rotation;
        let [tx, ty] = translation;
        if !(c.is_finite() && s.is_finite() && tx.is_finite() && ty.is_finite()) {
            return Err(PoseError::NonFinite {
                rotation,
                translation,
            });
        }
        if c == 0.0 && s == 0.0 {
            return Err(PoseError::ZeroRotation);
        }
        Ok(Pose { c, s, tx, ty })
    }

    /// The rotation by `radians` (its cosine and sine as `f64::cos`/`f64::sin` round
    /// them) followed by the translation.
    ///
    /// # Errors
    /// [`PoseError::NonFinite`] when the angle or a translation component is not finite.
    pub fn from_angle(radians: f64, translation: [f64; 2]) -> Result<Pose, PoseError> {
        if !radians.is_finite() {
            return Err(PoseError::NonFinite {
                rotation: [f64::NAN, f64::NAN],
                translation,
            });
        }
        Pose::new([radians.cos(), radians.sin()], translation)
    }

    /// `[c, s]`.
    pub fn rotation(&self) -> [f64; 2] {
        [self.c, self.s]
    }

    /// `[tx, ty]`.
    pub fn translation(&self) -> [f64; 2] {
        [self.tx, self.ty]
    }

    /// The same rotation with the translation `[tx + dx, ty + dy]`, each sum rounded to
    /// nearest (IEEE addition).
    ///
    /// # Errors
    /// [`PoseError::NonFinite`] when a sum is not finite.
    pub fn translated(&self, dx: f64, dy: f64) -> Result<Pose, PoseError> {
        Pose::new([self.c, self.s], [self.tx + dx, self.ty + dy])
    }

    /// Whether this is the identity map (`c = 1`, `s = 0`, no translation).
    #[cfg(test)]
    pub(crate) fn is_identity(&self) -> bool {
        self.c == 1.0 && self.s == 0.0 && self.tx == 0.0 && self.ty == 0.0
    }

    /// The image of `p`, each coordinate correctly rounded (nearest, ties to even; an
    /// exact zero is `+0`), or `None` when a coordinate's rounding overflows or `p` is
    /// not finite. O(1) (the type's docs give the cost).
    #[inline]
    pub fn apply(&self, p: Point) -> Option<Point> {
        if !p.is_finite() {
            return None;
        }
        let [fx, fy] = fast_apply(self, p);
        let x = match fx {
            Some(x) => x,
            None => rounded_affine(self.c, p.x, self.s, p.y, self.tx)?,
        };
        let y = match fy {
            Some(y) => y,
            None => rounded_affine(self.s, p.x, -self.c, p.y, self.ty)?,
        };
        Some(Point::new(x, y))
    }
}

/// Products at least this large have a representable error (`fma(a, b, −a·b)` is exact).
const TINY_PRODUCT: f64 = 1.0e-289; // below 2^-960
const U: f64 = f64::EPSILON / 2.0;

/// Factors below this split without overflow (Veltkamp's splitting multiplies by 2^27 + 1).
const SPLIT_LIMIT: f64 = 1.0e299; // below 2^995

/// Veltkamp's split: `hi + lo = v` exactly, each with at most 26 significant bits.
#[inline(always)]
fn split(v: f64) -> (f64, f64) {
    let c = 134_217_729.0 * v; // 2^27 + 1
    let hi = c - (c - v);
    (hi, v - hi)
}

/// Dekker's two-product: `a·b − p` exactly, for `p = a·b` finite with a representable
/// error (`|p| ≥ 2^-960` or a zero factor) and `|a|, |b|` zero or in `[2^-996, 2^995)`. Plain operations, no
/// fused multiply-add: without the target feature `mul_add` is a library call, several
/// times slower than these seventeen operations.
#[inline(always)]
fn product_error(a: f64, b: f64, p: f64) -> f64 {
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    ((ah * bh - p) + ah * bl + al * bh) + al * bl
}

/// Knuth's two-sum: `s + e = a + b` exactly (finite operands, finite `s`).
#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a·x − b·y + t` (all finite) rounded once to nearest, ties to even; `None` on overflow.
#[inline]
fn rounded_affine(a: f64, x: f64, b: f64, y: f64, t: f64) -> Option<f64> {
    match fast_affine(a, x, b, y, t) {
        Some(r) => Some(r),
        None => exact_affine(a, x, b, y, t),
    }
}

/// The fast path: `Some(r)` only when `r` is proved to be the correctly rounded value.
#[inline]
fn fast_affine(a: f64, x: f64, b: f64, y: f64, t: f64) -> Option<f64> {
    let p1 = a * x;
    let p2 = b * y;
    // Each product's error is exact when the product is finite and not tiny (or exactly
    // zero because a factor is).
    let exact_product = |p: f64, f: f64, g: f64| p.abs() >= TINY_PRODUCT || f == 0.0 || g == 0.0;
    // Splitting is exact for factors in the normal range, far from overflow.
    let normal = |v: f64| v == 0.0 || v.abs() >= 1.0e-300;
    let splittable = a.abs().max(x.abs()).max(b.abs()).max(y.abs()) < SPLIT_LIMIT
        && normal(a)
        && normal(x)
        && normal(b)
        && normal(y);
    if !(splittable && p1.is_finite() && p2.is_finite() && exact_product(p1, a, x) && exact_product(p2, b, y))
    {
        return None;
    }
    let e1 = product_error(a, x, p1);
    let e2 = product_error(b, y, p2);
    let (s1, t1) = two_sum(p1, -p2);
    let (s2, t2) = two_sum(s1, t);
    if !s2.is_finite() {
        return None;
    }
    // X = s2 + (t1 + t2 + e1 − e2) exactly; the tail is summed with at most three
    // roundings, each at most U times a partial sum: the error is below 3.01·U·S.
    let tail = ((t1 + t2) + e1) - e2;
    let sum_abs = ((t1.abs() + t2.abs()) + e1.abs()) + e2.abs();
    let delta = sum_abs * (4.0 * U) + f64::from_bits(1);
    let (r, r_err) = two_sum(s2, tail);
    if r.is_nan() || r.abs() >= f64::MAX {
        return None;
    }
    // X ∈ [r + r_err − δ, r + r_err + δ]; r is its rounding when that interval lies
    // strictly between the midpoints around r. The half-gaps are exact (or zero in the
    // subnormal range, which then fails); the two comparisons hold for the exact sums
    // when they hold for the rounded ones, since rounding is monotone and the half-gaps
    // are doubles.
    let half_up = (r.next_up() - r) * 0.5;
    let half_down = (r - r.next_down()) * 0.5;
    if r_err + delta < half_up && r_err - delta > -half_down {
        Some(r)
    } else {
        None
    }
}

/// Both coordinates on [`fast_affine`]'s path, with the four factors split and
/// range-checked once for the two (each coordinate's two products share them): `Some`
/// only where the coordinate is proved the correctly rounded value; `None` sends that
/// coordinate to [`rounded_affine`].
#[inline]
fn fast_apply(pose: &Pose, p: Point) -> [Option<f64>; 2] {
    let (c, s, x, y) = (pose.c, pose.s, p.x, p.y);
    let normal = |v: f64| v == 0.0 || v.abs() >= 1.0e-300;
    let splittable = c.abs().max(s.abs()).max(x.abs()).max(y.abs()) < SPLIT_LIMIT
        && normal(c)
        && normal(s)
        && normal(x)
        && normal(y);
    if !splittable {
        return [None, None];
    }
    let (cx, sy, sx, cy) = (c * x, s * y, s * x, c * y);
    let exact_product =
        |p: f64, f: f64, g: f64| p.is_finite() && (p.abs() >= TINY_PRODUCT || f == 0.0 || g == 0.0);
    if !(exact_product(cx, c, x)
        && exact_product(sy, s, y)
        && exact_product(sx, s, x)
        && exact_product(cy, c, y))
    {
        return [None, None];
    }
    let ((ch, cl), (sh, sl), (xh, xl), (yh, yl)) = (split(c), split(s), split(x), split(y));
    // Dekker's two-product error from the splits (`product_error`).
    let err = |ah: f64, al: f64, bh: f64, bl: f64, p: f64| ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    // c·x − s·y + tx and s·x + c·y + ty; negating a product and its error is exact.
    [
        finish_affine(
            cx,
            err(ch, cl, xh, xl, cx),
            -sy,
            -err(sh, sl, yh, yl, sy),
            pose.tx,
        ),
        finish_affine(sx, err(sh, sl, xh, xl, sx), cy, err(ch, cl, yh, yl, cy), pose.ty),
    ]
}

/// `p1 + e1 + p2 + e2 + t` (exactly the affine value, `e1`, `e2` the products' errors)
/// rounded once, when [`fast_affine`]'s bound proves it; the same summation and test.
#[inline(always)]
fn finish_affine(p1: f64, e1: f64, p2: f64, e2: f64, t: f64) -> Option<f64> {
    let (s1, t1) = two_sum(p1, p2);
    let (s2, t2) = two_sum(s1, t);
    if !s2.is_finite() {
        return None;
    }
    let tail = ((t1 + t2) + e1) + e2;
    let sum_abs = ((t1.abs() + t2.abs()) + e1.abs()) + e2.abs();
    let delta = sum_abs * (4.0 * U) + f64::from_bits(1);
    let (r, r_err) = two_sum(s2, tail);
    if r.is_nan() || r.abs() >= f64::MAX {
        return None;
    }
    // The gaps to r's neighbours, from the bits of |r| (finite, below MAX): what
    // `next_up` and `next_down` give, without their special cases. At 0 the half-gaps
    // round to 0 and the test below fails anyway.
    let a = r.abs();
    if a == 0.0 {
        return None;
    }
    let bits = a.to_bits();
    let (above, below) = (f64::from_bits(bits + 1) - a, a - f64::from_bits(bits - 1));
    let (gap_up, gap_down) = if r > 0.0 { (above, below) } else { (below, above) };
    let (half_up, half_down) = (gap_up * 0.5, gap_down * 0.5);
    (r_err + delta < half_up && r_err - delta > -half_down).then_some(r)
}

/// The slow path: exact rationals, one rounding.
#[cold]
fn exact_affine(a: f64, x: f64, b: f64, y: f64, t: f64) -> Option<f64> {
    let r = |v: f64| Rational::from_f64(v);
    let exact = &(&(&r(a) * &r(x)) - &(&r(b) * &r(y))) + &r(t);
    let v = exact.to_f64();
    if v.is_finite() {
        // `to_f64` gives +0 for an exact zero.
        Some(v)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    /// The reference: the exact value of each coordinate, rounded once.
    fn reference(pose: &Pose, p: Point) -> Option<Point> {
        let r = |v: f64| Rational::from_f64(v);
        let (c, s, tx, ty) = (r(pose.c), r(pose.s), r(pose.tx), r(pose.ty));
        let (x, y) = (r(p.x), r(p.y));
        let wx = (&(&(&c * &x) - &(&s * &y)) + &tx).to_f64();
        let wy = (&(&(&s * &x) + &(&c * &y)) + &ty).to_f64();
        (wx.is_finite() && wy.is_finite()).then(|| Point::new(wx, wy))
    }

    fn same(a: Option<Point>, b: Option<Point>) -> bool {
        match (a, b) {
            (None, None) => true,
            (Some(a), Some(b)) => a.x.to_bits() == b.x.to_bits() && a.y.to_bits() == b.y.to_bits(),
            _ => false,
        }
    }

    fn check(pose: Pose, p: Point) {
        let got = pose.apply(p);
        let want = reference(&pose, p);
        assert!(
            same(got, want),
            "pose {pose:?} point {p:?}: got {got:?}, exact {want:?}"
        );
    }

    /// A double with a random sign, a mantissa and an exponent in `lo..=hi`.
    fn spread(rng: &mut SmallRng, lo: i32, hi: i32) -> f64 {
        let m: f64 = rng.random_range(1.0..2.0);
        let e = rng.random_range(lo..=hi);
        // Two steps, so 2^e is never formed below the normal range (it would be 0).
        let v = m * 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
        if rng.random_bool(0.5) { -v } else { v }
    }

    #[test]
    fn matches_the_exact_reference_on_random_poses() {
        let mut rng = SmallRng::seed_from_u64(38);
        let mut fast = 0usize;
        let total = 200_000;
        for _ in 0..total {
            let theta: f64 = rng.random_range(-10.0..10.0);
            let pose =
                Pose::from_angle(theta, [rng.random_range(-1e3..1e3), rng.random_range(-1e3..1e3)]).unwrap();
            let p = Point::new(rng.random_range(-1e3..1e3), rng.random_range(-1e3..1e3));
            check(pose, p);
            fast += usize::from(fast_affine(pose.c, p.x, pose.s, p.y, pose.tx).is_some());
        }
        // The fast path decides almost every ordinary input (the others are still exact).
        assert!(fast > total * 99 / 100, "fast path decided {fast} of {total}");
    }

    #[test]
    fn matches_the_exact_reference_across_the_exponent_range() {
        let mut rng = SmallRng::seed_from_u64(1038);
        for _ in 0..100_000 {
            let (lo, hi) = match rng.random_range(0..4) {
                0 => (-1074, 1023),
                1 => (980, 1023),
                2 => (-1074, -1000),
                _ => (-60, 60),
            };
            let pose = Pose::new(
                [spread(&mut rng, lo, hi), spread(&mut rng, lo, hi)],
                [spread(&mut rng, lo, hi), spread(&mut rng, lo, hi)],
            )
            .unwrap();
            let p = Point::new(spread(&mut rng, lo, hi), spread(&mut rng, lo, hi));
            check(pose, p);
        }
    }

    #[test]
    fn ties_round_to_even() {
        // 1 + 2^-53 is halfway between 1 and 1 + 2^-52: rounds to 1 (even); 1 + 3·2^-53
        // is halfway between 1 + 2^-52 and 1 + 2^-51: rounds up to the even 1 + 2^-51.
        let half = 2f64.powi(-53);
        let pose = Pose::new([1.0, 0.0], [half, 3.0 * half]).unwrap();
        assert_eq!(
            pose.apply(Point::new(1.0, 1.0)),
            Some(Point::new(1.0, 1.0 + 4.0 * half))
        );
        check(pose, Point::new(1.0, 1.0));
        // A tie made by the products: (1 + 2^-52)² = 1 + 2^-51 + 2^-104, just above a
        // tie with the translation −2^-104 making it exact.
        let u = 1.0 + 2f64.powi(-52);
        for t in [
            -2f64.powi(-104),
            0.0,
            2f64.powi(-104),
            -2f64.powi(-53),
            2f64.powi(-53),
        ] {
            let pose = Pose::new([u, 0.0], [t, t]).unwrap();
            check(pose, Point::new(u, u));
            let pose = Pose::new([u, u], [t, -t]).unwrap();
            check(pose, Point::new(u, -u));
        }
        // Ties at every scale, made exact by a translation of half an ulp.
        let mut rng = SmallRng::seed_from_u64(2038);
        for _ in 0..20_000 {
            let x = spread(&mut rng, -1000, 1000);
            let c = spread(&mut rng, -20, 20);
            let prod = c * x;
            let err = c.mul_add(x, -prod);
            let ulp = prod.abs().next_up() - prod.abs();
            for t in [ulp / 2.0 - err, -ulp / 2.0 - err, ulp / 2.0, -ulp / 2.0, -err] {
                if t.is_finite() {
                    check(Pose::new([c, 0.0], [t, t]).unwrap(), Point::new(x, x));
                }
            }
        }
    }

    #[test]
    fn cancellation_keeps_what_the_leading_terms_lose() {
        let mut rng = SmallRng::seed_from_u64(3038);
        for _ in 0..50_000 {
            // c·x ≈ s·y: the leading sum cancels and the error terms are the answer.
            let c = spread(&mut rng, -30, 30);
            let s = spread(&mut rng, -30, 30);
            let x = spread(&mut rng, -30, 30);
            let y = c * x / s;
            let t = if rng.random_bool(0.5) {
                0.0
            } else {
                spread(&mut rng, -200, 0)
            };
            check(Pose::new([c, s], [t, -t]).unwrap(), Point::new(x, y));
            check(Pose::new([c, s], [t, -t]).unwrap(), Point::new(x.next_up(), y));
        }
        // Exact zeros come out as +0.
        let p = Pose::new([1.0, 1.0], [0.0, 0.0])
            .unwrap()
            .apply(Point::new(-0.0, -0.0))
            .unwrap();
        assert_eq!(p.x.to_bits(), 0f64.to_bits());
        let q = Pose::new([3.0, 2.0], [0.0, -0.0])
            .unwrap()
            .apply(Point::new(2.0, 3.0))
            .unwrap();
        assert_eq!((q.x.to_bits(), q.y), (0f64.to_bits(), 13.0));
    }

    #[test]
    fn huge_tiny_and_overflowing_images() {
        let big = 2f64.powi(1000);
        let tiny = 2f64.powi(-1000);
        let sub = 5e-324;
        let cases = [
            (
                Pose::new([1.0, 0.0], [0.0, 0.0]).unwrap(),
                Point::new(f64::MAX, -f64::MAX),
            ),
            (
                Pose::new([2.0, 0.0], [0.0, 0.0]).unwrap(),
                Point::new(f64::MAX, 1.0),
            ),
            (
                Pose::new([1.0, 1.0], [0.0, 0.0]).unwrap(),
                Point::new(f64::MAX, f64::MAX),
            ),
            (
                Pose::new([1.0, -1.0], [0.0, 0.0]).unwrap(),
                Point::new(f64::MAX, f64::MAX),
            ),
            (Pose::new([big, big], [big, -big]).unwrap(), Point::new(big, big)),
            (
                Pose::new([big, tiny], [tiny, big]).unwrap(),
                Point::new(tiny, big),
            ),
            (
                Pose::new([tiny, tiny], [sub, -sub]).unwrap(),
                Point::new(tiny, -tiny),
            ),
            (Pose::new([0.5, 0.5], [0.0, 0.0]).unwrap(), Point::new(sub, sub)),
            (
                Pose::new([0.5, 0.0], [sub, sub]).unwrap(),
                Point::new(sub, 3.0 * sub),
            ),
            (
                Pose::new([1.0, 0.0], [f64::MAX, 0.0]).unwrap(),
                Point::new(f64::MAX.next_down(), 1.0),
            ),
            (
                Pose::new([1.0, 0.0], [-f64::MAX, 0.0]).unwrap(),
                Point::new(f64::MAX, 1.0),
            ),
        ];
        for (pose, p) in cases {
            check(pose, p);
        }
        assert_eq!(
            Pose::new([2.0, 0.0], [0.0, 0.0])
                .unwrap()
                .apply(Point::new(f64::MAX, 0.0)),
            None
        );
        // Products that overflow on their own but cancel exactly.
        assert_eq!(
            rounded_affine(2.0, f64::MAX, 2.0, f64::MAX, 0.0),
            Some(0.0),
            "2·MAX − 2·MAX is exactly 0"
        );
        // ... while the other coordinate, 2·MAX + 2·MAX, overflows: no image.
        assert_eq!(
            Pose::new([2.0, 2.0], [0.0, 0.0])
                .unwrap()
                .apply(Point::new(f64::MAX, f64::MAX)),
            None
        );
        // Max plus just under half an ulp stays finite; plus half an ulp overflows.
        let half_ulp = 2f64.powi(970);
        let edge = Pose::new([1.0, 0.0], [half_ulp.next_down(), 0.0]).unwrap();
        assert_eq!(edge.apply(Point::new(f64::MAX, 0.0)).map(|p| p.x), Some(f64::MAX));
        let over = Pose::new([1.0, 0.0], [half_ulp, 0.0]).unwrap();
        assert_eq!(over.apply(Point::new(f64::MAX, 0.0)), None);
    }

    #[test]
    fn refuses_non_finite_and_zero_rotations() {
        assert_eq!(Pose::new([0.0, -0.0], [0.0, 0.0]), Err(PoseError::ZeroRotation));
        assert!(matches!(
            Pose::new([f64::NAN, 1.0], [0.0, 0.0]),
            Err(PoseError::NonFinite { .. })
        ));
        assert!(matches!(
            Pose::new([1.0, 0.0], [f64::INFINITY, 0.0]),
            Err(PoseError::NonFinite { .. })
        ));
        assert!(Pose::from_angle(f64::INFINITY, [0.0, 0.0]).is_err());
        assert!(
            Pose::identity()
                .translated(f64::MAX, 0.0)
                .unwrap()
                .translated(f64::MAX, 0.0)
                .is_err()
        );
        assert!(Pose::identity().is_identity() && Pose::default() == Pose::identity());
        assert_eq!(Pose::identity().apply(Point::new(f64::NAN, 0.0)), None);
        let msg = Pose::new([0.0, 0.0], [1.0, 2.0]).unwrap_err().to_string();
        assert!(msg.contains("both zero"), "{msg}");
    }

    #[test]
    fn identity_and_quarter_turns_are_exact() {
        let mut rng = SmallRng::seed_from_u64(4038);
        let quarter = Pose::new([0.0, 1.0], [0.0, 0.0]).unwrap();
        for _ in 0..10_000 {
            let p = Point::new(spread(&mut rng, -1074, 1023), spread(&mut rng, -1074, 1023));
            assert_eq!(Pose::identity().apply(p), Some(p));
            assert_eq!(quarter.apply(p), Some(Point::new(-p.y, p.x)));
        }
    }
}
