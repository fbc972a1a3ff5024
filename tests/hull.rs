//! Graham's scan and the monotone chain against each other and against the definition
//! of the hull (a strictly convex counter-clockwise polygon whose vertices are input
//! points and which contains every input point is the hull), on random and adversarial
//! sets; the angular sort against the definition of a simple polygon.
//!
//! `POLYSECT_HULL_ROUNDS` scales the random rounds (default 400).

use polysect::polygon::{HullAlgorithm, angular_order, convex_hull, graham_scan, hull_vertices, pivot_index};
use polysect::{ConvexPolygon, Exact, Kernel, Orientation, Point, PolygonError, SimplePolygon};
use rand::rngs::SmallRng;
use rand::seq::SliceRandom;
use rand::{Rng, SeedableRng};

const SEED: u64 = 0x006e_a4a3;

fn rounds() -> usize {
    std::env::var("POLYSECT_HULL_ROUNDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(400)
}

/// The hull's defining properties, checked exactly.
fn assert_is_hull(hull: &[Point], points: &[Point], what: &str) {
    let lowest = points
        .iter()
        .min_by(|a, b| a.y.total_cmp(&b.y).then(a.x.total_cmp(&b.x)))
        .unwrap();
    assert_eq!(
        hull[0], *lowest,
        "{what}: starts at the lowest-then-leftmost point"
    );
    for v in hull {
        assert!(points.contains(v), "{what}: {v:?} is not an input point");
    }
    match hull.len() {
        1 => assert!(points.iter().all(|p| p == &hull[0]), "{what}"),
        2 => {
            let (a, b) = (hull[0], hull[1]);
            assert_ne!(a, b);
            for &p in points {
                assert_eq!(Exact.orient(a, b, p), Orientation::Collinear, "{what}");
                // Between the ends (inclusive).
                assert_ne!(
                    Exact.dot(p, a, p, b),
                    polysect::Sign::Positive,
                    "{what}: {p:?} beyond the ends"
                );
            }
        }
        _ => {
            ConvexPolygon::from_ccw_unchecked(hull.to_vec())
                .debug_validate()
                .unwrap_or_else(|e| panic!("{what}: {e}"));
            for &p in points {
                for i in 0..hull.len() {
                    assert_ne!(
                        Exact.orient(hull[i], hull[(i + 1) % hull.len()], p),
                        Orientation::Cw,
                        "{what}: {p:?} outside edge {i}"
                    );
                }
            }
        }
    }
}

fn check(points: &[Point], what: &str) {
    let g = hull_vertices(points, HullAlgorithm::Graham).unwrap();
    let m = hull_vertices(points, HullAlgorithm::Monotone).unwrap();
    assert_eq!(g, m, "{what}: graham and monotone differ");
    assert_is_hull(&g, points, what);
    // The polygon-returning forms agree with the vertex lists (up to the start vertex).
    match (graham_scan(points), convex_hull(points)) {
        (Ok(gp), Ok(mp)) => {
            assert_eq!(gp.vertices(), &g[..], "{what}");
            let s = mp.vertices().iter().position(|&v| v == g[0]).unwrap();
            assert_eq!(mp.starting_at(s).vertices(), &g[..], "{what}");
        }
        (Err(a), Err(b)) => {
            assert_eq!(a, b, "{what}");
            assert!(g.len() < 3, "{what}");
        }
        (a, b) => panic!("{what}: graham {a:?}, monotone {b:?}"),
    }
    // Input order never matters.
    let mut shuffled = points.to_vec();
    shuffled.shuffle(&mut SmallRng::seed_from_u64(points.len() as u64));
    assert_eq!(
        hull_vertices(&shuffled, HullAlgorithm::Graham).unwrap(),
        g,
        "{what}: shuffled"
    );
}

fn random_set(rng: &mut SmallRng, round: usize) -> Vec<Point> {
    let n = rng.random_range(1..150);
    match round % 5 {
        0 => (0..n)
            .map(|_| Point::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)))
            .collect(),
        // Small grid: duplicates and collinear runs on every hull edge.
        1 => (0..n)
            .map(|_| Point::new(rng.random_range(0..5) as f64, rng.random_range(0..5) as f64))
            .collect(),
        // One line (random integer direction), with repeats.
        2 => {
            let (dx, dy) = (rng.random_range(-3..4) as f64, rng.random_range(-3..4) as f64);
            (0..n)
                .map(|_| {
                    let t = rng.random_range(-5..6) as f64;
                    Point::new(1.0 + t * dx, 2.0 + t * dy)
                })
                .collect()
        }
        // Points on a circle and its centre.
        3 => (0..n)
            .map(|i| {
                if i % 7 == 0 {
                    return Point::new(0.0, 0.0);
                }
                let a = std::f64::consts::TAU * rng.random_range(0..64) as f64 / 64.0;
                Point::new(a.cos(), a.sin())
            })
            .collect(),
        // Huge, tiny and offset coordinates on a grid.
        _ => {
            let (scale, offset) =
                [(1e300, 0.0), (5e-324, 0.0), (1.0, 2f64.powi(53)), (1e-300, 1.0)][rng.random_range(0..4)];
            (0..n)
                .map(|_| {
                    Point::new(
                        offset + scale * rng.random_range(-4..5) as f64,
                        offset + scale * rng.random_range(-4..5) as f64,
                    )
                })
                .collect()
        }
    }
}

#[test]
fn graham_equals_monotone_and_both_are_the_hull() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    for round in 0..rounds() {
        let pts = random_set(&mut rng, round);
        check(&pts, &format!("round {round}"));
    }
}

#[test]
fn degenerate_sets_have_documented_hulls() {
    let p = |x: f64, y: f64| Point::new(x, y);
    for algorithm in HullAlgorithm::ALL {
        let h = |pts: &[Point]| hull_vertices(pts, algorithm);
        assert_eq!(h(&[]), Err(PolygonError::TooFewVertices { distinct: 0 }));
        assert_eq!(h(&[p(1., 1.)]), Ok(vec![p(1., 1.)]));
        assert_eq!(h(&[p(1., 1.); 4]), Ok(vec![p(1., 1.)]));
        assert_eq!(h(&[p(2., 0.), p(1., 1.)]), Ok(vec![p(2., 0.), p(1., 1.)]));
        // Collinear: the two ends, the lowest (then leftmost) first.
        assert_eq!(
            h(&[p(0., 3.), p(2., 1.), p(3., 0.), p(1., 2.)]),
            Ok(vec![p(3., 0.), p(0., 3.)])
        );
        assert_eq!(
            h(&[p(4., 5.), p(-1., 5.), p(2., 5.)]),
            Ok(vec![p(-1., 5.), p(4., 5.)])
        );
        assert_eq!(
            h(&[p(0., 4.), p(0., -1.), p(0., 2.)]),
            Ok(vec![p(0., -1.), p(0., 4.)])
        );
        assert!(matches!(
            h(&[p(0., 0.), p(f64::INFINITY, 0.)]),
            Err(PolygonError::NonFinite { index: 1, .. })
        ));
        // Collinear points on every side of a square, the pivot repeated.
        let square = [
            p(0., 0.),
            p(1., 0.),
            p(2., 0.),
            p(2., 1.),
            p(2., 2.),
            p(1., 2.),
            p(0., 2.),
            p(0., 1.),
            p(0., 0.),
            p(1., 1.),
        ];
        assert_eq!(h(&square), Ok(vec![p(0., 0.), p(2., 0.), p(2., 2.), p(0., 2.)]));
    }
    assert_eq!(
        graham_scan(&[p(0., 0.), p(1., 1.), p(2., 2.)]),
        Err(PolygonError::AllCollinear)
    );
    assert_eq!(
        graham_scan(&[p(0., 0.), p(1., 1.), p(0., 0.)]),
        Err(PolygonError::TooFewVertices { distinct: 2 })
    );
}

#[test]
fn one_ulp_inside_and_outside() {
    // A point one ulp outside a hull edge is a vertex; one on the edge is not.
    let o = 2f64.powi(52);
    let up = |x: f64| f64::from_bits(x.to_bits() + 1);
    let base = [
        Point::new(o, o),
        Point::new(o + 4.0, o),
        Point::new(o + 4.0, o + 4.0),
        Point::new(o, o + 4.0),
    ];
    let mut on = base.to_vec();
    on.push(Point::new(o + 2.0, o + 2.0 + 2.0)); // on the top edge
    check(&on, "on edge");
    assert_eq!(hull_vertices(&on, HullAlgorithm::Graham).unwrap().len(), 4);
    let mut out = base.to_vec();
    out.push(Point::new(o + 2.0, up(o + 4.0)));
    check(&out, "one ulp out");
    assert_eq!(hull_vertices(&out, HullAlgorithm::Graham).unwrap().len(), 5);
}

#[test]
fn angular_order_is_a_simple_polygon() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    for round in 0..rounds() {
        let pts = random_set(&mut rng, round);
        let order = angular_order(&pts);
        let pivot = pivot_index(&pts).unwrap();
        assert_eq!(order[0], pivot, "round {round}");
        // Every point but the pivot's copies, each once.
        let mut sorted = order.clone();
        sorted.sort();
        sorted.dedup();
        assert_eq!(sorted.len(), order.len(), "round {round}");
        let kept = pts.iter().filter(|&&p| p != pts[pivot]).count() + 1;
        assert_eq!(order.len(), kept, "round {round}");
        // Without repeats and with three non-collinear points, a simple polygon.
        let mut poly: Vec<Point> = order.iter().map(|&i| pts[i]).collect();
        let mut seen = std::collections::HashSet::new();
        poly.retain(|p| seen.insert((p.x.to_bits(), p.y.to_bits())));
        if convex_hull(&poly).is_ok() {
            SimplePolygon::new(poly.clone()).unwrap_or_else(|e| panic!("round {round}: {e}: {poly:?}"));
        }
    }
    // The notes' case: collinear points on the last ray, farthest first.
    let pts = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [1.0, 1.0], [3.0, 3.0]].map(Point::from);
    assert_eq!(angular_order(&pts), [0, 1, 4, 2, 3]);
    SimplePolygon::new(angular_order(&pts).iter().map(|&i| pts[i]).collect::<Vec<_>>()).unwrap();
}

#[test]
fn protocol_diameter_is_a_farthest_pair() {
    use polysect::polygon::calipers::{compare_distances, farthest_pair_naive};
    use polysect::protocol::hull::hull_line;
    let mut rng = SmallRng::seed_from_u64(SEED + 2);
    for round in 0..rounds() / 4 {
        let pts = random_set(&mut rng, round);
        let line = format!("{{\"points\": {}}}", polysect::protocol::points_json(&pts));
        for algorithm in HullAlgorithm::ALL {
            let reply: serde_json::Value =
                serde_json::from_str(&hull_line(line.as_bytes(), algorithm)).unwrap();
            let hull: Vec<Point> = serde_json::from_value(reply["hull"].clone()).unwrap();
            assert_eq!(hull, hull_vertices(&pts, algorithm).unwrap(), "round {round}");
            let [a, b]: [Point; 2] = serde_json::from_value(reply["diameter"].clone()).unwrap();
            let (c, d) = farthest_pair_naive(&pts).unwrap();
            assert_eq!(
                compare_distances(a, b, c, d),
                std::cmp::Ordering::Equal,
                "round {round}: {reply}"
            );
            let (ia, ib) = (
                hull.iter().position(|&p| p == a),
                hull.iter().position(|&p| p == b),
            );
            assert!(ia.is_some() && ib.is_some() && ia <= ib, "round {round}: {reply}");
        }
    }
}
