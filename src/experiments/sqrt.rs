//! Experiment 5 of the thesis (4.3.1, Figure 4.6): CLM's time per query divided by
//! √(size(P) + size(Q)), which should level off to a constant if the expected time is
//! O(√n).

use super::plot::Chart;
use super::scaling::{Point, csv, draw, measure_grid, relation_name, series, short_ns, sizes};
use super::{Config, Report};
use crate::generate::Family;
use crate::intersect::Algorithm;
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
