//! Experiment 5 of the thesis (4.3.1, Figure 4.6): CLM's time per query divided by
//! √(size(P) + size(Q)), which should level off to a constant if the expected time is
//! O(√n). Also CLM's counts per query on the same pairs (`clm_counts.csv`,
//! `clm_counts.svg`): samples, LP calls, constraints and examined points per LP, chain
//! walks and vertices per walk, kept apart.

use super::plot::Chart;
use super::plot::Series;
use super::scaling::{Point, csv, draw, measure_grid, pairs, relation_name, series, short_ns, sizes};
use super::{Config, Csv, Report};
use crate::generate::{Family, Relation};
use crate::intersect::{Algorithm, Counts, CountsSummary};
use crate::kernel::Precision;
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
    report.summary = t;
    Ok(report)
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
