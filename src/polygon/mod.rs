//! Polygon types: validated convex polygons as sorted arrays ([`ConvexPolygon`]),
//! editable convex polygons as arena-backed doubly linked lists ([`LinkedPolygon`]),
//! simple (possibly non-convex) polygons in either orientation ([`SimplePolygon`],
//! validated by an exact O(n log n) sweep), the convex hull of a point set
//! ([`convex_hull`] by monotone chain, [`graham_scan`], both behind [`hull_vertices`]),
//! rotating calipers ([`calipers`]: diameter, width, least-area rectangle), and the
//! O(log n) line, ray and segment queries on a convex polygon
//! ([`ConvexPolygon::line_chord`] and its siblings). Everyday queries on one polygon
//! (point containment, the extreme vertex in a direction, area, centroid) are methods
//! of these types, indexed in [`queries`]. Common shapes have constructors on both
//! convex types: [`ConvexPolygon::rectangle`], [`ConvexPolygon::oriented_rectangle`],
//! [`ConvexPolygon::regular`], [`ConvexPolygon::circle`] and [`ConvexPolygon::hull_of`]
//! (invalid parameters are a [`PolygonError::BadParameter`]).
//!
//! # Orientation and cleaning
//! Input may come clockwise or counter-clockwise, from any start vertex. The two
//! convex types store the boundary **counter-clockwise** with strictly convex turns:
//! consecutive duplicates, a repeated closing vertex and collinear middle vertices
//! are removed on construction (the polygon is the region they bound). Every
//! decision is taken with the exact kernel, so cleaning never depends on rounding.
//!
//! # Errors
//! Invalid input is a [`PolygonError`] naming the input vertex index and what is wrong.

mod boundary;
pub mod calipers;
mod convex;
mod error;
mod graham;
mod hull;
mod line_query;
mod linked;
pub mod queries;
mod shapes;
mod simple;
mod vertices;

pub(crate) use boundary::Boundary;
pub use convex::ConvexPolygon;
pub(crate) use convex::box_of;
pub use error::{EditError, PolygonError};
#[cfg(not(feature = "instrument"))]
pub(crate) use graham::angular_order;
pub use graham::graham_scan;
#[cfg(feature = "instrument")]
pub use graham::{angular_order, pivot_index};
pub use hull::{HullAlgorithm, convex_hull, hull_vertices};
#[cfg(feature = "instrument")]
pub use line_query::line_chord_linear;
pub use line_query::{Chord, ChordEnd, LineQueryError};
pub(crate) use linked::Identity;
pub use linked::sampling::SampleWorkspace;
pub(crate) use linked::turn_margin;
pub use linked::{LinkedPolygon, VertexId};
pub use simple::{SimplePolygon, SimplePolygonError};
pub(crate) use vertices::{PosedVertices, Vertices};

use crate::kernel::{Exact, Kernel, Orientation, Point};

/// Why a vertex list fails the checks shared by every polygon type.
pub(crate) enum Prefilter {
    NonFinite { index: usize },
    TooFew { distinct: usize },
    AllCollinear,
}

/// An index into an input vertex list, as validation stores it: `u32` for lists of up
/// to 2^32 − 1 vertices (4 bytes a vertex while validating), `usize` beyond.
pub(crate) trait InputIndex: Copy {
    fn new(i: usize) -> Self;
    fn get(self) -> usize;
}

impl InputIndex for u32 {
    #[inline]
    fn new(i: usize) -> Self {
        i as u32
    }
    #[inline]
    fn get(self) -> usize {
        self as usize
    }
}

impl InputIndex for usize {
    #[inline]
    fn new(i: usize) -> Self {
        i
    }
    #[inline]
    fn get(self) -> usize {
        self
    }
}

/// The first steps of validating a vertex list, shared by [`ConvexPolygon`] and
/// [`SimplePolygon`]: non-finite coordinates are refused; consecutive duplicates and a
/// repeated closing vertex are dropped (each kept vertex keeps its input index); fewer
/// than three distinct vertices, or all of them on one line (exact kernel), are refused.
/// Returns the input indices of the distinct vertices.
pub(crate) fn distinct_indices<I: InputIndex>(points: &[Point]) -> Result<Vec<I>, Prefilter> {
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(Prefilter::NonFinite { index });
    }
    let at = |i: I| points[i.get()];
    let mut v: Vec<I> = Vec::with_capacity(points.len());
    for (i, &p) in points.iter().enumerate() {
        if v.last().is_none_or(|&q| at(q) != p) {
            v.push(I::new(i));
        }
    }
    while v.len() > 1 && at(v[v.len() - 1]) == at(v[0]) {
        v.pop();
    }
    if v.len() < 3 {
        return Err(Prefilter::TooFew { distinct: v.len() });
    }
    if (2..v.len()).all(|i| Exact.orient(at(v[0]), at(v[1]), at(v[i])) == Orientation::Collinear) {
        return Err(Prefilter::AllCollinear);
    }
    Ok(v)
}
