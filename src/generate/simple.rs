//! Random simple polygons, as in the crossings experiments (`docs/crossings.md`): point sets drawn from a uniform,
//! normal or integer-grid distribution, joined into a simple polygon by **space
//! partitioning** (after Auer and Held), by an angular sort into a **star-shaped**
//! polygon, or by the **angular sort of the lecture notes on convex hulls** around a
//! pivot of the set.
//!
//! # Space partitioning
//! Choose two points s_f, s_l at random; the line through them splits the rest into
//! the points on its left and on its right. Each side is joined into a chain from
//! one of them to the other by the recursion: for a set S with chain ends f and l,
//! if S has no point besides f and l the chain is the segment fl; otherwise choose
//! s ∈ S at random and a random point r on segment fl, split S by the line through
//! s and r into the points on f's side (points on the line included) and those on
//! l's side, and concatenate the chains f → s and s → l of the two halves. The
//! halves' convex hulls share only s, so the chains meet only there and the polygon
//! is simple. The recursion runs on an explicit stack (no depth limit); expected
//! time O(n log n), worst case O(n²) (unlucky splits, as in quicksort).
//!
//! # Star-shaped polygons
//! The points are sorted by angle around the distribution's centre (exact
//! comparisons: half-plane, then orientation; points on one ray by distance).
//!
//! # Angular sort around a pivot (the lecture notes)
//! The pivot is a point of the set, the lowest (then leftmost), and is kept; the
//! others follow by angle around it, nearer first on a ray, except on the last ray,
//! where the farther come first so that the boundary can return to the pivot
//! ([`crate::polygon::angular_order`], exact). Every point of the set is a vertex.
//!
//! # Degeneracies
//! Sides and orders are decided by the [`Exact`] kernel. Collinear triples (always
//! possible on a grid, with probability ~0 for real coordinates) can make a
//! construction degenerate; every result is validated by [`SimplePolygon::new`] and
//! a failed attempt is redrawn, up to [`MAX_ATTEMPTS`] times.

use super::MAX_VERTICES;
use crate::kernel::{Exact, Kernel, Orientation, Point};
use crate::polygon::{SimplePolygon, angular_order};
use rand::Rng;
use std::collections::HashSet;
use std::f64::consts::TAU;
use std::fmt;
use std::str::FromStr;

/// How many point sets a generator draws before giving up.
pub const MAX_ATTEMPTS: usize = 200;

/// The distribution of the vertices (the crossings experiments' two data sets, plus a grid for
/// degenerate tests).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PointDistribution {
    /// x and y uniform in [min, max) (the crossings experiments: min = 0, max = Δ).
    Uniform {
        /// Lower bound of each coordinate.
        min: f64,
        /// Upper bound of each coordinate (excluded).
        max: f64,
    },
    /// x and y normal with the given mean and standard deviation (the crossings experiments: μ = 0),
    /// by the Box–Muller transform.
    Normal {
        /// Mean of each coordinate.
        mean: f64,
        /// Standard deviation of each coordinate.
        sigma: f64,
    },
    /// x and y uniform integers in [0, size): many equal x, collinear triples,
    /// shared vertices and overlapping edges between two polygons.
    Grid {
        /// Number of integer values per coordinate.
        size: u32,
    },
}

/// The largest radius r = √(−2 ln u₁) of a Box–Muller sample: u₁ = 1 − U with U a
/// multiple of 2^-53 below 1, so u₁ ≥ 2^-53 and r ≤ √(106 ln 2) < 8.58.
const BOX_MULLER_MAX_RADIUS: f64 = 8.58;

impl PointDistribution {
    /// One random point. Never panics; for parameters that [`validate`](Self::validate)
    /// refuses the point is unspecified and may be NaN or infinite.
    pub fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> Point {
        match *self {
            PointDistribution::Uniform { min, max } => {
                Point::new(uniform(min, max, rng), uniform(min, max, rng))
            }
            PointDistribution::Normal { mean, sigma } => {
                // Box–Muller: u1 in (0, 1] keeps the logarithm finite.
                let u1: f64 = 1.0 - rng.random::<f64>();
                let u2: f64 = rng.random();
                let r = (-2.0 * u1.ln()).sqrt();
                let (s, c) = (TAU * u2).sin_cos();
                Point::new(mean + sigma * r * c, mean + sigma * r * s)
            }
            PointDistribution::Grid { size: 0 } => Point::new(f64::NAN, f64::NAN),
            PointDistribution::Grid { size } => {
                Point::new(rng.random_range(0..size) as f64, rng.random_range(0..size) as f64)
            }
        }
    }

    /// Whether every sample is a finite point: a finite non-empty uniform range (its
    /// width may exceed `f64::MAX`); a finite mean and a sigma > 0 small enough that
    /// mean ± 8.58·sigma, the farthest a sample can land, is finite; a grid of size ≥ 1.
    ///
    /// # Errors
    /// [`GenerateError::InvalidParameters`], saying which parameter is wrong.
    pub fn validate(&self) -> Result<(), GenerateError> {
        let bad = |what: String| Err(GenerateError::InvalidParameters(what));
        match *self {
            PointDistribution::Uniform { min, max } => {
                if !(min.is_finite() && max.is_finite() && min < max) {
                    return bad(format!("uniform range [{min}, {max}) is empty or not finite"));
                }
            }
            PointDistribution::Normal { mean, sigma } => {
                if !(mean.is_finite() && sigma.is_finite() && sigma > 0.0) {
                    return bad(format!(
                        "normal distribution needs a finite mean and sigma > 0 (got {mean:?}, {sigma:?})"
                    ));
                }
                if !(mean.abs() + BOX_MULLER_MAX_RADIUS * sigma).is_finite() {
                    return bad(format!(
                        "normal samples reach mean ± {BOX_MULLER_MAX_RADIUS}·sigma, which overflows f64 (mean {mean:?}, sigma {sigma:?})"
                    ));
                }
            }
            PointDistribution::Grid { size } => {
                if size == 0 {
                    return bad("a grid of size 0 has no points".into());
                }
            }
        }
        Ok(())
    }

    /// The centre the star-shaped generator sorts around. For the grid it is the
    /// middle cell's centre offset by a quarter, so that it is no grid point.
    pub fn center(&self) -> Point {
        match *self {
            PointDistribution::Uniform { min, max } => {
                let c = min / 2.0 + max / 2.0;
                Point::new(c, c)
            }
            PointDistribution::Normal { mean, .. } => Point::new(mean, mean),
            PointDistribution::Grid { size } => {
                let c = (size / 2) as f64 + 0.25;
                Point::new(c, c + 0.25)
            }
        }
    }

    fn check(&self, n: usize) -> Result<(), GenerateError> {
        let bad = |what: String| Err(GenerateError::InvalidParameters(what));
        if n < 3 {
            return bad(format!("a polygon needs at least 3 vertices, asked for {n}"));
        }
        if n > MAX_VERTICES {
            return bad(format!(
                "{n} vertices is more than the {MAX_VERTICES} a generator makes"
            ));
        }
        self.validate()?;
        if let PointDistribution::Grid { size } = *self
            && (size as usize).saturating_mul(size as usize) < n
        {
            return bad(format!("a {size}x{size} grid has fewer than {n} points"));
        }
        Ok(())
    }
}

/// Uniform in [min, max). A range wider than `f64::MAX` (which the `rand` sampler
/// refuses) is sampled as the convex combination min·(1 − u) + max·u, which cannot
/// overflow; a result rounded up to `max` becomes its predecessor.
fn uniform<R: Rng + ?Sized>(min: f64, max: f64, rng: &mut R) -> f64 {
    if min < max && (max - min).is_finite() {
        rng.random_range(min..max)
    } else {
        let u: f64 = rng.random();
        let x = min * (1.0 - u) + max * u;
        if x < max { x } else { max.next_down() }
    }
}

/// How the points are joined into a polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SimpleMethod {
    /// Space partitioning (after Auer and Held).
    SpacePartition,
    /// Angular sort around the distribution's centre.
    Star,
    /// Angular sort around the lowest point of the set, kept as a vertex (the lecture
    /// notes' simple polygon).
    Angular,
}

impl SimpleMethod {
    /// Every method, in the order the CLI lists them.
    pub const ALL: &'static [SimpleMethod] = &[
        SimpleMethod::SpacePartition,
        SimpleMethod::Star,
        SimpleMethod::Angular,
    ];

    /// The method's name in the CLI (`gen --simple --method`).
    pub fn name(self) -> &'static str {
        match self {
            SimpleMethod::SpacePartition => "space-partition",
            SimpleMethod::Star => "star",
            SimpleMethod::Angular => "angular",
        }
    }
}

impl fmt::Display for SimpleMethod {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for SimpleMethod {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        SimpleMethod::ALL
            .iter()
            .copied()
            .find(|m| m.name() == s)
            .ok_or_else(|| format!("unknown method '{s}' (valid: space-partition, star, angular)"))
    }
}

/// Why a generator returned no polygon.
#[derive(Clone, Debug, PartialEq)]
pub enum GenerateError {
    /// The parameters cannot give a polygon (fewer than 3 or more than
    /// [`MAX_VERTICES`] vertices, an empty or non-finite range, samples that would
    /// overflow, a grid with too few points, a radius that is zero or not finite).
    InvalidParameters(String),
    /// [`MAX_ATTEMPTS`] point sets in a row gave degenerate constructions (for the
    /// ellipse families: rounded to no area, or spoiled the steering).
    GaveUp {
        /// How many point sets (or draws) were tried.
        attempts: usize,
    },
}

impl fmt::Display for GenerateError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GenerateError::InvalidParameters(what) => write!(f, "invalid generator parameters: {what}"),
            GenerateError::GaveUp { attempts } => {
                write!(
                    f,
                    "no polygon after {attempts} attempts (the points round together or are collinear)"
                )
            }
        }
    }
}

impl std::error::Error for GenerateError {}

/// `n` distinct random points (exact duplicates are redrawn).
///
/// # Errors
/// [`GenerateError::InvalidParameters`] when `dist` or `n` cannot give `n` distinct
/// finite points; [`GenerateError::GaveUp`] when redrawing duplicates takes more than
/// `100·n + 1000` draws.
pub fn random_points<R: Rng + ?Sized>(
    dist: PointDistribution,
    n: usize,
    rng: &mut R,
) -> Result<Vec<Point>, GenerateError> {
    dist.check(n)?;
    let mut seen = HashSet::with_capacity(n);
    let mut out = Vec::with_capacity(n);
    let mut draws = 0usize;
    while out.len() < n {
        draws += 1;
        if draws > 100 * n + 1000 {
            return Err(GenerateError::GaveUp { attempts: draws });
        }
        let p = dist.sample(rng);
        // +0.0 identifies -0.0 with 0.0.
        if seen.insert(((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())) {
            out.push(p);
        }
    }
    Ok(out)
}

/// A random simple polygon with `n` vertices from `dist`, joined by `method`.
/// Cleaning may drop a straight vertex (collinear with its neighbours), so the
/// result can have fewer than `n` vertices on a grid.
///
/// # Errors
/// [`GenerateError`] for impossible parameters (see [`PointDistribution::validate`];
/// n below 3 or above [`MAX_VERTICES`]), or when [`MAX_ATTEMPTS`] draws in a row were
/// degenerate (a tiny range or sigma that rounds the points together, a grid).
///
/// ```
/// use polysect::generate::simple::{random_simple_polygon, PointDistribution, SimpleMethod};
/// use rand::SeedableRng;
/// let mut rng = rand::rngs::SmallRng::seed_from_u64(1);
/// let dist = PointDistribution::Uniform { min: 0.0, max: 100.0 };
/// let p = random_simple_polygon(SimpleMethod::SpacePartition, dist, 500, &mut rng)?;
/// assert_eq!(p.len(), 500);
/// # Ok::<(), polysect::generate::simple::GenerateError>(())
/// ```
pub fn random_simple_polygon<R: Rng + ?Sized>(
    method: SimpleMethod,
    dist: PointDistribution,
    n: usize,
    rng: &mut R,
) -> Result<SimplePolygon, GenerateError> {
    dist.check(n)?;
    for _ in 0..MAX_ATTEMPTS {
        let points = random_points(dist, n, rng)?;
        let order = match method {
            SimpleMethod::SpacePartition => space_partition(&points, rng),
            SimpleMethod::Star => Some(star_order(&points, dist.center())),
            SimpleMethod::Angular => Some(angular_order(&points).into_iter().map(|i| points[i]).collect()),
        };
        if let Some(v) = order
            && let Ok(p) = SimplePolygon::new(v)
        {
            return Ok(p);
        }
    }
    Err(GenerateError::GaveUp {
        attempts: MAX_ATTEMPTS,
    })
}

/// Orders `points` (distinct) into a polygon by space partitioning (see the module
/// docs). `None` when a degenerate split (collinear points) blocks the construction,
/// or for fewer than 3 points or a non-finite one.
/// The result is simple when no three points are collinear; validate it otherwise.
pub fn space_partition<R: Rng + ?Sized>(points: &[Point], rng: &mut R) -> Option<Vec<Point>> {
    let n = points.len();
    if n < 3 || points.iter().any(|p| !p.is_finite()) {
        return None;
    }
    // Points on the line through s_f and s_l join the left side; the right side must
    // then be non-empty, or the closing edge would run over them.
    let (left, right, f, l) = (0..16).find_map(|_| {
        let f = rng.random_range(0..n);
        let l = rng.random_range(0..n);
        if f == l {
            return None;
        }
        let (mut left, mut right, mut collinear) = (Vec::new(), Vec::new(), false);
        for i in 0..n {
            if i != f && i != l {
                match Exact.orient(points[f], points[l], points[i]) {
                    Orientation::Ccw => left.push(i),
                    Orientation::Collinear => {
                        collinear = true;
                        left.push(i);
                    }
                    Orientation::Cw => right.push(i),
                }
            }
        }
        (!collinear || !right.is_empty()).then_some((left, right, f, l))
    })?;
    let mut out = Vec::with_capacity(n);
    chain(points, left, f, l, rng, &mut out)?;
    chain(points, right, l, f, rng, &mut out)?;
    Some(out.into_iter().map(|i| points[i]).collect())
}

/// Appends the chain from `f` to `l` (without `l`) through the points `set`.
fn chain<R: Rng + ?Sized>(
    points: &[Point],
    set: Vec<usize>,
    f: usize,
    l: usize,
    rng: &mut R,
    out: &mut Vec<usize>,
) -> Option<()> {
    let mut stack = vec![(set, f, l)];
    while let Some((set, f, l)) = stack.pop() {
        if set.is_empty() {
            out.push(f);
            continue;
        }
        let (pf, pl) = (points[f], points[l]);
        let off_line: Vec<usize> = set
            .iter()
            .copied()
            .filter(|&i| Exact.orient(pf, pl, points[i]) != Orientation::Collinear)
            .collect();
        if off_line.is_empty() {
            // Every point lies on line fl: the chain runs straight from f to l, valid
            // only when all of them lie between f and l.
            let mut on = set;
            let (lo, hi) = if pf.lex_cmp(pl).is_lt() {
                (pf, pl)
            } else {
                (pl, pf)
            };
            if on
                .iter()
                .any(|&i| points[i].lex_cmp(lo).is_le() || points[i].lex_cmp(hi).is_ge())
            {
                return None;
            }
            on.sort_unstable_by(|&a, &b| points[a].lex_cmp(points[b]));
            if pf.lex_cmp(pl).is_gt() {
                on.reverse();
            }
            out.push(f);
            out.extend(on);
            continue;
        }
        let s = off_line[rng.random_range(0..off_line.len())];
        let ps = points[s];
        // A random line through s that crosses segment fl strictly between f and l.
        let (r, side_f) = (0..16).find_map(|_| {
            let t: f64 = rng.random_range(0.01..0.99);
            // A convex combination, which cannot overflow where pl − pf would; a
            // rounding to infinity next to f64::MAX is skipped like a degenerate draw.
            let r = Point::new(pf.x * (1.0 - t) + pl.x * t, pf.y * (1.0 - t) + pl.y * t);
            if !r.is_finite() {
                return None;
            }
            let of = Exact.orient(ps, r, pf);
            let ol = Exact.orient(ps, r, pl);
            (of != Orientation::Collinear && ol != Orientation::Collinear && of != ol).then_some((r, of))
        })?;
        let (mut sl, mut sr) = (Vec::new(), Vec::new());
        for &i in &set {
            if i == s {
                continue;
            }
            let o = Exact.orient(ps, r, points[i]);
            if o == side_f || o == Orientation::Collinear {
                sl.push(i);
            } else {
                sr.push(i);
            }
        }
        stack.push((sr, s, l));
        stack.push((sl, f, s));
    }
    Some(())
}

/// Orders `points` by angle around `center` (points equal to it, and points that are
/// not finite, are dropped; on one ray, nearer first). The result is star-shaped from
/// `center` when the points surround it; validate it. A non-finite `center` has no
/// angles around it: the finite points come back in input order.
pub fn star_order(points: &[Point], center: Point) -> Vec<Point> {
    let upper = |p: Point| {
        let dy = p.y - center.y;
        dy > 0.0 || (dy == 0.0 && p.x > center.x)
    };
    let mut v: Vec<Point> = points
        .iter()
        .copied()
        .filter(|&p| p != center && p.is_finite())
        .collect();
    if !center.is_finite() {
        return v;
    }
    v.sort_unstable_by(|&a, &b| {
        let (ua, ub) = (upper(a), upper(b));
        if ua != ub {
            return ub.cmp(&ua);
        }
        match Exact.orient(center, a, b) {
            Orientation::Ccw => std::cmp::Ordering::Less,
            Orientation::Cw => std::cmp::Ordering::Greater,
            Orientation::Collinear => {
                // Same ray: lexicographic order is distance order when the ray points
                // lexicographically forward.
                let forward = a.x > center.x || (a.x == center.x && a.y > center.y);
                if forward { a.lex_cmp(b) } else { b.lex_cmp(a) }
            }
        }
    });
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand::rngs::SmallRng;

    #[test]
    fn angular_sort_keeps_every_point_and_the_pivot() {
        let mut rng = SmallRng::seed_from_u64(5);
        for n in [3, 6, 50, 1000] {
            for dist in [
                PointDistribution::Uniform { min: 0.0, max: 100.0 },
                PointDistribution::Normal {
                    mean: 0.0,
                    sigma: 50.0,
                },
            ] {
                let p = random_simple_polygon(SimpleMethod::Angular, dist, n, &mut rng).unwrap();
                assert_eq!(p.len(), n, "{dist:?}");
            }
        }
        // The lecture notes' case: collinear points on the last ray come farthest first, and
        // the pivot (a point of the set) stays.
        let pts = [
            [0.0, 0.0],
            [4.0, 0.0],
            [3.0, 2.0],
            [1.0, 1.0],
            [2.0, 2.0],
            [3.0, 3.0],
        ]
        .map(Point::from);
        let order: Vec<Point> = angular_order(&pts).into_iter().map(|i| pts[i]).collect();
        assert_eq!(order.len(), 6);
        assert_eq!(order[0], Point::new(0.0, 0.0));
        // A simple polygon; its straight vertices (2, 2) and (1, 1) are cleaned away.
        let p = SimplePolygon::new(order.clone()).unwrap();
        assert_eq!(p.len(), 4);
        assert_eq!(
            &order[3..],
            &[[3.0, 3.0], [2.0, 2.0], [1.0, 1.0]].map(Point::from)
        );
    }

    #[test]
    fn every_method_and_distribution_gives_valid_polygons() {
        let mut rng = SmallRng::seed_from_u64(3);
        for &method in SimpleMethod::ALL {
            for dist in [
                PointDistribution::Uniform { min: 0.0, max: 10.0 },
                PointDistribution::Normal {
                    mean: 0.0,
                    sigma: 20.0,
                },
                PointDistribution::Grid { size: 12 },
            ] {
                for n in [3, 4, 5, 17, 60] {
                    let p = random_simple_polygon(method, dist, n, &mut rng).unwrap();
                    assert!(p.debug_validate().is_ok());
                    assert!(p.len() <= n);
                    if !matches!(dist, PointDistribution::Grid { .. }) {
                        assert_eq!(p.len(), n, "{method} {dist:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn bad_parameters_are_errors() {
        let mut rng = SmallRng::seed_from_u64(3);
        for (dist, n) in [
            (PointDistribution::Uniform { min: 1.0, max: 1.0 }, 5),
            (
                PointDistribution::Uniform {
                    min: 0.0,
                    max: f64::NAN,
                },
                5,
            ),
            (
                PointDistribution::Normal {
                    mean: 0.0,
                    sigma: 0.0,
                },
                5,
            ),
            (PointDistribution::Grid { size: 2 }, 5),
            (PointDistribution::Grid { size: 10 }, 2),
        ] {
            let e = random_simple_polygon(SimpleMethod::Star, dist, n, &mut rng).unwrap_err();
            assert!(matches!(e, GenerateError::InvalidParameters(_)), "{e}");
        }
        // Three points of a 2x2 grid always form a valid triangle.
        let t = random_simple_polygon(
            SimpleMethod::SpacePartition,
            PointDistribution::Grid { size: 2 },
            3,
            &mut rng,
        )
        .unwrap();
        assert_eq!(t.len(), 3);
        assert_eq!("star".parse::<SimpleMethod>(), Ok(SimpleMethod::Star));
        assert!("zigzag".parse::<SimpleMethod>().is_err());
    }

    #[test]
    fn star_order_surrounds_the_center() {
        let pts = [
            Point::new(1., 0.),
            Point::new(0., 1.),
            Point::new(-1., 0.),
            Point::new(0., -1.),
            Point::new(2., 0.),
        ];
        let v = star_order(&pts, Point::new(0., 0.));
        assert_eq!(v[0], Point::new(1., 0.));
        assert_eq!(v[1], Point::new(2., 0.));
        assert_eq!(v[4], Point::new(0., -1.));
    }
}
