//! The everyday queries on one polygon: closed point containment and the extreme
//! vertex in a direction, at n = 2^10, 2^14, 2^18 and 2^20 vertices.
//!
//! Groups (filter by name as usual with criterion):
//! * `contains_point`: `array` ([`ConvexPolygon::contains_point`], O(log n)),
//!   `linked` ([`LinkedPolygon::contains_point_with`], sampled, expected O(√n)) and
//!   `linked_walk` (every edge of the linked list tested, O(n): what a caller without
//!   the query would write).
//! * `extreme_vertex`: `array`, `linked` (sampled) and `linked_walk` (every vertex
//!   compared: the 4–6 ms walk a user measured for the rightmost vertex of a 2^20-gon).
//!
//! Polygons: random ellipses (`generate::ellipse_polygon`), linked in shuffled arena
//! order as after a long edit history. Points: 1,024 per size, uniform in the bounding
//! box (about 80% inside); directions: 1,024 uniform angles. Each iteration answers one
//! query and asserts the answer computed beforehand by the array query.
//!
//! Shared machines: `cargo bench --bench queries -- --warm-up-time 1 --measurement-time 2`.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use polysect::generate::{Density, ellipse_polygon};
use polysect::{ConvexPolygon, Exact, Kernel, LinkedPolygon, Orientation, Point, Sign};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::hint::black_box;

const SEED: u64 = 0x9e5_be4c;
const LOG2_SIZES: [u32; 4] = [10, 14, 18, 20];
const QUERIES: usize = 1024;

struct Case {
    n: usize,
    array: ConvexPolygon,
    linked: LinkedPolygon,
    points: Vec<(Point, bool)>,
    directions: Vec<(Point, Point)>,
}

fn case(log2: u32) -> Case {
    let mut rng = SmallRng::seed_from_u64(SEED ^ u64::from(log2));
    let array = ellipse_polygon(&mut rng, 1 << log2, &Density::Uniform, true);
    let linked = LinkedPolygon::from_convex_shuffled(&array, &mut rng);
    let polysect::BoundingBox { min: lo, max: hi } = array.bounding_box();
    let points = (0..QUERIES)
        .map(|_| {
            let x = Point::new(rng.random_range(lo.x..hi.x), rng.random_range(lo.y..hi.y));
            (x, array.contains_point(x))
        })
        .collect();
    let directions = (0..QUERIES)
        .map(|_| {
            let t: f64 = rng.random_range(0.0..std::f64::consts::TAU);
            let d = Point::new(t.cos(), t.sin());
            (d, array.vertices()[array.extreme_vertex(d).expect("a direction")])
        })
        .collect();
    Case {
        n: array.len(),
        array,
        linked,
        points,
        directions,
    }
}

/// Every edge of the linked list, in boundary order: the O(n) containment test.
fn contains_by_walk(p: &LinkedPolygon, x: Point) -> bool {
    let mut pos = 0;
    for _ in 0..p.len() {
        let next = p.next_at(pos);
        if Exact.orient(p.point_at(pos), p.point_at(next), x) == Orientation::Cw {
            return false;
        }
        pos = next;
    }
    true
}

/// Every vertex of the linked list compared exactly, in boundary order (`iter`): the
/// O(n) extreme vertex.
fn extreme_by_walk(p: &LinkedPolygon, d: Point) -> Point {
    let o = Point::new(0.0, 0.0);
    let mut vertices = p.iter().map(|(_, v)| v);
    let first = vertices.next().expect("a polygon has vertices");
    vertices.fold(first, |best, v| {
        if Exact.dot(o, d, best, v) == Sign::Positive {
            v
        } else {
            best
        }
    })
}

fn bench(c: &mut Criterion) {
    let cases: Vec<Case> = LOG2_SIZES.iter().map(|&l| case(l)).collect();
    let mut g = c.benchmark_group("contains_point");
    for case in &cases {
        let mut i = 0;
        let mut next = || {
            i = (i + 1) % QUERIES;
            case.points[i]
        };
        g.bench_function(BenchmarkId::new("array", case.n), |b| {
            b.iter(|| {
                let (x, want) = next();
                assert_eq!(case.array.contains_point(black_box(x)), want);
            })
        });
        let mut rng = SmallRng::seed_from_u64(SEED);
        g.bench_function(BenchmarkId::new("linked", case.n), |b| {
            b.iter(|| {
                let (x, want) = next();
                assert_eq!(
                    case.linked.contains_point_with(Exact, black_box(x), &mut rng),
                    want
                );
            })
        });
        if case.n <= 1 << 18 {
            g.bench_function(BenchmarkId::new("linked_walk", case.n), |b| {
                b.iter(|| {
                    let (x, want) = next();
                    // The walk stops at the first edge with x outside: time it on the
                    // points inside (a full walk), the worst and the common case.
                    if want {
                        assert!(contains_by_walk(&case.linked, black_box(x)));
                    }
                })
            });
        }
    }
    g.finish();
    let mut g = c.benchmark_group("extreme_vertex");
    for case in &cases {
        let mut i = 0;
        let mut next = || {
            i = (i + 1) % QUERIES;
            case.directions[i]
        };
        g.bench_function(BenchmarkId::new("array", case.n), |b| {
            b.iter(|| {
                let (d, want) = next();
                let v = case.array.extreme_vertex(black_box(d)).expect("a direction");
                assert_eq!(case.array.vertices()[v], want);
            })
        });
        let mut rng = SmallRng::seed_from_u64(SEED);
        g.bench_function(BenchmarkId::new("linked", case.n), |b| {
            b.iter(|| {
                let (d, want) = next();
                let v = case.linked.extreme_vertex_with(Exact, black_box(d), &mut rng);
                assert_eq!(case.linked.point(v.expect("a direction")), Ok(want));
            })
        });
        g.bench_function(BenchmarkId::new("linked_walk", case.n), |b| {
            b.iter(|| {
                let (d, want) = next();
                assert_eq!(extreme_by_walk(&case.linked, black_box(d)), want);
            })
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20);
    targets = bench
}
criterion_main!(benches);
