//! The thesis's input figures, drawn from our generators: Figure 4.1 (random vertices
//! on the unit circle, then squashed with a = 1, b = 0.1), Figure 4.4 (a piecewise-linear
//! angle density with two peaks and a polygon drawn from it) and Figure 4.5 (a uniform
//! `ellipse` pair and a `non-uniform` pair, the first vertex of each array ringed).
//! Written by `polysect bench --protocol thesis` next to its measurements.
//!
//! The algorithm illustrations of the thesis's chapter 3 are drawn from traces
//! ([`crate::intersect::trace`]) by [`write_trace_figures`]: one strip of steps per
//! algorithm (Barba–Langerman's T_P and T_Q's edge lines, Dobkin–Souvaine's chain
//! pairs and heights, Chazelle–Dobkin's pencil, window and chains, CLM's samples, LP
//! lines and walks), each ending with the answer's certificate.

use super::Report;
use super::plot::{self, Chart, Series};
use crate::generate::{self, Density, Family, Relation};
use crate::intersect::{Algorithm, Role, Shape, Trace, trace_rng};
use crate::kernel::{Exact, Point};
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

const TRACE_PANEL: f64 = 280.0;
const P_COLOUR: &str = "#2d5a96";
const Q_COLOUR: &str = "#b3260d";

fn role_colour(role: Role) -> &'static str {
    match role {
        Role::Triangle | Role::Chain => "#1f7a3a",
        Role::Bound => "#7a5cc2",
        Role::Pencil => "#c27a00",
        Role::Window => "#d4a017",
        Role::Sample => "#0a7f8c",
        Role::Separator => "#111111",
        Role::Witness => "#d0021b",
    }
}

/// Escapes text for SVG.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// `trace`'s steps `shown` (indices) side by side, on the polygons `p` and `q`: the
/// polygons' outlines, the kept vertices thick, those pruned at that step dashed grey,
/// the step's marks; each panel's caption is the step number and its `<title>` the
/// step's text.
pub fn trace_svg(p: &[Point], q: &[Point], trace: &Trace, shown: &[usize]) -> String {
    let all: Vec<Point> = p.iter().chain(q).copied().collect();
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for v in &all {
        x0 = x0.min(v.x);
        x1 = x1.max(v.x);
        y0 = y0.min(v.y);
        y1 = y1.max(v.y);
    }
    let span = (x1 - x0).max(y1 - y0).max(1e-12);
    let scale = (TRACE_PANEL - 2.0 * MARGIN) / span;
    let width = shown.len() as f64 * TRACE_PANEL;
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{h}" viewBox="0 0 {width} {h}" font-family="sans-serif" font-size="12">"#,
        h = TRACE_PANEL + CAPTION
    );
    let _ = writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#);
    for (i, &k) in shown.iter().enumerate() {
        let step = &trace.steps[k];
        let left = i as f64 * TRACE_PANEL + MARGIN + (TRACE_PANEL - 2.0 * MARGIN - (x1 - x0) * scale) / 2.0;
        let top = MARGIN + (TRACE_PANEL - 2.0 * MARGIN - (y1 - y0) * scale) / 2.0;
        let map = |v: Point| (left + (v.x - x0) * scale, top + (y1 - v.y) * scale);
        let coords = |pts: &mut dyn Iterator<Item = Point>| -> String {
            pts.map(|v| {
                let (x, y) = map(v);
                format!("{x:.2},{y:.2}")
            })
            .collect::<Vec<_>>()
            .join(" ")
        };
        let clip = format!("panel{i}");
        let _ = writeln!(
            out,
            r#"<clipPath id="{clip}"><rect x="{:.1}" y="0" width="{TRACE_PANEL}" height="{TRACE_PANEL}"/></clipPath><g clip-path="url(#{clip})"><title>{}</title>"#,
            i as f64 * TRACE_PANEL,
            escape(&step.text)
        );
        for (poly, colour) in [(p, P_COLOUR), (q, Q_COLOUR)] {
            let _ = writeln!(
                out,
                r#"<polygon points="{}" fill="{colour}" fill-opacity="0.06" stroke="{colour}" stroke-opacity="0.45" stroke-width="1"/>"#,
                coords(&mut poly.iter().copied())
            );
        }
        for (side, (poly, colour)) in [(p, P_COLOUR), (q, Q_COLOUR)].into_iter().enumerate() {
            for (spans, style) in [
                (
                    &step.pruned[side],
                    r##"stroke="#9aa3b2" stroke-width="3" stroke-dasharray="4 3""##.to_string(),
                ),
                (&step.kept[side], format!(r#"stroke="{colour}" stroke-width="3""#)),
            ] {
                for span in spans {
                    let mut pts = span.indices(poly.len()).map(|j| poly[j]);
                    if span.len == 1 {
                        let (x, y) = map(poly[span.start % poly.len()]);
                        let _ = writeln!(
                            out,
                            r#"<circle cx="{x:.2}" cy="{y:.2}" r="3.5" fill="{colour}"/>"#
                        );
                    } else {
                        let _ = writeln!(
                            out,
                            r#"<polyline points="{}" fill="none" {style}/>"#,
                            coords(&mut pts)
                        );
                    }
                }
            }
        }
        for mark in &step.marks {
            let colour = role_colour(mark.role);
            let dash = if matches!(mark.role, Role::Bound | Role::Window) {
                r#" stroke-dasharray="6 4""#
            } else {
                ""
            };
            let width = if matches!(mark.role, Role::Separator | Role::Witness) {
                2.5
            } else {
                1.5
            };
            let stroke = format!(r#"fill="none" stroke="{colour}" stroke-width="{width}"{dash}"#);
            match &mark.shape {
                Shape::Points(pts) => {
                    for &v in pts {
                        let (x, y) = map(v);
                        let _ = writeln!(out, r#"<circle cx="{x:.2}" cy="{y:.2}" r="3" fill="{colour}"/>"#);
                    }
                }
                Shape::Polyline(pts) => {
                    let _ = writeln!(
                        out,
                        r#"<polyline points="{}" {stroke}/>"#,
                        coords(&mut pts.iter().copied())
                    );
                }
                Shape::Polygon(pts) => {
                    let _ = writeln!(
                        out,
                        r#"<polygon points="{}" {stroke}/>"#,
                        coords(&mut pts.iter().copied())
                    );
                }
                Shape::Segment(a, b) => {
                    let _ = writeln!(
                        out,
                        r#"<polyline points="{}" {stroke}/>"#,
                        coords(&mut [*a, *b].into_iter())
                    );
                }
                Shape::Line(a, b) => {
                    let (dx, dy) = (b.x - a.x, b.y - a.y);
                    let len = dx.hypot(dy);
                    if len > 0.0 && len.is_finite() {
                        let e = 4.0 * span / len;
                        let far = [
                            Point::new(a.x - dx * e, a.y - dy * e),
                            Point::new(a.x + dx * e, a.y + dy * e),
                        ];
                        let _ = writeln!(
                            out,
                            r#"<polyline points="{}" {stroke}/>"#,
                            coords(&mut far.into_iter())
                        );
                    }
                }
            }
        }
        let caption = match step.answer {
            Some(true) => "answer: intersecting".to_string(),
            Some(false) => "answer: disjoint".to_string(),
            None => format!("step {} of {}", k + 1, trace.steps.len()),
        };
        let _ = writeln!(
            out,
            r#"</g><text x="{:.1}" y="{:.1}" text-anchor="middle">{caption}</text>"#,
            i as f64 * TRACE_PANEL + TRACE_PANEL / 2.0,
            TRACE_PANEL + CAPTION - 8.0
        );
    }
    out.push_str("</svg>\n");
    out
}

/// The steps a strip shows: at most `max` spread over the trace, always the first and
/// the last.
fn spread(len: usize, max: usize) -> Vec<usize> {
    if len <= max {
        return (0..len).collect();
    }
    let mut out: Vec<usize> = (0..max).map(|i| i * (len - 1) / (max - 1)).collect();
    out.dedup();
    out
}

/// The file names [`write_trace_figures`] writes.
pub const TRACE_FIGURES: [&str; 4] = [
    "thesis_ch3_barba.svg",
    "thesis_ch3_dobkin.svg",
    "thesis_ch3_chazelle_dobkin.svg",
    "thesis_ch3_clm.svg",
];

/// Writes the chapter 3 illustrations ([`TRACE_FIGURES`]) into `dir`, drawn from traces
/// of each algorithm on a fixed pair (`seed`), under the exact kernel; returns the
/// files' names.
///
/// # Errors
/// Writing a file failed.
pub fn write_trace_figures(dir: &Path, seed: u64) -> io::Result<Vec<String>> {
    let mut rng = SmallRng::seed_from_u64(seed);
    let algorithms = [
        (Algorithm::Barba, 40),
        (Algorithm::Dobkin, 40),
        (Algorithm::ChazelleDobkin, 40),
        (Algorithm::Clm, 600),
    ];
    let mut names = Vec::new();
    for ((algorithm, n), name) in algorithms.into_iter().zip(TRACE_FIGURES) {
        // The first near-touching disjoint pair on which the algorithm takes at least
        // four steps (some pairs are decided at once, e.g. by Dobkin's heights).
        let mut chosen = None;
        for _ in 0..100 {
            let (p, q) = generate::pair(Family::Ellipse, n, Relation::Disjoint, &mut rng);
            let t = trace_rng(algorithm, Exact, &p, &q, &mut SmallRng::seed_from_u64(seed));
            let enough = t.steps.len() >= 5;
            chosen = Some((p, q, t));
            if enough {
                break;
            }
        }
        let (p, q, t) = chosen.expect("at least one pair");
        let fig = trace_svg(p.vertices(), q.vertices(), &t, &spread(t.steps.len(), 5));
        fs::write(dir.join(name), fig)?;
        names.push(name.to_string());
    }
    Ok(names)
}

/// The two-peak density of Figure 4.4: high weights around two angles, low elsewhere.
pub(crate) fn two_peak_density() -> Density {
    let mut weights = vec![0.03; 13];
    weights[3] = 1.0;
    weights[9] = 1.0;
    Density::PiecewiseLinear { weights }
}

/// Writes `thesis_fig4_1.svg`, `thesis_fig4_4a.svg`, `thesis_fig4_4b.svg`,
/// `thesis_fig4_5.svg` and the chapter 3 illustrations ([`TRACE_FIGURES`]) into `dir`.
pub(crate) fn write_all(dir: &Path, seed: u64, report: &mut Report) -> io::Result<()> {
    for name in write_trace_figures(dir, seed)? {
        report.files.push(name);
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trace_figures_are_written_with_their_steps_and_answers() {
        let dir = std::env::temp_dir().join(format!("polysect-trace-figures-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let names = write_trace_figures(&dir, 7).unwrap();
        assert_eq!(names, TRACE_FIGURES);
        for name in names {
            let svg = fs::read_to_string(dir.join(&name)).unwrap();
            assert!(
                svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"),
                "{name}"
            );
            assert!(svg.contains("answer: disjoint"), "{name}: no final answer");
            assert!(
                svg.matches("<g clip-path").count() >= 3,
                "{name}: fewer than 3 steps"
            );
            // Each algorithm draws its own marks.
            let mark = match name.as_str() {
                "thesis_ch3_barba.svg" => "#1f7a3a",
                "thesis_ch3_dobkin.svg" => "#7a5cc2",
                "thesis_ch3_chazelle_dobkin.svg" => "#c27a00",
                _ => "#0a7f8c",
            };
            assert!(svg.contains(mark), "{name}: no {mark} mark");
        }
        fs::remove_dir_all(&dir).unwrap();
    }

    /// Writes the figures docs/thesis.md links (`cargo test --release --lib --
    /// --ignored trace_figures_for_the_docs`), with the thesis protocol's default seed,
    /// as `polysect bench --protocol thesis` writes them.
    #[test]
    #[ignore = "writes docs/img/thesis; run by hand"]
    fn trace_figures_for_the_docs() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/img/thesis");
        let seed = crate::experiments::ThesisConfig::full(&dir).seed;
        write_trace_figures(&dir, seed).unwrap();
    }
}
