//! `ChazelleDobkin` against the exact reference (`Linear`, and the O(n·m) oracle on
//! small inputs) on random, touching, nested and extreme families, with shifted start
//! vertices (the pivot is vertex 0, so every start is a different pivot). The exact
//! kernel must never disagree; the fast kernel's disagreements are counted per family
//! and printed (a measurement, not a failure).

use polysect::generate::{self, Family, Relation, map_pair, regular_polygon};
use polysect::intersect::ArrayEngine;
use polysect::intersect::{ArrayIntersection, ChazelleDobkin, Iterations, Linear, brute_force};
use polysect::{ConvexPolygon, Exact, Fast, Point};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const SEED: u64 = 0xcd19_8701;

type Pair = (ConvexPolygon, ConvexPolygon);

/// The reference answer: `Linear`, cross-checked by the oracle when small.
fn truth(p: &ConvexPolygon, q: &ConvexPolygon) -> bool {
    let t = Linear.intersects_with(Exact, p, q);
    if p.len() * q.len() <= 4096 {
        assert_eq!(brute_force(Exact, p, q), t, "reference disagrees with oracle");
    }
    t
}

/// Asserts the exact answer on (p, q) and (q, p); returns how many of the two fast
/// answers agree.
fn check(p: &ConvexPolygon, q: &ConvexPolygon, what: &str) -> (u32, u32) {
    let want = truth(p, q);
    assert_eq!(
        ChazelleDobkin.intersects_with(Exact, p, q),
        want,
        "exact wrong: {what}\n{p:?}\n{q:?}"
    );
    assert_eq!(
        ChazelleDobkin.intersects_with(Exact, q, p),
        want,
        "exact wrong (swapped): {what}\n{q:?}\n{p:?}"
    );
    let fast = [
        ChazelleDobkin.intersects_with(Fast, p, q),
        ChazelleDobkin.intersects_with(Fast, q, p),
    ];
    (fast.iter().filter(|&&a| a != want).count() as u32, 2)
}

/// Checks the pair at its generated starts, at random starts, and at every start of
/// the smaller polygon when it is small.
fn check_pair(pair: &Pair, rng: &mut SmallRng, what: &str) -> (u32, u32) {
    let (p, q) = pair;
    let mut acc = check(p, q, what);
    let add = |acc: &mut (u32, u32), r: (u32, u32)| {
        acc.0 += r.0;
        acc.1 += r.1;
    };
    let (rp, rq) = (
        p.starting_at(rng.random_range(0..p.len())),
        q.starting_at(rng.random_range(0..q.len())),
    );
    add(&mut acc, check(&rp, &rq, &format!("{what} random starts")));
    if p.len() <= 8 {
        for s in 1..p.len() {
            add(
                &mut acc,
                check(&p.starting_at(s), q, &format!("{what} p start {s}")),
            );
        }
    }
    if q.len() <= 8 {
        for s in 1..q.len() {
            add(
                &mut acc,
                check(p, &q.starting_at(s), &format!("{what} q start {s}")),
            );
        }
    }
    acc
}

#[test]
fn random_pairs_of_every_family_and_size() {
    let mut rng = SmallRng::seed_from_u64(SEED);
    let sizes = [3, 4, 5, 6, 7, 8, 10, 13, 20, 33, 64, 100, 257, 1000];
    let mut report = Vec::new();
    for &family in Family::ALL {
        let (mut wrong, mut total) = (0, 0);
        for i in 0..700 {
            let n = if i % 70 == 69 {
                1 << rng.random_range(10..=16)
            } else {
                sizes[i % sizes.len()]
            };
            let relation = [Relation::Any, Relation::Intersecting, Relation::Disjoint][i % 3];
            let pair = generate::pair(family, n, relation, &mut rng);
            let r = check_pair(&pair, &mut rng, &format!("{family} n={n} {relation:?} #{i}"));
            wrong += r.0;
            total += r.1;
        }
        report.push(format!("{family}: {wrong}/{total}"));
    }
    println!("chazelle-dobkin fast-kernel disagreements: {}", report.join(", "));
}

#[test]
fn different_sizes_on_each_side() {
    let mut rng = SmallRng::seed_from_u64(SEED + 1);
    let mut wrong = 0;
    let mut total = 0;
    for i in 0..600 {
        let (n, m) = ([3, 5, 40, 700][i % 4], [4, 9, 3000, 3][(i / 4) % 4]);
        let family = [Family::Ellipse, Family::Rotated, Family::NonUniform][i % 3];
        let relation = [Relation::Any, Relation::Intersecting, Relation::Disjoint][(i / 3) % 3];
        let (p, _) = generate::pair(family, n, relation, &mut rng);
        let (_, q) = generate::pair(family, m, relation, &mut rng);
        let r = check_pair(&(p, q), &mut rng, &format!("mixed sizes n={n} m={m} #{i}"));
        wrong += r.0;
        total += r.1;
    }
    println!("chazelle-dobkin fast-kernel disagreements, mixed sizes: {wrong}/{total}");
}

#[test]
fn touching_families_at_every_start() {
    let mut rng = SmallRng::seed_from_u64(SEED + 2);
    let mut report = Vec::new();
    for &family in Family::TOUCHING {
        let (mut wrong, mut total) = (0, 0);
        for i in 0..150 {
            let relation = if i % 2 == 0 {
                Relation::Intersecting
            } else {
                Relation::Disjoint
            };
            let n = 3 + i % 9;
            let pair = generate::pair(family, n, relation, &mut rng);
            // every start of both polygons (every pivot)
            for s in 0..pair.0.len() {
                for t in 0..pair.1.len().min(4) {
                    let r = check(
                        &pair.0.starting_at(s),
                        &pair.1.starting_at(t),
                        &format!("{family} n={n} s={s} t={t}"),
                    );
                    wrong += r.0;
                    total += r.1;
                }
            }
        }
        report.push(format!("{family}: {wrong}/{total}"));
    }
    println!(
        "chazelle-dobkin fast-kernel disagreements, touching at every start: {}",
        report.join(", ")
    );
}

#[test]
fn containment_identity_and_nesting() {
    let mut rng = SmallRng::seed_from_u64(SEED + 3);
    for n in [3, 4, 5, 7, 16, 100, 1024] {
        let outer = regular_polygon(n, 2.0);
        let inner = regular_polygon(n, 1.0);
        let rot =
            ConvexPolygon::new(inner.vertices().iter().map(|v| Point::new(-v.y * 0.9, v.x * 0.9))).unwrap();
        for s in [0, 1, n / 2, n - 1] {
            for (a, b) in [
                (&outer, &inner),
                (&outer, &rot),
                (&inner, &inner),
                (&outer, &outer),
            ] {
                check(&a.starting_at(s), b, &format!("nested/identical n={n} s={s}"));
            }
        }
        // Identical polygons at random starts, and a tiny polygon deep inside.
        let (p, _) = generate::pair(Family::NonUniform, n, Relation::Any, &mut rng);
        check(&p, &p.starting_at(rng.random_range(0..p.len())), "identical");
        let tiny = ConvexPolygon::new([[0.0, 0.0], [1e-9, 0.0], [0.0, 1e-9]]).unwrap();
        check(&outer, &tiny, "tiny inside");
        for s in 0..3 {
            check(&tiny.starting_at(s), &outer, "tiny inside (pivot in tiny)");
        }
    }
    for i in 0..200 {
        let n = [3, 4, 5, 8, 30, 500][i % 6];
        let relation = [Relation::Intersecting, Relation::Disjoint][i % 2];
        let pair = generate::pair(Family::Nested, n, relation, &mut rng);
        check_pair(&pair, &mut rng, &format!("Nested n={n} #{i}"));
    }
}

#[test]
fn triangles_against_large_polygons() {
    let mut rng = SmallRng::seed_from_u64(SEED + 4);
    let big = regular_polygon(1 << 20, 1.0);
    let medium = regular_polygon(1 << 12, 1.0);
    for poly in [&medium, &big] {
        let n = poly.len();
        for i in 0..60 {
            // A triangle near the boundary at a random angle: inside, crossing, outside,
            // or with a vertex exactly on a vertex of the polygon.
            let k = rng.random_range(0..n);
            let v = poly.vertex(k);
            let r = [0.5, 0.999, 1.0, 1.001, 1.5][i % 5];
            let c = Point::new(v.x * r, v.y * r);
            let d = 1e-3 * rng.random_range(0.1..2.0);
            let tri = ConvexPolygon::new([
                c,
                Point::new(c.x + d * v.x + d * v.y, c.y + d * v.y - d * v.x),
                Point::new(c.x + d * v.x - d * v.y, c.y + d * v.y + d * v.x),
            ])
            .unwrap();
            let s = rng.random_range(0..n);
            let p = if i % 2 == 0 {
                poly.starting_at(s)
            } else {
                poly.clone()
            };
            check(&p, &tri, &format!("triangle vs {n}-gon #{i} r={r}"));
            for t in 1..3 {
                check(
                    &p,
                    &tri.starting_at(t),
                    &format!("triangle vs {n}-gon #{i} r={r} t={t}"),
                );
            }
        }
    }
}

#[test]
fn extremes_scaled_offset_and_one_ulp() {
    let mut rng = SmallRng::seed_from_u64(SEED + 5);
    // Fast-kernel disagreements per variant: scale 2^1000, 2^-1000, 2^600, 2^-1022,
    // offset 2^40..2^52, offset after scaling by 2^20 (rounded pairs that stop being
    // valid polygons are skipped).
    let labels = [
        "x2^1000",
        "x2^-1000",
        "x2^600",
        "x2^-1022",
        "offset",
        "offset+x2^20",
    ];
    let mut wrong = [0u32; 6];
    let mut total = [0u32; 6];
    for i in 0..400 {
        let family = Family::ALL[i % Family::ALL.len()];
        let relation = [Relation::Intersecting, Relation::Disjoint, Relation::Any][i % 3];
        let n = [3, 5, 12, 40, 200][i % 5];
        let base = generate::pair(family, n, relation, &mut rng);
        let ei = i % 4;
        let s = 2f64.powi([1000, -1000, 600, -1022][ei]);
        let off = 2f64.powi(rng.random_range(40..=52));
        let variants = [
            (ei, map_pair(&base, |p| Point::new(p.x * s, p.y * s))),
            (4, map_pair(&base, |p| Point::new(p.x + off, p.y - off))),
            (
                5,
                map_pair(&base, |p| {
                    Point::new(p.x * 2f64.powi(20) + off, p.y * 2f64.powi(20) - off)
                }),
            ),
        ];
        for (v, pair) in variants {
            if let Some(pair) = pair {
                let r = check_pair(
                    &pair,
                    &mut rng,
                    &format!("extreme {family} n={n} #{i} {}", labels[v]),
                );
                wrong[v] += r.0;
                total[v] += r.1;
            }
        }
    }
    let report: Vec<String> = (0..6)
        .map(|v| format!("{}: {}/{}", labels[v], wrong[v], total[v]))
        .collect();
    println!(
        "chazelle-dobkin fast-kernel disagreements on extremes: {}",
        report.join(", ")
    );
    // One-ulp gaps and their touching twins.
    for n in [3, 10, 100, 1000] {
        for _ in 0..30 {
            let seed: u64 = rng.random();
            for (relation, want) in [(Relation::Intersecting, true), (Relation::Disjoint, false)] {
                let (p, q) =
                    generate::pair(Family::OneUlpGap, n, relation, &mut SmallRng::seed_from_u64(seed));
                for s in [0, 1, p.len() / 2] {
                    let p = p.starting_at(s);
                    assert_eq!(ChazelleDobkin.intersects(&p, &q), want, "one ulp n={n}");
                    assert_eq!(ChazelleDobkin.intersects(&q, &p), want, "one ulp swapped n={n}");
                }
            }
        }
    }
}

#[test]
fn iterations_grow_like_log_n() {
    let n: usize = 1 << 20;
    let log2n = 20u64;
    let p = regular_polygon(n, 1.0);
    let mut rng = SmallRng::seed_from_u64(SEED + 6);
    let mut worst = 0;
    for i in 0..12 {
        let angle = rng.random_range(0.0..std::f64::consts::TAU);
        let dist = [1.9, 2.1, 2.0, 1.0][i % 4];
        let (dx, dy) = (dist * angle.cos(), dist * angle.sin());
        let q = p.map(|v| Point::new(v.x + dx, v.y + dy)).unwrap();
        let q = q.starting_at(rng.random_range(0..n));
        let p = p.starting_at(rng.random_range(0..n));
        let mut it = Iterations::default();
        let got = ChazelleDobkin.intersects_probed(Exact, &p, &q, &mut it);
        assert_eq!(got, Linear.intersects(&p, &q), "2^20 pair #{i}");
        worst = worst.max(it.0);
    }
    println!("chazelle-dobkin pruning iterations at n = 2^20: worst {worst}");
    assert!(worst <= 3 * log2n, "{worst} iterations at n = 2^20");
}

/// Hulls of random points on a small lattice: many collinear triples, shared
/// vertices, vertices on edges and overlapping edges, at every start of P.
#[test]
fn lattice_hulls_at_every_pivot() {
    let mut rng = SmallRng::seed_from_u64(SEED + 7);
    let lattice_poly = |rng: &mut SmallRng, size: i32| loop {
        let k = rng.random_range(3..12);
        let pts: Vec<Point> = (0..k)
            .map(|_| Point::new(rng.random_range(0..size) as f64, rng.random_range(0..size) as f64))
            .collect();
        if let Ok(h) = polysect::polygon::convex_hull(&pts) {
            return h;
        }
    };
    let mut count = 0;
    for i in 0..STRESS_LATTICE {
        let size = [3, 5, 8][i % 3];
        let p = lattice_poly(&mut rng, size);
        let q = lattice_poly(&mut rng, size);
        let want = truth(&p, &q);
        for s in 0..p.len() {
            let ps = p.starting_at(s);
            assert_eq!(
                ChazelleDobkin.intersects(&ps, &q),
                want,
                "lattice #{i}\n{ps:?}\n{q:?}"
            );
            count += 1;
        }
    }
    assert!(count >= STRESS_LATTICE);
}

const STRESS_LATTICE: usize = 20_000;
