//! polysect in DataFusion: exact convex-polygon intersection over WKB columns, and a
//! spatial join planned as a partitioned hash join.
//!
//! - [`wkb`]: WKB polygons to and from [`polysect::ConvexPolygon`].
//! - [`udf`]: `polysect_intersects(a, b)` and the grid functions the join is made of;
//!   [`udf::register`] adds them to a `SessionContext` for SQL.
//! - [`join`]: [`join::spatial_join`], "left JOIN right ON polysect_intersects", as a
//!   grid partitioning, an equi-join on cell ids, a box filter, one reference cell per
//!   pair and the exact test; never a nested loop.
//! - [`grid`]: the grid and why its rounding cannot lose a pair.
//! - [`tables`]: seeded tables of random convex polygons (GeoParquet).
//!
//! ```
//! # #[tokio::main(flavor = "current_thread")] async fn main() -> Result<(), Box<dyn std::error::Error>> {
//! use datafusion::prelude::*;
//! use polysect::ConvexPolygon;
//! use polysect_datafusion::udf::{OnInvalid, register};
//! use polysect_datafusion::wkb::polygon_to_wkb;
//! let ctx = SessionContext::new();
//! register(&ctx, OnInvalid::Error);
//! // Two unit squares sharing the edge x = 1: touching counts.
//! let hex = |p: &ConvexPolygon| polygon_to_wkb(p).iter().map(|b| format!("{b:02X}")).collect::<String>();
//! let a = ConvexPolygon::new([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])?;
//! let b = ConvexPolygon::new([[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]])?;
//! let sql = format!("SELECT polysect_intersects(X'{}', X'{}') AS hit", hex(&a), hex(&b));
//! let batches = ctx.sql(&sql).await?.collect().await?;
//! let hit = batches[0].column(0).as_any().downcast_ref::<datafusion::arrow::array::BooleanArray>().unwrap();
//! assert!(hit.value(0));
//! # Ok(()) }
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod grid;
pub mod join;
pub mod tables;
pub mod udf;
pub mod wkb;
