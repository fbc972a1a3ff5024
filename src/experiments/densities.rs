//! Experiment 4 of the thesis (4.2.4): the O(log n) tests and CLM on rotated ellipses
//! with uniformly distributed angles against angles from random piecewise-linear
//! densities (clustered vertices, sparse stretches).

use super::plot::Chart;
use super::scaling::{Point, csv, draw, measure_grid, relation_name, series, sizes, table};
use super::{Config, Report};
use crate::generate::{Family, Relation};
use crate::intersect::Algorithm;
use crate::kernel::Precision;
use std::io;

pub(crate) fn run(config: &Config) -> io::Result<Report> {
    let families = [Family::Rotated, Family::NonUniform];
    let sizes = sizes(config);
    let algs: Vec<(Algorithm, Precision)> = Algorithm::LOGARITHMIC
        .iter()
        .chain(&[Algorithm::Clm])
        .map(|&a| (a, Precision::Exact))
        .collect();
    let bar = super::progress(config, "densities", families.len() * sizes.len() * 2);
    let points = measure_grid(config, &bar, &families, &sizes, &algs);
    let mut report = Report::default();
    csv(&points).write(&config.out, "densities.csv", &mut report)?;
    for relation in [Relation::Intersecting, Relation::Disjoint] {
        let r = relation_name(relation);
        let title = format!("uniform (rotated) vs non-uniform densities, {r}");
        let chart = Chart {
            title: &title,
            x_label: "n (vertices per polygon)",
            y_label: "ns per query",
            log2_x: true,
            log_y: true,
            scatter: false,
        };
        let s = series(
            &points,
            |p: &Point| p.relation == relation,
            |p| {
                format!(
                    "{} {}",
                    p.alg,
                    if p.family == Family::Rotated {
                        "uniform"
                    } else {
                        "non-uniform"
                    }
                )
            },
            |p| p.median_ns,
        );
        draw(config, &mut report, &format!("densities_{r}.svg"), &chart, &s)?;
    }
    report.summary = table(&points, &families);
    Ok(report)
}
