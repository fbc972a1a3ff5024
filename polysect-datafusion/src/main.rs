//! `polysect-datafusion`: the spatial join and the table generator from the command
//! line (thin: parse, call the library, print).

use clap::{Parser, Subcommand, ValueEnum};
use datafusion::arrow::util::display::{ArrayFormatter, FormatOptions};
use datafusion::prelude::{ParquetReadOptions, SessionContext, col};
use polysect::Point;
use polysect_datafusion::grid::Grid;
use polysect_datafusion::join::{JoinOptions, spatial_join};
use polysect_datafusion::tables::{self, Layout, TableSpec};
use polysect_datafusion::udf::OnInvalid;
use std::io::{BufWriter, ErrorKind, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

#[derive(Parser)]
#[command(
    name = "polysect-datafusion",
    version,
    about = "Exact spatial joins of convex polygons on DataFusion"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Every pair of rows whose polygons intersect (touching counts), as CSV
    /// `left_id,right_id` on standard output; timings on standard error.
    Join {
        /// The left table: (Geo)Parquet with a WKB polygon column.
        left: PathBuf,
        /// The right table.
        right: PathBuf,
        /// The geometry column of both tables.
        #[arg(long, default_value = "geometry")]
        geometry: String,
        /// The left table's geometry column, if named otherwise.
        #[arg(long)]
        left_geometry: Option<String>,
        /// The right table's geometry column, if named otherwise.
        #[arg(long)]
        right_geometry: Option<String>,
        /// The left table's id column.
        #[arg(long, default_value = "id")]
        left_id: String,
        /// The right table's id column.
        #[arg(long, default_value = "id")]
        right_id: String,
        /// The grid's cell size (default: chosen from the data in one extra pass).
        #[arg(long)]
        cell_size: Option<f64>,
        /// A geometry that is not a convex polygon: fail (error) or skip its row (null).
        #[arg(long, value_enum, default_value_t = Invalid::Error)]
        invalid: Invalid,
    },
    /// Writes a GeoParquet table of seeded random convex polygons (`id`, `geometry`).
    Gen {
        /// Where to write it.
        #[arg(long)]
        out: PathBuf,
        /// How many rows.
        #[arg(long, default_value_t = 1000)]
        rows: usize,
        /// Vertices per polygon.
        #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(3..=1 << 20))]
        vertices: u32,
        /// The generator's seed.
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// About how many polygons of a like table each polygon meets.
        #[arg(long, default_value_t = 2.0)]
        partners: f64,
        /// Where polygons are placed.
        #[arg(long, value_enum, default_value_t = LayoutArg::Uniform)]
        layout: LayoutArg,
        /// With `--layout adversarial`: where to write the second table, whose row i
        /// touches (or misses by the smallest step) row i of the first.
        #[arg(long)]
        partner_out: Option<PathBuf>,
    },
}

#[derive(Clone, Copy, ValueEnum)]
enum Invalid {
    Error,
    Null,
}

#[derive(Clone, Copy, ValueEnum)]
enum LayoutArg {
    Uniform,
    Clustered,
    /// Pairs of exact touchings, one-ulp gaps and nested polygons, written row for row
    /// to `--out` and `--partner-out` (`--partners` does not apply).
    Adversarial,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let runtime = match tokio::runtime::Builder::new_multi_thread().enable_all().build() {
        Ok(r) => r,
        Err(e) => {
            eprintln!("polysect-datafusion: cannot start the runtime: {e}");
            return ExitCode::from(1);
        }
    };
    match runtime.block_on(run(cli.command)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.kind() == ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("polysect-datafusion: {e}");
            ExitCode::from(1)
        }
    }
}

fn io(e: impl std::fmt::Display) -> std::io::Error {
    std::io::Error::other(e.to_string())
}

/// Writes polygons as a GeoParquet table (`id` from 0, batches of 8,192 rows).
fn write_table(out: &std::path::Path, polygons: &[polysect::ConvexPolygon]) -> std::io::Result<()> {
    let batches = polygons
        .chunks(8192)
        .enumerate()
        .map(|(i, c)| tables::batch(c, (i * 8192) as i64))
        .collect::<Result<Vec<_>, _>>()
        .map_err(io)?;
    tables::write_geoparquet(out, &batches).map_err(io)
}

async fn run(command: Command) -> std::io::Result<()> {
    match command {
        Command::Gen {
            out,
            rows,
            vertices,
            seed,
            partners,
            layout,
            partner_out,
        } => {
            if !(partners.is_finite() && partners > 0.0) {
                return Err(io(format!(
                    "--partners {partners} must be a finite positive number"
                )));
            }
            let started = Instant::now();
            let layout = match layout {
                LayoutArg::Uniform => Layout::Uniform,
                LayoutArg::Clustered => Layout::Clustered,
                LayoutArg::Adversarial => {
                    let Some(partner_out) = partner_out else {
                        return Err(io("--layout adversarial needs --partner-out"));
                    };
                    let (left, right) = tables::adversarial_pairs(rows, vertices as usize, seed)
                        .map_err(|e| io(format!("--layout adversarial: {e}")))?;
                    write_table(&out, &left)?;
                    write_table(&partner_out, &right)?;
                    eprintln!(
                        "wrote {rows} adversarial pairs to {} and {} in {:.2?}",
                        out.display(),
                        partner_out.display(),
                        started.elapsed()
                    );
                    return Ok(());
                }
            };
            if partner_out.is_some() {
                return Err(io("--partner-out needs --layout adversarial"));
            }
            let spec = TableSpec {
                rows,
                vertices: vertices as usize,
                seed,
                partners,
                layout,
            };
            write_table(&out, &tables::polygons(&spec))?;
            eprintln!(
                "wrote {rows} polygons to {} in {:.2?}",
                out.display(),
                started.elapsed()
            );
            Ok(())
        }
        Command::Join {
            left,
            right,
            geometry,
            left_geometry,
            right_geometry,
            left_id,
            right_id,
            cell_size,
            invalid,
        } => {
            let lg = left_geometry.unwrap_or_else(|| geometry.clone());
            let rg = right_geometry.unwrap_or(geometry);
            let grid = match cell_size {
                Some(s) => {
                    Some(Grid::new(s, Point::new(0.0, 0.0)).map_err(|e| io(format!("--cell-size: {e}")))?)
                }
                None => None,
            };
            let on_invalid = match invalid {
                Invalid::Error => OnInvalid::Error,
                Invalid::Null => OnInvalid::Null,
            };
            let ctx = SessionContext::new();
            let path = |p: &PathBuf| {
                p.to_str()
                    .map(str::to_string)
                    .ok_or_else(|| io(format!("{} is not UTF-8", p.display())))
            };
            let started = Instant::now();
            let a = ctx
                .read_parquet(path(&left)?, ParquetReadOptions::default())
                .await
                .map_err(io)?;
            let b = ctx
                .read_parquet(path(&right)?, ParquetReadOptions::default())
                .await
                .map_err(io)?;
            let joined = spatial_join(a, &lg, b, &rg, &JoinOptions { on_invalid, grid })
                .await
                .map_err(io)?;
            let planned = started.elapsed();
            let pairs = joined
                .select(vec![
                    col(format!("left.{left_id}")).alias("left_id"),
                    col(format!("right.{right_id}")).alias("right_id"),
                ])
                .map_err(io)?;
            let batches = pairs.collect().await.map_err(io)?;
            let elapsed = started.elapsed();
            let stdout = std::io::stdout();
            let mut out = BufWriter::new(stdout.lock());
            writeln!(out, "left_id,right_id")?;
            let options = FormatOptions::default();
            let mut count = 0usize;
            for batch in &batches {
                let l = ArrayFormatter::try_new(batch.column(0).as_ref(), &options).map_err(io)?;
                let r = ArrayFormatter::try_new(batch.column(1).as_ref(), &options).map_err(io)?;
                for i in 0..batch.num_rows() {
                    writeln!(out, "{},{}", l.value(i), r.value(i))?;
                }
                count += batch.num_rows();
            }
            out.flush()?;
            eprintln!("{count} pairs in {elapsed:.2?} (grid pass and planning {planned:.2?})");
            Ok(())
        }
    }
}
