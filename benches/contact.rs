//! Contact queries against parry2d-f64 (`query::distance` and `query::contact` on
//! `ConvexPolygon`s with identity poses), for n = 16, 256, 4,096 and 65,536 vertices per
//! polygon, side by side in one run:
//! * `contact-distance`, disjoint pairs: polysect's `distance_with` (distance and a
//!   closest pair, correctly rounded) under both kernels, `contact_with` (the same plus
//!   the exact rationals), parry's `distance`;
//! * `contact-depth`, overlapping pairs: polysect's `contact_with` (depth, normal,
//!   overlap polygon and area) and `depth_with` (depth and normal only) beside parry's
//!   `contact` (depth, normal and points; it has no overlap polygon).
//!
//! Pairs come from the generators' rotated ellipses (`generate::pair`); the expected
//! relation is asserted inside every iteration.
//!
//! Quick run: `cargo bench --bench contact -- --warm-up-time 1 --measurement-time 3`.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{contact as parry_contact, distance as parry_distance};
use parry2d_f64::shape::ConvexPolygon as ParryPolygon;
use polysect::contact::{Contact, contact_with, depth_with, distance_with};
use polysect::generate::{self, Family, Relation};
use polysect::intersect::{ArrayIntersection, Linear};
use polysect::{ConvexPolygon, Exact, Fast};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;

const SEED: u64 = 0xc0_7ac7;
const SIZES: [usize; 4] = [16, 256, 4096, 65536];

fn pair(n: usize, relation: Relation, rng: &mut SmallRng) -> (ConvexPolygon, ConvexPolygon) {
    let want = relation == Relation::Intersecting;
    loop {
        let (p, q) = generate::pair(Family::Rotated, n, relation, rng);
        if Linear.intersects(&p, &q) == want {
            return (p, q);
        }
    }
}

fn parry_polygon(p: &ConvexPolygon) -> ParryPolygon {
    let pts = p.vertices().iter().map(|v| Vector::new(v.x, v.y)).collect();
    ParryPolygon::from_convex_polyline_unmodified(pts).expect("a valid convex polygon")
}

fn bench(c: &mut Criterion) {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let id = Pose::identity();
    let mut group = c.benchmark_group("contact-distance");
    for n in SIZES {
        let (p, q) = pair(n, Relation::Disjoint, &mut rng);
        group.bench_function(BenchmarkId::new("polysect", n), |b| {
            b.iter(|| {
                assert!(
                    distance_with(Exact, black_box(&p), black_box(&q))
                        .is_some_and(|d| d.distance > Some(0.0))
                )
            })
        });
        group.bench_function(BenchmarkId::new("polysect-fast", n), |b| {
            b.iter(|| {
                assert!(
                    distance_with(Fast, black_box(&p), black_box(&q)).is_some_and(|d| d.distance > Some(0.0))
                )
            })
        });
        group.bench_function(BenchmarkId::new("polysect-contact", n), |b| {
            b.iter(|| assert!(!contact_with(Exact, black_box(&p), black_box(&q)).intersects()))
        });
        let (pp, pq) = (parry_polygon(&p), parry_polygon(&q));
        group.bench_function(BenchmarkId::new("parry2d", n), |b| {
            b.iter(|| {
                let d = parry_distance(&id, black_box(&pp), &id, black_box(&pq)).expect("supported");
                assert!(d.distance > 0.0)
            })
        });
    }
    group.finish();
    let mut group = c.benchmark_group("contact-depth");
    // The exact overlap of large pairs takes milliseconds to seconds per query.
    group.sample_size(10);
    for n in SIZES {
        let (p, q) = pair(n, Relation::Intersecting, &mut rng);
        group.bench_function(BenchmarkId::new("polysect", n), |b| {
            b.iter(|| {
                let Contact::Overlapping(o) = contact_with(Exact, black_box(&p), black_box(&q)) else {
                    panic!("the pair overlaps")
                };
                assert!(o.overlap.len() >= 3)
            })
        });
        group.bench_function(BenchmarkId::new("polysect-depth", n), |b| {
            b.iter(|| assert!(depth_with(Exact, black_box(&p), black_box(&q)).is_some()))
        });
        let (pp, pq) = (parry_polygon(&p), parry_polygon(&q));
        group.bench_function(BenchmarkId::new("parry2d", n), |b| {
            b.iter(|| {
                let c = parry_contact(&id, black_box(&pp), &id, black_box(&pq), 0.0).expect("supported");
                assert!(c.is_some_and(|c| c.dist <= 0.0))
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
