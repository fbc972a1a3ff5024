//! The thesis's variants of Barba and of Dobkin against the exact reference on every
//! generator family, touching and disjoint-by-an-ulp pairs included, both argument
//! orders and shifted start vertices; every certified call's certificate must pass
//! `verify`, and every variant stays within its iteration bound.
//!
//! - [`BarbaVariant`]: the thesis's first triangle, its finish on three edges of Q, the
//!   other order of the separating-line tests, and their combinations.
//! - [`DobkinVariant`]: ours (one cut per iteration in the compact form of the thesis's
//!   Code 3.2) and every pruning rule by its own `if` (Code 3.1).
//!
//! `POLYSECT_VARIANT_PAIRS` (default 300) sets the pairs per family.

use polysect::experiments::thesis::iteration_bound;
use polysect::generate::{self, Family, Relation};
use polysect::intersect::ArrayEngine;
use polysect::intersect::{
    Algorithm, ArrayIntersection, Barba, BarbaVariant, Dobkin, DobkinVariant, Iterations, Linear, verify,
};
use polysect::{ConvexPolygon, Exact};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const BARBA_SEED: u64 = 0x5eed_0ba4;
const DOBKIN_SEED: u64 = 0x5eed_d0b1;

fn pairs_per_family() -> usize {
    std::env::var("POLYSECT_VARIANT_PAIRS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(300)
}

/// Answer and certificate of one variant on (p, q) against the reference.
fn check_one<A: ArrayIntersection>(alg: &A, name: &str, p: &ConvexPolygon, q: &ConvexPolygon, what: &str) {
    let truth = Linear.intersects_with(Exact, p, q);
    assert_eq!(
        alg.intersects(p, q),
        truth,
        "{name} wrong on {what}\np = {p:?}\nq = {q:?}"
    );
    let c = alg.certified(p, q);
    assert_eq!(c.intersects(), truth, "{name} certified wrong on {what}");
    assert_eq!(verify(p, q, &c), Ok(()), "{name} certificate on {what}: {c:?}");
}

fn count<A: ArrayEngine>(alg: &A, p: &ConvexPolygon, q: &ConvexPolygon) -> u64 {
    let mut it = Iterations::default();
    alg.intersects_probed(Exact, p, q, &mut it);
    it.0
}

fn barba_variants(p: &ConvexPolygon, q: &ConvexPolygon, what: &str) {
    for (a, b) in [(p, q), (q, p)] {
        check_one(&BarbaVariant::<false, 7, false>, "halving", a, b, what);
        check_one(&BarbaVariant::<true, 7, false>, "thirds", a, b, what);
        check_one(&BarbaVariant::<false, 4, false>, "finish-on-3-edges", a, b, what);
        check_one(&BarbaVariant::<false, 7, true>, "p-edges-first", a, b, what);
        check_one(&BarbaVariant::<true, 4, true>, "thesis", a, b, what);
        check_one(&BarbaVariant::<true, 5, false>, "thirds-5", a, b, what);
    }
}

fn dobkin_variants(p: &ConvexPolygon, q: &ConvexPolygon, what: &str) {
    for (a, b) in [(p, q), (q, p)] {
        check_one(&DobkinVariant::<false>, "compact", a, b, what);
        check_one(&DobkinVariant::<true>, "lemma-by-lemma", a, b, what);
    }
}

/// `check` on `pairs_per_family()` pairs of every family: mostly small, one in ten up
/// to 4095 vertices, every relation, half of them with shifted start vertices.
fn on_every_family(seed: u64, check: fn(&ConvexPolygon, &ConvexPolygon, &str)) {
    let mut rng = SmallRng::seed_from_u64(seed);
    let per = pairs_per_family();
    for &family in Family::ALL {
        for i in 0..per {
            let n = if i % 10 == 0 {
                rng.random_range(3..4096)
            } else {
                rng.random_range(3..64)
            };
            let relation = [Relation::Any, Relation::Intersecting, Relation::Disjoint][i % 3];
            let (p, q) = generate::pair(family, n, relation, &mut rng);
            let (p, q) = if i % 2 == 0 {
                (
                    p.starting_at(rng.random_range(0..p.len())),
                    q.starting_at(rng.random_range(0..q.len())),
                )
            } else {
                (p, q)
            };
            check(&p, &q, &format!("{family} n={n} {relation:?} #{i}"));
        }
    }
}

/// `check` on small polygons, every size from 3: Barba's first triangle's thirds
/// coincide with neighbours, Dobkin's chains have one or two edges and the medians'
/// edges reach past both ends of the common y-interval, and no chain has an interior
/// vertex.
fn on_tiny_polygons(seed: u64, check: fn(&ConvexPolygon, &ConvexPolygon, &str)) {
    let mut rng = SmallRng::seed_from_u64(seed);
    for n in 3..12 {
        for &family in Family::TOUCHING {
            for i in 0..20 {
                let relation = [Relation::Intersecting, Relation::Disjoint][i % 2];
                let (p, q) = generate::pair(family, n, relation, &mut rng);
                check(&p, &q, &format!("{family} n={n} #{i}"));
            }
        }
    }
}

#[test]
fn barba_variants_agree_with_the_reference_on_every_family() {
    on_every_family(BARBA_SEED, barba_variants);
}

#[test]
fn barba_variants_on_tiny_polygons() {
    on_tiny_polygons(BARBA_SEED ^ 1, barba_variants);
}

#[test]
fn dobkin_variants_agree_with_the_reference_on_every_family() {
    on_every_family(DOBKIN_SEED, dobkin_variants);
}

#[test]
fn dobkin_variants_on_tiny_polygons() {
    on_tiny_polygons(DOBKIN_SEED ^ 1, dobkin_variants);
}

/// The variants stay logarithmic, and `Barba` is the variant with the thesis's first
/// triangle (the faster one on balance, docs/thesis.md).
#[test]
fn barba_variants_iterations_are_logarithmic() {
    let mut rng = SmallRng::seed_from_u64(BARBA_SEED ^ 2);
    for log in [8u32, 12, 16] {
        let n = 1usize << log;
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            let (p, q) = generate::pair(Family::Rotated, n, relation, &mut rng);
            let bound = 4 * u64::from(log) + 8;
            let mut it = Iterations::default();
            let ours = Barba.intersects_probed(Exact, &p, &q, &mut it);
            let mut it2 = Iterations::default();
            let same = BarbaVariant::<true, 7, false>.intersects_probed(Exact, &p, &q, &mut it2);
            assert_eq!((ours, it.0), (same, it2.0));
            for (name, iterations) in [
                ("halving", count(&BarbaVariant::<false, 7, false>, &p, &q)),
                ("thesis", count(&BarbaVariant::<true, 4, true>, &p, &q)),
            ] {
                assert!(iterations <= bound, "{name}: {iterations} iterations at n = {n}");
            }
        }
    }
}

/// `Dobkin` is the compact variant (same answers, same iterations), and both stay
/// within Dobkin's bound 2·log2 P + 2·log2 Q.
#[test]
fn dobkin_variants_iterations_within_the_bound() {
    let mut rng = SmallRng::seed_from_u64(DOBKIN_SEED ^ 2);
    let mut totals = [0u64; 2];
    for log in [8u32, 12, 16] {
        let n = 1usize << log;
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            let (p, q) = generate::pair(Family::Rotated, n, relation, &mut rng);
            let mut it = Iterations::default();
            let ours = Dobkin.intersects_probed(Exact, &p, &q, &mut it);
            let mut it2 = Iterations::default();
            let same = DobkinVariant::<false>.intersects_probed(Exact, &p, &q, &mut it2);
            assert_eq!((ours, it.0), (same, it2.0));
            let bound = iteration_bound(Algorithm::Dobkin, p.len(), q.len()).unwrap();
            assert!(it.0 as f64 <= bound, "compact: {} iterations at n = {n}", it.0);
            let every = count(&DobkinVariant::<true>, &p, &q);
            assert!(
                every as f64 <= bound,
                "lemma-by-lemma: {every} iterations at n = {n}, bound {bound}"
            );
            totals[0] += it.0;
            totals[1] += every;
        }
    }
    println!("iterations: compact {}, lemma-by-lemma {}", totals[0], totals[1]);
    // The variant takes its own path: it cuts both chains in some iteration.
    assert!(totals[1] < totals[0], "{totals:?}");
}
