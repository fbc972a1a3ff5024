//! Where a line meets a convex polygon: the O(log n) `line_chord` against the linear
//! reference `line_chord_linear`, on regular polygons of n vertices and random lines
//! through the polygon's bounding box. The two answers are asserted equal outside the
//! timed loop; inside it, the chord is checked to exist when the line passes the centre.
//!
//! ```text
//! cargo bench --bench line_query -- --warm-up-time 1 --measurement-time 2
//! ```

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use polysect::Point;
use polysect::generate::regular_polygon;
use polysect::polygon::line_chord_linear;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::hint::black_box;

fn lines(c: &mut Criterion) {
    let mut group = c.benchmark_group("line_chord");
    group.throughput(Throughput::Elements(1));
    for log2 in [4u32, 10, 16, 20] {
        let n = 1usize << log2;
        let p = regular_polygon(n, 1.0);
        let mut rng = SmallRng::seed_from_u64(u64::from(log2));
        // Lines through the origin (always a chord) in random directions.
        let queries: Vec<(Point, Point)> = (0..1024)
            .map(|_| {
                let a: f64 = rng.random_range(0.0..std::f64::consts::TAU);
                (Point::new(-2.0 * a.cos(), -2.0 * a.sin()), Point::new(0.0, 0.0))
            })
            .collect();
        for &(a, b) in &queries[..16] {
            assert_eq!(p.line_chord(a, b).unwrap(), line_chord_linear(&p, a, b).unwrap());
        }
        let mut i = 0;
        group.bench_with_input(BenchmarkId::new("log", n), &p, |bench, p| {
            bench.iter(|| {
                i = (i + 1) % queries.len();
                let (a, b) = queries[i];
                let c = p.line_chord(black_box(a), black_box(b)).unwrap();
                assert!(c.is_some());
                c
            })
        });
        if n <= 1 << 16 {
            group.bench_with_input(BenchmarkId::new("linear", n), &p, |bench, p| {
                bench.iter(|| {
                    i = (i + 1) % queries.len();
                    let (a, b) = queries[i];
                    let c = line_chord_linear(p, black_box(a), black_box(b)).unwrap();
                    assert!(c.is_some());
                    c
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, lines);
criterion_main!(benches);
