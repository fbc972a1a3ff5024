//! Rotating calipers against the O(n²) references: the farthest pair of point sets and
//! of polygons (array and linked), the width and the least-area rectangle, on random
//! and adversarial inputs (collinear sets, duplicates, many points on a circle, huge and
//! tiny coordinates, one-ulp differences). Lengths are compared exactly, never the
//! pairs themselves (ties may pick different pairs).
//!
//! `POLYSECT_CALIPERS_ROUNDS` scales the random rounds (default 300).

use polysect::polygon::calipers::{
    compare_areas, compare_distances, compare_widths, farthest_pair, farthest_pair_linked,
    farthest_pair_naive, farthest_pair_of_points, min_area_rectangle, min_area_rectangle_naive, width,
    width_naive,
};
use polysect::polygon::convex_hull;
use polysect::{ConvexPolygon, LinkedPolygon, Point, PolygonError};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::cmp::Ordering;

const SEED: u64 = 0xca11_9e55;

fn rounds() -> usize {
    std::env::var("POLYSECT_CALIPERS_ROUNDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(300)
}

/// Checks every caliper answer on `points` against the references.
fn check(points: &[Point], what: &str) {
    let fast = farthest_pair_of_points(points).unwrap_or_else(|e| panic!("{what}: {e}"));
    let slow = farthest_pair_naive(points).expect("non-empty");
    assert_eq!(
        compare_distances(fast.0, fast.1, slow.0, slow.1),
        Ordering::Equal,
        "{what}: calipers {fast:?}, naive {slow:?}"
    );
    assert!(points.contains(&fast.0) && points.contains(&fast.1), "{what}");
    let Ok(hull) = convex_hull(points) else { return };
    hull.debug_validate().unwrap();
    check_polygon(&hull, what);
    assert_eq!(
        compare_distances(fast.0, fast.1, slow.0, slow.1),
        compare_distances(farthest_pair(&hull).0, farthest_pair(&hull).1, slow.0, slow.1),
        "{what}"
    );
}

fn check_polygon(p: &ConvexPolygon, what: &str) {
    let slow = farthest_pair_naive(p.vertices()).unwrap();
    // Every rotation of the array, and the linked form in a shuffled arena order.
    let mut rng = SmallRng::seed_from_u64(p.len() as u64);
    let starts = [0, 1, p.len() / 2, p.len() - 1];
    for s in starts {
        let r = p.starting_at(s);
        let d = farthest_pair(&r);
        assert_eq!(
            compare_distances(d.0, d.1, slow.0, slow.1),
            Ordering::Equal,
            "{what} (start {s}): {d:?} vs {slow:?}"
        );
        let w = width(&r);
        let wn = width_naive(&r);
        assert_eq!(
            compare_widths(&w, &wn),
            Ordering::Equal,
            "{what}: width {w:?} vs {wn:?}"
        );
        let m = min_area_rectangle(&r);
        let mn = min_area_rectangle_naive(&r);
        assert_eq!(
            compare_areas(&m, &mn),
            Ordering::Equal,
            "{what}: rectangle {m:?} vs {mn:?}"
        );
    }
    let linked = LinkedPolygon::from_convex_shuffled(p, &mut rng);
    let d = farthest_pair_linked(&linked);
    assert_eq!(
        compare_distances(d.0, d.1, slow.0, slow.1),
        Ordering::Equal,
        "{what}: linked"
    );
}

#[test]
fn random_point_sets() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    for round in 0..rounds() {
        let n = rng.random_range(1..120);
        let pts: Vec<Point> = match round % 3 {
            // Uniform in a square.
            0 => (0..n)
                .map(|_| Point::new(rng.random_range(-1e3..1e3), rng.random_range(-1e3..1e3)))
                .collect(),
            // A small grid: duplicates, collinear triples, many equal distances.
            1 => (0..n)
                .map(|_| Point::new(rng.random_range(0..6) as f64, rng.random_range(0..6) as f64))
                .collect(),
            // A disc, with repeats.
            _ => {
                let mut v: Vec<Point> = (0..n)
                    .map(|_| {
                        let (a, r): (f64, f64) = (rng.random_range(0.0..std::f64::consts::TAU), rng.random());
                        Point::new(r.sqrt() * a.cos(), r.sqrt() * a.sin())
                    })
                    .collect();
                let dup = v[rng.random_range(0..v.len())];
                v.push(dup);
                v
            }
        };
        check(&pts, &format!("round {round}"));
    }
}

#[test]
fn points_on_a_circle_and_regular_polygons() {
    // Many points on a circle: nearly every pair is nearly a diameter; exact
    // comparisons must still pick a farthest one.
    for n in [3, 4, 5, 6, 7, 8, 64, 360, 1000] {
        let pts: Vec<Point> = (0..n)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                Point::new(a.cos(), a.sin())
            })
            .collect();
        check(&pts, &format!("circle {n}"));
        // Integer points on a circle: exact ties between different pairs.
        let r = 5.0;
        let lattice: Vec<Point> = [
            (5., 0.),
            (4., 3.),
            (3., 4.),
            (0., 5.),
            (-3., 4.),
            (-4., 3.),
            (-5., 0.),
            (-4., -3.),
            (-3., -4.),
            (0., -5.),
            (3., -4.),
            (4., -3.),
        ]
        .map(|(x, y)| Point::new(x * r, y * r))
        .to_vec();
        check(&lattice, "lattice circle");
    }
}

#[test]
fn degenerate_point_sets() {
    let p = |x: f64, y: f64| Point::new(x, y);
    assert_eq!(
        farthest_pair_of_points(&[]),
        Err(PolygonError::TooFewVertices { distinct: 0 })
    );
    assert!(matches!(
        farthest_pair_of_points(&[p(0., 0.), p(f64::NAN, 1.)]),
        Err(PolygonError::NonFinite { index: 1, .. })
    ));
    assert_eq!(farthest_pair_of_points(&[p(1., 2.)]), Ok((p(1., 2.), p(1., 2.))));
    assert_eq!(
        farthest_pair_of_points(&[p(1., 2.); 5]),
        Ok((p(1., 2.), p(1., 2.)))
    );
    // Collinear, unsorted, with repeats: the two ends.
    let line = [p(3., 3.), p(0., 0.), p(5., 5.), p(1., 1.), p(5., 5.), p(-2., -2.)];
    assert_eq!(farthest_pair_of_points(&line), Ok((p(-2., -2.), p(5., 5.))));
    let vertical = [p(0., 3.), p(0., -1.), p(0., 2.)];
    assert_eq!(farthest_pair_of_points(&vertical), Ok((p(0., -1.), p(0., 3.))));
    check(&line, "collinear");
    check(&vertical, "vertical");
}

#[test]
fn huge_tiny_and_one_ulp_coordinates() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    for (scale, offset) in [
        (1e300, 0.0),
        (1e-300, 0.0),
        (f64::MIN_POSITIVE, 0.0),
        (5e-324, 0.0),
        (1.0, 2f64.powi(52)),
        (1.0, 1e15),
    ] {
        for round in 0..20 {
            let n = rng.random_range(3..40);
            let pts: Vec<Point> = (0..n)
                .map(|_| {
                    Point::new(
                        offset + scale * rng.random_range(-8..8) as f64,
                        offset + scale * rng.random_range(-8..8) as f64,
                    )
                })
                .collect();
            check(&pts, &format!("scale {scale:e} offset {offset:e} round {round}"));
        }
    }
    // Two candidate pairs that differ by one ulp in one coordinate: the longer must win.
    let o = 2f64.powi(40);
    let up = |x: f64| f64::from_bits(x.to_bits() + 1);
    let pts = [
        Point::new(o, o),
        Point::new(o + 1024.0, o),
        Point::new(o + 512.0, o - 1024.0),
        Point::new(o + 512.0, up(o - 1024.0 + 2048.0)),
    ];
    let d = farthest_pair_of_points(&pts).unwrap();
    assert_eq!(d, (pts[2], pts[3]), "one ulp longer");
    check(&pts, "one ulp");
    // The same without the ulp: a tie, and the lengths still agree with the reference.
    let tie = [pts[0], pts[1], pts[2], Point::new(o + 512.0, o + 1024.0)];
    check(&tie, "tie");
}

#[test]
fn width_and_rectangle_of_known_shapes() {
    let square = ConvexPolygon::new([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]).unwrap();
    assert_eq!(width(&square).value(), 2.0);
    assert_eq!(min_area_rectangle(&square).area(), 4.0);
    // A long thin diamond: the rectangle is tilted with the diamond.
    let diamond = ConvexPolygon::new([[0.0, 0.0], [10.0, 10.0], [9.0, 11.0], [-1.0, 1.0]]).unwrap();
    let r = min_area_rectangle(&diamond);
    assert!((r.area() - 20.0).abs() < 1e-9, "{r:?} area {}", r.area());
    for c in r.corners() {
        assert!(c.x.is_finite() && c.y.is_finite());
    }
    assert!((width(&diamond).value() - 2f64.sqrt()).abs() < 1e-12);
    check_polygon(&diamond, "diamond");
}
