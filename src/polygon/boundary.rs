//! Cyclic access to a convex polygon's boundary, shared by every search that walks it:
//! the same code reads a vertex array and a [`LinkedPolygon`]. O(1) per step; no
//! arithmetic on coordinates.

use super::LinkedPolygon;
use crate::kernel::Point;

/// Cyclic access to a convex polygon's boundary: a slice of counter-clockwise vertices
/// (indices mod n) or a [`LinkedPolygon`] (arena positions, which are exactly `0..len`).
pub(crate) trait Boundary {
    fn count(&self) -> usize;
    fn at(&self, v: usize) -> Point;
    fn next(&self, v: usize) -> usize;
    fn prev(&self, v: usize) -> usize;
}

impl Boundary for [Point] {
    #[inline]
    fn count(&self) -> usize {
        self.len()
    }
    #[inline]
    fn at(&self, v: usize) -> Point {
        self[v]
    }
    #[inline]
    fn next(&self, v: usize) -> usize {
        if v + 1 == self.len() { 0 } else { v + 1 }
    }
    #[inline]
    fn prev(&self, v: usize) -> usize {
        if v == 0 { self.len() - 1 } else { v - 1 }
    }
}

impl Boundary for LinkedPolygon {
    #[inline]
    fn count(&self) -> usize {
        self.len()
    }
    #[inline]
    fn at(&self, v: usize) -> Point {
        self.point_at(v)
    }
    #[inline]
    fn next(&self, v: usize) -> usize {
        self.next_at(v)
    }
    #[inline]
    fn prev(&self, v: usize) -> usize {
        self.prev_at(v)
    }
}
