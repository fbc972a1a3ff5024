//! The spatial join: every pair of rows whose polygons intersect, planned as a
//! partitioned equi-join, never a nested loop.
//!
//! [`spatial_join`] rewrites "`left JOIN right ON polysect_intersects(l.g, r.g)`" into
//! standard DataFusion operators, so that every DataFusion planner (and a distributed
//! one such as Ballista, which ships standard operators and named functions only)
//! runs it as it runs any hash join:
//!
//! 1. **Grid.** One aggregate pass over both tables' bounding boxes (`polysect_box`)
//!    gives their extent and the median box size; the grid's cell is the larger side
//!    of a typical box, but never less than the extent over
//!    [`MAX_COLUMNS`](crate::grid::MAX_COLUMNS) ([`Grid::for_boxes`]). A grid given in
//!    [`JoinOptions::grid`] skips this pass.
//! 2. **Partition.** Each row gets its box and the ids of the cells the box covers
//!    (`polysect_cells`), one row per cell (`unnest`).
//! 3. **Equi-join** on the cell id: a hash join, partitioned by cell, in parallel.
//! 4. **Filter**, in order: the boxes overlap; the pair's reference cell
//!    (`polysect_cell` of the lower-left corner of the boxes' intersection) is this
//!    cell, so that a pair sharing several cells is kept once; and the exact test
//!    (`polysect_intersects`).
//!
//! # Complexity
//! For N rows whose boxes cover C cells in all, and K candidate pairs (pairs sharing a
//! cell): O(C) rows after the unnest and O(K) exact tests of O(n + m) each (parsing and
//! validating both polygons dominates the O(log n + log m) test). For boxes about
//! one cell wide, C ≈ 4N and K is a small multiple of the pairs whose boxes overlap.
//! The worst case is boxes all as large as the data's extent: every box in every one
//! of up to about [`MAX_COLUMNS`](crate::grid::MAX_COLUMNS)² cells.
//!
//! # Degeneracies and precision
//! Exact, like `polysect_intersects`: touching polygons (a shared edge or vertex, a
//! vertex on an edge) are reported; polygons one ulp apart are not. The grid only
//! decides where a pair is examined, and its rounding cannot lose a pair
//! ([`crate::grid`], "What must hold").
//!
//! # Errors
//! A geometry that is not a convex polygon fails the query (or is skipped, with
//! [`OnInvalid::Null`]), as `polysect_intersects` would on it.

use crate::grid::{BoxStats, Grid};
use crate::udf::{self, OnInvalid};
use datafusion::arrow::array::{Array, AsArray, RecordBatch};
use datafusion::arrow::datatypes::{Float64Type, Int64Type};
use datafusion::common::{Column, Result, exec_err};
use datafusion::functions::core::expr_fn::{get_field, greatest};
use datafusion::functions_aggregate::expr_fn::{approx_median, count, max, min};
use datafusion::logical_expr::{Expr, JoinType, col, lit};
use datafusion::prelude::DataFrame;
use polysect::{BoundingBox, Point};

/// How [`spatial_join`] runs.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct JoinOptions {
    /// What to do with a geometry that is not a convex polygon.
    pub on_invalid: OnInvalid,
    /// The grid to partition with; `None` chooses one from the data (one extra pass).
    pub grid: Option<Grid>,
}

/// The qualifier of the left table's columns in the result.
pub const LEFT: &str = "left";
/// The qualifier of the right table's columns in the result.
pub const RIGHT: &str = "right";

const BOX: &str = "__polysect_box";
const CELL: &str = "__polysect_cell";

/// Every pair of a `left` row and a `right` row whose polygons (WKB in the columns
/// `left_geom` and `right_geom`) intersect, with all columns of both, qualified
/// [`LEFT`] and [`RIGHT`] (`col("left.id")`). Each pair appears once; the order of rows
/// is unspecified. See the module docs for the plan.
///
/// # Errors
/// A missing column, a planning error, or (when the grid is chosen from the data) an
/// invalid geometry met by the first pass.
///
/// ```no_run
/// # async fn f() -> datafusion::error::Result<()> {
/// use datafusion::prelude::*;
/// use polysect_datafusion::join::{JoinOptions, spatial_join};
/// let ctx = SessionContext::new();
/// let a = ctx.read_parquet("a.parquet", ParquetReadOptions::default()).await?;
/// let b = ctx.read_parquet("b.parquet", ParquetReadOptions::default()).await?;
/// let pairs = spatial_join(a, "geometry", b, "geometry", &JoinOptions::default()).await?
///     .select(vec![col("left.id"), col("right.id")])?;
/// pairs.show().await?;
/// # Ok(()) }
/// ```
pub async fn spatial_join(
    left: DataFrame,
    left_geom: &str,
    right: DataFrame,
    right_geom: &str,
    options: &JoinOptions,
) -> Result<DataFrame> {
    let grid = match options.grid {
        Some(g) => g,
        None => choose_grid(&left, left_geom, &right, right_geom, options.on_invalid).await?,
    };
    let left_columns = original_columns(&left, LEFT);
    let right_columns = original_columns(&right, RIGHT);
    let l = partitioned(left, left_geom, grid, options.on_invalid)?.alias(LEFT)?;
    let r = partitioned(right, right_geom, grid, options.on_invalid)?.alias(RIGHT)?;

    let field = |side: &str, f: &str| get_field(Expr::Column(Column::new(Some(side), BOX)), f);
    let cell = |side: &str| Expr::Column(Column::new(Some(side), CELL));
    let geom = |side: &str, name: &str| Expr::Column(Column::new(Some(side), name));
    let overlap = field(LEFT, "xmin")
        .lt_eq(field(RIGHT, "xmax"))
        .and(field(RIGHT, "xmin").lt_eq(field(LEFT, "xmax")))
        .and(field(LEFT, "ymin").lt_eq(field(RIGHT, "ymax")))
        .and(field(RIGHT, "ymin").lt_eq(field(LEFT, "ymax")));
    let reference = udf::cell_udf()
        .call(vec![
            greatest(vec![field(LEFT, "xmin"), field(RIGHT, "xmin")]),
            greatest(vec![field(LEFT, "ymin"), field(RIGHT, "ymin")]),
            lit(grid.cell_size()),
            lit(grid.origin().x),
            lit(grid.origin().y),
        ])
        .eq(cell(LEFT));
    // The exact test (which parses and validates both polygons) runs only on the rows
    // that pass the box and reference-cell tests (`polysect_intersects_if`).
    let exact = udf::intersects_if_udf(options.on_invalid).call(vec![
        overlap.and(reference),
        geom(LEFT, left_geom),
        geom(RIGHT, right_geom),
    ]);
    let joined = l.join_on(r, JoinType::Inner, vec![cell(LEFT).eq(cell(RIGHT)), exact])?;
    joined.select(left_columns.into_iter().chain(right_columns).collect::<Vec<_>>())
}

/// The input's own columns, as they will be named in the result.
fn original_columns(df: &DataFrame, side: &str) -> Vec<Expr> {
    df.schema()
        .fields()
        .iter()
        .map(|f| Expr::Column(Column::new(Some(side), f.name())))
        .collect()
}

/// `df` with its box and one row per covered cell.
fn partitioned(df: DataFrame, geom: &str, grid: Grid, on_invalid: OnInvalid) -> Result<DataFrame> {
    let g = Expr::Column(Column::new_unqualified(geom));
    let boxed = df.with_column(BOX, udf::box_udf(on_invalid).call(vec![g]))?;
    let b = |f: &str| get_field(col(BOX), f);
    let cells = udf::cells_udf().call(vec![
        b("xmin"),
        b("ymin"),
        b("xmax"),
        b("ymax"),
        lit(grid.cell_size()),
        lit(grid.origin().x),
        lit(grid.origin().y),
    ]);
    // Rows whose box is null (null or skipped geometries) keep a null cell after the
    // unnest, and a null key matches nothing.
    boxed.with_column(CELL, cells)?.unnest_columns(&[CELL])
}

/// The grid for these two tables: one aggregate pass over each table's boxes.
///
/// # Errors
/// As the pass's query: an invalid geometry, unless skipped.
pub async fn choose_grid(
    left: &DataFrame,
    left_geom: &str,
    right: &DataFrame,
    right_geom: &str,
    on_invalid: OnInvalid,
) -> Result<Grid> {
    let (a, na, ma) = box_stats(left.clone(), left_geom, on_invalid).await?;
    let (b, nb, mb) = box_stats(right.clone(), right_geom, on_invalid).await?;
    let extent = match (a, b) {
        (Some(a), Some(b)) => BoundingBox::new(
            Point::new(a.min.x.min(b.min.x), a.min.y.min(b.min.y)),
            Point::new(a.max.x.max(b.max.x), a.max.y.max(b.max.y)),
        ),
        (Some(e), None) | (None, Some(e)) => e,
        (None, None) => BoundingBox::new(Point::new(0.0, 0.0), Point::new(1.0, 1.0)),
    };
    // The larger table's typical size, or the only one there is.
    let typical_half_side = if na >= nb { ma.or(mb) } else { mb.or(ma) }.unwrap_or(0.0);
    Ok(Grid::for_boxes(&BoxStats {
        extent,
        typical_half_side,
    }))
}

/// The extent of a table's boxes, how many boxes there are and the median of their
/// larger half sides (`None` for an empty table).
async fn box_stats(
    df: DataFrame,
    geom: &str,
    on_invalid: OnInvalid,
) -> Result<(Option<BoundingBox>, i64, Option<f64>)> {
    let g = Expr::Column(Column::new_unqualified(geom));
    let boxed = df.select(vec![udf::box_udf(on_invalid).call(vec![g]).alias(BOX)])?;
    let b = |f: &str| get_field(col(BOX), f);
    let half = |lo: &str, hi: &str| b(hi) * lit(0.5) - b(lo) * lit(0.5);
    let stats = boxed.aggregate(
        vec![],
        vec![
            min(b("xmin")).alias("x0"),
            min(b("ymin")).alias("y0"),
            max(b("xmax")).alias("x1"),
            max(b("ymax")).alias("y1"),
            count(b("xmin")).alias("n"),
            approx_median(greatest(vec![half("xmin", "xmax"), half("ymin", "ymax")])).alias("m"),
        ],
    )?;
    let batches: Vec<RecordBatch> = stats.collect().await?;
    let Some(batch) = batches.iter().find(|b| b.num_rows() > 0) else {
        return exec_err!("the box statistics query returned no row");
    };
    let f = |i: usize| {
        let c = batch.column(i).as_primitive::<Float64Type>();
        c.is_valid(0).then(|| c.value(0))
    };
    let n = batch.column(4).as_primitive::<Int64Type>().value(0);
    let extent = match (f(0), f(1), f(2), f(3)) {
        (Some(x0), Some(y0), Some(x1), Some(y1)) => {
            Some(BoundingBox::new(Point::new(x0, y0), Point::new(x1, y1)))
        }
        _ => None,
    };
    Ok((extent, n, f(5)))
}
