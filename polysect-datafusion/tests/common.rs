//! Helpers shared by the integration tests: tables from polygons, and the reference
//! answer from polysect's `Scene`.
#![allow(dead_code)]

use datafusion::arrow::array::{AsArray, RecordBatch};
use datafusion::arrow::datatypes::Int64Type;
use datafusion::prelude::{DataFrame, SessionConfig, SessionContext, col};
use polysect::store::Scene;
use polysect::{ConvexPolygon, LinkedPolygon};
use polysect_datafusion::join::{JoinOptions, spatial_join};
use polysect_datafusion::tables;
use std::collections::{BTreeSet, HashMap};

/// A context with `partitions` target partitions and small batches, so that plans
/// really repartition and functions see many batches.
pub fn context(partitions: usize, batch_size: usize) -> SessionContext {
    let config = SessionConfig::new()
        .with_target_partitions(partitions)
        .with_batch_size(batch_size);
    SessionContext::new_with_config(config)
}

/// A table `id, geometry` of these polygons, ids 0, 1, ... (split into batches of
/// `chunk` rows).
pub fn table(ctx: &SessionContext, polygons: &[ConvexPolygon], chunk: usize) -> DataFrame {
    let batches: Vec<RecordBatch> = polygons
        .chunks(chunk.max(1))
        .enumerate()
        .map(|(i, c)| tables::batch(c, (i * chunk.max(1)) as i64).unwrap())
        .collect();
    if batches.is_empty() {
        return ctx.read_batch(tables::batch(&[], 0).unwrap()).unwrap();
    }
    ctx.read_batches(batches).unwrap()
}

/// The pairs `(left index, right index)` that intersect, by the core `Scene` with
/// both tables inserted.
pub fn scene_pairs(left: &[ConvexPolygon], right: &[ConvexPolygon]) -> BTreeSet<(i64, i64)> {
    let mut scene = Scene::new();
    let mut side = HashMap::new();
    for (i, p) in left.iter().enumerate() {
        side.insert(scene.insert(LinkedPolygon::from_convex(p)), (true, i as i64));
    }
    for (i, p) in right.iter().enumerate() {
        side.insert(scene.insert(LinkedPolygon::from_convex(p)), (false, i as i64));
    }
    let mut out = BTreeSet::new();
    for (a, b) in scene.intersecting_pairs() {
        match (side[&a], side[&b]) {
            ((true, i), (false, j)) | ((false, j), (true, i)) => {
                out.insert((i, j));
            }
            _ => {}
        }
    }
    out
}

/// The join's `(left.id, right.id)` rows, in order of arrival.
pub async fn collect_pairs(df: DataFrame) -> datafusion::error::Result<Vec<(i64, i64)>> {
    let batches = df
        .select(vec![col("left.id"), col("right.id")])?
        .collect()
        .await?;
    let mut out = Vec::new();
    for b in &batches {
        let (l, r) = (
            b.column(0).as_primitive::<Int64Type>(),
            b.column(1).as_primitive::<Int64Type>(),
        );
        out.extend((0..b.num_rows()).map(|i| (l.value(i), r.value(i))));
    }
    Ok(out)
}

/// Runs the join and checks that no pair comes twice; returns the pair set.
pub async fn join_pairs(
    ctx: &SessionContext,
    left: &[ConvexPolygon],
    right: &[ConvexPolygon],
    options: &JoinOptions,
) -> BTreeSet<(i64, i64)> {
    let (l, r) = (table(ctx, left, 37), table(ctx, right, 53));
    let df = spatial_join(l, "geometry", r, "geometry", options).await.unwrap();
    let rows = collect_pairs(df).await.unwrap();
    let set: BTreeSet<(i64, i64)> = rows.iter().copied().collect();
    assert_eq!(set.len(), rows.len(), "a pair was reported more than once");
    set
}
