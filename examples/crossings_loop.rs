//! Runs one crossings algorithm in a loop on one generated pair, for CPU-time
//! measurements that survive a loaded machine (docs/crossings.md):
//!
//! ```text
//! cargo build --release --example crossings_loop
//! perf stat -e task-clock target/release/examples/crossings_loop uniform 2000 brute 0
//! perf stat -e task-clock target/release/examples/crossings_loop uniform 2000 brute 20
//! ```
//!
//! The difference of the two task-clock figures divided by the count (20) is the CPU
//! time of one query (the first run measures the set-up: generating the pair).
//!
//! Arguments: the family (`uniform`: space partitioning of uniform points in
//! [0, 100)²; `normal`: normal points, σ = 50; or a `polysect::generate::hard` family
//! name), n, the algorithm (`sweep`, `list`, `tree`, `brute`, `division` and
//! `division-sweep` (the brute force and sweep of docs/crossings.md's report), `geo` (geo's sweep over both
//! edge sets)) and the count. The pair comes from a fixed seed per n. Prints the
//! number of points, the lists' work and which sweep `Sweep` chose, on standard error.
//!
//! The algorithm `json` instead writes the pair COUNT times as `polysect crossings`
//! input lines on standard output, to time the command line on the same pairs:
//!
//! ```text
//! target/release/examples/crossings_loop needles 16000 json 1 > needles16k.jsonl
//! target/release/polysect crossings needles16k.jsonl
//! ```

use geo::algorithm::sweep::{Cross, Intersections};
use polysect::crossings::ListWorkspace;
use polysect::crossings::{Brute, Crossings, ListSweep, Sweep, SweepWorkspace, TreeSweep};
use polysect::experiments::crossings::{division_brute, division_sweep};
use polysect::generate::hard::{HardFamily, hard_pair};
use polysect::generate::simple::{PointDistribution, SimpleMethod, random_simple_polygon};
use polysect::{Exact, SimplePolygon};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;
use std::process::ExitCode;

#[derive(Clone, Debug)]
struct Tagged {
    line: geo::Line<f64>,
    poly: u8,
}

impl Cross for Tagged {
    type Scalar = f64;
    fn line(&self) -> geo::Line<f64> {
        self.line
    }
}

fn tagged(p: &SimplePolygon, poly: u8) -> impl Iterator<Item = Tagged> + '_ {
    (0..p.len()).map(move |i| {
        let (a, b) = p.edge(i);
        Tagged {
            line: geo::Line::new(geo::coord! { x: a.x, y: a.y }, geo::coord! { x: b.x, y: b.y }),
            poly,
        }
    })
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    let [_, family, n, alg, count] = args.as_slice() else {
        eprintln!("usage: crossings_loop FAMILY N ALGORITHM COUNT");
        return ExitCode::from(2);
    };
    let (Ok(n), Ok(count)) = (n.parse::<usize>(), count.parse::<usize>()) else {
        eprintln!("N and COUNT are integers");
        return ExitCode::from(2);
    };
    let mut rng = SmallRng::seed_from_u64(2027 + n as u64);
    let random = |dist, rng: &mut SmallRng| {
        let mut one =
            || random_simple_polygon(SimpleMethod::SpacePartition, dist, n, rng).expect("a polygon");
        (one(), one())
    };
    let (p, q) = match family.as_str() {
        "uniform" => random(PointDistribution::Uniform { min: 0.0, max: 100.0 }, &mut rng),
        "normal" => random(
            PointDistribution::Normal {
                mean: 0.0,
                sigma: 50.0,
            },
            &mut rng,
        ),
        other => match other.parse::<HardFamily>() {
            Ok(f) => hard_pair(f, n, &mut rng),
            Err(e) => {
                eprintln!("{e}");
                return ExitCode::from(2);
            }
        },
    };
    if alg == "json" {
        let ring = |p: &SimplePolygon| {
            let v: Vec<String> = p
                .vertices()
                .iter()
                .map(|v| format!("[{:?},{:?}]", v.x, v.y))
                .collect();
            format!("[{}]", v.join(","))
        };
        let line = format!("{{\"p\": {}, \"q\": {}}}", ring(&p), ring(&q));
        for _ in 0..count {
            println!("{line}");
        }
        return ExitCode::SUCCESS;
    }
    let edges: Vec<Tagged> = tagged(&p, 0).chain(tagged(&q, 1)).collect();
    let (mut ws, mut lists, mut events, mut out) = (
        SweepWorkspace::default(),
        ListWorkspace::default(),
        Vec::new(),
        Vec::new(),
    );
    let mut found = 0;
    for _ in 0..count {
        let (p, q) = (black_box(&p), black_box(&q));
        found = match alg.as_str() {
            "sweep" => {
                Sweep.crossings_in(Exact, p, q, &mut ws, &mut out);
                out.len()
            }
            "list" => ListSweep.crossings_with(Exact, p, q).len(),
            "tree" => TreeSweep.crossings_with(Exact, p, q).len(),
            "brute" => Brute.crossings_with(Exact, p, q).len(),
            "division" => {
                division_brute(p, q, &mut out);
                out.len()
            }
            "division-sweep" => {
                division_sweep(p, q, &mut events, &mut lists, &mut out);
                out.len()
            }
            "geo" => Intersections::from_iter(edges.iter())
                .filter(|(a, b, _)| a.poly != b.poly)
                .count(),
            other => {
                eprintln!("unknown algorithm {other}");
                return ExitCode::from(2);
            }
        };
    }
    let work = ListSweep::work(&p, &q);
    eprintln!(
        "{family} n = {} + {}: {alg} found {found}; lists: {} candidates, {} tests; sweep runs {}",
        p.len(),
        q.len(),
        work.candidates,
        work.tests,
        Sweep::choice(&p, &q)
    );
    ExitCode::SUCCESS
}
