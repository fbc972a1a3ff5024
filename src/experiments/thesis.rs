//! The thesis's own protocol (chapter 4), run as §4.1 describes it: `polysect bench
//! --protocol thesis`.
//!
//! # Protocol
//! - **Placement.** Each pair is two random ellipse polygons, each translated by a
//!   random vector in [-1, 1]² ([`Relation::Any`]); nothing steers the pair. The outcome
//!   (decided by the exact [`Linear`]) sorts it into *intersecting* or *disjoint*, so
//!   the two groups have whatever sizes the placement gives (§4.1 "Early termination").
//! - **Sizes.** n = size(P) + size(Q) = 2^4 … 2^22 with size(P) = size(Q) = n/2 for
//!   Barba, Dobkin (and our Chazelle–Dobkin); 2^4 … 2^20 for the linked tests (CLM and
//!   Convert, §4.3.1).
//! - **Repetitions.** For each pair and algorithm: start the clock, run the query
//!   [`ThesisConfig::repetitions`] times (1000) on the same pair, stop the clock,
//!   divide (§4.1 "Measuring Time"). The linked tests use
//!   [`ThesisConfig::large_repetitions`] (10) above [`ThesisConfig::large_from_log2`]
//!   (2^18) as §4.3.1 does; Convert, which is linear, also caps its repetitions at
//!   [`ThesisConfig::convert_budget`] vertices walked per pair (our deviation: 1000
//!   linear walks of 2^18 vertices per pair would take the run hours).
//! - **Pairs.** [`ThesisConfig::pairs`] (100) per size; each pair is used by every
//!   algorithm, and every answer is checked against the exact reference (the thesis
//!   discards disagreeing runs; we count them in `wrong`, which must be 0).
//! - **Statistics.** The thesis reports the mean over pairs; we write the mean and the
//!   median of the per-pair times.
//! - **Experiments.** 1–2: unrotated ellipses starting at the leftmost vertex
//!   (`ellipse`); 3: rotated, random start index (`rotated`); 4: non-uniform angle
//!   densities, rotated, random start (`non-uniform`); 5 and §4.4 (Figs. 4.6–4.8): CLM
//!   and Convert on the `non-uniform` pairs, linked in shuffled arena order (§4.3).
//!
//! # Counts
//! Every query also runs once untimed with a [`Counts`] probe: pruning iterations
//! against the thesis's bounds (log2 P + log2 Q for Barba, 2·log2 P + 2·log2 Q for
//! Dobkin, the same for Chazelle–Dobkin; `over_bound` counts queries above), and for
//! CLM the samples, LP calls, constraints per LP, constraints the LP examined, chain
//! walks and vertices per walk (kept apart).
//!
//! # Output
//! `thesis.csv` (rewritten after every size, so an interrupted run keeps what it
//! measured) and the figures `thesis_fig4_2a_*.svg` (time), `thesis_fig4_2b_*.svg`
//! (time / log2 n), `thesis_fig4_3_*.svg` (iterations), `thesis_fig4_6.svg` (CLM time /
//! √n), `thesis_fig4_7.svg` (all algorithms) and `thesis_fig4_8.svg` (CLM against
//! Convert), all of means like the thesis's figures; and the input figures 4.1, 4.4
//! and 4.5 (`thesis_fig4_1.svg`, `thesis_fig4_4a.svg`, `thesis_fig4_4b.svg`,
//! `thesis_fig4_5.svg`).

use super::measure::median;
use super::plot::{self, Chart, Series};
use super::{Csv, PreparedPair, Report, ns};
use crate::generate::{self, Family, Relation};
use crate::intersect::ArrayEngine;
use crate::intersect::{
    Algorithm, ArrayIntersection, Barba, ChazelleDobkin, Counts, CountsSummary, Dobkin, Linear, Probe,
};
use crate::kernel::{Exact, Precision};
use crate::polygon::ConvexPolygon;
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::collections::BTreeMap;
use std::fs;
use std::hint::black_box;
use std::io;
use std::path::PathBuf;
use std::time::Instant;

/// How much of the thesis protocol to run; [`ThesisConfig::full`] is §4 as written.
#[derive(Clone, Debug)]
pub struct ThesisConfig {
    /// Where `thesis.csv` and the figures go (created if missing).
    pub out: PathBuf,
    /// Seed of every generator.
    pub seed: u64,
    /// log2 of n = size(P) + size(Q) for the array tests (thesis: 4 … 22).
    pub log2_totals: Vec<u32>,
    /// log2 of n for the linked tests, CLM and Convert (thesis: 4 … 20).
    pub linked_log2_totals: Vec<u32>,
    /// Generated pairs per size (thesis: 100).
    pub pairs: usize,
    /// Queries per timed loop (thesis: 1000).
    pub repetitions: usize,
    /// Queries per timed loop of the linked tests above `large_from_log2` (thesis: 10).
    pub large_repetitions: usize,
    /// log2 n above which the linked tests use `large_repetitions` (thesis: 18).
    pub large_from_log2: u32,
    /// Convert's repetitions are capped at this many vertices walked per pair (≥ 1
    /// repetition).
    pub convert_budget: usize,
    /// The experiments' input families, in the order they run at each size.
    pub families: Vec<Family>,
    /// Show a progress bar on standard error.
    pub progress: bool,
}

impl ThesisConfig {
    /// §4 as written: 100 pairs × 1000 repetitions, n = 2^4 … 2^22 (2^20 for the linked
    /// tests). Long: on a shared 2-core machine under a load average of 17 it reached
    /// n = 2^17 in 40 minutes; the larger sizes generate 200 polygons of up to 2^21
    /// vertices each.
    pub fn full(out: impl Into<PathBuf>) -> ThesisConfig {
        ThesisConfig {
            out: out.into(),
            seed: 0x7e5_0175,
            log2_totals: (4..=22).collect(),
            linked_log2_totals: (4..=20).collect(),
            pairs: 100,
            repetitions: 1000,
            large_repetitions: 10,
            large_from_log2: 18,
            convert_budget: 1 << 24,
            families: vec![Family::Ellipse, Family::Rotated, Family::NonUniform],
            progress: true,
        }
    }

    /// The same protocol shrunk to run in seconds: n = 2^4 … 2^14 in steps of 2, 20
    /// pairs × 50 repetitions.
    pub fn quick(out: impl Into<PathBuf>) -> ThesisConfig {
        ThesisConfig {
            log2_totals: vec![4, 6, 8, 10, 12, 14],
            linked_log2_totals: vec![4, 6, 8, 10, 12, 14],
            pairs: 20,
            repetitions: 50,
            large_repetitions: 10,
            large_from_log2: 12,
            convert_budget: 1 << 18,
            ..ThesisConfig::full(out)
        }
    }

    fn repetitions_for(&self, alg: Algorithm, log2_total: u32) -> usize {
        let linked = Algorithm::LINKED.contains(&alg);
        let mut reps = if linked && log2_total > self.large_from_log2 {
            self.large_repetitions
        } else {
            self.repetitions
        };
        if alg == Algorithm::Convert {
            reps = reps.min(self.convert_budget >> log2_total);
        }
        reps.max(1)
    }
}

/// The algorithms the thesis runs on a family: the O(log n) tests everywhere, and on
/// the non-uniform pairs (experiment 5, §4.4) also the linked tests.
pub fn algorithms(family: Family) -> &'static [Algorithm] {
    const ARRAY: &[Algorithm] = &[Algorithm::Barba, Algorithm::Dobkin, Algorithm::ChazelleDobkin];
    const ALL: &[Algorithm] = &[
        Algorithm::Barba,
        Algorithm::Dobkin,
        Algorithm::ChazelleDobkin,
        Algorithm::Clm,
        Algorithm::Convert,
    ];
    if family == Family::NonUniform { ALL } else { ARRAY }
}

/// The thesis's iteration bound for `alg` on polygons of `p` and `q` vertices (§4.2.1):
/// log2 P + log2 Q for Barba, 2·log2 P + 2·log2 Q for Dobkin (and, by the same
/// two-chain-pairs argument, Chazelle–Dobkin); `None` for the others.
pub fn iteration_bound(alg: Algorithm, p: usize, q: usize) -> Option<f64> {
    let logs = (p as f64).log2() + (q as f64).log2();
    match alg {
        Algorithm::Barba => Some(logs),
        Algorithm::Dobkin | Algorithm::ChazelleDobkin => Some(2.0 * logs),
        _ => None,
    }
}

/// One query's measurement.
struct Sample {
    ns: f64,
    total: usize,
    counts: Counts,
    bound: Option<f64>,
    wrong: bool,
}

/// A curve point: family, log2 n, algorithm, outcome (true = intersecting).
type Key = (usize, u32, usize, bool);

fn alg_index(alg: Algorithm) -> usize {
    Algorithm::ALL.iter().position(|&a| a == alg).unwrap_or(0)
}

fn outcome_name(intersecting: bool) -> &'static str {
    if intersecting { "intersecting" } else { "disjoint" }
}

/// Runs an array test once with `probe`, exact kernel.
fn array_query<P: Probe>(alg: Algorithm, p: &ConvexPolygon, q: &ConvexPolygon, probe: &mut P) -> bool {
    match alg {
        Algorithm::Barba => Barba.intersects_probed(Exact, p, q, probe),
        Algorithm::Dobkin => Dobkin.intersects_probed(Exact, p, q, probe),
        Algorithm::ChazelleDobkin => ChazelleDobkin.intersects_probed(Exact, p, q, probe),
        _ => Linear.intersects_probed(Exact, p, q, probe),
    }
}

/// Nanoseconds per query of `reps` back-to-back queries (the thesis's loop).
fn timed(reps: usize, mut f: impl FnMut() -> bool) -> f64 {
    let start = Instant::now();
    for _ in 0..reps {
        black_box(f());
    }
    start.elapsed().as_secs_f64() * 1e9 / reps as f64
}

/// Measures one generated pair with every algorithm of `algs`.
fn measure_pair(
    config: &ThesisConfig,
    log2_total: u32,
    algs: &[Algorithm],
    (p, q): (ConvexPolygon, ConvexPolygon),
    seed: u64,
    out: &mut Vec<(Algorithm, bool, Sample)>,
) {
    let truth = Linear.intersects_with(Exact, &p, &q);
    let total = p.len() + q.len();
    let linked = algs.iter().any(|a| Algorithm::LINKED.contains(a));
    let mut prepared = linked.then(|| PreparedPair::new(p.clone(), q.clone(), seed));
    for &alg in algs {
        let reps = config.repetitions_for(alg, log2_total);
        let (answer, counts, ns) = match prepared.as_mut() {
            Some(pp) if Algorithm::LINKED.contains(&alg) => {
                let (answer, counts) = pp.counts(alg, Precision::Exact);
                let ns = timed(reps, || pp.query(alg, Precision::Exact));
                (answer, counts, ns)
            }
            _ => {
                let mut counts = Counts::default();
                let answer = array_query(alg, &p, &q, &mut counts);
                let ns = timed(reps, || array_query(alg, black_box(&p), black_box(&q), &mut ()));
                (answer, counts, ns)
            }
        };
        out.push((
            alg,
            truth,
            Sample {
                ns,
                total,
                counts,
                bound: iteration_bound(alg, p.len(), q.len()),
                wrong: answer != truth,
            },
        ));
    }
}

/// Runs the protocol, writing `thesis.csv` and the figures into `config.out`.
///
/// # Errors
/// When the output directory or a file cannot be written.
pub fn run(config: &ThesisConfig) -> io::Result<Report> {
    fs::create_dir_all(&config.out)?;
    let mut sizes: Vec<u32> = config
        .log2_totals
        .iter()
        .chain(&config.linked_log2_totals)
        .copied()
        .collect();
    sizes.sort_unstable();
    sizes.dedup();
    let bar = super::progress_bar(config.progress, "thesis", sizes.len() * config.families.len());
    let mut cells: BTreeMap<Key, Vec<Sample>> = BTreeMap::new();
    let mut report = Report::default();
    for &lt in &sizes {
        for (fi, &family) in config.families.iter().enumerate() {
            bar.set_message(format!("{family} n=2^{lt}"));
            let algs: Vec<Algorithm> = algorithms(family)
                .iter()
                .copied()
                .filter(|a| {
                    if Algorithm::LINKED.contains(a) {
                        config.linked_log2_totals.contains(&lt)
                    } else {
                        config.log2_totals.contains(&lt)
                    }
                })
                .collect();
            if algs.is_empty() {
                bar.inc(1);
                continue;
            }
            let salt = u64::from(lt).wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ (fi as u64) << 48;
            let mut rng = SmallRng::seed_from_u64(config.seed ^ salt);
            let per_polygon = (1usize << lt) / 2;
            let mut measured = Vec::new();
            for i in 0..config.pairs {
                let pair = generate::pair(family, per_polygon, Relation::Any, &mut rng);
                measure_pair(
                    config,
                    lt,
                    &algs,
                    pair,
                    config.seed ^ salt ^ i as u64,
                    &mut measured,
                );
            }
            for (alg, outcome, sample) in measured {
                cells
                    .entry((fi, lt, alg_index(alg), outcome))
                    .or_default()
                    .push(sample);
            }
            bar.inc(1);
        }
        // Rewritten after every size: an interrupted run keeps what it measured.
        let points = summarize(config, &cells);
        csv(&points).write(&config.out, "thesis.csv", &mut Report::default())?;
    }
    bar.finish();
    let points = summarize(config, &cells);
    csv(&points).write(&config.out, "thesis.csv", &mut report)?;
    figures(config, &points, &mut report)?;
    super::thesis_figures::write_all(&config.out, config.seed, &mut report)?;
    report.summary = summary(&points);
    Ok(report)
}

/// One row of `thesis.csv`.
#[derive(Clone, Debug)]
pub(crate) struct ThesisPoint {
    family: Family,
    log2_total: u32,
    alg: Algorithm,
    intersecting: bool,
    total: f64,
    pairs: usize,
    repetitions: usize,
    mean_ns: f64,
    median_ns: f64,
    it_mean: f64,
    it_median: f64,
    it_max: u64,
    bound_mean: Option<f64>,
    over_bound: usize,
    counts: CountsSummary,
    wrong: usize,
}

fn mean(xs: impl Iterator<Item = f64>) -> f64 {
    let (sum, count) = xs.fold((0.0, 0usize), |(s, c), x| (s + x, c + 1));
    if count == 0 { f64::NAN } else { sum / count as f64 }
}

fn summarize(config: &ThesisConfig, cells: &BTreeMap<Key, Vec<Sample>>) -> Vec<ThesisPoint> {
    cells
        .iter()
        .map(|(&(fi, lt, ai, intersecting), samples)| {
            let alg = Algorithm::ALL[ai];
            let mut times: Vec<f64> = samples.iter().map(|s| s.ns).collect();
            let mut its: Vec<f64> = samples.iter().map(|s| s.counts.iterations as f64).collect();
            ThesisPoint {
                family: config.families[fi],
                log2_total: lt,
                alg,
                intersecting,
                total: mean(samples.iter().map(|s| s.total as f64)),
                pairs: samples.len(),
                repetitions: config.repetitions_for(alg, lt),
                mean_ns: mean(times.iter().copied()),
                median_ns: median(&mut times),
                it_mean: mean(its.iter().copied()),
                it_median: median(&mut its),
                it_max: samples.iter().map(|s| s.counts.iterations).max().unwrap_or(0),
                bound_mean: samples
                    .iter()
                    .map(|s| s.bound)
                    .collect::<Option<Vec<f64>>>()
                    .map(|b| mean(b.into_iter())),
                over_bound: samples
                    .iter()
                    .filter(|s| s.bound.is_some_and(|b| s.counts.iterations as f64 > b))
                    .count(),
                counts: CountsSummary::of(samples.iter().map(|s| &s.counts)),
                wrong: samples.iter().filter(|s| s.wrong).count(),
            }
        })
        .collect()
}

/// The columns of `thesis.csv`.
pub const CSV_HEADER: [&str; 27] = [
    "family",
    "outcome",
    "algorithm",
    "log2_total",
    "n_per_polygon",
    "total_vertices",
    "pairs",
    "repetitions",
    "mean_ns",
    "median_ns",
    "mean_ns_per_log2_total",
    "mean_ns_per_sqrt_total",
    "iterations_mean",
    "iterations_median",
    "iterations_max",
    "bound_mean",
    "over_bound",
    "samples_mean",
    "lp_calls_mean",
    "one_lp_share",
    "constraints_per_lp",
    "lp_work_per_lp",
    "walks_mean",
    "steps_per_walk",
    "longest_walk",
    "wrong",
    "kernel",
];

/// A float with `digits` decimals, empty when not a number (no LP calls, no bound).
fn num(x: f64, digits: usize) -> String {
    if x.is_finite() {
        format!("{x:.digits$}")
    } else {
        String::new()
    }
}

/// A table cell: `x` with `digits` decimals, or "—" when it is not a number (a mean
/// over no LP or no walk, a ratio to a zero time).
fn cell(x: f64, digits: usize) -> String {
    if x.is_finite() {
        format!("{x:.digits$}")
    } else {
        "—".to_string()
    }
}

fn csv(points: &[ThesisPoint]) -> Csv {
    let mut csv = Csv::new(&CSV_HEADER);
    for p in points {
        let clm = p.alg == Algorithm::Clm;
        let clm_only = |x: f64, d: usize| if clm { num(x, d) } else { String::new() };
        csv.row(&[
            p.family.to_string(),
            outcome_name(p.intersecting).into(),
            p.alg.to_string(),
            p.log2_total.to_string(),
            ((1usize << p.log2_total) / 2).to_string(),
            format!("{:.1}", p.total),
            p.pairs.to_string(),
            p.repetitions.to_string(),
            ns(p.mean_ns),
            ns(p.median_ns),
            ns(p.mean_ns / p.total.log2()),
            ns(p.mean_ns / p.total.sqrt()),
            format!("{:.2}", p.it_mean),
            format!("{:.1}", p.it_median),
            p.it_max.to_string(),
            p.bound_mean.map_or(String::new(), |b| format!("{b:.2}")),
            p.over_bound.to_string(),
            clm_only(p.counts.samples_mean, 1),
            clm_only(p.counts.lp_calls_mean, 3),
            clm_only(p.counts.one_lp_share, 3),
            clm_only(p.counts.constraints_per_lp, 1),
            clm_only(p.counts.work_per_lp, 1),
            clm_only(p.counts.walks_mean, 3),
            clm_only(p.counts.steps_per_walk, 2),
            if clm {
                p.counts.longest_walk.to_string()
            } else {
                String::new()
            },
            p.wrong.to_string(),
            "exact".into(),
        ]);
    }
    csv
}

fn series(
    points: &[ThesisPoint],
    keep: impl Fn(&ThesisPoint) -> bool,
    y: impl Fn(&ThesisPoint) -> f64,
) -> Vec<Series> {
    let mut out: Vec<Series> = Vec::new();
    for p in points.iter().filter(|p| keep(p)) {
        let name = format!("{} {}", p.alg, outcome_name(p.intersecting));
        let xy = ((1u64 << p.log2_total) as f64, y(p));
        match out.iter_mut().find(|s| s.name == name) {
            Some(s) => s.points.push(xy),
            None => out.push(Series::new(name, vec![xy])),
        }
    }
    out
}

fn figures(config: &ThesisConfig, points: &[ThesisPoint], report: &mut Report) -> io::Result<()> {
    let mut draw = |name: String, chart: &Chart<'_>, s: Vec<Series>| -> io::Result<()> {
        if s.is_empty() {
            return Ok(());
        }
        plot::draw(&config.out.join(&name), chart, &s)?;
        report.files.push(name);
        Ok(())
    };
    let log_alg = |p: &ThesisPoint| Algorithm::LOGARITHMIC.contains(&p.alg);
    for &family in &config.families {
        let keep = |p: &ThesisPoint| p.family == family && log_alg(p);
        let title = format!("Fig. 4.2(a): mean time per query, {family}");
        let chart = Chart {
            title: &title,
            x_label: "n = size(P) + size(Q)",
            y_label: "mean ns per query",
            log2_x: true,
            log_y: true,
            scatter: false,
        };
        draw(
            format!("thesis_fig4_2a_{family}.svg"),
            &chart,
            series(points, keep, |p| p.mean_ns),
        )?;
        let title = format!("Fig. 4.2(b): mean time / log2 n, {family}");
        let chart = Chart {
            title: &title,
            y_label: "mean ns / log2 n",
            log_y: false,
            ..chart
        };
        draw(
            format!("thesis_fig4_2b_{family}.svg"),
            &chart,
            series(points, keep, |p| p.mean_ns / p.total.log2()),
        )?;
        let title = format!("Fig. 4.3: mean iterations, {family}");
        let chart = Chart {
            title: &title,
            y_label: "mean iterations",
            ..chart
        };
        draw(
            format!("thesis_fig4_3_{family}.svg"),
            &chart,
            series(points, keep, |p| p.it_mean),
        )?;
    }
    let nonuniform = |p: &ThesisPoint| p.family == Family::NonUniform;
    let chart = Chart {
        title: "Fig. 4.6: CLM mean time / sqrt(n), non-uniform",
        x_label: "n = size(P) + size(Q)",
        y_label: "mean ns / sqrt(n)",
        log2_x: true,
        log_y: false,
        scatter: false,
    };
    draw(
        "thesis_fig4_6.svg".into(),
        &chart,
        series(
            points,
            |p| nonuniform(p) && p.alg == Algorithm::Clm,
            |p| p.mean_ns / p.total.sqrt(),
        ),
    )?;
    let chart = Chart {
        title: "Fig. 4.7: mean time per query, every algorithm, non-uniform",
        y_label: "mean ns per query",
        log_y: true,
        ..chart
    };
    draw(
        "thesis_fig4_7.svg".into(),
        &chart,
        series(points, nonuniform, |p| p.mean_ns),
    )?;
    let chart = Chart {
        title: "Fig. 4.8: CLM against Convert (walk, then Barba), non-uniform",
        ..chart
    };
    draw(
        "thesis_fig4_8.svg".into(),
        &chart,
        series(
            points,
            |p| nonuniform(p) && Algorithm::LINKED.contains(&p.alg),
            |p| p.mean_ns,
        ),
    )
}

fn summary(points: &[ThesisPoint]) -> String {
    let mut out = String::from(
        "mean ns per query (median in parentheses), intersecting / disjoint, pairs per outcome\n\n",
    );
    let mut sizes: Vec<u32> = points.iter().map(|p| p.log2_total).collect();
    sizes.sort_unstable();
    sizes.dedup();
    let mut rows: Vec<(Family, Algorithm)> = Vec::new();
    for p in points {
        if !rows.contains(&(p.family, p.alg)) {
            rows.push((p.family, p.alg));
        }
    }
    out.push_str("| family | algorithm |");
    for lt in &sizes {
        out.push_str(&format!(" 2^{lt} |"));
    }
    out.push_str("\n|---|---|");
    out.push_str(&"---|".repeat(sizes.len()));
    out.push('\n');
    for &(family, alg) in &rows {
        out.push_str(&format!("| {family} | {alg} |"));
        for &lt in &sizes {
            let cell = |intersecting: bool| {
                points
                    .iter()
                    .find(|p| {
                        p.family == family
                            && p.alg == alg
                            && p.log2_total == lt
                            && p.intersecting == intersecting
                    })
                    .map_or("—".to_string(), |p| {
                        format!("{} ({}) ×{}", cell(p.mean_ns, 0), cell(p.median_ns, 0), p.pairs)
                    })
            };
            out.push_str(&format!(" {} / {} |", cell(true), cell(false)));
        }
        out.push('\n');
    }
    out.push_str(
        "\nCLM counts per query (means): LP calls, constraints per LP, examined per LP, walks, \
         vertices per walk, samples; and the disjoint/intersecting time ratio\n\n\
         | n | outcome | LP calls | one-LP share | constraints/LP | examined/LP | walks | vertices/walk | samples | mean ns | ratio |\n\
         |---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for &lt in &sizes {
        let get = |i: bool| {
            points
                .iter()
                .find(|p| p.alg == Algorithm::Clm && p.log2_total == lt && p.intersecting == i)
        };
        let (yes, no) = (get(true), get(false));
        for p in [yes, no].into_iter().flatten() {
            let r = match (yes, no) {
                (Some(a), Some(b)) => cell(b.mean_ns / a.mean_ns, 1),
                _ => "–".into(),
            };
            out.push_str(&format!(
                "| 2^{lt} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {r} |\n",
                outcome_name(p.intersecting),
                cell(p.counts.lp_calls_mean, 2),
                cell(p.counts.one_lp_share, 2),
                cell(p.counts.constraints_per_lp, 1),
                cell(p.counts.work_per_lp, 1),
                cell(p.counts.walks_mean, 2),
                cell(p.counts.steps_per_walk, 1),
                cell(p.counts.samples_mean, 1),
                cell(p.mean_ns, 0)
            ));
        }
    }
    let over: usize = points.iter().map(|p| p.over_bound).sum();
    let wrong: usize = points.iter().map(|p| p.wrong).sum();
    out.push_str(&format!(
        "\nqueries above the thesis's iteration bound: {over}; answers differing from the exact reference: {wrong}\n"
    ));
    out
}
