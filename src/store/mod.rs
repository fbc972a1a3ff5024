//! The dynamic polygon store: a [`Scene`] of editable convex polygons that plans each
//! intersection query.
//!
//! # Model only what the queries need
//! Every polygon lives as a [`LinkedPolygon`](crate::LinkedPolygon): O(1) validated
//! edits, O(1) sampling. An array snapshot ([`ConvexPolygon`](crate::ConvexPolygon)) is
//! built only when the planner decides conversion pays, kept while the polygon is
//! unchanged, and dropped at its first edit (a per-polygon version counter), so memory
//! is one linked polygon per polygon plus a snapshot only for polygons that are queried
//! more than they are edited.
//!
//! # The planner
//! `intersects(a, b)`:
//! 1. Bounding boxes first (exact comparisons): disjoint boxes answer `false`.
//! 2. Both snapshots valid: an O(log n) array test on the snapshots.
//! 3. Otherwise, for each polygon without a snapshot: convert it now if it is small
//!    (n at most the calibrated crossover, below which converting plus an array test
//!    is cheaper than one sampled query), or if the sampled queries it has taken part
//!    in since its last edit have already cost as much as converting it would
//!    (ski rental: pay rent until it sums to the purchase price, then buy; never worse
//!    than twice the cost of the best offline choice). If both now have snapshots, step 2;
//!    else the sublinear sampled test on the linked polygons, charging each unconverted
//!    polygon its estimated share of that query as rent.
//!
//! The cost estimates come from a [`CostModel`]: a measured default, or
//! [`Scene::calibrate`] on the user's machine.
//!
//! # Bounding boxes under edits
//! Growing a box is O(1) per edit. A removal or an inward move of a vertex on the box
//! may shrink the true box; the stored box is then kept (it still contains the polygon,
//! so the broad phase stays conservative and correct) and marked loose; it becomes
//! tight again whenever the polygon is walked anyway (at conversion).
//!
//! # Broad phase
//! An R-tree (`rstar`) over the bounding boxes, updated lazily: edits mark polygons
//! dirty, and the next scene query re-inserts the dirty boxes (or bulk-loads the tree
//! when most of them are dirty).
//!
//! # Parallel batches
//! [`Scene::intersects_batch`] and [`Scene::intersecting_pairs`] plan sequentially,
//! convert the chosen snapshots in parallel, then answer the pairs in parallel on
//! read-only polygons (per-thread workspaces, a per-pair seeded RNG). Results come back
//! in input order (pairs sorted by id), independent of the thread count.

mod broad;
mod interop;
mod planner;
mod scene;
pub mod workload;

pub use broad::BoundingBox;
pub use planner::{CostModel, PlannerStats, Strategy};
pub use scene::{PolygonId, Scene, SceneError};
