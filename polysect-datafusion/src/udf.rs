//! Scalar functions over WKB polygon columns.
//!
//! | function | arguments | result |
//! |---|---|---|
//! | `polysect_intersects(a, b)` | two WKB polygons | whether the closed polygons meet (touching counts) |
//! | `polysect_intersects_if(c, a, b)` | a condition, two WKB polygons | `c AND polysect_intersects(a, b)`, reading `a` and `b` only where `c` is true |
//! | `polysect_box(g)` | a WKB polygon | its bounding box, `{xmin, ymin, xmax, ymax}` |
//! | `polysect_cells(xmin, ymin, xmax, ymax, s, ox, oy)` | a box, a grid | the ids of the grid cells the box covers |
//! | `polysect_cell(x, y, s, ox, oy)` | a point, a grid | the id of the grid cell containing it |
//!
//! WKB arguments may be `Binary`, `LargeBinary` or `BinaryView` (each argument its own
//! type); they are read by [`crate::wkb::parse_polygon`], which validates them. The
//! grid functions are the spatial join's partitioning ([`crate::grid`]); every number
//! argument is `Float64` (others are cast).
//!
//! # Degeneracies and errors
//! A null argument gives a null result. A value that is not a convex polygon (see
//! [`crate::wkb`]) is an execution error naming the function, the argument and the
//! row of the batch, unless the functions were made with [`OnInvalid::Null`], when it
//! gives null.
//!
//! # Complexity and precision
//! `polysect_intersects` is exact: polysect's Barba–Langerman test with the exact
//! kernel, O(log n + log m) per row after O(n + m) parsing and validation. A constant
//! argument (a literal, or a value the planner folded) is parsed once per batch, not
//! once per row. `polysect_box` is O(n) and exact (the box of the cleaned vertices).

use crate::grid::{Grid, GridError};
use crate::wkb::{WkbError, parse_polygon};
use datafusion::arrow::array::{
    Array, ArrayRef, AsArray, BooleanBuilder, Float64Array, Int64Builder, ListBuilder, StructArray,
};
use datafusion::arrow::buffer::NullBuffer;
use datafusion::arrow::datatypes::{DataType, Field, Fields, Float64Type};
use datafusion::common::{Result, ScalarValue, exec_err, plan_err};
use datafusion::logical_expr::{
    ColumnarValue, ScalarFunctionArgs, ScalarUDF, ScalarUDFImpl, Signature, Volatility,
};
use datafusion::prelude::SessionContext;
use polysect::intersect::{ArrayIntersection, Barba};
use polysect::{BoundingBox, ConvexPolygon, Point};
use std::sync::Arc;

/// What the WKB functions do with a value that is not a convex polygon.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum OnInvalid {
    /// Fail the query with an error saying what is wrong and where (the default).
    #[default]
    Error,
    /// Return null for that row.
    Null,
}

/// Registers all five functions with `ctx` (see the module docs).
pub fn register(ctx: &SessionContext, on_invalid: OnInvalid) {
    ctx.register_udf(intersects_udf(on_invalid));
    ctx.register_udf(intersects_if_udf(on_invalid));
    ctx.register_udf(box_udf(on_invalid));
    ctx.register_udf(ScalarUDF::from(Cells::new()));
    ctx.register_udf(ScalarUDF::from(Cell::new()));
}

/// `polysect_intersects` as a [`ScalarUDF`].
pub fn intersects_udf(on_invalid: OnInvalid) -> ScalarUDF {
    ScalarUDF::from(Intersects {
        signature: Signature::user_defined(Volatility::Immutable),
        on_invalid,
    })
}

/// `polysect_intersects_if` as a [`ScalarUDF`].
pub fn intersects_if_udf(on_invalid: OnInvalid) -> ScalarUDF {
    ScalarUDF::from(IntersectsIf {
        signature: Signature::user_defined(Volatility::Immutable),
        on_invalid,
    })
}

/// `polysect_box` as a [`ScalarUDF`].
pub fn box_udf(on_invalid: OnInvalid) -> ScalarUDF {
    ScalarUDF::from(BoxOf {
        signature: Signature::user_defined(Volatility::Immutable),
        on_invalid,
    })
}

/// `polysect_cells` as a [`ScalarUDF`].
pub fn cells_udf() -> ScalarUDF {
    ScalarUDF::from(Cells::new())
}

/// `polysect_cell` as a [`ScalarUDF`].
pub fn cell_udf() -> ScalarUDF {
    ScalarUDF::from(Cell::new())
}

/// Accepts the three binary types (and untyped nulls) as they are.
fn coerce_wkb(name: &str, types: &[DataType], arity: usize) -> Result<Vec<DataType>> {
    if types.len() != arity {
        return plan_err!("{name} takes {arity} WKB argument(s), got {}", types.len());
    }
    types
        .iter()
        .enumerate()
        .map(|(i, t)| match t {
            DataType::Binary | DataType::LargeBinary | DataType::BinaryView | DataType::Null => Ok(t.clone()),
            other => plan_err!(
                "{name}: argument {} is {other}, not WKB (Binary, LargeBinary or BinaryView)",
                i + 1
            ),
        })
        .collect()
}

/// One WKB argument: a column, or a constant parsed once.
enum Wkb<'a> {
    Constant(Option<Result<ConvexPolygon, WkbError>>),
    Binary(&'a datafusion::arrow::array::BinaryArray),
    LargeBinary(&'a datafusion::arrow::array::LargeBinaryArray),
    BinaryView(&'a datafusion::arrow::array::BinaryViewArray),
    Nulls,
}

impl<'a> Wkb<'a> {
    fn new(name: &str, arg: &'a ColumnarValue) -> Result<Wkb<'a>> {
        Ok(match arg {
            ColumnarValue::Scalar(s) => match s {
                ScalarValue::Binary(v) | ScalarValue::LargeBinary(v) | ScalarValue::BinaryView(v) => {
                    Wkb::Constant(v.as_deref().map(parse_polygon))
                }
                ScalarValue::Null => Wkb::Nulls,
                other => return exec_err!("{name}: a constant {} is not WKB", other.data_type()),
            },
            ColumnarValue::Array(a) => match a.data_type() {
                DataType::Binary => Wkb::Binary(a.as_binary::<i32>()),
                DataType::LargeBinary => Wkb::LargeBinary(a.as_binary::<i64>()),
                DataType::BinaryView => Wkb::BinaryView(a.as_binary_view()),
                DataType::Null => Wkb::Nulls,
                other => return exec_err!("{name}: a column of {other} is not WKB"),
            },
        })
    }

    /// The polygon in row `i`: `None` for null.
    fn get(&self, i: usize) -> Option<Result<ConvexPolygon, WkbError>> {
        match self {
            Wkb::Constant(c) => c.clone(),
            Wkb::Binary(a) => a.is_valid(i).then(|| parse_polygon(a.value(i))),
            Wkb::LargeBinary(a) => a.is_valid(i).then(|| parse_polygon(a.value(i))),
            Wkb::BinaryView(a) => a.is_valid(i).then(|| parse_polygon(a.value(i))),
            Wkb::Nulls => None,
        }
    }
}

/// Turns an invalid value into an error or a null, as asked.
fn settle(
    name: &str,
    arg: usize,
    row: usize,
    on_invalid: OnInvalid,
    value: Option<Result<ConvexPolygon, WkbError>>,
) -> Result<Option<ConvexPolygon>> {
    match value {
        None => Ok(None),
        Some(Ok(p)) => Ok(Some(p)),
        Some(Err(e)) => match on_invalid {
            OnInvalid::Null => Ok(None),
            OnInvalid::Error => exec_err!("{name}: argument {arg}, row {row} of the batch: {e}"),
        },
    }
}

/// `polysect_intersects(a, b)`.
#[derive(Debug, PartialEq, Eq, Hash)]
struct Intersects {
    signature: Signature,
    on_invalid: OnInvalid,
}

impl ScalarUDFImpl for Intersects {
    fn name(&self) -> &str {
        "polysect_intersects"
    }

    fn signature(&self) -> &Signature {
        &self.signature
    }

    fn coerce_types(&self, arg_types: &[DataType]) -> Result<Vec<DataType>> {
        coerce_wkb(self.name(), arg_types, 2)
    }

    fn return_type(&self, _arg_types: &[DataType]) -> Result<DataType> {
        Ok(DataType::Boolean)
    }

    fn invoke_with_args(&self, args: ScalarFunctionArgs) -> Result<ColumnarValue> {
        intersects_rows(
            self.name(),
            self.on_invalid,
            &args.args[0],
            &args.args[1],
            None,
            args.number_rows,
        )
    }
}

/// `polysect_intersects_if(c, a, b)`: `c AND polysect_intersects(a, b)`, reading `a` and
/// `b` only in the rows where `c` is true (a null `c` counts as false). The spatial join
/// gates the exact test by its box and reference-cell tests with it: DataFusion
/// evaluates the right side of an AND on whole batches unless few rows pass the left,
/// and rewrites a boolean CASE into ANDs.
#[derive(Debug, PartialEq, Eq, Hash)]
struct IntersectsIf {
    signature: Signature,
    on_invalid: OnInvalid,
}

impl ScalarUDFImpl for IntersectsIf {
    fn name(&self) -> &str {
        "polysect_intersects_if"
    }

    fn signature(&self) -> &Signature {
        &self.signature
    }

    fn coerce_types(&self, arg_types: &[DataType]) -> Result<Vec<DataType>> {
        let name = self.name();
        if arg_types.len() != 3 {
            return plan_err!(
                "{name} takes a condition and two WKB arguments, got {} argument(s)",
                arg_types.len()
            );
        }
        if !matches!(arg_types[0], DataType::Boolean | DataType::Null) {
            return plan_err!("{name}: argument 1 is {}, not Boolean", arg_types[0]);
        }
        let mut out = vec![DataType::Boolean];
        out.extend(coerce_wkb(name, &arg_types[1..], 2)?);
        Ok(out)
    }

    fn return_type(&self, _arg_types: &[DataType]) -> Result<DataType> {
        Ok(DataType::Boolean)
    }

    fn invoke_with_args(&self, args: ScalarFunctionArgs) -> Result<ColumnarValue> {
        let gate = args.args[0].to_array(args.number_rows)?;
        let gate = if gate.data_type() == &DataType::Boolean {
            gate.as_boolean().clone()
        } else {
            datafusion::arrow::array::BooleanArray::new_null(args.number_rows)
        };
        let out = intersects_rows(
            self.name(),
            self.on_invalid,
            &args.args[1],
            &args.args[2],
            Some(&gate),
            args.number_rows,
        )?;
        // Rows the gate closed are false, not null.
        let array = out.to_array(args.number_rows)?;
        let array = array.as_boolean();
        let mut fixed = BooleanBuilder::with_capacity(array.len());
        for i in 0..array.len() {
            let open = gate.is_valid(i) && gate.value(i);
            if !open {
                fixed.append_value(false);
            } else if array.is_valid(i) {
                fixed.append_value(array.value(i));
            } else {
                fixed.append_null();
            }
        }
        Ok(ColumnarValue::Array(Arc::new(fixed.finish())))
    }
}

/// The rows of `polysect_intersects(a, b)`; with a `gate`, rows where it is not true are
/// null and their values are not read.
fn intersects_rows(
    name: &str,
    on_invalid: OnInvalid,
    arg_a: &ColumnarValue,
    arg_b: &ColumnarValue,
    gate: Option<&datafusion::arrow::array::BooleanArray>,
    number_rows: usize,
) -> Result<ColumnarValue> {
    let (a, b) = (Wkb::new(name, arg_a)?, Wkb::new(name, arg_b)?);
    // Constants are settled once, so that an invalid one is reported even for an
    // empty batch and is not re-reported per row.
    let constant = |w: &Wkb, arg| match w {
        Wkb::Constant(c) => settle(name, arg, 0, on_invalid, c.clone()).map(Some),
        _ => Ok(None),
    };
    let (ca, cb) = (constant(&a, 1)?, constant(&b, 2)?);
    let all_scalar = gate.is_none()
        && matches!(arg_a, ColumnarValue::Scalar(_))
        && matches!(arg_b, ColumnarValue::Scalar(_));
    let rows = if all_scalar { 1 } else { number_rows };
    let mut out = BooleanBuilder::with_capacity(rows);
    for i in 0..rows {
        if gate.is_some_and(|g| !(g.is_valid(i) && g.value(i))) {
            out.append_null();
            continue;
        }
        // Constants are borrowed, column values read per row.
        let (row_p, row_q);
        let p = match &ca {
            Some(c) => c.as_ref(),
            None => {
                row_p = settle(name, 1, i, on_invalid, a.get(i))?;
                row_p.as_ref()
            }
        };
        let q = match &cb {
            Some(c) => c.as_ref(),
            None => {
                row_q = settle(name, 2, i, on_invalid, b.get(i))?;
                row_q.as_ref()
            }
        };
        match (p, q) {
            (Some(p), Some(q)) => {
                out.append_value(p.bounding_box().overlaps(&q.bounding_box()) && Barba.intersects(p, q))
            }
            _ => out.append_null(),
        }
    }
    let array: ArrayRef = Arc::new(out.finish());
    if all_scalar {
        return Ok(ColumnarValue::Scalar(ScalarValue::try_from_array(&array, 0)?));
    }
    Ok(ColumnarValue::Array(array))
}

/// The fields of `polysect_box`'s struct.
fn box_fields() -> Fields {
    Fields::from(
        ["xmin", "ymin", "xmax", "ymax"]
            .map(|n| Field::new(n, DataType::Float64, false))
            .to_vec(),
    )
}

/// `polysect_box(g)`.
#[derive(Debug, PartialEq, Eq, Hash)]
struct BoxOf {
    signature: Signature,
    on_invalid: OnInvalid,
}

impl ScalarUDFImpl for BoxOf {
    fn name(&self) -> &str {
        "polysect_box"
    }

    fn signature(&self) -> &Signature {
        &self.signature
    }

    fn coerce_types(&self, arg_types: &[DataType]) -> Result<Vec<DataType>> {
        coerce_wkb(self.name(), arg_types, 1)
    }

    fn return_type(&self, _arg_types: &[DataType]) -> Result<DataType> {
        Ok(DataType::Struct(box_fields()))
    }

    fn invoke_with_args(&self, args: ScalarFunctionArgs) -> Result<ColumnarValue> {
        let name = self.name();
        let g = Wkb::new(name, &args.args[0])?;
        let scalar = matches!(args.args[0], ColumnarValue::Scalar(_));
        let rows = if scalar { 1 } else { args.number_rows };
        let mut cols: [Vec<f64>; 4] = std::array::from_fn(|_| Vec::with_capacity(rows));
        let mut valid = Vec::with_capacity(rows);
        for i in 0..rows {
            let b = settle(name, 1, i, self.on_invalid, g.get(i))?.map(|p| p.bounding_box());
            valid.push(b.is_some());
            let b = b.map_or([0.0; 4], |b| [b.min.x, b.min.y, b.max.x, b.max.y]);
            for (c, v) in cols.iter_mut().zip(b) {
                c.push(v);
            }
        }
        let arrays: Vec<ArrayRef> = cols
            .into_iter()
            .map(|c| Arc::new(Float64Array::from(c)) as ArrayRef)
            .collect();
        let nulls = NullBuffer::from(valid);
        let array: ArrayRef = Arc::new(StructArray::try_new(box_fields(), arrays, Some(nulls))?);
        if scalar {
            return Ok(ColumnarValue::Scalar(ScalarValue::try_from_array(&array, 0)?));
        }
        Ok(ColumnarValue::Array(array))
    }
}

/// The `Float64` arguments of a grid function as arrays of the batch's length.
fn floats(args: &ScalarFunctionArgs) -> Result<Vec<ArrayRef>> {
    args.args.iter().map(|a| a.to_array(args.number_rows)).collect()
}

/// The grid given by three arguments of row `i` (`None` if one is null).
fn grid_at(name: &str, cols: &[&Float64Array], i: usize) -> Result<Option<Grid>> {
    if cols.iter().any(|c| c.is_null(i)) {
        return Ok(None);
    }
    let (s, ox, oy) = (cols[0].value(i), cols[1].value(i), cols[2].value(i));
    match Grid::new(s, Point::new(ox, oy)) {
        Ok(g) => Ok(Some(g)),
        Err(e) => exec_err!("{name}: row {i} of the batch: {e}"),
    }
}

/// `polysect_cells(xmin, ymin, xmax, ymax, cell_size, origin_x, origin_y)`.
#[derive(Debug, PartialEq, Eq, Hash)]
struct Cells {
    signature: Signature,
}

impl Cells {
    fn new() -> Cells {
        Cells {
            signature: Signature::exact(vec![DataType::Float64; 7], Volatility::Immutable),
        }
    }
}

impl ScalarUDFImpl for Cells {
    fn name(&self) -> &str {
        "polysect_cells"
    }

    fn signature(&self) -> &Signature {
        &self.signature
    }

    fn return_type(&self, _arg_types: &[DataType]) -> Result<DataType> {
        Ok(DataType::List(Arc::new(Field::new_list_field(
            DataType::Int64,
            true,
        ))))
    }

    fn invoke_with_args(&self, args: ScalarFunctionArgs) -> Result<ColumnarValue> {
        let name = self.name();
        let arrays = floats(&args)?;
        let cols: Vec<&Float64Array> = arrays.iter().map(|a| a.as_primitive::<Float64Type>()).collect();
        let mut out = ListBuilder::new(Int64Builder::new());
        for i in 0..args.number_rows {
            let grid = grid_at(name, &cols[4..], i)?;
            let Some(grid) = grid.filter(|_| cols[..4].iter().all(|c| c.is_valid(i))) else {
                out.append_null();
                continue;
            };
            let (x0, y0, x1, y1) = (
                cols[0].value(i),
                cols[1].value(i),
                cols[2].value(i),
                cols[3].value(i),
            );
            if !(x0 <= x1 && y0 <= y1 && [x0, y0, x1, y1].iter().all(|v| v.is_finite())) {
                return exec_err!(
                    "{name}: row {i} of the batch: ({x0}, {y0}) to ({x1}, {y1}) is not a box of finite corners"
                );
            }
            let b = BoundingBox::new(Point::new(x0, y0), Point::new(x1, y1));
            let block = grid.cells(&b).map_err(|e: GridError| {
                datafusion::error::DataFusionError::Execution(format!("{name}: row {i} of the batch: {e}"))
            })?;
            for id in block.ids() {
                out.values().append_value(id);
            }
            out.append(true);
        }
        Ok(ColumnarValue::Array(Arc::new(out.finish())))
    }
}

/// `polysect_cell(x, y, cell_size, origin_x, origin_y)`.
#[derive(Debug, PartialEq, Eq, Hash)]
struct Cell {
    signature: Signature,
}

impl Cell {
    fn new() -> Cell {
        Cell {
            signature: Signature::exact(vec![DataType::Float64; 5], Volatility::Immutable),
        }
    }
}

impl ScalarUDFImpl for Cell {
    fn name(&self) -> &str {
        "polysect_cell"
    }

    fn signature(&self) -> &Signature {
        &self.signature
    }

    fn return_type(&self, _arg_types: &[DataType]) -> Result<DataType> {
        Ok(DataType::Int64)
    }

    fn invoke_with_args(&self, args: ScalarFunctionArgs) -> Result<ColumnarValue> {
        let name = self.name();
        let arrays = floats(&args)?;
        let cols: Vec<&Float64Array> = arrays.iter().map(|a| a.as_primitive::<Float64Type>()).collect();
        let mut out = Int64Builder::with_capacity(args.number_rows);
        for i in 0..args.number_rows {
            let grid = grid_at(name, &cols[2..], i)?;
            match grid.filter(|_| cols[0].is_valid(i) && cols[1].is_valid(i)) {
                Some(g) => {
                    let (x, y) = (cols[0].value(i), cols[1].value(i));
                    if !(x.is_finite() && y.is_finite()) {
                        return exec_err!("{name}: row {i} of the batch: point ({x}, {y}) is not finite");
                    }
                    out.append_value(g.cell_of(Point::new(x, y)));
                }
                None => out.append_null(),
            }
        }
        Ok(ColumnarValue::Array(Arc::new(out.finish())))
    }
}
