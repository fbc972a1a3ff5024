//! Contact geometry of two convex polygons: how far apart (distance and a closest pair)
//! or how deep (penetration depth, its normal, the overlap polygon P ∩ Q and its area),
//! exactly, every constructed number correctly rounded.
//!
//! ```
//! use polysect::contact::{Contact, contact};
//! use polysect::ConvexPolygon;
//! let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
//! let q = ConvexPolygon::new([[5.0, 1.0], [6.0, 0.0], [6.0, 3.0]])?;
//! let Contact::Separated(s) = contact(&p, &q) else { unreachable!() };
//! assert_eq!(s.distance, Some(3.0));
//! assert_eq!(s.closest, [[2.0, 1.0].into(), [5.0, 1.0].into()]);
//!
//! let r = ConvexPolygon::new([[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]])?;
//! let Contact::Overlapping(o) = contact(&p, &r) else { unreachable!() };
//! assert_eq!((o.depth, o.area), (Some(1.0), Some(1.0)));
//! assert_eq!(o.overlap, [[1.0, 1.0].into(), [2.0, 1.0].into(), [2.0, 2.0].into(), [1.0, 2.0].into()]);
//! # Ok::<(), polysect::PolygonError>(())
//! ```
//!
//! # Algorithm
//! Everything is read off the Minkowski difference D = Q ⊕ (−P), whose points are the
//! differences `y − x` of points `x ∈ P`, `y ∈ Q`: the polygons meet iff the origin lies
//! in D, their distance is the origin's distance to D, and the penetration depth (the
//! length of the shortest translation of Q after which they only touch) is the origin's
//! distance to D's boundary. D is never built: its boundary is walked in O(n + m) by
//! merging the edge directions of Q and −P (`walk`), and every question about a feature
//! of D is a predicate on input points.
//! * **Distance** (disjoint): the walk stops at the first feature of D whose exact test
//!   certifies it as nearest the origin: a vertex of one polygon outside an edge of the
//!   other, projecting onto it, and deepest across it (the D-edge supports D and the
//!   origin lies beyond it), or two vertices each in the other's normal cone. The
//!   certificate is a handful of orientations and dot products, so a misjudging kernel
//!   cannot produce a wrong closest pair silently: when no feature passes, the exact
//!   kernel walks again.
//! * **Depth and normal** (meeting): for convex polygons the shortest separating
//!   translation is along one of the edge normals of either polygon, and its length
//!   along edge e is how deep the other polygon's deepest vertex lies across e's line
//!   (its D-edge's distance from the origin). The walk pairs every edge with that
//!   vertex; the candidates `o²/|e|²` (`o` the cross product that measures the depth)
//!   are compared exactly as rationals, through the kernel's sign of
//!   `o₁²·|e₂|² − o₂²·|e₁|²`.
//! * **Overlap**: the chords that each edge of one polygon cuts from the other, found
//!   by the O(log n) segment queries, give every vertex of P ∩ Q as an exact rational
//!   point; their exact convex hull, without collinear vertices, is P ∩ Q (`overlap`).
//!   The area is the exact shoelace sum over it.
//!
//! Whether they meet is decided first by the O(log n) [`Barba`] test under the same
//! kernel, except for the distance under an exact kernel on pairs of at most 40
//! vertices in all: a certified feature proves them disjoint, and the exact walk finds
//! one iff they are, so the walk alone answers. Under an exact kernel the depth
//! candidates are first bounded in floating point (coordinates 0 or in
//! [2^-100, 2^100]), and only those the bounds cannot rule out are compared exactly.
//!
//! # Complexity
//! For n and m vertices: distance O(log n + log m) for the test that they are disjoint
//! plus O(n + m) predicates for the walk (it stops at the nearest feature: on average
//! half the boundary); depth O(n + m) predicates of degree 6 in the input; overlap
//! O((n + m) log(n + m)) predicates and exact arithmetic on at most 2(n + m) rational
//! points (denominators grow with the number of edge crossings, which is small for
//! ordinary pairs and up to 2·min(n, m)). Linked polygons are converted to arrays
//! first (O(n + m)).
//!
//! # Degeneracies
//! * **Touching** (a shared vertex, a vertex on an edge, a shared edge portion) is
//!   meeting: depth 0, area 0, the overlap one point or two (a touching segment), and
//!   the normal a unit direction along which every move of Q separates them (the normal
//!   of an edge whose line passes through the touching point, with the other polygon
//!   on its outer side).
//! * **Parallel closest edges**: any closest pair on them is a valid answer; the walk
//!   returns the first certified feature from D's lowest vertex, deterministic for a
//!   given input.
//! * **Containment** either way: the depth is the inner polygon's escape along the
//!   best edge normal, the overlap the inner polygon.
//! * Tied depth directions: the first minimum in the walk's order.
//!
//! # Precision
//! Decisions (disjoint or not, which feature is nearest, which depth candidate is
//! smallest) are the kernel's: exact under [`Exact`], possibly wrong under [`Fast`] on
//! nearly degenerate input. Constructed values are exact [`Rational`]s rounded once:
//! squared distance, squared depth and twice the area are rationals; the distance and
//! the depth are the correctly rounded square roots of the first two; closest points,
//! overlap vertices and the normal's components (each `±√(c²/|e|²)`) correctly rounded
//! (the double nearest the exact value, ties to even). A distance, depth or area whose
//! rounding overflows is `None`.
//!
//! [`Fast`]: crate::Fast
//! [`Barba`]: crate::intersect::Barba

mod construct;
mod overlap;
mod rounded;
mod search;
mod walk;

pub use walk::Feature;

use crate::intersect::{ArrayIntersection, Barba};
use crate::kernel::sealed::Predicates as _;
use crate::kernel::{Exact, Kernel, Point, Rational, Sign};
use crate::polygon::{ConvexPolygon, LinkedPolygon};
use construct::DepthOrder;
use std::ops::ControlFlow;

/// How two disjoint polygons are apart.
#[derive(Clone, Debug, PartialEq)]
pub struct Separation {
    /// The squared distance, exactly.
    pub squared_distance: Rational,
    /// The distance, correctly rounded; `None` when that overflows.
    pub distance: Option<f64>,
    /// A closest pair, first on P then on Q, each coordinate correctly rounded.
    pub closest: [Point; 2],
    /// The same pair exactly (`[x, y]` of P's point, then of Q's).
    pub closest_exact: [[Rational; 2]; 2],
    /// The feature of the Minkowski difference the pair comes from.
    pub feature: Feature,
}

/// How two meeting polygons overlap.
#[derive(Clone, Debug, PartialEq)]
pub struct Penetration {
    /// The squared penetration depth, exactly.
    pub squared_depth: Rational,
    /// The penetration depth (the length of the shortest translation of Q after which
    /// the two only touch), correctly rounded; `None` when that overflows.
    pub depth: Option<f64>,
    /// That translation's unit direction, each component correctly rounded; for depth
    /// 0 a direction along which every move of Q separates them.
    pub normal: [f64; 2],
    /// P ∩ Q: counter-clockwise, without collinear vertices, each vertex correctly
    /// rounded, a point repeated after rounding dropped, starting from the lowest (then
    /// leftmost) rounded point.
    pub overlap: Vec<Point>,
    /// Twice the area of P ∩ Q, exactly.
    pub twice_area: Rational,
    /// The area of P ∩ Q, correctly rounded; `None` when that overflows.
    pub area: Option<f64>,
    /// P ∩ Q exactly, counter-clockwise (any start vertex).
    pub overlap_exact: Vec<[Rational; 2]>,
}

/// The contact of two convex polygons: apart, or overlapping (touching included).
#[derive(Clone, Debug, PartialEq)]
pub enum Contact {
    /// They do not meet.
    Separated(Separation),
    /// They meet (closed sets: touching counts).
    Overlapping(Penetration),
}

impl Contact {
    /// Whether the polygons meet.
    pub fn intersects(&self) -> bool {
        matches!(self, Contact::Overlapping(_))
    }
}

/// [`contact_with`] under the exact kernel.
pub fn contact(p: &ConvexPolygon, q: &ConvexPolygon) -> Contact {
    contact_with(Exact, p, q)
}

/// The contact of `p` and `q`, decisions by `kernel` (module docs: algorithm,
/// complexity, degeneracies, precision).
pub fn contact_with<K: Kernel>(kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Contact {
    match separated_feature(kernel, p, q) {
        Some(feature) => Contact::Separated(construct::separation(p.vertices(), q.vertices(), feature)),
        None => Contact::Overlapping(penetration_of(kernel, p, q)),
    }
}

/// [`contact_with`] for linked polygons (converted to arrays, O(n + m)).
pub fn contact_linked_with<K: Kernel>(kernel: K, p: &LinkedPolygon, q: &LinkedPolygon) -> Contact {
    contact_with(kernel, &p.to_convex(), &q.to_convex())
}

/// [`contact_linked_with`] under the exact kernel.
pub fn contact_linked(p: &LinkedPolygon, q: &LinkedPolygon) -> Contact {
    contact_linked_with(Exact, p, q)
}

/// The distance and a closest pair of `p` and `q`, or `None` when they meet.
pub fn separation_with<K: Kernel>(kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Option<Separation> {
    match contact_with(kernel, p, q) {
        Contact::Separated(s) => Some(s),
        Contact::Overlapping(_) => None,
    }
}

/// Below this many vertices in all, the distance walks D whole instead of searching it.
const LINEAR_BELOW: usize = 40;

/// How far apart two disjoint polygons are, correctly rounded: a [`Separation`]
/// without its exact rationals, answered without big integers when a floating-point
/// bound decides every rounding (nearly always), else rounded from the exact values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Distance {
    /// The distance, correctly rounded; `None` when that overflows.
    pub distance: Option<f64>,
    /// A closest pair, first on P then on Q, each coordinate correctly rounded.
    pub closest: [Point; 2],
    /// The feature of the Minkowski difference the pair comes from.
    pub feature: Feature,
}

/// The distance and a closest pair of `p` and `q`, decisions by `kernel`, or `None`
/// when they meet: the same values as [`Separation`]'s (the same feature), without
/// allocating when the certified double-double rounding decides them (inputs between
/// 2^-250 and 2^250 in magnitude, the exact value not within about 2^-100 of a midpoint
/// between doubles); O(log n + log m) on ordinary input (module docs).
pub fn distance_with<K: Kernel>(kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Option<Distance> {
    let feature = separated_feature(kernel, p, q)?;
    let (pv, qv) = (p.vertices(), q.vertices());
    Some(match rounded::separation(pv, qv, feature) {
        Some((d, [a, b])) => Distance {
            distance: Some(d),
            // The exact rounding never gives −0 (a zero rational rounds to +0), but an
            // input vertex or a double-double sum may: `+ 0.0` turns −0 into +0 and
            // leaves every other value alone.
            closest: [a, b].map(|v| Point::new(v.x + 0.0, v.y + 0.0)),
            feature,
        },
        None => {
            let s = construct::separation(pv, qv, feature);
            Distance {
                distance: s.distance,
                closest: s.closest,
                feature,
            }
        }
    })
}

/// [`distance_with`] under the exact kernel.
pub fn distance(p: &ConvexPolygon, q: &ConvexPolygon) -> Option<Distance> {
    distance_with(Exact, p, q)
}

/// How deep two meeting polygons overlap: a [`Penetration`] without its overlap
/// polygon and area.
#[derive(Clone, Debug, PartialEq)]
pub struct Depth {
    /// The squared penetration depth, exactly.
    pub squared_depth: Rational,
    /// The penetration depth, correctly rounded; `None` when that overflows.
    pub depth: Option<f64>,
    /// The unit direction of the shortest translation of Q that leaves the two only
    /// touching, each component correctly rounded (for depth 0, a direction along which
    /// every move of Q separates them).
    pub normal: [f64; 2],
}

/// The penetration depth and normal of `p` and `q`, decisions by `kernel`, or `None`
/// when they do not meet: the same values as [`Penetration`]'s, without building the
/// overlap polygon (which dominates [`contact_with`] on meeting pairs). O(n + m): the
/// walk over D's edges.
pub fn depth_with<K: Kernel>(kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Option<Depth> {
    if !Barba.intersects_with(kernel, p, q) {
        return None;
    }
    let k = kernel.within([p.bounding_box(), q.bounding_box()]);
    let (edge, of_q) = deepest_edge(k, p.vertices(), q.vertices());
    // The double-double rounding nearly always decides; the exact square root otherwise.
    Some(match rounded::depth_and_normal(edge, of_q) {
        Some((depth, normal)) => Depth {
            squared_depth: construct::squared_depth(edge),
            depth: Some(depth),
            normal,
        },
        None => {
            let (squared, normal) = construct::depth_and_normal(edge, of_q);
            Depth {
                depth: construct::finite(squared.sqrt_to_f64()),
                squared_depth: squared,
                normal,
            }
        }
    })
}

/// [`depth_with`] under the exact kernel.
pub fn depth(p: &ConvexPolygon, q: &ConvexPolygon) -> Option<Depth> {
    depth_with(Exact, p, q)
}

/// The nearest feature of D when the kernel finds `p` and `q` disjoint, `None` when it
/// finds them meeting.
///
/// A certified feature proves the polygons disjoint by itself (`walk::is_nearest`: a
/// separating edge line with the other polygon's extreme vertex strictly beyond it, or
/// a vertex pair meeting the optimality conditions of convex distance), and under an
/// exact kernel the whole walk certifies a feature iff they are disjoint. So an exact
/// kernel on a small pair skips the intersection test and walks at once: a walk
/// without a certificate means they meet. Larger pairs, and every inexact kernel, are
/// tested first by [`Barba`] (the search alone could not tell "meeting" from "missed
/// the window" without the whole walk). Either way the feature is the one
/// [`nearest_feature`] finds, so every query answers the same pair.
fn separated_feature<K: Kernel>(kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Option<Feature> {
    let (pv, qv) = (p.vertices(), q.vertices());
    if K::EXACT && pv.len() + qv.len() <= LINEAR_BELOW {
        let k = kernel.within([p.bounding_box(), q.bounding_box()]);
        return walk::nearest_feature(k, pv, qv);
    }
    if Barba.intersects_with(kernel, p, q) {
        return None;
    }
    Some(nearest_feature(kernel, p, q))
}

/// The nearest feature of D for two polygons the kernel found disjoint. When the
/// kernel's walk certifies no feature (a misjudging kernel), the exact kernel decides
/// again, and when they do meet after all, the feature is the touching point's
/// (distance 0).
///
/// Every predicate reads input vertices only, so the kernel restricted to the two
/// bounding boxes ([`Kernel::within`]: one semi-static error bound per query instead
/// of one per call) answers them.
fn nearest_feature<K: Kernel>(kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Feature {
    let (pv, qv) = (p.vertices(), q.vertices());
    let boxes = [p.bounding_box(), q.bounding_box()];
    let k = kernel.within(boxes);
    // Small pairs: the whole walk costs less than the search's setup.
    let searched = if pv.len() + qv.len() > LINEAR_BELOW {
        search::nearest_feature(k, pv, qv)
    } else {
        None
    };
    searched
        .or_else(|| walk::nearest_feature(k, pv, qv))
        .or_else(|| walk::nearest_feature(Exact.within(boxes), pv, qv))
        .or_else(|| touching_feature(pv, qv))
        // Only reachable when the polygons overlap properly but the kernel said
        // disjoint: the first vertex pair, at its exact distance.
        .unwrap_or(Feature::Vertices { p: 0, q: 0 })
}

/// A feature of D through the origin, when the polygons only touch.
fn touching_feature(p: &[Point], q: &[Point]) -> Option<Feature> {
    walk::walk(Exact, p, q, |f| {
        let on = match construct::edge_and_vertex(p, q, f) {
            Some([a, b, v]) => {
                Exact.orient(a, b, v) == crate::kernel::Orientation::Collinear
                    && Exact.dot(a, b, a, v) != Sign::Negative
                    && Exact.dot(b, a, b, v) != Sign::Negative
            }
            None => match f {
                Feature::Vertices { p: i, q: j } => p[i] == q[j],
                _ => false,
            },
        };
        if on {
            ControlFlow::Break(f)
        } else {
            ControlFlow::Continue(())
        }
    })
}

/// The D-edge nearest the origin among all of D's edges (each paired by the walk with
/// its deepest vertex), by exact comparison of the candidates' squared depths: the edge
/// and vertex `[a, b, v]`, and whether the edge is Q's. Of tied edges, the first in the
/// walk's order.
///
/// Under an exact kernel, when every coordinate is 0 or of magnitude in
/// [2^-100, 2^100] ([`depth_bounds`]), each candidate's squared depth is first bounded in
/// floating point; a candidate whose lower bound exceeds the least upper bound is
/// strictly deeper than the minimum and is never compared exactly. The exact scan over
/// the rest (in the walk's order) picks the same edge as the scan over all.
fn deepest_edge<K: Kernel>(kernel: K, p: &[Point], q: &[Point]) -> ([Point; 3], bool) {
    let filtered = K::EXACT && p.iter().chain(q).all(|v| moderate(v.x) && moderate(v.y));
    let mut candidates: Vec<([Point; 3], bool, f64)> = Vec::new();
    let mut least_upper = f64::INFINITY;
    let mut best: Option<([Point; 3], bool)> = None;
    let consider = |c: [Point; 3], of_q: bool, best: &mut Option<([Point; 3], bool)>| {
        let better = match *best {
            None => true,
            Some((b, _)) => kernel.sign(&DepthOrder(c, b)) == Sign::Negative,
        };
        if better {
            *best = Some((c, of_q));
        }
    };
    if filtered {
        candidates.reserve(p.len() + q.len());
    }
    walk::walk::<K, ()>(kernel, p, q, |f| {
        if let Some(c) = construct::edge_and_vertex(p, q, f) {
            let of_q = matches!(f, Feature::EdgeOfQ { .. });
            if filtered {
                let (low, high) = depth_bounds(c);
                least_upper = least_upper.min(high);
                candidates.push((c, of_q, low));
            } else {
                consider(c, of_q, &mut best);
            }
        }
        ControlFlow::Continue(())
    });
    for &(c, of_q, low) in &candidates {
        // `low > least_upper`: strictly deeper than some candidate, so never the first
        // minimum (NaN never excludes).
        let excluded = low > least_upper;
        if !excluded {
            consider(c, of_q, &mut best);
        }
    }
    // The walk visits n + m ≥ 6 edges, so `best` is set.
    best.unwrap_or(([p[0], p[1], q[0]], false))
}

/// Whether a coordinate is 0 or of magnitude in [2^-100, 2^100]: then every nonzero
/// coordinate difference is at least 2^-152, every nonzero product of two at least
/// 2^-304 and at most 2^204, and nothing in [`depth_bounds`] overflows or underflows.
#[inline(always)]
fn moderate(x: f64) -> bool {
    const LOW: f64 = 7.888609052210118e-31; // 2^-100
    const HIGH: f64 = 1.2676506002282294e30; // 2^100
    x == 0.0 || (LOW..=HIGH).contains(&x.abs())
}

/// Bounds `[low, high]` on the squared depth `o²/l` of the D-edge `[a, b, v]`
/// (`o = e × (v − a)`, `l = |e|²`, `e = b − a`), for coordinates that are
/// [`moderate`].
///
/// With rounded differences, the computed `õ` is within `E = (3 + 16u)u(|ex·wy| + |ey·wx|)`
/// of `o` (Shewchuk's bound for the orientation determinant), and the computed `l̃`
/// within a factor `(1 ± u)⁴` of `l` (two roundings of each difference's square, one
/// of the sum), so `l ∈ [l̃(1 − 5u), l̃(1 + 5u)]`. Then
/// `o²/l ∈ [(|õ| − E)₊² / (l̃(1 + 8u)), (|õ| + E)² / (l̃(1 − 8u))]` (8u: 5u is not a
/// double's distance from 1), and the six roundings of each end are covered by the
/// factors `1 ∓ 10u`. In the moderate range a
/// nonzero `o` is a multiple of 2^-304 and every intermediate stays normal, so no
/// underflow weakens a relative bound; `õ = E = 0` only when both products are zero,
/// that is when `o = 0`.
#[inline(always)]
fn depth_bounds([a, b, v]: [Point; 3]) -> (f64, f64) {
    const U: f64 = f64::EPSILON / 2.0;
    let (ex, ey) = (b.x - a.x, b.y - a.y);
    let (wx, wy) = (v.x - a.x, v.y - a.y);
    let (left, right) = (ex * wy, ey * wx);
    let o = (left - right).abs();
    // (3 + 2^-40)u covers Shewchuk's (3 + 16u)u and the bound's own two roundings.
    let err = (3.0 + 1.0 / (1u64 << 40) as f64) * U * (left.abs() + right.abs());
    let l = ex * ex + ey * ey;
    let under = o - err;
    let low = if under > 0.0 {
        under * under / (l * (1.0 + 8.0 * U)) * (1.0 - 10.0 * U)
    } else {
        0.0
    };
    let over = o + err;
    let high = over * over / (l * (1.0 - 8.0 * U)) * (1.0 + 10.0 * U);
    (low, high)
}

/// The penetration of two polygons the kernel found meeting.
fn penetration_of<K: Kernel>(kernel: K, p: &ConvexPolygon, q: &ConvexPolygon) -> Penetration {
    let (pv, qv) = (p.vertices(), q.vertices());
    let k = kernel.within([p.bounding_box(), q.bounding_box()]);
    let (edge, of_q) = deepest_edge(k, pv, qv);
    construct::penetration(edge, of_q, overlap::overlap(p, q))
}

#[cfg(test)]
mod tests;
