//! `polysect demo`: the main job. A scene of editable polygons runs through mixed
//! edit/query workloads under every strategy; every answer is checked against the exact
//! reference; the scene is drawn as SVG.

use indicatif::{HumanDuration, ProgressBar, ProgressState, ProgressStyle};
use polysect::Exact;
use polysect::render::{Panel, Style, Swatch, svg};
use polysect::store::Strategy;
use polysect::store::workload::{self, WorkloadSpec};
use std::io::{self, Write};
use std::time::{Duration, Instant};

/// The demo refuses options whose scene would need more memory than this (bytes).
pub const MEMORY_LIMIT: u64 = 4_000_000_000;

/// Bytes per vertex of a scene polygon while the demo runs: the linked polygon's node
/// (32) and handle slot (about 40 with the slab's bookkeeping), its array snapshot (16)
/// and the generator's temporary copies (about 24); measured peaks stay below this.
const BYTES_PER_VERTEX: u64 = 112;

/// The expected memory of the demo's scene: `polygons` of sizes log-uniform in
/// 2^3..=2^max_log2, so of mean (2^(max+1) − 8) / (max − 2) vertices.
pub fn estimated_bytes(polygons: usize, max_log2: u32) -> u64 {
    let max = max_log2.clamp(3, 62);
    let mean = ((1u128 << (max + 1)) - 8) / u128::from(max - 2);
    let total = polygons as u128 * mean * u128::from(BYTES_PER_VERTEX);
    u64::try_from(total).unwrap_or(u64::MAX)
}

/// Vertices drawn per polygon at most (every k-th vertex beyond): the picture of a
/// 2^18-gon is the same at this size, and the file stays small.
const DRAWN_VERTICES: usize = 720;

pub fn run(polygons: usize, max_log2: u32, steps: usize, seed: u64, svg_path: &str) -> io::Result<()> {
    let started = Instant::now();
    // Create the picture's file first, so an unwritable path fails before the work.
    let mut picture_file = if svg_path == "-" {
        None
    } else {
        Some(
            std::fs::File::create(svg_path)
                .map_err(|e| io::Error::new(e.kind(), format!("cannot write {svg_path}: {e}")))?,
        )
    };
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
        "Other commands: polysect check | crossings | scene | gen | render | bench | serve | list | --help\n"
    )?;
    let specs = WorkloadSpec::standard(steps, seed);
    let bar = ProgressBar::new((specs.len() * Strategy::ALL.len() * steps) as u64);
    bar.set_style(
        ProgressStyle::with_template("{msg:>22} [{bar:30}] {pos}/{len} ops {left}")
            .expect("valid template")
            .with_key("left", time_left)
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
    writeln!(
        out,
        "Planner: its total query time divided by that of each fixed strategy on the same \
         operations\n(below 1: the planner was faster; above 1: slower; it aims to stay within 1.2x \
         of the best):"
    )?;
    for spec in &specs {
        let of = |st: Strategy| {
            rows.iter()
                .find(|r| r.0 == spec.name && r.1 == st)
                .filter(|r| r.2.queries > 0)
                .map(|r| r.2.query_time.as_secs_f64())
        };
        let fixed = [Strategy::Sampled, Strategy::Convert, Strategy::Cached];
        let best = fixed
            .iter()
            .filter_map(|&st| of(st).map(|t| (t, st)))
            .min_by(|a, b| a.0.total_cmp(&b.0));
        let worst = fixed
            .iter()
            .filter_map(|&st| of(st).map(|t| (t, st)))
            .max_by(|a, b| a.0.total_cmp(&b.0));
        match (best, worst, of(Strategy::Planner)) {
            (Some((best_t, best_s)), Some((worst_t, worst_s)), Some(planner)) if best_t > 0.0 => writeln!(
                out,
                "{:<12} planner = {:.2}x the best fixed strategy ({}), {:.2}x the slowest ({})",
                spec.name,
                planner / best_t,
                best_s.name(),
                planner / worst_t,
                worst_s.name()
            )?,
            _ => writeln!(out, "{:<12} no queries to compare", spec.name)?,
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

    // The scene of the table, as every run started from it, with its intersecting
    // polygons highlighted.
    let mut scene = workload::scattered_scene(Exact, polygons, max_log2, 3.0, seed);
    let pairs = scene.intersecting_pairs();
    let ids: Vec<_> = scene.ids().collect();
    let mut panel = Panel::default();
    let (mut hit_count, mut thinned) = (0, false);
    for &id in &ids {
        let hit = pairs.iter().any(|&(a, b)| a != b && (a == id || b == id));
        hit_count += usize::from(hit);
        let polygon = scene.polygon(id).expect("live").to_convex();
        let step = polygon.len().div_ceil(DRAWN_VERTICES);
        thinned |= step > 1;
        let verts = polygon.vertices().iter().step_by(step).copied().collect();
        panel
            .polygons
            .push((verts, if hit { Style::Highlight } else { Style::Plain }));
    }
    panel.caption = format!(
        "The demo's scene (seed {seed}) before its workloads: {} polygons, 2^3 to 2^{max_log2} \
         vertices{}, {} intersecting pairs.",
        ids.len(),
        if thinned {
            format!(" (drawn with at most {DRAWN_VERTICES})")
        } else {
            String::new()
        },
        pairs.len(),
    );
    let red = format!("intersects another polygon ({hit_count})");
    let blue = format!("intersects none ({})", ids.len() - hit_count);
    let legend = [
        (Swatch::Fill(Style::Highlight), red.as_str()),
        (Swatch::Fill(Style::Plain), blue.as_str()),
    ];
    let text = svg(&[panel], 1, 640.0, &legend);
    match &mut picture_file {
        Some(file) => {
            file.write_all(text.as_bytes())
                .and_then(|()| file.flush())
                .map_err(|e| io::Error::new(e.kind(), format!("cannot write {svg_path}: {e}")))?;
            writeln!(
                out,
                "\nWrote {svg_path}: the scene above, polygons that intersect another in red."
            )?;
        }
        None => out.write_all(text.as_bytes())?,
    }
    writeln!(out, "Done in {:.0} s.", started.elapsed().as_secs_f64())?;
    out.flush()?;
    if all_agree {
        Ok(())
    } else {
        Err(io::Error::other("answers disagreed with the exact reference"))
    }
}

/// The progress bar's estimate of the time left, shown once it means something (after
/// 2 s and 3% of the operations); until then the bar says it is estimating.
fn time_left(state: &ProgressState, w: &mut dyn std::fmt::Write) {
    let len = state.len().unwrap_or(0);
    if state.elapsed() < Duration::from_secs(2) || state.pos() * 33 < len {
        let _ = w.write_str("(estimating the time left)");
    } else {
        let _ = write!(w, "(about {} left)", HumanDuration(state.eta()));
    }
}
