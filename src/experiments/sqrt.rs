//! Experiment 5 of the thesis (4.3.1, Figure 4.6): CLM's time per query divided by
//! √(size(P) + size(Q)), which should level off to a constant if the expected time is
//! O(√n). Also CLM's counts per query on the same pairs (`clm_counts.csv`,
//! `clm_counts.svg`): samples, LP calls, constraints and examined points per LP, chain
//! walks and vertices per walk, kept apart.
//!
//! And CLM against the memory limit (`clm_limit.csv`, `clm_limit.svg`): on the same
//! pairs and arenas, a bare chase of as many linked nodes as CLM walked, all its walks
//! in lockstep (their cache misses overlapping), plus a bare read of as many random
//! vertices as it sampled. CLM cannot beat that: its walks visit those nodes and its
//! samples read those vertices (and its LPs compute on top). CLM and the limit are
//! timed interleaved, pair by pair, so a noisy moment hits both.

use super::measure::{median, time_per_query};
use super::plot::Chart;
use super::plot::Series;
use super::query::PreparedPair;
use super::scaling::{Point, csv, draw, measure_grid, pairs, relation_name, series, short_ns, sizes};
use super::{Config, Csv, Report};
use crate::generate::{Family, Relation};
use crate::intersect::{Algorithm, Counts, CountsSummary};
use crate::kernel::Precision;
use crate::polygon::LinkedPolygon;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::hint::black_box;
use std::io;

pub(crate) fn run(config: &Config) -> io::Result<Report> {
    let sizes = sizes(config);
    let algs = [(Algorithm::Clm, Precision::Exact)];
    let bar = super::progress(config, "sqrt", sizes.len() * 2);
    let points = measure_grid(config, &bar, &[Family::Rotated], &sizes, &algs);
    let mut report = Report::default();
    csv(&points).write(&config.out, "clm_sqrt.csv", &mut report)?;
    let chart = Chart {
        title: "CLM: time / sqrt(2n), rotated ellipses (exact kernel)",
        x_label: "n (vertices per polygon)",
        y_label: "ns / sqrt(2n)",
        log2_x: true,
        log_y: false,
        scatter: false,
    };
    let s = series(
        &points,
        |_| true,
        |p: &Point| relation_name(p.relation).to_string(),
        Point::per_sqrt,
    );
    draw(config, &mut report, "clm_sqrt.svg", &chart, &s)?;
    counts(config, &sizes, &mut report)?;
    let limits = limit(config, &sizes, &mut report)?;
    let variants = variants(config, &mut report)?;
    let mut t = String::from(
        "| n | intersecting ns/√(2n) | disjoint ns/√(2n) | intersecting time | disjoint time |\n|---|---|---|---|---|\n",
    );
    for n in sizes {
        let at = |r| points.iter().find(|p| p.n == n && p.relation == r);
        let (i, d) = (
            at(crate::generate::Relation::Intersecting),
            at(crate::generate::Relation::Disjoint),
        );
        if let (Some(i), Some(d)) = (i, d) {
            t.push_str(&format!(
                "| 2^{} | {:.1} | {:.1} | {} | {} |\n",
                n.trailing_zeros(),
                i.per_sqrt(),
                d.per_sqrt(),
                short_ns(i.median_ns),
                short_ns(d.median_ns)
            ));
        }
    }
    t.push_str(
        "\nCLM against the memory limit (bare lockstep chase of its walked nodes + bare reads of its samples, same arenas, interleaved; the limit with all of a query's walks in flight, and with at most two, as CLM can):\n\n| n | relation | CLM | limit | CLM / limit | two-walk limit | CLM / two-walk limit |\n|---|---|---|---|---|---|---|\n",
    );
    for l in &limits {
        t.push_str(&format!(
            "| 2^{} | {} | {} | {} | {:.2} | {} | {:.2} |\n",
            l.n.trailing_zeros(),
            relation_name(l.relation),
            short_ns(l.clm_ns),
            short_ns(l.limit_ns),
            l.clm_ns / l.limit_ns,
            short_ns(l.limit_two_ns),
            l.clm_ns / l.limit_two_ns
        ));
    }
    t.push_str(&variants);
    report.summary = t;
    Ok(report)
}

/// The implementation variants of sampling (independent draws, or the thesis's 3.3.1
/// Fisher–Yates) and of the LP's randomisation (the caller's, thesis 3.3.5, the
/// default; or the LP's own shuffle), the chain-against-chain LPs by the LP instead
/// of [`separate_chains`](crate::lp::separate_chains), and the LPs on the samples by the
/// LP instead of walks on the ordered samples (`ClmVariant::sample_walk` off), against
/// the default, at a few sizes: per pair the six variants
/// are timed in turn, three rounds, the pair's figure the median of each; the point's
/// the median over pairs. Writes `clm_variants.csv`; returns a Markdown table.
fn variants(config: &Config, report: &mut Report) -> io::Result<String> {
    use crate::intersect::{ClmVariant, LpOrder, Sampling};
    let named = [
        (
            "default: independent + caller shuffles",
            Sampling::Independent,
            LpOrder::Caller,
            (true, true),
        ),
        (
            "default with chain-against-chain by the LP",
            Sampling::Independent,
            LpOrder::Caller,
            (false, true),
        ),
        (
            "default with the samples' LPs by the LP",
            Sampling::Independent,
            LpOrder::Caller,
            (true, false),
        ),
        (
            "independent + LP shuffles",
            Sampling::Independent,
            LpOrder::Lp,
            (true, true),
        ),
        (
            "thesis: Fisher–Yates + caller shuffles",
            Sampling::FisherYates,
            LpOrder::Caller,
            (true, true),
        ),
        (
            "Fisher–Yates + LP shuffles",
            Sampling::FisherYates,
            LpOrder::Lp,
            (true, true),
        ),
    ]
    .map(|(name, sampling, lp_order, (chain_walk, sample_walk))| {
        (
            name,
            ClmVariant {
                sampling,
                lp_order,
                chain_walk,
                sample_walk,
                ..ClmVariant::default()
            },
        )
    });
    let mut csv = Csv::new(&[
        "relation",
        "n",
        "pairs",
        "variant",
        "median_ns",
        "over_default",
        "lp_work_mean",
    ]);
    let mut t = String::from(
        "\nSampling and LP-order variants (median per query; in brackets, variant / default; then the LP points examined per query, mean of 16 counted queries per pair):\n\n| n | relation |",
    );
    for (name, _) in &named {
        t.push_str(&format!(" {name} |"));
    }
    t.push_str("\n|---|---|");
    t.push_str(&"---|".repeat(named.len()));
    t.push('\n');
    // 2^10, 2^14 (and 2^18, 2^20 in a full run), within the run's sizes.
    let largest = config.log2_sizes.iter().copied().max().unwrap_or(10);
    let wanted: &[u32] = if config.log2_sizes.len() < 10 {
        &[10, 14]
    } else {
        &[10, 14, 18, 20]
    };
    let mut sizes: Vec<u32> = wanted.iter().copied().filter(|&l| l <= largest).collect();
    if sizes.is_empty() {
        sizes.push(largest);
    }
    for l in sizes {
        let n = 1usize << l;
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            let mut prepared = pairs(config, Family::Rotated, relation, n, config.pairs_for(n));
            let mut times = vec![Vec::new(); named.len()];
            let mut work = vec![0u64; named.len()];
            for pp in &mut prepared {
                for (i, &(_, v)) in named.iter().enumerate() {
                    work[i] += (0..SHAPES)
                        .map(|_| pp.counts_clm_variant(v).lp_work())
                        .sum::<u64>();
                }
                let mut rounds = vec![Vec::new(); named.len()];
                for _ in 0..3 {
                    for (i, &(_, v)) in named.iter().enumerate() {
                        rounds[i].push(time_per_query(config.min_time, || pp.query_clm_variant(v)));
                    }
                }
                for (i, r) in rounds.iter_mut().enumerate() {
                    times[i].push(median(r));
                }
            }
            let medians: Vec<f64> = times.iter_mut().map(|x| median(x)).collect();
            let queries = (prepared.len() * SHAPES) as f64;
            t.push_str(&format!("| 2^{l} | {} |", relation_name(relation)));
            for (i, (name, _)) in named.iter().enumerate() {
                let ratio = medians[i] / medians[0];
                csv.row(&[
                    relation_name(relation).into(),
                    n.to_string(),
                    prepared.len().to_string(),
                    (*name).into(),
                    super::ns(medians[i]),
                    format!("{ratio:.3}"),
                    format!("{:.1}", work[i] as f64 / queries),
                ]);
                t.push_str(&format!(
                    " {} ({ratio:.2}); {:.0} |",
                    short_ns(medians[i]),
                    work[i] as f64 / queries
                ));
            }
            t.push('\n');
        }
    }
    csv.write(&config.out, "clm_variants.csv", report)?;
    Ok(t)
}

/// CLM and its memory limit at one size and relation (medians over pairs).
struct Limit {
    n: usize,
    relation: Relation,
    clm_ns: f64,
    limit_ns: f64,
    /// The limit with at most two walks in flight, in CLM's order ([`Shape::replay`]).
    limit_two_ns: f64,
}

/// Counted queries per pair whose walks and samples the limit replays.
const SHAPES: usize = 16;

/// The memory accesses of one counted CLM query, replayed without the algorithm:
/// each walk's start (a random arena position of its polygon) and length, and the
/// sampled positions.
struct Shape {
    walks: Vec<(bool, usize, usize)>,
    samples_p: Vec<u32>,
    samples_q: Vec<u32>,
}

impl Shape {
    /// The shape of a query with counts `c` on `p` and `q`: walks alternate P, Q, P, Q
    /// as CLM runs them (first chains, then second chains), from random starts.
    fn new(c: &Counts, p: &LinkedPolygon, q: &LinkedPolygon, rng: &mut SmallRng) -> Shape {
        let walks = c
            .walks
            .iter()
            .enumerate()
            .map(|(i, &len)| {
                let on_q = i % 2 == 1;
                let n = if on_q { q.len() } else { p.len() };
                (on_q, rng.random_range(0..n), len)
            })
            .collect();
        let draw =
            |n: usize, k: usize, rng: &mut SmallRng| (0..k).map(|_| rng.random_range(0..n as u32)).collect();
        Shape {
            walks,
            samples_p: draw(p.len(), c.samples_p, rng),
            samples_q: draw(q.len(), c.samples_q, rng),
        }
    }

    /// Replays the shape: the walks in lockstep, at most `in_flight` (1..=8) at a time
    /// in CLM's order (a walk that ends hands its cursor to the next one; 8 puts all of
    /// a query's walks in flight at once), a step reading the node's point and following
    /// its link; then the sampled reads, which are independent and so overlap. Returns a
    /// sum of coordinates, for `black_box`.
    fn replay(&self, p: &LinkedPolygon, q: &LinkedPolygon, in_flight: usize) -> f64 {
        let mut acc = 0.0;
        let mut cursors = [(false, 0usize, 0usize); 8];
        let live = in_flight.clamp(1, cursors.len());
        let mut next = 0;
        loop {
            let mut active = 0;
            for cursor in &mut cursors[..live] {
                // A free cursor takes the next walk (skipping empty ones, so that a
                // round with walks left always has one in flight).
                while cursor.2 == 0 && next < self.walks.len() {
                    *cursor = self.walks[next];
                    next += 1;
                }
                let (on_q, v, left) = cursor;
                if *left == 0 {
                    continue;
                }
                let poly = if *on_q { q } else { p };
                acc += poly.point_at(*v).x;
                *v = poly.next_at(*v);
                *left -= 1;
                active += 1;
            }
            if active == 0 {
                break;
            }
        }
        for (poly, positions) in [(p, &self.samples_p), (q, &self.samples_q)] {
            for &i in positions {
                acc += poly.point_at(i as usize).y;
            }
        }
        acc
    }
}

/// CLM's time and its memory limit per size and relation, on the same pairs: per pair,
/// [`SHAPES`] counted queries give the walks and samples to replay; CLM and the replay
/// are then timed in turn, three rounds each, and the pair's figures are the medians.
/// Writes `clm_limit.csv` and `clm_limit.svg`.
fn limit(config: &Config, sizes: &[usize], report: &mut Report) -> io::Result<Vec<Limit>> {
    let mut csv = Csv::new(&[
        "family",
        "relation",
        "n",
        "pairs",
        "clm_ns",
        "limit_ns",
        "clm_over_limit",
        "limit_two_ns",
        "clm_over_limit_two",
        "walked_mean",
        "samples_mean",
    ]);
    let mut out = Vec::new();
    let mut lines: Vec<Series> = Vec::new();
    for relation in [Relation::Intersecting, Relation::Disjoint] {
        let r = relation_name(relation);
        let (mut ratio, mut ratio_two) = (Vec::new(), Vec::new());
        for &n in sizes {
            let mut prepared = pairs(config, Family::Rotated, relation, n, config.pairs_for(n));
            let (mut clm, mut lim, mut lim2) = (Vec::new(), Vec::new(), Vec::new());
            let (mut walked, mut sampled) = (0usize, 0usize);
            let mut rng = SmallRng::seed_from_u64(config.seed ^ n as u64);
            for pp in &mut prepared {
                let shapes: Vec<Shape> = (0..SHAPES)
                    .map(|_| {
                        let c = pp.counts(Algorithm::Clm, Precision::Exact).1;
                        walked += c.chain_steps();
                        sampled += c.samples();
                        let (p, q) = pp.arenas();
                        Shape::new(&c, p, q, &mut rng)
                    })
                    .collect();
                let (a, b, c) = clm_and_limit(config, pp, &shapes);
                clm.push(a);
                lim.push(b);
                lim2.push(c);
            }
            let queries = (prepared.len() * SHAPES) as f64;
            let l = Limit {
                n,
                relation,
                clm_ns: median(&mut clm),
                limit_ns: median(&mut lim),
                limit_two_ns: median(&mut lim2),
            };
            csv.row(&[
                Family::Rotated.to_string(),
                r.into(),
                n.to_string(),
                prepared.len().to_string(),
                super::ns(l.clm_ns),
                super::ns(l.limit_ns),
                format!("{:.3}", l.clm_ns / l.limit_ns),
                super::ns(l.limit_two_ns),
                format!("{:.3}", l.clm_ns / l.limit_two_ns),
                format!("{:.1}", walked as f64 / queries),
                format!("{:.1}", sampled as f64 / queries),
            ]);
            ratio.push((n as f64, l.clm_ns / l.limit_ns));
            ratio_two.push((n as f64, l.clm_ns / l.limit_two_ns));
            out.push(l);
        }
        lines.push(Series::new(format!("CLM / limit, {r}"), ratio));
        lines.push(Series::new(format!("CLM / two-walk limit, {r}"), ratio_two));
    }
    csv.write(&config.out, "clm_limit.csv", report)?;
    let chart = Chart {
        title: "CLM time / memory limit (lockstep chase of its walks + its sampled reads)",
        x_label: "n (vertices per polygon)",
        y_label: "CLM time / limit",
        log2_x: true,
        log_y: true,
        scatter: false,
    };
    draw(config, report, "clm_limit.svg", &chart, &lines)?;
    Ok(out)
}

/// One pair's CLM time and its two limits (ns per query): all of a query's walks in
/// flight at once, and at most two (CLM's own bound: its second chains start from the
/// lines its first chains give). Timed in turn, three rounds of each, the median of each.
fn clm_and_limit(config: &Config, pp: &mut PreparedPair, shapes: &[Shape]) -> (f64, f64, f64) {
    let (mut clm, mut lim, mut lim2) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..3 {
        clm.push(time_per_query(config.min_time, || {
            pp.query(Algorithm::Clm, Precision::Exact)
        }));
        let (p, q) = pp.arenas();
        for (in_flight, out) in [(8, &mut lim), (2, &mut lim2)] {
            let mut i = 0;
            out.push(time_per_query(config.min_time, || {
                i = (i + 1) % shapes.len();
                black_box(shapes[i].replay(p, q, in_flight)) > f64::MAX
            }));
        }
    }
    (median(&mut clm), median(&mut lim), median(&mut lim2))
}

/// CLM's counts on the pairs the timing used (regenerated from the same seed), one
/// untimed counted query per pair: `clm_counts.csv` and `clm_counts.svg`.
fn counts(config: &Config, sizes: &[usize], report: &mut Report) -> io::Result<()> {
    let mut csv = Csv::new(&[
        "family",
        "relation",
        "n",
        "pairs",
        "samples_mean",
        "lp_calls_mean",
        "one_lp_share",
        "constraints_per_lp",
        "lp_work_per_lp",
        "walks_mean",
        "steps_per_walk",
        "longest_walk",
        "work_mean",
    ]);
    let mut lines: Vec<Series> = Vec::new();
    for relation in [Relation::Intersecting, Relation::Disjoint] {
        let r = relation_name(relation);
        let mut per_lp = Vec::new();
        let mut per_walk = Vec::new();
        for &n in sizes {
            let mut prepared = pairs(config, Family::Rotated, relation, n, config.pairs_for(n));
            let all: Vec<Counts> = prepared
                .iter_mut()
                .map(|pp| pp.counts(Algorithm::Clm, Precision::Exact).1)
                .collect();
            let c = CountsSummary::of(&all);
            let opt = |x: f64, d: usize| {
                if x.is_finite() {
                    format!("{x:.d$}")
                } else {
                    String::new()
                }
            };
            csv.row(&[
                Family::Rotated.to_string(),
                r.into(),
                n.to_string(),
                c.queries.to_string(),
                format!("{:.1}", c.samples_mean),
                format!("{:.3}", c.lp_calls_mean),
                format!("{:.3}", c.one_lp_share),
                opt(c.constraints_per_lp, 1),
                opt(c.work_per_lp, 1),
                format!("{:.3}", c.walks_mean),
                opt(c.steps_per_walk, 2),
                c.longest_walk.to_string(),
                format!("{:.1}", c.iterations_mean),
            ]);
            per_lp.push((n as f64, c.work_per_lp));
            if c.steps_per_walk.is_finite() {
                per_walk.push((n as f64, c.steps_per_walk));
            }
        }
        lines.push(Series::new(format!("examined per LP, {r}"), per_lp));
        if !per_walk.is_empty() {
            lines.push(Series::new(format!("vertices per walk, {r}"), per_walk));
        }
    }
    csv.write(&config.out, "clm_counts.csv", report)?;
    let chart = Chart {
        title: "CLM counts per query, rotated ellipses (means over pairs)",
        x_label: "n (vertices per polygon)",
        y_label: "points / vertices",
        log2_x: true,
        log_y: true,
        scatter: false,
    };
    draw(config, report, "clm_counts.svg", &chart, &lines)
}
