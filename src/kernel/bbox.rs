//! [`BoundingBox`]: the closed axis-aligned box of a point set, the one box type of
//! the crate (polygons, scenes, the kernels' error bounds). Built and compared by
//! comparisons of input coordinates only, so it is exact.

use super::Point;

/// A closed axis-aligned box. `overlaps` and `grow` use comparisons only (exact).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BoundingBox {
    /// The lower-left corner: the smallest x and the smallest y.
    pub min: Point,
    /// The upper-right corner: the largest x and the largest y.
    pub max: Point,
}

impl BoundingBox {
    /// The box with corners `min` (smallest x and y) and `max` (largest x and y); nothing
    /// is checked.
    #[inline]
    pub const fn new(min: Point, max: Point) -> BoundingBox {
        BoundingBox { min, max }
    }

    /// True when the closed box contains `p`, boundary included. Exact (comparisons).
    #[inline]
    pub fn contains_point(&self, p: impl Into<Point>) -> bool {
        let p = p.into();
        self.min.x <= p.x && p.x <= self.max.x && self.min.y <= p.y && p.y <= self.max.y
    }

    /// The box of a non-empty point set; `None` for an empty one. O(n).
    ///
    /// ```
    /// use polysect::{BoundingBox, Point};
    /// let b = BoundingBox::of([Point::new(1.0, 5.0), Point::new(-2.0, 3.0)]).unwrap();
    /// assert_eq!((b.min, b.max), (Point::new(-2.0, 3.0), Point::new(1.0, 5.0)));
    /// assert!(b.contains_point([0.0, 5.0]) && !b.contains_point([0.0, 5.5]));
    /// assert!(BoundingBox::of([]).is_none());
    /// ```
    pub fn of(points: impl IntoIterator<Item = Point>) -> Option<BoundingBox> {
        let mut it = points.into_iter();
        let first = it.next()?;
        let mut b = BoundingBox {
            min: first,
            max: first,
        };
        for p in it {
            b.grow(p);
        }
        Some(b)
    }

    /// Extends the box to contain `p`.
    #[inline]
    pub(crate) fn grow(&mut self, p: Point) {
        self.min.x = self.min.x.min(p.x);
        self.min.y = self.min.y.min(p.y);
        self.max.x = self.max.x.max(p.x);
        self.max.y = self.max.y.max(p.y);
    }

    /// True when the closed boxes share a point.
    #[inline]
    pub fn overlaps(&self, o: &BoundingBox) -> bool {
        self.min.x <= o.max.x && o.min.x <= self.max.x && self.min.y <= o.max.y && o.min.y <= self.max.y
    }

    /// True when `p` lies on the box's boundary (removing or moving it may shrink the box).
    #[inline]
    pub(crate) fn touches_boundary(&self, p: Point) -> bool {
        p.x == self.min.x || p.x == self.max.x || p.y == self.min.y || p.y == self.max.y
    }
}
