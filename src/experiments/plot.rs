//! SVG line and scatter charts (plotters, SVG backend only).
//!
//! Logarithmic axes are drawn as linear axes over log2 (x) or log10 (y) of the values,
//! with tick labels showing the values, so one code path serves every chart.

use plotters::prelude::*;
use std::io;
use std::path::Path;

/// One named curve.
#[derive(Clone, Debug)]
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
}

impl Series {
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>) -> Series {
        Series {
            name: name.into(),
            points,
        }
    }
}

/// How a chart looks.
#[derive(Clone, Debug)]
pub struct Chart<'a> {
    pub title: &'a str,
    pub x_label: &'a str,
    pub y_label: &'a str,
    /// x values are powers of two: the axis is log2 x, labelled 2^k.
    pub log2_x: bool,
    /// y on a log10 axis.
    pub log_y: bool,
    /// Points only (a scatter plot), with each series' name written beside its points.
    pub scatter: bool,
}

const COLORS: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

fn err(e: impl std::fmt::Display) -> io::Error {
    io::Error::other(e.to_string())
}

/// A short number: 3 significant digits, SI suffix for large and small values.
fn short(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        "0".into()
    } else if a >= 1e9 {
        format!("{:.3}G", v / 1e9)
    } else if a >= 1e6 {
        format!("{:.3}M", v / 1e6)
    } else if a >= 1e3 {
        format!("{:.3}k", v / 1e3)
    } else if a >= 1.0 {
        format!("{v:.3}")
    } else {
        format!("{v:.3e}")
    }
    .replace(".000", "")
}

/// Draws `series` into the SVG file `path` (640×400).
///
/// # Errors
/// When the file cannot be written.
pub fn draw(path: &Path, chart: &Chart<'_>, series: &[Series]) -> io::Result<()> {
    let fx = |x: f64| if chart.log2_x { x.log2() } else { x };
    let fy = |y: f64| if chart.log_y { y.log10() } else { y };
    let pts: Vec<Vec<(f64, f64)>> = series
        .iter()
        .map(|s| {
            s.points
                .iter()
                .map(|&(x, y)| (fx(x), fy(y)))
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .collect()
        })
        .collect();
    let all = pts.iter().flatten();
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(x, y) in all {
        (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
    }
    if x0 > x1 {
        (x0, x1, y0, y1) = (0.0, 1.0, 0.0, 1.0);
    }
    let pad_x = ((x1 - x0) * 0.05).max(0.5);
    let pad_y = ((y1 - y0) * 0.08).max(if chart.log_y { 0.1 } else { y1.abs() * 0.05 + 1e-9 });
    let (y0, y1) = if !chart.log_y && y0 >= 0.0 {
        (0.0, y1 + pad_y)
    } else {
        (y0 - pad_y, y1 + pad_y)
    };
    let (x0, x1) = (
        x0 - pad_x,
        x1 + if chart.scatter {
            (x1 - x0) * 0.25 + pad_x
        } else {
            pad_x
        },
    );

    let root = SVGBackend::new(path, (640, 400)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let mut c = ChartBuilder::on(&root)
        .caption(chart.title, ("sans-serif", 17))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(err)?;
    let x_fmt = |x: &f64| {
        if chart.log2_x {
            format!("2^{x:.0}")
        } else {
            short(*x)
        }
    };
    let y_fmt = |y: &f64| {
        if chart.log_y {
            short(10f64.powf(*y))
        } else {
            short(*y)
        }
    };
    c.configure_mesh()
        .x_desc(chart.x_label)
        .y_desc(chart.y_label)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .light_line_style(WHITE.mix(0.0))
        .draw()
        .map_err(err)?;
    for (i, (s, p)) in series.iter().zip(&pts).enumerate() {
        let color = COLORS[i % COLORS.len()];
        if chart.scatter {
            c.draw_series(p.iter().map(|&xy| Circle::new(xy, 4, color.filled())))
                .map_err(err)?;
            c.draw_series(p.iter().map(|&(x, y)| {
                Text::new(
                    s.name.clone(),
                    (x, y),
                    ("sans-serif", 11).into_font().color(&color),
                )
            }))
            .map_err(err)?;
        } else {
            c.draw_series(LineSeries::new(p.iter().copied(), color.stroke_width(2)))
                .map_err(err)?
                .label(&s.name)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], color.stroke_width(2)));
            c.draw_series(p.iter().map(|&xy| Circle::new(xy, 2, color.filled())))
                .map_err(err)?;
        }
    }
    if !chart.scatter {
        c.configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.3))
            .position(SeriesLabelPosition::UpperLeft)
            .draw()
            .map_err(err)?;
    }
    root.present().map_err(err)
}
