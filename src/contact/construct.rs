//! Exact constructions from a certified feature: the squared distance and the closest
//! pair, the squared depth and the normal, each as a [`Rational`] and then correctly
//! rounded.

use super::walk::Feature;
use super::{Penetration, Separation};
use crate::kernel::{Point, Polynomial, Rational, Ring, Sign};
use std::collections::HashSet;

/// An exact point.
pub(crate) type Exact2 = [Rational; 2];

pub(crate) fn exact(p: Point) -> Exact2 {
    [Rational::from_f64(p.x), Rational::from_f64(p.y)]
}

pub(crate) fn minus(a: &Exact2, b: &Exact2) -> Exact2 {
    [&a[0] - &b[0], &a[1] - &b[1]]
}

pub(crate) fn dot(u: &Exact2, v: &Exact2) -> Rational {
    &(&u[0] * &v[0]) + &(&u[1] * &v[1])
}

pub(crate) fn cross(u: &Exact2, v: &Exact2) -> Rational {
    &(&u[0] * &v[1]) - &(&u[1] * &v[0])
}

/// The exact point rounded coordinate by coordinate (never overflows: it lies in the
/// bounding box of finite input points).
pub(crate) fn rounded(p: &Exact2) -> Point {
    Point::new(p[0].to_f64(), p[1].to_f64())
}

/// A correctly rounded value, `None` when the rounding overflows.
pub(crate) fn finite(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

/// The exact point of segment `a → b` nearest `v`, and the squared distance.
fn project(a: Point, b: Point, v: Point) -> (Exact2, Rational) {
    let (a, b, v) = (exact(a), exact(b), exact(v));
    let e = minus(&b, &a);
    let w = minus(&v, &a);
    let l = dot(&e, &e);
    let t = dot(&w, &e);
    let c = cross(&e, &w);
    let point = [&a[0] + &(&e[0] * &t).div(&l), &a[1] + &(&e[1] * &t).div(&l)];
    (point, c.square().div(&l))
}

/// The separation certified by `feature` (a nearest feature of D, polygons disjoint).
pub(crate) fn separation(p: &[Point], q: &[Point], feature: Feature) -> Separation {
    let (n, m) = (p.len(), q.len());
    let (on_p, on_q, squared) = match feature {
        Feature::Vertices { p: i, q: j } => {
            let (a, b) = (exact(p[i]), exact(q[j]));
            let d = minus(&a, &b);
            let s = dot(&d, &d);
            (a, b, s)
        }
        Feature::EdgeOfQ { q: j, p: i } => {
            let (point, s) = project(q[j], q[(j + 1) % m], p[i]);
            (exact(p[i]), point, s)
        }
        Feature::EdgeOfP { p: i, q: j } => {
            let (point, s) = project(p[i], p[(i + 1) % n], q[j]);
            (point, exact(q[j]), s)
        }
    };
    Separation {
        distance: finite(squared.sqrt_to_f64()),
        closest: [rounded(&on_p), rounded(&on_q)],
        closest_exact: [on_p, on_q],
        squared_distance: squared,
        feature,
    }
}

/// The edge `a → b` and the vertex `v` of a D-edge: `(a, b, v)`.
pub(crate) fn edge_and_vertex(p: &[Point], q: &[Point], feature: Feature) -> Option<[Point; 3]> {
    let (n, m) = (p.len(), q.len());
    match feature {
        Feature::Vertices { .. } => None,
        Feature::EdgeOfQ { q: j, p: i } => Some([q[j], q[(j + 1) % m], p[i]]),
        Feature::EdgeOfP { p: i, q: j } => Some([p[i], p[(i + 1) % n], q[j]]),
    }
}

/// `o₁²·l₂ − o₂²·l₁` for two D-edges, `oₖ = (bₖ − aₖ) × (vₖ − aₖ)` the vertex's depth
/// across the edge's line times the edge's length and `lₖ = |bₖ − aₖ|²`: negative when
/// the first D-edge's line is nearer the origin (both `oₖ ≥ 0` inside D).
pub(crate) struct DepthOrder(pub [Point; 3], pub [Point; 3]);

impl Polynomial for DepthOrder {
    fn eval<R: Ring>(&self) -> R {
        let f = R::from_f64;
        let parts = |[a, b, v]: [Point; 3]| {
            let (ex, ey) = (f(b.x) - f(a.x), f(b.y) - f(a.y));
            let (wx, wy) = (f(v.x) - f(a.x), f(v.y) - f(a.y));
            let o = ex.clone() * wy - ey.clone() * wx;
            let l = ex.clone() * ex + ey.clone() * ey;
            (o, l)
        };
        let (o1, l1) = parts(self.0);
        let (o2, l2) = parts(self.1);
        o1.clone() * o1 * l2 - o2.clone() * o2 * l1
    }
}

/// The correctly rounded `sign · √(c² / l)`.
fn unit_component(c: &Rational, l: &Rational) -> f64 {
    let magnitude = c.square().div(l).sqrt_to_f64();
    if c.sign() == Sign::Negative {
        -magnitude
    } else {
        magnitude
    }
}

/// The squared depth `o²/l` of the D-edge of edge `a → b` with vertex `v` (as for
/// [`depth_and_normal`]).
pub(crate) fn squared_depth(edge: [Point; 3]) -> Rational {
    squared_depth_parts(edge).0
}

/// The squared depth, the edge vector `e = b − a` and `l = |e|²`, exactly.
fn squared_depth_parts([a, b, v]: [Point; 3]) -> (Rational, Exact2, Rational) {
    let (a, b, v) = (exact(a), exact(b), exact(v));
    let e = minus(&b, &a);
    let l = dot(&e, &e);
    let o = cross(&e, &minus(&v, &a));
    (o.square().div(&l), e, l)
}

/// The squared depth and the normal of the D-edge of edge `a → b` with vertex `v`
/// (`[a, b, v]`; `of_q`: the edge is Q's): the translation of Q that makes the polygons
/// touch is `−depth · n_D`, `n_D` the D-edge's outward normal (Q's edge's outward normal
/// for an edge of Q, the opposite of P's for an edge of P).
pub(crate) fn depth_and_normal([a, b, v]: [Point; 3], of_q: bool) -> (Rational, [f64; 2]) {
    let (squared, e, l) = squared_depth_parts([a, b, v]);
    // Counter-clockwise edge e: outward normal (e_y, −e_x).
    let direction = if of_q {
        [-&e[1], e[0].clone()]
    } else {
        [e[1].clone(), -&e[0]]
    };
    (
        squared,
        [
            unit_component(&direction[0], &l),
            unit_component(&direction[1], &l),
        ],
    )
}

/// The penetration from its deepest D-edge (as for [`depth_and_normal`]) and the
/// overlap polygon (exact, counter-clockwise, strictly convex, any start).
pub(crate) fn penetration(edge: [Point; 3], of_q: bool, overlap: Vec<Exact2>) -> Penetration {
    let (squared, normal) = depth_and_normal(edge, of_q);
    let twice_area = twice_area(&overlap);
    let mut points: Vec<Point> = Vec::with_capacity(overlap.len());
    let mut seen = HashSet::with_capacity(overlap.len());
    for v in &overlap {
        let r = rounded(v);
        // Rounding never yields −0 (a zero rational rounds to +0), so bits identify points.
        if seen.insert((r.x.to_bits(), r.y.to_bits())) {
            points.push(r);
        }
    }
    if let Some(start) = (0..points.len()).min_by(|&i, &k| {
        let (a, b) = (points[i], points[k]);
        a.y.total_cmp(&b.y).then(a.x.total_cmp(&b.x))
    }) {
        points.rotate_left(start);
    }
    let half = Rational::from_f64(0.5);
    Penetration {
        depth: finite(squared.sqrt_to_f64()),
        squared_depth: squared,
        normal,
        overlap: points,
        area: finite((&twice_area * &half).to_f64()),
        twice_area,
        overlap_exact: overlap,
    }
}

/// Twice the signed area of an exact polygon (zero below three vertices).
pub(crate) fn twice_area(v: &[Exact2]) -> Rational {
    let k = v.len();
    if k < 3 {
        return Rational::zero();
    }
    let mut sum = Rational::zero();
    for i in 0..k {
        let (a, b) = (&v[i], &v[(i + 1) % k]);
        sum = &sum + &cross(a, b);
    }
    sum
}
