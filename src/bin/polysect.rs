//! The `polysect` command line: a thin layer over the library.

use clap::{Parser, Subcommand, ValueEnum};
use polysect::crossings::{CrossingAlgorithm, CrossingOptions, Touching};
use polysect::experiments::{self, Config, Experiment, ThesisConfig};
use polysect::generate::simple::{GenerateError, PointDistribution, SimpleMethod, random_simple_polygon};
use polysect::generate::{self, Family, Relation};
use polysect::intersect::Algorithm;
use polysect::polygon::HullAlgorithm;
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
        cannot be read, an unwritable output); 2 for a usage error (an unknown name, a \
        value out of range, options that do not fit together); 3 when `check \
        --verify-expected` found an answer that disagrees with its line's \"expected\"."
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Answer "do P and Q intersect?" for JSON Lines pairs {"p": [[x,y],...], "q": [...]}
    /// (closed polygons: touching counts).
    Check {
        /// Input file (JSON Lines); standard input when absent or "-".
        file: Option<String>,
        /// Algorithm: auto (= barba), linear, barba, dobkin, chazelle-dobkin, clm or convert.
        #[arg(long, default_value = "auto", value_parser = parse_algorithm)]
        algorithm: AlgorithmArg,
        /// Kernel of the predicates: exact (exact for every finite input) or fast
        /// (plain f64, may misjudge near-touching input).
        #[arg(long, default_value = "exact", value_parser = parse_precision)]
        precision: Precision,
        /// Seed (any unsigned 64-bit integer) of the sampled tests (clm, convert), for
        /// reproducible runs; from the operating system when absent.
        #[arg(long)]
        seed: Option<u64>,
        /// Compare each answer with the line's "expected" field (true or false, as
        /// `polysect gen` writes it): replies get "agrees": true|false, a line without
        /// "expected" is an error line, a summary goes to standard error, and the exit
        /// code is 3 when an answer disagrees.
        #[arg(long)]
        verify_expected: bool,
        /// Add to each answer a certificate that proves it, checkable exactly: a
        /// separating edge, a vertex inside, or two crossing edges (input vertices).
        #[arg(long, conflicts_with = "verify_expected")]
        certificate: bool,
    },
    /// Drive one scene of editable polygons with JSON Lines operations
    /// ({"op": "add"|"drop"|"insert"|"remove"|"move"|"translate"|"intersects"|"pairs"|"vertices", ...}),
    /// one reply line per input line.
    Scene {
        /// Input file (JSON Lines); standard input when absent or "-".
        file: Option<String>,
        /// How queries are answered: planner, sampled, convert or cached.
        #[arg(long, default_value = "planner", value_parser = parse_strategy)]
        strategy: Strategy,
        /// Kernel of the queries: exact or fast (edits are always validated exactly).
        #[arg(long, default_value = "exact", value_parser = parse_precision)]
        precision: Precision,
        /// Add a certificate to each `intersects` answer, as `check --certificate` does.
        #[arg(long)]
        certificate: bool,
        /// Seed (any unsigned 64-bit integer) of the sampled test; from the operating
        /// system when absent.
        #[arg(long)]
        seed: Option<u64>,
    },
    /// Report where the boundaries of simple polygons meet, for JSON Lines pairs
    /// {"p": [[x,y],...], "q": [...]}: writes {"points": [[x,y],...]} per line (a shared
    /// edge gives its two endpoints).
    ///
    /// The points are the distinct points where the two boundaries meet: proper
    /// crossings, touchings (a vertex on an edge, a shared vertex), and where edges
    /// overlap along a line, the two endpoints of each overlap (a shared edge gives its
    /// two endpoints, not the points between them).
    Crossings {
        /// Input file (JSON Lines); standard input when absent or "-".
        file: Option<String>,
        /// Algorithm: sweep (Žalik's sweep line) or brute (all edge pairs).
        #[arg(long, default_value = "sweep", value_parser = parse_crossing_algorithm)]
        algorithm: CrossingAlgorithm,
        /// Kernel of the predicates: exact or fast.
        #[arg(long, default_value = "exact", value_parser = parse_precision)]
        precision: Precision,
        /// include: every point where the boundaries meet; exclude: only proper
        /// crossings and the ends of collinear overlaps (the crossings report).
        #[arg(long, default_value = "include", value_parser = parse_touching)]
        touching: Touching,
    },
    /// Convex hull and farthest pair of point sets, for JSON Lines {"points": [[x,y],...]}:
    /// writes {"hull": [[x,y],...], "diameter": [[x,y],[x,y]]} per line (counter-clockwise
    /// from the lowest, then leftmost, vertex; one point gives [p] and [p, p], collinear
    /// points their two ends).
    Hull {
        /// Input file (JSON Lines); standard input when absent.
        file: Option<String>,
        /// Algorithm: graham (Graham's scan) or monotone (Andrew's monotone chain).
        #[arg(long, default_value = "monotone", value_parser = parse_hull_algorithm)]
        algorithm: HullAlgorithm,
    },
    /// Write generated pairs as JSON Lines in the `check` input format, or with
    /// `--simple` pairs of simple polygons in the `crossings` input format.
    Gen {
        /// Generator family: rotated, ellipse, non-uniform, shared-vertex,
        /// vertex-on-edge, shared-edge, overlapping-edges, nested or one-ulp-gap.
        #[arg(long, default_value = "rotated", value_parser = parse_family)]
        family: Family,
        /// Simple (possibly non-convex) polygons instead, joined by this method:
        /// space-partition, star or angular (around the set's lowest point).
        #[arg(long, value_parser = parse_simple_method, conflicts_with_all = ["family", "relation"])]
        simple: Option<SimpleMethod>,
        /// With --simple: coordinates uniform in [0, DELTA) (the default, Δ = 100).
        #[arg(long, requires = "simple", conflicts_with = "sigma")]
        delta: Option<f64>,
        /// With --simple: coordinates normal with mean 0 and standard deviation SIGMA.
        #[arg(long, requires = "simple")]
        sigma: Option<f64>,
        /// Vertices per polygon, 3 to 16777216 (about: ellipse hulls may drop a few,
        /// lattice families round to what their lattice allows).
        #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u64).range(3..=MAX_GEN_N))]
        n: u64,
        /// Number of pairs.
        #[arg(long, default_value_t = 10)]
        count: u64,
        /// Which answer the pairs get: any (the family's random placement),
        /// intersecting or disjoint.
        #[arg(long, value_enum, default_value_t = RelationArg::Any)]
        relation: RelationArg,
        /// Vertex order written: counter-clockwise, clockwise, or random per polygon.
        #[arg(long, value_enum, default_value_t = OrderArg::Ccw)]
        order: OrderArg,
        /// Seed (any unsigned 64-bit integer): the same seed writes the same pairs.
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
        /// trade, clm-factor, crossings.
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
        /// Output directory (created if missing).
        #[arg(long, default_value = "bench-out")]
        out: PathBuf,
        /// Seed (any unsigned 64-bit integer) of the generated inputs; a fixed default
        /// when absent.
        #[arg(long)]
        seed: Option<u64>,
        /// No progress bar.
        #[arg(long)]
        no_progress: bool,
    },
    /// List the algorithms, precisions and generator families.
    List,
    /// Run a scene of editable polygons through mixed edit/query workloads under every
    /// strategy, check every answer, and draw the scene as SVG (the default command).
    Demo {
        /// Polygons in the scene, 1 to 4096.
        #[arg(long, default_value_t = 48, value_parser = clap::value_parser!(u64).range(1..=4096))]
        polygons: u64,
        /// Largest polygon size, as a power of two, 3 to 24 (sizes are log-uniform
        /// from 2^3 to 2^MAX_LOG2).
        #[arg(long, default_value_t = 18, value_parser = clap::value_parser!(u32).range(3..=24))]
        max_log2: u32,
        /// Operations per workload, 1 to 10000000.
        #[arg(long, default_value_t = 1000, value_parser = clap::value_parser!(u64).range(1..=10_000_000))]
        steps: u64,
        /// Seed (any unsigned 64-bit integer) of the scene and the workloads.
        #[arg(long, default_value_t = 7)]
        seed: u64,
        /// Where to write the SVG picture of the scene: a .svg file, or a name without an
        /// extension such as /dev/null (the demo writes SVG only; a name ending in
        /// another extension is refused; convert with e.g. `rsvg-convert scene.svg -o
        /// scene.png`).
        #[arg(long, default_value = "polysect-demo.svg")]
        svg: String,
    },
    /// Draw JSON Lines pairs (the `check` input format) as SVG panels: convex pairs with
    /// their answer (q red when it intersects p, teal when not), other simple pairs with
    /// the points where their boundaries meet, invalid lines as error panels.
    Render {
        /// Input file (JSON Lines); standard input when absent or "-".
        file: Option<String>,
        /// Output file: a .svg file, a name without an extension, or "-" for standard
        /// output (render writes SVG only; a name ending in another extension is
        /// refused; convert with e.g. `rsvg-convert pairs.svg -o pairs.png`).
        #[arg(long, default_value = "polysect-pairs.svg")]
        out: String,
        /// At most this many pairs are drawn, 1 to 10000 (a warning says when the input
        /// has more).
        #[arg(long, default_value_t = 24, value_parser = clap::value_parser!(u64).range(1..=10_000))]
        limit: u64,
        /// Draw every pair as simple polygons with the points where their boundaries
        /// meet, convex pairs too.
        #[arg(long)]
        crossings: bool,
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

/// The largest `gen --n`: 2^24 vertices per polygon (about 1.5 GB while generating).
const MAX_GEN_N: u64 = 1 << 24;

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

fn parse_touching(s: &str) -> Result<Touching, String> {
    s.parse()
}

fn parse_simple_method(s: &str) -> Result<SimpleMethod, String> {
    s.parse()
}

fn parse_hull_algorithm(s: &str) -> Result<HullAlgorithm, String> {
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
    let result: Result<(), Failure> = match cli.command {
        None => demo_command(48, 18, 1000, 7, "polysect-demo.svg"),
        Some(Command::Check {
            file,
            algorithm,
            precision,
            seed,
            verify_expected,
            certificate,
        }) => check(
            file.as_deref(),
            algorithm.resolve(),
            precision,
            seed,
            verify_expected,
            certificate,
        ),
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
            scene(file.as_deref(), precision, options)
        }
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
        )
        .map_err(Failure::Io),
        Some(Command::Hull { file, algorithm }) => open_input(file.as_deref())
            .and_then(|input| protocol::hull::hull(input, output(), algorithm))
            .map_err(Failure::Io),
        Some(Command::Gen {
            simple: Some(method),
            delta,
            sigma,
            n,
            count,
            order,
            seed,
            ..
        }) => {
            let dist = match sigma {
                Some(sigma) => PointDistribution::Normal { mean: 0.0, sigma },
                None => PointDistribution::Uniform {
                    min: 0.0,
                    max: delta.unwrap_or(100.0),
                },
            };
            gen_simple(method, dist, n as usize, count as usize, order, seed)
        }
        Some(Command::Gen {
            family,
            n,
            count,
            relation,
            order,
            seed,
            a,
            b,
            ..
        }) => gen_pairs(family, n as usize, count, relation, order, seed, a.zip(b)).map_err(Failure::Io),
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
        }
        .map_err(Failure::Io),
        Some(Command::List) => list().map_err(Failure::Io),
        Some(Command::Demo {
            polygons,
            max_log2,
            steps,
            seed,
            svg,
        }) => demo_command(polygons as usize, max_log2, steps as usize, seed, &svg),
        Some(Command::Render {
            file,
            out,
            limit,
            crossings,
        }) => render(file.as_deref(), &out, limit as usize, crossings),
        Some(Command::Calibrate) => calibrate().map_err(Failure::Io),
        Some(Command::Serve { port, bind }) => serve(bind, port).map_err(Failure::Io),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // The reader closed the pipe: it has what it wanted; stop quietly.
        Err(Failure::Io(e)) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(Failure::Io(e)) => {
            let _ = writeln!(io::stderr(), "polysect: {e}");
            ExitCode::from(1)
        }
        Err(Failure::Usage { command, message }) => {
            let _ = writeln!(
                io::stderr(),
                "error: {message}\n\nFor more information, try 'polysect {command} --help'."
            );
            ExitCode::from(2)
        }
        Err(Failure::Disagreed(message)) => {
            let _ = writeln!(io::stderr(), "polysect: {message}");
            ExitCode::from(3)
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

/// Why a command failed, and so its exit code.
enum Failure {
    /// Exit 2: a usage error found after parsing (options that do not fit together,
    /// an output name render cannot write, a run that would not fit in memory).
    Usage { command: &'static str, message: String },
    /// Exit 1: input or output failed (0 when the reader closed the output pipe).
    Io(io::Error),
    /// Exit 3: `check --verify-expected` found answers that disagree with "expected".
    Disagreed(String),
}

impl From<io::Error> for Failure {
    fn from(e: io::Error) -> Self {
        Failure::Io(e)
    }
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
    verify_expected: bool,
    certificate: bool,
) -> Result<(), Failure> {
    let mut rng = match seed {
        Some(seed) => SmallRng::seed_from_u64(seed),
        None => SmallRng::from_rng(&mut rand::rng()),
    };
    if certificate {
        // Under the fast kernel a certificate is checked exactly before it is printed
        // (O(n + m), as reading the line) and replaced if it fails: every one verifies.
        return Ok(protocol::check::check_certified(
            open_input(file)?,
            output(),
            |p, q| {
                let certificate = algorithm.run_certified_rng(precision, p, q, &mut rng).0;
                match precision {
                    Precision::Exact => certificate,
                    Precision::Fast => polysect::intersect::proven(p, q, certificate),
                }
            },
        )?);
    }
    let answer = |p: &ConvexPolygon, q: &ConvexPolygon| algorithm.run_rng(precision, p, q, &mut rng).0;
    if !verify_expected {
        return Ok(protocol::check::check(open_input(file)?, output(), answer)?);
    }
    let tally = protocol::check::check_expected(open_input(file)?, output(), answer)?;
    let summary = format!(
        "{} answer(s) compared with \"expected\", {} disagree; {} line(s) without an answer",
        tally.compared, tally.disagreed, tally.errors
    );
    if tally.disagreed > 0 {
        return Err(Failure::Disagreed(summary));
    }
    let _ = writeln!(io::stderr(), "polysect: {summary}");
    Ok(())
}

fn scene(file: Option<&str>, precision: Precision, options: SceneOptions) -> Result<(), Failure> {
    match precision {
        Precision::Exact => run_session(SceneSession::with_kernel(Exact, options), file),
        Precision::Fast => run_session(SceneSession::with_kernel(Fast, options), file),
    }
}

fn run_session<K: Kernel>(mut session: SceneSession<K>, file: Option<&str>) -> Result<(), Failure> {
    let input = open_input(file).map_err(Failure::Io)?;
    session.run(input, output()).map_err(Failure::Io)
}

fn crossings(
    file: Option<&str>,
    algorithm: CrossingAlgorithm,
    precision: Precision,
    options: CrossingOptions,
) -> io::Result<()> {
    protocol::check::crossings(open_input(file)?, output(), |p, q| {
        algorithm.run_with_options(precision, p, q, options)
    })
}

fn gen_pairs(
    family: Family,
    n: usize,
    count: u64,
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
        let (p, q) = match axes {
            None => generate::try_pair(family, n, relation, &mut rng)
                .map_err(|e| io::Error::new(io::ErrorKind::InvalidInput, e))?,
            Some(_) => generate::pair_with_axes(family, n, relation, axes, &mut rng),
        };
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

/// Pairs of random simple polygons as `crossings` input lines. Parameters are checked
/// (as a usage error) before anything is written.
fn gen_simple(
    method: SimpleMethod,
    dist: PointDistribution,
    n: usize,
    count: usize,
    order: OrderArg,
    seed: u64,
) -> Result<(), Failure> {
    let mut rng = SmallRng::seed_from_u64(seed);
    let mut out = BufWriter::new(io::stdout().lock());
    let distribution = match dist {
        PointDistribution::Normal { sigma, .. } => format!("\"sigma\": {sigma:?}"),
        PointDistribution::Uniform { max, .. } => format!("\"delta\": {max:?}"),
        PointDistribution::Grid { size } => format!("\"grid\": {size}"),
    };
    for i in 0..count {
        let mut polygon = || match random_simple_polygon(method, dist, n, &mut rng) {
            Ok(p) => Ok(p),
            Err(e @ GenerateError::InvalidParameters(_)) => Err(Failure::Usage {
                command: "gen",
                message: e.to_string(),
            }),
            Err(e) => Err(Failure::Io(io::Error::other(e.to_string()))),
        };
        let (p, q) = (polygon()?, polygon()?);
        let mut write_order = |poly: &polysect::SimplePolygon| {
            let mut v = poly.vertices().to_vec();
            let reverse = match order {
                OrderArg::Ccw => false,
                OrderArg::Cw => true,
                OrderArg::Random => rand::Rng::random_bool(&mut rng, 0.5),
            };
            // Counter-clockwise first (exact), then the order asked for.
            if poly.is_ccw() == reverse {
                v.reverse();
            }
            protocol::points_json(&v)
        };
        let (pj, qj) = (write_order(&p), write_order(&q));
        writeln!(
            out,
            "{{\"id\": {i}, \"method\": \"{method}\", {distribution}, \"n\": {n}, \"p\": {pj}, \"q\": {qj}}}"
        )
        .map_err(Failure::Io)?;
    }
    out.flush().map_err(Failure::Io)
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
    let names: Vec<&str> = HullAlgorithm::ALL.iter().map(|a| a.name()).collect();
    writeln!(
        out,
        "hulls:      {} (default {})",
        names.join(", "),
        HullAlgorithm::default()
    )?;
    writeln!(out, "precisions: fast, exact (default)")?;
    let names: Vec<&str> = Strategy::ALL.iter().map(|s| s.name()).collect();
    writeln!(out, "strategies: {} (scene; default planner)", names.join(", "))?;
    let fams: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
    writeln!(out, "families:   {}", fams.join(", "))?;
    out.flush()
}

/// Checks, before any work, that `path` may receive SVG text: "-" (standard output), a
/// name ending in .svg, or one without an extension (`/dev/null`, `/dev/stdout`). A name
/// ending in another extension (`x.png`) would get SVG text under a false name.
fn svg_output(command: &'static str, option: &str, path: &str) -> Result<(), Failure> {
    let is_svg = path == "-"
        || std::path::Path::new(path)
            .extension()
            .is_none_or(|e| e.eq_ignore_ascii_case("svg"));
    if is_svg {
        return Ok(());
    }
    Err(Failure::Usage {
        command,
        message: format!(
            "{option} {path}: polysect writes SVG only; name a .svg file (or - for standard output) \
             and convert it, e.g. `rsvg-convert picture.svg -o picture.png`"
        ),
    })
}

fn write_svg(path: &str, svg: &str) -> io::Result<()> {
    if path == "-" {
        let mut out = io::stdout().lock();
        out.write_all(svg.as_bytes())?;
        return out.flush();
    }
    std::fs::write(path, svg).map_err(|e| io::Error::new(e.kind(), format!("cannot write {path}: {e}")))
}

fn render(file: Option<&str>, out_path: &str, limit: usize, crossings: bool) -> Result<(), Failure> {
    use polysect::render::{RenderMode, render_pairs};
    svg_output("render", "--out", out_path)?;
    let mode = if crossings {
        RenderMode::Crossings
    } else {
        RenderMode::Auto
    };
    let picture = render_pairs(open_input(file)?, mode, limit)?;
    write_svg(out_path, &picture.svg)?;
    let mut err = io::stderr().lock();
    if picture.more {
        let _ = writeln!(
            err,
            "polysect: render stopped at its limit of {limit} pairs; the rest of the input was not \
             read (--limit N draws more)"
        );
    }
    if out_path != "-" {
        let _ = writeln!(err, "wrote {} panel(s) to {out_path}", picture.drawn);
    }
    Ok(())
}

fn demo_command(polygons: usize, max_log2: u32, steps: usize, seed: u64, svg: &str) -> Result<(), Failure> {
    svg_output("demo", "--svg", svg)?;
    let need = demo::estimated_bytes(polygons, max_log2);
    if need > demo::MEMORY_LIMIT {
        return Err(Failure::Usage {
            command: "demo",
            message: format!(
                "--polygons {polygons} --max-log2 {max_log2} would need about {:.1} GB (polygons of up to \
                 2^{max_log2} vertices); the demo stops at {:.0} GB: lower either",
                need as f64 / 1e9,
                demo::MEMORY_LIMIT as f64 / 1e9
            ),
        });
    }
    Ok(demo::run(polygons, max_log2, steps, seed, svg)?)
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
    // Its errors name the file or directory that failed.
    let report = experiments::run(experiments, &config)?;
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
