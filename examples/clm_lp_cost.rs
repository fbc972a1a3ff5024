//! CLM's LP cost per constraint, for instruction counters and profilers:
//! `clm_lp_cost intersecting|disjoint LOG2 QUERIES [walk|lp]` runs QUERIES CLM queries
//! (exact kernel, default variant; with `lp` the chain-against-chain LPs by the LP, not
//! the walk) on 16 Rotated pairs of 2^LOG2 vertices per polygon in
//! shuffled arena order, cycled, and prints the wall time per query (timed pass), and
//! the LPs' constraints, examined points and walked chain vertices per query (a
//! separate counted pass over the same queries). Count instructions with `valgrind
//! --tool=callgrind` (both passes run: 2 × QUERIES queries) and subtract a run with 0
//! queries (the setup): docs/results.md, "The LP's cost per constraint".

use polysect::generate::{self, Family, Relation};
use polysect::intersect::LinkedEngine;
use polysect::intersect::{ArrayIntersection, ClmVariant, ClmWorkspace, Counts, Linear, LinkedIntersection};
use polysect::{Exact, LinkedPolygon};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: clm_lp_cost intersecting|disjoint LOG2 QUERIES [walk|lp]";
    let (relation, log2, queries, chain_walk) = match args.as_slice() {
        [r, l, q] => (r, l, q, true),
        [r, l, q, m] if m == "walk" || m == "lp" => (r, l, q, m == "walk"),
        _ => {
            eprintln!("{usage}");
            std::process::exit(2);
        }
    };
    let clm = ClmVariant {
        chain_walk,
        ..ClmVariant::default()
    };
    let (want, rel) = match relation.as_str() {
        "intersecting" => (true, Relation::Intersecting),
        "disjoint" => (false, Relation::Disjoint),
        _ => {
            eprintln!("{usage}");
            std::process::exit(2)
        }
    };
    let (Ok(log2), Ok(queries)) = (log2.parse::<u32>(), queries.parse::<usize>()) else {
        eprintln!("{usage}");
        std::process::exit(2)
    };
    let mut rng = SmallRng::seed_from_u64(0x1c05);
    let pairs: Vec<(LinkedPolygon, LinkedPolygon)> = (0..16)
        .map(|_| {
            loop {
                let (p, q) = generate::pair(Family::Rotated, 1 << log2, rel, &mut rng);
                if Linear.intersects(&p, &q) == want {
                    break (
                        LinkedPolygon::from_convex_shuffled(&p, &mut rng),
                        LinkedPolygon::from_convex_shuffled(&q, &mut rng),
                    );
                }
            }
        })
        .collect();
    // The LP's counts over the same queries and seeds, in a separate pass.
    let mut counts = Counts::default();
    let mut ws = ClmWorkspace::default();
    let mut qrng = SmallRng::seed_from_u64(7);
    for i in 0..queries {
        let (p, q) = &pairs[i % pairs.len()];
        let hit = clm.intersects_in(Exact, p, q, &mut qrng, &mut ws, &mut counts);
        assert_eq!(hit, want);
    }
    let mut qrng = SmallRng::seed_from_u64(7);
    let start = Instant::now();
    let mut hits = 0usize;
    for i in 0..queries {
        let (p, q) = &pairs[i % pairs.len()];
        hits +=
            usize::from(clm.intersects_with_workspace(Exact, black_box(p), black_box(q), &mut qrng, &mut ws));
    }
    let secs = start.elapsed().as_secs_f64();
    let per = |x: u64| x as f64 / queries.max(1) as f64;
    let ns = secs * 1e9 / queries.max(1) as f64;
    let constraints = per(counts.lp_constraints() as u64);
    println!(
        "{queries} queries, {hits} intersecting; {ns:.0} ns/query; per query: {:.2} LPs, {constraints:.0} constraints, {:.0} examined, {:.0} walked; {:.2} examined/constraint",
        per(counts.lp_calls() as u64),
        per(counts.lp_work()),
        per(counts.chain_steps() as u64),
        counts.lp_work() as f64 / counts.lp_constraints().max(1) as f64,
    );
}
