//! The nearest feature of D = Q ⊕ (−P) in O((log n + log m) · k), k the iterations of a
//! floating-point GJK (a handful on ordinary input): the GJK's supports are O(log n)
//! extreme-vertex searches on the arrays, its last direction names a D-vertex near
//! the nearest feature, and a short exact walk around that vertex certifies it
//! ([`walk::is_nearest`](super::walk)). Floating point only *proposes*: when no feature
//! in the window passes its exact test (a misjudged direction, overflow at extreme
//! scales, a degenerate input), the caller walks all of D.

use super::walk::{self, Feature};
use crate::kernel::{Kernel, Orientation, Point};

/// Edge `i` of `v` (from vertex `i` to `i + 1`) as an `f64` vector.
#[inline]
fn edge(v: &[Point], i: usize) -> (f64, f64) {
    let (a, b) = (v[i], v[walk::next(i, v.len())]);
    (b.x - a.x, b.y - a.y)
}

/// The vertex of the convex counter-clockwise `v` extreme in direction `u`
/// (approximately: f64 arithmetic), in O(log n).
///
/// Edge directions measured counter-clockwise from `r = u` turned clockwise are a
/// rotated sorted sequence; edges in the first half-turn rise along `u`, the others
/// fall, so the extreme vertex starts the first edge of the second half-turn. One
/// binary search finds the smallest direction, a second the first of the second half.
pub(crate) fn extreme(v: &[Point], u: (f64, f64)) -> usize {
    let n = v.len();
    let r = (u.1, -u.0);
    // Which half-turn from r, then the order within a half (cross products of edges).
    let half = |i: usize| {
        let e = edge(v, i);
        let c = r.0 * e.1 - r.1 * e.0;
        if c > 0.0 || (c == 0.0 && r.0 * e.0 + r.1 * e.1 > 0.0) {
            0u8
        } else {
            1u8
        }
    };
    let less = |i: usize, j: usize| {
        let (hi, hj) = (half(i), half(j));
        if hi != hj {
            return hi < hj;
        }
        let (a, b) = (edge(v, i), edge(v, j));
        a.0 * b.1 - a.1 * b.0 > 0.0
    };
    // The smallest direction of the rotated sorted sequence.
    let (mut lo, mut hi) = (0, n - 1);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if less(hi, mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    let start = lo;
    // The first edge of the second half-turn, counting from `start`.
    let (mut lo, mut hi) = (0, n);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if half((start + mid) % n) == 0 {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    (start + lo) % n
}

fn dot(a: (f64, f64), b: (f64, f64)) -> f64 {
    a.0 * b.0 + a.1 * b.1
}

/// The D-vertex extreme in direction `u`: Q's extreme vertex in `u`, P's in `−u`.
fn support(p: &[Point], q: &[Point], u: (f64, f64)) -> (usize, usize, (f64, f64)) {
    let j = extreme(q, u);
    let i = extreme(p, (-u.0, -u.1));
    (i, j, (q[j].x - p[i].x, q[j].y - p[i].y))
}

/// The point of segment `a`–`b` nearest the origin, and whether it is inside the
/// segment (not at an end).
fn nearest_on_segment(a: (f64, f64), b: (f64, f64)) -> ((f64, f64), Option<bool>) {
    let e = (b.0 - a.0, b.1 - a.1);
    let l = dot(e, e);
    let t = -dot(a, e) / l;
    // A NaN parameter (a degenerate segment) keeps the first end.
    if t.is_nan() || t <= 0.0 {
        (a, Some(false))
    } else if t >= 1.0 {
        (b, None)
    } else {
        ((a.0 + t * e.0, a.1 + t * e.1), Some(true))
    }
}

/// The direction from D towards the origin after a 2D GJK on D's supports: the
/// approximate outward normal of D at its point nearest the origin. `None` when the
/// arithmetic broke down (non-finite values) or the origin seems inside.
fn gjk_direction(p: &[Point], q: &[Point]) -> Option<(f64, f64)> {
    let centre = |v: &[Point]| {
        let (a, b) = (v[0], v[v.len() / 2]);
        (0.5 * a.x + 0.5 * b.x, 0.5 * a.y + 0.5 * b.y)
    };
    let (cp, cq) = (centre(p), centre(q));
    let mut x = support(p, q, (cp.0 - cq.0, cp.1 - cq.1)).2;
    // The simplex: one or two points of D (`len` of them); `x` its point nearest the
    // origin.
    let mut simplex = [x, x];
    let mut len = 1;
    for _ in 0..48 {
        let w = support(p, q, (-x.0, -x.1)).2;
        let xx = dot(x, x);
        if !(xx.is_finite() && w.0.is_finite() && w.1.is_finite()) || xx == 0.0 {
            return None;
        }
        // No support farther along −x than x itself: x is (nearly) the nearest point.
        if xx - dot(x, w) <= 1e-12 * xx {
            break;
        }
        match len {
            1 => {
                let a = simplex[0];
                let (nx, inside) = nearest_on_segment(a, w);
                x = nx;
                (simplex, len) = match inside {
                    Some(true) => ([a, w], 2),
                    Some(false) => ([a, a], 1),
                    None => ([w, w], 1),
                };
            }
            _ => {
                let [a, b] = simplex;
                // Keep the better of the two segments through w (the origin lies outside D).
                let (xa, ia) = nearest_on_segment(a, w);
                let (xb, ib) = nearest_on_segment(b, w);
                let (nx, keep, inside) = if dot(xa, xa) <= dot(xb, xb) {
                    (xa, a, ia)
                } else {
                    (xb, b, ib)
                };
                x = nx;
                (simplex, len) = match inside {
                    Some(true) => ([keep, w], 2),
                    Some(false) => ([keep, keep], 1),
                    None => ([w, w], 1),
                };
            }
        }
    }
    let u = (-x.0, -x.1);
    (u.0.is_finite() && u.1.is_finite() && (u.0 != 0.0 || u.1 != 0.0)).then_some(u)
}

/// The D-vertex before `(i, j)` on D's counter-clockwise boundary: the incoming edge of
/// larger direction is the last one walked (exact comparison).
fn step_back<K: Kernel>(kernel: K, p: &[Point], q: &[Point], i: usize, j: usize) -> (usize, usize) {
    let (n, m) = (p.len(), q.len());
    let (ip, jp) = ((i + n - 1) % n, (j + m - 1) % m);
    // Q's incoming edge q_{j-1} → q_j against −P's, p_{i-1} → p_i negated.
    match kernel.cross(q[jp], q[j], p[i], p[ip]) {
        // −P's incoming edge is counter-clockwise of Q's: it came last.
        Orientation::Ccw => (ip, j),
        _ => (i, jp),
    }
}

/// The nearest feature of D for two disjoint polygons, proposed by GJK and certified
/// exactly in a window of D's boundary around it; `None` when the window certifies
/// nothing.
pub(crate) fn nearest_feature<K: Kernel>(kernel: K, p: &[Point], q: &[Point]) -> Option<Feature> {
    let u = gjk_direction(p, q)?;
    let (mut i, mut j, _) = support(p, q, u);
    for _ in 0..3 {
        (i, j) = step_back(kernel, p, q, i, j);
    }
    walk::walk_from(kernel, p, q, (i, j), 14, |f| {
        if walk::is_nearest(kernel, p, q, f) {
            std::ops::ControlFlow::Break(f)
        } else {
            std::ops::ControlFlow::Continue(())
        }
    })
}
