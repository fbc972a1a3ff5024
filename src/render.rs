//! SVG pictures of polygons: pairs with their answers, and scenes with the intersecting
//! polygons highlighted. Plain SVG text, no dependencies; y points up as in the input.

use crate::kernel::Point;
use std::fmt::Write;

/// How a polygon is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// First polygon of a pair / an ordinary scene polygon.
    Plain,
    /// Second polygon of a pair.
    Other,
    /// A polygon that intersects another.
    Highlight,
}

impl Style {
    fn colours(self) -> (&'static str, &'static str) {
        match self {
            Style::Plain => ("#4c78a8", "#4c78a8"),
            Style::Other => ("#72b7b2", "#2f6f6a"),
            Style::Highlight => ("#e45756", "#9c1f1e"),
        }
    }
}

/// One framed picture: polygons and a caption.
#[derive(Clone, Debug, Default)]
pub struct Panel {
    pub polygons: Vec<(Vec<Point>, Style)>,
    pub caption: String,
}

const SIZE: f64 = 320.0;
const MARGIN: f64 = 12.0;
const CAPTION: f64 = 22.0;

/// Lays the panels out in a grid of `columns` and returns the SVG document.
pub fn svg(panels: &[Panel], columns: usize) -> String {
    let columns = columns.max(1);
    let rows = panels.len().div_ceil(columns).max(1);
    let (w, h) = (columns as f64 * SIZE, rows as f64 * (SIZE + CAPTION));
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif" font-size="13">"#
    );
    let _ = writeln!(s, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
    for (i, panel) in panels.iter().enumerate() {
        let (ox, oy) = (
            (i % columns) as f64 * SIZE,
            (i / columns) as f64 * (SIZE + CAPTION),
        );
        draw_panel(&mut s, panel, ox, oy);
    }
    s.push_str("</svg>\n");
    s
}

fn draw_panel(s: &mut String, panel: &Panel, ox: f64, oy: f64) {
    let _ = writeln!(
        s,
        r##"<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#ccc"/>"##,
        ox + 2.0,
        oy + 2.0,
        SIZE - 4.0,
        SIZE - 4.0
    );
    let all = panel.polygons.iter().flat_map(|(v, _)| v.iter());
    let (mut lo, mut hi) = (Point::new(f64::MAX, f64::MAX), Point::new(f64::MIN, f64::MIN));
    for p in all {
        lo = Point::new(lo.x.min(p.x), lo.y.min(p.y));
        hi = Point::new(hi.x.max(p.x), hi.y.max(p.y));
    }
    // Scale in two steps so that huge and tiny coordinates stay finite.
    let span = ((hi.x - lo.x) / 2.0).max((hi.y - lo.y) / 2.0);
    let scale = if span > 0.0 && span.is_finite() {
        (SIZE - 2.0 * MARGIN) / 2.0 / span
    } else {
        1.0
    };
    let map = |p: &Point| {
        let x = ox + MARGIN + (p.x / 2.0 - lo.x / 2.0) * scale;
        let y = oy + SIZE - MARGIN - (p.y / 2.0 - lo.y / 2.0) * scale;
        (x, y)
    };
    for (vertices, style) in &panel.polygons {
        let (fill, stroke) = style.colours();
        let pts: Vec<String> = vertices
            .iter()
            .map(|p| {
                let (x, y) = map(p);
                format!("{x:.2},{y:.2}")
            })
            .collect();
        let _ = writeln!(
            s,
            r#"<polygon points="{}" fill="{fill}" fill-opacity="0.35" stroke="{stroke}" stroke-width="1"/>"#,
            pts.join(" ")
        );
    }
    let caption = panel
        .caption
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;");
    let _ = writeln!(
        s,
        r#"<text x="{}" y="{}">{caption}</text>"#,
        ox + 6.0,
        oy + SIZE + 16.0
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn draws_every_polygon_and_escapes_captions() {
        let tri = vec![Point::new(0., 0.), Point::new(1., 0.), Point::new(0., 1.)];
        let huge: Vec<Point> = tri
            .iter()
            .map(|p| Point::new(p.x * f64::MAX, p.y * f64::MAX))
            .collect();
        let panels = vec![
            Panel {
                polygons: vec![(tri.clone(), Style::Plain), (tri, Style::Highlight)],
                caption: "a < b".into(),
            },
            Panel {
                polygons: vec![(huge, Style::Other)],
                caption: "huge".into(),
            },
        ];
        let out = svg(&panels, 2);
        assert_eq!(out.matches("<polygon").count(), 3);
        assert!(out.contains("a &lt; b"));
        assert!(!out.contains("NaN") && !out.contains("inf"), "{out}");
    }
}
