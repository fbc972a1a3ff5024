//! Scene workloads × strategies: edit-heavy, balanced, query-heavy, and a 2^18-vertex
//! polygon holding its snapshot against a triangle moved before every query; all-pairs
//! queries on a scene of 1,000 polygons; `intersecting_pairs` on fresh grids of 10k and
//! 40k overlapping squares (batch planning must stay near-linear); and the O(1) edit
//! paths (insert + remove, move) on a linked polygon and through a scene. Each workload
//! iteration runs on a fresh clone of the same scene, so snapshot caching starts from
//! the same state every time. The `ratios` group runs the planner interleaved with the
//! fixed strategies and prints its ratio to the best of them over the same rounds.

use criterion::{BatchSize, BenchmarkId, Criterion, criterion_group, criterion_main};
use polysect::generate::regular_polygon;
use polysect::store::workload::{self, WorkloadSpec};
use polysect::store::{PolygonId, Scene, Strategy};
use polysect::{Exact, LinkedPolygon, Point, VertexId};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;
use std::time::{Duration, Instant};

fn workloads(c: &mut Criterion) {
    let base = workload::scattered_scene(Exact, 48, 16, 3.0, 7);
    for spec in WorkloadSpec::standard(1000, 11) {
        let mut group = c.benchmark_group(format!("workload/{}", spec.name));
        group.sample_size(10);
        for strategy in Strategy::ALL {
            group.bench_function(BenchmarkId::from_parameter(strategy.name()), |b| {
                b.iter_batched(
                    || {
                        let mut s = base.clone();
                        s.set_strategy(strategy);
                        s
                    },
                    |mut scene| {
                        let r = workload::run(&mut scene, &spec, false, || {});
                        assert_eq!(r.queries + r.edits, spec.steps as u64);
                        r
                    },
                    BatchSize::LargeInput,
                )
            });
        }
        group.finish();
    }
}

/// A shuffled 2^18-vertex circle that already holds its snapshot, and a triangle in the
/// corner of its bounding box (outside the circle: disjoint, the expensive answer) whose
/// vertex moves before every query. Converting the triangle and testing the arrays costs
/// a fraction of one sampled query on the big polygon.
fn big_snapshot_small_moving(c: &mut Criterion) {
    let base = BigSnapshot::new();
    let mut group = c.benchmark_group("workload/big-snapshot-vs-moving-triangle");
    group.sample_size(10);
    for strategy in Strategy::ALL {
        // One scene per strategy for all iterations: an even number of steps brings the
        // triangle back, and the big polygon keeps its snapshot under every strategy.
        let mut run = base.with(strategy);
        group.bench_function(BenchmarkId::from_parameter(strategy.name()), |b| {
            b.iter(|| run.steps())
        });
        assert!(run.scene.has_snapshot(run.big).unwrap());
    }
    group.finish();
}

/// The big-snapshot workload's scene, ready for any strategy.
struct BigSnapshot {
    scene: Scene,
    big: PolygonId,
    small: PolygonId,
    vertex: VertexId,
}

impl BigSnapshot {
    const STEPS: usize = 32;

    fn new() -> BigSnapshot {
        let mut rng = SmallRng::seed_from_u64(0xb16);
        let mut scene = Scene::new();
        let big = scene.insert(LinkedPolygon::from_convex_shuffled(
            &regular_polygon(1 << 18, 1.0),
            &mut rng,
        ));
        let small = scene.insert_points([[0.8, 0.8], [0.9, 0.8], [0.8, 0.9]]).unwrap();
        scene.set_strategy(Strategy::Cached);
        assert!(!scene.intersects(big, small).unwrap());
        assert!(scene.has_snapshot(big).unwrap());
        let vertex = scene
            .polygon(small)
            .unwrap()
            .next(scene.polygon(small).unwrap().first())
            .unwrap();
        BigSnapshot {
            scene,
            big,
            small,
            vertex,
        }
    }

    /// A clone with `strategy` (handles belong to one scene: the clone's are found by
    /// rank).
    fn with(&self, strategy: Strategy) -> BigSnapshot {
        let mut scene = self.scene.clone();
        scene.set_strategy(strategy);
        let rank = |id: PolygonId| self.scene.ids().position(|x| x == id).unwrap();
        let ids: Vec<PolygonId> = scene.ids().collect();
        let (big, small) = (ids[rank(self.big)], ids[rank(self.small)]);
        let vertex = scene
            .polygon(small)
            .unwrap()
            .next(scene.polygon(small).unwrap().first())
            .unwrap();
        BigSnapshot {
            scene,
            big,
            small,
            vertex,
        }
    }

    /// Moves the triangle's vertex and queries, `STEPS` times (even: back where it was).
    fn steps(&mut self) {
        for step in 0..Self::STEPS {
            let x = if step % 2 == 0 { 0.95 } else { 0.9 };
            self.scene
                .move_vertex(self.small, self.vertex, Point::new(x, 0.8))
                .unwrap();
            assert!(!self.scene.intersects(self.big, self.small).unwrap());
        }
    }
}

/// The planner against the fixed strategies that can be best here (sampled, cached;
/// convert is 30× to 100,000× slower on every workload, see the groups above),
/// interleaved: each criterion iteration runs one round of every strategy on the same
/// workload from the same state, and the planner's time is what criterion records.
/// After each workload the bench prints each strategy's median round and the planner's
/// ratio to the best fixed strategy over the same rounds: on a busy machine, where speed
/// drifts between criterion's groups, the pairing keeps the ratio meaningful.
fn planner_ratios(c: &mut Criterion) {
    const SHOWN: [Strategy; 3] = [Strategy::Sampled, Strategy::Cached, Strategy::Planner];
    let base = workload::scattered_scene(Exact, 48, 16, 3.0, 7);
    let big = BigSnapshot::new();
    let mut group = c.benchmark_group("ratios");
    group.sample_size(10);
    let specs = WorkloadSpec::standard(1000, 11);
    for name in specs
        .iter()
        .map(|s| s.name)
        .chain(["big-snapshot-vs-moving-triangle"])
    {
        let mut rounds: Vec<[Duration; 3]> = Vec::new();
        let mut runs: Vec<BigSnapshot> = SHOWN.iter().map(|&st| big.with(st)).collect();
        group.bench_function(BenchmarkId::new("planner-interleaved", name), |b| {
            b.iter_custom(|iters| {
                let mut planner = Duration::ZERO;
                for _ in 0..iters {
                    let mut round = [Duration::ZERO; 3];
                    for (i, &strategy) in SHOWN.iter().enumerate() {
                        round[i] = match specs.iter().find(|s| s.name == name) {
                            Some(spec) => {
                                let mut scene = base.clone();
                                scene.set_strategy(strategy);
                                let start = Instant::now();
                                let r = workload::run(&mut scene, spec, false, || {});
                                let t = start.elapsed();
                                assert_eq!(r.queries + r.edits, spec.steps as u64);
                                t
                            }
                            None => {
                                let start = Instant::now();
                                runs[i].steps();
                                start.elapsed()
                            }
                        };
                    }
                    planner += round[2];
                    rounds.push(round);
                }
                planner
            })
        });
        if rounds.is_empty() {
            continue; // filtered out on the command line
        }
        let stat = |i: usize| {
            let mut v: Vec<Duration> = rounds.iter().map(|r| r[i]).collect();
            v.sort();
            (v[0], v[v.len() / 2])
        };
        let m: Vec<(Duration, Duration)> = (0..3).map(stat).collect();
        let mut per_round: Vec<f64> = rounds
            .iter()
            .map(|r| r[2].as_secs_f64() / r[0].min(r[1]).as_secs_f64())
            .collect();
        per_round.sort_by(f64::total_cmp);
        let ratio = |a: Duration, b: Duration, c: Duration| a.as_secs_f64() / b.min(c).as_secs_f64();
        eprintln!(
            "{name}: {} interleaved rounds; min / median: sampled {:?} / {:?}, cached {:?} / {:?}, planner {:?} / {:?}; \
             planner / best fixed: median of per-round ratios {:.2}, of minima {:.2}, of medians {:.2}",
            rounds.len(),
            m[0].0,
            m[0].1,
            m[1].0,
            m[1].1,
            m[2].0,
            m[2].1,
            per_round[per_round.len() / 2],
            ratio(m[2].0, m[0].0, m[1].0),
            ratio(m[2].1, m[0].1, m[1].1),
        );
    }
    group.finish();
}

/// An m × m grid of squares of side 1.5 at unit spacing: each overlaps its eight
/// neighbours, so the scene has 2m(m − 1) + 2(m − 1)² intersecting pairs.
fn grid(m: usize) -> (Scene, usize) {
    let mut scene = Scene::new();
    for i in 0..m {
        for j in 0..m {
            let (x, y) = (i as f64, j as f64);
            scene
                .insert_points([[x, y], [x + 1.5, y], [x + 1.5, y + 1.5], [x, y + 1.5]])
                .unwrap();
        }
    }
    (scene, 2 * m * (m - 1) + 2 * (m - 1) * (m - 1))
}

/// `intersecting_pairs` on a fresh grid (no snapshots, broad phase not built yet), at
/// 10k and 40k polygons: planning the batch must not be quadratic.
fn fresh_grid_pairs(c: &mut Criterion) {
    let mut group = c.benchmark_group("batch/fresh-grid");
    group.sample_size(10);
    for m in [100, 200] {
        let (base, expected) = grid(m);
        group.bench_function(BenchmarkId::from_parameter(m * m), |b| {
            b.iter_batched(
                || base.clone(),
                |mut scene| {
                    assert_eq!(scene.intersecting_pairs().len(), expected);
                    scene
                },
                BatchSize::LargeInput,
            )
        });
    }
    group.finish();
}

fn all_pairs(c: &mut Criterion) {
    let base = workload::scattered_scene(Exact, 1000, 10, 40.0, 3);
    let expected = base.clone().intersecting_pairs().len();
    let mut group = c.benchmark_group("all-pairs/1000");
    group.sample_size(10);
    for strategy in Strategy::ALL {
        group.bench_function(BenchmarkId::from_parameter(strategy.name()), |b| {
            b.iter_batched(
                || {
                    let mut s = base.clone();
                    s.set_strategy(strategy);
                    s
                },
                |mut scene| assert_eq!(scene.intersecting_pairs().len(), expected),
                BatchSize::LargeInput,
            )
        });
    }
    group.finish();
}

/// For each vertex v of a regular 64-gon: a point just outside the edge from v to its
/// successor (a valid insertion after v) and a point just outside v itself (a valid move).
fn edit_targets(p: &LinkedPolygon) -> Vec<(VertexId, Point, Point, Point)> {
    p.iter()
        .map(|(v, a)| {
            let b = p.point(p.next(v).unwrap()).unwrap();
            let out = |x: f64, y: f64, f: f64| Point::new(x * f, y * f);
            (
                v,
                a,
                out((a.x + b.x) / 2.0, (a.y + b.y) / 2.0, 1.0001),
                out(a.x, a.y, 1.0001),
            )
        })
        .collect()
}

fn edits(c: &mut Criterion) {
    let base = LinkedPolygon::from_convex(&regular_polygon(64, 1.0));
    let mut group = c.benchmark_group("edits");
    group.bench_function("linked/insert+remove", |b| {
        // A clone is a polygon of its own: its handles, not `base`'s.
        let mut p = base.clone();
        let targets = edit_targets(&p);
        let mut i = 0;
        b.iter(|| {
            let (v, _, ins, _) = targets[i % targets.len()];
            i += 1;
            let w = p.insert_after(black_box(v), black_box(ins)).unwrap();
            p.remove(black_box(w)).unwrap()
        })
    });
    group.bench_function("linked/move+back", |b| {
        // A clone is a polygon of its own: its handles, not `base`'s.
        let mut p = base.clone();
        let targets = edit_targets(&p);
        let mut i = 0;
        b.iter(|| {
            let (v, at, _, out) = targets[i % targets.len()];
            i += 1;
            p.move_vertex(black_box(v), black_box(out)).unwrap();
            p.move_vertex(black_box(v), black_box(at)).unwrap()
        })
    });
    let mut scene = Scene::new();
    let _other = scene.insert(base.clone());
    let id = scene.insert(base.clone());
    let targets = edit_targets(scene.polygon(id).unwrap());
    group.bench_function("scene/insert+remove", |b| {
        let mut i = 0;
        b.iter(|| {
            let (v, _, ins, _) = targets[i % targets.len()];
            i += 1;
            let w = scene
                .insert_vertex(black_box(id), black_box(v), black_box(ins))
                .unwrap();
            scene.remove_vertex(black_box(id), black_box(w)).unwrap()
        })
    });
    group.bench_function("scene/move+back", |b| {
        let mut i = 0;
        b.iter(|| {
            let (v, at, _, out) = targets[i % targets.len()];
            i += 1;
            scene
                .move_vertex(black_box(id), black_box(v), black_box(out))
                .unwrap();
            scene
                .move_vertex(black_box(id), black_box(v), black_box(at))
                .unwrap()
        })
    });
    group.finish();
}

criterion_group!(
    benches,
    workloads,
    big_snapshot_small_moving,
    planner_ratios,
    all_pairs,
    fresh_grid_pairs,
    edits
);
criterion_main!(benches);
