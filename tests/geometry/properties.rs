//! Property tests with shrinking: every algorithm, its certificates, the distance and the
//! scene against the O(n·m) oracle on small convex polygons drawn from a coarse lattice.
//!
//! The lattice makes degeneracies common rather than rare: shared vertices, a vertex on
//! an edge, collinear overlapping edges, a polygon inside the other. A scale of 2^k
//! (|k| up to 1000, exact for lattice points) reaches both ends of the exponent range,
//! and an optional one-ulp nudge of the second polygon's offset turns touches into
//! near misses and back. When a property fails, proptest shrinks the pair to a small
//! counterexample (fewer points, smaller coordinates) before reporting it. The seed is
//! fixed, so a run is reproducible; the seeded loops of the other test files cover
//! larger polygons and the generator families.

use polysect::contact::distance_with;
use polysect::intersect::{Algorithm, brute_force, verify};
use polysect::store::Scene;
use polysect::{ConvexPolygon, Exact, LinkedPolygon, Point};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

/// What a case is built from: two point sets on the lattice, a common scale exponent,
/// an offset of the second set (in lattice units) and whether that offset is nudged by
/// one ulp.
#[derive(Clone, Debug)]
struct Case {
    p: Vec<(i8, i8)>,
    q: Vec<(i8, i8)>,
    scale: i32,
    offset: (i8, i8),
    nudge: bool,
}

fn case() -> impl Strategy<Value = Case> {
    let set = || prop::collection::vec((-6i8..=6, -6i8..=6), 3..14);
    let scale = prop_oneof![4 => Just(0i32), 1 => -1000i32..=1000];
    (set(), set(), scale, (-8i8..=8, -8i8..=8), any::<bool>()).prop_map(|(p, q, scale, offset, nudge)| Case {
        p,
        q,
        scale,
        offset,
        nudge,
    })
}

/// 2^k exactly (k within the normal exponent range).
fn pow2(k: i32) -> f64 {
    f64::from_bits(((1023 + i64::from(k)) as u64) << 52)
}

/// The case's two polygons (hulls of the scaled point sets), or `None` when a set is
/// degenerate (fewer than three distinct points, or all on one line).
fn polygons(c: &Case) -> Option<(ConvexPolygon, ConvexPolygon)> {
    let s = pow2(c.scale);
    let mut ox = f64::from(c.offset.0) * s;
    if c.nudge {
        ox = ox.next_up();
    }
    let oy = f64::from(c.offset.1) * s;
    let p = ConvexPolygon::hull_of(c.p.iter().map(|&(x, y)| [f64::from(x) * s, f64::from(y) * s])).ok()?;
    // The nudge is one rounding of each point's x (exact without it): the offset is
    // added to the lattice coordinate, as a user would place the second polygon.
    let q = ConvexPolygon::hull_of(
        c.q.iter()
            .map(|&(x, y)| [f64::from(x) * s + ox, f64::from(y) * s + oy]),
    )
    .ok()?;
    Some((p, q))
}

fn config() -> Config {
    Config {
        cases: 600,
        rng_seed: RngSeed::Fixed(0x5eed_0f90),
        failure_persistence: None,
        ..Config::default()
    }
}

/// The distance from `x` to the segment `a`–`b`, in plain `f64` (for lattice input
/// without scaling every step but the square root and the division is exact).
fn point_segment(x: Point, a: Point, b: Point) -> f64 {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let t = (((x.x - a.x) * dx + (x.y - a.y) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
    (x.x - (a.x + t * dx)).hypot(x.y - (a.y + t * dy))
}

/// The distance between two disjoint convex polygons: the least distance from a vertex
/// of one to an edge of the other.
fn brute_distance(p: &ConvexPolygon, q: &ConvexPolygon) -> f64 {
    let edges = |v: &[Point]| {
        (0..v.len())
            .map(|i| (v[i], v[(i + 1) % v.len()]))
            .collect::<Vec<_>>()
    };
    let one = |a: &ConvexPolygon, b: &ConvexPolygon| {
        a.vertices()
            .iter()
            .flat_map(|&x| {
                edges(b.vertices())
                    .into_iter()
                    .map(move |(s, t)| point_segment(x, s, t))
            })
            .fold(f64::INFINITY, f64::min)
    };
    one(p, q).min(one(q, p))
}

proptest! {
    #![proptest_config(config())]

    /// Every algorithm (the linked ones through their shuffled linking) gives the
    /// oracle's answer under the exact kernel, in both argument orders.
    #[test]
    fn every_algorithm_equals_the_oracle(c in case()) {
        let Some((p, q)) = polygons(&c) else { return Ok(()) };
        let truth = brute_force(Exact, &p, &q);
        for &alg in Algorithm::ALL {
            prop_assert_eq!(alg.intersects_with(Exact, &p, &q), truth, "{} on (p, q)", alg.name());
            prop_assert_eq!(alg.intersects_with(Exact, &q, &p), truth, "{} on (q, p)", alg.name());
        }
    }

    /// Every array algorithm's certificate passes the independent check and states the
    /// oracle's answer.
    #[test]
    fn every_certificate_verifies(c in case()) {
        let Some((p, q)) = polygons(&c) else { return Ok(()) };
        let truth = brute_force(Exact, &p, &q);
        for &alg in Algorithm::ARRAY {
            let certificate = alg.certified_with(Exact, &p, &q);
            prop_assert!(verify(&p, &q, &certificate).is_ok(), "{}: {:?} does not verify", alg.name(), certificate);
            prop_assert_eq!(certificate.intersects(), truth, "{}: {:?}", alg.name(), certificate);
        }
    }

    /// The distance is given exactly for the polygons that do not meet, and only for
    /// them; on unscaled lattice input it agrees with a brute-force distance to within
    /// the latter's own rounding.
    #[test]
    fn distance_for_exactly_the_disjoint_pairs(c in case()) {
        let Some((p, q)) = polygons(&c) else { return Ok(()) };
        let truth = brute_force(Exact, &p, &q);
        let d = distance_with(Exact, &p, &q);
        prop_assert_eq!(d.is_none(), truth);
        if let Some(d) = d {
            let exact = d.distance.expect("lattice distances are finite");
            prop_assert!(exact > 0.0);
            if c.scale == 0 && !c.nudge {
                let brute = brute_distance(&p, &q);
                prop_assert!((exact - brute).abs() <= 1e-12 * brute, "distance {} against {}", exact, brute);
            }
        }
    }

    /// A scene holding the two polygons answers as the oracle does, and still does after
    /// the second polygon is moved back by its offset (a translation that is exact on
    /// the lattice, or rounds once after a nudge).
    #[test]
    fn the_scene_equals_the_oracle(c in case()) {
        let Some((p, q)) = polygons(&c) else { return Ok(()) };
        let mut scene = Scene::new();
        let a = scene.insert(LinkedPolygon::from_convex(&p));
        let b = scene.insert(LinkedPolygon::from_convex(&q));
        prop_assert_eq!(scene.intersects(a, b).unwrap(), brute_force(Exact, &p, &q));
        let (dx, dy) = (-f64::from(c.offset.0) * pow2(c.scale), -f64::from(c.offset.1) * pow2(c.scale));
        if scene.translate(b, dx, dy).is_ok() {
            let moved = ConvexPolygon::new(scene.polygon(b).unwrap().iter().map(|(_, x)| x)).unwrap();
            prop_assert_eq!(scene.intersects(a, b).unwrap(), brute_force(Exact, &p, &moved));
            let pairs = scene.intersecting_pairs();
            prop_assert_eq!(pairs.len() == 1, brute_force(Exact, &p, &moved));
        }
    }
}
