//! The dynamic polygon store: a [`Scene`] of editable convex polygons that plans each
//! intersection query.
//!
//! # Model only what the queries need
//! Every polygon lives as a [`LinkedPolygon`](crate::LinkedPolygon): O(1) validated
//! edits, O(1) sampling. An array snapshot ([`ConvexPolygon`](crate::ConvexPolygon)) is
//! built only when the planner decides conversion pays, kept while the polygon is
//! unchanged, and dropped at its first edit (a per-polygon version counter), so memory
//! is one linked polygon per polygon plus a snapshot only for polygons that are queried
//! more than they are edited. A translation shifts the snapshot at once and leaves the
//! linked polygon's for its next reader (`lazy.rs`: at most eight wait, applied with the
//! same roundings, so the coordinates are eager translation's bit for bit).
//!
//! # The planner
//! `intersects(a, b)` is a batch of one; `intersects_batch`, `intersecting` and
//! `intersecting_pairs` plan all their pairs together:
//! 1. Bounding boxes first (exact comparisons): disjoint boxes answer `false`.
//! 2. Every polygon without a snapshot is credited, for each planned query it is in,
//!    with what its conversion would save that query: the whole saving (the query's
//!    cost without snapshots, less the array test) when the other polygon has a
//!    snapshot, half of it when neither has one.
//! 3. A polygon is converted when the queries being planned alone pay for its
//!    conversion, or when what its missing snapshot has cost the queries since its
//!    last edit plus their saving reaches the price of converting it, unless the queries expected before its next edit
//!    would not pay for it. Polygons whose partners were just chosen are offered the
//!    other half of the saving once more.
//! 4. Pairs with two snapshots get an array test (the linear one for small pairs,
//!    Barba–Langerman's O(log n) above). The others get the cheaper of two tests on
//!    the linked polygons by the cost tables: the linear walk
//!    ([`LinearLinked`](crate::intersect::LinearLinked)) for small polygons, the
//!    sublinear sampled test (Chazelle–Liu–Magen) for large ones; each unconverted
//!    polygon adds its share of the saving to what its missing snapshot has cost. An
//!    edit drops the snapshot and that sum; a translation keeps both.
//!
//! Charging each polygon what *its* conversion saves is what makes a triangle moved
//! before every query against a large polygon holding its snapshot convert at once
//! (a few hundred nanoseconds) instead of paying a sampled query on the large polygon
//! every time. Planning is O(1) per pair (per-polygon marks), so a batch is planned in
//! linear time.
//!
//! The estimates come from a [`CostModel`]: one table per route (conversion, sampled
//! test, linear walk, array test) over sizes 2^2..2^18, walks priced between
//! boundary-order and shuffled arenas by each polygon's inserts and removals since it
//! was built; a measured default, or [`Scene::calibrate`] on the user's machine.

//! # Bounding boxes under edits
//! Growing a box is O(1) per edit. A removal or an inward move of a vertex on the box
//! may shrink the true box; the stored box is then kept (it still contains the polygon,
//! so the broad phase stays conservative and correct) and marked loose; it becomes
//! tight again whenever the polygon is walked anyway (at conversion).
//!
//! # Broad phase
//! Sort and sweep over the bounding boxes (`broad.rs`), updated lazily: edits mark
//! polygons dirty, and the next scene query re-reads the dirty boxes and repairs the
//! order by insertion sort (or sorts again when most moved far); the last sweep's pairs
//! are reused while nothing changes.
//!
//! # Warm starts across frames
//! [`Scene::intersecting_pairs`] keeps, per candidate pair, what its test learnt (`warm.rs`):
//! a pair separated last frame is first checked against the separating edge it had
//! (vertex handles, the other polygon's deepest vertex hill-climbed along the links),
//! O(1) under coherent motion; only when that fails does the planner's route answer.
//! Memory is O(candidate pairs of the last frame). Off by default (measured: it does not
//! pay where translations keep snapshots and the array test is already cheap;
//! docs/store.md); [`Scene::set_warm_starts`] turns it on.
//!
//! # Queries through `&self`
//! [`Scene::intersects_shared`] and [`Scene::contains_point_shared`] read only what
//! the scene holds and change nothing (`shared.rs`), so one `&Scene` can be queried
//! from several threads; they do not plan, convert or feed the planner's counters.
//! docs/store.md lists what the planned queries change and why.
//!
//! # User data
//! Each polygon carries a `u128` of the caller's ([`Scene::insert_with_user_data`],
//! [`Scene::user_data`], [`Scene::set_user_data`]), kept through edits, translations
//! and poses.
//!
//! # Parallel batches
//! [`Scene::intersects_batch`] and [`Scene::intersecting_pairs`] plan sequentially,
//! convert the chosen snapshots in parallel, then answer the pairs in parallel on
//! read-only polygons (per-thread workspaces, a per-pair seeded RNG). Results come back
//! in input order (pairs sorted by id), independent of the thread count.

mod broad;
mod contact;
mod cost;
#[cfg(feature = "geo-types")]
mod interop;
mod lazy;
mod ordered;
mod planner;
mod query;
mod route;
mod scene;
mod shared;
mod warm;
// The demo's and the benches' workloads: the tool's, not an API to build on.
#[doc(hidden)]
pub mod workload;

pub use crate::kernel::BoundingBox;
pub use cost::{COST_SIZES, CostModel, PlannerStats, Strategy};
// Warm-start counts: for experiments.
pub use scene::{PolygonId, Scene, SceneError};
#[cfg(feature = "instrument")]
pub use warm::WarmStats;
