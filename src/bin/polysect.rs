//! The `polysect` command line: a thin layer over the library.

use clap::{Parser, Subcommand, ValueEnum};
use polysect::crossings::CrossingAlgorithm;
use polysect::experiments::{self, Config, Experiment, ThesisConfig};
use polysect::generate::{self, Family, Relation};
use polysect::intersect::Algorithm;
use polysect::protocol::{self, scene::SceneOptions, scene::SceneSession};
use polysect::store::Strategy;
use polysect::{ConvexPolygon, Exact, Fast, Kernel, Precision};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::io::{self, BufWriter, Read, Write};
use std::net::IpAddr;
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
        Exit codes: 0 when every input line was answered (error lines included) or the \
        reader closed the output pipe early; 1 when input or output failed (a file that \
        cannot be read, an unwritable output); 2 for a usage error."
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
        /// Seed of the sampled tests (clm, convert); from the operating system when absent.
        #[arg(long)]
        seed: Option<u64>,
    },
    /// Drive one scene of editable polygons with JSON Lines operations
    /// ({"op": "add"|"drop"|"insert"|"remove"|"move"|"translate"|"intersects"|"pairs"|"vertices", ...}),
    /// one reply line per input line.
    Scene {
        /// Input file (JSON Lines); standard input when absent.
        file: Option<String>,
        /// How queries are answered: planner, sampled, convert or cached.
        #[arg(long, default_value = "planner", value_parser = parse_strategy)]
        strategy: Strategy,
        /// Kernel of the queries (edits are always validated exactly).
        #[arg(long, default_value = "exact", value_parser = parse_precision)]
        precision: Precision,
        /// Add a certificate to each `intersects` answer.
        #[arg(long)]
        certificate: bool,
        /// Seed of the sampled test; from the operating system when absent.
        #[arg(long)]
        seed: Option<u64>,
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
        /// Semi-axis a (along x before rotation) of the ellipse families' polygons, fixed
        /// instead of drawn from (0.05, 1] (thesis Figure 4.1: a = 1, b = 0.1).
        #[arg(long, value_parser = parse_axis, requires = "b")]
        a: Option<f64>,
        /// Semi-axis b (along y before rotation); given together with --a.
        #[arg(long, value_parser = parse_axis, requires = "a")]
        b: Option<f64>,
    },
    /// Measure the experiments (thesis ch. 4, the speed–accuracy trade) and write CSV
    /// files and SVG plots.
    Bench {
        /// Experiments to run (default: all): scaling, densities, sqrt, crossover,
        /// trade, clm-factor.
        #[arg(value_parser = parse_experiment)]
        experiments: Vec<Experiment>,
        /// Fewer sizes and shorter loops (under a minute).
        #[arg(long)]
        quick: bool,
        /// How pairs are placed and timed: `ours` (steered pairs, median of timed loops;
        /// runs the named experiments) or `thesis` (the thesis's chapter 4 as written:
        /// random translations sorted by outcome, 100 pairs × 1000 repetitions, mean and
        /// median, n = 2^4 … 2^22; runs experiments 1–5 together and takes no names).
        #[arg(long, value_enum, default_value_t = ProtocolArg::Ours)]
        protocol: ProtocolArg,
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
    /// Serve the live page: polygons moving, colliding and being edited in a scene.
    /// Prints the page's URL once listening; stops on Ctrl-C or SIGTERM.
    Serve {
        /// Port to listen on (0: any free port; the printed URL names it).
        #[arg(long, default_value_t = 8080)]
        port: u16,
        /// Address to listen on (loopback by default: the page is for this machine).
        #[arg(long, default_value = "127.0.0.1", value_parser = parse_bind)]
        bind: IpAddr,
    },
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

fn parse_strategy(s: &str) -> Result<Strategy, String> {
    Strategy::ALL.into_iter().find(|t| t.name() == s).ok_or_else(|| {
        let names: Vec<&str> = Strategy::ALL.iter().map(|t| t.name()).collect();
        format!("unknown strategy '{s}' (valid: {})", names.join(", "))
    })
}

fn parse_crossing_algorithm(s: &str) -> Result<CrossingAlgorithm, String> {
    s.parse()
}

fn parse_precision(s: &str) -> Result<Precision, String> {
    s.parse()
}

fn parse_experiment(s: &str) -> Result<Experiment, String> {
    s.parse()
}

fn parse_bind(s: &str) -> Result<IpAddr, String> {
    if s == "localhost" {
        return Ok(IpAddr::from([127, 0, 0, 1]));
    }
    s.parse()
        .map_err(|_| format!("'{s}' is not an IP address (e.g. 127.0.0.1, ::1, 0.0.0.0)"))
}

fn parse_family(s: &str) -> Result<Family, String> {
    s.parse()
}

/// An ellipse semi-axis: a number in [0.001, 1000] (narrower would let rounding make
/// every generated point collinear).
fn parse_axis(s: &str) -> Result<f64, String> {
    let v: f64 = s.parse().map_err(|_| format!("'{s}' is not a number"))?;
    if (1e-3..=1e3).contains(&v) {
        Ok(v)
    } else {
        Err(format!("{s} is outside [0.001, 1000]"))
    }
}

#[derive(Clone, Copy, ValueEnum)]
enum RelationArg {
    Any,
    Intersecting,
    Disjoint,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum ProtocolArg {
    Ours,
    Thesis,
}

#[derive(Clone, Copy, ValueEnum)]
enum OrderArg {
    Ccw,
    Cw,
    Random,
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_exit(e),
    };
    let result = match cli.command {
        None => demo::run(48, 18, 1000, 7, "polysect-demo.svg"),
        Some(Command::Check {
            file,
            algorithm,
            precision,
            seed,
        }) => check(file.as_deref(), algorithm.resolve(), precision, seed),
        Some(Command::Scene {
            file,
            strategy,
            precision,
            certificate,
            seed,
        }) => {
            let options = SceneOptions {
                strategy,
                seed,
                certificate,
            };
            match scene(file.as_deref(), precision, options) {
                Err(Failure::Usage(message)) => {
                    let _ = writeln!(
                        io::stderr(),
                        "error: {message}\n\nFor more information, try 'polysect scene --help'."
                    );
                    return ExitCode::from(2);
                }
                Err(Failure::Io(e)) => Err(e),
                Ok(()) => Ok(()),
            }
        }
        Some(Command::Crossings {
            file,
            algorithm,
            precision,
        }) => crossings(file.as_deref(), algorithm, precision),
        Some(Command::Gen {
            family,
            n,
            count,
            relation,
            order,
            seed,
            a,
            b,
        }) => gen_pairs(family, n, count, relation, order, seed, a.zip(b)),
        Some(Command::Bench {
            experiments,
            quick,
            protocol,
            out,
            seed,
            no_progress,
        }) => match protocol {
            ProtocolArg::Ours => bench(&experiments, quick, out, seed, !no_progress),
            ProtocolArg::Thesis => bench_thesis(&experiments, quick, out, seed, !no_progress),
        },
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
        Some(Command::Serve { port, bind }) => serve(bind, port),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // The reader closed the pipe: it has what it wanted; stop quietly.
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => {
            let _ = writeln!(io::stderr(), "polysect: {e}");
            ExitCode::from(1)
        }
    }
}

/// Prints clap's help, version or usage error: help and version go to standard output
/// (exit 0; 1 if it cannot be written), usage errors to standard error (exit 2).
fn clap_exit(e: clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
        let text = e.render().to_string();
        let mut out = io::stdout().lock();
        return match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
            Err(e) => {
                let _ = writeln!(io::stderr(), "polysect: cannot write the help: {e}");
                ExitCode::from(1)
            }
        };
    }
    let _ = e.print();
    ExitCode::from(2)
}

enum Failure {
    Usage(String),
    Io(io::Error),
}

fn open_input(file: Option<&str>) -> io::Result<Box<dyn Read>> {
    Ok(match file {
        None | Some("-") => Box::new(io::stdin().lock()),
        Some(path) => {
            let cannot = |e: io::Error| io::Error::new(e.kind(), format!("cannot read {path}: {e}"));
            let file = std::fs::File::open(path).map_err(cannot)?;
            Box::new(InputFile {
                path: path.to_string(),
                file,
            })
        }
    })
}

/// A file whose read errors name it.
struct InputFile {
    path: String,
    file: std::fs::File,
}

impl Read for InputFile {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        self.file
            .read(buf)
            .map_err(|e| io::Error::new(e.kind(), format!("cannot read {}: {e}", self.path)))
    }
}

/// Standard output, buffered; the protocols flush it whenever they would wait for input.
fn output() -> BufWriter<io::StdoutLock<'static>> {
    BufWriter::with_capacity(64 * 1024, io::stdout().lock())
}

fn check(
    file: Option<&str>,
    algorithm: Algorithm,
    precision: Precision,
    seed: Option<u64>,
) -> io::Result<()> {
    let mut rng = match seed {
        Some(seed) => SmallRng::seed_from_u64(seed),
        None => SmallRng::from_rng(&mut rand::rng()),
    };
    protocol::check::check(open_input(file)?, output(), |p, q| {
        algorithm.run_rng(precision, p, q, &mut rng).0
    })
}

fn scene(file: Option<&str>, precision: Precision, options: SceneOptions) -> Result<(), Failure> {
    match precision {
        Precision::Exact => run_session(SceneSession::with_kernel(Exact, options), file),
        Precision::Fast => run_session(SceneSession::with_kernel(Fast, options), file),
    }
}

/// Options are checked before the input is opened: a usage error comes first.
fn run_session<K: Kernel>(
    session: Result<SceneSession<K>, protocol::scene::OptionError>,
    file: Option<&str>,
) -> Result<(), Failure> {
    let mut session = session.map_err(|e| Failure::Usage(e.to_string()))?;
    let input = open_input(file).map_err(Failure::Io)?;
    session.run(input, output()).map_err(Failure::Io)
}

fn crossings(file: Option<&str>, algorithm: CrossingAlgorithm, precision: Precision) -> io::Result<()> {
    protocol::check::crossings(open_input(file)?, output(), |p, q| algorithm.run(precision, p, q))
}

fn gen_pairs(
    family: Family,
    n: usize,
    count: usize,
    relation: RelationArg,
    order: OrderArg,
    seed: u64,
    axes: Option<(f64, f64)>,
) -> io::Result<()> {
    if axes.is_some() && !matches!(family, Family::Ellipse | Family::Rotated | Family::NonUniform) {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("--a/--b apply to the ellipse families (ellipse, rotated, non-uniform), not to {family}"),
        ));
    }
    let mut rng = SmallRng::seed_from_u64(seed);
    let relation = match relation {
        RelationArg::Any => Relation::Any,
        RelationArg::Intersecting => Relation::Intersecting,
        RelationArg::Disjoint => Relation::Disjoint,
    };
    let mut out = BufWriter::new(io::stdout().lock());
    for i in 0..count {
        let (p, q) = generate::pair_with_axes(family, n, relation, axes, &mut rng);
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
            protocol::points_json(&v)
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
    let mut out = io::stdout().lock();
    let names: Vec<&str> = Algorithm::ALL.iter().map(|a| a.name()).collect();
    writeln!(
        out,
        "algorithms: auto (= {}), {}",
        Algorithm::fastest_array(),
        names.join(", ")
    )?;
    let names: Vec<&str> = CrossingAlgorithm::ALL.iter().map(|a| a.name()).collect();
    writeln!(
        out,
        "crossings:  {} (default {})",
        names.join(", "),
        CrossingAlgorithm::default()
    )?;
    writeln!(out, "precisions: fast, exact (default)")?;
    let names: Vec<&str> = Strategy::ALL.iter().map(|s| s.name()).collect();
    writeln!(out, "strategies: {} (scene; default planner)", names.join(", "))?;
    let fams: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
    writeln!(out, "families:   {}", fams.join(", "))?;
    out.flush()
}

fn render(file: Option<&str>, out_path: &str, limit: usize) -> io::Result<()> {
    use polysect::render::{Panel, Style, svg};
    let mut panels = Vec::new();
    protocol::check::for_each_pair(open_input(file)?, |line_no, pair| {
        if panels.len() >= limit {
            return false;
        }
        let panel = match pair {
            Ok((p, q)) => {
                let hit = Algorithm::Linear.intersects(Precision::Exact, &p, &q);
                let style = if hit { Style::Highlight } else { Style::Other };
                Panel {
                    polygons: vec![(p.into_vertices(), Style::Plain), (q.into_vertices(), style)],
                    caption: format!("line {line_no}: {}", if hit { "intersect" } else { "disjoint" }),
                }
            }
            Err(message) => Panel {
                polygons: vec![],
                caption: format!(
                    "line {line_no}: error: {}",
                    message
                        .split_once(": ")
                        .map_or(message.as_str(), |(_, m)| m)
                        .chars()
                        .take(40)
                        .collect::<String>()
                ),
            },
        };
        panels.push(panel);
        panels.len() < limit
    })?;
    std::fs::write(out_path, svg(&panels, 4))
        .map_err(|e| io::Error::new(e.kind(), format!("cannot write {out_path}: {e}")))?;
    let _ = writeln!(io::stderr(), "wrote {} panel(s) to {out_path}", panels.len());
    Ok(())
}

/// Listens, prints the URL, and serves until SIGINT or SIGTERM (then exits with 0).
fn serve(bind: IpAddr, port: u16) -> io::Result<()> {
    let server = polysect::serve::Server::bind(bind, port)?;
    let (done, finished) = std::sync::mpsc::channel::<io::Result<()>>();
    let stop = done.clone();
    ctrlc::set_handler(move || {
        let _ = stop.send(Ok(()));
    })
    .map_err(io::Error::other)?;
    let url = server.url();
    std::thread::spawn(move || {
        let why = server
            .run()
            .and(Err(io::Error::other("the server stopped accepting connections")));
        let _ = done.send(why);
    });
    let mut out = io::stdout().lock();
    writeln!(out, "{url}")?;
    out.flush()?;
    drop(out);
    finished.recv().unwrap_or(Ok(()))
}

fn calibrate() -> io::Result<()> {
    let _ = writeln!(
        io::stderr(),
        "measuring conversion and sampled-query costs (a few seconds)..."
    );
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

/// `bench --protocol thesis`: the thesis's chapter 4 protocol (see
/// `polysect::experiments::thesis`).
fn bench_thesis(
    experiments: &[Experiment],
    quick: bool,
    out: PathBuf,
    seed: Option<u64>,
    progress: bool,
) -> io::Result<()> {
    if !experiments.is_empty() {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            "--protocol thesis runs the thesis's experiments 1-5 together and takes no experiment names",
        ));
    }
    let mut config = if quick {
        ThesisConfig::quick(out)
    } else {
        ThesisConfig::full(out)
    };
    if let Some(seed) = seed {
        config.seed = seed;
    }
    config.progress = progress;
    let start = Instant::now();
    let report = experiments::thesis::run(&config)
        .map_err(|e| io::Error::new(e.kind(), format!("cannot write to {}: {e}", config.out.display())))?;
    let mut out = io::stdout().lock();
    writeln!(out, "{}", report.summary)?;
    writeln!(
        out,
        "wrote {} files to {} in {:.1} s",
        report.files.len(),
        config.out.display(),
        start.elapsed().as_secs_f64()
    )?;
    out.flush()
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
    let report = experiments::run(experiments, &config)
        .map_err(|e| io::Error::new(e.kind(), format!("cannot write to {}: {e}", config.out.display())))?;
    let mut out = io::stdout().lock();
    writeln!(out, "{}", report.summary)?;
    writeln!(
        out,
        "wrote {} files to {} in {:.1} s",
        report.files.len(),
        config.out.display(),
        start.elapsed().as_secs_f64()
    )?;
    out.flush()
}
