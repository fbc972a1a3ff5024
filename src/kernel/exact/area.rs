//! The exact sign of a polygon's signed area: an `f64` sum with an error bound after an
//! exact power-of-two rescaling, big integers ([`Dyadic`]) when that cannot decide.

use super::dyadic::Dyadic;
use super::out_of_line::{scaled_by, scaling_exponent};
use crate::kernel::{Point, Ring, Sign};

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
#[cfg(test)]
pub(crate) fn area_sign(points: &[Point]) -> Sign {
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
