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
//! 3. Otherwise, each polygon without a snapshot is converted now if the sampled
//!    queries it has taken part in since its last edit have already cost as much as
//!    converting it would (ski rental: pay rent until it sums to the purchase price, then
//!    buy; never more than twice the cost of the best choice made knowing the future).
//!    If both now have snapshots, step 2; else the sublinear sampled test
//!    (Chazelle–Liu–Magen) on the linked polygons, charging each unconverted polygon the
//!    estimated cost of that query as rent. An edit drops the snapshot and clears the rent.
//!
//! The estimates come from a [`CostModel`]: conversion costs `c_convert · n`, a sampled
//! query `c_sampled · √n` for the larger polygon; a measured default, or
//! [`Scene::calibrate`] on the user's machine. A polygon of n vertices is therefore
//! converted after about `(c_convert / c_sampled) · √n` sampled queries without an edit
//! (about 95 at n = 2^18 with the default model): small polygons almost at once, large
//! ones only when they are queried far more often than edited. The model's `crossover`
//! (the size below which one conversion plus an array test beats one sampled query) is
//! measured and reported; the rule does not need it separately. We first also converted
//! every polygon below the crossover at once; on the demo's workloads that made the
//! planner 1.4× slower than always sampling, because small polygons were edited again
//! before their snapshots paid off (docs/store.md).

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
#[cfg(feature = "geo-types")]
mod interop;
mod planner;
mod scene;
pub mod workload;

pub use broad::BoundingBox;
pub use planner::{CostModel, PlannerStats, Strategy};
pub use scene::{PolygonId, Scene, SceneError};
