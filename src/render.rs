//! SVG pictures of polygons: pairs with their answers (`polysect render`), and scenes
//! with the intersecting polygons highlighted (the demo). Plain SVG text, no
//! dependencies; y points up as in the input.
//!
//! # Layout
//! A legend strip on top, then a grid of square panels, each with a caption of up to
//! two lines below it. Each panel is scaled so that its polygons fill it (the larger of
//! their width and height spans the panel, less a margin) and centred; huge and tiny
//! coordinates are scaled without overflow. An error panel shows its message wrapped
//! inside the panel. Text is wrapped by an estimate of the font's width (0.62 em per
//! character), so it stays inside its panel.
//!
//! # Pairs (`polysect render`)
//! [`render_pairs`] reads `check` lines and decides per pair what to draw:
//! * both polygons convex ([`ConvexPolygon::new`] accepts both): p in blue, q in red
//!   when they intersect, teal when they do not (exact [`Linear`] test);
//! * otherwise, both simple ([`SimplePolygon::new`] accepts both; one may be convex): the
//!   points where the boundaries meet are marked (exact [`Sweep`], as `polysect
//!   crossings`), q red when the regions intersect (the boundaries meet, or one
//!   contains a vertex of the other), teal when not;
//! * otherwise an error panel with the simple-polygon validation error (the more
//!   general of the two).
//!
//! [`RenderMode::Crossings`] (the CLI's `--crossings`) draws every pair as simple
//! polygons with its crossing points marked, convex pairs too.

use crate::crossings::{Crossings, Sweep};
use crate::intersect::{ArrayIntersection, Linear};
use crate::kernel::{Exact, Point};
use crate::polygon::{ConvexPolygon, SimplePolygon};
use crate::protocol::check::for_each_pair_with_id;
use std::fmt::Write;
use std::io::{self, Read};

/// How a polygon is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// Blue: the first polygon of a pair, or a scene polygon that meets no other.
    Plain,
    /// Teal: the second polygon of a pair that does not intersect the first.
    Other,
    /// Red: the second polygon of an intersecting pair, or a scene polygon that meets
    /// another.
    Highlight,
}

impl Style {
    fn colours(self) -> (&'static str, &'static str) {
        match self {
            Style::Plain => ("#4c78a8", "#2d4f78"),
            Style::Other => ("#72b7b2", "#2f6f6a"),
            Style::Highlight => ("#e45756", "#9c1f1e"),
        }
    }
}

/// What a legend entry shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Swatch {
    /// A filled square in a polygon style.
    Fill(Style),
    /// The marker of a point (crossing points).
    Mark,
}

/// One framed picture: polygons, marked points, a caption, or an error message.
#[derive(Clone, Debug, Default)]
pub struct Panel {
    /// The polygons, as vertex lists in order (either orientation), drawn in this order
    /// so later ones lie on top.
    pub polygons: Vec<(Vec<Point>, Style)>,
    /// Points drawn as black dots on top (crossing points).
    pub marks: Vec<Point>,
    /// Text below the panel, wrapped to two lines at most (cut with "…" beyond).
    pub caption: String,
    /// When set, the panel shows this message (wrapped) instead of polygons.
    pub error: Option<String>,
}

const MARGIN: f64 = 14.0;
const FONT: f64 = 13.0;
const LINE: f64 = 16.0;
/// Estimated advance of one character, in ems: generous for sans-serif (DejaVu Sans
/// digits are 0.64 em, most letters narrower).
const CHAR_EM: f64 = 0.66;
const CAPTION_LINES: usize = 2;
const LEGEND: f64 = 30.0;

/// The SVG document: a legend strip (omitted when `legend` is empty), then the panels
/// in a grid of `columns`, each `size` pixels square plus its caption.
///
/// ```
/// use polysect::Point;
/// use polysect::render::{Panel, Style, Swatch, svg};
/// let tri = vec![Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(0.0, 1.0)];
/// let panel = Panel { polygons: vec![(tri, Style::Plain)], caption: "a triangle".into(), ..Panel::default() };
/// let text = svg(&[panel], 1, 320.0, &[(Swatch::Fill(Style::Plain), "p")]);
/// assert!(text.starts_with("<svg") && text.contains("a triangle"));
/// ```
pub fn svg(panels: &[Panel], columns: usize, size: f64, legend: &[(Swatch, &str)]) -> String {
    let columns = columns.clamp(1, panels.len().max(1));
    let rows = panels.len().div_ceil(columns).max(1);
    let top = if legend.is_empty() { 0.0 } else { LEGEND };
    let cell_h = size + CAPTION_LINES as f64 * LINE + 8.0;
    let (w, h) = (columns as f64 * size, top + rows as f64 * cell_h);
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif" font-size="{FONT}">"#
    );
    let _ = writeln!(s, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
    draw_legend(&mut s, legend);
    for (i, panel) in panels.iter().enumerate() {
        let (ox, oy) = ((i % columns) as f64 * size, top + (i / columns) as f64 * cell_h);
        draw_panel(&mut s, panel, ox, oy, size);
    }
    s.push_str("</svg>\n");
    s
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Splits `text` into lines of at most `width` characters, at spaces where possible.
/// At most `max_lines` lines; the last one ends in "…" when text was cut.
pub fn wrap(text: &str, width: usize, max_lines: usize) -> Vec<String> {
    let width = width.max(4);
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        let mut word: Vec<char> = word.chars().collect();
        loop {
            let used = line.chars().count();
            let room = if used == 0 {
                width
            } else {
                width.saturating_sub(used + 1)
            };
            if word.len() <= room {
                if used > 0 {
                    line.push(' ');
                }
                line.extend(&word);
                break;
            }
            if used > 0 {
                lines.push(std::mem::take(&mut line));
                continue;
            }
            // A word longer than a line: break it.
            let rest = word.split_off(width);
            lines.push(word.into_iter().collect());
            word = rest;
        }
    }
    if !line.is_empty() {
        lines.push(line);
    }
    if lines.len() > max_lines {
        lines.truncate(max_lines);
        let last = &mut lines[max_lines - 1];
        let mut chars: Vec<char> = last.chars().collect();
        chars.truncate(width - 1);
        *last = chars.into_iter().collect::<String>() + "…";
    }
    lines
}

fn draw_legend(s: &mut String, legend: &[(Swatch, &str)]) {
    let mut x = 8.0;
    let y = LEGEND / 2.0;
    for (swatch, label) in legend {
        match swatch {
            Swatch::Fill(style) => {
                let (fill, stroke) = style.colours();
                let _ = writeln!(
                    s,
                    r#"<rect x="{x}" y="{}" width="14" height="14" fill="{fill}" fill-opacity="0.35" stroke="{stroke}"/>"#,
                    y - 7.0
                );
            }
            Swatch::Mark => {
                let _ = writeln!(
                    s,
                    r#"<circle cx="{}" cy="{y}" r="3.5" fill="black" stroke="white" stroke-width="1"/>"#,
                    x + 7.0
                );
            }
        }
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{}">{}</text>"#,
            x + 20.0,
            y + 4.5,
            escape(label)
        );
        x += 20.0 + label.chars().count() as f64 * FONT * 0.56 + 16.0;
    }
}

fn draw_panel(s: &mut String, panel: &Panel, ox: f64, oy: f64, size: f64) {
    let _ = writeln!(
        s,
        r##"<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#ccc"/>"##,
        ox + 2.0,
        oy + 2.0,
        size - 4.0,
        size - 4.0
    );
    let chars_per_line = ((size - 12.0) / (FONT * CHAR_EM)) as usize;
    if let Some(message) = &panel.error {
        let _ = writeln!(
            s,
            r##"<rect x="{}" y="{}" width="{}" height="{}" fill="#fbeaea"/>"##,
            ox + 3.0,
            oy + 3.0,
            size - 6.0,
            size - 6.0
        );
        let max_lines = ((size - 2.0 * MARGIN) / LINE) as usize;
        for (k, line) in wrap(message, chars_per_line - 1, max_lines).iter().enumerate() {
            let _ = writeln!(
                s,
                r##"<text x="{}" y="{}" fill="#7a1c1c">{}</text>"##,
                ox + 10.0,
                oy + MARGIN + 10.0 + k as f64 * LINE,
                escape(line)
            );
        }
    } else {
        draw_shapes(s, panel, ox, oy, size);
    }
    for (k, line) in wrap(&panel.caption, chars_per_line, CAPTION_LINES)
        .iter()
        .enumerate()
    {
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{}">{}</text>"#,
            ox + 6.0,
            oy + size + 14.0 + k as f64 * LINE,
            escape(line)
        );
    }
}

/// Maps coordinates into the panel: the larger span fills it, the other is centred.
/// Works on halves (`x/2 − lo/2` never overflows) and divides before it multiplies, so
/// spans from subnormal to `f64::MAX` stay finite.
fn draw_shapes(s: &mut String, panel: &Panel, ox: f64, oy: f64, size: f64) {
    let all = panel
        .polygons
        .iter()
        .flat_map(|(v, _)| v.iter())
        .chain(&panel.marks)
        .filter(|p| p.is_finite());
    let (mut lo, mut hi) = (Point::new(f64::MAX, f64::MAX), Point::new(-f64::MAX, -f64::MAX));
    for p in all {
        lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    if lo.x > hi.x {
        return;
    }
    let (half_w, half_h) = (hi.x / 2.0 - lo.x / 2.0, hi.y / 2.0 - lo.y / 2.0);
    let half_span = half_w.max(half_h);
    let room = size - 2.0 * MARGIN;
    let fraction = |d: f64| if half_span > 0.0 { d / half_span } else { 0.5 };
    let (pad_x, pad_y) = (
        (room - fraction(half_w) * room) / 2.0,
        (room - fraction(half_h) * room) / 2.0,
    );
    let map = |p: &Point| {
        let x = ox + MARGIN + pad_x + fraction(p.x / 2.0 - lo.x / 2.0) * room;
        let y = oy + size - MARGIN - pad_y - fraction(p.y / 2.0 - lo.y / 2.0) * room;
        (x, y)
    };
    for (vertices, style) in &panel.polygons {
        let (fill, stroke) = style.colours();
        let xy: Vec<(f64, f64)> = vertices.iter().filter(|p| p.is_finite()).map(map).collect();
        let pts: Vec<String> = xy.iter().map(|(x, y)| format!("{x:.2},{y:.2}")).collect();
        let _ = writeln!(
            s,
            r#"<polygon points="{}" fill="{fill}" fill-opacity="0.35" stroke="{stroke}" stroke-width="1.2" stroke-linejoin="round"/>"#,
            pts.join(" ")
        );
        // A polygon far smaller than the panel's span would be invisible: ring it.
        let (x0, x1, y0, y1) = xy
            .iter()
            .fold((f64::MAX, f64::MIN, f64::MAX, f64::MIN), |b, &(x, y)| {
                (b.0.min(x), b.1.max(x), b.2.min(y), b.3.max(y))
            });
        if x0 <= x1 && (x1 - x0).max(y1 - y0) < 3.0 {
            let _ = writeln!(
                s,
                r#"<circle cx="{:.2}" cy="{:.2}" r="6" fill="none" stroke="{stroke}" stroke-width="1.5"/>"#,
                (x0 + x1) / 2.0,
                (y0 + y1) / 2.0
            );
        }
    }
    for p in panel.marks.iter().filter(|p| p.is_finite()) {
        let (x, y) = map(p);
        let _ = writeln!(
            s,
            r#"<circle cx="{x:.2}" cy="{y:.2}" r="3.5" fill="black" stroke="white" stroke-width="1"/>"#
        );
    }
    if let Some((length, label)) = scale_bar(half_span) {
        // `length` data units over `length / (2·half_span)` of the room, bottom left.
        let px = length / half_span * room / 2.0;
        let (x0, y) = (ox + 8.0, oy + size - 8.0);
        let _ = writeln!(
            s,
            r##"<path d="M{x0:.2},{:.2} V{y:.2} H{:.2} V{:.2}" fill="none" stroke="#555" stroke-width="1.2"/>"##,
            y - 4.0,
            x0 + px,
            y - 4.0
        );
        let _ = writeln!(
            s,
            r##"<text x="{:.2}" y="{:.2}" font-size="10" fill="#555">{label}</text>"##,
            x0 + px + 4.0,
            y
        );
    }
}

/// The scale bar of a panel whose larger half-span is `half_span` data units: the
/// largest 1, 2 or 5 × 10^k not above half of it (a quarter of the span) and its label,
/// written from the digits (so `1e-300` reads exactly). `None` for an empty span.
fn scale_bar(half_span: f64) -> Option<(f64, String)> {
    let target = half_span / 2.0;
    if !(target > 0.0 && target.is_finite()) {
        return None;
    }
    let mut k = target.log10().floor() as i32;
    // log10 may round across a power of ten: settle k so that 10^k ≤ target < 10^(k+1).
    while k > -330 && pow10(k) > target {
        k -= 1;
    }
    while pow10(k + 1) <= target {
        k += 1;
    }
    let m = [5u32, 2, 1]
        .into_iter()
        .find(|&m| f64::from(m) * pow10(k) <= target)?;
    let length = f64::from(m) * pow10(k);
    let label = match k {
        0..=5 => format!("{m}{}", "0".repeat(k as usize)),
        -4..=-1 => format!("0.{}{m}", "0".repeat((-k - 1) as usize)),
        _ => format!("{m}e{k}"),
    };
    (length > 0.0).then_some((length, label))
}

/// 10^k as the nearest `f64` the parser gives (exact for the digits written).
fn pow10(k: i32) -> f64 {
    format!("1e{k}").parse().unwrap_or(0.0)
}

/// How [`render_pairs`] treats a pair.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RenderMode {
    /// Convex pairs with their intersection answer; other simple pairs with their
    /// crossing points (module docs).
    #[default]
    Auto,
    /// Every pair as simple polygons with the points where the boundaries meet.
    Crossings,
}

/// What [`render_pairs`] drew.
#[derive(Clone, Debug, Default)]
pub struct PairsPicture {
    /// The SVG document.
    pub svg: String,
    /// Panels drawn (one per input line up to the limit).
    pub drawn: usize,
    /// True when the input had more lines than the limit (they were not read).
    pub more: bool,
}

/// Reads `check` lines from `input` and draws up to `limit` of them, one panel per
/// line (module docs: which pairs are drawn how). Stops reading at the first line
/// beyond the limit, and says so in [`PairsPicture::more`].
///
/// # Errors
/// Only I/O errors of `input`; a bad line becomes an error panel.
///
/// ```
/// use polysect::render::{RenderMode, render_pairs};
/// let input = br#"{"p": [[0,0],[2,0],[2,2],[0,2]], "q": [[2,2],[3,2],[3,3]]}
/// {"p": [[0,0],[4,0],[4,4],[2,1],[0,4]], "q": [[1,0],[3,0],[2,3]]}
/// not json
/// "#;
/// let picture = render_pairs(&input[..], RenderMode::Auto, 2)?;
/// assert_eq!((picture.drawn, picture.more), (2, true));
/// assert!(picture.svg.contains("line 1: intersect"));
/// assert!(picture.svg.contains("crossing points")); // the arrowhead is not convex
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn render_pairs<R: Read>(input: R, mode: RenderMode, limit: usize) -> io::Result<PairsPicture> {
    let mut panels = Vec::new();
    let mut more = false;
    for_each_pair_with_id(input, |line_no, id, pair| {
        if panels.len() >= limit {
            more = true;
            return false;
        }
        let name = panel_name(line_no, id);
        panels.push(match pair {
            Ok((p, q)) => pair_panel(&name, p, q, mode),
            Err(message) => error_panel(&name, message),
        });
        true
    })?;
    let mut legend = vec![(Swatch::Fill(Style::Plain), "p")];
    let has = |style: Style| panels.iter().any(|p| p.polygons.iter().any(|(_, s)| *s == style));
    if has(Style::Highlight) {
        legend.push((Swatch::Fill(Style::Highlight), "q, intersecting p"));
    }
    if has(Style::Other) {
        legend.push((Swatch::Fill(Style::Other), "q, disjoint from p"));
    }
    if panels
        .iter()
        .any(|p| p.caption.contains("crossing point") || p.caption.contains("boundaries"))
    {
        legend.push((Swatch::Mark, "where the boundaries meet"));
    }
    Ok(PairsPicture {
        svg: svg(&panels, 4, 320.0, &legend),
        drawn: panels.len(),
        more,
    })
}

/// A panel's name: the line's `"id"` (a string without its quotes, anything else as
/// written) and its line number, or the line number alone.
fn panel_name(line_no: u64, id: Option<&str>) -> String {
    match id {
        Some(id) => {
            let shown = match serde_json::from_str::<serde_json::Value>(id) {
                Ok(serde_json::Value::String(text)) => text,
                _ => id.to_string(),
            };
            format!("{shown} (line {line_no})")
        }
        None => format!("line {line_no}"),
    }
}

fn error_panel(name: &str, message: String) -> Panel {
    // The protocol's message starts "line N: " (or "line N, column C: ").
    let text = message
        .split_once(": ")
        .filter(|(place, _)| place.starts_with("line "))
        .map_or(message.as_str(), |(_, m)| m)
        .to_string();
    Panel {
        caption: format!("{name}: error"),
        error: Some(text),
        ..Panel::default()
    }
}

fn pair_panel(name: &str, p: Vec<Point>, q: Vec<Point>, mode: RenderMode) -> Panel {
    if mode == RenderMode::Auto
        && let (Ok(cp), Ok(cq)) = (
            ConvexPolygon::new(p.iter().copied()),
            ConvexPolygon::new(q.iter().copied()),
        )
    {
        let hit = Linear.intersects(&cp, &cq);
        return Panel {
            polygons: vec![
                (cp.into_vertices(), Style::Plain),
                (
                    cq.into_vertices(),
                    if hit { Style::Highlight } else { Style::Other },
                ),
            ],
            caption: format!("{name}: {}", if hit { "intersect" } else { "disjoint" }),
            ..Panel::default()
        };
    }
    let (sp, sq) = match (SimplePolygon::new(p), SimplePolygon::new(q)) {
        (Ok(sp), Ok(sq)) => (sp, sq),
        (Err(e), _) => return error_panel(name, format!("p: {e}")),
        (_, Err(e)) => return error_panel(name, format!("q: {e}")),
    };
    let points = Sweep.crossings_with(Exact, &sp, &sq);
    let hit = !points.is_empty() || sp.contains_point(sq.vertex(0)) || sq.contains_point(sp.vertex(0));
    let caption = match points.len() {
        0 if hit => format!("{name}: boundaries apart, one inside the other"),
        0 => format!("{name}: boundaries apart, disjoint"),
        1 => format!("{name}: 1 crossing point"),
        k => format!("{name}: {k} crossing points"),
    };
    Panel {
        polygons: vec![
            (sp.into_vertices(), Style::Plain),
            (
                sq.into_vertices(),
                if hit { Style::Highlight } else { Style::Other },
            ),
        ],
        marks: points,
        caption,
        error: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The numbers of every `<polygon points="...">` and circle centre.
    fn coordinates(svg: &str) -> Vec<(f64, f64)> {
        let mut out = Vec::new();
        for chunk in svg.split("points=\"").skip(1) {
            let list = &chunk[..chunk.find('"').unwrap()];
            for pair in list.split(' ') {
                let (x, y) = pair.split_once(',').unwrap();
                out.push((x.parse().unwrap(), y.parse().unwrap()));
            }
        }
        out
    }

    #[test]
    fn shapes_fill_their_panel_at_every_scale() {
        for scale in [1.0, 1e-300, 1e300, f64::MAX / 4.0, 5e-324 * 8.0] {
            let tri = vec![
                Point::new(0.0, 0.0),
                Point::new(2.0 * scale, 0.0),
                Point::new(0.0, scale),
            ];
            let panel = Panel {
                polygons: vec![(tri, Style::Plain)],
                ..Panel::default()
            };
            let out = svg(&[panel], 1, 320.0, &[]);
            let xy = coordinates(&out);
            let (x0, x1) = xy
                .iter()
                .fold((f64::MAX, f64::MIN), |a, p| (a.0.min(p.0), a.1.max(p.0)));
            let (y0, y1) = xy
                .iter()
                .fold((f64::MAX, f64::MIN), |a, p| (a.0.min(p.1), a.1.max(p.1)));
            // The width (twice the height) spans the panel less its margins, centred.
            assert!(
                (x0 - MARGIN).abs() < 0.02 && (x1 - (320.0 - MARGIN)).abs() < 0.02,
                "{scale}: x {x0}..{x1}"
            );
            let mid = (y0 + y1) / 2.0;
            assert!(
                (mid - 160.0).abs() < 0.02 && (y1 - y0 - 146.0).abs() < 0.03,
                "{scale}: y {y0}..{y1}"
            );
        }
    }

    #[test]
    fn draws_every_polygon_and_escapes_text() {
        let tri = vec![Point::new(0., 0.), Point::new(1., 0.), Point::new(0., 1.)];
        let huge: Vec<Point> = tri
            .iter()
            .map(|p| Point::new(p.x * f64::MAX, p.y * f64::MAX))
            .collect();
        let panels = vec![
            Panel {
                polygons: vec![(tri.clone(), Style::Plain), (tri, Style::Highlight)],
                marks: vec![Point::new(0.5, 0.5)],
                caption: "a < b".into(),
                error: None,
            },
            Panel {
                polygons: vec![(huge, Style::Other)],
                caption: "huge".into(),
                ..Panel::default()
            },
        ];
        let out = svg(&panels, 2, 320.0, &[(Swatch::Mark, "x & y")]);
        assert_eq!(out.matches("<polygon").count(), 3);
        assert_eq!(out.matches("<circle").count(), 2);
        assert!(out.contains("a &lt; b") && out.contains("x &amp; y"));
        assert!(!out.contains("NaN") && !out.contains("inf"), "{out}");
    }

    /// Simple pairs are marked where the boundaries meet, exactly as the all-pairs
    /// reference finds them; q is red exactly when the regions meet.
    #[test]
    fn crossing_marks_equal_the_brute_force() {
        use crate::crossings::Brute;
        use crate::generate::simple::{PointDistribution, SimpleMethod, random_simple_polygon};
        use rand::SeedableRng;
        use rand::rngs::SmallRng;
        let mut rng = SmallRng::seed_from_u64(23);
        let (mut marked, mut apart) = (0, 0);
        for round in 0..300 {
            let method = [SimpleMethod::SpacePartition, SimpleMethod::Star][round % 2];
            let dist = [
                PointDistribution::Uniform { min: 0.0, max: 100.0 },
                PointDistribution::Grid { size: 8 },
            ][round / 2 % 2];
            let n = [3, 5, 12, 40][round / 4 % 4];
            let p = random_simple_polygon(method, dist, n, &mut rng).unwrap();
            let q = random_simple_polygon(method, dist, 3 + round % 9, &mut rng).unwrap();
            for mode in [RenderMode::Auto, RenderMode::Crossings] {
                let panel = pair_panel("line 1", p.vertices().to_vec(), q.vertices().to_vec(), mode);
                let convex = ConvexPolygon::new(p.vertices().iter().copied()).is_ok()
                    && ConvexPolygon::new(q.vertices().iter().copied()).is_ok();
                let want = Brute.crossings(&p, &q);
                let hit = panel.polygons[1].1 == Style::Highlight;
                if mode == RenderMode::Crossings || !convex {
                    assert_eq!(panel.marks, want, "{:?} {:?}", p.vertices(), q.vertices());
                    marked += usize::from(!want.is_empty());
                }
                if want.is_empty() {
                    apart += 1;
                    // Apart boundaries: the regions meet iff one holds the other's vertex.
                    let inside = |a: &SimplePolygon, b: &SimplePolygon| {
                        b.vertices().iter().all(|&v| a.contains_point(v))
                    };
                    assert_eq!(
                        hit,
                        inside(&p, &q) || inside(&q, &p),
                        "{:?} {:?}",
                        p.vertices(),
                        q.vertices()
                    );
                } else {
                    assert!(hit);
                }
            }
        }
        assert!(marked > 100 && apart > 20, "{marked} marked, {apart} apart");
        // A polygon against itself: every edge is shared, so every vertex is marked.
        let p = SimplePolygon::new([[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [2.0, 1.0], [0.0, 4.0]]).unwrap();
        let panel = pair_panel(
            "line 1",
            p.vertices().to_vec(),
            p.vertices().to_vec(),
            RenderMode::Auto,
        );
        let mut corners = p.vertices().to_vec();
        corners.sort_unstable_by(|a, b| a.lex_cmp(*b));
        assert_eq!(panel.marks, corners);
        assert_eq!(panel.polygons[1].1, Style::Highlight);
    }

    #[test]
    fn wrap_keeps_lines_short_and_marks_cuts() {
        let text =
            "vertex 3 is reflex: the polygon is not convex, and averyveryverylongwordthatdoesnotfit here";
        let lines = wrap(text, 20, 10);
        assert!(lines.iter().all(|l| l.chars().count() <= 20), "{lines:?}");
        assert_eq!(lines.join(" ").replace(' ', ""), text.replace(' ', ""));
        let cut = wrap(text, 20, 2);
        assert_eq!(cut.len(), 2);
        assert!(cut[1].ends_with('…') && cut[1].chars().count() <= 20, "{cut:?}");
        assert!(wrap("", 20, 2).is_empty());
    }

    #[test]
    fn scale_bars_are_round_lengths_within_a_quarter_of_the_span() {
        for (half_span, length, label) in [
            (1.0, 0.5, "0.5"),
            (2.0, 1.0, "1"),
            (10.0, 5.0, "5"),
            (7.0, 2.0, "2"),
            (400.0, 200.0, "200"),
            (3e-300, 1e-300, "1e-300"),
            (f64::MAX, 5e307, "5e307"),
            (0.003, 0.001, "0.001"),
        ] {
            let (l, t) = scale_bar(half_span).unwrap();
            assert_eq!((l, t.as_str()), (length, label), "{half_span}");
            assert!(l <= half_span / 2.0 && l * 5.0 > half_span / 2.0, "{half_span}");
        }
        assert_eq!(scale_bar(0.0), None);
        assert_eq!(scale_bar(f64::NAN), None);
        // Every panel with a span draws its bar and label.
        let tri = vec![Point::new(0.0, 0.0), Point::new(40.0, 0.0), Point::new(0.0, 40.0)];
        let text = svg(
            &[Panel {
                polygons: vec![(tri, Style::Plain)],
                ..Panel::default()
            }],
            1,
            320.0,
            &[],
        );
        assert!(
            text.contains(">10</text>") && text.contains("<path d=\"M"),
            "{text}"
        );
    }

    #[test]
    fn panels_are_named_by_the_lines_id() {
        let input = br#"{"id": "left & right", "p": [[0,0],[2,0],[2,2]], "q": [[5,5],[6,5],[6,6]]}
{"id": 42, "p": [[0,0],[2,0],[2,2]], "q": [[1,0],[3,0],[3,1]]}
{"p": [[0,0],[2,0],[2,2]], "q": [[1,0],[3,0],[3,1]]}
{"id": "bad", "p": [[0,0],[1,1]], "q": [[1,0],[3,0],[3,1]]}
"#;
        let picture = render_pairs(&input[..], RenderMode::Auto, 10).unwrap();
        assert!(
            picture.svg.contains("left &amp; right (line 1): disjoint"),
            "{}",
            picture.svg
        );
        assert!(picture.svg.contains("42 (line 2): intersect"));
        assert!(picture.svg.contains(">line 3: intersect"));
        assert!(picture.svg.contains("bad (line 4): error"));
    }
}
