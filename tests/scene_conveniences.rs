//! The scene's conveniences against exact references: `Scene::contains_point` on plain,
//! translated (translations waiting in the linked polygon), edited and posed polygons,
//! with and without array snapshots, under every strategy.

use polysect::generate::regular_polygon;
use polysect::kernel::Pose;
use polysect::store::{PolygonId, Scene, SceneError, Strategy};
use polysect::{Exact, Kernel, LinkedPolygon, Orientation, Point};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

/// Closed containment by brute force: strictly right of no edge of the
/// counter-clockwise polygon `v` (exact).
fn inside(v: &[Point], x: Point) -> bool {
    let n = v.len();
    x.is_finite() && (0..n).all(|i| Exact.orient(v[i], v[(i + 1) % n], x) != Orientation::Cw)
}

/// Points to probe `v` with: every vertex, points on, one ulp off and near each edge,
/// the box's corners, points far away and non-finite ones.
fn probes(v: &[Point], rng: &mut SmallRng) -> Vec<Point> {
    let n = v.len();
    let mut out = Vec::new();
    for i in 0..n {
        let (a, b) = (v[i], v[(i + 1) % n]);
        let mid = Point::new(a.x / 2.0 + b.x / 2.0, a.y / 2.0 + b.y / 2.0);
        out.extend([
            a,
            mid,
            Point::new(mid.x.next_up(), mid.y),
            Point::new(mid.x.next_down(), mid.y),
            Point::new(mid.x, mid.y.next_up()),
            Point::new(mid.x, mid.y.next_down()),
            Point::new(a.x.next_up(), a.y.next_up()),
            Point::new(a.x.next_down(), a.y.next_down()),
        ]);
    }
    let (lo, hi) = v.iter().fold(
        (
            Point::new(f64::INFINITY, f64::INFINITY),
            Point::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
        ),
        |(lo, hi), p| {
            (
                Point::new(lo.x.min(p.x), lo.y.min(p.y)),
                Point::new(hi.x.max(p.x), hi.y.max(p.y)),
            )
        },
    );
    out.extend([lo, hi, Point::new(lo.x, hi.y), Point::new(hi.x, lo.y)]);
    for _ in 0..20 {
        out.push(Point::new(
            rng.random_range(lo.x - 1.0..hi.x + 1.0),
            rng.random_range(lo.y - 1.0..hi.y + 1.0),
        ));
    }
    out.extend([
        Point::new(1e300, -1e300),
        Point::new(f64::NAN, 0.0),
        Point::new(0.0, f64::INFINITY),
    ]);
    out
}

/// Probes every polygon of `scene` and compares with the brute-force answer on its
/// world points; returns how many probes met a polygon with a snapshot and without.
fn check_all(scene: &mut Scene, ids: &[PolygonId], rng: &mut SmallRng, label: &str) -> [usize; 2] {
    let mut tally = [0, 0];
    for &id in ids {
        let world = scene.world_points(id).unwrap();
        let snapshot = scene.has_snapshot(id).unwrap();
        let stats = scene.stats();
        for x in probes(&world, rng) {
            let got = scene.contains_point(id, x).unwrap();
            assert_eq!(got, inside(&world, x), "{label}: {id} at {x:?}");
            tally[usize::from(!snapshot)] += 1;
        }
        assert_eq!(scene.stats(), stats, "{label}: containment changed the counters");
        assert_eq!(scene.has_snapshot(id).unwrap(), snapshot, "{label}: converted");
    }
    scene.debug_validate().unwrap();
    tally
}

#[test]
fn contains_point_matches_brute_force_on_every_kind_of_polygon() {
    let mut rng = SmallRng::seed_from_u64(0xc07a_1250);
    let mut tally = [0usize, 0];
    let mut add = |t: [usize; 2]| {
        tally[0] += t[0];
        tally[1] += t[1];
    };
    for strategy in Strategy::ALL {
        for round in 0..6u64 {
            let mut scene = Scene::new();
            scene.seed(round);
            scene.set_strategy(strategy);
            let mut ids = Vec::new();
            for i in 0..8 {
                let n = [3usize, 4, 7, 16, 64, 300][rng.random_range(0..6)];
                let r = rng.random_range(0.5..4.0);
                let mut pts: Vec<Point> = regular_polygon(n, r).vertices().to_vec();
                let (cx, cy) = (rng.random_range(-6.0..6.0), rng.random_range(-6.0..6.0));
                for p in &mut pts {
                    *p = Point::new(p.x + cx, p.y + cy);
                }
                if i % 3 == 0 {
                    // Far from the origin, where rounding is coarse.
                    for p in &mut pts {
                        *p = Point::new(p.x * 1e12 + 3e15, p.y * 1e12);
                    }
                }
                ids.push(scene.insert(LinkedPolygon::from_points(pts).unwrap()));
            }
            let label = format!("{strategy:?} round {round}");
            add(check_all(&mut scene, &ids, &mut rng, &format!("{label} fresh")));
            // Queries give some polygons snapshots (the cached strategy all of them).
            scene.intersecting_pairs();
            for &id in &ids {
                scene.intersects(id, ids[0]).unwrap();
            }
            add(check_all(&mut scene, &ids, &mut rng, &format!("{label} queried")));
            // Translations wait in the linked polygon; a snapshot shifts at once.
            for &id in &ids {
                scene.translate(id, 0.375, -1.25).unwrap();
            }
            add(check_all(
                &mut scene,
                &ids,
                &mut rng,
                &format!("{label} translated"),
            ));
            // An edit drops the snapshot; a pose puts the world polygon elsewhere.
            let first = scene.polygon(ids[1]).unwrap().first();
            let p = scene.polygon(ids[1]).unwrap().point(first).unwrap();
            let _ = scene.remove_vertex(ids[1], first);
            let _ = scene.move_vertex(ids[1], scene.polygon(ids[1]).unwrap().first(), p);
            scene
                .set_pose(ids[2], Pose::new([0.6, 0.8], [-2.5, 7.0]).unwrap())
                .unwrap();
            scene
                .set_pose(ids[3], Pose::new([-1.0, 0.0], [0.0, 0.0]).unwrap())
                .unwrap();
            add(check_all(
                &mut scene,
                &ids,
                &mut rng,
                &format!("{label} edited and posed"),
            ));
        }
    }
    // Both paths, the array search and the sampled search, were taken many times.
    assert!(tally[0] > 1_000 && tally[1] > 1_000, "{tally:?}");
}

#[test]
fn contains_point_refuses_stale_and_foreign_handles() {
    let mut scene = Scene::new();
    let a = scene.insert_points([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]).unwrap();
    let mut other = scene.clone();
    assert_eq!(
        other.contains_point(a, [0.0, 0.0]),
        Err(SceneError::ForeignPolygon(a))
    );
    scene.remove(a).unwrap();
    assert_eq!(
        scene.contains_point(a, [0.0, 0.0]),
        Err(SceneError::StalePolygon(a))
    );
}

/// User data against a plain map kept beside the scene: random inserts (with and
/// without a value), removals (slots reused), sets, vertex edits, translations, poses
/// and queries that build snapshots; every live handle reads its value, every removed
/// one is `StalePolygon` (also once its slot holds another polygon), a clone's handles
/// read the same values in slot order, and refused calls change nothing.
#[test]
fn user_data_stays_with_its_polygon_through_everything() {
    use std::collections::HashMap;
    let mut rng = SmallRng::seed_from_u64(0x05e2_da7a);
    for strategy in Strategy::ALL {
        let mut scene = Scene::new();
        scene.set_strategy(strategy);
        scene.seed(3);
        let mut model: HashMap<PolygonId, u128> = HashMap::new();
        let mut removed: Vec<PolygonId> = Vec::new();
        for step in 0..3_000 {
            let live: Vec<PolygonId> = scene.ids().collect();
            let pick = |rng: &mut SmallRng| live[rng.random_range(0..live.len())];
            match rng.random_range(0..10) {
                _ if live.len() < 4 => {
                    let n = rng.random_range(3..40);
                    let (cx, cy) = (rng.random_range(-20.0..20.0), rng.random_range(-20.0..20.0));
                    let pts: Vec<Point> = regular_polygon(n, rng.random_range(0.5..5.0))
                        .vertices()
                        .iter()
                        .map(|p| Point::new(p.x + cx, p.y + cy))
                        .collect();
                    let polygon = LinkedPolygon::from_points(pts).unwrap();
                    let (id, value) = if rng.random_bool(0.5) {
                        let value: u128 = rng.random();
                        (scene.insert_with_user_data(polygon, value), value)
                    } else {
                        (scene.insert(polygon), 0)
                    };
                    model.insert(id, value);
                }
                0 => {
                    let id = pick(&mut rng);
                    scene.remove(id).unwrap();
                    model.remove(&id);
                    removed.push(id);
                }
                1 | 2 => {
                    let id = pick(&mut rng);
                    let value = if rng.random_bool(0.2) {
                        u128::MAX
                    } else {
                        rng.random()
                    };
                    let old = scene.set_user_data(id, value).unwrap();
                    assert_eq!(Some(old), model.insert(id, value), "step {step}");
                }
                3 => {
                    let id = pick(&mut rng);
                    let v = scene.polygon(id).unwrap().first();
                    let _ = scene.remove_vertex(id, v);
                    let (v, w) = {
                        let p = scene.polygon(id).unwrap();
                        let v = p.first();
                        (v, p.next(v).unwrap())
                    };
                    let (a, b) = (
                        scene.polygon(id).unwrap().point(v).unwrap(),
                        scene.polygon(id).unwrap().point(w).unwrap(),
                    );
                    let _ = scene.insert_vertex(
                        id,
                        v,
                        Point::new(a.x / 2.0 + b.x / 2.0, a.y / 2.0 + b.y / 2.0 - 1e-3),
                    );
                }
                4 | 5 => {
                    let id = pick(&mut rng);
                    // Refused likewise where rounding would flatten a corner.
                    let _ = scene.translate(id, rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0));
                }
                6 => {
                    let id = pick(&mut rng);
                    let t = rng.random_range(0.0..std::f64::consts::TAU);
                    let pose = Pose::new([t.cos(), t.sin()], [rng.random_range(-9.0..9.0), 0.0]).unwrap();
                    // Refused (changing nothing) when rounding the turned image
                    // flattens a corner that an insertion made nearly straight.
                    let _ = scene.set_pose(id, pose);
                }
                7 => {
                    scene.intersecting_pairs();
                }
                _ => {
                    // Refused calls on stale handles change nothing.
                    if let Some(&gone) = removed.last() {
                        assert_eq!(scene.user_data(gone), Err(SceneError::StalePolygon(gone)));
                        assert_eq!(scene.set_user_data(gone, 1), Err(SceneError::StalePolygon(gone)));
                    }
                }
            }
            for (&id, &value) in &model {
                assert_eq!(scene.user_data(id), Ok(value), "{strategy:?} step {step}");
            }
            assert_eq!(model.len(), scene.len());
        }
        for &gone in &removed {
            assert_eq!(scene.user_data(gone), Err(SceneError::StalePolygon(gone)));
        }
        let copy = scene.clone();
        let original: Vec<u128> = scene.ids().map(|id| scene.user_data(id).unwrap()).collect();
        let copied: Vec<u128> = copy.ids().map(|id| copy.user_data(id).unwrap()).collect();
        assert_eq!(original, copied);
        let some = scene.ids().next().unwrap();
        assert_eq!(copy.user_data(some), Err(SceneError::ForeignPolygon(some)));
        scene.debug_validate().unwrap();
    }
}

/// `intersects_shared` and `contains_point_shared` through `&Scene`, from three threads
/// at once, against brute force on the world polygons: fresh polygons, polygons with
/// snapshots, with translations waiting, edited and posed, large enough for the sampled
/// test. Nothing the planner keeps changes: counters, snapshots, versions.
#[test]
fn shared_queries_answer_exactly_from_several_threads_and_change_nothing() {
    use polysect::ConvexPolygon;
    use polysect::intersect::{ArrayIntersection, Linear};
    fn assert_sync<T: Sync>(_: &T) {}
    let mut rng = SmallRng::seed_from_u64(0x5ba2_ed00);
    for round in 0..4u64 {
        let mut scene = Scene::new();
        scene.seed(round);
        let mut ids = Vec::new();
        for i in 0..24 {
            let n = [3usize, 8, 16, 200, 3_000][i % 5];
            let (cx, cy) = (rng.random_range(-8.0..8.0), rng.random_range(-8.0..8.0));
            let pts: Vec<Point> = regular_polygon(n, rng.random_range(0.5..3.0))
                .vertices()
                .iter()
                .map(|p| Point::new(p.x + cx, p.y + cy))
                .collect();
            ids.push(scene.insert(LinkedPolygon::from_points(pts).unwrap()));
        }
        // Some snapshots, some translations waiting, a pose, an edit.
        scene.intersecting_pairs();
        for &id in ids.iter().step_by(3) {
            scene.translate(id, 0.125, -0.5).unwrap();
        }
        scene
            .set_pose(ids[1], Pose::new([0.0, 1.0], [1.0, 2.0]).unwrap())
            .unwrap();
        let v = scene.polygon(ids[4]).unwrap().first();
        scene.remove_vertex(ids[4], v).unwrap();
        // Both kinds of answer are reached: arrays, and linked polygons large enough to
        // be sampled.
        let held: Vec<bool> = ids.iter().map(|&id| scene.has_snapshot(id).unwrap()).collect();
        assert!(held.iter().filter(|&&h| h).count() >= 2, "{held:?}");
        assert!(
            ids.iter()
                .zip(&held)
                .any(|(&id, &h)| !h && scene.polygon(id).unwrap().len() >= 200),
            "{held:?}"
        );
        let worlds: Vec<ConvexPolygon> = ids
            .iter()
            .map(|&id| ConvexPolygon::new(scene.world_points(id).unwrap()).unwrap())
            .collect();
        let pairs: Vec<(usize, usize)> = (0..ids.len())
            .flat_map(|i| (0..ids.len()).map(move |j| (i, j)))
            .collect();
        let truth: Vec<bool> = pairs
            .iter()
            .map(|&(i, j)| Linear.intersects(&worlds[i], &worlds[j]))
            .collect();
        assert!(
            truth.iter().filter(|&&t| t).count() > ids.len(),
            "some pairs meet"
        );
        let probes: Vec<(usize, Point)> = (0..600)
            .map(|k| {
                let i = k % ids.len();
                let w = worlds[i].vertices();
                let (a, b) = (w[k % w.len()], w[(k + 1) % w.len()]);
                let mid = Point::new(a.x / 2.0 + b.x / 2.0, a.y / 2.0 + b.y / 2.0);
                let x = match k % 3 {
                    0 => a,
                    1 => Point::new(mid.x.next_up(), mid.y.next_down()),
                    _ => Point::new(mid.x * 0.9, mid.y * 0.9),
                };
                (i, x)
            })
            .collect();
        let (stats, snapshots, versions) = (
            scene.stats(),
            scene.snapshot_count(),
            ids.iter()
                .map(|&id| scene.version(id).unwrap())
                .collect::<Vec<_>>(),
        );
        let shared = &scene;
        assert_sync(shared);
        std::thread::scope(|s| {
            for t in 0..3 {
                let (pairs, truth, probes, worlds, ids) = (&pairs, &truth, &probes, &worlds, &ids);
                s.spawn(move || {
                    for (k, &(i, j)) in pairs.iter().enumerate().skip(t).step_by(3) {
                        assert_eq!(
                            shared.intersects_shared(ids[i], ids[j]),
                            Ok(truth[k]),
                            "round {round}: {i} {j}"
                        );
                    }
                    for &(i, x) in probes.iter().skip(t).step_by(3) {
                        let want = worlds[i].contains_point(x);
                        assert_eq!(shared.contains_point_shared(ids[i], x), Ok(want), "{i} {x:?}");
                    }
                    // One polygon against all, and the frame, from two of the threads,
                    // against the same truth.
                    let n = ids.len();
                    match t {
                        0 => {
                            for i in 0..n {
                                let want: Vec<_> = (0..n)
                                    .filter(|&j| j != i && truth[i * n + j])
                                    .map(|j| ids[j])
                                    .collect();
                                assert_eq!(
                                    shared.intersecting_shared(ids[i]),
                                    Ok(want),
                                    "round {round}: {i}"
                                );
                            }
                        }
                        1 => {
                            let want: Vec<_> = (0..n)
                                .flat_map(|i| (i + 1..n).map(move |j| (i, j)))
                                .filter(|&(i, j)| truth[i * n + j])
                                .map(|(i, j)| (ids[i], ids[j]))
                                .collect();
                            assert_eq!(shared.intersecting_pairs_shared(), want, "round {round}");
                        }
                        _ => {}
                    }
                });
            }
        });
        assert_eq!(scene.stats(), stats);
        assert_eq!(scene.snapshot_count(), snapshots);
        let after: Vec<u64> = ids.iter().map(|&id| scene.version(id).unwrap()).collect();
        assert_eq!(after, versions);
        // The planned queries agree.
        for (k, &(i, j)) in pairs.iter().enumerate().step_by(7) {
            assert_eq!(scene.intersects(ids[i], ids[j]), Ok(truth[k]));
        }
        scene.debug_validate().unwrap();
        let gone = ids[0];
        scene.remove(gone).unwrap();
        assert_eq!(
            scene.intersects_shared(gone, ids[1]),
            Err(SceneError::StalePolygon(gone))
        );
        assert_eq!(
            scene.contains_point_shared(gone, [0.0, 0.0]),
            Err(SceneError::StalePolygon(gone))
        );
        assert_eq!(
            scene.intersecting_shared(gone),
            Err(SceneError::StalePolygon(gone))
        );
        // The frame through `&self` is the planned frame.
        assert_eq!(scene.intersecting_pairs_shared(), scene.intersecting_pairs());
    }
}
