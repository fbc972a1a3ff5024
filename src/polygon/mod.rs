//! Polygon types: validated convex polygons as sorted arrays ([`ConvexPolygon`]),
//! editable convex polygons as arena-backed doubly linked lists ([`LinkedPolygon`]),
//! simple (possibly non-convex) polygons in either orientation ([`SimplePolygon`],
//! validated by an exact O(n log n) sweep), and the convex hull of a point set
//! ([`convex_hull`]).
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

mod convex;
mod error;
mod hull;
mod linked;
mod simple;

pub use convex::ConvexPolygon;
pub use error::{EditError, PolygonError};
pub use hull::convex_hull;
pub use linked::{LinkedPolygon, SampleWorkspace, VertexId};
pub use simple::{SimplePolygon, SimplePolygonError};
