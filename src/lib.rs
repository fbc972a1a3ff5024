//! polysect: dynamic convex polygons with sublinear intersection queries.
#![forbid(unsafe_code)]

pub mod crossings;
pub mod experiments;
pub mod generate;
pub mod intersect;
pub mod jsonl;
pub mod kernel;
pub mod lp;
pub mod polygon;

pub use kernel::{Exact, Fast, Kernel, Orientation, Point, Precision, Sign};

pub use polygon::{ConvexPolygon, EditError, LinkedPolygon, PolygonError, VertexId};
pub use polygon::{SimplePolygon, SimplePolygonError};
