//! The exact kernel at extreme but well-conditioned scales: the same inputs multiplied
//! by a power of two (exact, so every answer is the same), timed side by side.
//!
//! * `scales/sweep-validate`: validation of two random simple polygons (space
//!   partitioning of n = 10,000 uniform points in [0, 100)², then `SimplePolygon::new`
//!   on each, Shamos–Hoey) plus Žalik's sweep for their crossing points, as the CLI's
//!   `crossings` does per line. Scales 1, 2^600, 2^-600 and 2^1016 (coordinates up to
//!   2^1022.6, near `f64::MAX`); `axes` multiplies x by 2^600 and y by 2^-600 (every
//!   product of a difference in x and one in y is then of moderate size: no slow path).
//! * `scales/sweep-validate-grid`: the same on integer points of a 2^20 grid, at scale
//!   1 and 2^-1074 (every coordinate subnormal, still exact).
//! * `scales/array-2^14`: each O(log n) algorithm on a random rotated-ellipse pair of
//!   2^14 vertices at scales 1, 2^600, 2^-600 and 2^1020.
//!
//! Every iteration asserts the answer found at scale 1 (the number of crossing points;
//! the intersection answer), except for `axes` and the subnormal grid: their decisions
//! are the same (a positive power-of-two scaling of each axis keeps every orientation
//! and comparison), but crossing points are constructed, and where x is 2^1200 times y
//! or coordinates are subnormal, constructed coordinates round (underflow) and
//! distinct points merge (see `crossing_point`); those assert their own count.
//!
//! `star`: two star-shaped polygons around the origin whose vertices alternate between
//! radii in [1, 2)·2^600 and [1, 2)·2^-600, so predicates mix magnitudes 2^1200 apart
//! in one call, which rescaling cannot bring into range: the exact but slow case. Its
//! baseline `star-moderate` has the same angles with radii in [1, 2)·4 and [1, 2).
//!
//! ```text
//! cargo bench --bench scales -- --warm-up-time 1 --measurement-time 3
//! ```

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use polysect::crossings::{Crossings, Sweep};
use polysect::generate::simple::{PointDistribution, SimpleMethod, random_simple_polygon};
use polysect::generate::{self, Family, Relation, map_pair};
use polysect::intersect::Algorithm;
use polysect::{Point, Precision, SimplePolygon};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;

const SEED: u64 = 0x005c_a1e5;
const N: usize = 10_000;

/// 2^k as a factor, for k in [-1074, 1023] (two normal factors where needed).
fn pow2(k: i32) -> (f64, f64) {
    (2f64.powi(k / 2), 2f64.powi(k - k / 2))
}

/// Multiplies x by 2^kx and y by 2^ky; exact for the inputs used here.
fn scaled(points: &[Point], kx: i32, ky: i32) -> Vec<Point> {
    let ((ax, bx), (ay, by)) = (pow2(kx), pow2(ky));
    points
        .iter()
        .map(|p| Point::new(p.x * ax * bx, p.y * ay * by))
        .collect()
}

/// Validation of both polygons and the sweep: what one `crossings` line costs.
fn sweep_validate(p: &[Point], q: &[Point]) -> usize {
    let p = SimplePolygon::new(p.iter().copied()).expect("a valid polygon");
    let q = SimplePolygon::new(q.iter().copied()).expect("a valid polygon");
    Sweep.crossings(&p, &q).len()
}

fn sweeps(c: &mut Criterion, group: &str, dist: PointDistribution, cases: &[(&str, i32, i32)]) {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let method = SimpleMethod::SpacePartition;
    let p = random_simple_polygon(method, dist, N, &mut rng).expect("a polygon");
    let q = random_simple_polygon(method, dist, N, &mut rng).expect("a polygon");
    let (p, q) = (p.vertices().to_vec(), q.vertices().to_vec());
    let want = sweep_validate(&p, &q);
    let mut group = c.benchmark_group(group);
    group.sample_size(10);
    for &(name, kx, ky) in cases {
        let (sp, sq) = (scaled(&p, kx, ky), scaled(&q, kx, ky));
        let got = sweep_validate(&sp, &sq);
        if kx == ky && kx > -1000 {
            assert_eq!(got, want, "{name}");
        }
        group.bench_function(BenchmarkId::new(name, N), |b| {
            b.iter(|| assert_eq!(sweep_validate(black_box(&sp), black_box(&sq)), got))
        });
    }
    group.finish();
}

/// A star-shaped polygon around the origin: `n` random angles, radii alternating
/// between `[1, 2)·2^big` and `[1, 2)·2^small`.
fn star(n: usize, big: i32, small: i32, rng: &mut SmallRng) -> Vec<Point> {
    use rand::Rng;
    let mut pts: Vec<(f64, f64)> = (0..n)
        .map(|i| {
            let t: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            let (a, b) = pow2(if i % 2 == 0 { big } else { small });
            (t, rng.random_range(1.0..2.0) * a * b)
        })
        .collect();
    pts.sort_by(|x, y| x.0.total_cmp(&y.0));
    pts.iter()
        .map(|&(t, r)| Point::new(r * t.cos(), r * t.sin()))
        .collect()
}

fn stars(c: &mut Criterion) {
    let mut group = c.benchmark_group("scales/sweep-validate-star");
    group.sample_size(10);
    for (name, big, small) in [("star-moderate", 2, 0), ("star", 600, -600)] {
        let mut rng = SmallRng::seed_from_u64(SEED ^ 2);
        let (p, q) = (star(N, big, small, &mut rng), star(N, big, small, &mut rng));
        let got = sweep_validate(&p, &q);
        group.bench_function(BenchmarkId::new(name, N), |b| {
            b.iter(|| assert_eq!(sweep_validate(black_box(&p), black_box(&q)), got))
        });
    }
    group.finish();
}

fn bench(c: &mut Criterion) {
    sweeps(
        c,
        "scales/sweep-validate",
        PointDistribution::Uniform { min: 0.0, max: 100.0 },
        &[
            ("1", 0, 0),
            ("2^600", 600, 600),
            ("2^-600", -600, -600),
            ("2^1016", 1016, 1016),
            ("axes", 600, -600),
        ],
    );
    sweeps(
        c,
        "scales/sweep-validate-grid",
        PointDistribution::Grid { size: 1 << 20 },
        &[("1", 0, 0), ("2^-1074", -1074, -1074)],
    );
    let mut rng = SmallRng::seed_from_u64(SEED ^ 1);
    let base = generate::pair(Family::Rotated, 1 << 14, Relation::Any, &mut rng);
    let mut group = c.benchmark_group("scales/array-2^14");
    for (name, k) in [("1", 0), ("2^600", 600), ("2^-600", -600), ("2^1020", 1020)] {
        let (a, b) = pow2(k);
        let (p, q) = map_pair(&base, |v| Point::new(v.x * a * b, v.y * a * b)).expect("an exact scaling");
        for &alg in Algorithm::LOGARITHMIC {
            let want = alg.intersects(Precision::Exact, &base.0, &base.1);
            assert_eq!(alg.intersects(Precision::Exact, &p, &q), want);
            group.bench_function(BenchmarkId::new(format!("{alg}/{name}"), 1 << 14), |bch| {
                bch.iter(|| {
                    assert_eq!(
                        alg.intersects(Precision::Exact, black_box(&p), black_box(&q)),
                        want
                    )
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench, stars);
criterion_main!(benches);
