//! Time per query of `ChazelleDobkin` (exact and fast kernel) against `Linear` on
//! regular n-gons, n = 2^10, 2^16, 2^20, intersecting and disjoint pairs separately.
//! Each iteration runs one query from a small set of pairs (Q shifted in different
//! directions, shifted start vertices) and asserts the expected answer.
//!
//! Short run: `cargo bench --bench chazelle_dobkin -- --warm-up-time 1 --measurement-time 2`

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use polysect::generate::regular_polygon;
use polysect::intersect::{ArrayIntersection, ChazelleDobkin, Linear};
use polysect::{ConvexPolygon, Exact, Fast, Point};
use std::hint::black_box;

fn pairs(n: usize, dist: f64) -> Vec<(ConvexPolygon, ConvexPolygon, bool)> {
    let p = regular_polygon(n, 1.0);
    (0..4)
        .map(|i| {
            let angle = 0.4 + i as f64 * 1.57;
            let q = p
                .map(|v| Point::new(v.x + dist * angle.cos(), v.y + dist * angle.sin()))
                .unwrap()
                .starting_at(i * n / 7);
            let p = p.starting_at(i * n / 5);
            let want = Linear.intersects(&p, &q);
            (p, q, want)
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    for (label, dist) in [("intersecting", 1.9), ("disjoint", 2.1)] {
        let mut group = c.benchmark_group(format!("array-intersection/{label}"));
        for log in [10, 16, 20] {
            let n = 1usize << log;
            let set = pairs(n, dist);
            assert!(set.iter().all(|s| s.2 == (dist < 2.0)));
            let mut run = |name: &str, f: &dyn Fn(&ConvexPolygon, &ConvexPolygon) -> bool| {
                group.bench_function(BenchmarkId::new(name, n), |b| {
                    let mut i = 0;
                    b.iter(|| {
                        let (p, q, want) = &set[i % set.len()];
                        i += 1;
                        assert_eq!(f(black_box(p), black_box(q)), *want);
                    })
                });
            };
            run("chazelle-dobkin/exact", &|p, q| {
                ChazelleDobkin.intersects_with(Exact, p, q)
            });
            run("chazelle-dobkin/fast", &|p, q| {
                ChazelleDobkin.intersects_with(Fast, p, q)
            });
            run("linear/exact", &|p, q| Linear.intersects_with(Exact, p, q));
        }
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
