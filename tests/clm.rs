//! `Clm` and `Convert` × both kernels against the exact reference `Linear` on every
//! generator family, sizes 3..2^16, touching and containment pairs, extremes, and after
//! edits; each pair is linked in several shuffled arena orders and queried with many
//! RNG seeds so that unlucky samples are exercised. Zero disagreements under `Exact`;
//! fast-kernel disagreements are counted and printed.

use polysect::generate::{Family, Relation, map_pair, pair, regular_polygon};
use polysect::intersect::LinkedEngine;
use polysect::intersect::{
    Algorithm, ArrayIntersection, Certificate, Clm, ClmVariant, ClmWithFactor, ClmWorkspace, Convert,
    ConvertWorkspace, Counts, Iterations, Linear, LinkedIntersection, LpOrder, Sampling, verify_linked,
};
use polysect::{ConvexPolygon, Exact, Fast, LinkedPolygon, Point, Precision};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const SEED: u64 = 0xc1a0_2026;
const PAIRS_PER_FAMILY: usize = 70;

#[derive(Default)]
struct Tally {
    queries: u64,
    fast_wrong_clm: u64,
    fast_wrong_convert: u64,
    fast_redone: u64,
}

struct Harness {
    rng: SmallRng,
    clm: ClmWorkspace,
    conv: ConvertWorkspace,
    tally: Tally,
}

impl Harness {
    fn new(seed: u64) -> Self {
        Harness {
            rng: SmallRng::seed_from_u64(seed),
            clm: ClmWorkspace::default(),
            conv: ConvertWorkspace::default(),
            tally: Tally::default(),
        }
    }

    /// Links the pair in `layouts` shuffled orders and queries each with `seeds` RNG draws.
    fn check(&mut self, p: &ConvexPolygon, q: &ConvexPolygon, layouts: usize, seeds: usize, what: &str) {
        let truth = Linear.intersects(p, q);
        for _ in 0..layouts {
            let lp = LinkedPolygon::from_convex_shuffled(p, &mut self.rng);
            let lq = LinkedPolygon::from_convex_shuffled(q, &mut self.rng);
            self.check_linked(&lp, &lq, truth, seeds, what);
        }
    }

    fn check_linked(
        &mut self,
        lp: &LinkedPolygon,
        lq: &LinkedPolygon,
        truth: bool,
        seeds: usize,
        what: &str,
    ) {
        for s in 0..seeds {
            let redone_before = self.clm.lp_stats().redone;
            let got = Clm.intersects_with_workspace(Exact, lp, lq, &mut self.rng, &mut self.clm);
            assert_eq!(
                got,
                truth,
                "clm exact differs on {what} (n = {}, m = {}, draw {s})\nP = {:?}\nQ = {:?}",
                lp.len(),
                lq.len(),
                lp.to_convex().vertices(),
                lq.to_convex().vertices()
            );
            assert_eq!(
                self.clm.lp_stats().redone,
                redone_before,
                "an exact LP failed its certification"
            );
            let swapped = Clm.intersects_with_workspace(Exact, lq, lp, &mut self.rng, &mut self.clm);
            assert_eq!(swapped, truth, "clm exact (swapped) differs on {what}");
            let redone_before = self.clm.lp_stats().redone;
            if Clm.intersects_with_workspace(Fast, lp, lq, &mut self.rng, &mut self.clm) != truth {
                self.tally.fast_wrong_clm += 1;
            }
            self.tally.fast_redone += self.clm.lp_stats().redone - redone_before;
            self.tally.queries += 1;
        }
        let conv = <Convert>::default();
        assert_eq!(
            conv.intersects_with_workspace(Exact, lp, lq, &mut self.rng, &mut self.conv),
            truth,
            "convert exact differs on {what}"
        );
        if conv.intersects_with_workspace(Fast, lp, lq, &mut self.rng, &mut self.conv) != truth {
            self.tally.fast_wrong_convert += 1;
        }
    }

    fn report(&self, name: &str) {
        println!(
            "{name}: {} clm queries; fast kernel wrong: clm {}, convert {}; fast LPs redone exactly: {}",
            self.tally.queries,
            self.tally.fast_wrong_clm,
            self.tally.fast_wrong_convert,
            self.tally.fast_redone
        );
    }
}

/// Mostly small sizes, a few large ones.
fn random_size(rng: &mut SmallRng) -> usize {
    match rng.random_range(0..100) {
        0..60 => rng.random_range(3..=24),
        60..85 => rng.random_range(25..=300),
        85..97 => rng.random_range(301..=4000),
        _ => 1 << rng.random_range(12..=14),
    }
}

#[test]
fn every_family_random_sizes() {
    let mut h = Harness::new(SEED);
    let mut pairs = 0;
    for &family in Family::ALL {
        for relation in [Relation::Any, Relation::Intersecting, Relation::Disjoint] {
            for _ in 0..PAIRS_PER_FAMILY {
                let n = random_size(&mut h.rng);
                let (p, q) = pair(family, n, relation, &mut h.rng);
                let seeds = if n <= 300 { 12 } else { 3 };
                h.check(&p, &q, 2, seeds, family.name());
                pairs += 1;
            }
        }
    }
    h.report("families");
    assert_eq!(pairs, Family::ALL.len() * 3 * PAIRS_PER_FAMILY);
}

#[test]
fn largest_sizes() {
    let mut h = Harness::new(SEED + 1);
    for (n, family) in [
        (1 << 16, Family::Rotated),
        (1 << 16, Family::Nested),
        (1 << 15, Family::SharedEdge),
    ] {
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            let (p, q) = pair(family, n, relation, &mut h.rng);
            h.check(&p, &q, 1, 3, family.name());
        }
    }
    h.report("largest");
}

#[test]
fn touching_families_many_draws() {
    let mut h = Harness::new(SEED + 2);
    for &family in Family::TOUCHING {
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            for _ in 0..40 {
                let n = random_size(&mut h.rng).min(2000);
                let (p, q) = pair(family, n, relation, &mut h.rng);
                h.check(&p, &q, 2, 20, family.name());
            }
        }
    }
    h.report("touching");
}

/// A small polygon deep inside, touching from inside, or just outside a large one; and
/// polygons smaller than the sample against large ones.
#[test]
fn containment_and_tiny_against_large() {
    let mut h = Harness::new(SEED + 3);
    for &n in &[3usize, 5, 17, 100, 1000, 8000] {
        let big = regular_polygon(n.max(3), 1.0);
        let tris: Vec<(ConvexPolygon, &str)> = vec![
            (
                ConvexPolygon::new([[-0.1, -0.1], [0.1, -0.1], [0.0, 0.1]]).unwrap(),
                "inside",
            ),
            (
                ConvexPolygon::new([[1.0, 0.0], [2.0, -1.0], [2.0, 1.0]]).unwrap(),
                "vertex on vertex",
            ),
            (
                ConvexPolygon::new([[0.5, 0.0], [1.0, 0.0], [0.7, 0.1]]).unwrap(),
                "touching from inside",
            ),
            (
                ConvexPolygon::new([[1.5, 0.0], [2.0, -1.0], [2.0, 1.0]]).unwrap(),
                "outside",
            ),
            (
                ConvexPolygon::new([[-5.0, -5.0], [5.0, -5.0], [0.0, 5.0]]).unwrap(),
                "containing",
            ),
        ];
        for (t, what) in &tris {
            h.check(&big, t, 3, 15, what);
        }
        // The same polygon, and a shrunken copy inside it.
        h.check(&big, &big, 2, 10, "identical");
        let small = big.map(|v| Point::new(v.x * 0.5, v.y * 0.5)).unwrap();
        h.check(&big, &small, 2, 10, "nested copy");
        // A copy shifted so that a vertex or an edge touches.
        let shifted = big.map(|v| Point::new(v.x + 2.0, v.y)).unwrap();
        h.check(&big, &shifted, 2, 10, "shifted copy");
    }
    h.report("containment");
}

/// Scaled by 2^±1000 and shifted by 2^40..2^52.
#[test]
fn extremes() {
    let mut h = Harness::new(SEED + 4);
    let mut mapped = 0;
    for &family in Family::ALL {
        for _ in 0..20 {
            let n = h.rng.random_range(3..=200);
            let base = pair(family, n, Relation::Any, &mut h.rng);
            let shift = 2f64.powi(h.rng.random_range(40..=52));
            let maps: [Box<dyn Fn(Point) -> Point>; 4] = [
                Box::new(|v: Point| Point::new(v.x * 2f64.powi(1000), v.y * 2f64.powi(1000))),
                Box::new(|v: Point| Point::new(v.x * 2f64.powi(-1000), v.y * 2f64.powi(-1000))),
                Box::new(move |v: Point| Point::new(v.x + shift, v.y + shift)),
                Box::new(move |v: Point| Point::new((v.x - shift) * 2f64.powi(-900), v.y * 2f64.powi(900))),
            ];
            for f in maps {
                if let Some((p, q)) = map_pair(&base, f) {
                    h.check(&p, &q, 1, 5, family.name());
                    mapped += 1;
                }
            }
        }
    }
    h.report("extremes");
    assert!(mapped > Family::ALL.len() * 20);
}

/// Random valid edits between queries: remove, insert just outside an edge, move a vertex.
#[test]
fn edits_between_queries() {
    let mut h = Harness::new(SEED + 5);
    let mut edits = 0;
    for round in 0..40 {
        let n = [8usize, 50, 400, 3000][round % 4];
        let (p, q) = pair(Family::Rotated, n, Relation::Any, &mut h.rng);
        let mut lp = LinkedPolygon::from_convex_shuffled(&p, &mut h.rng);
        let mut lq = LinkedPolygon::from_convex_shuffled(&q, &mut h.rng);
        for _ in 0..30 {
            let target = if h.rng.random_bool(0.5) { &mut lp } else { &mut lq };
            let v = target.random_vertex(&mut h.rng);
            let ok = match h.rng.random_range(0..3) {
                0 => target.remove(v).is_ok(),
                1 => {
                    let a = target.point(v).unwrap();
                    let b = target.point(target.next(v).unwrap()).unwrap();
                    let t: f64 = h.rng.random_range(0.2..0.8);
                    let push: f64 = h.rng.random_range(0.0..0.05);
                    let m = Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
                    let outward = Point::new(b.y - a.y, a.x - b.x);
                    target
                        .insert_after(v, Point::new(m.x + push * outward.x, m.y + push * outward.y))
                        .is_ok()
                }
                _ => {
                    let a = target.point(v).unwrap();
                    let d = Point::new(h.rng.random_range(-0.3..0.3), h.rng.random_range(-0.3..0.3));
                    target.move_vertex(v, Point::new(a.x + d.x, a.y + d.y)).is_ok()
                }
            };
            edits += usize::from(ok);
            lp.debug_validate().unwrap();
            lq.debug_validate().unwrap();
            let truth = Linear.intersects(&lp.to_convex(), &lq.to_convex());
            h.check_linked(&lp, &lq, truth, 3, "after edits");
        }
    }
    h.report("edits");
    assert!(edits > 300);
}

/// The enum path (`Algorithm::run`) and the probe.
#[test]
fn algorithm_enum_and_probe() {
    let mut rng = SmallRng::seed_from_u64(SEED + 6);
    for _ in 0..200 {
        let n = rng.random_range(3..=500);
        let (p, q) = pair(Family::NonUniform, n, Relation::Any, &mut rng);
        let truth = Linear.intersects(&p, &q);
        for alg in [Algorithm::Clm, Algorithm::Convert] {
            for precision in Precision::ALL {
                let (got, iterations) = alg.run(precision, &p, &q);
                if precision == Precision::Exact {
                    assert_eq!(got, truth, "{alg}");
                }
                assert!(iterations > 0, "{alg} reported no work");
            }
        }
    }
    assert_eq!("clm".parse::<Algorithm>(), Ok(Algorithm::Clm));
    assert_eq!("convert".parse::<Algorithm>(), Ok(Algorithm::Convert));
    // Other sample factors give the same answers.
    let (p, q) = pair(Family::Rotated, 5000, Relation::Disjoint, &mut rng);
    let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
    let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
    for c in [0.05, 0.3, 1.0, 4.0, 100.0] {
        let mut it = Iterations::default();
        let got =
            ClmWithFactor(c).intersects_in(Exact, &lp, &lq, &mut rng, &mut ClmWorkspace::default(), &mut it);
        assert!(!got, "c = {c}");
        assert!(it.0 > 0);
    }
}

/// The thesis's variants (Fisher–Yates sampling, the caller randomising the LP), with
/// and without the chain-against-chain walk, the samples in boundary order and the
/// prefixes' quadrilaterals, answer as `Linear` does under the exact kernel, on the
/// touching families and random pairs, several seeds per pair.
#[test]
fn thesis_variants_agree_with_linear() {
    let mut rng = SmallRng::seed_from_u64(SEED + 9);
    let mut ws = ClmWorkspace::default();
    // (sampling, LP order, chain-against-chain walk, samples in boundary order, the
    // prefixes' quadrilaterals)
    let variants = [
        (Sampling::FisherYates, LpOrder::Lp, true, true, true),
        (Sampling::Independent, LpOrder::Caller, false, true, true),
        (Sampling::Independent, LpOrder::Caller, true, true, false),
        (Sampling::Independent, LpOrder::Caller, true, false, true),
        (Sampling::FisherYates, LpOrder::Caller, false, false, true),
        (Sampling::Independent, LpOrder::Lp, false, false, true),
    ];
    let (mut queries, mut intersecting) = (0u32, 0u32);
    for &family in Family::TOUCHING.iter().chain([Family::Rotated].iter()) {
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            for _ in 0..12 {
                let n = random_size(&mut rng).min(4000);
                let (p, q) = pair(family, n, relation, &mut rng);
                let truth = Linear.intersects_with(Exact, &p, &q);
                let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
                let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
                for (sampling, lp_order, chain_walk, sample_walk, prefix_quads) in variants {
                    let v = ClmVariant {
                        sampling,
                        lp_order,
                        chain_walk,
                        sample_walk,
                        prefix_quads,
                        ..ClmVariant::default()
                    };
                    for _ in 0..3 {
                        let got = v.intersects_in(Exact, &lp, &lq, &mut rng, &mut ws, &mut ());
                        assert_eq!(
                            got, truth,
                            "{family:?} n = {n}, {sampling:?}, {lp_order:?}, {chain_walk}, {sample_walk}, {prefix_quads}"
                        );
                        queries += 1;
                        intersecting += u32::from(got);
                    }
                }
            }
        }
    }
    assert!(
        intersecting > queries / 5 && intersecting < queries * 4 / 5,
        "{intersecting} of {queries}"
    );
}

/// The prefixes' quadrilaterals: on every family and at sizes where the samples have
/// more than a prefix, a query they answer is intersecting and its certificate (the
/// vertex inside) verifies; they answer most intersecting queries on the crossing
/// families, never a disjoint one, and with or without them the answers are the same.
#[test]
fn prefix_quadrilaterals_answer_only_intersecting_queries_with_verified_certificates() {
    let mut rng = SmallRng::seed_from_u64(SEED + 21);
    let mut ws = ClmWorkspace::default();
    let without = ClmVariant {
        prefix_quads: false,
        ..ClmVariant::default()
    };
    let (mut rotated, mut rotated_inside) = (0usize, 0usize);
    for &family in Family::ALL {
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            for i in 0..8 {
                // 2^9 .. 2^14 vertices: samples of 23 .. 128 points.
                let n = 1 << (9 + i % 6);
                let (p, q) = pair(family, n, relation, &mut rng);
                let truth = Linear.intersects_with(Exact, &p, &q);
                let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
                let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
                for _ in 0..4 {
                    let mut counts = Counts::default();
                    let c = Clm.certified_in(Exact, &lp, &lq, &mut rng, &mut ws, &mut counts);
                    assert_eq!(c.intersects(), truth, "{family:?} n = {n}");
                    assert_eq!(verify_linked(&lp, &lq, &c), Ok(()), "{family:?} n = {n}");
                    if counts.inside > 0 {
                        assert!(truth, "{family:?} n = {n}: a vertex inside on disjoint polygons");
                        assert!(
                            matches!(c, Certificate::VertexInside { .. }),
                            "{family:?} n = {n}: {c:?}"
                        );
                        // Answered before any LP.
                        assert_eq!(counts.lp_calls(), 0, "{family:?} n = {n}");
                    }
                    if family == Family::Rotated && truth {
                        rotated += 1;
                        rotated_inside += counts.inside;
                    }
                    let plain = without.intersects_in(Exact, &lp, &lq, &mut rng, &mut ws, &mut ());
                    assert_eq!(plain, truth, "{family:?} n = {n}, without the quadrilaterals");
                }
            }
        }
    }
    assert!(
        rotated_inside * 10 > rotated * 8,
        "{rotated_inside} of {rotated} intersecting Rotated queries answered by a vertex inside"
    );
}
