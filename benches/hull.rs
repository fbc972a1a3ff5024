//! Convex hulls of point sets: Graham's scan against Andrew's monotone chain (both
//! exact, through `hull_vertices`), and the farthest pair through the hull (rotating
//! calipers). Inputs: n uniform points in a square (a hull of O(log n) vertices) and n
//! points on a circle (every point on the hull). The expected hull size is asserted
//! inside every iteration.
//!
//! ```text
//! cargo bench --bench hull -- --warm-up-time 1 --measurement-time 2
//! ```

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use polysect::Point;
use polysect::polygon::calipers::farthest_pair_of_points;
use polysect::polygon::{HullAlgorithm, hull_vertices};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::hint::black_box;

const SIZES: [usize; 4] = [1 << 8, 1 << 12, 1 << 16, 1 << 20];

fn inputs(n: usize) -> [(&'static str, Vec<Point>); 2] {
    let mut rng = SmallRng::seed_from_u64(n as u64);
    let square = (0..n)
        .map(|_| Point::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)))
        .collect();
    let circle = (0..n)
        .map(|_| {
            let a: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            Point::new(a.cos(), a.sin())
        })
        .collect();
    [("square", square), ("circle", circle)]
}

fn hulls(c: &mut Criterion) {
    for n in SIZES {
        for (shape, pts) in inputs(n) {
            let want = hull_vertices(&pts, HullAlgorithm::Monotone).unwrap().len();
            let mut group = c.benchmark_group(format!("hull/{shape}"));
            group.throughput(Throughput::Elements(n as u64));
            if n >= 1 << 16 {
                group.sample_size(10);
            }
            for algorithm in HullAlgorithm::ALL {
                group.bench_with_input(BenchmarkId::new(algorithm.name(), n), &pts, |b, pts| {
                    b.iter(|| {
                        let h = hull_vertices(black_box(pts), algorithm).unwrap();
                        assert_eq!(h.len(), want);
                        h
                    })
                });
            }
            group.bench_with_input(BenchmarkId::new("diameter", n), &pts, |b, pts| {
                b.iter(|| farthest_pair_of_points(black_box(pts)).unwrap())
            });
            group.finish();
        }
    }
}

criterion_group!(benches, hulls);
criterion_main!(benches);
