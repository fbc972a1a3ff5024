//! Area and centroid: constructed values, computed with error-free transformations and
//! compensated sums.
//!
//! # Formula
//! With o the first vertex and dᵢ = vᵢ − o, twice the signed area is the sum of the fan
//! cross products cᵢ = dᵢ × dᵢ₊₁ (i = 1 … n−2), and the centroid is
//! o + Σ cᵢ (dᵢ + dᵢ₊₁) / (3 Σ cᵢ). Working relative to a vertex removes the
//! cancellation of the textbook shoelace sum at large offsets (a unit square at 2^50
//! has shoelace terms near 2^100 and an area of 1); for a convex polygon every cᵢ is
//! positive, so the sum itself does not cancel.
//!
//! # Precision
//! * Each difference dᵢ is kept exactly as a sum of two `f64` (two-sum), each product
//!   of the leading parts exactly as a sum of two `f64` (Dekker's two-product), the
//!   remaining small products in plain floating point (they are below 2^−52 of the
//!   leading ones), and everything is added with a compensated sum (two-sum of the
//!   running total, the errors added apart, as in Ogita, Rump and Oishi's `Sum2`).
//!   The computed area A′ then satisfies
//!   |A′ − A| ≤ 2^−53·A + 4n²·2^−106·P, where P is the sum of |dᵢ.x·dᵢ₊₁.y| +
//!   |dᵢ.y·dᵢ₊₁.x| (so P/A is a condition number: about n for a regular polygon, large
//!   only for needles). tests/geometry/queries.rs checks the bound against the exact area
//!   computed with big integers; every area there came out correctly rounded.
//! * The centroid is a quotient of constructed sums; each term cᵢ (dᵢ + dᵢ₊₁) is
//!   rounded, so per coordinate |C′ − C| ≤ 4·2^−53·D·Q + ½ ulp(C), where D is the
//!   largest |dᵢ| coordinate (at most the polygon's width) and Q = Σ|cᵢ| / |Σ cᵢ|
//!   (1 for convex polygons). It lies in the polygon unless the polygon is thinner
//!   than that error.
//! * A simple polygon's signed area has the **exact** sign: its orientation, decided by
//!   the exact kernel ([`SimplePolygon::is_ccw`]); the magnitude carries the bound above
//!   (with cancellation possible, since its cᵢ differ in sign).
//!
//! # Range
//! Every finite input is accepted. The differences are scaled by a power of two
//! (exact) so that the largest is about 1: no intermediate overflows, even for
//! coordinates near `f64::MAX`, and the centroid is finite for every polygon. The area
//! itself overflows to `+∞` when it exceeds `f64::MAX` and is rounded into the
//! subnormal range (losing relative accuracy) below `f64::MIN_POSITIVE`; products of
//! differences smaller than 2^−484 of the largest are not exact (their share of the
//! area is below 2^−968 of the square of the polygon's extent).
//!
//! # Complexity
//! O(n) for n vertices (two passes over the boundary); no allocation. On a linked
//! polygon the passes walk the list.

use crate::kernel::Point;
use crate::polygon::{ConvexPolygon, LinkedPolygon, SimplePolygon};

/// Knuth's two-sum: `s + e == a + b` exactly, `s = fl(a + b)`.
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Veltkamp's split of `a` into two halves of 26 bits each (|a| ≤ 2^996).
#[inline]
fn split(a: f64) -> (f64, f64) {
    let c = 134_217_729.0 * a; // 2^27 + 1
    let hi = c - (c - a);
    (hi, a - hi)
}

/// Dekker's two-product: `p + e == a · b` exactly (no overflow, no underflow below
/// 2^−969), `p = fl(a · b)`.
#[inline]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let ((ah, al), (bh, bl)) = (split(a), split(b));
    (p, al * bl - (((p - ah * bh) - al * bh) - ah * bl))
}

/// A compensated sum: the running total and, apart, the sum of its rounding errors.
#[derive(Clone, Copy, Default)]
struct Compensated {
    hi: f64,
    lo: f64,
}

impl Compensated {
    #[inline]
    fn add(&mut self, x: f64) {
        let (s, e) = two_sum(self.hi, x);
        self.hi = s;
        self.lo += e;
    }

    #[inline]
    fn value(self) -> f64 {
        self.hi + self.lo
    }
}

/// `x · 2^e`, by steps that neither overflow nor underflow before the last one.
fn scale(mut x: f64, mut e: i32) -> f64 {
    while e > 1000 {
        x *= 2f64.powi(1000);
        e -= 1000;
    }
    while e < -1000 {
        x *= 2f64.powi(-1000);
        e += 1000;
    }
    x * 2f64.powi(e)
}

/// The base-2 exponent of a positive finite `x`: 2^e ≤ x < 2^(e+1).
fn exponent(x: f64) -> i32 {
    let biased = ((x.to_bits() >> 52) & 0x7ff) as i32;
    if biased == 0 {
        // Subnormal: 2^-1074 times the fraction.
        -1074 + (63 - (x.to_bits() & ((1 << 52) - 1)).leading_zeros() as i32)
    } else {
        biased - 1023
    }
}

/// Twice the signed area and the centroid of the closed chain `points` (at least three
/// points, all finite, not all equal), as in the module docs.
struct Moments {
    twice_area: f64,
    centroid: Point,
}

fn moments<I: Iterator<Item = Point> + Clone>(points: I) -> Moments {
    let mut it = points.clone();
    let o = it.next().expect("a polygon has vertices");
    // 1. The largest coordinate difference from o, to scale by a power of two. When a
    //    difference overflows, every coordinate is first multiplied by 1/4 (exact for
    //    all but subnormal coordinates, whose share is below 2^-2000 of the extent).
    let widest = |pre: f64| {
        let o = Point::new(o.x * pre, o.y * pre);
        points
            .clone()
            .map(|p| ((p.x * pre - o.x).abs()).max((p.y * pre - o.y).abs()))
            .fold(0.0, f64::max)
    };
    let mut pre = 1.0;
    let mut m = widest(pre);
    if !m.is_finite() {
        pre = 0.25;
        m = widest(pre);
    }
    if m == 0.0 {
        return Moments {
            twice_area: 0.0,
            centroid: o,
        };
    }
    // Differences times 2^k lie in (−2, 2), with 2^k split into two safe factors.
    let k = -exponent(m);
    let (f1, f2) = (2f64.powi(k / 2), 2f64.powi(k - k / 2));
    let po = Point::new(o.x * pre, o.y * pre);
    let diff = |p: Point| {
        let (sx, ex) = two_sum(p.x * pre, -po.x);
        let (sy, ey) = two_sum(p.y * pre, -po.y);
        ((sx * f1 * f2, ex * f1 * f2), (sy * f1 * f2, ey * f1 * f2))
    };
    // 2. The fan sums.
    let mut area = Compensated::default();
    let (mut nx, mut ny) = (Compensated::default(), Compensated::default());
    let mut prev = diff(it.next().expect("a polygon has three vertices"));
    for p in it {
        let d = diff(p);
        let ((ax, eax), (ay, eay)) = prev;
        let ((bx, ebx), (by, eby)) = d;
        // (ax + eax)(by + eby) − (ay + eay)(bx + ebx), the leading products exactly.
        let (p1, e1) = two_prod(ax, by);
        let (p2, e2) = two_prod(ay, bx);
        let small = (e1 - e2) + ((ax * eby + eax * by) - (ay * ebx + eay * bx)) + (eax * eby - eay * ebx);
        let (s, e) = two_sum(p1, -p2);
        let rest = e + small;
        area.add(s);
        area.lo += rest;
        let c = s + rest;
        nx.add(c * (ax + bx));
        ny.add(c * (ay + by));
        prev = d;
    }
    let twice = area.value();
    let unscale = -k;
    // o + c, added in the pre-scaled units (where nothing overflows), then scaled back;
    // a centroid lies in the polygon's box, so only rounding could pass f64::MAX.
    let place = |o: f64, c: f64| ((o * pre + scale(c, unscale)) / pre).clamp(-f64::MAX, f64::MAX);
    let centroid = if twice != 0.0 {
        let (cx, cy) = (nx.value() / (3.0 * twice), ny.value() / (3.0 * twice));
        Point::new(place(o.x, cx), place(o.y, cy))
    } else {
        o
    };
    Moments {
        twice_area: scale(scale(twice, unscale), unscale) / (pre * pre),
        centroid,
    }
}

/// The points of a linked polygon in boundary order, as a cloneable iterator.
fn linked_points(p: &LinkedPolygon) -> impl Iterator<Item = Point> + Clone + '_ {
    let mut pos = 0;
    (0..p.len()).map(move |_| {
        let here = pos;
        pos = p.next_at(pos);
        p.point_at(here)
    })
}

impl ConvexPolygon {
    /// The area, computed with compensated sums: relative error about 2^−53 (every
    /// area in tests/geometry/queries.rs equals the exact area rounded to nearest). `+∞` when
    /// the area exceeds `f64::MAX`.
    ///
    /// # Complexity
    /// O(n) for n vertices; no allocation.
    ///
    /// # Precision
    /// A constructed value (not exact): |A′ − A| ≤ 2^−53·A + 4n²·2^−106·P, where P is
    /// the sum of the magnitudes of the fan products |dᵢ.x·dᵢ₊₁.y| + |dᵢ.y·dᵢ₊₁.x| with
    /// dᵢ = vᵢ − v₀ (about n·A for round polygons, more for needles; see
    /// [`polygon::queries`](crate::polygon::queries)). Differences are taken exactly, so
    /// there is no cancellation at large offsets: a unit square at 2^50 has area
    /// exactly 1.
    ///
    /// ```
    /// use polysect::ConvexPolygon;
    /// let o = 2f64.powi(50);
    /// let p = ConvexPolygon::new([[o, o], [o + 1.0, o], [o + 1.0, o + 1.0], [o, o + 1.0]])?;
    /// assert_eq!(p.area(), 1.0);
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn area(&self) -> f64 {
        moments(self.vertices().iter().copied()).twice_area / 2.0
    }

    /// The centroid (centre of mass of the region), computed with compensated sums.
    ///
    /// # Complexity
    /// O(n) for n vertices; no allocation.
    ///
    /// # Precision
    /// A constructed point: per coordinate within 4·2^−53·D + ½ ulp of the true
    /// centroid, where D is the polygon's extent from its first vertex. Always finite,
    /// even when the area overflows.
    ///
    /// ```
    /// use polysect::{ConvexPolygon, Point};
    /// let t = ConvexPolygon::new([[0.0, 0.0], [3.0, 0.0], [0.0, 3.0]])?;
    /// assert_eq!(t.centroid(), Point::new(1.0, 1.0));
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn centroid(&self) -> Point {
        moments(self.vertices().iter().copied()).centroid
    }
}

impl LinkedPolygon {
    /// The area, as [`ConvexPolygon::area`] (same value for the same vertices from the
    /// same start, [`first`](Self::first)): O(n), walking the list.
    ///
    /// ```
    /// use polysect::LinkedPolygon;
    /// let p = LinkedPolygon::from_points([[0.0, 0.0], [4.0, 0.0], [4.0, 3.0]])?;
    /// assert_eq!(p.area(), 6.0);
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn area(&self) -> f64 {
        moments(linked_points(self)).twice_area / 2.0
    }

    /// The centroid, as [`ConvexPolygon::centroid`]: O(n), walking the list.
    ///
    /// ```
    /// use polysect::{LinkedPolygon, Point};
    /// let p = LinkedPolygon::from_points([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])?;
    /// assert_eq!(p.centroid(), Point::new(1.0, 1.0));
    /// # Ok::<(), polysect::PolygonError>(())
    /// ```
    pub fn centroid(&self) -> Point {
        moments(linked_points(self)).centroid
    }
}

impl SimplePolygon {
    /// The area (positive in either orientation), computed with compensated sums.
    ///
    /// # Complexity
    /// O(n) for n vertices; no allocation.
    ///
    /// # Precision
    /// A constructed value: |A′ − A| ≤ 2^−53·A + 4n²·2^−106·P as for
    /// [`ConvexPolygon::area`]; on a non-convex polygon P/A can also grow through
    /// cancellation between fan triangles of opposite signs.
    ///
    /// ```
    /// use polysect::SimplePolygon;
    /// // An L shape, clockwise.
    /// let l = SimplePolygon::new([[0.0, 0.0], [0.0, 2.0], [1.0, 2.0], [1.0, 1.0], [2.0, 1.0], [2.0, 0.0]])?;
    /// assert_eq!(l.area(), 3.0);
    /// # Ok::<(), polysect::SimplePolygonError>(())
    /// ```
    pub fn area(&self) -> f64 {
        moments(self.vertices().iter().copied()).twice_area.abs() / 2.0
    }

    /// The signed area: positive when the boundary runs counter-clockwise, negative
    /// when clockwise. The **sign is exact** ([`is_ccw`](Self::is_ccw), an exact
    /// predicate), the magnitude is [`area`](Self::area).
    ///
    /// ```
    /// use polysect::SimplePolygon;
    /// let cw = SimplePolygon::new([[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]])?;
    /// assert_eq!(cw.signed_area(), -0.5);
    /// # Ok::<(), polysect::SimplePolygonError>(())
    /// ```
    pub fn signed_area(&self) -> f64 {
        let a = self.area();
        if self.is_ccw() { a } else { -a }
    }

    /// The centroid of the region, computed with compensated sums: per coordinate
    /// within 4·2^−53·D·Q + ½ ulp of the true centroid (D the extent from the first
    /// vertex, Q = Σ|cᵢ| / |Σ cᵢ| over the fan triangles, module docs). For a
    /// non-convex polygon it may lie outside the polygon (an L shape's centroid can).
    ///
    /// ```
    /// use polysect::SimplePolygon;
    /// let l = SimplePolygon::new([[0.0, 0.0], [3.0, 0.0], [3.0, 1.0], [1.0, 1.0], [1.0, 3.0], [0.0, 3.0]])?;
    /// let c = l.centroid(); // (1.1, 1.1), up to rounding
    /// assert!((c.x - 1.1).abs() < 1e-15 && (c.y - 1.1).abs() < 1e-15);
    /// # Ok::<(), polysect::SimplePolygonError>(())
    /// ```
    pub fn centroid(&self) -> Point {
        moments(self.vertices().iter().copied()).centroid
    }
}
