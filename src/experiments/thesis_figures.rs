//! The thesis's input figures, drawn from our generators: Figure 4.1 (random vertices
//! on the unit circle, then squashed with a = 1, b = 0.1), Figure 4.4 (a piecewise-linear
//! angle density with two peaks and a polygon drawn from it) and Figure 4.5 (a uniform
//! `ellipse` pair and a `non-uniform` pair, the first vertex of each array ringed).
//! Written by `polysect bench --protocol thesis` next to its measurements.

use super::Report;
use super::plot::{self, Chart, Series};
use crate::generate::{self, Density, Family, Relation};
use crate::kernel::Point;
use rand::SeedableRng;
use rand::rngs::SmallRng;
use std::fmt::Write;
use std::fs;
use std::io;
use std::path::Path;

const PANEL: f64 = 300.0;
const MARGIN: f64 = 14.0;
const CAPTION: f64 = 24.0;
const COLOURS: [&str; 2] = ["#d62728", "#2ca02c"];

/// One panel: polygons (drawn with their vertices, the first one ringed) and a caption.
struct Panel {
    polygons: Vec<Vec<Point>>,
    caption: String,
}

/// Panels side by side, each scaled to fit (same scale on x and y).
fn svg(panels: &[Panel]) -> String {
    let width = panels.len() as f64 * PANEL;
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{}" viewBox="0 0 {width} {}" font-family="sans-serif" font-size="13">"#,
        PANEL + CAPTION,
        PANEL + CAPTION
    );
    let _ = writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#);
    for (i, panel) in panels.iter().enumerate() {
        let pts = panel.polygons.iter().flatten();
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for p in pts {
            x0 = x0.min(p.x);
            x1 = x1.max(p.x);
            y0 = y0.min(p.y);
            y1 = y1.max(p.y);
        }
        let span = (x1 - x0).max(y1 - y0).max(1e-12);
        let scale = (PANEL - 2.0 * MARGIN) / span;
        let left = i as f64 * PANEL + MARGIN + (PANEL - 2.0 * MARGIN - (x1 - x0) * scale) / 2.0;
        let top = MARGIN + (PANEL - 2.0 * MARGIN - (y1 - y0) * scale) / 2.0;
        let map = |p: &Point| (left + (p.x - x0) * scale, top + (y1 - p.y) * scale);
        for (k, poly) in panel.polygons.iter().enumerate() {
            let colour = COLOURS[k % COLOURS.len()];
            let path: Vec<String> = poly
                .iter()
                .map(|p| {
                    let (x, y) = map(p);
                    format!("{x:.2},{y:.2}")
                })
                .collect();
            let _ = writeln!(
                out,
                r#"<polygon points="{}" fill="{colour}" fill-opacity="0.08" stroke="{colour}" stroke-width="1"/>"#,
                path.join(" ")
            );
            for p in poly {
                let (x, y) = map(p);
                let _ = writeln!(out, r#"<circle cx="{x:.2}" cy="{y:.2}" r="2" fill="{colour}"/>"#);
            }
            if let Some(first) = poly.first() {
                let (x, y) = map(first);
                let _ = writeln!(
                    out,
                    r#"<circle cx="{x:.2}" cy="{y:.2}" r="6" fill="none" stroke="black" stroke-width="1.5"/>"#
                );
            }
        }
        let _ = writeln!(
            out,
            r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">{}</text>"#,
            i as f64 * PANEL + PANEL / 2.0,
            PANEL + CAPTION - 8.0,
            panel.caption
        );
    }
    out.push_str("</svg>\n");
    out
}

fn write(dir: &Path, name: &str, text: &str, report: &mut Report) -> io::Result<()> {
    fs::write(dir.join(name), text)?;
    report.files.push(name.to_string());
    Ok(())
}

/// The two-peak density of Figure 4.4: high weights around two angles, low elsewhere.
pub(crate) fn two_peak_density() -> Density {
    let mut weights = vec![0.03; 13];
    weights[3] = 1.0;
    weights[9] = 1.0;
    Density::PiecewiseLinear { weights }
}

/// Writes `thesis_fig4_1.svg`, `thesis_fig4_4a.svg`, `thesis_fig4_4b.svg` and
/// `thesis_fig4_5.svg` into `dir`.
pub(crate) fn write_all(dir: &Path, seed: u64, report: &mut Report) -> io::Result<()> {
    let n = 64;
    // Figure 4.1: the same random angles on the unit circle and squashed (a = 1, b = 0.1).
    let circle = generate::ellipse_polygon_axes(
        &mut SmallRng::seed_from_u64(seed),
        n,
        &Density::Uniform,
        false,
        Some((1.0, 1.0)),
    );
    let squashed = generate::ellipse_polygon_axes(
        &mut SmallRng::seed_from_u64(seed),
        n,
        &Density::Uniform,
        false,
        Some((1.0, 0.1)),
    );
    let fig = svg(&[
        Panel {
            polygons: vec![circle.vertices().to_vec()],
            caption: "(a) random angles, a = b = 1".into(),
        },
        Panel {
            polygons: vec![squashed.vertices().to_vec()],
            caption: "(b) squashed: a = 1, b = 0.1".into(),
        },
    ]);
    write(dir, "thesis_fig4_1.svg", &fig, report)?;

    // Figure 4.4: the density over angles 0 … 2π and a polygon drawn from it.
    let density = two_peak_density();
    if let Density::PiecewiseLinear { weights } = &density {
        let k = (weights.len() - 1) as f64;
        let points = weights
            .iter()
            .enumerate()
            .map(|(i, &w)| (i as f64 / k * std::f64::consts::TAU, w))
            .collect();
        let chart = Chart {
            title: "Fig. 4.4(a): piecewise-linear density of the angle",
            x_label: "angle (radians)",
            y_label: "weight",
            log2_x: false,
            log_y: false,
            scatter: false,
        };
        plot::draw(
            &dir.join("thesis_fig4_4a.svg"),
            &chart,
            &[Series::new("density", points)],
        )?;
        report.files.push("thesis_fig4_4a.svg".into());
    }
    let peaked = generate::ellipse_polygon_axes(
        &mut SmallRng::seed_from_u64(seed ^ 4),
        n,
        &density,
        false,
        Some((1.0, 0.6)),
    );
    let fig = svg(&[Panel {
        polygons: vec![peaked.vertices().to_vec()],
        caption: "Fig. 4.4(b): a polygon from the density".into(),
    }]);
    write(dir, "thesis_fig4_4b.svg", &fig, report)?;

    // Figure 4.5: a uniform, unrotated pair and a non-uniform, rotated pair with a random
    // start index; the first vertex of each array is ringed.
    let mut rng = SmallRng::seed_from_u64(seed ^ 5);
    let (p, q) = generate::pair(Family::Ellipse, n, Relation::Any, &mut rng);
    let (r, s) = generate::pair(Family::NonUniform, n, Relation::Any, &mut rng);
    let fig = svg(&[
        Panel {
            polygons: vec![p.vertices().to_vec(), q.vertices().to_vec()],
            caption: "(a) ellipse: uniform, start leftmost".into(),
        },
        Panel {
            polygons: vec![r.vertices().to_vec(), s.vertices().to_vec()],
            caption: "(b) non-uniform, rotated, random start".into(),
        },
    ]);
    write(dir, "thesis_fig4_5.svg", &fig, report)
}
