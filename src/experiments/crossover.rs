//! The conversion-versus-sampling crossover (thesis 4.4, Figure 4.8): on linked
//! polygons, CLM (expected O(√n)) against Convert (walk both lists into arrays, O(n),
//! then Barba), at sizes a half-power of two apart, and the n from which CLM stays
//! faster.

use super::measure::median;
use super::plot::Chart;
use super::scaling::{Point, csv, draw, measure, relation_name, series, short_ns};
use super::{Config, Report};
use crate::generate::{Family, Relation};
use crate::intersect::Algorithm;
use crate::kernel::Precision;
use std::io;

/// The smallest measured n from which `fast` beats `slow` at every larger measured n
/// (None when it never does at the largest).
pub(crate) fn crossover(sizes: &[usize], fast: &[f64], slow: &[f64]) -> Option<usize> {
    let mut from = None;
    for i in (0..sizes.len()).rev() {
        if fast[i] < slow[i] {
            from = Some(sizes[i]);
        } else {
            break;
        }
    }
    from
}

pub(crate) fn run(config: &Config) -> io::Result<Report> {
    let mut sizes: Vec<usize> = config
        .crossover_log2_sizes
        .iter()
        .map(|&h| 2f64.powf(h).round() as usize)
        .collect();
    sizes.dedup();
    let algs = [
        (Algorithm::Clm, Precision::Exact),
        (Algorithm::Convert, Precision::Exact),
    ];
    let bar = super::progress(config, "crossover", sizes.len() * 2);
    let mut points: Vec<Point> = Vec::new();
    for &n in &sizes {
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            bar.set_message(format!("{} n={n}", relation_name(relation)));
            points.extend(measure(config, Family::Rotated, relation, n, &algs));
            bar.inc(1);
        }
    }
    bar.finish();
    let mut report = Report::default();
    csv(&points).write(&config.out, "crossover.csv", &mut report)?;
    let chart = Chart {
        title: "CLM vs convert-then-Barba on linked polygons (rotated ellipses)",
        x_label: "n (vertices per polygon)",
        y_label: "ns per query",
        log2_x: true,
        log_y: true,
        scatter: false,
    };
    let s = series(
        &points,
        |_| true,
        |p: &Point| format!("{} {}", p.alg, relation_name(p.relation)),
        |p| p.median_ns,
    );
    draw(config, &mut report, "crossover.svg", &chart, &s)?;
    let time = |alg, r: Option<Relation>, n| {
        let mut v: Vec<f64> = points
            .iter()
            .filter(|p| p.alg == alg && p.n == n && r.is_none_or(|r| p.relation == r))
            .map(|p| p.median_ns)
            .collect();
        median(&mut v)
    };
    let mut t = String::from("| pairs | CLM faster from n = |\n|---|---|\n");
    for (label, r) in [
        ("intersecting", Some(Relation::Intersecting)),
        ("disjoint", Some(Relation::Disjoint)),
        ("both (mean of the medians)", None),
    ] {
        let clm: Vec<f64> = sizes.iter().map(|&n| time(Algorithm::Clm, r, n)).collect();
        let conv: Vec<f64> = sizes.iter().map(|&n| time(Algorithm::Convert, r, n)).collect();
        let at = crossover(&sizes, &clm, &conv).map_or("not within the sizes measured".into(), |n| {
            format!("{n} (2^{:.1})", (n as f64).log2())
        });
        t.push_str(&format!("| {label} | {at} |\n"));
    }
    t.push_str("\n| n | CLM int. | convert int. | CLM disj. | convert disj. |\n|---|---|---|---|---|\n");
    for &n in &sizes {
        t.push_str(&format!(
            "| {n} | {} | {} | {} | {} |\n",
            short_ns(time(Algorithm::Clm, Some(Relation::Intersecting), n)),
            short_ns(time(Algorithm::Convert, Some(Relation::Intersecting), n)),
            short_ns(time(Algorithm::Clm, Some(Relation::Disjoint), n)),
            short_ns(time(Algorithm::Convert, Some(Relation::Disjoint), n)),
        ));
    }
    report.summary = t;
    Ok(report)
}

#[cfg(test)]
mod tests {
    use super::crossover;

    #[test]
    fn crossover_is_the_start_of_the_final_winning_run() {
        let sizes = [1, 2, 4, 8, 16];
        assert_eq!(
            crossover(&sizes, &[5., 1., 5., 1., 1.], &[2., 2., 2., 2., 2.]),
            Some(8)
        );
        assert_eq!(crossover(&sizes, &[1.; 5], &[2.; 5]), Some(1));
        assert_eq!(crossover(&sizes, &[1., 1., 1., 1., 3.], &[2.; 5]), None);
    }
}
