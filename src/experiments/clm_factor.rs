//! CLM's sample-size constant: time per query against c (samples of ⌈c·√n⌉ vertices
//! per polygon) at a few sizes, on rotated ellipses: the median over the pairs of each
//! relation apart (pooled, the median of half cheap intersecting and half costly
//! disjoint queries falls between the two groups and says nothing). The table shows
//! the disjoint medians, which the choice of c is about; the CSV has both. Each pair
//! times all factors in turn, three rounds (its time is the median of the three).

use super::measure::{median, time_per_query};
use super::plot::{Chart, Series};
use super::scaling::{draw, pairs, relation_name, short_ns};
use super::{Config, Csv, Report, ns};
use crate::generate::{Family, Relation};
use std::io;

pub(crate) fn run(config: &Config) -> io::Result<Report> {
    let bar = super::progress(config, "clm-factor", config.factor_log2_sizes.len() * 2);
    let mut csv = Csv::new(&[
        "n",
        "relation",
        "factor",
        "pairs",
        "median_ns",
        "ns_per_sqrt_total",
    ]);
    let mut series: Vec<Series> = Vec::new();
    let mut t = String::from("Disjoint pairs, median time per query:\n\n| n |");
    for c in &config.factors {
        t.push_str(&format!(" c = {c} |"));
    }
    t.push_str("\n|---|");
    t.push_str(&"---|".repeat(config.factors.len()));
    t.push('\n');
    for &l in &config.factor_log2_sizes {
        let n = 1usize << l;
        let count = config.pairs_for(n);
        let mut prepared = Vec::new();
        for relation in [Relation::Intersecting, Relation::Disjoint] {
            bar.set_message(format!("generating n={n}"));
            prepared.push((relation, pairs(config, Family::Rotated, relation, n, count)));
            bar.inc(1);
        }
        let total = 2.0 * n as f64;
        let mut s = Series::new(format!("n = 2^{l}, disjoint"), Vec::new());
        t.push_str(&format!("| 2^{l} |"));
        // Every pair times every factor in turn, three rounds, so that a change of the
        // machine's load falls on all factors alike; each pair's time is its median.
        let mut cells = Vec::new();
        for (relation, pairs) in &mut prepared {
            let mut times = vec![vec![Vec::new(); pairs.len()]; config.factors.len()];
            for _ in 0..3 {
                for (i, pp) in pairs.iter_mut().enumerate() {
                    for (f, &c) in config.factors.iter().enumerate() {
                        times[f][i].push(time_per_query(config.min_time, || pp.query_clm_factor(c)));
                    }
                }
            }
            for (f, per_pair) in times.iter_mut().enumerate() {
                let mut medians: Vec<f64> = per_pair.iter_mut().map(|ts| median(ts)).collect();
                cells.push((f, *relation, pairs.len(), median(&mut medians)));
            }
        }
        cells.sort_by_key(|&(f, relation, _, _)| (f, relation != Relation::Intersecting));
        for (f, relation, count, m) in cells {
            let c = config.factors[f];
            csv.row(&[
                n.to_string(),
                relation_name(relation).into(),
                c.to_string(),
                count.to_string(),
                ns(m),
                ns(m / total.sqrt()),
            ]);
            if relation == Relation::Disjoint {
                s.points.push((c, m / total.sqrt()));
                t.push_str(&format!(" {} |", short_ns(m)));
            }
        }
        t.push('\n');
        series.push(s);
    }
    bar.finish();
    let mut report = Report::default();
    csv.write(&config.out, "clm_factor.csv", &mut report)?;
    let chart = Chart {
        title: "CLM, disjoint pairs: time / sqrt(2n) against the sample factor c",
        x_label: "c (samples of c*sqrt(n) vertices)",
        y_label: "ns / sqrt(2n)",
        log2_x: true,
        log_y: false,
        scatter: false,
    };
    draw(config, &mut report, "clm_factor.svg", &chart, &series)?;
    report.summary = t;
    Ok(report)
}
