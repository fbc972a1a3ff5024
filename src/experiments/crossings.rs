//! The experiment of docs/crossings.md's report (its figure and its two tables): the crossings of two random
//! simple polygons (space partitioning) with n vertices each, for uniform points in
//! [0, Δ)² with Δ ∈ {10, 50, 100, 500} and normal points (μ = 0) with
//! σ ∈ {10, 20, 50, 100}, timed for four algorithms:
//!
//! | algorithm | what |
//! |---|---|
//! | `sweep` | [`Sweep`] (exact kernel), the default |
//! | `brute` | [`Brute`]: every pair, a bounding-box rejection, then the exact segment test |
//! | `brute-nobox` | every pair through the exact segment test, no box rejection |
//! | `brute-division` | the report's brute force: every pair, the intersection of the two lines by division (plain `f64`), kept when it lies in both segments' boxes |
//! | `sweep-division` | the report's sweep: Žalik's lists, every candidate through the same division test (no y-range check) |
//!
//! Every algorithm constructs the points it reports. Before timing, the sweep's
//! points are checked against the brute force's (`wrong` counts pairs where they
//! differ; it must be 0). The counts explain the ratios: `brute_pairs` = n·m pairs
//! for every brute force, against `candidates` = Σ r for Žalik's lists (each
//! insertion checks the other polygon's listed edges) of which `tests` pass the
//! y-range check and get a segment test; `points` is the sweep's output and
//! `division_points` the report's method's (it finds no overlap and decides touchings
//! by rounding). Files: `crossings.csv`, `crossings_uniform.svg`,
//! `crossings_normal.svg`, `crossings_ratios.svg`.

use super::measure::{median, time_per_query};
use super::plot::{Chart, Series};
use super::scaling::{draw, short_ns};
use super::{Config, Csv, Report, ns};
use crate::crossings::{ListWorkspace, every_candidate};

use crate::crossings::{Brute, Crossings, ListSweep, Sweep, SweepWorkspace, crossing_point};
use crate::generate::simple::{PointDistribution, SimpleMethod, random_simple_polygon};
use crate::kernel::{Exact, Point, SegmentContact, segment_contact};
use crate::polygon::SimplePolygon;
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::hint::black_box;
use std::io;

/// Δ of the uniform table (uniform points in [0, Δ)²).
pub const DELTAS: [f64; 4] = [10.0, 50.0, 100.0, 500.0];
/// σ of the normal table (normal points, μ = 0).
pub const SIGMAS: [f64; 4] = [10.0, 20.0, 50.0, 100.0];
/// The n of both tables.
pub const SEED_SIZES: [usize; 8] = [5, 50, 100, 200, 500, 800, 1000, 2000];

const ALGORITHMS: [&str; 5] = [
    "sweep",
    "brute",
    "brute-nobox",
    "brute-division",
    "sweep-division",
];

/// The report's segment test: the intersection point of the two lines (none for
/// parallel lines), kept when it lies in the bounding boxes of both segments. Plain
/// `f64`: a touching may be kept or lost by rounding and an overlap is never found.
#[inline]
pub fn division_point(a: Point, b: Point, c: Point, d: Point) -> Option<Point> {
    let within = |a: Point, b: Point, x: f64, y: f64| {
        x >= a.x.min(b.x) && x <= a.x.max(b.x) && y >= a.y.min(b.y) && y <= a.y.max(b.y)
    };
    let (a1, b1) = (b.y - a.y, a.x - b.x);
    let c1 = a1 * a.x + b1 * a.y;
    let (a2, b2) = (d.y - c.y, c.x - d.x);
    let c2 = a2 * c.x + b2 * c.y;
    let det = a1 * b2 - a2 * b1;
    if det == 0.0 {
        return None;
    }
    let x = (b2 * c1 - b1 * c2) / det;
    let y = (a1 * c2 - a2 * c1) / det;
    (within(a, b, x, y) && within(c, d, x, y)).then_some(Point::new(x, y))
}

/// The report's brute force: [`division_point`] on every pair.
pub fn division_brute(p: &SimplePolygon, q: &SimplePolygon, out: &mut Vec<Point>) {
    out.clear();
    for i in 0..p.len() {
        let (a, b) = p.edge(i);
        for j in 0..q.len() {
            let (c, d) = q.edge(j);
            out.extend(division_point(a, b, c, d));
        }
    }
}

/// The report's sweep: Žalik's lists with every candidate through [`division_point`]
/// (no y-range check, no exact predicate). `events` and `ws` are scratch memory.
pub fn division_sweep(
    p: &SimplePolygon,
    q: &SimplePolygon,
    events: &mut Vec<(Point, u32)>,
    ws: &mut ListWorkspace,
    out: &mut Vec<Point>,
) {
    out.clear();
    every_candidate(p, q, events, ws, |a, b, c, d| {
        out.extend(division_point(a, b, c, d))
    });
}

/// Every pair through the exact segment test, no box rejection; crossings constructed.
fn nobox_brute(p: &SimplePolygon, q: &SimplePolygon, out: &mut Vec<Point>) {
    out.clear();
    for i in 0..p.len() {
        let (a, b) = p.edge(i);
        for j in 0..q.len() {
            let (c, d) = q.edge(j);
            match segment_contact(Exact, a, b, c, d) {
                SegmentContact::Disjoint => {}
                SegmentContact::Crossing => out.push(crossing_point(a, b, c, d)),
                // Random real input has (almost) no other contacts; count them as one point.
                _ => out.push(a),
            }
        }
    }
}

/// One measured point: a distribution, n, an algorithm.
#[derive(Clone, Debug)]
struct Row {
    dist: &'static str,
    param: f64,
    n: usize,
    alg: &'static str,
    pairs: usize,
    median_ns: f64,
    points: f64,
    division_points: f64,
    candidates: f64,
    tests: f64,
    wrong: usize,
}

fn distributions() -> Vec<(&'static str, f64, PointDistribution)> {
    let uniform = DELTAS.map(|d| ("uniform", d, PointDistribution::Uniform { min: 0.0, max: d }));
    let normal = SIGMAS.map(|s| ("normal", s, PointDistribution::Normal { mean: 0.0, sigma: s }));
    uniform.into_iter().chain(normal).collect()
}

pub(crate) fn run(config: &Config) -> io::Result<Report> {
    let dists = distributions();
    let bar = super::progress(config, "crossings", dists.len() * config.crossings_sizes.len());
    let mut rows = Vec::new();
    for (di, &(dist, param, pd)) in dists.iter().enumerate() {
        for &n in &config.crossings_sizes {
            bar.set_message(format!("{dist} {param} n={n}"));
            let mut rng = SmallRng::seed_from_u64(config.seed ^ (di as u64) << 40 ^ n as u64);
            let polys: Vec<(SimplePolygon, SimplePolygon)> = (0..config.crossings_pairs.max(1))
                .filter_map(|_| {
                    let p =
                        random_simple_polygon(SimpleMethod::SpacePartition, pd, n.max(3), &mut rng).ok()?;
                    let q =
                        random_simple_polygon(SimpleMethod::SpacePartition, pd, n.max(3), &mut rng).ok()?;
                    Some((p, q))
                })
                .collect();
            rows.extend(measure(config, dist, param, n, &polys));
            bar.inc(1);
        }
    }
    bar.finish();
    let mut report = Report::default();
    let mut csv = Csv::new(&[
        "distribution",
        "parameter",
        "n",
        "algorithm",
        "pairs",
        "median_ns",
        "points",
        "division_points",
        "brute_pairs",
        "candidates",
        "tests",
        "wrong",
    ]);
    for r in &rows {
        csv.row(&[
            r.dist.to_string(),
            r.param.to_string(),
            r.n.to_string(),
            r.alg.to_string(),
            r.pairs.to_string(),
            ns(r.median_ns),
            r.points.to_string(),
            r.division_points.to_string(),
            (r.n * r.n).to_string(),
            r.candidates.to_string(),
            r.tests.to_string(),
            r.wrong.to_string(),
        ]);
    }
    csv.write(&config.out, "crossings.csv", &mut report)?;
    for (dist, symbol) in [("uniform", "Δ"), ("normal", "σ")] {
        let mut series = Vec::new();
        for alg in ["brute", "sweep"] {
            for &(d, param, _) in dists.iter().filter(|x| x.0 == dist) {
                let pts = rows
                    .iter()
                    .filter(|r| r.dist == d && r.param == param && r.alg == alg)
                    .map(|r| (r.n as f64, r.median_ns / 1e6))
                    .collect();
                series.push(Series::new(format!("{alg}, {symbol} = {param}"), pts));
            }
        }
        let title = format!("crossings of two random polygons, {dist} points");
        let chart = Chart {
            title: &title,
            x_label: "n = m (vertices per polygon)",
            y_label: "ms per query",
            log2_x: false,
            log_y: true,
            scatter: false,
        };
        draw(
            config,
            &mut report,
            &format!("crossings_{dist}.svg"),
            &chart,
            &series,
        )?;
    }
    // Ratios to the sweep at Δ = 100 and σ = 50, with the pair-count ratio n·m / W.
    let mut series = Vec::new();
    for (dist, param) in [("uniform", 100.0), ("normal", 50.0)] {
        let at = |alg: &str| {
            rows.iter()
                .filter(move |r| r.dist == dist && r.param == param && r.alg == alg)
                .cloned()
                .collect::<Vec<Row>>()
        };
        let sweep = at("sweep");
        let ratio = |num: &[Row], den: &[Row]| -> Vec<(f64, f64)> {
            num.iter()
                .zip(den)
                .map(|(r, s)| (r.n as f64, r.median_ns / s.median_ns))
                .collect()
        };
        series.push(Series::new(
            format!("brute / sweep, {dist} {param}"),
            ratio(&at("brute"), &sweep),
        ));
        series.push(Series::new(
            format!("brute-division / sweep-division, {dist} {param}"),
            ratio(&at("brute-division"), &at("sweep-division")),
        ));
        let pts = sweep
            .iter()
            .filter(|s| s.candidates > 0.0)
            .map(|s| (s.n as f64, (s.n * s.n) as f64 / s.candidates))
            .collect();
        series.push(Series::new(format!("n·m / candidates, {dist} {param}"), pts));
    }
    let chart = Chart {
        title: "brute / sweep, the report's pair: division brute / division sweep, and n·m / W",
        x_label: "n = m (vertices per polygon)",
        y_label: "ratio",
        log2_x: false,
        log_y: true,
        scatter: false,
    };
    draw(config, &mut report, "crossings_ratios.svg", &chart, &series)?;
    report.summary = summary(&rows, &dists);
    Ok(report)
}

/// Times every algorithm on `polys` (median over the pairs of each pair's median).
fn measure(
    config: &Config,
    dist: &'static str,
    param: f64,
    n: usize,
    polys: &[(SimplePolygon, SimplePolygon)],
) -> Vec<Row> {
    let mut ws = SweepWorkspace::default();
    let (mut lists, mut events) = (ListWorkspace::default(), Vec::new());
    let mut out = Vec::new();
    let (mut points, mut division_points, mut candidates, mut tests) = (vec![], vec![], vec![], vec![]);
    let mut wrong = 0;
    for (p, q) in polys {
        let want = Brute.crossings(p, q);
        Sweep.crossings_in(Exact, p, q, &mut ws, &mut out);
        wrong += usize::from(out != want);
        points.push(want.len() as f64);
        division_brute(p, q, &mut out);
        division_points.push(out.len() as f64);
        let work = ListSweep::work(p, q);
        candidates.push(work.candidates as f64);
        tests.push(work.tests as f64);
    }
    let (points, division_points) = (median(&mut points), median(&mut division_points));
    let (candidates, tests) = (median(&mut candidates), median(&mut tests));
    ALGORITHMS
        .iter()
        .map(|&alg| {
            let mut times: Vec<f64> = polys
                .iter()
                .map(|(p, q)| {
                    time_per_query(config.min_time, || {
                        match alg {
                            "sweep" => Sweep.crossings_in(Exact, p, q, &mut ws, &mut out),
                            "brute" => out = Brute.crossings(p, q),
                            "brute-nobox" => nobox_brute(p, q, &mut out),
                            "brute-division" => division_brute(p, q, &mut out),
                            _ => division_sweep(p, q, &mut events, &mut lists, &mut out),
                        }
                        black_box(out.len()) > 0
                    })
                })
                .collect();
            Row {
                dist,
                param,
                n,
                alg,
                pairs: polys.len(),
                median_ns: median(&mut times),
                points,
                division_points,
                candidates,
                tests,
                wrong,
            }
        })
        .collect()
}

/// Tables in the report's layout, with the ratios and the pair counts.
fn summary(rows: &[Row], dists: &[(&'static str, f64, PointDistribution)]) -> String {
    let mut t = String::from(
        "| distribution | n = m | points | brute | brute-nobox | brute-division | sweep | sweep-division | brute / sweep | brute-division / sweep-division | n·m / candidates | wrong |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for &(dist, param, _) in dists {
        let sizes: Vec<usize> = {
            let mut s: Vec<usize> = rows.iter().filter(|r| r.dist == dist).map(|r| r.n).collect();
            s.sort_unstable();
            s.dedup();
            s
        };
        for n in sizes {
            let at = |alg: &str| {
                rows.iter()
                    .find(|r| r.dist == dist && r.param == param && r.n == n && r.alg == alg)
            };
            let (Some(s), Some(b), Some(nb), Some(d), Some(sd)) = (
                at("sweep"),
                at("brute"),
                at("brute-nobox"),
                at("brute-division"),
                at("sweep-division"),
            ) else {
                continue;
            };
            let symbol = if dist == "uniform" { "Δ" } else { "σ" };
            t.push_str(&format!(
                "| {dist} {symbol} = {param} | {n} | {} | {} | {} | {} | {} | {} | {:.1}× | {:.1}× | {:.1} | {} |\n",
                s.points,
                short_ns(b.median_ns),
                short_ns(nb.median_ns),
                short_ns(d.median_ns),
                short_ns(s.median_ns),
                short_ns(sd.median_ns),
                b.median_ns / s.median_ns,
                d.median_ns / sd.median_ns,
                (n * n) as f64 / s.candidates.max(1.0),
                s.wrong,
            ));
        }
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn division_brute_finds_proper_crossings() {
        let p = SimplePolygon::new([[0., 0.], [4., 0.], [4., 4.], [0., 4.]]).unwrap();
        let q = SimplePolygon::new([[2., -1.], [6., 2.], [2., 5.]]).unwrap();
        let mut out = Vec::new();
        division_brute(&p, &q, &mut out);
        out.sort_by(|a, b| a.lex_cmp(*b));
        let mut want = Brute.crossings(&p, &q);
        want.sort_by(|a, b| a.lex_cmp(*b));
        assert_eq!(out.len(), want.len());
        for (a, b) in out.iter().zip(&want) {
            assert!((a.x - b.x).abs() < 1e-12 && (a.y - b.y).abs() < 1e-12);
        }
        // Overlaps are invisible to it: identical squares give nothing.
        division_brute(&p, &p, &mut out);
        assert!(out.iter().all(|v| p.vertices().contains(v)));
    }
}
