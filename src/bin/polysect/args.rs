//! The command line's options and subcommands (clap), and the parsers of their values.

use clap::{Parser, Subcommand, ValueEnum};
use polysect::Precision;
use polysect::crossings::{CrossingAlgorithm, Touching};
use polysect::experiments::Experiment;
use polysect::generate::Family;
use polysect::generate::simple::SimpleMethod;
use polysect::intersect::Algorithm;
use polysect::polygon::HullAlgorithm;
use polysect::store::Strategy;
use std::net::IpAddr;
use std::path::PathBuf;

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
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) command: Option<Command>,
}

#[derive(Subcommand)]
pub(crate) enum Command {
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
    /// ({"op": "add"|"drop"|"insert"|"remove"|"move"|"translate"|"intersects"|"contact"|"pairs"|"vertices", ...}),
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
    /// Contact geometry of convex polygons, for JSON Lines pairs {"p": [[x,y],...], "q":
    /// [...]}: {"intersects": false, "distance": D, "closest": [[x,y],[x,y]]} or
    /// {"intersects": true, "depth": D, "normal": [nx,ny], "overlap": [[x,y],...], "area": A}
    /// per line, every number correctly rounded (null when it overflows).
    Contact {
        /// Input file (JSON Lines); standard input when absent or "-".
        file: Option<String>,
        /// Kernel of the decisions: exact or fast (constructed numbers are always
        /// correctly rounded from exact values).
        #[arg(long, default_value = "exact", value_parser = parse_precision)]
        precision: Precision,
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
        /// crossings and the ends of collinear overlaps.
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
pub(crate) const MAX_GEN_N: u64 = 1 << 24;

#[derive(Clone, Copy)]
pub(crate) enum AlgorithmArg {
    Auto,
    Named(Algorithm),
}

impl AlgorithmArg {
    pub(crate) fn resolve(self) -> Algorithm {
        match self {
            AlgorithmArg::Auto => Algorithm::fastest_array(),
            AlgorithmArg::Named(a) => a,
        }
    }
}

pub(crate) fn parse_algorithm(s: &str) -> Result<AlgorithmArg, String> {
    if s == "auto" {
        return Ok(AlgorithmArg::Auto);
    }
    s.parse::<Algorithm>()
        .map(AlgorithmArg::Named)
        .map_err(|e| e.replace("(valid: ", "(valid: auto, "))
}

pub(crate) fn parse_strategy(s: &str) -> Result<Strategy, String> {
    Strategy::ALL.into_iter().find(|t| t.name() == s).ok_or_else(|| {
        let names: Vec<&str> = Strategy::ALL.iter().map(|t| t.name()).collect();
        format!("unknown strategy '{s}' (valid: {})", names.join(", "))
    })
}

pub(crate) fn parse_crossing_algorithm(s: &str) -> Result<CrossingAlgorithm, String> {
    s.parse()
}

pub(crate) fn parse_touching(s: &str) -> Result<Touching, String> {
    s.parse()
}

pub(crate) fn parse_simple_method(s: &str) -> Result<SimpleMethod, String> {
    s.parse()
}

pub(crate) fn parse_hull_algorithm(s: &str) -> Result<HullAlgorithm, String> {
    s.parse()
}

pub(crate) fn parse_precision(s: &str) -> Result<Precision, String> {
    s.parse()
}

pub(crate) fn parse_experiment(s: &str) -> Result<Experiment, String> {
    s.parse()
}

pub(crate) fn parse_bind(s: &str) -> Result<IpAddr, String> {
    if s == "localhost" {
        return Ok(IpAddr::from([127, 0, 0, 1]));
    }
    s.parse()
        .map_err(|_| format!("'{s}' is not an IP address (e.g. 127.0.0.1, ::1, 0.0.0.0)"))
}

pub(crate) fn parse_family(s: &str) -> Result<Family, String> {
    s.parse()
}

/// An ellipse semi-axis: a number in [0.001, 1000] (narrower would let rounding make
/// every generated point collinear).
pub(crate) fn parse_axis(s: &str) -> Result<f64, String> {
    let v: f64 = s.parse().map_err(|_| format!("'{s}' is not a number"))?;
    if (1e-3..=1e3).contains(&v) {
        Ok(v)
    } else {
        Err(format!("{s} is outside [0.001, 1000]"))
    }
}

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum RelationArg {
    Any,
    Intersecting,
    Disjoint,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum ProtocolArg {
    Ours,
    Thesis,
}

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum OrderArg {
    Ccw,
    Cw,
    Random,
}
