//! A driver for counting the instructions one algorithm spends per query under one
//! kernel: random rotated ellipses (the `rotated` family, any relation), prepared once,
//! then `queries` queries cycling over the pairs inside `run_queries`, which is never
//! inlined so that callgrind can count it alone:
//!
//! ```text
//! cargo build --release --example kernel_overhead
//! valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*run_queries*' \
//!     target/release/examples/kernel_overhead barba exact 18 16 20000
//! ```
//!
//! Arguments: algorithm, precision (`fast` | `exact`), log2 of n, number of pairs,
//! number of queries. It prints the number of intersecting answers, so the two kernels
//! can be checked to agree. With the precision `both` it times instead: eleven rounds,
//! each running the queries under the fast kernel and then under the exact one, and
//! prints the median time per query of each, the median of the rounds' ratios, and
//! the ratio of the fastest rounds.

use polysect::Precision;
use polysect::experiments::PreparedPair;
use polysect::generate::{self, Family, Relation};
use polysect::intersect::Algorithm;
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;
use std::time::Instant;

const ROUNDS: usize = 11;

#[inline(never)]
fn run_queries(pairs: &mut [PreparedPair], alg: Algorithm, precision: Precision, queries: usize) -> usize {
    let mut hits = 0;
    for i in 0..queries {
        let k = i % pairs.len();
        hits += usize::from(black_box(&mut pairs[k]).query(alg, precision));
    }
    hits
}

fn main() {
    let mut args: Vec<String> = std::env::args().collect();
    let timed = args.get(2).is_some_and(|a| a == "both");
    if timed {
        args[2] = "exact".into();
    }
    let usage = "usage: kernel_overhead ALGORITHM fast|exact|both LOG2_N PAIRS QUERIES";
    if args.len() != 6 {
        eprintln!("{usage}");
        std::process::exit(2);
    }
    let parse = || -> Result<(Algorithm, Precision, u32, usize, usize), String> {
        Ok((
            args[1].parse()?,
            args[2].parse()?,
            args[3].parse().map_err(|e| format!("{e}"))?,
            args[4].parse().map_err(|e| format!("{e}"))?,
            args[5].parse().map_err(|e| format!("{e}"))?,
        ))
    };
    let (alg, precision, log2, count, queries) = parse().unwrap_or_else(|e| {
        eprintln!("{e}\n{usage}");
        std::process::exit(2)
    });
    let mut rng = SmallRng::seed_from_u64(0x0e4e_4ead);
    let mut pairs: Vec<PreparedPair> = (0..count.max(1))
        .map(|i| {
            let (p, q) = generate::pair(Family::Rotated, 1 << log2, Relation::Any, &mut rng);
            PreparedPair::new(p, q, i as u64)
        })
        .collect();
    let truth = pairs.iter().filter(|p| p.truth).count();
    if timed {
        let mut time = |precision| {
            let start = Instant::now();
            black_box(run_queries(&mut pairs, alg, precision, queries));
            start.elapsed().as_secs_f64() * 1e9 / queries as f64
        };
        let (mut fast, mut exact, mut ratio) = (vec![], vec![], vec![]);
        for _ in 0..ROUNDS {
            let f = time(Precision::Fast);
            let e = time(Precision::Exact);
            fast.push(f);
            exact.push(e);
            ratio.push(e / f);
        }
        let median = |v: &mut Vec<f64>| {
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        let (f, e, r) = (median(&mut fast), median(&mut exact), median(&mut ratio));
        println!(
            "{alg} n=2^{log2}: fast {f:.1} ns, exact {e:.1} ns, exact/fast {r:.3} (rounds {:.3}..{:.3}; fastest {:.3})",
            ratio[0],
            ratio[ROUNDS - 1],
            exact[0] / fast[0],
        );
        return;
    }
    let hits = run_queries(&mut pairs, alg, precision, queries);
    println!(
        "{alg} {precision} n=2^{log2}: {hits} intersecting of {queries} queries ({truth} of {count} pairs)"
    );
}
