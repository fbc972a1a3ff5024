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

/// The fixed strategies the planner is compared with.
const FIXED: [Strategy; 3] = [Strategy::Sampled, Strategy::Convert, Strategy::Cached];

/// Runs of the planner comparison: the ratio printed is their median.
const TIMING_RUNS: usize = 21;

/// Fixed strategies slower than this multiple of the best in the checked run are not
/// timed again (they cannot be the best; the convert strategy is often 50x slower).
const CONTENDER_FACTOR: f64 = 3.0;

/// The planner's aim: at most this multiple of the best fixed strategy's query time.
const AIM: f64 = 1.2;

/// The planner against the best fixed strategy over several runs.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Comparison {
    /// The fixed strategy with the least median query time.
    best: Strategy,
    /// Over the runs, of planner time / best fixed time in the same run: the median,
    /// the least and greatest, and the quartiles (nearest rank: the middle half of the
    /// runs lies between them).
    median: f64,
    low: f64,
    high: f64,
    quartiles: (f64, f64),
}

/// The comparison from `times[run][k]`, the query time of `strategies[k]` in each run
/// (the planner among them). `None` when there is no planner, no fixed strategy, no run
/// or a zero time (no queries).
fn planner_ratio(strategies: &[Strategy], times: &[Vec<f64>]) -> Option<Comparison> {
    let planner = strategies.iter().position(|&s| s == Strategy::Planner)?;
    let fixed: Vec<usize> = (0..strategies.len()).filter(|&k| k != planner).collect();
    let median = |mut v: Vec<f64>| -> Option<f64> {
        if v.is_empty() {
            return None;
        }
        v.sort_by(f64::total_cmp);
        let m = v.len() / 2;
        Some(if v.len() % 2 == 1 {
            v[m]
        } else {
            (v[m - 1] + v[m]) / 2.0
        })
    };
    let best = fixed
        .iter()
        .filter_map(|&k| median(times.iter().map(|run| run[k]).collect()).map(|t| (t, k)))
        .min_by(|a, b| a.0.total_cmp(&b.0))?
        .1;
    let mut ratios = Vec::with_capacity(times.len());
    for run in times {
        let least = fixed.iter().map(|&k| run[k]).fold(f64::INFINITY, f64::min);
        if least <= 0.0 || !least.is_finite() {
            return None;
        }
        ratios.push(run[planner] / least);
    }
    ratios.sort_by(f64::total_cmp);
    let n = ratios.len();
    Some(Comparison {
        best: strategies[best],
        low: *ratios.first()?,
        high: *ratios.last()?,
        quartiles: (ratios[n / 4], ratios[(3 * n) / 4]),
        median: median(ratios)?,
    })
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
    let base = workload::scattered_scene(Exact, polygons, max_log2, 3.0, seed);
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
            let mut scene = base.clone();
            scene.set_strategy(strategy);
            let report = workload::run(&mut scene, spec, true, || bar.inc(1));
            rows.push((spec.name, strategy, report, scene.stats(), scene.snapshot_count()));
        }
    }
    // The planner comparison: the planner and the fixed strategies that could be the
    // best are timed again, without the checks, in interleaved runs.
    let contenders: Vec<Vec<Strategy>> = specs
        .iter()
        .map(|spec| {
            let time = |st: Strategy| {
                rows.iter()
                    .find(|r| r.0 == spec.name && r.1 == st)
                    .map_or(0.0, |r| r.2.query_time.as_secs_f64())
            };
            let best = FIXED.iter().map(|&st| time(st)).fold(f64::INFINITY, f64::min);
            let mut chosen: Vec<Strategy> = FIXED
                .iter()
                .copied()
                .filter(|&st| time(st) <= CONTENDER_FACTOR * best)
                .collect();
            chosen.push(Strategy::Planner);
            chosen
        })
        .collect();
    let timed_runs: u64 = contenders.iter().map(|c| c.len() as u64).sum::<u64>() * TIMING_RUNS as u64;
    bar.set_length(bar.length().unwrap_or(0) + timed_runs * steps as u64);
    // times[spec][run][strategy index in contenders[spec]]
    let mut times = vec![Vec::with_capacity(TIMING_RUNS); specs.len()];
    for run in 0..TIMING_RUNS {
        for (i, spec) in specs.iter().enumerate() {
            let mut this_run = Vec::new();
            for &strategy in &contenders[i] {
                bar.set_message(format!("timing {}/{TIMING_RUNS}: {}", run + 1, spec.name));
                let mut scene = base.clone();
                scene.set_strategy(strategy);
                let report = workload::run(&mut scene, spec, false, || bar.inc(1));
                this_run.push(report.query_time.as_secs_f64());
            }
            times[i].push(this_run);
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
        "Planner: its total query time divided by that of the best fixed strategy on the same \
         operations,\nthe median of {TIMING_RUNS} runs without the checks (in brackets: the middle half \
         of the runs and all of them;\nbelow 1: the planner was faster; above 1: slower; it aims to stay within \
         {AIM}x of the best):"
    )?;
    let mut missed = Vec::new();
    for (i, spec) in specs.iter().enumerate() {
        match planner_ratio(&contenders[i], &times[i]) {
            Some(c) => {
                let slowest = FIXED
                    .iter()
                    .filter_map(|&st| {
                        rows.iter()
                            .find(|r| r.0 == spec.name && r.1 == st)
                            .map(|r| (r.2.query_time.as_secs_f64(), st))
                    })
                    .max_by(|a, b| a.0.total_cmp(&b.0));
                let planner_first = rows
                    .iter()
                    .find(|r| r.0 == spec.name && r.1 == Strategy::Planner)
                    .map_or(0.0, |r| r.2.query_time.as_secs_f64());
                let slowest = match slowest {
                    Some((t, st)) if planner_first > 0.0 => {
                        format!(
                            ", the slowest ({}) took {:.0}x as long",
                            st.name(),
                            t / planner_first
                        )
                    }
                    _ => String::new(),
                };
                let mark = if c.median > AIM {
                    missed.push(spec.name);
                    "  <- above the aim"
                } else {
                    ""
                };
                writeln!(
                    out,
                    "{:<12} planner = {:.2}x the best fixed strategy ({}) [middle half {:.2}x to {:.2}x, \
                     all {:.2}x to {:.2}x]{slowest}{mark}",
                    spec.name,
                    c.median,
                    c.best.name(),
                    c.quartiles.0,
                    c.quartiles.1,
                    c.low,
                    c.high,
                )?
            }
            None => writeln!(out, "{:<12} no queries to compare", spec.name)?,
        }
    }
    if !missed.is_empty() {
        writeln!(
            out,
            "The planner missed its {AIM}x aim on {} in these runs (the ranges show how much runs \
             vary here);\nit plans from a cost model, which `polysect calibrate` measures for this machine.",
            missed.join(", ")
        )?;
    }
    writeln!(
        out,
        "\n(sampled/arrays/boxes: how queries were answered; convert: arrays built; \
         snapshots: kept at the end; the table's times are one run with the checks, on this machine)"
    )?;
    if !all_agree {
        writeln!(
            out,
            "\nDISAGREEMENT with the exact reference: please report this as a bug."
        )?;
    }

    // The scene of the table, as every run started from it, with its intersecting
    // polygons highlighted.
    let mut scene = base;
    let pairs = scene.intersecting_pairs();
    let ids: Vec<_> = scene.ids().collect();
    // Coloured by how many others each polygon meets: none, up to the median of those
    // that meet any, more (in a dense scene every polygon meets another).
    let degree = |id| {
        pairs
            .iter()
            .filter(|&&(a, b)| a != b && (a == id || b == id))
            .count()
    };
    let degrees: Vec<usize> = ids.iter().map(|&id| degree(id)).collect();
    let mut meeting: Vec<usize> = degrees.iter().copied().filter(|&d| d > 0).collect();
    meeting.sort_unstable();
    let median = meeting
        .get(meeting.len().saturating_sub(1) / 2)
        .copied()
        .unwrap_or(1);
    let style_of = |d: usize| match d {
        0 => Style::Plain,
        d if d <= median => Style::Other,
        _ => Style::Highlight,
    };
    let mut panel = Panel::default();
    let mut thinned = false;
    for (&id, &d) in ids.iter().zip(&degrees) {
        let polygon = scene.polygon(id).expect("live").to_convex();
        let step = polygon.len().div_ceil(DRAWN_VERTICES);
        thinned |= step > 1;
        let verts = polygon.vertices().iter().step_by(step).copied().collect();
        panel.polygons.push((verts, style_of(d)));
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
    let count = |style: Style| degrees.iter().filter(|&&d| style_of(d) == style).count();
    let others = |d: usize| if d == 1 { "other" } else { "others" };
    let red = format!(
        "intersects more than {median} {} ({})",
        others(median),
        count(Style::Highlight)
    );
    let teal = if median == 1 {
        format!("intersects 1 other ({})", count(Style::Other))
    } else {
        format!("intersects 1 to {median} others ({})", count(Style::Other))
    };
    let blue = format!("intersects none ({})", count(Style::Plain));
    let legend = [
        (Swatch::Fill(Style::Highlight), red.as_str()),
        (Swatch::Fill(Style::Other), teal.as_str()),
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
                "\nWrote {svg_path}: the scene above, coloured by how many others each polygon intersects."
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ratio_is_the_median_of_the_runs_against_the_best_of_each_run() {
        let strategies = [Strategy::Sampled, Strategy::Cached, Strategy::Planner];
        // Runs: planner/least = 2/1, 3/2, 1/4 (cached best in the last), 5/5, 4/2.
        let times = vec![
            vec![1.0, 3.0, 2.0],
            vec![2.0, 4.0, 3.0],
            vec![8.0, 4.0, 1.0],
            vec![5.0, 6.0, 5.0],
            vec![2.0, 9.0, 4.0],
        ];
        let c = planner_ratio(&strategies, &times).unwrap();
        let mut ratios = [2.0, 1.5, 0.25, 1.0, 2.0];
        ratios.sort_by(f64::total_cmp);
        assert_eq!(c.median, ratios[2]);
        assert_eq!((c.low, c.high), (0.25, 2.0));
        // Nearest rank over [0.25, 1, 1.5, 2, 2]: positions 1 and 3.
        assert_eq!(c.quartiles, (1.0, 2.0));
        // Sampled's median time (2) is below cached's (4).
        assert_eq!(c.best, Strategy::Sampled);
        // An even count of runs takes the mean of the middle two.
        let c = planner_ratio(&strategies, &times[..4]).unwrap();
        assert_eq!(c.median, (1.0 + 1.5) / 2.0);
    }

    #[test]
    fn no_ratio_without_a_planner_a_fixed_strategy_runs_or_time() {
        assert_eq!(planner_ratio(&[Strategy::Sampled], &[vec![1.0]]), None);
        assert_eq!(planner_ratio(&[Strategy::Planner], &[vec![1.0]]), None);
        assert_eq!(planner_ratio(&[Strategy::Sampled, Strategy::Planner], &[]), None);
        assert_eq!(
            planner_ratio(&[Strategy::Sampled, Strategy::Planner], &[vec![0.0, 1.0]]),
            None
        );
    }
}
