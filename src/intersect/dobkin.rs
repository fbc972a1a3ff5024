//! [`Dobkin`]: the Dobkin–Souvaine O(log n) test on sorted arrays (thesis 3.2).
//!
//! # The algorithm
//! 1. **Top and bottom by binary search.** The edge directions of a convex polygon
//!    stored counter-clockwise turn monotonically through one full turn, so "edge i
//!    points further round than a target direction, measured from edge 0" is a
//!    monotone predicate of i. Two binary searches find the first edge pointing
//!    strictly below west (it starts at the topmost vertex, the left one if the top
//!    is a horizontal edge) and the first edge pointing strictly above east (it starts
//!    at the bottommost vertex, the right one if the bottom is horizontal). A
//!    horizontal top or bottom edge is detected by looking at the edge just before.
//! 2. **Chains.** The *left chain* runs counter-clockwise from the top (left end of a
//!    horizontal top) down to the bottom (left end of a horizontal bottom); every edge
//!    strictly descends. The *right chain* runs from the bottom (right end) up to
//!    the top (right end); every edge strictly ascends. Horizontal edges belong to
//!    neither. The left chain bounds the region `L = {y ∈ [y_bot, y_top], x ≥ x_L(y)}`,
//!    the right chain `R = {y ∈ [y_bot, y_top], x ≤ x_R(y)}`, and `P = L_P ∩ R_P`.
//!    Chains are index ranges into the polygon's array; nothing is copied.
//! 3. **Lemma (Dobkin–Souvaine).** P and Q intersect iff `L_P ∩ R_Q ≠ ∅` and
//!    `L_Q ∩ R_P ≠ ∅`. (On the common y-interval put `h1 = x_R^Q − x_L^P` and
//!    `h2 = x_R^P − x_L^Q`; both are concave and `h1 + h2 ≥ 0` because both polygons
//!    have non-negative width, so if `{h1 ≥ 0}` and `{h2 ≥ 0}` are both non-empty
//!    they cannot be disjoint intervals: a height between them would make the sum
//!    negative.)
//! 4. **Pruning a left chain against a right chain** (the LR-region lemmas, stated
//!    here as a search for the maximum of the concave function `g = x_R − x_L` on
//!    the common y-interval I; the regions meet iff `max g ≥ 0`). Take the median
//!    edge e of the left chain and f of the right chain, with slopes `s_L = dx/dy`
//!    and `s_R`; their comparison is one `cross` on input points. `x_L` is convex
//!    and `x_R` concave in y, so
//!    * if `s_R ≥ s_L`, g is non-decreasing below `min(top(e), top(f))`: the lower
//!      part of the chain whose median ends lower is pruned and I starts there;
//!    * if `s_R < s_L`, g is decreasing above `max(bottom(e), bottom(f))`: the upper
//!      part of the chain whose median starts higher is pruned and I ends there.
//!
//!    When the cut would empty I, the maximum lies at the end of I and a single
//!    height is tested. Each iteration halves one chain, so once both have one
//!    edge left g is linear on I and its two ends are tested.
//! 5. **Height test.** Every end of I is the height of a vertex w of one of the
//!    chains (both ranges always cover I and every cut is at a vertex), so "is
//!    `x_L ≤ x_R` at that height" is one `orient` of w against the other chain's
//!    edge at that height (found by binary search) or one comparison of x
//!    coordinates when both chains have a vertex there.
//!
//! # Complexity
//! O(log n + log m) time, O(1) memory, for polygons of n and m vertices, on every
//! input: four binary searches for the extreme vertices, two chain-pair searches
//! that halve a chain per iteration, at most four height tests of O(log) each.
//!
//! # Degeneracies
//! Horizontal top and bottom edges are excluded from the chains (step 1), so no
//! slope is infinite. Touching pairs are intersecting: every test is closed (`≥`,
//! `orient ≠ Cw`). Polygons whose y-ranges meet in a single height reduce to one
//! height test. Equal slopes fall in the `s_R ≥ s_L` case, which is valid for
//! equality.
//!
//! # Precision
//! Every decision is a comparison of input coordinates or an `orient`/`cross`/`dot`
//! on input points (the west and east directions are the exact vectors (−1, 0) and
//! (1, 0)); exact under [`Exact`](crate::Exact). Under [`Fast`](crate::Fast) the
//! searches may misjudge near-degenerate input but always terminate: every loop
//! shrinks an index range.

use super::{ArrayIntersection, Probe};
use crate::kernel::{Kernel, Orientation, Point, Sign};
use crate::polygon::ConvexPolygon;

/// The Dobkin–Souvaine O(log n) test; see the module docs.
///
/// ```
/// use polysect::{ConvexPolygon, intersect::{ArrayIntersection, Dobkin}};
/// let p = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
/// let touching = ConvexPolygon::new([[2.0, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// let apart = ConvexPolygon::new([[2.5, 1.0], [3.0, 0.0], [3.0, 2.0]])?;
/// assert!(Dobkin.intersects(&p, &touching));
/// assert!(!Dobkin.intersects(&p, &apart));
/// # Ok::<(), polysect::PolygonError>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct Dobkin;

impl ArrayIntersection for Dobkin {
    const NAME: &'static str = "dobkin";

    fn intersects_probed<K: Kernel, P: Probe>(
        &self,
        k: K,
        p: &ConvexPolygon,
        q: &ConvexPolygon,
        probe: &mut P,
    ) -> bool {
        let (pv, qv) = (p.vertices(), q.vertices());
        let (pl, pr) = chains(k, pv);
        let (ql, qr) = chains(k, qv);
        pair_meets(k, pv, pl, qv, qr, probe) && pair_meets(k, qv, ql, pv, pr, probe)
    }
}

/// A chain: `len` consecutive vertices of a polygon starting at array index `start`.
#[derive(Clone, Copy, Debug)]
struct Chain {
    start: usize,
    len: usize,
}

/// The vertex at position `pos` of a chain.
#[inline]
fn at(v: &[Point], c: Chain, pos: usize) -> Point {
    let i = c.start + pos;
    v[if i >= v.len() { i - v.len() } else { i }]
}

const ORIGIN: Point = Point::new(0.0, 0.0);
const WEST: Point = Point::new(-1.0, 0.0);
const EAST: Point = Point::new(1.0, 0.0);

/// The left chain (top to bottom, strictly descending) and the right chain (bottom
/// to top, strictly ascending) of a counter-clockwise polygon.
fn chains<K: Kernel>(k: K, v: &[Point]) -> (Chain, Chain) {
    let n = v.len();
    let edge = |i: usize| (v[i], v[(i + 1) % n]);
    let top_left = first_edge_past(k, v, (ORIGIN, WEST));
    let bottom_right = first_edge_past(k, v, (ORIGIN, EAST));
    let is_dir = |i: usize, d: Point| {
        let (a, b) = edge(i);
        k.cross(a, b, ORIGIN, d) == Orientation::Collinear && k.dot(a, b, ORIGIN, d) == Sign::Positive
    };
    let before = |i: usize| (i + n - 1) % n;
    let top_right = if is_dir(before(top_left), WEST) {
        before(top_left)
    } else {
        top_left
    };
    let bottom_left = if is_dir(before(bottom_right), EAST) {
        before(bottom_right)
    } else {
        bottom_right
    };
    let span = |from: usize, to: usize| Chain {
        start: from,
        len: (to + n - from) % n + 1,
    };
    (span(top_left, bottom_left), span(bottom_right, top_right))
}

/// The start of the first edge whose direction, measured counter-clockwise from
/// edge 0, lies strictly beyond `target`: a binary search over the monotone
/// sequence of edge directions. Returns 0 when no edge does (the wrap-around).
fn first_edge_past<K: Kernel>(k: K, v: &[Point], target: (Point, Point)) -> usize {
    let n = v.len();
    let base = (v[0], v[1]);
    let (mut lo, mut hi) = (0, n);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if turn_gt(k, base, (v[mid], v[(mid + 1) % n]), target) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo % n
}

/// Whether direction `a` is turned further counter-clockwise from `base` than `c`,
/// with turns measured in [0, 2π).
pub(super) fn turn_gt<K: Kernel>(k: K, base: (Point, Point), a: (Point, Point), c: (Point, Point)) -> bool {
    let class = |d: (Point, Point)| match k.cross(base.0, base.1, d.0, d.1) {
        Orientation::Ccw => 1,
        Orientation::Cw => 3,
        Orientation::Collinear => {
            if k.dot(base.0, base.1, d.0, d.1) == Sign::Positive {
                0
            } else {
                2
            }
        }
    };
    let (ca, cc) = (class(a), class(c));
    if ca != cc {
        ca > cc
    } else {
        (ca == 1 || ca == 3) && k.cross(c.0, c.1, a.0, a.1) == Orientation::Ccw
    }
}

/// Which chain a vertex bounding the y-interval belongs to.
#[derive(Clone, Copy)]
enum Side {
    Left,
    Right,
}

/// Whether the region right of left chain `l` (of polygon `lv`) meets the region
/// left of right chain `r` (of polygon `rv`); see step 4 of the module docs.
fn pair_meets<K: Kernel, P: Probe>(
    k: K,
    lv: &[Point],
    l: Chain,
    rv: &[Point],
    r: Chain,
    probe: &mut P,
) -> bool {
    let lp = |i: usize| at(lv, l, i);
    let rp = |j: usize| at(rv, r, j);
    // Left positions i0..=i1 descend from top to bottom; right j0..=j1 ascend.
    let (mut i0, mut i1, mut j0, mut j1) = (0, l.len - 1, 0, r.len - 1);
    let mut lo = if lp(i1).y >= rp(j0).y {
        (Side::Left, lp(i1))
    } else {
        (Side::Right, rp(j0))
    };
    let mut hi = if lp(i0).y <= rp(j1).y {
        (Side::Left, lp(i0))
    } else {
        (Side::Right, rp(j1))
    };
    if lo.1.y > hi.1.y {
        return false;
    }
    let test = |(side, w): (Side, Point), i0: usize, i1: usize, j0: usize, j1: usize| match side {
        Side::Left => inside_right_chain(k, &rp, j0, j1, w),
        Side::Right => inside_left_chain(k, &lp, i0, i1, w),
    };
    loop {
        if lo.1.y >= hi.1.y {
            return test(lo, i0, i1, j0, j1);
        }
        let (le, re) = (i1 - i0, j1 - j0);
        if le <= 1 && re <= 1 {
            return test(lo, i0, i1, j0, j1) || test(hi, i0, i1, j0, j1);
        }
        if le == 0 || re == 0 {
            // Only reachable with an inconsistent kernel: a chain that does not cover I.
            return test(lo, i0, i1, j0, j1) || test(hi, i0, i1, j0, j1);
        }
        probe.iteration();
        let ke = i0 + le / 2; // e = (lp(ke), lp(ke + 1)), top to bottom
        let kf = j0 + re / 2; // f = (rp(kf), rp(kf + 1)), bottom to top
        let (e_top, e_bot) = (lp(ke), lp(ke + 1));
        let (f_bot, f_top) = (rp(kf), rp(kf + 1));
        if k.cross(f_bot, f_top, e_bot, e_top) != Orientation::Cw {
            // s_R ≥ s_L: g is non-decreasing below min(top(e), top(f)).
            if e_top.y <= f_top.y {
                if e_top.y >= hi.1.y {
                    return test(hi, i0, i1, j0, j1);
                }
                i1 = ke;
                if e_top.y > lo.1.y {
                    lo = (Side::Left, e_top);
                }
            } else {
                if f_top.y >= hi.1.y {
                    return test(hi, i0, i1, j0, j1);
                }
                j0 = kf + 1;
                if f_top.y > lo.1.y {
                    lo = (Side::Right, f_top);
                }
            }
        } else if e_bot.y >= f_bot.y {
            // s_R < s_L: g is decreasing above max(bottom(e), bottom(f)).
            if e_bot.y <= lo.1.y {
                return test(lo, i0, i1, j0, j1);
            }
            i0 = ke + 1;
            if e_bot.y < hi.1.y {
                hi = (Side::Left, e_bot);
            }
        } else {
            if f_bot.y <= lo.1.y {
                return test(lo, i0, i1, j0, j1);
            }
            j1 = kf;
            if f_bot.y < hi.1.y {
                hi = (Side::Right, f_bot);
            }
        }
    }
}

/// Whether `w` lies on or left of the ascending right chain (positions `j0..=j1`) at
/// the height of `w`.
fn inside_right_chain<K: Kernel>(k: K, rp: &impl Fn(usize) -> Point, j0: usize, j1: usize, w: Point) -> bool {
    // Last position with y ≤ w.y (clamped to the range).
    let (mut lo, mut hi) = (j0, j1);
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        if rp(mid).y <= w.y {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    let a = rp(lo);
    if a.y == w.y || lo == j1 {
        return w.x <= a.x;
    }
    k.orient(a, rp(lo + 1), w) != Orientation::Cw
}

/// Whether `w` lies on or right of the descending left chain (positions `i0..=i1`)
/// at the height of `w`.
fn inside_left_chain<K: Kernel>(k: K, lp: &impl Fn(usize) -> Point, i0: usize, i1: usize, w: Point) -> bool {
    // Last position with y ≥ w.y (clamped to the range).
    let (mut lo, mut hi) = (i0, i1);
    while lo < hi {
        let mid = lo + (hi - lo).div_ceil(2);
        if lp(mid).y >= w.y {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    let a = lp(lo);
    if a.y == w.y || lo == i1 {
        return a.x <= w.x;
    }
    k.orient(a, lp(lo + 1), w) != Orientation::Cw
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Exact;

    fn poly(pts: &[[f64; 2]]) -> ConvexPolygon {
        ConvexPolygon::new(pts.iter().copied()).unwrap()
    }

    #[test]
    fn chains_with_horizontal_top_and_bottom() {
        // A square starting at every vertex: top-left is (0,2), bottom-right (2,0).
        let sq = [[0., 0.], [2., 0.], [2., 2.], [0., 2.]];
        for s in 0..4 {
            let pts: Vec<[f64; 2]> = (0..4).map(|i| sq[(s + i) % 4]).collect();
            let p = poly(&pts);
            let v = p.vertices();
            let (l, r) = chains(Exact, v);
            assert_eq!(
                (at(v, l, 0), at(v, l, l.len - 1)),
                (Point::new(0., 2.), Point::new(0., 0.))
            );
            assert_eq!(
                (at(v, r, 0), at(v, r, r.len - 1)),
                (Point::new(2., 0.), Point::new(2., 2.))
            );
            assert_eq!((l.len, r.len), (2, 2));
        }
        // A diamond: single top and bottom vertices shared by both chains.
        let d = poly(&[[0., -1.], [1., 0.], [0., 1.], [-1., 0.]]);
        let (l, r) = chains(Exact, d.vertices());
        assert_eq!((l.len, r.len), (3, 3));
        assert_eq!(at(d.vertices(), l, 0), Point::new(0., 1.));
        assert_eq!(at(d.vertices(), r, 0), Point::new(0., -1.));
    }

    #[test]
    fn hand_cases() {
        let sq = poly(&[[0., 0.], [2., 0.], [2., 2.], [0., 2.]]);
        let cases: &[(&[[f64; 2]], bool)] = &[
            (&[[1., 1.], [1.5, 1.], [1., 1.5]], true),
            (&[[-1., -1.], [3., -1.], [3., 3.], [-1., 3.]], true),
            (&[[2., 2.], [3., 2.], [3., 3.]], true),
            (&[[2., 0.5], [3., 0.], [3., 1.]], true),
            (&[[2., 0.], [3., 0.], [3., 2.], [2., 2.]], true),
            (&[[0., 2.], [2., 2.], [1., 3.]], true), // shared horizontal top edge
            (&[[0., 2.5], [2., 2.5], [1., 3.]], false),
            (&[[2.5, 0.], [3., 0.], [3., 2.]], false),
            (&[[3., 3.], [4., 3.], [4., 4.]], false),
            (&[[1.5, 3.], [3., 1.5], [3., 3.]], false),
        ];
        for (q, want) in cases {
            let q = poly(q);
            assert_eq!(Dobkin.intersects(&sq, &q), *want, "{q:?}");
            assert_eq!(Dobkin.intersects(&q, &sq), *want, "{q:?}");
        }
    }
}
