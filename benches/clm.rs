//! The sublinear test on linked polygons (thesis 4.3, experiment 5, and Figure 4.8).
//!
//! Groups (filter by name as usual with criterion):
//! * `clm/intersecting`, `clm/disjoint`: [`Clm`] for n = 2^4, 2^6, ... up to
//!   2^`POLYSECT_BENCH_MAX_LOG2` (default 22) vertices per polygon, Rotated pairs linked
//!   in shuffled arena order; the answer is asserted inside the loop. `clm-certified`
//!   is the certified call (answer and certificate) on the same pairs.
//! * `convert_vs_clm`: [`Convert`] against [`Clm`] on the same pairs, n up to 2^16
//!   (Convert is linear: beyond that it only burns machine time).
//! * `clm_factor`: the sample factor c of [`ClmWithFactor`] at n = 2^12 and 2^18.
//!
//! The √n-normalised curve and the crossover as tables and plots come from
//! `polysect bench sqrt crossover` (src/experiments/, docs/results.md).
//!
//! Shared machines: `cargo bench --bench clm -- --warm-up-time 1 --measurement-time 2`.

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use polysect::generate::{Family, Relation, pair};
use polysect::intersect::{
    ArrayIntersection, Clm, ClmWithFactor, ClmWorkspace, Convert, ConvertWorkspace, Linear,
    LinkedIntersection,
};
use polysect::{Exact, LinkedPolygon};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;

const SEED: u64 = 0xbe4c_c1a0;
const CONVERT_MAX_LOG2: u32 = 16;

fn max_log2() -> u32 {
    std::env::var("POLYSECT_BENCH_MAX_LOG2")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(22)
        .clamp(4, 24)
}

/// Linked pairs with their exact answers: a few per size (fewer at large n, where
/// each polygon costs hundreds of megabytes of generation time and memory).
struct Pairs {
    pairs: Vec<(LinkedPolygon, LinkedPolygon)>,
    answer: bool,
}

fn make_pairs(log2: u32, relation: Relation) -> Pairs {
    let n = 1usize << log2;
    let count = if log2 <= 12 {
        8
    } else if log2 <= 18 {
        4
    } else {
        1
    };
    let mut rng = SmallRng::seed_from_u64(SEED ^ (log2 as u64) << 8 ^ relation_tag(relation));
    let answer = matches!(relation, Relation::Intersecting);
    let pairs = (0..count)
        .map(|_| {
            let (p, q) = pair(Family::Rotated, n, relation, &mut rng);
            assert_eq!(Linear.intersects(&p, &q), answer);
            (
                LinkedPolygon::from_convex_shuffled(&p, &mut rng),
                LinkedPolygon::from_convex_shuffled(&q, &mut rng),
            )
        })
        .collect();
    Pairs { pairs, answer }
}

fn relation_tag(r: Relation) -> u64 {
    match r {
        Relation::Any => 0,
        Relation::Intersecting => 1,
        Relation::Disjoint => 2,
    }
}

fn sizes() -> impl Iterator<Item = u32> {
    (4..=max_log2()).step_by(2)
}

fn bench_clm(c: &mut Criterion) {
    for relation in [Relation::Intersecting, Relation::Disjoint] {
        let name = if relation == Relation::Intersecting {
            "clm/intersecting"
        } else {
            "clm/disjoint"
        };
        let mut group = c.benchmark_group(name);
        for log2 in sizes() {
            let set = make_pairs(log2, relation);
            let n = 1u64 << log2;
            group.throughput(Throughput::Elements(n));
            let mut rng = SmallRng::seed_from_u64(SEED + 1);
            let mut ws = ClmWorkspace::default();
            let mut i = 0;
            group.bench_with_input(BenchmarkId::new("clm", n), &set, |b, set| {
                b.iter(|| {
                    let (p, q) = &set.pairs[i % set.pairs.len()];
                    i += 1;
                    let got =
                        Clm.intersects_with_workspace(Exact, black_box(p), black_box(q), &mut rng, &mut ws);
                    assert_eq!(got, set.answer);
                })
            });
            // The certified call on the same pairs, with the same RNG seed and a warm workspace.
            let mut rng = SmallRng::seed_from_u64(SEED + 1);
            let mut i = 0;
            group.bench_with_input(BenchmarkId::new("clm-certified", n), &set, |b, set| {
                b.iter(|| {
                    let (p, q) = &set.pairs[i % set.pairs.len()];
                    i += 1;
                    let got =
                        Clm.certified_with_workspace(Exact, black_box(p), black_box(q), &mut rng, &mut ws);
                    assert_eq!(got.intersects(), set.answer);
                })
            });
        }
        group.finish();
    }
}

fn bench_convert_vs_clm(c: &mut Criterion) {
    let mut group = c.benchmark_group("convert_vs_clm");
    for log2 in (4..=max_log2().min(CONVERT_MAX_LOG2)).step_by(2) {
        let n = 1u64 << log2;
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            let set = make_pairs(log2, relation);
            let tag = if relation == Relation::Intersecting {
                "int"
            } else {
                "dis"
            };
            let mut rng = SmallRng::seed_from_u64(SEED + 2);
            let mut ws = ClmWorkspace::default();
            let mut cws = ConvertWorkspace::default();
            let mut i = 0;
            group.bench_with_input(BenchmarkId::new(format!("clm-{tag}"), n), &set, |b, set| {
                b.iter(|| {
                    let (p, q) = &set.pairs[i % set.pairs.len()];
                    i += 1;
                    assert_eq!(
                        Clm.intersects_with_workspace(Exact, p, q, &mut rng, &mut ws),
                        set.answer
                    );
                })
            });
            group.bench_with_input(BenchmarkId::new(format!("convert-{tag}"), n), &set, |b, set| {
                b.iter(|| {
                    let (p, q) = &set.pairs[i % set.pairs.len()];
                    i += 1;
                    let got = <Convert>::default().intersects_with_workspace(Exact, p, q, &mut rng, &mut cws);
                    assert_eq!(got, set.answer);
                })
            });
        }
    }
    group.finish();
}

fn bench_factor(c: &mut Criterion) {
    let mut group = c.benchmark_group("clm_factor");
    for log2 in [12u32, 18].into_iter().filter(|&l| l <= max_log2()) {
        let n = 1u64 << log2;
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            let set = make_pairs(log2, relation);
            let tag = if relation == Relation::Intersecting {
                "int"
            } else {
                "dis"
            };
            for factor in [0.5, 1.0, 1.5, 2.0, 3.0] {
                let mut rng = SmallRng::seed_from_u64(SEED + 3);
                let mut ws = ClmWorkspace::default();
                let mut i = 0;
                group.bench_with_input(BenchmarkId::new(format!("c{factor}-{tag}"), n), &set, |b, set| {
                    b.iter(|| {
                        let (p, q) = &set.pairs[i % set.pairs.len()];
                        i += 1;
                        let got =
                            ClmWithFactor(factor).intersects_with_workspace(Exact, p, q, &mut rng, &mut ws);
                        assert_eq!(got, set.answer);
                    })
                });
            }
        }
    }
    group.finish();
}

/// Median over batches of the mean time per query, in microseconds.
fn all(c: &mut Criterion) {
    bench_clm(c);
    bench_convert_vs_clm(c);
    bench_factor(c);
}

criterion_group!(benches, all);

criterion_main!(benches);
