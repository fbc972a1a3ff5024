//! Times `spatial_join` against the core `Scene` (both tables inserted, then
//! `intersecting_pairs`) on the same generated tables, in one run, and checks that the
//! pair sets agree.
//!
//! `cargo run --release -p polysect-datafusion --example join_vs_scene -- ROWS VERTICES [RUNS]`

use datafusion::arrow::array::AsArray;
use datafusion::arrow::datatypes::Int64Type;
use datafusion::prelude::{SessionContext, col};
use polysect::LinkedPolygon;
use polysect::store::Scene;
use polysect_datafusion::join::{JoinOptions, choose_grid, spatial_join};
use polysect_datafusion::tables::{self, Layout, TableSpec};
use std::collections::BTreeSet;
use std::time::Instant;

#[tokio::main]
async fn main() -> datafusion::error::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let rows: usize = args.first().and_then(|a| a.parse().ok()).unwrap_or(100_000);
    let vertices: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(64);
    let runs: usize = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(3);
    let spec = |seed| TableSpec {
        rows,
        vertices,
        seed,
        partners: 2.0,
        layout: Layout::Uniform,
    };
    let (a, b) = (tables::polygons(&spec(1)), tables::polygons(&spec(2)));
    let batches = |p: &[polysect::ConvexPolygon]| -> datafusion::error::Result<Vec<_>> {
        p.chunks(8192)
            .enumerate()
            .map(|(i, c)| tables::batch(c, (i * 8192) as i64))
            .collect()
    };
    let (ba, bb) = (batches(&a)?, batches(&b)?);
    println!("{rows} x {rows} polygons of {vertices} vertices, {runs} runs each, interleaved");
    for run in 0..runs {
        // The join, from Arrow batches in memory (WKB), grid chosen from the data.
        let ctx = SessionContext::new();
        let started = Instant::now();
        let (l, r) = (ctx.read_batches(ba.clone())?, ctx.read_batches(bb.clone())?);
        let grid = choose_grid(&l, "geometry", &r, "geometry", Default::default()).await?;
        let grid_time = started.elapsed();
        let options = JoinOptions {
            grid: Some(grid),
            ..JoinOptions::default()
        };
        let df = spatial_join(l, "geometry", r, "geometry", &options).await?;
        let out = df
            .select(vec![col("left.id"), col("right.id")])?
            .collect()
            .await?;
        let join_time = started.elapsed();
        let mut pairs = BTreeSet::new();
        for bt in &out {
            let (x, y) = (
                bt.column(0).as_primitive::<Int64Type>(),
                bt.column(1).as_primitive::<Int64Type>(),
            );
            pairs.extend((0..bt.num_rows()).map(|i| (x.value(i), y.value(i))));
        }

        // The Scene, from the polygons.
        let started = Instant::now();
        let mut scene = Scene::new();
        let ids_a: Vec<_> = a
            .iter()
            .map(|p| scene.insert(LinkedPolygon::from_convex(p)))
            .collect();
        let ids_b: Vec<_> = b
            .iter()
            .map(|p| scene.insert(LinkedPolygon::from_convex(p)))
            .collect();
        let inserted = started.elapsed();
        let found = scene.intersecting_pairs();
        let scene_time = started.elapsed();
        let index: std::collections::HashMap<_, _> = ids_a
            .iter()
            .enumerate()
            .map(|(i, id)| (*id, (true, i as i64)))
            .chain(ids_b.iter().enumerate().map(|(i, id)| (*id, (false, i as i64))))
            .collect();
        let reference: BTreeSet<(i64, i64)> = found
            .iter()
            .filter_map(|(x, y)| match (index[x], index[y]) {
                ((true, i), (false, j)) | ((false, j), (true, i)) => Some((i, j)),
                _ => None,
            })
            .collect();
        assert_eq!(pairs, reference, "the join and the scene disagree");
        println!(
            "run {run}: join {:.3} s (grid pass {:.3} s), scene {:.3} s (insert {:.3} s); {} pairs; join/scene = {:.2}; cell {:.3}",
            join_time.as_secs_f64(),
            grid_time.as_secs_f64(),
            scene_time.as_secs_f64(),
            inserted.as_secs_f64(),
            pairs.len(),
            join_time.as_secs_f64() / scene_time.as_secs_f64(),
            grid.cell_size(),
        );
    }
    Ok(())
}
