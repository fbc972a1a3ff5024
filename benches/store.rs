//! Scene workloads (edit-heavy, balanced, query-heavy) × strategies, and all-pairs
//! queries on a scene of 1,000 polygons. Each iteration runs on a fresh clone of the
//! same scene, so snapshot caching starts from the same state every time.

use criterion::{BatchSize, BenchmarkId, Criterion, criterion_group, criterion_main};
use polysect::Exact;
use polysect::store::Strategy;
use polysect::store::workload::{self, WorkloadSpec};

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

criterion_group!(benches, workloads, all_pairs);
criterion_main!(benches);
