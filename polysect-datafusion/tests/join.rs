//! The spatial join against the core `Scene`'s pair set on seeded random and
//! adversarial tables, under several grids and partition counts.

mod common;

use common::{context, join_pairs, scene_pairs, table};
use datafusion::arrow::array::{BinaryBuilder, Int64Array, RecordBatch};
use datafusion::arrow::datatypes::{DataType, Field, Schema};
use polysect::generate::{Family, Relation, map_pair, pair};
use polysect::rand::rngs::SmallRng;
use polysect::rand::{Rng, SeedableRng};
use polysect::{ConvexPolygon, Point};
use polysect_datafusion::grid::Grid;
use polysect_datafusion::join::{JoinOptions, spatial_join};
use polysect_datafusion::tables::{self, Layout, TableSpec};
use polysect_datafusion::udf::OnInvalid;
use polysect_datafusion::wkb::{polygon_to_wkb, ring_to_wkb};
use std::sync::Arc;

const SEED: u64 = 0x6a6f_696e;

/// Grids that stress the partitioning: chosen from the data, cells much smaller than
/// the polygons (a pair shares many cells and must be kept once), one cell for all,
/// and an origin off the data.
fn grids(polygons: &[ConvexPolygon]) -> Vec<Option<Grid>> {
    let side = polygons
        .iter()
        .map(|p| {
            let b = p.bounding_box();
            (b.max.x * 0.5 - b.min.x * 0.5).max(b.max.y * 0.5 - b.min.y * 0.5)
        })
        .fold(0.0f64, f64::max);
    let mut out = vec![None, Some(Grid::new(f64::MAX, Point::new(0.0, 0.0)).unwrap())];
    if side > 0.0 && side.is_finite() {
        // About 8 cells across the largest polygon: at most ~100 cells per polygon.
        out.push(Some(
            Grid::new(side / 4.0, Point::new(side / 3.0, -side / 7.0)).unwrap(),
        ));
    }
    out
}

async fn check(left: &[ConvexPolygon], right: &[ConvexPolygon], what: &str) -> usize {
    let expected = scene_pairs(left, right);
    let all: Vec<ConvexPolygon> = left.iter().chain(right).cloned().collect();
    for (partitions, batch) in [(1, 8192), (3, 17)] {
        let ctx = context(partitions, batch);
        for grid in grids(&all) {
            let options = JoinOptions {
                grid,
                ..JoinOptions::default()
            };
            let got = join_pairs(&ctx, left, right, &options).await;
            assert_eq!(got, expected, "{what}: partitions {partitions}, grid {grid:?}");
        }
    }
    expected.len()
}

#[tokio::test]
async fn random_tables_match_the_scene() {
    let mut found = 0;
    for (k, layout) in [Layout::Uniform, Layout::Clustered].into_iter().enumerate() {
        for (s, vertices) in [3usize, 8, 40].into_iter().enumerate() {
            let spec = |seed, rows| TableSpec {
                rows,
                vertices,
                seed,
                partners: 2.0,
                layout,
            };
            let seed = SEED + (10 * k + s) as u64;
            let left = tables::polygons(&spec(seed, 150));
            let right = tables::polygons(&spec(seed + 100, 120));
            found += check(&left, &right, &format!("{layout:?}, {vertices} vertices")).await;
        }
    }
    assert!(
        found > 200,
        "the tables should have many intersecting pairs, found {found}"
    );
}

/// Pairs from polysect's adversarial families (shared vertices and edges, a vertex on
/// an edge, overlapping collinear edges, one-ulp gaps, nested), all laid on top of one
/// another so that every pair is also a candidate for every other.
fn family_tables(rng: &mut SmallRng, scale: f64) -> (Vec<ConvexPolygon>, Vec<ConvexPolygon>) {
    let (mut left, mut right) = (Vec::new(), Vec::new());
    for &family in Family::ALL {
        for relation in [Relation::Intersecting, Relation::Disjoint, Relation::Any] {
            for n in [3, 4, 9, 33] {
                let p = pair(family, n, relation, rng);
                // Scaling by a power of two is exact unless it overflows or
                // underflows, which map_pair refuses.
                let Some((a, b)) = map_pair(&p, |v| Point::new(v.x * scale, v.y * scale)) else {
                    continue;
                };
                if rng.random_bool(0.5) {
                    left.push(a);
                    right.push(b);
                } else {
                    left.push(b);
                    right.push(a);
                }
            }
        }
    }
    (left, right)
}

#[tokio::test]
async fn adversarial_families_match_the_scene_at_every_scale() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    for scale in [1.0, 2f64.powi(-1000), 2f64.powi(900), -2f64.powi(960)] {
        let (left, right) = family_tables(&mut rng, scale);
        assert!(left.len() > 60, "scale {scale:e}: {} pairs kept", left.len());
        let found = check(&left, &right, &format!("families at scale {scale:e}")).await;
        assert!(found > 0);
    }
}

/// A lattice of unit squares against the same lattice moved by a whole step (shared
/// edges and corners everywhere), by half a step, and by one ulp beyond a step.
#[tokio::test]
async fn lattices_touching_along_edges_and_corners_match_the_scene() {
    let square = |x: f64, y: f64, s: f64| {
        ConvexPolygon::new([[x, y], [x + s, y], [x + s, y + s], [x, y + s]]).unwrap()
    };
    let lattice = |dx: f64, dy: f64| -> Vec<ConvexPolygon> {
        (0..8)
            .flat_map(|i| (0..8).map(move |j| (i, j)))
            .map(|(i, j)| square(2.0 * i as f64 + dx, 2.0 * j as f64 + dy, 1.0))
            .collect()
    };
    let base = lattice(0.0, 0.0);
    for (dx, dy) in [
        (1.0, 0.0),
        (1.0, 1.0),
        (0.5, 0.5),
        (1f64.next_up(), 0.0),
        (1f64.next_up(), 1f64.next_up()),
    ] {
        let moved = lattice(dx, dy);
        check(&base, &moved, &format!("lattice moved by ({dx:e}, {dy:e})")).await;
    }
    // Huge coordinates: the same lattice near the largest doubles, touching exactly.
    let big = 2f64.powi(1020);
    let huge = |dx: f64| -> Vec<ConvexPolygon> {
        (0..6)
            .map(|i| square(big * (2.0 * i as f64 + dx) / 16.0, -big, big / 16.0))
            .collect()
    };
    assert!(check(&huge(0.0), &huge(1.0), "huge lattice").await > 0);
}

/// The generator's adversarial tables (`gen --layout adversarial`): only row i meets
/// row i, about half the rows touch, the one-ulp rows are touching or exactly one ulp
/// apart, and the join finds the `Scene`'s pairs.
#[tokio::test]
async fn generated_adversarial_tables_match_the_scene() {
    let families = tables::ADVERSARIAL_FAMILIES;
    let ulp_row = families.iter().position(|&f| f == Family::OneUlpGap).unwrap();
    for vertices in [3usize, 8, 33] {
        let rows = 90;
        let (left, right) = tables::adversarial_pairs(rows, vertices, SEED + vertices as u64).unwrap();
        assert_eq!((left.len(), right.len()), (rows, rows));
        let (mut touching, mut gaps) = (0, 0);
        for i in (ulp_row..rows).step_by(families.len()) {
            let (a, b) = (left[i].bounding_box(), right[i].bounding_box());
            let (lo, hi) = if a.min.x < b.min.x { (a, b) } else { (b, a) };
            if hi.min.x == lo.max.x {
                touching += 1;
            } else {
                assert_eq!(hi.min.x, lo.max.x.next_up(), "row {i}: {lo:?} {hi:?}");
                gaps += 1;
            }
        }
        assert!(
            touching > 0 && gaps > 0,
            "{touching} touching, {gaps} one ulp apart"
        );
        let expected = scene_pairs(&left, &right);
        assert!(expected.iter().all(|&(i, j)| i == j), "a pair across tiles");
        assert!(
            (rows / 4..rows * 3 / 4).contains(&expected.len()),
            "{} of {rows} rows meet",
            expected.len()
        );
        check(
            &left,
            &right,
            &format!("generated adversarial, {vertices} vertices"),
        )
        .await;
    }
}

#[tokio::test]
async fn empty_tables_give_no_pairs() {
    let some = tables::polygons(&TableSpec {
        rows: 5,
        vertices: 5,
        seed: 1,
        partners: 2.0,
        layout: Layout::Uniform,
    });
    let ctx = context(2, 8192);
    for (l, r) in [(&[][..], &some[..]), (&some[..], &[][..]), (&[][..], &[][..])] {
        assert!(join_pairs(&ctx, l, r, &JoinOptions::default()).await.is_empty());
    }
}

#[tokio::test]
async fn the_plan_is_a_hash_join_on_cells_not_a_nested_loop() {
    let polys = tables::polygons(&TableSpec {
        rows: 50,
        vertices: 6,
        seed: 2,
        partners: 2.0,
        layout: Layout::Uniform,
    });
    let ctx = context(4, 8192);
    let df = spatial_join(
        table(&ctx, &polys, 50),
        "geometry",
        table(&ctx, &polys, 50),
        "geometry",
        &JoinOptions::default(),
    )
    .await
    .unwrap();
    let plan = df.explain(false, false).unwrap().collect().await.unwrap();
    let text = datafusion::arrow::util::pretty::pretty_format_batches(&plan)
        .unwrap()
        .to_string();
    assert!(text.contains("HashJoinExec"), "{text}");
    assert!(text.contains("__polysect_cell"), "{text}");
    for nested in ["NestedLoopJoinExec", "CrossJoinExec"] {
        assert!(!text.contains(nested), "{text}");
    }
}

/// A table whose geometry column holds these values (None: null).
fn raw_table(
    ctx: &datafusion::prelude::SessionContext,
    values: &[Option<Vec<u8>>],
) -> datafusion::prelude::DataFrame {
    let schema = Arc::new(Schema::new(vec![
        Field::new("id", DataType::Int64, false),
        Field::new("geometry", DataType::Binary, true),
    ]));
    let mut g = BinaryBuilder::new();
    for v in values {
        match v {
            Some(b) => g.append_value(b),
            None => g.append_null(),
        }
    }
    let ids = Int64Array::from_iter_values(0..values.len() as i64);
    ctx.read_batch(RecordBatch::try_new(schema, vec![Arc::new(ids), Arc::new(g.finish())]).unwrap())
        .unwrap()
}

#[tokio::test]
async fn invalid_geometries_fail_the_join_or_are_skipped_and_nulls_match_nothing() {
    let polys = tables::polygons(&TableSpec {
        rows: 40,
        vertices: 7,
        seed: 3,
        partners: 4.0,
        layout: Layout::Uniform,
    });
    let dart = ring_to_wkb(&[
        Point::new(0.0, 0.0),
        Point::new(2.0, 0.0),
        Point::new(1.0, 0.5),
        Point::new(1.0, 2.0),
    ]);
    let mut right: Vec<Option<Vec<u8>>> = polys.iter().map(|p| Some(polygon_to_wkb(p))).collect();
    right[5] = Some(dart);
    right[9] = None;
    let ctx = context(2, 8192);
    let left = || table(&ctx, &polys, 16);
    let err = async {
        let df = spatial_join(
            left(),
            "geometry",
            raw_table(&ctx, &right),
            "geometry",
            &JoinOptions::default(),
        )
        .await?;
        common::collect_pairs(df).await
    }
    .await
    .unwrap_err()
    .to_string();
    assert!(
        err.contains("polysect_box") && err.contains("not a convex polygon"),
        "{err}"
    );

    let options = JoinOptions {
        on_invalid: OnInvalid::Null,
        ..JoinOptions::default()
    };
    let df = spatial_join(left(), "geometry", raw_table(&ctx, &right), "geometry", &options)
        .await
        .unwrap();
    let got: std::collections::BTreeSet<(i64, i64)> =
        common::collect_pairs(df).await.unwrap().into_iter().collect();
    let expected: std::collections::BTreeSet<(i64, i64)> = scene_pairs(&polys, &polys)
        .into_iter()
        .filter(|&(_, j)| j != 5 && j != 9)
        .collect();
    assert!(!expected.is_empty());
    assert_eq!(got, expected);
}
