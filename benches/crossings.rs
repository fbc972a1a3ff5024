//! Crossing points of two random simple polygons (seed 003, Tables 6.1 and 6.2):
//! Žalik's sweep (exact and fast kernels) against the O(n·m) brute force, with geo's
//! sweep (`geo::algorithm::sweep::Intersections` over both edge sets) as a peer.
//!
//! Polygons come from space partitioning of n uniform points in [0, Δ)² (Δ = 100)
//! and of n normal points (μ = 0, σ = 50). Δ and σ only scale the point sets (the
//! coordinates are real), so the seed's other Δ and σ give the same combinatorics.
//! The expected number of points (brute force, exact) is asserted inside every
//! iteration. Brute force stops at n = 5,000 (n·m = 25·10⁶ edge pairs).
//! `brute-nobox-exact` is the seed's baseline (a segment test on every pair, no
//! bounding-box rejection, no point construction), up to the seed's n = 2,000.
//!
//! ```text
//! cargo bench --bench crossings -- --warm-up-time 1 --measurement-time 2
//! ```

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use geo::algorithm::sweep::{Cross, Intersections};
use geo::{Line, coord};
use polysect::crossings::{Brute, Crossings, Sweep, SweepWorkspace};
use polysect::generate::simple::{PointDistribution, SimpleMethod, random_simple_polygon};
use polysect::kernel::segment_contact;
use polysect::{Exact, Fast, SimplePolygon};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;

const SIZES: [usize; 11] = [5, 50, 100, 200, 500, 800, 1000, 2000, 5000, 10_000, 20_000];
const BRUTE_MAX: usize = 5000;
/// The largest size in the seed's tables.
const SEED_MAX: usize = 2000;

/// An edge tagged with its polygon, for geo's sweep over both edge sets.
#[derive(Clone, Debug)]
struct Tagged {
    line: Line<f64>,
    poly: u8,
}

impl Cross for Tagged {
    type Scalar = f64;
    fn line(&self) -> Line<f64> {
        self.line
    }
}

fn tagged(p: &SimplePolygon, poly: u8) -> impl Iterator<Item = Tagged> + '_ {
    (0..p.len()).map(move |i| {
        let (a, b) = p.edge(i);
        Tagged {
            line: Line::new(coord! { x: a.x, y: a.y }, coord! { x: b.x, y: b.y }),
            poly,
        }
    })
}

fn bench(c: &mut Criterion) {
    let dists = [
        (
            "uniform-delta100",
            PointDistribution::Uniform { min: 0.0, max: 100.0 },
        ),
        (
            "normal-sigma50",
            PointDistribution::Normal {
                mean: 0.0,
                sigma: 50.0,
            },
        ),
    ];
    let mut rng = SmallRng::seed_from_u64(2026);
    for (dname, dist) in dists {
        let mut group = c.benchmark_group(format!("crossings/{dname}"));
        group.sample_size(10);
        for n in SIZES {
            let p = random_simple_polygon(SimpleMethod::SpacePartition, dist, n, &mut rng).unwrap();
            let q = random_simple_polygon(SimpleMethod::SpacePartition, dist, n, &mut rng).unwrap();
            let expected = Sweep.crossings(&p, &q);
            if n <= BRUTE_MAX {
                assert_eq!(Brute.crossings(&p, &q), expected);
            }
            let k = expected.len();
            eprintln!("{dname}: n = m = {n}: {k} points");
            group.throughput(Throughput::Elements((p.len() + q.len()) as u64));
            let mut ws = SweepWorkspace::default();
            let mut out = Vec::new();
            group.bench_with_input(BenchmarkId::new("sweep-exact", n), &(&p, &q), |b, (p, q)| {
                b.iter(|| {
                    Sweep.crossings_in(Exact, black_box(p), black_box(q), &mut ws, &mut out);
                    assert_eq!(out.len(), k);
                })
            });
            group.bench_with_input(BenchmarkId::new("sweep-fast", n), &(&p, &q), |b, (p, q)| {
                b.iter(|| {
                    Sweep.crossings_in(Fast, black_box(p), black_box(q), &mut ws, &mut out);
                    assert_eq!(out.len(), k);
                })
            });
            if n <= BRUTE_MAX {
                group.bench_with_input(BenchmarkId::new("brute-exact", n), &(&p, &q), |b, (p, q)| {
                    b.iter(|| assert_eq!(Brute.crossings_with(Exact, black_box(p), black_box(q)).len(), k))
                });
            }
            if n <= SEED_MAX {
                // The seed's baseline: a segment test on every pair, no bounding-box
                // rejection (counting meeting pairs: random input has no touchings).
                group.bench_with_input(
                    BenchmarkId::new("brute-nobox-exact", n),
                    &(&p, &q),
                    |b, (p, q)| {
                        b.iter(|| {
                            let mut meets = 0;
                            for i in 0..p.len() {
                                let (p1, p2) = p.edge(i);
                                for j in 0..q.len() {
                                    let (q1, q2) = q.edge(j);
                                    meets += segment_contact(Exact, p1, p2, q1, q2).meets() as usize;
                                }
                            }
                            assert_eq!(meets, k);
                        })
                    },
                );
            }
            let edges: Vec<Tagged> = tagged(&p, 0).chain(tagged(&q, 1)).collect();
            group.bench_with_input(BenchmarkId::new("geo-sweep", n), &edges, |b, edges| {
                b.iter(|| {
                    let found = Intersections::from_iter(black_box(edges).iter())
                        .filter(|(a, b, _)| a.poly != b.poly)
                        .count();
                    // Random real input: no touchings, so one edge pair per point.
                    assert_eq!(found, k);
                })
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
