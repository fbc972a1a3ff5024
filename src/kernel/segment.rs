//! Closed segment–segment tests without division (orientation and bounding box): orientation signs
//! decide whether the segments straddle each other's lines, and exact coordinate
//! comparisons decide the collinear cases.
//!
//! # Degeneracies
//! Segments are closed: sharing an endpoint, an endpoint on the other segment and
//! collinear overlap all count as intersection. A segment whose endpoints coincide
//! is a point and is handled like any other segment.

use super::{Kernel, Orientation, Point};

/// How two closed segments meet.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SegmentContact {
    /// No common point.
    Disjoint,
    /// The interiors cross at a single point that is an endpoint of neither segment.
    Crossing,
    /// A single common point that is an endpoint of at least one segment.
    Touching,
    /// Collinear with a common part of positive length.
    Overlapping,
}

impl SegmentContact {
    /// True unless `Disjoint`.
    #[inline]
    pub fn meets(self) -> bool {
        self != SegmentContact::Disjoint
    }
}

/// True when `p`, known to be collinear with `a` and `b`, lies on the closed segment ab.
/// Exact: only coordinate comparisons.
#[inline]
fn within_box(a: Point, b: Point, p: Point) -> bool {
    p.x >= a.x.min(b.x) && p.x <= a.x.max(b.x) && p.y >= a.y.min(b.y) && p.y <= a.y.max(b.y)
}

/// True when `p` lies on the closed segment ab.
#[inline]
pub fn point_on_segment<K: Kernel>(k: K, a: Point, b: Point, p: Point) -> bool {
    k.orient(a, b, p) == Orientation::Collinear && within_box(a, b, p)
}

/// True when the closed segments p1p2 and q1q2 have a common point.
#[inline]
pub fn segments_intersect<K: Kernel>(k: K, p1: Point, p2: Point, q1: Point, q2: Point) -> bool {
    segment_contact(k, p1, p2, q1, q2).meets()
}

/// Classifies how the closed segments p1p2 and q1q2 meet.
pub fn segment_contact<K: Kernel>(k: K, p1: Point, p2: Point, q1: Point, q2: Point) -> SegmentContact {
    use Orientation::{Collinear, Cw};
    let o1 = k.orient(p1, p2, q1);
    let o2 = k.orient(p1, p2, q2);
    if o1 == o2 && o1 != Collinear {
        return SegmentContact::Disjoint;
    }
    let o3 = k.orient(q1, q2, p1);
    let o4 = k.orient(q1, q2, p2);
    if o3 == o4 && o3 != Collinear {
        return SegmentContact::Disjoint;
    }
    if o1 == Collinear && o2 == Collinear && o3 == Collinear && o4 == Collinear {
        return collinear_contact(p1, p2, q1, q2);
    }
    // Not all collinear: the lines meet in at most one point.
    let straddle =
        |a: Orientation, b: Orientation| a != Collinear && b != Collinear && (a == Cw) != (b == Cw);
    if straddle(o1, o2) && straddle(o3, o4) {
        return SegmentContact::Crossing;
    }
    let touches = (o1 == Collinear && within_box(p1, p2, q1))
        || (o2 == Collinear && within_box(p1, p2, q2))
        || (o3 == Collinear && within_box(q1, q2, p1))
        || (o4 == Collinear && within_box(q1, q2, p2));
    if touches {
        SegmentContact::Touching
    } else {
        SegmentContact::Disjoint
    }
}

/// Both segments lie on one line (or are points on it): compare along the line.
fn collinear_contact(p1: Point, p2: Point, q1: Point, q2: Point) -> SegmentContact {
    let (pa, pb) = if p1.lex_cmp(p2).is_le() {
        (p1, p2)
    } else {
        (p2, p1)
    };
    let (qa, qb) = if q1.lex_cmp(q2).is_le() {
        (q1, q2)
    } else {
        (q2, q1)
    };
    // Along a line, lexicographic order is the order of the points on it.
    let lo = if pa.lex_cmp(qa).is_ge() { pa } else { qa };
    let hi = if pb.lex_cmp(qb).is_le() { pb } else { qb };
    match lo.lex_cmp(hi) {
        std::cmp::Ordering::Greater => SegmentContact::Disjoint,
        std::cmp::Ordering::Equal => SegmentContact::Touching,
        std::cmp::Ordering::Less => SegmentContact::Overlapping,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::{Exact, Fast};
    use SegmentContact::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    fn contact(a: [f64; 4], b: [f64; 4]) -> SegmentContact {
        let r = segment_contact(Exact, p(a[0], a[1]), p(a[2], a[3]), p(b[0], b[1]), p(b[2], b[3]));
        // Symmetric in the segments and in each segment's direction.
        assert_eq!(
            r,
            segment_contact(Exact, p(b[2], b[3]), p(b[0], b[1]), p(a[0], a[1]), p(a[2], a[3]))
        );
        assert_eq!(
            r,
            segment_contact(Fast, p(a[2], a[3]), p(a[0], a[1]), p(b[0], b[1]), p(b[2], b[3]))
        );
        r
    }

    #[test]
    fn classifies_every_case() {
        assert_eq!(contact([0., 0., 2., 2.], [0., 2., 2., 0.]), Crossing);
        assert_eq!(contact([0., 0., 2., 0.], [1., 0., 1., 5.]), Touching);
        assert_eq!(contact([0., 0., 2., 0.], [2., 0., 3., 1.]), Touching);
        assert_eq!(contact([0., 0., 2., 0.], [1., 1., 3., 1.]), Disjoint);
        assert_eq!(contact([0., 0., 2., 0.], [3., 0., 4., 0.]), Disjoint);
        assert_eq!(contact([0., 0., 2., 0.], [2., 0., 4., 0.]), Touching);
        assert_eq!(contact([0., 0., 2., 0.], [1., 0., 4., 0.]), Overlapping);
        assert_eq!(contact([0., 0., 4., 4.], [1., 1., 2., 2.]), Overlapping);
        assert_eq!(contact([0., 0., 0., 4.], [0., 1., 0., 1.]), Touching);
        assert_eq!(contact([0., 0., 0., 4.], [0., 5., 0., 5.]), Disjoint);
        assert_eq!(contact([1., 1., 1., 1.], [1., 1., 1., 1.]), Touching);
        // The line through q meets p's line beyond p's end.
        assert_eq!(contact([0., 0., 1., 0.], [2., 0., 3., 1.]), Disjoint);
        assert_eq!(contact([0., 0., 1., 0.], [2., -1., 3., 1.]), Disjoint);
    }

    #[test]
    fn one_ulp_gap_is_disjoint_under_the_exact_kernel() {
        let a = p(0.0, 0.0);
        let b = p(1.0, 3.0);
        let c = p(1.0f64.next_up(), 3.0);
        let d = p(5.0, 3.0);
        assert!(segments_intersect(Exact, a, b, b, d));
        assert!(!segments_intersect(Exact, a, b, c, d));
        // Far from the origin the same gap is one ulp of 2^50.
        let o = 2f64.powi(50);
        let (a, b) = (p(o, o), p(o + 4.0, o + 4.0));
        let c = p(o + 2.0, (o + 2.0).next_up());
        assert!(!segments_intersect(Exact, a, b, c, p(o, o + 4.0)));
        assert!(segments_intersect(
            Exact,
            a,
            b,
            p(o + 2.0, o + 2.0),
            p(o, o + 4.0)
        ));
    }
}
