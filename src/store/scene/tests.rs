//! The scene's private invariants: skipped translation checks, the grid, lazy
//! translations.

use super::*;
use crate::generate::regular_polygon;
use rand::Rng;

/// The scene skips the convexity check of a translation when the margin kept from
/// the last check proves rounding harmless. Against a copy translated with the full
/// check every time, on polygons whose vertices are a few ulps apart (where rounding
/// does break convexity) and on ordinary ones: the same acceptances, the same
/// refusals, the same coordinates, and skips actually taken.
fn snapped(points: &[Point], bits: i32) -> Vec<Point> {
    let g = 2f64.powi(-bits);
    let snap = |x: f64| (x / g).round() * g;
    let pts: Vec<Point> = points.iter().map(|p| Point::new(snap(p.x), snap(p.y))).collect();
    crate::polygon::convex_hull(&pts).unwrap().into_vertices()
}

/// `grid_of` is the largest power of two dividing both coordinates.
#[test]
fn grid_of_is_the_largest_dividing_power_of_two() {
    let mut rng = SmallRng::seed_from_u64(0x9e1d);
    assert_eq!(grid_of(Point::new(0.0, 0.0)), f64::INFINITY);
    assert_eq!(grid_of(Point::new(3.0, 0.0)), 1.0);
    assert_eq!(grid_of(Point::new(0.75, -6.0)), 0.25);
    assert_eq!(grid_of(Point::new(f64::from_bits(1), 1.0)), f64::from_bits(1));
    assert_eq!(grid_of(Point::new(f64::MAX, 0.0)), 2f64.powi(971));
    assert_eq!(grid_of(Point::new(f64::MIN_POSITIVE, 0.0)), f64::MIN_POSITIVE);
    for _ in 0..10_000 {
        let x = f64::from_bits(rng.random::<u64>() >> 1) * if rng.random_bool(0.5) { 1.0 } else { -1.0 };
        if !x.is_finite() || x == 0.0 {
            continue;
        }
        let g = grid_of(Point::new(x, 0.0));
        assert!(g.is_finite() && g > 0.0 && g.to_bits() & ((1u64 << 52) - 1) == 0 || g < f64::MIN_POSITIVE);
        // x / g is an odd integer (exact: dividing by a power of two, no underflow
        // below g itself).
        let q = x / g;
        assert_eq!(q, q.trunc(), "{x:e}");
        assert_eq!(q.abs() % 2.0, 1.0, "{x:e}");
    }
}

#[test]
fn skipped_translation_checks_agree_with_full_checks() {
    let mut rng = SmallRng::seed_from_u64(0x7a11);
    let shapes: Vec<Vec<Point>> = vec![
        // A triangle a few ulps wide near 2^20.
        vec![
            Point::new(1048576.0, 1048576.0),
            Point::new(1048576.0 + 4.0 * 2.3283064365386963e-10, 1048576.0),
            Point::new(1048576.0, 1048576.0 + 3.0 * 2.3283064365386963e-10),
        ],
        // Nearly flat turns: the hull of a fine regular polygon far from the origin.
        crate::polygon::convex_hull(
            &regular_polygon(4096, 1e-3)
                .vertices()
                .iter()
                .map(|p| Point::new(p.x + 1e8, p.y - 3e7))
                .collect::<Vec<_>>(),
        )
        .unwrap()
        .into_vertices(),
        regular_polygon(16, 1.0).into_vertices(),
        regular_polygon(256, 5.0).into_vertices(),
        // On a grid of 2^-20 (dyadic translations are then often exact).
        snapped(regular_polygon(64, 3.0).vertices(), 20),
        snapped(regular_polygon(1024, 0.5).vertices(), 30),
    ];
    let mut skipped = 0;
    let mut refused = 0;
    let mut exact_skips = 0;
    for (s, shape) in shapes.iter().enumerate() {
        let mut scene = Scene::new();
        let id = scene.insert_points(shape.iter().copied()).unwrap();
        let mut copy = scene.polygon(id).unwrap().clone();
        // Half the runs with a snapshot (checked on the array), half without.
        if s % 2 == 0 {
            scene.set_strategy(Strategy::Cached);
            let other = scene.insert_points(shape.iter().copied()).unwrap();
            scene.intersects(id, other).unwrap();
            assert!(scene.has_snapshot(id).unwrap());
        }
        for step in 0..3000 {
            let scale = [1e-12, 1e-6, 1.0, 1e3, 1e7][rng.random_range(0..5)];
            // The grid shapes keep to dyadic vectors (one other would lose the grid).
            let (dx, dy) = if s < 4 && rng.random_bool(0.5) {
                (rng.random_range(-scale..scale), rng.random_range(-scale..scale))
            } else {
                // Dyadic: k · 2^-j, exact or rounding depending on j and the size.
                let j = match s {
                    4 => rng.random_range(10..=20),
                    5 => rng.random_range(20..=30),
                    _ => rng.random_range(-10..60),
                };
                let mut d = || rng.random_range(-(1i64 << 20)..(1i64 << 20)) as f64 * 2f64.powi(-j);
                (d(), d())
            };
            let key = scene.key(id).unwrap();
            let margin_before = scene.entries[key].rounding_margin;
            let got = scene.translate(id, dx, dy);
            let want = copy.translate(dx, dy);
            assert_eq!(
                got,
                want.clone().map_err(|e| SceneError::Edit(id, e)),
                "shape {s} step {step}"
            );
            if want.is_err() {
                refused += 1;
            } else if margin_before > 0.0 && scene.entries[key].rounding_margin < margin_before {
                skipped += 1;
            }
            let ours: Vec<Point> = scene.polygon(id).unwrap().iter().map(|(_, p)| p).collect();
            let theirs: Vec<Point> = copy.iter().map(|(_, p)| p).collect();
            assert_eq!(ours, theirs, "shape {s} step {step}");
            if step % 500 == 0 {
                scene.debug_validate().unwrap();
            }
        }
        scene.debug_validate().unwrap();
        exact_skips += scene.exact_skips;
    }
    assert!(skipped > 1000, "{skipped} checks skipped");
    assert!(
        exact_skips > 500,
        "{exact_skips} translations proved exact by the grid"
    );
    assert!(refused > 10, "{refused} translations refused");
}

/// Translations of a polygon wait (up to the list's length) while only its snapshot
/// is read, and every reader of the linked polygon sees them applied: shared reads
/// through a twin, edits and conversions in place; the coordinates are eager
/// translation's, bit for bit.
#[test]
fn translations_wait_until_the_linked_polygon_is_read() {
    use super::super::lazy::MAX_PENDING;
    let mut scene = Scene::new();
    scene.set_strategy(Strategy::Cached);
    let a = scene.insert(LinkedPolygon::from_convex(&regular_polygon(64, 1.0)));
    let b = scene.insert(LinkedPolygon::from_convex(&regular_polygon(32, 0.5)));
    let mut eager = scene.polygon(a).unwrap().clone();
    assert!(scene.intersects(a, b).unwrap());
    assert!(scene.has_snapshot(a).unwrap());
    let key = scene.key(a).unwrap();
    let pending = |s: &Scene| s.entries[key].polygon.pending();
    let coords = |p: &LinkedPolygon| -> Vec<(u64, u64)> {
        p.iter().map(|(_, q)| (q.x.to_bits(), q.y.to_bits())).collect()
    };
    let mut max_seen = 0;
    for step in 0..3 * MAX_PENDING + 1 {
        let (dx, dy) = (0.01 + step as f64 * 1e-4, -0.007);
        scene.translate(a, dx, dy).unwrap();
        eager.translate(dx, dy).unwrap();
        max_seen = max_seen.max(pending(&scene));
        // Only the snapshot is read by the array test.
        scene.intersects(a, b).unwrap();
        assert_eq!(scene.stats().array_tests as usize, step + 2);
    }
    assert_eq!(
        max_seen, MAX_PENDING,
        "translations wait, and no more than the list holds"
    );
    assert!(pending(&scene) > 0);
    // A shared read: the twin, with handles valid on the polygon.
    let first = scene.polygon(a).unwrap().first();
    assert_eq!(coords(scene.polygon(a).unwrap()), coords(&eager));
    assert!(pending(&scene) > 0);
    // An edit: applied in place first (the old point is the translated one).
    let p = scene.polygon(a).unwrap().point(first).unwrap();
    assert_eq!(
        scene.move_vertex(a, first, p).unwrap(),
        eager.point(eager.first()).unwrap()
    );
    assert_eq!(pending(&scene), 0);
    assert_eq!(coords(scene.polygon(a).unwrap()), coords(&eager));
    // A translation without a snapshot waits too; a conversion applies it.
    assert!(!scene.has_snapshot(a).unwrap());
    scene.translate(a, 0.25, 0.5).unwrap();
    eager.translate(0.25, 0.5).unwrap();
    assert_eq!(pending(&scene), 1);
    scene.convert(key);
    assert_eq!(pending(&scene), 0);
    assert_eq!(coords(scene.polygon(a).unwrap()), coords(&eager));
    scene.debug_validate().unwrap();
    // Removal returns the translated polygon.
    scene.translate(a, -3.0, 1.0 / 3.0).unwrap();
    eager.translate(-3.0, 1.0 / 3.0).unwrap();
    assert_eq!(coords(&scene.remove(a).unwrap()), coords(&eager));
}
