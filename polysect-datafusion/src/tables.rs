//! Seeded tables of random convex polygons, for trying and benchmarking the join.
//!
//! Each polygon is polysect's ellipse generator's ([`polysect::generate`]): about `n`
//! vertices on an ellipse with semi-axes in (0.05, 1], rotated, then moved to a point
//! drawn uniformly in a square (or near one of a few centres, [`Layout::Clustered`]).
//! The square's side is chosen so that a polygon meets about
//! [`TableSpec::partners`] polygons of another table of the same size and spec
//! (an estimate from the mean Minkowski-sum area; the real count is measured, not
//! promised). Rows are `id` (`Int64`, 0, 1, ...) and `geometry` (WKB, `Binary`).

use crate::wkb::polygon_to_wkb;
use datafusion::arrow::array::{ArrayRef, BinaryBuilder, Int64Array, RecordBatch};
use datafusion::arrow::datatypes::{DataType, Field, Schema, SchemaRef};
use polysect::ConvexPolygon;
use polysect::Point;
use polysect::generate::{Density, try_ellipse_polygon};
use polysect::rand::rngs::SmallRng;
use polysect::rand::{Rng, SeedableRng};
use std::sync::Arc;

/// Where polygons are placed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layout {
    /// Uniformly in the square.
    Uniform,
    /// Around 16 centres drawn in the square, normally distributed with a spread of a
    /// twentieth of its side.
    Clustered,
}

/// What to generate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TableSpec {
    /// How many rows.
    pub rows: usize,
    /// Vertices per polygon (a few fewer where rounding made neighbours collinear).
    pub vertices: usize,
    /// The generator's seed.
    pub seed: u64,
    /// About how many polygons of a like table each polygon should meet (sets the
    /// square's side).
    pub partners: f64,
    /// Where polygons go.
    pub layout: Layout,
}

impl TableSpec {
    /// The side of the square the polygons are placed in.
    pub fn side(&self) -> f64 {
        // Axes uniform in (0.05, 1]: mean area π·E[a]E[b] ≈ 0.87 and mean perimeter
        // ≈ 2π·0.525 ≈ 3.3, so the mean area of a Minkowski sum of two is about
        // 2·0.87 + 3.3²/(2π) ≈ 3.47; a polygon meets rows·3.47/side² others.
        (self.rows as f64 * 3.47 / self.partners.max(1e-9))
            .sqrt()
            .max(1.0)
    }
}

/// The schema of a generated table.
pub fn schema() -> SchemaRef {
    Arc::new(Schema::new(vec![
        Field::new("id", DataType::Int64, false),
        Field::new("geometry", DataType::Binary, false),
    ]))
}

/// The polygons of a table.
pub fn polygons(spec: &TableSpec) -> Vec<ConvexPolygon> {
    let mut rng = SmallRng::seed_from_u64(spec.seed);
    let side = spec.side();
    let centres: Vec<Point> = (0..16)
        .map(|_| Point::new(rng.random_range(0.0..side), rng.random_range(0.0..side)))
        .collect();
    let mut out = Vec::with_capacity(spec.rows);
    while out.len() < spec.rows {
        let Ok(p) = try_ellipse_polygon(&mut rng, spec.vertices, &Density::Uniform, true) else {
            continue;
        };
        let at = match spec.layout {
            Layout::Uniform => Point::new(rng.random_range(0.0..side), rng.random_range(0.0..side)),
            Layout::Clustered => {
                let c = centres[rng.random_range(0..centres.len())];
                // A sum of uniforms: close enough to normal for a layout.
                let g = |rng: &mut SmallRng| {
                    (0..4).map(|_| rng.random_range(-1.0..1.0)).sum::<f64>() * side / 40.0
                };
                Point::new(c.x + g(&mut rng), c.y + g(&mut rng))
            }
        };
        // Moving may round vertices into non-convex position; such draws are redrawn.
        if let Ok(moved) = p.map(|v| Point::new(v.x + at.x, v.y + at.y)) {
            out.push(moved);
        }
    }
    out
}

/// Polygons as a record batch of [`schema`], ids counting from `first_id`.
///
/// # Errors
/// Never in practice: the arrays match the schema.
pub fn batch(polygons: &[ConvexPolygon], first_id: i64) -> datafusion::error::Result<RecordBatch> {
    let ids = Int64Array::from_iter_values((0..polygons.len() as i64).map(|i| first_id + i));
    let mut wkb = BinaryBuilder::new();
    for p in polygons {
        wkb.append_value(polygon_to_wkb(p));
    }
    let columns: Vec<ArrayRef> = vec![Arc::new(ids), Arc::new(wkb.finish())];
    Ok(RecordBatch::try_new(schema(), columns)?)
}

/// The GeoParquet 1.1 file metadata (`"geo"`) for a table of [`schema`].
pub fn geoparquet_metadata() -> String {
    r#"{"version":"1.1.0","primary_column":"geometry","columns":{"geometry":{"encoding":"WKB","geometry_types":["Polygon"]}}}"#
        .to_string()
}

/// Writes batches as a GeoParquet file.
///
/// # Errors
/// An I/O or encoding error.
pub fn write_geoparquet(path: &std::path::Path, batches: &[RecordBatch]) -> datafusion::error::Result<()> {
    use datafusion::parquet::arrow::ArrowWriter;
    use datafusion::parquet::file::metadata::KeyValue;
    use datafusion::parquet::file::properties::WriterProperties;
    let file = std::fs::File::create(path)?;
    let props = WriterProperties::builder()
        .set_key_value_metadata(Some(vec![KeyValue::new(
            "geo".to_string(),
            geoparquet_metadata(),
        )]))
        .build();
    let mut writer = ArrowWriter::try_new(file, schema(), Some(props))?;
    for b in batches {
        writer.write(b)?;
    }
    writer.close()?;
    Ok(())
}
