//! `polysect_intersects` and the grid functions through SQL, against polysect's exact
//! linear-time reference.

mod common;

use datafusion::arrow::array::{
    Array, ArrayRef, AsArray, BinaryBuilder, BinaryViewBuilder, Int64Array, LargeBinaryBuilder, RecordBatch,
};
use datafusion::arrow::datatypes::{DataType, Field, Schema};
use datafusion::prelude::SessionContext;
use polysect::generate::{Family, Relation, pair};
use polysect::intersect::{ArrayIntersection, Linear};
use polysect::rand::SeedableRng;
use polysect::rand::rngs::SmallRng;
use polysect::{ConvexPolygon, Point};
use polysect_datafusion::udf::{OnInvalid, register};
use polysect_datafusion::wkb::{polygon_to_wkb, ring_to_wkb};
use std::sync::Arc;

const SEED: u64 = 0x0073_716c;

/// A geometry column of `values` (None: null) as `kind`.
fn column(kind: &DataType, values: &[Option<Vec<u8>>]) -> ArrayRef {
    match kind {
        DataType::Binary => {
            let mut b = BinaryBuilder::new();
            values.iter().for_each(|v| b.append_option(v.as_deref()));
            Arc::new(b.finish())
        }
        DataType::LargeBinary => {
            let mut b = LargeBinaryBuilder::new();
            values.iter().for_each(|v| b.append_option(v.as_deref()));
            Arc::new(b.finish())
        }
        DataType::BinaryView => {
            let mut b = BinaryViewBuilder::new();
            values.iter().for_each(|v| b.append_option(v.as_deref()));
            Arc::new(b.finish())
        }
        other => panic!("not a WKB type: {other}"),
    }
}

/// Registers `pairs(id, a, b)` with columns of the given types.
fn register_pairs(
    ctx: &SessionContext,
    ta: &DataType,
    tb: &DataType,
    a: &[Option<Vec<u8>>],
    b: &[Option<Vec<u8>>],
) {
    let schema = Arc::new(Schema::new(vec![
        Field::new("id", DataType::Int64, false),
        Field::new("a", ta.clone(), true),
        Field::new("b", tb.clone(), true),
    ]));
    let ids = Arc::new(Int64Array::from_iter_values(0..a.len() as i64));
    let batch = RecordBatch::try_new(schema, vec![ids, column(ta, a), column(tb, b)]).unwrap();
    ctx.register_batch("pairs", batch).unwrap();
}

/// Polygon pairs from every generator family, touching ones included.
fn family_pairs() -> Vec<(ConvexPolygon, ConvexPolygon)> {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let mut out = Vec::new();
    for &family in Family::ALL {
        for relation in [Relation::Intersecting, Relation::Disjoint, Relation::Any] {
            for n in [3, 5, 16, 64] {
                out.push(pair(family, n, relation, &mut rng));
            }
        }
    }
    out
}

/// Runs a query returning one Boolean column.
async fn booleans(ctx: &SessionContext, sql: &str) -> datafusion::error::Result<Vec<Option<bool>>> {
    let batches = ctx.sql(sql).await?.collect().await?;
    let mut out = Vec::new();
    for b in &batches {
        let c = b.column(0).as_boolean();
        out.extend((0..c.len()).map(|i| c.is_valid(i).then(|| c.value(i))));
    }
    Ok(out)
}

#[tokio::test]
async fn every_binary_type_gives_the_reference_answers() {
    let pairs = family_pairs();
    let expected: Vec<Option<bool>> = pairs.iter().map(|(p, q)| Some(Linear.intersects(p, q))).collect();
    assert!(expected.contains(&Some(true)) && expected.contains(&Some(false)));
    let a: Vec<_> = pairs.iter().map(|(p, _)| Some(polygon_to_wkb(p))).collect();
    let b: Vec<_> = pairs.iter().map(|(_, q)| Some(polygon_to_wkb(q))).collect();
    let types = [DataType::Binary, DataType::LargeBinary, DataType::BinaryView];
    for ta in &types {
        for tb in &types {
            let ctx = common::context(2, 13);
            register(&ctx, OnInvalid::Error);
            register_pairs(&ctx, ta, tb, &a, &b);
            let got = booleans(&ctx, "SELECT polysect_intersects(a, b) FROM pairs ORDER BY id")
                .await
                .unwrap();
            assert_eq!(got, expected, "{ta} × {tb}");
            // Symmetric.
            let got = booleans(&ctx, "SELECT polysect_intersects(b, a) FROM pairs ORDER BY id")
                .await
                .unwrap();
            assert_eq!(got, expected, "{tb} × {ta}");
        }
    }
}

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02X}")).collect()
}

#[tokio::test]
async fn a_constant_argument_is_read_once_and_answers_every_row() {
    let pairs = family_pairs();
    let q = &pairs[0].1;
    let a: Vec<_> = pairs.iter().map(|(p, _)| Some(polygon_to_wkb(p))).collect();
    let ctx = SessionContext::new();
    register(&ctx, OnInvalid::Error);
    register_pairs(&ctx, &DataType::Binary, &DataType::Binary, &a, &a);
    let expected: Vec<Option<bool>> = pairs.iter().map(|(p, _)| Some(Linear.intersects(p, q))).collect();
    let sql = format!(
        "SELECT polysect_intersects(a, X'{}') FROM pairs ORDER BY id",
        hex(&polygon_to_wkb(q))
    );
    assert_eq!(booleans(&ctx, &sql).await.unwrap(), expected);
    let sql = format!(
        "SELECT polysect_intersects(X'{}', a) FROM pairs ORDER BY id",
        hex(&polygon_to_wkb(q))
    );
    assert_eq!(booleans(&ctx, &sql).await.unwrap(), expected);
    // Both constant.
    let w = hex(&polygon_to_wkb(q));
    assert_eq!(
        booleans(&ctx, &format!("SELECT polysect_intersects(X'{w}', X'{w}')"))
            .await
            .unwrap(),
        vec![Some(true)]
    );
    // An invalid constant is reported once, as the constant it is.
    let dart = hex(&ring_to_wkb(&[
        Point::new(0.0, 0.0),
        Point::new(2.0, 0.0),
        Point::new(1.0, 0.5),
        Point::new(1.0, 2.0),
    ]));
    let err = booleans(
        &ctx,
        &format!("SELECT polysect_intersects(a, X'{dart}') FROM pairs"),
    )
    .await
    .unwrap_err()
    .to_string();
    assert!(
        err.contains("argument 2") && err.contains("not a convex polygon"),
        "{err}"
    );
}

#[tokio::test]
async fn nulls_give_null_and_invalid_values_fail_or_give_null() {
    let sq = ConvexPolygon::new([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]).unwrap();
    let open = {
        let mut w = polygon_to_wkb(&sq);
        w.truncate(w.len() - 16); // drop the closing point, fix the count
        let n = u32::from_le_bytes(w[9..13].try_into().unwrap()) - 1;
        w[9..13].copy_from_slice(&n.to_le_bytes());
        w
    };
    let a = vec![
        Some(polygon_to_wkb(&sq)),
        None,
        Some(open),
        Some(vec![1, 1, 0, 0, 0]),
    ];
    let b = vec![Some(polygon_to_wkb(&sq)); 4];
    let sql = "SELECT polysect_intersects(a, b) FROM pairs ORDER BY id";

    let ctx = SessionContext::new();
    register(&ctx, OnInvalid::Error);
    register_pairs(&ctx, &DataType::Binary, &DataType::Binary, &a, &b);
    let err = booleans(&ctx, sql).await.unwrap_err().to_string();
    assert!(
        err.contains("polysect_intersects: argument 1, row 2") && err.contains("not closed"),
        "{err}"
    );

    let ctx = SessionContext::new();
    register(&ctx, OnInvalid::Null);
    register_pairs(&ctx, &DataType::Binary, &DataType::Binary, &a, &b);
    assert_eq!(
        booleans(&ctx, sql).await.unwrap(),
        vec![Some(true), None, None, None]
    );
    assert_eq!(
        booleans(&ctx, "SELECT polysect_intersects(NULL, b) FROM pairs")
            .await
            .unwrap(),
        vec![None; 4]
    );
}

#[tokio::test]
async fn non_wkb_arguments_are_planning_errors() {
    let ctx = SessionContext::new();
    register(&ctx, OnInvalid::Error);
    let err = ctx
        .sql("SELECT polysect_intersects(1, 'x')")
        .await
        .unwrap_err()
        .to_string();
    assert!(err.contains("not WKB"), "{err}");
}

/// The join's building blocks in plain SQL: boxes, cells, the reference cell. A pair
/// of squares sharing a corner is found once though they share four cells.
#[tokio::test]
async fn the_grid_functions_compose_into_a_join_in_sql() {
    let sq = |x: f64, y: f64| {
        ConvexPolygon::new([[x, y], [x + 2.0, y], [x + 2.0, y + 2.0], [x, y + 2.0]]).unwrap()
    };
    let a = vec![
        Some(polygon_to_wkb(&sq(0.0, 0.0))),
        Some(polygon_to_wkb(&sq(10.0, 10.0))),
    ];
    let b = vec![
        Some(polygon_to_wkb(&sq(2.0, 2.0))),
        Some(polygon_to_wkb(&sq(0.5, 0.5))),
    ];
    let ctx = SessionContext::new();
    register(&ctx, OnInvalid::Error);
    register_pairs(&ctx, &DataType::Binary, &DataType::Binary, &a, &b);
    let sql = "
        WITH l AS (SELECT id, a AS g, polysect_box(a) AS bx FROM pairs),
             r AS (SELECT id, b AS g, polysect_box(b) AS bx FROM pairs),
             lc AS (SELECT id, g, bx, unnest(polysect_cells(get_field(bx, 'xmin'), get_field(bx, 'ymin'), get_field(bx, 'xmax'), get_field(bx, 'ymax'), 0.7, 0.0, 0.0)) AS cell FROM l),
             rc AS (SELECT id, g, bx, unnest(polysect_cells(get_field(bx, 'xmin'), get_field(bx, 'ymin'), get_field(bx, 'xmax'), get_field(bx, 'ymax'), 0.7, 0.0, 0.0)) AS cell FROM r)
        SELECT lc.id AS l, rc.id AS r FROM lc JOIN rc ON lc.cell = rc.cell
        WHERE get_field(lc.bx, 'xmin') <= get_field(rc.bx, 'xmax') AND get_field(rc.bx, 'xmin') <= get_field(lc.bx, 'xmax')
          AND get_field(lc.bx, 'ymin') <= get_field(rc.bx, 'ymax') AND get_field(rc.bx, 'ymin') <= get_field(lc.bx, 'ymax')
          AND polysect_cell(greatest(get_field(lc.bx, 'xmin'), get_field(rc.bx, 'xmin')), greatest(get_field(lc.bx, 'ymin'), get_field(rc.bx, 'ymin')), 0.7, 0.0, 0.0) = lc.cell
          AND polysect_intersects(lc.g, rc.g)
        ORDER BY l, r";
    let batches = ctx.sql(sql).await.unwrap().collect().await.unwrap();
    let mut got = Vec::new();
    for bt in &batches {
        let (l, r) = (
            bt.column(0)
                .as_primitive::<datafusion::arrow::datatypes::Int64Type>(),
            bt.column(1)
                .as_primitive::<datafusion::arrow::datatypes::Int64Type>(),
        );
        got.extend((0..bt.num_rows()).map(|i| (l.value(i), r.value(i))));
    }
    // (0, 0) meets (2, 2) at one corner and contains (0.5, 0.5)'s corner region.
    assert_eq!(got, vec![(0, 0), (0, 1)]);
}
