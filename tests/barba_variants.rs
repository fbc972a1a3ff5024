//! Every [`BarbaVariant`] (the thesis's first triangle, its finish on three edges of Q,
//! the other order of the separating-line tests, and their combinations) against the
//! exact reference on every generator family, touching and disjoint-by-an-ulp pairs
//! included, both argument orders and shifted start vertices; the certified call's
//! certificate must pass `verify`. `POLYSECT_VARIANT_PAIRS` (default 300) sets the
//! pairs per family.

use polysect::generate::{self, Family, Relation};
use polysect::intersect::{ArrayIntersection, Barba, BarbaVariant, Iterations, Linear, verify};
use polysect::{ConvexPolygon, Exact};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

const SEED: u64 = 0x5eed_0ba4;

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

fn count<A: ArrayIntersection>(alg: &A, p: &ConvexPolygon, q: &ConvexPolygon) -> u64 {
    let mut it = Iterations::default();
    alg.intersects_probed(Exact, p, q, &mut it);
    it.0
}

fn check_all(p: &ConvexPolygon, q: &ConvexPolygon, what: &str) {
    for (a, b) in [(p, q), (q, p)] {
        check_one(&BarbaVariant::<false, 7, false>, "halving", a, b, what);
        check_one(&BarbaVariant::<true, 7, false>, "thirds", a, b, what);
        check_one(&BarbaVariant::<false, 4, false>, "finish-on-3-edges", a, b, what);
        check_one(&BarbaVariant::<false, 7, true>, "p-edges-first", a, b, what);
        check_one(&BarbaVariant::<true, 4, true>, "thesis", a, b, what);
        check_one(&BarbaVariant::<true, 5, false>, "thirds-5", a, b, what);
    }
}

#[test]
fn variants_agree_with_the_reference_on_every_family() {
    let mut rng = SmallRng::seed_from_u64(SEED);
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
                    p.rotated(rng.random_range(0..p.len())),
                    q.rotated(rng.random_range(0..q.len())),
                )
            } else {
                (p, q)
            };
            check_all(&p, &q, &format!("{family} n={n} {relation:?} #{i}"));
        }
    }
}

/// Small polygons: every size from 3, where the first triangle's thirds coincide with
/// neighbours and chains have no interior vertex.
#[test]
fn variants_on_tiny_polygons() {
    let mut rng = SmallRng::seed_from_u64(SEED ^ 1);
    for n in 3..12 {
        for &family in Family::TOUCHING {
            for i in 0..20 {
                let relation = [Relation::Intersecting, Relation::Disjoint][i % 2];
                let (p, q) = generate::pair(family, n, relation, &mut rng);
                check_all(&p, &q, &format!("{family} n={n} #{i}"));
            }
        }
    }
}

/// The variants stay logarithmic, and `Barba` is the variant with the thesis's first
/// triangle (the faster one on balance, docs/thesis.md).
#[test]
fn variants_iterations_are_logarithmic() {
    let mut rng = SmallRng::seed_from_u64(SEED ^ 2);
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
