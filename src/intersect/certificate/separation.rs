//! Separating edges from support lines and faces, and the turn comparisons they use.

use crate::intersect::certificate::Boundary;
use crate::kernel::{Kernel, Orientation, Point, Sign};

use crate::intersect::{Certificate, Which};
use Orientation::{Ccw, Collinear, Cw};

/// Whether the edge `u` → `v` of one polygon separates the other polygon `b`, given
/// that polygon's vertex `w`: `w` is strictly right of the edge's line and neither of
/// its neighbours lies deeper on the inner side (`w` is extreme against the edge, and
/// on a convex polygon a local extreme is global). Three predicates.
#[inline]
pub(crate) fn separates<K: Kernel, B: Boundary + ?Sized>(k: K, u: Point, v: Point, b: &B, w: usize) -> bool {
    let x = b.at(w);
    k.orient(u, v, x) == Cw
        && k.cross(u, v, x, b.at(b.next(w))) != Ccw
        && k.cross(u, v, x, b.at(b.prev(w))) != Ccw
}

/// A separating edge at the faces where one closed separating line supports both
/// polygons: `face_a` holds the vertices of `a` extreme in the line's normal direction
/// (towards `b`), `face_b` those of `b` extreme the other way (one vertex, or the two
/// ends of an edge parallel to the line; extra vertices only cost time). Tries the
/// edges of `b` at `face_b` against `face_a`, then the edges of `a` at `face_a`
/// against `face_b`, each with [`separates`].
///
/// Some candidate succeeds whenever the faces are right and the polygons disjoint: the
/// vertex of a − b extreme in the line's normal direction lies at the faces, and one
/// of the edges of a − b next to that face separates 0 (module docs). The certificate
/// names `a` as [`Which::P`].
pub(crate) fn from_faces<K: Kernel, A: Boundary + ?Sized, B: Boundary + ?Sized>(
    k: K,
    a: &A,
    face_a: &[usize],
    b: &B,
    face_b: &[usize],
) -> Option<Certificate> {
    for &x in face_b {
        for (u, v) in [(b.prev(x), x), (x, b.next(x))] {
            let (pu, pv) = (b.at(u), b.at(v));
            if face_a.iter().any(|&y| separates(k, pu, pv, a, y)) {
                return Some(Certificate::Separated {
                    of: Which::Q,
                    from: pu,
                    to: pv,
                });
            }
        }
    }
    for &y in face_a {
        for (u, v) in [(a.prev(y), y), (y, a.next(y))] {
            let (pu, pv) = (a.at(u), a.at(v));
            if face_b.iter().any(|&x| separates(k, pu, pv, b, x)) {
                return Some(Certificate::Separated {
                    of: Which::P,
                    from: pu,
                    to: pv,
                });
            }
        }
    }
    None
}

/// [`from_faces`] for a closed separating line `s` → `e` through (or parallel to the
/// support at) the extreme vertices `a0` of `a` (on the right) and `b0` of `b` (on the
/// left): each face is the vertex plus a neighbour whose edge to it is parallel to the
/// line.
pub(crate) fn from_support<K: Kernel, A: Boundary + ?Sized, B: Boundary + ?Sized>(
    k: K,
    (s, e): (Point, Point),
    a: &A,
    a0: usize,
    b: &B,
    b0: usize,
) -> Option<Certificate> {
    let face = |poly: &dyn Fn(usize) -> Point, v: usize, prev: usize, next: usize| {
        let mut f = [v, v, v];
        let mut len = 1;
        for nb in [prev, next] {
            if k.cross(s, e, poly(v), poly(nb)) == Collinear {
                f[len] = nb;
                len += 1;
            }
        }
        (f, len)
    };
    let (fa, la) = face(&|i| a.at(i), a0, a.prev(a0), a.next(a0));
    let (fb, lb) = face(&|i| b.at(i), b0, b.prev(b0), b.next(b0));
    from_faces(k, a, &fa[..la], b, &fb[..lb])
}

/// `v` is a vertex of the convex polygon whose directed line `s` → `e` has the polygon on
/// its closed right side: neither neighbour of `v` lies strictly left of the line through
/// `v` parallel to it, so (by convexity) no vertex does. Two predicates.
#[inline]
pub(crate) fn supports_right<K: Kernel, A: Boundary + ?Sized>(
    k: K,
    (s, e): (Point, Point),
    a: &A,
    v: usize,
) -> bool {
    let x = a.at(v);
    k.cross(s, e, x, a.at(a.next(v))) != Ccw && k.cross(s, e, x, a.at(a.prev(v))) != Ccw
}

/// As [`supports_right`], for a polygon on the closed left side.
#[inline]
pub(crate) fn supports_left<K: Kernel, A: Boundary + ?Sized>(
    k: K,
    (s, e): (Point, Point),
    a: &A,
    v: usize,
) -> bool {
    let x = a.at(v);
    k.cross(s, e, x, a.at(a.next(v))) != Cw && k.cross(s, e, x, a.at(a.prev(v))) != Cw
}

/// Whether directions `a` and `b` (each from its first point to its second) are equal.
#[inline]
pub(crate) fn same_direction<K: Kernel>(k: K, a: (Point, Point), b: (Point, Point)) -> bool {
    k.cross(a.0, a.1, b.0, b.1) == Collinear && k.dot(a.0, a.1, b.0, b.1) == Sign::Positive
}

/// Whether direction `a` is turned further counter-clockwise from `base` than `c`,
/// with turns measured in [0, 2π).
#[inline]
pub(crate) fn turn_gt<K: Kernel>(k: K, base: (Point, Point), a: (Point, Point), c: (Point, Point)) -> bool {
    turn_gt_classed(k, base, (a, turn_class(k, base, a)), c)
}

/// The quadrant of direction `d`'s turn from `base`: 0 (none), 1 (in (0, π)), 2 (π) or
/// 3 (in (π, 2π)).
#[inline]
pub(super) fn turn_class<K: Kernel>(k: K, base: (Point, Point), d: (Point, Point)) -> u8 {
    match k.cross(base.0, base.1, d.0, d.1) {
        Ccw => 1,
        Cw => 3,
        Collinear => {
            if k.dot(base.0, base.1, d.0, d.1) == Sign::Positive {
                0
            } else {
                2
            }
        }
    }
}

/// [`turn_gt`] with `a`'s [`turn_class`] computed once by the caller.
#[inline]
pub(super) fn turn_gt_classed<K: Kernel>(
    k: K,
    base: (Point, Point),
    (a, ca): ((Point, Point), u8),
    c: (Point, Point),
) -> bool {
    let cc = turn_class(k, base, c);
    if ca != cc {
        ca > cc
    } else {
        (ca == 1 || ca == 3) && k.cross(c.0, c.1, a.0, a.1) == Ccw
    }
}

/// A vertex of the convex polygon `v` (counter-clockwise) farthest to the left of the
/// directed line `s` → `e`, by binary search: O(log n) predicates.
///
/// Leftness grows along edges turned less than the reversed direction e → s (counted
/// from edge 0's direction, in [0, 2π)) and shrinks along the others, so the extreme
/// vertex starts the first edge turned at least that far.
pub(crate) fn extreme_left<K: Kernel>(k: K, v: &[Point], (s, e): (Point, Point)) -> usize {
    let n = v.len();
    let base = (v[0], v[1]);
    let target = (e, s);
    let target = (target, turn_class(k, base, target));
    // First index i in 0..n with turn(edge i) ≥ turn(target); n if none.
    let reached = |i: usize| !turn_gt_classed(k, base, target, (v[i], v[if i + 1 == n { 0 } else { i + 1 }]));
    let (mut lo, mut hi) = (0, n);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if reached(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo % n
}
