//! Seeded tables of random convex polygons, for trying and benchmarking the join.
//!
//! Each polygon is polysect's ellipse generator's ([`polysect::generate`]): about `n`
//! vertices on an ellipse with semi-axes in (0.05, 1], rotated, then moved to a point
//! drawn uniformly in a square (or near one of a few centres, [`Layout::Clustered`]).
//! The square's side is chosen so that a polygon meets about
//! [`TableSpec::partners`] polygons of another table of the same size and spec
//! (an estimate from the mean Minkowski-sum area; the real count is measured, not
//! promised). Rows are `id` (`Int64`, 0, 1, ...) and `geometry` (WKB, `Binary`).
//!
//! [`adversarial_pairs`] makes two tables row for row: row i of each holds one polygon
//! of an exact touching (shared vertex, vertex on an edge, shared edge, overlapping
//! collinear edges), of its twin one lattice step apart, of a one-ulp gap or its
//! touching twin, or of a nested pair, from [`polysect::generate::pair`], moved onto
//! its own tile of a square lattice. The moves are exact (integer coordinates below
//! 2^53, checked), so every touching stays a touching and every gap stays one ulp wide.

use crate::wkb::polygon_to_wkb;
use datafusion::arrow::array::{ArrayRef, BinaryBuilder, Int64Array, RecordBatch};
use datafusion::arrow::datatypes::{DataType, Field, Schema, SchemaRef};
use polysect::ConvexPolygon;
use polysect::Point;
use polysect::generate::{
    Density, Family, GenerateError, MAX_ATTEMPTS, Relation, try_ellipse_polygon, try_pair,
};
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

/// The families of [`adversarial_pairs`]: the exact touchings and the one-ulp gaps,
/// and nested polygons (boundaries apart, one inside the other).
pub const ADVERSARIAL_FAMILIES: &[Family] = &[
    Family::SharedVertex,
    Family::VertexOnEdge,
    Family::SharedEdge,
    Family::OverlappingEdges,
    Family::OneUlpGap,
    Family::Nested,
];

/// The largest integer below which every integer is a double.
const EXACT_INTEGERS: f64 = 9_007_199_254_740_992.0; // 2^53

/// `p` moved by the integers `(dx, dy)`, when every moved coordinate is an integer of
/// magnitude below 2^53 (so the move is exact); `None` otherwise.
fn exact_move(p: &ConvexPolygon, dx: f64, dy: f64) -> Option<ConvexPolygon> {
    let exact = |v: f64, d: f64| v.fract() == 0.0 && (v.abs() + d.abs()) < EXACT_INTEGERS;
    if !p.vertices().iter().all(|v| exact(v.x, dx) && exact(v.y, dy)) {
        return None;
    }
    p.map(|v| Point::new(v.x + dx, v.y + dy)).ok()
}

/// Two tables of `rows` polygons each whose row i (and only row i) may meet: pairs of
/// [`ADVERSARIAL_FAMILIES`] with about `vertices` vertices, each family in turn, touching
/// or apart by the smallest step (half each), on tiles of a square lattice wide enough
/// that pairs of different rows are far apart. Which table gets which polygon of a pair
/// is drawn at random.
///
/// The one-ulp pairs are made touching and moved; the gap is then opened on the moved
/// pair (the contact vertices' x one float up), where it is one ulp of the tile's
/// coordinates. Nested pairs (not on integers) are moved with rounding, which keeps
/// them nested or apart by a wide margin. A pair that a move would round, or that does
/// not fit its tile, is drawn again.
///
/// # Errors
/// As [`try_pair`] for `vertices` (too many); [`GenerateError::GaveUp`] when
/// [`MAX_ATTEMPTS`] draws in a row could not be placed (tiles past 2^53).
pub fn adversarial_pairs(
    rows: usize,
    vertices: usize,
    seed: u64,
) -> Result<(Vec<ConvexPolygon>, Vec<ConvexPolygon>), GenerateError> {
    type Pair = (ConvexPolygon, ConvexPolygon);
    let mut rng = SmallRng::seed_from_u64(seed);
    let draw = |rng: &mut SmallRng, i: usize| -> Result<(Family, bool, Pair), GenerateError> {
        let family = ADVERSARIAL_FAMILIES[i % ADVERSARIAL_FAMILIES.len()];
        let touch = rng.random_bool(0.5);
        // One-ulp pairs are opened after the move; the others are steered here.
        let relation = if touch || family == Family::OneUlpGap {
            Relation::Intersecting
        } else {
            Relation::Disjoint
        };
        Ok((family, touch, try_pair(family, vertices, relation, rng)?))
    };
    let extent = |(p, q): &Pair| {
        let (a, b) = (p.bounding_box(), q.bounding_box());
        let w = a.max.x.max(b.max.x) - a.min.x.min(b.min.x);
        let h = a.max.y.max(b.max.y) - a.min.y.min(b.min.y);
        w.max(h)
    };
    // The tile: twice the widest of a first draw of each family four times, an integer.
    let mut tile = 1.0f64;
    for i in 0..ADVERSARIAL_FAMILIES.len() * 4 {
        tile = tile.max(extent(&draw(&mut rng, i)?.2));
    }
    let tile = tile.ceil() * 2.0;
    let across = (rows as f64).sqrt().ceil().max(1.0) as usize;
    let (mut left, mut right) = (Vec::with_capacity(rows), Vec::with_capacity(rows));
    for i in 0..rows {
        let (dx, dy) = ((i % across) as f64 * tile, (i / across) as f64 * tile);
        let mut placed = None;
        for _ in 0..MAX_ATTEMPTS {
            let (family, touch, pair) = draw(&mut rng, i)?;
            if extent(&pair) > tile / 2.0 {
                continue;
            }
            let moved = if family == Family::Nested {
                let by = |v: Point| Point::new(v.x + dx, v.y + dy);
                pair.0.map(by).ok().zip(pair.1.map(by).ok())
            } else {
                exact_move(&pair.0, dx, dy).zip(exact_move(&pair.1, dx, dy))
            };
            let Some((p, q)) = moved else { continue };
            if family == Family::OneUlpGap && !touch {
                // Q's leftmost vertices sit on P's rightmost x: one float right of it.
                let contact = p.vertices().iter().map(|v| v.x).fold(f64::MIN, f64::max);
                let open = |v: Point| Point::new(if v.x == contact { v.x.next_up() } else { v.x }, v.y);
                if let Ok(q) = q.map(open) {
                    placed = Some((p, q));
                    break;
                }
                continue;
            }
            placed = Some((p, q));
            break;
        }
        let Some((p, q)) = placed else {
            return Err(GenerateError::GaveUp {
                attempts: MAX_ATTEMPTS,
            });
        };
        if rng.random_bool(0.5) {
            left.push(p);
            right.push(q);
        } else {
            left.push(q);
            right.push(p);
        }
    }
    Ok((left, right))
}
