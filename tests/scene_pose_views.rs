//! Posed polygons read by the array test through their poses (no world snapshot built
//! per pose): every answer and certificate against the exact reference on the world
//! polygons, `Pose::apply` of each shape vertex (itself checked against a rational
//! reference in `scene_poses.rs`).

use polysect::intersect::{ArrayIntersection, Linear, verify};
use polysect::kernel::Pose;
use polysect::store::{PolygonId, Scene, Strategy};
use polysect::{ConvexPolygon, Point};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::f64::consts::TAU;

const SEED: u64 = 0x0038_0006;

/// A strictly convex polygon of `n` vertices about the origin (an ellipse, sorted
/// angles, the hull of the points).
fn shape(rng: &mut SmallRng, n: usize) -> Vec<Point> {
    let (a, b) = (rng.random_range(0.5..1.0), rng.random_range(0.5..1.0));
    let pts: Vec<Point> = (0..n)
        .map(|_| {
            let t: f64 = rng.random_range(0.0..TAU);
            Point::new(a * t.cos(), b * t.sin())
        })
        .collect();
    polysect::polygon::convex_hull(&pts).unwrap().into_vertices()
}

fn world(scene: &Scene, id: PolygonId) -> ConvexPolygon {
    ConvexPolygon::from_ccw_unchecked(scene.world_points(id).unwrap())
}

/// Every pair of the scene against the reference, by `intersects`, by
/// `intersects_certified` (verified on the world polygons) and by the frame's pairs.
fn check_all(scene: &mut Scene, ids: &[PolygonId]) -> usize {
    let worlds: Vec<ConvexPolygon> = ids.iter().map(|&id| world(scene, id)).collect();
    let index = |id: PolygonId| ids.iter().position(|&x| x == id).unwrap();
    let mut want = Vec::new();
    for i in 0..ids.len() {
        for j in i + 1..ids.len() {
            if Linear.intersects(&worlds[i], &worlds[j]) {
                want.push((i, j));
            }
        }
    }
    let normal = |(a, b): (PolygonId, PolygonId)| {
        let (i, j) = (index(a), index(b));
        (i.min(j), i.max(j))
    };
    let mut got: Vec<(usize, usize)> = scene.intersecting_pairs().into_iter().map(normal).collect();
    got.sort_unstable();
    assert_eq!(got, want);
    let certified = scene.intersecting_pairs_certified();
    assert_eq!(certified.len(), want.len());
    for (a, b, c) in certified {
        assert_eq!(verify(&worlds[index(a)], &worlds[index(b)], &c), Ok(()), "{c:?}");
    }
    // Single queries, certified, on pairs of every kind (most are disjoint).
    for i in 0..ids.len() {
        let j = (i * 7 + 3) % ids.len();
        let c = scene.intersects_certified(ids[i], ids[j]).unwrap();
        assert_eq!(
            c.intersects(),
            i == j || Linear.intersects(&worlds[i], &worlds[j])
        );
        assert_eq!(verify(&worlds[i], &worlds[j], &c), Ok(()), "{c:?}");
        assert_eq!(scene.intersects(ids[i], ids[j]).unwrap(), c.intersects());
    }
    want.len()
}

/// Frames of random absolute poses: once the planner holds snapshots, the poses are
/// lazy and the array test reads the polygons through them (conversions stop while
/// array tests go on); every frame's pairs and certificates match the reference.
#[test]
fn random_poses_read_through_the_pose_match_the_reference() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    for round in 0..6 {
        let mut scene = Scene::new();
        scene.set_strategy(Strategy::Cached);
        let count = 24;
        let side = 4.0;
        let mut ids = Vec::new();
        for _ in 0..count {
            let n = rng.random_range(24..200);
            ids.push(scene.insert_points(shape(&mut rng, n)).unwrap());
        }
        let mut hits = 0;
        let mut conversions_after_warm_up = None;
        for frame in 0..12 {
            for &id in &ids {
                let scale = if round % 3 == 2 {
                    rng.random_range(0.5..2.0)
                } else {
                    1.0
                };
                let angle: f64 = rng.random_range(0.0..TAU);
                let pose = Pose::new(
                    [scale * angle.cos(), scale * angle.sin()],
                    [rng.random_range(0.0..side), rng.random_range(0.0..side)],
                )
                .unwrap();
                scene.set_pose(id, pose).unwrap();
            }
            hits += check_all(&mut scene, &ids);
            if frame == 2 {
                conversions_after_warm_up = Some(scene.stats().conversions);
            }
            let pairs = scene.stats().array_tests;
            // Certified and plain pairs both ran array tests on the later frames.
            assert!(frame < 3 || pairs > 0);
        }
        assert!(
            hits > 50,
            "{hits} intersecting pairs: the scene is too sparse to test"
        );
        // Lazy poses left the snapshots owed and nothing converted them again: the
        // array tests read the polygons through their poses.
        let settled = conversions_after_warm_up.unwrap();
        assert!(
            scene.stats().conversions <= settled + 2 * count as u64,
            "conversions went on: {} after {settled}",
            scene.stats().conversions
        );
    }
}

/// A triangle touching a turned polygon's extreme world vertex, and one ulp away from
/// it, read through the pose.
#[test]
fn touches_one_ulp_apart_after_a_turn_read_through_the_pose() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    for _ in 0..60 {
        let mut scene = Scene::new();
        scene.set_strategy(Strategy::Cached);
        let b = scene.insert_points(shape(&mut rng, 64)).unwrap();
        let far = scene
            .insert_points([[1e3, 1e3], [1e3 + 1.0, 1e3], [1e3, 1e3 + 1.0]])
            .unwrap();
        let a = scene
            .insert_points([[0.0, 0.0], [1.0, -1.0], [1.0, 1.0]])
            .unwrap();
        // First pose (checked in full), a query (the planner converts), then the pose
        // under test, lazy: `b`'s snapshot is owed.
        scene
            .set_pose(b, Pose::from_angle(0.1, [0.0, 0.0]).unwrap())
            .unwrap();
        scene
            .set_pose(a, Pose::new([1.0, 0.0], [50.0, 50.0]).unwrap())
            .unwrap();
        let _ = scene.intersects(a, b).unwrap();
        let _ = scene.intersecting_pairs();
        let pose = Pose::from_angle(rng.random_range(0.0..TAU), [rng.random_range(-9.0..9.0), 3.0]).unwrap();
        scene.set_pose(b, pose).unwrap();
        let w = scene.world_points(b).unwrap();
        let right = *w
            .iter()
            .max_by(|p, q| p.x.total_cmp(&q.x).then(q.y.total_cmp(&p.y)))
            .unwrap();
        for (gap, expect) in [(right.x, true), (right.x.next_up(), false)] {
            // `a` placed by a pose too (identity rotation), its tip at (gap, right.y).
            let tip = Pose::new([1.0, 0.0], [gap, right.y]).unwrap();
            scene.set_pose(a, tip).unwrap();
            let wa = world(&scene, a);
            assert_eq!(wa.vertices()[0], Point::new(gap, right.y), "an exact translation");
            let wb = ConvexPolygon::from_ccw_unchecked(w.clone());
            assert_eq!(Linear.intersects(&wa, &wb), expect);
            assert_eq!(scene.intersects(a, b).unwrap(), expect);
            let c = scene.intersects_certified(b, a).unwrap();
            assert_eq!(c.intersects(), expect);
            assert_eq!(verify(&wb, &wa, &c), Ok(()));
            let pairs = scene.intersecting_pairs();
            assert_eq!(
                pairs.iter().any(|&(x, y)| (x, y) == (a, b) || (x, y) == (b, a)),
                expect
            );
            assert!(!pairs.iter().any(|&(x, y)| x == far || y == far));
        }
    }
}
