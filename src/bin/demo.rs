//! `polysect demo`: the main job. A scene of editable polygons runs through mixed
//! edit/query workloads under every strategy; every answer is checked against the exact
//! reference; a small scene is drawn as SVG.

use indicatif::{ProgressBar, ProgressStyle};
use polysect::Exact;
use polysect::render::{Panel, Style, svg};
use polysect::store::Strategy;
use polysect::store::workload::{self, WorkloadSpec};
use std::io::{self, Write};

pub fn run(polygons: usize, max_log2: u32, steps: usize, seed: u64, svg_path: &str) -> io::Result<()> {
    let mut out = io::stdout().lock();
    writeln!(
        out,
        "polysect: dynamic convex polygons with sublinear intersection queries.\n"
    )?;
    writeln!(
        out,
        "Demo: a scene of {polygons} editable convex polygons (2^3 to 2^{max_log2} vertices each),"
    )?;
    writeln!(
        out,
        "{steps} operations per workload, every answer checked against the exact O(n+m) test."
    )?;
    writeln!(
        out,
        "Other commands: polysect check | crossings | gen | render | calibrate | list | --help\n"
    )?;
    let specs = WorkloadSpec::standard(steps, seed);
    let bar = ProgressBar::new((specs.len() * Strategy::ALL.len() * steps) as u64);
    bar.set_style(
        ProgressStyle::with_template("{msg:>22} [{bar:30}] {pos}/{len} ops ({eta})")
            .expect("valid template")
            .progress_chars("=> "),
    );
    let mut rows = Vec::new();
    for spec in &specs {
        for strategy in Strategy::ALL {
            bar.set_message(format!("{} / {}", spec.name, strategy.name()));
            let mut scene = workload::scattered_scene(Exact, polygons, max_log2, 3.0, seed);
            scene.set_strategy(strategy);
            let report = workload::run(&mut scene, spec, true, || bar.inc(1));
            rows.push((spec.name, strategy, report, scene.stats(), scene.snapshot_count()));
        }
    }
    bar.finish_and_clear();
    writeln!(
        out,
        "{:<12} {:<8} {:>7} {:>6} {:>11} {:>8} {:>8} {:>7} {:>7} {:>9} {:>11}",
        "workload",
        "strategy",
        "queries",
        "edits",
        "queries/s",
        "sampled",
        "arrays",
        "boxes",
        "convert",
        "snapshots",
        "agree"
    )?;
    let mut all_agree = true;
    for (name, strategy, r, s, snaps) in &rows {
        all_agree &= r.mismatches == 0;
        writeln!(
            out,
            "{:<12} {:<8} {:>7} {:>6} {:>11.0} {:>8} {:>8} {:>7} {:>7} {:>9} {:>11}",
            name,
            strategy.name(),
            r.queries,
            r.edits,
            r.queries_per_second(),
            s.sampled_tests,
            s.array_tests,
            s.box_rejects,
            s.conversions + s.throwaway_conversions,
            snaps,
            format!("{}/{}", r.checked - r.mismatches, r.checked)
        )?;
    }
    writeln!(out)?;
    for spec in &specs {
        let of = |st: Strategy| {
            rows.iter()
                .find(|r| r.0 == spec.name && r.1 == st)
                .map(|r| r.2.query_time.as_secs_f64())
        };
        let fixed = [Strategy::Sampled, Strategy::Convert, Strategy::Cached];
        let best = fixed
            .iter()
            .filter_map(|&st| of(st).map(|t| (t, st)))
            .min_by(|a, b| a.0.total_cmp(&b.0));
        let worst = fixed.iter().filter_map(|&st| of(st)).fold(0.0, f64::max);
        if let (Some((best_t, best_s)), Some(planner)) = (best, of(Strategy::Planner)) {
            writeln!(
                out,
                "{:<12} planner query time = {:.2}× the best fixed strategy ({}), {:.2}× the worst",
                spec.name,
                planner / best_t,
                best_s.name(),
                planner / worst.max(1e-12)
            )?;
        }
    }
    writeln!(
        out,
        "\n(sampled/arrays/boxes: how queries were answered; convert: arrays built; \
         snapshots: kept at the end; times measured on this machine, one run)"
    )?;
    if !all_agree {
        writeln!(
            out,
            "\nDISAGREEMENT with the exact reference: please report this as a bug."
        )?;
    }

    // A small scene, drawn with its intersecting polygons highlighted.
    let mut small = workload::scattered_scene(Exact, 14, 6, 3.0, seed);
    let pairs = small.intersecting_pairs();
    let mut panel = Panel {
        caption: format!("{} polygons, {} intersecting pairs", small.len(), pairs.len()),
        ..Panel::default()
    };
    for id in small.ids().collect::<Vec<_>>() {
        let hit = pairs.iter().any(|&(a, b)| a == id || b == id);
        let verts = small.polygon(id).expect("live").to_convex().into_vertices();
        panel
            .polygons
            .push((verts, if hit { Style::Highlight } else { Style::Plain }));
    }
    match std::fs::write(svg_path, svg(&[panel], 1)) {
        Ok(()) => writeln!(
            out,
            "\nWrote {svg_path}: a small scene, intersecting polygons in red."
        )?,
        Err(e) => writeln!(out, "\nCould not write {svg_path}: {e}")?,
    }
    if all_agree {
        Ok(())
    } else {
        Err(io::Error::other("answers disagreed with the exact reference"))
    }
}
