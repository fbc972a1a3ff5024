//! The scene: operations and stale handles, planned answers against the exact reference
//! under random edit/query streams for every strategy, broad phase against brute force,
//! parallel batches against sequential queries.

use polysect::generate::{self, Family, Relation, regular_polygon};
use polysect::intersect::{ArrayIntersection, Linear};
use polysect::store::{Scene, SceneError, Strategy};
use polysect::{ConvexPolygon, EditError, LinkedPolygon, Point, VertexId};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const SEEDS: [u64; 3] = [0x5ce1, 0x5ce2, 0x5ce3];

fn truth(scene: &Scene, a: polysect::store::PolygonId, b: polysect::store::PolygonId) -> bool {
    let p = scene.polygon(a).unwrap().to_convex();
    let q = scene.polygon(b).unwrap().to_convex();
    Linear.intersects(&p, &q)
}

/// A scene of `count` polygons of mixed sizes scattered so that some overlap.
fn scattered_scene(rng: &mut SmallRng, count: usize, max_log2: u32) -> Scene {
    let mut scene = Scene::new();
    for _ in 0..count {
        let n = 1usize << rng.random_range(2..=max_log2);
        let (p, _) = generate::pair(Family::NonUniform, n, Relation::Any, rng);
        let (dx, dy) = (rng.random_range(-4.0..4.0), rng.random_range(-4.0..4.0));
        let moved = p.map(|v| Point::new(v.x + dx, v.y + dy)).unwrap_or(p);
        scene.insert(LinkedPolygon::from_convex_shuffled(&moved, rng));
    }
    scene
}

/// A random edit that is usually valid: a vertex nudged along its position vector, a
/// point pushed out of an edge, a removal, or a translation (now and then by an offset
/// so large that rounding collapses the polygon, which must be refused).
fn random_edit(
    scene: &mut Scene,
    id: polysect::store::PolygonId,
    rng: &mut SmallRng,
) -> Result<(), SceneError> {
    let poly = scene.polygon(id)?;
    let v: VertexId = poly.random_vertex(rng);
    let edit = |e| SceneError::Edit(id, e);
    let a = poly.point(v).map_err(edit)?;
    let b = poly.point(poly.next(v).map_err(edit)?).map_err(edit)?;
    let c = poly.to_convex();
    let (cx, cy) = centroid(&c);
    match rng.random_range(0..4) {
        3 => {
            let scale = if rng.random_bool(0.05) { 1e17 } else { 0.5 };
            let (dx, dy) = (rng.random_range(-scale..scale), rng.random_range(-scale..scale));
            let before = scene.polygon(id)?.to_convex();
            let had_snapshot = scene.has_snapshot(id)?;
            let result = scene.translate(id, dx, dy);
            match &result {
                Ok(()) => assert_eq!(
                    scene.has_snapshot(id)?,
                    had_snapshot,
                    "translation keeps the snapshot"
                ),
                Err(_) => assert_eq!(
                    scene.polygon(id)?.to_convex(),
                    before,
                    "a refused translation changes nothing"
                ),
            }
            result
        }
        0 => {
            let f = 1.0 + rng.random_range(-0.05..0.05);
            scene
                .move_vertex(id, v, Point::new(cx + (a.x - cx) * f, cy + (a.y - cy) * f))
                .map(|_| ())
        }
        1 => {
            let f = 1.0 + rng.random_range(0.0..0.02);
            let (mx, my) = ((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
            scene
                .insert_vertex(id, v, Point::new(cx + (mx - cx) * f, cy + (my - cy) * f))
                .map(|_| ())
        }
        _ => scene.remove_vertex(id, v).map(|_| ()),
    }
}

fn centroid(c: &ConvexPolygon) -> (f64, f64) {
    let n = c.len() as f64;
    let (sx, sy) = c
        .vertices()
        .iter()
        .fold((0.0, 0.0), |(x, y), p| (x + p.x, y + p.y));
    (sx / n, sy / n)
}

#[test]
fn handles_go_stale_and_failed_operations_change_nothing() {
    let mut scene = Scene::new();
    let a = scene.insert_points([[0., 0.], [1., 0.], [0., 1.]]).unwrap();
    let b = scene.insert_points([[5., 5.], [6., 5.], [5., 6.]]).unwrap();
    assert!(matches!(
        scene.insert_points([[0., 0.], [1., 1.]]),
        Err(SceneError::Polygon(_))
    ));
    assert_eq!(scene.len(), 2);
    scene.remove(a).unwrap();
    assert_eq!(scene.remove(a).unwrap_err(), SceneError::StalePolygon(a));
    assert_eq!(scene.intersects(a, b), Err(SceneError::StalePolygon(a)));
    // The freed slot is reused; the old handle still refuses.
    let c = scene.insert_points([[0., 0.], [1., 0.], [0., 1.]]).unwrap();
    assert_ne!(a, c);
    assert_eq!(scene.polygon(a).unwrap_err(), SceneError::StalePolygon(a));
    let first = scene.polygon(c).unwrap().first();
    let before = scene.polygon(c).unwrap().to_convex();
    let err = scene.move_vertex(c, first, Point::new(0.5, 0.5)).unwrap_err();
    assert!(matches!(
        err,
        SceneError::Edit(id, EditError::WouldBreakConvexity { .. }) if id == c
    ));
    assert_eq!(
        scene.remove_vertex(c, first).unwrap_err(),
        SceneError::Edit(c, EditError::TooFewVertices)
    );
    assert_eq!(scene.polygon(c).unwrap().to_convex(), before);
    assert_eq!(scene.version(c), Ok(0));
    assert!(!scene.intersects(b, c).unwrap());
    assert!(scene.intersects(c, c).unwrap());
    scene.debug_validate().unwrap();
}

/// The newcomer's case: a vertex handle of one polygon given to another (of the same
/// scene or another), and polygon handles of another scene or of a clone. Every method
/// taking a handle refuses with the foreign-handle error and changes nothing.
#[test]
fn foreign_handles_are_refused_by_every_method() {
    let square = [[0., 0.], [4., 0.], [4., 4.], [0., 4.]];
    let mut scene = Scene::new();
    let s1 = scene.insert_points(square).unwrap();
    let s2 = scene.insert_points(square).unwrap();
    let s3 = scene.insert_points([[10., 10.], [11., 10.], [11., 11.]]).unwrap();
    let mut other = Scene::new();
    let o1 = other.insert_points(square).unwrap();
    let copy = scene.clone();
    let c1 = copy.ids().next().unwrap();
    assert_eq!(
        copy.polygon(c1).unwrap().to_convex(),
        scene.polygon(s1).unwrap().to_convex()
    );

    let snapshot = |scene: &Scene| -> Vec<_> {
        scene
            .ids()
            .map(|id| (scene.polygon(id).unwrap().to_convex(), scene.version(id).unwrap()))
            .collect()
    };
    let before = snapshot(&scene);
    for foreign in [o1, c1] {
        let e = Err(SceneError::ForeignPolygon(foreign));
        assert_eq!(scene.polygon(foreign).map(|_| ()), e);
        assert_eq!(scene.bounding_box(foreign).map(|_| ()), e);
        assert_eq!(scene.version(foreign).map(|_| ()), e);
        assert_eq!(scene.has_snapshot(foreign).map(|_| ()), e);
        let v = scene.polygon(s1).unwrap().first();
        assert_eq!(
            scene.insert_vertex(foreign, v, Point::new(2., -1.)).map(|_| ()),
            e
        );
        assert_eq!(scene.remove_vertex(foreign, v).map(|_| ()), e);
        assert_eq!(scene.move_vertex(foreign, v, Point::new(-1., -1.)).map(|_| ()), e);
        assert_eq!(scene.translate(foreign, 1.0, 0.0), e);
        assert_eq!(scene.intersects(s1, foreign).map(|_| ()), e);
        assert_eq!(scene.intersects(foreign, s1).map(|_| ()), e);
        assert_eq!(scene.intersecting(foreign).map(|_| ()), e);
        assert_eq!(
            scene.intersects_batch(&[(s1, s2), (s1, foreign)]),
            vec![Ok(true), Err(SceneError::ForeignPolygon(foreign))]
        );
        assert_eq!(scene.remove(foreign).map(|_| ()), e);
    }
    // Vertex handles of another polygon: of this scene (s2, s3: the same slots and
    // generations as s1's own handles), of another scene, of the clone.
    let vertex_of = |scene: &Scene, id| scene.polygon(id).unwrap().first();
    for v in [
        vertex_of(&scene, s2),
        vertex_of(&scene, s3),
        vertex_of(&other, o1),
        vertex_of(&copy, c1),
    ] {
        let e = Err(SceneError::Edit(s1, EditError::ForeignHandle));
        assert_eq!(scene.insert_vertex(s1, v, Point::new(2., -1.)).map(|_| ()), e);
        assert_eq!(scene.remove_vertex(s1, v).map(|_| ()), e);
        assert_eq!(scene.move_vertex(s1, v, Point::new(-1., -1.)).map(|_| ()), e);
        assert!(!scene.polygon(s1).unwrap().has_vertex(v));
    }
    assert_eq!(snapshot(&scene), before, "refused calls change nothing");
    // The clone refuses the original's handles too; its own work.
    assert_eq!(copy.polygon(s1).map(|_| ()), Err(SceneError::ForeignPolygon(s1)));
    // A polygon's own vertex handles keep working through the scene and after removal.
    let mut poly = LinkedPolygon::from_points(square).unwrap();
    let mine = poly.first();
    poly.move_vertex(mine, Point::new(-1., -1.)).unwrap();
    let id = scene.insert(poly);
    assert_eq!(
        scene.move_vertex(id, mine, Point::new(0., 0.)),
        Ok(Point::new(-1., -1.))
    );
    let back = scene.remove(id).unwrap();
    assert_eq!(back.point(mine), Ok(Point::new(0., 0.)));
    scene.debug_validate().unwrap();
}

/// Cycles of the hostile-use test; `POLYSECT_HOSTILE_CYCLES` raises it (the issue's
/// report used 5 million).
fn hostile_cycles() -> usize {
    std::env::var("POLYSECT_HOSTILE_CYCLES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1_000_000)
}

/// Memory stays O(live polygons + vertices) whatever the call pattern: insert /
/// `intersects` / remove cycles, edits alone and translations alone never reach a
/// broad-phase query, and used to grow its list of changed boxes by one entry each.
#[test]
fn memory_is_bounded_under_calls_that_never_query_the_broad_phase() {
    let cycles = hostile_cycles();
    let mut scene = Scene::new();
    let a = scene
        .insert_points([[0., 0.], [4., 0.], [4., 4.], [0., 4.]])
        .unwrap();
    let triangle = LinkedPolygon::from_points([[1., 1.], [5., 1.], [1., 5.]]).unwrap();
    // A polygon's first translation allocates its fixed list of waiting translations
    // once: translate before the baseline, so that what follows must not grow at all.
    scene.translate(a, 0.5, 0.5).unwrap();
    scene.translate(a, -0.5, -0.5).unwrap();
    let mut baseline = 0;
    for i in 0..cycles {
        let b = scene.insert(triangle.clone());
        assert!(scene.intersects(a, b).unwrap());
        scene.remove(b).unwrap();
        if i == 1_000 {
            baseline = scene.heap_bytes();
        }
    }
    let after_cycles = scene.heap_bytes();
    assert!(
        after_cycles <= baseline,
        "{cycles} insert/intersects/remove cycles: {baseline} -> {after_cycles} bytes"
    );
    // Edits alone: a vertex pushed out and back (the box grows and stays loose), and
    // translations (every one moves the box).
    let corner = scene
        .polygon(a)
        .unwrap()
        .next(scene.polygon(a).unwrap().first())
        .unwrap();
    for i in 0..cycles / 2 {
        let to = if i % 2 == 0 {
            Point::new(5., -1.)
        } else {
            Point::new(4., 0.)
        };
        scene.move_vertex(a, corner, to).unwrap();
        let d = if i % 2 == 0 { 0.5 } else { -0.5 };
        scene.translate(a, d, d).unwrap();
    }
    let after_edits = scene.heap_bytes();
    assert!(
        after_edits <= baseline,
        "{cycles} edits: {baseline} -> {after_edits} bytes"
    );
    assert_eq!(scene.candidate_pairs(), vec![]);
    scene.debug_validate().unwrap();
}

#[test]
fn an_edit_after_a_snapshot_never_yields_a_stale_answer() {
    for strategy in Strategy::ALL {
        let mut scene = Scene::new();
        scene.set_strategy(strategy);
        let a = scene
            .insert_points([[0., 0.], [2., 0.], [2., 2.], [0., 2.]])
            .unwrap();
        let b = scene.insert_points([[3., 0.], [4., 0.], [4., 2.]]).unwrap();
        for _ in 0..3 {
            assert!(!scene.intersects(a, b).unwrap());
        }
        let corner = scene
            .polygon(a)
            .unwrap()
            .next(scene.polygon(a).unwrap().first())
            .unwrap();
        scene.move_vertex(a, corner, Point::new(3.0, 0.0)).unwrap();
        assert!(
            !scene.has_snapshot(a).unwrap(),
            "{strategy:?}: the edit drops the snapshot"
        );
        assert!(scene.intersects(a, b).unwrap(), "{strategy:?}");
        scene.move_vertex(a, corner, Point::new(2.5, 0.0)).unwrap();
        assert!(!scene.intersects(a, b).unwrap(), "{strategy:?}");
        scene.debug_validate().unwrap();
    }
}

#[test]
fn planned_answers_equal_the_reference_under_edit_query_streams() {
    for seed in SEEDS {
        for strategy in Strategy::ALL {
            let mut rng = SmallRng::seed_from_u64(seed);
            let mut scene = scattered_scene(&mut rng, 24, 12);
            scene.set_strategy(strategy);
            let ids: Vec<_> = scene.ids().collect();
            let mut queries = 0;
            for step in 0..3_000 {
                let a = ids[rng.random_range(0..ids.len())];
                if rng.random_bool(0.3) {
                    let _ = random_edit(&mut scene, a, &mut rng);
                } else {
                    let b = ids[rng.random_range(0..ids.len())];
                    let want = truth(&scene, a, b);
                    assert_eq!(
                        scene.intersects(a, b).unwrap(),
                        want,
                        "seed {seed} {strategy:?} step {step}"
                    );
                    queries += 1;
                }
                if step % 500 == 0 {
                    scene.debug_validate().unwrap();
                }
            }
            assert!(queries > 1_500);
            let s = scene.stats();
            match strategy {
                Strategy::Sampled => assert_eq!(s.conversions, 0),
                Strategy::Convert => assert!(s.throwaway_conversions > 0 && s.conversions == 0),
                Strategy::Cached => assert!(s.conversions > 0 && s.sampled_tests == 0),
                Strategy::Planner => assert!(s.conversions > 0),
            }
        }
    }
}

#[test]
fn broad_phase_and_scene_queries_equal_brute_force() {
    for seed in SEEDS {
        let mut rng = SmallRng::seed_from_u64(seed ^ 0xb0);
        let mut scene = scattered_scene(&mut rng, 60, 9);
        // Touching boxes and polygons: integer squares sharing edges and corners.
        for i in 0..6 {
            let x = i as f64;
            scene
                .insert_points([[x, 10.], [x + 1., 10.], [x + 1., 11.], [x, 11.]])
                .unwrap();
        }
        for round in 0..4 {
            let ids: Vec<_> = scene.ids().collect();
            for _ in 0..50 {
                let id = ids[rng.random_range(0..ids.len())];
                let _ = random_edit(&mut scene, id, &mut rng);
            }
            if round == 2 {
                scene.remove(ids[3]).unwrap();
            }
            let ids: Vec<_> = scene.ids().collect();
            let mut want_candidates = Vec::new();
            let mut want_pairs = Vec::new();
            for (i, &a) in ids.iter().enumerate() {
                for &b in &ids[i + 1..] {
                    if scene
                        .bounding_box(a)
                        .unwrap()
                        .overlaps(&scene.bounding_box(b).unwrap())
                    {
                        want_candidates.push((a, b));
                    }
                    if truth(&scene, a, b) {
                        want_pairs.push((a, b));
                    }
                }
            }
            assert_eq!(
                scene.candidate_pairs(),
                want_candidates,
                "seed {seed} round {round}"
            );
            assert_eq!(
                scene.intersecting_pairs(),
                want_pairs,
                "seed {seed} round {round}"
            );
            let a = ids[round];
            let want: Vec<_> = ids
                .iter()
                .copied()
                .filter(|&b| b != a && truth(&scene, a, b))
                .collect();
            assert_eq!(scene.intersecting(a).unwrap(), want);
            scene.debug_validate().unwrap();
        }
    }
}

#[test]
fn parallel_batches_equal_sequential_queries_for_any_thread_count() {
    let mut rng = SmallRng::seed_from_u64(0xba7c);
    // Every scene built the same way, with one removed polygon; pairs name polygons by
    // their rank in `ids()` (handles belong to one scene), the last index the removed one.
    let build = || {
        let mut scene = scattered_scene(&mut SmallRng::seed_from_u64(1), 40, 11);
        let stale = scene.insert_points([[0., 0.], [1., 0.], [0., 1.]]).unwrap();
        scene.remove(stale).unwrap();
        let mut ids: Vec<_> = scene.ids().collect();
        ids.push(stale);
        (scene, ids)
    };
    let count = build().1.len() - 1;
    let mut pairs: Vec<(usize, usize)> = (0..400)
        .map(|_| (rng.random_range(0..count), rng.random_range(0..count)))
        .collect();
    pairs.push((count, 0));
    let handles = |ids: &[polysect::store::PolygonId]| -> Vec<_> {
        pairs.iter().map(|&(a, b)| (ids[a], ids[b])).collect()
    };
    let (mut sequential_scene, ids) = build();
    let sequential: Vec<_> = handles(&ids)
        .iter()
        .map(|&(a, b)| sequential_scene.intersects(a, b))
        .collect();
    assert!(matches!(
        sequential.last(),
        Some(Err(SceneError::StalePolygon(_)))
    ));
    let mut plan = None;
    for threads in [1, 2, 3] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let (mut scene, ids) = build();
        let pairs = handles(&ids);
        let batch = pool.install(|| scene.intersects_batch(&pairs));
        // Errors name handles of their own scene: compare them as messages.
        let message = |r: &Vec<Result<bool, SceneError>>| -> Vec<Result<bool, String>> {
            r.iter().map(|a| a.clone().map_err(|e| e.to_string())).collect()
        };
        assert_eq!(message(&batch), message(&sequential), "{threads} threads");
        // The batch is planned as a whole (it may convert where sequential queries
        // would not), but the plan never depends on the thread count.
        let stats = scene.stats();
        assert_eq!(*plan.get_or_insert(stats), stats, "{threads} threads: same plan");
    }
}

#[test]
fn scene_churn_with_queries() {
    let mut rng = SmallRng::seed_from_u64(0x5c);
    let mut scene = Scene::new();
    let ids: Vec<_> = (0..8)
        .map(|i| {
            let base = regular_polygon(256, 1.0)
                .map(|v| Point::new(v.x + 1.5 * (i % 4) as f64, v.y + 1.5 * (i / 4) as f64));
            scene.insert(LinkedPolygon::from_convex_shuffled(&base.unwrap(), &mut rng))
        })
        .collect();
    for (round, strategy) in Strategy::ALL.into_iter().cycle().take(8).enumerate() {
        scene.set_strategy(strategy);
        for step in 0..50_000 {
            let id = ids[rng.random_range(0..ids.len())];
            let v = scene.polygon(id).unwrap().random_vertex(&mut rng);
            let a = scene.polygon(id).unwrap().point(v).unwrap();
            let centre = scene.polygon(id).unwrap().to_convex().centre();
            let f = 1.0 + rng.random_range(-0.01..0.01);
            let _ = scene.move_vertex(
                id,
                v,
                Point::new(centre.x + (a.x - centre.x) * f, centre.y + (a.y - centre.y) * f),
            );
            if step % 500 == 0 {
                let (x, y) = (ids[rng.random_range(0..8)], ids[rng.random_range(0..8)]);
                let truth = Linear.intersects(
                    &scene.polygon(x).unwrap().to_convex(),
                    &scene.polygon(y).unwrap().to_convex(),
                );
                assert_eq!(
                    scene.intersects(x, y).unwrap(),
                    truth,
                    "round {round} step {step}"
                );
            }
        }
        scene.debug_validate().unwrap();
    }
}

trait Centre {
    fn centre(&self) -> Point;
}

impl Centre for ConvexPolygon {
    /// The mean of the vertices (inside a convex polygon). O(n): test helper only.
    fn centre(&self) -> Point {
        let (x, y) = centroid(self);
        Point::new(x, y)
    }
}

/// The planner's linear-walk route, certified: with conversion priced out, small
/// unconverted pairs are walked along their links, and every certificate (the walk's
/// separating edge, or the completion's witness) verifies.
#[test]
fn certified_linear_walks_verify() {
    use polysect::intersect::verify_linked;
    let mut rng = SmallRng::seed_from_u64(0x11ea);
    let mut scene = scattered_scene(&mut rng, 24, 5);
    let mut tables = scene.costs().tables();
    // Conversion (shuffled and ordered arenas) priced out.
    tables[0] = tables[0].map(|_| 1e12);
    tables[1] = tables[1].map(|_| 1e12);
    scene.set_costs(polysect::store::CostModel::from_tables(tables));
    let ids: Vec<_> = scene.ids().collect();
    let (mut separated, mut meeting) = (0, 0);
    for step in 0..600 {
        let (a, b) = (
            ids[rng.random_range(0..ids.len())],
            ids[rng.random_range(0..ids.len())],
        );
        let want = truth(&scene, a, b);
        let walks_before = scene.stats().linear_tests;
        let c = scene.intersects_certified(a, b).unwrap();
        let (p, q) = (scene.polygon(a).unwrap(), scene.polygon(b).unwrap());
        assert_eq!(verify_linked(p, q, &c), Ok(()), "step {step}: {c:?}");
        assert_eq!(c.intersects(), want, "step {step}");
        if scene.stats().linear_tests > walks_before {
            if want { meeting += 1 } else { separated += 1 }
        }
    }
    let s = scene.stats();
    assert!(s.linear_tests > 0 && s.conversions == 0, "{s:?}");
    assert!(separated > 0 && meeting > 0, "{separated} {meeting}");
}

#[test]
fn certified_scene_queries_verify_on_every_route() {
    use polysect::intersect::verify_linked;
    for strategy in Strategy::ALL {
        let mut rng = SmallRng::seed_from_u64(0xce47);
        let mut scene = scattered_scene(&mut rng, 16, 10);
        scene.set_strategy(strategy);
        let ids: Vec<_> = scene.ids().collect();
        let mut queries = 0;
        for step in 0..1_500 {
            let a = ids[rng.random_range(0..ids.len())];
            if rng.random_bool(0.2) {
                let _ = random_edit(&mut scene, a, &mut rng);
                continue;
            }
            let b = ids[rng.random_range(0..ids.len())];
            let want = truth(&scene, a, b);
            let c = scene.intersects_certified(a, b).unwrap();
            let (p, q) = (scene.polygon(a).unwrap(), scene.polygon(b).unwrap());
            assert_eq!(verify_linked(p, q, &c), Ok(()), "{strategy:?} step {step}: {c:?}");
            assert_eq!(c.intersects(), want, "{strategy:?} step {step}");
            queries += 1;
        }
        assert!(queries > 1_000);
        // Every route was taken: boxes, a polygon against itself, and the strategy's tests.
        let s = scene.stats();
        assert!(s.box_rejects > 0, "{strategy:?}: {s:?}");
        match strategy {
            Strategy::Sampled => assert!(s.sampled_tests > 0),
            Strategy::Convert => assert!(s.throwaway_conversions > 0),
            Strategy::Cached => assert!(s.array_tests > 0),
            Strategy::Planner => assert!(s.array_tests > 0 && s.sampled_tests + s.linear_tests > 0, "{s:?}"),
        }
        // The batches: the same pairs as the plain batch, each proved.
        let plain = scene.intersecting_pairs();
        let certified = scene.intersecting_pairs_certified();
        assert_eq!(
            plain,
            certified.iter().map(|&(a, b, _)| (a, b)).collect::<Vec<_>>()
        );
        for (a, b, c) in &certified {
            let (p, q) = (scene.polygon(*a).unwrap(), scene.polygon(*b).unwrap());
            assert_eq!(verify_linked(p, q, c), Ok(()));
        }
        // Every candidate pair with its certificate: the same candidates as the broad
        // phase, each proved, the intersecting ones exactly the batch's pairs.
        let candidates = scene.candidate_pairs();
        let answered = scene.candidate_pairs_certified();
        assert_eq!(
            candidates,
            answered.iter().map(|&(a, b, _)| (a, b)).collect::<Vec<_>>()
        );
        for (a, b, c) in &answered {
            let c = c.as_ref().unwrap();
            let (p, q) = (scene.polygon(*a).unwrap(), scene.polygon(*b).unwrap());
            assert_eq!(verify_linked(p, q, c), Ok(()));
            assert_eq!(c.intersects(), truth(&scene, *a, *b));
        }
        assert_eq!(
            plain,
            answered
                .iter()
                .filter(|(_, _, c)| c.as_ref().unwrap().intersects())
                .map(|&(a, b, _)| (a, b))
                .collect::<Vec<_>>()
        );
        assert!(answered.iter().any(|(_, _, c)| !c.as_ref().unwrap().intersects()));
        let pairs: Vec<_> = ids
            .iter()
            .flat_map(|&a| ids.iter().map(move |&b| (a, b)))
            .collect();
        for (&(a, b), c) in pairs.iter().zip(scene.intersects_batch_certified(&pairs)) {
            let c = c.unwrap();
            let (p, q) = (scene.polygon(a).unwrap(), scene.polygon(b).unwrap());
            assert_eq!(verify_linked(p, q, &c), Ok(()));
            assert_eq!(c.intersects(), truth(&scene, a, b));
        }
    }
}

/// Warm starts across frames never change an answer. Two scenes built alike, one with
/// warm starts and one without (the default), follow the same frames: coherent
/// translations, vertex edits (moves, inserts, removals: cached handles die or their
/// edges change), teleports, polygons removed and new ones inserted in the freed slots
/// (same keys, new generations); every frame both report their intersecting pairs (every
/// third frame the certified call, each certificate verified), which must be equal, and
/// every tenth frame equal to the exact reference on every pair. Every path of the warm
/// start is taken: kept certificates that still hold, ones that fail, linear walks that
/// fill the cache. The cache stays O(candidate pairs).
///
/// Half the runs are on a grid (integer vertices, steps of 1/4): there polygons touch
/// at vertices and along edges all the time, where "strictly outside" matters.
///
/// Size: `POLYSECT_WARM_FRAMES` frames (default 150) per seed, strategy and layout.
#[test]
fn warm_starts_never_change_an_answer() {
    use polysect::intersect::verify_linked;
    use polysect::store::PolygonId;
    let frames: usize = std::env::var("POLYSECT_WARM_FRAMES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(150);
    let mut totals = polysect::store::WarmStats::default();
    let runs = SEEDS
        .iter()
        .zip([Strategy::Planner, Strategy::Sampled, Strategy::Cached]);
    for ((&seed, strategy), grid) in runs.flat_map(|r| [(r, false), (r, true)]) {
        // A small convex polygon with integer vertices, or a scattered float one.
        let shape = |rng: &mut SmallRng| {
            let (cx, cy) = (rng.random_range(0..10) as f64, rng.random_range(0..10) as f64);
            let points: Vec<Point> = (0..6)
                .map(|_| {
                    Point::new(
                        cx + rng.random_range(0..4) as f64,
                        cy + rng.random_range(0..4) as f64,
                    )
                })
                .collect();
            polysect::polygon::convex_hull(&points)
        };
        let build = || {
            let mut rng = SmallRng::seed_from_u64(seed);
            if !grid {
                return scattered_scene(&mut rng, 40, 7);
            }
            let mut scene = Scene::new();
            while scene.len() < 40 {
                if let Ok(p) = shape(&mut rng) {
                    scene.insert(LinkedPolygon::from_convex(&p));
                }
            }
            scene
        };
        let step = |rng: &mut SmallRng| {
            if grid {
                (
                    rng.random_range(-1..=1) as f64 * 0.25,
                    rng.random_range(-1..=1) as f64 * 0.25,
                )
            } else {
                (rng.random_range(-0.05..0.05), rng.random_range(-0.05..0.05))
            }
        };
        let (mut warm, mut cold) = (build(), build());
        assert!(!cold.warm_starts());
        warm.set_warm_starts(true);
        for s in [&mut warm, &mut cold] {
            s.set_strategy(strategy);
            s.seed(seed);
        }
        let mut ids: Vec<(PolygonId, PolygonId)> = warm.ids().zip(cold.ids()).collect();
        let mut rng = SmallRng::seed_from_u64(seed ^ 0x3a77);
        let mut velocity: Vec<(f64, f64)> = (0..ids.len()).map(|_| step(&mut rng)).collect();
        for frame in 0..frames {
            for (i, &(w, c)) in ids.clone().iter().enumerate() {
                let r: f64 = rng.random();
                if r < 0.7 {
                    let (dx, dy) = velocity[i];
                    assert_eq!(
                        warm.translate(w, dx, dy).is_ok(),
                        cold.translate(c, dx, dy).is_ok()
                    );
                } else if r < 0.85 {
                    // The same random edit on both (same polygon, same generator state).
                    let mut twin = rng.clone();
                    let a = random_edit(&mut warm, w, &mut rng).is_ok();
                    assert_eq!(a, random_edit(&mut cold, c, &mut twin).is_ok());
                } else if r < 0.88 {
                    let (dx, dy) = (rng.random_range(-6..=6) as f64, rng.random_range(-6..=6) as f64);
                    assert_eq!(
                        warm.translate(w, dx, dy).is_ok(),
                        cold.translate(c, dx, dy).is_ok()
                    );
                } else if r < 0.9 {
                    // Removed, and a new polygon takes the freed slot.
                    warm.remove(w).unwrap();
                    cold.remove(c).unwrap();
                    let p = if grid {
                        let mut p = shape(&mut rng);
                        while p.is_err() {
                            p = shape(&mut rng);
                        }
                        p.unwrap()
                    } else {
                        let n = 1usize << rng.random_range(2..=6);
                        let p = regular_polygon(n, rng.random_range(0.3..1.5));
                        let (dx, dy) = (rng.random_range(-4.0..4.0), rng.random_range(-4.0..4.0));
                        p.map(|v| Point::new(v.x + dx, v.y + dy)).unwrap()
                    };
                    let (nw, nc) = (
                        warm.insert(LinkedPolygon::from_convex(&p)),
                        cold.insert(LinkedPolygon::from_convex(&p)),
                    );
                    ids[i] = (nw, nc);
                    velocity[i] = step(&mut rng);
                }
            }
            // Pairs as indices into `ids`, comparable across the two scenes.
            let index = |scene: usize, x: PolygonId| {
                ids.iter()
                    .position(|p| if scene == 0 { p.0 == x } else { p.1 == x })
                    .unwrap()
            };
            let got: Vec<(usize, usize)> = if frame % 3 == 0 {
                let certified = warm.intersecting_pairs_certified();
                for (a, b, c) in &certified {
                    let (p, q) = (warm.polygon(*a).unwrap(), warm.polygon(*b).unwrap());
                    assert_eq!(verify_linked(p, q, c), Ok(()), "frame {frame}: {c:?}");
                }
                certified
                    .iter()
                    .map(|&(a, b, _)| (index(0, a), index(0, b)))
                    .collect()
            } else {
                warm.intersecting_pairs()
                    .into_iter()
                    .map(|(a, b)| (index(0, a), index(0, b)))
                    .collect()
            };
            let want: Vec<(usize, usize)> = cold
                .intersecting_pairs()
                .into_iter()
                .map(|(a, b)| (index(1, a), index(1, b)))
                .collect();
            assert_eq!(got, want, "{strategy:?} seed {seed:x} grid {grid} frame {frame}");
            if frame % 10 == 0 {
                let mut truth_pairs = Vec::new();
                for (i, &(a, _)) in ids.iter().enumerate() {
                    for (j, &(b, _)) in ids.iter().enumerate().skip(i + 1) {
                        if truth(&warm, a, b) {
                            truth_pairs.push((i.min(j), i.max(j)));
                        }
                    }
                }
                let mut sorted: Vec<(usize, usize)> =
                    got.iter().map(|&(a, b)| (a.min(b), a.max(b))).collect();
                sorted.sort_unstable();
                truth_pairs.sort_unstable();
                assert_eq!(
                    sorted, truth_pairs,
                    "{strategy:?} seed {seed:x} frame {frame}: reference"
                );
            }
        }
        // The kept states: one per candidate pair of the last frame, no more.
        let candidates = warm.candidate_pairs().len();
        let with = warm.heap_bytes();
        warm.set_warm_starts(false);
        let kept = with - warm.heap_bytes();
        assert!(
            kept > 0 && kept <= 96 * candidates,
            "{kept} bytes kept for {candidates} candidates"
        );
        let s = warm.warm_stats();
        totals.hits += s.hits;
        totals.misses += s.misses;
        totals.fills += s.fills;
        assert_eq!(cold.warm_stats(), polysect::store::WarmStats::default());
    }
    eprintln!("warm starts: {totals:?}");
    assert!(
        totals.hits > 1_000 && totals.misses > 10 && totals.fills > 100,
        "{totals:?}"
    );
}

/// Translations wait in the scene's linked polygons until something reads them; the
/// coordinates must still be bit-for-bit those of eager translation on every path.
/// A scene is driven beside a plain list of linked polygons translated at once
/// (`LinkedPolygon::translate`) through long random sessions: coherent and rounding
/// translations, bursts that fill the pending list, near-overflow and collapsing ones
/// (refused alike), vertex moves, inserts and removals (the old point returned must be
/// the eager one), queries of every route and strategy (answers against the exact
/// reference on the eager list, certificates verified), warm starts on half the runs,
/// `polygon` reads, removals returning the polygon, and clones of the scene. Sessions
/// are `POLYSECT_LAZY_STEPS` long (1,500 by default).
#[test]
fn deferred_translations_equal_eager_ones_on_every_path() {
    use polysect::intersect::verify_linked;
    use polysect::store::PolygonId;
    let steps: usize = std::env::var("POLYSECT_LAZY_STEPS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1500);
    let bits = |p: &LinkedPolygon| -> Vec<(u64, u64)> {
        p.iter().map(|(_, q)| (q.x.to_bits(), q.y.to_bits())).collect()
    };
    /// One polygon on both sides: the scene's handle and the eager copy, with the
    /// vertex handles of each side in the same order.
    struct Twin {
        id: PolygonId,
        eager: LinkedPolygon,
        handles: Vec<(VertexId, VertexId)>,
    }
    let insert = |scene: &mut Scene, rng: &mut SmallRng| -> Twin {
        let n = 1usize << rng.random_range(2..=7);
        let (p, _) = generate::pair(Family::NonUniform, n, Relation::Any, rng);
        let (dx, dy) = (rng.random_range(-3.0..3.0), rng.random_range(-3.0..3.0));
        let moved = p.map(|v| Point::new(v.x + dx, v.y + dy)).unwrap_or(p);
        // Half on a grid of 2^-24, where dyadic translations are exact.
        let snap = |x: f64| (x * 2f64.powi(24)).round() * 2f64.powi(-24);
        let moved = match rng.random_bool(0.5) {
            true => moved.map(|v| Point::new(snap(v.x), snap(v.y))).unwrap_or(moved),
            false => moved,
        };
        let linked = if rng.random_bool(0.5) {
            LinkedPolygon::from_convex_shuffled(&moved, rng)
        } else {
            LinkedPolygon::from_convex(&moved)
        };
        let eager = linked.clone();
        let id = scene.insert(linked);
        let ours: Vec<VertexId> = scene.polygon(id).unwrap().iter().map(|(v, _)| v).collect();
        let theirs: Vec<VertexId> = eager.iter().map(|(v, _)| v).collect();
        Twin {
            id,
            eager,
            handles: ours.into_iter().zip(theirs).collect(),
        }
    };
    let mut counts = [0usize; 9];
    let strategies = [
        Strategy::Planner,
        Strategy::Cached,
        Strategy::Sampled,
        Strategy::Convert,
    ];
    for (run, &seed) in SEEDS.iter().chain(&[0x5ce4, 0x5ce5]).enumerate() {
        let mut rng = SmallRng::seed_from_u64(seed ^ 0x1a2e);
        let mut scene = Scene::new();
        scene.seed(seed);
        scene.set_warm_starts(run % 2 == 1);
        let mut twins: Vec<Twin> = (0..12).map(|_| insert(&mut scene, &mut rng)).collect();
        // A huge triangle, for translations that overflow (refused as not finite).
        let huge = LinkedPolygon::from_points([[0.0, 0.0], [1e307, 0.0], [0.0, 1e307]]).unwrap();
        let id = scene.insert(huge.clone());
        let ours: Vec<VertexId> = scene.polygon(id).unwrap().iter().map(|(v, _)| v).collect();
        let theirs: Vec<VertexId> = huge.iter().map(|(v, _)| v).collect();
        twins.push(Twin {
            id,
            eager: huge,
            handles: ours.into_iter().zip(theirs).collect(),
        });
        // Half the velocities dyadic (2^-20): exact on the grid polygons.
        let mut velocity: Vec<(f64, f64)> = (0..twins.len())
            .map(|k| {
                let v = (rng.random_range(-0.05..0.05), rng.random_range(-0.05..0.05));
                let snap = |x: f64| (x * 2f64.powi(20)).round() * 2f64.powi(-20);
                if k % 2 == 0 { (snap(v.0), snap(v.1)) } else { v }
            })
            .collect();
        velocity.push((0.05, -0.05));
        for step in 0..steps {
            let strategy = strategies[(step / 37 + run) % strategies.len()];
            scene.set_strategy(strategy);
            let i = rng.random_range(0..twins.len());
            let r: f64 = rng.random();
            if r < 0.45 {
                // One translation, or a burst of them (longer than the pending list)
                // for a few polygons, without any read in between.
                let burst = if rng.random_bool(0.1) { 20 } else { 1 };
                let who: Vec<usize> = if burst > 1 {
                    (0..3).map(|_| rng.random_range(0..twins.len())).collect()
                } else {
                    vec![i]
                };
                for _ in 0..burst {
                    for &k in &who {
                        let far = (rng.random_range(-1e6..1e6), rng.random_range(-1e6..1e6));
                        let vectors = match rng.random_range(0..10) {
                            // Coherent motion (exact for dyadic steps on the grid
                            // polygons, rounding for the others).
                            0..=5 => vec![velocity[k]],
                            // Far away and back: rounds at every step.
                            6 => vec![far, (-far.0, -far.1)],
                            // Collapses the polygon by rounding: refused.
                            7 => vec![(2f64.powi(rng.random_range(60..1000)), 0.0)],
                            // Next to overflow (the huge triangle overflows after a
                            // few; the others collapse), or not finite at all.
                            8 => vec![match rng.random_range(0..3) {
                                0 => (4e307 * rng.random_range(-1.0..1.0), 0.0),
                                1 => (0.0, f64::MAX * rng.random_range(-1.0..1.0)),
                                _ => (f64::INFINITY, 0.0),
                            }],
                            _ => vec![(-velocity[k].0, rng.random_range(-1e-9..1e-9))],
                        };
                        for (dx, dy) in vectors {
                            let t = &mut twins[k];
                            let got = scene.translate(t.id, dx, dy);
                            let want = t.eager.translate(dx, dy);
                            assert_eq!(
                                got,
                                want.map_err(|e| SceneError::Edit(t.id, e)),
                                "run {run} step {step}"
                            );
                            counts[if got.is_ok() { 0 } else { 1 }] += 1;
                            if matches!(got, Err(SceneError::Edit(_, EditError::NonFinite { .. }))) {
                                counts[8] += 1;
                            }
                        }
                    }
                }
            } else if r < 0.65 {
                // A vertex edit through the handles kept since insertion: the point it
                // returns is read from the (materialized) linked polygon.
                let t = &mut twins[i];
                let j = rng.random_range(0..t.handles.len());
                let (vs, ve) = t.handles[j];
                let a = t.eager.point(ve).unwrap();
                let b = t.eager.point(t.eager.next(ve).unwrap()).unwrap();
                let (cx, cy) = centroid(&t.eager.to_convex());
                match rng.random_range(0..3) {
                    0 => {
                        let f = 1.0 + rng.random_range(-0.05..0.05);
                        let p = Point::new(cx + (a.x - cx) * f, cy + (a.y - cy) * f);
                        let got = scene.move_vertex(t.id, vs, p);
                        let want = t.eager.move_vertex(ve, p);
                        // Debug text: a refused point may hold a NaN (the huge triangle).
                        assert_eq!(
                            format!("{:?}", got.map(|q| (q.x.to_bits(), q.y.to_bits()))),
                            format!(
                                "{:?}",
                                want.map(|q| (q.x.to_bits(), q.y.to_bits()))
                                    .map_err(|e| SceneError::Edit(t.id, e))
                            ),
                            "run {run} step {step}: move"
                        );
                    }
                    1 => {
                        let f = 1.0 + rng.random_range(0.0..0.02);
                        let (mx, my) = ((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
                        let p = Point::new(cx + (mx - cx) * f, cy + (my - cy) * f);
                        let got = scene.insert_vertex(t.id, vs, p);
                        let want = t.eager.insert_after(ve, p);
                        assert_eq!(got.is_ok(), want.is_ok(), "run {run} step {step}: insert");
                        if let (Ok(s), Ok(e)) = (got, want) {
                            t.handles.insert(j + 1, (s, e));
                        }
                    }
                    _ => {
                        let got = scene.remove_vertex(t.id, vs);
                        let want = t.eager.remove(ve);
                        assert_eq!(
                            got.clone().map(|q| (q.x.to_bits(), q.y.to_bits())),
                            want.map(|q| (q.x.to_bits(), q.y.to_bits()))
                                .map_err(|e| SceneError::Edit(t.id, e)),
                            "run {run} step {step}: remove"
                        );
                        if got.is_ok() {
                            t.handles.remove(j);
                        }
                    }
                }
                counts[2] += 1;
            } else if r < 0.9 {
                // A query of some route, against the exact reference on the eager list.
                let truth = |a: usize, b: usize| {
                    Linear.intersects(&twins[a].eager.to_convex(), &twins[b].eager.to_convex())
                };
                let j = rng.random_range(0..twins.len());
                match rng.random_range(0..5) {
                    0 => {
                        let got = scene.intersects(twins[i].id, twins[j].id).unwrap();
                        assert_eq!(got, truth(i, j), "run {run} step {step}: intersects");
                    }
                    1 => {
                        let c = scene.intersects_certified(twins[i].id, twins[j].id).unwrap();
                        assert_eq!(c.intersects(), truth(i, j), "run {run} step {step}");
                        let (p, q) = (
                            scene.polygon(twins[i].id).unwrap(),
                            scene.polygon(twins[j].id).unwrap(),
                        );
                        assert_eq!(verify_linked(p, q, &c), Ok(()), "run {run} step {step}");
                    }
                    2 => {
                        let pairs: Vec<(PolygonId, PolygonId)> = (0..6)
                            .map(|_| {
                                let (a, b) =
                                    (rng.random_range(0..twins.len()), rng.random_range(0..twins.len()));
                                (twins[a].id, twins[b].id)
                            })
                            .collect();
                        let got = scene.intersects_batch(&pairs);
                        for ((a, b), hit) in pairs.iter().zip(got) {
                            let ka = twins.iter().position(|t| t.id == *a).unwrap();
                            let kb = twins.iter().position(|t| t.id == *b).unwrap();
                            assert_eq!(hit.unwrap(), truth(ka, kb), "run {run} step {step}: batch");
                        }
                    }
                    3 => {
                        let got = scene.intersecting(twins[i].id).unwrap();
                        let mut want: Vec<PolygonId> = (0..twins.len())
                            .filter(|&k| k != i && truth(i, k))
                            .map(|k| twins[k].id)
                            .collect();
                        want.sort();
                        assert_eq!(got, want, "run {run} step {step}: intersecting");
                    }
                    _ => {
                        let got = if rng.random_bool(0.5) {
                            scene.intersecting_pairs()
                        } else {
                            scene
                                .intersecting_pairs_certified()
                                .into_iter()
                                .map(|(a, b, _)| (a, b))
                                .collect()
                        };
                        let mut want = Vec::new();
                        for a in 0..twins.len() {
                            for b in 0..twins.len() {
                                if twins[a].id < twins[b].id && truth(a, b) {
                                    want.push((twins[a].id, twins[b].id));
                                }
                            }
                        }
                        want.sort();
                        assert_eq!(got, want, "run {run} step {step}: pairs");
                    }
                }
                counts[3] += 1;
            } else if r < 0.95 {
                // Reading the polygon (through a shared reference), every polygon.
                for t in &twins {
                    let p = scene.polygon(t.id).unwrap();
                    assert_eq!(bits(p), bits(&t.eager), "run {run} step {step}: polygon");
                }
                scene.debug_validate().unwrap();
                counts[4] += 1;
            } else if r < 0.98 {
                // Removal returns the translated polygon; a new one takes the slot.
                let t = twins.swap_remove(i);
                let removed = scene.remove(t.id).unwrap();
                assert_eq!(bits(&removed), bits(&t.eager), "run {run} step {step}: remove");
                twins.push(insert(&mut scene, &mut rng));
                velocity.swap_remove(i);
                velocity.push((rng.random_range(-0.05..0.05), rng.random_range(-0.05..0.05)));
                counts[5] += 1;
            } else {
                // A clone is another scene with the same coordinates.
                let copy = scene.clone();
                for (id, cid) in scene.ids().zip(copy.ids()) {
                    let t = twins.iter().find(|t| t.id == id).unwrap();
                    assert_eq!(
                        bits(copy.polygon(cid).unwrap()),
                        bits(&t.eager),
                        "run {run} step {step}: clone"
                    );
                }
                counts[6] += 1;
            }
        }
        for t in &twins {
            assert_eq!(
                bits(scene.polygon(t.id).unwrap()),
                bits(&t.eager),
                "run {run}: end"
            );
        }
        scene.debug_validate().unwrap();
        counts[7] += scene.stats().array_tests as usize;
    }
    eprintln!(
        "translations accepted {}, refused {} ({} not finite); vertex edits {}; queries {}; reads {}; removals {}; clones {}; array tests {}",
        counts[0], counts[1], counts[8], counts[2], counts[3], counts[4], counts[5], counts[6], counts[7]
    );
    assert!(
        counts[8] > 5 && counts[1] > counts[8] && counts[0] > 2 * counts[1],
        "{counts:?}"
    );
    assert!(counts[7] > 100, "{counts:?}");
}
