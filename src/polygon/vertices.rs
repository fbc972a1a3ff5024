//! [`Vertices`]: read access to a convex polygon's vertices by index, counter-clockwise,
//! so that an array algorithm written once reads either a stored array or vertices
//! computed on demand.
//!
//! # Implementations
//! * `[Point]`: the stored array (a [`ConvexPolygon`](super::ConvexPolygon)'s vertices).
//!   [`get`](Vertices::get) is the indexing itself, inlined: an algorithm generic over
//!   `Vertices` compiles on a slice to the code it had when it took `&[Point]`.
//! * [`PosedVertices`]: a shape's array under a [`Pose`], each vertex mapped when it is
//!   read. It is the world polygon a posed scene polygon stands for, without the O(n)
//!   pass that builds it: an O(log n) search reads O(log n) vertices.
//!
//! # Complexity
//! `len` O(1); `get` O(1): an index for a slice, one [`Pose::apply`] (two correctly
//! rounded affine maps, a few dozen floating-point operations) for a posed view.
//! [`with_slice`](Vertices::with_slice) is O(1) for a slice and O(n) for a posed view
//! (it builds the world array), for the rare paths that need a slice.
//!
//! # Precision
//! A posed view's vertex is bit for bit `pose.apply(shape[i])`, the vertex the world
//! array would hold: an algorithm reading the view answers exactly as on that array,
//! and points it reports (certificate vertices) are the world polygon's.

use crate::kernel::{Point, Pose};

/// A convex polygon's vertices, counter-clockwise, read by index.
pub(crate) trait Vertices {
    /// The number of vertices.
    fn len(&self) -> usize;
    /// Vertex `i`, for `i < len()`.
    fn get(&self, i: usize) -> Point;
    /// `f` on the vertices as a slice: the slice itself, or the vertices collected.
    fn with_slice<R>(&self, f: impl FnOnce(&[Point]) -> R) -> R;
}

impl Vertices for [Point] {
    #[inline(always)]
    fn len(&self) -> usize {
        <[Point]>::len(self)
    }

    #[inline(always)]
    fn get(&self, i: usize) -> Point {
        self[i]
    }

    #[inline(always)]
    fn with_slice<R>(&self, f: impl FnOnce(&[Point]) -> R) -> R {
        f(self)
    }
}

/// A shape's vertices under a pose: vertex `i` is `pose.apply(shape[i])`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PosedVertices<'a> {
    shape: &'a [Point],
    pose: Pose,
}

impl<'a> PosedVertices<'a> {
    /// The view of `shape` (counter-clockwise, strictly convex) under `pose`, without
    /// checks: the caller has established that every image is finite and that the
    /// rounded image is strictly convex (the scene does when it accepts a pose), so
    /// that the view is a valid convex polygon.
    pub(crate) fn new_unchecked(shape: &'a [Point], pose: Pose) -> Self {
        PosedVertices { shape, pose }
    }

    /// The world vertices, in order. O(n).
    pub(crate) fn to_points(self) -> Vec<Point> {
        (0..self.shape.len()).map(|i| self.get(i)).collect()
    }
}

impl Vertices for PosedVertices<'_> {
    #[inline(always)]
    fn len(&self) -> usize {
        self.shape.len()
    }

    #[inline]
    fn get(&self, i: usize) -> Point {
        self.pose
            .apply(self.shape[i])
            .expect("a posed view's images are finite (new_unchecked's contract)")
    }

    fn with_slice<R>(&self, f: impl FnOnce(&[Point]) -> R) -> R {
        f(&self.to_points())
    }
}

#[cfg(test)]
#[path = "vertices_tests.rs"]
mod tests;
