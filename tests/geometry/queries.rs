//! The everyday queries (point containment, extreme vertex, area, centroid) against brute
//! force: every vertex or edge looked at with exact predicates, and areas and centroids
//! computed exactly with big integers. Random polygons from every generator family, and
//! adversarial inputs: points on vertices and edges and one ulp off them, directions
//! perpendicular to an edge and one ulp off, offsets of 2^50, coordinates scaled by
//! 2^±1000 and near `f64::MAX`, subnormals. Linked polygons run in shuffled arena order,
//! after edits, under several seeds, and large enough (2^16) that the sampled walk is
//! much shorter than the polygon. `POLYSECT_QUERY_CASES` scales the random rounds.

use num_bigint::BigInt;
use num_traits::{Signed, ToPrimitive, Zero};
use polysect::generate::simple::{PointDistribution, SimpleMethod, random_simple_polygon};
use polysect::generate::{self, Family, Relation, regular_polygon};
use polysect::{ConvexPolygon, Exact, Fast, Kernel, LinkedPolygon, Orientation, Point, Sign, SimplePolygon};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const SEED: u64 = 0x9e3_1e5;
const U: f64 = f64::EPSILON / 2.0; // 2^-53

fn rounds() -> usize {
    std::env::var("POLYSECT_QUERY_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1)
}

// ---------- brute force ----------

/// Closed containment: not strictly right of any edge (counter-clockwise polygon).
fn contains_brute(p: &ConvexPolygon, x: Point) -> bool {
    if !x.is_finite() {
        return false;
    }
    let v = p.vertices();
    (0..v.len()).all(|i| Exact.orient(v[i], v[(i + 1) % v.len()], x) != Orientation::Cw)
}

/// The vertices maximising d·v, compared exactly; of two (an edge perpendicular to d),
/// the edge's start.
fn extreme_brute(p: &ConvexPolygon, d: Point) -> usize {
    let o = Point::new(0.0, 0.0);
    let v = p.vertices();
    let n = v.len();
    let mut best = 0;
    for i in 1..n {
        if Exact.dot(o, d, v[best], v[i]) == Sign::Positive {
            best = i;
        }
    }
    let maxima: Vec<usize> = (0..n)
        .filter(|&i| Exact.dot(o, d, v[best], v[i]) == Sign::Zero)
        .collect();
    match maxima[..] {
        [i] => i,
        [i, j] if j == i + 1 => i,
        [0, j] if j == n - 1 => j,
        _ => panic!("{} maxima on a strictly convex polygon", maxima.len()),
    }
}

/// A finite f64 as mantissa · 2^exponent.
fn dyadic(x: f64) -> (BigInt, i64) {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i64;
    let fraction = (bits & ((1u64 << 52) - 1)) as i64;
    let (m, e) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1 << 52), biased - 1075)
    };
    (BigInt::from(if bits >> 63 == 1 { -m } else { m }), e)
}

/// m · 2^e as the nearest f64 (to within 2^-60 relative), infinite beyond the range.
fn to_f64(m: &BigInt, e: i64) -> f64 {
    if m.is_zero() {
        return 0.0;
    }
    let shift = m.bits() as i64 - 64;
    let (top, e) = if shift > 0 {
        (m >> shift as usize, e + shift)
    } else {
        (m.clone(), e)
    };
    let mut x = top.to_f64().unwrap();
    let mut e = e;
    while e > 900 {
        x *= 2f64.powi(900);
        e -= 900;
    }
    while e < -900 {
        x *= 2f64.powi(-900);
        e += 900;
    }
    x * 2f64.powi(e as i32)
}

/// n / d · 2^e as an f64 (d ≠ 0).
fn ratio_to_f64(n: &BigInt, d: &BigInt, e: i64) -> f64 {
    let s = d.bits() as i64 - n.bits() as i64 + 70;
    let s = s.max(0);
    to_f64(&((n << s as usize) / d), e - s)
}

/// Exact twice-area (shoelace) and centroid numerators on a common scale: coordinates
/// become integers X = x · 2^-emin.
struct ExactMoments {
    twice_area: BigInt,
    nx: BigInt,
    ny: BigInt,
    emin: i64,
}

fn exact_moments(v: &[Point]) -> ExactMoments {
    let parts: Vec<((BigInt, i64), (BigInt, i64))> = v.iter().map(|p| (dyadic(p.x), dyadic(p.y))).collect();
    let emin = parts.iter().flat_map(|(a, b)| [a.1, b.1]).min().unwrap();
    let int = |(m, e): &(BigInt, i64)| m.clone() << (e - emin) as usize;
    let xy: Vec<(BigInt, BigInt)> = parts.iter().map(|(a, b)| (int(a), int(b))).collect();
    let n = xy.len();
    let (mut a, mut nx, mut ny) = (BigInt::zero(), BigInt::zero(), BigInt::zero());
    for i in 0..n {
        let (x0, y0) = &xy[i];
        let (x1, y1) = &xy[(i + 1) % n];
        let c = x0 * y1 - x1 * y0;
        nx += (x0 + x1) * &c;
        ny += (y0 + y1) * &c;
        a += c;
    }
    ExactMoments {
        twice_area: a,
        nx,
        ny,
        emin,
    }
}

impl ExactMoments {
    fn area(&self) -> f64 {
        to_f64(&self.twice_area.abs(), 2 * self.emin) / 2.0
    }
    fn centroid(&self) -> Point {
        let d = &self.twice_area * 3;
        Point::new(
            ratio_to_f64(&self.nx, &d, self.emin),
            ratio_to_f64(&self.ny, &d, self.emin),
        )
    }
}

/// P and D of the documented bounds: the sum of the fan products' magnitudes and the
/// largest coordinate difference from the first vertex (in f64, with a margin).
fn fan_magnitudes(v: &[Point]) -> (f64, f64) {
    let o = v[0];
    // Halved so that differences near f64::MAX stay finite; the result is doubled back.
    let d = |p: Point| ((p.x / 2.0 - o.x / 2.0), (p.y / 2.0 - o.y / 2.0));
    let mut sum = 0.0;
    let mut width: f64 = 0.0;
    for i in 1..v.len() {
        let (ax, ay) = d(v[i]);
        width = width.max(ax.abs()).max(ay.abs());
        if i + 1 < v.len() {
            let (bx, by) = d(v[i + 1]);
            sum += 4.0 * ((ax * by).abs() + (ay * bx).abs());
        }
    }
    (sum, 2.0 * width)
}

fn ulp(x: f64) -> f64 {
    let a = x.abs();
    if a == 0.0 {
        f64::from_bits(1)
    } else {
        a.next_up() - a
    }
}

/// Checks area and centroid of `v` (the polygon's vertex list as the type stores it)
/// against the exact values and the documented bounds. `q` = Σ|cᵢ|/|Σcᵢ| ≥ 1 allowance.
fn check_moments(v: &[Point], area: f64, centroid: Point, q: f64, what: &str) {
    let exact = exact_moments(v);
    let truth = exact.area();
    let (p_sum, width) = fan_magnitudes(v);
    let n = v.len() as f64;
    if truth.is_infinite() || truth > f64::MAX / 2.0 {
        assert!(area >= f64::MAX / 4.0, "{what}: area {area} vs exact {truth}");
    } else if truth >= f64::MIN_POSITIVE * 2f64.powi(60) {
        let bound = 2.0 * U * truth + 4.0 * n * n * U * U * p_sum + truth * 2f64.powi(-58);
        assert!(
            (area - truth).abs() <= bound,
            "{what}: area {area:e} vs exact {truth:e}, error {:e} > bound {bound:e}",
            (area - truth).abs()
        );
    } else {
        // Subnormal territory: only an absolute bound is meaningful.
        assert!(
            (area - truth).abs() <= 2f64.powi(-1000),
            "{what}: {area:e} vs {truth:e}"
        );
    }
    assert!(centroid.is_finite(), "{what}: centroid {centroid:?}");
    let c = exact.centroid();
    for (got, want) in [(centroid.x, c.x), (centroid.y, c.y)] {
        let bound = 4.0 * U * width * q + ulp(want) + want.abs() * 2f64.powi(-58);
        // Below the normal range the reference's own conversion is coarse.
        let bound = bound.max(4.0 * f64::MIN_POSITIVE);
        assert!(
            (got - want).abs() <= bound,
            "{what}: centroid coordinate {got:e} vs exact {want:e}, error {:e} > {bound:e}",
            (got - want).abs()
        );
    }
}

// ---------- inputs ----------

/// Random pairs from every family, both polygons, at a few sizes.
fn family_polygons(rng: &mut SmallRng) -> Vec<(String, ConvexPolygon)> {
    let mut out = Vec::new();
    for &family in Family::ALL {
        for n in [3, 4, 7, 32, 300] {
            let (p, q) = generate::pair(family, n, Relation::Any, rng);
            out.push((format!("{family} n={n} p"), p));
            out.push((format!("{family} n={n} q"), q));
        }
    }
    for n in [3, 4, 5, 64, 1000] {
        out.push((format!("regular {n}"), regular_polygon(n, 1.0)));
    }
    out
}

type PointMap = Box<dyn Fn(Point) -> Point>;

/// The same polygon moved to the edges of the f64 range: offset 2^50, scaled by
/// 2^±1000, scaled to reach f64::MAX, and scaled into the subnormals.
fn extremes_of(p: &ConvexPolygon) -> Vec<(String, ConvexPolygon)> {
    let polysect::BoundingBox { min: lo, max: hi } = p.bounding_box();
    let extent = (hi.x - lo.x)
        .max(hi.y - lo.y)
        .max(hi.x.abs())
        .max(hi.y.abs())
        .max(lo.x.abs())
        .max(lo.y.abs());
    let to_max = f64::MAX / extent / 2.0;
    let maps: Vec<(&str, PointMap)> = vec![
        (
            "offset 2^50",
            Box::new(|v: Point| Point::new(v.x + 2f64.powi(50), v.y - 2f64.powi(50))),
        ),
        (
            "scaled 2^1000",
            Box::new(|v: Point| Point::new(v.x * 2f64.powi(1000), v.y * 2f64.powi(1000))),
        ),
        (
            "scaled 2^-1000",
            Box::new(|v: Point| Point::new(v.x * 2f64.powi(-1000), v.y * 2f64.powi(-1000))),
        ),
        (
            "near f64::MAX",
            Box::new(move |v: Point| Point::new(v.x * to_max, v.y * to_max)),
        ),
        (
            "subnormal",
            Box::new(|v: Point| Point::new(v.x * 2f64.powi(-1060), v.y * 2f64.powi(-1060))),
        ),
    ];
    maps.into_iter()
        .filter_map(|(name, f)| p.map(f).ok().map(|q| (name.to_string(), q)))
        .collect()
}

/// Points to test against `p`: every vertex and its one-ulp neighbours, edge points
/// (exact midpoints where representable, else rounded) and their neighbours, random
/// points in and around the box, and points far away.
fn probe_points(p: &ConvexPolygon, rng: &mut SmallRng) -> Vec<Point> {
    let v = p.vertices();
    let n = v.len();
    let mut out = Vec::new();
    let nudge = |q: Point| {
        [
            q,
            Point::new(q.x.next_up(), q.y),
            Point::new(q.x.next_down(), q.y),
            Point::new(q.x, q.y.next_up()),
            Point::new(q.x, q.y.next_down()),
        ]
    };
    let step = (n / 64).max(1);
    for i in (0..n).step_by(step) {
        let (a, b) = (v[i], v[(i + 1) % n]);
        out.extend(nudge(a));
        let mid = Point::new(a.x / 2.0 + b.x / 2.0, a.y / 2.0 + b.y / 2.0);
        out.extend(nudge(mid));
    }
    let polysect::BoundingBox { min: lo, max: hi } = p.bounding_box();
    let (w, h) = ((hi.x / 2.0 - lo.x / 2.0) * 2.0, (hi.y / 2.0 - lo.y / 2.0) * 2.0);
    for _ in 0..200 {
        let (s, t): (f64, f64) = (rng.random_range(-0.2..1.2), rng.random_range(-0.2..1.2));
        out.push(Point::new(lo.x + s * w, lo.y + t * h));
    }
    out.extend([
        Point::new(f64::MAX, 0.0),
        Point::new(-f64::MAX, -f64::MAX),
        Point::new(f64::NAN, lo.y),
        Point::new(lo.x, f64::INFINITY),
    ]);
    out
}

/// Directions: random, axes, every edge's outward normal (ties) and one-ulp turns of
/// it, scaled by 2^±1000, and the unusable ones.
fn probe_directions(p: &ConvexPolygon, rng: &mut SmallRng) -> Vec<Point> {
    let v = p.vertices();
    let n = v.len();
    let mut out = vec![
        Point::new(1.0, 0.0),
        Point::new(-1.0, 0.0),
        Point::new(0.0, 1.0),
        Point::new(0.0, -1.0),
        Point::new(1.0, 1.0),
        Point::new(f64::MIN_POSITIVE, 0.0),
        Point::new(0.0, f64::from_bits(1)),
        Point::new(f64::MAX, -f64::MAX),
    ];
    for _ in 0..40 {
        let t: f64 = rng.random_range(0.0..std::f64::consts::TAU);
        out.push(Point::new(t.cos(), t.sin()));
    }
    let step = (n / 32).max(1);
    for i in (0..n).step_by(step) {
        let (a, b) = (v[i], v[(i + 1) % n]);
        // The outward normal of edge a→b, exact when the difference is exact.
        let (ex, ey) = (b.x - a.x, b.y - a.y);
        for d in [
            Point::new(ey, -ex),
            Point::new(ey.next_up(), -ex),
            Point::new(ey, (-ex).next_down()),
            Point::new(ey * 2f64.powi(-1000), -ex * 2f64.powi(-1000)),
        ] {
            if d.is_finite() && (d.x != 0.0 || d.y != 0.0) {
                out.push(d);
            }
        }
    }
    out
}

fn shuffled(p: &ConvexPolygon, rng: &mut SmallRng) -> LinkedPolygon {
    LinkedPolygon::from_convex_shuffled(p, rng)
}

// ---------- containment ----------

fn check_containment(p: &ConvexPolygon, what: &str, rng: &mut SmallRng) {
    let linked = shuffled(p, rng);
    for x in probe_points(p, rng) {
        let want = contains_brute(p, x);
        assert_eq!(p.contains_point(x), want, "{what}: array, point {x:?}");
        let mut draws = SmallRng::seed_from_u64(rng.random());
        assert_eq!(
            linked.contains_point_with(Exact, x, &mut draws),
            want,
            "{what}: linked, point {x:?}"
        );
        // The fast kernel may misjudge, but never panics.
        let _ = p.contains_point_with(Fast, x);
        let _ = linked.contains_point_with(Fast, x, &mut draws);
    }
}

#[test]
fn containment_equals_brute_force_on_every_family_and_at_the_extremes() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    for _ in 0..rounds() {
        for (what, p) in family_polygons(&mut rng) {
            check_containment(&p, &what, &mut rng);
            for (how, q) in extremes_of(&p) {
                check_containment(&q, &format!("{what}, {how}"), &mut rng);
            }
        }
    }
}

#[test]
fn containment_on_lattice_edges_is_exact() {
    // Integer polygons: every lattice point on an edge is exactly representable, so
    // these are true boundary points, with their one-ulp neighbours just outside.
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    let mut outside = 0;
    for family in [Family::SharedEdge, Family::VertexOnEdge, Family::OverlappingEdges] {
        for _ in 0..10 * rounds() {
            let (p, _) = generate::pair(family, 40, Relation::Intersecting, &mut rng);
            let linked = shuffled(&p, &mut rng);
            let v = p.vertices();
            for i in 0..v.len() {
                let (a, b) = (v[i], v[(i + 1) % v.len()]);
                let (dx, dy) = (b.x - a.x, b.y - a.y);
                let g = gcd(dx.abs() as u64, dy.abs() as u64).max(1) as f64;
                for k in 0..=(g as u64).min(8) {
                    let on = Point::new(a.x + dx / g * k as f64, a.y + dy / g * k as f64);
                    assert!(p.contains_point(on), "{on:?} on edge {a:?}-{b:?}");
                    assert!(linked.contains_point(on), "linked {on:?}");
                    // One ulp along the outward normal (dy, -dx).
                    let outward = Point::new(nudge(on.x, dy), nudge(on.y, -dx));
                    let want = contains_brute(&p, outward);
                    outside += usize::from(!want);
                    assert_eq!(p.contains_point(outward), want, "{outward:?}");
                    assert_eq!(linked.contains_point(outward), want, "linked {outward:?}");
                }
            }
        }
    }
    assert!(outside > 100, "the nudged points leave the polygon: {outside}");
}

/// The neighbouring float of `x` in the direction of the sign of `s` (x itself for 0).
fn nudge(x: f64, s: f64) -> f64 {
    if s > 0.0 {
        x.next_up()
    } else if s < 0.0 {
        x.next_down()
    } else {
        x
    }
}

fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 { a } else { gcd(b, a % b) }
}

#[test]
fn linked_containment_samples_a_short_walk_on_large_polygons_under_any_seed() {
    let mut rng = SmallRng::seed_from_u64(SEED + 2);
    let big = regular_polygon(1 << 16, 1.0);
    let linked = shuffled(&big, &mut rng);
    let v = big.vertices();
    let mut points = Vec::new();
    for _ in 0..300 {
        let i = rng.random_range(0..v.len());
        let (a, b) = (v[i], v[(i + 1) % v.len()]);
        points.push(a);
        points.push(Point::new(a.x / 2.0 + b.x / 2.0, a.y / 2.0 + b.y / 2.0));
        points.push(Point::new(a.x * (1.0 + 1e-12), a.y * (1.0 + 1e-12)));
        points.push(Point::new(a.x * (1.0 - 1e-12), a.y * (1.0 - 1e-12)));
        points.push(Point::new(
            rng.random_range(-1.1..1.1),
            rng.random_range(-1.1..1.1),
        ));
    }
    for x in points {
        let want = contains_brute(&big, x);
        assert_eq!(big.contains_point(x), want, "{x:?}");
        for seed in 0..3 {
            let mut draws = SmallRng::seed_from_u64(seed);
            assert_eq!(
                linked.contains_point_with(Exact, x, &mut draws),
                want,
                "{x:?} seed {seed}"
            );
        }
    }
}

#[test]
fn linked_queries_follow_edits() {
    let mut rng = SmallRng::seed_from_u64(SEED + 3);
    let mut linked = shuffled(&regular_polygon(500, 10.0), &mut rng);
    for step in 0..300 {
        if linked.len() > 3 && rng.random_bool(0.7) {
            let v = linked.random_vertex(&mut rng);
            linked.remove(v).unwrap();
        } else {
            let a = linked.random_vertex(&mut rng);
            let (pa, pb) = (
                linked.point(a).unwrap(),
                linked.point(linked.next(a).unwrap()).unwrap(),
            );
            let out = Point::new((pa.x + pb.x) * 0.5 * 1.0001, (pa.y + pb.y) * 0.5 * 1.0001);
            let _ = linked.insert_after(a, out);
        }
        let array = linked.to_convex();
        for x in probe_points(&array, &mut rng).into_iter().step_by(7) {
            assert_eq!(
                linked.contains_point(x),
                contains_brute(&array, x),
                "step {step} {x:?}"
            );
        }
        for d in probe_directions(&array, &mut rng).into_iter().step_by(5) {
            let want = array.vertices()[extreme_brute(&array, d)];
            let got = linked.extreme_vertex(d).unwrap();
            assert_eq!(linked.point(got).unwrap(), want, "step {step} {d:?}");
        }
    }
}

// ---------- extreme vertex ----------

fn check_extreme(p: &ConvexPolygon, what: &str, rng: &mut SmallRng) {
    let linked = shuffled(p, rng);
    for d in probe_directions(p, rng) {
        let want = extreme_brute(p, d);
        assert_eq!(p.extreme_vertex(d), Some(want), "{what}: array, direction {d:?}");
        let mut draws = SmallRng::seed_from_u64(rng.random());
        let got = linked.extreme_vertex_with(Exact, d, &mut draws).unwrap();
        assert_eq!(
            linked.point(got).unwrap(),
            p.vertices()[want],
            "{what}: linked, direction {d:?}"
        );
        let _ = p.extreme_vertex_with(Fast, d);
        let _ = linked.extreme_vertex_with(Fast, d, &mut draws);
    }
    for bad in [
        Point::new(0.0, 0.0),
        Point::new(-0.0, 0.0),
        Point::new(f64::NAN, 1.0),
        Point::new(1.0, f64::INFINITY),
    ] {
        assert_eq!(p.extreme_vertex(bad), None, "{what}: {bad:?}");
        assert_eq!(linked.extreme_vertex(bad), None, "{what}: {bad:?}");
    }
}

#[test]
fn extreme_vertex_equals_brute_force_on_every_family_and_at_the_extremes() {
    let mut rng = SmallRng::seed_from_u64(SEED + 4);
    for _ in 0..rounds() {
        for (what, p) in family_polygons(&mut rng) {
            check_extreme(&p, &what, &mut rng);
            for start in [1, p.len() / 2, p.len() - 1] {
                check_extreme(&p.starting_at(start), &format!("{what} from {start}"), &mut rng);
            }
            for (how, q) in extremes_of(&p) {
                check_extreme(&q, &format!("{what}, {how}"), &mut rng);
            }
        }
    }
}

#[test]
fn extreme_vertex_breaks_one_ulp_ties_exactly() {
    // Two vertices whose x differ by one ulp at 2^52 + 1: only exact comparison of the
    // dot products can order them; a plain f64 dot product with d = (1, 1e-30) rounds
    // both to the same value.
    let o = 2f64.powi(52);
    let p = ConvexPolygon::new([[0.0, 0.0], [o, 0.0], [o + 1.0, 1.0], [o, 2.0], [0.0, 2.0]]).unwrap();
    assert_eq!(
        p.vertices()[p.extreme_vertex([1.0, 1e-30]).unwrap()],
        Point::new(o + 1.0, 1.0)
    );
    let q = ConvexPolygon::new([[0.0, 0.0], [o, 0.0], [o, 1.0], [0.0, 1.0]]).unwrap();
    // Edge (o, 0)–(o, 1) is perpendicular to (1, 0): its start; a tilt of one part in
    // 2^1074 picks the upper end.
    assert_eq!(q.extreme_vertex([1.0, 0.0]), Some(1));
    assert_eq!(q.extreme_vertex([1.0, f64::from_bits(1)]), Some(2));
    assert_eq!(q.extreme_vertex([1.0, -f64::from_bits(1)]), Some(1));
    let lq = LinkedPolygon::from_convex(&q);
    assert_eq!(
        lq.point(lq.extreme_vertex([1.0, f64::from_bits(1)]).unwrap())
            .unwrap(),
        Point::new(o, 1.0)
    );
    assert_eq!(
        lq.point(lq.extreme_vertex([1.0, 0.0]).unwrap()).unwrap(),
        Point::new(o, 0.0)
    );
}

#[test]
fn linked_extreme_vertex_on_a_large_polygon_under_any_seed() {
    let mut rng = SmallRng::seed_from_u64(SEED + 5);
    let big = regular_polygon(1 << 16, 1.0);
    let linked = shuffled(&big, &mut rng);
    for d in probe_directions(&big, &mut rng) {
        let want = big.vertices()[extreme_brute(&big, d)];
        assert_eq!(big.vertices()[big.extreme_vertex(d).unwrap()], want);
        for seed in 0..4 {
            let mut draws = SmallRng::seed_from_u64(seed);
            let got = linked.extreme_vertex_with(Exact, d, &mut draws).unwrap();
            assert_eq!(linked.point(got).unwrap(), want, "{d:?} seed {seed}");
        }
    }
}

// ---------- area and centroid ----------

#[test]
fn area_and_centroid_within_the_documented_bounds_of_the_exact_values() {
    let mut rng = SmallRng::seed_from_u64(SEED + 6);
    for _ in 0..rounds() {
        for (what, p) in family_polygons(&mut rng) {
            let mut cases = vec![(what.clone(), p.clone())];
            cases.extend(
                extremes_of(&p)
                    .into_iter()
                    .map(|(h, q)| (format!("{what}, {h}"), q)),
            );
            for (what, q) in cases {
                check_moments(q.vertices(), q.area(), q.centroid(), 1.0, &what);
                let linked = shuffled(&q, &mut rng);
                let from_first = linked.to_convex();
                check_moments(
                    from_first.vertices(),
                    linked.area(),
                    linked.centroid(),
                    1.0,
                    &format!("{what} linked"),
                );
                assert_eq!(linked.area(), from_first.area(), "{what}");
            }
        }
    }
}

#[test]
fn area_has_no_cancellation_at_large_offsets_and_handles_needles() {
    for e in [0, 20, 50, 52] {
        let o = 2f64.powi(e);
        let sq = ConvexPolygon::new([[o, o], [o + 1.0, o], [o + 1.0, o + 1.0], [o, o + 1.0]]).unwrap();
        assert_eq!(sq.area(), 1.0, "offset 2^{e}");
        assert_eq!(sq.centroid(), Point::new(o + 0.5, o + 0.5), "offset 2^{e}");
    }
    // A needle: base 1, height 2^-30, offset 2^20.
    let o = 2f64.powi(20);
    let needle = ConvexPolygon::new([[o, o], [o + 1.0, o], [o + 0.5, o + 2f64.powi(-30)]]).unwrap();
    check_moments(needle.vertices(), needle.area(), needle.centroid(), 1.0, "needle");
    assert_eq!(needle.area(), 2f64.powi(-31));
    // Near f64::MAX: the differences overflow f64, the area is beyond it, the centroid
    // is not.
    let m = f64::MAX;
    let huge = ConvexPolygon::new([[-m, -m], [m, -m], [0.0, m]]).unwrap();
    assert_eq!(huge.area(), f64::INFINITY);
    let c = huge.centroid();
    assert!(
        (c.y - (-m / 3.0)).abs() <= 8.0 * U * m && c.x.abs() <= 8.0 * U * m,
        "{c:?}"
    );
    check_moments(huge.vertices(), huge.area(), c, 1.0, "huge");
    // Subnormal: the area 8·2^-2148 rounds to 0; the centroid (4t/3, 4t/3) to (t, t).
    let t = f64::from_bits(1);
    let tiny = ConvexPolygon::new([[0.0, 0.0], [4.0 * t, 0.0], [0.0, 4.0 * t]]).unwrap();
    assert_eq!(tiny.area(), 0.0);
    assert_eq!(tiny.centroid(), Point::new(t, t));
}

#[test]
fn simple_polygons_signed_area_has_the_exact_sign() {
    let mut rng = SmallRng::seed_from_u64(SEED + 7);
    for _ in 0..rounds() {
        for method in [SimpleMethod::SpacePartition, SimpleMethod::Star] {
            for dist in [
                PointDistribution::Uniform { min: 0.0, max: 100.0 },
                PointDistribution::Normal {
                    mean: 0.0,
                    sigma: 1e6,
                },
                PointDistribution::Grid { size: 30 },
            ] {
                for n in [3, 5, 20, 200] {
                    let p = random_simple_polygon(method, dist, n, &mut rng).unwrap();
                    for q in [p.clone(), p.reversed()] {
                        let v = q.vertices();
                        let exact = exact_moments(v);
                        let sum_abs = fan_abs_sum(v);
                        let qratio = (sum_abs / (2.0 * exact.area())).max(1.0);
                        check_moments(v, q.area(), q.centroid(), qratio, "simple");
                        assert_eq!(q.signed_area() > 0.0, exact.twice_area.is_positive());
                        assert_eq!(q.signed_area() > 0.0, q.is_ccw());
                        assert_eq!(q.signed_area().abs(), q.area());
                    }
                }
            }
        }
    }
    // A thin zig-zag: cancellation between the fan triangles.
    let z = SimplePolygon::new([[0.0, 0.0], [10.0, 0.0], [10.0, 1e-9], [5.0, 2e-9], [0.0, 1e-9]]).unwrap();
    assert!(z.signed_area() > 0.0);
}

/// Σ|cᵢ| over the fan from the first vertex (f64, for the centroid's Q allowance).
fn fan_abs_sum(v: &[Point]) -> f64 {
    let o = v[0];
    (1..v.len() - 1)
        .map(|i| {
            let (a, b) = (v[i], v[i + 1]);
            ((a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x)).abs()
        })
        .sum()
}

#[test]
fn every_query_answers_the_same_from_any_start_vertex() {
    let mut rng = SmallRng::seed_from_u64(SEED + 8);
    for (what, p) in family_polygons(&mut rng).into_iter().take(40) {
        let points = probe_points(&p, &mut rng);
        let dirs = probe_directions(&p, &mut rng);
        for start in 0..p.len().min(9) {
            let r = p.starting_at(start);
            for &x in &points {
                assert_eq!(r.contains_point(x), p.contains_point(x), "{what} start {start}");
            }
            for &d in &dirs {
                let (i, j) = (r.extreme_vertex(d).unwrap(), p.extreme_vertex(d).unwrap());
                assert_eq!(r.vertices()[i], p.vertices()[j], "{what} start {start} {d:?}");
            }
            let rel = (r.area() - p.area()).abs() / p.area();
            assert!(rel <= 4.0 * U || !p.area().is_normal(), "{what}: {rel:e}");
        }
    }
}

// ---------- work ----------

/// The sampled queries' work, counted in predicates (not timed): O(√n) per query on
/// average, over many random points and directions.
#[cfg(feature = "instrument")]
#[test]
fn sampled_queries_do_sublinear_work() {
    use polysect::kernel::Counted;
    let mut rng = SmallRng::seed_from_u64(SEED + 9);
    for log2 in [10u32, 14, 18] {
        let p = generate::ellipse_polygon(&mut rng, 1 << log2, &generate::Density::Uniform, true);
        let linked = shuffled(&p, &mut rng);
        let polysect::BoundingBox { min: lo, max: hi } = p.bounding_box();
        let queries = 400;
        Counted::<Exact>::take();
        for _ in 0..queries {
            let x = Point::new(rng.random_range(lo.x..hi.x), rng.random_range(lo.y..hi.y));
            assert_eq!(
                linked.contains_point_with(Counted(Exact), x, &mut rng),
                p.contains_point(x)
            );
        }
        let contains = Counted::<Exact>::take() as f64 / queries as f64;
        for _ in 0..queries {
            let t: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            let d = Point::new(t.cos(), t.sin());
            let v = linked.extreme_vertex_with(Counted(Exact), d, &mut rng).unwrap();
            assert_eq!(
                linked.point(v).unwrap(),
                p.vertices()[p.extreme_vertex(d).unwrap()]
            );
        }
        let extreme = Counted::<Exact>::take() as f64 / queries as f64;
        // Measured: about 2.3·√n and 1.6·√n; a linear walk would be n.
        let root = (p.len() as f64).sqrt();
        assert!(
            contains <= 4.0 * root + 20.0,
            "2^{log2}: {contains} predicates per containment"
        );
        assert!(
            extreme <= 3.0 * root + 20.0,
            "2^{log2}: {extreme} predicates per extreme vertex"
        );
    }
}

// ---------- containment in simple polygons ----------

/// The winding number of the closed chain `v` around x by quadrant counting (exact:
/// comparisons and `orient`), an independent reference for the crossing count; 0 when x
/// lies on the boundary is not needed (boundary points are tested apart).
fn winding(v: &[Point], x: Point) -> i64 {
    let quadrant = |p: Point| match (p.x > x.x, p.y > x.y) {
        (true, false) if p.y == x.y => 0,
        (true, false) => 3,
        (true, true) => 0,
        (false, true) => 1,
        (false, false) if p.x == x.x => 3,
        (false, false) => 2,
    };
    let mut total = 0i64;
    for i in 0..v.len() {
        let (a, b) = (v[i], v[(i + 1) % v.len()]);
        let (qa, qb) = (quadrant(a), quadrant(b));
        let mut d = (qb - qa + 4) % 4;
        if d == 3 {
            d = -1;
        } else if d == 2 {
            // Opposite quadrants: the side of x decides the way round.
            d = if Exact.orient(a, b, x) == Orientation::Ccw {
                2
            } else {
                -2
            };
        }
        total += d;
    }
    total / 4
}

fn contains_simple_brute(p: &SimplePolygon, x: Point) -> bool {
    let v = p.vertices();
    (0..v.len()).any(|i| polysect::kernel::point_on_segment(Exact, v[i], v[(i + 1) % v.len()], x))
        || winding(v, x) != 0
}

#[test]
fn simple_polygon_containment_equals_the_winding_number() {
    let mut rng = SmallRng::seed_from_u64(SEED + 10);
    let mut inside = 0;
    for _ in 0..rounds() {
        for method in [SimpleMethod::SpacePartition, SimpleMethod::Star] {
            for dist in [
                PointDistribution::Uniform { min: 0.0, max: 100.0 },
                PointDistribution::Grid { size: 12 },
            ] {
                for n in [3, 6, 20, 100] {
                    let p = random_simple_polygon(method, dist, n, &mut rng).unwrap();
                    let mut points: Vec<Point> = Vec::new();
                    for &v in p.vertices() {
                        points.extend([
                            v,
                            Point::new(v.x.next_up(), v.y),
                            Point::new(v.x, v.y.next_down()),
                        ]);
                    }
                    for i in 0..p.len() {
                        let (a, b) = p.edge(i);
                        points.push(Point::new(a.x / 2.0 + b.x / 2.0, a.y / 2.0 + b.y / 2.0));
                    }
                    for _ in 0..200 {
                        // Grid and half-grid points hit vertices, edges and vertex heights.
                        let (gx, gy) = (rng.random_range(-2..30), rng.random_range(-2..30));
                        points.push(Point::new(gx as f64 / 2.0, gy as f64 / 2.0));
                        points.push(Point::new(
                            rng.random_range(-5.0..105.0),
                            rng.random_range(-5.0..105.0),
                        ));
                    }
                    for q in [p.clone(), p.reversed()] {
                        for &x in &points {
                            let want = contains_simple_brute(&q, x);
                            inside += usize::from(want);
                            assert_eq!(q.contains_point(x), want, "{x:?} in {:?}", q.vertices());
                        }
                    }
                }
            }
        }
    }
    assert!(inside > 1000, "{inside} points inside");
    // Convex simple polygons agree with the convex query.
    for (what, c) in family_polygons(&mut rng) {
        let s = SimplePolygon::new(c.vertices().iter().copied()).unwrap();
        for x in probe_points(&c, &mut rng) {
            assert_eq!(s.contains_point(x), c.contains_point(x), "{what} {x:?}");
        }
    }
}
