//! The reference test (`Linear`) against the O(n·m) oracle on random, touching and
//! extreme families. The exact kernel must never disagree; the fast kernel's
//! disagreements are counted and printed (a measurement, not a failure).

use polysect::generate::{self, Family, Relation, map_pair};
use polysect::intersect::{ArrayIntersection, Linear, brute_force};
use polysect::{ConvexPolygon, Exact, Fast, Point};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const SEED: u64 = 0x9e37_79b9;

type Pair = (ConvexPolygon, ConvexPolygon);

fn check_pair(pair: &Pair, what: &str) -> bool {
    let (p, q) = pair;
    let truth = brute_force(Exact, p, q);
    assert_eq!(brute_force(Exact, q, p), truth, "oracle not symmetric: {what}");
    assert_eq!(
        Linear.intersects_with(Exact, p, q),
        truth,
        "linear/exact wrong: {what}\n{p:?}\n{q:?}"
    );
    assert_eq!(
        Linear.intersects_with(Exact, q, p),
        truth,
        "linear/exact wrong (swapped): {what}"
    );
    Linear.intersects_with(Fast, p, q) == truth
}

#[test]
fn linear_equals_oracle_on_every_family() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let mut fast_wrong = Vec::new();
    for &family in Family::ALL {
        let mut wrong = 0;
        let mut total = 0;
        for i in 0..400 {
            let n = [3, 4, 5, 8, 13, 40, 120][i % 7];
            let relation = [Relation::Any, Relation::Intersecting, Relation::Disjoint][i % 3];
            let pair = generate::pair(family, n, relation, &mut rng);
            total += 1;
            if !check_pair(&pair, &format!("{family} n={n} #{i}")) {
                wrong += 1;
            }
        }
        fast_wrong.push(format!("{family}: {wrong}/{total}"));
    }
    println!(
        "fast-kernel disagreements with the oracle: {}",
        fast_wrong.join(", ")
    );
}

#[test]
fn linear_equals_oracle_on_extremes() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    let mut fast_wrong = 0;
    let mut total = 0;
    for i in 0..600 {
        let family = Family::TOUCHING[i % Family::TOUCHING.len()];
        let relation = if i % 2 == 0 {
            Relation::Intersecting
        } else {
            Relation::Disjoint
        };
        let base = generate::pair(family, 3 + i % 30, relation, &mut rng);
        let e = [1000, -1000, 600, -1022, 0][i % 5];
        let s = 2f64.powi(e);
        let variants = [
            map_pair(&base, |p| Point::new(p.x * s, p.y * s)),
            map_pair(&base, |p| Point::new(p.x + 2f64.powi(40), p.y - 2f64.powi(40))),
            map_pair(&base, |p| {
                Point::new(p.x * 2f64.powi(-30) + 2f64.powi(50), p.y * 2f64.powi(-30))
            }),
        ];
        for pair in variants.into_iter().flatten() {
            total += 1;
            if !check_pair(&pair, &format!("extreme {family} #{i} e={e}")) {
                fast_wrong += 1;
            }
        }
    }
    println!("fast-kernel disagreements on extremes: {fast_wrong}/{total}");
}

#[test]
fn one_ulp_apart_and_touching_twins_differ() {
    let mut rng = SmallRng::seed_from_u64(SEED + 2);
    for n in [3, 10, 100] {
        for _ in 0..50 {
            let seed: u64 = rng.random();
            let touch = generate::pair(
                Family::OneUlpGap,
                n,
                Relation::Intersecting,
                &mut SmallRng::seed_from_u64(seed),
            );
            let gap = generate::pair(
                Family::OneUlpGap,
                n,
                Relation::Disjoint,
                &mut SmallRng::seed_from_u64(seed),
            );
            assert!(Linear.intersects(&touch.0, &touch.1));
            assert!(!Linear.intersects(&gap.0, &gap.1));
        }
    }
}

#[test]
fn unit_squares_offset_by_2_pow_50() {
    let o = 2f64.powi(50);
    let sq = |x: f64, y: f64| {
        ConvexPolygon::new([
            [o + x, o + y],
            [o + x + 1.0, o + y],
            [o + x + 1.0, o + y + 1.0],
            [o + x, o + y + 1.0],
        ])
        .unwrap()
    };
    assert!(Linear.intersects(&sq(0.0, 0.0), &sq(1.0, 0.0)));
    assert!(Linear.intersects(&sq(0.0, 0.0), &sq(1.0, 1.0)));
    assert!(!Linear.intersects(&sq(0.0, 0.0), &sq(1.25, 0.0)));
    // A diagonal gap of one ulp of 2^50 (0.25) across a corner.
    let tri = ConvexPolygon::new([[o + 1.25, o + 1.0], [o + 3.0, o + 1.0], [o + 1.25, o + 3.0]]).unwrap();
    assert!(!Linear.intersects(&sq(0.0, 0.0), &tri));
}

#[test]
fn large_circle_against_triangles() {
    let circle = generate::regular_polygon(1 << 16, 1.0);
    let mut rng = SmallRng::seed_from_u64(SEED + 3);
    for _ in 0..100 {
        let t: f64 = rng.random_range(0.0..std::f64::consts::TAU);
        let r: f64 = rng.random_range(0.9..1.1);
        let (x, y) = (r * t.cos(), r * t.sin());
        let tri = ConvexPolygon::new([[x, y], [x + 0.001, y], [x, y + 0.001]]).unwrap();
        assert_eq!(
            Linear.intersects(&circle, &tri),
            brute_force(Exact, &circle, &tri)
        );
    }
}
