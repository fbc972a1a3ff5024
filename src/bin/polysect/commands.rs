//! Each subcommand but `gen`: options in, the library's protocols, experiments and
//! servers wired to standard input and output.

use crate::demo;
use crate::failure::Failure;
use crate::streams::{open_input, output};
use polysect::crossings::{CrossingAlgorithm, CrossingOptions};
use polysect::experiments::{self, Config, Experiment, ThesisConfig};
use polysect::generate::Family;
use polysect::intersect::Algorithm;
use polysect::polygon::HullAlgorithm;
use polysect::protocol::{self, scene::SceneOptions, scene::SceneSession};
use polysect::store::Strategy;
use polysect::{ConvexPolygon, Exact, Fast, Kernel, Precision};
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::io::{self, Write};
use std::net::IpAddr;
use std::path::PathBuf;
use std::time::Instant;

pub(crate) fn check(
    file: Option<&str>,
    algorithm: Algorithm,
    precision: Precision,
    seed: Option<u64>,
    verify_expected: bool,
    certificate: bool,
) -> Result<(), Failure> {
    let mut rng = match seed {
        Some(seed) => SmallRng::seed_from_u64(seed),
        None => polysect::seeding::fresh_rng(),
    };
    if certificate {
        // Under the fast kernel a certificate is checked exactly before it is printed
        // (O(n + m), as reading the line) and replaced if it fails: every one verifies.
        return Ok(protocol::check::check_certified(
            open_input(file)?,
            output(),
            |p, q| {
                let certificate = algorithm.run_certified_rng(precision, p, q, &mut rng).0;
                match precision {
                    Precision::Exact => certificate,
                    Precision::Fast => polysect::intersect::verified_or_exact(p, q, certificate),
                }
            },
        )?);
    }
    let answer = |p: &ConvexPolygon, q: &ConvexPolygon| algorithm.run_rng(precision, p, q, &mut rng).0;
    if !verify_expected {
        return Ok(protocol::check::check(open_input(file)?, output(), answer)?);
    }
    let tally = protocol::check::check_expected(open_input(file)?, output(), answer)?;
    let summary = format!(
        "{} answer(s) compared with \"expected\", {} disagree; {} line(s) without an answer",
        tally.compared, tally.disagreed, tally.errors
    );
    if tally.disagreed > 0 {
        return Err(Failure::Disagreed(summary));
    }
    let _ = writeln!(io::stderr(), "polysect: {summary}");
    Ok(())
}

pub(crate) fn scene(file: Option<&str>, precision: Precision, options: SceneOptions) -> Result<(), Failure> {
    match precision {
        Precision::Exact => run_session(SceneSession::with_kernel(Exact, options), file),
        Precision::Fast => run_session(SceneSession::with_kernel(Fast, options), file),
    }
}

pub(crate) fn run_session<K: Kernel>(
    mut session: SceneSession<K>,
    file: Option<&str>,
) -> Result<(), Failure> {
    let input = open_input(file).map_err(Failure::Io)?;
    session.run(input, output()).map_err(Failure::Io)
}

pub(crate) fn crossings(
    file: Option<&str>,
    algorithm: CrossingAlgorithm,
    precision: Precision,
    options: CrossingOptions,
) -> io::Result<()> {
    protocol::check::crossings(open_input(file)?, output(), |p, q| {
        algorithm.run_with_options(precision, p, q, options)
    })
}

pub(crate) fn contact(file: Option<&str>, precision: Precision) -> io::Result<()> {
    let input = open_input(file)?;
    match precision {
        Precision::Exact => protocol::contact::contact_with_kernel(Exact, input, output()),
        Precision::Fast => protocol::contact::contact_with_kernel(Fast, input, output()),
    }
}

pub(crate) fn list() -> io::Result<()> {
    let mut out = io::stdout().lock();
    let names: Vec<&str> = Algorithm::ALL.iter().map(|a| a.name()).collect();
    writeln!(
        out,
        "algorithms: auto (= {}), {}",
        Algorithm::fastest_array(),
        names.join(", ")
    )?;
    let names: Vec<&str> = CrossingAlgorithm::ALL.iter().map(|a| a.name()).collect();
    writeln!(
        out,
        "crossings:  {} (default {})",
        names.join(", "),
        CrossingAlgorithm::default()
    )?;
    let names: Vec<&str> = HullAlgorithm::ALL.iter().map(|a| a.name()).collect();
    writeln!(
        out,
        "hulls:      {} (default {})",
        names.join(", "),
        HullAlgorithm::default()
    )?;
    writeln!(out, "precisions: fast, exact (default)")?;
    let names: Vec<&str> = Strategy::ALL.iter().map(|s| s.name()).collect();
    writeln!(out, "strategies: {} (scene; default planner)", names.join(", "))?;
    let fams: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
    writeln!(out, "families:   {}", fams.join(", "))?;
    out.flush()
}

/// Checks, before any work, that `path` may receive SVG text: "-" (standard output), a
/// name ending in .svg, or one without an extension (`/dev/null`, `/dev/stdout`). A name
/// ending in another extension (`x.png`) would get SVG text under a false name.
pub(crate) fn svg_output(command: &'static str, option: &str, path: &str) -> Result<(), Failure> {
    let is_svg = path == "-"
        || std::path::Path::new(path)
            .extension()
            .is_none_or(|e| e.eq_ignore_ascii_case("svg"));
    if is_svg {
        return Ok(());
    }
    Err(Failure::Usage {
        command,
        message: format!(
            "{option} {path}: polysect writes SVG only; name a .svg file (or - for standard output) \
             and convert it, e.g. `rsvg-convert picture.svg -o picture.png`"
        ),
    })
}

pub(crate) fn write_svg(path: &str, svg: &str) -> io::Result<()> {
    if path == "-" {
        let mut out = io::stdout().lock();
        out.write_all(svg.as_bytes())?;
        return out.flush();
    }
    std::fs::write(path, svg).map_err(|e| io::Error::new(e.kind(), format!("cannot write {path}: {e}")))
}

pub(crate) fn render(
    file: Option<&str>,
    out_path: &str,
    limit: usize,
    crossings: bool,
) -> Result<(), Failure> {
    use polysect::render::{RenderMode, render_pairs};
    svg_output("render", "--out", out_path)?;
    let mode = if crossings {
        RenderMode::Crossings
    } else {
        RenderMode::Auto
    };
    let picture = render_pairs(open_input(file)?, mode, limit)?;
    write_svg(out_path, &picture.svg)?;
    let mut err = io::stderr().lock();
    if picture.more {
        let _ = writeln!(
            err,
            "polysect: render stopped at its limit of {limit} pairs; the rest of the input was not \
             read (--limit N draws more)"
        );
    }
    if out_path != "-" {
        let _ = writeln!(err, "wrote {} panel(s) to {out_path}", picture.drawn);
    }
    Ok(())
}

pub(crate) fn demo_command(
    polygons: usize,
    max_log2: u32,
    steps: usize,
    seed: u64,
    svg: &str,
) -> Result<(), Failure> {
    svg_output("demo", "--svg", svg)?;
    let need = demo::estimated_bytes(polygons, max_log2);
    if need > demo::MEMORY_LIMIT {
        return Err(Failure::Usage {
            command: "demo",
            message: format!(
                "--polygons {polygons} --max-log2 {max_log2} would need about {:.1} GB (polygons of up to \
                 2^{max_log2} vertices); the demo stops at {:.0} GB: lower either",
                need as f64 / 1e9,
                demo::MEMORY_LIMIT as f64 / 1e9
            ),
        });
    }
    Ok(demo::run(polygons, max_log2, steps, seed, svg)?)
}

/// Listens, prints the URL, and serves until SIGINT or SIGTERM (then exits with 0).
pub(crate) fn serve(bind: IpAddr, port: u16) -> io::Result<()> {
    let server = polysect::serve::Server::bind(bind, port)?;
    let (done, finished) = std::sync::mpsc::channel::<io::Result<()>>();
    let stop = done.clone();
    ctrlc::set_handler(move || {
        let _ = stop.send(Ok(()));
    })
    .map_err(io::Error::other)?;
    let url = server.url();
    if let Some(warning) = server.exposure_warning() {
        let _ = writeln!(io::stderr(), "polysect: {warning}");
    }
    std::thread::spawn(move || {
        let why = server
            .run()
            .and(Err(io::Error::other("the server stopped accepting connections")));
        let _ = done.send(why);
    });
    let mut out = io::stdout().lock();
    writeln!(out, "{url}")?;
    out.flush()?;
    drop(out);
    finished.recv().unwrap_or(Ok(()))
}

/// The JSON `calibrate` writes: the sizes the tables are indexed by, then the model's
/// fields (so the whole object deserialises as a `CostModel`, the extra field ignored).
#[derive(serde::Serialize)]
struct Calibrated<'a> {
    sizes: [usize; polysect::store::COST_SIZES],
    #[serde(flatten)]
    costs: &'a polysect::store::CostModel,
}

/// `calibrate`: the measured model as JSON on standard output, nothing else; progress and
/// the summary on standard error.
pub(crate) fn calibrate() -> io::Result<()> {
    use polysect::store::CostModel;
    let _ = writeln!(
        io::stderr(),
        "measuring conversion and sampled-query costs (about ten seconds)..."
    );
    let costs = CostModel::calibrate(polysect::Exact);
    let json = Calibrated {
        sizes: CostModel::sizes(),
        costs: &costs,
    };
    let mut out = io::stdout().lock();
    writeln!(
        out,
        "{}",
        serde_json::to_string_pretty(&json).map_err(io::Error::other)?
    )?;
    out.flush()?;
    let _ = writeln!(
        io::stderr(),
        "{}\nEntry i of each table is for polygons of sizes[i] vertices, times in ns. Use it with \
         scene.set_costs(serde_json::from_str::<CostModel>(&text)?) (feature `serde`).",
        costs.summary()
    );
    Ok(())
}

/// `bench --protocol thesis`: the thesis's chapter 4 protocol (see
/// `polysect::experiments::thesis`).
pub(crate) fn bench_thesis(
    experiments: &[Experiment],
    quick: bool,
    out: PathBuf,
    seed: Option<u64>,
    progress: bool,
) -> io::Result<()> {
    if !experiments.is_empty() {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            "--protocol thesis runs the thesis's experiments 1-5 together and takes no experiment names",
        ));
    }
    let mut config = if quick {
        ThesisConfig::quick(out)
    } else {
        ThesisConfig::full(out)
    };
    if let Some(seed) = seed {
        config.seed = seed;
    }
    config.progress = progress;
    let start = Instant::now();
    let report = experiments::thesis::run(&config)
        .map_err(|e| io::Error::new(e.kind(), format!("cannot write to {}: {e}", config.out.display())))?;
    let mut out = io::stdout().lock();
    writeln!(out, "{}", report.summary)?;
    writeln!(
        out,
        "wrote {} files to {} in {:.1} s",
        report.files.len(),
        config.out.display(),
        start.elapsed().as_secs_f64()
    )?;
    out.flush()
}

pub(crate) fn bench(
    experiments: &[Experiment],
    quick: bool,
    out: PathBuf,
    seed: Option<u64>,
    progress: bool,
) -> io::Result<()> {
    let mut config = if quick {
        Config::quick(out)
    } else {
        Config::full(out)
    };
    if let Some(seed) = seed {
        config.seed = seed;
    }
    config.progress = progress;
    let experiments = if experiments.is_empty() {
        Experiment::ALL
    } else {
        experiments
    };
    let start = Instant::now();
    // Its errors name the file or directory that failed.
    let report = experiments::run(experiments, &config)?;
    let mut out = io::stdout().lock();
    writeln!(out, "{}", report.summary)?;
    writeln!(
        out,
        "wrote {} files to {} in {:.1} s",
        report.files.len(),
        config.out.display(),
        start.elapsed().as_secs_f64()
    )?;
    out.flush()
}
