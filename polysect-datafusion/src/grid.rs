//! The uniform grid that partitions the plane for the spatial join.
//!
//! A grid is a cell size `s > 0` and an origin `o`. Coordinate `v` falls in column
//! `floor((v − o_x) / s)` (rows likewise), clamped to the `i32` range; a cell's id packs
//! column and row into one `i64`. A bounding box covers the block of cells between the
//! cells of its two corners.
//!
//! # What must hold
//! The join is exact only if every pair of overlapping boxes shares the cell of its
//! *reference point*, the lower-left corner `(max(a.min.x, b.min.x), max(a.min.y,
//! b.min.y))` of the boxes' intersection. That point lies in both (closed) boxes, so it
//! suffices that the column of a coordinate never decreases as the coordinate grows,
//! and it never does: the column is computed as `floor(((v/2 − o/2) / s) · 2)`, a chain of
//! correctly rounded operations each monotone in `v` (overflow included, as ±∞), then
//! a saturating cast and a clamp, both monotone. Halving first keeps the difference
//! finite for every pair of finite coordinates; no NaN can arise from finite input and
//! a finite positive `s`. The columns of a box's corners therefore bracket the
//! reference point's column, so the pair meets in exactly one cell of the equi-join
//! (each polygon lists each of its cells once) and is reported once.
//!
//! # Complexity
//! A box covers `(1 + ⌊w/s⌋ or so) × (1 + ⌊h/s⌋ or so)` cells for width `w` and height
//! `h`. [`Grid::for_boxes`] picks `s` from the median box size and never below the
//! data's span over [`MAX_COLUMNS`], so no box covers more than about `MAX_COLUMNS²`
//! cells; a table of boxes all as large as the data's span is the worst case (every
//! box in every cell, a quadratic number of candidates, as for any box filter).

use polysect::{BoundingBox, Point};
use std::fmt;

/// The most columns (and rows) a chosen grid spans over the data: bounds the cells of
/// the largest box to about `MAX_COLUMNS²`.
pub const MAX_COLUMNS: f64 = 1024.0;

/// The most cells one box may cover before [`Grid::cells`] refuses it: far above what
/// a grid from [`Grid::for_boxes`] produces (about `MAX_COLUMNS²`), reached only with a
/// cell size chosen by hand that is tiny against a box.
pub const MAX_CELLS_PER_BOX: u64 = 1 << 22;

/// A cell size and origin for the join's partitioning.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    cell_size: f64,
    origin: Point,
}

/// Why a grid cannot be made or used.
#[derive(Clone, Debug, PartialEq)]
pub enum GridError {
    /// The cell size is not finite and positive.
    CellSize(f64),
    /// An origin coordinate is not finite.
    Origin(Point),
    /// A box covers more than [`MAX_CELLS_PER_BOX`] cells of this grid.
    TooManyCells {
        /// How many it covers.
        cells: u64,
        /// The grid's cell size.
        cell_size: f64,
    },
}

impl fmt::Display for GridError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GridError::CellSize(s) => write!(f, "grid cell size {s} is not a finite positive number"),
            GridError::Origin(p) => write!(f, "grid origin ({}, {}) is not finite", p.x, p.y),
            GridError::TooManyCells { cells, cell_size } => write!(
                f,
                "a bounding box covers {cells} cells of size {cell_size}, more than {MAX_CELLS_PER_BOX}; use a larger cell size"
            ),
        }
    }
}

impl std::error::Error for GridError {}

/// What [`Grid::for_boxes`] needs to know about the boxes of both tables.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoxStats {
    /// The box around all boxes.
    pub extent: BoundingBox,
    /// A typical box's larger side divided by two (halved so that it is finite for
    /// every box of finite coordinates): the median, or an approximation of it.
    pub typical_half_side: f64,
}

/// The block of cells a box covers: columns and rows, both inclusive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CellBlock {
    /// First and last column.
    pub columns: (i32, i32),
    /// First and last row.
    pub rows: (i32, i32),
}

impl CellBlock {
    /// How many cells the block has.
    pub fn len(&self) -> u64 {
        let span = |(a, b): (i32, i32)| (i64::from(b) - i64::from(a) + 1) as u64;
        span(self.columns) * span(self.rows)
    }

    /// Always false: a block has at least one cell.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The cells' ids, column by column.
    pub fn ids(self) -> impl Iterator<Item = i64> {
        let (c0, c1) = self.columns;
        let (r0, r1) = self.rows;
        (c0..=c1).flat_map(move |c| (r0..=r1).map(move |r| cell_id(c, r)))
    }
}

/// Packs a column and a row into one id (distinct pairs, distinct ids).
pub fn cell_id(column: i32, row: i32) -> i64 {
    (i64::from(column) << 32) | i64::from(row as u32)
}

impl Grid {
    /// A grid with cells of side `cell_size` whose cell (0, 0) starts at `origin`.
    ///
    /// # Errors
    /// [`GridError`] when `cell_size` is not finite and positive or `origin` is not
    /// finite.
    pub fn new(cell_size: f64, origin: Point) -> Result<Grid, GridError> {
        if !(cell_size.is_finite() && cell_size > 0.0) {
            return Err(GridError::CellSize(cell_size));
        }
        if !(origin.x.is_finite() && origin.y.is_finite()) {
            return Err(GridError::Origin(origin));
        }
        Ok(Grid { cell_size, origin })
    }

    /// The grid for joining boxes like these: the origin at the extent's lower-left
    /// corner, the cell size the typical box's larger side, but at least the extent's
    /// larger side over [`MAX_COLUMNS`].
    pub fn for_boxes(stats: &BoxStats) -> Grid {
        let e = stats.extent;
        let half_span = (e.max.x * 0.5 - e.min.x * 0.5).max(e.max.y * 0.5 - e.min.y * 0.5);
        let floor = (half_span / MAX_COLUMNS) * 2.0;
        let typical = stats.typical_half_side * 2.0;
        let mut s = typical.max(floor);
        if !(s.is_finite() && s > 0.0) {
            // Non-finite only by overflow (then the largest double), zero only for an
            // empty input (then any size does).
            s = if s > 0.0 { f64::MAX } else { 1.0 };
        }
        let origin = if e.min.x.is_finite() && e.min.y.is_finite() {
            e.min
        } else {
            Point::new(0.0, 0.0)
        };
        Grid { cell_size: s, origin }
    }

    /// The cell side.
    pub fn cell_size(&self) -> f64 {
        self.cell_size
    }

    /// The lower-left corner of cell (0, 0).
    pub fn origin(&self) -> Point {
        self.origin
    }

    /// The column (or row) of coordinate `v` against origin coordinate `o`; never
    /// decreases as `v` grows (module docs).
    fn index(&self, v: f64, o: f64) -> i32 {
        let t = ((v * 0.5 - o * 0.5) / self.cell_size) * 2.0;
        // `as` saturates (and maps NaN, which finite input cannot produce, to 0).
        (t.floor() as i64).clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
    }

    /// The id of the cell containing `p` (a point on a cell's lower or left side
    /// belongs to it).
    pub fn cell_of(&self, p: Point) -> i64 {
        cell_id(self.index(p.x, self.origin.x), self.index(p.y, self.origin.y))
    }

    /// The cells a box covers.
    ///
    /// # Errors
    /// [`GridError::TooManyCells`] when they are more than [`MAX_CELLS_PER_BOX`].
    pub fn cells(&self, b: &BoundingBox) -> Result<CellBlock, GridError> {
        let block = CellBlock {
            columns: (
                self.index(b.min.x, self.origin.x),
                self.index(b.max.x, self.origin.x),
            ),
            rows: (
                self.index(b.min.y, self.origin.y),
                self.index(b.max.y, self.origin.y),
            ),
        };
        let cells = block.len();
        if cells > MAX_CELLS_PER_BOX {
            return Err(GridError::TooManyCells {
                cells,
                cell_size: self.cell_size,
            });
        }
        Ok(block)
    }

    /// The cell in which a pair of overlapping boxes is reported: the one containing
    /// the lower-left corner of their intersection.
    pub fn reference_cell(&self, a: &BoundingBox, b: &BoundingBox) -> i64 {
        self.cell_of(reference_point(a, b))
    }
}

/// The lower-left corner of two boxes' intersection (inside both when they overlap).
pub fn reference_point(a: &BoundingBox, b: &BoundingBox) -> Point {
    Point::new(a.min.x.max(b.min.x), a.min.y.max(b.min.y))
}

#[cfg(test)]
mod tests;
