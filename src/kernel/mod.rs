//! Points and the geometric predicates every algorithm is written against.
//!
//! Algorithms never compare constructed coordinates when a predicate on input
//! points answers the same question: they ask a [`Kernel`] for the *sign* of a
//! polynomial in the input coordinates. Two kernels implement the trait:
//!
//! * [`Fast`] evaluates each polynomial once in plain `f64` arithmetic. It is
//!   right whenever rounding cannot flip the sign, which is almost always on
//!   random input and often wrong on nearly collinear or touching input.
//! * [`Exact`] returns the sign of the exact real value for every finite `f64`
//!   input, in three layers: a floating-point filter that decides almost every
//!   call at the cost of the fast kernel plus one comparison, Shewchuk's
//!   adaptive orientation (the `robust` crate) inside the exponent range where
//!   it is exact, and exact big-integer arithmetic on the dyadic values of the
//!   inputs everywhere else (docs/design.md, "The exact kernel's range"). The algorithms, which know the
//!   bounding boxes of the points a query reads, narrow the kernel to them: a
//!   semi-static filter (one error bound per query) in front of those layers.
//!
//! Kernels are zero-sized values chosen at compile time (`Barba.intersects_with(Exact, ..)`);
//! [`Precision`] names them at run time (the CLI's `--precision`).
//!
//! # Degeneracies
//! Predicates return three-way answers ([`Orientation`], [`Sign`]); a zero is a
//! real answer (collinear, parallel, perpendicular), never an error.

mod bbox;
#[cfg(feature = "instrument")]
mod counted;
pub(crate) mod exact;
#[cfg(feature = "serde")]
mod point_serde;
mod pose;
mod rational;
mod segment;

pub use bbox::BoundingBox;
#[cfg(feature = "instrument")]
pub use counted::Counted;
pub use exact::Exact;
pub use pose::{Pose, PoseError};
pub use rational::Rational;
pub use segment::{SegmentContact, point_on_segment, segment_contact, segments_intersect};

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Mul, Sub};
use std::str::FromStr;

/// A point (or vector) in the plane. Every finite `f64` coordinate is valid;
/// constructors that validate input reject NaN and infinities.
///
/// Serialised (serde) as `[x, y]`, the form the command line reads and writes;
/// deserialised from `[x, y]` or `{"x": x, "y": y}`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Point {
    /// The x coordinate.
    pub x: f64,
    /// The y coordinate.
    pub y: f64,
}

impl Point {
    /// The point `(x, y)`; nothing is checked (see [`Point::is_finite`]).
    #[inline]
    pub const fn new(x: f64, y: f64) -> Self {
        Point { x, y }
    }

    /// True when both coordinates are finite (neither NaN nor infinite).
    #[inline]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }

    /// The dot product `x·ox + y·oy`, rounded: a measurement, not a predicate (use
    /// [`Kernel::dot`] for an exact sign).
    #[inline]
    pub fn dot(self, o: Point) -> f64 {
        self.x * o.x + self.y * o.y
    }

    /// The cross product `x·oy − y·ox` (the z component of the 3D cross product),
    /// rounded: positive when `o` is counter-clockwise of `self`. For an exact sign use
    /// [`Kernel::orient`] or [`Kernel::cross`].
    #[inline]
    pub fn cross(self, o: Point) -> f64 {
        self.x * o.y - self.y * o.x
    }

    /// The Euclidean length of the vector, `hypot(x, y)` (no overflow or underflow in
    /// the intermediate square; within about an ulp of the exact value).
    #[inline]
    pub fn length(self) -> f64 {
        self.x.hypot(self.y)
    }

    /// The Euclidean distance to `o`: `(o - self).length()`; the difference is rounded
    /// first, so the result is exact up to those roundings and hypot's.
    #[inline]
    pub fn distance(self, o: Point) -> f64 {
        (o - self).length()
    }

    /// Lexicographic order: by x, then by y. Exact (no arithmetic).
    /// Both coordinates must be comparable (not NaN); NaN compares as equal.
    #[inline]
    pub fn lex_cmp(self, other: Point) -> Ordering {
        self.x
            .partial_cmp(&other.x)
            .unwrap_or(Ordering::Equal)
            .then(self.y.partial_cmp(&other.y).unwrap_or(Ordering::Equal))
    }
}

impl From<[f64; 2]> for Point {
    fn from([x, y]: [f64; 2]) -> Self {
        Point { x, y }
    }
}

impl From<(f64, f64)> for Point {
    fn from((x, y): (f64, f64)) -> Self {
        Point { x, y }
    }
}

impl From<Point> for [f64; 2] {
    fn from(p: Point) -> Self {
        [p.x, p.y]
    }
}

/// The sign of a real number.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sign {
    /// Below zero.
    Negative,
    /// Exactly zero.
    Zero,
    /// Above zero.
    Positive,
}

impl Sign {
    /// The sign of `x`; NaN maps to `Zero` (kernels never produce NaN on finite input
    /// except the fast kernel on overflow, where any answer is a guess).
    #[inline]
    pub fn of(x: f64) -> Sign {
        if x > 0.0 {
            Sign::Positive
        } else if x < 0.0 {
            Sign::Negative
        } else {
            Sign::Zero
        }
    }

    /// The sign of the negated number.
    #[inline]
    pub fn reverse(self) -> Sign {
        match self {
            Sign::Negative => Sign::Positive,
            Sign::Zero => Sign::Zero,
            Sign::Positive => Sign::Negative,
        }
    }

    /// As an ordering against zero.
    #[inline]
    pub(crate) fn to_ordering(self) -> Ordering {
        match self {
            Sign::Negative => Ordering::Less,
            Sign::Zero => Ordering::Equal,
            Sign::Positive => Ordering::Greater,
        }
    }
}

/// Orientation of an ordered triple of points, or of one direction relative to another.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// Clockwise: a right turn.
    Cw,
    /// The points are collinear (or some coincide).
    Collinear,
    /// Counter-clockwise: a left turn.
    Ccw,
}

impl Orientation {
    /// The orientation of the reversed triple (or of the directions swapped).
    #[inline]
    pub fn reverse(self) -> Orientation {
        match self {
            Orientation::Cw => Orientation::Ccw,
            Orientation::Collinear => Orientation::Collinear,
            Orientation::Ccw => Orientation::Cw,
        }
    }
}

impl From<Sign> for Orientation {
    #[inline]
    fn from(s: Sign) -> Self {
        match s {
            Sign::Negative => Orientation::Cw,
            Sign::Zero => Orientation::Collinear,
            Sign::Positive => Orientation::Ccw,
        }
    }
}

/// A number type a predicate polynomial can be evaluated in: plain `f64`
/// (the fast kernel), a rounding-safe interval (the exact kernel's filter) or an
/// exact dyadic big number (the exact kernel's fallback).
pub(crate) trait Ring:
    Clone + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Sized
{
    /// The exact value of a finite `f64` (or its plain copy, for `f64`).
    fn from_f64(x: f64) -> Self;
    /// The sign if it is certain, `None` when this representation cannot tell.
    fn certain_sign(&self) -> Option<Sign>;
}

impl Ring for f64 {
    #[inline]
    fn from_f64(x: f64) -> Self {
        x
    }
    #[inline]
    fn certain_sign(&self) -> Option<Sign> {
        Some(Sign::of(*self))
    }
}

/// A predicate: a polynomial in input coordinates whose sign answers a geometric question.
///
/// Write the polynomial once, generic over [`Ring`]; each kernel chooses how to
/// evaluate it. Only `+`, `-` and `*` of input coordinates are allowed, so the exact
/// kernel can always evaluate it exactly.
pub(crate) trait Polynomial {
    /// The polynomial's value, evaluated in the number type `R`.
    fn eval<R: Ring>(&self) -> R;
}

/// Kernels are the crate's own ([`Fast`], [`Exact`], their bounded forms, and with the
/// `instrument` feature `Counted`): the algorithms rely on contracts a predicate cannot
/// state in its signature (what [`Predicates::within`] may assume, which calls
/// [`Predicates::EXACT`] lets them skip), so the predicates beyond [`Kernel`]'s live in
/// this crate-private supertrait, which seals it.
pub(crate) mod sealed {
    use super::{BoundingBox, CrossProductsPoly, DirectedLine, Kernel, Orientation, Point, Polynomial, Sign};

    /// The predicates and contracts the algorithms use beyond [`Kernel`]'s.
    pub(crate) trait Predicates: Copy + Sized {
        /// Whether every predicate is exact, so that answers never contradict each other:
        /// an algorithm may then skip tests that only re-check earlier answers (the LP's
        /// final certification). `false` unless a kernel says so.
        const EXACT: bool = false;

        /// The kernel [`within`](Kernel::within) returns.
        type Within: Kernel;

        /// The same predicates for one query whose predicates only ever see points inside
        /// the union of the bounding boxes `boxes` (each `(min, max)`): the exact kernel
        /// turns the boxes into a *semi-static* filter, one error bound per query for
        /// every call, so that a certified sign costs one comparison more than the
        /// [`Fast`] kernel's, and nothing when the answer is certain. Fast returns itself.
        ///
        /// A predicate asked of the returned kernel on a point outside the boxes may
        /// answer wrongly: callers pass the boxes of every polygon whose vertices the
        /// query reads, and ask only about those vertices.
        fn within(self, boxes: [BoundingBox; 2]) -> Self::Within;

        /// The same predicates for calls whose coordinate differences, as computed in
        /// `f64`, are all at most `w` in magnitude: for `cross(a, b, c, d)` and
        /// `dot(a, b, c, d)` the differences of `b − a` and `d − c`, for `orient(a, b, c)`
        /// those of any two of the points, for [`cross_products_sign`](Kernel::cross_products_sign)
        /// those of every factor's pairs. The cross product of two edges of polygons whose
        /// [`ConvexPolygon::edge_extent`](crate::ConvexPolygon::edge_extent) is at most `w`
        /// is such a call, however far apart the edges lie: [`ExactWithin`]'s semi-static
        /// bound scaled to `w` decides such calls where a bound scaled to the boxes, much
        /// larger when the edges are short, would not. A call outside this contract may
        /// answer wrongly.
        ///
        /// The default is [`within`](Kernel::within) of a box of side `w`, which is right
        /// for kernels whose `within` relies only on the differences of points in the
        /// boxes being at most the boxes' side (both kernels of this crate; [`Fast`]
        /// returns itself).
        #[inline]
        fn within_differences(self, w: f64) -> Self::Within {
            let side = BoundingBox::new(Point::new(0.0, 0.0), Point::new(w, w));
            self.within([side, side])
        }

        /// `orient(*a, *b, *c)` for points a caller reads from memory (a polygon's
        /// vertices in a binary search): the same answer. [`ExactWithin`] hands the
        /// references, not the values, to its out-of-line path, so the caller need not keep
        /// a copy of each loaded point beside the differences it computes from it (with
        /// two-operand SSE instructions, one register copy per point and call). The default
        /// calls [`orient`](Kernel::orient).
        #[inline]
        fn orient_of(self, a: &Point, b: &Point, c: &Point) -> Orientation
        where
            Self: Kernel,
        {
            self.orient(*a, *b, *c)
        }

        /// `orient(line.from(), line.to(), c)`, for many points `c` against one line: a
        /// kernel may use the line's direction, computed once by [`DirectedLine::new`],
        /// instead of computing two differences per call. The answer is the same
        /// orientation (exact under [`Exact`] and [`ExactWithin`]); the default calls
        /// [`orient`](Kernel::orient).
        #[inline]
        fn orient_line(self, line: &DirectedLine, c: Point) -> Orientation
        where
            Self: Kernel,
        {
            self.orient(line.from, line.to, c)
        }

        /// The sign of a predicate polynomial.
        fn sign<P: Polynomial>(self, poly: &P) -> Sign;

        /// [`cross`](Kernel::cross) for call sites whose directions are often short next to
        /// the boxes of a [`within`](Kernel::within) kernel: the same answer, possibly
        /// decided differently. [`ExactWithin`]'s bound is scaled to the
        /// boxes, so it seldom decides the cross product of two short edges of a large
        /// polygon (Dobkin's and Barba's pruning tests at large n); it overrides this to try
        /// [`Exact`]'s static filter inline before going out of line, which would cost every
        /// other call registers and code. The default is `cross`.
        #[inline]
        fn cross_of_short_edges(self, a: Point, b: Point, c: Point, d: Point) -> Orientation
        where
            Self: Kernel,
        {
            self.cross(a, b, c, d)
        }

        /// The sign of `C₀·C₁ + C₂·C₃`, a polynomial of degree 4, where each
        /// `Cᵢ = (bᵢ − aᵢ) × (dᵢ − cᵢ)` is the cross product of the directions of the point
        /// pairs in `factors[i] = [aᵢ, bᵢ, cᵢ, dᵢ]`. [`line_meet_side`] and the slope
        /// comparison of Chazelle–Dobkin are of this form. A method so that a kernel can
        /// add a static filter.
        #[inline]
        fn cross_products_sign(self, factors: [[Point; 4]; 4]) -> Sign {
            self.sign(&CrossProductsPoly(factors))
        }

        /// [`cross_products_sign`](Kernel::cross_products_sign) for call sites whose
        /// factors each cross a short direction with a long one, the short one first: in
        /// every `factors[i] = [aᵢ, bᵢ, cᵢ, dᵢ]`, `bᵢ − aᵢ` is an edge of a large polygon and
        /// `dᵢ − cᵢ` may span the boxes of a [`within`](Kernel::within) kernel (the slope
        /// comparison of Chazelle–Dobkin). The same answer, possibly decided differently:
        /// [`ExactWithin`] scales its bound to the lengths of the short directions, which
        /// decides at large n the calls its box-sized bound leaves open. The default is
        /// `cross_products_sign`.
        #[inline]
        fn cross_products_sign_of_short_edges(self, factors: [[Point; 4]; 4]) -> Sign {
            self.cross_products_sign(factors)
        }

        /// The same kernel for a query whose degree-4 calls are all
        /// [`cross_products_sign_of_short_edges`](Kernel::cross_products_sign_of_short_edges)
        /// calls (or [`cross_products_sign`](Kernel::cross_products_sign) calls of that
        /// form) whose short directions `bᵢ − aᵢ` have computed coordinate differences at
        /// most `e` in magnitude (edges of polygons whose
        /// [`ConvexPolygon::edge_extent`](crate::ConvexPolygon::edge_extent) is at most `e()`),
        /// the long ones staying within this kernel's contract. [`ExactWithin`] then
        /// decides those calls with one per-query bound scaled to `e()`, the comparisons the
        /// fast kernel makes, instead of computing a bound per call. A degree-4 call
        /// outside this contract may answer wrongly; the other predicates are unchanged.
        /// `e` is called only by a kernel that uses it. The default returns the kernel
        /// itself.
        #[inline]
        fn within_short_edges(self, e: impl FnOnce() -> f64) -> Self {
            let _ = e;
            self
        }
    }
}

/// Geometric predicates, answered either quickly ([`Fast`]) or exactly ([`Exact`]).
///
/// All methods take finite coordinates. `orient` is the hot predicate and has a
/// dedicated implementation; the others evaluate a predicate polynomial.
///
/// The trait is sealed: the crate's kernels implement it, and no other type can (the
/// algorithms rely on contracts a signature cannot state, such as what a kernel
/// narrowed to a query's bounding boxes may assume). To count the predicates an algorithm
/// asks, the `instrument` feature has `kernel::Counted`.
#[allow(private_bounds)] // the supertrait seals it: see `sealed`
pub trait Kernel: sealed::Predicates + Copy + Clone + Default + fmt::Debug + Send + Sync + 'static {
    /// A short name (`"fast"` or `"exact"`).
    const NAME: &'static str;

    /// Orientation of the triple (a, b, c): the sign of (b − a) × (c − a).
    fn orient(self, a: Point, b: Point, c: Point) -> Orientation;

    /// The sign of the cross product (b − a) × (d − c): `Ccw` when direction d − c
    /// points counter-clockwise from direction b − a, `Collinear` when parallel.
    #[inline]
    fn cross(self, a: Point, b: Point, c: Point, d: Point) -> Orientation {
        self.sign(&CrossPoly(a, b, c, d)).into()
    }

    /// The sign of the dot product (b − a) · (d − c).
    #[inline]
    fn dot(self, a: Point, b: Point, c: Point, d: Point) -> Sign {
        self.sign(&DotPoly(a, b, c, d))
    }
}

/// A directed line through two points with its direction `to − from` (computed once,
/// in `f64`), for [`Kernel::orient_line`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct DirectedLine {
    from: Point,
    to: Point,
    /// `(to.x − from.x, to.y − from.y)`, each rounded: the kernels' filters bound the
    /// error of exactly these differences.
    dir: Point,
}

impl DirectedLine {
    /// The line from `from` to `to`.
    #[inline]
    pub fn new(from: Point, to: Point) -> Self {
        DirectedLine {
            from,
            to,
            dir: Point::new(to.x - from.x, to.y - from.y),
        }
    }

    /// The first point.
    #[inline]
    pub fn from(&self) -> Point {
        self.from
    }

    /// The second point.
    #[inline]
    pub fn to(&self) -> Point {
        self.to
    }

    /// The two products of `orient(from, to, c)` with `from` as the pivot:
    /// (to − from) × (c − from) = left − right. The same shape as `orient`'s own
    /// products, which take `c` as the pivot: `orient(from, to, c)` equals
    /// `orient(to, c, from)`, whose products these are, so the same error bounds hold.
    #[inline(always)]
    pub(crate) fn products(&self, c: Point) -> (f64, f64) {
        let (a, d) = (self.from, self.dir);
        (d.x * (c.y - a.y), d.y * (c.x - a.x))
    }
}

/// The polynomial behind [`Kernel::cross_products_sign`].
pub(crate) struct CrossProductsPoly(pub(crate) [[Point; 4]; 4]);
impl Polynomial for CrossProductsPoly {
    #[inline]
    fn eval<R: Ring>(&self) -> R {
        let f = R::from_f64;
        let cross = |[a, b, c, d]: [Point; 4]| {
            (f(b.x) - f(a.x)) * (f(d.y) - f(c.y)) - (f(b.y) - f(a.y)) * (f(d.x) - f(c.x))
        };
        let [c0, c1, c2, c3] = self.0;
        cross(c0) * cross(c1) + cross(c2) * cross(c3)
    }
}

pub(crate) struct CrossPoly(
    pub(crate) Point,
    pub(crate) Point,
    pub(crate) Point,
    pub(crate) Point,
);
impl Polynomial for CrossPoly {
    #[inline]
    fn eval<R: Ring>(&self) -> R {
        let f = R::from_f64;
        let (a, b, c, d) = (self.0, self.1, self.2, self.3);
        (f(b.x) - f(a.x)) * (f(d.y) - f(c.y)) - (f(b.y) - f(a.y)) * (f(d.x) - f(c.x))
    }
}

pub(crate) struct DotPoly(
    pub(crate) Point,
    pub(crate) Point,
    pub(crate) Point,
    pub(crate) Point,
);
impl Polynomial for DotPoly {
    #[inline]
    fn eval<R: Ring>(&self) -> R {
        let f = R::from_f64;
        let (a, b, c, d) = (self.0, self.1, self.2, self.3);
        (f(b.x) - f(a.x)) * (f(d.x) - f(c.x)) + (f(b.y) - f(a.y)) * (f(d.y) - f(c.y))
    }
}

/// Where the intersection point X of the lines ab and cd lies relative to the
/// directed line ef: `Ccw` when X is left of e→f, `Cw` when right, `Collinear` on it.
///
/// X is never constructed: the sign is that of the degree-4 polynomial
/// `D·((f−e)×(a−e)) + N·((f−e)×(b−a))` with `D = (b−a)×(d−c)` and `N = (c−a)×(d−c)`,
/// multiplied by the sign of `D` (X = a + (N/D)(b−a)), asked of
/// [`Kernel::cross_products_sign`]. Exact under [`Exact`].
/// The lines must not be parallel (`D ≠ 0`); for parallel lines the answer is `Collinear`.
#[inline(always)]
pub(crate) fn line_meet_side<K: Kernel>(
    k: K,
    (a, b): (Point, Point),
    (c, d): (Point, Point),
    (e, f): (Point, Point),
) -> Orientation {
    let den = k.cross(a, b, c, d);
    if den == Orientation::Collinear {
        return Orientation::Collinear;
    }
    let s: Orientation = k
        .cross_products_sign([[a, b, c, d], [e, f, e, a], [a, c, c, d], [e, f, a, b]])
        .into();
    if den == Orientation::Ccw { s } else { s.reverse() }
}

/// `K` with [`Kernel::cross`] answered by [`Kernel::cross_of_short_edges`]: for a whole
/// function whose cross products are of short edges, without changing its helpers.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ShortEdges<K>(pub(crate) K);

impl<K: Kernel> Kernel for ShortEdges<K> {
    const NAME: &'static str = K::NAME;

    #[inline]
    fn orient(self, a: Point, b: Point, c: Point) -> Orientation {
        self.0.orient(a, b, c)
    }

    #[inline]
    fn cross(self, a: Point, b: Point, c: Point, d: Point) -> Orientation {
        self.0.cross_of_short_edges(a, b, c, d)
    }

    #[inline]
    fn dot(self, a: Point, b: Point, c: Point, d: Point) -> Sign {
        self.0.dot(a, b, c, d)
    }
}

impl<K: Kernel> sealed::Predicates for ShortEdges<K> {
    const EXACT: bool = K::EXACT;

    type Within = ShortEdges<K::Within>;

    #[inline]
    fn within(self, boxes: [BoundingBox; 2]) -> Self::Within {
        ShortEdges(self.0.within(boxes))
    }

    #[inline]
    fn within_differences(self, w: f64) -> Self::Within {
        ShortEdges(self.0.within_differences(w))
    }

    #[inline]
    fn orient_line(self, line: &DirectedLine, c: Point) -> Orientation {
        self.0.orient_line(line, c)
    }

    #[inline]
    fn orient_of(self, a: &Point, b: &Point, c: &Point) -> Orientation {
        self.0.orient_of(a, b, c)
    }

    #[inline]
    fn sign<P: Polynomial>(self, poly: &P) -> Sign {
        self.0.sign(poly)
    }

    #[inline]
    fn cross_of_short_edges(self, a: Point, b: Point, c: Point, d: Point) -> Orientation {
        self.0.cross_of_short_edges(a, b, c, d)
    }

    #[inline]
    fn cross_products_sign(self, factors: [[Point; 4]; 4]) -> Sign {
        self.0.cross_products_sign(factors)
    }

    #[inline]
    fn cross_products_sign_of_short_edges(self, factors: [[Point; 4]; 4]) -> Sign {
        self.0.cross_products_sign_of_short_edges(factors)
    }

    #[inline]
    fn within_short_edges(self, e: impl FnOnce() -> f64) -> Self {
        ShortEdges(self.0.within_short_edges(e))
    }
}

/// Plain `f64` predicates: one floating-point evaluation, no error analysis.
///
/// # Precision
/// The answer is wrong whenever rounding flips the sign: nearly collinear
/// triples, exact touchings at large offsets, coordinates beyond about 2^±500
/// (overflow and underflow). Measured per input family in docs/results.md.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Fast;

impl Kernel for Fast {
    const NAME: &'static str = "fast";

    #[inline]
    fn orient(self, a: Point, b: Point, c: Point) -> Orientation {
        let det = (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
        Sign::of(det).into()
    }
}

impl sealed::Predicates for Fast {
    type Within = Fast;

    #[inline]
    fn within(self, _boxes: [BoundingBox; 2]) -> Fast {
        self
    }

    #[inline]
    fn within_differences(self, _w: f64) -> Fast {
        self
    }

    #[inline]
    fn sign<P: Polynomial>(self, poly: &P) -> Sign {
        Sign::of(poly.eval::<f64>())
    }
}

/// The run-time name of a kernel (the CLI's `--precision`). Algorithms are
/// generic over [`Kernel`]; a `match` on a `Precision` picks the instance.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Precision {
    /// The [`Fast`] kernel.
    Fast,
    /// The [`Exact`] kernel (the default).
    #[default]
    Exact,
}

impl Precision {
    /// Both kernels, fast first.
    pub const ALL: [Precision; 2] = [Precision::Fast, Precision::Exact];

    /// The kernel's [`Kernel::NAME`], as `--precision` spells it.
    pub fn name(self) -> &'static str {
        match self {
            Precision::Fast => Fast::NAME,
            Precision::Exact => Exact::NAME,
        }
    }
}

impl fmt::Display for Precision {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Precision {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Precision::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| format!("unknown precision '{s}' (valid: fast, exact)"))
    }
}

/// Vector arithmetic on points, in plain `f64`: each coordinate rounded to nearest. These
/// construct new coordinates, so they are not exact; geometric decisions belong to a
/// [`Kernel`] predicate on the original points (`orient(a, b, c)`, not the sign of a
/// cross product of `b - a` and `c - a`).
///
/// ```
/// use polysect::Point;
/// let (a, b) = (Point::new(1.0, 2.0), Point::new(0.5, -1.0));
/// assert_eq!(a + b, Point::new(1.5, 1.0));
/// assert_eq!(a - b, Point::new(0.5, 3.0));
/// assert_eq!(-a, Point::new(-1.0, -2.0));
/// assert_eq!(a * 2.0, Point::new(2.0, 4.0));
/// assert_eq!(2.0 * a, a * 2.0);
/// assert_eq!(a / 2.0, Point::new(0.5, 1.0));
/// let mut c = a;
/// c += b;
/// c -= a;
/// c *= 4.0;
/// c /= 2.0;
/// assert_eq!(c, Point::new(1.0, -2.0));
/// assert_eq!((a.dot(b), a.cross(b)), (-1.5, -2.0));
/// assert_eq!(Point::new(3.0, 4.0).length(), 5.0);
/// assert_eq!(Point::new(1.0, 1.0).distance(Point::new(4.0, 5.0)), 5.0);
/// assert_eq!(a.to_string(), "(1, 2)");
/// ```
impl Add for Point {
    type Output = Point;
    #[inline]
    fn add(self, o: Point) -> Point {
        Point::new(self.x + o.x, self.y + o.y)
    }
}

impl Sub for Point {
    type Output = Point;
    #[inline]
    fn sub(self, o: Point) -> Point {
        Point::new(self.x - o.x, self.y - o.y)
    }
}

impl std::ops::Neg for Point {
    type Output = Point;
    #[inline]
    fn neg(self) -> Point {
        Point::new(-self.x, -self.y)
    }
}

/// Scaling by a number: `p * s` multiplies both coordinates by `s` (rounded).
impl Mul<f64> for Point {
    type Output = Point;
    #[inline]
    fn mul(self, s: f64) -> Point {
        Point::new(self.x * s, self.y * s)
    }
}

/// Scaling by a number from the left: `s * p` is `p * s`.
impl Mul<Point> for f64 {
    type Output = Point;
    #[inline]
    fn mul(self, p: Point) -> Point {
        p * self
    }
}

/// Division by a number: `p / s` divides both coordinates by `s` (rounded).
impl std::ops::Div<f64> for Point {
    type Output = Point;
    #[inline]
    fn div(self, s: f64) -> Point {
        Point::new(self.x / s, self.y / s)
    }
}

impl std::ops::AddAssign for Point {
    #[inline]
    fn add_assign(&mut self, o: Point) {
        *self = *self + o;
    }
}

impl std::ops::SubAssign for Point {
    #[inline]
    fn sub_assign(&mut self, o: Point) {
        *self = *self - o;
    }
}

impl std::ops::MulAssign<f64> for Point {
    #[inline]
    fn mul_assign(&mut self, s: f64) {
        *self = *self * s;
    }
}

impl std::ops::DivAssign<f64> for Point {
    #[inline]
    fn div_assign(&mut self, s: f64) {
        *self = *self / s;
    }
}

/// `(x, y)`, each coordinate in the shortest form that parses back to the same `f64`:
/// plain decimals between 10^-5 and 10^16 (`(4.5, 2)`), scientific notation beyond
/// (`(1.7976931348623157e308, 5e-324)`), so huge and tiny values stay short. A
/// precision (`{:.2}`) applies to both coordinates.
impl fmt::Display for Point {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let one = |f: &mut fmt::Formatter<'_>, v: f64| match f.precision() {
            Some(digits) => write!(f, "{v:.digits$}"),
            None if v == 0.0 || !v.is_finite() || (1e-5..1e16).contains(&v.abs()) => write!(f, "{v}"),
            None => write!(f, "{v:e}"),
        };
        f.write_str("(")?;
        one(f, self.x)?;
        f.write_str(", ")?;
        one(f, self.y)?;
        f.write_str(")")
    }
}

#[cfg(test)]
mod tests;
