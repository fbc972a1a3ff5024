//! Every array algorithm in `Algorithm::ARRAY`, under both kernels, against the exact
//! reference (`Linear`, and `brute_force` on small pairs) on random, touching and
//! extreme families. The exact kernel must never disagree; the fast kernel's
//! disagreements are counted per family and printed (a measurement, not a failure).
//! Run with `--nocapture` to see the counts.

use crate::cases::companions;
use polysect::generate::{self, Family, Relation, map_pair};
use polysect::intersect::{Algorithm, ArrayIntersection, Linear, brute_force};
use polysect::{ConvexPolygon, Exact, Point, Precision};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::collections::BTreeMap;
use std::f64::consts::TAU;

const SEED_RANDOM: u64 = 0x5eed_0001;
const SEED_TOUCHING: u64 = 0x5eed_0002;
const SEED_EXTREME: u64 = 0x5eed_0003;
const SEED_CIRCLE: u64 = 0x5eed_0004;
const SEED_ITERATIONS: u64 = 0x5eed_0005;

type Pair = (ConvexPolygon, ConvexPolygon);

/// Fast-kernel disagreements per (algorithm, family): (wrong, total).
#[derive(Default)]
struct FastCounts(BTreeMap<(String, String), (u64, u64)>);

impl FastCounts {
    fn print(&self, title: &str) {
        println!("fast-kernel disagreements with the exact reference ({title}):");
        for ((alg, fam), (wrong, total)) in &self.0 {
            println!("  {alg:>8} {fam:<20} {wrong:>6} / {total}");
        }
    }
}

/// Checks every algorithm on (p, q) and (q, p): exact answers must equal the
/// reference, fast answers are counted.
fn check(pair: &Pair, family: &str, what: &str, fast: &mut FastCounts) {
    check_refs(&pair.0, &pair.1, family, what, fast)
}

fn check_refs(p: &ConvexPolygon, q: &ConvexPolygon, family: &str, what: &str, fast: &mut FastCounts) {
    let truth = Linear.intersects_with(Exact, p, q);
    if p.len() * q.len() <= 4096 {
        assert_eq!(
            brute_force(Exact, p, q),
            truth,
            "linear vs oracle: {what}\n{p:?}\n{q:?}"
        );
    }
    // Linear is the reference itself (checked against the oracle in tests/geometry/reference.rs).
    for &alg in Algorithm::ARRAY.iter().filter(|&&a| a != Algorithm::Linear) {
        for (a, b) in [(p, q), (q, p)] {
            let got = alg.intersects(Precision::Exact, a, b);
            assert_eq!(got, truth, "{alg}/exact wrong on {what}\np = {a:?}\nq = {b:?}");
            let entry = fast
                .0
                .entry((alg.name().to_string(), family.to_string()))
                .or_default();
            entry.1 += 1;
            if alg.intersects(Precision::Fast, a, b) != truth {
                entry.0 += 1;
            }
        }
    }
}

/// Rotates both polygons to random start vertices (the thesis's shifted start).
fn shifted(pair: &Pair, rng: &mut SmallRng) -> Pair {
    let (p, q) = pair;
    (
        p.starting_at(rng.random_range(0..p.len())),
        q.starting_at(rng.random_range(0..q.len())),
    )
}

/// Mostly small sizes (log-uniform in 3..2^10), one in fifty up to 2^16.
fn random_size(rng: &mut SmallRng) -> usize {
    let max_log = if rng.random_range(0..50) == 0 { 16.0 } else { 10.0 };
    let e: f64 = rng.random_range(1.585..max_log);
    (2f64.powf(e) as usize).max(3)
}

const RELATIONS: [Relation; 3] = [Relation::Any, Relation::Intersecting, Relation::Disjoint];

#[test]
fn random_pairs_of_every_family() {
    let mut rng = SmallRng::seed_from_u64(SEED_RANDOM);
    let mut fast = FastCounts::default();
    for &family in Family::ALL {
        for i in 0..2400 {
            let n = random_size(&mut rng);
            let relation = RELATIONS[i % 3];
            let pair = generate::pair(family, n, relation, &mut rng);
            let pair = if i % 2 == 0 {
                shifted(&pair, &mut rng)
            } else {
                pair
            };
            check(
                &pair,
                family.name(),
                &format!("{family} n={n} {relation:?} #{i}"),
                &mut fast,
            );
        }
    }
    fast.print("random pairs, 2400 per family, both orders");
}

/// Touching families, containment both ways, identical polygons, nested n-gons and
/// triangles against large polygons.
#[test]
fn touching_containment_identical_nested() {
    let mut rng = SmallRng::seed_from_u64(SEED_TOUCHING);
    let mut fast = FastCounts::default();
    for &family in Family::TOUCHING.iter().chain([Family::Nested].iter()) {
        for i in 0..600 {
            let n = [3, 4, 5, 7, 16, 33, 100, 1000][i % 8];
            let relation = if i % 2 == 0 {
                Relation::Intersecting
            } else {
                Relation::Disjoint
            };
            let pair = shifted(&generate::pair(family, n, relation, &mut rng), &mut rng);
            check(
                &pair,
                family.name(),
                &format!("{family} n={n} {relation:?} #{i}"),
                &mut fast,
            );
        }
    }
    for i in 0..300 {
        let n = [3, 4, 6, 10, 50, 500][i % 6];
        let (p, _) = generate::pair(Family::Ellipse, n, Relation::Any, &mut rng);
        // Identical, and identical from another start vertex.
        check(
            &(p.clone(), p.clone()),
            "identical",
            &format!("identical n={n}"),
            &mut fast,
        );
        check(
            &(p.clone(), p.starting_at(i)),
            "identical",
            &format!("identical rotated n={n}"),
            &mut fast,
        );
        // Containment (a shrunken copy) and triangles against the polygon: around
        // vertices, on edges, outside near edges.
        for (q, family, what) in companions(&p, i) {
            check(&(p.clone(), q), family, &what, &mut fast);
        }
    }
    // Nested regular n-gons: the inner one inscribed in the outer one's edge midpoints
    // (touching) and slightly smaller (disjoint boundaries, containment).
    for n in [3, 4, 5, 8, 31, 64, 257, 4096] {
        let outer = generate::regular_polygon(n, 1.0);
        let r = (TAU / (2 * n) as f64).cos();
        let mids = outer.map(|p| p).unwrap();
        let mid_pts: Vec<[f64; 2]> = (0..n)
            .map(|i| {
                let (a, b) = (mids.vertex(i), mids.vertex(i + 1));
                [(a.x + b.x) / 2.0, (a.y + b.y) / 2.0]
            })
            .collect();
        if let Ok(inner) = ConvexPolygon::new(mid_pts) {
            check(
                &(outer.clone(), inner),
                "nested-n-gon",
                &format!("midpoint n-gon {n}"),
                &mut fast,
            );
        }
        let smaller = generate::regular_polygon(n, r * 0.999);
        check(
            &(outer.clone(), smaller.starting_at(n / 3)),
            "nested-n-gon",
            &format!("inner n-gon {n}"),
            &mut fast,
        );
    }
    fast.print("touching, containment, identical, nested, triangles");
}

/// A 2^20-vertex circle (long runs of nearly collinear vertices) against small
/// polygons near its boundary, inside and outside.
#[test]
fn huge_circle_against_small_polygons() {
    let circle = generate::regular_polygon(1 << 20, 1.0);
    let mut rng = SmallRng::seed_from_u64(SEED_CIRCLE);
    let mut fast = FastCounts::default();
    for i in 0..120 {
        let t: f64 = rng.random_range(0.0..TAU);
        let r = 1.0 + [-1e-3, -1e-9, 0.0, 1e-12, 1e-9, 1e-3][i % 6];
        let (x, y) = (r * t.cos(), r * t.sin());
        let s = [1e-12, 1e-9, 1e-6, 1e-3][i % 4];
        let shapes: [&[[f64; 2]]; 2] = [
            &[[x, y], [x + s, y], [x, y + s]],
            &[[x - s, y - s], [x + s, y - s], [x + s, y + s], [x - s, y + s]],
        ];
        for sh in shapes {
            if let Ok(small) = ConvexPolygon::new(sh.iter().copied()) {
                check_refs(
                    &circle,
                    &small,
                    "circle-2^20",
                    &format!("circle #{i} r={r} s={s}"),
                    &mut fast,
                );
            }
        }
        // A vertex of the circle exactly shared.
        let v = circle.vertex(rng.random_range(0..1 << 20));
        if let Ok(t) = ConvexPolygon::new([
            [v.x, v.y],
            [v.x * 2.0, v.y * 2.0 + 0.1],
            [v.x * 2.0 + 0.1, v.y * 2.0],
        ]) {
            check_refs(
                &circle,
                &t,
                "circle-2^20",
                &format!("circle shared vertex #{i}"),
                &mut fast,
            );
        }
    }
    fast.print("2^20-gon against small polygons");
}

/// Scaled by 2^±1000, offset by 2^40..2^52, and one-ulp gaps.
#[test]
fn extremes() {
    let mut rng = SmallRng::seed_from_u64(SEED_EXTREME);
    let mut fast = FastCounts::default();
    for i in 0..500 {
        let family = Family::ALL[i % Family::ALL.len()];
        let relation = if i % 2 == 0 {
            Relation::Intersecting
        } else {
            Relation::Disjoint
        };
        let n = [3, 5, 12, 40, 200][i % 5];
        let base = generate::pair(family, n, relation, &mut rng);
        let e = [1000, -1000][i % 2];
        let s = 2f64.powi(e);
        let off = 2f64.powi(rng.random_range(40..=52));
        let variants = [
            (
                format!("scale-2^{e}"),
                map_pair(&base, |p| Point::new(p.x * s, p.y * s)),
            ),
            (
                "offset-2^40..52".to_string(),
                map_pair(&base, |p| Point::new(p.x + off, p.y - off)),
            ),
        ];
        for (name, pair) in variants {
            if let Some(pair) = pair {
                check(&pair, &name, &format!("{name} {family} n={n} #{i}"), &mut fast);
            }
        }
    }
    for i in 0..600 {
        let n = [3, 4, 10, 100, 1000, 5000][i % 6];
        let relation = if i % 2 == 0 {
            Relation::Intersecting
        } else {
            Relation::Disjoint
        };
        let pair = shifted(
            &generate::pair(Family::OneUlpGap, n, relation, &mut rng),
            &mut rng,
        );
        let want = relation == Relation::Intersecting;
        assert_eq!(Linear.intersects(&pair.0, &pair.1), want);
        check(&pair, "one-ulp-gap", &format!("one-ulp n={n} #{i}"), &mut fast);
    }
    fast.print("extremes");
}

/// The thesis's experiment 2: iterations grow like log n. At n = 2^20 per polygon,
/// every O(log n) algorithm stays within 4·log2 n + 8 iterations on rotated
/// ellipses (intersecting and disjoint) and on near-touching small polygons against
/// a 2^20-gon, and the mean count at 2^20 is below 4× the mean count at 2^10.
#[test]
fn iterations_grow_like_log_n() {
    let mut rng = SmallRng::seed_from_u64(SEED_ITERATIONS);
    let mut sums: BTreeMap<(&str, usize), (u64, u64)> = BTreeMap::new();
    for log in [10, 20] {
        let n = 1usize << log;
        let mut pairs = Vec::new();
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            for _ in 0..3 {
                pairs.push(generate::pair(Family::Rotated, n, relation, &mut rng));
            }
        }
        let circle = generate::regular_polygon(n, 1.0);
        for i in 0..6 {
            let t: f64 = rng.random_range(0.0..TAU);
            let r = 1.0 + [-1e-7, 1e-7, 0.0][i % 3];
            let (x, y) = (r * t.cos(), r * t.sin());
            let s = 1e-9;
            let tri = ConvexPolygon::new([[x, y], [x + s, y], [x, y + s]]).unwrap();
            pairs.push((circle.clone(), tri));
        }
        for (p, q) in &pairs {
            let truth = Linear.intersects(p, q);
            for &alg in Algorithm::LOGARITHMIC {
                for (a, b) in [(p, q), (q, p)] {
                    let (answer, iterations) = alg.run(Precision::Exact, a, b);
                    assert_eq!(answer, truth, "{alg} n={n}");
                    let bound = 4 * log as u64 + 8;
                    assert!(
                        iterations <= bound,
                        "{alg}: {iterations} iterations at n = 2^{log}"
                    );
                    let e = sums.entry((alg.name(), log)).or_default();
                    e.0 += iterations;
                    e.1 = e.1.max(iterations);
                }
            }
        }
    }
    for &alg in Algorithm::LOGARITHMIC {
        let (a, b) = (sums[&(alg.name(), 10)], sums[&(alg.name(), 20)]);
        println!(
            "{alg}: iterations mean {:.1} (max {}) at 2^10, mean {:.1} (max {}) at 2^20",
            a.0 as f64 / 24.0,
            a.1,
            b.0 as f64 / 24.0,
            b.1
        );
        assert!(
            b.0 < 4 * a.0,
            "{alg}: {} iterations at 2^20 vs {} at 2^10",
            b.0,
            a.0
        );
    }
}
