//! Layer 1 of the exact kernel, the static filter: each predicate evaluated in `f64`
//! with a bound on its rounding error (derivations at `certain` and
//! `cross_products_filtered`); a value farther from zero than the bound has the exact
//! sign. Pure arithmetic, inline; the layers above call it.

use crate::kernel::{Point, Sign};

/// Shewchuk's `ccwerrboundA`: (3 + 16ε)ε with ε = 2^-53.
pub(super) const ORIENT_ERR: f64 = (3.0 + 16.0 * (f64::EPSILON / 2.0)) * (f64::EPSILON / 2.0);

/// The static filter for `det = l − r` or `det = l + r`, `l` and `r` each a product of
/// two differences of inputs (`orient`, `cross`, `dot`): the sign of `det` when it is
/// certain, `None` otherwise (including overflow and NaN).
///
/// The test is `|det| > C·|l| + 2·f64::MIN_POSITIVE` (see [`certain`]).
#[inline(always)]
pub(super) fn two_products_filtered(det: f64, l: f64) -> Option<Sign> {
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
pub(super) fn certain(det: f64, l: f64) -> bool {
    let m = det.abs();
    m > two_products_bound(l, m)
}

/// The right-hand side of [`certain`], for `m = |det|`.
#[inline(always)]
pub(super) fn two_products_bound(l: f64, m: f64) -> f64 {
    const C: f64 = 2.0 * ORIENT_ERR * (1.0 + 1.0 / (1u64 << 30) as f64);
    const INFINITE_WITH_DET: f64 = 1.0 / (1u64 << 60) as f64;
    C * l.abs() + (INFINITE_WITH_DET * m + 2.0 * f64::MIN_POSITIVE)
}

/// A number of sign `s`: the slow paths' answers take the place of the computed
/// determinant, so that the fast and the slow path end in the same sign test (the
/// one [`Fast`](crate::Fast) makes) instead of merging enum values.
#[inline(always)]
pub(super) fn as_value(s: Sign) -> f64 {
    match s {
        Sign::Negative => -1.0,
        Sign::Zero => 0.0,
        Sign::Positive => 1.0,
    }
}

/// The sign of a value known to be non-zero (one comparison instead of two).
#[inline(always)]
pub(super) fn nonzero_sign(x: f64) -> Sign {
    if x > 0.0 { Sign::Positive } else { Sign::Negative }
}

/// The two products of `orient`: (a − c) × (b − c) = left − right.
#[inline(always)]
pub(super) fn orient_products(a: Point, b: Point, c: Point) -> (f64, f64) {
    ((a.x - c.x) * (b.y - c.y), (a.y - c.y) * (b.x - c.x))
}

/// The two products of `cross`: (b − a) × (d − c) = left − right.
#[inline(always)]
pub(super) fn cross_products(a: Point, b: Point, c: Point, d: Point) -> (f64, f64) {
    ((b.x - a.x) * (d.y - c.y), (b.y - a.y) * (d.x - c.x))
}

/// The two products of `dot`: (b − a) · (d − c) = left + right.
#[inline(always)]
pub(super) fn dot_products(a: Point, b: Point, c: Point, d: Point) -> (f64, f64) {
    ((b.x - a.x) * (d.x - c.x), (b.y - a.y) * (d.y - c.y))
}

#[inline(always)]
pub(super) fn orient_filtered(a: Point, b: Point, c: Point) -> Option<Sign> {
    let (left, right) = orient_products(a, b, c);
    two_products_filtered(left - right, left)
}

#[inline(always)]
pub(super) fn cross_filtered(a: Point, b: Point, c: Point, d: Point) -> Option<Sign> {
    let (left, right) = cross_products(a, b, c, d);
    two_products_filtered(left - right, left)
}

#[inline(always)]
pub(super) fn dot_filtered(a: Point, b: Point, c: Point, d: Point) -> Option<Sign> {
    let (left, right) = dot_products(a, b, c, d);
    two_products_filtered(left + right, left)
}

/// The differences `[b.x − a.x, b.y − a.y, d.x − c.x, d.y − c.y]` of one factor
/// `(b − a) × (d − c)` of [`Kernel::cross_products_sign`].
#[inline(always)]
pub(super) fn factor_differences([a, b, c, d]: [Point; 4]) -> [f64; 4] {
    [b.x - a.x, b.y - a.y, d.x - c.x, d.y - c.y]
}

/// One factor from its differences `[ux, uy, vx, vy]`: its value `ux·vy − uy·vx` and the
/// magnitude `|l| + |r|` of its two products.
#[inline(always)]
pub(super) fn cross_and_magnitude([ux, uy, vx, vy]: [f64; 4]) -> (f64, f64) {
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
pub(super) fn cross_products_filtered(factors: &[[Point; 4]; 4]) -> Option<Sign> {
    let (s, bound, valid) = cross_products_bounded(factors);
    if s.abs() > bound && valid {
        Some(nonzero_sign(s))
    } else {
        None
    }
}

/// `S̃`, the error bound of [`cross_products_filtered`] and whether the bound is valid.
#[inline(always)]
pub(super) fn cross_products_bounded(factors: &[[Point; 4]; 4]) -> (f64, f64, bool) {
    cross_products_from_differences(factors.map(factor_differences))
}

/// [`cross_products_bounded`] from the factors' differences (computed in `f64`, or
/// those scaled exactly by a power of two: the analysis is the same).
#[inline(always)]
pub(super) fn cross_products_from_differences(d: [[f64; 4]; 4]) -> (f64, f64, bool) {
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
