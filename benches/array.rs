//! Intersection queries on sorted arrays: every algorithm in `Algorithm::ARRAY` (and
//! the O(log n) ones also under the fast kernel), each followed by its certified call
//! (`<name>-certified`: the answer with its certificate), and the sublinear `clm` (and
//! `clm-certified`) on the same
//! polygons linked once in a shuffled arena, against the peers geo (`Intersects`
//! on `Polygon` and on `MonotoneChainPolygon`) and parry2d-f64 (`intersection_test`
//! on `ConvexPolygon`), for n = 2^4, 2^6, …, 2^max vertices per polygon, intersecting
//! and disjoint pairs in separate groups. Inputs (pairs, peer shapes) are built
//! outside the timed loop; every iteration asserts the expected answer.
//!
//! `POLYSECT_BENCH_MAX_LOG2` (default 22) sets the largest size.
//! geo's `Intersects` on plain `Polygon`s grows much faster than linearly on
//! intersecting pairs (seconds per query at 2^18), so it runs only up to
//! `POLYSECT_BENCH_GEO_POLYGON_MAX_LOG2` (default 14); the other peers run at every
//! size. To measure the
//! report's sizes quickly on a shared machine:
//! `cargo bench --bench array -- --warm-up-time 1 --measurement-time 2 '/(262144|1048576)$'`

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use geo::{Intersects, LineString, MonotoneChainPolygon};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::intersection_test;
use parry2d_f64::shape::ConvexPolygon as ParryPolygon;
use polysect::generate::{self, Family, Relation};
use polysect::intersect::{Algorithm, ArrayIntersection, Clm, ClmWorkspace, Linear, LinkedIntersection};
use polysect::{ConvexPolygon, Exact, LinkedPolygon, Precision};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;

const SEED: u64 = 0xbe4c_0001;

fn env_log2(name: &str, default: u32) -> u32 {
    std::env::var(name)
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default)
}

/// A pair of the requested relation (redrawn until the exact answer matches).
fn pair(n: usize, relation: Relation, rng: &mut SmallRng) -> (ConvexPolygon, ConvexPolygon) {
    let want = relation == Relation::Intersecting;
    loop {
        let (p, q) = generate::pair(Family::Rotated, n, relation, rng);
        if Linear.intersects(&p, &q) == want {
            return (p, q);
        }
    }
}

fn geo_polygon(p: &ConvexPolygon) -> geo::Polygon<f64> {
    let ring: Vec<(f64, f64)> = p.vertices().iter().map(|v| (v.x, v.y)).collect();
    geo::Polygon::new(LineString::from(ring), vec![])
}

fn parry_polygon(p: &ConvexPolygon) -> ParryPolygon {
    let pts = p.vertices().iter().map(|v| Vector::new(v.x, v.y)).collect();
    ParryPolygon::from_convex_polyline_unmodified(pts).expect("a valid convex polygon")
}

fn bench(c: &mut Criterion) {
    let mut rng = SmallRng::seed_from_u64(SEED);
    for relation in [Relation::Intersecting, Relation::Disjoint] {
        let want = relation == Relation::Intersecting;
        let name = if want {
            "array/intersecting"
        } else {
            "array/disjoint"
        };
        let mut group = c.benchmark_group(name);
        let geo_polygon_max = env_log2("POLYSECT_BENCH_GEO_POLYGON_MAX_LOG2", 14);
        for log in (4..=env_log2("POLYSECT_BENCH_MAX_LOG2", 22)).step_by(2) {
            let n = 1usize << log;
            let (p, q) = pair(n, relation, &mut rng);
            group.throughput(Throughput::Elements(n as u64));
            group.sample_size(if log >= 14 { 10 } else { 50 });
            for &alg in Algorithm::ARRAY {
                group.bench_with_input(BenchmarkId::new(alg.name(), n), &(&p, &q), |b, (p, q)| {
                    b.iter(|| assert_eq!(alg.intersects(Precision::Exact, black_box(p), black_box(q)), want))
                });
                // The same query with its certificate, right after the plain one.
                let id = BenchmarkId::new(format!("{}-certified", alg.name()), n);
                group.bench_with_input(id, &(&p, &q), |b, (p, q)| {
                    b.iter(|| {
                        let c = alg.certified(Precision::Exact, black_box(p), black_box(q));
                        assert_eq!(c.intersects(), want)
                    })
                });
            }
            // The sublinear test on the same polygons, linked once in shuffled arena order
            // outside the timed loop (linking is O(n)), with a reused workspace and RNG.
            let (lp, lq) = (
                LinkedPolygon::from_convex_shuffled(&p, &mut rng),
                LinkedPolygon::from_convex_shuffled(&q, &mut rng),
            );
            let mut ws = ClmWorkspace::default();
            let mut clm_rng = SmallRng::seed_from_u64(SEED ^ n as u64);
            group.bench_function(BenchmarkId::new("clm", n), |b| {
                b.iter(|| {
                    let hit = Clm.intersects_with_workspace(
                        Exact,
                        black_box(&lp),
                        black_box(&lq),
                        &mut clm_rng,
                        &mut ws,
                    );
                    assert_eq!(hit, want)
                })
            });
            group.bench_function(BenchmarkId::new("clm-certified", n), |b| {
                b.iter(|| {
                    let c = Clm.certified_with_workspace(
                        Exact,
                        black_box(&lp),
                        black_box(&lq),
                        &mut clm_rng,
                        &mut ws,
                    );
                    assert_eq!(c.intersects(), want)
                })
            });
            drop((lp, lq));
            for &alg in Algorithm::LOGARITHMIC {
                let id = BenchmarkId::new(format!("{}-fast", alg.name()), n);
                group.bench_with_input(id, &(&p, &q), |b, (p, q)| {
                    b.iter(|| assert_eq!(alg.intersects(Precision::Fast, black_box(p), black_box(q)), want))
                });
            }
            let (gp, gq) = (geo_polygon(&p), geo_polygon(&q));
            if log <= geo_polygon_max {
                group.bench_function(BenchmarkId::new("geo-polygon", n), |b| {
                    b.iter(|| assert_eq!(black_box(&gp).intersects(black_box(&gq)), want))
                });
            }
            let (mp, mq) = (MonotoneChainPolygon::from(&gp), MonotoneChainPolygon::from(&gq));
            group.bench_function(BenchmarkId::new("geo-monotone-chain", n), |b| {
                b.iter(|| assert_eq!(black_box(&mp).intersects(black_box(&mq)), want))
            });
            drop((mp, mq));
            let (pp, pq) = (parry_polygon(&p), parry_polygon(&q));
            let id = Pose::identity();
            group.bench_function(BenchmarkId::new("parry2d", n), |b| {
                b.iter(|| {
                    let r = intersection_test(&id, black_box(&pp), &id, black_box(&pq)).expect("supported");
                    assert_eq!(r.intersecting, want)
                })
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
