//! polysect: dynamic convex polygons with sublinear intersection queries.
#![forbid(unsafe_code)]

#[doc(hidden)]
pub mod fuzzing;
pub mod generate;
pub mod intersect;
pub mod jsonl;
pub mod kernel;
pub mod polygon;

pub use kernel::{Exact, Fast, Kernel, Orientation, Point, Precision, Sign};

pub use polygon::{ConvexPolygon, EditError, LinkedPolygon, PolygonError, VertexId};
