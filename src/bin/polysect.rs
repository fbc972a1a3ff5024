//! The `polysect` command line: a thin layer over the library.

use clap::{Parser, Subcommand, ValueEnum};
use polysect::crossings::{CrossingAlgorithm, CrossingOptions, Touching};
use polysect::experiments::{self, Config, Experiment};
use polysect::generate::{self, Family, Relation};
use polysect::intersect::Algorithm;
use polysect::jsonl;
use polysect::{ConvexPolygon, Precision};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::io::{self, BufRead, BufWriter, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

mod demo;

#[derive(Parser)]
#[command(
    name = "polysect",
    version,
    about = "Dynamic convex polygons with sublinear intersection queries",
    long_about = "Dynamic convex polygons with sublinear intersection queries.\n\n\
        Exit codes: 0 when every input line was answered (error lines included), \
        1 when input or output failed (a file that cannot be read, a closed pipe), \
        2 for a usage error."
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Answer "do P and Q intersect?" for JSON Lines pairs {"p": [[x,y],...], "q": [...]}.
    Check {
        /// Input file (JSON Lines); standard input when absent.
        file: Option<String>,
        /// Algorithm: auto, or one of the names `polysect list` prints.
        #[arg(long, default_value = "auto", value_parser = parse_algorithm)]
        algorithm: AlgorithmArg,
        #[arg(long, default_value = "exact", value_parser = parse_precision)]
        precision: Precision,
    },
    /// Report where the boundaries of simple polygons meet, for JSON Lines pairs
    /// {"p": [[x,y],...], "q": [...]}: writes {"points": [[x,y],...]} per line.
    Crossings {
        /// Input file (JSON Lines); standard input when absent.
        file: Option<String>,
        /// Algorithm: sweep (Žalik's sweep line) or brute (all edge pairs).
        #[arg(long, default_value = "sweep", value_parser = parse_crossing_algorithm)]
        algorithm: CrossingAlgorithm,
        #[arg(long, default_value = "exact", value_parser = parse_precision)]
        precision: Precision,
        /// include: every point where the boundaries meet; exclude: only proper
        /// crossings and the ends of collinear overlaps (seed 003).
        #[arg(long, default_value = "include", value_parser = parse_touching)]
        touching: Touching,
    },
    /// Write generated pairs as JSON Lines in the `check` input format.
    Gen {
        /// Generator family.
        #[arg(long, default_value = "rotated", value_parser = parse_family)]
        family: Family,
        /// Vertices per polygon (about; ellipse hulls may drop a few).
        #[arg(long, default_value_t = 16)]
        n: usize,
        /// Number of pairs.
        #[arg(long, default_value_t = 10)]
        count: usize,
        #[arg(long, value_enum, default_value_t = RelationArg::Any)]
        relation: RelationArg,
        /// Vertex order written: counter-clockwise, clockwise, or random per polygon.
        #[arg(long, value_enum, default_value_t = OrderArg::Ccw)]
        order: OrderArg,
        #[arg(long, default_value_t = 1)]
        seed: u64,
    },
    /// Measure the experiments (thesis ch. 4, the speed–accuracy trade) and write CSV
    /// files and SVG plots.
    Bench {
        /// Experiments to run (default: all): scaling, densities, sqrt, crossover,
        /// trade, clm-factor, crossings.
        #[arg(value_parser = parse_experiment)]
        experiments: Vec<Experiment>,
        /// Fewer sizes and shorter loops (under a minute).
        #[arg(long)]
        quick: bool,
        /// Output directory.
        #[arg(long, default_value = "bench-out")]
        out: PathBuf,
        /// Seed of the generated inputs.
        #[arg(long)]
        seed: Option<u64>,
        /// No progress bar.
        #[arg(long)]
        no_progress: bool,
    },
    /// List the algorithms, precisions and generator families.
    List,
    /// Run a scene of editable polygons through mixed edit/query workloads under every
    /// strategy, check every answer, and draw a small scene as SVG (the default command).
    Demo {
        /// Polygons in the scene.
        #[arg(long, default_value_t = 48)]
        polygons: usize,
        /// Largest polygon size, as a power of two (sizes are log-uniform from 2^3).
        #[arg(long, default_value_t = 18)]
        max_log2: u32,
        /// Operations per workload.
        #[arg(long, default_value_t = 1000)]
        steps: usize,
        #[arg(long, default_value_t = 7)]
        seed: u64,
        /// Where to write the SVG picture of a small scene.
        #[arg(long, default_value = "polysect-demo.svg")]
        svg: String,
    },
    /// Draw JSON Lines pairs (the `check` input format) as SVG panels with their answers.
    Render {
        /// Input file (JSON Lines); standard input when absent.
        file: Option<String>,
        /// Output SVG file.
        #[arg(long, default_value = "polysect-pairs.svg")]
        out: String,
        /// At most this many pairs are drawn.
        #[arg(long, default_value_t = 24)]
        limit: usize,
    },
    /// Measure the planner's cost model (conversion vs sampling crossover) on this machine.
    Calibrate,
}

#[derive(Clone, Copy)]
enum AlgorithmArg {
    Auto,
    Named(Algorithm),
}

impl AlgorithmArg {
    fn resolve(self) -> Algorithm {
        match self {
            AlgorithmArg::Auto => Algorithm::fastest_array(),
            AlgorithmArg::Named(a) => a,
        }
    }
}

fn parse_algorithm(s: &str) -> Result<AlgorithmArg, String> {
    if s == "auto" {
        return Ok(AlgorithmArg::Auto);
    }
    s.parse::<Algorithm>()
        .map(AlgorithmArg::Named)
        .map_err(|e| e.replace("(valid: ", "(valid: auto, "))
}

fn parse_crossing_algorithm(s: &str) -> Result<CrossingAlgorithm, String> {
    s.parse()
}

fn parse_touching(s: &str) -> Result<Touching, String> {
    s.parse()
}

fn parse_precision(s: &str) -> Result<Precision, String> {
    s.parse()
}

fn parse_experiment(s: &str) -> Result<Experiment, String> {
    s.parse()
}

fn parse_family(s: &str) -> Result<Family, String> {
    s.parse()
}

#[derive(Clone, Copy, ValueEnum)]
enum RelationArg {
    Any,
    Intersecting,
    Disjoint,
}

#[derive(Clone, Copy, ValueEnum)]
enum OrderArg {
    Ccw,
    Cw,
    Random,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => demo::run(48, 18, 1000, 7, "polysect-demo.svg"),
        Some(Command::Check {
            file,
            algorithm,
            precision,
        }) => check(file.as_deref(), algorithm.resolve(), precision),
        Some(Command::Crossings {
            file,
            algorithm,
            precision,
            touching,
        }) => crossings(
            file.as_deref(),
            algorithm,
            precision,
            CrossingOptions { touching },
        ),
        Some(Command::Gen {
            family,
            n,
            count,
            relation,
            order,
            seed,
        }) => gen_pairs(family, n, count, relation, order, seed),
        Some(Command::Bench {
            experiments,
            quick,
            out,
            seed,
            no_progress,
        }) => bench(&experiments, quick, out, seed, !no_progress),
        Some(Command::List) => list(),
        Some(Command::Demo {
            polygons,
            max_log2,
            steps,
            seed,
            svg,
        }) => demo::run(polygons, max_log2, steps, seed, &svg),
        Some(Command::Render { file, out, limit }) => render(file.as_deref(), &out, limit),
        Some(Command::Calibrate) => calibrate(),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("polysect: {e}");
            ExitCode::from(1)
        }
    }
}

fn open_input(file: Option<&str>) -> io::Result<Box<dyn BufRead>> {
    Ok(match file {
        None | Some("-") => Box::new(io::stdin().lock()),
        Some(path) => {
            let f = std::fs::File::open(path)
                .map_err(|e| io::Error::new(e.kind(), format!("cannot read {path}: {e}")))?;
            Box::new(io::BufReader::new(f))
        }
    })
}

/// Reads lines as bytes (invalid UTF-8 becomes an error line, not a crash) and calls
/// `answer` on each, without its line terminator.
fn for_each_line(input: &mut dyn BufRead, mut answer: impl FnMut(&[u8]) -> io::Result<()>) -> io::Result<()> {
    let mut buf = Vec::new();
    loop {
        buf.clear();
        if input.read_until(b'\n', &mut buf)? == 0 {
            return Ok(());
        }
        let mut line = buf.as_slice();
        if let Some(rest) = line.strip_suffix(b"\n") {
            line = rest;
        }
        if let Some(rest) = line.strip_suffix(b"\r") {
            line = rest;
        }
        answer(line)?;
    }
}

fn check(file: Option<&str>, algorithm: Algorithm, precision: Precision) -> io::Result<()> {
    let mut input = open_input(file)?;
    let mut out = BufWriter::new(io::stdout().lock());
    for_each_line(&mut input, |line| {
        let reply = jsonl::check_line(line, |p, q| algorithm.intersects(precision, p, q));
        writeln!(out, "{reply}")
    })?;
    out.flush()
}

fn crossings(
    file: Option<&str>,
    algorithm: CrossingAlgorithm,
    precision: Precision,
    options: CrossingOptions,
) -> io::Result<()> {
    let mut input = open_input(file)?;
    let mut out = BufWriter::new(io::stdout().lock());
    for_each_line(&mut input, |line| {
        let reply = jsonl::crossings_line(line, |p, q| algorithm.run_with_options(precision, p, q, options));
        writeln!(out, "{reply}")
    })?;
    out.flush()
}

fn gen_pairs(
    family: Family,
    n: usize,
    count: usize,
    relation: RelationArg,
    order: OrderArg,
    seed: u64,
) -> io::Result<()> {
    let mut rng = SmallRng::seed_from_u64(seed);
    let relation = match relation {
        RelationArg::Any => Relation::Any,
        RelationArg::Intersecting => Relation::Intersecting,
        RelationArg::Disjoint => Relation::Disjoint,
    };
    let mut out = BufWriter::new(io::stdout().lock());
    for i in 0..count {
        let (p, q) = generate::pair(family, n, relation, &mut rng);
        let expected = Algorithm::Linear.intersects(Precision::Exact, &p, &q);
        let mut write_order = |poly: &ConvexPolygon| {
            let mut v = poly.vertices().to_vec();
            let reverse = match order {
                OrderArg::Ccw => false,
                OrderArg::Cw => true,
                OrderArg::Random => rand::Rng::random_bool(&mut rng, 0.5),
            };
            if reverse {
                v.reverse();
            }
            jsonl::points_json(&v)
        };
        let (pj, qj) = (write_order(&p), write_order(&q));
        writeln!(
            out,
            "{{\"id\": {i}, \"family\": \"{family}\", \"n\": {n}, \"expected\": {expected}, \"p\": {pj}, \"q\": {qj}}}"
        )?;
    }
    out.flush()
}

fn list() -> io::Result<()> {
    let names: Vec<&str> = Algorithm::ALL.iter().map(|a| a.name()).collect();
    println!(
        "algorithms: auto (= {}), {}",
        Algorithm::fastest_array(),
        names.join(", ")
    );
    let names: Vec<&str> = CrossingAlgorithm::ALL.iter().map(|a| a.name()).collect();
    println!(
        "crossings:  {} (default {})",
        names.join(", "),
        CrossingAlgorithm::default()
    );
    println!("precisions: fast, exact (default)");
    let fams: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
    println!("families:   {}", fams.join(", "));
    Ok(())
}

fn render(file: Option<&str>, out_path: &str, limit: usize) -> io::Result<()> {
    use polysect::render::{Panel, Style, svg};
    let mut input = open_input(file)?;
    let mut panels = Vec::new();
    let mut line_no = 0;
    for_each_line(&mut input, |line| {
        line_no += 1;
        if panels.len() >= limit {
            return Ok(());
        }
        let panel = match jsonl::parse_pair(line).and_then(|pair| jsonl::convex_pair(&pair)) {
            Ok((p, q)) => {
                let hit = Algorithm::Linear.intersects(Precision::Exact, &p, &q);
                let style = if hit { Style::Highlight } else { Style::Other };
                Panel {
                    polygons: vec![(p.into_vertices(), Style::Plain), (q.into_vertices(), style)],
                    caption: format!("line {line_no}: {}", if hit { "intersect" } else { "disjoint" }),
                }
            }
            Err(e) => Panel {
                polygons: vec![],
                caption: format!(
                    "line {line_no}: error: {}",
                    e.message.chars().take(40).collect::<String>()
                ),
            },
        };
        panels.push(panel);
        Ok(())
    })?;
    std::fs::write(out_path, svg(&panels, 4))
        .map_err(|e| io::Error::new(e.kind(), format!("cannot write {out_path}: {e}")))?;
    eprintln!("wrote {} panel(s) to {out_path}", panels.len());
    Ok(())
}

fn calibrate() -> io::Result<()> {
    eprintln!("measuring conversion and sampled-query costs (a few seconds)...");
    let costs = polysect::store::CostModel::calibrate(polysect::Exact);
    let mut out = io::stdout().lock();
    writeln!(
        out,
        "{}",
        serde_json::to_string_pretty(&costs).expect("serialisable")
    )?;
    writeln!(
        out,
        "Polygons of at most {} vertices are converted at once; larger ones after their sampled\n\
         queries since the last edit cost as much as converting them ({:.1} ns/vertex vs {:.1} ns·√n per query).",
        costs.crossover, costs.convert_ns_per_vertex, costs.sampled_ns_per_sqrt_n
    )
}

fn bench(
    experiments: &[Experiment],
    quick: bool,
    out: PathBuf,
    seed: Option<u64>,
    progress: bool,
) -> io::Result<()> {
    let mut config = if quick {
        Config::quick(out)
    } else {
        Config::full(out)
    };
    if let Some(seed) = seed {
        config.seed = seed;
    }
    config.progress = progress;
    let experiments = if experiments.is_empty() {
        Experiment::ALL
    } else {
        experiments
    };
    let start = Instant::now();
    let report = experiments::run(experiments, &config)?;
    println!("{}", report.summary);
    println!(
        "wrote {} files to {} in {:.1} s",
        report.files.len(),
        config.out.display(),
        start.elapsed().as_secs_f64()
    );
    Ok(())
}
