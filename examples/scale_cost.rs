//! A driver for counting the instructions the exact kernel spends on validation plus
//! the crossings sweep of one random pair (n = 10,000 per polygon, the pair of
//! `benches/scales.rs`) with every coordinate multiplied by 2^KX (x) and 2^KY (y):
//! the pair is built and scaled first, then `rounds` runs of `SimplePolygon::new` on
//! both polygons and `Sweep` happen inside `run`, which is never inlined so that
//! callgrind can count it alone:
//!
//! ```text
//! cargo build --release --example scale_cost
//! valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*scale_cost*run*' \
//!     target/release/examples/scale_cost 600 600 1
//! ```
//!
//! Arguments: KX, KY (powers of two in [-1074, 1023]; the inputs lie in [0, 100)) and
//! the number of rounds. Prints the number of crossing points, so that scales can be
//! checked to give the same answer.

use polysect::crossings::{Crossings, Sweep};
use polysect::generate::simple::{PointDistribution, SimpleMethod, random_simple_polygon};
use polysect::{Point, SimplePolygon};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;

/// The seed and size of `benches/scales.rs`.
const SEED: u64 = 0x005c_a1e5;
const N: usize = 10_000;

/// Multiplies x by 2^kx and y by 2^ky, in two steps where one power is not normal.
fn scaled(points: &[Point], kx: i32, ky: i32) -> Vec<Point> {
    let f = |k: i32| (2f64.powi(k / 2), 2f64.powi(k - k / 2));
    let ((ax, bx), (ay, by)) = (f(kx), f(ky));
    points
        .iter()
        .map(|p| Point::new(p.x * ax * bx, p.y * ay * by))
        .collect()
}

#[inline(never)]
fn run(p: &[Point], q: &[Point], rounds: usize) -> usize {
    let mut count = 0;
    for _ in 0..rounds {
        let sp = SimplePolygon::new(black_box(p).iter().copied()).expect("a valid polygon");
        let sq = SimplePolygon::new(black_box(q).iter().copied()).expect("a valid polygon");
        count = Sweep.crossings(&sp, &sq).len();
    }
    count
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: scale_cost KX KY ROUNDS";
    let parse = |i: usize| args.get(i).and_then(|s| s.parse::<i64>().ok());
    let (Some(kx), Some(ky), Some(rounds)) = (parse(1), parse(2), parse(3)) else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let in_range = |k: i64| (-1074..=1023).contains(&k);
    if !in_range(kx) || !in_range(ky) || rounds < 1 {
        eprintln!("{usage}");
        std::process::exit(2);
    }
    let mut rng = SmallRng::seed_from_u64(SEED);
    let dist = PointDistribution::Uniform { min: 0.0, max: 100.0 };
    let method = SimpleMethod::SpacePartition;
    let p = random_simple_polygon(method, dist, N, &mut rng).expect("a polygon");
    let q = random_simple_polygon(method, dist, N, &mut rng).expect("a polygon");
    let (p, q) = (
        scaled(p.vertices(), kx as i32, ky as i32),
        scaled(q.vertices(), kx as i32, ky as i32),
    );
    let count = run(&p, &q, rounds as usize);
    println!("scale 2^{kx} x 2^{ky}: {count} crossing points");
}
