//! Crossing points of two random simple polygons (space partitioning on uniform and normal points, as in docs/crossings.md's report):
//! the sweep (`sweep-exact`, `sweep-fast`: the default, which picks Žalik's lists or
//! the ordered red–blue sweep; `list-sweep` and `tree-sweep`: each of the two alone)
//! against the O(n·m) brute force, with geo's sweep
//! (`geo::algorithm::sweep::Intersections` over both edge sets) as a peer.
//!
//! Polygons come from space partitioning of n uniform points in [0, Δ)² (Δ = 100)
//! and of n normal points (μ = 0, σ = 50). Δ and σ only scale the point sets (the
//! coordinates are real), so the report's other Δ and σ give the same combinatorics.
//! The expected number of points (brute force, exact) is asserted inside every
//! iteration. Brute force stops at n = 5,000 (n·m = 25·10⁶ edge pairs).
//! `brute-nobox-exact` is a segment test on every pair with no bounding-box
//! rejection and no point construction, up to the report's n = 2,000
//! (`polysect bench crossings` times the report's own brute force).
//!
//! The worst cases of a sweep with unordered lists (`polysect::generate::hard`):
//! `zigzag` (every edge spans one x-range, about n crossings), `stacked-zigzag` (the
//! same without contact) and `needles` (two combs of needles 10⁻⁶ apart), at
//! n = 1,000 … 64,000 vertices per polygon, with the lists and the brute force up to
//! n = 8,000 and geo up to 16,000 (it is quadratic there too).
//! `POLYSECT_BENCH_MAX_N` caps the sizes of every group.
//!
//! ```text
//! cargo bench --bench crossings -- --warm-up-time 1 --measurement-time 2
//! ```

use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use geo::algorithm::sweep::{Cross, Intersections};
use geo::{Line, coord};
use polysect::crossings::{Brute, Crossings, ListSweep, Sweep, SweepWorkspace, TreeSweep};
use polysect::generate::hard::{HardFamily, hard_pair};
use polysect::generate::simple::{PointDistribution, SimpleMethod, random_simple_polygon};
use polysect::kernel::segment_contact;
use polysect::{Exact, Fast, SimplePolygon};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;

const SIZES: [usize; 11] = [5, 50, 100, 200, 500, 800, 1000, 2000, 5000, 10_000, 20_000];
const BRUTE_MAX: usize = 5000;
const HARD_SIZES: [usize; 7] = [1000, 2000, 4000, 8000, 16_000, 32_000, 64_000];
const HARD_BRUTE_MAX: usize = 8000;
/// geo's sweep is quadratic on these families (3.5 s per query at n = 16,000).
const HARD_GEO_MAX: usize = 16_000;
const HARD: [HardFamily; 3] = [HardFamily::Zigzag, HardFamily::StackedZigzag, HardFamily::Needles];

/// The largest n to run (`POLYSECT_BENCH_MAX_N`, default no limit).
fn max_n() -> usize {
    std::env::var("POLYSECT_BENCH_MAX_N")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(usize::MAX)
}
/// The largest size in the report's tables.
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

/// What to time on one pair besides the default sweep and the tree sweep.
struct Plan {
    /// The default sweep with the fast kernel.
    fast: bool,
    /// The lists alone.
    lists: bool,
    /// The brute force.
    brute: bool,
    /// A segment test on every pair, no box rejection.
    nobox: bool,
    /// geo's sweep, with the number of edge pairs it must find.
    geo: Option<usize>,
}

/// Times the algorithms of `plan` on `p` and `q`, asserting the `k` expected points
/// (or geo's own count) in every iteration.
fn bench_pair(
    group: &mut BenchmarkGroup<'_, WallTime>,
    n: usize,
    (p, q): (&SimplePolygon, &SimplePolygon),
    k: usize,
    plan: Plan,
) {
    group.throughput(Throughput::Elements((p.len() + q.len()) as u64));
    let mut ws = SweepWorkspace::default();
    let mut out = Vec::new();
    let pq = (p, q);
    group.bench_with_input(BenchmarkId::new("sweep-exact", n), &pq, |b, (p, q)| {
        b.iter(|| {
            Sweep.crossings_in(Exact, black_box(p), black_box(q), &mut ws, &mut out);
            assert_eq!(out.len(), k);
        })
    });
    if plan.fast {
        group.bench_with_input(BenchmarkId::new("sweep-fast", n), &pq, |b, (p, q)| {
            b.iter(|| {
                Sweep.crossings_in(Fast, black_box(p), black_box(q), &mut ws, &mut out);
                assert_eq!(out.len(), k);
            })
        });
    }
    // The two sweeps that `sweep` chooses between, each alone.
    if plan.lists {
        group.bench_with_input(BenchmarkId::new("list-sweep", n), &pq, |b, (p, q)| {
            b.iter(|| {
                assert_eq!(
                    ListSweep.crossings_with(Exact, black_box(p), black_box(q)).len(),
                    k
                )
            })
        });
    }
    group.bench_with_input(BenchmarkId::new("tree-sweep", n), &pq, |b, (p, q)| {
        b.iter(|| {
            assert_eq!(
                TreeSweep.crossings_with(Exact, black_box(p), black_box(q)).len(),
                k
            )
        })
    });
    if plan.brute {
        group.bench_with_input(BenchmarkId::new("brute-exact", n), &pq, |b, (p, q)| {
            b.iter(|| assert_eq!(Brute.crossings_with(Exact, black_box(p), black_box(q)).len(), k))
        });
    }
    if plan.nobox {
        // A segment test on every pair, no bounding-box rejection (counting meeting
        // pairs: random input has no touchings).
        group.bench_with_input(BenchmarkId::new("brute-nobox-exact", n), &pq, |b, (p, q)| {
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
        });
    }
    if let Some(geo_k) = plan.geo {
        let edges: Vec<Tagged> = tagged(p, 0).chain(tagged(q, 1)).collect();
        group.bench_with_input(BenchmarkId::new("geo-sweep", n), &edges, |b, edges| {
            b.iter(|| {
                let found = Intersections::from_iter(black_box(edges).iter())
                    .filter(|(a, b, _)| a.poly != b.poly)
                    .count();
                assert_eq!(found, geo_k);
            })
        });
    }
}

/// geo's count of edge pairs between the polygons.
fn geo_count(p: &SimplePolygon, q: &SimplePolygon) -> usize {
    let edges: Vec<Tagged> = tagged(p, 0).chain(tagged(q, 1)).collect();
    Intersections::from_iter(edges.iter())
        .filter(|(a, b, _)| a.poly != b.poly)
        .count()
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
        for n in SIZES.into_iter().filter(|&n| n <= max_n()) {
            let p = random_simple_polygon(SimpleMethod::SpacePartition, dist, n, &mut rng).unwrap();
            let q = random_simple_polygon(SimpleMethod::SpacePartition, dist, n, &mut rng).unwrap();
            let expected = Sweep.crossings(&p, &q);
            if n <= BRUTE_MAX {
                assert_eq!(Brute.crossings(&p, &q), expected);
            }
            let k = expected.len();
            eprintln!("{dname}: n = m = {n}: {k} points");
            // Random real input: no touchings, so geo finds one edge pair per point.
            let plan = Plan {
                fast: true,
                lists: true,
                brute: n <= BRUTE_MAX,
                nobox: n <= SEED_MAX,
                geo: Some(k),
            };
            bench_pair(&mut group, n, (&p, &q), k, plan);
        }
        group.finish();
    }
    for family in HARD {
        let mut group = c.benchmark_group(format!("crossings/{family}"));
        group.sample_size(10);
        for n in HARD_SIZES.into_iter().filter(|&n| n <= max_n()) {
            let mut rng = SmallRng::seed_from_u64(2027 + n as u64);
            let (p, q) = hard_pair(family, n, &mut rng);
            let expected = Sweep.crossings(&p, &q);
            if n <= HARD_BRUTE_MAX {
                assert_eq!(Brute.crossings(&p, &q), expected);
            }
            let k = expected.len();
            let geo = (n <= HARD_GEO_MAX).then(|| geo_count(&p, &q));
            eprintln!(
                "{family}: n = {} + {}: {k} points, geo finds {geo:?} pairs",
                p.len(),
                q.len()
            );
            let plan = Plan {
                fast: false,
                lists: n <= HARD_BRUTE_MAX,
                brute: n <= HARD_BRUTE_MAX,
                nobox: false,
                geo,
            };
            bench_pair(&mut group, n, (&p, &q), k, plan);
        }
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
