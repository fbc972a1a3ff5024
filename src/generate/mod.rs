//! Seeded, reproducible input generators: the thesis's experiment inputs (chapter 4)
//! and adversarial families for the differential tests.
//!
//! Every generator takes the caller's RNG, so a seed reproduces a pair exactly.
//!
//! | [`Family`] | what | source |
//! |---|---|---|
//! | `Ellipse` | random angles on an ellipse (axes in (0, 1], translated in [-1, 1]²), array starting at the leftmost vertex | thesis 4.2.1 |
//! | `Rotated` | as `Ellipse`, randomly rotated, with a random start index | thesis 4.2.3 |
//! | `NonUniform` | angles from a random piecewise-linear density, rotated, random start | thesis 4.2.4 |
//! | `SharedVertex`, `VertexOnEdge`, `SharedEdge`, `OverlappingEdges` | exact touchings on integer coordinates; `Disjoint` moves Q one lattice step away | |
//! | `Nested` | a regular n-gon of radius 1 inside the n-gon of radius ½(1 + 1/cos(2π/n)) at the same angles (1.5 for n < 5): boundaries disjoint, answer true | |
//! | `OneUlpGap` | a vertex of Q one ulp to the right of P's rightmost x, at offsets 0 and 2^10..2^52; `Intersecting` gives the touching twin | |
//!
//! Ellipse-based polygons are convex hulls of the generated points, so they may have
//! slightly fewer than n vertices where rounding made neighbours collinear.

pub mod hard;
pub mod simple;

pub use simple::{GenerateError, MAX_ATTEMPTS};

use crate::intersect::{ArrayIntersection, Linear};
use crate::kernel::Point;
use crate::polygon::{ConvexPolygon, convex_hull};
use rand::Rng;
use std::f64::consts::TAU;
use std::fmt;
use std::str::FromStr;

/// The most vertices any generator puts in one polygon (2^26, about 1 GiB of points).
/// Larger requests are refused with [`GenerateError::InvalidParameters`] before
/// anything is allocated: an allocation that fails aborts the process, and a size
/// near `usize::MAX` would.
pub const MAX_VERTICES: usize = 1 << 26;

/// Refuses vertex counts above [`MAX_VERTICES`].
fn check_size(n: usize) -> Result<(), GenerateError> {
    if n > MAX_VERTICES {
        Err(GenerateError::InvalidParameters(format!(
            "{n} vertices is more than the {MAX_VERTICES} a generator makes"
        )))
    } else {
        Ok(())
    }
}

/// A generator family; see the module table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    /// Random angles on an axis-aligned ellipse, starting at the leftmost vertex (`ellipse`).
    Ellipse,
    /// A randomly rotated ellipse with a random start index (`rotated`).
    Rotated,
    /// Angles from a random piecewise-linear density (`non-uniform`).
    NonUniform,
    /// Integer polygons sharing exactly one vertex (`shared-vertex`).
    SharedVertex,
    /// A vertex of one on an edge of the other (`vertex-on-edge`).
    VertexOnEdge,
    /// Two polygons sharing a whole edge (`shared-edge`).
    SharedEdge,
    /// Collinear edges that overlap in part (`overlapping-edges`).
    OverlappingEdges,
    /// One regular polygon strictly inside another (`nested`).
    Nested,
    /// A vertex one ulp beyond the other polygon's extreme x (`one-ulp-gap`).
    OneUlpGap,
}

impl Family {
    /// Every family, in the order of the module table.
    pub const ALL: &'static [Family] = &[
        Family::Ellipse,
        Family::Rotated,
        Family::NonUniform,
        Family::SharedVertex,
        Family::VertexOnEdge,
        Family::SharedEdge,
        Family::OverlappingEdges,
        Family::Nested,
        Family::OneUlpGap,
    ];

    /// The families whose pairs touch exactly (or miss by the smallest step) when steered.
    pub const TOUCHING: &'static [Family] = &[
        Family::SharedVertex,
        Family::VertexOnEdge,
        Family::SharedEdge,
        Family::OverlappingEdges,
        Family::OneUlpGap,
    ];

    /// The family's name in the CLI (`--family`) and in the benches' CSVs.
    pub fn name(self) -> &'static str {
        match self {
            Family::Ellipse => "ellipse",
            Family::Rotated => "rotated",
            Family::NonUniform => "non-uniform",
            Family::SharedVertex => "shared-vertex",
            Family::VertexOnEdge => "vertex-on-edge",
            Family::SharedEdge => "shared-edge",
            Family::OverlappingEdges => "overlapping-edges",
            Family::Nested => "nested",
            Family::OneUlpGap => "one-ulp-gap",
        }
    }
}

impl fmt::Display for Family {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Family {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Family::ALL
            .iter()
            .copied()
            .find(|f| f.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
                format!("unknown family '{s}' (valid: {})", names.join(", "))
            })
    }
}

/// Which answer a generated pair should have.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Relation {
    /// Whatever the family's random placement gives (thesis: translations in [-1, 1]²).
    #[default]
    Any,
    /// Steered to intersect (for touching families: to touch).
    Intersecting,
    /// Steered apart (for touching families: by the smallest step).
    Disjoint,
}

/// A probability density on [0, 1) for the angles of ellipse vertices.
#[derive(Clone, Debug, PartialEq)]
pub enum Density {
    /// Every angle equally likely.
    Uniform,
    /// Piecewise linear through `weights[i]` at i / (len − 1) (thesis 4.2.4). Only the
    /// weights' ratios matter. A weight that is negative, NaN or infinite counts as
    /// zero; with fewer than two weights, or none positive, the density is uniform.
    PiecewiseLinear {
        /// The density's values at equally spaced knots on [0, 1].
        weights: Vec<f64>,
    },
}

impl Density {
    /// A random piecewise-linear density: [0, 1] split into 1..=10 equal segments with
    /// uniformly random weights at the knots (thesis 4.2.4).
    pub fn random<R: Rng + ?Sized>(rng: &mut R) -> Density {
        let segments = rng.random_range(1..=10);
        let weights = (0..=segments)
            .map(|_| rng.random_range(0.0..1.0) + 1e-3)
            .collect();
        Density::PiecewiseLinear { weights }
    }

    /// One sample in [0, 1]. Never panics, whatever the weights (see [`Density`]).
    pub fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> f64 {
        match self {
            Density::Uniform => rng.random_range(0.0..1.0),
            Density::PiecewiseLinear { weights } => {
                // Usable weights, scaled so that the largest is 1 (their sum cannot overflow).
                let usable = |w: f64| if w.is_finite() && w > 0.0 { w } else { 0.0 };
                let top = weights.iter().map(|&w| usable(w)).fold(0.0, f64::max);
                if weights.len() < 2 || top == 0.0 {
                    return rng.random_range(0.0..1.0);
                }
                let weights: Vec<f64> = weights.iter().map(|&w| usable(w) / top).collect();
                let k = weights.len() - 1;
                let areas: Vec<f64> = weights.windows(2).map(|w| w[0] + w[1]).collect();
                let mut pick = rng.random_range(0.0..areas.iter().sum::<f64>());
                let mut seg = 0;
                while seg + 1 < k && pick >= areas[seg] {
                    pick -= areas[seg];
                    seg += 1;
                }
                // Inverse CDF of the linear density from w0 to w1 on [0, 1].
                let (w0, w1) = (weights[seg], weights[seg + 1]);
                let u: f64 = rng.random_range(0.0..1.0);
                let delta = w1 - w0;
                let s = if delta.abs() < 1e-12 {
                    u
                } else {
                    let target = u * (w0 + w1) / 2.0;
                    ((w0 * w0 + 2.0 * delta * target).max(0.0).sqrt() - w0) / delta
                };
                (seg as f64 + s.clamp(0.0, 1.0)) / k as f64
            }
        }
    }
}

/// A random convex polygon with about `n` vertices on an ellipse: axes in (0.05, 1],
/// angles from `density`, optionally rotated, translated by a vector in [-1, 1]²;
/// the array starts at the leftmost vertex (rotate it with [`ConvexPolygon::rotated`]).
/// Fewer than 3 vertices are taken as 3.
///
/// # Panics
/// When `n` exceeds [`MAX_VERTICES`]; [`try_ellipse_polygon`] returns an error instead.
#[track_caller]
pub fn ellipse_polygon<R: Rng + ?Sized>(
    rng: &mut R,
    n: usize,
    density: &Density,
    rotate: bool,
) -> ConvexPolygon {
    try_ellipse_polygon(rng, n, density, rotate).unwrap_or_else(|e| panic!("{e}"))
}

/// [`ellipse_polygon`], refusing more than [`MAX_VERTICES`] vertices.
///
/// # Errors
/// [`GenerateError::InvalidParameters`] when `n` exceeds [`MAX_VERTICES`].
pub fn try_ellipse_polygon<R: Rng + ?Sized>(
    rng: &mut R,
    n: usize,
    density: &Density,
    rotate: bool,
) -> Result<ConvexPolygon, GenerateError> {
    try_ellipse_polygon_axes(rng, n, density, rotate, None)
}

/// [`ellipse_polygon`] with the semi-axes `(a, b)` given instead of drawn (the thesis's
/// Figure 4.1 squashes the unit circle with a = 1, b = 0.1); `None` draws them.
///
/// # Panics
/// When [`try_ellipse_polygon_axes`] refuses the parameters.
#[track_caller]
pub fn ellipse_polygon_axes<R: Rng + ?Sized>(
    rng: &mut R,
    n: usize,
    density: &Density,
    rotate: bool,
    axes: Option<(f64, f64)>,
) -> ConvexPolygon {
    try_ellipse_polygon_axes(rng, n, density, rotate, axes).unwrap_or_else(|e| panic!("{e}"))
}

/// The smallest semi-axis an ellipse generator accepts: 2^-40. The polygons are
/// translated by up to 1, where the spacing of doubles is 2^-53, so an axis this short
/// still spans 2^13 rounding steps; much shorter ones round every point onto a line.
pub const MIN_AXIS: f64 = 9.094947017729282e-13;

/// The largest semi-axis an ellipse generator accepts: 2^1000, so that rotating,
/// translating and separating the polygons stays far from overflow.
pub const MAX_AXIS: f64 = 1.0715086071862673e301;

/// The largest ratio of the longer semi-axis to the shorter: 2^40. Moving a polygon
/// by its long axis rounds coordinates to steps of 2^-53 of that length, which must
/// stay far below the short axis.
pub const MAX_AXIS_RATIO: f64 = 1099511627776.0;

/// Refuses semi-axes outside [[`MIN_AXIS`], [`MAX_AXIS`]] (NaN included) or further
/// apart than [`MAX_AXIS_RATIO`].
fn check_axes(axes: Option<(f64, f64)>) -> Result<(), GenerateError> {
    let Some((a, b)) = axes else { return Ok(()) };
    let ok = |v: f64| (MIN_AXIS..=MAX_AXIS).contains(&v);
    if !(ok(a) && ok(b)) {
        return Err(GenerateError::InvalidParameters(format!(
            "ellipse semi-axes ({a:e}, {b:e}) must lie in [{MIN_AXIS:e}, {MAX_AXIS:e}]"
        )));
    }
    if a.max(b) / a.min(b) > MAX_AXIS_RATIO {
        return Err(GenerateError::InvalidParameters(format!(
            "ellipse semi-axes ({a:e}, {b:e}) differ by more than a factor {MAX_AXIS_RATIO:e}"
        )));
    }
    Ok(())
}

/// [`ellipse_polygon_axes`], refusing what cannot be drawn. Each attempt is O(n log n)
/// (the hull); at most [`MAX_ATTEMPTS`] attempts are made.
///
/// # Errors
/// [`GenerateError::InvalidParameters`] when `n` exceeds [`MAX_VERTICES`], an axis
/// lies outside [[`MIN_AXIS`], [`MAX_AXIS`]] (zero, NaN and infinities included) or
/// the axes differ by more than [`MAX_AXIS_RATIO`];
/// [`GenerateError::GaveUp`] when [`MAX_ATTEMPTS`] draws in a row rounded to no area.
pub fn try_ellipse_polygon_axes<R: Rng + ?Sized>(
    rng: &mut R,
    n: usize,
    density: &Density,
    rotate: bool,
    axes: Option<(f64, f64)>,
) -> Result<ConvexPolygon, GenerateError> {
    check_size(n)?;
    check_axes(axes)?;
    let n = n.max(3);
    for _ in 0..MAX_ATTEMPTS {
        let (a, b) = match axes {
            Some(ab) => ab,
            None => (rng.random_range(0.05..=1.0), rng.random_range(0.05..=1.0)),
        };
        let phi: f64 = if rotate { rng.random_range(0.0..TAU) } else { 0.0 };
        let (c, s) = (phi.cos(), phi.sin());
        let (tx, ty) = (rng.random_range(-1.0..=1.0), rng.random_range(-1.0..=1.0));
        let pts: Vec<Point> = (0..n)
            .map(|_| {
                let t = density.sample(rng) * TAU;
                let (x, y) = (a * t.cos(), b * t.sin());
                Point::new(c * x - s * y + tx, s * x + c * y + ty)
            })
            .collect();
        if let Ok(h) = convex_hull(&pts) {
            return Ok(h);
        }
    }
    Err(GenerateError::GaveUp {
        attempts: MAX_ATTEMPTS,
    })
}

/// A regular n-gon of the given radius centred at the origin, first vertex at angle 0
/// (vertex i at angle 2πi/n, coordinates rounded; fewer than 3 vertices taken as 3).
/// Where rounding makes the points non-convex (a huge n, a radius near the subnormal
/// range) the polygon is their convex hull, with fewer vertices. Panics on bad
/// parameters; see [`try_regular_polygon`] for the checked form.
///
/// # Panics
/// When [`try_regular_polygon`] refuses the parameters.
///
/// ```
/// use polysect::generate::regular_polygon;
/// let hexagon = regular_polygon(6, 2.0);
/// assert_eq!(hexagon.len(), 6);
/// assert!(hexagon.contains_point([1.9, 0.0]));
/// ```
#[track_caller]
pub fn regular_polygon(n: usize, radius: f64) -> ConvexPolygon {
    match try_regular_polygon(n, radius) {
        Ok(p) => p,
        Err(e) => panic!("regular_polygon({n}, {radius:?}): {e}"),
    }
}

/// [`regular_polygon`], refusing what cannot give a polygon. O(n); memory 16 bytes a
/// vertex for the points plus the polygon itself.
///
/// # Errors
/// [`GenerateError::InvalidParameters`] for a radius that is not finite and positive,
/// for more than [`MAX_VERTICES`] vertices, and for a radius so small that the rounded
/// points have no area.
///
/// ```
/// use polysect::generate::{GenerateError, try_regular_polygon};
/// assert_eq!(try_regular_polygon(4, 1.0)?.len(), 4);
/// assert!(matches!(try_regular_polygon(5, 0.0), Err(GenerateError::InvalidParameters(_))));
/// assert!(matches!(try_regular_polygon(5, f64::NAN), Err(GenerateError::InvalidParameters(_))));
/// # Ok::<(), GenerateError>(())
/// ```
pub fn try_regular_polygon(n: usize, radius: f64) -> Result<ConvexPolygon, GenerateError> {
    check_size(n)?;
    if !(radius.is_finite() && radius > 0.0) {
        return Err(GenerateError::InvalidParameters(format!(
            "a regular polygon needs a finite radius > 0, got {radius:?}"
        )));
    }
    let n = n.max(3);
    let pts: Vec<Point> = (0..n)
        .map(|i| {
            let t = TAU * i as f64 / n as f64;
            Point::new(radius * t.cos(), radius * t.sin())
        })
        .collect();
    ConvexPolygon::new(pts.iter().copied())
        .or_else(|_| convex_hull(&pts))
        .map_err(|e| {
            GenerateError::InvalidParameters(format!("radius {radius:?} rounds the points together: {e}"))
        })
}

/// A generated pair from `family` with about `n` vertices per polygon (fewer than 3
/// taken as 3), steered by `relation`.
///
/// # Panics
/// When `n` exceeds [`MAX_VERTICES`]; [`try_pair`] returns an error instead.
#[track_caller]
pub fn pair<R: Rng + ?Sized>(
    family: Family,
    n: usize,
    relation: Relation,
    rng: &mut R,
) -> (ConvexPolygon, ConvexPolygon) {
    try_pair(family, n, relation, rng).unwrap_or_else(|e| panic!("{e}"))
}

/// [`pair`], refusing more than [`MAX_VERTICES`] vertices.
///
/// # Errors
/// [`GenerateError::InvalidParameters`] when `n` exceeds [`MAX_VERTICES`];
/// [`GenerateError::GaveUp`] when an ellipse family's draws keep rounding to no area
/// (see [`try_ellipse_polygon_axes`]).
pub fn try_pair<R: Rng + ?Sized>(
    family: Family,
    n: usize,
    relation: Relation,
    rng: &mut R,
) -> Result<(ConvexPolygon, ConvexPolygon), GenerateError> {
    try_pair_with_axes(family, n, relation, None, rng)
}

/// [`pair`] for the ellipse families with both polygons' semi-axes fixed to `axes`
/// (`None`: drawn as usual); other families ignore `axes`.
///
/// # Panics
/// When [`try_pair_with_axes`] refuses the parameters.
#[track_caller]
pub fn pair_with_axes<R: Rng + ?Sized>(
    family: Family,
    n: usize,
    relation: Relation,
    axes: Option<(f64, f64)>,
    rng: &mut R,
) -> (ConvexPolygon, ConvexPolygon) {
    try_pair_with_axes(family, n, relation, axes, rng).unwrap_or_else(|e| panic!("{e}"))
}

/// [`pair_with_axes`], refusing what cannot be drawn; every family makes a bounded
/// number of attempts.
///
/// # Errors
/// As [`try_ellipse_polygon_axes`] (the axes are checked for the ellipse families only).
pub fn try_pair_with_axes<R: Rng + ?Sized>(
    family: Family,
    n: usize,
    relation: Relation,
    axes: Option<(f64, f64)>,
    rng: &mut R,
) -> Result<(ConvexPolygon, ConvexPolygon), GenerateError> {
    check_size(n)?;
    Ok(match family {
        Family::Ellipse | Family::Rotated | Family::NonUniform => {
            ellipse_pair(family, n, relation, axes, rng)?
        }
        Family::SharedVertex | Family::VertexOnEdge | Family::SharedEdge | Family::OverlappingEdges => {
            touching_pair(family, n, relation, rng)
        }
        Family::Nested => nested_pair(n, relation, rng),
        Family::OneUlpGap => one_ulp_pair(n, relation, rng),
    })
}

fn ellipse_polygon_of(
    family: Family,
    n: usize,
    axes: Option<(f64, f64)>,
    rng: &mut (impl Rng + ?Sized),
) -> Result<ConvexPolygon, GenerateError> {
    Ok(match family {
        Family::Ellipse => try_ellipse_polygon_axes(rng, n, &Density::Uniform, false, axes)?,
        Family::Rotated => {
            let p = try_ellipse_polygon_axes(rng, n, &Density::Uniform, true, axes)?;
            let start = rng.random_range(0..p.len());
            p.starting_at(start)
        }
        _ => {
            let d = Density::random(rng);
            let p = try_ellipse_polygon_axes(rng, n, &d, true, axes)?;
            let start = rng.random_range(0..p.len());
            p.starting_at(start)
        }
    })
}

fn ellipse_pair<R: Rng + ?Sized>(
    family: Family,
    n: usize,
    relation: Relation,
    axes: Option<(f64, f64)>,
    rng: &mut R,
) -> Result<(ConvexPolygon, ConvexPolygon), GenerateError> {
    check_axes(axes)?;
    let p = ellipse_polygon_of(family, n, axes, rng)?;
    let q = ellipse_polygon_of(family, n, axes, rng)?;
    // The separating gap grows with the axes, or rounding at large coordinates eats it.
    let scale = axes.map_or(1.0, |(a, b)| a.max(b).max(1.0));
    // Each steering draw is redrawn when rounding spoils it, at most MAX_ATTEMPTS times.
    for _ in 0..MAX_ATTEMPTS {
        match relation {
            Relation::Any => return Ok((p, q)),
            Relation::Intersecting => {
                // Move a random interior point of Q onto a random interior point of P.
                let (a, b) = (interior_point(&p, rng), interior_point(&q, rng));
                if let Some(moved) = translate(&q, a.x - b.x, a.y - b.y)
                    && Linear.intersects(&p, &moved)
                {
                    return Ok((p, moved));
                }
            }
            Relation::Disjoint => {
                // Push Q along a random direction u beyond P's extent in u, by a small gap.
                let t: f64 = rng.random_range(0.0..TAU);
                let (ux, uy) = (t.cos(), t.sin());
                let dot = |v: &Point| v.x * ux + v.y * uy;
                let p_max = p.vertices().iter().map(dot).fold(f64::MIN, f64::max);
                let q_min = q.vertices().iter().map(dot).fold(f64::MAX, f64::min);
                let gap = rng.random_range(1e-9..0.05) * scale;
                let shift = p_max - q_min + gap;
                if let Some(moved) = translate(&q, shift * ux, shift * uy)
                    && !Linear.intersects(&p, &moved)
                {
                    return Ok((p, moved));
                }
            }
        }
    }
    Err(GenerateError::GaveUp {
        attempts: MAX_ATTEMPTS,
    })
}

/// A random point inside `p`: a random convex combination of three vertices.
fn interior_point<R: Rng + ?Sized>(p: &ConvexPolygon, rng: &mut R) -> Point {
    let w: [f64; 3] = [
        rng.random_range(0.1..1.0),
        rng.random_range(0.1..1.0),
        rng.random_range(0.1..1.0),
    ];
    let total: f64 = w.iter().sum();
    let mut x = 0.0;
    let mut y = 0.0;
    for wi in w {
        let v = p.vertex(rng.random_range(0..p.len()));
        x += wi / total * v.x;
        y += wi / total * v.y;
    }
    Point::new(x, y)
}

/// `p` moved by (dx, dy); `None` when rounding leaves no area (a far move of a tiny
/// polygon).
fn translate(p: &ConvexPolygon, dx: f64, dy: f64) -> Option<ConvexPolygon> {
    let moved = p.vertices().iter().map(|v| Point::new(v.x + dx, v.y + dy));
    let pts: Vec<Point> = moved.collect();
    // Rounding can merge or straighten vertices; the hull keeps the result valid.
    ConvexPolygon::new(pts.iter().copied())
        .or_else(|_| convex_hull(&pts))
        .ok()
}

/// A convex polygon on integer coordinates with about `n` vertices: the hull of
/// rounded points on a circle of radius ~ 2·n^1.5 around `(cx, cy)` (a lattice polygon
/// of radius R has O(R^⅔) vertices at most).
fn lattice_polygon<R: Rng + ?Sized>(
    rng: &mut R,
    n: usize,
    cx: f64,
    cy: f64,
    radius: Option<f64>,
) -> Vec<Point> {
    let n = n.max(3);
    let r = radius
        .unwrap_or_else(|| (2.0 * (n as f64).powf(1.5)).max(4.0))
        .round();
    let phase: f64 = rng.random_range(0.0..TAU);
    (0..n)
        .map(|i| {
            let t = phase + TAU * i as f64 / n as f64;
            Point::new((cx + r * t.cos()).round(), (cy + r * t.sin()).round())
        })
        .collect()
}

/// Exact touchings on integer coordinates. Q is `base + x·normal + y·along` for the
/// points (x, y) of a lattice polygon C whose points other than its contact points have
/// x ≥ 1: the linear map has a positive determinant, so Q is convex, lies beyond the
/// supporting line of P through `base` and meets it exactly in the contact points.
fn touching_pair<R: Rng + ?Sized>(
    family: Family,
    n: usize,
    relation: Relation,
    rng: &mut R,
) -> (ConvexPolygon, ConvexPolygon) {
    let touch = match relation {
        Relation::Any => rng.random_bool(0.5),
        Relation::Intersecting => true,
        Relation::Disjoint => false,
    };
    // P doubled so that edge midpoints are lattice points.
    let p_pts: Vec<Point> = lattice_polygon(rng, n, 0.0, 0.0, None)
        .into_iter()
        .map(|v| Point::new(2.0 * v.x, 2.0 * v.y))
        .collect();
    let p = convex_hull(&p_pts).expect("a lattice circle has area");
    let k = p.len();
    let i = rng.random_range(0..k);
    let (prev, v, next) = (p.vertex(i + k - 1), p.vertex(i), p.vertex(i + 1));
    let right_perp = |d: Point| Point::new(d.y, -d.x);
    let sub = |a: Point, b: Point| Point::new(a.x - b.x, a.y - b.y);
    let (base, normal, along, contacts): (Point, Point, Point, &[(f64, f64)]) = match family {
        Family::SharedVertex => {
            let d = sub(next, prev);
            (v, right_perp(d), d, &[(0.0, 0.0)])
        }
        Family::VertexOnEdge => {
            let d = sub(next, v);
            let mid = Point::new((v.x + next.x) / 2.0, (v.y + next.y) / 2.0);
            (mid, right_perp(d), d, &[(0.0, 0.0)])
        }
        Family::SharedEdge => {
            let d = sub(next, v);
            (v, right_perp(d), d, &[(0.0, 0.0), (0.0, 1.0)])
        }
        _ => {
            // OverlappingEdges: Q's edge runs from the midpoint of P's edge to half an edge beyond it.
            let d = sub(next, v);
            let half = Point::new(d.x / 2.0, d.y / 2.0);
            (v, right_perp(d), half, &[(0.0, 1.0), (0.0, 3.0)])
        }
    };
    let m = (n / 2).max(3);
    let r = (m as f64).powf(1.5).max(3.0).round();
    let gap = if touch { 0.0 } else { 1.0 };
    let mut c: Vec<(f64, f64)> = lattice_polygon(rng, m, r + 1.0, 0.0, Some(r))
        .into_iter()
        .map(|p| (p.x, p.y))
        .collect();
    c.extend_from_slice(contacts);
    let q_pts: Vec<Point> = c
        .into_iter()
        .map(|(x, y)| {
            let x = x + gap;
            Point::new(
                base.x + x * normal.x + y * along.x,
                base.y + x * normal.y + y * along.y,
            )
        })
        .collect();
    let q = convex_hull(&q_pts).expect("the lattice image has area");
    let (sp, sq) = (rng.random_range(0..p.len()), rng.random_range(0..q.len()));
    (p.starting_at(sp), q.starting_at(sq))
}

fn nested_pair<R: Rng + ?Sized>(n: usize, relation: Relation, rng: &mut R) -> (ConvexPolygon, ConvexPolygon) {
    let n = n.max(3);
    let outer_radius = if n >= 5 {
        0.5 * (1.0 + 1.0 / (TAU / n as f64).cos())
    } else {
        1.5
    };
    let outer = regular_polygon(n, outer_radius);
    let mut inner = regular_polygon(n, 1.0);
    let apart = match relation {
        Relation::Any => rng.random_bool(0.5),
        Relation::Intersecting => false,
        Relation::Disjoint => true,
    };
    if apart {
        // Integer-sized moves of a unit polygon keep its area.
        inner = translate(&inner, 2.0 * outer_radius + 1.0, 0.0).expect("a moved unit polygon has area");
    }
    if rng.random_bool(0.5) {
        (outer, inner)
    } else {
        (inner, outer)
    }
}

/// P's rightmost x is `off`; Q's leftmost vertices sit at `off` (touching) or at the
/// next float above it (a one-ulp gap).
fn one_ulp_pair<R: Rng + ?Sized>(
    n: usize,
    relation: Relation,
    rng: &mut R,
) -> (ConvexPolygon, ConvexPolygon) {
    let touch = match relation {
        Relation::Any => rng.random_bool(0.5),
        Relation::Intersecting => true,
        Relation::Disjoint => false,
    };
    let exps = [None, Some(10), Some(20), Some(40), Some(52)];
    let off = exps[rng.random_range(0..exps.len())].map_or(0.0, |e| 2f64.powi(e));
    let l = convex_hull(&lattice_polygon(rng, n, 0.0, 0.0, None)).expect("lattice polygon");
    let m = convex_hull(&lattice_polygon(rng, n, 0.0, 0.0, None)).expect("lattice polygon");
    let max_x = l.vertices().iter().map(|v| v.x).fold(f64::MIN, f64::max);
    let right = *l
        .vertices()
        .iter()
        .find(|v| v.x == max_x)
        .expect("a rightmost vertex");
    let min_x = m.vertices().iter().map(|v| v.x).fold(f64::MAX, f64::min);
    let left = *m
        .vertices()
        .iter()
        .find(|v| v.x == min_x)
        .expect("a leftmost vertex");
    let p: Vec<Point> = l
        .vertices()
        .iter()
        .map(|v| Point::new(v.x - max_x + off, v.y))
        .collect();
    let contact_x = if touch { off } else { off.next_up() };
    let q: Vec<Point> = m
        .vertices()
        .iter()
        .map(|v| {
            let x = v.x - min_x;
            let y = v.y - left.y + right.y;
            Point::new(if x == 0.0 { contact_x } else { x + off }, y)
        })
        .collect();
    let p = ConvexPolygon::new(p).expect("a translated lattice polygon");
    let q = ConvexPolygon::new(q).expect("a one-ulp move of a leftmost vertex keeps convexity");
    (p, q)
}

/// Maps both polygons of a pair by `f` and validates them again; `None` when the map
/// destroys a polygon (rounding at extreme offsets can make it degenerate).
pub fn map_pair(
    pair: &(ConvexPolygon, ConvexPolygon),
    f: impl Fn(Point) -> Point,
) -> Option<(ConvexPolygon, ConvexPolygon)> {
    let p = pair.0.map(&f).ok()?;
    let q = pair.1.map(&f).ok()?;
    Some((p, q))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Exact;
    use crate::intersect::brute_force;
    use rand::SeedableRng;
    use rand::rngs::SmallRng;

    #[test]
    fn every_family_yields_valid_pairs_with_the_steered_answer() {
        let mut rng = SmallRng::seed_from_u64(0xfa11);
        for &family in Family::ALL {
            for n in [3, 4, 5, 17, 200] {
                for relation in [Relation::Intersecting, Relation::Disjoint] {
                    let (p, q) = pair(family, n, relation, &mut rng);
                    p.debug_validate().unwrap();
                    q.debug_validate().unwrap();
                    let want = relation == Relation::Intersecting;
                    assert_eq!(brute_force(Exact, &p, &q), want, "{family} n={n} {relation:?}");
                }
            }
        }
    }

    #[test]
    fn same_seed_same_pair() {
        for &family in Family::ALL {
            let a = pair(family, 50, Relation::Any, &mut SmallRng::seed_from_u64(5));
            let b = pair(family, 50, Relation::Any, &mut SmallRng::seed_from_u64(5));
            assert_eq!(a, b);
        }
    }

    #[test]
    fn ellipse_sizes_are_close_to_n() {
        let mut rng = SmallRng::seed_from_u64(1);
        let p = ellipse_polygon(&mut rng, 4096, &Density::Uniform, true);
        assert!(p.len() > 4000, "{}", p.len());
    }

    #[test]
    fn piecewise_density_stays_in_range_and_is_not_uniform() {
        let mut rng = SmallRng::seed_from_u64(2);
        let d = Density::PiecewiseLinear {
            weights: vec![0.0, 0.0, 1.0],
        };
        let xs: Vec<f64> = (0..10_000).map(|_| d.sample(&mut rng)).collect();
        assert!(xs.iter().all(|&x| (0.0..=1.0).contains(&x)));
        assert!(xs.iter().all(|&x| x >= 0.5), "no mass where the weights are zero");
        let upper = xs.iter().filter(|&&x| x > 0.75).count();
        assert!(upper > 7_000, "density rises towards 1: {upper}");
    }
}
