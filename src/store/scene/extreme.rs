//! The world box of a posed polygon from its shape's array, in O(log n): four
//! extreme-vertex searches, each vertex compared exactly, and four images.
//!
//! # Why it is the box of the rounded image
//! A world coordinate is the exact value of an affine function of the shape vertex,
//! rounded once to nearest (`Pose::apply`). Rounding is monotone, so the largest rounded
//! x is the rounding of the largest exact x: the image of a shape vertex that maximises
//! `c·x − s·y` exactly. Two vertices whose exact values differ by less than an ulp may
//! round alike or not; comparing exactly and rounding the winner gives the right answer
//! either way. The same holds for the least x and for y (`s·x + c·y`).
//!
//! # Complexity
//! O(log n) comparisons per direction on a strictly convex counter-clockwise array (the
//! values along the boundary rise to one maximum, a vertex or an edge, then fall); the
//! search stops only at a vertex proved to be at least both neighbours, which on a
//! strictly convex polygon is the maximum. Should the bisection ever fail to settle (it
//! does not on a valid array), a linear scan with the same exact comparisons decides.
//!
//! # Precision
//! Each comparison is the sign of `d·(p − q)`, evaluated in floating point under a
//! certified error bound and, when the bound cannot decide (ties, near-ties, operands
//! near underflow or overflow), with exact rationals.
//!
//! # Degeneracies
//! Exact ties (an edge perpendicular to the direction) return either end of the edge:
//! both have the same exact value, hence the same rounding.

use crate::kernel::{BoundingBox, Point, Pose, Rational, Sign};
use std::cmp::Ordering;

const U: f64 = f64::EPSILON / 2.0;

/// The sign of `d·(p − q)`, exactly.
pub(super) fn compare(d: [f64; 2], p: Point, q: Point) -> Ordering {
    let (dx, dy) = (p.x - q.x, p.y - q.y);
    let (a, b) = (d[0] * dx, d[1] * dy);
    let v = a + b;
    let size = a.abs() + b.abs();
    // Each difference, each product and the sum round once (relative error U each, in
    // the normal range): |v − exact| ≤ (3U + O(U²))·size; 4U covers it. Below 2^-960
    // (products may be subnormal) or when something overflowed, decide exactly.
    if size.is_finite() && size >= 1e-289 {
        let bound = size * (4.0 * U);
        if v > bound {
            return Ordering::Greater;
        }
        if v < -bound {
            return Ordering::Less;
        }
    }
    exact_compare(d, p, q)
}

#[cold]
fn exact_compare(d: [f64; 2], p: Point, q: Point) -> Ordering {
    let r = Rational::from_f64;
    let v = &(&r(d[0]) * &(&r(p.x) - &r(q.x))) + &(&r(d[1]) * &(&r(p.y) - &r(q.y)));
    match v.sign() {
        Sign::Negative => Ordering::Less,
        Sign::Zero => Ordering::Equal,
        Sign::Positive => Ordering::Greater,
    }
}

/// The position of a vertex of `vs` (strictly convex, counter-clockwise, non-empty)
/// maximising `d·v` exactly.
pub(super) fn extreme(vs: &[Point], d: [f64; 2]) -> usize {
    let n = vs.len();
    if n < 3 {
        return scan(vs, d);
    }
    let at = |i: usize| vs[i % n];
    // f(i) vs f(j).
    let cmp = |i: usize, j: usize| compare(d, at(i), at(j));
    let up = |i: usize| cmp(i + 1, i) == Ordering::Greater;
    // A vertex at least both neighbours is the maximum (values along a strictly convex
    // boundary are unimodal).
    let top = |i: usize| !up(i) && cmp(i + n - 1, i) != Ordering::Greater;
    if top(0) {
        return 0;
    }
    // The maximum lies strictly between a and b (b = n stands for 0); `up_a` tells
    // whether the values rise at a.
    let (mut a, mut b) = (0usize, n);
    let mut up_a = up(0);
    while b > a + 1 {
        let c = (a + b) / 2;
        let up_c = up(c);
        if !up_c && cmp(c - 1, c) != Ordering::Greater {
            return c;
        }
        let max_before_c = if up_a {
            // Rising at a: the maximum is before c when c falls, or when c rises again
            // below a (the values went over the top and through the bottom).
            !up_c || cmp(a, c) == Ordering::Greater
        } else {
            // Falling at a: before c only when c falls from above a (the values went
            // through the bottom and over the top).
            !up_c && cmp(a, c) == Ordering::Less
        };
        if max_before_c {
            b = c;
        } else {
            a = c;
            up_a = up_c;
        }
    }
    #[cfg(test)]
    SCANS.with(|s| s.set(s.get() + 1));
    scan(vs, d)
}

#[cfg(test)]
thread_local! {
    /// Searches that fell back to the linear scan (a bisection bug; tests assert zero).
    pub(super) static SCANS: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// The linear scan: the first position whose value no other exceeds.
fn scan(vs: &[Point], d: [f64; 2]) -> usize {
    let mut best = 0;
    for (i, &p) in vs.iter().enumerate().skip(1) {
        if compare(d, p, vs[best]) == Ordering::Greater {
            best = i;
        }
    }
    best
}

/// The bounding box of the image of `vs` (a strictly convex counter-clockwise array)
/// under `pose`, each coordinate rounded as [`Pose::apply`] rounds it; `None` when an
/// extreme coordinate overflows (then some image does, and no other image can
/// overflow otherwise: every image lies within the box). O(log n).
pub(super) fn image_box(vs: &[Point], pose: &Pose) -> Option<BoundingBox> {
    let [c, s] = pose.rotation();
    // World x = c·x − s·y + tx, world y = s·x + c·y + ty; negating a direction is exact.
    let (dx, dy) = ([c, -s], [s, c]);
    let max_x = pose.apply(vs[extreme(vs, dx)])?.x;
    let min_x = pose.apply(vs[extreme(vs, [-dx[0], -dx[1]])])?.x;
    let max_y = pose.apply(vs[extreme(vs, dy)])?.y;
    let min_y = pose.apply(vs[extreme(vs, [-dy[0], -dy[1]])])?.y;
    Some(BoundingBox {
        min: Point::new(min_x, min_y),
        max: Point::new(max_x, max_y),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::polygon::convex_hull;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    fn scans() -> u64 {
        SCANS.with(|s| s.get())
    }

    /// The reference: every vertex's exact value, the largest.
    fn reference_max(vs: &[Point], d: [f64; 2]) -> Rational {
        let r = Rational::from_f64;
        vs.iter()
            .map(|p| &(&r(d[0]) * &r(p.x)) + &(&r(d[1]) * &r(p.y)))
            .max()
            .expect("vertices")
    }

    fn value(vs: &[Point], i: usize, d: [f64; 2]) -> Rational {
        let r = Rational::from_f64;
        &(&r(d[0]) * &r(vs[i].x)) + &(&r(d[1]) * &r(vs[i].y))
    }

    fn reference_box(vs: &[Point], pose: &Pose) -> Option<BoundingBox> {
        let pts: Option<Vec<Point>> = vs.iter().map(|&p| pose.apply(p)).collect();
        BoundingBox::of(pts?)
    }

    fn random_polygon(rng: &mut SmallRng, n: usize, scale: f64) -> Vec<Point> {
        let pts: Vec<Point> = (0..n)
            .map(|_| {
                let t: f64 = rng.random_range(0.0..std::f64::consts::TAU);
                Point::new(scale * t.cos(), 0.6 * scale * t.sin())
            })
            .collect();
        convex_hull(&pts)
            .expect("points on an ellipse")
            .vertices()
            .to_vec()
    }

    #[test]
    fn extreme_matches_the_exact_maximum_on_random_polygons() {
        let mut rng = SmallRng::seed_from_u64(3801);
        let before = scans();
        for round in 0..3000 {
            let n = [3, 4, 5, 8, 16, 100, 1000][round % 7];
            let scale = 10f64.powi(rng.random_range(-5..6));
            let vs = random_polygon(&mut rng, n, scale);
            for _ in 0..8 {
                let t: f64 = rng.random_range(-10.0..10.0);
                let d = [t.cos(), t.sin()];
                let i = extreme(&vs, d);
                assert_eq!(value(&vs, i, d), reference_max(&vs, d), "n {n} d {d:?}");
            }
            // Directions along an edge's normal: an exact tie at the top.
            let k = rng.random_range(0..vs.len());
            let (p, q) = (vs[k], vs[(k + 1) % vs.len()]);
            let d = [q.y - p.y, p.x - q.x];
            let i = extreme(&vs, d);
            assert_eq!(value(&vs, i, d), reference_max(&vs, d));
            let i = extreme(&vs, [-d[0], -d[1]]);
            assert_eq!(value(&vs, i, [-d[0], -d[1]]), reference_max(&vs, [-d[0], -d[1]]));
        }
        assert_eq!(scans(), before, "the bisection settled every search");
    }

    #[test]
    fn image_box_is_the_box_of_the_rounded_image() {
        let mut rng = SmallRng::seed_from_u64(3802);
        for round in 0..3000 {
            let n = [3, 4, 7, 16, 64, 500][round % 6];
            let scale = 10f64.powi(rng.random_range(-3..4));
            let vs = random_polygon(&mut rng, n, scale);
            let pose = Pose::from_angle(
                rng.random_range(-10.0..10.0),
                [rng.random_range(-1e3..1e3), rng.random_range(-1e3..1e3)],
            )
            .unwrap();
            assert_eq!(image_box(&vs, &pose), reference_box(&vs, &pose));
        }
    }

    #[test]
    fn box_ties_one_ulp_apart() {
        // Two top vertices whose exact images differ by far less than an ulp, or by
        // one ulp, or tie exactly: the box is still the rounded image's.
        let mut rng = SmallRng::seed_from_u64(3803);
        for _ in 0..2000 {
            let x: f64 = rng.random_range(1.0..100.0);
            let gap = [0.0, f64::EPSILON * x, 2.0 * f64::EPSILON * x, 1e-30][rng.random_range(0..4)];
            // A flat top at y = 1 (or nearly: the right corner lowered by `gap`), below
            // a wide base.
            let vs = vec![
                Point::new(-x, -1.0),
                Point::new(x, -1.0),
                Point::new(x, 1.0 - gap),
                Point::new(-x, 1.0),
            ];
            for pose in [
                Pose::identity(),
                Pose::new([1.0, 0.0], [0.1, 0.3]).unwrap(),
                Pose::new([0.0, 1.0], [0.0, 0.0]).unwrap(),
                Pose::new([1.0, f64::EPSILON * rng.random_range(-4.0..4.0)], [0.5, 0.25]).unwrap(),
                Pose::new([1.0, 1e-300], [0.0, 0.0]).unwrap(),
                Pose::from_angle(rng.random_range(-1e-15..1e-15), [0.0, 0.0]).unwrap(),
            ] {
                assert_eq!(
                    image_box(&vs, &pose),
                    reference_box(&vs, &pose),
                    "x {x} gap {gap}"
                );
            }
        }
    }

    #[test]
    fn comparisons_near_underflow_and_overflow_are_exact() {
        let tiny = 2f64.powi(-1060);
        let big = f64::MAX / 4.0;
        for (d, p, q) in [
            ([1.0, 1.0], Point::new(tiny, 0.0), Point::new(0.0, 0.0)),
            ([1e-300, 1e-300], Point::new(1e-20, 0.0), Point::new(0.0, 1e-20)),
            ([1.0, 0.0], Point::new(big, 0.0), Point::new(-big * 3.0, 0.0)),
            ([1e300, -1e300], Point::new(1e10, 1e10), Point::new(-1e10, 1e10)),
            ([1.0, -1.0], Point::new(1.0, 1.0), Point::new(2.0, 2.0)),
        ] {
            let r = Rational::from_f64;
            let want = (&(&r(d[0]) * &(&r(p.x) - &r(q.x))) + &(&r(d[1]) * &(&r(p.y) - &r(q.y))))
                .cmp(&Rational::zero());
            assert_eq!(compare(d, p, q), want, "{d:?} {p:?} {q:?}");
        }
    }
}
