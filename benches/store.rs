//! Scene workloads (edit-heavy, balanced, query-heavy) × strategies, all-pairs
//! queries on a scene of 1,000 polygons, and the O(1) edit paths (insert + remove, move)
//! on a linked polygon and through a scene. Each workload iteration runs on a fresh
//! clone of the same scene, so snapshot caching starts from the same state every time.

use criterion::{BatchSize, BenchmarkId, Criterion, criterion_group, criterion_main};
use polysect::generate::regular_polygon;
use polysect::store::Scene;
use polysect::store::Strategy;
use polysect::store::workload::{self, WorkloadSpec};
use polysect::{Exact, LinkedPolygon, Point, VertexId};
use std::hint::black_box;

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
    let targets = edit_targets(&base);
    let mut group = c.benchmark_group("edits");
    group.bench_function("linked/insert+remove", |b| {
        let mut p = base.clone();
        let mut i = 0;
        b.iter(|| {
            let (v, _, ins, _) = targets[i % targets.len()];
            i += 1;
            let w = p.insert_after(black_box(v), black_box(ins)).unwrap();
            p.remove(black_box(w)).unwrap()
        })
    });
    group.bench_function("linked/move+back", |b| {
        let mut p = base.clone();
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

criterion_group!(benches, workloads, all_pairs, edits);
criterion_main!(benches);
