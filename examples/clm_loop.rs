//! CLM's time per query on a few pairs, each pair's arenas queried alone (as
//! `polysect bench sqrt` does per pair), for comparing builds run in turn.
//!
//! `cargo run --release --example clm_loop -- LOG2 SECONDS [FACTOR] [i]`: 4 Rotated
//! pairs of 2^LOG2 vertices each, disjoint (or intersecting with `i`), arenas
//! shuffled; each pair queried with sample factor FACTOR (default 1) for SECONDS in five
//! slices; prints each pair's median slice (µs per query) and the median over the
//! pairs. Every answer is checked against the linear test's.

use polysect::generate::{self, Family, Relation};
use polysect::intersect::LinkedEngine;
use polysect::intersect::{ArrayIntersection, ClmWithFactor, ClmWorkspace, Linear};
use polysect::{Exact, LinkedPolygon};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let log2: u32 = args.first().and_then(|s| s.parse().ok()).unwrap_or(18);
    let secs: f64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(0.3);
    let c: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1.0);
    let rel = if args.get(3).map(|s| s.as_str()) == Some("i") {
        Relation::Intersecting
    } else {
        Relation::Disjoint
    };
    let want = rel == Relation::Intersecting;
    let mut rng = SmallRng::seed_from_u64(11);
    let mut ws = ClmWorkspace::default();
    let mut all = Vec::new();
    for _ in 0..4 {
        let (p, q) = loop {
            let (p, q) = generate::pair(Family::Rotated, 1 << log2, rel, &mut rng);
            if Linear.intersects(&p, &q) == want {
                break (p, q);
            }
        };
        let lp = LinkedPolygon::from_convex_shuffled(&p, &mut rng);
        let lq = LinkedPolygon::from_convex_shuffled(&q, &mut rng);
        drop((p, q));
        let mut meds = Vec::new();
        for _ in 0..5 {
            let t = Instant::now();
            let mut k = 0u64;
            while t.elapsed().as_secs_f64() < secs / 5.0 {
                for _ in 0..16 {
                    assert_eq!(
                        ClmWithFactor(c).intersects_in(Exact, &lp, &lq, &mut rng, &mut ws, &mut ()),
                        want
                    );
                }
                k += 16;
            }
            meds.push(t.elapsed().as_secs_f64() * 1e9 / k as f64);
        }
        meds.sort_by(f64::total_cmp);
        all.push(meds[2]);
    }
    let mut s = all.clone();
    s.sort_by(f64::total_cmp);
    println!(
        "2^{log2} c={c} per pair us: {:?} median {:.1}",
        all.iter().map(|x| (x / 100.0).round() / 10.0).collect::<Vec<_>>(),
        (s[1] + s[2]) / 2000.0
    );
}
