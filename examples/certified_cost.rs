//! The cost of the certified calls beside the plain ones, for instruction counters:
//! `certified_cost ALGORITHM plain|certified intersecting|disjoint LOG2 QUERIES` runs
//! QUERIES queries of one kind on 32 Rotated pairs of 2^LOG2 vertices per polygon
//! (cycled, exact kernel). Count with e.g. `perf stat -e instructions` and subtract a
//! run with 0 queries (the setup): docs/certificates.md, "Cost". ALGORITHM is an
//! algorithm's name or one of Barba's variants (docs/thesis.md): `barba-halving` (first
//! triangle at first/middle/last), `barba-thirds` (= `barba`), and with the halving
//! triangle `barba-finish3` (finish on three edges of Q) and `barba-p-edges-first`;
//! `barba-thesis` has all three of the thesis's choices. `dobkin-lemmas` is Dobkin's
//! variant with every pruning rule by its own `if` (the thesis's Code 3.1 form),
//! `dobkin-compact` ours (= `dobkin`). `clm` runs CLM on the pairs as linked polygons
//! in shuffled arena order (one workspace, one seeded generator, as in the `clm` bench).

use polysect::generate::{self, Family, Relation};
use polysect::intersect::{
    Algorithm, ArrayIntersection, Barba, BarbaVariant, ChazelleDobkin, Clm, ClmWorkspace, Dobkin,
    DobkinVariant, Linear, LinkedIntersection,
};
use polysect::{ConvexPolygon, Exact, LinkedPolygon};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: certified_cost ALGORITHM plain|certified intersecting|disjoint LOG2 QUERIES";
    let [alg, mode, relation, log2, queries] = args.as_slice() else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let variant = match alg.as_str() {
        "barba-thirds" => Some(0),
        "barba-finish3" => Some(1),
        "barba-p-edges-first" => Some(2),
        "barba-thesis" => Some(3),
        "barba-halving" => Some(4),
        "dobkin-compact" => Some(5),
        "dobkin-lemmas" => Some(6),
        _ => None,
    };
    let alg: Algorithm = if variant.is_some() {
        Algorithm::Barba
    } else {
        alg.parse().unwrap_or_else(|e| {
            eprintln!("{e}");
            std::process::exit(2)
        })
    };
    let want = match relation.as_str() {
        "intersecting" => true,
        "disjoint" => false,
        _ => {
            eprintln!("{usage}");
            std::process::exit(2)
        }
    };
    let (Ok(log2), Ok(queries)) = (log2.parse::<u32>(), queries.parse::<usize>()) else {
        eprintln!("{usage}");
        std::process::exit(2)
    };
    let certified = mode == "certified";
    let rel = if want {
        Relation::Intersecting
    } else {
        Relation::Disjoint
    };
    let mut rng = SmallRng::seed_from_u64(0xce47);
    let pairs: Vec<(ConvexPolygon, ConvexPolygon)> = (0..32)
        .map(|_| {
            loop {
                let (p, q) = generate::pair(Family::Rotated, 1 << log2, rel, &mut rng);
                if Linear.intersects(&p, &q) == want {
                    break (p, q);
                }
            }
        })
        .collect();
    if alg == Algorithm::Clm {
        // CLM on linked polygons in shuffled arena order (as in the `clm` bench), one
        // workspace and one seeded generator for the whole run.
        let linked: Vec<(LinkedPolygon, LinkedPolygon)> = pairs
            .iter()
            .map(|(p, q)| {
                (
                    LinkedPolygon::from_convex_shuffled(p, &mut rng),
                    LinkedPolygon::from_convex_shuffled(q, &mut rng),
                )
            })
            .collect();
        let mut ws = ClmWorkspace::default();
        let mut hits = 0usize;
        for i in 0..queries {
            let (p, q) = &linked[i % linked.len()];
            let (p, q) = (black_box(p), black_box(q));
            let hit = if certified {
                Clm.certified_with_workspace(Exact, p, q, &mut rng, &mut ws)
                    .intersects()
            } else {
                Clm.intersects_with_workspace(Exact, p, q, &mut rng, &mut ws)
            };
            hits += usize::from(hit == want);
        }
        assert_eq!(hits, queries, "a wrong answer");
        return;
    }
    let mut hits = 0usize;
    for i in 0..queries {
        let (p, q) = &pairs[i % pairs.len()];
        let (p, q) = (black_box(p), black_box(q));
        let hit = match (variant, certified) {
            (Some(0), false) => BarbaVariant::<true, 7, false>.intersects_with(Exact, p, q),
            (Some(0), true) => BarbaVariant::<true, 7, false>
                .certified_with(Exact, p, q)
                .intersects(),
            (Some(1), false) => BarbaVariant::<false, 4, false>.intersects_with(Exact, p, q),
            (Some(1), true) => BarbaVariant::<false, 4, false>
                .certified_with(Exact, p, q)
                .intersects(),
            (Some(2), false) => BarbaVariant::<false, 7, true>.intersects_with(Exact, p, q),
            (Some(2), true) => BarbaVariant::<false, 7, true>
                .certified_with(Exact, p, q)
                .intersects(),
            (Some(4), false) => BarbaVariant::<false, 7, false>.intersects_with(Exact, p, q),
            (Some(4), true) => BarbaVariant::<false, 7, false>
                .certified_with(Exact, p, q)
                .intersects(),
            (Some(5), false) => DobkinVariant::<false>.intersects_with(Exact, p, q),
            (Some(5), true) => DobkinVariant::<false>.certified_with(Exact, p, q).intersects(),
            (Some(6), false) => DobkinVariant::<true>.intersects_with(Exact, p, q),
            (Some(6), true) => DobkinVariant::<true>.certified_with(Exact, p, q).intersects(),
            (Some(_), false) => BarbaVariant::<true, 4, true>.intersects_with(Exact, p, q),
            (Some(_), true) => BarbaVariant::<true, 4, true>
                .certified_with(Exact, p, q)
                .intersects(),
            (None, _) => match (alg, certified) {
                (Algorithm::Barba, false) => Barba.intersects_with(Exact, p, q),
                (Algorithm::Barba, true) => Barba.certified_with(Exact, p, q).intersects(),
                (Algorithm::Dobkin, false) => Dobkin.intersects_with(Exact, p, q),
                (Algorithm::Dobkin, true) => Dobkin.certified_with(Exact, p, q).intersects(),
                (Algorithm::ChazelleDobkin, false) => ChazelleDobkin.intersects_with(Exact, p, q),
                (Algorithm::ChazelleDobkin, true) => ChazelleDobkin.certified_with(Exact, p, q).intersects(),
                (Algorithm::Linear, false) => Linear.intersects_with(Exact, p, q),
                (Algorithm::Linear, true) => Linear.certified_with(Exact, p, q).intersects(),
                (other, true) => other.certified_with(Exact, p, q).intersects(),
                (other, false) => other.intersects_with(Exact, p, q),
            },
        };
        hits += usize::from(hit == want);
    }
    assert_eq!(hits, queries, "a wrong answer");
}
