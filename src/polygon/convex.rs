//! [`ConvexPolygon`]: a validated convex polygon stored as a counter-clockwise array.

use super::hull::hull_indices;
use super::{InputIndex, PolygonError, Prefilter, distinct_indices};
use crate::kernel::exact::area_sign_of;
use crate::kernel::{BoundingBox, Exact, Kernel, Orientation, Point, Sign};
use std::sync::OnceLock;

/// A convex polygon with at least three vertices, stored counter-clockwise with
/// every turn strictly convex (no repeated and no collinear vertices).
///
/// The start vertex is the first vertex of the input that survives cleaning, so
/// callers control where the array starts (the thesis's "shifted start index").
///
/// # Complexity
/// Construction is O(n) for n input vertices (error reporting for a vertex list in
/// convex position but out of order costs O(n log n)).
#[derive(Clone, Debug)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "Vec<Point>", into = "Vec<Point>"))]
pub struct ConvexPolygon {
    vertices: Vec<Point>,
    /// The bounding box `(min, max)`, kept with the vertices so that a query can hand
    /// the exact kernel a per-query error bound in O(1) ([`Kernel::within`]).
    bbox: BoundingBox,
    /// [`ConvexPolygon::edge_extent`]: computed by [`ConvexPolygon::new`], whose checks
    /// cost far more, and otherwise by the first call that asks for it (only the exact
    /// kernel's linear test does), so that a conversion does not pay the pass: it would
    /// nearly triple the instructions of converting a linked polygon in boundary order
    /// (docs/results.md).
    edge_extent: OnceLock<f64>,
}

impl ConvexPolygon {
    /// Validates and cleans `points` (either orientation, any start vertex).
    ///
    /// # Errors
    /// A [`PolygonError`] naming the offending input vertex: non-finite coordinates,
    /// fewer than three distinct vertices, all collinear, a spike, a reflex vertex,
    /// an out-of-order (bowtie) list, or a boundary winding more than once.
    ///
    /// ```
    /// use polysect::{ConvexPolygon, Point};
    /// // Clockwise, with a repeated closing vertex and a collinear middle vertex.
    /// let p = ConvexPolygon::new([[0.0, 0.0], [0.0, 2.0], [2.0, 2.0], [2.0, 1.0], [2.0, 0.0], [0.0, 0.0]])?;
    /// assert_eq!(p.len(), 4);
    /// assert_eq!(p.vertices()[0], Point::new(0.0, 0.0));
    /// assert_eq!(p.vertices()[1], Point::new(2.0, 0.0)); // now counter-clockwise
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn new<I, P>(points: I) -> Result<Self, PolygonError>
    where
        I: IntoIterator<Item = P>,
        P: Into<Point>,
    {
        let points: Vec<Point> = points.into_iter().map(Into::into).collect();
        let polygon = clean(&points).map(ConvexPolygon::with_box)?;
        // Validation costs far more per vertex than the extent's pass; conversions
        // (`from_ccw_unchecked`) leave it to the first query that asks.
        polygon.edge_extent();
        Ok(polygon)
    }

    /// Wraps a list already known to be strictly convex and counter-clockwise.
    /// Nothing is checked; an invalid list makes every algorithm's answer meaningless.
    /// Tests check such lists with `ConvexPolygon::debug_validate` (`instrument`).
    pub fn from_ccw_unchecked(vertices: Vec<Point>) -> Self {
        ConvexPolygon::with_box(vertices)
    }

    /// The polygon on `vertices` with its bounding box computed (the edge extent is
    /// computed when first asked for). O(n).
    fn with_box(vertices: Vec<Point>) -> Self {
        let bbox = box_of(&vertices);
        let edge_extent = OnceLock::new();
        ConvexPolygon {
            vertices,
            bbox,
            edge_extent,
        }
    }

    /// The vertices, counter-clockwise.
    #[inline]
    pub fn vertices(&self) -> &[Point] {
        &self.vertices
    }

    /// Number of vertices (at least 3).
    #[inline]
    #[allow(clippy::len_without_is_empty)]
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Vertex `i` counted cyclically (`i` may exceed `len()`).
    #[inline]
    pub fn vertex(&self, i: usize) -> Point {
        self.vertices[i % self.vertices.len()]
    }

    /// Consumes the polygon, returning its counter-clockwise vertices.
    pub fn into_vertices(self) -> Vec<Point> {
        self.vertices
    }

    /// The same polygon (the same region, nothing moves) with its vertex list starting
    /// at vertex `start` (counted cyclically). O(n).
    ///
    /// ```
    /// use polysect::{ConvexPolygon, Point};
    /// let p = ConvexPolygon::new([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])?;
    /// assert_eq!(p.starting_at(1).vertices()[0], Point::new(1.0, 0.0));
    /// assert_eq!(p.starting_at(1).area(), p.area());
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn starting_at(&self, start: usize) -> ConvexPolygon {
        let mut v = self.vertices.clone();
        let n = v.len();
        v.rotate_left(start % n);
        ConvexPolygon {
            vertices: v,
            bbox: self.bbox,
            edge_extent: self.edge_extent.clone(),
        }
    }

    /// The old name of [`starting_at`](Self::starting_at): it renumbers the vertices and
    /// does not rotate the polygon in the plane.
    #[deprecated(note = "renamed `starting_at`: it renumbers the vertices, the polygon does not turn")]
    pub fn rotated(&self, start: usize) -> ConvexPolygon {
        self.starting_at(start)
    }

    /// The polygon with every vertex mapped by `f`, validated again (an affine map
    /// with a positive determinant keeps convexity but rounding may not).
    ///
    /// # Errors
    /// The [`PolygonError`] of the mapped vertices, as [`ConvexPolygon::new`] gives it.
    pub fn map(&self, f: impl Fn(Point) -> Point) -> Result<ConvexPolygon, PolygonError> {
        ConvexPolygon::new(self.vertices.iter().map(|&p| f(p)))
    }

    /// Translates every vertex in place, each coordinate rounded to nearest, without
    /// validating: for callers that validated the same rounded coordinates already (a
    /// scene translating a linked polygon and its snapshot together). O(n), one pass.
    ///
    /// The box is shifted, not recomputed: rounding to nearest is monotone, so
    /// `round(min xᵢ + dx) = min round(xᵢ + dx)`, and the box's corners are vertex
    /// coordinates, which the caller has seen stay finite. The edge extent is forgotten,
    /// to be computed again when asked for (rounding changes the edges' differences).
    pub(crate) fn translate_unchecked(&mut self, dx: f64, dy: f64) {
        for p in &mut self.vertices {
            *p = Point::new(p.x + dx, p.y + dy);
        }
        let BoundingBox { min: lo, max: hi } = self.bbox;
        self.bbox = BoundingBox::new(Point::new(lo.x + dx, lo.y + dy), Point::new(hi.x + dx, hi.y + dy));
        self.edge_extent = OnceLock::new();
    }

    /// The axis-aligned bounding box. O(1): computed at construction.
    #[inline]
    pub fn bounding_box(&self) -> BoundingBox {
        self.bbox
    }

    instrument_pub! {
        /// The largest coordinate difference along an edge: the maximum of
        /// `|fl(vᵢ₊₁.x − vᵢ.x)|` and `|fl(vᵢ₊₁.y − vᵢ.y)|` over the edges (closing edge
        /// included), each difference computed in `f64` as the predicates compute it.
        /// The cross product of two edges of polygons whose extents are at most `w` can be
        /// asked of the kernel narrowed to differences of at most `w`, whose error bound is
        /// scaled to `w` instead of the boxes. O(1) after [`ConvexPolygon::new`], which
        /// computes it; after [`ConvexPolygon::from_ccw_unchecked`] O(n) on the first call
        /// and O(1) after (kept with the polygon). Infinite
        /// when a difference overflows (coordinates beside `±f64::MAX`).
        ///
        /// ```
        /// use polysect::ConvexPolygon;
        /// let p = ConvexPolygon::new([[0.0, 0.0], [4.0, 0.0], [4.0, 1.0], [0.0, 3.0]])?;
        /// assert_eq!(p.edge_extent(), 4.0);
        /// # Ok::<(), polysect::PolygonError>(())
        /// ```
        #[inline]
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn edge_extent(&self) -> f64 {
            *self.edge_extent.get_or_init(|| edge_extent_of(&self.vertices))
        }
    }

    instrument_pub! {
        /// Checks the invariant exactly: at least three finite vertices, every turn
        /// strictly counter-clockwise, winding once. O(n).
        ///
        /// # Errors
        /// A description of the first violation found.
        #[cfg_attr(not(feature = "instrument"), allow(dead_code))]
        fn debug_validate(&self) -> Result<(), String> {
            let v = &self.vertices;
            if v.len() < 3 {
                return Err(format!("{} vertices", v.len()));
            }
            if let Some(i) = v.iter().position(|p| !p.is_finite()) {
                return Err(format!("vertex {i} is not finite"));
            }
            let n = v.len();
            for i in 0..n {
                let turn = Exact.orient(v[(i + n - 1) % n], v[i], v[(i + 1) % n]);
                if turn != Orientation::Ccw {
                    return Err(format!("turn at vertex {i} is {turn:?}"));
                }
            }
            match winding_number(v) {
                1 => Ok(()),
                w => Err(format!("winds {w} times")),
            }
        }
    }
}

impl From<ConvexPolygon> for Vec<Point> {
    fn from(p: ConvexPolygon) -> Self {
        p.vertices
    }
}

/// Two polygons are equal when their vertex lists are (the box and the edge extent
/// follow from the vertices; the extent may be computed in one and not the other).
impl PartialEq for ConvexPolygon {
    fn eq(&self, other: &Self) -> bool {
        self.vertices == other.vertices
    }
}

impl TryFrom<Vec<Point>> for ConvexPolygon {
    type Error = PolygonError;
    fn try_from(points: Vec<Point>) -> Result<Self, Self::Error> {
        ConvexPolygon::new(points)
    }
}

/// The bounding box of a list (a zero box at the origin for an empty
/// one, which no polygon has). Plain comparisons rather than `f64::min`/`max`, whose
/// NaN handling costs instructions that finite vertices do not need (CLM computes the
/// boxes of its LPs' points with it).
pub(crate) fn box_of(vertices: &[Point]) -> BoundingBox {
    let Some(&first) = vertices.first() else {
        return BoundingBox::new(Point::default(), Point::default());
    };
    let (mut lo, mut hi) = (first, first);
    for p in &vertices[1..] {
        lo.x = if p.x < lo.x { p.x } else { lo.x };
        lo.y = if p.y < lo.y { p.y } else { lo.y };
        hi.x = if p.x > hi.x { p.x } else { hi.x };
        hi.y = if p.y > hi.y { p.y } else { hi.y };
    }
    BoundingBox::new(lo, hi)
}

/// [`ConvexPolygon::edge_extent`] of the closed chain `vertices` (0 for fewer than two).
fn edge_extent_of(vertices: &[Point]) -> f64 {
    let Some(&last) = vertices.last() else {
        return 0.0;
    };
    let mut prev = last;
    let mut w = 0.0f64;
    for &p in vertices {
        let (dx, dy) = ((p.x - prev.x).abs(), (p.y - prev.y).abs());
        w = if dx > w { dx } else { w };
        w = if dy > w { dy } else { w };
        prev = p;
    }
    w
}

/// Whether direction `d` lies in the upper half-turn [0, π) of angles.
/// Exact: `b − a` computed in floating point has the sign of the true difference.
#[inline]
pub(crate) fn upper(a: Point, b: Point) -> bool {
    let dy = b.y - a.y;
    dy > 0.0 || (dy == 0.0 && b.x > a.x)
}

/// How many times the edge directions of a closed chain with all-left turns go
/// around: the number of edges leaving the lower half-turn of directions for the
/// upper one (each turn is less than π, so no crossing is skipped).
fn winding_number(v: &[Point]) -> usize {
    winding_of(v.iter().copied())
}

/// [`winding_number`] of the closed chain listed by `points` (from any vertex). The
/// count is the same for the chain walked backwards (negating every edge direction
/// swaps the half-turns, and reversing the order swaps "leaving" and "entering").
fn winding_of(mut points: impl Iterator<Item = Point>) -> usize {
    let (Some(first), Some(second)) = (points.next(), points.next()) else {
        return 0;
    };
    let mut count = 0;
    let mut step = |a: Point, b: Point, c: Point| {
        if !upper(a, b) && upper(b, c) {
            count += 1;
        }
    };
    let (mut a, mut b) = (first, second);
    for c in points {
        step(a, b, c);
        (a, b) = (b, c);
    }
    step(a, b, first);
    step(b, first, second);
    count
}

/// Validates and cleans a vertex list; see [`ConvexPolygon::new`]. Returns the
/// strictly convex counter-clockwise vertices, starting at the first surviving input vertex.
pub(crate) fn clean(points: &[Point]) -> Result<Vec<Point>, PolygonError> {
    // Validation keeps input indices, not copies of the points: 4 bytes a vertex, plus
    // one byte for its turn, until the cleaned polygon itself is built.
    if u32::try_from(points.len()).is_ok() {
        clean_with::<u32>(points)
    } else {
        clean_with::<usize>(points)
    }
}

fn clean_with<I: InputIndex>(points: &[Point]) -> Result<Vec<Point>, PolygonError> {
    // 1. Non-finite values, repeats, too few or collinear vertices (shared checks).
    let v = distinct_indices::<I>(points).map_err(|e| match e {
        Prefilter::NonFinite { index } => PolygonError::NonFinite {
            index,
            point: points[index],
        },
        Prefilter::TooFew { distinct } => PolygonError::TooFewVertices { distinct },
        Prefilter::AllCollinear => PolygonError::AllCollinear,
    })?;
    let n = v.len();
    let at = |i: usize| points[v[i].get()];
    // 2. Turns on the deduplicated list. Dropping a collinear vertex that lies between
    //    its neighbours leaves the other turns' signs unchanged (the neighbour lies on the
    //    same ray), so one pass decides everything.
    let mut turns = Vec::with_capacity(n);
    for (i, &input) in v.iter().enumerate() {
        let (prev, cur, next) = (at((i + n - 1) % n), at(i), at((i + 1) % n));
        let t = Exact.orient(prev, cur, next);
        if t == Orientation::Collinear && !strictly_between(prev, cur, next) {
            return Err(PolygonError::DoublesBack { index: input.get() });
        }
        turns.push(t);
    }
    let ccw = turns.iter().filter(|&&t| t == Orientation::Ccw).count();
    let cw = turns.iter().filter(|&&t| t == Orientation::Cw).count();
    if ccw > 0 && cw > 0 {
        return Err(non_convex_error(points, v, turns, ccw, cw));
    }
    let kept = || {
        v.iter()
            .zip(&turns)
            .filter(|(_, t)| **t != Orientation::Collinear)
            .map(|(&i, _)| points[i.get()])
    };
    // The winding is counted before the cleaned list is built (either direction gives
    // the same count).
    match winding_of(kept()) {
        1 => {}
        times => return Err(PolygonError::WindsMoreThanOnce { times }),
    }
    let mut kept: Vec<Point> = kept().collect();
    if cw > 0 {
        kept.reverse();
        kept.rotate_right(1); // keep the same start vertex
    }
    Ok(kept)
}

/// `cur` lies strictly inside the segment prev–next (given the three are collinear and
/// `cur` differs from both): exact coordinate comparisons.
fn strictly_between(prev: Point, cur: Point, next: Point) -> bool {
    let inside = |a: f64, b: f64, c: f64| (a <= b && b <= c) || (c <= b && b <= a);
    inside(prev.x, cur.x, next.x) && inside(prev.y, cur.y, next.y) && prev != next
}

/// Mixed turns: name a vertex that turns against the polygon's overall orientation
/// (decided by the sign of the signed area, exactly at every magnitude, or by the
/// majority of turns when the area is zero).
/// `v` holds the input indices of the distinct vertices, `turns` their turns.
fn non_convex_error<I: InputIndex>(
    points: &[Point],
    mut v: Vec<I>,
    turns: Vec<Orientation>,
    ccw: usize,
    cw: usize,
) -> PolygonError {
    let overall = match area_sign_of(v.len(), |i| points[v[i].get()]) {
        Sign::Positive => Orientation::Ccw,
        Sign::Zero if ccw >= cw => Orientation::Ccw,
        _ => Orientation::Cw,
    };
    let i = turns
        .iter()
        .position(|&t| t == overall.reverse())
        .expect("mixed turns include one against the overall orientation");
    let index = v[i].get();
    let non_collinear = turns.iter().filter(|&&t| t != Orientation::Collinear).count();
    drop(turns);
    // In convex position (every distinct vertex on the hull) the list is merely out
    // of order; otherwise some vertex is truly reflex. The hull reorders `v` in place.
    let hull = hull_indices(points, &mut v).len();
    let on_hull = if hull >= 3 { hull } else { 0 };
    if on_hull == non_collinear {
        PolygonError::OutOfOrder { index }
    } else {
        PolygonError::Reflex { index }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_shifted_box_is_the_box_of_the_translated_vertices() {
        // Vectors that round (odd multiples of tiny values, large offsets), that are
        // exact, and that cross zero; the box must equal a recomputed one every time.
        let mut p = poly(&[[0.1, 0.2], [3.7, -1.3], [5.0, 4.4], [-2.9, 3.3]]).unwrap();
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        for step in 0..2_000 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let scale = [1e-17, 0.3, 7.0, 1e6, 3e12][step % 5];
            let unit = |b: u64| (b % 2001) as f64 / 1000.0 - 1.0;
            let (dx, dy) = (unit(seed) * scale, unit(seed >> 20) * scale);
            p.translate_unchecked(dx, dy);
            assert_eq!(
                p.bounding_box(),
                box_of(p.vertices()),
                "step {step} by ({dx}, {dy})"
            );
            // The extent kept with the polygon is the one of its vertices now, and the
            // unchecked construction computes the same when first asked.
            let fresh = ConvexPolygon::from_ccw_unchecked(p.vertices().to_vec());
            assert_eq!(p.edge_extent(), edge_extent_of(p.vertices()), "step {step}");
            assert_eq!(fresh, p, "equality ignores whether the extent was computed");
            assert_eq!(fresh.edge_extent(), p.edge_extent(), "step {step}");
        }
    }

    fn poly(pts: &[[f64; 2]]) -> Result<ConvexPolygon, PolygonError> {
        ConvexPolygon::new(pts.iter().copied())
    }

    const SQUARE: [[f64; 2]; 4] = [[0., 0.], [1., 0.], [1., 1.], [0., 1.]];

    #[test]
    fn accepts_both_orientations_and_any_start() {
        let ccw = poly(&SQUARE).unwrap();
        let mut cw_list = SQUARE;
        cw_list.reverse();
        let cw = poly(&cw_list).unwrap();
        assert_eq!(cw.vertices()[0], Point::new(0., 1.));
        assert_eq!(cw.starting_at(1).vertices(), ccw.vertices());
        #[allow(deprecated)]
        let old_name = cw.rotated(1);
        assert_eq!(old_name, cw.starting_at(1));
        for p in [&ccw, &cw] {
            p.debug_validate().unwrap();
        }
    }

    #[test]
    fn cleans_duplicates_closing_vertex_and_collinear_runs() {
        let p = poly(&[
            [0., 0.],
            [0., 0.],
            [1., 0.],
            [2., 0.],
            [3., 0.],
            [3., 3.],
            [3., 3.],
            [0., 3.],
            [0., 1.5],
            [0., 0.],
            [0., 0.],
        ])
        .unwrap();
        assert_eq!(
            p.vertices(),
            &[
                Point::new(0., 0.),
                Point::new(3., 0.),
                Point::new(3., 3.),
                Point::new(0., 3.)
            ]
        );
        // The start vertex itself collinear: the next surviving vertex starts.
        let q = poly(&[[1., 0.], [2., 0.], [2., 2.], [0., 2.], [0., 0.]]).unwrap();
        assert_eq!(q.vertices()[0], Point::new(2., 0.));
        assert_eq!(q.len(), 4);
    }

    #[test]
    fn reports_each_error_with_its_vertex() {
        use PolygonError::*;
        assert!(matches!(
            poly(&[[0., 0.], [f64::NAN, 1.], [1., 1.]]),
            Err(NonFinite { index: 1, .. })
        ));
        assert!(matches!(
            poly(&[[0., 0.], [1., f64::INFINITY], [1., 1.]]),
            Err(NonFinite { index: 1, .. })
        ));
        assert_eq!(poly(&[[0., 0.], [1., 1.]]), Err(TooFewVertices { distinct: 2 }));
        assert_eq!(
            poly(&[[0., 0.], [1., 1.], [1., 1.], [0., 0.]]),
            Err(TooFewVertices { distinct: 2 })
        );
        assert_eq!(poly(&[]), Err(TooFewVertices { distinct: 0 }));
        assert_eq!(poly(&[[0., 0.], [1., 1.], [2., 2.]]), Err(AllCollinear));
        assert_eq!(
            poly(&[[0., 0.], [2., 0.], [1., 0.], [1., 1.]]),
            Err(DoublesBack { index: 1 })
        );
        // An arrowhead: vertex 3 points inwards.
        assert_eq!(
            poly(&[[0., 0.], [4., 0.], [4., 4.], [2., 1.], [0., 4.]]),
            Err(Reflex { index: 3 })
        );
        // Same arrowhead, clockwise.
        assert_eq!(
            poly(&[[0., 4.], [2., 1.], [4., 4.], [4., 0.], [0., 0.]]),
            Err(Reflex { index: 1 })
        );
        // A bowtie: the square's vertices in the wrong order.
        assert!(matches!(
            poly(&[[0., 0.], [1., 1.], [1., 0.], [0., 1.]]),
            Err(OutOfOrder { .. })
        ));
        // A pentagram: every turn the same way, winding twice.
        let star: Vec<[f64; 2]> = (0..5)
            .map(|i| {
                let a = std::f64::consts::TAU * (2 * i) as f64 / 5.0;
                [a.cos(), a.sin()]
            })
            .collect();
        assert_eq!(poly(&star), Err(WindsMoreThanOnce { times: 2 }));
    }

    /// The arrowhead's error names vertex 3 (1 when clockwise) at every magnitude: the
    /// overall orientation is decided exactly, so a float area that would overflow
    /// (4e300 squared) or underflow (subnormal coordinates) cannot flip it.
    #[test]
    fn reflex_vertex_is_named_at_every_scale() {
        use PolygonError::*;
        let arrow = [[0., 0.], [4., 0.], [4., 4.], [2., 1.], [0., 4.]];
        let scales = [
            1.0,
            1e300,
            2f64.powi(600),
            2f64.powi(-600),
            2f64.powi(1021),  // 4·2^1021 = 2^1023, near f64::MAX
            2f64.powi(-1070), // every coordinate subnormal
            5e-324,
        ];
        for s in scales {
            let scaled: Vec<[f64; 2]> = arrow.iter().map(|&[x, y]| [x * s, y * s]).collect();
            assert_eq!(poly(&scaled), Err(Reflex { index: 3 }), "scale {s:e}");
            let mut cw = scaled.clone();
            cw.reverse();
            assert_eq!(poly(&cw), Err(Reflex { index: 1 }), "clockwise, scale {s:e}");
        }
        // The issue's polygon as written.
        assert_eq!(
            poly(&[[0., 0.], [4e300, 0.], [4e300, 4e300], [2e300, 1e300], [0., 4e300]]),
            Err(Reflex { index: 3 })
        );
    }

    #[test]
    fn errors_have_readable_messages() {
        let e = poly(&[[0., 0.], [4., 0.], [4., 4.], [2., 1.], [0., 4.]]).unwrap_err();
        assert_eq!(e.to_string(), "vertex 3 is reflex: the polygon is not convex");
    }

    #[test]
    fn keeps_one_ulp_turns_at_large_offsets() {
        let o = 2f64.powi(50);
        // The middle vertex is one ulp outside the chord: a genuine (tiny) convex turn.
        let p = poly(&[[o, o], [o + 2.0, o], [o + 4.0, o + 0.25], [o + 4.0, o + 4.0]]);
        assert_eq!(p.unwrap().len(), 4);
        let q = poly(&[[o, o], [o + 2.0, o], [o + 4.0, o], [o + 4.0, o + 4.0]]).unwrap();
        assert_eq!(q.len(), 3);
    }
}
