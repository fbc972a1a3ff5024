//! The `polysect` command line: a thin layer over the library. `args.rs` declares the
//! options, `commands.rs` and `generated.rs` wire each command to the library, `demo.rs`
//! is the default command; `streams.rs` opens input and output, `failure.rs` says how a
//! command failed.

use crate::args::{Cli, Command, ProtocolArg};
use crate::commands::{
    bench, bench_thesis, calibrate, check, contact, crossings, demo_command, list, render, scene, serve,
};
use crate::failure::Failure;
use crate::generated::{gen_pairs, gen_simple};
use crate::streams::{open_input, output};
use clap::Parser;
use polysect::crossings::CrossingOptions;
use polysect::generate::simple::PointDistribution;
use polysect::protocol::{self, scene::SceneOptions};
use std::io::{self, Write};
use std::process::ExitCode;

mod args;
mod commands;
mod demo;
mod failure;
mod generated;
mod streams;

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_exit(e),
    };
    let result: Result<(), Failure> = match cli.command {
        None => demo_command(48, 18, 1000, 7, "polysect-demo.svg"),
        Some(Command::Check {
            file,
            algorithm,
            precision,
            seed,
            verify_expected,
            certificate,
        }) => check(
            file.as_deref(),
            algorithm.resolve(),
            precision,
            seed,
            verify_expected,
            certificate,
        ),
        Some(Command::Scene {
            file,
            strategy,
            precision,
            certificate,
            seed,
        }) => {
            let options = SceneOptions {
                strategy,
                seed,
                certificate,
            };
            scene(file.as_deref(), precision, options)
        }
        Some(Command::Crossings {
            file,
            algorithm,
            precision,
            touching,
        }) => crossings(
            file.as_deref(),
            algorithm,
            precision,
            CrossingOptions { touching },
        )
        .map_err(Failure::Io),
        Some(Command::Contact { file, precision }) => {
            contact(file.as_deref(), precision).map_err(Failure::Io)
        }
        Some(Command::Hull { file, algorithm }) => open_input(file.as_deref())
            .and_then(|input| protocol::hull::hull(input, output(), algorithm))
            .map_err(Failure::Io),
        Some(Command::Gen {
            simple: Some(method),
            delta,
            sigma,
            n,
            count,
            order,
            seed,
            ..
        }) => {
            let dist = match sigma {
                Some(sigma) => PointDistribution::Normal { mean: 0.0, sigma },
                None => PointDistribution::Uniform {
                    min: 0.0,
                    max: delta.unwrap_or(100.0),
                },
            };
            gen_simple(method, dist, n as usize, count as usize, order, seed)
        }
        Some(Command::Gen {
            family,
            n,
            count,
            relation,
            order,
            seed,
            a,
            b,
            ..
        }) => gen_pairs(family, n as usize, count, relation, order, seed, a.zip(b)).map_err(Failure::Io),
        Some(Command::Bench {
            experiments,
            quick,
            protocol,
            out,
            seed,
            no_progress,
        }) => match protocol {
            ProtocolArg::Ours => bench(&experiments, quick, out, seed, !no_progress),
            ProtocolArg::Thesis => bench_thesis(&experiments, quick, out, seed, !no_progress),
        }
        .map_err(Failure::Io),
        Some(Command::List) => list().map_err(Failure::Io),
        Some(Command::Demo {
            polygons,
            max_log2,
            steps,
            seed,
            svg,
        }) => demo_command(polygons as usize, max_log2, steps as usize, seed, &svg),
        Some(Command::Render {
            file,
            out,
            limit,
            crossings,
        }) => render(file.as_deref(), &out, limit as usize, crossings),
        Some(Command::Calibrate) => calibrate().map_err(Failure::Io),
        Some(Command::Serve { port, bind }) => serve(bind, port).map_err(Failure::Io),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // The reader closed the pipe: it has what it wanted; stop quietly.
        Err(Failure::Io(e)) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(Failure::Io(e)) => {
            let _ = writeln!(io::stderr(), "polysect: {e}");
            ExitCode::from(1)
        }
        Err(Failure::Usage { command, message }) => {
            let _ = writeln!(
                io::stderr(),
                "error: {message}\n\nFor more information, try 'polysect {command} --help'."
            );
            ExitCode::from(2)
        }
        Err(Failure::Disagreed(message)) => {
            let _ = writeln!(io::stderr(), "polysect: {message}");
            ExitCode::from(3)
        }
    }
}

/// Prints clap's help, version or usage error: help and version go to standard output
/// (exit 0; 1 if it cannot be written), usage errors to standard error (exit 2).
pub(crate) fn clap_exit(e: clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
        let text = e.render().to_string();
        let mut out = io::stdout().lock();
        return match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
            Err(e) => {
                let _ = writeln!(io::stderr(), "polysect: cannot write the help: {e}");
                ExitCode::from(1)
            }
        };
    }
    let _ = e.print();
    ExitCode::from(2)
}
