//! Measured experiments: the thesis's experiments 1–5 (chapter 4), the
//! conversion-versus-sampling crossover, the speed–accuracy trade of the kernels and
//! the effect of CLM's sample factor, written as CSV files and SVG plots. The
//! `polysect bench` subcommand is a thin front end to [`run`].
//!
//! | [`Experiment`] | what | thesis | files |
//! |---|---|---|---|
//! | `scaling` | time and iterations per query against n, every algorithm, intersecting and disjoint pairs, on unrotated ellipses (experiment 1) and on rotated ellipses with a random start index (experiment 3) | 4.2.1–4.2.3, Figs. 4.2, 4.3, 4.7 | `scaling.csv`, `time_raw_*.svg`, `time_log_*.svg`, `time_sqrt_*.svg`, `iterations_*.svg`, `intersecting_vs_disjoint.svg` |
//! | `densities` | the O(log n) tests on uniform against non-uniform (piecewise-linear) angle densities | 4.2.4 | `densities.csv`, `densities.svg` |
//! | `sqrt` | CLM's time divided by √n | 4.3.1, Fig. 4.6 | `clm_sqrt.csv`, `clm_sqrt.svg` |
//! | `crossover` | CLM against Convert (walk the lists, then Barba) on linked polygons, and the n from which sampling wins | 4.4, Fig. 4.8 | `crossover.csv`, `crossover.svg` |
//! | `trade` | every algorithm × kernel on adversarial families: time per query and wrong answers against [`Linear`](crate::intersect::Linear) under the exact kernel; the exact kernel's overhead (exact/fast time) per algorithm on random rotated ellipses at [`Config::ratio_log2_sizes`] | | `trade.csv`, `trade_ratio.csv`, `trade.md`, `trade.svg` |
//! | `clm-factor` | CLM's time against its sample factor c (samples of ⌈c·√n⌉) | | `clm_factor.csv`, `clm_factor.svg` |
//! | `crossings` | crossing points of two random simple polygons: the sweep and three brute forces against n, for every Δ and σ of the report in docs/crossings.md | that report's figure and its uniform and normal tables | `crossings.csv`, `crossings_uniform.svg`, `crossings_normal.svg`, `crossings_ratios.svg` |
//!
//! # Sizes
//! n is the number of vertices of *each* polygon (the thesis's figures use the total,
//! size(P) + size(Q) = 2n). Ellipse polygons are convex hulls of n random points on an
//! ellipse, so they may have a few vertices fewer.
//!
//! # Measurement
//! For each point of a curve, [`Config::pairs`] generated pairs; for each pair the query
//! runs in a timed loop, in batches that double until [`Config::min_time`] has passed,
//! three times; the pair's time per query is the median of the three, and the point's
//! time is the median over the pairs (not the mean: a shared machine's interruptions
//! only ever add time). Answers go through [`std::hint::black_box`]; each answer is
//! checked against the exact [`Linear`](crate::intersect::Linear) before timing, and
//! iteration counts come from an untimed run with an
//! [`Iterations`](crate::intersect::Iterations) probe. Clm and Convert run on linked
//! polygons built once per pair in shuffled arena order, with a workspace and an RNG
//! reused across queries, so their times exclude the linking.
//!
//! Timings are wall-clock on whatever else the machine runs: compare curves of one run,
//! not absolute numbers across machines.

mod clm_factor;
pub mod crossings;
mod crossover;
mod densities;
pub mod measure;
pub mod plot;
mod query;
mod scaling;
mod sqrt;
pub mod thesis;
mod thesis_figures;
mod trade;

pub use query::{Kernels, PreparedPair};
pub use thesis::ThesisConfig;
pub use thesis_figures::{TRACE_FIGURES, trace_svg, write_trace_figures};
pub use trade::needle_pair;

use indicatif::{ProgressBar, ProgressStyle};
use std::fmt;
use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::str::FromStr;
use std::time::Duration;

/// One experiment; see the module table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Experiment {
    Scaling,
    Densities,
    Sqrt,
    Crossover,
    Trade,
    ClmFactor,
    Crossings,
}

impl Experiment {
    pub const ALL: &'static [Experiment] = &[
        Experiment::Scaling,
        Experiment::Densities,
        Experiment::Sqrt,
        Experiment::Crossover,
        Experiment::Trade,
        Experiment::ClmFactor,
        Experiment::Crossings,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Experiment::Scaling => "scaling",
            Experiment::Densities => "densities",
            Experiment::Sqrt => "sqrt",
            Experiment::Crossover => "crossover",
            Experiment::Trade => "trade",
            Experiment::ClmFactor => "clm-factor",
            Experiment::Crossings => "crossings",
        }
    }
}

impl fmt::Display for Experiment {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Experiment {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Experiment::ALL
            .iter()
            .copied()
            .find(|e| e.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = Experiment::ALL.iter().map(|e| e.name()).collect();
                format!("unknown experiment '{s}' (valid: {})", names.join(", "))
            })
    }
}

/// How much to measure. [`Config::full`] and [`Config::quick`] are the CLI's presets;
/// the fields are public for smaller runs (tests).
#[derive(Clone, Debug)]
pub struct Config {
    /// Where CSV and SVG files go (created if missing).
    pub out: PathBuf,
    /// Seed of every generator; a seed reproduces the inputs exactly.
    pub seed: u64,
    /// log2 of the sizes n (vertices per polygon) of the scaling curves.
    pub log2_sizes: Vec<u32>,
    /// log2 of the sizes of the crossover curve (finer around the crossover).
    pub crossover_log2_sizes: Vec<f64>,
    /// Pairs per point for n ≤ 2^16 (fewer, [`Config::large_pairs`], above).
    pub pairs: usize,
    /// Pairs per point for n > 2^16.
    pub large_pairs: usize,
    /// Minimum time of one timed loop.
    pub min_time: Duration,
    /// Vertices of the polygons of the trade experiment's random families.
    pub trade_n: usize,
    /// Pairs per family in the trade experiment.
    pub trade_pairs: usize,
    /// log2 of the big circle's size in the trade experiment (the issue asks for 20).
    pub trade_circle_log2: u32,
    /// log2 of the sizes at which the trade experiment measures the exact kernel's
    /// overhead (exact time / fast time) on random rotated ellipses.
    pub ratio_log2_sizes: Vec<u32>,
    /// Sizes and factors of the CLM sample-factor experiment.
    pub factor_log2_sizes: Vec<u32>,
    pub factors: Vec<f64>,
    /// Vertices per polygon (n = m) of the crossings experiment.
    pub crossings_sizes: Vec<usize>,
    /// Polygon pairs per point of the crossings experiment.
    pub crossings_pairs: usize,
    /// Show a progress bar on standard error.
    pub progress: bool,
}

impl Config {
    /// The full run (about 10 minutes on 2 cores): n = 2^4 … 2^20.
    pub fn full(out: impl Into<PathBuf>) -> Config {
        Config {
            out: out.into(),
            seed: 0x7e5_0175,
            log2_sizes: (4..=20).collect(),
            crossover_log2_sizes: (12..=32).map(|h| h as f64 / 2.0).collect(),
            pairs: 10,
            large_pairs: 4,
            min_time: Duration::from_millis(8),
            trade_n: 256,
            trade_pairs: 40,
            trade_circle_log2: 20,
            ratio_log2_sizes: vec![10, 14, 18],
            factor_log2_sizes: vec![12, 16, 18, 20],
            factors: vec![0.5, 0.71, 1.0, 1.41, 2.0, 2.83],
            crossings_sizes: crossings::SEED_SIZES.to_vec(),
            crossings_pairs: 5,
            progress: true,
        }
    }

    /// The quick run (under a minute): n = 2^4 … 2^18 in steps of 2, fewer pairs,
    /// shorter loops, a 2^16-vertex circle in the trade experiment.
    pub fn quick(out: impl Into<PathBuf>) -> Config {
        Config {
            log2_sizes: vec![4, 6, 8, 10, 12, 14, 16, 18],
            crossover_log2_sizes: (6..=14).map(|h| h as f64).collect(),
            pairs: 3,
            large_pairs: 2,
            min_time: Duration::from_millis(2),
            trade_pairs: 8,
            trade_circle_log2: 16,
            factor_log2_sizes: vec![10, 14],
            factors: vec![0.5, 1.0, 2.0],
            crossings_sizes: vec![5, 50, 200, 1000],
            crossings_pairs: 2,
            ..Config::full(out)
        }
    }

    /// Pairs for size n.
    pub fn pairs_for(&self, n: usize) -> usize {
        if n > 1 << 16 { self.large_pairs } else { self.pairs }.max(1)
    }
}

/// What an experiment wrote.
#[derive(Clone, Debug, Default)]
pub struct Report {
    /// Files written, relative to [`Config::out`].
    pub files: Vec<String>,
    /// Markdown tables and one-line findings to print.
    pub summary: String,
}

/// Runs `experiments` in order, writing into `config.out`.
///
/// # Errors
/// When the output directory or a file cannot be written.
pub fn run(experiments: &[Experiment], config: &Config) -> io::Result<Report> {
    fs::create_dir_all(&config.out).map_err(naming(&config.out, "cannot create the directory"))?;
    let mut report = Report::default();
    for &e in experiments {
        let r = match e {
            Experiment::Scaling => scaling::run(config)?,
            Experiment::Densities => densities::run(config)?,
            Experiment::Sqrt => sqrt::run(config)?,
            Experiment::Crossover => crossover::run(config)?,
            Experiment::Trade => trade::run(config)?,
            Experiment::ClmFactor => clm_factor::run(config)?,
            Experiment::Crossings => crossings::run(config)?,
        };
        report.files.extend(r.files);
        report.summary.push_str(&format!("## {e}\n\n{}\n", r.summary));
    }
    Ok(report)
}

/// A progress bar of `len` steps labelled `name` (hidden when progress is off).
pub(crate) fn progress(config: &Config, name: &str, len: usize) -> ProgressBar {
    progress_bar(config.progress, name, len)
}

/// A progress bar of `len` steps labelled `name`, hidden unless `show`.
pub(crate) fn progress_bar(show: bool, name: &str, len: usize) -> ProgressBar {
    if !show {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(len as u64);
    bar.set_style(
        ProgressStyle::with_template("{prefix:>11} [{elapsed_precise}] {wide_bar} {pos}/{len} {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    bar.set_prefix(name.to_string());
    bar
}

/// A CSV file under construction: a header, then rows of already formatted fields.
pub(crate) struct Csv {
    text: String,
    columns: usize,
}

impl Csv {
    pub(crate) fn new(header: &[&str]) -> Csv {
        Csv {
            text: header.join(",") + "\n",
            columns: header.len(),
        }
    }

    pub(crate) fn row(&mut self, fields: &[String]) {
        debug_assert_eq!(fields.len(), self.columns);
        self.text.push_str(&fields.join(","));
        self.text.push('\n');
    }

    pub(crate) fn write(&self, dir: &Path, name: &str, report: &mut Report) -> io::Result<()> {
        let path = dir.join(name);
        fs::write(&path, &self.text).map_err(naming(&path, "cannot write"))?;
        report.files.push(name.to_string());
        Ok(())
    }
}

/// Adds the path to an I/O error: `cannot write out/x.csv: No space left on device`.
pub(crate) fn naming(path: &Path, what: &'static str) -> impl FnOnce(io::Error) -> io::Error {
    let path = path.display().to_string();
    move |e| io::Error::new(e.kind(), format!("{what} {path}: {e}"))
}

/// Formats a time in nanoseconds with 4 significant digits.
pub(crate) fn ns(t: f64) -> String {
    format!("{t:.4}")
}
