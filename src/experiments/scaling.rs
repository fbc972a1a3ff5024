//! Experiments 1–3 of the thesis (4.2.1–4.2.3): time and iterations per query against
//! n for every algorithm, intersecting and disjoint pairs measured separately, on
//! unrotated ellipses starting at the leftmost vertex (experiment 1) and on rotated
//! ellipses with a random start index (experiment 3). Also the measuring loop shared by
//! the other curve experiments ([`measure`]).

use super::measure::{median, time_per_query};
use super::plot::{self, Chart, Series};
use super::{Config, Csv, PreparedPair, Report, ns};
use crate::generate::{self, Family, Relation};
use crate::intersect::Algorithm;
use crate::kernel::Precision;
use indicatif::ProgressBar;
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::io;

/// One measured point of a curve.
#[derive(Clone, Debug)]
pub(crate) struct Point {
    pub family: Family,
    pub relation: Relation,
    pub alg: Algorithm,
    pub precision: Precision,
    /// The requested vertices per polygon.
    pub n: usize,
    /// Mean of size(P) + size(Q) over the pairs (the thesis's input size).
    pub total: f64,
    pub pairs: usize,
    pub median_ns: f64,
    pub median_iterations: f64,
    /// Pairs where the answer differed from the exact one.
    pub wrong: usize,
}

impl Point {
    pub fn per_log(&self) -> f64 {
        self.median_ns / self.total.log2()
    }
    pub fn per_sqrt(&self) -> f64 {
        self.median_ns / self.total.sqrt()
    }
}

pub(crate) fn relation_name(r: Relation) -> &'static str {
    match r {
        Relation::Any => "any",
        Relation::Intersecting => "intersecting",
        Relation::Disjoint => "disjoint",
    }
}

/// The pairs of one curve point: `count` pairs of `family` with n vertices per polygon,
/// steered by `relation`, reproducible from the config's seed.
pub(crate) fn pairs(
    config: &Config,
    family: Family,
    relation: Relation,
    n: usize,
    count: usize,
) -> Vec<PreparedPair> {
    let salt =
        (n as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ (family as u64) << 48 ^ (relation as u64) << 56;
    let mut rng = SmallRng::seed_from_u64(config.seed ^ salt);
    (0..count)
        .map(|i| {
            let (p, q) = generate::pair(family, n, relation, &mut rng);
            PreparedPair::new(p, q, config.seed ^ salt ^ i as u64)
        })
        .collect()
}

/// Measures every (algorithm, precision) on fresh pairs of one family, relation and n.
pub(crate) fn measure(
    config: &Config,
    family: Family,
    relation: Relation,
    n: usize,
    algs: &[(Algorithm, Precision)],
) -> Vec<Point> {
    let mut prepared = pairs(config, family, relation, n, config.pairs_for(n));
    let total = prepared
        .iter()
        .map(|pp| (pp.p.len() + pp.q.len()) as f64)
        .sum::<f64>()
        / prepared.len() as f64;
    algs.iter()
        .map(|&(alg, precision)| {
            let mut times = Vec::new();
            let mut iterations = Vec::new();
            let mut wrong = 0;
            for pp in prepared.iter_mut() {
                let (answer, it) = pp.iterations(alg, precision);
                wrong += usize::from(answer != pp.truth);
                iterations.push(it as f64);
                times.push(time_per_query(config.min_time, || pp.query(alg, precision)));
            }
            Point {
                family,
                relation,
                alg,
                precision,
                n,
                total,
                pairs: prepared.len(),
                median_ns: median(&mut times),
                median_iterations: median(&mut iterations),
                wrong,
            }
        })
        .collect()
}

/// Measures every (family, relation, n) of a curve experiment with a progress bar.
pub(crate) fn measure_grid(
    config: &Config,
    bar: &ProgressBar,
    families: &[Family],
    sizes: &[usize],
    algs: &[(Algorithm, Precision)],
) -> Vec<Point> {
    let mut points = Vec::new();
    for &family in families {
        for &n in sizes {
            for relation in [Relation::Intersecting, Relation::Disjoint] {
                bar.set_message(format!("{family} {} n={n}", relation_name(relation)));
                points.extend(measure(config, family, relation, n, algs));
                bar.inc(1);
            }
        }
    }
    bar.finish();
    points
}

pub(crate) const CSV_HEADER: [&str; 13] = [
    "family",
    "relation",
    "algorithm",
    "kernel",
    "n",
    "total_vertices",
    "pairs",
    "median_ns",
    "ns_per_log2_total",
    "ns_per_sqrt_total",
    "median_iterations",
    "wrong",
    "log2_n",
];

pub(crate) fn csv(points: &[Point]) -> Csv {
    let mut csv = Csv::new(&CSV_HEADER);
    for p in points {
        csv.row(&[
            p.family.to_string(),
            relation_name(p.relation).into(),
            p.alg.to_string(),
            p.precision.to_string(),
            p.n.to_string(),
            format!("{:.1}", p.total),
            p.pairs.to_string(),
            ns(p.median_ns),
            ns(p.per_log()),
            ns(p.per_sqrt()),
            format!("{:.1}", p.median_iterations),
            p.wrong.to_string(),
            format!("{:.2}", (p.n as f64).log2()),
        ]);
    }
    csv
}

/// One series per distinct `key` among the points passing `keep`, with y = `y(point)`.
pub(crate) fn series(
    points: &[Point],
    keep: impl Fn(&Point) -> bool,
    key: impl Fn(&Point) -> String,
    y: impl Fn(&Point) -> f64,
) -> Vec<Series> {
    let mut out: Vec<Series> = Vec::new();
    for p in points.iter().filter(|p| keep(p)) {
        let k = key(p);
        let xy = (p.n as f64, y(p));
        match out.iter_mut().find(|s| s.name == k) {
            Some(s) => s.points.push(xy),
            None => out.push(Series::new(k, vec![xy])),
        }
    }
    out
}

pub(crate) fn sizes(config: &Config) -> Vec<usize> {
    config.log2_sizes.iter().map(|&l| 1usize << l).collect()
}

pub(crate) fn draw(
    config: &Config,
    report: &mut Report,
    name: &str,
    chart: &Chart<'_>,
    series: &[Series],
) -> io::Result<()> {
    let path = config.out.join(name);
    plot::draw(&path, chart, series).map_err(super::naming(&path, "cannot write"))?;
    report.files.push(name.to_string());
    Ok(())
}

pub(crate) fn run(config: &Config) -> io::Result<Report> {
    let families = [Family::Ellipse, Family::Rotated];
    let sizes = sizes(config);
    let algs: Vec<(Algorithm, Precision)> = Algorithm::ALL.iter().map(|&a| (a, Precision::Exact)).collect();
    let bar = super::progress(config, "scaling", families.len() * sizes.len() * 2);
    let points = measure_grid(config, &bar, &families, &sizes, &algs);
    let mut report = Report::default();
    csv(&points).write(&config.out, "scaling.csv", &mut report)?;
    let log_algs = |p: &Point| Algorithm::LOGARITHMIC.contains(&p.alg);
    for family in families {
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            let r = relation_name(relation);
            let keep = |p: &Point| p.family == family && p.relation == relation;
            let by_alg = |p: &Point| p.alg.to_string();
            let title = format!("time per query, {family}, {r} (exact kernel)");
            let chart = Chart {
                title: &title,
                x_label: "n (vertices per polygon)",
                y_label: "ns per query",
                log2_x: true,
                log_y: true,
                scatter: false,
            };
            let s = series(&points, keep, by_alg, |p| p.median_ns);
            draw(config, &mut report, &format!("time_{family}_{r}.svg"), &chart, &s)?;
            let title = format!("time / log2(2n), {family}, {r}");
            let chart = Chart {
                title: &title,
                y_label: "ns / log2(2n)",
                log_y: false,
                ..chart
            };
            let s = series(&points, |p| keep(p) && log_algs(p), by_alg, Point::per_log);
            draw(
                config,
                &mut report,
                &format!("time_per_log_{family}_{r}.svg"),
                &chart,
                &s,
            )?;
            let title = format!("time / sqrt(2n), {family}, {r}");
            let chart = Chart {
                title: &title,
                y_label: "ns / sqrt(2n)",
                log_y: true,
                ..chart
            };
            let s = series(&points, keep, by_alg, Point::per_sqrt);
            draw(
                config,
                &mut report,
                &format!("time_per_sqrt_{family}_{r}.svg"),
                &chart,
                &s,
            )?;
        }
        let keep = |p: &Point| p.family == family && log_algs(p);
        let by_alg_rel = |p: &Point| format!("{} {}", p.alg, relation_name(p.relation));
        let title = format!("iterations per query, {family}");
        let chart = Chart {
            title: &title,
            x_label: "n (vertices per polygon)",
            y_label: "iterations (median)",
            log2_x: true,
            log_y: false,
            scatter: false,
        };
        let s = series(&points, keep, by_alg_rel, |p| p.median_iterations);
        draw(
            config,
            &mut report,
            &format!("iterations_{family}.svg"),
            &chart,
            &s,
        )?;
        let title = format!("intersecting vs disjoint, {family}");
        let chart = Chart {
            title: &title,
            y_label: "ns per query",
            ..chart
        };
        let s = series(&points, keep, by_alg_rel, |p| p.median_ns);
        draw(
            config,
            &mut report,
            &format!("intersecting_vs_disjoint_{family}.svg"),
            &chart,
            &s,
        )?;
    }
    report.summary = table(&points, &[Family::Rotated]);
    Ok(report)
}

/// A markdown table: median time per query for each algorithm (rows) at each n
/// (columns), intersecting / disjoint, each cell with its unit.
pub(crate) fn table(points: &[Point], families: &[Family]) -> String {
    let mut out = String::new();
    for &family in families {
        let mut ns_list: Vec<usize> = points
            .iter()
            .filter(|p| p.family == family)
            .map(|p| p.n)
            .collect();
        ns_list.dedup();
        ns_list.sort_unstable();
        ns_list.dedup();
        let mut algs: Vec<(Algorithm, Precision)> = Vec::new();
        for p in points.iter().filter(|p| p.family == family) {
            if !algs.contains(&(p.alg, p.precision)) {
                algs.push((p.alg, p.precision));
            }
        }
        out.push_str(&format!(
            "{family}: median time per query (ns, µs or ms as marked), intersecting / disjoint\n\n| algorithm |"
        ));
        for n in &ns_list {
            out.push_str(&format!(" 2^{} |", n.trailing_zeros()));
        }
        out.push_str("\n|---|");
        out.push_str(&"---|".repeat(ns_list.len()));
        out.push('\n');
        for &(alg, precision) in &algs {
            out.push_str(&format!("| {alg} ({precision}) |"));
            for &n in &ns_list {
                let get = |r| {
                    points
                        .iter()
                        .find(|p| {
                            p.family == family
                                && p.alg == alg
                                && p.precision == precision
                                && p.n == n
                                && p.relation == r
                        })
                        .map_or("–".to_string(), |p| short_ns(p.median_ns))
                };
                out.push_str(&format!(
                    " {} / {} |",
                    get(Relation::Intersecting),
                    get(Relation::Disjoint)
                ));
            }
            out.push('\n');
        }
        out.push('\n');
    }
    out
}

/// A time given in ns, written in ns, µs, ms or s with its unit and 3 significant
/// digits (`812 ns`, `1.25 µs`, `43.1 ms`).
pub(crate) fn short_ns(t: f64) -> String {
    if !t.is_finite() {
        return "–".into();
    }
    let (v, unit) = if t >= 1e9 {
        (t / 1e9, "s")
    } else if t >= 1e6 {
        (t / 1e6, "ms")
    } else if t >= 1e3 {
        (t / 1e3, "µs")
    } else {
        (t, "ns")
    };
    let decimals = if v >= 100.0 {
        0
    } else if v >= 10.0 {
        1
    } else {
        2
    };
    format!("{v:.decimals$} {unit}")
}

#[cfg(test)]
mod tests {
    use super::short_ns;

    #[test]
    fn times_carry_their_unit_and_three_digits() {
        assert_eq!(short_ns(812.3), "812 ns");
        assert_eq!(short_ns(1.5), "1.50 ns");
        assert_eq!(short_ns(1_254.0), "1.25 µs");
        assert_eq!(short_ns(43_120_000.0), "43.1 ms");
        assert_eq!(short_ns(2.5e9), "2.50 s");
        assert_eq!(short_ns(f64::NAN), "–");
    }
}
